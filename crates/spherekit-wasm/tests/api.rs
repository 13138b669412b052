// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! wasm-bindgen tests of the JS-facing API, run under node by `just test-wasm`.

#![cfg(target_arch = "wasm32")]

use spherekit_wasm::{
    Playground, continuity, methods, render_rgba, sample, sample_array, sample_at, validate,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

const S2: &str =
    r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0],[0,0,1]],"samples":5}"#;
const S3: &str = r#"{"space":"S3","method":"squad","points":[[1,0,0,0],[0.9239,0,0,0.3827],[0.7071,0.5,0.5,0],[0.5,-0.5,0.5,0.5]]}"#;

fn message(e: wasm_bindgen::JsError) -> String {
    let v: JsValue = e.into();
    js_sys::Reflect::get(&v, &"message".into())
        .ok()
        .and_then(|m| m.as_string())
        .unwrap_or_default()
}

#[wasm_bindgen_test]
fn methods_lists_every_method() {
    let list: serde_json::Value = serde_json::from_str(&methods()).unwrap();
    let ids: Vec<&str> = list
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["id"].as_str().unwrap())
        .collect();
    let expected: Vec<&str> = spherekit_scene::METHODS.iter().map(|m| m.id).collect();
    assert_eq!(ids, expected, "the same list as the registry");
    assert_eq!(
        list[0]["params"],
        serde_json::json!([]),
        "with the parameter schemas"
    );
}

#[wasm_bindgen_test]
fn sample_matches_the_cli_output() {
    let out: serde_json::Value = serde_json::from_str(&sample(S2, false, None).unwrap()).unwrap();
    let scene = spherekit_scene::Scene::from_json(S2).unwrap();
    assert_eq!(
        out,
        scene.sample_json(&scene.build().unwrap(), false),
        "same JSON as the CLI"
    );
    let points = sample_array(S2, 0, "points").unwrap();
    assert_eq!(points.len(), 15, "5 samples × 3 coordinates");
    let omega = sample_array(S3, 0, "angular_velocity").unwrap();
    assert_eq!(omega.len() % 3, 0, "rows of 3");
    assert!(!omega.is_empty(), "S3 has angular velocity");
}

#[wasm_bindgen_test]
fn the_playground_samples_its_built_curves_like_the_free_function() {
    let pg = Playground::new(S3).unwrap();
    for field in ["t", "points", "angular_velocity", "controls", "domain"] {
        assert_eq!(
            pg.sample_array(0, field).unwrap(),
            sample_array(S3, 0, field).unwrap(),
            "{field}"
        );
    }
    assert!(
        message(pg.sample_array(0, "speed").unwrap_err())
            .starts_with("field \"speed\" is not a sample field (t, points,"),
        "unknown field"
    );
    assert!(
        message(pg.sample_array(1, "t").unwrap_err()).contains("curves[1]"),
        "curve index"
    );
}

#[wasm_bindgen_test]
fn bad_input_gives_the_cli_message() {
    let bad = r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,0,0]]}"#;
    assert_eq!(
        message(validate(bad).unwrap_err()),
        "points[1] has zero length and cannot be normalised"
    );
    assert!(
        message(sample("{", false, None).unwrap_err()).starts_with("invalid scene JSON: "),
        "JSON error"
    );
    assert!(
        message(render_rgba(S2, 3).unwrap_err()).starts_with("size: 3 is outside"),
        "size error"
    );
    assert!(
        message(sample_array(S2, 4, "points").unwrap_err()).contains("curves[4]"),
        "curve index"
    );
}

#[wasm_bindgen_test]
fn sample_reports_body_frame_rates() {
    let space: serde_json::Value =
        serde_json::from_str(&sample(S3, true, Some("space".into())).unwrap()).unwrap();
    let body: serde_json::Value =
        serde_json::from_str(&sample(S3, true, Some("body".into())).unwrap()).unwrap();
    // Same speed, other components (the keys turn about different axes).
    let norm = |v: &serde_json::Value| {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap().powi(2))
            .sum::<f64>()
            .sqrt()
    };
    let (a, b) = (
        &space["angular_velocity"][40],
        &body["angular_velocity"][40],
    );
    assert!(
        (norm(a) - norm(b)).abs() < 1e-12,
        "|ω| is the same in both frames"
    );
    assert_ne!(a, b, "the components differ");
    assert!(
        message(sample(S3, true, Some("world".into())).unwrap_err()).starts_with("frame:"),
        "a bad frame is named"
    );
}

