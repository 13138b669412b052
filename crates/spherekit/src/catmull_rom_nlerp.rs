// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The normalised ambient Catmull-Rom spline: the Euclidean Catmull-Rom curve of the points as
//! vectors of ℝ^(m+1) (ℝ⁴ for quaternions), projected back onto the sphere.

use crate::ambient::Ambient;
#[cfg(any(test, feature = "compact"))]
use crate::ambient::VecN;
use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::geodesic::{MIN_LOOP_POINTS, check_chain, check_loop};
use crate::knots::Knots;
use crate::manifold::Manifold;

/// The normalised Catmull-Rom spline `q(t) = c(t)/|c(t)|`, where `c` is the Euclidean
/// Catmull-Rom spline of the points taken as vectors of the ambient space ℝ^(m+1) (ℝ⁴ for unit
/// quaternions): the cheap C¹ quaternion spline of game engines, which Gortler (2012), §9.3
/// mentions beside the slerp construction of [`CatmullRom`](crate::CatmullRom).
///
/// The input is `c₋₁, c₀, …, cₙ, cₙ₊₁` (n + 3 points, as for [`CatmullRom`](crate::CatmullRom));
/// `c₋₁` and `cₙ₊₁` set the end tangents and are not interpolated. Knots `t₀ < … < tₙ` belong to
/// `c₀ … cₙ` (default `0, 1, …, n`). Segment `i` on `[tᵢ, tᵢ₊₁]` (width `hᵢ`,
/// `τ = (t − tᵢ)/hᵢ`) is the cubic Bézier curve of ℝ^(m+1) (Gortler (2012), §9.1–9.2,
/// eqs. (9.13)–(9.14), with the non-uniform tangents of [`CatmullRom`](crate::CatmullRom)):
///
/// ```text
/// Tᵢ = (cᵢ₊₁ − cᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁)          with t₋₁ = t₀ − h₀,  tₙ₊₁ = tₙ + hₙ₋₁
/// dᵢ = cᵢ + hᵢ·Tᵢ/3,   eᵢ = cᵢ₊₁ − hᵢ·Tᵢ₊₁/3    (uniform knots: dᵢ = cᵢ + (cᵢ₊₁ − cᵢ₋₁)/6)
/// c(τ) = (1−τ)³cᵢ + 3(1−τ)²τ dᵢ + 3(1−τ)τ² eᵢ + τ³cᵢ₊₁,        q = c/|c|
/// q′ = (c′ − q(q·c′))/|c|,   q″ = (c″ − 2q′(q·c′) − q(q′·c′ + q·c″))/|c|
/// ```
///
/// `c` is C¹ in `t` (the Euclidean Catmull-Rom property `c′(tᵢ±) = Tᵢ`), and so is `q`, since
/// the normalisation is smooth away from 0; neither is C² in general. The curve interpolates
/// `c₀ … cₙ`, but unlike the spherical constructions its **speed is not constant** on an arc
/// (it is the nlerp speed law, faster in the middle of a segment) and it **leaves the great
/// circle** through the keys whenever `cᵢ₋₁, cᵢ, cᵢ₊₁, cᵢ₊₂` are not on one great circle (it
/// stays on a great circle through keys that are, since `c(t)` stays in that plane).
///
/// Keys are used as given; canonicalise quaternion keys with [`unflip`](crate::unflip) first
/// (the normalised curve of `q` and `−q` keys is a different curve).
///
/// # Errors at construction
///
/// The normalisation needs `c(t) ≠ 0`. It is guaranteed when the four Bézier points of each
/// segment lie in the open half-space `x·(cᵢ + cᵢ₊₁) > 0` (the curve lies in their convex
/// hull); a segment whose control points do not is rejected with
/// [`SplineError::ThroughOrigin`] (it happens only for keys more than about a half turn apart).
///
/// # Examples
///
/// ```
/// use spherekit::{continuity, CatmullRomNlerp, Curve, Manifold, S2Point};
/// use spherekit::glam::DVec3;
///
/// let p = |x: f64, y: f64, z: f64| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let pts = vec![p(1.0, -0.5, 0.0), S2Point::X, p(1.0, 1.0, 0.3), S2Point::Y, p(-0.5, 1.0, 0.5)];
/// let c = CatmullRomNlerp::try_new(pts, None).unwrap();
/// assert_eq!(c.domain(), [0.0, 2.0]);
/// assert!(c.eval(1.0).dist(&p(1.0, 1.0, 0.3)) < 1e-15);
/// assert!(continuity(&c)[0].c1 < 1e-12); // C¹ at the inner key
/// ```
#[derive(Clone, Debug)]
pub struct CatmullRomNlerp<P: Manifold> {
    points: Vec<P>,
    /// `c₋₁ … cₙ₊₁` as vectors (closed: the keys with the last before them and the first two
    /// after them).
    vectors: Vec<P::Vector>,
    knots: Knots,
    closed: bool,
    /// Per segment `hᵢ/(tᵢ₊₁ − tᵢ₋₁)` and `hᵢ/(tᵢ₊₂ − tᵢ)`.
    ratios: Vec<[f64; 2]>,
}

