// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Batch evaluation (`Curve::eval_many`, `Curve::jet_many`) agrees with one-at-a-time
//! evaluation bit for bit, for every registered method, parameter choice and sphere, at
//! sorted, unsorted and out-of-domain parameters, at and beside the joints.

use spherekit::{Ambient, Manifold};
use spherekit_scene::{Built, BuiltCurve};

use crate::support::cases;

fn parameters([t0, t1]: [f64; 2], joints: &[f64]) -> Vec<f64> {
    let mut ts: Vec<f64> = (0..=200)
        .map(|i| t0 + (t1 - t0) * f64::from(i) / 200.0)
        .collect();
    // At and beside the joints.
    for &t in joints {
        ts.extend([t.next_down(), t, t.next_up()]);
    }
    // Unsorted, repeated and outside the domain.
    ts.extend([
        t1,
        t0,
        0.5 * (t0 + t1),
        t0 - 1.0,
        t1 + 1.0,
        t0,
        -1e300,
        1e300,
    ]);
    ts
}

fn check<P: Manifold>(name: &str, b: &Built<P>) -> Result<(), String> {
    let c = &*b.curve;
    let ts = parameters(c.domain(), c.joints());
    let mut points = vec![c.eval(ts[0]); ts.len()];
    let mut jets = vec![c.jet(ts[0]); ts.len()];
    c.eval_many(&ts, &mut points);
    c.jet_many(&ts, &mut jets);
    for (i, &t) in ts.iter().enumerate() {
        let (p, j) = (c.eval(t), c.jet(t));
        let same = points[i].to_vector().to_vec() == p.to_vector().to_vec()
            && jets[i].point.to_vector().to_vec() == j.point.to_vector().to_vec()
            && jets[i].velocity.to_vec() == j.velocity.to_vec()
            && jets[i].acceleration.to_vec() == j.acceleration.to_vec();
        if !same {
            return Err(format!(
                "{name}: batch differs from one at a time at t = {t}"
            ));
        }
    }
    Ok(())
}

#[test]
fn batch_equals_one_at_a_time_for_every_registered_method() {
    let cases = cases::built(12);
    assert!(cases.len() > 40, "{} cases", cases.len());
    let mut failures = Vec::new();
    for (name, _, curves) in &cases {
        let r = match &curves[0] {
            BuiltCurve::S2(b) => check(name, b),
            BuiltCurve::S3(b) => check(name, b),
            BuiltCurve::Sm(b) => check(name, b),
        };
        failures.extend(r.err());
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The default, knots and closed cases of every method build; a parameter variant may need
/// more than its own value (clamped ends need velocities) and is then rejected in one line.
#[test]
fn every_registered_method_builds_its_cases() {
    let failures: Vec<String> = cases::scenes(12)
        .into_iter()
        .filter_map(|(name, scene)| {
            let e = spherekit_scene::Scene::from_json(&scene.to_string())
                .and_then(|s| s.build())
                .err()?;
            let variant = name.contains('=');
            (!variant || e.to_string().contains('\n')).then(|| format!("{name}: {e}"))
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
