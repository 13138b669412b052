// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The C² cubic spline through keys at given times, cubic in the tangent space of each key
//! (scipy's `RotationSpline` on S³, the same construction on every sphere).
//!
//! # Construction
//!
//! Keys `p₀ … p_{n−1}` at times `t₀ < … < t_{n−1}` (closed: `n` segments and one more time
//! `t_n`, the segment `n − 1` going from `p_{n−1}` back to `p₀`). With `hᵢ = tᵢ₊₁ − tᵢ`,
//! `rᵢ = Log_{pᵢ}(pᵢ₊₁)` (angle `θᵢ = |rᵢ| < π`, direction `eᵢ`) and `s = t − tᵢ`:
//!
//! ```text
//! c(t)  = Exp_{pᵢ}(vᵢ(s)),        Exp_p(v) = cos|v|·p + sin|v|/|v|·v
//! vᵢ(s) = Vᵢ·s + (3rᵢ/hᵢ − 2Vᵢ − Uᵢ)·s²/hᵢ + (−2rᵢ/hᵢ + Vᵢ + Uᵢ)·s³/hᵢ²
//! ```
//!
//! a cubic in the tangent space at `pᵢ` with `vᵢ(0) = 0`, `vᵢ(hᵢ) = rᵢ`, `vᵢ′(0) = Vᵢ` (the key
//! velocity at `pᵢ`) and `vᵢ′(hᵢ) = Uᵢ = (dExpᵢ)⁻¹ Vᵢ₊₁`, so that the velocity is continuous.
//!
//! **The differential of Exp.** At `v = θe` (`|e| = 1`, tangent at `p`), split a tangent vector
//! `w = w∥·e + w⊥`. With `q = Exp_p(v)` and the unit tangent `e′ = −sin θ·p + cos θ·e` at `q`
//! (the parallel transport of `e`):
//!
//! ```text
//! dExp_v[w] = w∥·e′ + (sin θ/θ)·w⊥                                       (1)
//! d²/ds² Exp_p(v(s)) = dExp_v[v″] + Q_v(v′),
//! Q_v(w) = −w∥²·q + |w⊥|²·(−(sin θ/θ)·p + σ′(θ)·e) + 2σ′(θ)·w∥·w⊥,   σ′(θ) = (θ cos θ − sin θ)/θ²
//! ```
//!
//! Its component tangent at `q` is `T_v(w) = |w⊥|²·κ(θ)·e′ + 2σ′(θ)·w∥·w⊥` with
//! `κ(θ) = (θ − sin θ cos θ)/θ²`; the normal part is `−|c′|²·q`, as on every curve of the sphere.
//! `σ′` and `κ` use their Taylor series below θ = 0.1; at θ = 0, `T = 0` and `dExp = id`.
//!
//! **Continuity of acceleration.** At an interior key `k` the acceleration from the left
//! (`s = h_{k−1}` on segment `k − 1`) equals the one from the right (`s = 0` on segment `k`,
//! where `dExp = id`). With `Mᵢ = dExpᵢ` at `rᵢ` (from `T_{pᵢ}` to `T_{pᵢ₊₁}`), `Nᵢ = Mᵢ⁻¹`,
//! `r̃ᵢ = Mᵢ rᵢ = θᵢ·eᵢ′ = −Log_{pᵢ₊₁}(pᵢ)`, this is, for `k = 1 … n − 2`:
//!
//! ```text
//! (2/h_{k−1})·M_{k−1}V_{k−1} + 4(1/h_{k−1} + 1/h_k)·V_k + (2/h_k)·N_k V_{k+1}
//!     + T_{k−1}(N_{k−1}V_k)  =  6 r̃_{k−1}/h_{k−1}² + 6 r_k/h_k²                        (2)
//! ```
//!
//! which is scipy's system (Rotation vectors of the body frame are twice the tangent vectors in
//! `q̄`-coordinates on S³: a linear map, so the same curve). On a great circle `M = N = id`,
//! `T = 0` and (2) is the Euclidean cubic spline of the angle.
//!
//! **Ends.** *Natural*: zero tangential acceleration at `p₀` and `p_{n−1}`: the rows of (2) with
//! the missing segment dropped, `(4/h₀)V₀ + (2/h₀)N₀V₁ = 6r₀/h₀²` and its mirror image with `T`.
//! *Clamped*: `V₀`, `V_{n−1}` given. *Scipy*: `V₀ = r₀/h₀` and `V_{n−1} = r̃_{n−2}/h_{n−2}`, the
//! mean velocities of the end segments (scipy sets the end angular rates to the first and last
//! segments' mean rates and solves the interior ones). *Closed*: (2) at every key, indices
//! mod `n`.
//!
//! **Not reversal symmetric.** Each segment is a cubic in the tangent space of its *first* key,
//! so the keys and times reversed give a different curve (exactly the same only on a great
//! circle); the difference shrinks like the cube of the step. scipy's `RotationSpline` has the
//! same property.
//!
//! **Solving.** The unknowns are written in orthonormal frames of the tangent spaces that are
//! parallel transported along the chain of geodesics (so `Mᵢ` becomes the symmetric
//! `sinc θᵢ·I + (1 − sinc θᵢ)·êᵢêᵢᵀ` and `Nᵢ` its inverse; a closed chain picks up the
//! holonomy rotation `H` at the seam), inside the span of the keys (and clamped velocities).
//! (2) is block tridiagonal (block cyclic when closed) with blocks of the tangent dimension.
//! Newton's method solves it from `V = 0`:
//!
//! - the first step solves the linear part (scipy's first iterate). At `V = 0` the Jacobian has
//!   the blocks `(2/hₖ₋₁)Mₖ₋₁`, a multiple of `I`, and `(2/hₖ)Nₖ`, and since `MₖNₖ = I` every
//!   pivot of its block LU factorisation is a multiple of `I`: the step is the scalar
//!   recurrence of the Euclidean spline with `M` and `N` applied as vectors (an open curve; a
//!   closed one uses the general factorisation);
//! - (open curves) a second step with the same scalar factorisation corrects for the nonlinear
//!   term: the linear part is solved at the first iterate, so the residual there is `T(wₖ)`,
//!   computed and eliminated (from the last row up: the pivots of that direction are scalars
//!   too) as the linear step's backward substitution yields each `Vₖ`, and substituted a row
//!   ahead of the next sweep. Newton's first factorisation then starts nearer the solution and
//!   the chord steps converge faster;
//! - the Jacobian at that point (`DT = 2B(u, ·)` added to the diagonal blocks) is factorised
//!   once, in O(n) (bordered for the cyclic case), and reused for chord steps while the
//!   residual falls by 10× per step, refactorised otherwise;
//! - a factorising step is a forward sweep, which evaluates a row of the residual, builds and
//!   factorises the row and eliminates it at once, and a backward substitution;
//! - a chord step does not evaluate the equations. They are linear in `V` but for the term
//!   `T(wₖ)` of each row, a quadratic form `B(w, w)` (`DT(w) = 2B(w, ·)`) in the end velocity
//!   `wₖ = N_{k−1}Vₖ` of the segment before the key, which depends on one unknown. A step
//!   `V ← V − D` solves `F(V) − J(V̄)D = 0` with the Jacobian at the factorisation point `V̄`,
//!   so the residual after it is exactly
//!
//!   ```text
//!   F(V − D)ₖ = T(w − s) − T(w) + DT(w̄)s = B(s − 2W, s),   s = wₖ(D),  W = wₖ(V − V̄)
//!   ```
//!
//!   (`H` applied across the seam): block diagonal, computed in the backward substitution as
//!   each `Dₖ` comes out; the next forward pass only eliminates it. (This leaves out the
//!   rounding of the factorised solve, `O(ε·|D|)`, far below the threshold; a unit test compares
//!   the updated residual with the evaluated one on random systems.)
//!
//! The iteration stops when the largest row residual, relative to the root sum of squares of
//! the row's terms, is at most 1e-12, and reports [`SolveError::NoConvergence`] if it is not
//! after the iteration limit. An updated residual is relative to the terms at the last
//! evaluation `V̄`; it is turned into a bound at `V`: each row's terms move by at most `Lₖ·ω`
//! when no unknown has moved by more than `ω ≤ 1` since (`Lₖ` from the row's coefficients:
//! `4/h` terms, `2/h`, `2/(h·sinc θ)`, and `|B(a, b)| ≤ (|κ| + |sinc′|)|a||b|` for the change of
//! `T`), and `ω` is at most the largest `|Wₖ|`, so the relative residual at `V` is at most the
//! updated one over `1 − ω·maxₖ Lₖ/|termsₖ(V̄)|` (a fresh evaluation when that is not
//! positive). The steps and residuals on the benchmark keys are in `BENCHMARKS.md`.
//!
//! # Sources
//!
//! - The construction (cubic rotation vectors in the body frame, the nonlinear term of the
//!   angular acceleration, the block tridiagonal iteration): N. Mayorov, *Smooth attitude
//!   interpolation*, 2019, the reference of scipy's `RotationSpline`
//!   (<https://github.com/scipy/scipy/files/2932755/attitude_interpolation.pdf>);
//!   P. Virtanen et al., *`SciPy` 1.0: fundamental algorithms for scientific computing in Python*,
//!   Nature Methods 17, 261–272 (2020), <https://doi.org/10.1038/s41592-019-0686-2>.
//! - Cubics in the tangent space at a key, the idea behind it: M.-J. Kim, M.-S. Kim,
//!   S. Y. Shin, *A C²-continuous B-spline quaternion curve interpolating a given sequence of
//!   solid orientations*, Computer Animation '95, 72–81, <https://doi.org/10.1109/CA.1995.393545>.
//! - The differential of the sphere's exponential map (1) and its second-order term are derived
//!   above from `Exp_p(v) = cos|v|·p + sinc|v|·v` by differentiating twice.

use glam::{DVec3, DVec4};

use crate::ambient::Ambient;
#[cfg(doc)]
use crate::curve::Curve;
use crate::curve::{Jet, Side};
use crate::error::{PointError, SolveError, SplineError};
use crate::knots::Knots;
use crate::manifold::{Manifold, geodesic_frame_sin_cos, renormalize};
use crate::math;
use crate::s3::UnitQuat;
#[cfg(any(test, target_arch = "wasm32"))]
use crate::{
    ambient::VecN,
    recast::{Recast, to_sn},
    sn::SnPoint,
};

/// Newton stops once the relative residual is at most this (an updated residual of a chord
/// step, [`FixedSolver::update`]: its bound, [`FixedSolver::bound`]).
const TARGET_RESIDUAL: f64 = 1e-12;
/// The construction fails when the relative residual stays above this.
const MAX_RESIDUAL: f64 = 1e-12;
/// Newton and chord steps at most.
const MAX_ITERATIONS: usize = 60;
/// A clamped velocity `v` at key `p` is tangent when `|p·v| ≤ TANGENT_TOLERANCE·|v|`.
pub const TANGENT_TOLERANCE: f64 = 1e-9;

/// How a [`CubicSpline`] ends (open curves only; a closed curve has no ends).
#[derive(Clone, Debug, PartialEq, Default)]
pub enum CubicEnd<V> {
    /// Zero tangential acceleration at the first and the last key (the default).
    #[default]
    Natural,
    /// The velocities at the first and the last key, ambient tangent vectors (per unit of the
    /// time parameter). On S³ see [`CubicEnd::clamped_angular_body`].
    Clamped {
        /// The velocity at the first key, tangent there.
        start: V,
        /// The velocity at the last key, tangent there.
        end: V,
    },
    /// scipy's `RotationSpline` end condition: the velocity at the first key is the mean
    /// velocity of the first segment, `Log_{p₀}(p₁)/h₀`, and at the last key that of the last
    /// segment, `−Log_{p_{n−1}}(p_{n−2})/h_{n−2}`.
    Scipy,
}

impl CubicEnd<DVec4> {
    /// Clamped ends on S³ from body-frame angular velocities `ω_body = 2·q̄·q′` (scipy's
    /// `RotationSpline(t, 1)` convention) at the first and the last key.
    #[must_use]
    pub fn clamped_angular_body(first: UnitQuat, start: DVec3, last: UnitQuat, end: DVec3) -> Self {
        Self::Clamped {
            start: crate::s3::velocity_from_angular_body(first, start),
            end: crate::s3::velocity_from_angular_body(last, end),
        }
    }

    /// Clamped ends on S³ from space-frame angular velocities `ω = 2·q′·q̄` (the convention of
    /// [`angular_velocity_acceleration`](crate::angular_velocity_acceleration)).
    #[must_use]
    pub fn clamped_angular(first: UnitQuat, start: DVec3, last: UnitQuat, end: DVec3) -> Self {
        Self::Clamped {
            start: crate::s3::velocity_from_angular(first, start),
            end: crate::s3::velocity_from_angular(last, end),
        }
    }
}

/// # Construction from rotations
impl CubicSpline<UnitQuat> {
    /// The open spline through rotations at the times `knots` (default `0, 1, 2, …`) whatever
    /// the signs of their quaternions: the keys are canonicalised first
    /// ([`unflip`](crate::unflip): each step the shorter rotation, the first key as given), so
    /// `q` and `−q` give the same curve. With [`CubicEnd::Scipy`] this is scipy's
    /// `RotationSpline(times, rotations)`, which works with the relative rotation vectors
    /// between neighbours and so never sees key signs. A clamped end velocity belongs to its key
    /// as given and is negated with it ([`CubicEnd::clamped_angular_body`] on the keys as
    /// given is right either way).
    ///
    /// [`try_new`](Self::try_new) takes the keys as points of S³, signs included. For a closed
    /// loop of rotations see [`RotationLoop`](crate::RotationLoop).
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new) for an open curve.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{CubicEnd, CubicSpline, Curve, UnitQuat};
    /// use spherekit::glam::DVec3;
    ///
    /// let keys: Vec<UnitQuat> = (0..4)
    ///     .map(|k| UnitQuat::from_axis_angle(DVec3::new(1.0, 2.0, f64::from(k)), 0.7 * f64::from(k)).unwrap())
    ///     .collect();
    /// let mut flipped = keys.clone();
    /// flipped[2] = -flipped[2];
    /// let a = CubicSpline::try_new_rotations(keys, None, CubicEnd::Scipy).unwrap();
    /// let b = CubicSpline::try_new_rotations(flipped, None, CubicEnd::Scipy).unwrap();
    /// assert_eq!(a.eval(1.5), b.eval(1.5));
    /// ```
    pub fn try_new_rotations(
        mut keys: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
        end: CubicEnd<DVec4>,
    ) -> Result<Self, SplineError> {
        let last = keys.last().copied();
        crate::unflip(&mut keys);
        let end = match (end, last, keys.last()) {
            (CubicEnd::Clamped { start, end }, Some(given), Some(&now)) if given != now => {
                CubicEnd::Clamped { start, end: -end }
            }
            (end, ..) => end,
        };
        Self::try_new(keys, knots, end, false)
    }
}

/// How the Newton solve of a [`CubicSpline`] ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CubicSolveInfo {
    /// Newton and chord steps performed (0 when there was nothing to solve).
    pub iterations: usize,
    /// Number of Jacobian factorisations.
    pub factorizations: usize,
    /// The largest residual of the continuity equations, each row relative to the size of its
    /// terms (≤ 1e-12 by construction).
    pub residual: f64,
}

/// One segment, `c(t) = Exp_p(v(s))`, `v(s) = a·s + b·s² + c·s³` in the local `s ∈ [0, 1]`.
#[derive(Clone, Debug)]
struct Segment<V> {
    start: V,
    a: V,
    b: V,
    c: V,
    inv_h: f64,
}

