// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The robustness corpus (`tests/robustness/`, see ROBUSTNESS.md):
//!
//! - `degenerate/NAME.ok.json`: valid but degenerate geometry; the scene must build, and every
//!   curve must give a finite point of unit norm with finite derivatives at every sample (both
//!   one-sided jets) and render without panicking;
//! - `degenerate/NAME.err.json` + `NAME.err.txt`: the mathematics has no answer; building must
//!   fail with an error line containing the text of the sidecar file;
//! - `bad/NAME.json` + `bad/NAME.txt`: malformed scenes; `spherekit sample` must exit 2 with one
//!   line on stderr containing the sidecar's text, and print nothing on stdout.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde_json::json;
use spherekit_scene::{METHODS, Scene, Spaces};

use crate::robust::{Outcome, check_scene};

fn corpus_dir(sub: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/robustness")
        .join(sub)
}

/// The files of `dir` whose names end with `suffix`, sorted.
fn files(dir: &Path, suffix: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.to_string_lossy().ends_with(suffix))
        .collect();
    v.sort();
    v
}

fn expected_text(path: &Path) -> String {
    std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .trim_end_matches('\n')
        .to_owned()
}

/// Builds, samples and renders a scene that must succeed.
fn check_ok(text: &str) -> Result<(), String> {
    match check_scene(text, Some(32))? {
        Outcome::Ok => Ok(()),
        Outcome::Rejected(e) => Err(format!("rejected: {e}")),
    }
}

/// The error line of a scene that must fail to build.
fn build_error(text: &str) -> Result<String, String> {
    let scene = Scene::from_json(text).map_err(|e| format!("parse: {e}"))?;
    match scene.build() {
        Ok(_) => Err("built, but an error was expected".into()),
        Err(e) => Ok(e.to_string()),
    }
}

#[test]
fn degenerate_corpus() {
    let dir = corpus_dir("degenerate");
    let mut failures = Vec::new();
    let ok = files(&dir, ".ok.json");
    let err = files(&dir, ".err.json");
    assert!(ok.len() + err.len() >= 300, "corpus is missing");
    for path in &ok {
        let text = std::fs::read_to_string(path).unwrap();
        let outcome =
            std::panic::catch_unwind(|| check_ok(&text)).unwrap_or_else(|_| Err("panicked".into()));
        if let Err(e) = outcome {
            failures.push(format!("{}: {e}", path.display()));
        }
    }
    for path in &err {
        let text = std::fs::read_to_string(path).unwrap();
        let sidecar = PathBuf::from(path.to_string_lossy().replace(".err.json", ".err.txt"));
        let want = expected_text(&sidecar);
        let outcome = std::panic::catch_unwind(|| build_error(&text))
            .unwrap_or_else(|_| Err("panicked".into()));
        match outcome {
            Ok(line) if line.contains(&want) && !line.contains('\n') => {}
            Ok(line) => failures.push(format!(
                "{}: error \"{line}\" does not contain \"{want}\"",
                path.display()
            )),
            Err(e) => failures.push(format!("{}: {e}", path.display())),
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} corpus cases failed:\n{}",
        failures.len(),
        ok.len() + err.len(),
        failures.join("\n")
    );
}

/// `n` points about 0.7 rad apart winding around the sphere with `coords` coordinates.
fn winding(coords: usize, n: usize) -> Vec<Vec<f64>> {
    (0..n)
        .map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "i < 10 000")]
            let i = i as f64;
            let (a, b) = (0.7 * i + 0.1, 0.45 * (1.3 * i + 1.0).sin());
            let mut p = vec![a.cos() * b.cos(), a.sin() * b.cos(), b.sin()];
            p.resize(coords, 0.3);
            p
        })
        .collect()
}

