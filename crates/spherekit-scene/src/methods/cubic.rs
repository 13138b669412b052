// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `cubic`: [`spherekit::CubicSpline`], the C² spline through keys at given times.

use serde_json::json;
use spherekit::glam::DVec3;
use spherekit::{Ambient, CubicEnd, CubicSpline, SplineError, UnitQuat};

use crate::built::{Built, BuiltCurve, ScenePoint, on_every_sphere};
use crate::error::{SceneError, field_error};
use crate::params::Param;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::{Input, Points};

pub(crate) static METHOD: Method = Method {
    id: "cubic",
    name: "Cubic spline",
    type_name: "CubicSpline",
    summary: "C² cubic spline through the points (keys) at their times",
    continuity: "C²",
    source: "cubic in the tangent space of each key, as scipy.spatial.transform.RotationSpline (Virtanen et al. 2020)",
    spaces: Spaces::All,
    knots: KnotRule::PerPoint { skip: 0 },
    min_points: 2,
    interpolates: true,
    single_piece: false,
    closes: true,
    params: &[
        Param::choice(
            "end",
            "end",
            "end condition: natural (zero angular acceleration), clamped (given end velocities) or scipy's (mean rates of the end segments)",
            &["natural", "clamped", "scipy"],
        )
        .open_only(),
        Param::vector(
            "start_velocity",
            "start velocity",
            "with end \"clamped\": S3 the angular velocity [x, y, z] at the first key (in params.frame), elsewhere a tangent vector there",
        )
        .requires("end", "clamped")
        .open_only(),
        Param::vector(
            "end_velocity",
            "end velocity",
            "with end \"clamped\": the same at the last key",
        )
        .requires("end", "clamped")
        .open_only(),
        Param::choice(
            "frame",
            "frame",
            "S3: the frame of the clamped angular velocities, space (ω = 2q′q̄) or body (2q̄q′, scipy's)",
            &["space", "body"],
        )
        .s3_only()
        .requires("end", "clamped")
        .open_only(),
    ],
    build,
};

/// An angular velocity `[x, y, z]`.
fn angular(name: &str, v: &[f64]) -> Result<DVec3, SceneError> {
    match v {
        &[x, y, z] => Ok(DVec3::new(x, y, z)),
        _ => Err(field_error(
            format!("params.{name}"),
            format!(
                "must be an angular velocity [x, y, z], got {} numbers",
                v.len()
            ),
        )),
    }
}

/// A tangent vector in scene coordinates, of the dimension of `points` (checked here, so that a
/// wrong count is the same error on S^m as on S² and S³, where the wasm build also builds on
/// S^m).
fn tangent_of<P: ScenePoint>(points: &[P], name: &str, v: &[f64]) -> Result<P::Vector, SceneError> {
    let dim = points.first().map_or(0, |p| p.to_vector().dim());
    P::vector_from_coords(v)
        .filter(|t| t.dim() == dim)
        .ok_or_else(|| {
            field_error(
                format!("params.{name}"),
                format!("has {} numbers, not a vector of this sphere", v.len()),
            )
        })
}

fn build(input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    build_curve(input).map_err(|e| match e {
        SceneError::Spline(SplineError::Solve(e)) => field_error(
            "points",
            format!(
                "the C² spline could not be solved ({e}): consecutive keys nearly antipodal, or time spacings of very different sizes"
            ),
        ),
        e => e,
    })
}

fn build_curve(mut input: Input<'_>) -> Result<BuiltCurve, SceneError> {
    let end = input.params.choice("end")?;
    let start = input.params.vector("start_velocity")?;
    let stop = input.params.vector("end_velocity")?;
    let body = match input.points {
        Points::S3(_) => input.params.choice("frame")? == "body",
        _ => false,
    };
    input.params.finish()?;
    let clamped = match (end, start, stop) {
        ("clamped", Some(a), Some(b)) => Some((a, b)),
        ("clamped", a, _) => {
            let name = if a.is_none() {
                "start_velocity"
            } else {
                "end_velocity"
            };
            return Err(field_error(
                format!("params.{name}"),
                "is needed with \"end\": \"clamped\"",
            ));
        }
        (_, Some(_), _) => {
            return Err(field_error(
                "params.start_velocity",
                "applies with \"end\": \"clamped\" only",
            ));
        }
        (_, _, Some(_)) => {
            return Err(field_error(
                "params.end_velocity",
                "applies with \"end\": \"clamped\" only",
            ));
        }
        _ => None,
    };
    let (knots, closed) = (input.knots, input.closed);
    if let Points::S3(keys) = &input.points
        && let Some((a, b)) = &clamped
    {
        let (first, last) = (keys[0], keys[keys.len() - 1]);
        let (a, b) = (angular("start_velocity", a)?, angular("end_velocity", b)?);
        let end = if body {
            CubicEnd::clamped_angular_body(first, a, last, b)
        } else {
            CubicEnd::clamped_angular(first, a, last, b)
        };
        let curve = CubicSpline::<UnitQuat>::try_new(keys.clone(), knots, end, closed)?;
        return Ok(BuiltCurve::S3(finish(curve, keys.clone())));
    }
    Ok(on_every_sphere!(input.points, |p| {
        let end = match (end, &clamped) {
            ("scipy", _) => CubicEnd::Scipy,
            (_, Some((a, b))) => CubicEnd::Clamped {
                start_velocity: tangent_of(&p, "start_velocity", a)?,
                end_velocity: tangent_of(&p, "end_velocity", b)?,
            },
            _ => CubicEnd::Natural,
        };
        finish(CubicSpline::try_new(p.clone(), knots, end, closed)?, p)
    }))
}

pub(crate) fn finish<P: ScenePoint>(curve: CubicSpline<P>, points: Vec<P>) -> Built<P> {
    let info = curve.solve_info();
    let knots = curve.knots().to_vec();
    Built::new(curve, points)
        .with_info("knots", json!(knots))
        .with_info("iterations", json!(info.iterations))
        .with_info("residual", json!(info.residual))
        .with_order(2)
}
