// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's corner smoothing of a great-circle polyline.

use glam::{DQuat, DVec4};

use crate::ambient::Ambient;
use crate::arc_blend::{check_loop_neighbours, check_neighbours, check_order};
use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::flow::{Flow, LeftMultiplication, PlaneRotation, Segment, Weights};
use crate::knots::Knots;
use crate::manifold::{Manifold, geodesic_frame, renormalize};
use crate::s3::UnitQuat;
use crate::smoothing::SmoothingPolynomials;

/// The default part of each edge used by a corner blend.
pub const DEFAULT_CORNER_FRACTION: f64 = 0.25;

/// The shared construction: edges `j` given by a flow whose orbit through `P_j` is the edge and
/// its angle `Θ_j` in the flow's parameter.
#[derive(Clone, Debug)]
struct CornerCore<V, F> {
    closed: bool,
    knots: Knots,
    poly: SmoothingPolynomials,
    fraction: f64,
    segments: Vec<Segment<V, F>>,
}

fn check_fraction(fraction: f64) -> Result<(), SplineError> {
    if fraction > 0.0 && fraction <= 0.5 {
        Ok(())
    } else {
        Err(SplineError::InvalidParameter {
            name: "fraction",
            reason: format!("must be in (0, 0.5], got {fraction}"),
        })
    }
}

/// The vertices `vs` as ambient vectors, for a closed polygon with the first repeated at the
/// end, after the checks of an open or closed polyline.
fn polyline<P: Manifold>(points: &[P], closed: bool) -> Result<Vec<P::Vector>, SplineError> {
    if closed {
        check_loop_neighbours(points, 3)?;
    } else {
        check_neighbours(points, 3)?;
    }
    let mut vs: Vec<P::Vector> = points.iter().map(Manifold::to_vector).collect();
    if closed {
        vs.push(vs[0].clone());
    }
    Ok(vs)
}

/// The errors of edge `index` of `edges` edges: the closing edge of a loop has its own.
fn edge_error(index: usize, edges: usize, closed: bool, antipodal: bool) -> SplineError {
    match (closed && index + 1 == edges, antipodal) {
        (true, true) => SplineError::AntipodalClosing,
        (true, false) => SplineError::CoincidentClosing,
        (false, true) => SplineError::Antipodal { index },
        (false, false) => SplineError::Coincident { index },
    }
}

impl<V: Ambient, F: Flow<V>> CornerCore<V, F> {
    /// `points` are the polyline's vertices `P_0 … P_M` (a closed polygon's with `P_M = P_0`),
    /// `edges[j]` the flow and angle of edge `P_j → P_{j+1}`.
    ///
    /// Open: the straight part of edge 0 from `P_0`, corner 1, …, the straight part of the last
    /// edge to `P_M`. Closed: a corner at every vertex, the curve starting where the corner at
    /// `P_0` ends on edge 0 (the cut `Q_0⁺`) and returning there after the corner at `P_0`; the
    /// speed factor `ω` is multiplied by `β_j/α_j = Θ_j/Θ_{j−1}` at each corner, a product that
    /// telescopes to 1 around the loop, so the seam is traversed at the speed it starts with.
    fn build(
        points: &[V],
        edges: Vec<(F, f64)>,
        order: usize,
        fraction: f64,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let poly = check_order(order)?;
        check_fraction(fraction)?;
        let m = edges.len();
        let mut segments = Vec::with_capacity(2 * m);
        let mut t = vec![0.0];
        let mut omega = 1.0;
        let mut push = |segment: Segment<V, F>, t: &mut Vec<f64>| {
            let last = t[t.len() - 1];
            t.push(last + segment.width);
            segments.push(segment);
        };
        for (j, (flow, theta)) in edges.iter().enumerate() {
            // Straight part of edge j: from Q_j⁺ (or P_0) to Q_{j+1}⁻ (or P_M).
            let (cut_start, straight) = if closed {
                (fraction * theta, (1.0 - 2.0 * fraction) * theta)
            } else if j == 0 {
                (0.0, (1.0 - fraction) * theta)
            } else if j + 1 == m {
                (fraction * theta, (1.0 - fraction) * theta)
            } else {
                (fraction * theta, (1.0 - 2.0 * fraction) * theta)
            };
            if straight > 0.0 {
                push(
                    Segment {
                        base: flow.apply(cut_start, &points[j]),
                        outer: flow.clone(),
                        outer_angle: straight,
                        inner: None,
                        weights: Weights::Linear,
                        width: straight / omega,
                    },
                    &mut t,
                );
            }
            if closed || j + 1 < m {
                // Corner at P_{j+1}: α = incoming cut on edge j, β = outgoing cut on edge j+1.
                let (next, next_theta) = &edges[(j + 1) % m];
                let alpha = fraction * theta;
                let beta = fraction * next_theta;
                push(
                    Segment {
                        base: points[j + 1].clone(),
                        outer: next.clone(),
                        outer_angle: beta,
                        inner: Some((flow.clone(), alpha)),
                        weights: Weights::Corner,
                        width: alpha / omega,
                    },
                    &mut t,
                );
                omega *= beta / alpha;
            }
        }
        let knots = Knots::try_new(t)?;
        // Use the exact knot widths so that u = (t − t_i)/width is consistent with `locate`.
        for (i, s) in segments.iter_mut().enumerate() {
            s.width = knots.width(i);
        }
        Ok(Self {
            closed,
            knots,
            poly,
            fraction,
            segments,
        })
    }

