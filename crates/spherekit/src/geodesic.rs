// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The piecewise geodesic (slerp) and piecewise normalised-linear (nlerp) curves through points.

use crate::ambient::Ambient;
use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::knots::Knots;
use crate::manifold::{Manifold, geodesic_frame, renormalize};
#[cfg(any(test, feature = "compact"))]
use crate::recast::{Recast, to_sm};

/// Checks that there are at least `min` points and no antipodal neighbours.
pub(crate) fn check_chain<P: Manifold>(points: &[P], min: usize) -> Result<(), SplineError> {
    if points.len() < min {
        return Err(SplineError::TooFewPoints {
            min,
            got: points.len(),
        });
    }
    match points.windows(2).position(|w| w[0].is_antipodal(&w[1])) {
        Some(index) => Err(SplineError::Antipodal { index }),
        None => Ok(()),
    }
}

/// The fewest points of a closed loop (two points would make a loop that doubles back on
/// itself).
pub(crate) const MIN_LOOP_POINTS: usize = 3;

/// Checks a closed loop: at least `min` points, no antipodal neighbours, and the last point not
/// antipodal to the first ([`SplineError::AntipodalClosing`]).
pub(crate) fn check_loop<P: Manifold>(points: &[P], min: usize) -> Result<(), SplineError> {
    check_chain(points, min.max(MIN_LOOP_POINTS))?;
    if points[points.len() - 1].is_antipodal(&points[0]) {
        return Err(SplineError::AntipodalClosing);
    }
    Ok(())
}

/// `p₀ … pₙ₋₁, p₀`: the points of a closed loop with the first repeated at the end.
pub(crate) fn wrapped<P: Clone>(points: &[P]) -> Vec<P> {
    let mut out = Vec::with_capacity(points.len() + 1);
    out.extend_from_slice(points);
    out.push(points[0].clone());
    out
}

/// One great-circle arc `cos(sθ)·p + sin(sθ)·e`, `s ∈ [0, 1]`, stored with its angular rate.
#[derive(Clone, Debug)]
struct Arc<V> {
    start: V,
    /// Unit tangent at `start` towards the end (zero for a zero-length arc).
    direction: V,
    theta: f64,
    /// `θ / h`: radians per unit of the global parameter.
    rate: f64,
}

/// The piecewise geodesic through points `p₀ … pₙ` at knots `u₀ < … < uₙ` (spherical linear
/// interpolation between consecutive points).
///
/// On `[uᵢ, uᵢ₊₁]`, with `s = (t − uᵢ)/hᵢ`, `θᵢ = ∠(pᵢ, pᵢ₊₁)` and `eᵢ` the unit tangent at `pᵢ`
/// towards `pᵢ₊₁`:
///
/// ```text
/// c(t)  = cos(sθᵢ)·pᵢ + sin(sθᵢ)·eᵢ   = slerp(pᵢ, pᵢ₊₁; s)
/// c′(t) = (θᵢ/hᵢ)·(−sin(sθᵢ)·pᵢ + cos(sθᵢ)·eᵢ)
/// c″(t) = −(θᵢ/hᵢ)²·c(t)
/// ```
///
/// Each piece has constant speed θᵢ/hᵢ; the curve is C⁰ at the knots. The closed loop
/// ([`try_new_closed`](Self::try_new_closed)) has one more piece, from `pₙ` back to `p₀` on
/// `[uₙ, uₙ₊₁]`, and is C⁰ at the seam too. On S³ the keys are used
/// as given (no sign flips): canonicalise them first with [`unflip`](crate::unflip) for the
/// shortest rotations. Works on any sphere ([`S2Point`](crate::S2Point),
/// [`UnitQuat`](crate::UnitQuat), [`SmPoint`](crate::SmPoint)).
///
/// # Examples
///
/// ```
/// use spherekit::{Curve, GeodesicSpline, Manifold, S2Point};
///
/// let c = GeodesicSpline::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z], None).unwrap();
/// assert_eq!(c.domain(), [0.0, 2.0]);
/// assert_eq!(c.eval(1.0), S2Point::Y);
/// // Constant speed: a quarter of the first arc at t = 0.25.
/// let d = S2Point::X.dist(&c.eval(0.25));
/// assert!((d - core::f64::consts::FRAC_PI_8).abs() < 1e-15);
/// ```
#[derive(Clone, Debug)]
pub struct GeodesicSpline<P: Manifold> {
    /// The points, and for a closed loop the first one again at the end.
    points: Vec<P>,
    knots: Knots,
    arcs: Vec<Arc<P::Vector>>,
    closed: bool,
}

