// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Extrapolation policies: what a curve is outside its parameter domain.

use crate::ambient::Ambient;
use crate::curve::{Curve, Jet, Side};
use crate::error::DomainError;
use crate::manifold::{Manifold, renormalize};
use crate::math;

/// What a curve is outside its domain `[t0, t1]` (see [`Extrapolated`]).
///
/// Inside the closed domain every policy gives the curve's own jet, bit for bit. Outside it
/// (with `Δ = t − t1` after the end, `Δ = t − t0 < 0` before the start):
///
/// | policy | point | velocity | acceleration |
/// |---|---|---|---|
/// | `Hold` | the end point | zero | zero |
/// | `Extend` | `exp_p(Δ·v)`: the geodesic from the end point `p` with the end velocity `v` | `v` transported along it (constant speed) | `−|v|²·c`: the normal part only |
/// | `Cycle` | `c(t0 + (t − t0) mod (t1 − t0))` (antiperiodic loops: `±`, the sign of the lap) | of the curve there | of the curve there |
/// | `Segment` | the end piece's own formula continued ([`Curve::jet_beyond`]) | of that formula | of that formula |
/// | `Error` | — | — | — |
///
/// `Extend` continues along the great circle at constant speed: the covariant (tangential)
/// acceleration is zero and the ambient acceleration is the centripetal `−|v|²·c` that keeps
/// the curve on the sphere. On S³ that is rotation at the constant angular velocity of the end,
/// `ω = 2·v·p̄`, with angular acceleration `α = 0`. The end velocity is the one-sided one
/// (left at `t1`, right at `t0`); an end at rest stays at the end point.
///
/// `Cycle` repeats `[t0, t1)` with period `t1 − t0` (meaningful for closed curves, where it is
/// continuous); a loop that ends at the antipode of its start ([`Curve::is_antiperiodic`], a
/// loop of rotations of an odd number of full turns) continues antiperiodically,
/// `c(t + T) = −c(t)`, the same rotations. At the parameters `t1 + k·(t1 − t0)` the right-sided jet is the curve's jet at
/// `t0` and the left-sided one the curve's left jet at `t1`.
///
/// `Segment` continues the first/last segment's polynomial in the tangent space, as scipy's
/// `RotationSpline` does: for an open [`CubicSpline`](crate::CubicSpline) the exponential of
/// the end segment's cubic at local parameters beyond `[0, 1]`
/// ([`CubicSpline::continued_jet`](crate::CubicSpline::continued_jet)). A curve without such a
/// continuation ([`Curve::jet_beyond`] is `None`) has no value outside its domain under it, nor
/// has the cubic where its polynomial overflows: [`DomainError::Unbounded`].
///
/// `Error` makes [`Extrapolated::try_jet`] return [`DomainError::Outside`]; the infallible
/// [`Curve`] methods clamp under it, as the curve itself does.
///
/// # Non-finite parameters
///
/// A NaN parameter is an error for [`Extrapolated::try_jet`] under every policy
/// ([`DomainError::NotANumber`]); the [`Curve`] methods treat it as `t0` (the held start at
/// rest under `Hold`, the curve's jet at `t0` otherwise). `±∞` holds the end under `Hold`. Under
/// `Extend`, `Cycle` and `Segment`, `±∞` (and an `Extend` angle `|v|·Δ` that overflows) has no value:
/// [`DomainError::Unbounded`] from `try_jet`, the curve's end jet from the [`Curve`] methods.
/// Nothing panics, in debug builds either.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Extrapolate {
    /// Stay at the end point, at rest: zero velocity and acceleration.
    #[default]
    Hold,
    /// Continue along the end's geodesic with the end's velocity.
    Extend,
    /// Repeat the curve periodically in `t` with period `t1 − t0`.
    Cycle,
    /// Continue the first/last segment's own formula ([`Curve::jet_beyond`]): for the cubic
    /// spline its polynomial in the tangent space, as scipy's `RotationSpline` does.
    Segment,
    /// A parameter outside the domain is a [`DomainError`] (checked calls only).
    Error,
}

