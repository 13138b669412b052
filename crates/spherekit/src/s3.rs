// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Unit quaternions: points of S³ and rotations of ℝ³.

use glam::{DQuat, DVec3, DVec4};

use crate::error::PointError;
use crate::manifold::{Manifold, normalize, renormalize};
use crate::math;

/// A unit quaternion: a point of S³ ⊂ ℝ⁴ and, up to sign, a rotation of ℝ³.
///
/// The rotation acts by `v ↦ q·v·q̄`; `q` and `−q` are the same rotation (the double cover).
/// As a point of S³ the ambient vector is glam's `x, y, z, w` [`DVec4`]; the scene format and the
/// CLI write quaternions scalar first, `[w, x, y, z]`.
///
/// # Guarantees
///
/// - All components are finite.
/// - `|q| = 1` up to rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct UnitQuat(DQuat);

/// # Construction
impl UnitQuat {
    /// The identity rotation `1`.
    pub const IDENTITY: Self = Self(DQuat::IDENTITY);

    /// Normalises `q`.
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] or [`PointError::ZeroLength`].
    pub fn try_new(q: DQuat) -> Result<Self, PointError> {
        normalize(DVec4::from(q)).map(|v| Self(DQuat::from_vec4(v)))
    }

    /// Normalises the quaternion `w + x i + y j + z k` given scalar first.
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] or [`PointError::ZeroLength`].
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::UnitQuat;
    ///
    /// let q = UnitQuat::from_wxyz([2.0, 0.0, 0.0, 2.0]).unwrap();
    /// let h = core::f64::consts::FRAC_1_SQRT_2;
    /// assert!((q.to_wxyz()[0] - h).abs() < 1e-15 && (q.to_wxyz()[3] - h).abs() < 1e-15);
    /// ```
    pub fn from_wxyz([w, x, y, z]: [f64; 4]) -> Result<Self, PointError> {
        Self::try_new(DQuat::from_xyzw(x, y, z, w))
    }

    /// Wraps a quaternion that is already unit; the invariant is checked in debug builds only.
    #[must_use]
    pub fn new_unchecked(q: DQuat) -> Self {
        debug_assert!(
            (q.length() - 1.0).abs() < 1e-12,
            "not a unit quaternion: {q:?}"
        );
        Self(q)
    }

    /// The exponential of the pure quaternion `v`: `cos|v| + sin|v|/|v|·v`.
    ///
    /// This is the rotation by the angle `2|v|` about `v`; see [`from_rotation_vector`](Self::from_rotation_vector)
    /// for the rotation-vector convention.
    #[must_use]
    pub fn exp(v: DVec3) -> Self {
        let theta = v.length();
        let c = math::cos(theta);
        Self(DQuat::from_vec4(renormalize(
            (v * math::sinc(theta)).extend(c),
        )))
    }

    /// The quaternion of the rotation vector `w` (axis × angle in radians): `exp(w/2)`.
    #[must_use]
    pub fn from_rotation_vector(w: DVec3) -> Self {
        Self::exp(0.5 * w)
    }

    /// The quaternion of the rotation by `angle` radians about `axis` (normalised here):
    /// `cos(φ/2) + sin(φ/2)·n`.
    ///
    /// # Errors
    ///
    /// [`PointError::ZeroLength`] or [`PointError::NonFinite`] for a bad axis;
    /// [`PointError::NonFinite`] for a non-finite angle.
    pub fn from_axis_angle(axis: DVec3, angle: f64) -> Result<Self, PointError> {
        if !angle.is_finite() {
            return Err(PointError::NonFinite);
        }
        let n = normalize(axis)?;
        Ok(Self::exp(n * (0.5 * angle)))
    }
}

/// # Access
impl UnitQuat {
    /// The quaternion.
    #[must_use]
    pub const fn as_dquat(self) -> DQuat {
        self.0
    }

    /// The components scalar first, `[w, x, y, z]`.
    #[must_use]
    pub fn to_wxyz(self) -> [f64; 4] {
        [self.0.w, self.0.x, self.0.y, self.0.z]
    }

    /// The scalar part `w`.
    #[must_use]
    pub fn scalar(self) -> f64 {
        self.0.w
    }

    /// The vector part `(x, y, z)`.
    #[must_use]
    pub fn vector(self) -> DVec3 {
        self.0.xyz()
    }
}

