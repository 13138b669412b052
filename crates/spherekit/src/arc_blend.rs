// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's interpolating Cⁿ spline: blending of circle arcs through consecutive triples.
//!
//! # Timing: how the parameter runs through the keys
//!
//! Every segment `i` of an [`ArcBlend`] is built in its own local parameter `u ∈ [0, 1]` as
//! `X_i(u)` (the formulas are on [`ArcBlend`]); its shape does not depend on any knot. The knots
//! only decide how fast each segment is traversed. The book's knot rule (Algorithm 8.1) makes
//! every segment affine in `t` and multiplies ratios along the whole sequence,
//! `Δ_i = Δ_{i−1}·ψ_{i−1}/φ_{i−1}`; on random data `ln Δ_i` is a random walk. On random walks of
//! keys 0.05–0.5 rad apart the spacings of the first 1 000 keys span 5 to 25 orders of
//! magnitude, and somewhere between a few hundred and a few thousand keys two knots round to
//! the same `f64`. The other timings ([`ArcBlendTiming`]) trace the **same curve** and stay Cⁿ in `t`
//! through a time warp per segment. The derivation, ours (the book gives only the affine rule):
//!
//! **Joints.** Near the key `p_i` (`1 ≤ i ≤ k − 1`) both neighbouring segments follow circle
//! `i − 1`, with rotation group `G`, to order `n`: `w₁,ₙ(u) − u` and `w₂,ₙ(u)` vanish to order
//! `n + 1` at `u = 1`, and `w₁,ₙ(u)`, `w₂,ₙ(u) − u` at `u = 0` (§7.6, Theorems 4–5), so
//!
//! ```text
//! X_{i−1}(u) = G((u − 1)·φ_{i−1}) p_i + O((1 − u)^{n+1})     end of segment i − 1
//! X_i(u)     = G(u·ψ_{i−1}) p_i       + O(u^{n+1})           start of segment i
//! ```
//!
//! With `h_i = t_{i+1} − t_i`, `s = (t − t_i)/h_i` and `u = σ_i(s)` on segment `i`, the curve is
//! `G(θ(t)) p_i` up to `O((t − t_i)^{n+1})` on either side, with the angle `θ_L = φ_{i−1}·(σ_{i−1}(s) − 1)`
//! on the left and `θ_R = ψ_{i−1}·σ_i(s)` on the right. `θ ↦ G(θ)p_i` is an immersion, so by
//! Faà di Bruno's formula the curve is Cⁿ at `t_i` exactly when `θ_L` and `θ_R` agree to order
//! `n`. We take warps with `σ^{(m)} = 0` at both ends for `m = 2…n`; the condition is then the
//! one equation of angular speeds
//!
//! ```text
//! φ_{i−1}·σ_{i−1}′(1)/h_{i−1} = ψ_{i−1}·σ_i′(0)/h_i
//! ```
//!
//! The book takes `σ = id` and solves for `h_i` (the ratio product). Any other spacing works
//! with `ρ_i = (φ_{i−1}/ψ_{i−1})·(h_i/h_{i−1})`, `A_i = σ_i′(0) = min(1, ρ_i)` and
//! `B_{i−1} = σ_{i−1}′(1) = min(1, 1/ρ_i)`: at each key the curve runs at the slower of the two
//! neighbours' mean speeds (`A_0 = B_{k−1} = 1` at the ends). Where `ρ_i = 1` nothing is warped.
//!
//! **The warp.** With Pobegailo's braking polynomial `w₂ = w₂,ₙ` (degree `2n + 1`):
//!
//! ```text
//! σ(s) = s + (A − 1)·w₂(s) + (1 − B)·w₂(1 − s)
//! σ(0) = 0, σ(1) = 1, σ′(0) = A, σ′(1) = B, σ^{(m)}(0) = σ^{(m)}(1) = 0 (m = 2…n)
//! ```
//!
//! from `w₂(0) = w₂(1) = 0`, `w₂′(0) = 1`, `w₂′(1) = 0` and `w₂^{(m)} = 0` at both ends for
//! `m = 2…n`. It is increasing: `σ′ = 1 − (1 − A)·w₂′(s) − (1 − B)·w₂′(1 − s)` is affine in
//! `(A, B) ∈ (0, 1]²`, hence a convex combination of its values at the four corners, with weight
//! `A·B` on the corner `(1, 1)` where it is 1. The other corners are `1 − w₂′(s)`,
//! `1 − w₂′(1 − s)` and `1 − w₂′(s) − w₂′(1 − s)`, all ≥ 0: `w₂′ = 1 − Sₙ − u·Sₙ′ ≤ 1`, and
//! `w₂″ = −c·u^{n−1}(1 − u)^{n−1}·((n + 1) − (2n + 1)u)` (`c > 0`), so `w₂′` falls from 1 to its
//! minimum at `u = (n + 1)/(2n + 1)` and rises to `w₂′(1) = 0`; it is negative from its only zero
//! on, and that zero is below ½ because `w₂′(½) = (1 − P)/2 − n·P < 0` with
//! `P = C(2n, n)/4ⁿ` (equivalent to `(2n + 1)·P > 1`, true for `n = 1` and increasing in `n`).
//! So `w₂′(s)` and `w₂′(1 − s)` are never both positive, and `σ′ ≥ A·B > 0`: a regular
//! reparametrisation. The derivatives in `t` follow by the chain rule (`jet_at`) or by composing
//! truncated Taylor series ([`ArcBlend::derivatives`], exact to rounding for any order).
//!
//! **What is Cⁿ in which parameter.** In every timing the curve is Cⁿ in `t` at every key and
//! analytic between keys (generically not Cⁿ⁺¹: neither the blend nor the warp matches order
//! `n + 1`), and its trace is the book's curve, which is Gⁿ whatever the spacings. In the book's
//! timing it is moreover affine in each segment's `u` and turns at one angular speed along each
//! circle across its key; in the others it is affine in `u` only where the warp is the identity.
//!
//! **Cost.** Construction is linear in the number of keys with no products along the sequence;
//! a warped evaluation adds two evaluations of `w₂` to the segment's.

