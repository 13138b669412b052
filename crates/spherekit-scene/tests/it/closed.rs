// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Editing closed curves: a loop's knots (one more than points) and per-joint lists (one entry
//! per point) follow inserted and removed points, for the methods whose open lists skip the end
//! points (Catmull-Rom's knots, Gamma's γ).

use serde_json::json;
use spherekit_scene::Document;

#[test]
fn a_loops_knots_and_per_joint_lists_follow_point_edits() {
    let points = json!([
        [1, 0, 0.5],
        [0.3, 0.9, 0.8],
        [-0.8, 0.6, 0.3],
        [-0.8, -0.6, 0.7]
    ]);
    let scene = json!({ "space": "S2", "method": "catmull-rom", "closed": true,
                        "points": points, "knots": [0, 1, 2, 4, 5] });
    let mut doc = Document::from_json(&scene.to_string()).unwrap();
    doc.insert_point(0, 4, &[0.3, -0.9, 0.4]).unwrap();
    // The new last point gets a knot midway to the time of the return.
    assert_eq!(doc.curve(0).unwrap()["knots"], json!([0, 1, 2, 4, 4.5, 5]));
    doc.remove_point(0, 1).unwrap();
    assert_eq!(doc.curve(0).unwrap()["knots"], json!([0, 2, 4, 4.5, 5]));
    assert_eq!(doc.curves().len(), 1);

    let q = json!([
        [1, 0.4, 0, 0.2],
        [1, 0, 0.4, 0.2],
        [1, -0.4, 0, 0.2],
        [1, 0, -0.4, 0.2]
    ]);
    let scene = json!({ "space": "S3", "method": "gamma", "closed": true, "points": q,
                        "params": { "gamma": [0.5, 1, 1.5, 2] } });
    let mut doc = Document::from_json(&scene.to_string()).unwrap();
    doc.insert_point(0, 2, &[1.0, -0.3, 0.3, 0.2]).unwrap();
    assert_eq!(
        doc.curve(0).unwrap()["params"]["gamma"],
        json!([0.5, 1, 1.5, 1.5, 2]),
        "a copy of the neighbour at its place"
    );
    doc.remove_point(0, 0).unwrap();
    assert_eq!(
        doc.curve(0).unwrap()["params"]["gamma"],
        json!([1, 1.5, 1.5, 2])
    );
    // Down to the fewest points of a loop, and no further.
    doc.remove_point(0, 0).unwrap();
    let e = doc.remove_point(0, 0).unwrap_err();
    assert!(e.to_string().contains("at least 3 points"), "{e}");
}

#[test]
fn opening_a_loop_drops_its_knots() {
    // A loop's knots do not fit the open curve: set_method keeps them only when the counts agree.
    let scene = json!({ "space": "S2", "method": "geodesic", "closed": true,
                        "points": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "knots": [0, 1, 2, 3] });
    let mut doc = Document::from_json(&scene.to_string()).unwrap();
    doc.set_method(0, "catmull-rom").unwrap();
    assert_eq!(
        doc.curve(0).unwrap()["knots"],
        json!([0, 1, 2, 3]),
        "both loops take 4"
    );
    doc.set_method(0, "arc-blend").unwrap();
    assert!(
        doc.curve(0).unwrap().get("knots").is_none(),
        "arc-blend computes its own"
    );
}

/// A camera orbit of one full turn (keys at 0°, 90°, 180°, 270° about z) returns to −q₀ on S³:
/// no choice of signs closes it with short steps, and the scene says so instead of drawing a
/// closing step that turns back the long way; with `"canonicalize": false` the keys are used as
/// given.
#[test]
fn a_loop_of_one_full_turn_is_refused_on_s3() {
    let keys: Vec<Vec<f64>> = (0..4)
        .map(|k| {
            let half = f64::from(k) * core::f64::consts::FRAC_PI_4;
            vec![half.cos(), 0.0, 0.0, half.sin()]
        })
        .collect();
    for method in ["geodesic", "squad", "catmull-rom", "arc-blend", "cubic"] {
        let scene = json!({ "space": "S3", "method": method, "closed": true, "points": keys });
        let e = Document::from_json(&scene.to_string()).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("closed: the keys turn by an odd number of full turns"),
            "{method}: {e}"
        );
        let scene = json!({ "space": "S3", "method": method, "closed": true, "points": keys,
                            "canonicalize": false });
        assert!(
            Document::from_json(&scene.to_string()).is_ok(),
            "{method} as given"
        );
    }
    // Two full turns close.
    let keys: Vec<Vec<f64>> = (0..8)
        .map(|k| {
            let half = f64::from(k) * core::f64::consts::FRAC_PI_4;
            vec![half.cos(), 0.0, 0.0, half.sin()]
        })
        .collect();
    let scene = json!({ "space": "S3", "method": "squad", "closed": true, "points": keys });
    assert!(Document::from_json(&scene.to_string()).is_ok());
}
