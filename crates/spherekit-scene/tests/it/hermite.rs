// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `params.velocities` of the `cubic` method: keys with a velocity at each (the Hermite spline),
//! on every sphere, open and closed, through the scene format.

use serde_json::{Value, json};
use spherekit::glam::{DVec3, DVec4};
use spherekit::{
    Ambient, Curve, Manifold, Side, UnitQuat, angular_velocity_acceleration,
    angular_velocity_acceleration_body, closes_at_antipode, unflip, velocity_from_angular,
};
use spherekit_scene::{Built, BuiltCurve, Scene};

fn build(scene: &Value) -> BuiltCurve {
    let scene = Scene::from_json(&scene.to_string()).unwrap();
    scene.build().unwrap().remove(0)
}

fn error(scene: &Value) -> String {
    let scene = Scene::from_json(&scene.to_string()).unwrap();
    scene.build().unwrap_err().to_string()
}

fn rotations(built: &BuiltCurve) -> &Built<UnitQuat> {
    match built {
        BuiltCurve::S3(b) => b,
        _ => panic!("not a curve of rotations"),
    }
}

/// Checks that `curve` passes through `keys` (scene coordinates) at `knots` with the tangent
/// `velocities`, from both sides of every joint.
fn check_keys<P: Manifold>(
    curve: &(dyn Curve<Point = P> + Send + Sync),
    keys: &[Vec<f64>],
    velocities: &[Vec<f64>],
    knots: &[f64],
) {
    for (k, ((key, v), &t)) in keys.iter().zip(velocities).zip(knots).enumerate() {
        for side in [Side::Left, Side::Right] {
            let j = curve.jet_at(t, side);
            let p = j.point.to_vector();
            let norm = key.iter().map(|x| x * x).sum::<f64>().sqrt();
            let dp = (p.clone() - p.with_coords(&key.iter().map(|x| x / norm).collect::<Vec<_>>()))
                .length();
            let dv = (j.velocity.clone() - p.with_coords(v)).length();
            assert!(dp < 1e-12, "key {k} ({side:?}): |c − p| = {dp:e}");
            assert!(dv < 1e-12, "key {k} ({side:?}): |c′ − v| = {dv:e}");
        }
    }
}

#[test]
fn velocities_are_interpolated_on_s2() {
    let keys = vec![
        vec![1.0, 0.0, 0.0],
        vec![0.0, 1.0, 0.0],
        vec![0.0, 0.0, 1.0],
    ];
    let velocities = vec![
        vec![0.0, 0.5, 0.2],
        vec![-0.3, 0.0, 0.4],
        vec![0.1, 0.6, 0.0],
    ];
    let knots = [0.0, 1.2, 2.0];
    let built = build(&json!({ "space": "S2", "method": "cubic", "points": keys,
        "knots": knots, "params": { "velocities": velocities } }));
    let BuiltCurve::S2(b) = &built else {
        panic!("S2")
    };
    check_keys(&*b.curve, &keys, &velocities, &knots);
    let (report, order) = built.continuity();
    assert_eq!(order, 1, "C¹ with key velocities");
    assert!(report.iter().all(|j| j.c1 < 1e-12), "{report:?}");
}