#[wasm_bindgen_test]
fn continuity_reports_the_joints() {
    let report: serde_json::Value = serde_json::from_str(&continuity(S2).unwrap()).unwrap();
    let joint = &report[0][0];
    assert_eq!(joint["t"], 1.0, "one interior joint");
    assert_eq!(joint["class"], "C⁰", "with a corner");
    // A Beta spline with bias β₁ ≠ 1 at a joint: the speed jumps, the direction does not.
    let beta = r#"{"space":"S2","method":"beta","points":[[1,0,0],[0.6,0.8,0],[0,0.6,0.8],[-0.6,0,0.8]],
        "params":{"beta1":[1,0.5,1,1]}}"#;
    let report: serde_json::Value = serde_json::from_str(&continuity(beta).unwrap()).unwrap();
    let classes: Vec<&str> = report[0]
        .as_array()
        .unwrap()
        .iter()
        .map(|j| j["class"].as_str().unwrap())
        .collect();
    assert_eq!(classes, ["G¹", "C¹"], "β₁ = 0.5 at t = 1, 1 at t = 2");
}

#[wasm_bindgen_test]
fn render_has_the_plot_strip_on_s3() {
    let rgba = render_rgba(S3, 64).unwrap();
    assert_eq!(rgba.len() % (64 * 4), 0, "whole rows, 64 wide");
    // The sphere's square, then the plot strip (a quarter of the size) and the legend.
    assert!(rgba.len() / (64 * 4) >= 64 + 16, "S3 has the plot strip");
    let s2 = render_rgba(S2, 64).unwrap();
    assert_eq!(s2.len(), 64 * 64 * 4, "one S2 curve: the sphere alone");
    assert!(rgba.chunks(4).all(|p| p[3] == 255), "opaque");
}

