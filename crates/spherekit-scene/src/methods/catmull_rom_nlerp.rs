// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `catmull-rom-nlerp`: [`spherekit::CatmullRomNlerp`].

use spherekit::CatmullRomNlerp;

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "catmull-rom-nlerp",
    name: "Normalised Catmull–Rom",
    type_name: "CatmullRomNlerp",
    summary: "Euclidean Catmull-Rom of the points in ℝ^(m+1) (ℝ⁴ for quaternions), normalised: not constant speed, off the great circles (first and last points steer the ends; closed: every point a key)",
    continuity: "C¹",
    source: "Catmull & Rom (1974); normalised in ℝ⁴ as in Gortler (2012), §9.3",
    spaces: Spaces::All,
    knots: KnotRule::PerPoint { skip: 1 },
    min_points: 4,
    interpolates: false,
    single_piece: false,
    closes: true,
    params: &[],
    build,
};

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let (knots, closed) = (input.knots, input.closed);
    input.params.finish()?;
    Ok(on_every_sphere!(input.points, |p| {
        let curve = if closed {
            CatmullRomNlerp::try_new_closed(p.clone(), knots)?
        } else {
            CatmullRomNlerp::try_new(p.clone(), knots)?
        };
        Built::new(curve, p).with_order(1)
    }))
}
