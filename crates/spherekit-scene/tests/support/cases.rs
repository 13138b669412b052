// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Every registered method on every sphere it works on, with each choice of each parameter,
//! with and without knots, open and closed: the curves the batch and allocation tests loop
//! over. A new method is covered by its registry entry alone.

#![allow(dead_code, reason = "each includer uses a part")]

use serde_json::{Value, json};
use spherekit_scene::{BuiltCurve, METHODS, Method, ParamKind, Scene, Spaces};

/// `n` distinct points of `space` along a spiral (no two consecutive ones near antipodal).
pub(crate) fn points(space: &str, n: usize) -> Vec<Vec<f64>> {
    (0..n)
        .map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let a = 0.45 * i as f64;
            let (s, c) = a.sin_cos();
            match space {
                "S2" => vec![c, s, 0.4 * (0.7 * a).sin()],
                "S3" => vec![1.0, 0.4 * c, 0.4 * s, 0.3 * (0.5 * a).sin()],
                _ => vec![c, s, 0.2, 0.3 * (0.5 * a).sin(), 0.3, -0.2],
            }
        })
        .collect()
}

/// `n` points of `space` around a loop, for closed curves.
pub(crate) fn loop_points(space: &str, n: usize) -> Vec<Vec<f64>> {
    (0..n)
        .map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let a = core::f64::consts::TAU * (i as f64 + 0.15 * (i % 3) as f64) / n as f64;
            let (s, c) = a.sin_cos();
            match space {
                "S2" => vec![c, s, 1.1],
                "S3" => vec![1.0, 0.4 * c, 0.4 * s, 0.3 * (2.0 * a).sin()],
                _ => vec![c, s, 1.0, 0.3 * (2.0 * a).sin(), 0.3, -0.2],
            }
        })
        .collect()
}

/// The spheres a method is checked on.
pub(crate) fn spaces(m: &Method) -> &'static [&'static str] {
    match m.spaces {
        Spaces::All => &["S2", "S3", "S5"],
        Spaces::S3 => &["S3"],
        Spaces::S2 => &["S2"],
    }
}

/// Scene descriptions of every case: `(name, scene)`, `n` points each (single-piece methods
/// take 4).
pub(crate) fn scenes(n: usize) -> Vec<(String, Value)> {
    let mut out = Vec::new();
    for m in METHODS {
        for &space in spaces(m) {
            let count = if m.single_piece {
                4
            } else {
                n.max(m.min_points)
            };
            let base = json!({ "space": space, "method": m.id, "points": points(space, count) });
            out.push((format!("{} {space}", m.id), base.clone()));
            // The curve-level timing fields wrap every method's curve.
            for (field, value) in [("parametrization", "arclength"), ("extrapolate", "extend")] {
                let mut scene = base.clone();
                scene[field] = json!(value);
                out.push((format!("{} {space} {field}={value}", m.id), scene));
            }
            for p in m.params {
                if !p.spaces.contains(
                    Scene::from_json(&base.to_string())
                        .map_or(spherekit_scene::Space::S2, |s| s.space),
                ) {
                    continue;
                }
                let values: Vec<Value> = match p.kind {
                    ParamKind::Choice(choices) => choices[1..].iter().map(|c| json!(c)).collect(),
                    ParamKind::Bool { default } => vec![json!(!default)],
                    ParamKind::Integer { default, min, max } if default >= min => {
                        vec![json!((default + 1).min(max))]
                    }
                    _ => Vec::new(),
                };
                for v in values {
                    let mut scene = base.clone();
                    scene["params"] = json!({ p.name: v });
                    out.push((format!("{} {space} {}={v}", m.id, p.name), scene));
                }
            }
            if let Some(k) = m.knots.count(count) {
                let mut scene = base.clone();
                #[expect(clippy::cast_precision_loss, reason = "small counts")]
                let knots: Vec<f64> = (0..k)
                    .map(|i| i as f64 * 0.7 + 0.05 * (i * i) as f64)
                    .collect();
                scene["knots"] = json!(knots);
                out.push((format!("{} {space} knots", m.id), scene));
            }
            if m.closes {
                let mut scene = base.clone();
                scene["closed"] = json!(true);
                scene["points"] = json!(loop_points(space, count));
                out.push((format!("{} {space} closed", m.id), scene.clone()));
                if let Some(k) = m.knots.count_for(count, true) {
                    #[expect(clippy::cast_precision_loss, reason = "small counts")]
                    let knots: Vec<f64> = (0..k)
                        .map(|i| i as f64 * 0.7 + 0.05 * (i * i) as f64)
                        .collect();
                    scene["knots"] = json!(knots);
                    out.push((format!("{} {space} closed knots", m.id), scene));
                }
            }
        }
    }
    out
}

/// Every case built; a case the construction rejects is a failure of the test that asks.
pub(crate) fn built(n: usize) -> Vec<(String, Scene, Vec<BuiltCurve>)> {
    scenes(n)
        .into_iter()
        .filter_map(|(name, scene)| {
            // Parameter values the construction rejects for these points (a Beta solve that
            // cannot interpolate with another solver setting, say) are not batch cases.
            let scene = Scene::from_json(&scene.to_string()).ok()?;
            let curves = scene.build().ok()?;
            Some((name, scene, curves))
        })
        .collect()
}