/// # Algebra
impl UnitQuat {
    /// The Hamilton product `self · rhs`: as rotations, first `rhs`, then `self`. Also `self * rhs`.
    #[must_use]
    #[allow(
        clippy::should_implement_trait,
        reason = "inherent so callers need no trait import; `Mul` delegates here"
    )]
    pub fn mul(self, rhs: Self) -> Self {
        Self(DQuat::from_vec4(renormalize(DVec4::from(self.0 * rhs.0))))
    }

    /// The conjugate `w − x i − y j − z k`, which for a unit quaternion is its inverse.
    #[must_use]
    pub fn conjugate(self) -> Self {
        Self(self.0.conjugate())
    }

    /// The inverse rotation (the conjugate).
    #[must_use]
    pub fn inverse(self) -> Self {
        self.conjugate()
    }

    /// The negation `−q`: the other quaternion of the same rotation. Also `-q`.
    #[must_use]
    #[allow(
        clippy::should_implement_trait,
        reason = "inherent so callers need no trait import; `Neg` delegates here"
    )]
    pub fn neg(self) -> Self {
        Self(-self.0)
    }

    /// The logarithm, a pure quaternion `atan2(|v|, w)/|v|·v` with `|log q| ∈ [0, π]`.
    ///
    /// No sign is flipped: `log(−q) ≠ log(q)`. At `q = −1` the logarithm is not unique and
    /// `π·i` is returned.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{glam::DVec3, UnitQuat};
    ///
    /// let v = DVec3::new(1e-9, -2e-9, 0.5);
    /// assert!((UnitQuat::exp(v).log() - v).length() < 1e-16);
    /// ```
    #[must_use]
    pub fn log(self) -> DVec3 {
        let v = self.0.xyz();
        let s = v.length();
        let w = self.0.w;
        if s == 0.0 {
            return if w >= 0.0 {
                DVec3::ZERO
            } else {
                DVec3::new(core::f64::consts::PI, 0.0, 0.0)
            };
        }
        v * (math::atan2(s, w) / s)
    }

    /// `q^t = exp(t·log q)`, the point at `t` of the one-parameter subgroup through `q`.
    #[must_use]
    pub fn powf(self, t: f64) -> Self {
        Self::exp(self.log() * t)
    }

    /// The rotation vector `2·log q` (axis × angle, angle ∈ [0, 2π]).
    #[must_use]
    pub fn to_rotation_vector(self) -> DVec3 {
        2.0 * self.log()
    }

    /// The rotation angle in `[0, π]`, independent of the sign of `q`.
    #[must_use]
    pub fn rotation_angle(self) -> f64 {
        2.0 * math::atan2(self.0.xyz().length(), self.0.w.abs())
    }

    /// Rotates `v` by `q·v·q̄`.
    #[must_use]
    pub fn rotate(self, v: DVec3) -> DVec3 {
        let q = self.0.xyz();
        let w = self.0.w;
        let t = 2.0 * q.cross(v);
        v + w * t + q.cross(t)
    }
}

impl core::ops::Mul for UnitQuat {
    type Output = Self;
    fn mul(self, rhs: Self) -> Self {
        Self::mul(self, rhs)
    }
}

impl core::ops::Neg for UnitQuat {
    type Output = Self;
    fn neg(self) -> Self {
        Self::neg(self)
    }
}

impl Manifold for UnitQuat {
    type Vector = DVec4;

    /// The rotation angle: `|ω| = 2|q′|`.
    const SPEED_SCALE: f64 = 2.0;

    #[inline]
    fn to_vector(&self) -> DVec4 {
        DVec4::from(self.0)
    }

    #[inline]
    fn from_vector_unchecked(v: DVec4) -> Self {
        Self::new_unchecked(DQuat::from_vec4(v))
    }
}

/// Canonicalises a key sequence for the double cover: negates keys so that every consecutive
/// pair has a non-negative dot product (each key is compared with its already canonical
/// predecessor). The first key is kept. Returns the number of keys negated.
///
/// Spline constructors on S³ take keys as given; the scene format calls this once, before
/// construction, unless `"canonicalize": false`.
///
/// # Examples
///
/// ```
/// use spherekit::{unflip, UnitQuat};
///
/// let q = UnitQuat::from_wxyz([0.9, 0.1, 0.0, 0.0]).unwrap();
/// let mut keys = [UnitQuat::IDENTITY, q.neg(), q];
/// assert_eq!(unflip(&mut keys), 1);
/// assert_eq!(keys[1], q);
/// assert_eq!(keys[2], q);
/// ```
pub fn unflip(keys: &mut [UnitQuat]) -> usize {
    let mut flips = 0;
    for i in 1..keys.len() {
        if keys[i - 1].0.dot(keys[i].0) < 0.0 {
            keys[i] = keys[i].neg();
            flips += 1;
        }
    }
    flips
}

