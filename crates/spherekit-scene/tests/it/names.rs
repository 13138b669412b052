// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Earlier spellings a scene may still use: a method id with underscores (`arc_blend`) and a
//! parameter's earlier name (`order` for `smoothness`). They give the same curve as the
//! current names, and the registry lists the current names only.

use serde_json::{Value, json};
use spherekit_scene::{Document, METHODS, Method, Scene, registry_json};

/// The samples (with derivatives) of a scene, as text: equal texts are equal bits.
fn samples(scene: &Value) -> String {
    let scene = Scene::from_value(scene).unwrap_or_else(|e| panic!("{scene}: {e}"));
    let curves = scene.build().unwrap_or_else(|e| panic!("{e}"));
    scene.sample_json(&curves, true).to_string()
}

#[test]
fn underscored_ids_find_the_hyphenated_method() {
    let mut spelled = 0;
    for m in METHODS {
        let snake = m.id.replace('-', "_");
        assert_eq!(Method::find(&snake).map(|f| f.id), Ok(m.id), "{snake}");
        spelled += usize::from(snake != m.id);
    }
    assert!(spelled >= 5, "{spelled} ids have a snake_case spelling");
    // Only `-` and `_` are interchangeable.
    assert!(Method::find("arc blend").is_err());
    assert!(Method::find("arc-blend-").is_err());
    let scene = json!({"space": "S2", "method": "catmull-rom", "samples": 9,
        "points": [[1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0.2], [0, -1, 0.3]]});
    let mut snake = scene.clone();
    snake["method"] = json!("catmull_rom");
    assert_eq!(samples(&snake), samples(&scene));
}

#[test]
fn order_is_read_as_smoothness() {
    for (space, points) in [
        (
            "S2",
            json!([
                [1, 0, 0.3],
                [0.6, 0.8, 0.4],
                [-0.2, 1, 0.1],
                [-0.9, 0.3, -0.2]
            ]),
        ),
        (
            "S3",
            json!([
                [1, 0, 0, 0],
                [0.9, 0.4, 0, 0.2],
                [0.5, 0.5, 0.5, -0.5],
                [0, 0.3, 0.9, 0.2]
            ]),
        ),
    ] {
        for method in ["arc-blend", "corner-blend"] {
            let scene = |params: Value| {
                json!({"space": space, "method": method, "points": points, "samples": 17,
                       "params": params})
            };
            let now = samples(&scene(json!({"smoothness": 3})));
            assert_eq!(
                samples(&scene(json!({"order": 3}))),
                now,
                "{method} on {space}"
            );
            // Not the default: the parameter was read.
            assert_ne!(samples(&scene(json!({}))), now, "{method} on {space}");
            let both = Scene::from_value(&scene(json!({"order": 3, "smoothness": 3})))
                .expect_err("both names");
            assert_eq!(
                both.to_string(),
                "params.order: is the earlier name of params.smoothness: give one of them"
            );
        }
    }
}

#[test]
fn the_registry_lists_current_names_only() {
    let registry = registry_json().to_string();
    assert!(registry.contains("\"smoothness\""));
    assert!(!registry.contains("\"order\""));
    assert!(!registry.contains("arc_blend"));
}

#[test]
fn editing_a_parameter_replaces_its_earlier_name() {
    let text = r#"{"space":"S2","method":"arc_blend","params":{"order":3},
        "points":[[1,0,0.3],[0.6,0.8,0.4],[-0.2,1,0.1],[-0.9,0.3,-0.2]]}"#;
    let mut doc = Document::from_json(text).expect("old spellings");
    doc.set_param(0, "smoothness", json!(4))
        .expect("the new name");
    let now: Value = serde_json::from_str(&doc.to_json()).expect("json");
    assert_eq!(now["params"], json!({"smoothness": 4}));
    doc.set_param(0, "order", json!(2)).expect("the old name");
    let now: Value = serde_json::from_str(&doc.to_json()).expect("json");
    assert_eq!(now["params"], json!({"order": 2}));
    // Another method with the parameter keeps it, under either name.
    doc.set_method(0, "corner-blend").expect("corner blend");
    let now: Value = serde_json::from_str(&doc.to_json()).expect("json");
    assert_eq!(now["params"], json!({"order": 2}));
}