impl<P: Manifold> GeodesicSpline<P> {
    /// Builds the curve; `knots` defaults to `0, 1, …, n`.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 2 points, [`SplineError::Antipodal`] for
    /// antipodal neighbours, and the knot errors of [`Knots::or_uniform`].
    pub fn try_new(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_chain(&points, 2)?;
        let knots = Knots::or_uniform(knots, points.len())?;
        Self::build(points, knots, false)
    }

    /// Builds the closed loop `p₀ → p₁ → … → pₙ → p₀`; `knots` are `n + 2` times, one per
    /// point and the last the time of the return to `p₀` (default `0, 1, …, n + 1`).
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 3 points, [`SplineError::Antipodal`] for
    /// antipodal neighbours, [`SplineError::AntipodalClosing`] for an antipodal last and first
    /// point, and the knot errors of [`Knots::or_uniform`] (`points.len() + 1` knots).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{Curve, GeodesicSpline, S2Point};
    ///
    /// let c = GeodesicSpline::try_new_closed(vec![S2Point::X, S2Point::Y, S2Point::Z], None).unwrap();
    /// assert_eq!(c.domain(), [0.0, 3.0]);
    /// assert_eq!(c.eval(3.0), S2Point::X);
    /// assert!(c.is_closed());
    /// ```
    pub fn try_new_closed(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_loop(&points, MIN_LOOP_POINTS)?;
        let knots = Knots::or_uniform(knots, points.len() + 1)?;
        Self::build(wrapped(&points), knots, true)
    }

    /// The arcs between consecutive `points` (the loop's already wrapped; at least two):
    /// on `P` itself, or with the `compact` feature once on S^m for every point type
    /// ([`crate::recast`]; the same bits, `tests::the_construction_gives_the_same_bits_on_sm`).
    fn build(points: Vec<P>, knots: Knots, closed: bool) -> Result<Self, SplineError> {
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
        let c = GeodesicSpline::construct(sm, knots, closed)?;
        Ok(Self {
            points: to.points(&c.points),
            knots: c.knots,
            arcs: c
                .arcs
                .iter()
                .map(|a| Arc {
                    start: to.vector(&a.start),
                    direction: to.vector(&a.direction),
                    theta: a.theta,
                    rate: a.rate,
                })
                .collect(),
            closed: c.closed,
        })
    }

    /// The construction of [`build`](Self::build) on `P`.
    fn construct(points: Vec<P>, knots: Knots, closed: bool) -> Result<Self, SplineError> {
        let last = points.len() - 2;
        let arcs = points
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let start = w[0].to_vector();
                let (theta, direction) =
                    geodesic_frame(&start, &w[1].to_vector()).ok_or(if closed && i == last {
                        SplineError::AntipodalClosing
                    } else {
                        SplineError::Antipodal { index: i }
                    })?;
                Ok(Arc {
                    start,
                    direction,
                    theta,
                    rate: theta / knots.width(i),
                })
            })
            .collect::<Result<_, SplineError>>()?;
        Ok(Self {
            points,
            knots,
            arcs,
            closed,
        })
    }

    /// The points interpolated at the knots (for a closed loop without the repeated first one).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points[..self.points.len() - usize::from(self.closed)]
    }

    /// The knots (for a closed loop, one more than points: the time of the return to `p₀`).
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }
}

crate::curve::piecewise_curve! {
    impl [P: Manifold] for GeodesicSpline<P> {
        type Point = P;
    }
}

impl<P: Manifold> GeodesicSpline<P> {
    fn jet_local(&self, i: usize, s: f64) -> Jet<P> {
        let arc = &self.arcs[i];
        // `slerp(pᵢ, pᵢ₊₁, s)` from the precomputed frame: the same operations, bit for bit,
        // without recomputing the frame, and one `sin_cos` for the point and the velocity.
        let (sn, cs) = crate::math::sin_cos(s * arc.theta);
        let point = if s == 1.0 {
            self.points[i + 1].clone()
        } else if s == 0.0 {
            self.points[i].clone()
        } else {
            P::from_vector_unchecked(renormalize(
                arc.start.clone() * cs + arc.direction.clone() * sn,
            ))
        };
        let velocity = (arc.direction.clone() * cs - arc.start.clone() * sn) * arc.rate;
        let acceleration = point.to_vector() * -(arc.rate * arc.rate);
        Jet {
            point,
            velocity,
            acceleration,
        }
    }

    /// `slerp(pᵢ, pᵢ₊₁, s)` from the precomputed frame (bit for bit the same as
    /// [`Manifold::try_slerp`], which computes this frame and then this combination).
    fn eval_local(&self, i: usize, s: f64) -> P {
        if s == 1.0 {
            return self.points[i + 1].clone();
        }
        if s == 0.0 {
            return self.points[i].clone();
        }
        let arc = &self.arcs[i];
        let (sn, cs) = crate::math::sin_cos(s * arc.theta);
        P::from_vector_unchecked(renormalize(
            arc.start.clone() * cs + arc.direction.clone() * sn,
        ))
    }
}

