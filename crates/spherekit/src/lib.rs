// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Spline curves on spheres: directions on S², orientations as unit quaternions (S³), and
//! points of S^m of any dimension.
//!
//! # Example
//!
//! ```
//! use spherekit::{Curve, GeodesicSpline, Manifold, UnitQuat, unflip};
//! use spherekit::glam::DVec3;
//!
//! // Three orientations; the last one is given with the "wrong" sign.
//! let q0 = UnitQuat::IDENTITY;
//! let q1 = UnitQuat::from_axis_angle(DVec3::Z, 1.0).unwrap();
//! let q2 = -UnitQuat::from_axis_angle(DVec3::X, 2.0).unwrap();
//! let mut keys = vec![q0, q1, q2];
//! unflip(&mut keys); // explicit double-cover canonicalisation
//! let curve = GeodesicSpline::try_new(keys, None).unwrap();
//!
//! // Halfway along the first piece: a rotation by 0.5 rad about z, turning at 1 rad per unit t.
//! let jet = curve.jet(0.5);
//! assert!(jet.point.dist(&UnitQuat::from_axis_angle(DVec3::Z, 0.5).unwrap()) < 1e-15);
//! let (omega, _alpha) = spherekit::angular_velocity_acceleration(jet.point, jet.velocity, jet.acceleration);
//! assert!((omega - DVec3::Z).length() < 1e-14);
//! ```
//!
//! # Curves
//!
//! | type | spheres | construction | continuity |
//! |---|---|---|---|
//! | [`GeodesicSpline`] | all | piecewise slerp through the points | C⁰ |
//! | [`NlerpSpline`] | all | piecewise normalised linear interpolation | C⁰ |
//! | [`Bezier`] | all | spherical Bézier of any degree by de Casteljau (Shoemake 1985) | C^∞ |
//! | [`BezierKim`] | S³ | Kim–Kim–Shin cumulative Bézier quaternion curve (1995) | C^∞ |
//! | [`BsplineKim`] | S³ | Kim–Kim–Shin cumulative cubic B-spline quaternion curve | C² |
//! | [`Squad`] | S³ | Shoemake's squad, non-uniform knots | C¹ |
//! | [`CatmullRom`] | all | Catmull-Rom by slerps (textbook rule on S³, intrinsic on S^m) | C¹ |
//! | [`CatmullRomNlerp`] | all | Euclidean Catmull-Rom in ℝ^(m+1), normalised (not constant speed, off the great circles) | C¹ |
//! | [`GammaSpline`] | S³ | Boehm's Gamma spline lifted to S³ with Kim's cubic segments | C¹ |
//! | [`CubicSpline`] | all | cubic in the tangent space of each key, key velocities solved for C² (scipy's `RotationSpline` on S³); natural, clamped, scipy ends or closed | C² |
//! | [`BetaSpline`] | all | spherical Beta spline (bias β₁, tension β₂) with a Newton interpolation solver | G¹ |
//! | [`ArcBlend`] | all | Pobegailo's interpolating spline blending circle arcs | Cⁿ |
//! | [`CornerBlend`], [`CornerBlendRotations`] | all, S³ | Pobegailo's corner smoothing of a great-circle polyline (S²: also of small-circle arcs), cuts per corner and side, start and speed ([`CornerCuts`], [`CornerTiming`]) | Cⁿ |
//!
//! The foundations these build on are public too: quaternion algebra ([`quaternion`]: the
//! ternary product, orthogonal complement and quotient, the 4×4 multiplication matrices), the
//! exponential of so(3) ([`exp_so3`], [`rotation_derivative`], [`skew`]), circles as planar
//! sections ([`PlaneSection`]) and the Bernstein polynomials ([`bernstein`]).
//!
//! Every type but the two Bézier curves also builds a **closed loop** (`try_new_closed`, and
//! [`ArcBlend::try_with_closed`]): the points wrap around, the curve returns to its first
//! point, [`Curve::is_closed`] is `true`, and the seam is a joint as smooth as the others, which
//! [`continuity`] reports last (`docs/derivations.md#closed-loops`).
//!
//! Each type's documentation gives the formula, its source (the publication, with section and
//! equation numbers) and the corrections the sources needed. The repository's
//! `docs/references.md` lists the publications and `docs/derivations.md` states the project's
//! own derivations and every correction of a source, each with the tests that pin it. The
//! [`continuity`] report measures the jumps of a curve's point, velocity and acceleration at
//! its joints from the exact one-sided jets.
//!
//! # Conventions
//!
//! - Angles are in radians. Distances on a sphere are great-circle angles in `[0, π]`; on S³
//!   that is the angle between the quaternions as unit 4-vectors, which is **half** the angle of
//!   the rotation between the two orientations.
//! - Points of every sphere are unit vectors of the ambient space ℝ^(m+1), and tangent vectors
//!   and derivatives of curves are ambient vectors ([`Ambient`]). For [`UnitQuat`] the ambient
//!   vector is a [`glam::DVec4`] in glam's `x, y, z, w` order; the scene format writes
//!   quaternions scalar first, `[w, x, y, z]`.
//! - A unit quaternion `q` rotates vectors by `v ↦ q·v·q̄`; `q₂·q₁` is "first `q₁`, then
//!   `q₂`". The quaternion of the rotation by φ about the unit axis `n` is
//!   `cos(φ/2) + sin(φ/2)·n`.
//! - **Angular velocity** of a quaternion curve `q(t)` is the space-frame (fixed-frame) vector
//!   `ω = 2·q′·q̄`, and the angular acceleration is `α = ω′ = 2·q″·q̄` (vector parts). The
//!   **factor 2** comes from the half-angle: a curve moving at speed `|q′|` on S³ turns the body
//!   at `2|q′|` radians per unit time. See [`angular_velocity_acceleration`]; the body-frame
//!   values `ω_b = 2·q̄·q′ = q̄·ω·q` and `α_b = q̄·α·q` (scipy's convention) are
//!   [`angular_velocity_acceleration_body`].
//! - **Double cover.** `q` and `−q` are the same rotation. Geodesic interpolation never flips
//!   signs; spline constructors use the keys as given. [`unflip`] makes consecutive keys have
//!   non-negative dot products, and the scene format calls it once before construction unless
//!   `"canonicalize": false`.
//! - **Domain.** Every curve has a parameter interval `[t0, t1]` ([`Curve::domain`]); outside it
//!   the parameter is clamped, and NaN is treated as `t0` (see [`Curve`]). Other policies
//!   (hold at rest, extend along the end geodesic, cycle, typed error, or continue the end
//!   segment's own formula as scipy's `RotationSpline` does) are [`Extrapolated`].
//! - **Arc length** is great-circle arc length on S² and S^m and the **rotation angle** on S³
//!   ([`Manifold::SPEED_SCALE`]: `|ω| = 2|q′|`); [`ArcLength`] reparametrises any curve by it.
//! - **Antipodal points** have no unique geodesic. Constructions reject them with
//!   [`SplineError::Antipodal`] (within [`ANTIPODAL_TOLERANCE`]); nothing returns NaN.
//!
//! # Numerics
//!
//! Angles come from `atan2` (never `acos` of a dot product); `sin x / x` and its relatives use
//! series branches near 0; geodesic interpolation is exact at `t = 0` and `t = 1`.
//!
//! # Feature flags
//!
//! - `std` (default): the standard library's float functions.
//! - `libm`: route every transcendental function through the `libm` crate, so that native and
//!   WebAssembly builds give bit-identical results. Enable it in binaries that render.
//! - `serde`: `Serialize` for points.
//! - `compact`: compile each construction whose arithmetic is the same on every sphere (arc
//!   blend, Beta spline, intrinsic Catmull–Rom, geodesic, cubic) once, on S^m, converting the
//!   keys and the built curve: smaller code (the browser build turns it on), the same bits,
//!   construction slower (the conversions, and `VecN` arithmetic, which allocates).
//!   Evaluation is unchanged.
//! - `mint`: conversions of [`S2Point`] and [`UnitQuat`] from and to [`mint`]'s `Vector3` and
//!   `Quaternion` (`f64`, and `f32` in), the way to and from another glam version (bevy's);
//!   glam's own `mint` conversions for the re-exported [`glam`]. The point types also convert
//!   from and to plain arrays without any feature (`S2Point::from_array`,
//!   `UnitQuat::from_xyzw`, `SmPoint::from_slice`, and `TryFrom`).
//!
//! An application on another glam version (bevy's, say) converts through mint, with glam's
//! `mint` feature on its side, without the two glams having to agree:
//!
//! ```
//! # #[cfg(feature = "mint")] {
//! use spherekit::{S2Point, UnitQuat};
//!
//! // f32 values as the application's glam gives them to mint (`Vec3::into`, `Quat::into`).
//! let up = mint::Vector3 { x: 0.0_f32, y: 2.0, z: 0.0 };
//! let turn = mint::Quaternion { v: mint::Vector3 { x: 0.0_f32, y: 0.0, z: 1.0 }, s: 1.0 };
//! let p = S2Point::try_from(up).unwrap();
//! let q = UnitQuat::try_from(turn).unwrap();
//! assert_eq!(p.to_array(), [0.0, 1.0, 0.0]);
//! // And back as f64 mint values, which the application's glam reads as `DVec3` / `DQuat`
//! // (then `.as_vec3()` / `.as_quat()` for f32).
//! let back: mint::Quaternion<f64> = q.into();
//! assert!((back.s - core::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
//! # }
//! ```