/// The C² cubic spline through keys at given times on any sphere, with natural, clamped or
/// scipy end conditions, or closed (periodic).
///
/// On each segment the curve is the exponential of a cubic in the tangent space of its first
/// key; the key velocities are solved so that velocity and acceleration are continuous at every
/// interior key (and at the seam of a closed curve). On S³ with [`CubicEnd::Scipy`] this is
/// scipy's `RotationSpline` (keys canonicalised by [`unflip`](crate::unflip), since scipy
/// interpolates the shortest rotations). The module documentation of the construction, the
/// continuity equations and their solution is reproduced here:
///
/// ```text
/// c(t) = Exp_{pᵢ}(vᵢ(t − tᵢ)),  vᵢ cubic,  vᵢ(0) = 0,  vᵢ(hᵢ) = Log_{pᵢ}(pᵢ₊₁)
/// (2/h_{k−1})·M_{k−1}V_{k−1} + 4(1/h_{k−1} + 1/h_k)·V_k + (2/h_k)·N_k V_{k+1}
///     + T_{k−1}(N_{k−1}V_k) = 6 r̃_{k−1}/h_{k−1}² + 6 r_k/h_k²
/// ```
///
/// with `M = dExp` at the segment's end, `N = M⁻¹` and `T` the tangential second-order term of
/// `Exp` (see the source for the closed forms). Newton's method on the block tridiagonal
/// system, O(n) per step, to a relative residual ≤ 1e-12 ([`solve_info`](Self::solve_info)).
///
/// Sources: N. Mayorov, *Smooth attitude interpolation* (2019), the reference of scipy's
/// `RotationSpline`; P. Virtanen et al., *`SciPy` 1.0*, Nature Methods 17 (2020),
/// <https://doi.org/10.1038/s41592-019-0686-2>.
///
/// # Domain and joints
///
/// The domain is `[t₀, t_{n−1}]` (closed: `[t₀, t_n]`); [`Curve::joints`] are all the key
/// times, so the interior keys are the joints between segments. A closed curve's seam is the
/// pair of domain ends: `jet_at(t₀, Right)` equals `jet_at(t_n, Left)` (C²), but the seam is not
/// an interior joint, so [`continuity`](crate::continuity) does not list it. Parameters outside
/// the domain are clamped.
///
/// # Examples
///
/// ```
/// use spherekit::{continuity, CubicEnd, CubicSpline, Curve, Manifold, S2Point};
/// use spherekit::glam::DVec3;
///
/// let p = |x: f64, y: f64, z: f64| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let keys = vec![p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.2), p(-0.5, 0.3, 1.0), p(0.0, -1.0, 0.5)];
/// let c = CubicSpline::try_new(keys.clone(), Some(vec![0.0, 0.5, 2.0, 3.0]), CubicEnd::Natural, false)
///     .unwrap();
/// assert!(c.eval(2.0).dist(&keys[2]) < 1e-15);
/// for joint in continuity(&c) {
///     assert!(joint.c1 < 1e-12 && joint.c2 < 1e-11);
/// }
/// // Natural end: the acceleration at the first key is normal to the sphere.
/// let j = c.jet(0.0);
/// let tangential = j.acceleration - j.point.as_dvec3() * j.point.as_dvec3().dot(j.acceleration);
/// assert!(tangential.length() < 1e-12);
/// assert!(c.solve_info().residual <= 1e-12);
/// ```
#[derive(Clone, Debug)]
pub struct CubicSpline<P: Manifold> {
    points: Vec<P>,
    knots: Knots,
    end: CubicEnd<P::Vector>,
    closed: bool,
    velocities: Vec<P::Vector>,
    segments: Vec<Segment<P::Vector>>,
    info: CubicSolveInfo,
}

/// # Construction
impl<P: Manifold> CubicSpline<P> {
    /// Builds the spline through `points` at the times `knots` (default `0, 1, 2, …`; closed:
    /// one more time than points, the time at which the curve is back at the first point).
    ///
    /// Keys are used as given; on S³ call [`unflip`](crate::unflip) first for the shortest
    /// rotations (scipy's convention), or build from rotations with
    /// [`try_new_rotations`](CubicSpline::try_new_rotations), which does. Consecutive identical keys are allowed (a segment with
    /// `Log = 0`: the curve leaves the key and comes back to it).
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 2 points (3 when `closed`);
    /// - [`SplineError::InvalidPoint`] with [`PointError::WrongDimension`] for points of spheres of
    ///   different dimensions ([`SnPoint`](crate::SnPoint));
    /// - [`SplineError::Antipodal`] for antipodal consecutive points and
    ///   [`SplineError::AntipodalClosing`] for an antipodal last and first point when `closed`;
    /// - the knot errors of [`Knots::or_uniform`] (non-finite, not increasing, spacing, and
    ///   [`SplineError::KnotCount`] unless there are `points.len()` knots, `points.len() + 1`
    ///   when `closed`);
    /// - [`SplineError::InvalidParameter`] (`end`) for an end condition other than
    ///   [`CubicEnd::Natural`] on a closed curve;
    /// - [`SplineError::InvalidEndVelocity`] for a clamped velocity that is not finite, has the
    ///   wrong dimension or is not tangent at its key (`|p·v| > 1e-9·|v|`; a tangent velocity
    ///   within that tolerance is projected onto the tangent space);
    /// - [`SplineError::Solve`] if Newton's method does not reach the residual 1e-12.
    pub fn try_new(
        points: Vec<P>,
        knots: Option<Vec<f64>>,
        end: CubicEnd<P::Vector>,
        closed: bool,
    ) -> Result<Self, SplineError> {
        // Natively on `P` itself; in the wasm build once on S^m for every point type
        // ([`crate::recast`]; the same bits, `tests::the_construction_gives_the_same_bits_on_sn`).
        #[cfg(not(target_arch = "wasm32"))]
        return Self::construct(points, knots, end, closed);
        #[cfg(target_arch = "wasm32")]
        return Self::construct_on_sn(points, knots, end, closed);
    }

    /// [`construct`](Self::construct) on the keys as points of S^m, the built curve converted
    /// back (the keys and the end condition are kept as given: the conversion copies
    /// coordinates).
    #[cfg(any(test, target_arch = "wasm32"))]
    fn construct_on_sn(
        points: Vec<P>,
        knots: Option<Vec<f64>>,
        end: CubicEnd<P::Vector>,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let sn = points.iter().map(to_sn).collect();
        let vector = |v: &P::Vector| VecN::new(v.to_vec());
        let end_sn = match &end {
            CubicEnd::Natural => CubicEnd::Natural,
            CubicEnd::Scipy => CubicEnd::Scipy,
            CubicEnd::Clamped { start, end } => CubicEnd::Clamped {
                start: vector(start),
                end: vector(end),
            },
        };
        let c = CubicSpline::<SnPoint>::construct(sn, knots, end_sn, closed)?;
        let to = Recast::to(&points[0]);
        Ok(Self {
            points,
            knots: c.knots,
            end,
            closed: c.closed,
            velocities: c.velocities.iter().map(|v| to.vector(v)).collect(),
            segments: c
                .segments
                .iter()
                .map(|g| Segment {
                    start: to.vector(&g.start),
                    a: to.vector(&g.a),
                    b: to.vector(&g.b),
                    c: to.vector(&g.c),
                    inv_h: g.inv_h,
                })
                .collect(),
            info: c.info,
        })
    }

    /// The construction of [`try_new`](Self::try_new) on `P`.
    fn construct(
        points: Vec<P>,
        knots: Option<Vec<f64>>,
        end: CubicEnd<P::Vector>,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let n = points.len();
        let min = if closed { 3 } else { 2 };
        if n < min {
            return Err(SplineError::TooFewPoints { min, got: n });
        }
        let dim = points[0].to_vector().dim();
        if let Some(index) = points.iter().position(|q| q.to_vector().dim() != dim) {
            return Err(SplineError::InvalidPoint {
                index,
                reason: PointError::WrongDimension {
                    expected: dim,
                    got: points[index].to_vector().dim(),
                },
            });
        }
        // Angle, direction, sine and cosine of each segment (the antipodal checks of the keys).
        let nseg = n - usize::from(!closed);
        let mut dirs = Vec::with_capacity(nseg);
        let mut thetas = Vec::with_capacity(nseg);
        let mut sin_cos = Vec::with_capacity(nseg);
        for i in 0..nseg {
            let next = if i + 1 == n { 0 } else { i + 1 };
            let (p, q) = (points[i].to_vector(), points[next].to_vector());
            let (theta, e, sc) = geodesic_frame_sin_cos(&p, &q).ok_or(if i + 1 == n {
                SplineError::AntipodalClosing
            } else {
                SplineError::Antipodal { index: i }
            })?;
            dirs.push(e);
            thetas.push(theta);
            sin_cos.push(sc);
        }
        let knots = Knots::or_uniform(knots, n + usize::from(closed))?;
        if closed && !matches!(end, CubicEnd::Natural) {
            return Err(SplineError::InvalidParameter {
                name: "end",
                reason: "must be natural (the default) for a closed curve, which has no ends"
                    .into(),
            });
        }
        let clamps = match &end {
            CubicEnd::Clamped { start, end } => Some((
                check_velocity(&points[0], start, true)?,
                check_velocity(&points[n - 1], end, false)?,
            )),
            _ => None,
        };

        // Span coordinates of the keys, the directions and the clamped velocities: the ambient
        // coordinates when the keys span the whole space (as keys on S³ in general position do).
        let vectors: Vec<P::Vector> = points.iter().map(Manifold::to_vector).collect();
        let clamp_vectors = clamps.iter().flat_map(|(s, e)| [s, e]);
        let basis = span_basis(dim, vectors.iter().chain(clamp_vectors));
        let r = basis.len();
        let whole = r == dim;
        let coords = |v: &P::Vector, out: &mut Vec<f64>| {
            if whole {
                out.extend_from_slice(v.as_slice());
            } else {
                out.extend(basis.iter().map(|b| b.dot(v)));
            }
        };
        let mut xs = Vec::with_capacity(n * r);
        for v in &vectors {
            coords(v, &mut xs);
        }
        let mut es = Vec::with_capacity(nseg * r);
        for e in &dirs {
            coords(e, &mut es);
        }
        let m = r - 1;
        let (frames, ehat) = Frames::new(&xs, &es, &sin_cos, r, closed);
        let mut geo = Geometry {
            n,
            m,
            closed,
            seg: (0..nseg)
                .map(|i| SegConst::new(thetas[i], knots.width(i), sin_cos[i]))
                .collect(),
            ehat,
            hol: Vec::new(),
            fixed: None,
        };
        if closed && m > 0 {
            geo.hol = frames.holonomy();
        }
        if m > 0 {
            match &end {
                CubicEnd::Natural => {}
                CubicEnd::Scipy => {
                    let (s0, s1) = (&geo.seg[0], &geo.seg[nseg - 1]);
                    let g0: Vec<f64> = geo.ehat[..m].iter().map(|e| e * s0.theta / s0.h).collect();
                    let g1: Vec<f64> = geo.ehat[(nseg - 1) * m..]
                        .iter()
                        .map(|e| e * s1.theta / s1.h)
                        .collect();
                    geo.fixed = Some((g0, g1));
                }
                CubicEnd::Clamped { .. } => {
                    let (s, e) = clamps.as_ref().expect("validated above");
                    let mut sc = Vec::with_capacity(r);
                    coords(s, &mut sc);
                    let mut ec = Vec::with_capacity(r);
                    coords(e, &mut ec);
                    let g0 = (0..m).map(|a| dot(frames.vector(0, a), &sc)).collect();
                    let g1 = (0..m).map(|a| dot(frames.vector(n - 1, a), &ec)).collect();
                    geo.fixed = Some((g0, g1));
                }
            }
        }
        let (x, info) = if m == 0 {
            (
                Vec::new(),
                CubicSolveInfo {
                    iterations: 0,
                    factorizations: 0,
                    residual: 0.0,
                },
            )
        } else {
            match m {
                1..=3 => FixedSolver::<3>::new(&geo).solve(),
                _ => geo.solve(Dynamic(m)),
            }?
        };

        // Back to ambient vectors: the key velocities Vₖ and the segments' coefficients.
        let zero = vectors[0].zeros_like();
        let ambient = |span: &[f64]| {
            if whole {
                return zero.with_coords(span);
            }
            let mut v = zero.clone();
            for (b, &c) in basis.iter().zip(span) {
                v += b.clone() * c;
            }
            v
        };
        let (velocities, segments) = frames.output(&geo, &x, &es, &vectors, ambient);
        Ok(Self {
            points,
            knots,
            end,
            closed,
            velocities,
            segments,
            info,
        })
    }
}

/// # Access
impl<P: Manifold> CubicSpline<P> {
    /// The keys.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The key times (closed: one more, the time of the return to the first key).
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }

    /// The solved velocity at each key (ambient, tangent at the key).
    #[must_use]
    pub fn key_velocities(&self) -> &[P::Vector] {
        &self.velocities
    }

    /// The end condition as given.
    #[must_use]
    pub fn end(&self) -> &CubicEnd<P::Vector> {
        &self.end
    }

    /// `true` for a closed (periodic) curve.
    #[must_use]
    pub fn closed(&self) -> bool {
        self.closed
    }

    /// Iterations and final residual of the solve for the key velocities.
    #[must_use]
    pub fn solve_info(&self) -> CubicSolveInfo {
        self.info
    }

    /// The number of segments (`n − 1` for `n` keys; `n` when closed).
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.segments.len()
    }

    /// The jet at any `t` of the first segment's formula (for `t` before the second key time)
    /// or the last segment's (otherwise), continued beyond the segment: the exponential of the
    /// segment's cubic `vᵢ(s)` in the tangent space of its first key, at `s = (t − tᵢ)/hᵢ`
    /// outside `[0, 1]` too. Inside those segments it is the curve's own jet (to rounding).
    ///
    /// This is how scipy's `RotationSpline` extrapolates (its `PPoly` continues the end
    /// polynomials of the rotation vectors), and what [`Curve::jet_beyond`] gives outside the
    /// domain of an open spline (see [`Extrapolate::Segment`](crate::Extrapolate::Segment)).
    /// `None` for a NaN `t` and where the cubic or the jet overflows (far outside: the
    /// tangent vector grows like `s³`).
    #[must_use]
    pub fn continued_jet(&self, t: f64) -> Option<Jet<P>> {
        if t.is_nan() {
            return None;
        }
        let knots = self.knots.as_slice();
        let i = if t < knots[1] {
            0
        } else {
            self.segments.len() - 1
        };
        let g = &self.segments[i];
        let s = (t - knots[i]) * g.inv_h;
        // The cubic, its derivative and its length must be finite for the exponential to be a
        // point (checked before `jet_local`, which renormalises).
        let v = ((g.c.clone() * s + g.b.clone()) * s + g.a.clone()) * s;
        let w = ((g.c.clone() * (3.0 * s) + g.b.clone() * 2.0) * s + g.a.clone()) * g.inv_h;
        if !(v.length().is_finite() && w.length().is_finite() && (s * g.inv_h).is_finite()) {
            return None;
        }
        let jet = self.jet_local(i, s);
        (jet.velocity.is_finite() && jet.acceleration.is_finite()).then_some(jet)
    }
}

crate::curve::piecewise_curve! {
    impl [P: Manifold] for CubicSpline<P> {
        type Point = P;

        /// Open splines: the end segments' cubics continued ([`CubicSpline::continued_jet`]); a
        /// closed spline has no ends (`None`; it repeats under
        /// [`Extrapolate::Cycle`](crate::Extrapolate::Cycle)).
        fn jet_beyond(&self, t: f64) -> Option<Jet<P>> {
            let [t0, t1] = self.domain();
            if self.closed || !(t < t0 || t > t1) {
                return None;
            }
            self.continued_jet(t)
        }
    }
}