/// A seeded random walk of `n` unit points with `coords` coordinates, steps of 0.05–0.5 rad in
/// random directions (the sequences on which the book's arc-blend knots used to overflow).
fn random_walk(coords: usize, n: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut state = seed;
    let mut uniform = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        #[expect(clippy::cast_precision_loss, reason = "53 random bits")]
        let u = (state >> 11) as f64 / (1u64 << 53) as f64;
        u
    };
    let mut p = vec![0.0; coords];
    p[0] = 1.0;
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        out.push(p.clone());
        // A random tangent direction: a random vector minus its component along p.
        let mut d: Vec<f64> = (0..coords).map(|_| uniform() - 0.5).collect();
        let dot: f64 = d.iter().zip(&p).map(|(a, b)| a * b).sum();
        d.iter_mut().zip(&p).for_each(|(a, b)| *a -= dot * b);
        let len = d.iter().map(|a| a * a).sum::<f64>().sqrt();
        let step = 0.05 + 0.45 * uniform();
        let (s, c) = step.sin_cos();
        p = p.iter().zip(&d).map(|(a, b)| c * a + s * b / len).collect();
    }
    out
}

/// Random walks of 100 000 keys on S² and S³ for every method whose cost is linear in the keys
/// (the single-piece Bézier curves are left to `ten_thousand_keys`): built, sampled with
/// derivatives, and the continuity report computed at every joint through the scene layer.
#[test]
fn hundred_thousand_key_random_walks() {
    let mut failures = Vec::new();
    for method in METHODS.iter().filter(|m| !m.single_piece) {
        let spaces: &[(&str, usize)] = match method.spaces {
            Spaces::All => &[("S2", 3), ("S3", 4)],
            Spaces::S3 => &[("S3", 4)],
            Spaces::S2 => &[("S2", 3)],
        };
        for &(space, coords) in spaces {
            let scene = json!({
                "space": space, "method": method.id, "points": random_walk(coords, 100_000, 7),
                "samples": 101,
            });
            match check_scene(&scene.to_string(), None) {
                Ok(Outcome::Ok) => {}
                Ok(Outcome::Rejected(e)) => {
                    failures.push(format!("{} {space}: rejected: {e}", method.id));
                }
                Err(e) => failures.push(format!("{} {space}: {e}", method.id)),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Very long sequences: 10 000 keys for every method and space. `bezier` is one curve of degree
/// n − 1 evaluated by the de Casteljau triangle, O(n²) slerps per evaluation (7.4 s per jet at
/// 10 000 keys in release), so it gets 300 keys here; `bezier-kim` (O(n²) flops, 21 ms per jet
/// in release) gets 10 000 keys but 3 samples. Neither is rendered.
#[test]
fn ten_thousand_keys() {
    let mut failures = Vec::new();
    for method in METHODS {
        let spaces: &[(&str, usize)] = match method.spaces {
            Spaces::All => &[("S2", 3), ("S3", 4), ("S5", 6)],
            Spaces::S3 => &[("S3", 4)],
            Spaces::S2 => &[("S2", 3)],
        };
        let one_curve = method.single_piece;
        // De Casteljau's triangle on S^m: O(n²) slerps per evaluation.
        let n = if one_curve && method.spaces == Spaces::All {
            300
        } else {
            10_000
        };
        let samples = if one_curve { 3 } else { 1001 };
        for &(space, coords) in spaces {
            let scene = json!({
                "space": space, "method": method.id, "points": winding(coords, n),
                "samples": samples,
            });
            let render = (space == "S2" && !one_curve).then_some(32);
            match check_scene(&scene.to_string(), render) {
                Ok(Outcome::Ok) => {}
                Ok(Outcome::Rejected(e)) => {
                    failures.push(format!("{} {space}: rejected: {e}", method.id));
                }
                Err(e) => failures.push(format!("{} {space}: {e}", method.id)),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn spherekit_cli(args: &[&str], stdin: &[u8]) -> std::process::Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_spherekit"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The tool may stop reading early (a parse error): a broken pipe here is not a failure.
    if let Err(e) = child.stdin.take().unwrap().write_all(stdin) {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().unwrap()
}

/// The malformed-scene catalog: `spherekit sample` and `spherekit render` exit 2 with one line
/// naming the problem (the sidecar `.txt` holds a substring of it), and write nothing.
#[test]
fn bad_scene_catalog() {
    let dir = corpus_dir("bad");
    let scenes = files(&dir, ".json");
    assert!(scenes.len() >= 40, "only {} bad scenes", scenes.len());
    let png = std::env::temp_dir().join(format!("spherekit-bad-{}.png", std::process::id()));
    let png_arg = png.to_string_lossy().into_owned();
    let mut failures = Vec::new();
    for path in &scenes {
        let want = expected_text(&path.with_extension("txt"));
        let bytes = std::fs::read(path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        // `view` is read by the renderer only: `sample` ignores it (files named `render_*`).
        let commands = [
            &["sample", "-", "--deriv"][..],
            &["render", "-", "-o", &png_arg, "--size", "16"][..],
        ];
        let skip = usize::from(name.starts_with("render_"));
        for args in &commands[skip..] {
            let out = spherekit_cli(args, &bytes);
            let stderr = String::from_utf8_lossy(&out.stderr);
            let ok = out.status.code() == Some(2)
                && out.stdout.is_empty()
                && stderr.lines().count() == 1
                && stderr.starts_with("error: ")
                && stderr.contains(&want)
                && !stderr.contains("panicked");
            if !ok {
                failures.push(format!(
                    "{name} ({}): status {:?}, stderr {stderr:?}, expected {want:?}",
                    args[0],
                    out.status.code()
                ));
            }
        }
        assert!(!png.exists(), "{name}: render wrote a file for a bad scene");
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The same catalog through the library: `Scene::from_json` + `build` + `render` report one
/// line and do not panic (this is what the golden harness and the wasm crate call).
#[test]
fn bad_scene_catalog_in_process() {
    for path in files(&corpus_dir("bad"), ".json") {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        let want = expected_text(&path.with_extension("txt"));
        match check_scene(&text, Some(16)) {
            Ok(Outcome::Rejected(e)) => assert!(
                // The CLI adds its own messages only for files it cannot read as text.
                e.contains(&want) || std::str::from_utf8(&bytes).is_err(),
                "{}: {e:?} does not contain {want:?}",
                path.display()
            ),
            other => panic!("{}: {other:?}", path.display()),
        }
    }
}

/// The golden harness reports a bad scene as `GoldenError::Scene` (no panic).
#[test]
fn golden_harness_reports_a_bad_scene() {
    use spherekit_cli::golden::{GoldenError, check, render_scene_file};
    let path = corpus_dir("bad").join("points_nan_literal.json");
    match render_scene_file(&path) {
        Err(GoldenError::Scene { name, message }) => {
            assert_eq!(name, "points_nan_literal");
            assert!(message.contains("invalid scene JSON"), "{message}");
        }
        other => panic!("expected GoldenError::Scene, got {other:?}"),
    }
    let path = corpus_dir("bad").join("points_zero_vector.json");
    match render_scene_file(&path) {
        Err(GoldenError::Scene { message, .. }) => {
            assert!(message.contains("points[1]"), "{message}");
        }
        other => panic!("expected GoldenError::Scene, got {other:?}"),
    }
    assert!(matches!(
        check("no such scene"),
        Err(GoldenError::Scene { .. })
    ));
}

/// Fuzz finding (`scene_bytes`, 2026-11-22): an unknown field whose name holds a JSON-escaped
/// newline made the error message two lines (serde quotes the name as is). `SceneError`'s
/// `Display` now escapes control characters. The fuzzer's literal input:
#[test]
fn fuzz_regression_unknown_field_with_escaped_newline_is_one_line() {
    let input = "{\n  \"space\": \"S2\",\n  \"method\": \"geodesic\",\n  \"poi\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\\nts\": [[1, 0, 0.2], [0.3, 1, 0.5], [-0.5, 0.3, 1], [-1, -0.6, 0, 1, 1.5, 3, 3.5],\n  \"view\": { \"plot\": \"speed\" }\n}\n";
    let e = Scene::from_json(input).unwrap_err().to_string();
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(e.contains("unknown field `poi\\\\"), "{e}");
    assert!(e.contains("\\nts`"), "{e}");
    let out = spherekit_cli(&["sample", "-"], input.as_bytes());
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);
}

/// `MAX_SAMPLES` bounds the evaluations of the whole scene: `--samples` on a `curves` list is
/// checked against the product too.
#[test]
fn samples_limit_counts_every_curve() {
    let scene = r#"{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]]},
        {"method":"nlerp","points":[[1,0,0],[0,1,0]]}]}"#;
    let out = spherekit_cli(&["sample", "-", "--samples", "600000"], scene.as_bytes());
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        stderr.trim_end(),
        "error: --samples: 2 curves × 600000 parameters exceed the limit of 1000000 evaluations per scene"
    );
    let mut s = Scene::from_json(scene).unwrap();
    assert!(s.set_samples(500_000).is_ok());
}

/// Fuzz finding (`scene_bytes`, 2026-11-22): knots 1e-96 apart gave accelerations near 1e192,
/// whose difference's norm overflowed in the continuity report (`c2: null` in the JSON); knots
/// 1e-160 apart overflowed the accelerations themselves, 5e-324 apart the velocities and
/// Catmull-Rom's control points. Knot spacings are now limited to
/// `MIN_KNOT_SPACING ..= MAX_KNOT_SPACING`, and `Ambient::length` rescales when the sum of
/// squares overflows.
#[test]
fn fuzz_regression_tiny_knot_spacing() {
    use spherekit::glam::DVec3;
    use spherekit::{Ambient, Knots, MAX_KNOT_SPACING, MIN_KNOT_SPACING, SplineError};
    let input =
        std::fs::read_to_string(corpus_dir("bad").join("knots_spacing_1e-96.json")).unwrap();
    let e = Scene::from_json(&input)
        .unwrap()
        .build()
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "knots[1] − knots[0] must be from 1e-50 to 1e50: derivatives would overflow"
    );
    assert!(Knots::try_new(vec![0.0, MIN_KNOT_SPACING, 1.0]).is_ok());
    assert!(Knots::try_new(vec![0.0, MAX_KNOT_SPACING]).is_ok());
    assert_eq!(
        Knots::try_new(vec![-1e308, 1e308]),
        Err(SplineError::KnotSpacing { index: 1 })
    );
    // The norm of a finite vector is finite when it is representable.
    let v = DVec3::new(3e200, -4e200, 0.0);
    assert!((Ambient::length(&v) / 5e200 - 1.0).abs() < 1e-15);
    assert_eq!(Ambient::length(&DVec3::new(3.0, 4.0, 0.0)), 5.0);
    // Near the limits (JSON parsing may be 1 ulp off the constants) every method with knots stays finite, continuity report included.
    for (method, space, points, knots) in [
        (
            "catmull-rom",
            "S2",
            "[[1,0,0],[0.6,0.8,0],[0,0.6,0.8],[0.8,0,0.6],[0,1,0]]",
            "[0,2e-50,5e49]",
        ),
        (
            "geodesic",
            "S2",
            "[[1,0,0],[0.6,0.8,0],[0,0.6,0.8],[0.8,0,0.6]]",
            "[0,2e-50,5e49,9e49]",
        ),
        (
            "nlerp",
            "S2",
            "[[1,0,0],[0.6,0.8,0],[0,0.6,0.8],[0.8,0,0.6]]",
            "[0,5e49,5e49,9e49]",
        ),
        (
            "squad",
            "S3",
            "[[1,0,0,0],[0.8,0.6,0,0],[0.6,0,0.8,0],[0.6,0,0,0.8]]",
            "[0,2e-50,5e49,9e49]",
        ),
        (
            "gamma",
            "S3",
            "[[1,0,0,0],[0.8,0.6,0,0],[0.6,0,0.8,0],[0.6,0,0,0.8],[0,1,0,0]]",
            "[0,2e-50,5e49]",
        ),
        (
            "catmull-rom",
            "S3",
            "[[1,0,0,0],[0.8,0.6,0,0],[0.6,0,0.8,0],[0.6,0,0,0.8],[0,1,0,0]]",
            "[0,2e-50,2e-50]",
        ),
    ] {
        let scene = format!(
            r#"{{"space":"{space}","method":"{method}","points":{points},"knots":{knots},"samples":33}}"#
        );
        match check_scene(&scene, Some(16)) {
            Ok(Outcome::Ok) => {}
            Ok(Outcome::Rejected(e))
                if knots == "[0,2e-50,2e-50]" || knots.contains("5e49,5e49") =>
            {
                assert!(e.contains("knots[2]"), "{e}");
            }
            other => panic!("{method} {knots}: {other:?}"),
        }
    }
}
