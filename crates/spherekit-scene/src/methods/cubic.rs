// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `cubic`: [`spherekit::CubicSpline`], the C² spline through keys at given times, or with
//! `params.velocities` the C¹ cubic Hermite spline through keys with a velocity at each
//! ([`CubicSpline::try_hermite`]).

use serde_json::json;
use spherekit::glam::DVec3;
use spherekit::{
    Ambient, CubicEnd, CubicSpline, SplineError, UnitQuat, velocity_from_angular,
    velocity_from_angular_body,
};

use crate::built::{Built, BuiltCurve, ScenePoint, on_every_sphere};
use crate::error::{SceneError, field_error};
use crate::params::Param;
use crate::registry::{KnotRule, Method, Spaces};
use crate::scene::{Input, Points};

pub(crate) static METHOD: Method = Method {
    id: "cubic",
    name: "Cubic spline",
    type_name: "CubicSpline",
    summary: "C² cubic spline through the points (keys) at their times; with params.velocities, C¹ through each key with its velocity (Hermite)",
    continuity: "C² (C¹ with params.velocities)",
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
        Param::vectors(
            "velocities",
            "key velocities",
            "a velocity at every point (key), one per point: S3 the angular velocity [x, y, z] (in params.frame), elsewhere a tangent vector; the curve is then C¹, through each key with its velocity (end natural; open or closed)",
        )
        .advanced(),
        Param::choice(
            "frame",
            "frame",
            "S3: the frame of the angular velocities (params.velocities, or the clamped end velocities), space (ω = 2q′q̄) or body (2q̄q′, scipy's)",
            &["space", "body"],
        )
        .s3_only(),
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
    let rates = input.params.vectors("velocities")?;
    let body = match input.points {
        Points::S3(_) => input.params.choice("frame")? == "body",
        _ => false,
    };
    input.params.finish()?;
    if let Some(rates) = rates {
        if end != "natural" || start.is_some() || stop.is_some() {
            return Err(field_error(
                "params.velocities",
                "gives the velocity at every key, the ends' too: it takes no \"end\" other than natural and no start_velocity or end_velocity",
            ));
        }
        return hermite(input.points, input.knots, input.closed, &rates, body);
    }
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
        return Ok(BuiltCurve::S3(finish(curve, keys.clone(), 2)));
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
        finish(CubicSpline::try_new(p.clone(), knots, end, closed)?, p, 2)
    }))
}

/// The Hermite spline of `params.velocities` (`rates`, one velocity per key): on S³ angular
/// velocities in the frame `body` or space, converted at each key as the curve takes it (so a
/// key whose sign canonicalisation flipped has its velocity negated with it: the angular
/// velocity is the rotation's, the same at `q` and `−q`); elsewhere tangent vectors.
fn hermite(
    points: Points,
    knots: Option<Vec<f64>>,
    closed: bool,
    rates: &[Vec<f64>],
    body: bool,
) -> Result<BuiltCurve, SceneError> {
    if let Points::S3(keys) = &points {
        let velocities = key_velocities(keys, rates, |name, q, w| {
            let w = angular(name, w)?;
            Ok(if body {
                velocity_from_angular_body(*q, w)
            } else {
                velocity_from_angular(*q, w)
            })
        })?;
        let curve = CubicSpline::try_hermite(keys.clone(), velocities, knots, closed)?;
        return Ok(BuiltCurve::S3(finish(curve, keys.clone(), 1)));
    }
    Ok(on_every_sphere!(points, |p| {
        let velocities = key_velocities(&p, rates, |name, _, v| tangent_of(&p, name, v))?;
        finish(
            CubicSpline::try_hermite(p.clone(), velocities, knots, closed)?,
            p,
            1,
        )
    }))
}

/// The velocity at every key from one entry of `rates` each (`velocity(name, key, entry)`,
/// `name` the entry's field), or an error on `params.velocities` for another count.
fn key_velocities<P, V>(
    keys: &[P],
    rates: &[Vec<f64>],
    velocity: impl Fn(&str, &P, &[f64]) -> Result<V, SceneError>,
) -> Result<Vec<V>, SceneError> {
    if rates.len() != keys.len() {
        return Err(field_error(
            "params.velocities",
            format!(
                "must have one velocity per point: expected {}, got {}",
                keys.len(),
                rates.len()
            ),
        ));
    }
    keys.iter()
        .zip(rates)
        .enumerate()
        .map(|(i, (key, v))| velocity(&format!("velocities[{i}]"), key, v))
        .collect()
}

/// The built curve with its knots and solve facts, C^`order` at its joints.
pub(crate) fn finish<P: ScenePoint>(
    curve: CubicSpline<P>,
    points: Vec<P>,
    order: usize,
) -> Built<P> {
    let info = curve.solve_info();
    let knots = curve.knots().to_vec();
    Built::new(curve, points)
        .with_info("knots", json!(knots))
        .with_info("iterations", json!(info.iterations))
        .with_info("residual", json!(info.residual))
        .with_order(order)
}