    fn jet(&self, t: f64, side: Side) -> (V, V, V) {
        let (i, s) = self.knots.locate(t, side);
        let (p, d1, d2) = self.segments[i].jet(self.poly, s);
        (renormalize(p), d1, d2)
    }

    fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<V> {
        let (i, s) = self.knots.locate(t, side);
        self.segments[i].derivatives(self.poly, s, order)
    }

    fn point(&self, t: f64) -> V {
        let (i, s) = self.knots.locate(t, Side::Right);
        renormalize(self.segments[i].point(self.poly, s))
    }

    /// `point` at each of `ts`, mapped by `f`, without a search for sorted parameters.
    fn points_into<P>(&self, ts: &[f64], out: &mut [P], f: impl Fn(V) -> P) {
        self.knots.map_into(ts, Side::Right, out, |i, s| {
            f(renormalize(self.segments[i].point(self.poly, s)))
        });
    }

    /// `jet` (right-sided) at each of `ts`, mapped by `f`.
    fn jets_into<P>(&self, ts: &[f64], out: &mut [P], f: impl Fn((V, V, V)) -> P) {
        self.knots.map_into(ts, Side::Right, out, |i, s| {
            let (p, d1, d2) = self.segments[i].jet(self.poly, s);
            f((renormalize(p), d1, d2))
        });
    }
}

