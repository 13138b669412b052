// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Points on the unit sphere S².

use glam::DVec3;

use crate::error::PointError;
use crate::manifold::{Manifold, normalize};

/// A point on the unit sphere S² ⊂ ℝ³ (a direction).
///
/// # Guarantees
///
/// - All components are finite.
/// - `|p| = 1` up to rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct S2Point(DVec3);

/// # Construction
impl S2Point {
    /// The point (1, 0, 0).
    pub const X: Self = Self(DVec3::X);
    /// The point (0, 1, 0).
    pub const Y: Self = Self(DVec3::Y);
    /// The point (0, 0, 1).
    pub const Z: Self = Self(DVec3::Z);

    /// Normalises `v` onto the sphere.
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] if a component is NaN or infinite, [`PointError::ZeroLength`]
    /// if `v` is zero.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{glam::DVec3, S2Point};
    ///
    /// let p = S2Point::try_new(DVec3::new(3.0, 0.0, 4.0)).unwrap();
    /// assert!((p.as_dvec3() - DVec3::new(0.6, 0.0, 0.8)).length() < 1e-15);
    /// assert!(S2Point::try_new(DVec3::ZERO).is_err());
    /// ```
    pub fn try_new(v: DVec3) -> Result<Self, PointError> {
        normalize(v).map(Self)
    }

    /// Wraps a vector that is already unit length, without normalising it; use
    /// [`try_new`](Self::try_new) for data.
    ///
    /// # Panics
    ///
    /// In debug builds, if `v` is not a finite unit vector (to within `1e-12`). Release builds
    /// do not check.
    #[must_use]
    pub fn new_unchecked(v: DVec3) -> Self {
        debug_assert!((v.length() - 1.0).abs() < 1e-12, "not a unit vector: {v:?}");
        Self(v)
    }

    /// The unit vector.
    #[must_use]
    pub const fn as_dvec3(self) -> DVec3 {
        self.0
    }
}

impl Manifold for S2Point {
    type Vector = DVec3;

    #[inline]
    fn to_vector(&self) -> DVec3 {
        self.0
    }

    #[inline]
    fn from_vector_unchecked(v: DVec3) -> Self {
        Self::new_unchecked(v)
    }
}
