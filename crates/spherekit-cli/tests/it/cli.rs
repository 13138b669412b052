// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The `spherekit` command line: output shape, and one clear line with exit status 2 for every
//! kind of bad input.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use std::io::Write;
use std::process::{Command, Output, Stdio};

use serde_json::Value;

fn spherekit(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_spherekit"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The tool may stop reading early (a parse error): a broken pipe here is not a failure.
    if let Err(e) = child.stdin.take().unwrap().write_all(stdin.as_bytes()) {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().unwrap()
}

fn sample(scene: &str, extra: &[&str]) -> Value {
    let mut args = vec!["sample", "-"];
    args.extend_from_slice(extra);
    let out = spherekit(&args, scene);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "failed: {stderr}");
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Runs a bad scene and returns the single stderr line, checking status 2 and empty stdout.
#[track_caller]
fn reject(scene: &str, extra: &[&str]) -> String {
    let mut args = vec!["sample", "-"];
    args.extend_from_slice(extra);
    let out = spherekit(&args, scene);
    assert_eq!(
        out.status.code(),
        Some(2),
        "scene {scene} should be rejected"
    );
    assert!(out.stdout.is_empty(), "no output on error");
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    assert!(stderr.starts_with("error: "), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr.trim_end().to_owned()
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

const S2_SCENE: &str =
    r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0],[0,0,1]],"samples":5}"#;

#[test]
fn sample_prints_the_documented_fields() {
    let out = sample(S2_SCENE, &[]);
    assert_eq!(out["space"], "S2");
    assert_eq!(out["method"], "geodesic");
    assert_eq!(out["domain"], serde_json::json!([0.0, 2.0]));
    assert_eq!(out["t"], serde_json::json!([0.0, 0.5, 1.0, 1.5, 2.0]));
    assert_eq!(out["points"].as_array().unwrap().len(), 5);
    assert_eq!(out["points"][2], serde_json::json!([0.0, 1.0, 0.0]));
    assert!(out.get("velocity").is_none());
    let d = sample(S2_SCENE, &["--deriv", "--samples", "9"]);
    assert_eq!(d["t"].as_array().unwrap().len(), 9);
    assert_eq!(d["velocity"].as_array().unwrap().len(), 9);
    assert_eq!(d["acceleration"].as_array().unwrap().len(), 9);
    assert!(
        d.get("angular_velocity").is_none(),
        "S2 has no angular velocity"
    );
    assert!(all_finite(&d));
}

#[test]
fn quaternion_scenes_report_angular_velocity_scalar_first() {
    // A rotation by 1 rad about z over t ∈ [0, 2]: ω = (0, 0, 0.5).
    let h = 0.5_f64.cos();
    let scene = format!(
        r#"{{"space":"S3","method":"geodesic","points":[[1,0,0,0],[{h},0,0,{}]],"knots":[0,2],"samples":3}}"#,
        0.5_f64.sin()
    );
    let out = sample(&scene, &["--deriv"]);
    let w = &out["angular_velocity"][1];
    assert!((w[2].as_f64().unwrap() - 0.5).abs() < 1e-14, "{w}");
    assert!(w[0].as_f64().unwrap().abs() < 1e-15);
    let p = &out["points"][2];
    assert!(
        (p[0].as_f64().unwrap() - h).abs() < 1e-15,
        "scalar first: {p}"
    );
    // velocity at the start is along +z, in [w, x, y, z] order.
    assert!(out["velocity"][0][3].as_f64().unwrap() > 0.2);
}