#[test]
fn velocities_are_interpolated_on_s4() {
    let keys: Vec<Vec<f64>> = vec![
        vec![1.0, 0.0, 0.2, 0.0, 0.1],
        vec![0.3, 1.0, 0.0, 0.4, 0.0],
        vec![0.0, 0.2, 1.0, 0.0, 0.5],
        vec![-0.4, 0.0, 0.3, 1.0, 0.2],
    ];
    // Tangent velocities: arbitrary vectors with their component along the key removed.
    let raw = [
        [0.3, -0.2, 0.5, 0.1, 0.0],
        [0.0, 0.4, -0.1, 0.2, 0.6],
        [-0.5, 0.1, 0.0, 0.3, 0.2],
        [0.2, 0.2, 0.2, -0.4, 0.1],
    ];
    let velocities: Vec<Vec<f64>> = keys
        .iter()
        .zip(raw)
        .map(|(p, v)| {
            let n2: f64 = p.iter().map(|x| x * x).sum();
            let d: f64 = p.iter().zip(v).map(|(a, b)| a * b).sum();
            v.iter().zip(p).map(|(v, p)| v - d / n2 * p).collect()
        })
        .collect();
    let knots = [0.0, 0.5, 1.7, 2.0];
    for closed in [false, true] {
        let mut scene = json!({ "space": "S4", "method": "cubic", "points": keys,
            "params": { "velocities": velocities } });
        if closed {
            scene["closed"] = json!(true);
            scene["knots"] = json!([0.0, 0.5, 1.7, 2.0, 3.1]);
        } else {
            scene["knots"] = json!(knots);
        }
        let BuiltCurve::Sm(b) = build(&scene) else {
            panic!("S4")
        };
        check_keys(&*b.curve, &keys, &velocities, &knots);
        if closed {
            // The seam: back at the first key with its velocity.
            check_keys(&*b.curve, &keys[..1], &velocities[..1], &[3.1]);
        }
    }
}

/// Three attitudes and the rates measured there.
fn attitudes() -> (Vec<UnitQuat>, Vec<DVec3>) {
    let keys = [
        DVec3::new(0.1, 0.0, 0.0),
        DVec3::new(0.2, 0.1, 0.9),
        DVec3::new(0.5, -0.2, 1.6),
    ]
    .map(|v| UnitQuat::from_rotation_vector(v).unwrap())
    .to_vec();
    let rates = vec![
        DVec3::new(0.0, 0.1, 0.9),
        DVec3::new(0.3, -0.2, 0.7),
        DVec3::new(0.4, 0.1, 0.5),
    ];
    (keys, rates)
}

fn wxyz(keys: &[UnitQuat]) -> Vec<[f64; 4]> {
    keys.iter().map(|q| q.to_wxyz()).collect()
}

#[test]
fn angular_velocities_are_interpolated_on_s3_space_and_body() {
    let (keys, rates) = attitudes();
    let knots = [0.0, 1.0, 2.5];
    let rates_json: Vec<[f64; 3]> = rates.iter().map(|w| w.to_array()).collect();
    for frame in ["space", "body"] {
        let built = build(
            &json!({ "space": "S3", "method": "cubic", "points": wxyz(&keys),
            "knots": knots, "params": { "velocities": rates_json, "frame": frame } }),
        );
        let b = rotations(&built);
        for (k, (q, w)) in keys.iter().zip(&rates).enumerate() {
            for side in [Side::Left, Side::Right] {
                let j = b.curve.jet_at(knots[k], side);
                let (omega, _) = if frame == "body" {
                    angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration)
                } else {
                    angular_velocity_acceleration(j.point, j.velocity, j.acceleration)
                };
                let dq = (j.point.to_vector() - q.to_vector()).length();
                assert!(dq < 1e-12, "{frame} key {k} ({side:?}): |q − q_k| = {dq:e}");
                let dw = (omega - *w).length();
                assert!(dw < 1e-12, "{frame} key {k} ({side:?}): |ω − ω_k| = {dw:e}");
            }
        }
    }
}

