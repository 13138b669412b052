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
//!   ahead of the next sweep. It takes `V` about 30× closer to the solution, so Newton's first
//!   factorisation starts nearer and the chord steps converge faster;
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
//! the row's terms, is at most 1e-12, and reports [`SolveError::NoConvergence`](crate::SolveError::NoConvergence) if it is not
//! after the iteration limit. An updated residual is relative to the terms at the last
//! evaluation `V̄`; it is turned into a bound at `V`: each row's terms move by at most `Lₖ·ω`
//! when no unknown has moved by more than `ω ≤ 1` since (`Lₖ` from the row's coefficients:
//! `4/h` terms, `2/h`, `2/(h·sinc θ)`, and `|B(a, b)| ≤ (|κ| + |sinc′|)|a||b|` for the change of
//! `T`), and `ω` is at most the largest `|Wₖ|`, so the relative residual at `V` is at most the
//! updated one over `1 − ω·maxₖ Lₖ/|termsₖ(V̄)|` (a fresh evaluation when that is not
//! positive). For the benchmarks' 1 000 random rotations of 0.4–1.2 rad at unit spacing it
//! takes the linear step and its correction, one Newton step and one chord step (residuals
//! 1.4 at `V = 0`, then 1.3e-8 and 5.4e-13, the last bound 0.4 % above the updated residual);
//! without the correction it took three chord steps (1.7e-2 at the first factorisation, then
//! 1.3e-5, 1.5e-8, 1.8e-11, 2.6e-14).
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
use crate::error::{PointError, SplineError};
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

use equations::{Dynamic, Geometry, SegConst, dot, sinc_deriv};
use fixed::FixedSolver;
use frames::Frames;

/// Newton stops once the relative residual is at most this (an updated residual of a chord
/// step, [`FixedSolver::update`](fixed::FixedSolver::update): its bound,
/// [`FixedSolver::bound`](fixed::FixedSolver::bound)).
const TARGET_RESIDUAL: f64 = 1e-12;
/// The construction fails when the relative residual stays above this.
const MAX_RESIDUAL: f64 = 1e-12;
/// Newton and chord steps at most.
const MAX_ITERATIONS: usize = 60;
/// A clamped velocity `v` at key `p` is tangent when `|p·v| ≤ TANGENT_TOLERANCE·|v|`.
pub const TANGENT_TOLERANCE: f64 = 1e-9;

mod dynamic;
mod equations;
mod fixed;
mod frames;
#[cfg(test)]
mod tests;

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
/// an interior joint, so [`continuity`](crate::continuity()) does not list it. Parameters outside
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
