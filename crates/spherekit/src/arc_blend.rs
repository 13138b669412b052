// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's interpolating Cⁿ spline: blending of circle arcs through consecutive triples.

use crate::ambient::Ambient;
use crate::circle::{COINCIDENT_TOLERANCE, CircleArc};
use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::flow::{PlaneRotation, Segment, Weights};
use crate::knots::Knots;
use crate::manifold::{Manifold, renormalize};
use crate::smoothing::SmoothingPolynomials;

/// The largest continuity order accepted by the spline constructors.
pub const MAX_BLEND_ORDER: usize = 10;

/// Checks `1 ≤ order ≤ MAX_BLEND_ORDER`.
pub(crate) fn check_order(order: usize) -> Result<SmoothingPolynomials, SplineError> {
    if order == 0 || order > MAX_BLEND_ORDER {
        return Err(SplineError::InvalidParameter {
            name: "order",
            reason: format!("must be an integer from 1 to {MAX_BLEND_ORDER}, got {order}"),
        });
    }
    SmoothingPolynomials::try_new(order)
}

/// Checks the point count and that consecutive points are neither coincident nor antipodal.
pub(crate) fn check_neighbours<P: Manifold>(points: &[P], min: usize) -> Result<(), SplineError> {
    if points.len() < min {
        return Err(SplineError::TooFewPoints {
            min,
            got: points.len(),
        });
    }
    for (index, w) in points.windows(2).enumerate() {
        let (p, q) = (w[0].to_vector(), w[1].to_vector());
        if (q.clone() - p.clone()).length() <= COINCIDENT_TOLERANCE {
            return Err(SplineError::Coincident { index });
        }
        if w[0].is_antipodal(&w[1]) {
            return Err(SplineError::Antipodal { index });
        }
    }
    Ok(())
}

