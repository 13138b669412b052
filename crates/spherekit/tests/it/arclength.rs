// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Arc-length parametrisation: equal steps, length against independent quadratures, unit speed,
//! derivatives, constant-speed curves reproduced, and stalls.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_precision_loss,
    reason = "tests: a panic is the failure report"
)]

use crate::support::{Rng, check_derivatives_at, interior_parameters};
use spherekit::glam::DVec3;
use spherekit::{
    Ambient, ArcLength, ArcLengthError, Bezier, CatmullRom, Curve, GeodesicSpline, Manifold,
    S2Point, Side, SmPoint, Squad, UnitQuat, angular_velocity_acceleration,
};

/// Composite Simpson of the speed over `[a, b]` with `n` (even) intervals per piece of the
/// curve, split at the joints (where the speed may have a kink).
fn simpson_length<C: Curve>(c: &C, a: f64, b: f64, n: usize) -> f64 {
    let mut cuts = vec![a];
    cuts.extend(c.joints().iter().copied().filter(|&j| j > a && j < b));
    cuts.push(b);
    cuts.windows(2)
        .map(|w| {
            let (lo, hi) = (w[0], w[1]);
            let h = (hi - lo) / n as f64;
            // One-sided at the ends so that a joint takes the piece's own limit.
            let mut sum = c.jet_at(lo, Side::Right).velocity.length()
                + c.jet_at(hi, Side::Left).velocity.length();
            for k in 1..n {
                let wgt = if k % 2 == 1 { 4.0 } else { 2.0 };
                sum += wgt * c.jet(lo + h * k as f64).velocity.length();
            }
            sum * h / 3.0 * C::Point::SPEED_SCALE
        })
        .sum()
}

/// The polyline of geodesic distances through `m + 1` equally spaced parameters (times the
/// speed scale), Richardson-extrapolated from `m` and `2m` (the polyline error is `O(1/m²)`).
fn polyline_length<C: Curve>(c: &C, m: usize) -> f64 {
    let poly = |m: usize| {
        let [t0, t1] = c.domain();
        let pts: Vec<C::Point> = (0..=m)
            .map(|k| c.eval(t0 + (t1 - t0) * k as f64 / m as f64))
            .collect();
        pts.windows(2).map(|w| w[0].dist(&w[1])).sum::<f64>() * C::Point::SPEED_SCALE
    };
    (4.0 * poly(2 * m) - poly(m)) / 3.0
}

fn curve_s2(rng: &mut Rng) -> CatmullRom<S2Point> {
    CatmullRom::try_new(rng.walk_s2(7, 0.6), Some(rng.knots(4))).unwrap()
}

fn curve_s3(rng: &mut Rng) -> Squad {
    Squad::try_new(rng.chain(6, 0.9), Some(rng.knots(5))).unwrap()
}

fn curve_s5(rng: &mut Rng) -> CatmullRom<SmPoint> {
    CatmullRom::try_new(rng.walk_sm(6, 5, 0.5), None).unwrap()
}

/// Equal steps in `s` cover equal lengths of the curve, measured by Simpson's rule on the
/// original curve between the parameters `t(s)`.
fn check_equal_steps<C: Curve>(c: C) {
    let a = ArcLength::try_new(c).unwrap();
    let len = a.length();
    let steps = 25;
    let ds = len / steps as f64;
    let ts: Vec<f64> = (0..=steps).map(|k| a.param_at(ds * k as f64)).collect();
    for w in ts.windows(2) {
        let piece = simpson_length(a.curve(), w[0], w[1], 400);
        assert!(
            (piece - ds).abs() <= 1e-9 * ds,
            "step [{}, {}]: length {piece} vs {ds}",
            w[0],
            w[1]
        );
    }
    // The points are the curve's points at those parameters.
    for (k, &t) in ts.iter().enumerate() {
        let d = a.eval(ds * k as f64).dist(&a.curve().eval(t));
        assert!(d < 1e-14, "point {k}: {d:e}");
    }
}

#[test]
fn equal_steps_cover_equal_lengths_s2() {
    let mut rng = Rng::new(1);
    for _ in 0..3 {
        check_equal_steps(curve_s2(&mut rng));
    }
}

