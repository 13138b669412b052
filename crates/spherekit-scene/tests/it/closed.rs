// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Editing closed curves: a loop's knots (one more than points) and per-joint lists (one entry
//! per point) follow inserted and removed points, for the methods whose open lists skip the end
//! points (Catmull-Rom's knots, Gamma's γ).

use serde_json::json;
use spherekit::{Curve, JointContinuity, Manifold, Side, UnitQuat};
use spherekit_scene::{Built, BuiltCurve, Document, METHODS, Scene, Space};

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

/// `n` keys of an orbit of `turns` full turns about z (w first), each tipped by a wobble of up
/// to `wobble` radians about x.
fn orbit(n: usize, turns: f64, wobble: f64) -> Vec<Vec<f64>> {
    (0..n)
        .map(|k| {
            let yaw = turns * core::f64::consts::TAU * k as f64 / n as f64;
            let tip = wobble * (1.7 * k as f64).sin();
            let (c, s) = ((0.5 * yaw).cos(), (0.5 * yaw).sin());
            let (ct, st) = ((0.5 * tip).cos(), (0.5 * tip).sin());
            // yaw about z, then tip about x: (c + s k)(ct + st i).
            vec![c * ct, c * st, s * st, s * ct]
        })
        .collect()
}

/// The built curve of rotations of a one-curve scene.
fn built_s3(scene: &serde_json::Value) -> Built<UnitQuat> {
    let scene = Scene::from_json(&scene.to_string()).unwrap();
    let built = scene.build().unwrap_or_else(|e| panic!("{scene:?}: {e}"));
    match built.into_iter().next().unwrap() {
        BuiltCurve::S3(b) => b,
        _ => panic!("a curve of rotations"),
    }
}

/// A camera orbit of one full turn ends at −q₀, the same rotation: every method that closes on
/// S³ builds it as the loop of rotations it is (the seam as smooth as the other joints up to
/// the sign), with its per-joint parameters, for 3 to 16 keys, with and without wobble, both
/// ways round; with `"canonicalize": false` the keys are used as given.
#[test]
fn a_loop_of_one_full_turn_is_a_loop_of_rotations_for_every_method() {
    let closing: Vec<_> = METHODS
        .iter()
        .filter(|m| m.closes && m.spaces.contains(Space::S3))
        .collect();
    assert!(closing.len() >= 10, "every method that closes on S3");
    for method in closing {
        for n in [3_usize, 4, 8, 16] {
            for (turns, wobble) in [(1.0, 0.0), (-1.0, 0.0), (1.0, 0.1), (-1.0, 0.1)] {
                let keys = orbit(n, turns, wobble);
                let label = format!("{}, {n} keys, {turns} turn, wobble {wobble}", method.id);
                let mut scene = json!({ "space": "S3", "method": method.id, "closed": true,
                                        "points": keys });
                // Per-joint lists, one entry per key, different at each (corner cuts: the
                // two sides of an edge take at most all of it).
                let base = if method.id == "corner-blend" {
                    0.3
                } else {
                    0.8
                };
                for param in method.params.iter().filter(|p| p.per_joint.is_some()) {
                    let list: Vec<f64> = (0..n).map(|k| base + 0.05 * (k % 3) as f64).collect();
                    scene["params"][param.name] = json!(list);
                }
                let b = built_s3(&scene);
                let c = &b.curve;
                assert!(c.is_closed() && c.is_antiperiodic(), "{label}");
                let [t0, t1] = c.domain();
                let (start, end) = (c.eval(t0).as_dquat(), c.eval(t1).as_dquat());
                assert!((start + end).length() <= 1e-12, "{label}: ends at −q₀");
                let report = b.continuity();
                let seam = report.last().unwrap();
                assert_eq!(seam.t, t1, "{label}: the seam last");
                let worst = |f: fn(&JointContinuity) -> f64| {
                    report[..report.len() - 1].iter().map(f).fold(0.0, f64::max)
                };
                let speed = c.jet_at(t1, Side::Left).velocity.length();
                assert!(seam.c0 <= 1e-12, "{label}: C⁰ at the seam");
                if b.order >= 1 {
                    assert!(
                        seam.c1 <= 1e-9 * speed.max(1.0)
                            && seam.c1 <= 10.0 * worst(|j| j.c1) + 1e-9,
                        "{label}: the seam as smooth as the joints: {seam:?}"
                    );
                }
                // The extras are the doubled loop's first half: compare with that loop, built
                // from the doubled keys as given.
                let mut doubled = scene.clone();
                let negated: Vec<Vec<f64>> = keys
                    .iter()
                    .map(|q| q.iter().map(|x| -x).collect())
                    .collect();
                doubled["points"] = json!([keys.clone(), negated].concat());
                doubled["canonicalize"] = json!(false);
                if let Some(params) = doubled["params"].as_object_mut() {
                    for list in params.values_mut() {
                        let v = list.as_array().unwrap().clone();
                        *list = json!([v.clone(), v].concat());
                    }
                }
                let d = built_s3(&doubled);
                for (what, mine, theirs) in [
                    ("controls", &b.controls, &d.controls),
                    ("auxiliary", &b.auxiliary, &d.auxiliary),
                ] {
                    assert_eq!(mine.len(), theirs.len().div_ceil(2), "{label}: {what}");
                    for (k, (a, x)) in mine.iter().zip(theirs).enumerate() {
                        let e = (a.as_dquat() - x.as_dquat()).length();
                        assert!(e <= 1e-9, "{label}: {what}[{k}] {e:e}");
                    }
                }
                for list in ["knots", "joints"] {
                    let (Some(mine), Some(theirs)) = (b.info.get(list), d.info.get(list)) else {
                        assert!(b.info.get(list).is_none() && d.info.get(list).is_none());
                        continue;
                    };
                    let (mine, theirs) = (mine.as_array().unwrap(), theirs.as_array().unwrap());
                    assert_eq!(mine.len(), theirs.len().div_ceil(2), "{label}: info.{list}");
                    if list == "knots" {
                        assert_eq!(
                            mine[mine.len() - 1].as_f64(),
                            Some(t1),
                            "{label}: ends at t1"
                        );
                    }
                }
            }
        }
        let keys = orbit(4, 1.0, 0.0);
        let scene = json!({ "space": "S3", "method": method.id, "closed": true, "points": keys,
                            "canonicalize": false });
        // As given: the literal quaternion loop (which a global solve may not find).
        if let Ok(mut built) = Scene::from_json(&scene.to_string()).unwrap().build() {
            let BuiltCurve::S3(b) = built.remove(0) else {
                panic!("a curve of rotations")
            };
            assert!(!b.curve.is_antiperiodic(), "{} as given", method.id);
            let [t0, t1] = b.curve.domain();
            assert!(b.curve.eval(t1).dist(&b.curve.eval(t0)) <= 1e-12);
        }
    }
    // Two full turns close at +q₀ as before.
    let scene =
        json!({ "space": "S3", "method": "squad", "closed": true, "points": orbit(8, 2.0, 0.0) });
    let b = built_s3(&scene);
    assert!(b.curve.is_closed() && !b.curve.is_antiperiodic());
}