use crate::ambient::Ambient;
use crate::circle::{COINCIDENT_TOLERANCE, CircleArc};
use crate::curve::{Jet, Side};
use crate::error::SplineError;
use crate::flow::{PlaneRotation, Segment, Weights};
use crate::knots::Knots;
use crate::manifold::{Manifold, renormalize};
#[cfg(any(test, feature = "compact"))]
use crate::recast::{Recast, to_sm};
use crate::smoothing::SmoothingPolynomials;

/// The largest continuity order accepted by the spline constructors.
pub const MAX_SMOOTHNESS: usize = 10;

/// Checks `1 ≤ smoothness ≤ MAX_SMOOTHNESS`.
pub(crate) fn check_smoothness(smoothness: usize) -> Result<SmoothingPolynomials, SplineError> {
    if smoothness == 0 || smoothness > MAX_SMOOTHNESS {
        return Err(SplineError::InvalidParameter {
            name: "smoothness",
            reason: format!("must be an integer from 1 to {MAX_SMOOTHNESS}, got {smoothness}"),
        });
    }
    SmoothingPolynomials::try_new(smoothness)
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

/// [`check_neighbours`] for a closed loop: also the last and the first point
/// ([`SplineError::CoincidentClosing`], [`SplineError::AntipodalClosing`]).
pub(crate) fn check_loop_neighbours<P: Manifold>(
    points: &[P],
    min: usize,
) -> Result<(), SplineError> {
    check_neighbours(points, min)?;
    let (p, q) = (points[points.len() - 1].to_vector(), points[0].to_vector());
    if (q - p).length() <= COINCIDENT_TOLERANCE {
        return Err(SplineError::CoincidentClosing);
    }
    if points[points.len() - 1].is_antipodal(&points[0]) {
        return Err(SplineError::AntipodalClosing);
    }
    Ok(())
}

/// How the parameter `t` of an [`ArcBlend`] runs through its keys: the knots `t₀ < … < t_k`
/// with `r(t_i) = p_i`. Every timing traces the same curve and is Cⁿ in `t` (module docs,
/// *Timing*); they differ in speed only.
///
/// | timing | knots | segments |
/// |---|---|---|
/// | `Book` | `t₀ = 0`, `t₁ = φ₀`, `Δ_i = Δ_{i−1}·ψ_{i−1}/φ_{i−1}` (Algorithm 8.1) | affine in `t` |
/// | `ArcLength` | cumulative mean length of the two circle arcs each segment blends | warped |
/// | `Uniform` | `t_i = i` | warped |
/// | `Knots` | given | warped |
/// | `Auto` | `Book` while well-conditioned, else `ArcLength`, else `Uniform` | |
///
/// **Closed loops** ([`ArcBlend::try_with_closed`]) have one knot more than points, the last
/// the time of the return to `p₀`, and every timing is solved around the loop rather than
/// propagated from the first key: at every key, the seam included, the warp of the module docs
/// makes the two neighbouring segments meet to order `n` for the given spacings. `ArcLength`,
/// `Uniform` and `Knots` therefore close every loop. `Book` carries the first spacing around by
/// the ratios `ψ_j/φ_j` and comes back multiplied by their product `Π = ∏ ψ_j/φ_j`; it is
/// accepted when `|Π − 1| ≤` [`CLOSURE_TOLERANCE`](Self::CLOSURE_TOLERANCE) (points on one circle:
/// `ψ_j = φ_{j+1}` and the product telescopes to 1), and otherwise fails with
/// [`SplineError::TimingNotClosed`]; the warps then absorb the rounding, so the seam is exact.
/// `Auto` takes `Book` when it closes and is well-conditioned, else `ArcLength`, else `Uniform`.
///
/// A knot sequence is *well-conditioned* here when
/// `max(|t₀|, |t_k|)/min_i (t_{i+1} − t_i) ≤` [`CONDITION_LIMIT`](Self::CONDITION_LIMIT) `= 1e8`:
/// rounding `t` to `f64` then moves a segment's local parameter by at most about 1e-8. Long
/// random sequences leave that range with the book's knots after a few hundred keys, while
/// arc-length knots stay in it for any length of ordinary data (it is about `k ×` mean step /
/// shortest step).
///
/// **Speed of the warped timings.** At a key the curve runs at the slower of its two
/// neighbouring segments' mean speeds (module docs); inside a segment the speed follows the
/// blend, which moves along two circle arcs of possibly very different lengths (a triple that
/// turns back has a circle looping almost all the way round). With `ArcLength` the speed is
/// exactly 1 on a circle and at the first and last keys; on a random walk of 10 000 directions
/// with steps of 0.05–0.5 rad it has median 1.02, 80 % of the parameter between 0.57 and 1.97,
/// and extremes 0.002 and 4.2 (test `arc_blend_ten_thousand_directions_used_to_fail` bounds it).
///
/// # Examples
///
/// ```
/// use spherekit::{ArcBlend, ArcBlendTiming, Curve, Manifold, S2Point, Side, glam::DVec3};
///
/// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let points = vec![p(1.0, 0.0, 0.3), p(0.6, 0.8, 0.4), p(-0.2, 1.0, 0.1), p(-0.9, 0.3, -0.2)];
/// let book = ArcBlend::try_new(points.clone(), 2).unwrap();
/// assert_eq!(book.timing(), ArcBlendTiming::Book); // short data: the book's knots
/// let uniform = ArcBlend::try_with(points.clone(), 2, ArcBlendTiming::Uniform).unwrap();
/// assert_eq!(uniform.knots(), [0.0, 1.0, 2.0, 3.0]);
/// // The same curve: the midpoint of segment 1 in its local parameter is passed by both.
/// let on_book = (0..=1000).map(|j| {
///     let t = book.knots()[1] + (book.knots()[2] - book.knots()[1]) * f64::from(j) / 1000.0;
///     uniform.eval(1.5).dist(&book.eval(t))
/// });
/// assert!(on_book.fold(f64::MAX, f64::min) < 1e-3);
/// // C² at the keys in the uniform parameter too.
/// let (l, r) = (uniform.jet_at(2.0, Side::Left), uniform.jet_at(2.0, Side::Right));
/// assert!((l.velocity - r.velocity).length() < 1e-12);
/// assert!((l.acceleration - r.acceleration).length() < 1e-11);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
#[non_exhaustive]
pub enum ArcBlendTiming {
    /// The book's knots while they are well-conditioned, else [`ArcLength`](Self::ArcLength)
    /// while that is, else [`Uniform`](Self::Uniform). Never fails. The default, and what
    /// [`ArcBlend::try_new`] uses.
    #[default]
    Auto,
    /// The book's knots, `t₀ = 0`, `t₁ = φ₀`, `t_{i+1} = t_i + (ψ_{i−1}/φ_{i−1})·(t_i − t_{i−1})`:
    /// every segment is affine in `t`, and the curve starts at unit angular speed along the
    /// first circle. Fails with [`SplineError::TimingNotRepresentable`] where the product of
    /// the ratios leaves what `f64` knots can hold.
    Book,
    /// Knots at the cumulative length of the circle arcs: segment `i` gets the mean of the
    /// lengths `ρ·angle` of its two arcs from `p_i` to `p_{i+1}` (on the circles of the triples
    /// ending and starting there; the end segments have one arc), an approximate arc length.
    /// The speed averages about 1 (see *Speed* above). Fails
    /// with [`SplineError::TimingNotRepresentable`] when an arc is too short to be added to the
    /// length before it in `f64`.
    ArcLength,
    /// The knots `0, 1, …, k`. Never fails.
    Uniform,
    /// The given knots, one per point, strictly increasing (validated as [`Knots::try_new`]).
    Knots(Vec<f64>),
}

impl ArcBlendTiming {
    /// The largest `max(|t₀|, |t_k|)/min spacing` of well-conditioned knots (see the type docs).
    pub const CONDITION_LIMIT: f64 = 1e8;

    /// The largest `|Π − 1|` for which the book's knots close a loop (see the type docs).
    pub const CLOSURE_TOLERANCE: f64 = 1e-9;

    /// The timing's name: `"auto"`, `"book"`, `"arc-length"`, `"uniform"` or `"knots"`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Book => "book",
            Self::ArcLength => "arc-length",
            Self::Uniform => "uniform",
            Self::Knots(_) => "knots",
        }
    }
}