/// Pobegailo's interpolating Cⁿ spline through points `p₀, …, p_k` (`k ≥ 2`) of a sphere,
/// blending the circle arcs through consecutive triples.
///
/// Source: the monograph (seed 002) §7.10, §8.4 (Algorithm 8.1) and §9.4 (Algorithm 9.1); spec
/// `pobegailo-s2.md` §7 (Algorithm A) and `pobegailo-s3.md` Algorithm 5. For triple
/// `j = 0…k−2` let `𝒢_j` be the rotation group of the circle through `p_j, p_{j+1}, p_{j+2}`
/// ([`CircleArc`]), with central angles `φ_j` (`p_j → p_{j+1}`) and `ψ_j` (`p_{j+1} → p_{j+2}`).
/// With `u = (t − t_i)/(t_{i+1} − t_i)`:
///
/// ```text
/// knots:       t₀ = 0,  t₁ = φ₀,  t_{i+1} = t_i + (ψ_{i−1}/φ_{i−1})·(t_i − t_{i−1})
/// segment 0:   r(t) = 𝒢₀(u·φ₀) p₀
/// segment i:   r(t) = 𝒢_i(w₁,ₙ(u)·φ_i) · 𝒢_{i−1}(w₂,ₙ(u)·ψ_{i−1}) · p_i      (1 ≤ i ≤ k−2)
/// segment k−1: r(t) = 𝒢_{k−2}(u·ψ_{k−2}) p_{k−1}
/// ```
///
/// The end follower (circle `i`, weight `w₁`) is the left factor and the start follower (circle
/// `i−1`, weight `w₂`) acts first. The knot rule makes the two arcs of circle `i−1` that meet at
/// `p_i` turn at the same angular speed, so the curve is **Cⁿ** at every knot (and in general not
/// Cⁿ⁺¹); between knots it is analytic. Derivatives are exact.
///
/// Properties: interpolation `r(t_i) = p_i`; points on one circle (in order) give back that
/// circle at unit angular speed; three points give the single arc; equivariant under
/// orthogonal maps of the ambient space (with identical knots); shape-local (segment `i` depends
/// on `p_{i−1} … p_{i+2}`), while the knot spacing carries the ratios `ψ_j/φ_j` forward.
///
/// On S² ([`S2Point`](crate::S2Point)) `𝒢_j = R(â_j, ·)`, the rotation about the circle's axis.
/// On S³ ([`UnitQuat`](crate::UnitQuat)) `𝒢_j` is the simple rotation of ℝ⁴ in the circle's
/// plane: the frame-consistent form that `pobegailo-s3.md` makes normative **\[D\]**. The book's
/// literal Procedure 9.4 applies circle `i−1`'s rotation in circle `i`'s frame and is only C⁰
/// (A-18). Keys are used as given (no sign flips): the spline interpolates these points of S³.
/// The same construction works on S^m ([`SnPoint`](crate::SnPoint)).
///
/// Readings of the book followed here (spec §13 items 12–17 of `pobegailo-s2.md`, A-10, A-11,
/// A-19 of `pobegailo-s3.md`): the forward circle carries `w₁` **\[I\]**; the triple of axis `j` is
/// `(p_j, p_{j+1}, p_{j+2})` **\[I\]**; knots by Algorithm 8.1 (the §7.10 recurrence is shifted by
/// one index) also on S³, where the book gives none; `k = 2` builds no blended segment.
///
/// Antipodal neighbours are rejected (on S³ they are the same orientation); the spec allows them
/// on S², where the circle through them is a great circle.
///
/// # Examples
///
/// ```
/// use spherekit::{ArcBlend, Curve, Manifold, S2Point, Side, glam::DVec3};
///
/// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let points = vec![p(1.0, 0.0, 0.3), p(0.6, 0.8, 0.4), p(-0.2, 1.0, 0.1), p(-0.9, 0.3, -0.2)];
/// let curve = ArcBlend::try_new(points.clone(), 2).unwrap();
/// let knots = curve.knots().to_vec();
/// assert_eq!(curve.domain(), [0.0, knots[3]]);
/// for (t, q) in knots.iter().zip(&points) {
///     assert!(curve.eval(*t).dist(q) < 1e-14); // interpolates
/// }
/// // C² at the joints.
/// let (l, r) = (curve.jet_at(knots[2], Side::Left), curve.jet_at(knots[2], Side::Right));
/// assert!((l.velocity - r.velocity).length() < 1e-12);
/// assert!((l.acceleration - r.acceleration).length() < 1e-11);
/// ```
#[derive(Clone, Debug)]
pub struct ArcBlend<P: Manifold> {
    points: Vec<P>,
    knots: Knots,
    poly: SmoothingPolynomials,
    circles: Vec<CircleArc<P>>,
    segments: Vec<Segment<P::Vector, PlaneRotation<P::Vector>>>,
}

impl<P: Manifold> ArcBlend<P> {
    /// The default continuity order (C²).
    pub const DEFAULT_ORDER: usize = 2;

