// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Catmull-Rom splines on spheres: piecewise cubic spherical Bézier curves whose inner control
//! points come from central differences of the keys (Gortler 2012, §9.1–9.3).

use crate::bezier::CubicSegment;
use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::geodesic::{MIN_LOOP_POINTS, check_chain, check_loop};
use crate::knots::Knots;
use crate::manifold::Manifold;
#[cfg(any(test, feature = "compact"))]
use crate::recast::{Recast, to_sm};
use crate::s3::UnitQuat;
use crate::slerp_jet::ScalarJet;

/// A Catmull-Rom spline through `c₀ … cₙ` (n ≥ 1) steered by two extra end points: the input is
/// `c₋₁, c₀, …, cₙ, cₙ₊₁` (n + 3 points); `c₋₁` and `cₙ₊₁` set the end tangents and are not
/// interpolated. Knots `t₀ < … < tₙ` belong to `c₀ … cₙ` (default `0, 1, …, n`). Source: Gortler
/// (2012), *Foundations of 3D Computer Graphics*, §9.2–9.3.
///
/// Segment `i` on `[tᵢ, tᵢ₊₁]` (width `hᵢ`, `τ = (t − tᵢ)/hᵢ`) is the cubic de Casteljau curve
/// with control points `cᵢ, dᵢ, eᵢ, cᵢ₊₁` (6 slerps, [`CubicSegment`]), where `dᵢ`, `eᵢ` step
/// from `cᵢ`, `cᵢ₊₁` a third of the segment along the tangents `Tᵢ` (velocities in `t`):
///
/// ```text
/// Wᵢ = tᵢ₊₁ − tᵢ₋₁                          with t₋₁ = t₀ − h₀,  tₙ₊₁ = tₙ + hₙ₋₁
/// dᵢ = exp_{cᵢ}( hᵢ·Tᵢ/3 ),   eᵢ = exp_{cᵢ₊₁}( −hᵢ·Tᵢ₊₁/3 )
/// ```
///
/// Two tangent rules:
///
/// - [`try_new`](Self::try_new) (any sphere): `Tᵢ = (log_{cᵢ}(cᵢ₊₁) − log_{cᵢ}(cᵢ₋₁))/Wᵢ`, the
///   intrinsic central difference.
/// - [`try_new_quaternion`](Self::try_new_quaternion) (S³, the rule of Gortler (2012), §9.3):
///   `Tᵢ = log(Xᵢ)·cᵢ/Wᵢ` with `Xᵢ = cᵢ₊₁·cᵢ₋₁⁻¹`, replaced by `−Xᵢ` when its scalar part is
///   negative (short-path rule, applied to the base of both `dᵢ` and `eᵢ₋₁`,
///   `docs/derivations.md#catmull-rom`). For uniform knots this is `dᵢ = Xᵢ^(1/6)·cᵢ`,
///   `eᵢ = Xᵢ₊₁^(−1/6)·cᵢ₊₁`, exactly the book's rule.
///
/// Both rules agree with each other (and with the scalar Catmull-Rom spline of the angles) when
/// all points lie on one great circle at angles αₖ with |αₖ₊₁ − αₖ₋₁| < π/2 (so that the
/// short-path rule does not act) and |αₖ₊₁ − αₖ| < π. Since
/// `c′(tᵢ±) = 3·log_{cᵢ}(dᵢ)/hᵢ = −3·log_{cᵢ}(eᵢ₋₁)/hᵢ₋₁ = Tᵢ`, the spline is **C¹ in t for any
/// knots** (the factor `hᵢ/3` scales the tangent per segment); it is not C² in general. For
/// uniform knots `Tᵢ` is half the difference over two steps, as in the Euclidean
/// `c′(i) = (cᵢ₊₁ − cᵢ₋₁)/2`.
///
/// **Closed loops** ([`try_new_closed`](Self::try_new_closed),
/// [`try_new_quaternion_closed`](Self::try_new_quaternion_closed)): every point is a key,
/// `c₀ … cₙ₋₁`, with knots `t₀ < … < tₙ` (the last the time of the return to `c₀`), and the
/// neighbours wrap around: `c₋₁ = cₙ₋₁`, `cₙ = c₀`, `cₙ₊₁ = c₁`, `t₋₁ = t₀ − hₙ₋₁`,
/// `tₙ₊₁ = tₙ + h₀`. The tangent at `c₀` is then the same at both ends of the domain, so the
/// loop is C¹ at the seam as at the other keys.
///
/// Keys are used as given (no sign flips besides the short-path rule of the quaternion tangent);
/// canonicalise quaternion keys with [`unflip`](crate::unflip) first.
///
/// # Examples
///
/// ```
/// use spherekit::{continuity, CatmullRom, Curve, S2Point};
/// use spherekit::glam::DVec3;
///
/// let p = |x: f64, y: f64, z: f64| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let pts = vec![p(1.0, -0.5, 0.0), S2Point::X, p(1.0, 1.0, 0.3), S2Point::Y, p(-0.5, 1.0, 0.5)];
/// let c = CatmullRom::try_new(pts, None).unwrap();
/// assert_eq!(c.domain(), [0.0, 2.0]);
/// assert_eq!(c.eval(1.0), p(1.0, 1.0, 0.3));
/// assert_eq!(c.controls().len(), 7); // c0 d0 e0 c1 d1 e1 c2
/// assert!(continuity(&c)[0].c1 < 1e-12);
/// ```
#[derive(Clone, Debug)]
pub struct CatmullRom<P: Manifold> {
    points: Vec<P>,
    closed: bool,
    knots: Knots,
    controls: Vec<P>,
    segments: Vec<CubicSegment<P>>,
}

