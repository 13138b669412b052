// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The curve-level timing fields on every registered method: `"extrapolate"` at the probe
//! parameters `t0 − 1`, `t1 + 1`, `±1e300` and NaN, and `"parametrization": "arclength"`
//! (equal steps equally far apart along the curve, unit speed, stalls reported, never NaN).

use serde_json::{Value, json};
use spherekit_scene::{BuiltCurve, Document, METHODS, Method, Scene};

use crate::support::cases;

/// The single-curve scene of `m` on `space` with `n` points and extra fields (points around
/// a loop when `extra` closes the curve).
fn scene(m: &Method, space: &str, extra: &Value) -> Value {
    let n = if m.single_piece {
        4
    } else {
        5.max(m.min_points)
    };
    let points = if extra["closed"] == json!(true) {
        cases::loop_points(space, n)
    } else {
        cases::points(space, n)
    };
    let mut s = json!({ "space": space, "method": m.id, "points": points });
    for (k, v) in extra.as_object().unwrap() {
        s[k] = v.clone();
    }
    s
}

fn domain(scene: &Value) -> [f64; 2] {
    let s = Scene::from_json(&scene.to_string()).unwrap();
    s.build().unwrap()[0].domain()
}

/// Samples `scene` with derivatives at `ts`.
fn sample_at(scene: &Value, ts: &[f64]) -> Result<Value, String> {
    let mut s = Scene::from_json(&scene.to_string()).map_err(|e| e.to_string())?;
    s.set_parameters(ts.to_vec()).map_err(|e| e.to_string())?;
    let curves = s.build().map_err(|e| e.to_string())?;
    Ok(s.sample_json(&curves, true))
}

fn row(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn diff(a: &[f64], b: &[f64]) -> f64 {
    norm(&a.iter().zip(b).map(|(x, y)| x - y).collect::<Vec<_>>())
}

/// The angle between unit vectors, accurate at every angle.
fn angle(a: &[f64], b: &[f64]) -> f64 {
    let d: Vec<f64> = a.iter().zip(b).map(|(x, y)| x - y).collect();
    let s: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + y).collect();
    2.0 * norm(&d).atan2(norm(&s))
}

/// Every method with the sphere it is tried on first.
fn methods() -> impl Iterator<Item = (&'static Method, &'static str)> {
    METHODS
        .iter()
        .flat_map(|m| cases::spaces(m).iter().take(2).map(move |s| (*m, *s)))
}

#[test]
fn hold_is_the_end_point_at_rest_on_every_method() {
    for (m, space) in methods() {
        let s = scene(m, space, &json!({ "extrapolate": "hold" }));
        let [t0, t1] = domain(&s);
        let out = sample_at(&s, &[t0 - 1.0, t1 + 1.0, -1e300, 1e300, t0, t1]).unwrap();
        let p = &out["points"];
        for (k, end) in [(0, 4), (1, 5), (2, 4), (3, 5)] {
            assert_eq!(p[k], p[end], "{} {space}: sample {k}", m.id);
            assert_eq!(norm(&row(&out["velocity"][k])), 0.0, "{} {space}", m.id);
            assert_eq!(norm(&row(&out["acceleration"][k])), 0.0, "{} {space}", m.id);
        }
    }
}

#[test]
fn extend_continues_the_end_geodesic_on_every_method() {
    for (m, space) in methods() {
        let s = scene(m, space, &json!({ "extrapolate": "extend" }));
        let [t0, t1] = domain(&s);
        let out = sample_at(&s, &[t0 - 1.0, t1 + 1.0, -1e300, 1e300, t0, t1]).unwrap();
        for (k, end) in [(0, 4), (1, 5)] {
            let v = row(&out["velocity"][end]);
            let speed = norm(&v);
            let d = angle(&row(&out["points"][k]), &row(&out["points"][end]));
            // One unit of t at the end's speed along a great circle (checked below a half turn).
            if speed < 3.0 {
                assert!((d - speed).abs() < 1e-9, "{} {space}: {d} vs {speed}", m.id);
            }
            assert!(
                (norm(&row(&out["velocity"][k])) - speed).abs() < 1e-12 * speed.max(1.0),
                "{} {space}: constant speed",
                m.id
            );
        }
        // Far out the extension still has a value, a point of the sphere.
        for k in [2, 3] {
            assert!(
                (norm(&row(&out["points"][k])) - 1.0).abs() < 1e-12,
                "{}",
                m.id
            );
        }
    }
}