/// Pobegailo's Cⁿ corner smoothing of the great-circle polyline `P₀ → P₁ → … → P_M` on a sphere,
/// with simple rotations (the S² construction; also valid on S³ and S^m).
///
/// Source: Pobegailo (2019), §8.5–8.8 (eqs. (8.19)–(8.22), Algorithm 8.2), extended to several
/// corners (the book treats one; `docs/derivations.md#pobegailo-corners`). Edge `j` is the minor
/// great-circle arc `P_j → P_{j+1}` with angle `Θ_j` and rotation group `R_j` (`R(ê_j, ·)` on S²).
/// Each interior vertex `P_j` gets a corner blend that starts
/// `α_j = f·Θ_{j−1}` before it and ends `β_j = f·Θ_j` after it (`f = fraction`):
///
/// ```text
/// corner j:  r(u) = R_j(w₁,ₙ(u)·β_j) · R_{j−1}(−w₁,ₙ(1 − u)·α_j) · P_j        (8.19)
/// edges:     r(u) = R_j(u·γ) Q,  the great-circle arcs between the corner blends
/// durations: an arc of angle γ lasts γ/ω; corner j lasts α_j/ω and sets ω ← ω·β_j/α_j; ω₀ = 1
/// ```
///
/// The curve starts at `P₀` at unit angular speed, follows the polyline's arcs **exactly**
/// outside the corner blends, and is **Cⁿ** everywhere (generically not Cⁿ⁺¹ at the junctions).
/// With `f = 0.5` consecutive corner blends meet directly. The corner blend does not in general
/// pass through `P_j`; for a straight vertex (continuing on the same great circle) it does.
///
/// **Correction** (`docs/derivations.md#pobegailo-8-21`). The printed (8.21) applies the
/// rotations to the cut point `Q₁`; the
/// corner segment then misses `Q₁` and `Q₂`. The corner point `P_j` is used, as in (8.19).
/// The inner weight is `w₁,ₙ(1 − u)`, not `w₂,ₙ(u)`.
///
/// # Examples
///
/// ```
/// use spherekit::{CornerBlend, Curve, Manifold, S2Point, Side};
///
/// let pts = vec![S2Point::X, S2Point::Y, S2Point::Z];
/// let c = CornerBlend::try_new(pts, 2, 0.25).unwrap();
/// let k = c.knots().to_vec();
/// let pi = core::f64::consts::PI;
/// // Unit angular speed: knots 0, 3π/8, π/2, 7π/8 for a 90° corner with fraction ¼.
/// assert!((k[1] - 3.0 * pi / 8.0).abs() < 1e-15 && (k[3] - 7.0 * pi / 8.0).abs() < 1e-15);
/// assert!(c.eval(k[0]).dist(&S2Point::X) < 1e-15 && c.eval(k[3]).dist(&S2Point::Z) < 1e-15);
/// let (l, r) = (c.jet_at(k[2], Side::Left), c.jet_at(k[2], Side::Right));
/// assert!((l.acceleration - r.acceleration).length() < 1e-13); // C²
/// ```
#[derive(Clone, Debug)]
pub struct CornerBlend<P: Manifold> {
    points: Vec<P>,
    core: CornerCore<P::Vector, PlaneRotation<P::Vector>>,
}

impl<P: Manifold> CornerBlend<P> {
    /// The default continuity order (C²).
    pub const DEFAULT_ORDER: usize = 2;

    /// Smooths the corners of the polyline through `points` with order `n = order` and the
    /// given `fraction` of every edge used by each corner blend.
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 3 points;
    /// - [`SplineError::InvalidParameter`] (`order`) unless `1 ≤ order ≤ 10`, (`fraction`)
    ///   unless `0 < fraction ≤ 0.5`;
    /// - [`SplineError::Coincident`] / [`SplineError::Antipodal`] for coincident or antipodal
    ///   consecutive points (no unique great-circle edge).
    pub fn try_new(points: Vec<P>, order: usize, fraction: f64) -> Result<Self, SplineError> {
        Self::build(points, order, fraction, false)
    }

    /// Smooths every corner of the closed polygon `P₀ → P₁ → … → P_{m−1} → P₀` (m ≥ 3), the
    /// one at `P₀` included. The loop starts where the corner at `P₀` ends on the first edge
    /// and returns there: it is Cⁿ at the seam as everywhere else (the speed factors telescope
    /// around the loop, `∏ Θ_j/Θ_{j−1} = 1`), and it follows the polygon's edges exactly
    /// outside the corner blends. It does not pass through the vertices.
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new), and [`SplineError::CoincidentClosing`] /
    /// [`SplineError::AntipodalClosing`] for a coincident or antipodal last and first point.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, CornerBlend, Curve, Manifold, S2Point};
    ///
    /// let c = CornerBlend::try_new_closed(vec![S2Point::X, S2Point::Y, S2Point::Z], 3, 0.25).unwrap();
    /// let [t0, t1] = c.domain();
    /// assert!(c.eval(t1).dist(&c.eval(t0)) < 1e-15);
    /// // Every corner is blended: 3 straight parts and 3 corners, the seam the last joint.
    /// let report = continuity(&c);
    /// assert_eq!(report.len(), 6);
    /// assert!(report.iter().all(|j| j.c1 < 1e-12 && j.c2 < 1e-11));
    /// ```
    pub fn try_new_closed(
        points: Vec<P>,
        order: usize,
        fraction: f64,
    ) -> Result<Self, SplineError> {
        Self::build(points, order, fraction, true)
    }

    fn build(
        points: Vec<P>,
        order: usize,
        fraction: f64,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let vs = polyline(&points, closed)?;
        let count = vs.len() - 1;
        let edges = vs
            .windows(2)
            .enumerate()
            .map(|(index, w)| {
                let (theta, e) = geodesic_frame(&w[0], &w[1])
                    .ok_or_else(|| edge_error(index, count, closed, true))?;
                if theta <= 0.0 {
                    return Err(edge_error(index, count, closed, false));
                }
                Ok((
                    PlaneRotation {
                        a: w[0].clone(),
                        b: e,
                    },
                    theta,
                ))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let core = CornerCore::build(&vs, edges, order, fraction, closed)?;
        Ok(Self { points, core })
    }

    /// The polyline's vertices.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The joints: ends of the straight arcs and corner blends, increasing from 0.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.core.knots.as_slice()
    }

    /// The continuity order `n`.
    #[must_use]
    pub fn order(&self) -> usize {
        self.core.poly.order()
    }

    /// The part of each edge used by a corner blend.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        self.core.fraction
    }

    /// The derivatives of orders `0…=order` at `t` (exact, any order; one-sided at joints).
    #[must_use]
    pub fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<P::Vector> {
        self.core.derivatives(t, side, order)
    }
}

