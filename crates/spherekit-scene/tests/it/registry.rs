// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Every registered method is complete: a golden scene, a section in the method gallery,
//! robustness cases; its descriptor agrees with what the construction accepts.

use std::path::PathBuf;

use serde_json::json;
use spherekit_scene::{KnotRule, METHODS, MIN_CLOSED_POINTS, ParamKind, Scene, Spaces};

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn golden_scenes() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(repo().join("tests/golden")).expect("tests/golden") {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "json") {
            let name = path
                .file_name()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            out.push((name, std::fs::read_to_string(&path).expect("golden scene")));
        }
    }
    out
}

#[test]
fn ids_are_unique_and_found() {
    for (i, m) in METHODS.iter().enumerate() {
        assert!(
            METHODS[..i].iter().all(|o| o.id != m.id),
            "{} registered twice",
            m.id
        );
        assert_eq!(spherekit_scene::Method::find(m.id).map(|f| f.id), Ok(m.id));
        assert!(!m.summary.is_empty() && !m.source.is_empty(), "{}", m.id);
    }
}

#[test]
fn every_method_has_a_golden_scene() {
    let scenes = golden_scenes();
    for m in METHODS {
        let found = scenes.iter().any(|(_, text)| {
            Scene::from_json(text).is_ok_and(|s| s.curves.iter().any(|c| c.method.id == m.id))
        });
        assert!(
            found,
            "method {} has no golden scene in tests/golden/",
            m.id
        );
    }
}

#[test]
fn every_method_has_a_gallery_section() {
    let docs = std::fs::read_to_string(repo().join("web/docs.html")).expect("web/docs.html");
    for m in METHODS {
        let section = format!("data-method=\"{}\"", m.id);
        assert!(
            docs.contains(&section),
            "web/docs.html has no section {section}"
        );
        let widget = format!("\"method\":\"{}\"", m.id);
        assert!(
            docs.contains(&widget),
            "web/docs.html has no widget of {}",
            m.id
        );
    }
}

#[test]
fn every_method_has_robustness_cases() {
    let dir = repo().join("tests/robustness/degenerate");
    let names: Vec<String> = std::fs::read_dir(&dir)
        .expect("tests/robustness/degenerate")
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .collect();
    for m in METHODS {
        let prefix = format!("{}_", m.id.replace('-', "_"));
        let count = names.iter().filter(|n| n.starts_with(&prefix)).count();
        assert!(
            count >= 10,
            "method {} has {count} robustness cases in tests/robustness/degenerate (run `just corpus`)",
            m.id
        );
    }
}

/// Points of `space` along a spiral, distinct and far from antipodal.
fn points(space: &str, n: usize) -> Vec<Vec<f64>> {
    (0..n)
        .map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let a = 0.4 * i as f64;
            let (s, c) = a.sin_cos();
            match space {
                "S2" => vec![c, s, 0.3 + 0.1 * a],
                "S3" => vec![1.0, 0.3 * c, 0.3 * s, 0.1 * a],
                _ => vec![c, s, 0.2, 0.1 * a, 0.3, -0.2],
            }
        })
        .collect()
}

/// `n` points of `space` around a loop (a small circle, or its analogue), for closed curves.
fn loop_points(space: &str, n: usize) -> Vec<Vec<f64>> {
    (0..n)
        .map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let a = core::f64::consts::TAU * (i as f64 + 0.1 * (i % 2) as f64) / n as f64;
            let (s, c) = a.sin_cos();
            match space {
                "S2" => vec![c, s, 1.2],
                "S3" => vec![1.0, 0.4 * c, 0.4 * s, 0.2],
                _ => vec![c, s, 1.0, 0.2, 0.3, -0.2],
            }
        })
        .collect()
}