#[test]
fn error_rejects_every_parameter_outside_the_domain_naming_it() {
    for (m, space) in methods() {
        let s = scene(m, space, &json!({ "extrapolate": "error" }));
        let [t0, t1] = domain(&s);
        assert!(
            sample_at(&s, &[t0, 0.5 * (t0 + t1), t1]).is_ok(),
            "{}",
            m.id
        );
        for (k, t) in [t0 - 1.0, t1 + 1.0, -1e300, 1e300].into_iter().enumerate() {
            let e = sample_at(&s, &[t0, t1, t]).unwrap_err();
            assert!(e.starts_with("eval_at[2]: "), "{} {space} ({k}): {e}", m.id);
            assert!(e.contains("is outside the domain"), "{e}");
            assert!(e.contains("\"extrapolate\" is \"error\""), "{e}");
        }
    }
}

#[test]
fn nan_and_infinite_parameters_are_errors_under_every_policy() {
    for (m, space) in methods() {
        for policy in ["hold", "extend", "error", "cycle", "segment"] {
            let mut extra = json!({ "extrapolate": policy });
            if policy == "cycle" {
                if !m.closes {
                    continue;
                }
                extra["closed"] = json!(true);
            }
            if policy == "segment" && m.id != "cubic" {
                continue;
            }
            let s = scene(m, space, &extra);
            for (t, shown) in [
                (f64::NAN, "NaN"),
                (f64::INFINITY, "inf"),
                (f64::NEG_INFINITY, "-inf"),
            ] {
                let e = sample_at(&s, &[0.0, t]).unwrap_err();
                assert_eq!(
                    e,
                    format!("eval_at[1]: {shown} is not a finite number"),
                    "{}",
                    m.id
                );
            }
        }
    }
}

#[test]
fn cycle_repeats_closed_curves_and_is_refused_for_open_ones() {
    for (m, space) in methods() {
        let e = Scene::from_json(&scene(m, space, &json!({ "extrapolate": "cycle" })).to_string())
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("extrapolate: \"cycle\" repeats a closed curve"),
            "{e}"
        );
        if !m.closes {
            continue;
        }
        let s = scene(m, space, &json!({ "extrapolate": "cycle", "closed": true }));
        let [t0, t1] = domain(&s);
        let period = t1 - t0;
        let ts = [t0 - 1.0, t1 + 1.0, t0 - 1.0 + period, t0 + 1.0];
        let out = sample_at(&s, &ts).unwrap();
        let p = &out["points"];
        assert!(diff(&row(&p[0]), &row(&p[2])) < 1e-12, "{} {space}", m.id);
        assert!(diff(&row(&p[1]), &row(&p[3])) < 1e-12, "{} {space}", m.id);
        // ±1e300 has a value too (a whole number of periods away, to rounding).
        assert!(sample_at(&s, &[-1e300, 1e300]).is_ok(), "{}", m.id);
    }
}

#[test]
fn segment_continues_the_open_cubic_and_is_refused_elsewhere() {
    for (m, space) in methods() {
        let s = scene(m, space, &json!({ "extrapolate": "segment" }));
        let built = Scene::from_json(&s.to_string()).unwrap().build();
        if m.id != "cubic" {
            let e = built.unwrap_err().to_string();
            assert!(
                e.starts_with("extrapolate: \"segment\" continues"),
                "{}: {e}",
                m.id
            );
            continue;
        }
        let [t0, t1] = domain(&s);
        let out = sample_at(&s, &[t0 - 1.0, t1 + 1.0, t0 - 1e-7, t0]).unwrap();
        // Smooth through the end: a step of 1e-7 before t0 moves by about 1e-7·|v|.
        let speed = norm(&row(&out["velocity"][3]));
        let step = angle(&row(&out["points"][2]), &row(&out["points"][3]));
        assert!((step - 1e-7 * speed).abs() < 1e-12, "{space}: {step}");
        assert!(diff(&row(&out["velocity"][2]), &row(&out["velocity"][3])) < 1e-5);
        for k in 0..2 {
            assert!((norm(&row(&out["points"][k])) - 1.0).abs() < 1e-12);
        }
        // Far out the cubic overflows: an error naming the parameter.
        for t in [-1e300, 1e300] {
            let e = sample_at(&s, &[t0, t]).unwrap_err();
            assert!(
                e.starts_with("eval_at[1]: ") && e.contains("overflows"),
                "{e}"
            );
        }
        // Closed: no ends to continue.
        let closed = scene(
            m,
            space,
            &json!({ "extrapolate": "segment", "closed": true }),
        );
        let e = Scene::from_json(&closed.to_string())
            .unwrap()
            .build()
            .unwrap_err();
        assert!(e.to_string().starts_with("extrapolate: "), "{e}");
    }
}

