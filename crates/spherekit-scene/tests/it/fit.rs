// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The scene's `"fit"`: samples fitted by the cubic spline, the record the built curve keeps,
//! and the errors on each field.

use serde_json::{Value, json};
use spherekit::glam::DVec3;
use spherekit::{CubicSpline, Curve, FitOptions, Manifold, S2Point, Smoothing, UnitQuat};
use spherekit_scene::{BuiltCurve, Document, MAX_FIT_SAMPLES, Scene, registry_json};

/// `n` noisy samples of a tilted circle on S² at times `0.2·i`, as scene points.
fn circle_samples(n: usize) -> (Vec<Value>, Vec<f64>) {
    let times: Vec<f64> = (0..n).map(|i| 0.2 * i as f64).collect();
    let points = times
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            let wobble = 0.02 * (i as f64 * 2.7).sin();
            json!([t.cos(), t.sin(), 0.4 + wobble])
        })
        .collect();
    (points, times)
}

fn build(scene: &Value) -> Result<Vec<BuiltCurve>, String> {
    Scene::from_value(scene)
        .and_then(|s| s.build())
        .map_err(|e| e.to_string())
}

#[test]
fn a_fit_keeps_its_samples_times_residuals_and_report() {
    let (points, times) = circle_samples(30);
    let scene = json!({ "space": "S2", "method": "cubic", "points": points, "knots": times,
                        "fit": { "smoothing": "gcv" }, "samples": 5 });
    let curves = build(&scene).unwrap();
    let BuiltCurve::S2(b) = &curves[0] else {
        panic!("an S2 curve")
    };
    let fit = b.fit.as_ref().unwrap();
    assert_eq!(b.inputs.len(), 30, "the samples are the inputs");
    assert_eq!(fit.times, times);
    assert_eq!(fit.keys.len(), 30);
    assert_eq!(fit.report.residuals.len(), 30);
    let report = &fit.report;
    assert!(report.lambda > 0.0 && report.edf.is_some());
    // The residuals are the report's: its RMS (unit weights) and its largest.
    let rms = (fit.report.residuals.iter().map(|d| d * d).sum::<f64>() / 30.0).sqrt();
    assert!(
        (rms - report.rms).abs() < 1e-12 * report.rms.max(1.0),
        "{rms} {}",
        report.rms
    );
    let max = fit.report.residuals.iter().copied().fold(0.0, f64::max);
    assert!((max - report.max).abs() < 1e-12, "{max} {}", report.max);
    // The same numbers in info.fit (what `spherekit sample` prints).
    let scene = Scene::from_value(&scene).unwrap();
    let out = scene.sample_json(&curves, false);
    let info = &out["info"]["fit"];
    assert_eq!(info["lambda"], json!(report.lambda));
    assert_eq!(info["rms"], json!(report.rms));
    assert_eq!(info["keys"], json!(30));
    assert_eq!(info["key_times"], json!(report.key_times));
    assert_eq!(info["edf"], json!(report.edf.unwrap()));
    assert_eq!(info["residuals"], json!(fit.report.residuals));
    assert_eq!(curves[0].fit_report(), Some(report));
}

#[test]
fn the_scene_fit_is_the_core_fit() {
    let (points, times) = circle_samples(25);
    let weights: Vec<f64> = (0..25).map(|i| 1.0 + 0.1 * f64::from(i % 4)).collect();
    let scene = json!({ "space": "S2", "method": "cubic", "points": points, "knots": times,
                        "fit": { "smoothing": 0.01, "weights": weights } });
    let curves = build(&scene).unwrap();
    let samples: Vec<S2Point> = points
        .iter()
        .map(|p| {
            let c: Vec<f64> = serde_json::from_value(p.clone()).unwrap();
            S2Point::try_new(DVec3::from_slice(&c)).unwrap()
        })
        .collect();
    let options = FitOptions {
        smoothing: Some(Smoothing::Lambda(0.01)),
        weights: Some(weights),
        ..FitOptions::default()
    };
    let (core, report) = CubicSpline::try_fit(samples, times, &options, false).unwrap();
    assert_eq!(curves[0].fit_report(), Some(&report));
    let BuiltCurve::S2(b) = &curves[0] else {
        panic!("an S2 curve")
    };
    for t in [0.0, 0.77, 2.5, 4.8] {
        assert!(b.curve.eval(t).dist(&core.eval(t)) < 1e-15, "t = {t}");
    }
}

