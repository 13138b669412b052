// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Conversions between unit quaternions and the other parametrizations of rotations: rotation
//! matrices, axis–angle, Rodrigues parameters (finite rotation vectors) and Euler parameters.
//!
//! Source: Pobegailo (2019), chapters 3–4 (see `docs/references.md`). The book's misprints that
//! matter here, and the readings followed instead (each stated in full in `docs/derivations.md`):
//!
//! - (4.12), the matrix of the Rodrigues parameters, has the signs of the `r₃` terms at (1,2)
//!   and (2,1) exchanged and is not orthogonal; the corrected form is used (§4.3;
//!   `docs/derivations.md#pobegailo-4-12`).
//! - (4.15)/(4.16), the composition of Rodrigues parameters, has the denominator `1 + r₁·r₂`;
//!   the correct one is `1 − r₁·r₂` (§4.5; `docs/derivations.md#pobegailo-4-15`).
//! - (3.16) and the Euler-parameter inverse of (4.13) lose signs or accuracy near a half turn;
//!   the matrix → quaternion conversion uses the four-branch method instead (adapted from §3.10),
//!   with the antisymmetric differences signed for the standard matrix (3.46), not the transposed
//!   (3.41) (`docs/derivations.md#pobegailo-3-41`).
//!
//! The rotation vector (axis × angle) conversions are [`UnitQuat::from_rotation_vector`] and
//! [`UnitQuat::to_rotation_vector`].

use core::fmt;

use glam::{DMat3, DQuat, DVec3, DVec4};

use crate::ambient::Ambient;
use crate::manifold::{normalize, renormalize, sin_cos_direction_huge};
use crate::math;
use crate::s3::UnitQuat;

/// Tolerance of the checks on rotation matrices and Euler parameters.
///
/// A matrix is accepted as a rotation when every entry of `RᵀR − I` is at most this in absolute
/// value and `|det R − 1|` is at most this; Euler parameters are accepted when
/// `|q₀² + q₁² + q₂² + q₃² − 1|` is at most this. The value admits data printed with six or
/// more significant digits while rejecting scaled, sheared or reflecting matrices.
pub const ROTATION_TOLERANCE: f64 = 1e-6;

/// Why a rotation could not be converted.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum RotationError {
    /// An input value is NaN or infinite.
    NonFinite,
    /// The matrix is not orthogonal: the largest entry of `|RᵀR − I|` exceeds
    /// [`ROTATION_TOLERANCE`].
    NotOrthogonal {
        /// The largest absolute entry of `RᵀR − I`.
        deviation: f64,
    },
    /// The matrix is orthogonal but not a proper rotation: `det R` is not `+1` within
    /// [`ROTATION_TOLERANCE`] (a reflection has `det R = −1`).
    NotProper {
        /// The determinant.
        det: f64,
    },
    /// Euler parameters are not a unit 4-vector within [`ROTATION_TOLERANCE`].
    NotUnit {
        /// The Euclidean length `√(q₀² + q₁² + q₂² + q₃²)`.
        norm: f64,
    },
    /// The rotation is a half turn (`q₀ = 0`), whose Rodrigues parameters `tan(φ/2)·n` are
    /// infinite; or a composition of Rodrigues parameters is a half turn (`r₁·r₂ = 1`).
    HalfTurn,
}

impl fmt::Display for RotationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite => f.write_str("has a non-finite value"),
            Self::NotOrthogonal { deviation } => write!(
                f,
                "is not an orthogonal matrix (|RᵀR − I| = {deviation:e}, tolerance {ROTATION_TOLERANCE:e})"
            ),
            Self::NotProper { det } => {
                write!(f, "is not a proper rotation (det = {det}, expected +1)")
            }
            Self::NotUnit { norm } => write!(
                f,
                "is not a unit quaternion (length {norm}, tolerance {ROTATION_TOLERANCE:e})"
            ),
            Self::HalfTurn => {
                f.write_str("is a half turn, whose Rodrigues parameters tan(φ/2)·n are infinite")
            }
        }
    }
}

impl core::error::Error for RotationError {}

