// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `beta`: [`spherekit::BetaSpline`].

use serde_json::json;
use spherekit::{BetaParams, BetaSolver, BetaSpline, ShapeParam};

use crate::built::{Built, BuiltCurve, on_every_sphere};
use crate::error::SceneError;
use crate::params::{NumberOrList, Param, Params};
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::Input;

pub(crate) static METHOD: Method = Method {
    id: "beta",
    name: "Beta spline",
    type_name: "BetaSpline",
    summary: "spherical Beta spline with bias β₁ and tension β₂, interpolating by a Newton solver",
    continuity: "G¹ (C¹ at β₁ = 1)",
    source: "the spherical cubic Beta spline on S^m with shape parameters β₁, β₂ (after Barsky's Beta-splines)",
    spaces: Spaces::All,
    knots: KnotRule::None,
    min_points: 2,
    interpolates: true,
    single_piece: false,
    closes: true,
    params: &[
        Param::number(
            "beta1",
            "β₁ bias",
            "bias β₁ > 0 (one for every point, or one for all)",
            [1.0, 0.1, 4.0],
        )
        .per_joint(0, 0),
        Param::number(
            "beta2",
            "β₂ tension",
            "tension β₂ ≥ 0 (one for every point, or one for all)",
            [0.0, 0.0, 20.0],
        )
        .per_joint(0, 0),
        Param::boolean(
            "interpolate",
            "interpolate",
            "solve for the control vertices so that the curve passes through the points",
            true,
        ),
        Param::choice(
            "solver",
            "solver",
            "the interpolation solver: Newton's method or the paper's Jacobi-style iteration",
            &["newton", "jacobi"],
        ),
        Param::number(
            "tolerance",
            "tolerance",
            "the solver's step tolerance (radians; absent: the solver's own)",
            [f64::NAN, 0.0, 0.0],
        )
        .advanced(),
        Param::number(
            "residual_tolerance",
            "residual tolerance",
            "the largest distance (radians) from the curve to a point the solve accepts (absent: the solver's own)",
            [f64::NAN, 0.0, 0.0],
        )
        .advanced(),
        Param::integer(
            "max_iterations",
            "max iterations",
            "the solver's iteration limit (absent: the solver's own)",
            [0, 1, 1_000_000],
        )
        .advanced(),
    ],
    build,
};

fn shape(params: &mut Params<'_>, name: &'static str) -> Result<ShapeParam, SceneError> {
    Ok(match params.number_or_list(name)? {
        NumberOrList::One(x) => ShapeParam::Constant(x),
        NumberOrList::List(v) => ShapeParam::PerPoint(v),
    })
}

fn build(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let params = &mut input.params;
    let beta = BetaParams {
        beta1: shape(params, "beta1")?,
        beta2: shape(params, "beta2")?,
        interpolate: params.boolean("interpolate")?,
        solver: BetaSolver::from_name(params.choice("solver")?).unwrap_or_default(),
        tolerance: params.positive("tolerance")?,
        residual_tolerance: params.positive("residual_tolerance")?,
        max_iterations: params.optional_integer("max_iterations")?,
    };
    input.params.finish()?;
    let closed = input.closed;
    let solved;
    let built = on_every_sphere!(input.points, |p| {
        let curve = if closed {
            BetaSpline::try_new_closed(p.clone(), &beta)?
        } else {
            BetaSpline::try_new(p.clone(), &beta)?
        };
        solved = curve.solve_info();
        let (controls, auxiliary) = (curve.controls().to_vec(), curve.auxiliary().to_vec());
        let mut built = Built::new(curve, p).with_controls(controls);
        built.auxiliary = auxiliary;
        built
    });
    Ok(match solved {
        Some(info) => built
            .with_info("solver", json!(info.solver.name()))
            .with_info("iterations", json!(info.iterations))
            .with_info("residual", json!(info.residual)),
        None => built,
    })
}
