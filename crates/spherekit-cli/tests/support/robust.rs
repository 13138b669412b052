// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Robustness checks and the generator of valid-but-extreme scenes, shared by the test modules
//! `tests/it/robustness.rs` and `tests/it/robust_properties.rs` (arbtest, stable CI; declared once
//! in `tests/it/main.rs`) and the cargo-fuzz targets in `fuzz/` (which include this file by
//! path). The including module must provide `arb`, the `arbitrary` crate (`use arbtest::arbitrary as arb;` or `use arbitrary as arb;`).

#![allow(
    dead_code,
    unreachable_pub,
    reason = "each includer uses a different part of this shared module"
)]

use serde_json::{Map, Value, json};
use spherekit::{Ambient, Extrapolate, Side};
use spherekit_scene::{
    Built, BuiltCurve, METHODS, Method, ParamKind, SampleOptions, Sampling, Scene, ScenePoint,
    Space,
};

use super::arb::{Result as ArbResult, Unstructured};

/// How far from 1 the norm of a sampled point may be.
pub const UNIT_TOLERANCE: f64 = 1e-12;

/// Parameters every built curve is also evaluated at, besides the scene's own.
pub const EXTREME_PARAMS: [f64; 10] = [
    f64::NEG_INFINITY,
    -f64::MAX,
    -1e300,
    -1.0,
    -0.0,
    f64::MIN_POSITIVE,
    0.5,
    1e300,
    f64::MAX,
    f64::INFINITY,
];

/// What happened to a scene that did not break any rule.
#[derive(Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Built, sampled (and rendered when asked) with finite unit results.
    Ok,
    /// Rejected with this one-line message.
    Rejected(String),
}

/// Checks every sample of one built curve; returns the first problem.
fn check_built<P: ScenePoint>(
    scene: &Scene,
    policy: Extrapolate,
    b: &Built<P>,
) -> Result<(), String> {
    let [t0, t1] = b.curve.domain();
    if !(t0.is_finite() && t1.is_finite() && t0 < t1) {
        return Err(format!("bad domain [{t0}, {t1}]"));
    }
    let mut ts = scene.parameters([t0, t1]);
    ts.extend(b.curve.joints().iter().copied());
    ts.extend(EXTREME_PARAMS);
    // Just inside and just outside both ends.
    for t in [t0, t1] {
        let h = 1e-9 * t.abs().max(1.0);
        ts.extend([t.next_down(), t.next_up(), t - h, t + h]);
    }
    // The extrapolation policy: `hold` is the nearer end point at rest; under `error`, and at
    // ±∞ where `extend`, `cycle` and `segment` have no value, the jet is the one at the nearer
    // end (the curve's clamping); elsewhere the checks below (finite, unit) apply.
    for side in [Side::Left, Side::Right] {
        for (outside, end) in [
            (f64::NEG_INFINITY, t0),
            (t0 - 1.0, t0),
            (t0.next_down(), t0),
            (t1.next_up(), t1),
            (t1 + 1.0, t1),
            (f64::INFINITY, t1),
        ] {
            if (t0..=t1).contains(&outside) {
                continue; // t1 + 1 rounds to t1 for t1 ≥ 2⁵³
            }
            let a = b.curve.jet_at(outside, side);
            let same = if policy == Extrapolate::Hold {
                a.point.to_vector().to_vec() == b.curve.eval(end).to_vector().to_vec()
                    && a.velocity.to_vec().iter().all(|&x| x == 0.0)
                    && a.acceleration.to_vec().iter().all(|&x| x == 0.0)
            } else if policy == Extrapolate::Error || outside.is_infinite() {
                let e = b.curve.jet_at(end, side);
                a.point.to_vector().to_vec() == e.point.to_vector().to_vec()
                    && a.velocity.to_vec() == e.velocity.to_vec()
                    && a.acceleration.to_vec() == e.acceleration.to_vec()
            } else {
                true
            };
            if !same {
                return Err(format!(
                    "extrapolate {policy:?}: jet_at({outside}, {side:?}) is not the policy's value (end {end})"
                ));
            }
        }
    }
    for t in ts {
        for side in [Side::Left, Side::Right] {
            let jet = b.curve.jet_at(t, side);
            let p = jet.point.to_vector();
            let norm = p.length();
            if !p.is_finite() || (norm - 1.0).abs() > UNIT_TOLERANCE {
                return Err(format!(
                    "t = {t} ({side:?}): point {:?}, norm {norm}",
                    p.to_vec()
                ));
            }
            if !jet.velocity.is_finite() || !jet.acceleration.is_finite() {
                return Err(format!(
                    "t = {t} ({side:?}): velocity {:?}, acceleration {:?}",
                    jet.velocity.to_vec(),
                    jet.acceleration.to_vec()
                ));
            }
        }
        let p = b.curve.eval(t).to_vector();
        if !p.is_finite() || (p.length() - 1.0).abs() > UNIT_TOLERANCE {
            return Err(format!("eval({t}) = {:?}", p.to_vec()));
        }
    }
    Ok(())
}

