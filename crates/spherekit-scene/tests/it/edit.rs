// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Editing a scene rebuilds what the edit changes, including every curve whose points are read
//! differently after it: the quaternion order and `canonicalize` (a change of sphere rebuilds
//! everything).

use serde_json::{Value, json};
use spherekit_scene::{BuiltCurve, Document};

/// The first point of every curve of a document, as the built curve gives it.
fn starts(doc: &Document) -> Vec<Vec<f64>> {
    doc.curves()
        .iter()
        .map(|c| match c {
            BuiltCurve::S3(b) => {
                let t0 = b.curve.domain()[0];
                b.curve.eval(t0).to_wxyz().to_vec()
            }
            BuiltCurve::S2(b) => b
                .curve
                .eval(b.curve.domain()[0])
                .as_dvec3()
                .to_array()
                .to_vec(),
            BuiltCurve::Sm(b) => b.curve.eval(b.curve.domain()[0]).coords().to_vec(),
        })
        .collect()
}

/// Applies `text` to `doc` and checks the document now has the curves a fresh one built from
/// `text` has.
#[track_caller]
fn check_rebuilt(doc: &mut Document, text: &Value) {
    doc.set_scene(&text.to_string()).unwrap();
    let fresh = Document::from_json(&text.to_string()).unwrap();
    assert_eq!(starts(doc), starts(&fresh), "the curves of {text}");
}

#[test]
fn changing_how_keys_are_read_rebuilds_every_curve() {
    let keys = json!([
        [0.9, 0.1, 0.2, 0.3],
        [0.2, 0.9, 0.1, 0.3],
        [0.3, 0.2, 0.9, 0.1]
    ]);
    let listed = json!({ "space": "S3", "curves": [
        { "method": "squad", "points": keys },
        { "method": "geodesic", "points": keys }
    ] });
    let mut doc = Document::from_json(&listed.to_string()).unwrap();
    // The quaternion order, the scene-level field of every curve.
    let mut xyzw = listed.clone();
    xyzw["quaternion_order"] = json!("xyzw");
    check_rebuilt(&mut doc, &xyzw);
    check_rebuilt(&mut doc, &listed);
    // `canonicalize` of a one-curve scene (scene level) and of each listed curve.
    let flipped = json!([
        [0.9, 0.1, 0.2, 0.3],
        [-0.2, -0.9, -0.1, -0.3],
        [0.3, 0.2, 0.9, 0.1]
    ]);
    let one = json!({ "space": "S3", "method": "geodesic", "points": flipped });
    let mut doc = Document::from_json(&one.to_string()).unwrap();
    let mut literal = one.clone();
    literal["canonicalize"] = json!(false);
    check_rebuilt(&mut doc, &literal);
    check_rebuilt(&mut doc, &one);
    let mut listed =
        json!({ "space": "S3", "curves": [{ "method": "geodesic", "points": flipped }] });
    let mut doc = Document::from_json(&listed.to_string()).unwrap();
    listed["curves"][0]["canonicalize"] = json!(false);
    check_rebuilt(&mut doc, &listed);
}