#[test]
fn equal_steps_cover_equal_lengths_s3_rotation_angle() {
    let mut rng = Rng::new(2);
    for _ in 0..3 {
        check_equal_steps(curve_s3(&mut rng));
    }
}

#[test]
fn equal_steps_cover_equal_lengths_s5() {
    let mut rng = Rng::new(3);
    for _ in 0..3 {
        check_equal_steps(curve_s5(&mut rng));
    }
}

/// On great-circle pieces the chord is the arc: equal steps give equal geodesic distances.
#[test]
fn equal_steps_are_equally_far_apart_on_a_nlerp_polyline() {
    let mut rng = Rng::new(4);
    let c = spherekit::NlerpSpline::try_new(rng.walk_s2(5, 0.7), None).unwrap();
    let a = ArcLength::try_new(c).unwrap();
    let n = 2000;
    let ds = a.length() / n as f64;
    let joints = a.joints().to_vec();
    for k in 0..n {
        let (s0, s1) = (ds * k as f64, ds * (k + 1) as f64);
        if joints.iter().any(|&j| j > s0 && j < s1) {
            continue; // the chord cuts a corner
        }
        let d = a.eval(s0).dist(&a.eval(s1));
        assert!((d - ds).abs() <= 1e-9 * ds, "step {k}: {d} vs {ds}");
    }
}

#[test]
fn length_agrees_with_independent_quadratures() {
    let mut rng = Rng::new(5);
    for _ in 0..3 {
        let c = curve_s2(&mut rng);
        let a = ArcLength::try_new(c.clone()).unwrap();
        let [t0, t1] = c.domain();
        let simpson = simpson_length(&c, t0, t1, 4000);
        assert!(
            (a.length() - simpson).abs() < 1e-10,
            "{} vs {simpson}",
            a.length()
        );
        let poly = polyline_length(&c, 20_000);
        assert!((a.length() - poly).abs() < 1e-9, "{} vs {poly}", a.length());
        // The map t ↦ s agrees with Simpson's rule from the start.
        for k in 1..10 {
            let t = t0 + (t1 - t0) * f64::from(k) / 10.0;
            let s = simpson_length(&c, t0, t, 4000);
            assert!((a.arc_length_at(t) - s).abs() < 1e-10, "s({t})");
        }
    }
    let mut rng = Rng::new(6);
    let c = curve_s3(&mut rng);
    let a = ArcLength::try_new(c.clone()).unwrap();
    let [t0, t1] = c.domain();
    let simpson = simpson_length(&c, t0, t1, 4000);
    assert!((a.length() - simpson).abs() < 1e-10);
    let poly = polyline_length(&c, 20_000);
    assert!((a.length() - poly).abs() < 1e-9, "{} vs {poly}", a.length());
}