/// The time warp `u = σ(s) = s + a·w₂(s) + b·w₂(1 − s)` of one segment, `a = A − 1`,
/// `b = 1 − B` (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Warp {
    a: f64,
    b: f64,
}

impl Warp {
    /// `A = σ′(0)`, `B = σ′(1)`.
    fn new(start_slope: f64, end_slope: f64) -> Self {
        Self {
            a: start_slope - 1.0,
            b: 1.0 - end_slope,
        }
    }

    fn is_identity(self) -> bool {
        self.a == 0.0 && self.b == 0.0
    }

    /// `σ(s)`, exactly 0 at 0 and 1 at 1.
    #[inline]
    fn value(self, poly: SmoothingPolynomials, s: f64) -> f64 {
        if self.is_identity() {
            return s;
        }
        (s + self.a * poly.w2(s) + self.b * poly.w2(1.0 - s)).clamp(0.0, 1.0)
    }

    /// `[σ, σ′, σ″]` at `s`.
    #[inline]
    fn jet(self, poly: SmoothingPolynomials, s: f64) -> [f64; 3] {
        if self.is_identity() {
            return [s, 1.0, 0.0];
        }
        let (_, w) = poly.jets(s);
        let (_, v) = poly.jets(1.0 - s);
        [
            (s + self.a * w[0] + self.b * v[0]).clamp(0.0, 1.0),
            1.0 + self.a * w[1] - self.b * v[1],
            self.a * w[2] + self.b * v[2],
        ]
    }

    /// `σ^{(k)}(s)` for `k = 0…=m`.
    fn derivatives(self, poly: SmoothingPolynomials, s: f64, m: usize) -> Vec<f64> {
        (0..=m)
            .map(|k| match k {
                0 => self.value(poly, s),
                _ => {
                    let sign = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
                    let linear = if k == 1 { 1.0 } else { 0.0 };
                    linear
                        + self.a * poly.w2_derivative(s, k)
                        + sign * self.b * poly.w2_derivative(1.0 - s, k)
                }
            })
            .collect()
    }
}

