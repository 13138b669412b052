// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Closed loops of rotations: a closed quaternion curve that ends at `−q₀`, the same rotation.
//!
//! # The rule
//!
//! A loop of orientations is closed in SO(3), not on S³. Take a camera orbiting 360° about the
//! vertical, eight keys 45° of yaw apart, `q_k = (cos(kπ/8), 0, 0, sin(kπ/8))` (w first). Each
//! step is the shortest rotation between neighbours (`q_k·q_{k+1} > 0`, which is what
//! [`unflip`](crate::unflip) gives), yet the last key is on the far side of the first:
//! `q₇·q₀ = cos(7π/8) < 0`. Closing the quaternion loop at `+q₀` would make the last step turn
//! by 315° the long way; its shortest step reaches `−q₀`, the same rotation. A loop whose
//! keys turn by an odd number of full turns always ends so: flipping the sign of a key changes
//! the sign of two of the loop's dot products, so the sign of their product is fixed by the
//! rotations alone.
//!
//! Such a loop is built as the key sequence continued **antiperiodically**,
//! `q_{k+n} = −q_k`: every construction's neighbours across the seam take that sign, the curve
//! runs from `q₀` at `t₀` to `−q₀` at `t_n`, and it repeats with `c(t + T) = −c(t)`
//! ([`Curve::is_antiperiodic`]), so the seam is as smooth as the other joints up to the sign,
//! which is what [`continuity`](crate::continuity) and
//! [`Extrapolate::Cycle`](crate::Extrapolate::Cycle) measure and follow.
//!
//! # How, once for every construction
//!
//! The antiperiodic construction through `q₀ … q_{n−1}` is the first half of the ordinary
//! (periodic) closed construction through the `2n` keys `q₀ … q_{n−1}, −q₀ … −q_{n−1}` with
//! the knots continued by one period, `t_{n+k} = t_n + (t_k − t₀)`. Every construction of the
//! crate commutes with the antipodal map (`slerp(−a, −b, t) = −slerp(a, b, t)`, and likewise
//! the logarithm, the exponential, the blends and the solvers' equations), so the doubled loop
//! is antiperiodic: a local construction uses exactly the antiperiodic neighbours, and a
//! global one (the cubic's C² system, the Beta solver, the arc blend's knots) has a unique
//! solution, which the symmetry maps to itself. [`RotationLoop`] builds that doubled loop with
//! the caller's closed constructor and keeps its first half; building costs twice, evaluating
//! the same.

use crate::curve::{Curve, Jet, Side, clamp_param};
use crate::s3::UnitQuat;

/// Whether keys read as a closed loop end on the far side of the first, `q_{n−1}·q₀ < 0`: for
/// keys with the shortest steps between neighbours (after [`unflip`](crate::unflip)), a loop of
/// an odd number of full turns, which [`RotationLoop`] closes at `−q₀`.
#[must_use]
pub fn closes_at_antipode(keys: &[UnitQuat]) -> bool {
    match (keys.first(), keys.last()) {
        (Some(first), Some(last)) if keys.len() >= 2 => first.as_dquat().dot(last.as_dquat()) < 0.0,
        _ => false,
    }
}