/// The tangent ratios `hᵢ/(tᵢ₊₁ − tᵢ₋₁)`, `hᵢ/(tᵢ₊₂ − tᵢ)` of every segment of the points
/// `vectors` (`c₋₁ … cₙ₊₁`) at `knots`, after the check that no Bézier point of a segment is on
/// the far side of the origin (normalising would pass through it).
fn ratios<V: Ambient>(
    vectors: &[V],
    knots: &Knots,
    closed: bool,
) -> Result<Vec<[f64; 2]>, SplineError> {
    let k = knots.as_slice();
    let n = k.len() - 1;
    let width = |i: usize| knots.width(i);
    // The spans tᵢ₊₁ − tᵢ₋₁ of the keys c₀ … cₙ, with the end intervals mirrored (open) or
    // the first and the last one around the seam (closed).
    let seam = width(0) + width(n - 1);
    let span = |i: usize| match i {
        _ if closed && (i == 0 || i == n) => seam,
        0 => 2.0 * width(0),
        _ if i == n => 2.0 * width(n - 1),
        _ => k[i + 1] - k[i - 1],
    };
    let mut ratios = Vec::with_capacity(n);
    for i in 0..n {
        let r = [width(i) / span(i), width(i) / span(i + 1)];
        // Bézier points cᵢ, dᵢ, eᵢ, cᵢ₊₁ from the weights at the ends (τ = 0, 1, and the
        // first derivatives there give dᵢ − cᵢ and cᵢ₊₁ − eᵢ times 3).
        let combine = |w: [f64; 4]| -> V {
            (0..4).fold(vectors[i].zeros_like(), |acc, j| {
                acc + vectors[i + j].clone() * w[j]
            })
        };
        let (w0, w1) = (weights(0.0, r), weights(1.0, r));
        let (c0, c1) = (vectors[i + 1].clone(), vectors[i + 2].clone());
        let d = c0.clone() + combine(w0[1]) * (1.0 / 3.0);
        let e = c1.clone() - combine(w1[1]) * (1.0 / 3.0);
        let m = c0.clone() + c1.clone();
        let lowest = [c0, d, e, c1]
            .iter()
            .map(|x| x.dot(&m))
            .fold(f64::INFINITY, f64::min);
        if lowest.is_nan() || lowest <= 1e-12 * m.length() {
            // The segment's keys in the points given (closed: no steering point first, and the
            // last segment returns to the first key).
            let (index, next) = if closed {
                (i, (i + 1) % n)
            } else {
                (i + 1, i + 2)
            };
            return Err(SplineError::ThroughOrigin { index, next });
        }
        ratios.push(r);
    }
    Ok(ratios)
}

/// [`ratios`] of the vectors as vectors of `VecN` (the `compact` build's one copy).
#[cfg(any(test, feature = "compact"))]
fn ratios_in_vecn<V: Ambient>(
    vectors: &[V],
    knots: &Knots,
    closed: bool,
) -> Result<Vec<[f64; 2]>, SplineError> {
    let vectors: Vec<VecN> = vectors.iter().map(|v| VecN::new(v.to_vec())).collect();
    ratios(&vectors, knots, closed)
}