/// The central-difference stencil of every key `c₀ … cₙ`: `(cₖ, cₖ₋₁, cₖ₊₁, tₖ₊₁ − tₖ₋₁)`.
/// Open (`points = c₋₁ … cₙ₊₁`): the end intervals are mirrored, `t₋₁ = t₀ − h₀`,
/// `tₙ₊₁ = tₙ + hₙ₋₁`. Closed (`points = c₀ … cₙ₋₁`): indices and spacings wrap around, and
/// the last key is `c₀` again.
fn stencil<'a, P>(points: &'a [P], knots: &Knots, closed: bool) -> Vec<(&'a P, &'a P, &'a P, f64)> {
    let n = knots.segment_count();
    let k = knots.as_slice();
    // t₋₁ … tₙ₊₁ with the end intervals mirrored (open curves).
    let mut ext = Vec::with_capacity(n + 3);
    ext.push(k[0] - knots.width(0));
    ext.extend_from_slice(k);
    ext.push(k[n] + knots.width(n - 1));
    (0..=n)
        .map(|k| {
            if closed {
                let (prev, next) = ((k + n - 1) % n, (k + 1) % n);
                let w = knots.width(prev) + knots.width(k % n);
                (&points[k % n], &points[prev], &points[next], w)
            } else {
                (
                    &points[k + 1],
                    &points[k],
                    &points[k + 2],
                    ext[k + 2] - ext[k],
                )
            }
        })
        .collect()
}

impl<P: Manifold> CatmullRom<P> {
    /// Builds the spline with the intrinsic central-difference tangent (any sphere).
    ///
    /// `points` are `c₋₁, c₀, …, cₙ, cₙ₊₁`; `knots` are the `n + 1` parameters of `c₀ … cₙ`.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 4 points; [`SplineError::Antipodal`] for
    /// antipodal consecutive points (index into `points`) or, in rare configurations, for
    /// antipodal derived control points of segment `i` (reported as index `i + 1`, the segment's
    /// first key); the knot errors of [`Knots::or_uniform`] (`n + 1` knots).
    pub fn try_new(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_chain(&points, 4)?;
        let knots = Knots::or_uniform(knots, points.len() - 2)?;
        Self::intrinsic(points, knots, false)
    }

    /// Builds the closed loop through the keys `points = c₀ … cₙ₋₁` (n ≥ 3) with the intrinsic
    /// tangent and periodic neighbours (type docs); `knots` are `n + 1` times, the last the
    /// time of the return to `c₀` (default `0, 1, …, n`).
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 3 points; [`SplineError::Antipodal`] for
    /// antipodal consecutive points and [`SplineError::AntipodalClosing`] for an antipodal last
    /// and first point (or, in rare configurations, for antipodal derived control points of
    /// segment `i`, reported as index `i`); the knot errors of [`Knots::or_uniform`]
    /// (`n + 1` knots).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, CatmullRom, Curve, S2Point};
    ///
    /// let c = CatmullRom::try_new_closed(vec![S2Point::X, S2Point::Y, S2Point::Z], None).unwrap();
    /// assert_eq!(c.domain(), [0.0, 3.0]);
    /// assert_eq!(c.eval(2.0), S2Point::Z);
    /// let seam = continuity(&c)[2]; // the seam at t = 3 is the last joint
    /// assert!(seam.t == 3.0 && seam.c0 < 1e-15 && seam.c1 < 1e-12);
    /// ```
    pub fn try_new_closed(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_loop(&points, MIN_LOOP_POINTS)?;
        let knots = Knots::or_uniform(knots, points.len() + 1)?;
        Self::intrinsic(points, knots, true)
    }

