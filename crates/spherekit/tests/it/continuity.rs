// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The continuity report.

#![allow(clippy::unwrap_used, reason = "tests unwrap known-valid fixtures")]

use spherekit::glam::DVec3;
use spherekit::{Bezier, CatmullRom, GeodesicSpline, S2Point, Squad, UnitQuat, continuity};

#[test]
fn geodesic_has_corners() {
    let c = GeodesicSpline::try_new(
        vec![S2Point::X, S2Point::Y, S2Point::Z, S2Point::X],
        Some(vec![0.0, 1.0, 1.5, 4.0]),
    )
    .unwrap();
    let r = continuity(&c);
    assert_eq!(
        r.iter().map(|j| j.t).collect::<Vec<_>>(),
        vec![1.0, 1.5],
        "interior joints"
    );
    // At t = 1: left velocity π/2·(−x) , right velocity π·z.
    let expected = (DVec3::new(-1.0, 0.0, 0.0) * core::f64::consts::FRAC_PI_2
        - DVec3::Z * core::f64::consts::PI)
        .length();
    assert!((r[0].c1 - expected).abs() < 1e-14, "{:?}", r[0]);
    assert!(r[0].c0 < 1e-16, "continuous");
    assert_eq!(r[0].order(1e-12), Some(0), "C0 only");
}

#[test]
fn one_piece_curves_have_no_interior_joints() {
    let c = Bezier::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z]).unwrap();
    assert!(continuity(&c).is_empty(), "no joints");
}

#[test]
fn squad_and_catmull_rom_are_c1_not_c2() {
    let keys: Vec<UnitQuat> = (0..6)
        .map(|i| {
            let f = f64::from(i);
            UnitQuat::from_axis_angle(DVec3::new(f.sin(), 1.0, f * 0.3), 0.3 + 0.5 * f).unwrap()
        })
        .collect();
    let s = Squad::try_new(keys.clone(), None).unwrap();
    let c = CatmullRom::try_new_quaternion(keys, None).unwrap();
    for r in continuity(&s).into_iter().chain(continuity(&c)) {
        assert_eq!(r.order(1e-12), Some(1), "{r:?}");
    }
}