/// The weights of `cᵢ₋₁, cᵢ, cᵢ₊₁, cᵢ₊₂` in `c(τ)` and their first two `τ`-derivatives, for the
/// tangent ratios `a = hᵢ/(tᵢ₊₁ − tᵢ₋₁)`, `b = hᵢ/(tᵢ₊₂ − tᵢ)` (cubic Hermite form of the Bézier
/// segment: `c = H₀₀cᵢ + H₁₀·hᵢTᵢ + H₀₁cᵢ₊₁ + H₁₁·hᵢTᵢ₊₁`). Not generic, so one copy serves
/// every sphere.
fn weights(tau: f64, [a, b]: [f64; 2]) -> [[f64; 4]; 3] {
    let (t, t2, t3) = (tau, tau * tau, tau * tau * tau);
    // H00, H10, H01, H11 and their derivatives.
    let h = [
        [
            2.0 * t3 - 3.0 * t2 + 1.0,
            t3 - 2.0 * t2 + t,
            -2.0 * t3 + 3.0 * t2,
            t3 - t2,
        ],
        [
            6.0 * t2 - 6.0 * t,
            3.0 * t2 - 4.0 * t + 1.0,
            -6.0 * t2 + 6.0 * t,
            3.0 * t2 - 2.0 * t,
        ],
        [
            12.0 * t - 6.0,
            6.0 * t - 4.0,
            -12.0 * t + 6.0,
            6.0 * t - 2.0,
        ],
    ];
    h.map(|[h00, h10, h01, h11]| [-a * h10, h00 - b * h11, h01 + a * h10, b * h11])
}

impl<P: Manifold> CatmullRomNlerp<P> {
    /// Builds the spline through `points` = `c₋₁, c₀, …, cₙ, cₙ₊₁` with knots for `c₀ … cₙ`.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 4 points; [`SplineError::Antipodal`] for
    /// antipodal consecutive points; [`SplineError::ThroughOrigin`] (index of the segment's
    /// first key in `points`) where the ambient curve could pass through 0; the knot errors of
    /// [`Knots::or_uniform`] (`n + 1` knots).
    pub fn try_new(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_chain(&points, 4)?;
        let knots = Knots::or_uniform(knots, points.len() - 2)?;
        let vectors: Vec<P::Vector> = points.iter().map(Manifold::to_vector).collect();
        Self::build(points, vectors, knots, false)
    }

    /// Builds the closed loop through `points` = `c₀ … c_{m−1}` (m ≥ 3), every point a key, at
    /// the `m + 1` knots `t₀ … t_m` (default `0, 1, …, m`; `t_m` is the time of the return to
    /// `c₀`): the open construction of the periodic sequence, `c₋₁ = c_{m−1}`, `c_m = c₀`,
    /// `c_{m+1} = c₁`, with the tangent at the seam from the knot intervals on both sides of
    /// it, `T₀ = (c₁ − c_{m−1})/(t₁ − t₀ + t_m − t_{m−1})`. C¹ at the seam as at every key.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 3 points; [`SplineError::Antipodal`] for
    /// antipodal consecutive points and [`SplineError::AntipodalClosing`] for an antipodal
    /// last and first point; [`SplineError::ThroughOrigin`] (index of the segment's first key)
    /// where the ambient curve could pass through 0; the knot errors of
    /// [`Knots::or_uniform`] (`m + 1` knots).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, CatmullRomNlerp, Curve, Manifold, S2Point};
    /// use spherekit::glam::DVec3;
    ///
    /// let p = |x: f64, y: f64, z: f64| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
    /// let ring = vec![p(1.0, 0.0, 0.5), p(0.0, 1.0, 0.5), p(-1.0, 0.0, 0.5), p(0.0, -1.0, 0.5)];
    /// let c = CatmullRomNlerp::try_new_closed(ring.clone(), None).unwrap();
    /// assert_eq!(c.domain(), [0.0, 4.0]);
    /// assert!(c.is_closed() && c.eval(4.0).dist(&ring[0]) < 1e-15);
    /// assert!(continuity(&c).iter().all(|j| j.c1 < 1e-12)); // C¹ at the seam too
    /// ```
    pub fn try_new_closed(points: Vec<P>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_loop(&points, MIN_LOOP_POINTS)?;
        let m = points.len();
        let knots = Knots::or_uniform(knots, m + 1)?;
        let mut vectors: Vec<P::Vector> = Vec::with_capacity(m + 3);
        vectors.push(points[m - 1].to_vector());
        vectors.extend(points.iter().map(Manifold::to_vector));
        vectors.push(points[0].to_vector());
        vectors.push(points[1].to_vector());
        Self::build(points, vectors, knots, true)
    }