/// Orientations turning by `turn` about a tilted axis, each off by a pseudo-random rotation of
/// up to about 0.03 rad, `[w, x, y, z]`.
fn rotations(n: usize, turn: f64) -> Vec<[f64; 4]> {
    let axis = DVec3::new(0.3, 0.2, 1.0).normalize();
    (0..n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let k = i as f64;
            let noise = 0.015 * DVec3::new((k * 2.3).sin(), (k * 3.7).cos(), (k * 1.3).sin());
            let q = UnitQuat::from_rotation_vector(noise).unwrap()
                * UnitQuat::from_axis_angle(axis, turn * t).unwrap();
            q.to_wxyz()
        })
        .collect()
}

#[test]
fn sign_flips_of_rotation_samples_change_nothing() {
    let q = rotations(20, 3.0);
    let times: Vec<f64> = (0..20).map(|i| 0.25 * f64::from(i)).collect();
    let flipped: Vec<[f64; 4]> = q
        .iter()
        .enumerate()
        .map(|(i, q)| if i % 3 == 1 { q.map(|x| -x) } else { *q })
        .collect();
    let reference = build(&json!({ "space": "S3", "method": "cubic", "points": q,
                                   "knots": times, "fit": { "smoothing": "gcv" } }))
    .unwrap();
    for canonicalize in [true, false] {
        let curves = build(
            &json!({ "space": "S3", "method": "cubic", "points": flipped,
                                    "knots": times, "canonicalize": canonicalize,
                                    "fit": { "smoothing": "gcv" } }),
        )
        .unwrap();
        let (a, b) = (
            reference[0].fit_report().unwrap(),
            curves[0].fit_report().unwrap(),
        );
        assert!((a.lambda - b.lambda).abs() < 1e-9 * a.lambda, "{a:?} {b:?}");
        assert!((a.rms - b.rms).abs() < 1e-12, "{a:?} {b:?}");
        let (BuiltCurve::S3(x), BuiltCurve::S3(y)) = (&reference[0], &curves[0]) else {
            panic!("S3 curves")
        };
        for t in [0.0, 1.3, 4.75] {
            let angle = (x.curve.eval(t).conjugate() * y.curve.eval(t)).rotation_angle();
            assert!(
                angle < 1e-9,
                "canonicalize {canonicalize}, t = {t}: {angle}"
            );
        }
        let fit = y.fit.as_ref().unwrap();
        let rms = (fit.report.residuals.iter().map(|d| d * d).sum::<f64>() / 20.0).sqrt();
        assert!(
            (rms - b.rms).abs() < 1e-12,
            "rotation-angle residuals: {rms} {}",
            b.rms
        );
    }
}

#[test]
fn closed_fits_need_the_return_time_and_fit_the_odd_turn_loop_in_so3() {
    // One full turn in 12 samples: taken the shorter way, the samples close at −q₀; the fit is
    // a loop in SO(3), ending at −q₀, whatever the signs as given.
    let q = rotations(12, 2.0 * std::f64::consts::PI);
    let times: Vec<f64> = (0..=12).map(f64::from).collect();
    for canonicalize in [true, false] {
        let curves = build(
            &json!({ "space": "S3", "method": "cubic", "points": q, "knots": times,
                                    "closed": true, "canonicalize": canonicalize,
                                    "fit": { "smoothing": 0.01 } }),
        )
        .unwrap();
        let BuiltCurve::S3(b) = &curves[0] else {
            panic!("a curve of rotations")
        };
        assert!(b.curve.is_antiperiodic());
        let fit = b.fit.as_ref().unwrap();
        assert_eq!((fit.keys.len(), fit.report.key_times.len()), (12, 13));
        assert!(fit.report.max < 0.05, "{:?}", fit.report);
        for (k, key) in fit.keys.iter().enumerate() {
            let c = b.curve.eval(fit.report.key_times[k]);
            assert!(c.dist(key).min(c.dist(&-*key)) < 1e-12);
        }
    }
    // A loop needs the return time.
    let (points, _) = circle_samples(12);
    let e = build(&json!({ "space": "S2", "method": "cubic", "points": points,
                           "knots": (0..12).collect::<Vec<_>>(), "closed": true, "fit": {} }))
    .unwrap_err();
    assert_eq!(e, "knots: expected 13 knots, got 12");
    let e = build(&json!({ "space": "S2", "method": "cubic", "points": points,
                           "closed": true, "fit": {} }))
    .unwrap_err();
    assert!(
        e.contains("and the time the loop returns to the first"),
        "{e}"
    );
}