/// # Rotations
///
/// Conversions to and from rotation matrices, axis–angle, Rodrigues parameters and Euler
/// parameters (Pobegailo (2019), §2.10, §3.10–3.13, §4.2–4.5). Matrices act on column vectors,
/// `p ↦ R·p`, and
/// `R(q)·p = q·p·q̄` ([`UnitQuat::rotate`]). `q` and `−q` give the same matrix.
impl UnitQuat {
    /// The rotation matrix of `q`, the standard active matrix (3.46) of Pobegailo (2019), §3.12:
    ///
    /// ```text
    /// R = (q₀² − q·q) I + 2 q₀ K(q) + 2 q qᵀ
    ///
    ///   = [ q0²+q1²−q2²−q3²   2(q1q2 − q0q3)     2(q1q3 + q0q2)   ]
    ///     [ 2(q1q2 + q0q3)    q0²−q1²+q2²−q3²    2(q2q3 − q0q1)   ]
    ///     [ 2(q1q3 − q0q2)    2(q2q3 + q0q1)     q0²−q1²−q2²+q3²  ]
    /// ```
    ///
    /// with `K(a)·b = a × b`. `R(−q) = R(q)`, `R(q̄) = Rᵀ`, `R(p·q) = R(p)·R(q)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{UnitQuat, glam::{DMat3, DVec3}};
    ///
    /// // Rotation by 90° about z: e₁ ↦ e₂.
    /// let q = UnitQuat::from_axis_angle(DVec3::Z, core::f64::consts::FRAC_PI_2).unwrap();
    /// let r: DMat3 = q.to_rotation_matrix();
    /// assert!((r * DVec3::X - DVec3::Y).length() < 1e-15);
    /// // Back by the robust four-branch method, canonical sign q₀ ≥ 0.
    /// let back = UnitQuat::from_rotation_matrix(r).unwrap();
    /// assert!((back.as_dquat() - q.as_dquat()).length() < 1e-15);
    /// // A reflection is rejected.
    /// assert!(UnitQuat::from_rotation_matrix(DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0))).is_err());
    /// ```
    #[must_use]
    pub fn to_rotation_matrix(self) -> DMat3 {
        let q = self.as_dquat();
        let (w, x, y, z) = (q.w, q.x, q.y, q.z);
        let (ww, xx, yy, zz) = (w * w, x * x, y * y, z * z);
        let (xy, xz, yz) = (x * y, x * z, y * z);
        let (wx, wy, wz) = (w * x, w * y, w * z);
        // glam matrices are column major: the arguments are the columns of (3.46).
        DMat3::from_cols(
            DVec3::new(ww + xx - yy - zz, 2.0 * (xy + wz), 2.0 * (xz - wy)),
            DVec3::new(2.0 * (xy - wz), ww - xx + yy - zz, 2.0 * (yz + wx)),
            DVec3::new(2.0 * (xz + wy), 2.0 * (yz - wx), ww - xx - yy + zz),
        )
    }

    /// The unit quaternion of a rotation matrix, by the four-branch method, with the
    /// sign chosen so that `q₀ ≥ 0`.
    ///
    /// ```text
    /// t₀ = 1 + r₁₁ + r₂₂ + r₃₃ = 4q₀²      r₃₂ − r₂₃ = 4q₀q₁   r₁₂ + r₂₁ = 4q₁q₂
    /// t₁ = 1 + r₁₁ − r₂₂ − r₃₃ = 4q₁²      r₁₃ − r₃₁ = 4q₀q₂   r₁₃ + r₃₁ = 4q₁q₃
    /// t₂ = 1 − r₁₁ + r₂₂ − r₃₃ = 4q₂²      r₂₁ − r₁₂ = 4q₀q₃   r₂₃ + r₃₂ = 4q₂q₃
    /// t₃ = 1 − r₁₁ − r₂₂ + r₃₃ = 4q₃²
    /// ```
    ///
    /// The largest `t_m` gives `q_m = √t_m / 2`, and the other three components come from the
    /// identities divided by `4q_m`. The four `t_k` sum to 4, so the largest is at least 1 and
    /// `q_m ≥ ½`: the division is always well conditioned and the result is accurate to machine precision for every angle,
    /// including half turns. (The book's single-branch inversion (4.13), `q₀ = ½√(1 + tr R)`,
    /// loses about half the digits near φ = π; and the book's (3.41)-based four-branch formulas
    /// are for the transposed matrix and return the conjugate —
    /// `docs/derivations.md#pobegailo-3-41`, `#pobegailo-3-16`.) The result is
    /// renormalised, so a matrix within the tolerance of a rotation gives an exact unit
    /// quaternion near it. At a half turn (`q₀ = 0`) the sign is the one with the largest
    /// component positive.
    ///
    /// # Errors
    ///
    /// [`RotationError::NonFinite`] for a NaN or infinite entry;
    /// [`RotationError::NotOrthogonal`] if an entry of `RᵀR − I` exceeds
    /// [`ROTATION_TOLERANCE`]; [`RotationError::NotProper`] if `|det R − 1|` exceeds it.
    pub fn from_rotation_matrix(m: DMat3) -> Result<Self, RotationError> {
        check_rotation_matrix(&m)?;
        Ok(Self::from_rotation_matrix_unchecked(m))
    }