#[test]
fn a_key_flipped_by_canonicalize_has_its_rate_negated_with_it() {
    let (keys, rates) = attitudes();
    let rates_json: Vec<[f64; 3]> = rates.iter().map(|w| w.to_array()).collect();
    let mut flipped = wxyz(&keys);
    flipped[1] = flipped[1].map(|x| -x);
    let scene = |points: &[[f64; 4]]| {
        json!({ "space": "S3", "method": "cubic", "points": points, "eval_at": [0, 0.4, 1, 1.7, 2],
                "params": { "velocities": rates_json, "frame": "body" } })
    };
    // The same curve as the rotations' (q and −q), sample for sample.
    let sample = |points: &[[f64; 4]]| {
        let s = Scene::from_json(&scene(points).to_string()).unwrap();
        s.sample_json(&s.build().unwrap(), true)
    };
    assert_eq!(sample(&flipped), sample(&wxyz(&keys)));
    // At the flipped key the curve is at −q (the canonical key) with the velocity of the key as
    // given negated: q′ = −(q·ω/2) of the given −q.
    let built = build(&scene(&flipped));
    let j = rotations(&built).curve.jet(1.0);
    let given = UnitQuat::from_wxyz(flipped[1]).unwrap();
    let v_given = spherekit::velocity_from_angular_body(given, rates[1]);
    assert!((j.point.to_vector() + given.to_vector()).length() < 1e-15);
    assert!((j.velocity + v_given).length() < 1e-12, "{:?}", j.velocity);
}

#[test]
fn a_closed_s3_loop_of_one_turn_with_rates() {
    // Four attitudes a quarter turn apart about a tilted axis: canonicalised, the last key is
    // on the far side of the first (one full turn closes at −q₀).
    let axis = DVec3::new(0.2, -0.1, 1.0).normalize();
    let tau = std::f64::consts::TAU;
    let keys: Vec<UnitQuat> = (0..4)
        .map(|k| {
            let wobble = DVec3::new(0.1 * f64::from(k), 0.0, 0.05);
            UnitQuat::from_rotation_vector(axis * (tau * f64::from(k) / 4.0) + wobble).unwrap()
        })
        .collect();
    let mut canonical = keys.clone();
    unflip(&mut canonical);
    assert!(closes_at_antipode(&canonical), "an odd number of turns");
    let rates: Vec<DVec3> = (0..4)
        .map(|k| axis * 1.5 + DVec3::new(0.1, 0.2 * f64::from(k), -0.1))
        .collect();
    let rates_json: Vec<[f64; 3]> = rates.iter().map(|w| w.to_array()).collect();
    let knots = [0.0, 1.0, 2.2, 3.0, 4.0];
    let built = build(&json!({ "space": "S3", "method": "cubic", "closed": true,
        "points": wxyz(&keys), "knots": knots, "params": { "velocities": rates_json } }));
    let b = rotations(&built);
    for k in 0..=4 {
        let (q, w) = (keys[k % 4], rates[k % 4]);
        for side in [Side::Left, Side::Right] {
            let j = b.curve.jet_at(knots[k], side);
            let (omega, _) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
            // The same rotation: q or −q.
            let dq = 1.0 - j.point.to_vector().dot(q.to_vector()).abs();
            assert!(dq < 1e-12, "key {k} ({side:?}): 1 − |q·q_k| = {dq:e}");
            let dw = (omega - w).length();
            assert!(dw < 1e-12, "key {k} ({side:?}): |ω − ω_k| = {dw:e}");
        }
    }
    // The loop ends at −q₀ and its velocity there is the first key's negated.
    let (start, end) = (
        b.curve.jet_at(0.0, Side::Right),
        b.curve.jet_at(4.0, Side::Left),
    );
    assert!((start.point.to_vector() + end.point.to_vector()).length() < 1e-12);
    assert!((start.velocity + end.velocity).length() < 1e-12);
    assert_eq!(b.inputs.len(), 4, "the loop keeps the keys given");
    assert_eq!(built.continuity().1, 1);
}