#[test]
fn descriptors_match_the_constructions() {
    for m in METHODS {
        let spaces: &[&str] = match m.spaces {
            Spaces::All => &["S2", "S3", "S5"],
            Spaces::S3 => &["S3"],
            Spaces::S2 => &["S2"],
        };
        for space in spaces {
            let build = |n: usize, knots: Option<Vec<f64>>| {
                let mut scene =
                    json!({ "space": space, "method": m.id, "points": points(space, n) });
                if let Some(k) = knots {
                    scene["knots"] = json!(k);
                }
                Scene::from_json(&scene.to_string()).and_then(|s| s.build())
            };
            let n = m.min_points.max(5);
            assert!(
                build(n, None).is_ok(),
                "{} {space}: {:?}",
                m.id,
                build(n, None).err()
            );
            // The minimum point count is the construction's.
            assert!(
                build(m.min_points, None).is_ok(),
                "{} {space} at min_points",
                m.id
            );
            let fewer = build(m.min_points - 1, None).expect_err("fewer points than the minimum");
            assert!(
                fewer.to_string().starts_with("points"),
                "{} {space}: {fewer}",
                m.id
            );
            // The knot rule's count is the one the construction takes.
            if let Some(count) = m.knots.count(n) {
                #[expect(clippy::cast_precision_loss, reason = "small counts")]
                let knots: Vec<f64> = (0..count).map(|i| i as f64 * 0.7).collect();
                assert!(
                    build(n, Some(knots.clone())).is_ok(),
                    "{} {space} with knots",
                    m.id
                );
                let mut more = knots;
                more.push(1e3);
                assert!(
                    build(n, Some(more)).is_err(),
                    "{} {space}: one knot too many",
                    m.id
                );
            } else {
                assert!(
                    build(n, Some(vec![0.0; n])).is_err(),
                    "{} takes no knots",
                    m.id
                );
                assert!(matches!(m.knots, KnotRule::Computed | KnotRule::None));
            }
        }
    }
}

