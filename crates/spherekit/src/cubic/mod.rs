// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The C² cubic spline through keys at given times, cubic in the tangent space of each key
//! (scipy's `RotationSpline` on S³, the same construction on every sphere).
//!
//! Keys `pᵢ` at times `tᵢ`, `hᵢ = tᵢ₊₁ − tᵢ`, `rᵢ = Log_{pᵢ}(pᵢ₊₁)`, `s = t − tᵢ`:
//!
//! ```text
//! c(t) = Exp_{pᵢ}(vᵢ(s)),  vᵢ cubic,  vᵢ(0) = 0,  vᵢ(hᵢ) = rᵢ,  vᵢ′(0) = Vᵢ,  vᵢ′(hᵢ) = (dExp_{rᵢ})⁻¹Vᵢ₊₁
//! ```
//!
//! The key velocities `Vᵢ` make the acceleration continuous at every interior key (and at the
//! seam of a closed curve): a block tridiagonal system (block cyclic when closed) with a
//! nonlinear term, solved by Newton's method in parallel-transported tangent frames.
//!
//! Source: N. Mayorov, *Smooth attitude interpolation* (2019), the reference of scipy's
//! `RotationSpline` (`docs/references.md`, entries 16–18). The derivation (the differential of
//! `Exp`, the continuity equations, the ends, the solver and its stopping rule) is in
//! `docs/derivations.md#cubic-spline`.
//!
//! The parts: [`frames`] (the tangent frames, and the solution back to ambient vectors),
//! [`equations`] (the segments' constants, the nonlinear term, the shared block algebra),
//! [`fixed`] (the solver of tangent dimensions 1 to 3) and [`dynamic`] (the solver of higher
//! dimensions on slices, and the test oracle of the first).

use glam::{DVec3, DVec4};

use crate::ambient::{Ambient, span_basis};
#[cfg(doc)]
use crate::curve::Curve;
use crate::curve::{Jet, Side};
use crate::error::{PointError, SplineError};
use crate::knots::Knots;
use crate::manifold::{Manifold, geodesic_frame_sin_cos, renormalize};
use crate::math;
use crate::s3::UnitQuat;
#[cfg(any(test, feature = "compact"))]
use crate::{
    ambient::VecN,
    recast::{Recast, to_sm},
    sm::SmPoint,
};