#[test]
fn every_velocities_error_names_its_field() {
    let s2 = json!([[1, 0, 0], [0, 1, 0], [0, 0, 1]]);
    let s3 = json!([[1, 0, 0, 0], [0.9, 0.1, 0, 0], [0.8, 0.2, 0.1, 0]]);
    let tangent = json!([[0, 1, 0], [1, 0, 0], [0, 1, 0]]);
    let cases = [
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": [[0, 1, 0], [1, 0, 0]] } }),
            "params.velocities: must have one velocity per point: expected 3, got 2",
        ),
        (
            json!({ "space": "S3", "method": "cubic", "points": s3, "closed": true,
                    "params": { "velocities": [[0, 0, 1]] } }),
            "params.velocities: must have one velocity per point: expected 3, got 1",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": [[0, 1, 0], [1, null, 0], [0, 1, 0]] } }),
            "params.velocities[1]: must be a list of finite numbers",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": [0, 1, 0] } }),
            "params.velocities[0]: must be a list of finite numbers",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": { "x": 1 } } }),
            "params.velocities: must be a list of vectors, one per point",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": [[0, 1, 0], [1, 0, 0], [0, 0, 1]] } }),
            "params.velocities[2]: is not tangent to its key",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": [[0, 1, 0], [1, 0], [0, 1, 0]] } }),
            "params.velocities[1]: has 2 numbers, not a vector of this sphere",
        ),
        (
            json!({ "space": "S3", "method": "cubic", "points": s3,
                    "params": { "velocities": [[0, 0, 1], [0, 0, 1, 0], [0, 0, 1]] } }),
            "params.velocities[1]: must be an angular velocity [x, y, z], got 4 numbers",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": tangent, "end": "clamped",
                                "start_velocity": [0, 1, 0], "end_velocity": [0, 1, 0] } }),
            "params.velocities: gives the velocity at every key, the ends' too",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": tangent, "end": "scipy" } }),
            "params.velocities: gives the velocity at every key",
        ),
        (
            json!({ "space": "S2", "method": "cubic", "points": s2,
                    "params": { "velocities": tangent, "start_velocity": [0, 1, 0] } }),
            "params.velocities: gives the velocity at every key",
        ),
    ];
    for (scene, want) in cases {
        let e = error(&scene);
        assert!(e.contains(want), "{scene}: {e}");
    }
}

#[test]
fn space_and_body_rates_differ_only_by_the_frame() {
    // ω_space = q ω_body q̄: the body rates of one curve, given in the body frame, give it again.
    let (keys, rates) = attitudes();
    let space: Vec<[f64; 3]> = rates.iter().map(|w| w.to_array()).collect();
    let body: Vec<[f64; 3]> = keys
        .iter()
        .zip(&rates)
        .map(|(q, w)| {
            let v: DVec4 = velocity_from_angular(*q, *w);
            let j = angular_velocity_acceleration_body(*q, v, DVec4::ZERO).0;
            j.to_array()
        })
        .collect();
    let sample = |rates: &[[f64; 3]], frame: &str| {
        let s = Scene::from_json(
            &json!({ "space": "S3", "method": "cubic", "points": wxyz(&keys), "samples": 9,
                     "params": { "velocities": rates, "frame": frame } })
            .to_string(),
        )
        .unwrap();
        s.build().unwrap()[0].sample_field(&s, "points").unwrap()
    };
    let (a, b) = (sample(&space, "space"), sample(&body, "body"));
    let d = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(d < 1e-14, "{d:e}");
}

#[test]
fn key_velocities_follow_point_edits() {
    let scene = json!({ "space": "S2", "method": "cubic",
        "points": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
        "params": { "velocities": [[0, 1, 0], [0, 0, 1], [1, 0, 0]] } });
    let mut doc = spherekit_scene::Document::from_json(&scene.to_string()).unwrap();
    doc.insert_point(0, 1, &[0.6, 0.8, 0.0]).unwrap();
    assert_eq!(
        doc.curve(0).unwrap()["params"]["velocities"],
        json!([[0, 1, 0], [0.0, 0.0, 0.0], [0, 0, 1], [1, 0, 0]]),
        "the new key at rest"
    );
    doc.remove_point(0, 3).unwrap();
    assert_eq!(
        doc.curve(0).unwrap()["params"]["velocities"],
        json!([[0, 1, 0], [0.0, 0.0, 0.0], [0, 0, 1]])
    );
    assert_eq!(doc.curves().len(), 1);
}
