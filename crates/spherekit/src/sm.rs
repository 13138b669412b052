// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Points on the unit sphere S^m of any dimension m ≥ 1.

use crate::ambient::{Ambient, VecN};
use crate::error::PointError;
use crate::manifold::{Manifold, normalize};

/// A point on the unit sphere S^m ⊂ ℝ^(m+1), with m chosen at run time.
///
/// # Guarantees
///
/// - At least two coordinates (m ≥ 1), all finite.
/// - `|p| = 1` up to rounding.
///
/// Points of spheres of different dimensions meet as points of the larger sphere, the shorter
/// coordinates padded with zeros (S^m ⊂ S^n, see [`VecN`]): their distance, logarithm and
/// geodesic are defined, and no operation panics on a mismatch.
#[derive(Clone, Debug, PartialEq)]
pub struct SmPoint(VecN);

/// # Construction
impl SmPoint {
    /// Normalises `coords` onto the sphere S^(len − 1).
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
    /// let p = SmPoint::try_new(vec![0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(p.dim(), 5);
    /// assert_eq!(p.coords(), &[0.0, 1.0, 0.0, 0.0, 0.0, 0.0]);
    /// ```
    pub fn try_new(coords: Vec<f64>) -> Result<Self, PointError> {
        if coords.len() < 2 {
            return Err(PointError::WrongDimension {
                expected: 2,
                got: coords.len(),
            });
        }
        normalize(VecN::new(coords)).map(Self)
    }

    /// The coordinates of the unit vector.
    #[must_use]
    pub fn coords(&self) -> &[f64] {
        self.0.as_slice()
    }

    /// The dimension m of the sphere S^m (one less than the number of coordinates).
    #[must_use]
    pub fn dim(&self) -> usize {
        self.0.dim() - 1
    }
}

impl Manifold for SmPoint {
    type Vector = VecN;

    fn to_vector(&self) -> VecN {
        self.0.clone()
    }

    fn from_vector_unchecked(v: VecN) -> Self {
        debug_assert!((v.length() - 1.0).abs() < 1e-12, "not a unit vector: {v:?}");
        Self(v)
    }
}
