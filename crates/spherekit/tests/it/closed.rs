// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Closed loops of every method that has one, on every sphere it works on: interpolation of
//! every key (interpolating methods), closure (point and derivatives at the end equal those at
//! the start), the method's continuity at the seam from the continuity report (the seam is its
//! last joint), exact derivatives against finite differences next to the seam, the arc-blend
//! circle, and the typed errors of bad loops.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_precision_loss,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::TAU;

use spherekit::glam::DVec3;
use spherekit::{
    Ambient, ArcBlend, ArcBlendTiming, BetaParams, BetaSolver, BetaSpline, BsplineKim, CatmullRom,
    CatmullRomNlerp, CornerBlend, CornerBlendRotations, CornerCuts, CornerTiming, Curve,
    GammaSpline, Gammas, GeodesicSpline, Manifold, NlerpSpline, S2Point, Side, SmPoint,
    SplineError, Squad, UnitQuat, continuity,
};

use crate::support::{Rng, check_derivatives, check_derivatives_at};

/// What a method guarantees at its joints, and so at the seam.
#[derive(Clone, Copy, Debug)]
enum Smooth {
    C0,
    /// The unit tangent is continuous; the speed ratio `|c′(t⁺)|/|c′(t⁻)|` is free.
    G1,
    C1,
    C2,
}

/// Relative jumps at a joint (point absolute).
fn relative(j: &spherekit::JointContinuity, v: f64, a: f64) -> (f64, f64, f64) {
    (j.c0, j.c1 / v.max(1e-300), j.c2 / a.max(1e-300))
}

/// The checks every closed curve passes: closed, returns to its start with the same jet, the
/// seam is the last entry of the continuity report and as smooth as `smooth` (as are the other
/// joints), derivatives against finite differences everywhere and next to the seam, and, given
/// the keys and their times, interpolation of every key.
#[track_caller]
fn check_loop<C: Curve>(c: &C, keys: Option<(&[C::Point], &[f64])>, smooth: Smooth) {
    assert!(c.is_closed(), "built closed");
    let [t0, t1] = c.domain();
    let joints = c.joints();
    let report = continuity(c);
    assert_eq!(report.len(), joints.len() - 1, "every joint and the seam");
    let seam = report[report.len() - 1];
    assert_eq!(seam.t, t1, "the seam is reported last, at t1");
    // Closure: the end from the left is the start from the right.
    let (end, start) = (c.jet_at(t1, Side::Left), c.jet_at(t0, Side::Right));
    assert!(
        c.eval(t1).dist(&c.eval(t0)) <= 1e-12,
        "returns to its first point"
    );
    let (v, a) = (start.velocity.length(), start.acceleration.length());
    assert!(
        (end.point.to_vector() - start.point.to_vector()).length() <= 1e-12,
        "point at the seam"
    );
    for j in &report {
        let (sv, sa) = {
            let l = c.jet_at(j.t, Side::Left);
            (l.velocity.length(), l.acceleration.length())
        };
        let (c0, c1, c2) = relative(j, sv, sa);
        let at = if j.t == t1 { "the seam" } else { "a joint" };
        assert!(c0 <= 1e-12, "C⁰ at {at} t = {}: {c0:e}", j.t);
        match smooth {
            Smooth::C0 => {}
            Smooth::G1 => assert!(j.g1 <= 1e-9, "G¹ at {at} t = {}: {:e}", j.t, j.g1),
            Smooth::C1 => assert!(c1 <= 1e-10, "C¹ at {at} t = {}: {c1:e}", j.t),
            Smooth::C2 => assert!(
                c1 <= 1e-10 && c2 <= 1e-9,
                "C² at {at} t = {}: {c1:e} {c2:e}",
                j.t
            ),
        }
    }
    if matches!(smooth, Smooth::C1 | Smooth::C2) {
        assert!(
            (end.velocity.clone() - start.velocity.clone()).length() <= 1e-10 * v.max(1.0),
            "velocity at the seam"
        );
    }
    if matches!(smooth, Smooth::C2) {
        assert!(
            (end.acceleration.clone() - start.acceleration.clone()).length() <= 1e-9 * a.max(1.0),
            "acceleration at the seam"
        );
    }
    // Exact derivatives against finite differences, next to the seam on both sides too.
    check_derivatives(c, 40);
    let first = joints[1] - joints[0];
    let last = joints[joints.len() - 1] - joints[joints.len() - 2];
    check_derivatives_at(c, &[t0 + 1e-3 * first, t1 - 1e-3 * last]);
    if let Some((keys, knots)) = keys {
        assert_eq!(knots.len(), keys.len() + 1, "one knot more than keys");
        for (i, (p, &t)) in keys.iter().zip(knots).enumerate() {
            for side in [Side::Left, Side::Right] {
                let d = c.jet_at(t, side).point.dist(p);
                assert!(d <= 1e-12, "key {i} from {side:?}: {d:e}");
            }
        }
        assert!(
            c.eval(knots[keys.len()]).dist(&keys[0]) <= 1e-12,
            "closing key"
        );
    }
}