/// A curve with an [`Extrapolate`] policy outside its domain.
///
/// Implements [`Curve`] on the same domain and joints as the wrapped curve; only parameters
/// outside the domain are treated differently (see [`Extrapolate`] for the exact values).
///
/// # Examples
///
/// ```
/// use spherekit::{Curve, Extrapolate, Extrapolated, GeodesicSpline, Manifold, S2Point};
/// use spherekit::glam::DVec3;
///
/// let c = GeodesicSpline::try_new(vec![S2Point::X, S2Point::Y], None).unwrap();
/// // The curve itself clamps and keeps reporting the end velocity.
/// assert!(c.jet(2.0).velocity.length() > 1.0);
///
/// let held = Extrapolated::new(c.clone(), Extrapolate::Hold);
/// assert_eq!(held.jet(2.0).point, S2Point::Y);
/// assert_eq!(held.jet(2.0).velocity, DVec3::ZERO);
///
/// // Extend: a quarter turn per unit t, continued past the end.
/// let ext = Extrapolated::new(c.clone(), Extrapolate::Extend);
/// let d = S2Point::Y.dist(&ext.eval(1.5));
/// assert!((d - core::f64::consts::FRAC_PI_4).abs() < 1e-15);
///
/// let strict = Extrapolated::new(c, Extrapolate::Error);
/// assert!(strict.try_jet(1.5).is_err());
/// assert!(strict.try_jet(f64::NAN).is_err());
/// assert!(strict.try_jet(0.5).is_ok());
/// ```
#[derive(Clone, Debug)]
pub struct Extrapolated<C> {
    curve: C,
    policy: Extrapolate,
}

impl<C: Curve> Extrapolated<C> {
    /// Wraps `curve` with `policy`.
    #[must_use]
    pub fn new(curve: C, policy: Extrapolate) -> Self {
        Self { curve, policy }
    }

    /// The policy.
    #[must_use]
    pub fn policy(&self) -> Extrapolate {
        self.policy
    }

    /// The wrapped curve.
    #[must_use]
    pub fn curve(&self) -> &C {
        &self.curve
    }

    /// Unwraps the curve.
    #[must_use]
    pub fn into_inner(self) -> C {
        self.curve
    }

    /// The jet at `t` under the policy, or why there is none (right-sided at joints).
    ///
    /// # Errors
    ///
    /// [`DomainError::NotANumber`] for NaN; [`DomainError::Outside`] outside the domain under
    /// [`Extrapolate::Error`]; [`DomainError::Unbounded`] for `±∞` under
    /// [`Extend`](Extrapolate::Extend), [`Cycle`](Extrapolate::Cycle) and
    /// [`Segment`](Extrapolate::Segment), for an `Extend` angle that overflows, and under
    /// `Segment` where the curve has no continuation or it overflows.
    pub fn try_jet(&self, t: f64) -> Result<Jet<C::Point>, DomainError> {
        self.try_jet_at(t, Side::Right)
    }

    /// [`try_jet`](Self::try_jet) with the one-sided limit from `side` at joints.
    ///
    /// # Errors
    ///
    /// As [`try_jet`](Self::try_jet).
    pub fn try_jet_at(&self, t: f64, side: Side) -> Result<Jet<C::Point>, DomainError> {
        if t.is_nan() {
            return Err(DomainError::NotANumber);
        }
        let domain = self.curve.domain();
        let [t0, t1] = domain;
        if (t0..=t1).contains(&t) {
            return Ok(self.curve.jet_at(t, side));
        }
        match self.policy {
            Extrapolate::Error => Err(DomainError::Outside { t, domain }),
            Extrapolate::Hold => Ok(self.hold(t)),
            Extrapolate::Extend => self.extend(t).ok_or(DomainError::Unbounded { t }),
            Extrapolate::Cycle => {
                if t.is_finite() {
                    Ok(self.cycle(t, side))
                } else {
                    Err(DomainError::Unbounded { t })
                }
            }
            Extrapolate::Segment => self.curve.jet_beyond(t).ok_or(DomainError::Unbounded { t }),
        }
    }

    /// Whether every parameter of `ts` is in the closed domain (then the batch calls are the
    /// curve's own).
    fn inside(&self, ts: &[f64]) -> bool {
        let [t0, t1] = self.curve.domain();
        ts.iter().all(|t| (t0..=t1).contains(t))
    }

    /// The point at `t` under the policy, or why there is none.
    ///
    /// # Errors
    ///
    /// As [`try_jet`](Self::try_jet).
    pub fn try_eval(&self, t: f64) -> Result<C::Point, DomainError> {
        self.try_jet(t).map(|j| j.point)
    }

    /// The end point at rest: the start for `t < t0` (and NaN), the end for `t > t1`.
    fn hold(&self, t: f64) -> Jet<C::Point> {
        let [t0, t1] = self.curve.domain();
        let point = self.curve.eval(if t > t1 { t1 } else { t0 });
        let zero = point.to_vector().zeros_like();
        Jet {
            point,
            velocity: zero.clone(),
            acceleration: zero,
        }
    }

