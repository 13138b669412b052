// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's corner smoothing of a great-circle polyline.

use core::f64::consts::TAU;

use glam::{DQuat, DVec4};

use crate::ambient::Ambient;
use crate::arc_blend::{check_loop_neighbours, check_neighbours, check_smoothness};
use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::flow::{Flow, LeftMultiplication, PlaneRotation, Segment, Weights};
use crate::knots::{Knots, MAX_KNOT_SPACING, MIN_KNOT_SPACING};
use crate::manifold::{Manifold, geodesic_frame, renormalize};
use crate::math;
use crate::s2::S2Point;
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
    /// Per corner `[incoming, outgoing]` fractions of the edges meeting there.
    cuts: Vec<[f64; 2]>,
    segments: Vec<Segment<V, F>>,
}

/// Where the corner blends of a [`CornerBlend`] or [`CornerBlendRotations`] start and end: the cut-back
/// of each corner along the edges meeting there, as fractions of those edges measured from the
/// corner (Pobegailo (2019), §8.5: the cut points `Q₁`, `Q₂` are chosen "from kinematic
/// requirements").
#[derive(Clone, Debug, PartialEq)]
pub enum CornerCuts {
    /// One fraction `f ∈ (0, 0.5]` of every edge at every corner (the cuts of two corners on an
    /// edge then never overlap).
    Uniform(f64),
    /// One fraction per corner (interior point `P₁ … P_{M−1}`), used on both of its edges.
    PerCorner(Vec<f64>),
    /// `[incoming, outgoing]` per corner: the part of the edge before the corner and of the
    /// edge after it that the corner blend replaces.
    Pairs(Vec<[f64; 2]>),
}

/// When a corner blend starts and how fast it runs: the parameter `t₀` at the first point and
/// the angular speed `ω₀` on the first edge (radians of the edge's rotation per unit `t`).
///
/// These are the book's free timing data, the knots `t₁ < t₂` of the lead-in arc (Pobegailo
/// (2019), §8.8, Algorithm 8.2: `ω₀ = φ₁/(t₂ − t₁)`). Every later knot is forced by Cⁿ
/// continuity: corner `j` lasts `α_j/ω` and leaves at `ω·β_j/α_j` (`α_j`, `β_j` its cut angles),
/// so per-corner durations are not free data; they follow from the cuts (equal cut angles keep
/// the speed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CornerTiming {
    /// The parameter at the first point.
    pub start: f64,
    /// The angular speed on the first edge, `> 0`.
    pub speed: f64,
}

impl Default for CornerTiming {
    /// Start at 0 with unit angular speed.
    fn default() -> Self {
        Self {
            start: 0.0,
            speed: 1.0,
        }
    }
}

fn cut_error(reason: String) -> SplineError {
    SplineError::InvalidParameter {
        name: "fraction",
        reason,
    }
}