/// `max(|t₀|, |t_k|)/min spacing` of increasing knots.
fn condition(t: &[f64]) -> f64 {
    let min = t
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    t[0].abs().max(t[t.len() - 1].abs()) / min
}

/// Cumulative sums `0, w₀, w₀ + w₁, …`.
fn cumulative(widths: &[f64]) -> Vec<f64> {
    let mut t = Vec::with_capacity(widths.len() + 1);
    t.push(0.0);
    for (i, w) in widths.iter().enumerate() {
        t.push(t[i] + w);
    }
    t
}

/// The knots from `widths`, or the error of the `timing` naming the first point without a knot
/// of its own.
fn timing_knots(timing: &'static str, widths: &[f64]) -> Result<Knots, SplineError> {
    let t = cumulative(widths);
    Knots::try_new(t.clone()).map_err(|e| {
        let index = match e {
            SplineError::InvalidKnot { index }
            | SplineError::KnotsNotIncreasing { index }
            | SplineError::KnotSpacing { index } => index.max(1),
            _ => 1,
        };
        SplineError::TimingNotRepresentable {
            timing,
            index,
            spacing: widths[index - 1],
            ratio: widths[index - 1] / widths[0],
            knot: t[index - 1],
        }
    })
}

/// Pobegailo's interpolating Cⁿ spline through points `p₀, …, p_k` (`k ≥ 2`) of a sphere,
/// blending the circle arcs through consecutive triples.
///
/// Source: A. P. Pobegailo, *Application of quaternions in computer geometry and graphics*
/// (Belarusian State University, Minsk, 2019), §7.10 (splines on manifolds), §8.4
/// (Algorithm 8.1, on S²) and §9.4 (Algorithm 9.1, on S³); the construction goes back to
/// A. P. Pobegailo, "Spherical splines and orientation interpolation", *The Visual Computer*
/// 11(1) (1994) 63–68. For triple `j = 0…k−2` let `𝒢_j` be the rotation group of the circle
/// through `p_j, p_{j+1}, p_{j+2}` ([`CircleArc`]), with central angles `φ_j` (`p_j → p_{j+1}`)
/// and `ψ_j` (`p_{j+1} → p_{j+2}`). Segment `i` runs from `p_i` to `p_{i+1}` with the local
/// parameter `u ∈ [0, 1]`:
///
/// ```text
/// segment 0:   X₀(u) = 𝒢₀(u·φ₀) p₀
/// segment i:   X_i(u) = 𝒢_i(w₁,ₙ(u)·φ_i) · 𝒢_{i−1}(w₂,ₙ(u)·ψ_{i−1}) · p_i      (1 ≤ i ≤ k−2)
/// segment k−1: X_{k−1}(u) = 𝒢_{k−2}(u·ψ_{k−2}) p_{k−1}
/// book knots:  t₀ = 0,  t₁ = φ₀,  t_{i+1} = t_i + (ψ_{i−1}/φ_{i−1})·(t_i − t_{i−1}),  u = (t − t_i)/(t_{i+1} − t_i)
/// ```
///
/// The end follower (circle `i`, weight `w₁`) is the left factor and the start follower (circle
/// `i−1`, weight `w₂`) acts first. The book's knot rule makes the two arcs of circle `i−1` that
/// meet at `p_i` turn at the same angular speed, so the curve is **Cⁿ** at every knot (and in
/// general not Cⁿ⁺¹); between knots it is analytic. Derivatives are exact.
///
/// **Timing.** The book's knots multiply the ratios `ψ/φ` along the whole sequence and cannot
/// be represented in `f64` beyond a few thousand random keys. [`try_new`](Self::try_new) uses
/// them while they are well-conditioned and otherwise arc-length knots (or uniform ones) with a
/// Cⁿ time warp per segment: the same curve, Cⁿ in `t`, for any number of keys, built in linear
/// time. [`try_with`](Self::try_with) chooses; see [`ArcBlendTiming`] and the module
/// docs (*Timing*) for the derivation and what is Cⁿ in which parameter.
///
/// Properties: interpolation `r(t_i) = p_i`; points on one circle (in order) give back that
/// circle at unit angular speed (book timing); three points give the single arc; equivariant
/// under orthogonal maps of the ambient space (with identical knots); shape-local (segment `i`
/// depends on `p_{i−1} … p_{i+2}`); with the book's knots the knot spacing carries the ratios
/// `ψ_j/φ_j` forward, with the other timings it is local too.
///
/// On S² ([`S2Point`](crate::S2Point)) `𝒢_j = R(â_j, ·)`, the rotation about the circle's axis.
/// On S³ ([`UnitQuat`](crate::UnitQuat)) `𝒢_j` is the simple rotation of ℝ⁴ in the circle's
/// plane, so that circle `i−1`'s group acts in its own frame; the literal reading of the book's
/// Procedure 9.4, which applies circle `i−1`'s rotation in circle `i`'s frame, is only C⁰. Keys
/// are used as given (no sign flips): the spline interpolates these points of S³. The same
/// construction works on S^m ([`SmPoint`](crate::SmPoint)).
///
/// Readings of the book followed here: the forward circle carries `w₁`; the triple of axis `j`
/// is `(p_j, p_{j+1}, p_{j+2})`; knots by Algorithm 8.1 (the §7.10 recurrence is shifted by one
/// index) also on S³, where the book gives none; `k = 2` builds no blended segment.
///
/// Antipodal neighbours are rejected (on S³ they are the same orientation); on S² the circle
/// through them would be a great circle.
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
    /// One warp per segment (whose `Segment::width` is then 1), or empty for the book's affine
    /// segments (whose `width` is the knot spacing).
    warps: Vec<Warp>,
    timing: Resolved,
    closed: bool,
}