#[test]
fn canonicalize_controls_the_double_cover() {
    let scene = |c: &str| {
        format!(r#"{{"space":"S3","method":"geodesic","points":[[1,0,0,0],[-0.9,0,0,-0.1]]{c}}}"#)
    };
    let out = sample(&scene(""), &["--samples", "3"]);
    // Flipped: the second key comes out as +(0.9, 0, 0, 0.1) normalised.
    assert!(out["points"][2][0].as_f64().unwrap() > 0.99);
    let out = sample(&scene(r#","canonicalize":false"#), &["--samples", "3"]);
    assert!(
        out["points"][2][0].as_f64().unwrap() < -0.99,
        "kept as given"
    );
}

#[test]
fn eval_at_and_sn_scenes() {
    let out = sample(
        r#"{"space":"S5","method":"nlerp","points":[[1,0,0,0,0,0],[0,0,0,0,0,3]],"eval_at":[0.5,-1,2]}"#,
        &[],
    );
    assert_eq!(out["space"], "S5");
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let p = out["points"][0].as_array().unwrap();
    assert_eq!(p.len(), 6);
    assert!(
        (p[0].as_f64().unwrap() - s).abs() < 1e-15 && (p[5].as_f64().unwrap() - s).abs() < 1e-15
    );
    assert_eq!(out["points"][1][0], 1.0, "clamped below the domain");
    assert_eq!(out["points"][2][5], 1.0, "clamped above the domain");
}

#[test]
fn scene_from_a_file_and_methods_list() {
    let dir = std::env::temp_dir().join(format!("spherekit-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.json");
    std::fs::write(&path, S2_SCENE).unwrap();
    let out = spherekit(&["sample", path.to_str().unwrap()], "");
    assert!(out.status.success());
    let missing = spherekit(&["sample", dir.join("nope.json").to_str().unwrap()], "");
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("cannot read scene file"));
    let methods = spherekit(&["methods"], "");
    let text = String::from_utf8(methods.stdout).unwrap();
    for id in [
        "geodesic",
        "nlerp",
        "bezier",
        "squad",
        "catmull-rom",
        "gamma",
        "beta",
        "arc-blend",
    ] {
        assert!(text.contains(id), "{id} listed");
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_field() {
    let cases: &[(&str, &[&str], &str)] = &[
        ("{", &[], "invalid scene JSON"),
        ("", &[], "invalid scene JSON"),
        (
            r#"{"space":"S2","method":"geodesic"}"#,
            &[],
            "missing field `points`",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"colour":1}"#,
            &[],
            "unknown field `colour`",
        ),
        // Parse errors name the JSON path where they happened, on any line.
        (
            "{\"space\": \"S2\", \"method\": \"geodesic\",\n \"points\": [[1, 0, 0],\n [0, 1e999, 0]]}",
            &[],
            "invalid scene JSON: points[1][1]: number out of range at line 3 column 10",
        ),
        (
            r#"{"space":"S2","curves":[{"method":"nlerp","points":[[1,0,0],[0,1,0]]},
                {"method":"nlerp","points":[[1,0,0],[0,1,0]],"knots":[0,"1"]}]}"#,
            &[],
            "curves[1].knots[1]: invalid type: string \"1\", expected f64",
        ),
        (
            r#"{"space":"S2","curves":[{"method":"nlerp","points":[[1,0,0],[0,1,0]],"sample":3}]}"#,
            &[],
            "invalid scene JSON: curves[0]: unknown field `sample`",
        ),
        ("null", &[], "invalid type: null, expected a scene object"),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"a.b":1}"#,
            &[],
            "invalid scene JSON: unknown field `a.b`",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0] [0,1,0]]}"#,
            &[],
            "invalid scene JSON: points[0]: expected `,` or `]`",
        ),
        (
            r#"{"space":"S2","method":"spline","points":[[1,0,0],[0,1,0]]}"#,
            &[],
            "method: unknown method \"spline\"",
        ),
        (
            r#"{"space":"S9999","method":"geodesic","points":[]}"#,
            &[],
            "space: \"S9999\"",
        ),
        (
            r#"{"space":"R3","method":"geodesic","points":[]}"#,
            &[],
            "space: \"R3\" is not a sphere",
        ),
        (
            r#"{"space":"S2","method":"squad","points":[[1,0,0],[0,1,0]]}"#,
            &[],
            "method: \"squad\" works on S3, not S2",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1]]}"#,
            &[],
            "points[1]: has 2 coordinates, S2 points have 3",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,0,0]]}"#,
            &[],
            "points[1] has zero length",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[1e400,0,0]]}"#,
            &[],
            "invalid scene JSON",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[NaN,0,0]]}"#,
            &[],
            "invalid scene JSON",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0]]}"#,
            &[],
            "points: this method needs at least 2 points, got 1",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[]}"#,
            &[],
            "needs at least 2 points, got 0",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0],[-1,0,0]],"knots":[0,2,1]}"#,
            &[],
            "knots[2] is not greater than knots[1]",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"knots":[0,1,2]}"#,
            &[],
            "knots: expected 2 knots, got 3",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[-1,0,0]]}"#,
            &[],
            "points[0] and points[1] are antipodal",
        ),
        (
            r#"{"space":"S3","method":"geodesic","points":[[1,0,0,0],[-1,0,0,0]],"canonicalize":false}"#,
            &[],
            "points[0] and points[1] are antipodal",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"canonicalize":true}"#,
            &[],
            "canonicalize: applies to S3",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"samples":0}"#,
            &[],
            "samples: must be a whole number from 2",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"samples":1e12}"#,
            &[],
            "samples: must be a whole number from 2 to 1000000",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"samples":2.5}"#,
            &[],
            "samples: must be a whole number",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"eval_at":[]}"#,
            &[],
            "eval_at: must have 1 to",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"samples":3,"eval_at":[0]}"#,
            &[],
            "eval_at: give either samples or eval_at",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"params":{"tension":1}}"#,
            &[],
            "params.tension: unknown parameter for method \"geodesic\"",
        ),
        (
            S2_SCENE,
            &["--samples", "x"],
            "--samples: \"x\" is not a whole number",
        ),
        (
            S2_SCENE,
            &["--samples", "1"],
            "--samples: must be a whole number from 2",
        ),
        (S2_SCENE, &["--bogus"], "unknown option --bogus"),
        (
            r#"{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]]},{"method":"nlerp","points":[[1,0,0],[-1,0,0]]}]}"#,
            &[],
            "curves[1].points[0] and points[1] are antipodal",
        ),
        (
            r#"{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]],"color":"red"}]}"#,
            &[],
            "curves[0].color: \"red\" is not a colour",
        ),
        (
            r#"{"space":"S2","curves":[{"method":"squad","points":[[1,0,0],[0,1,0]]}]}"#,
            &[],
            "curves[0].method: \"squad\" works on S3, not S2",
        ),
        (
            r#"{"space":"S2","curves":[]}"#,
            &[],
            "curves: must list at least one curve",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"curves":[]}"#,
            &[],
            "curves: give either",
        ),
    ];
    for (scene, extra, expected) in cases {
        let line = reject(scene, extra);
        assert!(
            line.contains(expected),
            "for {scene}: got `{line}`, expected `{expected}`"
        );
    }
    // Deeply nested JSON is rejected by the parser's depth limit, not by a stack overflow.
    let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    assert!(reject(&deep, &[]).contains("invalid scene JSON"));
}

