// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `geodesic`: [`spherekit::GeodesicSpline`].

use spherekit::GeodesicSpline;

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "geodesic",
    name: "Great-circle arcs (slerp)",
    type_name: "GeodesicSpline",
    summary: "piecewise geodesic (slerp) through the points",
    continuity: "C⁰",
    source: "Shoemake (1985), Animating rotation with quaternion curves",
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
            GeodesicSpline::try_new_closed(p.clone(), knots)?
        } else {
            GeodesicSpline::try_new(p.clone(), knots)?
        };
        Built::new(curve, p)
    }))
}
