// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `BuiltCurve::sample_field` gives the numbers of `Scene::sample_json`, field by field.

use serde_json::Value;
use spherekit_scene::{SAMPLE_FIELDS, Scene};

/// A field of one curve's JSON samples, rows flattened.
fn flattened(curve: &Value, field: &str) -> Vec<f64> {
    let mut out = Vec::new();
    for row in curve
        .get(field)
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
    {
        match row {
            Value::Array(xs) => out.extend(xs.iter().map(|x| x.as_f64().expect("number"))),
            x => out.push(x.as_f64().expect("number")),
        }
    }
    out
}

#[test]
fn every_field_of_every_space_equals_the_json() {
    let scenes = [
        r#"{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1],[1,1,1]],"samples":7}"#,
        r#"{"space":"S3","method":"bspline-kim","samples":9,
            "points":[[1,0,0,0],[0.9239,0,0,0.3827],[0.7071,0.5,0.5,0],[0.5,-0.5,0.5,0.5]]}"#,
        r#"{"space":"S4","method":"catmull-rom","eval_at":[0,0.5,1,2.5],
            "points":[[1,0,0,0,0],[0,1,0,0,0],[0,0,1,0,0],[0,0,0,1,0]]}"#,
        r#"{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]]},
            {"method":"bezier","points":[[1,0,0],[0,1,0],[0,0,1]]}]}"#,
    ];
    for text in scenes {
        let scene = Scene::from_json(text).expect("valid scene");
        let curves = scene.build().expect("builds");
        // Points come from `eval_many` without derivatives and from `jet_many` with them
        // (equal to rounding); `sample_field` gives the former.
        for deriv in [false, true] {
            let json = scene.sample_json(&curves, deriv);
            let listed: Vec<&Value> = match json.get("curves") {
                Some(Value::Array(list)) => list.iter().collect(),
                _ => vec![&json],
            };
            assert_eq!(listed.len(), curves.len());
            for (curve, one) in curves.iter().zip(listed) {
                for field in SAMPLE_FIELDS {
                    let with_deriv = !matches!(field, "t" | "points" | "controls" | "auxiliary");
                    if field != "domain" && with_deriv != deriv {
                        continue;
                    }
                    let got = curve.sample_field(&scene, field).expect("a sample field");
                    assert_eq!(got, flattened(one, field), "{text}: {field}");
                }
                assert!(curve.sample_field(&scene, "info").is_none());
            }
        }
    }
}