#[test]
fn unknown_names_are_errors_naming_the_field() {
    let base = json!({ "space": "S2", "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]] });
    for (field, value, start) in [
        (
            "extrapolate",
            "clamp",
            "extrapolate: \"clamp\" is not an extrapolation policy",
        ),
        (
            "parametrization",
            "time",
            "parametrization: \"time\" is not a parametrization",
        ),
    ] {
        let mut s = base.clone();
        s[field] = json!(value);
        let e = Scene::from_json(&s.to_string()).unwrap_err().to_string();
        assert!(e.starts_with(start), "{e}");
    }
    // In a list they belong to each curve.
    let listed = json!({ "space": "S2", "extrapolate": "hold",
        "curves": [{ "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]] }] });
    let e = Scene::from_json(&listed.to_string())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("curves: with \"curves\""), "{e}");
}

/// The length of the curve between two samples, from a fine polyline of its points
/// (Richardson-extrapolated from `n` and `2n` chords: independent of the arc-length table).
fn polyline_length(points: &[Vec<f64>], scale: f64) -> f64 {
    let chords = |step: usize| -> f64 {
        points
            .iter()
            .step_by(step)
            .collect::<Vec<_>>()
            .windows(2)
            .map(|w| angle(w[0], w[1]) * scale)
            .sum()
    };
    let (fine, coarse) = (chords(1), chords(2));
    fine + (fine - coarse) / 3.0
}

#[test]
fn arclength_on_every_method_has_equal_steps_and_unit_speed() {
    for (m, space) in methods() {
        let s = scene(
            m,
            space,
            &json!({ "parametrization": "arclength", "samples": 9 }),
        );
        let scene_ = Scene::from_json(&s.to_string()).unwrap();
        let curves = scene_.build().unwrap();
        let out = scene_.sample_json(&curves, true);
        let length = out["info"]["arclength"]["length"].as_f64().unwrap();
        assert_eq!(out["domain"], json!([0.0, length]), "{} {space}", m.id);
        let scale = if space == "S3" { 2.0 } else { 1.0 };
        // Unit speed (|ω| = 1 on S³) at every sample.
        for v in out["velocity"].as_array().unwrap() {
            let speed = norm(&row(v)) * scale;
            assert!(
                (speed - 1.0).abs() < 1e-9,
                "{} {space}: speed {speed}",
                m.id
            );
        }
        // Equal steps are equally far apart along the curve: each of the 8 steps measured by
        // polylines through the curve's own points, split at the joints (where C⁰ methods turn).
        let step = length / 8.0;
        let joints = joints(&curves[0]);
        for k in 0..8_u8 {
            let (a, b) = (f64::from(k) * step, f64::from(k + 1) * step);
            let mut cuts: Vec<f64> = joints.iter().copied().filter(|&j| j > a && j < b).collect();
            cuts.insert(0, a);
            cuts.push(b);
            let l: f64 = cuts
                .windows(2)
                .map(|w| {
                    let ts: Vec<f64> = (0..=64)
                        .map(|i| w[0] + (w[1] - w[0]) * f64::from(i) / 64.0)
                        .collect();
                    polyline_length(&points_at(&s, &ts), scale)
                })
                .sum();
            assert!(
                (l - step).abs() < 1e-9 * length,
                "{} {space}: step {k} is {l}, not {step}",
                m.id
            );
        }
    }
}

/// The joints of a built curve.
fn joints(c: &BuiltCurve) -> Vec<f64> {
    match c {
        BuiltCurve::S2(b) => b.curve.joints().to_vec(),
        BuiltCurve::S3(b) => b.curve.joints().to_vec(),
        BuiltCurve::Sm(b) => b.curve.joints().to_vec(),
    }
}

/// The points of `scene`'s curve at `ts`.
fn points_at(scene: &Value, ts: &[f64]) -> Vec<Vec<f64>> {
    let out = sample_at(scene, ts).unwrap();
    out["points"].as_array().unwrap().iter().map(row).collect()
}

#[test]
fn arclength_stays_finite_and_reports_stalls_at_identical_keys_and_cusps() {
    // Identical consecutive keys: a piece of zero length.
    let twice = json!({ "space": "S2", "method": "geodesic", "parametrization": "arclength",
        "points": [[1, 0, 0], [0, 1, 0], [0, 1, 0], [0, 0, 1]], "samples": 41 });
    // A cusp: the Bézier curve goes out to its middle control point and comes back.
    let cusp = json!({ "space": "S2", "method": "bezier", "parametrization": "arclength",
        "points": [[1, 0, 0], [0, 1, 0], [1, 0, 0]], "samples": 41 });
    for s in [twice, cusp] {
        let scene_ = Scene::from_json(&s.to_string()).unwrap();
        let curves = scene_.build().unwrap();
        let out = scene_.sample_json(&curves, true);
        let stalls = out["info"]["arclength"]["stalls"].as_array().unwrap();
        assert!(!stalls.is_empty(), "{s}: the stall is reported");
        for k in ["points", "velocity", "acceleration"] {
            for v in out[k].as_array().unwrap() {
                assert!(row(v).iter().all(|x| x.is_finite()), "{s}: {k}");
            }
        }
    }
    // All keys at one point: no arc length, said on the field.
    let still = json!({ "space": "S2", "method": "geodesic", "parametrization": "arclength",
        "points": [[1, 0, 0], [1, 0, 0]] });
    let e = Scene::from_json(&still.to_string())
        .unwrap()
        .build()
        .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("parametrization: the curve has zero length"),
        "{e}"
    );
}

#[test]
fn geodesic_at_constant_speed_is_reproduced() {
    // Knots proportional to the angles: the geodesic spline already has unit speed.
    let s = json!({ "space": "S2", "method": "geodesic",
        "points": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
        "knots": [0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI],
        "eval_at": [0.3, 1.0, 2.0, 3.0] });
    let arc = {
        let mut a = s.clone();
        a["parametrization"] = json!("arclength");
        a
    };
    let (x, y) = (
        sample_at(&s, &[0.3, 1.0, 2.0, 3.0]).unwrap(),
        sample_at(&arc, &[0.3, 1.0, 2.0, 3.0]).unwrap(),
    );
    for k in 0..4 {
        assert!(
            diff(&row(&x["points"][k]), &row(&y["points"][k])) < 1e-10,
            "{k}"
        );
        assert!(
            diff(&row(&x["velocity"][k]), &row(&y["velocity"][k])) < 1e-9,
            "{k}"
        );
    }
}

#[test]
fn documents_carry_both_fields_and_write_them_back() {
    let mut doc = Document::from_json(
        r#"{"space":"S2","method":"cubic","points":[[1,0,0],[0,1,0],[0,0,1]]}"#,
    )
    .unwrap();
    // Only the curve's own fields: the scene's (`space`) stay where they are.
    let mut only = Document::from_json(
        r#"{"space":"S2","method":"cubic","points":[[1,0,0],[0,1,0],[0,0,1]],"samples":5}"#,
    )
    .unwrap();
    let fields = json!({ "method": "geodesic", "extrapolate": "error" });
    only.set_curve(0, fields.as_object().unwrap().clone())
        .unwrap();
    let back: Value = serde_json::from_str(&only.to_json()).unwrap();
    assert_eq!(
        (back["space"].clone(), back["samples"].clone()),
        (json!("S2"), json!(5))
    );
    assert_eq!(back["extrapolate"], "error");
    let mut fields = doc.curve(0).unwrap().clone();
    fields.remove("points");
    fields.insert("parametrization".into(), json!("arclength"));
    fields.insert("extrapolate".into(), json!("extend"));
    doc.set_curve(0, fields.clone()).unwrap();
    let back: Value = serde_json::from_str(&doc.to_json()).unwrap();
    assert_eq!(back["parametrization"], "arclength");
    assert_eq!(back["extrapolate"], "extend");
    let length =
        doc.scene().sample_json(doc.curves(), false)["info"]["arclength"]["length"].clone();
    assert_eq!(json!(doc.curves()[0].domain()), json!([0.0, length]));
    // A second curve: the single curve's fields move into the list with it.
    doc.add_curve("geodesic").unwrap();
    let back: Value = serde_json::from_str(&doc.to_json()).unwrap();
    assert_eq!(back["curves"][0]["extrapolate"], "extend");
    assert!(back.get("extrapolate").is_none());
    // A bad value leaves the document as it was, with the field named.
    let mut bad = doc.curve(0).unwrap().clone();
    bad.remove("points");
    bad.insert("extrapolate".into(), json!("cycle"));
    let e = doc.set_curve(0, bad).unwrap_err().to_string();
    assert!(e.starts_with("curves[0].extrapolate: "), "{e}");
    assert_eq!(doc.curve(0).unwrap()["extrapolate"], "extend");
    // A document sampled at a parameter outside the domain of an "error" curve is refused.
    let e = doc
        .set_scene(r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"extrapolate":"error","eval_at":[2]}"#)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("eval_at[0]: 2 is outside the domain [0, 1]"),
        "{e}"
    );
    // Another method: "segment" goes with the cubic (as knots go with a method that takes
    // none), every other field stays.
    let mut cubic = Document::from_json(
        r#"{"space":"S2","method":"cubic","points":[[1,0,0],[0,1,0],[0,0,1]],"extrapolate":"segment","parametrization":"native"}"#,
    )
    .unwrap();
    cubic.set_method(0, "geodesic").unwrap();
    let back: Value = serde_json::from_str(&cubic.to_json()).unwrap();
    assert_eq!(
        (back["method"].clone(), back.get("extrapolate")),
        (json!("geodesic"), None)
    );
    assert_eq!(back["parametrization"], "native");
}