#[wasm_bindgen_test]
fn playground_rebuilds_only_what_changed() {
    let mut pg = Playground::new(S2).unwrap();
    assert_eq!(pg.builds(), 1, "built once");
    pg.render(128).unwrap();
    let first = pg.rgba();
    pg.set_view("camera", r#"{"yaw": 10, "pitch": 20}"#)
        .unwrap();
    assert_eq!(pg.builds(), 1, "a camera change does not rebuild");
    pg.render(128).unwrap();
    assert_ne!(pg.rgba(), first, "but re-renders");
    pg.set_point(0, 1, &[0.0, 1.0, 0.5]).unwrap();
    assert_eq!(pg.builds(), 2, "a point change rebuilds the curve");
    pg.add_curve("nlerp").unwrap();
    assert_eq!(pg.curve_count(), 2, "two curves");
    assert_eq!(pg.builds(), 3, "only the new curve is built");
    // A failed edit leaves everything as it was.
    let before = pg.scene_json();
    assert!(pg.set_point(1, 0, &[0.0, 0.0, 0.0]).is_err(), "zero point");
    assert!(pg.set_scene("{").is_err(), "not JSON");
    assert!(
        pg.set_point(0, 9, &[1.0, 0.0, 0.0]).is_err(),
        "no such point"
    );
    assert_eq!(pg.scene_json(), before, "unchanged");
    assert!(pg.remove_point(0, 0).is_ok(), "remove");
    assert_eq!(pg.point(0, 0).unwrap(), vec![0.0, 1.0, 0.5], "points shift");
}

#[wasm_bindgen_test]
fn adding_and_removing_points_keeps_knots_and_per_joint_lists_in_step() {
    let curve = |pg: &Playground| -> serde_json::Value {
        serde_json::from_str(&pg.curve_json(0).unwrap()).unwrap()
    };
    let numbers = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    // Catmull-Rom on S2: knots for c0..cn (the end points have none).
    let mut pg = Playground::new(
        r#"{"space":"S2","method":"catmull-rom","knots":[0,1,3],
            "points":[[1,0,0],[0.8,0.6,0],[0,1,0],[0,0.6,0.8],[0,0,1]]}"#,
    )
    .unwrap();
    pg.insert_point(0, 2, &[0.5, 0.8, 0.3]).unwrap();
    assert_eq!(numbers(&curve(&pg)["knots"]), vec![0.0, 0.5, 1.0, 3.0]);
    pg.insert_point(0, 6, &[0.3, 0.0, 1.0]).unwrap();
    assert_eq!(numbers(&curve(&pg)["knots"]), vec![0.0, 0.5, 1.0, 3.0, 5.0]);
    pg.remove_point(0, 2).unwrap();
    assert_eq!(numbers(&curve(&pg)["knots"]), vec![0.0, 1.0, 3.0, 5.0]);
    // Beta with per-point bias and tension: one value per point.
    let mut pg = Playground::new(
        r#"{"space":"S2","method":"beta","points":[[1,0,0],[0.6,0.8,0],[0,0.6,0.8]],
            "params":{"beta1":[1,0.5,2],"beta2":[0,3,0]}}"#,
    )
    .unwrap();
    pg.insert_point(0, 3, &[-0.6, 0.0, 0.8]).unwrap();
    let c = curve(&pg);
    assert_eq!(numbers(&c["params"]["beta1"]), vec![1.0, 0.5, 2.0, 2.0]);
    assert_eq!(numbers(&c["params"]["beta2"]), vec![0.0, 3.0, 0.0, 0.0]);
    pg.remove_point(0, 0).unwrap();
    assert_eq!(numbers(&curve(&pg)["params"]["beta1"]), vec![0.5, 2.0, 2.0]);
    // Gamma: knots u0..ul and γ1..γ(l-1) for l + 3 points.
    let mut pg = Playground::new(
        r#"{"space":"S3","method":"gamma","knots":[0,1,2,4],"params":{"gamma":[0.5,2]},
            "points":[[1,0,0,0],[0.9,0.3,0.3,0.1],[0.6,0.2,0.7,0.3],[0.3,0.8,0.4,0.3],
                      [0.2,0.3,0.5,0.8],[0.5,0.1,0.2,0.8]]}"#,
    )
    .unwrap();
    pg.insert_point(0, 6, &[0.1, 0.1, 0.1, 1.0]).unwrap();
    let c = curve(&pg);
    assert_eq!(numbers(&c["knots"]), vec![0.0, 1.0, 2.0, 4.0, 6.0]);
    assert_eq!(numbers(&c["params"]["gamma"]), vec![0.5, 2.0, 2.0]);
    pg.remove_point(0, 0).unwrap();
    assert_eq!(numbers(&curve(&pg)["params"]["gamma"]), vec![2.0, 2.0]);
    // Down to one interior knot and below: the list becomes one number, so points can be added
    // again.
    pg.remove_point(0, 0).unwrap();
    pg.remove_point(0, 0).unwrap();
    assert_eq!(curve(&pg)["params"]["gamma"], serde_json::json!(2.0));
    pg.insert_point(0, 0, &[1.0, 0.0, 0.0, 0.0]).unwrap();
    assert_eq!(curve(&pg)["points"].as_array().unwrap().len(), 5);
}

#[wasm_bindgen_test]
fn picking_and_dragging_use_the_render_projection() {
    let mut pg = Playground::new(S2).unwrap();
    let p = pg.point(0, 0).unwrap();
    let xy = pg.project(p[0], p[1], p[2], 200);
    if xy[2] >= 0.0 {
        assert_eq!(
            pg.pick(xy[0], xy[1], 200, 5.0),
            Some(vec![0, 0]),
            "picks the point"
        );
    }
    pg.pin_camera().unwrap();
    pg.move_point_to(0, 1, 100.0, 100.0, 200).unwrap();
    let q = pg.point(0, 1).unwrap();
    let c = pg.unproject(100.0, 100.0, 200);
    let d: f64 = q.iter().zip(&c).map(|(a, b)| (a - b).abs()).sum();
    assert!(d < 1e-12, "the point is under the pointer");
}