impl<P: Manifold> Curve for CornerBlend<P> {
    type Point = P;

    fn domain(&self) -> [f64; 2] {
        self.core.knots.domain()
    }

    fn joints(&self) -> &[f64] {
        self.core.knots.as_slice()
    }

    fn is_closed(&self) -> bool {
        self.core.closed
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<P> {
        let (p, velocity, acceleration) = self.core.jet(t, side);
        Jet {
            point: P::from_vector_unchecked(p),
            velocity,
            acceleration,
        }
    }

    fn eval(&self, t: f64) -> P {
        P::from_vector_unchecked(self.core.point(t))
    }

    fn eval_many(&self, ts: &[f64], out: &mut [P]) {
        self.core.points_into(ts, out, P::from_vector_unchecked);
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<P>]) {
        self.core
            .jets_into(ts, out, |(p, velocity, acceleration)| Jet {
                point: P::from_vector_unchecked(p),
                velocity,
                acceleration,
            });
    }
}

/// Pobegailo's Cⁿ corner smoothing of an orientation polyline `q₀ → q₁ → … → q_M` of unit
/// quaternions, with the rotations applied in the base frame (left multiplication).
///
/// Source: Pobegailo (2019), §9.5–9.8 (eqs. (9.18)–(9.21)), extended to several corners as for
/// [`CornerBlend`] (`docs/derivations.md#pobegailo-corners`). Edge `j` is
/// the great-circle arc of S³ from `q_j` to `q_{j+1}`, `e_{n_j}(s)·q_j` with
/// `e_n(s) = cos s + sin s·n` and `s ∈ [0, Ω_j]` (`Ω_j` the angle on S³, half the rotation angle;
/// this is slerp; keys are used as given, so canonicalise with [`unflip`](crate::unflip) for the
/// shorter rotations). Corner `j`, with `α_j = f·Ω_{j−1}`, `β_j = f·Ω_j`:
///
/// ```text
/// r(u) = e_{n_j}(w₁,ₙ(u)·β_j) · e_{n_{j−1}}(−w₁,ₙ(1 − u)·α_j) · q_j
/// ```
///
/// which is `Rot(n_j, ·)·Rot(n_{j−1}, ·)·P_j` of the book with the base point corrected from
/// `Q₁` to `P₂` (`docs/derivations.md#pobegailo-8-21`). Durations and continuity as for
/// [`CornerBlend`]; the first edge is traversed at unit speed on S³ (angular velocity of magnitude
/// 2). The angular velocity is
/// constant on the edges.
///
/// Unlike [`CornerBlend<UnitQuat>`], whose corner uses simple rotations of ℝ⁴, this is the
/// book's orientation construction; the two agree outside the corner blends.
///
/// # Examples
///
/// ```
/// use spherekit::{CornerBlendS3, Curve, Manifold, Side, UnitQuat, glam::DVec3};
///
/// let q1 = UnitQuat::from_axis_angle(DVec3::X, core::f64::consts::FRAC_PI_2).unwrap();
/// let q2 = UnitQuat::from_axis_angle(DVec3::Y, core::f64::consts::FRAC_PI_2).unwrap().mul(q1);
/// let c = CornerBlendS3::try_new(vec![UnitQuat::IDENTITY, q1, q2], 2, 0.25).unwrap();
/// let k = c.knots().to_vec();
/// assert!(c.eval(k[3]).dist(&q2) < 1e-15);
/// let (l, r) = (c.jet_at(k[1], Side::Left), c.jet_at(k[1], Side::Right));
/// assert!((l.acceleration - r.acceleration).length() < 1e-13); // C²
/// ```
#[derive(Clone, Debug)]
pub struct CornerBlendS3 {
    points: Vec<UnitQuat>,
    core: CornerCore<DVec4, LeftMultiplication>,
}

