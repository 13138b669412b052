// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `gamma`: [`spherekit::GammaSpline`].

use serde_json::Value;
use spherekit::{GammaSpline, Gammas, LastEdge};

use crate::built::{Built, BuiltCurve};
use crate::error::SceneError;
use crate::params::{NumberOrList, Param};
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "gamma",
    name: "Gamma spline",
    type_name: "GammaSpline",
    summary: "Gamma quaternion spline (Boehm's Gamma spline on S³)",
    continuity: "C¹ (C² under a condition on γ and the knots)",
    source: "Boehm (1985), Curvature continuous curves and surfaces; lifted to S³ with Kim, Kim & Shin's cumulative cubic Bézier segments",
    spaces: Spaces::S3,
    knots: KnotRule::PerPoint { skip: 1 },
    min_points: 4,
    interpolates: false,
    single_piece: false,
    closes: true,
    params: &[
        Param::number(
            "gamma",
            "γ",
            "the Gamma spline's shape parameters γᵢ > 0 (one for every inner joint, closed: for every point; or one for all)",
            [1.0, 0.05, 4.0],
        )
        .per_joint(2, 1),
        Param::choice(
            "last_edge",
            "last edge",
            "the last control edge by the paper's formula, or as its worked example computes it",
            &["formula", "paper-example"],
        ),
    ],
    build,
};

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let keys = super::s3_keys(&input)?;
    let gamma = match input.params.number_or_list("gamma")? {
        NumberOrList::One(x) => Gammas::All(x),
        NumberOrList::List(v) => Gammas::Each(v),
    };
    let last_edge = LastEdge::from_name(input.params.choice("last_edge")?)?;
    input.params.finish()?;
    let curve = if input.closed {
        GammaSpline::try_new_closed(keys.clone(), input.knots, gamma)?
    } else {
        GammaSpline::try_new(keys.clone(), input.knots, gamma, last_edge)?
    };
    let controls = curve.controls().to_vec();
    let report = curve.joint_report();
    Ok(BuiltCurve::S3(
        Built::new(curve, keys)
            .with_controls(controls)
            .with_info(
                "joints",
                serde_json::to_value(report).unwrap_or(Value::Null),
            )
            .with_order(1),
    ))
}