#[wasm_bindgen_test]
fn the_time_axis_eval_and_readout_use_the_curves_own_t() {
    let scene = r#"{"space":"S3","method":"squad","knots":[0,1,3,4],
        "points":[[1,0,0,0],[0.9239,0,0,0.3827],[0.7071,0.5,0.5,0],[0.5,-0.5,0.5,0.5]]}"#;
    let pg = Playground::new(scene).unwrap();
    assert_eq!(
        pg.time_axis(),
        vec![0.0, 4.0, 0.0],
        "t from 0 to the last knot"
    );
    // At a knot the curve passes through its key.
    let q = pg.eval(0, 3.0).unwrap();
    let key = [0.7071, 0.5, 0.5, 0.0];
    let dot: f64 = q[..4].iter().zip(key).map(|(a, b)| a * b).sum();
    assert!(
        (dot.abs() - 1.0).abs() < 1e-3,
        "eval at t = 3 is key 2: {q:?}"
    );
    // Outside the domain: clamped, never NaN.
    assert_eq!(
        pg.eval(0, 9.0).unwrap(),
        pg.eval(0, 4.0).unwrap(),
        "clamped"
    );
    assert!(
        pg.eval(0, f64::NAN).unwrap().iter().all(|x| x.is_finite()),
        "NaN is t0"
    );
    let r: serde_json::Value = serde_json::from_str(&pg.readout(0, 2.0, None).unwrap()).unwrap();
    assert_eq!(r["t"], 2.0);
    let omega: Vec<f64> = serde_json::from_value(r["omega"].clone()).unwrap();
    let speed = r["speed"].as_f64().unwrap();
    assert!(
        (omega.iter().map(|w| w * w).sum::<f64>().sqrt() - speed).abs() < 1e-12,
        "|ω|"
    );
    // The body frame: the same angular speed, ω turned by the orientation's inverse.
    let b: serde_json::Value =
        serde_json::from_str(&pg.readout(0, 2.0, Some("body".into())).unwrap()).unwrap();
    assert!(
        (b["speed"].as_f64().unwrap() - speed).abs() < 1e-12,
        "same |ω|"
    );
    assert_ne!(b["omega"], r["omega"], "another frame");
    // Against a central difference: |ω| is twice the rate of the quaternion's angle.
    let h = 1e-6;
    let q0 = pg.eval(0, 2.0 - h).unwrap();
    let q1 = pg.eval(0, 2.0 + h).unwrap();
    let angle = 2.0
        * (q0[..4]
            .iter()
            .zip(&q1[..4])
            .map(|(a, b)| a * b)
            .sum::<f64>())
        .abs()
        .min(1.0)
        .acos();
    assert!(
        (angle / (2.0 * h) - speed).abs() < 1e-4,
        "|ω| is the rate of turning"
    );
    assert!(
        pg.readout(0, 1.0, Some("world".into())).is_err(),
        "bad frame"
    );
    assert!(pg.readout(3, 1.0, None).is_err(), "no curve 3");
    // The normalized plot time: u from 0 to 1 over each curve.
    let mut pg = pg;
    pg.set_view("plot_time", r#""normalized""#).unwrap();
    assert_eq!(pg.time_axis(), vec![0.0, 1.0, 1.0]);
    let r: serde_json::Value = serde_json::from_str(&pg.readout(0, 0.75, None).unwrap()).unwrap();
    assert_eq!(r["t"], 3.0, "u = 0.75 is t = 3");
}

#[wasm_bindgen_test]
fn the_plot_axes_of_the_last_frame() {
    let mut pg = Playground::new(S3).unwrap();
    assert_eq!(pg.plot_axes(), "[]", "nothing rendered yet");
    pg.render(256).unwrap();
    let axes: serde_json::Value = serde_json::from_str(&pg.plot_axes()).unwrap();
    let a = &axes[0];
    let (left, right, top, bottom) = (
        a["left"].as_f64().unwrap(),
        a["right"].as_f64().unwrap(),
        a["top"].as_f64().unwrap(),
        a["bottom"].as_f64().unwrap(),
    );
    assert!(0.0 < left && left < right && right < 256.0, "{a}");
    assert!(256.0 < top && top < bottom, "under the sphere: {a}");
    assert_eq!((a["t0"].as_f64(), a["t1"].as_f64()), (Some(0.0), Some(3.0)));
    let mut s2 = Playground::new(S2).unwrap();
    s2.render(64).unwrap();
    assert_eq!(s2.plot_axes(), "[]", "no plot");
}

#[wasm_bindgen_test]
fn a_failed_beta_interpolation_reports_the_miss_distance() {
    let scene = r#"{"space":"S2","method":"beta","points":[[0.6296,-0.1171,-0.768],[-0.8142,-0.2856,0.5055],[-0.4037,0.6855,0.6059],[-0.7206,-0.5462,-0.427]],"params":{"beta1":1,"beta2":0}}"#;
    let mut pg = Playground::new(scene).unwrap();
    assert_eq!(pg.failure(), "null");
    let e = pg.set_param(0, "beta1", "1.5").unwrap_err();
    assert!(message(e).contains("did not converge"));
    let f: serde_json::Value = serde_json::from_str(&pg.failure()).unwrap();
    let miss = f["residual"].as_f64().unwrap();
    assert!(miss > 0.01 && miss < 3.2, "a miss in radians: {f}");
    assert!(f["iterations"].as_u64().unwrap() > 0);
    assert_eq!(f["curve"], serde_json::Value::Null, "one curve");
    // Another kind of failure, or a success, forgets it.
    assert!(pg.set_point(0, 1, &[0.0, 0.0, 0.0]).is_err());
    assert_eq!(pg.failure(), "null");
    pg.set_param(0, "interpolate", "false").unwrap();
    pg.set_param(0, "beta1", "1.5").unwrap();
    assert_eq!(
        pg.failure(),
        "null",
        "the approximating spline takes any β₁"
    );
}