impl<P: Manifold> CubicSpline<P> {
    /// The key at the end of segment `i`.
    fn end_key(&self, i: usize) -> &P {
        &self.points[(i + 1) % self.points.len()]
    }

    fn eval_local(&self, i: usize, s: f64) -> P {
        if s == 0.0 {
            return self.points[i].clone();
        }
        if s == 1.0 {
            return self.end_key(i).clone();
        }
        let g = &self.segments[i];
        let v = ((g.c.clone() * s + g.b.clone()) * s + g.a.clone()) * s;
        let rho = v.length();
        let (sn, cs) = math::sin_cos(rho);
        let sinc = if rho < 1e-4 {
            math::sinc(rho)
        } else {
            sn / rho
        };
        P::from_vector_unchecked(renormalize(g.start.clone() * cs + v * sinc))
    }

    /// The point and velocity of segment `i` at `s`, with what the acceleration needs.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn local(&self, i: usize, s: f64) -> Local<P> {
        let g = &self.segments[i];
        let v = ((g.c.clone() * s + g.b.clone()) * s + g.a.clone()) * s;
        let w = ((g.c.clone() * (3.0 * s) + g.b.clone() * 2.0) * s + g.a.clone()) * g.inv_h;
        let p = &g.start;
        let rho = v.length();
        let (sn, cs) = math::sin_cos(rho);
        let sinc = if rho < 1e-4 {
            math::sinc(rho)
        } else {
            sn / rho
        };
        // The unit direction of v (zero for |v| ≈ 0, where every term it enters is O(|v|)).
        let e = if rho > 1e-150 {
            v.clone() * (1.0 / rho)
        } else {
            v.zeros_like()
        };
        let q = p.clone() * cs + v * sinc;
        let e_end = e.clone() * cs - p.clone() * sn;
        let w_par = w.dot(&e);
        let w_perp = w - e.clone() * w_par;
        let velocity = e_end.clone() * w_par + w_perp.clone() * sinc;
        let point = if s == 0.0 {
            self.points[i].clone()
        } else if s == 1.0 {
            self.end_key(i).clone()
        } else {
            P::from_vector_unchecked(renormalize(q.clone()))
        };
        Local {
            point,
            velocity,
            q,
            e,
            e_end,
            w_par,
            w_perp,
            rho,
            sinc,
            sin_cos: (sn, cs),
        }
    }

    fn jet_local(&self, i: usize, s: f64) -> Jet<P> {
        let g = &self.segments[i];
        let acc = (g.c.clone() * (6.0 * s) + g.b.clone() * 2.0) * (g.inv_h * g.inv_h);
        let Local {
            point,
            velocity,
            q,
            e,
            e_end,
            w_par,
            w_perp,
            rho,
            sinc,
            sin_cos,
        } = self.local(i, s);
        let dsinc = sinc_deriv(rho, sin_cos);
        let a_par = acc.dot(&e);
        let a_perp = acc - e.clone() * a_par;
        let perp2 = w_perp.dot(&w_perp);
        let acceleration = e_end * a_par
            + a_perp * sinc
            + q * (-w_par * w_par)
            + g.start.clone() * (-perp2 * sinc)
            + e * (perp2 * dsinc)
            + w_perp * (2.0 * dsinc * w_par);
        Jet {
            point,
            velocity,
            acceleration,
        }
    }

    /// The point and the velocity at `t`: the [`Curve::jet`] without its acceleration, the
    /// same bits, in about three quarters of the time (the angular rate needs no more).
    #[must_use]
    pub fn point_velocity(&self, t: f64) -> (P, P::Vector) {
        let (i, s) = self.knots.locate(t, Side::Right);
        let l = self.local(i, s);
        (l.point, l.velocity)
    }

    /// [`point_velocity`](Self::point_velocity) at many parameters (increasing parameters
    /// are located by stepping, as in [`Curve::jet_many`]).
    ///
    /// # Panics
    ///
    /// If `out` and `ts` have different lengths.
    pub fn point_velocity_many(&self, ts: &[f64], out: &mut [(P, P::Vector)]) {
        self.knots.map_into(ts, Side::Right, out, |i, s| {
            let l = self.local(i, s);
            (l.point, l.velocity)
        });
    }
}

/// The first-order part of a segment's jet, and the terms its acceleration reuses.
struct Local<P: Manifold> {
    point: P,
    velocity: P::Vector,
    /// `Exp` before renormalisation.
    q: P::Vector,
    /// The unit direction of the tangent vector `v`, and its parallel transport to `q`.
    e: P::Vector,
    e_end: P::Vector,
    /// The parts of `v′` along and across `e`.
    w_par: f64,
    w_perp: P::Vector,
    /// `|v|`, `sin|v|/|v|` and `(sin|v|, cos|v|)`.
    rho: f64,
    sinc: f64,
    sin_cos: (f64, f64),
}

/// Checks a clamped velocity at `key` and returns its tangent projection.
fn check_velocity<P: Manifold>(
    key: &P,
    v: &P::Vector,
    start: bool,
) -> Result<P::Vector, SplineError> {
    let p = key.to_vector();
    let reason = if v.dim() != p.dim() {
        "has the wrong number of coordinates"
    } else if !v.is_finite() {
        "has a non-finite coordinate"
    } else if p.dot(v).abs() > TANGENT_TOLERANCE * v.length() {
        if start {
            "is not tangent to the first key"
        } else {
            "is not tangent to the last key"
        }
    } else {
        return Ok(key.project_tangent(v));
    };
    Err(SplineError::InvalidEndVelocity { start, reason })
}

/// `σ′(x) = (x cos x − sin x)/x²`, the derivative of `sin x / x`, from `(sin x, cos x)` (series
/// below 0.1).
fn sinc_deriv(x: f64, (s, c): (f64, f64)) -> f64 {
    if x.abs() < 0.1 {
        let x2 = x * x;
        x * (-1.0 / 3.0
            + x2 * (1.0 / 30.0 + x2 * (-1.0 / 840.0 + x2 * (1.0 / 45360.0 - x2 / 3_991_680.0))))
    } else {
        (x * c - s) / (x * x)
    }
}

/// `κ(x) = (x − sin x cos x)/x²` (series below 0.1).
fn kappa(x: f64) -> f64 {
    if x.abs() < 0.1 {
        let x2 = x * x;
        x * (2.0 / 3.0
            + x2 * (-2.0 / 15.0 + x2 * (4.0 / 315.0 + x2 * (-2.0 / 2835.0 + x2 * 4.0 / 155_925.0))))
    } else {
        let (s, c) = math::sin_cos(x);
        (x - s * c) / (x * x)
    }
}

/// An orthonormal basis of the span of `vectors` (modified Gram–Schmidt, twice, on the
/// normalised vectors; zero vectors are skipped).
fn span_basis<'a, V: Ambient + 'a>(dim: usize, vectors: impl IntoIterator<Item = &'a V>) -> Vec<V> {
    let mut basis: Vec<V> = Vec::with_capacity(dim);
    for p in vectors {
        if basis.len() == dim {
            break;
        }
        let l = p.length();
        if l == 0.0 {
            continue;
        }
        let mut v = p.clone() * (1.0 / l);
        for _ in 0..2 {
            for b in &basis {
                let c = b.dot(&v);
                v = v - b.clone() * c;
            }
        }
        let l = v.length();
        if l > 1e-13 {
            basis.push(v * (1.0 / l));
        }
    }
    basis
}

#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `x ← S x` with `S = σ·I + (1 − σ)·ê êᵀ` (pass `1/sinc θ` for `S⁻¹`).
#[inline]
fn apply_s(ehat: &[f64], sigma: f64, x: &mut [f64]) {
    let c = (1.0 - sigma) * dot(ehat, x);
    for (xi, ei) in x.iter_mut().zip(ehat) {
        *xi = sigma * *xi + c * ei;
    }
}

/// Orthonormal tangent frames at the keys, in span coordinates, parallel transported along
/// the segments from a frame at the first key.
struct Frames {
    r: usize,
    /// `(n + closed) × (r − 1) × r`: frame `k` (the last one, when closed, is the transport of
    /// frame 0 around the loop).
    data: Vec<f64>,
}

/// Calls `$body` with `$d` bound to the dimension `$r` as a [`Dim`]: a constant for 4 (the
/// span of keys on S³, so that the short loops over coordinates are unrolled), [`Dynamic`]
/// otherwise. The wasm build has the [`Dynamic`] copy only (the same loops, so the same
/// bits).
#[cfg(not(target_arch = "wasm32"))]
macro_rules! with_dim {
    ($r:expr, |$d:ident| $body:expr) => {
        match $r {
            4 => {
                let $d = Const::<4>;
                $body
            }
            r => {
                let $d = Dynamic(r);
                $body
            }
        }
    };
}
#[cfg(target_arch = "wasm32")]
macro_rules! with_dim {
    ($r:expr, |$d:ident| $body:expr) => {{
        let $d = Dynamic($r);
        $body
    }};
}

impl Frames {
    /// The frames, and the frame coordinates `ê` of each segment's direction (`nseg × (r − 1)`,
    /// the components along `e` that the transport rotates).
    fn new(
        xs: &[f64],
        es: &[f64],
        sin_cos: &[(f64, f64)],
        r: usize,
        closed: bool,
    ) -> (Self, Vec<f64>) {
        with_dim!(r, |d| Self::build(d, xs, es, sin_cos, closed))
    }

    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn build<D: Dim>(
        d: D,
        xs: &[f64],
        es: &[f64],
        sin_cos: &[(f64, f64)],
        closed: bool,
    ) -> (Self, Vec<f64>) {
        let r = d.get();
        let m = r - 1;
        let n = xs.len() / r;
        let count = n + usize::from(closed);
        let mut data = Vec::with_capacity(count * m * r);
        // Frame 0: the Householder reflection taking the largest axis to x₀, other columns.
        let x0 = &xs[..r];
        let mut u = x0.to_vec();
        let jmax = (0..r).fold(0, |j, i| if u[i].abs() > u[j].abs() { i } else { j });
        u[jmax] += if u[jmax] >= 0.0 { 1.0 } else { -1.0 };
        let uu = dot(&u, &u);
        for k in (0..r).filter(|&k| k != jmax) {
            let scale = 2.0 * u[k] / uu;
            data.extend(u.iter().enumerate().map(|(j, &uj)| {
                let id = if j == k { 1.0 } else { 0.0 };
                id - scale * uj
            }));
        }
        data.resize(count * m * r, 0.0);
        let mut ehat = vec![0.0; (count - 1) * m];
        let mut e_end = vec![0.0; r];
        for k in 0..count - 1 {
            let (x, e) = (&xs[k * r..(k + 1) * r], &es[k * r..(k + 1) * r]);
            let next = if k + 1 == n { 0 } else { (k + 1) * r };
            let y = &xs[next..next + r];
            let (sn, cs) = sin_cos[k];
            for ((o, xj), ej) in e_end.iter_mut().zip(x).zip(e) {
                *o = -sn * xj + (cs - 1.0) * ej;
            }
            // Frame k + 1: each vector of frame k with its component along e rotated into e′
            // (the parallel transport), then orthogonalised against the next key. The dot
            // products are all taken of frame k (`g·y = f·y + (f·e)(d·y)`), so that the chain
            // from frame to frame is short.
            let (done, rest) = data.split_at_mut((k + 1) * m * r);
            let frame = done[k * m * r..].chunks_exact(r);
            let ehat = &mut ehat[k * m..(k + 1) * m];
            let dy = dot(&e_end, y);
            for ((f, g), fe) in frame.zip(rest.chunks_exact_mut(r)).zip(ehat) {
                *fe = dot(f, e);
                let gy = dot(f, y) + *fe * dy;
                for (((gj, fj), dj), yj) in g.iter_mut().zip(f).zip(&e_end).zip(y) {
                    *gj = fj + *fe * dj - gy * yj;
                }
            }
        }
        (Self { r, data }, ehat)
    }

    /// Vector `a` of frame `k`.
    #[inline]
    fn vector(&self, k: usize, a: usize) -> &[f64] {
        let m = self.r - 1;
        &self.data[(k * m + a) * self.r..(k * m + a + 1) * self.r]
    }

    /// The key velocities `Vₖ` and the segments, from the solution `x` in frame coordinates:
    /// with the end velocity `Uᵢ = Nᵢ Vᵢ₊₁` and `lᵢ = θᵢ·eᵢ` (`es`: span coordinates of the
    /// directions), `a = hV`, `b = 3l − 2hV − hU` and `c = −2l + hV + hU`, formed in span
    /// coordinates and made ambient vectors by `ambient`.
    fn output<V: Clone>(
        &self,
        geo: &Geometry,
        x: &[f64],
        es: &[f64],
        keys: &[V],
        ambient: impl Fn(&[f64]) -> V,
    ) -> (Vec<V>, Vec<Segment<V>>) {
        with_dim!(self.r, |d| self.output_in(d, geo, x, es, keys, &ambient))
    }

    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn output_in<D: Dim, V: Clone>(
        &self,
        d: D,
        geo: &Geometry,
        x: &[f64],
        es: &[f64],
        keys: &[V],
        ambient: impl Fn(&[f64]) -> V,
    ) -> (Vec<V>, Vec<Segment<V>>) {
        let r = d.get();
        let m = r - 1;
        let nseg = geo.seg.len();
        let mut velocities = Vec::with_capacity(geo.n);
        let mut segments = Vec::with_capacity(nseg);
        let (mut v, mut big_u, mut coef) = (vec![0.0; r], vec![0.0; r], vec![0.0; r]);
        let mut u = vec![0.0; m];
        for k in 0..geo.n {
            self.combine_in(d, k, &x[k * m..(k + 1) * m], &mut v);
            velocities.push(ambient(&v));
            if k == nseg {
                break;
            }
            // `U = S⁻¹·(Vₖ₊₁ transported back)`, with `S⁻¹ = I/sinc θ + (1 − 1/sinc θ)·e eᵀ` in
            // span coordinates.
            let next = if k + 1 == geo.n {
                geo.to_segment_end(k, &x[..m], &mut u);
                &u[..]
            } else {
                &x[(k + 1) * m..(k + 2) * m]
            };
            self.combine_in(d, k, next, &mut big_u);
            let (sc, e) = (&geo.seg[k], &es[k * r..(k + 1) * r]);
            apply_s(e, sc.inv_sinc, &mut big_u[..r]);
            let (h, theta) = (sc.h, sc.theta);
            for (o, va) in coef[..r].iter_mut().zip(&v) {
                *o = va * h;
            }
            let a = ambient(&coef);
            for (o, ((va, ua), ea)) in coef[..r].iter_mut().zip(v.iter().zip(&big_u).zip(e)) {
                *o = ea * theta * 3.0 - va * (2.0 * h) - ua * h;
            }
            let b = ambient(&coef);
            for (o, ((va, ua), ea)) in coef[..r].iter_mut().zip(v.iter().zip(&big_u).zip(e)) {
                *o = ea * theta * -2.0 + va * h + ua * h;
            }
            let c = ambient(&coef);
            segments.push(Segment {
                start: keys[k].clone(),
                a,
                b,
                c,
                inv_h: 1.0 / h,
            });
        }
        (velocities, segments)
    }

    /// `out = Σₐ cₐ·(frame k)ₐ`.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn combine_in<D: Dim>(&self, d: D, k: usize, c: &[f64], out: &mut [f64]) {
        let r = d.get();
        let out = &mut out[..r];
        out.fill(0.0);
        let frame = &self.data[k * c.len() * r..(k + 1) * c.len() * r];
        for (&ca, f) in c.iter().zip(frame.chunks_exact(r)) {
            for (o, fj) in out.iter_mut().zip(f) {
                *o += ca * fj;
            }
        }
    }

    /// `H[a][b] = (frame 0)ₐ · (frame n)_b`: frame-0 coordinates of the transported frame.
    fn holonomy(&self) -> Vec<f64> {
        let m = self.r - 1;
        let last = self.data.len() / (m * self.r) - 1;
        let mut h = Vec::with_capacity(m * m);
        for a in 0..m {
            for b in 0..m {
                h.push(dot(self.vector(0, a), self.vector(last, b)));
            }
        }
        h
    }
}