/// `m` points of S² around a loop (a ring with jitter in angle and height).
fn ring_s2(rng: &mut Rng, m: usize) -> Vec<S2Point> {
    (0..m)
        .map(|k| {
            let a = TAU * (k as f64 + rng.range(-0.2, 0.2)) / m as f64;
            S2Point::try_new(DVec3::new(a.cos(), a.sin(), rng.range(0.6, 1.2))).unwrap()
        })
        .collect()
}

/// `m` rotations around a loop (the axis turns once round z).
fn ring_s3(rng: &mut Rng, m: usize) -> Vec<UnitQuat> {
    (0..m)
        .map(|k| {
            let a = TAU * (k as f64 + rng.range(-0.2, 0.2)) / m as f64;
            let axis = DVec3::new(a.cos(), a.sin(), rng.range(0.5, 1.5));
            UnitQuat::from_axis_angle(axis, rng.range(0.6, 1.4)).unwrap()
        })
        .collect()
}

/// `m` points of S⁵ around a loop.
fn ring_s5(rng: &mut Rng, m: usize) -> Vec<SmPoint> {
    (0..m)
        .map(|k| {
            let a = TAU * (k as f64 + rng.range(-0.2, 0.2)) / m as f64;
            SmPoint::try_new(vec![
                a.cos(),
                a.sin(),
                rng.range(0.5, 0.9),
                rng.range(-0.3, 0.3),
                0.2,
                rng.range(-0.3, 0.3),
            ])
            .unwrap()
        })
        .collect()
}

/// `count` increasing knots with spacings in [0.5, 2].
fn times(rng: &mut Rng, count: usize) -> Vec<f64> {
    rng.knots(count - 1)
}

fn uniform(count: usize) -> Vec<f64> {
    (0..count).map(|i| i as f64).collect()
}

#[test]
fn geodesic_and_nlerp_loops_interpolate_and_are_c0_at_the_seam() {
    let mut rng = Rng::new(11);
    for m in [3, 7] {
        let k = times(&mut rng, m + 1);
        let p = ring_s2(&mut rng, m);
        let g = GeodesicSpline::try_new_closed(p.clone(), Some(k.clone())).unwrap();
        check_loop(&g, Some((&p, &k)), Smooth::C0);
        assert_eq!(g.points(), &p[..]);
        let n = NlerpSpline::try_new_closed(p.clone(), None).unwrap();
        check_loop(&n, Some((&p, &uniform(m + 1))), Smooth::C0);
        let q = ring_s3(&mut rng, m);
        let g = GeodesicSpline::try_new_closed(q.clone(), Some(k.clone())).unwrap();
        check_loop(&g, Some((&q, &k)), Smooth::C0);
        let n = NlerpSpline::try_new_closed(q.clone(), Some(k.clone())).unwrap();
        check_loop(&n, Some((&q, &k)), Smooth::C0);
        let s = ring_s5(&mut rng, m);
        let g = GeodesicSpline::try_new_closed(s.clone(), None).unwrap();
        check_loop(&g, Some((&s, &uniform(m + 1))), Smooth::C0);
        let n = NlerpSpline::try_new_closed(s.clone(), Some(k.clone())).unwrap();
        check_loop(&n, Some((&s, &k)), Smooth::C0);
    }
}