#[wasm_bindgen_test]
fn view_options_fill_in_the_renderers_defaults() {
    let v = |scene: &str| -> serde_json::Value {
        serde_json::from_str(&Playground::new(scene).unwrap().view_options()).unwrap()
    };
    let s2 = v(S2);
    assert_eq!(s2["plot"], "none", "one S2 curve: no plot");
    assert_eq!(s2["legend"], false, "nor a legend");
    let s3 = v(S3);
    assert_eq!(
        (s3["plot"].as_str(), s3["legend"].as_bool()),
        (Some("speed"), Some(true)),
        "S3: both"
    );
    assert_eq!(
        s3["axes"],
        serde_json::json!(["x", "y", "z"]),
        "one S3 curve traces three axes"
    );
    let chosen = v(
        r#"{"space":"S3","method":"squad","points":[[1,0,0,0],[0,1,0,0]],
        "view":{"plot":"omega","legend":false,"axes":["z"],"frames":4,"omega_frame":"body"}}"#,
    );
    assert_eq!(
        chosen,
        serde_json::json!({"plot":"omega","legend":false,"axes":["z"],"frames":4,"omega_frame":"body"})
    );
    assert_eq!(
        s3["omega_frame"], "space",
        "ω in the space frame by default"
    );
}

#[wasm_bindgen_test]
fn the_text_floor_changes_the_layout_only_when_it_is_above_the_figures_text() {
    let scene = r#"{"space":"S3","method":"squad","points":[[1,0,0,0],[0.9,0.3,0.3,0],[0.7,0,0.7,0]],
        "view":{"plot":"omega"}}"#;
    let mut pg = Playground::new(scene).unwrap();
    let plain = pg.render(256).unwrap();
    pg.set_min_text(1.0);
    assert_eq!(
        pg.render(256).unwrap(),
        plain,
        "a floor under the figure's text changes nothing"
    );
    pg.set_min_text(22.0);
    assert!(
        pg.render(256).unwrap() > plain,
        "a higher floor makes the plots and legend taller"
    );
    pg.set_min_text(f32::NAN);
    assert_eq!(pg.render(256).unwrap(), plain, "NaN is no floor");
}