#[test]
fn reparametrised_velocity_has_unit_speed() {
    let mut rng = Rng::new(7);
    let s2 = ArcLength::try_new(curve_s2(&mut rng)).unwrap();
    let s3 = ArcLength::try_new(curve_s3(&mut rng)).unwrap();
    let s5 = ArcLength::try_new(curve_s5(&mut rng)).unwrap();
    for k in 0..=1000 {
        let f = f64::from(k) / 1000.0;
        for side in [Side::Left, Side::Right] {
            let v = s2.jet_at(f * s2.length(), side).velocity;
            assert!((v.length() - 1.0).abs() < 1e-9, "S²: |v| = {}", v.length());
            let v = s5.jet_at(f * s5.length(), side).velocity;
            assert!((v.length() - 1.0).abs() < 1e-9, "S⁵: |v| = {}", v.length());
            let j = s3.jet_at(f * s3.length(), side);
            let (omega, _) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
            assert!(
                (omega.length() - 1.0).abs() < 1e-9,
                "S³: |ω| = {}",
                omega.length()
            );
            assert!((j.velocity.length() - 0.5).abs() < 1e-9, "S³: |q′| = 1/2");
        }
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let mut rng = Rng::new(8);
    let s2 = ArcLength::try_new(curve_s2(&mut rng)).unwrap();
    check_derivatives_at(&s2, &interior_parameters(&s2, 7));
    let s3 = ArcLength::try_new(curve_s3(&mut rng)).unwrap();
    check_derivatives_at(&s3, &interior_parameters(&s3, 7));
    let s5 = ArcLength::try_new(curve_s5(&mut rng)).unwrap();
    check_derivatives_at(&s5, &interior_parameters(&s5, 7));
}

/// The tangential acceleration of the arc-length curve is the geodesic curvature vector of the
/// trace: orthogonal to the velocity (unit speed has no tangential component).
#[test]
fn acceleration_is_orthogonal_to_velocity() {
    let mut rng = Rng::new(9);
    let a = ArcLength::try_new(curve_s3(&mut rng)).unwrap();
    for k in 0..200 {
        let j = a.jet(a.length() * (f64::from(k) + 0.5) / 200.0);
        let dot = j.velocity.dot(j.acceleration);
        assert!(
            dot.abs() < 1e-9 * j.acceleration.length().max(1.0),
            "{dot:e}"
        );
    }
}

/// A geodesic spline with knots proportional to the angles already has constant speed: its
/// arc-length map is `s = (t − t0)·speed`, one cell per piece.
#[test]
fn constant_speed_geodesic_is_reproduced() {
    let mut rng = Rng::new(10);
    let keys = rng.chain(8, 1.0);
    let rate = 0.7; // parameter per radian of S³
    let mut knots = vec![-2.0];
    for w in keys.windows(2) {
        knots.push(knots.last().unwrap() + rate * w[0].dist(&w[1]));
    }
    let c = GeodesicSpline::try_new(keys, Some(knots.clone())).unwrap();
    let a = ArcLength::try_new(c.clone()).unwrap();
    // Rotation angle = 2 × distance on S³.
    let per_t = 2.0 / rate;
    assert_eq!(a.info().cells, knots.len() - 1);
    assert!(a.info().stalls.is_empty());
    let t0 = knots[0];
    let total = (knots[knots.len() - 1] - t0) * per_t;
    assert!((a.length() - total).abs() < 1e-13 * total);
    for k in 0..=300 {
        let t = t0 + (knots[knots.len() - 1] - t0) * f64::from(k) / 300.0;
        let s = a.arc_length_at(t);
        assert!((s - (t - t0) * per_t).abs() < 1e-13 * total, "s({t}) = {s}");
        let back = a.param_at((t - t0) * per_t);
        assert!(
            (back - t).abs() < 1e-13 * (1.0 + t.abs()),
            "t({s}) = {back} vs {t}"
        );
        let d = a.eval((t - t0) * per_t).dist(&c.eval(t));
        assert!(d < 1e-14, "point at t = {t}: {d:e}");
    }
    for (j, k) in a.joints().iter().zip(&knots) {
        assert!((j - (k - t0) * per_t).abs() < 1e-13 * total, "joint {k}");
    }
}

#[test]
fn joints_are_the_images_of_the_joints() {
    let mut rng = Rng::new(11);
    let c = curve_s2(&mut rng);
    let a = ArcLength::try_new(c.clone()).unwrap();
    assert_eq!(a.joints().len(), c.joints().len());
    assert_eq!(a.joints()[0], 0.0);
    assert_eq!(*a.joints().last().unwrap(), a.length());
    for (s, &t) in a.joints().iter().zip(c.joints()) {
        assert_eq!(*s, a.arc_length_at(t));
        // Both one-sided jets at a joint image are the curve's one-sided points there.
        for side in [Side::Left, Side::Right] {
            let d = a.jet_at(*s, side).point.dist(&c.jet_at(t, side).point);
            assert!(d < 1e-14, "joint {t}, {side:?}");
        }
    }
}

#[test]
fn identical_keys_stay_finite() {
    let p = [
        S2Point::X,
        S2Point::try_new(DVec3::new(1.0, 1.0, 0.0)).unwrap(),
        S2Point::Y,
        S2Point::Z,
    ];
    // A zero-length piece between two identical keys, and one at the end.
    let keys = vec![p[0], p[1], p[1], p[2], p[3], p[3]];
    let c = GeodesicSpline::try_new(keys, None).unwrap();
    let a = ArcLength::try_new(c).unwrap();
    let quarter = core::f64::consts::FRAC_PI_2;
    assert!((a.length() - 2.0 * quarter).abs() < 1e-14);
    let stalls = &a.info().stalls;
    assert_eq!(stalls.len(), 2, "{stalls:?}");
    assert_eq!(stalls[0].t, [1.0, 2.0]);
    assert_eq!(stalls[1].t, [4.0, 5.0]);
    assert!((stalls[0].s - 0.5 * quarter).abs() < 1e-15);
    // Joints: the collapsed pieces' two ends have one image.
    assert_eq!(a.joints().len(), 4, "{:?}", a.joints());
    let n = 997;
    for k in 0..=n {
        for side in [Side::Left, Side::Right] {
            let j = a.jet_at(a.length() * f64::from(k) / f64::from(n), side);
            assert!(j.point.to_vector().is_finite() && j.velocity.is_finite());
            assert!(j.acceleration.is_finite());
            assert!((j.velocity.length() - 1.0).abs() < 1e-12);
        }
    }
    for &s in a.joints() {
        for side in [Side::Left, Side::Right] {
            let j = a.jet_at(s, side);
            assert!(
                (j.velocity.length() - 1.0).abs() < 1e-12,
                "joint {s} {side:?}"
            );
        }
    }
    // t ↦ s is constant on a collapsed piece.
    assert_eq!(a.arc_length_at(1.3), a.arc_length_at(1.0));
    assert_eq!(a.arc_length_at(2.0), a.arc_length_at(1.0));

    // S³, a repeated key in the middle.
    let q = [
        UnitQuat::IDENTITY,
        UnitQuat::from_axis_angle(DVec3::Z, 1.0).unwrap(),
    ];
    let c = GeodesicSpline::try_new(vec![q[0], q[1], q[1], q[0]], None).unwrap();
    let a = ArcLength::try_new(c).unwrap();
    assert!((a.length() - 2.0).abs() < 1e-14, "two turns of 1 rad");
    assert_eq!(a.info().stalls.len(), 1);
    let j = a.jet(1.0);
    let (omega, _) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
    assert!((omega + DVec3::Z).length() < 1e-14, "turning back: {omega}");
}

/// A quadratic Bézier curve A → B → A turns back at its middle, where the speed is zero (a
/// cusp of the trace in arc length): finite everywhere, the cusp reported.
#[test]
fn cusp_stays_finite_and_is_reported() {
    let a0 = S2Point::X;
    let b0 = S2Point::try_new(DVec3::new(1.0, 1.0, 0.2)).unwrap();
    let c = Bezier::try_new(vec![a0, b0, a0]).unwrap();
    assert!(c.jet(0.5).velocity.length() < 1e-15, "the cusp");
    let a = ArcLength::try_new(c.clone()).unwrap();
    let stalls = &a.info().stalls;
    assert_eq!(stalls.len(), 1, "{stalls:?}");
    let st = stalls[0];
    assert!(
        st.t[0] <= 0.5 && 0.5 <= st.t[1] && st.t[1] - st.t[0] < 1e-5,
        "{st:?}"
    );
    assert!((st.s - 0.5 * a.length()).abs() < 1e-9);
    assert!((a.length() - 2.0 * a0.dist(&c.eval(0.5))).abs() < 1e-10);
    for k in 0..=2000 {
        let s = a.length() * f64::from(k) / 2000.0;
        for side in [Side::Left, Side::Right] {
            let j = a.jet_at(s, side);
            assert!(
                j.velocity.is_finite() && j.acceleration.is_finite(),
                "s = {s}"
            );
            assert!((j.velocity.length() - 1.0).abs() < 1e-9, "s = {s}");
        }
    }
    // At the exact cusp parameter: the one-sided limits of the direction, by side.
    let at = a.arc_length_at(0.5);
    let (l, r) = (a.jet_at(at, Side::Left), a.jet_at(at, Side::Right));
    assert!(
        (l.velocity + r.velocity).length() < 1e-6,
        "reversal at the cusp"
    );
    // Away from the cusp, derivatives as usual.
    let ts: Vec<f64> = [0.1, 0.3, 0.7, 0.9]
        .iter()
        .map(|f| f * a.length())
        .collect();
    check_derivatives_at(&a, &ts);
}

#[test]
fn errors() {
    let c = GeodesicSpline::try_new(vec![S2Point::X, S2Point::X], None).unwrap();
    assert_eq!(
        ArcLength::try_new(c).unwrap_err(),
        ArcLengthError::ZeroLength
    );
    let c = GeodesicSpline::try_new(vec![S2Point::X, S2Point::Y], None).unwrap();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = ArcLength::try_with_accuracy(c.clone(), bad).unwrap_err();
        assert!(matches!(e, ArcLengthError::InvalidAccuracy { .. }));
        assert!(e.to_string().contains("accuracy"));
    }
}

