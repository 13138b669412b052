// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `corner-blend`: [`spherekit::CornerBlend`] (S² and S^m) and [`spherekit::CornerBlendRotations`].

use serde_json::json;
use spherekit::{
    CornerBlend, CornerBlendRotations, CornerCuts, CornerTiming, DEFAULT_CORNER_FRACTION,
};

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::params::{NumberOrList, Param, Params};
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::{Input, Points};

pub(crate) static METHOD: Method = Method {
    id: "corner-blend",
    name: "Corner blend",
    type_name: "CornerBlend",
    summary: "Pobegailo's corner smoothing of a polyline of great-circle (S2: or small-circle) arcs",
    continuity: "Cⁿ (n = smoothness ≤ 10)",
    source: "Pobegailo (2019), §8.5–8.8 (S²) and §9.5–9.8 (S³)",
    spaces: Spaces::All,
    knots: KnotRule::Computed,
    min_points: 3,
    interpolates: false,
    single_piece: false,
    closes: true,
    params: &[
        super::arc_blend::SMOOTHNESS,
        Param::number(
            "fraction",
            "fraction",
            "how far back along the edges each corner blend starts, as a fraction of the edge (one number at most 0.5, or one per corner); with fraction_out, the edge before the corner",
            [DEFAULT_CORNER_FRACTION, 0.02, 0.5],
        )
        .per_joint(1, 1),
        Param::number(
            "fraction_out",
            "fraction out",
            "the part of the edge after each corner that its blend replaces (one number or one per corner; absent: as fraction)",
            [f64::NAN, 0.02, 0.98],
        )
        .per_joint(1, 1)
        .advanced(),
        Param::number(
            "start",
            "start",
            "the parameter t at the first point",
            [0.0, -10.0, 10.0],
        )
        .advanced(),
        Param::number(
            "speed",
            "speed",
            "the angular speed on the first edge (later edges follow from the cuts: ×β/α at each corner)",
            [1.0, 0.1, 10.0],
        ),
        Param::number(
            "bend",
            "bend",
            "S2: each edge's circle through its two points, from −1 to 1 (0: the great arc; > 0 bows it to the right of travel), one number or one per edge",
            [0.0, -0.95, 0.95],
        )
        .s2_only(),
    ],
    build,
};

/// The cuts from `fraction` and `fraction_out`.
fn cuts(params: &mut Params<'_>) -> Result<CornerCuts, SceneError> {
    let incoming = params.number_or_list("fraction")?;
    let outgoing = params.number_or_list("fraction_out")?;
    Ok(match (incoming, outgoing) {
        (NumberOrList::One(f), NumberOrList::One(g)) if g.is_nan() => CornerCuts::Uniform(f),
        (NumberOrList::List(v), NumberOrList::One(g)) if g.is_nan() => CornerCuts::PerCorner(v),
        (i, o) => {
            // Pairs: a single number stands for every corner.
            let len = match (&i, &o) {
                (NumberOrList::List(v), _) | (_, NumberOrList::List(v)) => v.len(),
                _ => 1,
            };
            let at = |x: &NumberOrList, j: usize| match x {
                NumberOrList::One(f) => *f,
                NumberOrList::List(v) => v.get(j).copied().unwrap_or(f64::NAN),
            };
            if let (NumberOrList::List(a), NumberOrList::List(b)) = (&i, &o)
                && a.len() != b.len()
            {
                return Err(crate::error::field_error(
                    "params.fraction_out",
                    format!(
                        "has {} entries but fraction has {}: one per corner each",
                        b.len(),
                        a.len()
                    ),
                ));
            }
            CornerCuts::Pairs((0..len).map(|j| [at(&i, j), at(&o, j)]).collect())
        }
    })
}

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let smoothness = input.params.integer("smoothness")?;
    let mut cuts = cuts(&mut input.params)?;
    let timing = CornerTiming {
        start: input.params.number("start")?,
        speed: input.params.number("speed")?,
    };
    let count = match &input.points {
        Points::S2(p) => p.len(),
        Points::S3(p) => p.len(),
        Points::Sm(p) => p.len(),
    };
    // A closed polygon has a corner at every point and an edge after every point.
    let closed = input.closed;
    let (corners, edges) = if closed {
        (count, count)
    } else {
        (count.saturating_sub(2), count.saturating_sub(1))
    };
    let bends = match input.points {
        Points::S2(_) => match input.params.number_or_list("bend")? {
            NumberOrList::One(0.0) => None,
            NumberOrList::One(b) => Some(vec![b; edges]),
            NumberOrList::List(v) => Some(v),
        },
        _ => None,
    };
    input.params.finish()?;
    // One number for every corner, once the number of corners is known.
    if let CornerCuts::Pairs(pairs) = &mut cuts
        && pairs.len() == 1
    {
        *pairs = vec![pairs[0]; corners];
    }
    let knots;
    let built = match input.points {
        Points::S3(keys) => {
            // The book's orientation construction (rotations act by left multiplication).
            let curve = if closed {
                CornerBlendRotations::try_with_closed(keys.clone(), smoothness, &cuts, timing)?
            } else {
                CornerBlendRotations::try_with(keys.clone(), smoothness, &cuts, timing)?
            };
            knots = curve.knots().to_vec();
            BuiltCurve::S3(Built::new(curve, keys))
        }
        Points::S2(p) if bends.is_some() => {
            let bends = bends.unwrap_or_default();
            let curve = if closed {
                CornerBlend::try_with_arcs_closed(p.clone(), smoothness, &cuts, timing, &bends)?
            } else {
                CornerBlend::try_with_arcs(p.clone(), smoothness, &cuts, timing, &bends)?
            };
            knots = curve.knots().to_vec();
            BuiltCurve::S2(Built::new(curve, p))
        }
        points => on_every_sphere!(points, |p| {
            let curve = if closed {
                CornerBlend::try_with_closed(p.clone(), smoothness, &cuts, timing)?
            } else {
                CornerBlend::try_with(p.clone(), smoothness, &cuts, timing)?
            };
            knots = curve.knots().to_vec();
            Built::new(curve, p)
        }),
    };
    Ok(built
        .with_info("knots", json!(knots))
        .with_order(smoothness))
}