#[test]
fn catmull_rom_loops_have_periodic_tangents_and_are_c1_at_the_seam() {
    let mut rng = Rng::new(12);
    for m in [3, 6] {
        let k = times(&mut rng, m + 1);
        let p = ring_s2(&mut rng, m);
        let c = CatmullRom::try_new_closed(p.clone(), Some(k.clone())).unwrap();
        check_loop(&c, Some((&p, &k)), Smooth::C1);
        assert_eq!(c.controls().len(), 3 * m + 1);
        let q = ring_s3(&mut rng, m);
        for c in [
            CatmullRom::try_new_closed(q.clone(), Some(k.clone())).unwrap(),
            CatmullRom::try_new_quaternion_closed(q.clone(), Some(k.clone())).unwrap(),
        ] {
            check_loop(&c, Some((&q, &k)), Smooth::C1);
        }
        let s = ring_s5(&mut rng, m);
        let c = CatmullRom::try_new_closed(s.clone(), None).unwrap();
        check_loop(&c, Some((&s, &uniform(m + 1))), Smooth::C1);
    }
}

/// The normalised Euclidean Catmull-Rom closes too: C¹ at the seam as at every key, on every
/// sphere, and with uniform knots it is the open spline of the wrapped sequence
/// `c_{m−1}, c₀ … c_{m−1}, c₀, c₁` (whose end steering points are the loop's neighbours).
#[test]
fn catmull_rom_nlerp_loops_are_c1_at_the_seam() {
    let mut rng = Rng::new(14);
    for m in [3, 6] {
        let k = times(&mut rng, m + 1);
        let p = ring_s2(&mut rng, m);
        let c = CatmullRomNlerp::try_new_closed(p.clone(), Some(k.clone())).unwrap();
        check_loop(&c, Some((&p, &k)), Smooth::C1);
        let q = ring_s3(&mut rng, m);
        let c = CatmullRomNlerp::try_new_closed(q.clone(), Some(k.clone())).unwrap();
        check_loop(&c, Some((&q, &k)), Smooth::C1);
        let s = ring_s5(&mut rng, m);
        let c = CatmullRomNlerp::try_new_closed(s.clone(), None).unwrap();
        check_loop(&c, Some((&s, &uniform(m + 1))), Smooth::C1);
    }
    let p = ring_s2(&mut rng, 5);
    let closed = CatmullRomNlerp::try_new_closed(p.clone(), None).unwrap();
    let mut open_points = vec![p[4]];
    open_points.extend_from_slice(&p);
    open_points.extend([p[0], p[1]]);
    let open = CatmullRomNlerp::try_new(open_points, None).unwrap();
    for j in 0..=50 {
        let t = 5.0 * f64::from(j) / 50.0;
        assert!(closed.eval(t).dist(&open.eval(t)) < 1e-15, "t = {t}");
    }
    // Bad loops: too few points, an antipodal seam.
    assert!(matches!(
        CatmullRomNlerp::try_new_closed(p[..2].to_vec(), None),
        Err(SplineError::TooFewPoints { min: 3, got: 2 })
    ));
    let mut seam = p[..3].to_vec();
    seam.push(S2Point::try_new(-p[0].as_dvec3()).unwrap());
    assert!(matches!(
        CatmullRomNlerp::try_new_closed(seam, None),
        Err(SplineError::AntipodalClosing)
    ));
}

/// The first key's tangent is the central difference of its periodic neighbours: the loop's
/// velocity at t₀ is that of an open spline whose steering points are the loop's neighbours.
#[test]
fn catmull_rom_loop_matches_the_open_spline_with_wrapped_neighbours() {
    let mut rng = Rng::new(13);
    let p = ring_s2(&mut rng, 5);
    let k = uniform(6);
    let closed = CatmullRom::try_new_closed(p.clone(), Some(k.clone())).unwrap();
    // c₄, c₀ … c₄, c₀, c₁: the open spline through c₀ … c₄, c₀ with the loop's neighbours.
    let mut open_points = vec![p[4]];
    open_points.extend_from_slice(&p);
    open_points.extend([p[0], p[1]]);
    let open = CatmullRom::try_new(open_points, Some(k)).unwrap();
    for j in 0..=50 {
        let t = 5.0 * f64::from(j) / 50.0;
        assert!(closed.eval(t).dist(&open.eval(t)) < 1e-15, "t = {t}");
    }
}

#[test]
fn squad_loops_are_c1_at_the_seam() {
    let mut rng = Rng::new(14);
    for m in [3, 8] {
        let k = times(&mut rng, m + 1);
        let q = ring_s3(&mut rng, m);
        let c = Squad::try_new_closed(q.clone(), Some(k.clone())).unwrap();
        check_loop(&c, Some((&q, &k)), Smooth::C1);
        assert_eq!(c.keys(), &q[..]);
        assert_eq!(c.controls()[0], c.controls()[m], "s_m = s_0");
        let c = Squad::try_new_closed(q.clone(), None).unwrap();
        check_loop(&c, Some((&q, &uniform(m + 1))), Smooth::C1);
    }
}