#[test]
fn non_finite_parameters_are_clamped() {
    let mut rng = Rng::new(12);
    let a = ArcLength::try_new(curve_s3(&mut rng)).unwrap();
    assert_eq!(a.jet(f64::NAN), a.jet(0.0));
    assert_eq!(a.jet(f64::NEG_INFINITY), a.jet(0.0));
    assert_eq!(a.jet(f64::INFINITY), a.jet(a.length()));
    assert_eq!(a.param_at(f64::NAN), a.curve().domain()[0]);
    assert_eq!(a.arc_length_at(f64::INFINITY), a.length());
    assert_eq!(a.arc_length_at(f64::NAN), 0.0);
}

/// Tighter accuracies are met, and need more cells.
#[test]
fn accuracy_parameter() {
    let mut rng = Rng::new(13);
    let c = curve_s2(&mut rng);
    let [t0, t1] = c.domain();
    let exact = simpson_length(&c, t0, t1, 8000);
    let mut last_cells = 0;
    for acc in [1e-4, 1e-7, 1e-10, 1e-12] {
        let a = ArcLength::try_with_accuracy(c.clone(), acc).unwrap();
        for k in 1..8 {
            let t = t0 + (t1 - t0) * f64::from(k) / 8.0;
            let s = simpson_length(&c, t0, t, 8000);
            assert!(
                (a.arc_length_at(t) - s).abs() <= acc.max(1e-13),
                "{acc:e} at {t}"
            );
        }
        assert!((a.length() - exact).abs() <= acc.max(1e-13));
        assert!(a.info().cells >= last_cells);
        last_cells = a.info().cells;
    }
}