    /// The geodesic continuation at `t` outside the domain; `None` when the angle is not finite.
    fn extend(&self, t: f64) -> Option<Jet<C::Point>> {
        let [t0, t1] = self.curve.domain();
        let (end, side) = if t > t1 {
            (t1, Side::Left)
        } else {
            (t0, Side::Right)
        };
        let jet = self.curve.jet_at(end, side);
        let delta = t - end;
        let p = jet.point.to_vector();
        let v = jet.velocity;
        let speed = v.length();
        let angle = speed * delta;
        if !angle.is_finite() {
            return None;
        }
        if speed == 0.0 {
            let zero = p.zeros_like();
            return Some(Jet {
                point: jet.point,
                velocity: zero.clone(),
                acceleration: zero,
            });
        }
        let e = v * (1.0 / speed);
        let (sn, cs) = math::sin_cos(angle);
        let q = renormalize(p.clone() * cs + e.clone() * sn);
        let velocity = (e * cs - p * sn) * speed;
        let acceleration = q.clone() * -(speed * speed);
        Some(Jet {
            point: C::Point::from_vector_unchecked(q),
            velocity,
            acceleration,
        })
    }

    /// The periodic jet at finite `t` outside the domain.
    fn cycle(&self, t: f64, side: Side) -> Jet<C::Point> {
        let [t0, t1] = self.curve.domain();
        let period = t1 - t0;
        let r = (t - t0).rem_euclid(period);
        // The whole periods before `t` (the lap `t` is on), for the sign of an antiperiodic
        // curve: exact for any lap count below 2⁵³.
        let mut laps = ((t - t0 - r) / period).round();
        // `r ∈ [0, period]` (rounding can give `period` itself); a whole number of periods is
        // the start from the right and the end from the left (of the lap before).
        let at_boundary = r == 0.0 || r >= period;
        if r >= period {
            laps += 1.0;
        }
        let tau = if at_boundary {
            match side {
                Side::Right => t0,
                Side::Left => {
                    laps -= 1.0;
                    t1
                }
            }
        } else {
            (t0 + r).min(t1)
        };
        let jet = self.curve.jet_at(tau, side);
        if self.curve.is_antiperiodic() && laps.rem_euclid(2.0) == 1.0 {
            jet.antipode()
        } else {
            jet
        }
    }
}

impl<C: Curve> Curve for Extrapolated<C> {
    type Point = C::Point;

    fn domain(&self) -> [f64; 2] {
        self.curve.domain()
    }

    fn joints(&self) -> &[f64] {
        self.curve.joints()
    }

    fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }

    fn is_antiperiodic(&self) -> bool {
        self.curve.is_antiperiodic()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<C::Point> {
        match self.try_jet_at(t, side) {
            Ok(jet) => jet,
            Err(_) if self.policy == Extrapolate::Hold => self.hold(t),
            // NaN, `Error` outside the domain, and no value under `Extend` or `Cycle`: the
            // curve's own clamped jet.
            Err(_) => self.curve.jet_at(t, side),
        }
    }

    fn eval(&self, t: f64) -> C::Point {
        let [t0, t1] = self.curve.domain();
        if (t0..=t1).contains(&t) {
            self.curve.eval(t)
        } else {
            self.jet(t).point
        }
    }

    /// The wrapped curve's continuation (so that wrapping twice changes nothing).
    fn jet_beyond(&self, t: f64) -> Option<Jet<C::Point>> {
        self.curve.jet_beyond(t)
    }

    /// The curve's own batch evaluation when every parameter is inside the domain, one by one
    /// otherwise (the same values either way).
    fn eval_many(&self, ts: &[f64], out: &mut [C::Point]) {
        if self.inside(ts) {
            self.curve.eval_many(ts, out);
        } else {
            crate::knots::check_batch(ts, out);
            for (&t, o) in ts.iter().zip(out) {
                *o = self.eval(t);
            }
        }
    }

    /// As [`eval_many`](Self::eval_many), for jets.
    fn jet_many(&self, ts: &[f64], out: &mut [Jet<C::Point>]) {
        if self.inside(ts) {
            self.curve.jet_many(ts, out);
        } else {
            crate::knots::check_batch(ts, out);
            for (&t, o) in ts.iter().zip(out) {
                *o = self.jet(t);
            }
        }
    }
}