/// The largest `c<order>` jump over the joints of a `--continuity` report.
fn max_jump(out: &Value, order: usize) -> f64 {
    let joints = out["continuity"].as_array().unwrap();
    assert!(!joints.is_empty(), "joints reported: {out}");
    joints
        .iter()
        .map(|j| j[format!("c{order}")].as_f64().unwrap())
        .fold(0.0, f64::max)
}

const S2_KEYS: &str = "[[1,0,0],[0.6,0.8,0],[0,0.6,0.8],[-0.6,0,0.8],[-0.8,-0.6,0]]";
const S3_KEYS: &str = "[[1,0,0,0],[0.9,0.3,0.3,0.1],[0.6,0.2,0.7,0.3],[0.3,0.8,0.4,0.3],[0.2,0.3,0.5,0.8],[0.5,0.1,0.2,0.8]]";

#[test]
fn continuity_controls_and_info_through_the_cli() {
    // arc-blend: Cⁿ at every joint for the order asked, and not C^(n+1) at order 1.
    let arc = |order: u32| {
        let scene = format!(
            r#"{{"space":"S2","method":"arc-blend","points":{S2_KEYS},"params":{{"order":{order}}}}}"#
        );
        sample(&scene, &["--continuity", "--samples", "3"])
    };
    let c2 = arc(2);
    assert!(max_jump(&c2, 0) < 1e-12 && max_jump(&c2, 1) < 1e-9 && max_jump(&c2, 2) < 1e-9);
    assert_eq!(c2["info"]["knots"].as_array().unwrap().len(), 5);
    assert!(max_jump(&arc(1), 2) > 1e-3, "order 1 is only C¹");

    // gamma: C¹ for any γ and spacing, with the C² residuals of every interior joint in `info`.
    let gamma = sample(
        &format!(
            r#"{{"space":"S3","method":"gamma","points":{S3_KEYS},"knots":[0,0.5,2,3],
                "params":{{"gamma":[0.4,2.5]}}}}"#
        ),
        &["--continuity", "--samples", "3"],
    );
    assert!(max_jump(&gamma, 1) < 1e-9, "{}", gamma["continuity"]);
    assert!(max_jump(&gamma, 2) > 1e-3, "not C² for these γ");
    assert_eq!(gamma["controls"].as_array().unwrap().len(), 3 * 3 + 1);
    let joints = gamma["info"]["joints"].as_array().unwrap();
    assert_eq!(joints.len(), 2);
    assert!(
        joints
            .iter()
            .all(|j| j["paper_residual"].as_f64().unwrap() > 0.0)
    );

    // squad: the inner quadrangle points are reported; C¹ but not C².
    let squad = sample(
        &format!(r#"{{"space":"S3","method":"squad","points":{S3_KEYS},"knots":[0,1,3,4,4.5,7]}}"#),
        &["--continuity", "--samples", "3"],
    );
    assert_eq!(squad["controls"].as_array().unwrap().len(), 6);
    assert!(max_jump(&squad, 1) < 1e-9 && max_jump(&squad, 2) > 1e-3);

    // beta: interpolates, with the solver's auxiliary vertices, iterations and residual.
    let beta = sample(
        &format!(
            r#"{{"space":"S2","method":"beta","points":{S2_KEYS},"params":{{"beta2":[0,1,2,1,0]}}}}"#
        ),
        &["--continuity", "--samples", "5"],
    );
    assert_eq!(beta["auxiliary"].as_array().unwrap().len(), 5);
    assert_eq!(beta["info"]["solver"], "newton");
    assert!(beta["info"]["iterations"].as_u64().unwrap() >= 1);
    assert!(beta["info"]["residual"].as_f64().unwrap() < 1e-12);
    assert!(
        max_jump(&beta, 0) < 1e-12 && max_jump(&beta, 1) < 1e-9,
        "C¹ at β₁ = 1"
    );
    assert_eq!(beta["domain"], serde_json::json!([0.0, 4.0]));
    let keys: Value = serde_json::from_str(S2_KEYS).unwrap();
    for k in 0..5 {
        let (key, got) = (&keys[k], &beta["points"][k]);
        let d: f64 = (0..3)
            .map(|i| (got[i].as_f64().unwrap() - key[i].as_f64().unwrap() / norm(key)).powi(2))
            .sum();
        assert!(d.sqrt() < 1e-12, "key {k} interpolated: {got} vs {key}");
    }
}

