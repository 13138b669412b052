// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Conversions of the point types from and to plain arrays, and with the `mint` feature from
//! and to [`mint`]'s vector and quaternion types.
//!
//! Arrays need no shared dependency: `[f64; 3]` for [`S2Point`], `[f64; 4]` in a named order
//! for [`UnitQuat`] ([`UnitQuat::from_xyzw`], [`UnitQuat::from_wxyz`]; there is no
//! `TryFrom<[f64; 4]>`, whose order a reader could not tell), any length ≥ 2 for [`SmPoint`].
//! Every constructor normalises and fails with a [`PointError`] instead of returning NaN.
//!
//! With the `mint` feature, [`S2Point`] and [`UnitQuat`] convert from and to `mint::Vector3` and
//! `mint::Quaternion` (the crate documentation's "Feature flags" has an example).

use glam::{DQuat, DVec3};

use crate::error::PointError;
use crate::{S2Point, SmPoint, UnitQuat};

/// # Arrays
impl S2Point {
    /// Normalises the vector `[x, y, z]` onto the sphere, as [`try_new`](Self::try_new).
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] or [`PointError::ZeroLength`].
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::S2Point;
    ///
    /// let p = S2Point::from_array([0.0, 0.0, 4.0]).unwrap();
    /// assert_eq!(p.to_array(), [0.0, 0.0, 1.0]);
    /// assert_eq!(S2Point::try_from([0.0, 0.0, 4.0]), Ok(p));
    /// assert!(S2Point::from_array([f64::NAN, 0.0, 1.0]).is_err());
    /// ```
    pub fn from_array(xyz: [f64; 3]) -> Result<Self, PointError> {
        Self::try_new(DVec3::from_array(xyz))
    }

    /// The unit vector `[x, y, z]`.
    #[must_use]
    pub fn to_array(self) -> [f64; 3] {
        self.as_dvec3().to_array()
    }
}

impl TryFrom<[f64; 3]> for S2Point {
    type Error = PointError;

    /// [`S2Point::from_array`].
    fn try_from(xyz: [f64; 3]) -> Result<Self, PointError> {
        Self::from_array(xyz)
    }
}

impl From<S2Point> for [f64; 3] {
    fn from(p: S2Point) -> Self {
        p.to_array()
    }
}

/// # Arrays
impl UnitQuat {
    /// Normalises the quaternion `x i + y j + z k + w` given scalar last (glam's, scipy's and
    /// mint's order; [`from_wxyz`](Self::from_wxyz) takes it scalar first).
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
    /// let q = UnitQuat::from_xyzw([0.0, 0.0, 2.0, 2.0]).unwrap();
    /// assert_eq!(q, UnitQuat::from_wxyz([2.0, 0.0, 0.0, 2.0]).unwrap());
    /// let h = core::f64::consts::FRAC_1_SQRT_2;
    /// assert!(q.to_xyzw().iter().zip([0.0, 0.0, h, h]).all(|(a, b)| (a - b).abs() < 1e-15));
    /// assert!(UnitQuat::from_xyzw([0.0; 4]).is_err());
    /// ```
    pub fn from_xyzw(xyzw: [f64; 4]) -> Result<Self, PointError> {
        Self::try_new(DQuat::from_array(xyzw))
    }

    /// The components scalar last, `[x, y, z, w]`.
    #[must_use]
    pub fn to_xyzw(self) -> [f64; 4] {
        self.as_dquat().to_array()
    }
}

/// # Arrays
impl SmPoint {
    /// Normalises `coords` onto the sphere S^(len − 1), as [`try_new`](Self::try_new).
    ///
    /// # Errors
    ///
    /// [`PointError::WrongDimension`] for fewer than two coordinates, [`PointError::NonFinite`]
    /// or [`PointError::ZeroLength`].
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::SmPoint;
    ///
    /// let p = SmPoint::from_slice(&[0.0, 0.0, 0.0, 0.0, 5.0]).unwrap();
    /// assert_eq!((p.dim(), p.coords()), (4, &[0.0, 0.0, 0.0, 0.0, 1.0][..]));
    /// assert_eq!(SmPoint::try_from([0.0, 0.0, 0.0, 0.0, 5.0]), Ok(p));
    /// assert!(SmPoint::from_slice(&[1.0]).is_err());
    /// ```
    pub fn from_slice(coords: &[f64]) -> Result<Self, PointError> {
        Self::try_new(coords.to_vec())
    }
}

impl TryFrom<&[f64]> for SmPoint {
    type Error = PointError;

    /// [`SmPoint::from_slice`].
    fn try_from(coords: &[f64]) -> Result<Self, PointError> {
        Self::from_slice(coords)
    }
}

impl<const N: usize> TryFrom<[f64; N]> for SmPoint {
    type Error = PointError;

    /// [`SmPoint::from_slice`]: S^(N − 1).
    fn try_from(coords: [f64; N]) -> Result<Self, PointError> {
        Self::from_slice(&coords)
    }
}

#[cfg(feature = "mint")]
mod with_mint {
    use super::{PointError, S2Point, UnitQuat};

    impl TryFrom<mint::Vector3<f64>> for S2Point {
        type Error = PointError;

        /// Normalises the vector, as [`S2Point::from_array`].
        fn try_from(v: mint::Vector3<f64>) -> Result<Self, PointError> {
            Self::from_array(v.into())
        }
    }

    impl TryFrom<mint::Vector3<f32>> for S2Point {
        type Error = PointError;

        /// Widens the components to `f64` and normalises, as [`S2Point::from_array`].
        fn try_from(v: mint::Vector3<f32>) -> Result<Self, PointError> {
            Self::from_array([v.x, v.y, v.z].map(f64::from))
        }
    }

    impl From<S2Point> for mint::Vector3<f64> {
        fn from(p: S2Point) -> Self {
            p.to_array().into()
        }
    }

    impl TryFrom<mint::Quaternion<f64>> for UnitQuat {
        type Error = PointError;

        /// Normalises `s + v` (mint's vector part `v` and scalar `s`), as
        /// [`UnitQuat::from_xyzw`].
        fn try_from(q: mint::Quaternion<f64>) -> Result<Self, PointError> {
            Self::from_xyzw(q.into())
        }
    }

    impl TryFrom<mint::Quaternion<f32>> for UnitQuat {
        type Error = PointError;

        /// Widens the components to `f64` and normalises, as [`UnitQuat::from_xyzw`].
        fn try_from(q: mint::Quaternion<f32>) -> Result<Self, PointError> {
            Self::from_xyzw([q.v.x, q.v.y, q.v.z, q.s].map(f64::from))
        }
    }

    impl From<UnitQuat> for mint::Quaternion<f64> {
        fn from(q: UnitQuat) -> Self {
            q.to_xyzw().into()
        }
    }
}
