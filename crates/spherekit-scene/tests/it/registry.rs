// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Every registered method is complete: a golden scene, a section in the method gallery,
//! robustness cases; its descriptor agrees with what the construction accepts.

use std::path::PathBuf;

use serde_json::json;
use spherekit_scene::{KnotRule, METHODS, ParamKind, Scene, Spheres};

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

#[test]
fn descriptors_match_the_constructions() {
    for m in METHODS {
        let spaces: &[&str] = match m.spheres {
            Spheres::All => &["S2", "S3", "S5"],
            Spheres::S3 => &["S3"],
            Spheres::S2 => &["S2"],
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

#[test]
fn every_parameter_default_is_accepted() {
    for m in METHODS {
        for p in m.params {
            let space = if p.spheres == Spheres::S3 || m.spheres == Spheres::S3 {
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
                ParamKind::Vector => continue,
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