    /// Builds the Cⁿ spline (`n = order`) through `points`, with knots starting at 0.
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 3 points;
    /// - [`SplineError::InvalidParameter`] (`order`) unless `1 ≤ order ≤ 10`;
    /// - [`SplineError::Coincident`] for equal consecutive points;
    /// - [`SplineError::Antipodal`] for antipodal consecutive points;
    /// - [`SplineError::NoCircle`] when `p_j = p_{j+2}` (no unique circle through the triple);
    /// - [`SplineError::KnotsNotIncreasing`] / [`SplineError::InvalidKnot`] if the knot ratios
    ///   overflow or underflow `f64` (extreme data).
    pub fn try_new(points: Vec<P>, order: usize) -> Result<Self, SplineError> {
        check_neighbours(&points, 3)?;
        let poly = check_order(order)?;
        let circles = points
            .windows(3)
            .enumerate()
            .map(|(j, w)| {
                CircleArc::through(&w[0], &w[1], &w[2]).map_err(|e| match e {
                    SplineError::Coincident { index } => {
                        SplineError::Coincident { index: j + index }
                    }
                    SplineError::NoCircle { index } => SplineError::NoCircle { index: j + index },
                    e => e,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let k = points.len() - 1;
        // Durations Δ_i: Δ₀ = φ₀, Δ_i = Δ_{i−1}·ψ_{i−1}/φ_{i−1}.
        let mut widths = Vec::with_capacity(k);
        widths.push(circles[0].first_angle());
        for i in 1..k {
            let c = &circles[i - 1];
            widths.push(widths[i - 1] * (c.second_angle() / c.first_angle()));
        }
        let mut t = Vec::with_capacity(k + 1);
        t.push(0.0);
        for (i, w) in widths.iter().enumerate() {
            t.push(t[i] + w);
        }
        let knots = Knots::try_new(t)?;
        let segments = (0..k)
            .map(|i| {
                let width = knots.width(i);
                if i == 0 {
                    Segment {
                        base: points[0].to_vector(),
                        outer: circles[0].flow().clone(),
                        outer_angle: circles[0].first_angle(),
                        inner: None,
                        weights: Weights::Linear,
                        width,
                    }
                } else if i == k - 1 {
                    let c = &circles[k - 2];
                    Segment {
                        base: points[k - 1].to_vector(),
                        outer: c.flow().clone(),
                        outer_angle: c.second_angle(),
                        inner: None,
                        weights: Weights::Linear,
                        width,
                    }
                } else {
                    let (c, prev) = (&circles[i], &circles[i - 1]);
                    Segment {
                        base: points[i].to_vector(),
                        outer: c.flow().clone(),
                        outer_angle: c.first_angle(),
                        inner: Some((prev.flow().clone(), prev.second_angle())),
                        weights: Weights::ArcBlend,
                        width,
                    }
                }
            })
            .collect();
        Ok(Self {
            points,
            knots,
            poly,
            circles,
            segments,
        })
    }

    /// The interpolated points.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The knots `t₀ = 0 < t₁ = φ₀ < … < t_k` where the curve passes the points.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }

    /// The continuity order `n`.
    #[must_use]
    pub fn order(&self) -> usize {
        self.poly.order()
    }

    /// The derivatives of orders `0…=order` at `t` with respect to `t` (ambient vectors; order 0
    /// is the point), exactly, for any order; at a joint the one-sided values from `side`.
    /// Used to check continuity beyond the second derivative of [`Curve::jet_at`].
    #[must_use]
    pub fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<P::Vector> {
        let (i, s) = self.knots.locate(t, side);
        self.segments[i].derivatives(self.poly, s, order)
    }

    /// The circles through the consecutive triples `(p_j, p_{j+1}, p_{j+2})`.
    #[must_use]
    pub fn circles(&self) -> &[CircleArc<P>] {
        &self.circles
    }
}

impl<P: Manifold> Curve for ArcBlend<P> {
    type Point = P;

    fn domain(&self) -> [f64; 2] {
        self.knots.domain()
    }

    fn joints(&self) -> &[f64] {
        self.knots.as_slice()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<P> {
        let (i, s) = self.knots.locate(t, side);
        self.jet_local(i, s)
    }

    fn eval(&self, t: f64) -> P {
        let (i, s) = self.knots.locate(t, Side::Right);
        self.eval_local(i, s)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.eval_local(i, s));
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.jet_local(i, s));
    }
}

impl<P: Manifold> ArcBlend<P> {
    fn jet_local(&self, i: usize, s: f64) -> Jet<P> {
        let (p, velocity, acceleration) = self.segments[i].jet(self.poly, s);
        let point = if s == 0.0 {
            self.points[i].clone()
        } else if s == 1.0 {
            self.points[i + 1].clone()
        } else {
            P::from_vector_unchecked(renormalize(p))
        };
        Jet {
            point,
            velocity,
            acceleration,
        }
    }

    fn eval_local(&self, i: usize, s: f64) -> P {
        if s == 0.0 {
            return self.points[i].clone();
        }
        if s == 1.0 {
            return self.points[i + 1].clone();
        }
        P::from_vector_unchecked(renormalize(self.segments[i].point(self.poly, s)))
    }
}