#[test]
fn kim_bspline_loops_have_a_periodic_control_polygon_and_are_c2() {
    let mut rng = Rng::new(15);
    for m in [3, 4, 9] {
        let q = ring_s3(&mut rng, m);
        let c = BsplineKim::try_new_closed(q.clone()).unwrap();
        assert_eq!(c.domain(), [0.0, m as f64]);
        assert_eq!(c.controls(), &q[..]);
        check_loop(&c, None, Smooth::C2);
        // Periodic: piece 0 of the loop is the open B-spline on q_{0..3} (wrapped).
        let open = BsplineKim::try_new(vec![q[0], q[1], q[2], q[3 % m]]).unwrap();
        for j in 0..=10 {
            let t = f64::from(j) / 10.0;
            assert!(c.eval(t).dist(&open.eval(t)) < 1e-15, "t = {t}");
        }
    }
}

#[test]
fn gamma_loops_are_c1_at_the_seam_and_report_it() {
    let mut rng = Rng::new(16);
    for m in [3, 6] {
        let k = times(&mut rng, m + 1);
        let q = ring_s3(&mut rng, m);
        let gammas: Vec<f64> = (0..m).map(|_| rng.range(0.3, 2.0)).collect();
        for g in [Gammas::All(1.0), Gammas::Each(gammas.clone())] {
            let c = GammaSpline::try_new_closed(q.clone(), Some(k.clone()), g).unwrap();
            check_loop(&c, None, Smooth::C1);
            assert_eq!(c.controls().len(), 3 * m + 1);
            let report = c.joint_report();
            assert_eq!(report.len(), m, "every knot, the seam last");
            assert_eq!(report[m - 1].index, m);
            assert!(report.iter().all(|j| j.first_derivative_jump < 1e-10));
            // The report's C² residual is the second-derivative jump over 6·|b₃ᵢ| (= 1).
            for j in &report {
                let predicted = 6.0 * j.general_residual.length();
                assert!(
                    (predicted - j.second_derivative_jump).abs() <= 1e-8 * predicted.max(1.0),
                    "joint {}: {predicted} vs {}",
                    j.index,
                    j.second_derivative_jump
                );
            }
        }
    }
}

#[test]
fn beta_loops_solve_the_periodic_system_on_every_sphere() {
    let mut rng = Rng::new(17);
    for solver in [BetaSolver::Newton, BetaSolver::Jacobi] {
        let params = BetaParams {
            solver,
            ..BetaParams::default()
        };
        for m in [3, 7] {
            let p = ring_s2(&mut rng, m);
            let c = BetaSpline::try_new_closed(p.clone(), &params).unwrap();
            check_loop(&c, Some((&p, &uniform(m + 1))), Smooth::C1);
            assert!(c.solve_info().unwrap().residual <= 1e-12 || solver == BetaSolver::Jacobi);
            let q = ring_s3(&mut rng, m);
            let c = BetaSpline::try_new_closed(q.clone(), &params).unwrap();
            check_loop(&c, Some((&q, &uniform(m + 1))), Smooth::C1);
            let s = ring_s5(&mut rng, m);
            let c = BetaSpline::try_new_closed(s.clone(), &params)
                .unwrap_or_else(|e| panic!("{solver:?} m = {m}: {e} {s:?}"));
            check_loop(&c, Some((&s, &uniform(m + 1))), Smooth::C1);
        }
    }
}