fn all_finite(v: &Value) -> bool {
    match v {
        Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        Value::Array(a) => a.iter().all(all_finite),
        Value::Object(o) => o.values().all(all_finite),
        Value::Null => false,
        _ => true,
    }
}

fn one_line(message: String) -> Result<Outcome, String> {
    if message.is_empty() || message.contains('\n') {
        Err(format!("error message is not one line: {message:?}"))
    } else {
        Ok(Outcome::Rejected(message))
    }
}

/// Parses, builds, samples (with derivatives and continuity) and, when `render_size` is given
/// and the sphere can be drawn, renders a scene. `Err` means a rule was broken: a non-finite or
/// non-unit result, or an error message that is not one line. (A panic is a broken rule too;
/// callers catch it or let it crash.)
pub fn check_scene(text: &str, render_size: Option<u32>) -> Result<Outcome, String> {
    check_scene_capped(text, render_size, usize::MAX)
}

/// [`check_scene`] with at most `max_samples` sampling parameters (the fuzz targets bound the
/// work of one input this way).
pub fn check_scene_capped(
    text: &str,
    render_size: Option<u32>,
    max_samples: usize,
) -> Result<Outcome, String> {
    let mut scene = match Scene::from_json(text) {
        Ok(s) => s,
        Err(e) => return one_line(e.to_string()),
    };
    match &mut scene.sampling {
        Sampling::Uniform(n) if *n > max_samples => *n = max_samples.max(2),
        Sampling::At(ts) => ts.truncate(max_samples.max(1)),
        _ => {}
    }
    let curves = match scene.build() {
        Ok(c) => c,
        Err(e) => return one_line(e.to_string()),
    };
    for (spec, c) in scene.curves.iter().zip(&curves) {
        let policy = spec.extrapolate;
        match c {
            BuiltCurve::S2(b) => check_built(&scene, policy, b),
            BuiltCurve::S3(b) => check_built(&scene, policy, b),
            BuiltCurve::Sm(b) => check_built(&scene, policy, b),
        }?;
    }
    let json = scene.sample_json_with(
        &curves,
        SampleOptions {
            deriv: true,
            continuity: true,
            body_frame: false,
        },
    );
    if !all_finite(&json) {
        return Err("the sample output has a non-finite number".into());
    }
    if let Some(size) = render_size
        && matches!(scene.space, Space::S2 | Space::S3 | Space::Sm(1))
        && let Err(e) = spherekit_render::render_built(&scene, &curves, size)
    {
        // A bad `view` (read by the renderer only) is a rejection like any other.
        return one_line(e.to_string());
    }
    Ok(Outcome::Ok)
}

/// Values that stress shape parameters: tiny, ordinary and huge.
const SHAPE_VALUES: [f64; 9] = [1e-300, 1e-12, 1e-9, 1e-3, 0.5, 1.0, 10.0, 1e6, 1e12];

fn pick<T: Copy>(u: &mut Unstructured<'_>, from: &[T]) -> ArbResult<T> {
    Ok(*u.choose(from)?)
}