/// A closed curve through keys of rotations that is closed in SO(3): when the keys end on the
/// far side of the first (`q_{n−1}·q₀ < 0`, a loop of an odd number of full turns) it ends at
/// `−q₀` and repeats antiperiodically; otherwise it is the ordinary closed curve, unchanged.
/// The rule, and why it holds for every construction: `docs/derivations.md`, "Closed loops"
/// (in short, the loop is the first half of the closed construction through the keys followed by
/// their antipodes, which every construction maps to an antiperiodic curve).
///
/// # Examples
///
/// A camera orbit: eight keys 45° of yaw apart, closed by the cubic spline.
///
/// ```
/// use spherekit::{
///     closes_at_antipode, continuity, CubicEnd, CubicSpline, Curve, RotationLoop, UnitQuat,
///     unflip,
/// };
/// use spherekit::glam::DVec3;
///
/// let mut keys: Vec<UnitQuat> = (0..8)
///     .map(|k| UnitQuat::from_axis_angle(DVec3::Z, f64::from(k) * std::f64::consts::FRAC_PI_4).unwrap())
///     .collect();
/// unflip(&mut keys);
/// assert!(closes_at_antipode(&keys));
/// let times: Vec<f64> = (0..=8).map(f64::from).collect();
/// let orbit = RotationLoop::try_new(keys, Some(times), |keys, knots| {
///     CubicSpline::try_new(keys, knots, CubicEnd::Natural, true)
/// })
/// .unwrap();
/// assert_eq!(orbit.domain(), [0.0, 8.0]);
/// assert!(orbit.is_antiperiodic());
/// // Ends at −q₀: the same rotation, reached by turning on, not back.
/// let end = orbit.eval(8.0).as_dquat();
/// assert!((end + UnitQuat::IDENTITY.as_dquat()).length() < 1e-12);
/// // Constant angular speed 2π/8 all the way round, the seam as smooth as the other joints.
/// let speed = 2.0 * orbit.jet(7.5).velocity.length();
/// assert!((speed - std::f64::consts::TAU / 8.0).abs() < 1e-3);
/// assert!(continuity(&orbit).iter().all(|j| j.c0 < 1e-12 && j.c1 < 1e-9 && j.c2 < 1e-9));
/// ```
#[derive(Clone, Debug)]
pub struct RotationLoop<C> {
    /// The closed curve built: through the doubled keys when antiperiodic.
    curve: C,
    /// Whether the loop ends at `−q₀` (then `curve` is the doubled loop).
    antiperiodic: bool,
    /// The loop's domain (antiperiodic: the first half of `curve`'s).
    domain: [f64; 2],
    /// The loop's joints (antiperiodic only; otherwise the curve's own).
    joints: Vec<f64>,
}

impl<C: Curve<Point = UnitQuat>> RotationLoop<C> {
    /// Builds the closed loop through `keys` with `build`, a closed constructor such as
    /// `|keys, knots| CubicSpline::try_new(keys, knots, CubicEnd::Natural, true)`.
    ///
    /// When the keys [close at the antipode](closes_at_antipode), `build` is called once
    /// with the `2n` keys `q₀ … q_{n−1}, −q₀ … −q_{n−1}` and, when `knots` are given (`n + 1`
    /// of them), the knots continued by one period, `t_{n+k} = t_n + (t_k − t₀)`; a
    /// construction with per-joint parameters takes each list twice. Otherwise `build` is
    /// called with `keys` and `knots` as given, and so is it when `knots` has not `n + 1`
    /// entries (so that the constructor reports the count in the caller's terms). The keys are
    /// used as given: canonicalise them first ([`unflip`](crate::unflip)) to have each step
    /// take the shorter way.
    ///
    /// # Errors
    ///
    /// What `build` returns. An error about a key or knot past `n` names its place in the
    /// doubled sequence (index `n + k` for key `k`).
    pub fn try_new<E>(
        keys: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
        build: impl FnOnce(Vec<UnitQuat>, Option<Vec<f64>>) -> Result<C, E>,
    ) -> Result<Self, E> {
        let n = keys.len();
        let knots_fit = knots.as_ref().is_none_or(|k| k.len() == n + 1);
        if !closes_at_antipode(&keys) || !knots_fit {
            return build(keys, knots).map(Self::periodic);
        }
        let doubled_keys: Vec<UnitQuat> = keys
            .iter()
            .copied()
            .chain(keys.iter().map(|&q| -q))
            .collect();
        let doubled_knots = knots.map(|k| {
            let mut out = k.clone();
            out.extend(k[1..].iter().map(|&t| k[n] + (t - k[0])));
            out
        });
        build(doubled_keys, doubled_knots).map(Self::from_doubled)
    }

    /// The loop of a closed curve that is not antiperiodic: the curve itself.
    fn periodic(curve: C) -> Self {
        let domain = curve.domain();
        Self {
            curve,
            antiperiodic: false,
            domain,
            joints: Vec::new(),
        }
    }