#[test]
fn key_reduction_and_key_counts() {
    let (points, times) = circle_samples(40);
    // Samples over 2 rad of the circle, re-timed at 0.05 s.
    let (points, times): (Vec<Value>, Vec<f64>) = (points, times.iter().map(|t| t / 4.0).collect());
    let points: Vec<Value> = points
        .iter()
        .zip(&times)
        .map(|(p, &t)| json!([t.cos(), t.sin(), p[2]]))
        .collect();
    let curves = build(&json!({ "space": "S2", "method": "cubic", "points": points,
                                "knots": times, "fit": { "max_error": 0.05 } }))
    .unwrap();
    let report = curves[0].fit_report().unwrap();
    assert!(report.keys < 40 && report.max <= 0.05, "{report:?}");
    let BuiltCurve::S2(b) = &curves[0] else {
        panic!("an S2 curve")
    };
    assert_eq!(b.fit.as_ref().unwrap().keys.len(), report.keys);
    let curves = build(&json!({ "space": "S2", "method": "cubic", "points": points,
                                "knots": times, "fit": { "keys": 10, "smoothing": 0.001 } }))
    .unwrap();
    assert_eq!(curves[0].fit_report().unwrap().keys, 10);
}

#[test]
fn arc_length_and_curves_lists_keep_the_record() {
    let (points, times) = circle_samples(15);
    let scene = json!({ "space": "S2", "curves": [
        { "method": "geodesic", "points": points },
        { "method": "cubic", "points": points, "knots": times, "fit": { "smoothing": 0.1 },
          "parametrization": "arclength" } ] });
    let curves = build(&scene).unwrap();
    assert!(curves[0].fit_report().is_none());
    let BuiltCurve::S2(b) = &curves[1] else {
        panic!("an S2 curve")
    };
    let fit = b.fit.as_ref().unwrap();
    assert_eq!(fit.times, times, "times in the fit's own parameter");
    assert!(b.info.contains_key("arclength") && b.info.contains_key("fit"));
}

#[test]
fn bad_fits_name_their_field() {
    let (points, times) = circle_samples(8);
    let base = json!({ "space": "S2", "method": "cubic", "points": points, "knots": times });
    let with = |changes: Value| {
        let mut s = base.clone();
        for (k, v) in changes.as_object().unwrap() {
            if v.is_null() {
                s.as_object_mut().unwrap().remove(k);
            } else {
                s[k] = v.clone();
            }
        }
        build(&s).unwrap_err()
    };
    let cases = [
        (
            json!({ "method": "catmull-rom", "fit": {} }),
            "fit: method \"catmull-rom\" does not fit samples",
        ),
        (json!({ "fit": 3 }), "fit: must be an object"),
        (
            json!({ "fit": { "smooth": 1 } }),
            "fit.smooth: unknown fit option; known: smoothing, weights, max_error, keys",
        ),
        (
            json!({ "fit": { "keys": 3, "max_error": 0.1 } }),
            "fit: give \"keys\" or \"max_error\", not both",
        ),
        (
            json!({ "fit": { "smoothing": -1 } }),
            "fit.smoothing: λ must be",
        ),
        (
            json!({ "fit": { "smoothing": "auto" } }),
            "fit.smoothing: must be a number λ ≥ 0",
        ),
        (
            json!({ "fit": { "smoothing": { "rms": 0 } } }),
            "fit.smoothing: the target rms",
        ),
        (
            json!({ "fit": { "smoothing": { "rms": 0.1, "x": 1 } } }),
            "fit.smoothing: must be",
        ),
        (
            json!({ "fit": { "smoothing": "gcv", "keys": 4 } }),
            "fit.smoothing: \"gcv\" needs",
        ),
        (
            json!({ "fit": { "weights": [1, 1] } }),
            "fit.weights: must have one weight per sample: 8 points, got 2",
        ),
        (
            json!({ "fit": { "weights": [1, 1, -2, 1, 1, 1, 1, 1] } }),
            "fit.weights[2]: must be a positive finite number, got -2",
        ),
        (
            json!({ "fit": { "weights": [1, 1, 1, "a", 1, 1, 1, 1] } }),
            "fit.weights[3]: must be a positive finite number, got \"a\"",
        ),
        (
            json!({ "fit": { "max_error": 0 } }),
            "fit.max_error: must be a positive",
        ),
        (
            json!({ "fit": { "max_error": "x" } }),
            "fit.max_error: must be a number",
        ),
        (
            json!({ "fit": { "keys": 1 } }),
            "fit.keys: must be between 2 and the number of samples, 8; got 1",
        ),
        (
            json!({ "fit": { "keys": 9 } }),
            "fit.keys: must be between 2",
        ),
        (
            json!({ "fit": { "keys": 2.5 } }),
            "fit.keys: must be a whole number",
        ),
        (
            json!({ "fit": {}, "knots": null }),
            "knots: are needed with \"fit\"",
        ),
        (
            json!({ "fit": {}, "knots": [0, 1, 2] }),
            "knots: expected 8 knots, got 3",
        ),
        (
            json!({ "fit": {}, "knots": [0, 1, 2, 3, 3, 5, 6, 7] }),
            "knots[4] is not greater than knots[3]",
        ),
        (
            json!({ "fit": {}, "params": { "end": "scipy" } }),
            "params.end: does not apply with \"fit\"",
        ),
        (
            json!({ "fit": {}, "params": { "velocities": [] } }),
            "params.velocities: does not apply with \"fit\"",
        ),
    ];
    for (changes, expected) in cases {
        let e = with(changes.clone());
        assert!(e.starts_with(expected), "{changes}: {e}");
    }
    // The natural ends are the fit's: saying so is fine.
    let mut s = base.clone();
    s["fit"] = json!({ "smoothing": 1 });
    s["params"] = json!({ "end": "natural" });
    build(&s).unwrap();
    // In a curves list the error names the curve.
    let e = build(&json!({ "space": "S2", "curves": [
        { "method": "cubic", "points": points, "knots": times, "fit": { "keys": 0 } } ] }))
    .unwrap_err();
    assert!(e.starts_with("curves[0].fit.keys: "), "{e}");
    let e = build(&json!({ "space": "S2", "method": "cubic", "points": points,
                           "fit": {}, "curves": [] }))
    .unwrap_err();
    assert!(e.starts_with("curves: "), "{e}");
}

