// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `arc-blend`: [`spherekit::ArcBlend`].

use serde_json::json;
use spherekit::{ArcBlend, ArcBlendTiming, MAX_SMOOTHNESS};

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::params::Param;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

/// The smoothness `n` of Pobegailo's blends (formerly `order`, a name that Python's
/// `curve(t, order)`, the derivative order, also uses).
pub(crate) const SMOOTHNESS: Param = Param::integer(
    "smoothness",
    "smoothness n",
    "the curve is Cⁿ at every joint",
    [2, 1, MAX_SMOOTHNESS as u64],
)
.formerly("order");

pub(crate) static METHOD: Method = Method {
    id: "arc-blend",
    name: "Arc blend",
    type_name: "ArcBlend",
    summary: "Pobegailo's interpolating Cⁿ spline blending circle arcs",
    continuity: "Cⁿ (n = smoothness ≤ 10)",
    source: "Pobegailo (2019), ch. 7–9: §8.4 Algorithm 8.1 (S²), §9.4 Algorithm 9.1 (S³)",
    spaces: Spaces::All,
    knots: KnotRule::Computed,
    min_points: 3,
    interpolates: true,
    single_piece: false,
    closes: true,
    params: &[
        SMOOTHNESS,
        Param::choice(
            "timing",
            "timing",
            "the parameter: the book's knots while representable, else arc length (auto); the book's knots or an error (closed: only where they close the loop); the mean arc lengths; uniform. Every timing traces the same curve, Cⁿ in t",
            &["auto", "book", "arc-length", "uniform"],
        ),
    ],
    build,
};

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let smoothness = input.params.integer("smoothness")?;
    let timing = match input.params.choice("timing")? {
        "book" => ArcBlendTiming::Book,
        "arc-length" => ArcBlendTiming::ArcLength,
        "uniform" => ArcBlendTiming::Uniform,
        _ => ArcBlendTiming::Auto,
    };
    input.params.finish()?;
    let closed = input.closed;
    let (knots, used);
    let built = on_every_sphere!(input.points, |p| {
        let curve = if closed {
            ArcBlend::try_with_closed(p.clone(), smoothness, timing.clone())?
        } else {
            ArcBlend::try_with(p.clone(), smoothness, timing.clone())?
        };
        knots = curve.knots().to_vec();
        used = curve.timing().name();
        Built::new(curve, p)
    });
    let built = built
        .with_info("knots", json!(knots))
        .with_order(smoothness);
    // `info.timing` says when the curve is not on the book's knots (auto switched away from
    // them, or another timing was asked for).
    Ok(if used == "book" {
        built
    } else {
        built.with_info("timing", json!(used))
    })
}
