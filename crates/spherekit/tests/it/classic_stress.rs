// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Randomised robustness of the classic curves: tiny, ordinary and large steps between points,
//! repeated points. Every jet must be finite and every point unit; with ordinary steps the
//! derivatives must match finite differences.

#![allow(clippy::unwrap_used, reason = "tests unwrap known-valid fixtures")]

use spherekit::{Ambient, Bezier, CatmullRom, Curve, Manifold, Squad, unflip};

use crate::support::*;

fn check_finite_unit<C: Curve>(c: &C) {
    let [t0, t1] = c.domain();
    for k in 0..=64 {
        let t = t0 + (t1 - t0) * f64::from(k) / 64.0;
        let j = c.jet(t);
        let v = j.point.to_vector();
        assert!(
            v.is_finite() && j.velocity.is_finite() && j.acceleration.is_finite(),
            "finite at {t}"
        );
        assert!((v.length() - 1.0).abs() < 1e-14, "unit at {t}");
        assert!(
            (c.eval(t).to_vector().length() - 1.0).abs() < 1e-14,
            "eval unit at {t}"
        );
    }
}

#[test]
fn random_configurations() {
    let mut g = Rng(99);
    for trial in 0..60 {
        let step = [1e-9, 1e-6, 0.3, 1.0, 2.0][trial % 5];
        let n = 4 + trial % 4;
        let mut s2 = g.walk_s2(n, step);
        if trial % 7 == 0 {
            s2[1] = s2[2];
        }
        let mut q = g.walk_quat(n, step);
        unflip(&mut q);
        let sn = g.walk_sm(n, 6, step);
        // Antipodal neighbours are possible only by chance with step 2.0; skip those.
        if let Ok(c) = Bezier::try_new(s2.clone()) {
            check_finite_unit(&c);
        }
        if let Ok(c) = Bezier::try_new(sn.clone()) {
            check_finite_unit(&c);
        }
        if let Ok(c) = CatmullRom::try_new(s2.clone(), None) {
            check_finite_unit(&c);
        }
        if let Ok(c) = CatmullRom::try_new_quaternion(q.clone(), None) {
            check_finite_unit(&c);
        }
        if let Ok(c) = CatmullRom::try_new(sn.clone(), None) {
            check_finite_unit(&c);
        }
        if let Ok(c) = Squad::try_new(q.clone(), None) {
            check_finite_unit(&c);
        }
        if (0.3..=1.0).contains(&step) {
            check_derivatives(&Bezier::try_new(s2.clone()).unwrap(), 7);
            check_derivatives(
                &CatmullRom::try_new_quaternion(q.clone(), None).unwrap(),
                17,
            );
            check_derivatives(&Squad::try_new(q.clone(), None).unwrap(), 17);
            check_derivatives(&CatmullRom::try_new(sn.clone(), None).unwrap(), 17);
        }
    }
}