/// With a bias β₁ per point the loop is G¹ everywhere, the seam included, with the speed ratio
/// `X′(i⁺) = β₁ᵢ·X′(i⁻)` of eq. (6), `β₁,₀` at the seam.
#[test]
fn beta_loops_with_bias_are_g1_with_the_bias_ratio_at_the_seam() {
    let mut rng = Rng::new(18);
    let m = 5;
    let p = ring_s2(&mut rng, m);
    let beta1: Vec<f64> = (0..m).map(|_| rng.range(0.5, 2.0)).collect();
    let beta2: Vec<f64> = (0..m).map(|_| rng.range(0.0, 3.0)).collect();
    let params = BetaParams {
        beta1: beta1.clone().into(),
        beta2: beta2.into(),
        ..BetaParams::default()
    };
    let c = BetaSpline::try_new_closed(p.clone(), &params).unwrap();
    check_loop(&c, Some((&p, &uniform(m + 1))), Smooth::G1);
    for (i, b) in beta1.iter().enumerate() {
        let left = c.jet_at(if i == 0 { m as f64 } else { i as f64 }, Side::Left);
        let right = c.jet_at(i as f64, Side::Right);
        let d = (right.velocity - left.velocity * *b).length();
        assert!(d < 1e-9, "speed ratio β₁ at joint {i}: {d:e}");
    }
    // Built from a periodic polygon of auxiliary vertices, without a solve.
    let aux = BetaSpline::try_new_closed(
        p.clone(),
        &BetaParams {
            interpolate: false,
            ..BetaParams::default()
        },
    )
    .unwrap();
    check_loop(&aux, None, Smooth::C1);
    assert!(aux.solve_info().is_none());
}

/// The derivatives of orders `0…=n` at the end (from the left) and at the start (from the
/// right) agree: Cⁿ at the seam, exactly, for any order.
#[track_caller]
fn check_seam_order<V: Ambient>(end: &[V], start: &[V], n: usize) {
    for (k, (a, b)) in end.iter().zip(start).enumerate().take(n + 1) {
        let scale = a.length().max(b.length()).max(1.0);
        let jump = (a.clone() - b.clone()).length() / scale;
        assert!(
            jump < 1e-10,
            "order {k} jump {jump:e} at the seam (n = {n})"
        );
    }
}

#[test]
fn arc_blend_loops_are_cn_at_the_seam_for_every_timing() {
    let mut rng = Rng::new(19);
    for n in [1, 2, 4] {
        for m in [3, 6] {
            let k = times(&mut rng, m + 1);
            let timings = [
                ArcBlendTiming::Auto,
                ArcBlendTiming::ArcLength,
                ArcBlendTiming::Uniform,
                ArcBlendTiming::Knots(k.clone()),
            ];
            let p = ring_s2(&mut rng, m);
            let q = ring_s3(&mut rng, m);
            let s = ring_s5(&mut rng, m);
            for timing in timings {
                let c = ArcBlend::try_with_closed(p.clone(), n, timing.clone()).unwrap();
                let smooth = if n == 1 { Smooth::C1 } else { Smooth::C2 };
                check_loop(&c, Some((&p, c.knots())), smooth);
                let [t0, t1] = c.domain();
                check_seam_order(
                    &c.derivatives(t1, Side::Left, n),
                    &c.derivatives(t0, Side::Right, n),
                    n,
                );
                let c = ArcBlend::try_with_closed(q.clone(), n, timing.clone()).unwrap();
                check_loop(&c, Some((&q, c.knots())), smooth);
                let [t0, t1] = c.domain();
                check_seam_order(
                    &c.derivatives(t1, Side::Left, n),
                    &c.derivatives(t0, Side::Right, n),
                    n,
                );
                let c = ArcBlend::try_with_closed(s.clone(), n, timing).unwrap();
                check_loop(&c, Some((&s, c.knots())), smooth);
            }
        }
    }
}

