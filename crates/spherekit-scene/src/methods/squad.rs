// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `squad`: [`spherekit::Squad`].

use spherekit::Squad;

use crate::built::{Built, BuiltCurve};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "squad",
    name: "Squad",
    type_name: "Squad",
    summary: "Shoemake's squad through keys",
    continuity: "C¹",
    source: "Shoemake (1987), Quaternion calculus and fast animation (SIGGRAPH course notes)",
    spaces: Spaces::S3,
    knots: KnotRule::PerPoint { skip: 0 },
    min_points: 2,
    interpolates: true,
    single_piece: false,
    closes: true,
    params: &[],
    build,
};

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let keys = super::s3_keys(&input)?;
    input.params.finish()?;
    let curve = if input.closed {
        Squad::try_new_closed(keys.clone(), input.knots)?
    } else {
        Squad::try_new(keys.clone(), input.knots)?
    };
    let controls = curve.controls().to_vec();
    Ok(BuiltCurve::S3(
        Built::new(curve, keys)
            .with_controls(controls)
            .with_order(1),
    ))
}