/// Scalars of one segment used by the solver.
#[derive(Clone, Debug)]
struct SegConst {
    theta: f64,
    h: f64,
    sinc: f64,
    inv_sinc: f64,
    kappa: f64,
    dsinc: f64,
    /// `2/h`, `4/h` and `6θ/h²`, the coefficients of the continuity equations.
    c2: f64,
    c4: f64,
    c6: f64,
}

impl SegConst {
    /// The scalars of a segment of angle `theta` (`(sin θ, cos θ)` given) and width `h`.
    fn new(theta: f64, h: f64, (sn, cs): (f64, f64)) -> Self {
        if theta.abs() < 0.1 {
            return Self {
                theta,
                h,
                sinc: math::sinc(theta),
                inv_sinc: math::inv_sinc(theta),
                kappa: kappa(theta),
                dsinc: sinc_deriv(theta, (sn, cs)),
                c2: 2.0 / h,
                c4: 4.0 / h,
                c6: 6.0 * theta / (h * h),
            };
        }
        // Above every series switch: the closed forms from the one `sin_cos`.
        let (inv_t, inv_h) = (1.0 / theta, 1.0 / h);
        let inv_t2 = inv_t * inv_t;
        Self {
            theta,
            h,
            sinc: sn * inv_t,
            inv_sinc: theta / sn,
            kappa: (theta - sn * cs) * inv_t2,
            dsinc: (theta * cs - sn) * inv_t2,
            c2: 2.0 * inv_h,
            c4: 4.0 * inv_h,
            c6: 6.0 * theta * inv_h * inv_h,
        }
    }
}

/// A block dimension of the slice-based solver (tangent dimensions above 3; 1 to 3 use
/// [`FixedSolver`]).
trait Dim: Copy {
    fn get(self) -> usize;
}

#[derive(Clone, Copy)]
struct Dynamic(usize);

/// A dimension known at compile time (native builds: [`with_dim`]).
#[cfg(not(target_arch = "wasm32"))]
#[derive(Clone, Copy)]
struct Const<const N: usize>;

#[cfg(not(target_arch = "wasm32"))]
impl<const N: usize> Dim for Const<N> {
    #[inline(always)]
    fn get(self) -> usize {
        N
    }
}

impl Dim for Dynamic {
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn get(self) -> usize {
        self.0
    }
}

/// The continuity equations in frame coordinates.
struct Geometry {
    n: usize,
    m: usize,
    closed: bool,
    seg: Vec<SegConst>,
    /// Frame coordinates of each segment's direction (`nseg × m`).
    ehat: Vec<f64>,
    /// Holonomy (closed only, `m × m`).
    hol: Vec<f64>,
    /// Fixed velocities at the first and last key (clamped and scipy ends), frame coordinates.
    fixed: Option<(Vec<f64>, Vec<f64>)>,
}

/// The block LU factors of the Jacobian.
struct Factors {
    /// `D̃ₖ⁻¹`.
    dinv: Vec<f64>,
    /// `Lₖ = Aₖ D̃ₖ₋₁⁻¹`.
    l: Vec<f64>,
    /// `Cₖ` (coupling of row k to unknown k + 1).
    c: Vec<f64>,
    /// Closed: `Zₖ` (fill of the border column), `A_{n−1}`, `C_{n−1}` and the inverse Schur
    /// complement of the last unknown.
    z: Vec<f64>,
    a_last: Vec<f64>,
    c_last: Vec<f64>,
    schur_inv: Vec<f64>,
}

impl Geometry {
    fn prev(&self, k: usize) -> Option<usize> {
        if k > 0 {
            Some(k - 1)
        } else if self.closed {
            Some(self.n - 1)
        } else {
            None
        }
    }

    fn next(&self, k: usize) -> Option<usize> {
        if self.closed || k + 1 < self.n {
            Some(k)
        } else {
            None
        }
    }

    fn is_seam(&self, seg: usize) -> bool {
        self.closed && seg + 1 == self.n
    }

    /// The fixed velocity of row `k`, if any.
    fn fixed_row(&self, k: usize) -> Option<&[f64]> {
        let (g0, g1) = self.fixed.as_ref()?;
        if k == 0 {
            Some(g0)
        } else if k + 1 == self.n {
            Some(g1)
        } else {
            None
        }
    }

    /// Transported-frame coordinates at the end of segment `seg` of a vector given in the frame
    /// of the end key (`Hᵀ·y` across the seam).
    fn to_segment_end(&self, seg: usize, y: &[f64], out: &mut [f64]) {
        let m = self.m;
        if self.is_seam(seg) {
            for (b, o) in out.iter_mut().enumerate().take(m) {
                *o = (0..m).map(|a| self.hol[a * m + b] * y[a]).sum();
            }
        } else {
            out.copy_from_slice(y);
        }
    }

    /// The inverse of [`to_segment_end`](Self::to_segment_end) (`H·y` across the seam).
    fn back_from_segment_end(&self, seg: usize, y: &[f64], out: &mut [f64]) {
        let m = self.m;
        if self.is_seam(seg) {
            for (a, o) in out.iter_mut().enumerate().take(m) {
                *o = (0..m).map(|b| self.hol[a * m + b] * y[b]).sum();
            }
        } else {
            out.copy_from_slice(y);
        }
    }

    fn ehat(&self, seg: usize) -> &[f64] {
        &self.ehat[seg * self.m..(seg + 1) * self.m]
    }

    /// The residuals `F(x)` into `f`; returns the largest row residual relative to the size of
    /// the row's terms.
    fn residual<D: Dim>(&self, d: D, x: &[f64], f: &mut [f64]) -> f64 {
        let m = d.get();
        let mut worst = 0.0_f64;
        let mut t1 = [0.0; 16];
        let mut t2 = [0.0; 16];
        let mut heap1;
        let mut heap2;
        let (y, u): (&mut [f64], &mut [f64]) = if m <= 16 {
            (&mut t1[..m], &mut t2[..m])
        } else {
            heap1 = vec![0.0; m];
            heap2 = vec![0.0; m];
            (&mut heap1[..], &mut heap2[..])
        };
        for k in 0..self.n {
            let xk = &x[k * m..(k + 1) * m];
            let fk = &mut f[k * m..(k + 1) * m];
            let mut scale = 0.0;
            if let Some(g) = self.fixed_row(k) {
                let h = if k == 0 {
                    self.seg[0].h
                } else {
                    self.seg[k - 1].h
                };
                let c = 4.0 / h;
                for a in 0..m {
                    fk[a] = c * (xk[a] - g[a]);
                }
                scale = c * (norm(xk) + norm(g));
            } else {
                fk.fill(0.0);
                if let Some(p) = self.prev(k) {
                    let sc = &self.seg[p];
                    let e = self.ehat(p);
                    let xp = &x[p * m..(p + 1) * m];
                    // (2/h) S xₚ + T(S⁻¹ H̃ᵀ xₖ) − 6θ ê/h², in transported coordinates.
                    y.copy_from_slice(xp);
                    apply_s(e, sc.sinc, y);
                    let c2 = 2.0 / sc.h;
                    let mut lin = 0.0;
                    for ya in y.iter_mut() {
                        *ya *= c2;
                        lin += *ya * *ya;
                    }
                    self.to_segment_end(p, xk, u);
                    apply_s(e, sc.inv_sinc, u);
                    let tn = add_t(sc, e, u, y);
                    let c6 = 6.0 * sc.theta / (sc.h * sc.h);
                    for (ya, ea) in y.iter_mut().zip(e) {
                        *ya -= c6 * ea;
                    }
                    self.back_from_segment_end(p, y, u);
                    let c4 = 4.0 / sc.h;
                    for a in 0..m {
                        fk[a] += u[a] + c4 * xk[a];
                    }
                    scale += lin.sqrt() + tn + c6 + c4 * norm(xk);
                }
                if let Some(nx) = self.next(k) {
                    let sc = &self.seg[nx];
                    let e = self.ehat(nx);
                    let j = (k + 1) % self.n;
                    self.to_segment_end(nx, &x[j * m..(j + 1) * m], y);
                    apply_s(e, sc.inv_sinc, y);
                    let (c2, c4) = (2.0 / sc.h, 4.0 / sc.h);
                    let c6 = 6.0 * sc.theta / (sc.h * sc.h);
                    for a in 0..m {
                        fk[a] += c2 * y[a] + c4 * xk[a] - c6 * e[a];
                    }
                    scale += c2 * norm(y) + c4 * norm(xk) + c6;
                }
            }
            let fnorm = norm(fk);
            if !fnorm.is_finite() {
                return f64::INFINITY;
            }
            if scale > 0.0 {
                worst = worst.max(fnorm / scale);
            } else if fnorm > 0.0 {
                return f64::INFINITY;
            }
        }
        worst
    }

    /// The Jacobian at `x`, factorised.
    fn factor<D: Dim>(&self, d: D, x: &[f64]) -> Option<Factors> {
        let m = d.get();
        let mm = m * m;
        let n = self.n;
        let mut a_blk = vec![0.0; mm];
        let mut d_blk = vec![0.0; mm];
        let mut tmp = vec![0.0; mm];
        let mut tmp2 = vec![0.0; mm];
        let mut u = vec![0.0; m];
        let mut fac = Factors {
            dinv: vec![0.0; n * mm],
            l: vec![0.0; n * mm],
            c: vec![0.0; n * mm],
            z: Vec::new(),
            a_last: Vec::new(),
            c_last: Vec::new(),
            schur_inv: Vec::new(),
        };
        let mut border = if self.closed {
            vec![0.0; n * mm]
        } else {
            Vec::new()
        };
        // Rows 0 … n−1 (open) or 0 … n−2 (closed; row n−1 is the border row).
        let last = if self.closed { n - 1 } else { n };
        let mut d_last = vec![0.0; mm];
        let mut a_last = vec![0.0; mm];
        let mut c_last = vec![0.0; mm];
        let mut c_blk = vec![0.0; mm];
        for k in 0..n {
            self.blocks(d, k, x, &mut a_blk, &mut d_blk, &mut tmp, &mut u);
            // C block: (2/h) S⁻¹ H̃ᵀ.
            c_blk.fill(0.0);
            if let (None, Some(nx)) = (self.fixed_row(k), self.next(k)) {
                {
                    let sc = &self.seg[nx];
                    s_matrix(self.ehat(nx), sc.inv_sinc, 2.0 / sc.h, &mut tmp);
                    if self.is_seam(nx) {
                        // tmp · Hᵀ
                        for i in 0..m {
                            for j in 0..m {
                                c_blk[i * m + j] =
                                    (0..m).map(|l| tmp[i * m + l] * self.hol[j * m + l]).sum();
                            }
                        }
                    } else {
                        c_blk.copy_from_slice(&tmp);
                    }
                }
            }
            if k == last {
                d_last.copy_from_slice(&d_blk);
                a_last.copy_from_slice(&a_blk);
                c_last.copy_from_slice(&c_blk);
                break;
            }
            if self.closed && k == 0 {
                border[..mm].copy_from_slice(&a_blk);
            }
            if k > 0 {
                // L = A D̃ₖ₋₁⁻¹; D̃ = D − L Cₖ₋₁.
                mat_mul(d, &a_blk, &fac.dinv[(k - 1) * mm..k * mm], &mut tmp);
                fac.l[k * mm..(k + 1) * mm].copy_from_slice(&tmp);
                mat_mul(d, &tmp, &fac.c[(k - 1) * mm..k * mm], &mut tmp2);
                for (dv, t) in d_blk.iter_mut().zip(&tmp2) {
                    *dv -= t;
                }
                if self.closed {
                    // G̃ₖ = Gₖ − L G̃ₖ₋₁.
                    mat_mul(d, &tmp, &border[(k - 1) * mm..k * mm], &mut tmp2);
                    for (g, t) in border[k * mm..(k + 1) * mm].iter_mut().zip(&tmp2) {
                        *g -= t;
                    }
                }
            }
            if self.closed && k + 2 == n {
                // The coupling of row n−2 to x_{n−1} belongs to the border column.
                for (g, cv) in border[k * mm..(k + 1) * mm].iter_mut().zip(&c_blk) {
                    *g += cv;
                }
                c_blk.fill(0.0);
            }
            fac.c[k * mm..(k + 1) * mm].copy_from_slice(&c_blk);
            if !invert(d, &d_blk, &mut fac.dinv[k * mm..(k + 1) * mm]) {
                return None;
            }
        }
        if self.closed {
            // Z_{n−2} = D̃⁻¹ G̃; Zₖ = D̃ₖ⁻¹ (G̃ₖ − Cₖ Zₖ₊₁).
            let mut z = vec![0.0; (n - 1) * mm];
            for k in (0..n - 1).rev() {
                tmp.copy_from_slice(&border[k * mm..(k + 1) * mm]);
                if k + 2 < n {
                    mat_mul(
                        d,
                        &fac.c[k * mm..(k + 1) * mm],
                        &z[(k + 1) * mm..(k + 2) * mm],
                        &mut tmp2,
                    );
                    for (t, s) in tmp.iter_mut().zip(&tmp2) {
                        *t -= s;
                    }
                }
                mat_mul(d, &fac.dinv[k * mm..(k + 1) * mm], &tmp, &mut tmp2);
                z[k * mm..(k + 1) * mm].copy_from_slice(&tmp2);
            }
            // Schur complement D − A Z_{n−2} − C Z₀.
            mat_mul(d, &a_last, &z[(n - 2) * mm..(n - 1) * mm], &mut tmp);
            mat_mul(d, &c_last, &z[..mm], &mut tmp2);
            for i in 0..mm {
                d_last[i] -= tmp[i] + tmp2[i];
            }
            let mut s_inv = vec![0.0; mm];
            if !invert(d, &d_last, &mut s_inv) {
                return None;
            }
            fac.z = z;
            fac.a_last = a_last;
            fac.c_last = c_last;
            fac.schur_inv = s_inv;
        }
        Some(fac)
    }