/// A closed loop of points on one circle (not a great circle, at unequal angles) is that circle:
/// the book's knots close (the ratios telescope), `Auto` takes them, and the curve turns at one
/// angular speed; the other timings trace the same circle.
#[test]
fn arc_blend_loop_of_co_circular_points_is_the_circle() {
    let (center, radius) = (DVec3::new(0.0, 0.0, 0.6), 0.8);
    let angles = [0.0, 0.9, 1.7, 2.9, 3.6, 4.4, 5.5];
    let p: Vec<S2Point> = angles
        .iter()
        .map(|&a: &f64| {
            S2Point::try_new(center + DVec3::new(a.cos(), a.sin(), 0.0) * radius).unwrap()
        })
        .collect();
    for n in [1, 2, 3] {
        let book = ArcBlend::try_new_closed(p.clone(), n).unwrap();
        assert_eq!(
            book.timing(),
            ArcBlendTiming::Book,
            "auto takes the book's knots"
        );
        let explicit = ArcBlend::try_with_closed(p.clone(), n, ArcBlendTiming::Book).unwrap();
        assert_eq!(explicit.knots(), book.knots());
        check_loop(&book, Some((&p, book.knots())), Smooth::C2);
        // The book's knots are the angles: t_i = α_i (unit angular speed, radius 0.8).
        for (t, a) in book.knots().iter().zip(angles.iter().chain([&TAU])) {
            assert!((t - a).abs() < 1e-12, "knot {t} vs angle {a}");
        }
        for timing in [
            ArcBlendTiming::Auto,
            ArcBlendTiming::ArcLength,
            ArcBlendTiming::Uniform,
        ] {
            let c = ArcBlend::try_with_closed(p.clone(), n, timing.clone()).unwrap();
            let [t0, t1] = c.domain();
            for j in 0..=700 {
                let t = t0 + (t1 - t0) * f64::from(j) / 700.0;
                let x = c.eval(t).as_dvec3();
                let off_plane = (x.z - center.z).abs();
                let off_circle = ((x - center).length() - radius).abs();
                assert!(
                    off_plane < 1e-12 && off_circle < 1e-12,
                    "{timing:?} t = {t}: {off_plane:e} {off_circle:e}"
                );
                if timing == ArcBlendTiming::Auto {
                    let speed = c.jet(t).velocity.length();
                    assert!((speed - radius).abs() < 1e-8, "speed {speed} at t = {t}");
                }
            }
        }
    }
}

#[test]
fn corner_blend_loops_blend_every_corner_and_are_cn_at_the_seam() {
    let mut rng = Rng::new(20);
    for n in [1, 2, 3] {
        for fraction in [0.2, 0.5] {
            for m in [3, 5] {
                let smooth = if n == 1 { Smooth::C1 } else { Smooth::C2 };
                let p = ring_s2(&mut rng, m);
                let c = CornerBlend::try_new_closed(p.clone(), n, fraction).unwrap();
                let corners = if fraction == 0.5 { m } else { 2 * m };
                assert_eq!(c.knots().len(), corners + 1, "a corner at every vertex");
                check_loop(&c, None, smooth);
                let [t0, t1] = c.domain();
                check_seam_order(
                    &c.derivatives(t1, Side::Left, n),
                    &c.derivatives(t0, Side::Right, n),
                    n,
                );
                // The speed at the seam is the speed it starts with (unit on the first edge).
                assert!((c.jet(t0).velocity.length() - 1.0).abs() < 1e-12);
                let q = ring_s3(&mut rng, m);
                let c = CornerBlendRotations::try_new_closed(q.clone(), n, fraction).unwrap();
                check_loop(&c, None, smooth);
                let [t0, t1] = c.domain();
                check_seam_order(
                    &c.derivatives(t1, Side::Left, n),
                    &c.derivatives(t0, Side::Right, n),
                    n,
                );
                let c = CornerBlend::try_new_closed(q, n, fraction).unwrap();
                check_loop(&c, None, smooth);
                let s = ring_s5(&mut rng, m);
                let c = CornerBlend::try_new_closed(s, n, fraction).unwrap();
                check_loop(&c, None, smooth);
            }
        }
    }
}