impl CornerCuts {
    /// The `[incoming, outgoing]` fractions of the `corners` corners, checked: each in `(0, 1)`,
    /// and the cuts of two consecutive corners on the edge between them at most the whole edge.
    ///
    /// A closed polygon has a corner at every vertex: entry `j` is the corner at point
    /// `(j + 1) mod m`, the last one at point 0, and the last and the first share the edge from
    /// point 0 to point 1.
    fn resolve(&self, corners: usize, closed: bool) -> Result<Vec<[f64; 2]>, SplineError> {
        let list: Vec<[f64; 2]> = match self {
            Self::Uniform(f) => {
                check_fraction(*f)?;
                return Ok(vec![[*f, *f]; corners]);
            }
            Self::PerCorner(v) => v.iter().map(|&f| [f, f]).collect(),
            Self::Pairs(v) => v.clone(),
        };
        if list.len() != corners {
            let which = if closed {
                format!("the points 1 to {} and 0", corners - 1)
            } else {
                format!("the points 1 to {corners}")
            };
            return Err(cut_error(format!(
                "expected {corners} entries (one per corner, {which}), got {}",
                list.len()
            )));
        }
        for (j, pair) in list.iter().enumerate() {
            for (side, f) in ["incoming", "outgoing"].iter().zip(pair) {
                if !(*f > 0.0 && *f < 1.0) {
                    return Err(cut_error(format!(
                        "entry {j} (the corner at point {}): the {side} cut must be in (0, 1), got {f}",
                        (j + 1) % (corners + usize::from(!closed))
                    )));
                }
            }
        }
        for (j, w) in list.windows(2).enumerate() {
            if w[0][1] + w[1][0] > 1.0 {
                return Err(cut_error(format!(
                    "entries {j} and {} overlap on the edge from point {} to point {}: the outgoing cut {} and the incoming cut {} add up to more than the edge",
                    j + 1,
                    j + 1,
                    j + 2,
                    w[0][1],
                    w[1][0]
                )));
            }
        }
        if closed {
            let (last, first) = (list[corners - 1], list[0]);
            if last[1] + first[0] > 1.0 {
                return Err(cut_error(format!(
                    "entries {} and 0 overlap on the edge from point 0 to point 1: the outgoing cut {} and the incoming cut {} add up to more than the edge",
                    corners - 1,
                    last[1],
                    first[0]
                )));
            }
        }
        Ok(list)
    }
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

/// Why the timing of a corner blend has no knots in `f64`: the first piece whose duration is
/// outside the knot spacing range or lost to rounding next to its start.
fn timing_error(t: &[f64], speeds: &[f64]) -> SplineError {
    let i = (1..t.len())
        .find(|&i| {
            let w = t[i] - t[i - 1];
            !(w.is_finite() && (MIN_KNOT_SPACING..=MAX_KNOT_SPACING).contains(&w))
        })
        .unwrap_or(1);
    let reason = format!(
        "piece {} of the curve (from t = {:e}) cannot be timed in f64: its angular speed {:e} makes it last {:e}; the speed is multiplied by β/α (the outgoing over the incoming cut angle) at each corner, so make the two cuts of each corner closer in angle (or the speed closer to 1)",
        i - 1,
        t[i - 1],
        speeds.get(i - 1).copied().unwrap_or(f64::NAN),
        t[i] - t[i - 1],
    );
    SplineError::InvalidParameter {
        name: if i == 1 { "speed" } else { "fraction" },
        reason,
    }
}

/// The minor great-circle arcs `P_j → P_{j+1}` as simple rotations in their planes, with their
/// angles.
fn great_circle_edges<V: Ambient>(
    vs: &[V],
    closed: bool,
) -> Result<Vec<(PlaneRotation<V>, f64)>, SplineError> {
    let count = vs.len() - 1;
    vs.windows(2)
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
        .collect()
}

/// The vertices as ambient vectors, for a closed polygon with the first repeated at the end,
/// after the checks of an open or closed polyline.
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

/// The error of edge `index` of `edges` edges: the closing edge of a loop has its own.
fn edge_error(index: usize, edges: usize, closed: bool, antipodal: bool) -> SplineError {
    match (closed && index + 1 == edges, antipodal) {
        (true, true) => SplineError::AntipodalClosing,
        (true, false) => SplineError::CoincidentClosing,
        (false, true) => SplineError::Antipodal { index },
        (false, false) => SplineError::Coincident { index },
    }
}

/// The largest relative mismatch `|∏ β_j/α_j − 1|` of the speed factors around a closed loop
/// (`docs/derivations.md#closed-loops`).
pub(crate) const LOOP_SPEED_TOLERANCE: f64 = 1e-10;

/// One piece of a corner-blend curve as [`plan`] lays it out, before its segment is formed.
#[derive(Clone, Copy, Debug)]
enum Piece {
    /// The straight part of edge `edge`, from `start` (the angle along the edge) for `angle`.
    Straight { edge: usize, start: f64, angle: f64 },
    /// The corner from edge `edge` into the next: `alpha` back along `edge`, `beta` along the
    /// next edge.
    Corner { edge: usize, alpha: f64, beta: f64 },
}

/// The layout of a corner-blend curve: its pieces, their knots, the resolved cuts and the blend
/// polynomials.
struct Plan {
    pieces: Vec<Piece>,
    knots: Knots,
    cuts: Vec<[f64; 2]>,
    poly: SmoothingPolynomials,
}

/// The [`Plan`] of a corner-blend curve from the edges' angles `thetas` alone
/// ([`CornerCore::build`]; not generic, so one copy serves every sphere and flow).
fn plan(
    thetas: &[f64],
    smoothness: usize,
    cuts: &CornerCuts,
    timing: CornerTiming,
    closed: bool,
) -> Result<Plan, SplineError> {
    let poly = check_smoothness(smoothness)?;
    let m = thetas.len();
    let cuts = cuts.resolve(if closed { m } else { m - 1 }, closed)?;
    if !timing.start.is_finite() {
        return Err(SplineError::InvalidParameter {
            name: "start",
            reason: format!("must be a finite number, got {}", timing.start),
        });
    }
    if !(timing.speed.is_finite() && timing.speed > 0.0) {
        return Err(SplineError::InvalidParameter {
            name: "speed",
            reason: format!("must be a positive number, got {}", timing.speed),
        });
    }
    let mut pieces = Vec::with_capacity(2 * m);
    let mut t = vec![timing.start];
    let mut omega = timing.speed;
    // The angular speed of each piece at its start, for the timing error.
    let mut speeds = Vec::with_capacity(2 * m);
    let mut push = |piece: Piece, width: f64, t: &mut Vec<f64>, omega: f64| {
        let last = t[t.len() - 1];
        t.push(last + width);
        pieces.push(piece);
        speeds.push(omega);
    };
    for (j, &theta) in thetas.iter().enumerate() {
        // Straight part of edge j: from Q_j⁺ (or P_0) to Q_{j+1}⁻ (or P_M).
        let out_cut = match (closed, j) {
            (true, _) => cuts[(j + m - 1) % m][1],
            (false, 0) => 0.0,
            (false, _) => cuts[j - 1][1],
        };
        let in_cut = if closed || j + 1 < m { cuts[j][0] } else { 0.0 };
        let cut_start = out_cut * theta;
        let straight = (1.0 - out_cut - in_cut) * theta;
        // Cuts that add up to the whole edge (to rounding) leave no straight part.
        if straight > 4.0 * f64::EPSILON * theta {
            let piece = Piece::Straight {
                edge: j,
                start: cut_start,
                angle: straight,
            };
            push(piece, straight / omega, &mut t, omega);
        }
        if closed || j + 1 < m {
            // Corner at P_{j+1}: α = incoming cut on edge j, β = outgoing cut on edge j+1.
            let next_theta = thetas[(j + 1) % m];
            let alpha = cuts[j][0] * theta;
            let beta = cuts[j][1] * next_theta;
            let piece = Piece::Corner {
                edge: j,
                alpha,
                beta,
            };
            push(piece, alpha / omega, &mut t, omega);
            omega *= beta / alpha;
        }
    }
    let returns = (omega / timing.speed - 1.0).abs() <= LOOP_SPEED_TOLERANCE;
    if closed && !returns {
        return Err(cut_error(format!(
            "closes the loop at {:e} times the starting speed: the speed is multiplied by β/α (the outgoing over the incoming cut angle) at each corner, and around a loop these factors must multiply to 1 (equal incoming and outgoing fractions do)",
            omega / timing.speed
        )));
    }
    let knots = match Knots::try_new(t.clone()) {
        Ok(k) => k,
        Err(_) => return Err(timing_error(&t, &speeds)),
    };
    Ok(Plan {
        pieces,
        knots,
        cuts,
        poly,
    })
}

impl<V: Ambient, F: Flow<V>> CornerCore<V, F> {
    /// `points` are the polyline's vertices `P_0 … P_M` (a closed polygon's with `P_M = P_0`),
    /// `edges[j]` the flow and angle of edge `P_j → P_{j+1}`.
    ///
    /// Open: the straight part of edge 0 from `P_0`, corner 1, …, the straight part of the last
    /// edge to `P_M`. Closed: a corner at every vertex, the curve starting where the corner at
    /// `P_0` ends on edge 0 and returning there after the corner at `P_0`. The speed is
    /// multiplied by `β_j/α_j` at each corner; around a loop the factors must multiply to 1
    /// (they do for equal incoming and outgoing fractions, `Θ_j/Θ_{j−1}` telescoping), or the
    /// seam would change speed.
    fn build(
        points: &[V],
        edges: Vec<(F, f64)>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let thetas: Vec<f64> = edges.iter().map(|e| e.1).collect();
        let Plan {
            pieces,
            knots,
            cuts,
            poly,
        } = plan(&thetas, smoothness, cuts, timing, closed)?;
        let m = edges.len();
        // Each segment's width is its exact knot width, so that u = (t − t_i)/width is
        // consistent with `locate`.
        let segments = pieces
            .iter()
            .enumerate()
            .map(|(i, piece)| match *piece {
                Piece::Straight { edge, start, angle } => Segment {
                    base: edges[edge].0.apply(start, &points[edge]),
                    outer: edges[edge].0.clone(),
                    outer_angle: angle,
                    inner: None,
                    weights: Weights::Linear,
                    width: knots.width(i),
                },
                Piece::Corner { edge, alpha, beta } => Segment {
                    base: points[edge + 1].clone(),
                    outer: edges[(edge + 1) % m].0.clone(),
                    outer_angle: beta,
                    inner: Some((edges[edge].0.clone(), alpha)),
                    weights: Weights::Corner,
                    width: knots.width(i),
                },
            })
            .collect();
        Ok(Self {
            closed,
            knots,
            poly,
            cuts,
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
/// `α_j = f·Θ_{j−1}` before it and ends `β_j = f·Θ_j` after it (`f = fraction`; with
/// [`try_with`](Self::try_with) the two fractions of each corner are chosen freely,
/// [`CornerCuts`], and so are the start and the first speed, [`CornerTiming`]; on S²,
/// [`try_with_arcs`](Self::try_with_arcs) takes small-circle edges;
/// `docs/derivations.md#pobegailo-general-corners`):
///
/// ```text
/// corner j:  r(u) = R_j(w₁,ₙ(u)·β_j) · R_{j−1}(−w₁,ₙ(1 − u)·α_j) · P_j        (8.19)
/// edges:     r(u) = R_j(u·γ) Q,  the great-circle arcs between the corner blends
/// durations: an arc of angle γ lasts γ/ω; corner j lasts α_j/ω and sets ω ← ω·β_j/α_j; ω₀ = 1
/// ```
///
/// The curve starts at `P₀` at unit angular speed (by default), follows the polyline's arcs **exactly**
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
    /// The default smoothness (C²).
    pub const DEFAULT_SMOOTHNESS: usize = 2;

    /// Smooths the corners of the polyline through `points` with smoothness `n = smoothness` and the
    /// given `fraction` of every edge used by each corner blend.
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 3 points;
    /// - [`SplineError::InvalidParameter`] (`smoothness`) unless `1 ≤ smoothness ≤ 10`, (`fraction`)
    ///   unless `0 < fraction ≤ 0.5`;
    /// - [`SplineError::Coincident`] / [`SplineError::Antipodal`] for coincident or antipodal
    ///   consecutive points (no unique great-circle edge).
    pub fn try_new(points: Vec<P>, smoothness: usize, fraction: f64) -> Result<Self, SplineError> {
        Self::try_with(
            points,
            smoothness,
            &CornerCuts::Uniform(fraction),
            CornerTiming::default(),
        )
    }

    /// Smooths the corners with the given cut-backs per corner and the given timing (start
    /// parameter and angular speed on the first edge).
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new); (`fraction`) for a list of cuts whose length is not the
    /// number of corners (`points − 2`), a cut outside `(0, 1)`, or two cuts that overlap on an
    /// edge; (`start`) for a non-finite start and (`speed`) for a speed that is not positive;
    /// the knot errors of [`Knots::try_new`] when the timing gives pieces too short or too long
    /// for `f64`.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{CornerBlend, CornerCuts, CornerTiming, Curve, S2Point, Side};
    ///
    /// let pts = vec![S2Point::X, S2Point::Y, S2Point::Z];
    /// // Cut back 40 % of the first edge and 10 % of the second; start at t = 2, speed 4.
    /// let timing = CornerTiming { start: 2.0, speed: 4.0 };
    /// let c = CornerBlend::try_with(pts, 3, &CornerCuts::Pairs(vec![[0.4, 0.1]]), timing).unwrap();
    /// let k = c.knots();
    /// let quarter = core::f64::consts::FRAC_PI_2;
    /// assert_eq!(k[0], 2.0);
    /// assert!((k[1] - (2.0 + 0.6 * quarter / 4.0)).abs() < 1e-15);
    /// // After the corner the speed is 4·β/α = 4·0.1/0.4 = 1.
    /// assert!((c.jet_at(k[2], Side::Right).velocity.length() - 1.0).abs() < 1e-14);
    /// ```
    pub fn try_with(
        points: Vec<P>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
    ) -> Result<Self, SplineError> {
        Self::build(points, smoothness, cuts, timing, false)
    }

    /// Smooths every corner of the closed polygon `P₀ → P₁ → … → P_{m−1} → P₀` (m ≥ 3), the
    /// one at `P₀` included, with the fraction `fraction` of every edge at every corner. The
    /// loop starts where the corner at `P₀` ends on the first edge and returns there: it is Cⁿ
    /// at the seam as everywhere else (the speed factors `Θ_j/Θ_{j−1}` telescope around the
    /// loop), follows the polygon's edges exactly outside the corner blends, and does not pass
    /// through the vertices.
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
        smoothness: usize,
        fraction: f64,
    ) -> Result<Self, SplineError> {
        Self::try_with_closed(
            points,
            smoothness,
            &CornerCuts::Uniform(fraction),
            CornerTiming::default(),
        )
    }

    /// The closed polygon of [`try_new_closed`](Self::try_new_closed) with cuts and timing as
    /// [`try_with`](Self::try_with): one cut entry per vertex, entry `j` for the corner at point
    /// `(j + 1) mod m` (the last at point 0); `timing` gives the parameter and the speed where
    /// the loop starts (after the corner at point 0).
    ///
    /// # Errors
    ///
    /// As [`try_new_closed`](Self::try_new_closed) and [`try_with`](Self::try_with), and
    /// [`SplineError::InvalidParameter`] (`fraction`) when the speed factors `β_j/α_j` of the
    /// corners do not multiply to 1 around the loop (within `1e-10`): unequal incoming and
    /// outgoing cuts whose ratios do not cancel would change the speed at the seam.
    pub fn try_with_closed(
        points: Vec<P>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
    ) -> Result<Self, SplineError> {
        Self::build(points, smoothness, cuts, timing, true)
    }

    fn build(
        points: Vec<P>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let vs = polyline(&points, closed)?;
        let edges = great_circle_edges(&vs, closed)?;
        let core = CornerCore::build(&vs, edges, smoothness, cuts, timing, closed)?;
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

    /// The smoothness `n`: the curve is Cⁿ at its joints.
    #[must_use]
    pub fn smoothness(&self) -> usize {
        self.core.poly.order()
    }

    /// The `[incoming, outgoing]` fractions of the edges used by each corner blend, one pair
    /// per corner (interior point).
    #[must_use]
    pub fn cuts(&self) -> &[[f64; 2]] {
        &self.core.cuts
    }

    /// The derivatives of orders `0…=order` at `t` (exact, any order; one-sided at joints).
    #[must_use]
    pub fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<P::Vector> {
        self.core.derivatives(t, side, order)
    }
}

/// Pobegailo's corner smoothing of a path of **circle arcs** on S², small circles included
/// (§8.5–8.8: the joint of `R(m, uφ)p₁` and `R(n, uψ)p₂`, with the corner formula (8.19) for
/// any two arcs of rotation orbits).
impl CornerBlend<S2Point> {
    /// Smooths the corners of the path whose edge `j` is the arc from `P_j` to `P_{j+1}` of the
    /// circle given by `bends[j] = b ∈ (−1, 1)` (one per edge, `points − 1` values):
    ///
    /// ```text
    /// m_j = √(1 − b²)·n̂ + b·ŝ,   n̂ = (P_j × P_{j+1})/|P_j × P_{j+1}|,   ŝ = (P_j + P_{j+1})/|P_j + P_{j+1}|
    /// edge j:  u ↦ R(m_j, u·φ_j)·P_j,   φ_j ∈ (0, 2π) the angle about m_j from P_j to P_{j+1}
    /// ```
    ///
    /// Every circle through two points has its axis `m` on the great circle of directions
    /// equidistant from them (`m·P_j = m·P_{j+1}`), so one number per edge gives every arc of
    /// the book's form `R(m, uφ)p` that joins the vertices: `b = 0` is the minor great arc
    /// (then this is [`try_with`](Self::try_with)), `b > 0` tilts the axis towards the chord's
    /// midpoint, bowing the arc to the right of travel (seen from outside the sphere), `b < 0`
    /// to the left, and `|b| → 1` makes the arc a half circle of an ever smaller circle
    /// (`φ → π`). The circle's plane is `m_j·x = b·cos(Θ_j/2)`, `Θ_j` the great-circle angle
    /// of the edge.
    ///
    /// Cuts and timing are measured in the rotation angles `φ_j` about the edges' axes; the
    /// corner blend and its Cⁿ continuity are those of the great-circle case, since (8.19) and
    /// the knot rule only use that each edge is an orbit of a one-parameter rotation group
    /// (`docs/derivations.md#pobegailo-general-corners`).
    ///
    /// # Errors
    ///
    /// As [`try_with`](Self::try_with); [`SplineError::InvalidParameter`] (`bend`) for a list
    /// whose length is not `points − 1` or a value outside `(−1, 1)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{CornerBlend, CornerCuts, CornerTiming, Curve, Manifold, S2Point, Side};
    /// use spherekit::glam::DVec3;
    ///
    /// let pts = vec![S2Point::X, S2Point::Y, S2Point::Z];
    /// let cuts = CornerCuts::Uniform(0.25);
    /// let c = CornerBlend::try_with_arcs(pts, 2, &cuts, CornerTiming::default(), &[0.5, -0.3])
    ///     .unwrap();
    /// let [t0, t1] = c.domain();
    /// assert!(c.eval(t0).dist(&S2Point::X) < 1e-15 && c.eval(t1).dist(&S2Point::Z) < 1e-15);
    /// // The first edge is a small circle: its midpoint is off the equator.
    /// assert!(c.eval(0.5 * c.knots()[1]).as_dvec3().z.abs() > 0.1);
    /// let (l, r) = (c.jet_at(c.knots()[1], Side::Left), c.jet_at(c.knots()[1], Side::Right));
    /// assert!((l.acceleration - r.acceleration).length() < 1e-13); // C²
    /// ```
    pub fn try_with_arcs(
        points: Vec<S2Point>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
        bends: &[f64],
    ) -> Result<Self, SplineError> {
        Self::arcs(points, smoothness, cuts, timing, bends, false)
    }

    /// The closed polygon of [`try_with_closed`](CornerBlend::try_with_closed) with the
    /// small-circle edges of [`try_with_arcs`](Self::try_with_arcs): one bend per edge, the
    /// closing edge from the last point to the first last.
    ///
    /// # Errors
    ///
    /// As [`try_with_closed`](CornerBlend::try_with_closed) and
    /// [`try_with_arcs`](Self::try_with_arcs) (`points.len()` bends).
    pub fn try_with_arcs_closed(
        points: Vec<S2Point>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
        bends: &[f64],
    ) -> Result<Self, SplineError> {
        Self::arcs(points, smoothness, cuts, timing, bends, true)
    }

    fn arcs(
        points: Vec<S2Point>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
        bends: &[f64],
        closed: bool,
    ) -> Result<Self, SplineError> {
        let vs = polyline(&points, closed)?;
        let edge_count = vs.len() - 1;
        let bend_error = |reason: String| SplineError::InvalidParameter {
            name: "bend",
            reason,
        };
        if bends.len() != edge_count {
            return Err(bend_error(format!(
                "expected {edge_count} values (one per edge), got {}",
                bends.len()
            )));
        }
        if let Some(j) = bends.iter().position(|b| b.is_nan() || b.abs() >= 1.0) {
            return Err(bend_error(format!(
                "entry {j} (the edge from point {j}): must be in (−1, 1), got {}",
                bends[j]
            )));
        }
        let mut edges = great_circle_edges(&vs, closed)?;
        for (j, (flow, theta)) in edges.iter_mut().enumerate() {
            let b = bends[j];
            if b == 0.0 {
                continue;
            }
            let (p, q) = (vs[j], vs[j + 1]);
            let (n, mid) = (p.cross(q).normalize(), (p + q).normalize());
            let m = n * (1.0 - b * b).sqrt() + mid * b;
            let centre = m * m.dot(p);
            let a = (p - centre).normalize();
            let e = m.cross(a);
            let r = q - centre;
            let angle = math::atan2(r.dot(e), r.dot(a));
            *theta = if angle > 0.0 { angle } else { angle + TAU };
            *flow = PlaneRotation { a, b: e };
        }
        let core = CornerCore::build(&vs, edges, smoothness, cuts, timing, closed)?;
        Ok(Self { points, core })
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
/// use spherekit::{CornerBlendRotations, Curve, Manifold, Side, UnitQuat, glam::DVec3};
///
/// let q1 = UnitQuat::from_axis_angle(DVec3::X, core::f64::consts::FRAC_PI_2).unwrap();
/// let q2 = UnitQuat::from_axis_angle(DVec3::Y, core::f64::consts::FRAC_PI_2).unwrap() * q1;
/// let c = CornerBlendRotations::try_new(vec![UnitQuat::IDENTITY, q1, q2], 2, 0.25).unwrap();
/// let k = c.knots().to_vec();
/// assert!(c.eval(k[3]).dist(&q2) < 1e-15);
/// let (l, r) = (c.jet_at(k[1], Side::Left), c.jet_at(k[1], Side::Right));
/// assert!((l.acceleration - r.acceleration).length() < 1e-13); // C²
/// ```
#[derive(Clone, Debug)]
pub struct CornerBlendRotations {
    points: Vec<UnitQuat>,
    core: CornerCore<DVec4, LeftMultiplication>,
}

impl CornerBlendRotations {
    /// The default smoothness (C²).
    pub const DEFAULT_SMOOTHNESS: usize = 2;

    /// Smooths the corners of the orientation polyline through `points`.
    ///
    /// # Errors
    ///
    /// As [`CornerBlend::try_new`]; antipodal keys (the same orientation) are rejected.
    pub fn try_new(
        points: Vec<UnitQuat>,
        smoothness: usize,
        fraction: f64,
    ) -> Result<Self, SplineError> {
        Self::try_with(
            points,
            smoothness,
            &CornerCuts::Uniform(fraction),
            CornerTiming::default(),
        )
    }

    /// Smooths the corners with the given cut-backs per corner and timing, as
    /// [`CornerBlend::try_with`] (the speed is the angular speed on S³, half the rotation rate).
    ///
    /// # Errors
    ///
    /// As [`CornerBlend::try_with`].
    pub fn try_with(
        points: Vec<UnitQuat>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
    ) -> Result<Self, SplineError> {
        Self::build(points, smoothness, cuts, timing, false)
    }

    /// Smooths every corner of the closed orientation polygon `q₀ → … → q_{m−1} → q₀`, as
    /// [`CornerBlend::try_new_closed`] does on the sphere.
    ///
    /// # Errors
    ///
    /// As [`CornerBlend::try_new_closed`].
    pub fn try_new_closed(
        points: Vec<UnitQuat>,
        smoothness: usize,
        fraction: f64,
    ) -> Result<Self, SplineError> {
        Self::try_with_closed(
            points,
            smoothness,
            &CornerCuts::Uniform(fraction),
            CornerTiming::default(),
        )
    }

    /// The closed polygon with cuts and timing, as [`CornerBlend::try_with_closed`].
    ///
    /// # Errors
    ///
    /// As [`CornerBlend::try_with_closed`].
    pub fn try_with_closed(
        points: Vec<UnitQuat>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
    ) -> Result<Self, SplineError> {
        Self::build(points, smoothness, cuts, timing, true)
    }

    fn build(
        points: Vec<UnitQuat>,
        smoothness: usize,
        cuts: &CornerCuts,
        timing: CornerTiming,
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
        let core = CornerCore::build(&vs, edges, smoothness, cuts, timing, closed)?;
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

    /// The smoothness `n`: the curve is Cⁿ at its joints.
    #[must_use]
    pub fn smoothness(&self) -> usize {
        self.core.poly.order()
    }

    /// The `[incoming, outgoing]` fractions of the edges used by each corner blend, one pair
    /// per corner (interior point).
    #[must_use]
    pub fn cuts(&self) -> &[[f64; 2]] {
        &self.core.cuts
    }

    /// The derivatives of orders `0…=order` at `t` (exact, any order; one-sided at joints).
    #[must_use]
    pub fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<DVec4> {
        self.core.derivatives(t, side, order)
    }
}

impl Curve for CornerBlendRotations {
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
