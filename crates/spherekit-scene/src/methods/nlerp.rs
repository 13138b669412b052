// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `nlerp`: [`spherekit::NlerpSpline`].

use spherekit::NlerpSpline;

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "nlerp",
    name: "Normalised lerp (nlerp)",
    type_name: "NlerpSpline",
    summary: "piecewise normalised-linear interpolation through the points",
    continuity: "C⁰",
    source: "normalised linear interpolation of the ambient coordinates",
    spaces: Spaces::All,
    knots: KnotRule::PerPoint { skip: 0 },
    min_points: 2,
    interpolates: true,
    single_piece: false,
    closes: true,
    params: &[],
    build,
};

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    input.params.finish()?;
    let (knots, closed) = (input.knots, input.closed);
    Ok(on_every_sphere!(input.points, |p| {
        let curve = if closed {
            NlerpSpline::try_new_closed(p.clone(), knots)?
        } else {
            NlerpSpline::try_new(p.clone(), knots)?
        };
        Built::new(curve, p)
    }))
}
