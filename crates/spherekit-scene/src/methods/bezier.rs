// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `bezier`: [`spherekit::Bezier`].

use spherekit::Bezier;

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "bezier",
    name: "Bézier",
    type_name: "Bezier",
    summary: "spherical Bézier curve of any degree by de Casteljau",
    continuity: "C^∞",
    source: "Shoemake (1985), Animating rotation with quaternion curves",
    spaces: Spaces::All,
    knots: KnotRule::None,
    min_points: 2,
    interpolates: false,
    single_piece: true,
    closes: false,
    params: &[],
    build,
};

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    input.params.finish()?;
    Ok(on_every_sphere!(input.points, |p| Built::new(
        Bezier::try_new(p.clone())?,
        p
    )))
}