/// A coordinate in [−1, 1] with 1e-3 resolution.
fn coord(u: &mut Unstructured<'_>) -> ArbResult<f64> {
    Ok(f64::from(u.int_in_range(-1000_i32..=1000)?) / 1000.0)
}

fn normalized(v: Vec<f64>) -> Vec<f64> {
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if n > 0.0 && n.is_finite() {
        v.into_iter().map(|x| x / n).collect()
    } else {
        v
    }
}

/// A unit vector at angle `eps` from the unit vector `p`, towards a direction from `u`.
fn rotate_by(u: &mut Unstructured<'_>, p: &[f64], eps: f64) -> ArbResult<Vec<f64>> {
    let mut d: Vec<f64> = (0..p.len()).map(|_| coord(u)).collect::<ArbResult<_>>()?;
    let dot: f64 = d.iter().zip(p).map(|(a, b)| a * b).sum();
    for (di, pi) in d.iter_mut().zip(p) {
        *di -= dot * pi;
    }
    let d = normalized(d);
    let (s, c) = eps.sin_cos();
    Ok(p.iter().zip(&d).map(|(a, b)| c * a + s * b).collect())
}

/// A small angle 10^−k, k in 1 ..= 16.
fn tiny(u: &mut Unstructured<'_>) -> ArbResult<f64> {
    Ok(10f64.powi(-u.int_in_range(1_i32..=16)?))
}