/// A per-joint list of the wrong length on a loop of one full turn is reported for the keys
/// given, not for the doubled loop the curve is built from.
#[test]
fn a_full_turn_loops_bad_lists_name_the_keys_given() {
    let scene = json!({ "space": "S3", "method": "gamma", "closed": true,
                        "points": orbit(4, 1.0, 0.0), "params": { "gamma": [1, 1, 1] } });
    let e = Scene::from_json(&scene.to_string())
        .unwrap()
        .build()
        .unwrap_err();
    assert!(e.to_string().contains('4'), "{e}");
    let scene = json!({ "space": "S3", "method": "cubic", "closed": true,
                        "points": orbit(4, 1.0, 0.0), "knots": [0, 1, 2] });
    let e = Scene::from_json(&scene.to_string())
        .unwrap()
        .build()
        .unwrap_err();
    assert!(e.to_string().contains('5'), "{e}");
}

/// Random closed loops of six rotations: about half turn by an odd number of full turns; every
/// one is built (none refused), closed in SO(3).
#[test]
fn random_closed_loops_of_rotations_are_all_built() {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut antiperiodic = 0;
    for _ in 0..40 {
        let keys: Vec<Vec<f64>> = (0..6)
            .map(|_| (0..4).map(|_| 2.0 * uniform() - 1.0).collect())
            .collect();
        for method in ["cubic", "squad", "catmull-rom", "geodesic"] {
            let scene = json!({ "space": "S3", "method": method, "closed": true, "points": keys });
            let b = built_s3(&scene);
            let c = &b.curve;
            let [t0, t1] = c.domain();
            assert!(
                c.eval(t1)
                    .dist(&c.eval(t0))
                    .min(c.eval(t1).dist(&-c.eval(t0)))
                    <= 1e-12
            );
            antiperiodic += usize::from(c.is_antiperiodic() && method == "cubic");
        }
    }
    assert!(
        (10..=30).contains(&antiperiodic),
        "{antiperiodic} of 40 loops turn an odd number of times"
    );
}