    /// The A and D blocks of row `k` at `x` (`tmp`, `u` scratch).
    #[allow(
        clippy::too_many_arguments,
        reason = "scratch buffers passed down to avoid allocation per row"
    )]
    fn blocks<D: Dim>(
        &self,
        d: D,
        k: usize,
        x: &[f64],
        a_blk: &mut [f64],
        d_blk: &mut [f64],
        tmp: &mut [f64],
        u: &mut [f64],
    ) {
        let m = d.get();
        a_blk.fill(0.0);
        d_blk.fill(0.0);
        if self.fixed_row(k).is_some() {
            let h = if k == 0 {
                self.seg[0].h
            } else {
                self.seg[k - 1].h
            };
            for i in 0..m {
                d_blk[i * m + i] = 4.0 / h;
            }
            return;
        }
        let mut diag = 0.0;
        if let Some(p) = self.prev(k) {
            let sc = &self.seg[p];
            let e = self.ehat(p);
            diag += 4.0 / sc.h;
            // A = (2/h) H̃ S.
            s_matrix(e, sc.sinc, 2.0 / sc.h, tmp);
            self.left_h(d, p, tmp, a_blk);
            // D += H̃ (DT(u) S⁻¹) H̃ᵀ, u = S⁻¹ H̃ᵀ xₖ.
            self.to_segment_end(p, &x[k * m..(k + 1) * m], u);
            apply_s(e, sc.inv_sinc, u);
            let up: f64 = dot(u, e);
            let mut wp = [0.0; 16];
            let mut wheap;
            let w_perp: &mut [f64] = if m <= 16 {
                &mut wp[..m]
            } else {
                wheap = vec![0.0; m];
                &mut wheap
            };
            for i in 0..m {
                w_perp[i] = u[i] - up * e[i];
            }
            let (k1, sp, si) = (sc.kappa, sc.dsinc, sc.inv_sinc);
            // DT = 2κ ê w⊥ᵀ + 2σ′ w∥ (I − êêᵀ) + 2σ′ w⊥ êᵀ;  DT S⁻¹ = σ⁻¹ DT + (1 − σ⁻¹) 2σ′ w⊥ êᵀ.
            for i in 0..m {
                for j in 0..m {
                    let id = if i == j { 1.0 } else { 0.0 };
                    let dt = 2.0 * k1 * e[i] * w_perp[j]
                        + 2.0 * sp * up * (id - e[i] * e[j])
                        + 2.0 * sp * w_perp[i] * e[j];
                    tmp[i * m + j] = si * dt + (1.0 - si) * 2.0 * sp * w_perp[i] * e[j];
                }
            }
            if self.is_seam(p) {
                // H tmp Hᵀ.
                let h = &self.hol;
                let mut t2 = vec![0.0; m * m];
                for i in 0..m {
                    for j in 0..m {
                        t2[i * m + j] = (0..m).map(|l| h[i * m + l] * tmp[l * m + j]).sum();
                    }
                }
                for i in 0..m {
                    for j in 0..m {
                        d_blk[i * m + j] +=
                            (0..m).map(|l| t2[i * m + l] * h[j * m + l]).sum::<f64>();
                    }
                }
            } else {
                for (dv, t) in d_blk.iter_mut().zip(tmp.iter()) {
                    *dv += t;
                }
            }
        }
        if let Some(nx) = self.next(k) {
            diag += 4.0 / self.seg[nx].h;
        }
        for i in 0..m {
            d_blk[i * m + i] += diag;
        }
    }

    /// `out = H̃·mat` (`H` across the seam, identity otherwise).
    fn left_h<D: Dim>(&self, d: D, seg: usize, mat: &[f64], out: &mut [f64]) {
        let m = d.get();
        if self.is_seam(seg) {
            mat_mul(d, &self.hol, mat, out);
        } else {
            out[..m * m].copy_from_slice(&mat[..m * m]);
        }
    }

    /// `x ← J⁻¹ x` with the factors.
    fn substitute<D: Dim>(&self, d: D, fac: &Factors, x: &mut [f64]) {
        let m = d.get();
        let mm = m * m;
        let n = self.n;
        let rows = if self.closed { n - 1 } else { n };
        let mut t = vec![0.0; m];
        // Forward: yₖ = bₖ − Lₖ yₖ₋₁.
        for k in 1..rows {
            mat_vec(
                d,
                &fac.l[k * mm..(k + 1) * mm],
                &x[(k - 1) * m..k * m],
                &mut t,
            );
            for (xa, ta) in x[k * m..(k + 1) * m].iter_mut().zip(&t) {
                *xa -= ta;
            }
        }
        // Back: wₖ = D̃ₖ⁻¹ (yₖ − Cₖ wₖ₊₁).
        for k in (0..rows).rev() {
            if k + 1 < rows {
                mat_vec(
                    d,
                    &fac.c[k * mm..(k + 1) * mm],
                    &x[(k + 1) * m..(k + 2) * m],
                    &mut t,
                );
                for (xa, ta) in x[k * m..(k + 1) * m].iter_mut().zip(&t) {
                    *xa -= ta;
                }
            }
            t.copy_from_slice(&x[k * m..(k + 1) * m]);
            mat_vec(
                d,
                &fac.dinv[k * mm..(k + 1) * mm],
                &t,
                &mut x[k * m..(k + 1) * m],
            );
        }
        if self.closed {
            // x_{n−1} = S⁻¹ (b_{n−1} − A w_{n−2} − C w₀); xₖ = wₖ − Zₖ x_{n−1}.
            let mut rhs = x[(n - 1) * m..].to_vec();
            mat_vec(d, &fac.a_last, &x[(n - 2) * m..(n - 1) * m], &mut t);
            for (r, ta) in rhs.iter_mut().zip(&t) {
                *r -= ta;
            }
            mat_vec(d, &fac.c_last, &x[..m], &mut t);
            for (r, ta) in rhs.iter_mut().zip(&t) {
                *r -= ta;
            }
            let mut last = vec![0.0; m];
            mat_vec(d, &fac.schur_inv, &rhs, &mut last);
            for k in 0..n - 1 {
                mat_vec(d, &fac.z[k * mm..(k + 1) * mm], &last, &mut t);
                for (xa, ta) in x[k * m..(k + 1) * m].iter_mut().zip(&t) {
                    *xa -= ta;
                }
            }
            x[(n - 1) * m..].copy_from_slice(&last);
        }
    }

    /// Newton's method from `x = 0`, reusing a factorisation while it converges fast.
    fn solve<D: Dim>(&self, d: D) -> Result<(Vec<f64>, CubicSolveInfo), SplineError> {
        let m = d.get();
        let mut x = vec![0.0; self.n * m];
        let mut f = vec![0.0; self.n * m];
        let mut residual = self.residual(d, &x, &mut f);
        let mut info = CubicSolveInfo {
            iterations: 0,
            factorizations: 0,
            residual,
        };
        let fail = |info: CubicSolveInfo| {
            SplineError::Solve(SolveError::NoConvergence {
                iterations: info.iterations,
                residual: info.residual,
            })
        };
        let mut fac: Option<Factors> = None;
        let mut fresh = false;
        while residual > TARGET_RESIDUAL && info.iterations < MAX_ITERATIONS {
            if fac.is_none() {
                fac = Some(self.factor(d, &x).ok_or_else(|| fail(info))?);
                info.factorizations += 1;
                fresh = true;
            }
            let factors = fac.as_ref().expect("factorised above");
            self.substitute(d, factors, &mut f);
            for (xa, fa) in x.iter_mut().zip(&f) {
                *xa -= fa;
            }
            info.iterations += 1;
            let new = self.residual(d, &x, &mut f);
            info.residual = new;
            if !new.is_finite() {
                return Err(fail(info));
            }
            if new >= residual && fresh {
                // No progress with a fresh Jacobian: rounding level reached.
                residual = new;
                break;
            }
            // Refactorise after the first (linear) step and whenever convergence is slow.
            if info.iterations == 1 || new > 0.1 * residual {
                fac = None;
            }
            fresh = false;
            residual = new;
        }
        info.residual = residual;
        if residual.is_nan() || residual > MAX_RESIDUAL || x.iter().any(|v| !v.is_finite()) {
            return Err(fail(info));
        }
        Ok((x, info))
    }
}

// The solver's small helpers are inlined by force natively (their calls cost more than their
// arithmetic); the wasm build, optimised for size, leaves inlining to the compiler (15.5 KB of
// the .wasm). Inlining changes no result: Rust contracts no float operations.

/// An m-vector and an m × m block (row-major) for a fixed tangent dimension.
type Vf<const M: usize> = [f64; M];
type Bf<const M: usize> = [[f64; M]; M];

/// `[f(0), …, f(M − 1)]`, always inlined (`vf` is not, in the solver's
/// loops, and its call per vector cost more than the arithmetic).
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn vf<const M: usize>(f: impl Fn(usize) -> f64) -> Vf<M> {
    let mut out = [0.0; M];
    for (a, o) in out.iter_mut().enumerate() {
        *o = f(a);
    }
    out
}

/// The block `[f(i, j)]`, as [`vf`].
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn bf<const M: usize>(f: impl Fn(usize, usize) -> f64) -> Bf<M> {
    let mut out = [[0.0; M]; M];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, o) in row.iter_mut().enumerate() {
            *o = f(i, j);
        }
    }
    out
}

#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn dotf<const M: usize>(a: &Vf<M>, b: &Vf<M>) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `x ← S x`, as [`apply_s`].
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn apply_sf<const M: usize>(e: &Vf<M>, sigma: f64, x: &mut Vf<M>) {
    let c = (1.0 - sigma) * dotf(e, x);
    for (xi, ei) in x.iter_mut().zip(e) {
        *xi = sigma * *xi + c * ei;
    }
}

/// `T(u)` added to `y`, as [`add_t`]; returns `|T(u)|²`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn add_tf<const M: usize>(sc: &SegConst, e: &Vf<M>, u: &Vf<M>, y: &mut Vf<M>) -> f64 {
    let up = dotf(u, e);
    let uu = dotf(u, u);
    let perp2 = (uu - up * up).max(0.0);
    let c1 = perp2 * sc.kappa;
    let c2 = 2.0 * sc.dsinc * up;
    let mut t2 = 0.0;
    for ((ya, ua), ea) in y.iter_mut().zip(u).zip(e) {
        let ta = c1 * ea + c2 * (ua - up * ea);
        t2 += ta * ta;
        *ya += ta;
    }
    t2
}

/// The symmetric bilinear form of `T` (`T(u) = B(u, u)`, [`add_tf`]):
/// `B(a, b) = κ(a·b − (a·ê)(b·ê))·ê + (sinc′ θ)·((a·ê)·b + (b·ê)·a − 2(a·ê)(b·ê)·ê)`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn bilinear_tf<const M: usize>(sc: &SegConst, e: &Vf<M>, a: &Vf<M>, b: &Vf<M>) -> Vf<M> {
    let (ae, be) = (dotf(a, e), dotf(b, e));
    let c1 = sc.kappa * (dotf(a, b) - ae * be) - 2.0 * sc.dsinc * ae * be;
    vf(|i| c1 * e[i] + sc.dsinc * (ae * b[i] + be * a[i]))
}

/// `zₖ ← zₖ − l·zₖ₋₁`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn eliminate_with<const M: usize>(l: &Bf<M>, k: usize, z: &mut [Vf<M>]) {
    let t = mat_vecf(l, &z[k - 1]);
    for a in 0..M {
        z[k][a] -= t[a];
    }
}

/// `v[k] = value`, or `v.push(value)` when `k == v.len()`: the first factorisation fills the
/// solver's rows in order, so they are not zeroed first.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn put<T>(v: &mut Vec<T>, k: usize, value: T) {
    if let Some(slot) = v.get_mut(k) {
        *slot = value;
    } else {
        debug_assert_eq!(k, v.len(), "rows are filled in order");
        v.push(value);
    }
}

/// `worst² = max(worst², |f|²/scale²)`, the division only for a row that raises it (infinite
/// for a non-finite residual).
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn raise_worst<const M: usize>(f: &Vf<M>, scale2: f64, worst2: &mut f64) {
    let fn2 = dotf(f, f);
    if fn2 > *worst2 * scale2 || !fn2.is_finite() {
        *worst2 = if fn2.is_finite() && scale2 > 0.0 {
            fn2 / scale2
        } else {
            f64::INFINITY
        };
    }
}

/// `scale·(σ·I + (1 − σ)·ê êᵀ)`, as [`s_matrix`].
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_matrixf<const M: usize>(e: &Vf<M>, sigma: f64, scale: f64) -> Bf<M> {
    let mut out = [[0.0; M]; M];
    for i in 0..M {
        for j in 0..M {
            let id = if i == j { sigma } else { 0.0 };
            out[i][j] = scale * (id + (1.0 - sigma) * e[i] * e[j]);
        }
    }
    out
}

/// `scale·S·x` for a block `x`, `S = σ·I + (1 − σ)·ê êᵀ`, without forming `S`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_left<const M: usize>(e: &Vf<M>, sigma: f64, scale: f64, x: &Bf<M>) -> Bf<M> {
    let ex: Vf<M> = vf(|j| (0..M).map(|l| e[l] * x[l][j]).sum());
    let (a, b) = (scale * sigma, scale * (1.0 - sigma));
    bf(|i, j| a * x[i][j] + b * e[i] * ex[j])
}

/// `scale·x·S` for a block `x`, as [`s_left`].
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_right<const M: usize>(x: &Bf<M>, e: &Vf<M>, sigma: f64, scale: f64) -> Bf<M> {
    let xe: Vf<M> = vf(|i| dotf(&x[i], e));
    let (a, b) = (scale * sigma, scale * (1.0 - sigma));
    bf(|i, j| a * x[i][j] + b * xe[i] * e[j])
}

#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn mat_mulf<const M: usize>(a: &Bf<M>, b: &Bf<M>) -> Bf<M> {
    let mut out = [[0.0; M]; M];
    for i in 0..M {
        for j in 0..M {
            let mut s = 0.0;
            for l in 0..M {
                s += a[i][l] * b[l][j];
            }
            out[i][j] = s;
        }
    }
    out
}

/// `a·bᵀ`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn mat_mul_tf<const M: usize>(a: &Bf<M>, b: &Bf<M>) -> Bf<M> {
    let mut out = [[0.0; M]; M];
    for i in 0..M {
        for j in 0..M {
            out[i][j] = (0..M).map(|l| a[i][l] * b[j][l]).sum();
        }
    }
    out
}

#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn mat_vecf<const M: usize>(a: &Bf<M>, x: &Vf<M>) -> Vf<M> {
    let mut out = [0.0; M];
    for i in 0..M {
        let mut s = 0.0;
        for l in 0..M {
            s += a[i][l] * x[l];
        }
        out[i] = s;
    }
    out
}

