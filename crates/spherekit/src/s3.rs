// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Unit quaternions: points of S³ and rotations of ℝ³.

use core::fmt;

use glam::{DQuat, DVec3, DVec4};

use crate::ambient::Ambient;
use crate::error::PointError;
use crate::manifold::{Manifold, normalize, renormalize, sin_cos_direction_huge};
use crate::math;

/// A unit quaternion: a point of S³ ⊂ ℝ⁴ and, up to sign, a rotation of ℝ³.
///
/// The rotation acts by `v ↦ q·v·q̄`; `q` and `−q` are the same rotation (the double cover).
/// As a point of S³ the ambient vector is glam's `x, y, z, w` [`DVec4`]; the scene format, the
/// CLI, [`from_wxyz`](Self::from_wxyz)/[`to_wxyz`](Self::to_wxyz), `Debug` and `Display` write
/// quaternions scalar first, `w, x, y, z`:
///
/// ```
/// use spherekit::UnitQuat;
///
/// let q = UnitQuat::from_wxyz([0.5, 0.5, 0.5, -0.5]).unwrap();
/// assert_eq!(q.to_wxyz(), [0.5, 0.5, 0.5, -0.5]);
/// assert_eq!(format!("{q:?}"), "UnitQuat { w: 0.5, x: 0.5, y: 0.5, z: -0.5 }");
/// assert_eq!(format!("{q}"), "0.5 + 0.5i + 0.5j - 0.5k");
/// assert_eq!(format!("{:.2}", UnitQuat::IDENTITY), "1.00 + 0.00i + 0.00j + 0.00k");
/// ```
///
/// # Guarantees
///
/// - All components are finite.
/// - `|q| = 1` up to rounding.
///
/// Every constructor and operation keeps them: a bad input is a typed [`PointError`] (or
/// [`RotationError`](crate::RotationError)) from the fallible forms, and the infallible forms
/// document the finite value they return instead (the identity, or the point at parameter 0),
/// the same in debug and release builds.
///
/// # Names
///
/// Two exponentials meet on S³. [`exp_pure`](Self::exp_pure) and [`log_pure`](Self::log_pure)
/// are the quaternion exponential and logarithm of a *pure* quaternion `(0, v)`: `exp_pure(v)`
/// is the rotation by the angle **`2|v|`** about `v` (its argument is a half rotation vector),
/// so `from_rotation_vector(w) = exp_pure(w/2)`. [`Manifold::exp`] and [`Manifold::log`] are
/// the sphere's exponential map and its inverse at a base point, with ambient `x, y, z, w`
/// tangents; at the identity they agree, `IDENTITY.exp(&v.extend(0.0)) = exp_pure(v)`.
#[derive(Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct UnitQuat(DQuat);

/// `UnitQuat { w: …, x: …, y: …, z: … }`, scalar first (the order of
/// [`to_wxyz`](UnitQuat::to_wxyz)); the formatter's options (`{:.3?}`, `{:#?}`) apply to
/// each component.
impl fmt::Debug for UnitQuat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("UnitQuat")
            .field("w", &self.0.w)
            .field("x", &self.0.x)
            .field("y", &self.0.y)
            .field("z", &self.0.z)
            .finish()
    }
}

/// `w + xi + yj + zk`, scalar first, with the sign of each imaginary part written as its
/// operator (`0.5 - 0.5i + 0.5j + 0.5k`); the formatter's options (`{:.3}`) apply to each
/// component.
impl fmt::Display for UnitQuat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0.w, f)?;
        for (c, unit) in [(self.0.x, 'i'), (self.0.y, 'j'), (self.0.z, 'k')] {
            f.write_str(if c < 0.0 { " - " } else { " + " })?;
            fmt::Display::fmt(&c.abs(), f)?;
            write!(f, "{unit}")?;
        }
        Ok(())
    }
}

/// # Construction
impl UnitQuat {
    /// The identity rotation `1`.
    pub const IDENTITY: Self = Self(DQuat::IDENTITY);

    /// Normalises `q` (glam's `x, y, z, w`).
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

    /// Wraps a quaternion (glam's `x, y, z, w`) that is already unit, without normalising it;
    /// use [`try_new`](Self::try_new) for data.
    ///
    /// # Panics
    ///
    /// In debug builds, if `q` is not a finite unit quaternion (to within `1e-12`). Release
    /// builds do not check.
    #[must_use]
    pub fn new_unchecked(q: DQuat) -> Self {
        debug_assert!(
            (q.length() - 1.0).abs() < 1e-12,
            "not a unit quaternion: {q:?}"
        );
        Self(q)
    }