/// The piecewise normalised-linear curve (nlerp) through points `p₀ … pₙ` at knots
/// `u₀ < … < uₙ`.
///
/// On `[uᵢ, uᵢ₊₁]`, with `s = (t − uᵢ)/hᵢ`, `v(t) = (1 − s)·pᵢ + s·pᵢ₊₁` and `n = |v|`:
///
/// ```text
/// c(t)  = v / n
/// c′(t) = (v′ − c·n′)/n,           v′ = (pᵢ₊₁ − pᵢ)/hᵢ,  n′ = c·v′
/// c″(t) = −(n″·c + 2n′·c′)/n,      n″ = c′·v′
/// ```
///
/// It traces the same great-circle arcs as [`GeodesicSpline`] but not at constant speed: it is
/// fastest at the middle of each piece. Cheap, and a common baseline in animation.
///
/// # Examples
///
/// ```
/// use spherekit::{Curve, Manifold, NlerpSpline, S2Point};
///
/// let c = NlerpSpline::try_new(vec![S2Point::X, S2Point::Y], None).unwrap();
/// let mid = c.eval(0.5).as_dvec3();
/// assert!((mid.x - mid.y).abs() < 1e-15 && mid.z == 0.0);
/// // Faster in the middle than at the ends.
/// assert!(c.jet(0.5).velocity.length() > c.jet(0.0).velocity.length());
/// ```
#[derive(Clone, Debug)]
pub struct NlerpSpline<P: Manifold> {
    /// The points, and for a closed loop the first one again at the end.
    points: Vec<P>,
    knots: Knots,
    closed: bool,
}

impl<P: Manifold> NlerpSpline<P> {
    /// Builds the curve; `knots` defaults to `0, 1, …, n`.
    ///
    /// # Errors
    ///
    /// As [`GeodesicSpline::try_new`] (antipodal neighbours would pass through the origin).
    pub fn try_new(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_chain(&points, 2)?;
        let knots = Knots::or_uniform(knots, points.len())?;
        Ok(Self {
            points,
            knots,
            closed: false,
        })
    }

    /// Builds the closed loop `p₀ → … → pₙ → p₀`, with knots as
    /// [`GeodesicSpline::try_new_closed`] (C⁰ at the seam, like the other joints).
    ///
    /// # Errors
    ///
    /// As [`GeodesicSpline::try_new_closed`].
    pub fn try_new_closed(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_loop(&points, MIN_LOOP_POINTS)?;
        let knots = Knots::or_uniform(knots, points.len() + 1)?;
        Ok(Self {
            points: wrapped(&points),
            knots,
            closed: true,
        })
    }

    /// The points interpolated at the knots (for a closed loop without the repeated first one).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points[..self.points.len() - usize::from(self.closed)]
    }

    /// The knots (for a closed loop, one more than points).
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }
}

impl<P: Manifold> Curve for NlerpSpline<P> {
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
        let (i, s) = self.knots.locate(t, side);
        self.jet_local(i, s)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.jet_local(i, s).point);
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.jet_local(i, s));
    }
}

impl<P: Manifold> NlerpSpline<P> {
    fn jet_local(&self, i: usize, s: f64) -> Jet<P> {
        let (a, b) = (self.points[i].to_vector(), self.points[i + 1].to_vector());
        let v = a.clone() * (1.0 - s) + b.clone() * s;
        let dv = (b - a) * (1.0 / self.knots.width(i));
        let n = v.length();
        let c = v * (1.0 / n);
        let dn = c.dot(&dv);
        let dc = (dv.clone() - c.clone() * dn) * (1.0 / n);
        let ddn = dc.dot(&dv);
        let ddc = (c.clone() * ddn + dc.clone() * (2.0 * dn)) * (-1.0 / n);
        let point = if s == 0.0 {
            self.points[i].clone()
        } else if s == 1.0 {
            self.points[i + 1].clone()
        } else {
            P::from_vector_unchecked(c)
        };
        Jet {
            point,
            velocity: dc,
            acceleration: ddc,
        }
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
                let points = if closed {
                    wrapped(points)
                } else {
                    points.to_vec()
                };
                let n = points.len();
                let uneven: Vec<f64> = (0..n).map(|i| (i * i) as f64 * 0.3 + i as f64).collect();
                for knots in [Knots::uniform(n), Knots::try_new(uneven).unwrap()] {
                    let native = GeodesicSpline::construct(points.clone(), knots.clone(), closed);
                    let on_sm = GeodesicSpline::construct_on_sm(points.clone(), knots, closed);
                    built += keys::same_bits(&native, &on_sm, &points);
                }
            }
            built
        }
        let built = keys::built(check, check);
        assert!(built > 30, "{built} curves built");
    }
}