    /// The four-branch method of [`from_rotation_matrix`](Self::from_rotation_matrix) without
    /// the orthogonality check. The input must be finite.
    fn from_rotation_matrix_unchecked(m: DMat3) -> Self {
        let r = |i: usize, j: usize| m.col(j)[i];
        let (r11, r22, r33) = (r(0, 0), r(1, 1), r(2, 2));
        let t = [
            1.0 + r11 + r22 + r33,
            1.0 + r11 - r22 - r33,
            1.0 - r11 + r22 - r33,
            1.0 - r11 - r22 + r33,
        ];
        let mut best = 0;
        for k in 1..4 {
            if t[k] > t[best] {
                best = k;
            }
        }
        // Both sides of the identities are 4·q_i·q_j.
        let d01 = r(2, 1) - r(1, 2);
        let d02 = r(0, 2) - r(2, 0);
        let d03 = r(1, 0) - r(0, 1);
        let s12 = r(0, 1) + r(1, 0);
        let s13 = r(0, 2) + r(2, 0);
        let s23 = r(1, 2) + r(2, 1);
        let qm = 0.5 * t[best].sqrt();
        let f = 0.25 / qm;
        // Components scalar first.
        let [w, x, y, z] = match best {
            0 => [qm, d01 * f, d02 * f, d03 * f],
            1 => [d01 * f, qm, s12 * f, s13 * f],
            2 => [d02 * f, s12 * f, qm, s23 * f],
            _ => [d03 * f, s13 * f, s23 * f, qm],
        };
        let sign = if w < 0.0 { -1.0 } else { 1.0 };
        let v = renormalize(DVec4::new(x, y, z, w) * sign);
        Self::new_unchecked(DQuat::from_vec4(v))
    }

    /// The rotation axis and angle, with the angle in `[0, π]` (Pobegailo (2019), §2.10, §3.13):
    ///
    /// ```text
    /// φ = 2·atan2(|q|, |q₀|),   n = sign(q₀)·q/|q|
    /// ```
    ///
    /// so `q` and `−q` give the same result. The axis is a unit vector. For the identity
    /// (`q = ±1`) the axis is undefined and `e₁ = (1, 0, 0)` is returned with angle 0; for a half
    /// turn (`q₀ = 0`) both `±n` are valid and `q/|q|` is returned.
    /// [`from_axis_angle`](Self::from_axis_angle) is the inverse.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{UnitQuat, glam::DVec3};
    ///
    /// let q = UnitQuat::from_axis_angle(DVec3::new(0.0, 0.0, -2.0), 0.5).unwrap();
    /// let (axis, angle) = (-q).to_axis_angle();
    /// assert!((axis + DVec3::Z).length() < 1e-15 && (angle - 0.5).abs() < 1e-15);
    /// // The rotation by −0.5 about z is the rotation by 0.5 about −z.
    /// let (axis, angle) = UnitQuat::from_axis_angle(DVec3::Z, -0.5).unwrap().to_axis_angle();
    /// assert!((axis + DVec3::Z).length() < 1e-15 && (angle - 0.5).abs() < 1e-15);
    /// assert_eq!(UnitQuat::IDENTITY.to_axis_angle(), (DVec3::X, 0.0));
    /// ```
    #[must_use]
    pub fn to_axis_angle(self) -> (DVec3, f64) {
        let q = self.as_dquat();
        let v = q.xyz();
        let s = v.length();
        if s == 0.0 {
            return (DVec3::X, 0.0);
        }
        let angle = 2.0 * math::atan2(s, q.w.abs());
        let sign = if q.w < 0.0 { -1.0 } else { 1.0 };
        (v * (sign / s), angle)
    }