#![cfg_attr(docsrs, feature(doc_cfg))]

pub use glam;

mod ambient;
mod arc_blend;
mod arclength;
mod banded;
pub mod bernstein;
mod beta_solve;
mod beta_spline;
mod bezier;
mod catmull_rom;
mod catmull_rom_nlerp;
mod circle;
mod continuity;
mod convert;
mod corner_blend;
mod cubic;
mod curve;
mod error;
mod extrapolate;
mod fit;
mod flow;
mod gamma_spline;
mod geodesic;
mod kim;
mod knots;
mod manifold;
mod math;
pub mod quaternion;
#[cfg(any(test, feature = "compact"))]
mod recast;
mod rotation;
mod rotation_loop;
mod s2;
mod s3;
mod section;
mod slerp_jet;
mod sm;
mod smoothing;
mod squad;

pub use ambient::{Ambient, VecN};
pub use arc_blend::{ArcBlend, ArcBlendTiming, MAX_SMOOTHNESS};
pub use arclength::{ArcLength, ArcLengthInfo, DEFAULT_ARC_LENGTH_ACCURACY, Stall};
pub use beta_spline::{
    BetaParams, BetaSolver, BetaSpline, COINCIDENT_TOLERANCE, ShapeParam, SolveInfo,
};
pub use bezier::{Bezier, CubicSegment, cubic_jet, de_casteljau, de_casteljau_jet};
pub use catmull_rom::CatmullRom;
pub use catmull_rom_nlerp::CatmullRomNlerp;
pub use circle::CircleArc;
pub use continuity::{ContinuityClass, JointContinuity, continuity};
pub use corner_blend::{
    CornerBlend, CornerBlendRotations, CornerCuts, CornerTiming, DEFAULT_CORNER_FRACTION,
};