/// `a⁻¹` for the pivot blocks of the Jacobian: the adjugate over the determinant for
/// `M ≤ 3` (branch-free, one division; the blocks are diagonally dominant, and a less accurate
/// inverse would only slow Newton's convergence, never change the residual it stops at), the
/// elimination of [`invert`] otherwise; `None` if singular.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn invertf<const M: usize>(a: &Bf<M>) -> Option<Bf<M>> {
    let mut out = [[0.0; M]; M];
    match M {
        1 => {
            out[0][0] = 1.0 / a[0][0];
            return (a[0][0] != 0.0 && out[0][0].is_finite()).then_some(out);
        }
        2 => {
            let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
            let r = 1.0 / det;
            out[0][0] = a[1][1] * r;
            out[0][1] = -a[0][1] * r;
            out[1][0] = -a[1][0] * r;
            out[1][1] = a[0][0] * r;
            return (det != 0.0 && r.is_finite() && out.iter().flatten().all(|v| v.is_finite()))
                .then_some(out);
        }
        3 => {
            let c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
            let c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
            let c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
            let det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
            let r = 1.0 / det;
            out[0][0] = c00 * r;
            out[1][0] = c01 * r;
            out[2][0] = c02 * r;
            out[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * r;
            out[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * r;
            out[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * r;
            out[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * r;
            out[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * r;
            out[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * r;
            return (det != 0.0 && r.is_finite() && out.iter().flatten().all(|v| v.is_finite()))
                .then_some(out);
        }
        _ => {}
    }
    invert_gj(a)
}

/// `a⁻¹` by the elimination of [`invert`]; `None` if singular.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn invert_gj<const M: usize>(a: &Bf<M>) -> Option<Bf<M>> {
    let mut w = *a;
    let mut out = [[0.0; M]; M];
    for (i, row) in out.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for col in 0..M {
        let piv = (col..M).fold(col, |p, r| {
            if w[r][col].abs() > w[p][col].abs() {
                r
            } else {
                p
            }
        });
        let pv = w[piv][col];
        if pv == 0.0 || !pv.is_finite() {
            return None;
        }
        if piv != col {
            w.swap(piv, col);
            out.swap(piv, col);
        }
        let inv = 1.0 / pv;
        for j in 0..M {
            w[col][j] *= inv;
            out[col][j] *= inv;
        }
        for r in 0..M {
            if r != col {
                let f = w[r][col];
                if f != 0.0 {
                    for j in 0..M {
                        w[r][j] -= f * w[col][j];
                        out[r][j] -= f * out[col][j];
                    }
                }
            }
        }
    }
    Some(out)
}

/// The solver for a fixed tangent dimension `M`: the continuity equations of [`Geometry`] with
/// arrays for vectors and blocks, and a workspace allocated once per solve.
///
/// Each Newton or chord step is two sweeps over the keys. The forward sweep evaluates the
/// residual row by row and eliminates it at once with the block LU factors (when the step
/// refactorises, the same sweep builds the Jacobian's row and the factors first), so the
/// arithmetic of the residual overlaps the dependent chain of the elimination. The backward
/// sweep substitutes, one block product deep per key (`δₖ = D̃ₖ⁻¹zₖ − Gₖ δₖ₊₁`).
struct FixedSolver<'g, const M: usize> {
    g: &'g Geometry,
    e: Vec<Vf<M>>,
    hol: Bf<M>,
    fixed: Option<(Vf<M>, Vf<M>)>,
    /// Per row of the block tridiagonal part, its factors.
    fac: Vec<RowFactors<M>>,
    /// Per row, from the last evaluation of the equations (the factorising sweep): the squared
    /// size of the row's terms, and `Wₖ`, the end velocity `S⁻¹H̃ᵀ(xₖ − x̄ₖ)` of the row's
    /// nonlinear term at the deviation of `x` from the point `x̄` of the factorisation.
    scale2: Vec<f64>,
    dev: Vec<Vf<M>>,
    /// From the last evaluation, the largest `Lₖ²/scale2ₖ` and `Qₖ²/scale2ₖ`, where
    /// `Lₖω + Qₖω²` bounds how much the row's terms can move when no unknown moves by more
    /// than `ω` (see [`bound`](Self::bound)), and since then the largest `|Wₖ|²`, which bounds
    /// `ω²`.
    sens2: f64,
    quad2: f64,
    dev2: f64,
    /// Closed: the border column (eliminated in the forward sweep, then `Zₖ`), `A_{n−1}`,
    /// `D_{n−1}`, `C_{n−1}`, the inverse Schur complement of the last unknown.
    border: Vec<Bf<M>>,
    a_last: Bf<M>,
    d_last: Bf<M>,
    c_last: Bf<M>,
    schur_inv: Bf<M>,
}

/// One row of the continuity equations: its residual, the squared size of its terms, and its
/// diagonal Jacobian block.
struct Row<const M: usize> {
    f: Vf<M>,
    scale2: f64,
    /// `Lₖ` and `Qₖ`: the row's terms move by at most `Lₖω + Qₖω²` when no unknown moves by
    /// more than `ω`.
    lip: f64,
    quad: f64,
    d: Bf<M>,
}

/// The block LU factors of one row: `Lₖ = Aₖ D̃ₖ₋₁⁻¹`, `D̃ₖ⁻¹` and `Gₖ = D̃ₖ⁻¹ Cₖ`.
struct RowFactors<const M: usize> {
    l: Bf<M>,
    dinv: Bf<M>,
    gm: Bf<M>,
}

/// The factorisation met a singular pivot block.
struct Singular;

#[allow(
    clippy::needless_range_loop,
    reason = "element loops over the fixed-size blocks, indexed like the formulas"
)]
impl<'g, const M: usize> FixedSolver<'g, M> {
    /// The solver for `g`, of tangent dimension `g.m ≤ M`: a smaller dimension is padded with
    /// zero coordinates (zero directions, fixed velocities and unknowns, an identity holonomy),
    /// on which the equations decouple into `σ·0 = 0`; the padded unknowns stay exactly 0.
    fn new(g: &'g Geometry) -> Self {
        let m = g.m;
        debug_assert!(m <= M, "tangent dimension {m} above {M}");
        let arr = |s: &[f64]| -> Vf<M> { vf(|a| if a < m { s[a] } else { 0.0 }) };
        let e = g.ehat.chunks_exact(m).map(arr).collect();
        let mut hol = [[0.0; M]; M];
        if g.closed {
            for (a, row) in hol.iter_mut().enumerate() {
                for (b, v) in row.iter_mut().enumerate() {
                    *v = if a < m && b < m {
                        g.hol[a * m + b]
                    } else if a == b {
                        1.0
                    } else {
                        0.0
                    };
                }
            }
        }
        let fixed = g.fixed.as_ref().map(|(g0, g1)| (arr(g0), arr(g1)));
        let n = g.n;
        let zero = [[0.0; M]; M];
        // The rows are filled in order by the first factorisation ([`put`]).
        Self {
            g,
            e,
            hol,
            fixed,
            fac: Vec::with_capacity(n),
            scale2: Vec::with_capacity(n),
            dev: Vec::with_capacity(n),
            sens2: 0.0,
            quad2: 0.0,
            dev2: 0.0,
            border: if g.closed {
                Vec::with_capacity(n)
            } else {
                Vec::new()
            },
            a_last: zero,
            d_last: zero,
            c_last: zero,
            schur_inv: zero,
        }
    }

    /// `Hᵀ·y`.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn hol_t(&self, y: &Vf<M>) -> Vf<M> {
        vf(|b| (0..M).map(|a| self.hol[a][b] * y[a]).sum())
    }

    /// The block `Aₖ` of a non-fixed row (the coupling to the unknown before; `seam`: the first
    /// row of a loop, coupled across the seam).
    fn a_block(&self, k: usize, seam: bool) -> Bf<M> {
        let p = if seam { self.g.n - 1 } else { k - 1 };
        let sc = &self.g.seg[p];
        let s = s_matrixf(&self.e[p], sc.sinc, sc.c2);
        if seam { mat_mulf(&self.hol, &s) } else { s }
    }

    /// The block `Cₖ` of a non-fixed row (the coupling to the unknown after; `seam`: the last
    /// row of a loop).
    fn c_block(&self, k: usize, seam: bool) -> Bf<M> {
        let sc = &self.g.seg[k];
        let c = s_matrixf(&self.e[k], sc.inv_sinc, sc.c2);
        if seam { mat_mul_tf(&c, &self.hol) } else { c }
    }

    /// `S⁻¹ H̃ᵀ x_{seg+1}` (the end velocity of segment `seg` in its transported frame; the
    /// holonomy only across the seam).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn end_velocity(&self, seg: usize, seam: bool, x: &[Vf<M>]) -> Vf<M> {
        let mut u = if seam { self.hol_t(&x[0]) } else { x[seg + 1] };
        apply_sf(&self.e[seg], self.g.seg[seg].inv_sinc, &mut u);
        u
    }

    /// Row `k` at `x`, given the end velocities of the segments before (`w_prev`) and after
    /// (`w_next`) the key; `first` and `last` say whether `k` is the first or last key (the
    /// callers pass constants, so the interior rows have no branches).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn row(
        &self,
        k: usize,
        first: bool,
        last: bool,
        x: &[Vf<M>],
        w_prev: &Vf<M>,
        w_next: &Vf<M>,
    ) -> Row<M> {
        let g = self.g;
        let n = g.n;
        let zero = [[0.0; M]; M];
        let mut row = Row {
            f: [0.0; M],
            scale2: 0.0,
            lip: 0.0,
            quad: 0.0,
            d: zero,
        };
        let xk = &x[k];
        if (first || last)
            && let Some((g0, g1)) = &self.fixed
        {
            let (gk, c4) = if first {
                (g0, g.seg[0].c4)
            } else {
                (g1, g.seg[k - 1].c4)
            };
            for a in 0..M {
                row.f[a] = c4 * (xk[a] - gk[a]);
            }
            row.scale2 = c4 * c4 * (dotf(xk, xk) + dotf(gk, gk));
            for i in 0..M {
                row.d[i][i] = c4;
            }
            return row;
        }
        let mut diag = 0.0;
        // The segment before the key (across the seam for the first key of a loop).
        if !first || g.closed {
            let (p, seam) = if first { (n - 1, true) } else { (k - 1, false) };
            let sc = &g.seg[p];
            let e = &self.e[p];
            let mut y = x[p];
            apply_sf(e, sc.sinc, &mut y);
            for ya in &mut y {
                *ya *= sc.c2;
            }
            let lin2 = dotf(&y, &y);
            let t2 = add_tf(sc, e, w_prev, &mut y);
            for (ya, ea) in y.iter_mut().zip(e) {
                *ya -= sc.c6 * ea;
            }
            let y = if seam {
                vf(|a| (0..M).map(|b| self.hol[a][b] * y[b]).sum())
            } else {
                y
            };
            for a in 0..M {
                row.f[a] += y[a];
            }
            row.scale2 += lin2 + t2 + sc.c6 * sc.c6;
            diag += sc.c4;
            // `c₂S·x_{k−1}` moves by at most `c₂ω`; `T(w)` by `|B(W, W + 2w)| ≤ c_B·ω(ω + 2|w|)`
            // (`|B(a, b)| ≤ (|κ| + |sinc′|)·|a||b|`, `W = S⁻¹Δxₖ`, `|Δxₖ| ≤ |W| ≤ ω`).
            let c_b = sc.kappa.abs() + sc.dsinc.abs();
            row.lip += sc.c2 + 2.0 * c_b * dotf(w_prev, w_prev).sqrt();
            row.quad = c_b;
            // DT·S⁻¹ at the end velocity `w_prev` (the derivative of T(S⁻¹ H̃ᵀ xₖ)):
            // β·I + ê qᵀ + γ·w⊥ êᵀ with q = α·w⊥ − β·ê.
            let u = w_prev;
            let up = dotf(u, e);
            let w_perp: Vf<M> = vf(|i| u[i] - up * e[i]);
            let alpha = 2.0 * sc.inv_sinc * sc.kappa;
            let beta = 2.0 * sc.inv_sinc * sc.dsinc * up;
            let gamma = 2.0 * sc.dsinc;
            let q: Vf<M> = vf(|j| alpha * w_perp[j] - beta * e[j]);
            let mut dt = [[0.0; M]; M];
            for i in 0..M {
                for j in 0..M {
                    dt[i][j] = e[i] * q[j] + gamma * w_perp[i] * e[j];
                }
                dt[i][i] += beta;
            }
            row.d = if seam {
                mat_mul_tf(&mat_mulf(&self.hol, &dt), &self.hol)
            } else {
                dt
            };
        }
        // The segment after the key (for the last key of a loop, the closing segment).
        if !last || g.closed {
            let sc = &g.seg[k];
            let e = &self.e[k];
            for a in 0..M {
                row.f[a] += sc.c2 * w_next[a] - sc.c6 * e[a];
            }
            row.scale2 += sc.c2 * sc.c2 * dotf(w_next, w_next) + sc.c6 * sc.c6;
            diag += sc.c4;
            row.lip += sc.c2 * sc.inv_sinc;
        }
        row.lip += diag;
        for a in 0..M {
            row.f[a] += diag * xk[a];
        }
        row.scale2 += diag * diag * dotf(xk, xk);
        for i in 0..M {
            row.d[i][i] += diag;
        }
        row
    }

    /// The forward sweep at `x`: the Jacobian's rows are built and factorised, and row `k`'s
    /// residual is eliminated into `z[k]`. Returns the largest row residual relative to the
    /// size of the row's terms (infinite for a non-finite residual).
    ///
    /// With `ul`, `x` is first corrected ([`correct`](Self::correct)), one row ahead of the
    /// sweep, from the right-hand side in `z` that [`linear_step`](Self::linear_step) left.
    fn sweep(
        &mut self,
        x: &mut [Vf<M>],
        z: &mut [Vf<M>],
        ul: Option<&[f64]>,
    ) -> Result<f64, Singular> {
        let g = self.g;
        let n = g.n;
        let mut worst2 = 0.0_f64;
        (self.sens2, self.quad2, self.dev2) = (0.0, 0.0, 0.0);
        let mut w_prev = if g.closed {
            self.end_velocity(n - 1, true, x)
        } else {
            [0.0; M]
        };
        let mut prev = [0.0; M];
        if let Some(ul) = ul {
            self.correct(0, x, z, ul, &mut prev);
            self.correct(1, x, z, ul, &mut prev);
        }
        self.edge_row(0, true, x, z, &mut w_prev, &mut worst2)?;
        for k in 1..n - 1 {
            if let Some(ul) = ul {
                self.correct(k + 1, x, z, ul, &mut prev);
            }
            self.sweep_row(k, false, false, x, z, &mut w_prev, &mut worst2)?;
        }
        self.edge_row(n - 1, false, x, z, &mut w_prev, &mut worst2)?;
        if g.closed {
            self.finish_border()?;
        }
        Ok(worst2.sqrt())
    }

    /// The first or last row: [`sweep_row`](Self::sweep_row) out of line (the interior rows
    /// are inlined into the sweep's loop, specialised for their position).
    #[inline(never)]
    fn edge_row(
        &mut self,
        k: usize,
        first: bool,
        x: &[Vf<M>],
        z: &mut [Vf<M>],
        w_prev: &mut Vf<M>,
        worst2: &mut f64,
    ) -> Result<(), Singular> {
        self.sweep_row(k, first, !first, x, z, w_prev, worst2)
    }

    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    #[allow(
        clippy::too_many_arguments,
        reason = "the state carried from row to row"
    )]
    fn sweep_row(
        &mut self,
        k: usize,
        first: bool,
        last: bool,
        x: &[Vf<M>],
        z: &mut [Vf<M>],
        w_prev: &mut Vf<M>,
        worst2: &mut f64,
    ) -> Result<(), Singular> {
        let g = self.g;
        let n = g.n;
        let w_next = if !last {
            self.end_velocity(k, false, x)
        } else if g.closed {
            self.end_velocity(n - 1, true, x)
        } else {
            [0.0; M]
        };
        let row = self.row(k, first, last, x, w_prev, &w_next);
        *w_prev = w_next;
        raise_worst(&row.f, row.scale2, worst2);
        // (Rows without the nonlinear term are solved exactly by a chord step.)
        if !first || g.closed {
            for (c, max2) in [(row.lip, &mut self.sens2), (row.quad, &mut self.quad2)] {
                if c * c > *max2 * row.scale2 {
                    *max2 = if row.scale2 > 0.0 {
                        c * c / row.scale2
                    } else {
                        f64::INFINITY
                    };
                }
            }
        }
        put(&mut self.scale2, k, row.scale2);
        put(&mut self.dev, k, [0.0; M]);
        if g.closed && last {
            // The Schur row: kept whole, eliminated in `back`.
            z[k] = row.f;
            self.a_last = self.a_block(k, false);
            self.d_last = row.d;
            self.c_last = self.c_block(k, true);
            return Ok(());
        }
        // A fixed row has no coupling; the others couple to both neighbours (the first key of
        // an open curve has no row before it).
        let fixed = (first || last) && self.fixed.is_some();
        let coupled_prev = !fixed && (!first || g.closed);
        let mut d = row.d;
        let l = if coupled_prev && !first {
            let (e, sc, prev) = (&self.e[k - 1], &g.seg[k - 1], &self.fac[k - 1]);
            let t = s_left(e, sc.sinc, sc.c2, &prev.gm);
            for i in 0..M {
                for j in 0..M {
                    d[i][j] -= t[i][j];
                }
            }
            s_left(e, sc.sinc, sc.c2, &prev.dinv)
        } else {
            [[0.0; M]; M]
        };
        let dinv = invertf(&d).ok_or(Singular)?;
        let merge = g.closed && k + 2 == n;
        if g.closed {
            let mut b = if first {
                self.a_block(k, true)
            } else {
                let t = mat_mulf(&l, &self.border[k - 1]);
                bf(|i, j| -t[i][j])
            };
            if merge {
                let c = self.c_block(k, false);
                for i in 0..M {
                    for j in 0..M {
                        b[i][j] += c[i][j];
                    }
                }
            }
            put(&mut self.border, k, b);
        }
        let gm = if fixed || merge || last {
            [[0.0; M]; M]
        } else {
            let (e, sc) = (&self.e[k], &g.seg[k]);
            s_right(&dinv, e, sc.inv_sinc, sc.c2)
        };
        // The elimination with the row's own `l` (not read back from `fac`, just stored).
        z[k] = row.f;
        if !first {
            eliminate_with(&l, k, z);
        }
        put(&mut self.fac, k, RowFactors { l, dinv, gm });
        Ok(())
    }

    /// `zₖ ← zₖ − Lₖ zₖ₋₁`.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn eliminate_row(&self, k: usize, z: &mut [Vf<M>]) {
        eliminate_with(&self.fac[k].l, k, z);
    }

    /// The forward elimination of a chord step: `z` holds the residual `F(x)` (from
    /// [`back`](Self::back)'s update), and is overwritten by `L⁻¹F(x)` (the last row of a loop
    /// is the Schur row, kept whole).
    fn eliminate(&self, z: &mut [Vf<M>]) {
        let rows = self.g.n - usize::from(self.g.closed);
        for k in 1..rows {
            self.eliminate_row(k, z);
        }
    }

    /// The residual of row `k` after the chord step `x ← x − d` (`d = dₖ`, the step of the
    /// row's unknown), from the residual `F(x) + J(x̄)(−d) = 0` that the step solves: the
    /// equations are linear in `x` except for the term `T(wₖ)` of the segment before the key,
    /// a quadratic form `B(w, w)` in the end velocity `wₖ = S⁻¹H̃ᵀxₖ`, so with `Wₖ = wₖ(x − x̄)`
    /// and `s = wₖ(d)`,
    ///
    /// ```text
    /// F(x − d)ₖ = T(w − s) − T(w) + DT(w̄)s = B(s − 2W, s)   (H̃ applied across the seam)
    /// ```
    ///
    /// exactly; `Wₖ` becomes `W − s`. Rows without the term (a fixed row, the first row of an
    /// open curve) are linear and solved exactly: 0.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn update(&mut self, k: usize, d: &Vf<M>) -> Vf<M> {
        let g = self.g;
        let (p, seam) = if k > 0 {
            (k - 1, false)
        } else if g.closed {
            (g.n - 1, true)
        } else {
            // No nonlinear term: `dev` keeps the deviation of the unknown itself (for `dev2`).
            let w = &mut self.dev[0];
            for i in 0..M {
                w[i] -= d[i];
            }
            self.dev2 = self.dev2.max(dotf(w, w));
            return [0.0; M];
        };
        if self.fixed.is_some() && k + 1 == g.n {
            return [0.0; M];
        }
        let mut s = if seam { self.hol_t(d) } else { *d };
        let (sc, e) = (&g.seg[p], &self.e[p]);
        apply_sf(e, sc.inv_sinc, &mut s);
        let w = &mut self.dev[k];
        let a: Vf<M> = vf(|i| s[i] - 2.0 * w[i]);
        for i in 0..M {
            w[i] -= s[i];
        }
        let w2 = dotf(w, w);
        if w2 > self.dev2 {
            self.dev2 = w2;
        }
        let f = bilinear_tf(sc, e, &a, &s);
        if seam {
            vf(|i| (0..M).map(|j| self.hol[i][j] * f[j]).sum())
        } else {
            f
        }
    }

    /// The first step of an open curve, `x ← −J(0)⁻¹F(0)`, from `x = 0`; returns the relative
    /// residual at `0`.
    ///
    /// At `x = 0` the end velocities vanish, so `T` and its derivative do too: the Jacobian is
    /// the linear part, whose blocks are `Aₖ = (2/hₖ₋₁)Sₖ₋₁`, `Dₖ = dₖ·I` and
    /// `Cₖ = (2/hₖ)Sₖ⁻¹`. Since `Aₖ₊₁Cₖ = (2/hₖ)²·I`, every pivot block of its LU factorisation is
    /// a multiple of the identity, `δₖ = dₖ − (2/hₖ₋₁)²/δₖ₋₁` (a fixed end row has no coupling),
    /// and the step costs two sweeps of `S`-products (the Euclidean spline's recurrence); `piv`
    /// receives `1/δₖ`.
    ///
    /// The backward sweep also prepares the correction ([`correct`](Self::correct)): as each
    /// `xₖ` comes out, the residual there, `T(wₖ)`, is eliminated from the last row up (the
    /// pivots of that direction, `πₖ = dₖ − (2/hₖ)²/πₖ₊₁`, are scalars too) into `z`, and
    /// `ul` receives `1/πₖ` (the forward sweep leaves the diagonal `dₖ` there).
    fn linear_step(
        &self,
        x: &mut [Vf<M>],
        piv: &mut [f64],
        z: &mut [Vf<M>],
        ul: &mut [f64],
    ) -> f64 {
        let g = self.g;
        let n = g.n;
        let fixed = self.fixed.as_ref();
        let mut worst2 = 0.0_f64;
        let mut z_prev = [0.0; M];
        let mut inv_prev = 1.0;
        for k in 0..n {
            let mut f = [0.0; M];
            let mut scale2 = 0.0;
            let mut d = 0.0;
            let mut z;
            match fixed {
                Some((g0, g1)) if k == 0 || k + 1 == n => {
                    let (gk, c4) = if k == 0 {
                        (g0, g.seg[0].c4)
                    } else {
                        (g1, g.seg[k - 1].c4)
                    };
                    for a in 0..M {
                        f[a] = -c4 * gk[a];
                    }
                    scale2 = c4 * c4 * dotf(gk, gk);
                    d = c4;
                    ul[k] = d;
                    z = f;
                }
                _ => {
                    for seg in [k.checked_sub(1), (k + 1 < n).then_some(k)]
                        .into_iter()
                        .flatten()
                    {
                        let sc = &g.seg[seg];
                        for (fa, ea) in f.iter_mut().zip(&self.e[seg]) {
                            *fa -= sc.c6 * ea;
                        }
                        scale2 += sc.c6 * sc.c6;
                        d += sc.c4;
                    }
                    z = f;
                    ul[k] = d;
                    if k > 0 {
                        let sc = &g.seg[k - 1];
                        let mut az = z_prev;
                        apply_sf(&self.e[k - 1], sc.sinc, &mut az);
                        let c = sc.c2 * inv_prev;
                        for a in 0..M {
                            z[a] -= c * az[a];
                        }
                        if fixed.is_none() || k > 1 {
                            d -= sc.c2 * c;
                        }
                    }
                }
            }
            let fn2 = dotf(&f, &f);
            if fn2 > worst2 * scale2 || !fn2.is_finite() {
                worst2 = if fn2.is_finite() && scale2 > 0.0 {
                    fn2 / scale2
                } else {
                    f64::INFINITY
                };
            }
            let inv = 1.0 / d;
            piv[k] = inv;
            x[k] = z;
            z_prev = z;
            inv_prev = inv;
        }
        let mut next: Vf<M> = vf(|a| x[n - 1][a] * piv[n - 1]);
        x[n - 1] = vf(|a| -next[a]);
        // The correction's right-hand side `T(wₖ)` (the residual at the new x) and its
        // elimination from the last row up, as each `xₖ` comes out (see `correct`).
        let is_fixed = |k: usize| fixed.is_some() && (k == 0 || k + 1 == n);
        let mut zeta = self.tee(n - 1, &x[n - 1]);
        let mut pi = ul[n - 1];
        z[n - 1] = zeta;
        ul[n - 1] = 1.0 / pi;
        for k in (0..n - 1).rev() {
            let mut t = x[k];
            let coupled_next = fixed.is_none() || k > 0;
            if coupled_next {
                let sc = &g.seg[k];
                let mut c = next;
                apply_sf(&self.e[k], sc.inv_sinc, &mut c);
                for a in 0..M {
                    t[a] -= sc.c2 * c[a];
                }
            }
            next = vf(|a| t[a] * piv[k]);
            x[k] = vf(|a| -next[a]);
            let mut r = self.tee(k, &x[k]);
            let mut d = ul[k];
            if coupled_next {
                let sc = &g.seg[k];
                let c = sc.c2 * ul[k + 1];
                apply_sf(&self.e[k], sc.inv_sinc, &mut zeta);
                for a in 0..M {
                    r[a] -= c * zeta[a];
                }
                if !is_fixed(k + 1) {
                    d -= sc.c2 * c;
                }
            }
            zeta = r;
            pi = d;
            z[k] = zeta;
            ul[k] = 1.0 / pi;
        }
        worst2.sqrt()
    }

    /// The nonlinear term `T(wₖ)` of row `k` of an open curve at `xₖ` (0 for the rows without
    /// it: the first and the fixed ones).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn tee(&self, k: usize, xk: &Vf<M>) -> Vf<M> {
        let mut f = [0.0; M];
        if k > 0 && !(self.fixed.is_some() && k + 1 == self.g.n) {
            let (sc, e) = (&self.g.seg[k - 1], &self.e[k - 1]);
            let mut w = *xk;
            apply_sf(e, sc.inv_sinc, &mut w);
            add_tf(sc, e, &w, &mut f);
        }
        f
    }

    /// Row `k` of the correction `x ← x − J(0)⁻¹T(w(x))` after
    /// [`linear_step`](Self::linear_step) (an open curve), which leaves the right-hand side
    /// eliminated from the last row up in `z` and those pivots in `ul`: the forward
    /// substitution, `prev` the correction of the row before. The linear part is solved at
    /// the linear step's `x`, so the residual there is the nonlinear term; this step with the
    /// linear Jacobian (scalar pivots, as in the linear step) takes `x` about 30× closer to the
    /// solution before Newton's first factorisation.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn correct(&self, k: usize, x: &mut [Vf<M>], z: &[Vf<M>], ul: &[f64], prev: &mut Vf<M>) {
        let g = self.g;
        let mut t = z[k];
        if k > 0 && !(self.fixed.is_some() && k + 1 == g.n) {
            let sc = &g.seg[k - 1];
            apply_sf(&self.e[k - 1], sc.sinc, prev);
            for a in 0..M {
                t[a] -= sc.c2 * prev[a];
            }
        }
        *prev = vf(|a| t[a] * ul[k]);
        for a in 0..M {
            x[k][a] -= prev[a];
        }
    }

    /// Closed: `Zₖ` from the eliminated border column, and the inverse Schur complement.
    fn finish_border(&mut self) -> Result<(), Singular> {
        let n = self.g.n;
        let rows = n - 1;
        let mut next = mat_mulf(&self.fac[rows - 1].dinv, &self.border[rows - 1]);
        self.border[rows - 1] = next;
        for k in (0..rows - 1).rev() {
            let mut zk = mat_mulf(&self.fac[k].dinv, &self.border[k]);
            let t = mat_mulf(&self.fac[k].gm, &next);
            for i in 0..M {
                for j in 0..M {
                    zk[i][j] -= t[i][j];
                }
            }
            self.border[k] = zk;
            next = zk;
        }
        let t1 = mat_mulf(&self.a_last, &self.border[n - 2]);
        let t2 = mat_mulf(&self.c_last, &self.border[0]);
        let mut s = self.d_last;
        for i in 0..M {
            for j in 0..M {
                s[i][j] -= t1[i][j] + t2[i][j];
            }
        }
        self.schur_inv = invertf(&s).ok_or(Singular)?;
        Ok(())
    }

    /// The updated residual `worst` (each row relative to the size of its terms at the last
    /// evaluation, [`back`](Self::back)) as a bound of the relative residual at the new `x`:
    /// no unknown has moved by more than `ω` (`ω² ≤ dev2`) since, so the size of row `k`'s
    /// terms is at least `√scale2ₖ − Lₖω − Qₖω² ≥ √scale2ₖ·(1 − δ)` with
    /// `δ = ω·√sens2 + ω²·√quad2`, and the relative residual at most `worst/(1 − δ)`.
    /// Infinite (no bound) unless `δ < 1`.
    fn bound(&self, worst: f64) -> f64 {
        let delta = (self.sens2 * self.dev2).sqrt() + self.dev2 * self.quad2.sqrt();
        if delta < 1.0 {
            worst / (1.0 - delta)
        } else {
            f64::INFINITY
        }
    }

    /// The backward sweep: `x ← x − J⁻¹F` from the eliminated residual `z`, which is
    /// overwritten by the residual at the new `x` ([`update`](Self::update)). Returns its
    /// largest row relative to the size of the row's terms at the last evaluation.
    fn back(&mut self, z: &mut [Vf<M>], x: &mut [Vf<M>]) -> f64 {
        let n = self.g.n;
        let mut worst2 = 0.0_f64;
        if !self.g.closed {
            let mut next = mat_vecf(&self.fac[n - 1].dinv, &z[n - 1]);
            for a in 0..M {
                x[n - 1][a] -= next[a];
            }
            z[n - 1] = self.update(n - 1, &next);
            raise_worst(&z[n - 1], self.scale2[n - 1], &mut worst2);
            for k in (0..n - 1).rev() {
                let f = &self.fac[k];
                let y = mat_vecf(&f.dinv, &z[k]);
                let t = mat_vecf(&f.gm, &next);
                let d: Vf<M> = vf(|a| y[a] - t[a]);
                for a in 0..M {
                    x[k][a] -= d[a];
                }
                z[k] = self.update(k, &d);
                raise_worst(&z[k], self.scale2[k], &mut worst2);
                next = d;
            }
            return worst2.sqrt();
        }
        let rows = n - 1;
        let mut next = mat_vecf(&self.fac[rows - 1].dinv, &z[rows - 1]);
        z[rows - 1] = next;
        for k in (0..rows - 1).rev() {
            let f = &self.fac[k];
            let y = mat_vecf(&f.dinv, &z[k]);
            let t = mat_vecf(&f.gm, &next);
            next = vf(|a| y[a] - t[a]);
            z[k] = next;
        }
        let mut rhs = z[n - 1];
        let t1 = mat_vecf(&self.a_last, &z[n - 2]);
        let t2 = mat_vecf(&self.c_last, &z[0]);
        for a in 0..M {
            rhs[a] -= t1[a] + t2[a];
        }
        let last = mat_vecf(&self.schur_inv, &rhs);
        for k in 0..rows {
            let t = mat_vecf(&self.border[k], &last);
            let d: Vf<M> = vf(|a| z[k][a] - t[a]);
            for a in 0..M {
                x[k][a] -= d[a];
            }
            z[k] = self.update(k, &d);
            raise_worst(&z[k], self.scale2[k], &mut worst2);
        }
        for a in 0..M {
            x[n - 1][a] -= last[a];
        }
        z[n - 1] = self.update(n - 1, &last);
        raise_worst(&z[n - 1], self.scale2[n - 1], &mut worst2);
        worst2.sqrt()
    }

    /// [`Geometry::solve`] for the fixed dimension: with the correction of the linear step
    /// ([`correct`](Self::correct)), and without it if that fails (far from the linear
    /// solution the correction can lead Newton's method astray, as on keys of alternating signs
    /// on S³, where the uncorrected iteration still converges).
    fn solve(mut self) -> Result<(Vec<f64>, CubicSolveInfo), SplineError> {
        self.run(true).or_else(|_| self.run(false))
    }

    fn run(&mut self, correct: bool) -> Result<(Vec<f64>, CubicSolveInfo), SplineError> {
        let n = self.g.n;
        let mut x = vec![[0.0; M]; n];
        let mut z = vec![[0.0; M]; n];
        let fail = |info: CubicSolveInfo| {
            SplineError::Solve(SolveError::NoConvergence {
                iterations: info.iterations,
                residual: info.residual,
            })
        };
        let mut info = CubicSolveInfo {
            iterations: 0,
            factorizations: 1,
            residual: f64::INFINITY,
        };
        // The Jacobian at x = 0 is the linear part: the first step is scipy's first iterate.
        let mut residual;
        if self.g.closed {
            residual = self.sweep(&mut x, &mut z, None).map_err(|_| fail(info))?;
        } else {
            let (mut piv, mut ul) = (vec![0.0; n], vec![0.0; n]);
            residual = self.linear_step(&mut x, &mut piv, &mut z, &mut ul);
            if residual > TARGET_RESIDUAL {
                info.iterations = 1;
                info.factorizations = 2;
                let new = self
                    .sweep(&mut x, &mut z, correct.then_some(&ul[..]))
                    .map_err(|_| fail(info))?;
                if !new.is_finite() || new >= residual {
                    info.residual = new;
                    return Err(fail(info));
                }
                residual = new;
            } else {
                x.fill([0.0; M]);
            }
        }
        info.residual = residual;
        // Whether the factors were built at the current `x` (and `residual` evaluated there).
        let mut fresh = true;
        while residual > TARGET_RESIDUAL && info.iterations < MAX_ITERATIONS {
            let updated = self.back(&mut z, &mut x);
            info.iterations += 1;
            // Refactorise after the first step of a loop (from x = 0).
            let refactor = info.iterations == 1;
            let mut new = if refactor {
                info.factorizations += 1;
                self.sweep(&mut x, &mut z, None).map_err(|_| fail(info))?
            } else {
                updated
            };
            info.residual = new;
            if !new.is_finite() {
                return Err(fail(info));
            }
            if new >= residual && fresh {
                // No progress with a fresh Jacobian: rounding level reached.
                residual = new;
                break;
            }
            fresh = refactor;
            if !refactor {
                // The updated residual is relative to the terms at the last evaluation.
                new = self.bound(new);
                info.residual = new;
            }
            if !refactor && new > TARGET_RESIDUAL {
                if new > 0.1 * residual {
                    // Slow convergence: refactorise at this x (the sweep again, with the factors).
                    info.factorizations += 1;
                    new = self.sweep(&mut x, &mut z, None).map_err(|_| fail(info))?;
                    fresh = true;
                } else if info.iterations < MAX_ITERATIONS {
                    // The next chord step (not needed once the residual meets the target).
                    self.eliminate(&mut z);
                }
            }
            residual = new;
        }
        info.residual = residual;
        let flat: Vec<f64> = x
            .iter()
            .flat_map(|v| v[..self.g.m].iter().copied())
            .collect();
        if residual.is_nan() || residual > MAX_RESIDUAL || flat.iter().any(|v| !v.is_finite()) {
            return Err(fail(info));
        }
        Ok((flat, info))
    }
}