/// A long curve far from `t = 0` (600 keys at unit spacing, t up to 599): a parameter near 500
/// is only known to `ε·500`, so the speed at the nodes of a small cell carries that much
/// noise. Each cell is held to the rounding level instead of being halved to the cell limit
/// (before: 267 144 cells, 46 043 unresolved, two seconds), and the length still agrees with
/// an independent quadrature.
#[test]
fn long_curve_far_from_zero_stops_at_the_rounding_of_its_parameters() {
    let mut rng = Rng::new(41);
    let mut keys = vec![UnitQuat::IDENTITY];
    while keys.len() < 600 {
        let step = UnitQuat::from_axis_angle(rng.unit3(), rng.range(0.4, 1.2)).expect("unit axis");
        keys.push(step * keys[keys.len() - 1]);
    }
    let c = spherekit::CubicSpline::try_new(keys, None, spherekit::CubicEnd::Scipy, false)
        .expect("cubic");
    let a = ArcLength::try_new(&c).expect("arc length");
    let info = a.info();
    assert!(info.cells < 20 * 599, "{} cells", info.cells);
    assert!(
        info.unresolved < info.cells / 10,
        "{} unresolved",
        info.unresolved
    );
    let [t0, t1] = c.domain();
    let reference = simpson_length(&c, t0, t1, 512);
    let len = a.domain()[1];
    assert!(
        (len - reference).abs() < 1e-9 * reference,
        "{len} vs {reference}"
    );
}