    /// The quaternion exponential of the pure quaternion `(0, v)`:
    /// `exp_pure(v) = cos|v| + sin|v|·v/|v|`, the rotation by the angle **`2|v|`** about `v`.
    ///
    /// `v` is a *half* rotation vector: [`from_rotation_vector`](Self::from_rotation_vector)`(w)`
    /// is `exp_pure(w/2)`. The inverse is [`log_pure`](Self::log_pure). Not to be confused with
    /// the sphere's exponential map [`Manifold::exp`] (see [Names](Self#names)).
    ///
    /// Total: the angle `|v|` may be any finite size. It is reduced modulo 2π (the period of
    /// the quaternion, a rotation angle `2|v|` modulo 4π, so the result is continuous in `v`)
    /// by the sine and cosine themselves, whose argument reduction is exact, so the result is
    /// the quaternion at the angle `|v|` as rounded to `f64`; beyond about 1e16 that rounding is
    /// more than a turn, and only the axis is meaningful. A `v` with a NaN or infinite
    /// coordinate gives the identity (the value at `v = 0`); check it first, or use
    /// [`from_rotation_vector`](Self::from_rotation_vector), to have an error instead.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{glam::DVec3, UnitQuat};
    ///
    /// // A quarter turn about z from the half rotation vector (0, 0, π/4).
    /// let q = UnitQuat::exp_pure(DVec3::new(0.0, 0.0, core::f64::consts::FRAC_PI_4));
    /// assert!((q.rotate(DVec3::X) - DVec3::Y).length() < 1e-15);
    /// assert_eq!(UnitQuat::exp_pure(DVec3::NAN), UnitQuat::IDENTITY);
    /// ```
    #[doc(alias = "exp")]
    #[must_use]
    pub fn exp_pure(v: DVec3) -> Self {
        if !v.is_finite() {
            return Self::IDENTITY;
        }
        let theta = v.length();
        if !theta.is_finite() {
            // |v|² overflows: the rescaled length, and halving if even that overflows.
            let (s, c, dir) = sin_cos_direction_huge(&v);
            return Self(DQuat::from_vec4(renormalize((dir * s).extend(c))));
        }
        let c = math::cos(theta);
        Self(DQuat::from_vec4(renormalize(
            (v * math::sinc(theta)).extend(c),
        )))
    }

    /// The quaternion of the rotation vector `w` (axis × angle in radians): `exp_pure(w/2)`,
    /// `cos(|w|/2) + sin(|w|/2)·w/|w|`, the rotation by `|w|` about `w`.
    ///
    /// Every finite `w` is a rotation: the angle is reduced modulo 4π (so that the quaternion
    /// is continuous in `w`; modulo 2π would flip its sign) by the sine and cosine of `|w|/2`
    /// themselves, exactly, as [`exp_pure`](Self::exp_pure) explains. The inverse is
    /// [`to_rotation_vector`](Self::to_rotation_vector) (up to the sign of the quaternion and
    /// multiples of 2π).
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] if a coordinate of `w` is NaN or infinite.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{glam::DVec3, UnitQuat};
    ///
    /// let q = UnitQuat::from_rotation_vector(DVec3::new(0.0, 0.0, core::f64::consts::FRAC_PI_2))?;
    /// assert!((q.rotate(DVec3::X) - DVec3::Y).length() < 1e-15);
    /// // A rotation by 1e300 rad about x: finite, unit, about x.
    /// let big = UnitQuat::from_rotation_vector(DVec3::new(1e300, 0.0, 0.0))?;
    /// assert!(big.vector().y == 0.0 && big.vector().z == 0.0);
    /// assert!(UnitQuat::from_rotation_vector(DVec3::new(f64::NAN, 0.0, 0.0)).is_err());
    /// # Ok::<(), spherekit::PointError>(())
    /// ```
    pub fn from_rotation_vector(w: DVec3) -> Result<Self, PointError> {
        if !w.is_finite() {
            return Err(PointError::NonFinite);
        }
        Ok(Self::exp_pure(0.5 * w))
    }

    /// The quaternion of the rotation by `angle` radians about `axis` (normalised here):
    /// `cos(φ/2) + sin(φ/2)·n`.
    ///
    /// Every finite angle is a rotation: `φ/2` is reduced modulo 2π exactly by the sine and
    /// cosine (see [`exp_pure`](Self::exp_pure)), so even `angle = 1e300` gives the rotation by
    /// exactly that angle (as an `f64`) about `axis`.
    ///
    /// # Errors
    ///
    /// [`PointError::NonFiniteAngle`] if `angle` is NaN or infinite;
    /// [`PointError::NonFinite`] or [`PointError::ZeroLength`] for a bad axis.
    pub fn from_axis_angle(axis: DVec3, angle: f64) -> Result<Self, PointError> {
        if !angle.is_finite() {
            return Err(PointError::NonFiniteAngle);
        }
        let n = normalize(axis)?;
        let (s, c) = math::sin_cos(0.5 * angle);
        Ok(Self(DQuat::from_vec4(renormalize((n * s).extend(c)))))
    }
}

