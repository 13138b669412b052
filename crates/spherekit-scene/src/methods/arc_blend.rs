// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `arc-blend`: [`spherekit::ArcBlend`].

use serde_json::json;
use spherekit::{ArcBlend, MAX_BLEND_ORDER};

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::params::{Param, ParamKind};
use crate::registry::{KnotRule, Method, Spheres};
use crate::scene::Input;

/// The continuity order `n` of Pobegailo's blends.
pub(crate) const ORDER: Param = Param::number(
    "order",
    "order n",
    "the continuity order n: the curve is Cⁿ at every joint",
    [0.0; 3],
)
.with_kind(ParamKind::Integer {
    default: 2,
    min: 1,
    max: MAX_BLEND_ORDER as u64,
});

pub(crate) static METHOD: Method = Method {
    id: "arc-blend",
    type_name: "ArcBlend",
    summary: "Pobegailo's interpolating Cⁿ spline blending circle arcs",
    continuity: "Cⁿ (n = order ≤ 10)",
    source: "Pobegailo (2019), ch. 7–9: §8.4 Algorithm 8.1 (S²), §9.4 Algorithm 9.1 (S³)",
    spheres: Spheres::All,
    knots: KnotRule::Computed,
    min_points: 3,
    interpolates: true,
    single_piece: false,
    params: &[ORDER],
    build,
};

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let order = input.params.integer("order")?;
    input.params.finish()?;
    Ok(on_every_sphere!(input.points, |p| {
        let curve = ArcBlend::try_new(p.clone(), order)?;
        let knots = curve.knots().to_vec();
        Built::new(curve, p)
            .with_info("knots", json!(knots))
            .with_order(order)
    }))
}
