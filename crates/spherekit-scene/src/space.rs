// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The sphere a scene lives on.

use crate::error::{SceneError, field_error};

/// The largest sphere dimension m accepted in `"S<m>"`.
pub const MAX_DIMENSION: usize = 1024;

/// The sphere a scene lives on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Space {
    /// Directions, points `[x, y, z]`.
    S2,
    /// Orientations, unit quaternions `[w, x, y, z]`.
    S3,
    /// S^m for any other m ≥ 1, points of m + 1 coordinates.
    Sm(usize),
}

impl Space {
    /// Parses `"S2"`, `"S3"` or `"S<m>"`.
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] on `space` for anything else.
    pub fn parse(s: &str) -> Result<Self, SceneError> {
        let bad = || {
            field_error(
                "space",
                format!(
                    "\"{s}\" is not a sphere: use \"S2\", \"S3\" or \"S<m>\" with 1 ≤ m ≤ {MAX_DIMENSION}"
                ),
            )
        };
        let m: usize = s
            .strip_prefix('S')
            .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
            .and_then(|d| d.parse().ok())
            .ok_or_else(bad)?;
        match m {
            2 => Ok(Self::S2),
            3 => Ok(Self::S3),
            1..=MAX_DIMENSION => Ok(Self::Sm(m)),
            _ => Err(bad()),
        }
    }

    /// The number of coordinates of a point.
    #[must_use]
    pub fn coords(self) -> usize {
        match self {
            Self::S2 => 3,
            Self::S3 => 4,
            Self::Sm(m) => m + 1,
        }
    }

    /// The scene name, `"S2"`, `"S3"` or `"S<m>"`.
    #[must_use]
    pub fn name(self) -> String {
        match self {
            Self::S2 => "S2".into(),
            Self::S3 => "S3".into(),
            Self::Sm(m) => format!("S{m}"),
        }
    }

    /// Whether the renderer can draw scenes on this sphere (S¹, S² and S³).
    #[must_use]
    pub fn drawable(self) -> bool {
        !matches!(self, Self::Sm(m) if m != 1)
    }
}