    /// The first half of a doubled antiperiodic loop.
    fn from_doubled(curve: C) -> Self {
        let [s0, s1] = curve.domain();
        let inner = curve.joints();
        // The joint where the doubled keys' second half starts: exactly `t_n` for knots given,
        // and for the constructions' own parameters (uniform, or computed from arcs of equal
        // lengths in both halves) the joint at the middle of the domain.
        let mid = 0.5 * (s0 + s1);
        let half = inner
            .iter()
            .copied()
            .min_by(|a, b| (a - mid).abs().total_cmp(&(b - mid).abs()))
            .filter(|m| (m - mid).abs() <= 1e-9 * (s1 - s0))
            .unwrap_or(mid);
        let mut joints: Vec<f64> = inner.iter().copied().filter(|&t| t < half).collect();
        joints.push(half);
        Self {
            curve,
            antiperiodic: true,
            domain: [s0, half],
            joints,
        }
    }
}

impl<C> RotationLoop<C> {
    /// The closed curve built: the loop itself, or when [antiperiodic](Curve::is_antiperiodic)
    /// the doubled loop whose first half this is.
    #[must_use]
    pub fn inner(&self) -> &C {
        &self.curve
    }

    /// Unwraps the curve built (see [`inner`](Self::inner)).
    #[must_use]
    pub fn into_inner(self) -> C {
        self.curve
    }
}

impl<C: Curve<Point = UnitQuat>> RotationLoop<C> {
    /// The parameter and side at which the doubled curve is evaluated for the loop's `t`:
    /// clamped to the loop's domain, its end as the left limit (the doubled curve goes on).
    fn clamped(&self, t: f64, side: Side) -> (f64, Side) {
        let [t0, t1] = self.domain;
        let t = clamp_param(t, self.domain);
        let side = if t >= t1 {
            Side::Left
        } else if t <= t0 {
            Side::Right
        } else {
            side
        };
        (t, side)
    }

    /// Whether every parameter is inside the loop's domain short of its end (then the batch
    /// calls are the doubled curve's own).
    fn passes_through(&self, ts: &[f64]) -> bool {
        let [t0, t1] = self.domain;
        !self.antiperiodic || ts.iter().all(|&t| t >= t0 && t < t1)
    }
}

impl<C: Curve<Point = UnitQuat>> Curve for RotationLoop<C> {
    type Point = UnitQuat;

    fn domain(&self) -> [f64; 2] {
        self.domain
    }

    fn joints(&self) -> &[f64] {
        if self.antiperiodic {
            &self.joints
        } else {
            self.curve.joints()
        }
    }

    fn is_closed(&self) -> bool {
        self.antiperiodic || self.curve.is_closed()
    }

    fn is_antiperiodic(&self) -> bool {
        self.antiperiodic || self.curve.is_antiperiodic()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        if !self.antiperiodic {
            return self.curve.jet_at(t, side);
        }
        let (t, side) = self.clamped(t, side);
        self.curve.jet_at(t, side)
    }

    fn eval(&self, t: f64) -> UnitQuat {
        if !self.antiperiodic {
            return self.curve.eval(t);
        }
        let (t, side) = self.clamped(t, Side::Right);
        match side {
            Side::Right => self.curve.eval(t),
            Side::Left => self.curve.jet_at(t, Side::Left).point,
        }
    }

    fn eval_many(&self, ts: &[f64], out: &mut [UnitQuat]) {
        if self.passes_through(ts) {
            self.curve.eval_many(ts, out);
        } else {
            crate::knots::check_batch(ts, out);
            for (&t, o) in ts.iter().zip(out) {
                *o = self.eval(t);
            }
        }
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<UnitQuat>]) {
        if self.passes_through(ts) {
            self.curve.jet_many(ts, out);
        } else {
            crate::knots::check_batch(ts, out);
            for (&t, o) in ts.iter().zip(out) {
                *o = self.jet(t);
            }
        }
    }

    fn jet_beyond(&self, t: f64) -> Option<Jet<UnitQuat>> {
        if self.antiperiodic {
            None
        } else {
            self.curve.jet_beyond(t)
        }
    }
}