    fn build(
        points: Vec<P>,
        vectors: Vec<P::Vector>,
        knots: Knots,
        closed: bool,
    ) -> Result<Self, SplineError> {
        // In the point type's vectors; the `compact` build checks every sphere's in `VecN`
        // (one copy of the code; the same bits, `tests::the_ratios_are_the_same_in_vecn`).
        #[cfg(not(feature = "compact"))]
        let ratios = ratios(&vectors, &knots, closed)?;
        #[cfg(feature = "compact")]
        let ratios = ratios_in_vecn(&vectors, &knots, closed)?;
        Ok(Self {
            points,
            vectors,
            knots,
            closed,
            ratios,
        })
    }

    /// The input points `c₋₁ … cₙ₊₁` (closed: the keys `c₀ … c_{m−1}`).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The knots `t₀ … tₙ` of `c₀ … cₙ`.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }

    /// `Σⱼ w[j]·scale·cᵢ₋₁₊ⱼ`: the ambient point or one of its derivatives on segment `i`.
    fn combine(&self, i: usize, w: [f64; 4], scale: f64) -> P::Vector {
        (0..4).fold(self.vectors[i].zeros_like(), |acc, j| {
            acc + self.vectors[i + j].clone() * (w[j] * scale)
        })
    }

    /// The ambient (unnormalised) point `c(t)` and its first two derivatives in `t`.
    fn ambient(&self, i: usize, tau: f64) -> [P::Vector; 3] {
        let [w0, w1, w2] = weights(tau, self.ratios[i]);
        let inv = 1.0 / self.knots.width(i);
        [
            self.combine(i, w0, 1.0),
            self.combine(i, w1, inv),
            self.combine(i, w2, inv * inv),
        ]
    }

    fn jet_local(&self, i: usize, tau: f64) -> Jet<P> {
        let [c, d1, d2] = self.ambient(i, tau);
        let r = c.length();
        let q = c * (1.0 / r);
        let r1 = q.dot(&d1);
        let q1 = (d1.clone() - q.clone() * r1) * (1.0 / r);
        let r2 = q1.dot(&d1) + q.dot(&d2);
        let q2 = (d2 - q1.clone() * (2.0 * r1) - q.clone() * r2) * (1.0 / r);
        Jet {
            point: P::from_vector_unchecked(q),
            velocity: q1,
            acceleration: q2,
        }
    }
}

impl<P: Manifold> Curve for CatmullRomNlerp<P> {
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
        self.jet_local(i, tau)
    }

    fn eval(&self, t: f64) -> P {
        let (i, tau) = self.knots.locate(t, Side::Right);
        let c = self.combine(i, weights(tau, self.ratios[i])[0], 1.0);
        let r = c.length();
        P::from_vector_unchecked(c * (1.0 / r))
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::S2Point;
    use crate::recast::keys;

    /// The `compact` build checks the segments in `VecN`; the ratios and the errors must be those of
    /// the point type's own vectors, bit for bit.
    #[test]
    fn the_ratios_are_the_same_in_vecn() {
        fn check<P: Manifold>(points: &[P]) -> [usize; 2] {
            let vectors: Vec<P::Vector> = points.iter().map(Manifold::to_vector).collect();
            let n = points.len() - 2;
            let uneven: Vec<f64> = (0..n).map(|i| (i * i) as f64 * 0.3 + i as f64).collect();
            let mut outcomes = [0, 0];
            for knots in [Knots::uniform(n), Knots::try_new(uneven).unwrap()] {
                let native = ratios(&vectors, &knots, false);
                let in_vecn = ratios_in_vecn(&vectors, &knots, false);
                outcomes[usize::from(native.is_err())] += 1;
                assert_eq!(format!("{native:?}"), format!("{in_vecn:?}"), "{points:?}");
            }
            outcomes
        }
        // Keys 100°, 170° and 110° apart: the ambient curve passes within 0.02 of the origin.
        let on_equator = |deg: f64| {
            let a = deg.to_radians();
            S2Point::try_new(DVec3::new(a.cos(), a.sin(), 0.0)).unwrap()
        };
        let through: Vec<S2Point> = [100.0, 0.0, 170.0, 60.0].map(on_equator).to_vec();
        let mut outcomes = [0, 0];
        for [ok, err] in keys::on_s2()
            .iter()
            .chain([&through])
            .map(|p| check(p))
            .chain(keys::on_s3().iter().map(|p| check(p)))
        {
            outcomes[0] += ok;
            outcomes[1] += err;
        }
        assert!(
            outcomes[0] >= 8 && outcomes[1] >= 2,
            "built {}, through the origin {}",
            outcomes[0],
            outcomes[1]
        );
    }
}