    /// The Rodrigues parameters (finite rotation vector) `r = tan(φ/2)·n = q/q₀` (Pobegailo (2019),
    /// §4.2–4.3).
    ///
    /// They do not depend on the sign of `q`. `r = 0` is the identity.
    ///
    /// # Errors
    ///
    /// [`RotationError::HalfTurn`] when `q₀ = 0` (a rotation by π, where `r` is infinite), or
    /// when `q₀` is so small that `q/q₀` overflows.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{RotationError, UnitQuat, glam::DVec3, rodrigues_compose, rotation_matrix_from_rodrigues};
    /// use core::f64::consts::FRAC_PI_4;
    ///
    /// // The book's example of §4.2–4.3, corrected: R(e₃, π/4) ↦ r = (0, 0, √2 − 1).
    /// let q = UnitQuat::from_axis_angle(DVec3::Z, FRAC_PI_4).unwrap();
    /// let r = q.to_rodrigues().unwrap();
    /// assert!((r - DVec3::new(0.0, 0.0, 2f64.sqrt() - 1.0)).length() < 1e-15);
    /// assert!((UnitQuat::from_rodrigues(r).unwrap().as_dquat() - q.as_dquat()).length() < 1e-15);
    /// // Matrix (corrected (4.12)) and composition (corrected (4.16), r₂ applied first).
    /// let m = rotation_matrix_from_rodrigues(r).unwrap();
    /// assert!(m.abs_diff_eq(q.to_rotation_matrix(), 1e-15));
    /// let r2 = rodrigues_compose(r, r).unwrap(); // two eighth turns = a quarter turn
    /// assert!((r2 - DVec3::Z).length() < 1e-15);
    /// // Half turns have no Rodrigues parameters. (`from_axis_angle(n, π)` has q₀ = cos(π/2) ≈ 6e-17,
    /// // so its r is finite, about 1.6e16·n.)
    /// let half_turn = UnitQuat::from_wxyz([0.0, 1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(half_turn.to_rodrigues(), Err(RotationError::HalfTurn));
    /// ```
    pub fn to_rodrigues(self) -> Result<DVec3, RotationError> {
        let q = self.as_dquat();
        if q.w == 0.0 {
            return Err(RotationError::HalfTurn);
        }
        let r = q.xyz() / q.w;
        if r.is_finite() {
            Ok(r)
        } else {
            Err(RotationError::HalfTurn)
        }
    }

    /// The unit quaternion of the Rodrigues parameters `r = tan(φ/2)·n`, with `q₀ > 0`
    /// (Pobegailo (2019), §4.3, (4.14)):
    ///
    /// ```text
    /// q = (1 + r) / √(1 + |r|²)
    /// ```
    ///
    /// Every finite `r` is a rotation by an angle in `[0, π)`; large `r` are scaled before
    /// normalising, so they do not overflow.
    ///
    /// # Errors
    ///
    /// [`RotationError::NonFinite`] if a component of `r` is NaN or infinite.
    pub fn from_rodrigues(r: DVec3) -> Result<Self, RotationError> {
        if !r.is_finite() {
            return Err(RotationError::NonFinite);
        }
        Self::try_new(DQuat::from_xyzw(r.x, r.y, r.z, 1.0)).map_err(|_| RotationError::NonFinite)
    }