/// The timing an [`ArcBlend`] was built with (`Auto` resolved).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Resolved {
    Book,
    ArcLength,
    Uniform,
    Knots,
}

impl<P: Manifold> ArcBlend<P> {
    /// The default smoothness (C²).
    pub const DEFAULT_SMOOTHNESS: usize = 2;

    /// Builds the Cⁿ spline (`n = smoothness`) through `points` with the [`ArcBlendTiming::Auto`]
    /// timing: the book's knots, starting at 0, while they are well-conditioned, otherwise
    /// arc-length (or uniform) knots with the same curve.
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 3 points;
    /// - [`SplineError::InvalidParameter`] (`smoothness`) unless `1 ≤ smoothness ≤ 10`;
    /// - [`SplineError::Coincident`] for equal consecutive points;
    /// - [`SplineError::Antipodal`] for antipodal consecutive points;
    /// - [`SplineError::NoCircle`] when `p_j = p_{j+2}` (no unique circle through the triple).
    pub fn try_new(points: Vec<P>, smoothness: usize) -> Result<Self, SplineError> {
        Self::try_with(points, smoothness, ArcBlendTiming::Auto)
    }

    /// Builds the Cⁿ spline (`n = smoothness`) through `points` with the given timing.
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new), and
    /// - [`SplineError::TimingNotRepresentable`] for [`ArcBlendTiming::Book`] or
    ///   [`ArcBlendTiming::ArcLength`] when a key gets no knot of its own in `f64`;
    /// - for [`ArcBlendTiming::Knots`]: [`SplineError::KnotCount`] unless there is one knot per
    ///   point, and the errors of [`Knots::try_new`].
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{ArcBlend, ArcBlendTiming, Curve, Manifold, S2Point, glam::DVec3};
    ///
    /// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
    /// let points = vec![p(1.0, 0.0, 0.3), p(0.6, 0.8, 0.4), p(-0.2, 1.0, 0.1), p(-0.9, 0.3, -0.2)];
    /// let times = vec![0.0, 2.0, 3.0, 7.0];
    /// let c = ArcBlend::try_with(points.clone(), 3, ArcBlendTiming::Knots(times)).unwrap();
    /// assert!(c.eval(3.0).dist(&points[2]) < 1e-15);
    /// let d = ArcBlend::try_with(points, 3, ArcBlendTiming::ArcLength).unwrap();
    /// assert!((d.jet(0.0).velocity.length() - 1.0).abs() < 1e-12); // unit speed at the start
    /// ```
    pub fn try_with(
        points: Vec<P>,
        smoothness: usize,
        timing: ArcBlendTiming,
    ) -> Result<Self, SplineError> {
        check_neighbours(&points, 3)?;
        Self::build(points, smoothness, timing, false)
    }

    /// Builds the closed Cⁿ loop through `points` (`p₀ … p_{m−1}`, m ≥ 3) with the
    /// [`ArcBlendTiming::Auto`] timing.
    ///
    /// # Errors
    ///
    /// As [`try_with_closed`](Self::try_with_closed).
    pub fn try_new_closed(points: Vec<P>, smoothness: usize) -> Result<Self, SplineError> {
        Self::try_with_closed(points, smoothness, ArcBlendTiming::Auto)
    }

    /// Builds the closed Cⁿ loop `p₀ → p₁ → … → p_{m−1} → p₀` (m ≥ 3) with the given timing.
    ///
    /// The triples wrap around the end: circle `j` passes through `p_j, p_{j+1}, p_{j+2}`
    /// (indices mod m) for `j = 0 … m−1`, and every segment, the closing one `p_{m−1} → p₀`
    /// included, is the blend `X_i(u) = 𝒢_i(w₁,ₙ(u)·φ_i)·𝒢_{i−1}(w₂,ₙ(u)·ψ_{i−1})·p_i` of the
    /// type docs with `𝒢_{−1} = 𝒢_{m−1}`: the loop is Cⁿ at every key and at the seam. The knots
    /// `t₀ < … < t_m` (one more than points) and the seam are solved as
    /// [`ArcBlendTiming`] describes under *Closed loops*. Points on one circle give that
    /// circle (with the book's knots, at unit angular speed).
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 3 points;
    /// - [`SplineError::InvalidParameter`] (`smoothness`) unless `1 ≤ smoothness ≤ 10`;
    /// - [`SplineError::Coincident`] / [`SplineError::Antipodal`] for coincident or antipodal
    ///   consecutive points, [`SplineError::CoincidentClosing`] /
    ///   [`SplineError::AntipodalClosing`] for the last and the first;
    /// - [`SplineError::NoCircle`] when `p_j = p_{j+2}`, [`SplineError::NoCircleAround`] for a
    ///   triple that wraps around the end;
    /// - [`SplineError::TimingNotClosed`] for [`ArcBlendTiming::Book`] when the book's knots do
    ///   not close, [`SplineError::TimingNotRepresentable`] as for open curves;
    /// - for [`ArcBlendTiming::Knots`]: [`SplineError::KnotCount`] unless there are `m + 1`
    ///   knots, and the errors of [`Knots::try_new`].
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, ArcBlend, ArcBlendTiming, Curve, Manifold, S2Point, glam::DVec3};
    ///
    /// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
    /// let points = vec![p(1.0, 0.0, 0.3), p(0.2, 0.9, 0.4), p(-0.8, 0.4, 0.1), p(-0.3, -0.9, 0.5)];
    /// let c = ArcBlend::try_with_closed(points.clone(), 3, ArcBlendTiming::Uniform).unwrap();
    /// assert_eq!(c.knots(), [0.0, 1.0, 2.0, 3.0, 4.0]);
    /// assert!(c.eval(4.0).dist(&points[0]) < 1e-15);
    /// let seam = continuity(&c)[3]; // the seam at t = 4, C³ (checked here to order 2)
    /// assert!(seam.t == 4.0 && seam.c1 < 1e-12 && seam.c2 < 1e-11);
    /// ```
    pub fn try_with_closed(
        points: Vec<P>,
        smoothness: usize,
        timing: ArcBlendTiming,
    ) -> Result<Self, SplineError> {
        check_loop_neighbours(&points, 3)?;
        Self::build(points, smoothness, timing, true)
    }

    /// The construction of [`try_with`](Self::try_with) and
    /// [`try_with_closed`](Self::try_with_closed), on checked points: on `P` itself, or with
    /// the `compact` feature once on S^m for every point type ([`crate::recast`]; the same
    /// bits, `tests::the_construction_gives_the_same_bits_on_sm`).
    fn build(
        points: Vec<P>,
        smoothness: usize,
        timing: ArcBlendTiming,
        closed: bool,
    ) -> Result<Self, SplineError> {
        #[cfg(not(feature = "compact"))]
        return Self::construct(points, smoothness, timing, closed);
        #[cfg(feature = "compact")]
        return Self::construct_on_sm(points, smoothness, timing, closed);
    }

    /// [`construct`](Self::construct) on the keys as points of S^m, the result converted back.
    #[cfg(any(test, feature = "compact"))]
    fn construct_on_sm(
        points: Vec<P>,
        smoothness: usize,
        timing: ArcBlendTiming,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let to = Recast::to(&points[0]);
        let sm = points.iter().map(to_sm).collect();
        let c = ArcBlend::construct(sm, smoothness, timing, closed)?;
        Ok(Self {
            points: to.points(&c.points),
            knots: c.knots,
            poly: c.poly,
            circles: c.circles.iter().map(|a| a.recast(&to)).collect(),
            segments: c.segments.iter().map(|g| g.recast(&to)).collect(),
            warps: c.warps,
            timing: c.timing,
            closed: c.closed,
        })
    }

    /// The construction of [`build`](Self::build) on `P`.
    fn construct(
        mut points: Vec<P>,
        smoothness: usize,
        timing: ArcBlendTiming,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let poly = check_smoothness(smoothness)?;
        let m = points.len();
        let triples = if closed { m } else { m - 2 };
        let circles = (0..triples)
            .map(|j| {
                let [a, b, c] = [j, (j + 1) % m, (j + 2) % m];
                CircleArc::through(&points[a], &points[b], &points[c]).map_err(|e| match e {
                    SplineError::NoCircle { .. } if c < a => SplineError::NoCircleAround {
                        first: a,
                        middle: b,
                        last: c,
                    },
                    SplineError::Coincident { index } if (j + index) % m == m - 1 && closed => {
                        SplineError::CoincidentClosing
                    }
                    SplineError::Coincident { index } => SplineError::Coincident {
                        index: (j + index) % m,
                    },
                    SplineError::NoCircle { index } => SplineError::NoCircle { index: j + index },
                    e => e,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        // Segments: k = m − 1 open, m closed (the closing one last).
        let k = if closed { m } else { m - 1 };
        let book_knots = || -> Result<Knots, SplineError> {
            let widths = book_widths(&circles, k);
            if closed {
                let c = &circles[m - 1];
                let ratio = widths[m - 1] * (c.second_angle() / c.first_angle()) / widths[0];
                let closes = (ratio - 1.0).abs() <= ArcBlendTiming::CLOSURE_TOLERANCE;
                if !closes {
                    return Err(SplineError::TimingNotClosed {
                        timing: "book",
                        ratio,
                    });
                }
            }
            timing_knots("book", &widths)
        };
        let arc_knots = || timing_knots("arc-length", &arc_length_widths(&circles, k, closed));
        let (knots, resolved) = match timing {
            ArcBlendTiming::Book => (book_knots()?, Resolved::Book),
            ArcBlendTiming::ArcLength => (arc_knots()?, Resolved::ArcLength),
            ArcBlendTiming::Uniform => (Knots::uniform(k + 1), Resolved::Uniform),
            ArcBlendTiming::Knots(t) => {
                if t.len() != k + 1 {
                    return Err(SplineError::KnotCount {
                        expected: k + 1,
                        got: t.len(),
                    });
                }
                (Knots::try_new(t)?, Resolved::Knots)
            }
            ArcBlendTiming::Auto => {
                let good = |r: Result<Knots, SplineError>| {
                    r.ok()
                        .filter(|t| condition(t.as_slice()) <= ArcBlendTiming::CONDITION_LIMIT)
                };
                if let Some(t) = good(book_knots()) {
                    (t, Resolved::Book)
                } else if let Some(t) = good(arc_knots()) {
                    (t, Resolved::ArcLength)
                } else {
                    (Knots::uniform(k + 1), Resolved::Uniform)
                }
            }
        };
        // The book's open segments are affine in t; every other curve is warped, the book's
        // closed loop too (its warps are within the closure tolerance of the identity and make
        // the seam exact).
        let book = resolved == Resolved::Book && !closed;
        let segments = (0..k)
            .map(|i| {
                // The affine segments are built in t, the warped ones in u (width 1).
                let width = if book { knots.width(i) } else { 1.0 };
                if !closed && i == 0 {
                    Segment {
                        base: points[0].to_vector(),
                        outer: circles[0].flow().clone(),
                        outer_angle: circles[0].first_angle(),
                        inner: None,
                        weights: Weights::Linear,
                        width,
                    }
                } else if !closed && i == k - 1 {
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
                    let (c, prev) = (&circles[i], &circles[(i + triples - 1) % triples]);
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
        let warps = if book {
            Vec::new()
        } else {
            warps(&circles, &knots, closed)
        };
        if closed {
            points.push(points[0].clone());
        }
        Ok(Self {
            points,
            knots,
            poly,
            circles,
            segments,
            warps,
            timing: resolved,
            closed,
        })
    }

    /// The interpolated points (for a closed loop without the repeated first one).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points[..self.points.len() - usize::from(self.closed)]
    }

    /// The knots `t₀ < t₁ < … < t_k` where the curve passes the points (`t₀ = 0` except for
    /// given knots; a closed loop has one more, the time of the return to `p₀`).
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }

    /// The timing the curve was built with; [`ArcBlendTiming::Auto`] is resolved to the one it
    /// chose, and [`ArcBlendTiming::Knots`] carries a copy of the knots.
    #[must_use]
    pub fn timing(&self) -> ArcBlendTiming {
        match self.timing {
            Resolved::Book => ArcBlendTiming::Book,
            Resolved::ArcLength => ArcBlendTiming::ArcLength,
            Resolved::Uniform => ArcBlendTiming::Uniform,
            Resolved::Knots => ArcBlendTiming::Knots(self.knots().to_vec()),
        }
    }

    /// The smoothness `n`: the curve is Cⁿ at its joints.
    #[must_use]
    pub fn smoothness(&self) -> usize {
        self.poly.order()
    }

    /// The derivatives of orders `0…=order` at `t` with respect to `t` (ambient vectors; order 0
    /// is the point), exactly, for any order; at a joint the one-sided values from `side`.
    /// Used to check continuity beyond the second derivative of [`Curve::jet_at`](crate::Curve::jet_at).
    #[must_use]
    pub fn derivatives(&self, t: f64, side: Side, order: usize) -> Vec<P::Vector> {
        let (i, s) = self.knots.locate(t, side);
        let Some(&warp) = self.warps.get(i) else {
            return self.segments[i].derivatives(self.poly, s, order);
        };
        // x(t) = X(σ(s)), s = (t − t_i)/h: compose the Taylor series of X at u = σ(s) with the
        // series δu = Σ_j c_j δtʲ, c_j = σ^{(j)}(s)/(j!·hʲ).
        let sigma = warp.derivatives(self.poly, s, order);
        let xs = self.segments[i].derivatives(self.poly, sigma[0], order);
        let h = self.knots.width(i);
        let mut c = vec![0.0; order + 1];
        let mut scale = 1.0;
        for j in 1..=order {
            scale *= j as f64 * h;
            c[j] = sigma[j] / scale;
        }
        // power[j] = [δtʲ] (δu)ᵏ for the current k, starting with k = 1.
        let mut power = c.clone();
        let mut out: Vec<P::Vector> = vec![xs[0].zeros_like(); order + 1];
        out[0] = xs[0].clone();
        let mut factorial = 1.0;
        for (k, x) in xs.iter().enumerate().skip(1) {
            factorial *= k as f64;
            let coefficient = x.clone() * (1.0 / factorial);
            for j in k..=order {
                out[j] += coefficient.clone() * power[j];
            }
            // power ← power·c (both start at order ≥ 1).
            let mut next = vec![0.0; order + 1];
            for a in k..=order {
                for b in 1..=order - a {
                    next[a + b] += power[a] * c[b];
                }
            }
            power = next;
        }
        // Taylor coefficients to derivatives.
        let mut factorial = 1.0;
        for (j, v) in out.iter_mut().enumerate().skip(1) {
            factorial *= j as f64;
            *v = v.clone() * factorial;
        }
        out
    }

    /// The circles through the consecutive triples `(p_j, p_{j+1}, p_{j+2})` (for a closed loop
    /// also the two that wrap around the end, indices mod m).
    #[must_use]
    pub fn circles(&self) -> &[CircleArc<P>] {
        &self.circles
    }
}

/// The book's spacings `Δ₀ = φ₀`, `Δ_i = Δ_{i−1}·ψ_{i−1}/φ_{i−1}` (Algorithm 8.1), for `k`
/// segments.
fn book_widths<P: Manifold>(circles: &[CircleArc<P>], k: usize) -> Vec<f64> {
    let mut widths = Vec::with_capacity(k);
    widths.push(circles[0].first_angle());
    for i in 1..k {
        let c = &circles[i - 1];
        widths.push(widths[i - 1] * (c.second_angle() / c.first_angle()));
    }
    widths
}

/// The mean lengths of the two circle arcs of each of the `k` segments (one arc at the ends of
/// an open curve).
fn arc_length_widths<P: Manifold>(circles: &[CircleArc<P>], k: usize, closed: bool) -> Vec<f64> {
    let first = |c: &CircleArc<P>| c.radius() * c.first_angle();
    let second = |c: &CircleArc<P>| c.radius() * c.second_angle();
    let n = circles.len();
    (0..k)
        .map(|i| {
            if closed {
                0.5 * (second(&circles[(i + n - 1) % n]) + first(&circles[i]))
            } else if i == 0 {
                first(&circles[0])
            } else if i == k - 1 {
                second(&circles[k - 2])
            } else {
                0.5 * (second(&circles[i - 1]) + first(&circles[i]))
            }
        })
        .collect()
}

/// The warps making the segments Cⁿ across the keys for the spacings of `knots` (module docs):
/// at key `i`, `ρ_i = (φ_{i−1}/ψ_{i−1})·(h_i/h_{i−1})`, `A_i = min(1, ρ_i)`,
/// `B_{i−1} = min(1, 1/ρ_i)`; `A₀ = B_{k−1} = 1` for an open curve, while a closed one has the
/// same condition at the seam (key 0 with `h₋₁ = h_{k−1}` and circle `k − 1`).
fn warps<P: Manifold>(circles: &[CircleArc<P>], knots: &Knots, closed: bool) -> Vec<Warp> {
    let k = knots.segment_count();
    let mut start = vec![1.0; k];
    let mut end = vec![1.0; k];
    let first_key = usize::from(!closed);
    for (i, a) in start.iter_mut().enumerate().skip(first_key) {
        let prev = (i + k - 1) % k;
        let c = &circles[prev];
        let rho = (c.first_angle() / c.second_angle()) * (knots.width(i) / knots.width(prev));
        if rho < 1.0 {
            *a = rho;
        } else if rho > 1.0 {
            end[prev] = 1.0 / rho;
        }
    }
    start
        .into_iter()
        .zip(end)
        .map(|(a, b)| Warp::new(a, b))
        .collect()
}

crate::curve::piecewise_curve! {
    impl [P: Manifold] for ArcBlend<P> {
        type Point = P;
    }
}

impl<P: Manifold> ArcBlend<P> {
    fn jet_local(&self, i: usize, s: f64) -> Jet<P> {
        let (p, velocity, acceleration) = match self.warps.get(i) {
            None => self.segments[i].jet(self.poly, s),
            Some(&warp) => {
                // Chain rule: x′ = X′·σ′/h, x″ = X″·(σ′/h)² + X′·σ″/h².
                let [u, d1, d2] = warp.jet(self.poly, s);
                let (p, x1, x2) = self.segments[i].jet(self.poly, u);
                let h = self.knots.width(i);
                let k1 = d1 / h;
                let k2 = d2 / (h * h);
                let v = x1.clone() * k1;
                (p, v, x2 * (k1 * k1) + x1 * k2)
            }
        };
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
        let u = self.warps.get(i).map_or(s, |w| w.value(self.poly, s));
        P::from_vector_unchecked(renormalize(self.segments[i].point(self.poly, u)))
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
                    check_loop_neighbours(points, 3)
                } else {
                    check_neighbours(points, 3)
                };
                if checked.is_err() {
                    continue;
                }
                let k = points.len() - usize::from(!closed);
                let knots: Vec<f64> = (0..=k).map(|i| (i * i) as f64 * 0.7 + i as f64).collect();
                for order in [1, 2, 3, 11] {
                    for timing in [
                        ArcBlendTiming::Auto,
                        ArcBlendTiming::Book,
                        ArcBlendTiming::ArcLength,
                        ArcBlendTiming::Uniform,
                        ArcBlendTiming::Knots(knots.clone()),
                    ] {
                        let native =
                            ArcBlend::construct(points.to_vec(), order, timing.clone(), closed);
                        let on_sm =
                            ArcBlend::construct_on_sm(points.to_vec(), order, timing, closed);
                        built += keys::same_bits(&native, &on_sm, &points);
                    }
                }
            }
            built
        }
        let built = keys::built(check, check);
        assert!(built > 50, "{built} curves built");
    }

    #[test]
    fn warp_end_conditions_and_monotonicity() {
        for n in 1..=MAX_SMOOTHNESS {
            let poly = SmoothingPolynomials::try_new(n).unwrap_or_else(|e| panic!("{e}"));
            for (a, b) in [
                (1.0, 1.0),
                (0.3, 1.0),
                (1.0, 1e-9),
                (1e-9, 1e-9),
                (0.7, 0.2),
            ] {
                let w = Warp::new(a, b);
                let (start, end) = (
                    w.derivatives(poly, 0.0, n + 1),
                    w.derivatives(poly, 1.0, n + 1),
                );
                assert!(
                    start[0] == 0.0 && end[0] == 1.0,
                    "σ(0) = 0, σ(1) = 1 exactly"
                );
                assert!(
                    (start[1] - a).abs() < 1e-14 && (end[1] - b).abs() < 1e-14,
                    "slopes"
                );
                for m in 2..=n {
                    assert!(
                        start[m].abs() < 1e-9 && end[m].abs() < 1e-9,
                        "σ^({m}) = 0 at the ends"
                    );
                }
                let jet = w.jet(poly, 0.37);
                let d = w.derivatives(poly, 0.37, 2);
                for k in 0..3 {
                    assert!((jet[k] - d[k]).abs() < 1e-12, "jet and derivatives agree");
                }
                // σ′ ≥ A·B (module docs), on a fine grid.
                for j in 0..=2000 {
                    let s = f64::from(j) / 2000.0;
                    let slope = w.derivatives(poly, s, 1)[1];
                    assert!(
                        slope >= a * b * (1.0 - 1e-12) - 1e-15,
                        "σ′({s}) = {slope} (n = {n})"
                    );
                }
            }
        }
    }
}