/// A scene of `method` on the first sphere it takes, with extra curve fields.
fn timing_scene(m: &spherekit_scene::Method, extra: &str) -> String {
    let s3 = m.spaces == spherekit_scene::Spaces::S3;
    // A loop goes around (a closed spline through an open path's points may not exist).
    let points = match (s3, extra.contains(r#""closed":true"#)) {
        (true, false) => {
            "[[1,0,0,0],[0.95,0.3,0,0],[0.9,0.3,0.3,0],[0.85,0.3,0.3,0.3],[0.8,0,0.4,0.4]]"
        }
        (false, false) => "[[1,0,0],[0.8,0.6,0],[0.6,0.6,0.5],[0.3,0.6,0.7],[0,0.6,0.8]]",
        (true, true) => {
            "[[1,0.4,0,0.1],[1,0.12,0.38,0],[1,-0.32,0.24,0.1],[1,-0.32,-0.24,0],[1,0.12,-0.38,0.1]]"
        }
        (false, true) => {
            "[[1,0,1.1],[0.31,0.95,1.1],[-0.81,0.59,1.1],[-0.81,-0.59,1.1],[0.31,-0.95,1.1]]"
        }
    };
    format!(
        r#"{{"space":"{}","method":"{}","points":{points}{extra}}}"#,
        if s3 { "S3" } else { "S2" },
        m.id
    )
}

fn finite(v: &serde_json::Value) -> bool {
    match v {
        serde_json::Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
        serde_json::Value::Array(a) => a.iter().all(finite),
        serde_json::Value::Object(o) => o.values().all(finite),
        _ => true,
    }
}

#[wasm_bindgen_test]
fn every_policy_on_every_method_at_the_probe_parameters() {
    for m in spherekit_scene::METHODS {
        let mut policies = vec!["hold", "extend", "error"];
        if m.closes {
            policies.push("cycle");
        }
        if m.id == "cubic" {
            policies.push("segment");
        }
        for policy in policies {
            let closed = if policy == "cycle" {
                r#","closed":true"#
            } else {
                ""
            };
            let scene = timing_scene(m, &format!(r#","extrapolate":"{policy}"{closed}"#));
            let [t0, t1] =
                <[f64; 2]>::try_from(sample_array(&scene, 0, "domain").unwrap()).unwrap();
            for t in [t0 - 1.0, t1 + 1.0, -1e300, 1e300] {
                let out = sample_at(&scene, &[t], true, None);
                let far = t.abs() == 1e300;
                match (policy, out) {
                    ("error", Err(e)) => {
                        let e = message(e);
                        assert!(
                            e.starts_with("eval_at[0]: ") && e.contains("outside the domain"),
                            "{}: {e}",
                            m.id
                        );
                    }
                    ("segment", Err(e)) if far => {
                        assert!(message(e).contains("overflows"), "{}", m.id);
                    }
                    ("hold" | "extend" | "cycle" | "segment", Ok(out)) => {
                        let out: serde_json::Value = serde_json::from_str(&out).unwrap();
                        assert!(
                            finite(&out["points"]) && finite(&out["velocity"]),
                            "{} {policy} at {t}",
                            m.id
                        );
                        if policy == "hold" {
                            let v = &out["velocity"][0];
                            assert!(
                                v.as_array()
                                    .unwrap()
                                    .iter()
                                    .all(|x| x.as_f64() == Some(0.0)),
                                "{} at rest",
                                m.id
                            );
                        }
                    }
                    (_, out) => panic!("{} {policy} at {t}: {:?}", m.id, out.map_err(message)),
                }
            }
            let e = message(sample_at(&scene, &[t0, f64::NAN], false, None).unwrap_err());
            assert_eq!(
                e, "eval_at[1]: NaN is not a finite number",
                "{} {policy}",
                m.id
            );
        }
    }
}

#[wasm_bindgen_test]
fn the_playground_carries_parametrization_and_extrapolate() {
    let mut pg = Playground::new(S3).unwrap();
    pg.set_curve(
        0,
        r#"{"method":"squad","parametrization":"arclength","extrapolate":"extend"}"#,
    )
    .map_err(message)
    .unwrap();
    let curve: serde_json::Value = serde_json::from_str(&pg.curve_json(0).unwrap()).unwrap();
    assert_eq!(curve["parametrization"], "arclength", "written back");
    assert_eq!(curve["extrapolate"], "extend", "written back");
    let scene: serde_json::Value = serde_json::from_str(&pg.scene_json()).unwrap();
    assert_eq!(scene["extrapolate"], "extend", "in the scene JSON");
    // Unit angular speed over [0, L], and the extension past L.
    let domain = pg.sample_array(0, "domain").unwrap();
    assert_eq!(domain[0], 0.0, "arc length starts at 0");
    let omega = pg.sample_array(0, "angular_velocity").unwrap();
    for w in omega.chunks(3) {
        let speed = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
        assert!((speed - 1.0).abs() < 1e-9, "|ω| = {speed}");
    }
    let out: serde_json::Value =
        serde_json::from_str(&pg.sample_at(&[domain[1] + 1.0], true, None).unwrap()).unwrap();
    let w = &out["angular_velocity"][0];
    let speed = (0..3)
        .map(|k| w[k].as_f64().unwrap().powi(2))
        .sum::<f64>()
        .sqrt();
    assert!(
        (speed - 1.0).abs() < 1e-9,
        "extended at unit speed: {speed}"
    );
    assert!(
        message(pg.sample_at(&[f64::INFINITY], false, None).unwrap_err())
            == "eval_at[0]: inf is not a finite number",
        "a typed error"
    );
    // A bad value is refused and names the field; the handle keeps the last good scene.
    let e = message(
        pg.set_curve(0, r#"{"method":"squad","extrapolate":"cycle"}"#)
            .unwrap_err(),
    );
    assert!(
        e.starts_with("extrapolate: \"cycle\" repeats a closed curve"),
        "{e}"
    );
    assert!(pg.curve_json(0).unwrap().contains("arclength"), "unchanged");
}