fn norm(v: &Value) -> f64 {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap().powi(2))
        .sum::<f64>()
        .sqrt()
}

#[test]
fn several_curves_in_one_scene() {
    let out = sample(
        r##"{"space":"S2","samples":3,"curves":[
            {"method":"geodesic","points":[[1,0,0],[0,1,0]],"color":"#d55e00"},
            {"method":"nlerp","points":[[1,0,0],[0,0,1]],"knots":[0,4]}]}"##,
        &[],
    );
    let curves = out["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 2);
    assert_eq!(curves[0]["method"], "geodesic");
    assert_eq!(curves[1]["domain"], serde_json::json!([0.0, 4.0]));
    assert_eq!(curves[1]["points"][2], serde_json::json!([0.0, 0.0, 1.0]));
}

#[test]
fn unknown_commands() {
    for args in [&["frobnicate"][..], &[], &["methods", "extra"], &["sample"]] {
        let out = spherekit(args, "");
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);
    }
    assert!(spherekit(&["help"], "").status.success());
}

#[test]
fn render_writes_a_png_and_nothing_for_a_bad_scene() {
    let dir = std::env::temp_dir().join(format!("spherekit-render-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("scene.png");
    let path = out.to_str().unwrap();
    let ok = spherekit(&["render", "-", "-o", path, "--size", "64"], S2_SCENE);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let png = spherekit_cli::decode_png(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!((png.width(), png.height()), (64, 64));
    std::fs::remove_file(&out).unwrap();
    let cases: &[(&str, &[&str], &str)] = &[
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[-1,0,0]]}"#,
            &[],
            "antipodal",
        ),
        (
            S2_SCENE,
            &["--size", "8"],
            "size: 8 is outside 16..=4096 pixels",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"view":{"camera":[0,0,0,0]}}"#,
            &[],
            "view.camera: quaternion has zero length",
        ),
        (
            r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"view":{"zoom":2}}"#,
            &[],
            "view.zoom: unknown view option",
        ),
        (
            r#"{"space":"S5","method":"geodesic","points":[[1,0,0,0,0,0],[0,1,0,0,0,0]]}"#,
            &[],
            "space: S5 scenes cannot be drawn",
        ),
    ];
    for (scene, extra, expected) in cases {
        let mut args = vec!["render", "-", "-o", path];
        args.extend_from_slice(extra);
        let bad = spherekit(&args, scene);
        assert_eq!(bad.status.code(), Some(2), "{scene}");
        let line = String::from_utf8(bad.stderr).unwrap();
        assert_eq!(line.lines().count(), 1, "{line}");
        assert!(
            line.contains(expected),
            "got `{line}`, expected `{expected}`"
        );
        assert!(!out.exists(), "no file is written for a bad scene");
    }
    let missing = spherekit(&["render", "-"], S2_SCENE);
    assert_eq!(missing.status.code(), Some(2));
    std::fs::remove_dir_all(dir).unwrap();
}