/// A valid-but-extreme scene: points that repeat, nearly repeat, are (nearly) antipodal, lie on
/// one great circle or are scaled by 1e±300; extreme knot spacings and shape parameters; and
/// parameters far outside the domain. Most come out valid; the rest must be rejected cleanly.
pub fn extreme_scene(u: &mut Unstructured<'_>) -> ArbResult<Value> {
    let space = pick(u, &["S1", "S2", "S3", "S3", "S3", "S4"])?;
    let dim = match space {
        "S1" => 2,
        "S2" => 3,
        "S3" => 4,
        _ => 5,
    };
    let parsed = Space::parse(space).unwrap_or(Space::S2);
    let methods: Vec<&'static Method> = METHODS
        .iter()
        .copied()
        .filter(|m| m.spaces.contains(parsed))
        .collect();
    let method = pick(u, &methods)?;
    // Mostly enough points for every method (4); sometimes too few.
    let n = if u.ratio(1, 8)? {
        u.int_in_range(1_usize..=3)?
    } else {
        u.int_in_range(4_usize..=10)?
    };
    // Unit points; `scale` is applied to the written coordinates only (1e±300 tests the
    // normalisation on input).
    let mut units: Vec<Vec<f64>> = Vec::with_capacity(n);
    let mut points: Vec<Vec<f64>> = Vec::with_capacity(n);
    let first = (0..dim).map(|_| coord(u)).collect::<ArbResult<Vec<_>>>()?;
    // (All coordinates 0 gives a zero point, which must be rejected naming it.)
    units.push(normalized(first));
    while units.len() < n {
        let prev = units[units.len() - 1].clone();
        let next = match u.int_in_range(0_u8..=19)? {
            0 | 1 => normalized((0..dim).map(|_| coord(u)).collect::<ArbResult<_>>()?),
            2 | 3 => prev.clone(),
            4..=6 => {
                let eps = tiny(u)?;
                rotate_by(u, &prev, eps)?
            }
            7 => prev.iter().map(|x| -x).collect(),
            8 | 9 => {
                let eps = tiny(u)?;
                rotate_by(u, &prev, eps)?.iter().map(|x| -x).collect()
            }
            10 | 11 => {
                // Continue along the great circle through the last two points.
                if units.len() >= 2 {
                    let a = &units[units.len() - 2];
                    let d: f64 = a.iter().zip(&prev).map(|(x, y)| x * y).sum();
                    normalized(a.iter().zip(&prev).map(|(x, y)| 2.0 * d * y - x).collect())
                } else {
                    rotate_by(u, &prev, 0.5)?
                }
            }
            12 | 13 => {
                let angle = pick(u, &[std::f64::consts::FRAC_PI_2, 3.0, std::f64::consts::PI])?;
                let angle = angle - tiny(u)?;
                rotate_by(u, &prev, angle)?
            }
            _ => {
                let angle = f64::from(u.int_in_range(1_u8..=30)?) * 0.1;
                rotate_by(u, &prev, angle)?
            }
        };
        units.push(next);
    }
    for p in &units {
        let scale = if u.ratio(1, 10)? {
            pick(u, &[1e-300, 1e-150, 1e150, 1e300])?
        } else {
            1.0
        };
        points.push(p.iter().map(|x| x * scale).collect());
    }
    let mut scene = Map::new();
    scene.insert("space".into(), json!(space));
    scene.insert("method".into(), json!(method.id));
    scene.insert("points".into(), json!(points));
    if space == "S3" && u.ratio(1, 3)? {
        scene.insert("canonicalize".into(), json!(false));
    }
    // A closed loop, sometimes, for the methods that have one (its knots: one per point and
    // the time of the return).
    let closed = method.closes && u.ratio(1, 3)?;
    if closed {
        scene.insert("closed".into(), json!(true));
    }
    if let Some(count) = method.knots.count_for(n, closed)
        && u.ratio(1, 2)?
    {
        let mut t = pick(u, &[0.0, -1e6, 1e9, 1e-9])?;
        let mut knots = Vec::with_capacity(count);
        for _ in 0..count {
            knots.push(t);
            // Mostly 1e-6 … 1e6; sometimes up to and past the limits 1e-50 and 1e50.
            let range = if u.ratio(1, 8)? { -60..=60 } else { -6..=6 };
            t += 10f64.powi(u.int_in_range(range)?);
        }
        scene.insert("knots".into(), json!(knots));
    }
    // Each parameter of the method's schema, sometimes, at an extreme or ordinary value.
    let mut params = Map::new();
    for p in method.params {
        if p.advanced || !p.spaces.contains(parsed) || !u.ratio(2, 3)? {
            continue;
        }
        let value = match p.kind {
            ParamKind::Number { max, .. } if max <= 1.0 => {
                json!(pick(u, &[1e-12, 1e-6, 0.1, 0.25, 0.5, max])?)
            }
            ParamKind::Number { .. } => json!(pick(u, &SHAPE_VALUES)?),
            ParamKind::Integer { min, max, .. } => {
                let hi = max.min(min + 20);
                json!(u.int_in_range(min..=hi)?)
            }
            ParamKind::Bool { default } => json!(!default),
            ParamKind::Choice(choices) => json!(pick(u, choices)?),
            ParamKind::Vector => {
                let n = if parsed == Space::S3 { 3 } else { dim };
                json!((0..n).map(|_| coord(u)).collect::<ArbResult<Vec<_>>>()?)
            }
            // One vector per point (advanced, so not reached while the schema says so).
            ParamKind::Vectors => continue,
        };
        params.insert(p.name.into(), value);
    }
    if !params.is_empty() {
        scene.insert("params".into(), Value::Object(params));
    }
    // The curve-level timing fields, sometimes (any policy: `cycle` on an open curve and
    // `segment` off the cubic must be rejected naming the field).
    if u.ratio(1, 4)? {
        scene.insert("parametrization".into(), json!("arclength"));
    }
    if u.ratio(1, 3)? {
        let policy = pick(u, &spherekit_scene::EXTRAPOLATIONS)?;
        scene.insert("extrapolate".into(), json!(policy));
    }
    let m = u.int_in_range(1_usize..=6)?;
    let mut ts = Vec::with_capacity(m);
    for _ in 0..m {
        let t: f64 = if u.ratio(1, 2)? {
            u.arbitrary()?
        } else {
            pick(
                u,
                &[
                    -1e300, -1.0, -1e-12, 0.0, 1e-12, 0.5, 1.0, 2.0, 9.0, 1e9, 1e300,
                ],
            )?
        };
        ts.push(if t.is_finite() { t } else { 0.0 });
    }
    scene.insert("eval_at".into(), json!(ts));
    Ok(Value::Object(scene))
}
