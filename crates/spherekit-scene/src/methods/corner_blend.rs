// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `corner-blend`: [`spherekit::CornerBlend`] (S² and S^m) and [`spherekit::CornerBlendS3`].

use serde_json::json;
use spherekit::{CornerBlend, CornerBlendS3, DEFAULT_CORNER_FRACTION};

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::params::Param;
use crate::registry::{KnotRule, Method, Spheres};
use crate::scene::{Input, Points};

pub(crate) static METHOD: Method = Method {
    id: "corner-blend",
    type_name: "CornerBlend",
    summary: "Pobegailo's corner smoothing of a great-circle polyline",
    continuity: "Cⁿ (n = order ≤ 10)",
    source: "Pobegailo (2019), §8.5–8.8 (S²) and §9.5–9.8 (S³)",
    spheres: Spheres::All,
    knots: KnotRule::Computed,
    min_points: 3,
    interpolates: false,
    single_piece: false,
    closes: true,
    params: &[
        super::arc_blend::ORDER,
        Param::number(
            "fraction",
            "fraction",
            "how far along each edge (as a fraction of it, at most 0.5) the corner blend starts",
            [DEFAULT_CORNER_FRACTION, 0.02, 0.5],
        ),
    ],
    build,
};

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let order = input.params.integer("order")?;
    let fraction = input.params.number("fraction")?;
    input.params.finish()?;
    let closed = input.closed;
    if let Points::S3(keys) = input.points {
        // The book's orientation construction (rotations act by left multiplication).
        let curve = if closed {
            CornerBlendS3::try_new_closed(keys.clone(), order, fraction)?
        } else {
            CornerBlendS3::try_new(keys.clone(), order, fraction)?
        };
        let knots = curve.knots().to_vec();
        return Ok(BuiltCurve::S3(
            Built::new(curve, keys)
                .with_info("knots", json!(knots))
                .with_order(order),
        ));
    }
    Ok(on_every_sphere!(input.points, |p| {
        let curve = if closed {
            CornerBlend::try_new_closed(p.clone(), order, fraction)?
        } else {
            CornerBlend::try_new(p.clone(), order, fraction)?
        };
        let knots = curve.knots().to_vec();
        Built::new(curve, p)
            .with_info("knots", json!(knots))
            .with_order(order)
    }))
}
