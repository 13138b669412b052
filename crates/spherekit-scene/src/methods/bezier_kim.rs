// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `bezier-kim`: [`spherekit::BezierKim`].

use spherekit::BezierKim;

use crate::built::{Built, BuiltCurve};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "bezier-kim",
    name: "Kim's Bézier",
    type_name: "BezierKim",
    summary: "Kim-Kim-Shin cumulative Bézier quaternion curve",
    continuity: "C^∞",
    source: "Kim, Kim & Shin (1995), A general construction scheme for unit quaternion curves with simple high order derivatives",
    spaces: Spaces::S3,
    knots: KnotRule::None,
    min_points: 2,
    interpolates: false,
    single_piece: true,
    closes: false,
    params: &[],
    build,
};

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let keys = super::s3_keys(&input)?;
    input.params.finish()?;
    Ok(BuiltCurve::S3(Built::new(
        BezierKim::try_new(keys.clone())?,
        keys,
    )))
}