/// Every method that closes does so on every sphere it works on: the minimum point count and
/// the knot count of a loop are the construction's, the curve returns to its first point with
/// the same jet, the seam is the last joint of the continuity report and as smooth as the other
/// joints; a method that does not close says so on `closed`.
#[test]
fn closed_descriptors_match_the_constructions() {
    for m in METHODS {
        let spaces: &[&str] = match m.spaces {
            Spaces::All => &["S2", "S3", "S5"],
            Spaces::S3 => &["S3"],
            Spaces::S2 => &["S2"],
        };
        for space in spaces {
            let build = |n: usize, knots: Option<Vec<f64>>| {
                let mut scene = json!({ "space": space, "method": m.id,
                                        "points": loop_points(space, n), "closed": true });
                if let Some(k) = knots {
                    scene["knots"] = json!(k);
                }
                Scene::from_json(&scene.to_string()).and_then(|s| s.build())
            };
            if !m.closes {
                let e = build(6, None).expect_err("no closed form");
                assert!(
                    e.to_string().starts_with("closed: "),
                    "{} {space}: {e}",
                    m.id
                );
                continue;
            }
            for n in [MIN_CLOSED_POINTS, 6] {
                let curves = build(n, None)
                    .unwrap_or_else(|e| panic!("{} {space} closed, {n} points: {e}", m.id));
                let (report, _) = curves[0].continuity();
                let (joints, seam, start, end) = match &curves[0] {
                    spherekit_scene::BuiltCurve::S2(b) => seam(&*b.curve),
                    spherekit_scene::BuiltCurve::S3(b) => seam(&*b.curve),
                    spherekit_scene::BuiltCurve::Sm(b) => seam(&*b.curve),
                };
                assert_eq!(
                    report.len(),
                    joints - 1,
                    "{} {space}: the seam is a joint",
                    m.id
                );
                assert!(
                    seam < 1e-12,
                    "{} {space}: returns to its start ({seam:e})",
                    m.id
                );
                let worst = report[..report.len() - 1]
                    .iter()
                    .fold(0.0_f64, |a, j| a.max(j.c1 / start.max(1e-300)));
                let at_seam = report[report.len() - 1].c1 / end.max(1e-300);
                // As smooth at the seam as at the other joints (C⁰ methods: no better).
                assert!(
                    at_seam <= worst.max(1e-10) * 10.0,
                    "{} {space}: velocity jump {at_seam:e} at the seam, {worst:e} elsewhere",
                    m.id
                );
            }
            let fewer = build(MIN_CLOSED_POINTS - 1, None).expect_err("too few points for a loop");
            assert!(
                fewer.to_string().starts_with("points"),
                "{} {space}: {fewer}",
                m.id
            );
            let n = 6;
            if let Some(count) = m.knots.count_for(n, true) {
                assert_eq!(count, n + 1, "a loop has one knot more than points");
                #[expect(clippy::cast_precision_loss, reason = "small counts")]
                let knots: Vec<f64> = (0..count).map(|i| i as f64 * 0.7).collect();
                assert!(
                    build(n, Some(knots.clone())).is_ok(),
                    "{} {space} closed with knots: {:?}",
                    m.id,
                    build(n, Some(knots.clone())).err()
                );
                for bad in [knots[..n].to_vec(), [knots.clone(), vec![1e3]].concat()] {
                    let e = build(n, Some(bad)).expect_err("wrong knot count");
                    assert!(
                        e.to_string().starts_with("knots: "),
                        "{} {space}: {e}",
                        m.id
                    );
                }
                let mut flat = knots;
                flat[3] = flat[2];
                let e = build(n, Some(flat)).expect_err("non-increasing knots");
                assert!(
                    e.to_string().starts_with("knots[3]"),
                    "{} {space}: {e}",
                    m.id
                );
            }
            // An antipodal closing pair is refused, naming the field.
            let mut pts = loop_points(space, 6);
            pts[5] = pts[0].iter().map(|x| -x).collect();
            let mut scene =
                json!({ "space": space, "method": m.id, "points": pts, "closed": true });
            if *space == "S3" {
                // Kept as given: canonicalising would flip the last key next to the first.
                scene["canonicalize"] = json!(false);
            }
            let e = Scene::from_json(&scene.to_string())
                .and_then(|s| s.build())
                .expect_err("antipodal closing pair");
            assert!(
                e.to_string().starts_with("closed: "),
                "{} {space}: {e}",
                m.id
            );
        }
    }
}

/// The number of joints, the point jump at the seam and the speeds at the start and the end.
fn seam<P: spherekit::Manifold>(
    c: &(dyn spherekit::Curve<Point = P> + Send + Sync),
) -> (usize, f64, f64, f64) {
    use spherekit::{Ambient, Side};
    let [t0, t1] = c.domain();
    let (a, b) = (c.jet_at(t1, Side::Left), c.jet_at(t0, Side::Right));
    (
        c.joints().len(),
        (a.point.to_vector() - b.point.to_vector()).length(),
        b.velocity.length(),
        a.velocity.length(),
    )
}

#[test]
fn every_parameter_default_is_accepted() {
    for m in METHODS {
        for p in m.params {
            let space = if p.spaces == Spaces::S3 || m.spaces == Spaces::S3 {
                "S3"
            } else {
                "S2"
            };
            let value = match p.kind {
                // Absent by default: the construction's own choice.
                ParamKind::Number { default, .. } if default.is_nan() => continue,
                ParamKind::Integer { default, min, .. } if default < min => continue,
                ParamKind::Number { default, .. } => json!(default),
                ParamKind::Integer { default, .. } => json!(default),
                ParamKind::Bool { default } => json!(default),
                ParamKind::Choice(choices) => json!(choices[0]),
                ParamKind::Vector | ParamKind::Vectors => continue,
            };
            let scene = json!({ "space": space, "method": m.id, "points": points(space, 6),
                                "params": { p.name: value } });
            let built = Scene::from_json(&scene.to_string()).and_then(|s| s.build());
            assert!(
                built.is_ok(),
                "{}.{} = {value}: {:?}",
                m.id,
                p.name,
                built.err()
            );
        }
    }
}