/// Cuts per corner, a start and a speed, and small-circle edges close too; incoming and
/// outgoing cuts whose speed factors do not multiply to 1 around the loop are refused.
#[test]
fn corner_blend_loops_with_cuts_timing_and_arcs() {
    let mut rng = Rng::new(22);
    let m = 5;
    let p = ring_s2(&mut rng, m);
    let timing = CornerTiming {
        start: -2.0,
        speed: 1.7,
    };
    let per: Vec<f64> = (0..m).map(|_| rng.range(0.1, 0.45)).collect();
    let c = CornerBlend::try_with_closed(p.clone(), 3, &CornerCuts::PerCorner(per.clone()), timing)
        .unwrap();
    assert_eq!(c.domain()[0], -2.0);
    assert!((c.jet(-2.0).velocity.length() - 1.7).abs() < 1e-12);
    check_loop(&c, None, Smooth::C2);
    let [t0, t1] = c.domain();
    check_seam_order(
        &c.derivatives(t1, Side::Left, 3),
        &c.derivatives(t0, Side::Right, 3),
        3,
    );
    let bends: Vec<f64> = (0..m).map(|_| rng.range(-0.3, 0.3)).collect();
    let arcs =
        CornerBlend::try_with_arcs_closed(p.clone(), 2, &CornerCuts::Uniform(0.3), timing, &bends)
            .unwrap();
    check_loop(&arcs, None, Smooth::C2);
    let e = CornerBlend::try_with_arcs_closed(
        p.clone(),
        2,
        &CornerCuts::Uniform(0.3),
        timing,
        &bends[..m - 1],
    )
    .unwrap_err();
    assert!(
        matches!(e, SplineError::InvalidParameter { name: "bend", .. }),
        "{e}"
    );
    // Pairs whose ratios cancel around the loop close; others would change speed at the seam.
    let pairs: Vec<[f64; 2]> = vec![[0.2, 0.3], [0.3, 0.2], [0.25, 0.25], [0.2, 0.2], [0.3, 0.3]];
    let q = ring_s3(&mut rng, m);
    let c = CornerBlendRotations::try_with_closed(q.clone(), 2, &CornerCuts::Pairs(pairs), timing)
        .unwrap();
    check_loop(&c, None, Smooth::C2);
    let skewed = vec![[0.2, 0.3]; m];
    let e = CornerBlendRotations::try_with_closed(q, 2, &CornerCuts::Pairs(skewed), timing)
        .unwrap_err();
    assert!(
        matches!(&e, SplineError::InvalidParameter { name: "fraction", reason } if reason.contains("multiply to 1")),
        "{e}"
    );
    let e =
        CornerBlend::try_with_closed(p, 2, &CornerCuts::PerCorner(per[..m - 1].to_vec()), timing)
            .unwrap_err();
    assert!(e.to_string().contains("the points 1 to 4 and 0"), "{e}");
}