    /// The intrinsic construction: on `P` itself, or with the `compact` feature once on S^m for
    /// every point type ([`crate::recast`]; the same bits,
    /// `tests::the_construction_gives_the_same_bits_on_sm`). `points` is not empty.
    fn intrinsic(points: Vec<P>, knots: Knots, closed: bool) -> Result<Self, SplineError> {
        #[cfg(not(feature = "compact"))]
        return Self::construct(points, knots, closed);
        #[cfg(feature = "compact")]
        return Self::construct_on_sm(points, knots, closed);
    }

    /// [`construct`](Self::construct) on the points as points of S^m, the result converted
    /// back.
    #[cfg(any(test, feature = "compact"))]
    fn construct_on_sm(points: Vec<P>, knots: Knots, closed: bool) -> Result<Self, SplineError> {
        let to = Recast::to(&points[0]);
        let sm = points.iter().map(to_sm).collect();
        let c = CatmullRom::construct(sm, knots, closed)?;
        Ok(Self {
            points: to.points(&c.points),
            closed: c.closed,
            knots: c.knots,
            controls: to.points(&c.controls),
            segments: c.segments.iter().map(|s| s.recast(&to)).collect(),
        })
    }

    /// The intrinsic tangents `Tₖ = (log_{cₖ}(cₖ₊₁) − log_{cₖ}(cₖ₋₁))/Wₖ` and the segments.
    fn construct(points: Vec<P>, knots: Knots, closed: bool) -> Result<Self, SplineError> {
        let stencil = stencil(&points, &knots, closed);
        let keys: Vec<P> = stencil.iter().map(|s| s.0.clone()).collect();
        let tangents: Vec<P::Vector> = stencil
            .iter()
            .map(|&(c, prev, next, w)| (c.log(next) - c.log(prev)) * (1.0 / w))
            .collect();
        Self::assemble(points, keys, knots, closed, |c, k, step| {
            c.exp(&(tangents[k].clone() * step))
        })
    }

    /// Builds the segments through `keys = c₀ … cₙ` from a rule `step(c_k, k, s) = point at
    /// parameter offset s along the tangent at c_k`.
    fn assemble(
        points: Vec<P>,
        keys: Vec<P>,
        knots: Knots,
        closed: bool,
        step: impl Fn(&P, usize, f64) -> P,
    ) -> Result<Self, SplineError> {
        let n = knots.segment_count();
        let mut controls = Vec::with_capacity(3 * n + 1);
        let mut segments = Vec::with_capacity(n);
        for i in 0..n {
            let h = knots.width(i);
            let (c0, c1) = (&keys[i], &keys[i + 1]);
            let d = step(c0, i, h / 3.0);
            let e = step(c1, i + 1, -h / 3.0);
            let seg = CubicSegment::try_new([c0.clone(), d, e, c1.clone()]).map_err(|_| {
                SplineError::Antipodal {
                    index: i + usize::from(!closed),
                }
            })?;
            controls.extend_from_slice(&seg.controls()[..3]);
            segments.push(seg);
        }
        controls.push(keys[n].clone());
        Ok(Self {
            points,
            closed,
            knots,
            controls,
            segments,
        })
    }

    /// The input points: `c₋₁ … cₙ₊₁` (open), `c₀ … cₙ₋₁` (closed).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The Bézier control points of all segments, `c₀, d₀, e₀, c₁, d₁, e₁, …, cₙ` (3n + 1
    /// points; segment `i` uses entries `3i … 3i + 3`).
    #[must_use]
    pub fn controls(&self) -> &[P] {
        &self.controls
    }

    /// The knots of `c₀ … cₙ` (closed: `n + 1`, the last for the return to `c₀`).
    #[must_use]
    pub fn knots(&self) -> &Knots {
        &self.knots
    }
}