/// Angular velocity and acceleration of a unit-quaternion curve from its ambient derivatives.
///
/// With `q(t)` acting by `v ↦ q v q̄`, the space-frame (fixed-frame) angular velocity is
/// `ω = 2·q′·q̄` and the angular acceleration `α = ω′ = 2·q″·q̄` (the term `2·q′·q̄′ = 2|q′|²` is
/// real and drops out of the vector part). The body-frame values are `q̄·ω·q` and `q̄·α·q`.
/// `dq` and `ddq` are ambient `x, y, z, w` vectors.
#[must_use]
#[inline]
pub fn angular_velocity_acceleration(q: UnitQuat, dq: DVec4, ddq: DVec4) -> (DVec3, DVec3) {
    let qc = q.0.conjugate();
    let omega = (DQuat::from_vec4(dq) * qc).xyz() * 2.0;
    let alpha = (DQuat::from_vec4(ddq) * qc).xyz() * 2.0;
    (omega, alpha)
}

/// Body-frame angular velocity and acceleration of a unit-quaternion curve from its ambient
/// derivatives: the counterpart of [`angular_velocity_acceleration`] in the frame that turns
/// with the body (scipy's `RotationSpline(t, 1)` and `RotationSpline(t, 2)`).
///
/// ```text
/// space frame:  ω = 2·q′·q̄,   α = ω′ = 2·q″·q̄     (vector parts)
/// body frame:   ω_b = 2·q̄·q′ = q̄·ω·q,   α_b = ω_b′ = 2·q̄·q″ = q̄·α·q
/// ```
///
/// `ω_b′ = 2·(q̄′·q′ + q̄·q″)`, and `q̄′·q′ = |q′|²` is real, so it drops out of the vector part.
/// The acceleration transforms like the velocity although the frame turns: differentiating
/// `ω_b = q̄·ω·q` with `q′ = ½·ω·q` (so `q̄′ = −½·q̄·ω`) gives
/// `ω_b′ = q̄·α·q + ½·q̄·(ω·ω − ω·ω)·q = q̄·α·q`: the turning of the frame contributes `ω × ω = 0`.
///
/// # Examples
///
/// ```
/// use spherekit::{angular_velocity_acceleration, angular_velocity_acceleration_body, UnitQuat};
/// use spherekit::glam::{DQuat, DVec3, DVec4};
///
/// let q = UnitQuat::from_axis_angle(DVec3::new(1.0, 2.0, 0.5), 0.8).unwrap();
/// // Turning about the body's own x axis at 3 rad per unit time: q′ = ½·q·(3 i).
/// let dq = DVec4::from(q.as_dquat() * DQuat::from_xyzw(1.5, 0.0, 0.0, 0.0));
/// let ddq = DVec4::from(q.as_dquat() * DQuat::from_xyzw(0.0, 0.0, 0.0, -2.25));
/// let (wb, ab) = angular_velocity_acceleration_body(q, dq, ddq);
/// assert!((wb - DVec3::new(3.0, 0.0, 0.0)).length() < 1e-14);
/// assert!(ab.length() < 1e-14);
/// let (w, _) = angular_velocity_acceleration(q, dq, ddq);
/// assert!((q.rotate(wb) - w).length() < 1e-14); // ω = q·ω_b·q̄
/// ```
#[must_use]
#[inline]
pub fn angular_velocity_acceleration_body(q: UnitQuat, dq: DVec4, ddq: DVec4) -> (DVec3, DVec3) {
    let qc = q.0.conjugate();
    let omega = (qc * DQuat::from_vec4(dq)).xyz() * 2.0;
    let alpha = (qc * DQuat::from_vec4(ddq)).xyz() * 2.0;
    (omega, alpha)
}

/// The ambient velocity `q′ = ½·ω·q` of a unit-quaternion curve at `q` turning with the
/// space-frame angular velocity `ω` (the inverse of [`angular_velocity_acceleration`]).
#[must_use]
pub fn velocity_from_angular(q: UnitQuat, omega: DVec3) -> DVec4 {
    DVec4::from(DQuat::from_vec4(omega.extend(0.0)) * q.0) * 0.5
}

/// The ambient velocity `q′ = ½·q·ω_b` of a unit-quaternion curve at `q` turning with the
/// body-frame angular velocity `ω_b` (the inverse of [`angular_velocity_acceleration_body`]).
#[must_use]
pub fn velocity_from_angular_body(q: UnitQuat, omega_body: DVec3) -> DVec4 {
    DVec4::from(q.0 * DQuat::from_vec4(omega_body.extend(0.0))) * 0.5
}