/// # Access
impl UnitQuat {
    /// The quaternion (glam's `x, y, z, w`).
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
///
/// The Hamilton product is the operator `p * q` (as rotations: first `q`, then `p`; the result
/// is renormalised) and the negation, the other quaternion of the same rotation, is `-q`.
impl UnitQuat {
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

    /// The quaternion logarithm, a pure quaternion `(0, atan2(|v|, w)·v/|v|)` with
    /// `|log_pure q| ∈ [0, π]`, returned as its vector part: the *half* rotation vector, so
    /// that [`exp_pure`](Self::exp_pure)`(q.log_pure()) = q` and
    /// [`to_rotation_vector`](Self::to_rotation_vector) is `2·log_pure`. Not to be confused
    /// with the sphere's logarithm [`Manifold::log`] (see [Names](Self#names)).
    ///
    /// No sign is flipped: `log_pure(−q) ≠ log_pure(q)`. At `q = −1` the logarithm is not
    /// unique and `π·i` is returned. Always finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{glam::DVec3, UnitQuat};
    ///
    /// let v = DVec3::new(1e-9, -2e-9, 0.5);
    /// assert!((UnitQuat::exp_pure(v).log_pure() - v).length() < 1e-16);
    /// ```
    #[doc(alias = "log")]
    #[must_use]
    pub fn log_pure(self) -> DVec3 {
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

    /// `q^t = exp_pure(t·log_pure q)`, the point at `t` of the one-parameter subgroup through
    /// `q` (no sign is flipped, so `q^t` follows the arc from 1 through `q`, not through `−q`).
    ///
    /// Any finite `t·|log_pure q|` is reduced exactly (see [`exp_pure`](Self::exp_pure)).
    ///
    /// # Errors
    ///
    /// [`PointError::NonFiniteParameter`] if `t` is NaN or infinite, or so large that
    /// `t·log_pure q` overflows.
    pub fn try_powf(self, t: f64) -> Result<Self, PointError> {
        if !t.is_finite() {
            return Err(PointError::NonFiniteParameter);
        }
        let v = self.log_pure() * t;
        if !v.is_finite() {
            return Err(PointError::NonFiniteParameter);
        }
        Ok(Self::exp_pure(v))
    }

    /// Like [`try_powf`](Self::try_powf), but the identity (`q⁰`) where that has no result: for
    /// a NaN or infinite `t`, or one so large that `t·log_pure q` overflows.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{glam::DVec3, UnitQuat};
    ///
    /// let q = UnitQuat::from_axis_angle(DVec3::Z, 1.0)?;
    /// assert!((q.powf(0.5).rotation_angle() - 0.5).abs() < 1e-15);
    /// assert_eq!(q.powf(f64::NAN), UnitQuat::IDENTITY);
    /// # Ok::<(), spherekit::PointError>(())
    /// ```
    #[must_use]
    pub fn powf(self, t: f64) -> Self {
        self.try_powf(t).unwrap_or(Self::IDENTITY)
    }

    /// The rotation vector `2·log_pure q` (axis × angle, angle ∈ [0, 2π]; no sign is flipped,
    /// so `q` and `−q` give angles `φ` and `2π − φ` about opposite axes). Always finite.
    #[must_use]
    pub fn to_rotation_vector(self) -> DVec3 {
        2.0 * self.log_pure()
    }

    /// The rotation angle in `[0, π]`, independent of the sign of `q`.
    #[must_use]
    pub fn rotation_angle(self) -> f64 {
        2.0 * math::atan2(self.0.xyz().length(), self.0.w.abs())
    }

    /// Rotates `v` by `q·v·q̄`.
    ///
    /// A linear map of `v`: a NaN or infinite coordinate of `v` gives non-finite coordinates.
    /// A finite `v` gives a finite result (no NaN from an intermediate overflow; the result
    /// has the length of `v`).
    #[must_use]
    pub fn rotate(self, v: DVec3) -> DVec3 {
        no_overflow_nan(v, |v| {
            let q = self.0.xyz();
            let w = self.0.w;
            let t = 2.0 * q.cross(v);
            v + w * t + q.cross(t)
        })
    }
}

impl core::ops::Mul for UnitQuat {
    type Output = Self;
    /// The Hamilton product `self · rhs`, renormalised: as rotations, first `rhs`, then `self`.
    fn mul(self, rhs: Self) -> Self {
        Self(DQuat::from_vec4(renormalize(DVec4::from(self.0 * rhs.0))))
    }
}

impl core::ops::Neg for UnitQuat {
    type Output = Self;
    /// `−q`: the other quaternion of the same rotation.
    fn neg(self) -> Self {
        Self(-self.0)
    }
}

/// `f(v)` for a linear map `f`, without a NaN from an intermediate overflow: when `v` is
/// finite but `f(v)` is not, `f` is evaluated at `v/16` (whose intermediates of these
/// quaternion products stay below `f64::MAX`) and scaled back, which can only overflow to ±∞.
/// A non-finite `v` gives `f(v)` as it is.
#[inline]
fn no_overflow_nan<V, W>(v: V, f: impl Fn(V) -> W) -> W
where
    V: Ambient + Copy,
    W: Ambient + Copy,
{
    let r = f(v);
    if r.is_finite() || !v.is_finite() {
        r
    } else {
        f(v * (1.0 / 16.0)) * 16.0
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
/// let mut keys = [UnitQuat::IDENTITY, -q, q];
/// assert_eq!(unflip(&mut keys), 1);
/// assert_eq!(keys[1], q);
/// assert_eq!(keys[2], q);
/// ```
pub fn unflip(keys: &mut [UnitQuat]) -> usize {
    let mut flips = 0;
    for i in 1..keys.len() {
        if keys[i - 1].0.dot(keys[i].0) < 0.0 {
            keys[i] = -keys[i];
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
///
/// Linear in `dq` and in `ddq`: a NaN or infinite coordinate of one gives non-finite
/// components of its output (so that a caller's check of its own derivatives still sees it);
/// finite ones give finite outputs (no NaN from an intermediate overflow), unless the exact
/// value overflows `f64`.
#[must_use]
#[inline]
pub fn angular_velocity_acceleration(q: UnitQuat, dq: DVec4, ddq: DVec4) -> (DVec3, DVec3) {
    let qc = q.0.conjugate();
    let space = |d: DVec4| no_overflow_nan(d, |d| (DQuat::from_vec4(d) * qc).xyz() * 2.0);
    (space(dq), space(ddq))
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
/// Non-finite and huge inputs as for [`angular_velocity_acceleration`].
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
    let body = |d: DVec4| no_overflow_nan(d, |d| (qc * DQuat::from_vec4(d)).xyz() * 2.0);
    (body(dq), body(ddq))
}

/// The ambient velocity `q′ = ½·ω·q` (`x, y, z, w`) of a unit-quaternion curve at `q` turning
/// with the space-frame angular velocity `ω` (the inverse of [`angular_velocity_acceleration`]).
///
/// Linear in `ω`: a NaN or infinite component gives non-finite coordinates (which
/// [`CubicEnd`](crate::CubicEnd)'s checks then reject); a finite `ω` gives a finite result.
#[must_use]
pub fn velocity_from_angular(q: UnitQuat, omega: DVec3) -> DVec4 {
    no_overflow_nan(omega, |w| {
        DVec4::from(DQuat::from_vec4(w.extend(0.0)) * q.0) * 0.5
    })
}

/// The ambient velocity `q′ = ½·q·ω_b` (`x, y, z, w`) of a unit-quaternion curve at `q`
/// turning with the body-frame angular velocity `ω_b` (the inverse of
/// [`angular_velocity_acceleration_body`]).
///
/// Non-finite and huge inputs as for [`velocity_from_angular`].
#[must_use]
pub fn velocity_from_angular_body(q: UnitQuat, omega_body: DVec3) -> DVec4 {
    no_overflow_nan(omega_body, |w| {
        DVec4::from(q.0 * DQuat::from_vec4(w.extend(0.0))) * 0.5
    })
}