/// `T(u)` added to `y` (both m-vectors in segment coordinates); returns `|T(u)|`.
fn add_t(sc: &SegConst, e: &[f64], u: &[f64], y: &mut [f64]) -> f64 {
    let up = dot(u, e);
    let uu = dot(u, u);
    let perp2 = (uu - up * up).max(0.0);
    let c1 = perp2 * sc.kappa;
    let c2 = 2.0 * sc.dsinc * up;
    let mut t2 = 0.0;
    for ((ya, ua), ea) in y.iter_mut().zip(u).zip(e) {
        let ta = c1 * ea + c2 * (ua - up * ea);
        t2 += ta * ta;
        *ya += ta;
    }
    t2.sqrt()
}

#[inline]
fn norm(x: &[f64]) -> f64 {
    dot(x, x).sqrt()
}

/// `out = scale·(σ·I + (1 − σ)·ê êᵀ)`.
fn s_matrix(e: &[f64], sigma: f64, scale: f64, out: &mut [f64]) {
    let m = e.len();
    for i in 0..m {
        for j in 0..m {
            let id = if i == j { sigma } else { 0.0 };
            out[i * m + j] = scale * (id + (1.0 - sigma) * e[i] * e[j]);
        }
    }
}

/// `out = a·b` for `m × m` row-major blocks.
#[inline]
fn mat_mul<D: Dim>(d: D, a: &[f64], b: &[f64], out: &mut [f64]) {
    let m = d.get();
    for i in 0..m {
        for j in 0..m {
            let mut s = 0.0;
            for l in 0..m {
                s += a[i * m + l] * b[l * m + j];
            }
            out[i * m + j] = s;
        }
    }
}