    /// The Euler parameters `(q₀, q₁, q₂, q₃) = (cos(φ/2), sin(φ/2)·n)` (Pobegailo (2019), §4.4),
    /// scalar first,
    /// with the sign chosen so that `q₀ ≥ 0` (so `φ ∈ [0, π]`).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{UnitQuat, glam::DVec3};
    /// use core::f64::consts::FRAC_PI_8;
    ///
    /// // The book's example of §4.4, corrected: R(e₃, π/4) ↦ (cos π/8, 0, 0, sin π/8).
    /// let q = UnitQuat::from_axis_angle(DVec3::Z, 2.0 * FRAC_PI_8).unwrap();
    /// let e = (-q).to_euler_parameters();
    /// assert!((e[0] - FRAC_PI_8.cos()).abs() < 1e-16 && (e[3] - FRAC_PI_8.sin()).abs() < 1e-16);
    /// assert_eq!(UnitQuat::from_euler_parameters(e).unwrap().to_euler_parameters(), e);
    /// assert!(UnitQuat::from_euler_parameters([1.0, 1.0, 0.0, 0.0]).is_err());
    /// ```
    #[must_use]
    pub fn to_euler_parameters(self) -> [f64; 4] {
        let q = if self.scalar() < 0.0 { -self } else { self };
        q.to_wxyz()
    }

    /// The unit quaternion of the Euler parameters `(q₀, q₁, q₂, q₃)`, scalar first. The sign is
    /// kept as given, and the input is renormalised to remove rounding.
    ///
    /// Unlike [`from_wxyz`](Self::from_wxyz), which normalises any non-zero 4-vector, this checks
    /// the constraint `q₀² + q₁² + q₂² + q₃² = 1` that defines Euler parameters.
    ///
    /// # Errors
    ///
    /// [`RotationError::NonFinite`] for a NaN or infinite component;
    /// [`RotationError::NotUnit`] if `|q| − 1` exceeds [`ROTATION_TOLERANCE`] in absolute value.
    pub fn from_euler_parameters([w, x, y, z]: [f64; 4]) -> Result<Self, RotationError> {
        let v = DVec4::new(x, y, z, w);
        if !v.is_finite() {
            return Err(RotationError::NonFinite);
        }
        // Rescaled when the sum of squares overflows, so that the error reports the length.
        let norm = Ambient::length(&v);
        if (norm - 1.0).abs() > ROTATION_TOLERANCE {
            return Err(RotationError::NotUnit { norm });
        }
        Ok(Self::new_unchecked(DQuat::from_vec4(v / norm)))
    }
}

/// Checks that `m` is finite, orthogonal and has determinant `+1`, within
/// [`ROTATION_TOLERANCE`].
fn check_rotation_matrix(m: &DMat3) -> Result<(), RotationError> {
    if !m.is_finite() {
        return Err(RotationError::NonFinite);
    }
    // Huge entries overflow RᵀR to ±∞ and ∞ − ∞ = NaN, which `f64::max` would skip: a NaN
    // counts as an infinite deviation.
    let deviation = (m.transpose() * *m - DMat3::IDENTITY)
        .abs()
        .to_cols_array()
        .iter()
        .fold(
            0.0_f64,
            |a, &b| if b.is_nan() { f64::INFINITY } else { a.max(b) },
        );
    if deviation > ROTATION_TOLERANCE {
        return Err(RotationError::NotOrthogonal { deviation });
    }
    let det = m.determinant();
    if det.is_nan() || (det - 1.0).abs() > ROTATION_TOLERANCE {
        return Err(RotationError::NotProper { det });
    }
    Ok(())
}

