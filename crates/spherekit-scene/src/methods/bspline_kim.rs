// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `bspline-kim`: [`spherekit::BsplineKim`].

use spherekit::BsplineKim;

use crate::built::{Built, BuiltCurve};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "bspline-kim",
    name: "Kim's B-spline",
    type_name: "BsplineKim",
    summary: "Kim-Kim-Shin cumulative cubic B-spline quaternion curve (C², approximating)",
    continuity: "C²",
    source: "Kim, Kim & Shin (1995), A general construction scheme for unit quaternion curves with simple high order derivatives",
    spaces: Spaces::S3,
    knots: KnotRule::None,
    min_points: 4,
    interpolates: false,
    single_piece: false,
    closes: true,
    params: &[],
    build,
};

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let keys = super::s3_keys(&input)?;
    input.params.finish()?;
    let curve = if input.closed {
        BsplineKim::try_new_closed(keys.clone())?
    } else {
        BsplineKim::try_new(keys.clone())?
    };
    Ok(BuiltCurve::S3(Built::new(curve, keys).with_order(2)))
}
