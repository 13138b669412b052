// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `catmull-rom`: [`spherekit::CatmullRom`].

use spherekit::CatmullRom;

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::params::Param;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::{Input, Points};

pub(crate) static METHOD: Method = Method {
    id: "catmull-rom",
    name: "Catmull–Rom",
    type_name: "CatmullRom",
    summary: "Catmull-Rom spline by slerps (first and last points steer the ends; closed: every point a key)",
    continuity: "C¹",
    source: "Catmull & Rom (1974); on S³ by slerps as in the textbook quaternion Catmull-Rom",
    spaces: Spaces::All,
    knots: KnotRule::PerPoint { skip: 1 },
    min_points: 4,
    interpolates: false,
    single_piece: false,
    closes: true,
    params: &[Param::choice(
        "tangent",
        "tangent",
        "S3: the textbook's quaternion-difference tangents or intrinsic (log map) ones",
        &["quaternion", "intrinsic"],
    )
    .s3_only()],
    build,
};

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let (knots, closed) = (input.knots, input.closed);
    if let Points::S3(keys) = input.points {
        let tangent = input.params.choice("tangent")?;
        input.params.finish()?;
        let curve = match (tangent == "quaternion", closed) {
            (true, false) => CatmullRom::try_new_quaternion(keys.clone(), knots)?,
            (true, true) => CatmullRom::try_new_quaternion_closed(keys.clone(), knots)?,
            (false, false) => CatmullRom::try_new(keys.clone(), knots)?,
            (false, true) => CatmullRom::try_new_closed(keys.clone(), knots)?,
        };
        let controls = curve.controls().to_vec();
        return Ok(BuiltCurve::S3(
            Built::new(curve, keys)
                .with_controls(controls)
                .with_order(1),
        ));
    }
    input.params.finish()?;
    Ok(on_every_sphere!(input.points, |p| {
        let curve = if closed {
            CatmullRom::try_new_closed(p.clone(), knots)?
        } else {
            CatmullRom::try_new(p.clone(), knots)?
        };
        let controls = curve.controls().to_vec();
        Built::new(curve, p).with_controls(controls).with_order(1)
    }))
}