pub use cubic::{CubicEnd, CubicSolveInfo, CubicSpline, TANGENT_TOLERANCE};
pub use curve::{Curve, Jet, Side};
pub use error::{ArcLengthError, DomainError, PointError, SolveError, SplineError};
pub use extrapolate::{Extrapolate, Extrapolated};
pub use fit::{FitKeys, FitOptions, FitReport, Smoothing};
pub use gamma_spline::{GammaJoint, GammaSpline, Gammas, LastEdge};
pub use geodesic::{GeodesicSpline, NlerpSpline};
pub use kim::{BezierKim, BsplineKim};
pub use knots::{Knots, MAX_KNOT_SPACING, MIN_KNOT_SPACING};
pub use manifold::{ANTIPODAL_TOLERANCE, Manifold};
pub use rotation::{
    ROTATION_TOLERANCE, RotationError, exp_so3, rodrigues_compose, rotation_derivative,
    rotation_matrix_from_rodrigues, skew,
};
pub use rotation_loop::{RotationLoop, closes_at_antipode};
pub use s2::S2Point;
pub use s3::{
    UnitQuat, angular_velocity_acceleration, angular_velocity_acceleration_body, unflip,
    velocity_from_angular, velocity_from_angular_body,
};
pub use section::PlaneSection;
pub use slerp_jet::{ScalarJet, slerp_jet};
pub use sm::SmPoint;
pub use smoothing::{GroupAlgebra, GroupJet, SmoothingPolynomials};
pub use squad::Squad;

/// The former name of [`CornerBlendRotations`] (the book's corner blend of rotations on S³,
/// a different construction from [`CornerBlend<UnitQuat>`](CornerBlend)).
#[deprecated(
    note = "renamed CornerBlendRotations: the book's construction on rotations, not CornerBlend<UnitQuat>"
)]
pub type CornerBlendS3 = CornerBlendRotations;

/// The README's Rust example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;

/// The crate README's (crates.io's page) example, run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct CrateReadmeDoctests;