impl CornerBlendS3 {
    /// The default continuity order (C²).
    pub const DEFAULT_ORDER: usize = 2;

    /// Smooths the corners of the orientation polyline through `points`.
    ///
    /// # Errors
    ///
    /// As [`CornerBlend::try_new`]; antipodal keys (the same orientation) are rejected.
    pub fn try_new(
        points: Vec<UnitQuat>,
        order: usize,
        fraction: f64,
    ) -> Result<Self, SplineError> {
        Self::build(points, order, fraction, false)
    }

    /// Smooths every corner of the closed orientation polygon `q₀ → … → q_{m−1} → q₀`, as
    /// [`CornerBlend::try_new_closed`] does on the sphere.
    ///
    /// # Errors
    ///
    /// As [`CornerBlend::try_new_closed`].
    pub fn try_new_closed(
        points: Vec<UnitQuat>,
        order: usize,
        fraction: f64,
    ) -> Result<Self, SplineError> {
        Self::build(points, order, fraction, true)
    }

    fn build(
        points: Vec<UnitQuat>,
        order: usize,
        fraction: f64,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let vs = polyline(&points, closed)?;
        let count = vs.len() - 1;
        let edges = vs
            .windows(2)
            .enumerate()
            .map(|(index, w)| {
                let (theta, e) = geodesic_frame(&w[0], &w[1])
                    .ok_or_else(|| edge_error(index, count, closed, true))?;
                if theta <= 0.0 {
                    return Err(edge_error(index, count, closed, false));
                }
                // e ⊥ q, so e·q̄ is a pure unit quaternion n with e = n·q.
                let n = (DQuat::from_vec4(e) * DQuat::from_vec4(w[0]).conjugate()).xyz();
                Ok((LeftMultiplication { axis: n }, theta))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let core = CornerCore::build(&vs, edges, order, fraction, closed)?;
        Ok(Self { points, core })
    }

    /// The polyline's vertices.
    #[must_use]
    pub fn points(&self) -> &[UnitQuat] {
        &self.points
    }

    /// The joints: ends of the straight arcs and corner blends, increasing from 0.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.core.knots.as_slice()
    }

    /// The continuity order `n`.
    #[must_use]
    pub fn order(&self) -> usize {
        self.core.poly.order()
    }

    /// The part of each edge used by a corner blend.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        self.core.fraction
    }

    /// The derivatives of orders `0…=order` at `t` (exact, any order; one-sided at joints).
    #[must_use]
    pub fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<DVec4> {
        self.core.derivatives(t, side, order)
    }
}

impl Curve for CornerBlendS3 {
    type Point = UnitQuat;

    fn domain(&self) -> [f64; 2] {
        self.core.knots.domain()
    }

    fn joints(&self) -> &[f64] {
        self.core.knots.as_slice()
    }

    fn is_closed(&self) -> bool {
        self.core.closed
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        let (p, velocity, acceleration) = self.core.jet(t, side);
        Jet {
            point: UnitQuat::from_vector_unchecked(p),
            velocity,
            acceleration,
        }
    }

    fn eval(&self, t: f64) -> UnitQuat {
        UnitQuat::from_vector_unchecked(self.core.point(t))
    }

    fn eval_many(&self, ts: &[f64], out: &mut [UnitQuat]) {
        self.core
            .points_into(ts, out, UnitQuat::from_vector_unchecked);
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<UnitQuat>]) {
        self.core
            .jets_into(ts, out, |(p, velocity, acceleration)| Jet {
                point: UnitQuat::from_vector_unchecked(p),
                velocity,
                acceleration,
            });
    }
}