/// The rotation matrix of the Rodrigues parameters `r = tan(φ/2)·n`: the corrected (4.12) of
/// Pobegailo (2019), §4.3 (`docs/derivations.md#pobegailo-4-12`),
///
/// ```text
/// R(r) = [(1 − |r|²) I + 2 r rᵀ + 2 K(r)] / (1 + |r|²)
///
///      = 1/(1 + |r|²) · [ 1+r1²−r2²−r3²   2(r1r2 − r3)     2(r1r3 + r2)   ]
///                       [ 2(r1r2 + r3)    1−r1²+r2²−r3²    2(r2r3 − r1)   ]
///                       [ 2(r1r3 − r2)    2(r2r3 + r1)     1−r1²−r2²+r3²  ]
/// ```
///
/// It equals the Cayley form `(I − K(r))⁻¹(I + K(r))` and `R(n, φ)`. **Correction:** the book's
/// printed (4.12) has the `r₃` terms at (1,2) and (2,1) exchanged and is not orthogonal.
///
/// This is (3.46) for the non-unit quaternion `1 + r` divided by its norm; for `|r|∞ > 1`
/// numerator and denominator are scaled by `1/|r|∞²`, so huge `r` (near half turns) give a
/// finite orthogonal matrix instead of overflowing.
/// See [`UnitQuat::to_rodrigues`] for an example.
///
/// # Errors
///
/// [`RotationError::NonFinite`] if a component of `r` is NaN or infinite.
pub fn rotation_matrix_from_rodrigues(r: DVec3) -> Result<DMat3, RotationError> {
    if !r.is_finite() {
        return Err(RotationError::NonFinite);
    }
    let scale = r.abs().max_element().max(1.0);
    let (w, v) = (1.0 / scale, r / scale);
    let n = w * w + v.length_squared();
    let diag = w * w - v.length_squared();
    let k = DMat3::from_cols(
        DVec3::new(0.0, v.z, -v.y),
        DVec3::new(-v.z, 0.0, v.x),
        DVec3::new(v.y, -v.x, 0.0),
    );
    let outer = DMat3::from_cols(v * v.x, v * v.y, v * v.z);
    Ok((DMat3::from_diagonal(DVec3::splat(diag)) + outer * 2.0 + k * (2.0 * w)) * (1.0 / n))
}

/// Composition of Rodrigues parameters (corrected (4.15)/(4.16) of Pobegailo (2019), §4.5;
/// `docs/derivations.md#pobegailo-4-15`): the parameters `r`
/// of `q₁·q₂`, that is `R(r) = R(r₁)·R(r₂)` (first `r₂`, then `r₁`),
///
/// ```text
/// r = (r₁ + r₂ + r₁ × r₂) / (1 − r₁·r₂)
/// ```
///
/// It follows from `(1 + r₁)(1 + r₂) = (1 − r₁·r₂) + (r₁ + r₂ + r₁ × r₂)`. **Correction:** the
/// book prints the denominator `1 + r₁·r₂`, which is wrong, and does not state the order.
///
/// Returns `None` when `r₁·r₂ = 1` (the composite is a half turn, with infinite `r`) or when the
/// result is not finite (non-finite input, or overflow next to a half turn); compose the
/// quaternions instead. See [`UnitQuat::to_rodrigues`] for an example.
#[must_use]
pub fn rodrigues_compose(r1: DVec3, r2: DVec3) -> Option<DVec3> {
    let den = 1.0 - r1.dot(r2);
    if den == 0.0 {
        return None;
    }
    let r = (r1 + r2 + r1.cross(r2)) / den;
    r.is_finite().then_some(r)
}

/// The skew matrix `K(v)` of so(3), `K(v)·x = v × x` (Pobegailo (2019), §4.6: `K₁, K₂, K₃` are
/// `K(e₁)`, `K(e₂)`, `K(e₃)` and `L = l₁K₁ + l₂K₂ + l₃K₃ = K(l)`).
///
/// # Examples
///
/// ```
/// use spherekit::glam::DVec3;
/// use spherekit::skew;
///
/// let (v, x) = (DVec3::new(1.0, -2.0, 0.5), DVec3::new(0.3, 0.1, -4.0));
/// assert_eq!(skew(v) * x, v.cross(x));
/// ```
#[must_use]
pub fn skew(v: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, v.z, -v.y),
        DVec3::new(-v.z, 0.0, v.x),
        DVec3::new(v.y, -v.x, 0.0),
    )
}