impl CatmullRom<UnitQuat> {
    /// Builds the quaternion spline with the tangent rule of Gortler (2012), §9.3:
    /// `dᵢ = Xᵢ^(hᵢ/(3Wᵢ))·cᵢ`, `eᵢ = Xᵢ₊₁^(−hᵢ/(3Wᵢ₊₁))·cᵢ₊₁` with `Xᵢ = ±cᵢ₊₁·cᵢ₋₁⁻¹` (sign
    /// making the scalar part non-negative). Arguments and errors as [`try_new`](Self::try_new).
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{CatmullRom, Curve, UnitQuat};
    /// use spherekit::glam::DVec3;
    ///
    /// // Rotations about one axis: the spline is the scalar Catmull-Rom spline of the angles.
    /// let q = |a: f64| UnitQuat::exp_pure(DVec3::Z * a);
    /// let a = [0.0, 0.1, 0.4, 0.6, 0.65];
    /// let c = CatmullRom::try_new_quaternion(a.iter().map(|&x| q(x)).collect(), None).unwrap();
    /// // Segment 0 has Bézier control angles c₀, c₀ + (c₁ − c₋₁)/6, c₁ − (c₂ − c₀)/6, c₁.
    /// let s = 0.5_f64;
    /// let v = [0.1, 0.1 + 0.4 / 6.0, 0.4 - 0.5 / 6.0, 0.4];
    /// let w = [1.0, 3.0, 3.0, 1.0];
    /// let expected: f64 = (0..4).map(|k| w[k] * s.powi(k as i32) * (1.0 - s).powi(3 - k as i32) * v[k]).sum();
    /// assert!((c.eval(0.5).as_dquat().z.atan2(c.eval(0.5).as_dquat().w) - expected).abs() < 1e-15);
    /// ```
    pub fn try_new_quaternion(
        points: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self, SplineError> {
        check_chain(&points, 4)?;
        let knots = Knots::or_uniform(knots, points.len() - 2)?;
        Self::quaternion(points, knots, false)
    }

    /// The closed loop of [`try_new_closed`](CatmullRom::try_new_closed) with the quaternion
    /// tangent rule of [`try_new_quaternion`](Self::try_new_quaternion).
    ///
    /// # Errors
    ///
    /// As [`try_new_closed`](CatmullRom::try_new_closed).
    pub fn try_new_quaternion_closed(
        points: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self, SplineError> {
        check_loop(&points, MIN_LOOP_POINTS)?;
        let knots = Knots::or_uniform(knots, points.len() + 1)?;
        Self::quaternion(points, knots, true)
    }

    /// `logs[k] = log(Xₖ)/Wₖ` with `Xₖ = ±cₖ₊₁·cₖ₋₁⁻¹` and the segments.
    fn quaternion(points: Vec<UnitQuat>, knots: Knots, closed: bool) -> Result<Self, SplineError> {
        let stencil = stencil(&points, &knots, closed);
        let keys: Vec<UnitQuat> = stencil.iter().map(|s| *s.0).collect();
        let logs: Vec<glam::DVec3> = stencil
            .iter()
            .map(|&(_, prev, next, w)| {
                let mut x = *next * prev.conjugate();
                if x.scalar() < 0.0 {
                    x = -x;
                }
                x.log_pure() * (1.0 / w)
            })
            .collect();
        Self::assemble(points, keys, knots, closed, |c, k, step| {
            UnitQuat::exp_pure(logs[k] * step) * *c
        })
    }
}

impl<P: Manifold> Curve for CatmullRom<P> {
    type Point = P;

    fn domain(&self) -> [f64; 2] {
        self.knots.domain()
    }

    fn joints(&self) -> &[f64] {
        self.knots.as_slice()
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<P> {
        let (i, tau) = self.knots.locate(t, side);
        self.segments[i].jet(ScalarJet::param(tau, 1.0 / self.knots.width(i)))
    }

    fn eval(&self, t: f64) -> P {
        let (i, tau) = self.knots.locate(t, Side::Right);
        self.segments[i].eval(tau)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.segments[i].eval(s));
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        self.knots.map_into(ts, Side::Right, out, |i, s| {
            self.segments[i].jet(ScalarJet::param(s, 1.0 / self.knots.width(i)))
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recast::keys;

    /// The `compact` build constructs on S^m and converts back; every field (and every error) must
    /// be what the construction on the point type itself gives, bit for bit (`{:?}` prints
    /// each `f64` in the shortest form that reads back to the same bits).
    #[test]
    fn the_construction_gives_the_same_bits_on_sm() {
        fn check<P: Manifold>(points: &[P]) -> usize {
            let mut built = 0;
            for closed in [false, true] {
                let checked = if closed {
                    check_loop(points, MIN_LOOP_POINTS)
                } else {
                    check_chain(points, 4)
                };
                if checked.is_err() {
                    continue;
                }
                let n = if closed {
                    points.len() + 1
                } else {
                    points.len() - 2
                };
                let uneven: Vec<f64> = (0..n).map(|i| (i * i) as f64 * 0.3 + i as f64).collect();
                for knots in [Knots::uniform(n), Knots::try_new(uneven).unwrap()] {
                    let native = CatmullRom::construct(points.to_vec(), knots.clone(), closed);
                    let on_sm = CatmullRom::construct_on_sm(points.to_vec(), knots, closed);
                    built += keys::same_bits(&native, &on_sm, &points);
                }
            }
            built
        }
        let built = keys::built(check, check);
        assert!(built > 12, "{built} curves built");
    }
}