/// A scene with two S³ curves: the legend names both, the traced axis and every kind of mark.
const S3_TWO_CURVES: &str = r#"{"space":"S3","curves":[
    {"method":"squad","points":[[1,0,0,0],[0.9239,0,0,0.3827],[0.7071,0.5,0.5,0],[0.5,-0.5,0.5,0.5]],"knots":[0,1,2.5,5.5],"label":"squad & <friends>"},
    {"method":"bezier","points":[[1,0,0,0],[0.9239,0,0,0.3827],[0.7071,0.5,0.5,0],[0.5,-0.5,0.5,0.5]]}],
    "view":{"title":"two curves","plot":"omega"}}"#;

#[test]
fn render_writes_svg_with_every_legend_entry() {
    let dir = std::env::temp_dir().join(format!("spherekit-svg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("figure.svg");
    let path = out.to_str().unwrap();
    let ok = spherekit(&["render", "-", "-o", path, "--size", "300"], S3_TWO_CURVES);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let text = std::fs::read_to_string(&out).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("width"), Some("300"));
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect();
    for entry in [
        "two curves",
        "squad & <friends>",
        "Bézier",
        "(traced: tip of body x)",
        "ω x",
        "ω y",
        "ω z",
        "key",
        "control point",
        "far side",
        "joint",
        "angular speed |ω| (rad per unit t)",
        "t",
    ] {
        assert!(texts.contains(&entry), "no <text> {entry:?} in {texts:?}");
    }
    assert!(
        doc.descendants().any(|n| n.has_tag_name("radialGradient")),
        "the sphere is a radial gradient"
    );
    // --format agrees with the extension, or names a file without one.
    let plain = dir.join("figure");
    let ok = spherekit(
        &[
            "render",
            "-",
            "-o",
            plain.to_str().unwrap(),
            "--format",
            "svg",
            "--size",
            "64",
        ],
        S2_SCENE,
    );
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    assert!(std::fs::read_to_string(&plain).unwrap().contains("<svg"));
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn render_refuses_extensions_it_cannot_write() {
    let dir = std::env::temp_dir().join(format!("spherekit-ext-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, extra, expected) in [
        (
            "figure.jpg",
            &[][..],
            "cannot write .jpg files (render writes .png and .svg)",
        ),
        ("figure.pdf", &[][..], "cannot write .pdf files"),
        (
            "figure.png",
            &["--format", "svg"][..],
            "does not match --format svg",
        ),
        (
            "figure.svg",
            &["--format", "gif"][..],
            "--format: \"gif\" is not a format",
        ),
    ] {
        let out = dir.join(name);
        let mut args = vec!["render", "-", "-o", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let bad = spherekit(&args, S2_SCENE);
        assert_eq!(bad.status.code(), Some(2), "{name}");
        let line = String::from_utf8(bad.stderr).unwrap();
        assert_eq!(line.lines().count(), 1, "{line}");
        assert!(
            line.contains(expected),
            "got `{line}`, expected `{expected}`"
        );
        assert!(!out.exists(), "nothing is written under {name}");
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn sample_of_keys_with_rates_passes_through_every_key_with_its_rate() {
    // The example scene: attitudes with the body rates a gyroscope measured at each.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/hermite-rates.json"
    );
    let scene: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let knots = scene["knots"].as_array().unwrap();
    let at: Vec<String> = knots.iter().map(Value::to_string).collect();
    let out = spherekit(
        &[
            "sample",
            path,
            "--deriv",
            "--frame",
            "body",
            "--at",
            &at.join(","),
        ],
        "",
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out: Value = serde_json::from_slice(&out.stdout).unwrap();
    let rows = |v: &Value| -> Vec<Vec<f64>> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|r| {
                r.as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect()
            })
            .collect()
    };
    let (keys, rates) = (rows(&scene["points"]), rows(&scene["params"]["velocities"]));
    let (points, omega) = (rows(&out["points"]), rows(&out["angular_velocity"]));
    assert_eq!(points.len(), keys.len());
    for (k, (key, p)) in keys.iter().zip(&points).enumerate() {
        let norm = key.iter().map(|x| x * x).sum::<f64>().sqrt();
        let d = key
            .iter()
            .zip(p)
            .map(|(a, b)| (a / norm - b).abs())
            .fold(0.0, f64::max);
        assert!(d < 1e-12, "key {k}: {d:e}");
        let d = rates[k]
            .iter()
            .zip(&omega[k])
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(d < 1e-12, "rate {k}: {d:e}");
    }
    assert_eq!(out["info"]["iterations"], 0, "no solve");
    // One rate short: one line naming the field.
    let mut short = scene.clone();
    short["params"]["velocities"].as_array_mut().unwrap().pop();
    let line = reject(&short.to_string(), &[]);
    assert_eq!(
        line,
        "error: params.velocities: must have one velocity per point: expected 4, got 3"
    );
}

/// Noisy samples of a circle of latitude at 0.1 s, fitted with λ given and by key count.
#[test]
fn sample_prints_the_fit_report() {
    let points: Vec<Value> = (0..20)
        .map(|i| {
            let t = 0.1 * f64::from(i);
            serde_json::json!([t.cos(), t.sin(), 0.4 + 0.01 * (f64::from(i) * 2.9).sin()])
        })
        .collect();
    let knots: Vec<f64> = (0..20).map(|i| 0.1 * f64::from(i)).collect();
    let scene = serde_json::json!({ "space": "S2", "method": "cubic", "points": points,
                                    "knots": knots, "fit": { "smoothing": 0.001 } });
    let out = sample(&scene.to_string(), &[]);
    let fit = &out["info"]["fit"];
    assert_eq!(fit["lambda"], 0.001);
    assert_eq!(fit["keys"], 20);
    assert_eq!(fit["key_times"], serde_json::json!(knots));
    assert_eq!(fit["residuals"].as_array().unwrap().len(), 20);
    let (rms, max) = (fit["rms"].as_f64().unwrap(), fit["max"].as_f64().unwrap());
    assert!(0.0 < rms && rms <= max && max < 0.02, "{fit}");
    assert!(fit["iterations"].as_u64().unwrap() >= 1);
    assert!(fit["edf"].as_f64().unwrap() > 2.0, "{fit}");
    // Fewer keys: no effective degrees of freedom.
    let mut scene = scene;
    scene["fit"] = serde_json::json!({ "keys": 5 });
    let fit = &sample(&scene.to_string(), &[])["info"]["fit"];
    assert_eq!(fit["keys"], 5);
    assert_eq!(fit["lambda"], 0.0);
    assert!(fit.get("edf").is_none(), "{fit}");
    assert_eq!(
        reject(&scene.to_string().replace("\"keys\":5", "\"keys\":50"), &[]),
        "error: fit.keys: must be between 2 and the number of samples, 20; got 50"
    );
    // The registry describes the fit object of the cubic.
    let methods = spherekit(&["methods", "--json"], "");
    let registry: Value = serde_json::from_slice(&methods.stdout).unwrap();
    let cubic = registry
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["id"] == "cubic")
        .unwrap();
    assert_eq!(cubic["fit"][0]["name"], "smoothing");
}