/// `out = a·x`.
#[inline]
fn mat_vec<D: Dim>(d: D, a: &[f64], x: &[f64], out: &mut [f64]) {
    let m = d.get();
    for i in 0..m {
        let mut s = 0.0;
        for l in 0..m {
            s += a[i * m + l] * x[l];
        }
        out[i] = s;
    }
}

/// `out = a⁻¹` by Gauss–Jordan elimination with partial pivoting; `false` if singular.
fn invert<D: Dim>(d: D, a: &[f64], out: &mut [f64]) -> bool {
    let m = d.get();
    let mut w = a[..m * m].to_vec();
    out[..m * m].fill(0.0);
    for i in 0..m {
        out[i * m + i] = 1.0;
    }
    for col in 0..m {
        let piv = (col..m).fold(col, |p, r| {
            if w[r * m + col].abs() > w[p * m + col].abs() {
                r
            } else {
                p
            }
        });
        let pv = w[piv * m + col];
        if pv == 0.0 || !pv.is_finite() {
            return false;
        }
        if piv != col {
            for j in 0..m {
                w.swap(piv * m + j, col * m + j);
                out.swap(piv * m + j, col * m + j);
            }
        }
        let inv = 1.0 / pv;
        for j in 0..m {
            w[col * m + j] *= inv;
            out[col * m + j] *= inv;
        }
        for r in 0..m {
            if r != col {
                let f = w[r * m + col];
                if f != 0.0 {
                    for j in 0..m {
                        w[r * m + j] -= f * w[col * m + j];
                        out[r * m + j] -= f * out[col * m + j];
                    }
                }
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recast::keys;

    /// The wasm build constructs on S^m and converts back; every field (and every error) must
    /// be what the construction on the point type itself gives, bit for bit (`{:?}` prints
    /// each `f64` in the shortest form that reads back to the same bits).
    #[test]
    fn the_construction_gives_the_same_bits_on_sn() {
        fn check<P: Manifold>(points: &[P]) -> usize {
            let mut built = 0;
            let n = points.len();
            // A tangent velocity at each end key, and one that is not tangent.
            let tangent = |p: &P, s: f64| {
                let v = p.to_vector();
                let raw = v.with_coords(
                    &(0..v.dim())
                        .map(|i| s * (1.0 + i as f64))
                        .collect::<Vec<_>>(),
                );
                p.project_tangent(&raw)
            };
            let ends = [
                CubicEnd::Natural,
                CubicEnd::Scipy,
                CubicEnd::Clamped {
                    start: tangent(&points[0], 0.3),
                    end: tangent(&points[n - 1], -0.7),
                },
                CubicEnd::Clamped {
                    start: points[0].to_vector(),
                    end: tangent(&points[n - 1], 0.2),
                },
            ];
            for closed in [false, true] {
                let count = n + usize::from(closed);
                let uneven: Vec<f64> = (0..count)
                    .map(|i| (i * i) as f64 * 0.7 + i as f64)
                    .collect();
                for knots in [None, Some(uneven)] {
                    for end in &ends {
                        let native = CubicSpline::construct(
                            points.to_vec(),
                            knots.clone(),
                            end.clone(),
                            closed,
                        );
                        let on_sn = CubicSpline::construct_on_sn(
                            points.to_vec(),
                            knots.clone(),
                            end.clone(),
                            closed,
                        );
                        built += keys::same_bits(&native, &on_sn, &points);
                    }
                }
            }
            built
        }
        let built = keys::built(check, check);
        assert!(built > 40, "{built} curves built");
    }

    #[test]
    fn series_match_closed_forms_at_the_switch() {
        let dsinc: fn(f64) -> f64 = |x| sinc_deriv(x, math::sin_cos(x));
        for f in [dsinc, kappa] {
            // One ulp apart across the switch: the series below, the closed form at 0.1.
            let below = f(0.1 - 1.5e-17);
            let above = f(0.1);
            assert!((below - above).abs() < 1e-15, "{below} vs {above}");
        }
        assert!(
            (kappa(1.0) - (1.0 - 1f64.sin() * 1f64.cos())).abs() < 1e-16,
            "kappa(1)"
        );
    }

    /// A random system of continuity equations: `n` keys, tangent dimension `m`, segment
    /// angles up to 2 rad and widths from 0.05 to 5 (spacings 100 apart), random directions,
    /// a random holonomy when closed, random fixed end velocities when `fixed`.
    fn random_geometry(seed: u64, n: usize, m: usize, closed: bool, fixed: bool) -> Geometry {
        let mut state = seed;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let unit = |next: &mut dyn FnMut() -> f64| {
            let v: Vec<f64> = (0..m).map(|_| next() - 0.5).collect();
            let l = norm(&v);
            v.into_iter().map(|a| a / l).collect::<Vec<_>>()
        };
        let nseg = n - usize::from(!closed);
        let mut seg = Vec::new();
        let mut ehat = Vec::new();
        for _ in 0..nseg {
            let theta = 0.01 + 1.99 * next();
            let h = 0.05 + 4.95 * next();
            seg.push(SegConst::new(theta, h, theta.sin_cos()));
            ehat.extend(unit(&mut next));
        }
        // An orthogonal holonomy: Gram–Schmidt of random columns.
        let mut hol = Vec::new();
        if closed {
            let mut cols: Vec<Vec<f64>> = Vec::new();
            while cols.len() < m {
                let mut v = unit(&mut next);
                for c in &cols {
                    let d = dot(c, &v);
                    v.iter_mut().zip(c).for_each(|(a, b)| *a -= d * b);
                }
                let l = norm(&v);
                cols.push(v.into_iter().map(|a| a / l).collect());
            }
            hol = (0..m * m).map(|i| cols[i % m][i / m]).collect();
        }
        let fixed = fixed.then(|| {
            let g0: Vec<f64> = unit(&mut next).into_iter().map(|a| 0.7 * a).collect();
            let g1: Vec<f64> = unit(&mut next).into_iter().map(|a| 1.3 * a).collect();
            (g0, g1)
        });
        Geometry {
            n,
            m,
            closed,
            seg,
            ehat,
            hol,
            fixed,
        }
    }

    /// The chord steps' residuals come from the exact quadratic update, not from evaluating
    /// the equations: the reported residual must bound the one the equations give at the
    /// solution (evaluated by a fresh sweep) and be close to it, and the solution must be the
    /// slice solver's (which evaluates every step).
    #[test]
    fn chord_residual_updates_equal_the_evaluated_residual() {
        let (mut checked, mut compared) = (0, 0);
        for case in 0..40_usize {
            let m = 1 + case % 3;
            let closed = case % 4 == 3;
            let fixed = !closed && case % 2 == 1;
            let n = 3 + (case * 7) % 40;
            let seed = case as u64;
            let geo = random_geometry(seed, n, m, closed, fixed);
            let Ok((x, info)) = FixedSolver::<3>::new(&geo).solve() else {
                continue;
            };
            let xv: Vec<Vf<3>> = x
                .chunks_exact(m)
                .map(|c| vf(|a| if a < m { c[a] } else { 0.0 }))
                .collect();
            let mut z = vec![[0.0; 3]; n];
            let evaluated = FixedSolver::<3>::new(&geo)
                .sweep(&mut xv.clone(), &mut z, None)
                .unwrap_or(f64::INFINITY);
            assert!(
                info.residual <= TARGET_RESIDUAL && evaluated <= TARGET_RESIDUAL,
                "seed {seed}: reported {:e}, evaluated {evaluated:e}",
                info.residual
            );
            // The reported residual of a chord step bounds the evaluated one (up to the rounding
            // of the solve, which the update leaves out); it is about as large (within 3× on
            // these systems, 0.1–12 % on most).
            assert!(
                evaluated <= 1.25 * info.residual + 1e-15
                    && info.residual <= 4.0 * evaluated + 1e-15,
                "seed {seed}: reported {:e}, evaluated {evaluated:e}",
                info.residual
            );
            checked += 1;
            // (The slice solver, without the correction step, fails on a few systems that
            // this one solves.)
            let Ok((y, _)) = geo.solve(Dynamic(m)) else {
                continue;
            };
            let scale = y.iter().fold(1.0_f64, |s, v| s.max(v.abs()));
            for (a, b) in x.iter().zip(&y) {
                assert!((a - b).abs() <= 1e-11 * scale, "seed {seed}: {a} vs {b}");
            }
            compared += 1;
        }
        assert!(checked >= 30, "only {checked} of 40 systems converged");
        assert!(compared >= 25, "only {compared} of 40 systems compared");
    }

    /// The correction after the linear step ([`FixedSolver::correct`]) brings the first
    /// iterate closer: the residual where Newton's first factorisation is evaluated falls.
    #[test]
    fn the_correction_brings_the_first_iterate_closer() {
        let mut ratios = Vec::new();
        for case in 0..40_usize {
            let (m, fixed, n) = (1 + case % 3, case % 2 == 1, 3 + (case * 7) % 40);
            let geo = random_geometry(100 + case as u64, n, m, false, fixed);
            let residual_at = |correct: bool| {
                let mut solver = FixedSolver::<3>::new(&geo);
                let (mut x, mut z) = (vec![[0.0; 3]; n], vec![[0.0; 3]; n]);
                let (mut piv, mut ul) = (vec![0.0; n], vec![0.0; n]);
                solver.linear_step(&mut x, &mut piv, &mut z, &mut ul);
                let ul = correct.then_some(&ul[..]);
                solver.sweep(&mut x, &mut z, ul).unwrap_or(f64::INFINITY)
            };
            let (plain, corrected) = (residual_at(false), residual_at(true));
            if plain > 1e-12 {
                ratios.push(corrected / plain);
            }
        }
        // On these systems (angles to 2 rad, widths 0.05–5: far from the linear solution) it
        // halves the residual typically, by 5× at best, 13 % worse at worst; on the benchmarks'
        // keys by 30× (the module documentation).
        ratios.sort_by(f64::total_cmp);
        assert!(ratios.len() >= 20, "{ratios:?}");
        assert!(ratios[ratios.len() / 2] < 0.6, "{ratios:?}");
        assert!(
            ratios[0] < 0.25 && ratios[ratios.len() - 1] < 1.2,
            "{ratios:?}"
        );
    }

    #[test]
    fn invert_roundtrip() {
        let a = [4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.1, 0.3, 2.0];
        let mut inv = [0.0; 9];
        assert!(invert(Dynamic(3), &a, &mut inv), "invertible");
        let mut id = [0.0; 9];
        mat_mul(Dynamic(3), &a, &inv, &mut id);
        // The fixed-size elimination is the same one.
        let rows = [[a[0], a[1], a[2]], [a[3], a[4], a[5]], [a[6], a[7], a[8]]];
        let inv_f = invert_gj(&rows).expect("invertible");
        assert_eq!(inv_f.concat(), inv.to_vec(), "invert_gj = invert");
        let adj = invertf(&rows).expect("invertible");
        for (x, y) in adj.concat().iter().zip(&inv) {
            assert!((x - y).abs() < 1e-15, "adjugate {x} vs {y}");
        }
        assert!(
            invertf(&[[1.0, 2.0], [2.0, 4.0]]).is_none(),
            "singular 2 × 2"
        );
        assert!(invertf(&[[0.0]]).is_none(), "singular 1 × 1");
        for i in 0..3 {
            for j in 0..3 {
                let e = if i == j { 1.0 } else { 0.0 };
                assert!((id[i * 3 + j] - e).abs() < 1e-15, "A·A⁻¹ = I");
            }
        }
    }
}