#[test]
fn too_many_samples_are_refused_before_fitting() {
    let n = MAX_FIT_SAMPLES + 1;
    let points = vec![json!([1, 0, 0]); n];
    let times: Vec<f64> = (0..n).map(|i| i as f64).collect();
    let e = build(
        &json!({ "space": "S2", "method": "cubic", "points": points, "knots": times,
                           "fit": { "max_error": 0.01 } }),
    )
    .unwrap_err();
    assert_eq!(
        e,
        format!("points: a fit takes at most {MAX_FIT_SAMPLES} samples, got {n}")
    );
}

#[test]
fn the_registry_lists_the_fit_options_of_the_cubic() {
    let registry = registry_json();
    for m in registry.as_array().unwrap() {
        let names: Vec<&str> = m["fit"]
            .as_array()
            .map(|f| f.iter().map(|o| o["name"].as_str().unwrap()).collect())
            .unwrap_or_default();
        if m["id"] == "cubic" {
            assert_eq!(names, ["smoothing", "weights", "max_error", "keys"]);
        } else {
            assert!(m["fit"].is_null(), "{}", m["id"]);
        }
    }
}

#[test]
fn weights_follow_point_edits_and_other_methods_drop_the_fit() {
    let (points, times) = circle_samples(5);
    let scene = json!({ "space": "S2", "method": "cubic", "points": points, "knots": times,
                        "fit": { "smoothing": 0.1, "weights": [1, 2, 3, 4, 5] } });
    let mut doc = Document::from_json(&scene.to_string()).unwrap();
    doc.insert_point(0, 2, &[0.3_f64.cos(), 0.3_f64.sin(), 0.4])
        .unwrap();
    let weights = |doc: &Document| -> Vec<f64> {
        serde_json::from_value(doc.curve(0).unwrap()["fit"]["weights"].clone()).unwrap()
    };
    assert_eq!(weights(&doc), [1.0, 2.0, 3.0, 3.0, 4.0, 5.0]);
    doc.remove_point(0, 0).unwrap();
    assert_eq!(weights(&doc), [2.0, 3.0, 3.0, 4.0, 5.0]);
    assert!(doc.curves()[0].fit_report().is_some());
    doc.set_method(0, "catmull-rom").unwrap();
    assert!(doc.curve(0).unwrap().get("fit").is_none());
    assert!(doc.curves()[0].fit_report().is_none());
}
