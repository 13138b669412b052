// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! One file per curve method: its registry entry and its build function.

pub(crate) mod arc_blend;
pub(crate) mod beta;
pub(crate) mod bezier;
pub(crate) mod bezier_kim;
pub(crate) mod bspline_kim;
pub(crate) mod catmull_rom;
pub(crate) mod catmull_rom_nlerp;
pub(crate) mod corner_blend;
pub(crate) mod cubic;
pub(crate) mod gamma;
pub(crate) mod geodesic;
pub(crate) mod nlerp;
pub(crate) mod squad;

use crate::error::{SceneError, field_error};
use crate::scene::{Input, Points};

/// The keys on S³, for the methods that have an S³ form only (the registry's spheres keep
/// other spheres from reaching them).
pub(crate) fn s3_keys(input: &Input<'_>) -> Result<Vec<spherekit::UnitQuat>, SceneError> {
    match &input.points {
        Points::S3(keys) => Ok(keys.clone()),
        _ => Err(field_error("method", "is available on S3 only")),
    }
}