use crate::banded::dot;
use crate::math::sinc_deriv;
use equations::{Geometry, SegConst};
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
        start_velocity: V,
        /// The velocity at the last key, tangent there.
        end_velocity: V,
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
            start_velocity: crate::s3::velocity_from_angular_body(first, start),
            end_velocity: crate::s3::velocity_from_angular_body(last, end),
        }
    }

    /// Clamped ends on S³ from space-frame angular velocities `ω = 2·q′·q̄` (the convention of
    /// [`angular_velocity_acceleration`](crate::angular_velocity_acceleration)).
    #[must_use]
    pub fn clamped_angular(first: UnitQuat, start: DVec3, last: UnitQuat, end: DVec3) -> Self {
        Self::Clamped {
            start_velocity: crate::s3::velocity_from_angular(first, start),
            end_velocity: crate::s3::velocity_from_angular(last, end),
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
            (
                CubicEnd::Clamped {
                    start_velocity,
                    end_velocity,
                },
                Some(given),
                Some(&now),
            ) if given != now => CubicEnd::Clamped {
                start_velocity,
                end_velocity: -end_velocity,
            },
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
pub(crate) struct Segment<V> {
    pub(crate) start: V,
    pub(crate) a: V,
    pub(crate) b: V,
    pub(crate) c: V,
    pub(crate) inv_h: f64,
}

/// The C² cubic spline through keys at given times on any sphere, with natural, clamped or
/// scipy end conditions, or closed (periodic).
///
/// On each segment the curve is the exponential of a cubic in the tangent space of its first
/// key; the key velocities are solved so that velocity and acceleration are continuous at every
/// interior key (and at the seam of a closed curve). On S³ with [`CubicEnd::Scipy`] this is
/// scipy's `RotationSpline` (keys canonicalised by [`unflip`](crate::unflip), since scipy
/// interpolates the shortest rotations). In short (the derivation:
/// `docs/derivations.md#cubic-spline`):
///
/// ```text
/// c(t) = Exp_{pᵢ}(vᵢ(t − tᵢ)),  vᵢ cubic,  vᵢ(0) = 0,  vᵢ(hᵢ) = Log_{pᵢ}(pᵢ₊₁)
/// (2/h_{k−1})·M_{k−1}V_{k−1} + 4(1/h_{k−1} + 1/h_k)·V_k + (2/h_k)·N_k V_{k+1}
///     + T_{k−1}(N_{k−1}V_k) = 6 r̃_{k−1}/h_{k−1}² + 6 r_k/h_k²
/// ```
///
/// with `M = dExp` at the segment's end, `N = M⁻¹` and `T` the tangential second-order term of
/// `Exp` (closed forms in the derivation). Newton's method on the block tridiagonal
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
    ///   different dimensions ([`SmPoint`](crate::SmPoint));
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
        // On `P` itself; with the `compact` feature once on S^m for every point type
        // ([`crate::recast`]; the same bits, `tests::the_construction_gives_the_same_bits_on_sm`).
        #[cfg(not(feature = "compact"))]
        return Self::construct(points, knots, end, closed, None);
        #[cfg(feature = "compact")]
        return Self::construct_on_sm(points, knots, end, closed, None);
    }

    /// The cubic Hermite spline on the sphere: through `points` at the times `knots` (as
    /// [`try_new`](Self::try_new)) with the given velocity at every key, an ambient tangent
    /// vector per unit of time (closed: the first key's velocity also at the end of the loop).
    ///
    /// Each segment is the one of [`try_new`](Self::try_new), `c(t) = Exp_{pᵢ}(vᵢ(t − tᵢ))` with
    /// `vᵢ` the cubic in the tangent space at `pᵢ` with `vᵢ(0) = 0`, `vᵢ′(0) = Vᵢ`,
    /// `vᵢ(hᵢ) = Log_{pᵢ}(pᵢ₊₁)` and `vᵢ′(hᵢ) = (dExp)⁻¹Vᵢ₊₁`, so the curve passes through every
    /// key at its time with the given velocity: C¹, with no system to solve
    /// ([`solve_info`](Self::solve_info) reports 0 iterations). The C² spline of
    /// [`try_new`](Self::try_new) is the one whose velocities make the acceleration continuous
    /// too. On S³, angular velocities (a gyroscope's rates) become key velocities with
    /// [`velocity_from_angular_body`](crate::velocity_from_angular_body) or
    /// [`velocity_from_angular`](crate::velocity_from_angular).
    ///
    /// An open curve's [`end`](Self::end) is [`CubicEnd::Clamped`] with the first and last
    /// velocities (which it is); a closed one's is [`CubicEnd::Natural`].
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new) for the keys and knots, and
    /// - [`SplineError::InvalidParameter`] (`velocities`) unless there is one velocity per key;
    /// - [`SplineError::InvalidKeyVelocity`] for a velocity that is not finite, has the wrong
    ///   dimension or is not tangent at its key (`|p·v| > 1e-9·|v|`; one within that tolerance is
    ///   projected onto the tangent space).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::glam::DVec3;
    /// use spherekit::{Curve, CubicSpline, UnitQuat, angular_velocity_acceleration_body,
    ///     velocity_from_angular_body};
    ///
    /// // Three attitudes with the body rates a gyroscope measured there.
    /// let keys = vec![
    ///     UnitQuat::IDENTITY,
    ///     UnitQuat::from_rotation_vector(DVec3::new(0.0, 0.0, 0.8)).unwrap(),
    ///     UnitQuat::from_rotation_vector(DVec3::new(0.3, 0.0, 1.5)).unwrap(),
    /// ];
    /// let rates = [DVec3::new(0.0, 0.0, 0.9), DVec3::new(0.2, 0.0, 0.7), DVec3::new(0.4, 0.1, 0.6)];
    /// let velocities = keys.iter().zip(rates).map(|(q, w)| velocity_from_angular_body(*q, w)).collect();
    /// let c = CubicSpline::try_hermite(keys, velocities, Some(vec![0.0, 1.0, 2.0]), false).unwrap();
    /// let j = c.jet(1.0);
    /// let (omega, _) = angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration);
    /// assert!((omega - rates[1]).length() < 1e-12);
    /// ```
    pub fn try_hermite(
        points: Vec<P>,
        velocities: Vec<P::Vector>,
        knots: Option<Vec<f64>>,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let end = match (closed, velocities.first(), velocities.last()) {
            (false, Some(start), Some(end)) => CubicEnd::Clamped {
                start_velocity: start.clone(),
                end_velocity: end.clone(),
            },
            _ => CubicEnd::Natural,
        };
        #[cfg(not(feature = "compact"))]
        return Self::construct(points, knots, end, closed, Some(velocities));
        #[cfg(feature = "compact")]
        return Self::construct_on_sm(points, knots, end, closed, Some(velocities));
    }

    /// [`construct`](Self::construct) on the keys as points of S^m, the built curve converted
    /// back (the keys and the end condition are kept as given: the conversion copies
    /// coordinates).
    #[cfg(any(test, feature = "compact"))]
    fn construct_on_sm(
        points: Vec<P>,
        knots: Option<Vec<f64>>,
        end: CubicEnd<P::Vector>,
        closed: bool,
        given: Option<Vec<P::Vector>>,
    ) -> Result<Self, SplineError> {
        let sm = points.iter().map(to_sm).collect();
        let vector = |v: &P::Vector| VecN::new(v.to_vec());
        let given = given.map(|g| g.iter().map(vector).collect());
        let end_sm = match &end {
            CubicEnd::Natural => CubicEnd::Natural,
            CubicEnd::Scipy => CubicEnd::Scipy,
            CubicEnd::Clamped {
                start_velocity,
                end_velocity,
            } => CubicEnd::Clamped {
                start_velocity: vector(start_velocity),
                end_velocity: vector(end_velocity),
            },
        };
        let c = CubicSpline::<SmPoint>::construct(sm, knots, end_sm, closed, given)?;
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

    /// The construction of [`try_new`](Self::try_new) on `P`, or with the velocity at every key
    /// `given`, of [`try_hermite`](Self::try_hermite) (no solve).
    fn construct(
        points: Vec<P>,
        knots: Option<Vec<f64>>,
        end: CubicEnd<P::Vector>,
        closed: bool,
        given: Option<Vec<P::Vector>>,
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
        let given = match given {
            Some(velocities) if velocities.len() != n => {
                return Err(SplineError::InvalidParameter {
                    name: "velocities",
                    reason: format!(
                        "must have one velocity per key: {n} keys, got {}",
                        velocities.len()
                    ),
                });
            }
            Some(velocities) => Some(
                velocities
                    .iter()
                    .zip(&points)
                    .enumerate()
                    .map(|(index, (v, key))| {
                        tangent_at(key, v)
                            .map_err(|reason| SplineError::InvalidKeyVelocity { index, reason })
                    })
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            None => None,
        };
        let clamps = match &end {
            CubicEnd::Clamped {
                start_velocity,
                end_velocity,
            } => Some((
                check_velocity(&points[0], start_velocity, true)?,
                check_velocity(&points[n - 1], end_velocity, false)?,
            )),
            _ => None,
        };

        // Span coordinates of the keys, the directions and the clamped velocities: the ambient
        // coordinates when the keys span the whole space (as keys on S³ in general position do).
        let vectors: Vec<P::Vector> = points.iter().map(Manifold::to_vector).collect();
        let clamp_vectors = clamps.iter().flat_map(|(s, e)| [s, e]);
        let given_vectors = given.iter().flatten();
        let basis = span_basis(
            dim,
            vectors.iter().chain(clamp_vectors).chain(given_vectors),
        );
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
        let (x, info) = if let Some(velocities) = &given {
            // Hermite: the unknowns of the solve, the key velocities in frame coordinates, are
            // given.
            let mut x = Vec::with_capacity(n * m);
            let mut vc = Vec::with_capacity(r);
            for (k, v) in velocities.iter().enumerate() {
                vc.clear();
                coords(v, &mut vc);
                x.extend((0..m).map(|a| dot(frames.vector(k, a), &vc)));
            }
            (
                x,
                CubicSolveInfo {
                    iterations: 0,
                    factorizations: 0,
                    residual: 0.0,
                },
            )
        } else if m == 0 {
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
                1..=3 => FixedSolver::new(&geo).solve(),
                _ => geo.solve(),
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

    /// The segments' cubics (the fit's energy and residuals).
    pub(crate) fn segments(&self) -> &[Segment<P::Vector>] {
        &self.segments
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
        let v = g.tangent(s);
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
        let v = g.tangent(s);
        let rho = v.length();
        let (sn, cs) = math::sin_cos(rho);
        let sinc = if rho < 1e-4 {
            math::sinc(rho)
        } else {
            sn / rho
        };
        P::from_vector_unchecked(renormalize(g.start.clone() * cs + v * sinc))
    }

    /// The point and velocity of segment `i` at `s` (the keys themselves at `s = 0` and `1`).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn local(&self, i: usize, s: f64) -> (P, Local<P::Vector>) {
        let l = self.segments[i].local(s);
        let point = if s == 0.0 {
            self.points[i].clone()
        } else if s == 1.0 {
            self.end_key(i).clone()
        } else {
            P::from_vector_unchecked(renormalize(l.q.clone()))
        };
        (point, l)
    }

    fn jet_local(&self, i: usize, s: f64) -> Jet<P> {
        let (point, local) = self.local(i, s);
        let (velocity, acceleration) = self.segments[i].velocity_acceleration(s, local);
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
        let (point, l) = self.local(i, s);
        (point, l.velocity)
    }

    /// [`point_velocity`](Self::point_velocity) at many parameters (increasing parameters
    /// are located by stepping, as in [`Curve::jet_many`]).
    ///
    /// # Panics
    ///
    /// If `out` and `ts` have different lengths.
    pub fn point_velocity_many(&self, ts: &[f64], out: &mut [(P, P::Vector)]) {
        self.knots.map_into(ts, Side::Right, out, |i, s| {
            let (point, l) = self.local(i, s);
            (point, l.velocity)
        });
    }
}

impl<V: Ambient> Segment<V> {
    /// The segment of the cubic Hermite formula from `p₀` to `p₁` over a width `h`, with the
    /// velocities `V₀` at `p₀` and `V₁` at `p₁` (ambient, tangent at their keys):
    /// `v(s) = a·s + b·s² + c·s³` in the local `s ∈ [0, 1]` with `v(0) = 0`, `v′(0) = h·V₀`,
    /// `v(1) = r = Log_{p₀}(p₁)` and `v′(1) = h·U`, `U = (dExp_r)⁻¹V₁`:
    ///
    /// ```text
    /// a = h·V₀,   b = 3r − 2h·V₀ − h·U,   c = h·V₀ + h·U − 2r,
    /// U = ê·(V₁·ê₁) + (V₁ − ê₁·(V₁·ê₁)) / sinc θ,   ê₁ = ê·cos θ − p₀·sin θ,
    /// ```
    ///
    /// with `θ = |r|`, `ê = r/θ`: the differential of `Exp_{p₀}` at `r` carries `ê` to the
    /// geodesic's direction `ê₁` at `p₁` and scales the directions normal to both by `sinc θ`
    /// (`docs/derivations.md#cubic-spline`). `None` for antipodal keys.
    pub(crate) fn hermite(p0: &V, p1: &V, v0: &V, v1: &V, h: f64) -> Option<Self> {
        let (theta, e, (sn, cs)) = geodesic_frame_sin_cos(p0, p1)?;
        let e1 = e.clone() * cs - p0.clone() * sn;
        let along = v1.dot(&e1);
        let sinc = if theta < 1e-4 {
            math::sinc(theta)
        } else {
            sn / theta
        };
        let u = e.clone() * along + (v1.clone() - e1 * along) * (1.0 / sinc);
        let r = e * theta;
        let (hv, hu) = (v0.clone() * h, u * h);
        Some(Self {
            start: p0.clone(),
            b: r.clone() * 3.0 - hv.clone() * 2.0 - hu.clone(),
            c: hv.clone() + hu - r * 2.0,
            a: hv,
            inv_h: 1.0 / h,
        })
    }

    /// The tangent vector `v(s)`, and its derivatives with respect to `s`.
    pub(crate) fn tangent(&self, s: f64) -> V {
        ((self.c.clone() * s + self.b.clone()) * s + self.a.clone()) * s
    }

    /// `∫|v″(t)|² dt` over the segment (`t = t₀ + s·h`): `(4|b|² + 12 b·c + 12|c|²)/h³`.
    pub(crate) fn energy(&self) -> f64 {
        let (b, c) = (&self.b, &self.c);
        (4.0 * b.dot(b) + 12.0 * b.dot(c) + 12.0 * c.dot(c)) * self.inv_h.powi(3)
    }

    /// The first-order part of the jet at `s`, with what the acceleration reuses.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    pub(crate) fn local(&self, s: f64) -> Local<V> {
        let v = self.tangent(s);
        let w =
            ((self.c.clone() * (3.0 * s) + self.b.clone() * 2.0) * s + self.a.clone()) * self.inv_h;
        let p = &self.start;
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
        Local {
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

    /// The velocity and the acceleration at `s` from the first-order part there.
    pub(crate) fn velocity_acceleration(&self, s: f64, local: Local<V>) -> (V, V) {
        let acc = (self.c.clone() * (6.0 * s) + self.b.clone() * 2.0) * (self.inv_h * self.inv_h);
        let Local {
            velocity,
            q,
            e,
            e_end,
            w_par,
            w_perp,
            rho,
            sinc,
            sin_cos,
        } = local;
        let dsinc = sinc_deriv(rho, sin_cos);
        let a_par = acc.dot(&e);
        let a_perp = acc - e.clone() * a_par;
        let perp2 = w_perp.dot(&w_perp);
        let acceleration = e_end * a_par
            + a_perp * sinc
            + q * (-w_par * w_par)
            + self.start.clone() * (-perp2 * sinc)
            + e * (perp2 * dsinc)
            + w_perp * (2.0 * dsinc * w_par);
        (velocity, acceleration)
    }
}

/// The first-order part of a segment's jet, and the terms its acceleration reuses.
pub(crate) struct Local<V> {
    pub(crate) velocity: V,
    /// `Exp` before renormalisation.
    pub(crate) q: V,
    /// The unit direction of the tangent vector `v`, and its parallel transport to `q`.
    e: V,
    e_end: V,
    /// The parts of `v′` along and across `e`.
    w_par: f64,
    w_perp: V,
    /// `|v|`, `sin|v|/|v|` and `(sin|v|, cos|v|)`.
    rho: f64,
    sinc: f64,
    sin_cos: (f64, f64),
}

/// Checks a velocity at `key` and returns its tangent projection, or what is wrong with it.
///
/// The test `|p·v| ≤ TANGENT_TOLERANCE·|v|` is homogeneous in `v`, so it is made on `v` divided
/// by its largest coordinate: a tiny velocity (`|v|²` below the smallest normal double, where
/// `|v|` would round to 0 and the rounding of `p·v` would fail it) is judged as its direction.
fn tangent_at<P: Manifold>(key: &P, v: &P::Vector) -> Result<P::Vector, &'static str> {
    let p = key.to_vector();
    if v.dim() != p.dim() {
        return Err("has the wrong number of coordinates");
    }
    if !v.is_finite() {
        return Err("has a non-finite coordinate");
    }
    let largest = v.as_slice().iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if largest > 0.0 {
        let coords: Vec<f64> = v.as_slice().iter().map(|x| x / largest).collect();
        let u = v.with_coords(&coords);
        if p.dot(&u).abs() > TANGENT_TOLERANCE * u.length() {
            return Err("is not tangent to its key");
        }
    }
    Ok(key.project_tangent(v))
}

/// Checks a clamped velocity at `key` and returns its tangent projection.
fn check_velocity<P: Manifold>(
    key: &P,
    v: &P::Vector,
    start: bool,
) -> Result<P::Vector, SplineError> {
    tangent_at(key, v).map_err(|reason| {
        let reason = match (reason, start) {
            ("is not tangent to its key", true) => "is not tangent to the first key",
            ("is not tangent to its key", false) => "is not tangent to the last key",
            (reason, _) => reason,
        };
        SplineError::InvalidEndVelocity { start, reason }
    })
}