#[test]
fn bad_loops_are_typed_errors() {
    let mut rng = Rng::new(21);
    let p = ring_s2(&mut rng, 5);
    let two = p[..2].to_vec();
    let few = SplineError::TooFewPoints { min: 3, got: 2 };
    assert_eq!(
        GeodesicSpline::try_new_closed(two.clone(), None).unwrap_err(),
        few
    );
    assert_eq!(
        NlerpSpline::try_new_closed(two.clone(), None).unwrap_err(),
        few
    );
    assert_eq!(
        CatmullRom::try_new_closed(two.clone(), None).unwrap_err(),
        few
    );
    assert_eq!(ArcBlend::try_new_closed(two.clone(), 2).unwrap_err(), few);
    assert_eq!(
        CornerBlend::try_new_closed(two.clone(), 2, 0.3).unwrap_err(),
        few
    );
    assert_eq!(
        BetaSpline::try_new_closed(two, &BetaParams::default()).unwrap_err(),
        few
    );
    let q = ring_s3(&mut rng, 5);
    let q2 = q[..2].to_vec();
    assert_eq!(Squad::try_new_closed(q2.clone(), None).unwrap_err(), few);
    assert_eq!(BsplineKim::try_new_closed(q2.clone()).unwrap_err(), few);
    assert_eq!(
        GammaSpline::try_new_closed(q2.clone(), None, Gammas::All(1.0)).unwrap_err(),
        few
    );
    assert_eq!(
        CornerBlendRotations::try_new_closed(q2, 2, 0.3).unwrap_err(),
        few
    );

    // Knots: one more than points.
    let count = SplineError::KnotCount {
        expected: 6,
        got: 5,
    };
    let five = Some(uniform(5));
    assert_eq!(
        GeodesicSpline::try_new_closed(p.clone(), five.clone()).unwrap_err(),
        count
    );
    assert_eq!(
        NlerpSpline::try_new_closed(p.clone(), five.clone()).unwrap_err(),
        count
    );
    assert_eq!(
        CatmullRom::try_new_closed(p.clone(), five.clone()).unwrap_err(),
        count
    );
    assert_eq!(
        Squad::try_new_closed(q.clone(), five.clone()).unwrap_err(),
        count
    );
    assert_eq!(
        GammaSpline::try_new_closed(q.clone(), five.clone(), Gammas::All(1.0)).unwrap_err(),
        count
    );
    assert_eq!(
        ArcBlend::try_with_closed(p.clone(), 2, ArcBlendTiming::Knots(uniform(5))).unwrap_err(),
        count
    );
    let flat_knots = vec![0.0, 1.0, 2.0, 2.0, 3.0, 4.0];
    let flat = Some(flat_knots.clone());
    let increasing = SplineError::KnotsNotIncreasing { index: 3 };
    assert_eq!(
        GeodesicSpline::try_new_closed(p.clone(), flat.clone()).unwrap_err(),
        increasing
    );
    assert_eq!(
        CatmullRom::try_new_closed(p.clone(), flat.clone()).unwrap_err(),
        increasing
    );
    assert_eq!(
        Squad::try_new_closed(q.clone(), flat.clone()).unwrap_err(),
        increasing
    );
    assert_eq!(
        ArcBlend::try_with_closed(p.clone(), 2, ArcBlendTiming::Knots(flat_knots)).unwrap_err(),
        increasing
    );
    // γ: one per knot but the last.
    assert!(matches!(
        GammaSpline::try_new_closed(q.clone(), None, Gammas::Each(vec![1.0; 4])).unwrap_err(),
        SplineError::InvalidParameter { name: "gamma", .. }
    ));

    // Antipodal neighbours, and an antipodal closing pair.
    let mut anti = p.clone();
    anti[2] = S2Point::try_new(-anti[1].as_dvec3()).unwrap();
    for e in [
        GeodesicSpline::try_new_closed(anti.clone(), None).unwrap_err(),
        CatmullRom::try_new_closed(anti.clone(), None).unwrap_err(),
        ArcBlend::try_new_closed(anti.clone(), 2).unwrap_err(),
        CornerBlend::try_new_closed(anti.clone(), 2, 0.3).unwrap_err(),
        BetaSpline::try_new_closed(anti, &BetaParams::default()).unwrap_err(),
    ] {
        assert_eq!(e, SplineError::Antipodal { index: 1 });
    }
    let mut closing = p.clone();
    closing[4] = S2Point::try_new(-closing[0].as_dvec3()).unwrap();
    for e in [
        GeodesicSpline::try_new_closed(closing.clone(), None).unwrap_err(),
        NlerpSpline::try_new_closed(closing.clone(), None).unwrap_err(),
        CatmullRom::try_new_closed(closing.clone(), None).unwrap_err(),
        ArcBlend::try_new_closed(closing.clone(), 2).unwrap_err(),
        CornerBlend::try_new_closed(closing.clone(), 2, 0.3).unwrap_err(),
        BetaSpline::try_new_closed(closing, &BetaParams::default()).unwrap_err(),
    ] {
        assert_eq!(e, SplineError::AntipodalClosing);
    }
    let mut qa = q.clone();
    qa[4] = -qa[0];
    for e in [
        Squad::try_new_closed(qa.clone(), None).unwrap_err(),
        BsplineKim::try_new_closed(qa.clone()).unwrap_err(),
        GammaSpline::try_new_closed(qa.clone(), None, Gammas::All(1.0)).unwrap_err(),
        CornerBlendRotations::try_new_closed(qa, 2, 0.3).unwrap_err(),
    ] {
        assert_eq!(e, SplineError::AntipodalClosing);
    }
    // A repeated first point at the end is not a loop of distinct points for the blends.
    let mut repeated = p.clone();
    repeated[4] = repeated[0];
    assert_eq!(
        ArcBlend::try_new_closed(repeated.clone(), 2).unwrap_err(),
        SplineError::CoincidentClosing
    );
    assert_eq!(
        CornerBlend::try_new_closed(repeated.clone(), 2, 0.3).unwrap_err(),
        SplineError::CoincidentClosing
    );
    assert_eq!(
        BetaSpline::try_new_closed(repeated, &BetaParams::default()).unwrap_err(),
        SplineError::CoincidentClosing
    );
    // A triple that wraps around the end with no circle: p₃ = p₀ (m = 5, triple 3, 4, 0).
    let mut wrap = p.clone();
    wrap[3] = wrap[0];
    assert_eq!(
        ArcBlend::try_new_closed(wrap, 2).unwrap_err(),
        SplineError::NoCircleAround {
            first: 3,
            middle: 4,
            last: 0
        }
    );
    // The book's knots close only when the ratios ψ/φ multiply to 1.
    let e = ArcBlend::try_with_closed(p.clone(), 2, ArcBlendTiming::Book).unwrap_err();
    assert!(
        matches!(e, SplineError::TimingNotClosed { timing: "book", ratio } if (ratio - 1.0).abs() > 1e-6),
        "{e:?}"
    );
    assert!(e.to_string().contains("do not close"), "{e}");
    // Auto falls back to a timing that closes.
    let auto = ArcBlend::try_new_closed(p, 2).unwrap();
    assert_ne!(auto.timing(), ArcBlendTiming::Book);
}