/// The exponential of so(3): `exp(K(l))` for the tangent (rotation) vector `l = φ·n`, which is
/// the rotation `R(n, φ)` by the angle `φ = |l|` about the unit axis `n` (Pobegailo (2019), §4.6):
///
/// ```text
/// exp(φK(n)) = cos φ·I + sin φ·K(n) + (1 − cos φ)·n nᵀ
/// ```
///
/// from `K^{2k} = (−1)^k (I − n nᵀ)` and `K^{2k+1} = (−1)^k K`. It equals the matrix of the
/// quaternion `exp_pure(l/2)` ([`UnitQuat::from_rotation_vector`]). The coefficients
/// `sin φ/φ` and `(1 − cos φ)/φ²` use series near 0, so `l → 0` gives `I + K(l)` smoothly.
/// Every finite `l` is a rotation: the angle is reduced modulo 2π exactly by the sine and
/// cosine (a `|l|` whose square overflows is handled through the unit axis).
///
/// # Errors
///
/// [`RotationError::NonFinite`] if a component of `l` is NaN or infinite.
///
/// # Examples
///
/// The book's example: `R(e₃, π/4)` has the tangent vector `l = (0, 0, π/4)`.
///
/// ```
/// use spherekit::glam::DVec3;
/// use spherekit::{UnitQuat, exp_so3};
///
/// let l = DVec3::new(0.0, 0.0, core::f64::consts::FRAC_PI_4);
/// let r = exp_so3(l)?;
/// let h = core::f64::consts::FRAC_1_SQRT_2;
/// assert!((r * DVec3::X - DVec3::new(h, h, 0.0)).length() < 1e-15);
/// assert!(r.abs_diff_eq(UnitQuat::from_rotation_vector(l).unwrap().to_rotation_matrix(), 1e-15));
/// # Ok::<(), spherekit::RotationError>(())
/// ```
pub fn exp_so3(l: DVec3) -> Result<DMat3, RotationError> {
    if !l.is_finite() {
        return Err(RotationError::NonFinite);
    }
    let phi2 = l.length_squared();
    if !phi2.is_finite() {
        // K(l)² would overflow: cos φ·I + sin φ·K(n) + (1 − cos φ)·n nᵀ with the unit axis.
        let (s, c, n) = sin_cos_direction_huge(&l);
        let k = skew(n);
        return Ok(DMat3::IDENTITY + k * s + k * k * (1.0 - c));
    }
    let phi = phi2.sqrt();
    // a = sin φ/φ, b = (1 − cos φ)/φ².
    let (a, b) = if phi < 1e-4 {
        (1.0 - phi2 / 6.0, 0.5 - phi2 / 24.0)
    } else {
        let half = math::sin(0.5 * phi);
        (math::sin(phi) / phi, 2.0 * half * half / phi2)
    };
    let k = skew(l);
    Ok(DMat3::IDENTITY + k * a + k * k * b)
}

/// The derivative of the one-parameter subgroup `t ↦ R(n, ωt)` (Pobegailo (2019), §4.6, (4.27)
/// at `t = 0`): `d/dt R(n, ωt) = ω·K(n)·R(n, ωt)`, for the unit axis `n` (normalised here) and
/// the angular speed `ω`. Returns `(R(n, ωt), d/dt R(n, ωt))`; `None` when `n` has no
/// direction (zero or not finite), or `ω` or `t` is NaN or infinite, or `ωt` overflows.
///
/// # Examples
///
/// ```
/// use spherekit::glam::DVec3;
/// use spherekit::{rotation_derivative, skew};
///
/// // At t = 0 the tangent is ω·K(n) (4.27).
/// let (r, dr) = rotation_derivative(DVec3::Z, 2.0, 0.0).unwrap();
/// assert_eq!(r, spherekit::glam::DMat3::IDENTITY);
/// assert_eq!(dr, skew(DVec3::Z) * 2.0);
/// ```
#[must_use]
pub fn rotation_derivative(n: DVec3, omega: f64, t: f64) -> Option<(DMat3, DMat3)> {
    if !(omega.is_finite() && t.is_finite()) {
        return None;
    }
    let len = n.length();
    let axis = if len.is_finite() && len > 0.0 {
        n / len
    } else {
        // |n|² overflows or underflows: normalise by rescaling.
        normalize(n).ok()?
    };
    let r = exp_so3(axis * (omega * t)).ok()?;
    Some((r, skew(axis) * r * omega))
}
