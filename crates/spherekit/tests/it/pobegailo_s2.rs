// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's smoothing polynomials, circle blending and corner smoothing on S²
//! (Pobegailo 2019, chapters 7–8; corrections in `docs/derivations.md`).

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::{FRAC_PI_2, FRAC_PI_8, PI};

use spherekit::glam::{DMat3, DVec3};
use spherekit::{
    ArcBlend, CircleArc, CornerBlend, Curve, GroupJet, Manifold, S2Point, Side,
    SmoothingPolynomials, SplineError,
};

use crate::support::{Rng, check_continuity, check_derivatives};

fn p(x: f64, y: f64, z: f64) -> S2Point {
    S2Point::try_new(DVec3::new(x, y, z)).unwrap()
}

fn close3(a: DVec3, b: [f64; 3], tol: f64) {
    let b = DVec3::from_array(b);
    assert!((a - b).length() < tol, "{a:?} vs {b:?}");
}

/// R(â, θ)v by Rodrigues' formula (Pobegailo 2019, §3.3–3.4).
fn rot(a: DVec3, theta: f64, v: DVec3) -> DVec3 {
    let (s, c) = theta.sin_cos();
    a * a.dot(v) + (v - a * a.dot(v)) * c + a.cross(v) * s
}

fn algorithm_a_points() -> Vec<S2Point> {
    vec![
        p(1.0, 0.0, 0.3),
        p(0.6, 0.8, 0.4),
        p(-0.2, 1.0, 0.1),
        p(-0.9, 0.3, -0.2),
        p(-0.7, -0.6, 0.0),
    ]
}

fn random_walk(rng: &mut Rng, count: usize) -> Vec<S2Point> {
    let mut x = DVec3::new(rng.normal(), rng.normal(), rng.normal()).normalize();
    let mut out = vec![S2Point::try_new(x).unwrap()];
    while out.len() < count {
        let step = DVec3::new(rng.normal(), rng.normal(), rng.normal()) * 0.8;
        x = (x + step - x * x.dot(step)).normalize();
        out.push(S2Point::try_new(x).unwrap());
    }
    out
}

fn poly_eval(coeffs: &[f64], u: f64) -> f64 {
    coeffs.iter().rev().fold(0.0, |acc, c| acc * u + c)
}

// ------------------------------------------------------------ smoothing polynomials (§7.5–7.7)

#[test]
fn smoothing_reference_values() {
    // Reference values, computed independently in higher precision.
    let table = [
        (
            1,
            [7.0 / 64.0, 3.0 / 8.0, 45.0 / 64.0],
            [9.0 / 64.0, 1.0 / 8.0, 3.0 / 64.0],
        ),
        (
            2,
            [67.0 / 1024.0, 11.0 / 32.0, 729.0 / 1024.0],
            [189.0 / 1024.0, 5.0 / 32.0, 39.0 / 1024.0],
        ),
        (
            3,
            [347.0 / 8192.0, 21.0 / 64.0, 5913.0 / 8192.0],
            [1701.0 / 8192.0, 11.0 / 64.0, 231.0 / 8192.0],
        ),
    ];
    for (n, w1, w2) in table {
        let w = SmoothingPolynomials::try_new(n).unwrap();
        for (i, u) in [0.25, 0.5, 0.75].into_iter().enumerate() {
            assert!((w.w1(u) - w1[i]).abs() < 1e-15, "w1,{n}({u})");
            assert!((w.w2(u) - w2[i]).abs() < 1e-15, "w2,{n}({u})");
        }
    }
}

#[test]
fn smoothing_monomial_forms() {
    // The explicit polynomials, n = 1…5, values and the first three derivatives.
    let w1: [&[f64]; 5] = [
        &[0.0, 0.0, 2.0, -1.0],
        &[0.0, 0.0, 0.0, 6.0, -8.0, 3.0],
        &[0.0, 0.0, 0.0, 0.0, 20.0, -45.0, 36.0, -10.0],
        &[0.0, 0.0, 0.0, 0.0, 0.0, 70.0, -224.0, 280.0, -160.0, 35.0],
        &[
            0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 252.0, -1050.0, 1800.0, -1575.0, 700.0, -126.0,
        ],
    ];
    for (i, c) in w1.iter().enumerate() {
        let w = SmoothingPolynomials::try_new(i + 1).unwrap();
        assert_eq!(w.degree(), c.len() - 1, "degree");
        let mut d = c.to_vec();
        for k in 0..4 {
            for j in 0..=20 {
                let u = f64::from(j) / 20.0;
                let want = poly_eval(&d, u);
                let scale = d.iter().map(|x| x.abs()).sum::<f64>().max(1.0);
                assert!(
                    (w.w1_derivative(u, k) - want).abs() < 1e-13 * scale,
                    "w1,{} ^({k}) at {u}",
                    i + 1
                );
                let lin = match k {
                    0 => u,
                    1 => 1.0,
                    _ => 0.0,
                };
                assert!(
                    (w.w2_derivative(u, k) - (lin - want)).abs() < 1e-13 * scale,
                    "w2 ^({k})"
                );
            }
            d = d
                .iter()
                .enumerate()
                .skip(1)
                .map(|(j, x)| x * j as f64)
                .collect();
        }
    }
}

#[test]
fn smoothing_boundary_derivatives_and_tightness() {
    // Order-(n+1) end derivatives (Theorems 4, 5 of §7.6).
    let tight = [
        (4.0, -2.0),
        (36.0, 24.0),
        (480.0, -360.0),
        (8400.0, 6720.0),
        (181_440.0, -151_200.0),
    ];
    for n in 1..=10 {
        let w = SmoothingPolynomials::try_new(n).unwrap();
        assert_eq!(w.w1(0.0), 0.0, "w1(0)");
        assert!((w.w1(1.0) - 1.0).abs() < 1e-15, "w1(1)");
        assert_eq!(w.w2(0.0), 0.0, "w2(0)");
        assert_eq!(w.w2(1.0), 0.0, "w2(1)");
        for m in 1..=n {
            let one = if m == 1 { 1.0 } else { 0.0 };
            assert!(w.w1_derivative(0.0, m).abs() < 1e-9, "w1^({m})(0), n = {n}");
            assert!(
                (w.w1_derivative(1.0, m) - one).abs() < 1e-9,
                "w1^({m})(1), n = {n}"
            );
            assert!(
                (w.w2_derivative(0.0, m) - one).abs() < 1e-9,
                "w2^({m})(0), n = {n}"
            );
            assert!(w.w2_derivative(1.0, m).abs() < 1e-9, "w2^({m})(1), n = {n}");
        }
        let (a, b) = (w.w1_derivative(0.0, n + 1), w.w1_derivative(1.0, n + 1));
        assert!(a.abs() > 1.0 && b.abs() > 1.0, "order n+1 non-zero");
        assert!(
            (w.w2_derivative(0.0, n + 1) + a).abs() < 1e-9 * a.abs(),
            "w2 = u − w1"
        );
        if n <= 5 {
            let (ta, tb) = tight[n - 1];
            assert!(
                (a - ta).abs() < 1e-9 * ta.abs() && (b - tb).abs() < 1e-9 * tb.abs(),
                "n = {n}: {a} {b}"
            );
        }
        // Degree 2n + 1: the derivative of order 2n + 2 vanishes.
        assert_eq!(w.w1_derivative(0.3, 2 * n + 2), 0.0, "degree");
        // Identity w1 + w2 = u (`docs/derivations.md#pobegailo-linear-precision`) and the value at
        // 1/2.
        for j in 0..=16 {
            let u = f64::from(j) / 16.0;
            assert!((w.w1(u) + w.w2(u) - u).abs() < 1e-15, "w1 + w2 = u");
            assert!(
                w.w1_derivative(u, 1) >= -1e-15 && w.w2(u) >= 0.0,
                "monotone / non-negative"
            );
        }
    }
}

#[test]
fn printed_w22_fails_the_boundary_conditions() {
    // The monograph prints w2,2 = (1−u)²u³ + 4(1−u)u⁴; its derivative at 0 is 0, not 1, and at 1
    // it is −4, not 0. The definition (used by the library) satisfies both.
    let printed_d = |u: f64| {
        // d/du [(1−u)²u³ + 4(1−u)u⁴]
        -2.0 * (1.0 - u) * u.powi(3)
            + 3.0 * (1.0 - u).powi(2) * u * u
            + 16.0 * (1.0 - u) * u.powi(3)
            - 4.0 * u.powi(4)
    };
    assert!((printed_d(0.0) - 1.0).abs() > 0.5, "printed w2,2'(0) = 0");
    assert!(
        (printed_d(1.0) + 4.0).abs() < 1e-15,
        "printed w2,2'(1) = −4"
    );
    let w = SmoothingPolynomials::try_new(2).unwrap();
    assert!(
        (w.w2_derivative(0.0, 1) - 1.0).abs() < 1e-15,
        "w2,2'(0) = 1"
    );
    assert!(w.w2_derivative(1.0, 1).abs() < 1e-15, "w2,2'(1) = 0");
}

#[test]
fn smoothing_derivatives_match_finite_differences_at_high_order() {
    let w = SmoothingPolynomials::try_new(7).unwrap();
    let h = 1e-5;
    for k in 0..8 {
        for u in [0.1, 0.45, 0.8] {
            let fd = (w.w1_derivative(u + h, k) - w.w1_derivative(u - h, k)) / (2.0 * h);
            let ex = w.w1_derivative(u, k + 1);
            assert!(
                (fd - ex).abs() < 1e-5 * ex.abs().max(1.0),
                "k = {k}, u = {u}: {fd} vs {ex}"
            );
        }
    }
}

#[test]
fn smoothing_order_validation() {
    assert!(matches!(
        SmoothingPolynomials::try_new(0),
        Err(SplineError::InvalidParameter { name: "order", .. })
    ));
    assert!(SmoothingPolynomials::try_new(SmoothingPolynomials::MAX_ORDER).is_ok());
    let w = SmoothingPolynomials::try_new(200).unwrap();
    for u in [0.0, 0.3, 0.5, 0.7, 1.0] {
        let (a, b) = (w.w1(u), w.w2(u));
        assert!(
            a.is_finite() && b.is_finite() && (a + b - u).abs() < 1e-13,
            "n = 200 at {u}"
        );
    }
}

// ------------------------------------------------------------------ blending on SO(3) (§7.8)

#[test]
fn lie_group_blend_matches_end_derivatives_on_so3() {
    let skew = |a: DVec3| {
        DMat3::from_cols(
            DVec3::new(0.0, a.z, -a.y),
            DVec3::new(-a.z, 0.0, a.x),
            DVec3::new(a.y, -a.x, 0.0),
        )
    };
    let subgroup = |x: DVec3| {
        move |s: f64| {
            let g = DMat3::from_axis_angle(x.normalize(), s * x.length());
            let k = skew(x);
            GroupJet {
                value: g,
                d1: k * g,
                d2: k * k * g,
            }
        }
    };
    let g1 = subgroup(DVec3::new(0.4, -0.2, 0.9));
    let g2 = subgroup(DVec3::new(-0.7, 0.3, 0.2));
    for n in 1..=3 {
        let w = SmoothingPolynomials::try_new(n).unwrap();
        let (s, e) = (w.blend(g1, g2, 0.0), w.blend(g1, g2, 1.0));
        let d = |a: DMat3, b: DMat3| {
            (a - b)
                .abs()
                .to_cols_array()
                .iter()
                .fold(0.0_f64, |m, x| m.max(*x))
        };
        assert!(d(s.value, DMat3::IDENTITY) < 1e-15, "g(0) = e");
        assert!(d(e.value, g1(1.0).value) < 1e-15, "g(1) = g1(1)");
        assert!(
            d(s.d1, g2(0.0).d1) < 1e-15 && d(e.d1, g1(1.0).d1) < 1e-14,
            "first derivatives"
        );
        let second = d(s.d2, g2(0.0).d2).max(d(e.d2, g1(1.0).d2));
        if n >= 2 {
            assert!(second < 1e-13, "second derivatives, n = {n}");
        } else {
            assert!(second > 1e-2, "n = 1 is not C² at the ends");
        }
        // Exact derivative vs finite differences inside.
        let h = 1e-6;
        let fd = (w.blend(g1, g2, 0.4 + h).d1 - w.blend(g1, g2, 0.4 - h).d1) * (0.5 / h);
        assert!(d(fd, w.blend(g1, g2, 0.4).d2) < 1e-7, "d2 vs FD");
    }
}

// ---------------------------------------------------------- circle through three points (§8.2)

#[test]
fn circle_reference_values() {
    let c = CircleArc::through(&p(1.0, 0.0, 1.0), &p(0.0, 1.0, 1.0), &p(-1.0, 0.0, 1.0)).unwrap();
    close3(c.axis(), [0.0, 0.0, 1.0], 1e-15);
    close3(
        c.center(),
        [0.0, 0.0, core::f64::consts::FRAC_1_SQRT_2],
        1e-15,
    );
    assert!(
        (c.first_angle() - FRAC_PI_2).abs() < 1e-15 && (c.second_angle() - FRAC_PI_2).abs() < 1e-15,
        "angles"
    );

    let (p1, p2, p3) = (p(1.0, 0.0, 0.2), p(0.0, 1.0, 0.5), p(-1.0, 0.3, 0.1));
    let c = CircleArc::through(&p1, &p2, &p3).unwrap();
    close3(c.axis(), [-0.103080757, -0.371987273, 0.922496518], 1e-9);
    close3(c.center(), [-0.008229705, -0.029698516, 0.073649773], 1e-9);
    assert!((c.radius() - 0.996807896).abs() < 1e-9, "radius");
    assert!(
        (c.first_angle() - 1.488851128).abs() < 1e-9
            && (c.second_angle() - 1.272407278).abs() < 1e-9,
        "angles"
    );
    // The arc meets p1, p2, p3 in order.
    let phi = c.first_angle() / (c.first_angle() + c.second_angle());
    assert!(
        c.point_at(0.0).dist(&p1) < 1e-15
            && c.point_at(phi).dist(&p2) < 1e-14
            && c.point_at(1.0).dist(&p3) < 1e-14,
        "arc"
    );
    // Reversing the triple negates the axis and swaps the angles.
    let r = CircleArc::through(&p3, &p2, &p1).unwrap();
    assert!((r.axis() + c.axis()).length() < 1e-14, "reversed axis");
    assert!(
        (r.first_angle() - c.second_angle()).abs() < 1e-14,
        "swapped angles"
    );
}

#[test]
fn circle_random_triples_properties() {
    let mut rng = Rng(0x1234_5678);
    for _ in 0..500 {
        let q: Vec<S2Point> = (0..3)
            .map(|_| p(rng.normal(), rng.normal(), rng.normal()))
            .collect();
        let c = CircleArc::through(&q[0], &q[1], &q[2]).unwrap();
        let (phi, psi) = (c.first_angle(), c.second_angle());
        assert!(
            phi > 0.0 && psi > 0.0 && phi + psi < 2.0 * PI,
            "angle ranges"
        );
        let a = c.axis();
        // δ = â·p_j is the same for the three points; c = δ â; R(â, φ)p1 = p2.
        let delta = a.dot(q[0].as_dvec3());
        for x in &q {
            assert!((a.dot(x.as_dvec3()) - delta).abs() < 1e-13, "plane");
        }
        assert!((c.center() - a * delta).length() < 1e-13, "centre");
        assert!(
            (rot(a, phi, q[0].as_dvec3()) - q[1].as_dvec3()).length() < 1e-13,
            "R(â, φ)p1 = p2"
        );
        assert!(
            (rot(a, phi + psi, q[0].as_dvec3()) - q[2].as_dvec3()).length() < 1e-13,
            "R(â, φ+ψ)p1 = p3"
        );
    }
}

#[test]
fn circle_degenerate_cases() {
    // Three points on a great circle: centre 0.
    let c = CircleArc::through(&S2Point::X, &p(1.0, 1.0, 0.0), &S2Point::Y).unwrap();
    assert!(
        c.center().length() < 1e-15 && (c.radius() - 1.0).abs() < 1e-15,
        "great circle"
    );
    // Antipodal p1, p3: the great circle through them.
    let c = CircleArc::through(&S2Point::Z, &S2Point::X, &p(0.0, 0.0, -1.0)).unwrap();
    close3(c.axis(), [0.0, 1.0, 0.0], 1e-15);
    assert!(
        (c.first_angle() - FRAC_PI_2).abs() < 1e-15 && (c.second_angle() - FRAC_PI_2).abs() < 1e-15,
        "antipodal"
    );
    // p2 diametrically opposite p1 on a small circle: φ = π.
    let h = core::f64::consts::FRAC_1_SQRT_2;
    let c = CircleArc::through(&p(1.0, 0.0, 1.0), &p(-1.0, 0.0, 1.0), &p(0.0, -1.0, 1.0)).unwrap();
    assert!(
        (c.first_angle() - PI).abs() < 1e-15 && (c.radius() - h).abs() < 1e-15,
        "φ = π"
    );
    // Coincident points: no circle.
    assert_eq!(
        CircleArc::through(&S2Point::X, &S2Point::X, &S2Point::Y).unwrap_err(),
        SplineError::Coincident { index: 0 }
    );
    assert_eq!(
        CircleArc::through(&S2Point::X, &S2Point::Y, &S2Point::Y).unwrap_err(),
        SplineError::Coincident { index: 1 }
    );
    assert_eq!(
        CircleArc::through(&S2Point::X, &S2Point::Y, &S2Point::X).unwrap_err(),
        SplineError::NoCircle { index: 0 }
    );
    // Nearly coincident points: finite, still through the three points.
    let c = CircleArc::through(&S2Point::X, &p(1.0, 1e-9, 0.0), &p(0.0, 0.3, 1.0)).unwrap();
    assert!(
        c.point_at(1.0).dist(&p(0.0, 0.3, 1.0)) < 1e-12,
        "near-coincident"
    );
}

// ----------------------------------------------------------------------- Algorithm 8.1 (§8.4)

#[test]
fn arc_blend_reference_values() {
    let curve = ArcBlend::try_new(algorithm_a_points(), 2).unwrap();
    let circles = [
        (
            [-0.409699376, -0.317786866, 0.855077733],
            [0.060109475, 0.046624435, -0.125453630],
            0.886152583,
            0.870106337,
        ),
        (
            [-0.352347351, -0.038766672, 0.935066035],
            [-0.043053980, -0.004736972, 0.114257462],
            0.866990865,
            1.098558448,
        ),
        (
            [-0.462608806, 0.107621514, 0.880006081],
            [-0.130085428, 0.030263131, 0.247457390],
            1.140750027,
            1.091907583,
        ),
    ];
    for (c, (a, centre, phi, psi)) in curve.circles().iter().zip(circles) {
        close3(c.axis(), a, 1e-9);
        close3(c.center(), centre, 1e-9);
        assert!(
            (c.first_angle() - phi).abs() < 1e-9 && (c.second_angle() - psi).abs() < 1e-9,
            "angles"
        );
    }
    let knots = [0.0, 0.886152583, 1.756258920, 2.858764961, 3.914066017];
    for (k, want) in curve.knots().iter().zip(knots) {
        assert!((k - want).abs() < 1e-9, "knot {k} vs {want}");
    }
    let k = curve.knots().to_vec();
    close3(
        curve.eval(1.103679167).as_dvec3(),
        [0.384496334, 0.862670407, 0.328576229],
        1e-9,
    );
    close3(
        curve.eval(1.321205751).as_dvec3(),
        [0.198898153, 0.944931345, 0.259892822],
        1e-9,
    );
    close3(
        curve.eval(2.307511940).as_dvec3(),
        [-0.646604154, 0.756704121, -0.096446575],
        1e-9,
    );
    let mids: [[[f64; 3]; 4]; 3] = [
        [
            [0.831991322, 0.406102978, 0.377982554],
            [0.199779586, 0.945358548, 0.257653514],
            [-0.645927514, 0.756957650, -0.098958387],
            [-0.965160720, -0.204862078, -0.162776880],
        ],
        [
            [0.831991322, 0.406102978, 0.377982554],
            [0.198898153, 0.944931345, 0.259892822],
            [-0.646604154, 0.756704121, -0.096446575],
            [-0.965160720, -0.204862078, -0.162776880],
        ],
        [
            [0.831991322, 0.406102978, 0.377982554],
            [0.198477382, 0.944731570, 0.260938671],
            [-0.646929424, 0.756574947, -0.095271565],
            [-0.965160720, -0.204862078, -0.162776880],
        ],
    ];
    for (n, row) in (1..=3).zip(mids) {
        let c = ArcBlend::try_new(algorithm_a_points(), n).unwrap();
        assert_eq!(c.knots(), curve.knots(), "knots do not depend on n");
        for (i, want) in row.into_iter().enumerate() {
            close3(c.eval(0.5 * (k[i] + k[i + 1])).as_dvec3(), want, 1e-9);
        }
    }
}

#[test]
fn arc_blend_interpolates_and_is_cn() {
    let mut rng = Rng(0xdead_beef);
    for n in 1..=10 {
        for _ in 0..5 {
            let pts = random_walk(&mut rng, 7);
            let c = ArcBlend::try_new(pts.clone(), n).unwrap();
            assert_eq!(c.smoothness(), n, "smoothness");
            for (t, q) in c.knots().iter().zip(&pts) {
                assert!(c.eval(*t).dist(q) < 1e-14, "interpolation");
                assert!(c.jet_at(*t, Side::Left).point.dist(q) < 1e-14, "left limit");
            }
            let k = c.knots();
            check_continuity(&c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
        }
    }
}

#[test]
fn arc_blend_knot_velocity() {
    // A4: r′(t_i) = ω_i â_{i−1} × p_i with ω_i = φ_{i−1,1}/(t_i − t_{i−1}); r′(t₀) = â₀ × p₀.
    let c = ArcBlend::try_new(algorithm_a_points(), 2).unwrap();
    let (k, circles, pts) = (c.knots(), c.circles(), c.points());
    let v0 = c.jet(0.0).velocity;
    assert!(
        (v0 - circles[0].axis().cross(pts[0].as_dvec3())).length() < 1e-15,
        "unit speed at start"
    );
    for i in 1..k.len() - 1 {
        let omega = circles[i - 1].first_angle() / (k[i] - k[i - 1]);
        let want = circles[i - 1].axis().cross(pts[i].as_dvec3()) * omega;
        assert!(
            (c.jet(k[i]).velocity - want).length() < 1e-14,
            "knot velocity {i}"
        );
    }
}

#[test]
fn arc_blend_reproduces_a_circle_at_constant_speed() {
    let axis = DVec3::new(0.3, -0.5, 0.8).normalize();
    let p0 = DVec3::new(0.9, 0.1, -0.2).normalize();
    let angles = [0.0, 0.4, 1.3, 1.9, 3.0, 3.5, 4.6];
    let pts: Vec<S2Point> = angles
        .iter()
        .map(|&a| S2Point::try_new(rot(axis, a, p0)).unwrap())
        .collect();
    for n in 1..=3 {
        let c = ArcBlend::try_new(pts.clone(), n).unwrap();
        for (k, a) in c.knots().iter().zip(angles) {
            assert!((k - a).abs() < 1e-14, "knots are the cumulative angles");
        }
        for j in 0..=100 {
            let t = 4.6 * f64::from(j) / 100.0;
            let jet = c.jet(t);
            assert!(
                (jet.point.as_dvec3() - rot(axis, t, p0)).length() < 1e-14,
                "on the circle at t"
            );
            let speed_want = axis.cross(p0).length();
            assert!(
                (jet.velocity.length() - speed_want).abs() < 1e-14,
                "constant speed"
            );
        }
    }
}

#[test]
fn arc_blend_three_points_is_one_arc() {
    let (a, b, q) = (p(1.0, 0.0, 0.2), p(0.0, 1.0, 0.5), p(-1.0, 0.3, 0.1));
    let c = ArcBlend::try_new(vec![a, b, q], 2).unwrap();
    let circle = CircleArc::through(&a, &b, &q).unwrap();
    let total = circle.first_angle() + circle.second_angle();
    assert!((c.domain()[1] - total).abs() < 1e-15, "domain = φ + ψ");
    for j in 0..=50 {
        let t = total * f64::from(j) / 50.0;
        assert!(
            c.eval(t).dist(&circle.point_at(t / total)) < 1e-14,
            "single arc"
        );
    }
}

#[test]
fn arc_blend_equivariance_and_no_reversal_symmetry() {
    let pts = algorithm_a_points();
    let c = ArcBlend::try_new(pts.clone(), 2).unwrap();
    let rotation = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 1.1);
    let reflection = DMat3::from_diagonal(DVec3::new(1.0, -1.0, 1.0)) * rotation;
    for g in [rotation, reflection] {
        let moved: Vec<S2Point> = pts
            .iter()
            .map(|x| S2Point::try_new(g * x.as_dvec3()).unwrap())
            .collect();
        let d = ArcBlend::try_new(moved, 2).unwrap();
        for (a, b) in c.knots().iter().zip(d.knots()) {
            assert!((a - b).abs() < 1e-14, "identical knots");
        }
        for j in 0..=80 {
            let t = c.domain()[1] * f64::from(j) / 80.0;
            let (x, y) = (c.jet(t), d.jet(t));
            assert!(
                (g * x.point.as_dvec3() - y.point.as_dvec3()).length() < 1e-14,
                "point"
            );
            assert!(
                (g * x.acceleration - y.acceleration).length() < 1e-13,
                "acceleration"
            );
        }
    }
    // A8: the reversed data give a different curve.
    let mut rev = pts.clone();
    rev.reverse();
    let r = ArcBlend::try_new(rev, 2).unwrap();
    let (lc, lr) = (c.domain()[1], r.domain()[1]);
    let gap = (0..=40)
        .map(|j| {
            let s = f64::from(j) / 40.0;
            // Compare the images at the same data-point fractions only where both are defined.
            c.eval(s * lc).dist(&r.eval((1.0 - s) * lr))
        })
        .fold(0.0_f64, f64::max);
    assert!(
        gap > 1e-4 || (lc - lr).abs() > 1e-3,
        "reversal symmetry would be a coincidence"
    );
}

#[test]
fn arc_blend_derivatives_match_finite_differences() {
    for n in 1..=3 {
        check_derivatives(&ArcBlend::try_new(algorithm_a_points(), n).unwrap(), 60);
    }
}

#[test]
fn arc_blend_bad_input() {
    let pts = algorithm_a_points();
    assert_eq!(
        ArcBlend::try_new(pts[..2].to_vec(), 2).unwrap_err(),
        SplineError::TooFewPoints { min: 3, got: 2 }
    );
    for n in [0, 11] {
        assert!(matches!(
            ArcBlend::try_new(pts.clone(), n),
            Err(SplineError::InvalidParameter {
                name: "smoothness",
                ..
            })
        ));
    }
    let mut dup = pts.clone();
    dup[2] = dup[1];
    assert_eq!(
        ArcBlend::try_new(dup, 2).unwrap_err(),
        SplineError::Coincident { index: 1 }
    );
    let mut anti = pts.clone();
    anti[3] = S2Point::try_new(-anti[2].as_dvec3()).unwrap();
    assert_eq!(
        ArcBlend::try_new(anti, 2).unwrap_err(),
        SplineError::Antipodal { index: 2 }
    );
    let back = vec![S2Point::X, S2Point::Y, S2Point::X, S2Point::Z];
    assert_eq!(
        ArcBlend::try_new(back, 2).unwrap_err(),
        SplineError::NoCircle { index: 0 }
    );
    // Nearly coincident and nearly antipodal neighbours: finite unit results.
    let near = vec![
        S2Point::X,
        p(1.0, 1e-9, 0.0),
        S2Point::Y,
        p(-1.0, -1e-7, 1e-9),
    ];
    let c = ArcBlend::try_new(near, 2).unwrap();
    for j in 0..=200 {
        let jet = c.jet(c.domain()[1] * f64::from(j) / 200.0);
        assert!(
            jet.point.as_dvec3().is_finite()
                && jet.velocity.is_finite()
                && jet.acceleration.is_finite(),
            "finite"
        );
        assert!((jet.point.as_dvec3().length() - 1.0).abs() < 1e-14, "unit");
    }
}

// ----------------------------------------------------------------------- Algorithm 8.2 (§8.8)

#[test]
fn corner_blend_reference_values() {
    let pts = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let want = [
        [
            [0.272621355, 0.961234066, 0.041311816],
            [0.146730474, 0.978470168, 0.145142339],
            [0.042938257, 0.961234066, 0.272369924],
        ],
        [
            [0.275940445, 0.960857473, 0.024693878],
            [0.134580709, 0.981888033, 0.133356379],
            [0.025691351, 0.960857473, 0.275849364],
        ],
    ];
    let closest = [0.207882344, 0.190614305];
    for (n, rows) in (1..=2).zip(want) {
        let c = CornerBlend::try_new(pts.clone(), n, 0.25).unwrap();
        let k = c.knots();
        let knots = [0.0, 3.0 * FRAC_PI_8, FRAC_PI_2, 7.0 * FRAC_PI_8];
        for (a, b) in k.iter().zip(knots) {
            assert!((a - b).abs() < 1e-9, "knots");
        }
        for (i, row) in rows.into_iter().enumerate() {
            let t = k[1] + (k[2] - k[1]) * 0.25 * (i as f64 + 1.0);
            close3(c.eval(t).as_dvec3(), row, 1e-9);
        }
        let mid = c.eval(0.5 * (k[1] + k[2]));
        assert!(
            (mid.dist(&S2Point::Y) - closest[n - 1]).abs() < 1e-9,
            "angle to P2"
        );
        // Unit angular speed throughout (symmetric cuts).
        for j in 0..=30 {
            let t = k[3] * f64::from(j) / 30.0;
            if !(k[1]..=k[2]).contains(&t) {
                assert!(
                    (c.jet(t).velocity.length() - 1.0).abs() < 1e-14,
                    "unit speed on the edges"
                );
            }
        }
    }
}

#[test]
fn corner_blend_printed_formula_misses_the_cut_points() {
    // (8.21) as printed applies the rotations to Q₁ instead of P₂.
    let (m, n) = (DVec3::Z, DVec3::X);
    let (phi2, psi1) = (FRAC_PI_8, FRAC_PI_8);
    let p2 = DVec3::Y;
    let q1 = rot(m, -phi2, p2);
    let q2 = rot(n, psi1, p2);
    let w = SmoothingPolynomials::try_new(2).unwrap();
    let printed = |u: f64| rot(n, w.w1(u) * psi1, rot(m, -w.w1(1.0 - u) * phi2, q1));
    let corrected = |u: f64| rot(n, w.w1(u) * psi1, rot(m, -w.w1(1.0 - u) * phi2, p2));
    assert!(
        (printed(0.0) - q1).length() > 0.1 && (printed(1.0) - q2).length() > 0.1,
        "printed misses Q1, Q2"
    );
    assert!(
        (corrected(0.0) - q1).length() < 1e-15 && (corrected(1.0) - q2).length() < 1e-15,
        "corrected hits them"
    );
    // The library's corner segment is the corrected one.
    let c = CornerBlend::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z], 2, 0.25).unwrap();
    let k = c.knots();
    for u in [0.0, 0.3, 0.7, 1.0] {
        let t = k[1] + u * (k[2] - k[1]);
        assert!(
            (c.eval(t).as_dvec3() - corrected(u)).length() < 1e-15,
            "library = corrected (8.21)"
        );
    }
}

#[test]
fn corner_blend_is_cn_and_follows_the_edges() {
    let mut rng = Rng(0xc0ffee);
    for n in 1..=10 {
        for fraction in [0.1, 0.25, 0.5] {
            let pts = random_walk(&mut rng, 6);
            let c = CornerBlend::try_new(pts.clone(), n, fraction).unwrap();
            assert!(
                c.eval(0.0).dist(&pts[0]) < 1e-15 && c.eval(c.domain()[1]).dist(&pts[5]) < 1e-14,
                "ends"
            );
            let k = c.knots();
            check_continuity(&c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
            // Outside the corners the curve is on the edges' great circles; the pieces alternate
            // edge, corner, (edge), corner, …, edge.
            let normals: Vec<DVec3> = pts
                .windows(2)
                .map(|w| w[0].as_dvec3().cross(w[1].as_dvec3()).normalize())
                .collect();
            let first_edge = c.eval(0.5 * k[1]).as_dvec3();
            assert!(normals[0].dot(first_edge).abs() < 1e-14, "first edge");
            let last = c.eval(0.5 * (k[k.len() - 2] + k[k.len() - 1])).as_dvec3();
            assert!(normals[4].dot(last).abs() < 1e-14, "last edge");
        }
    }
}

#[test]
fn corner_blend_straight_vertex_passes_the_vertex() {
    let pts = vec![S2Point::X, p(1.0, 1.0, 0.0), S2Point::Y];
    let c = CornerBlend::try_new(pts, 2, 0.5).unwrap();
    let mut best = f64::MAX;
    for j in 0..=2000 {
        let x = c.eval(c.domain()[1] * f64::from(j) / 2000.0).as_dvec3();
        assert!(x.z.abs() < 1e-15, "stays on the great circle");
        best = best.min((x - p(1.0, 1.0, 0.0).as_dvec3()).length());
    }
    assert!(best < 1e-3, "passes P2");
}

#[test]
fn corner_blend_equivariance_and_derivatives() {
    let pts = algorithm_a_points();
    let c = CornerBlend::try_new(pts.clone(), 3, 0.3).unwrap();
    check_derivatives(&c, 80);
    let g = DMat3::from_diagonal(DVec3::new(-1.0, 1.0, 1.0))
        * DMat3::from_axis_angle(DVec3::new(0.2, 0.9, -0.1).normalize(), 2.0);
    let moved: Vec<S2Point> = pts
        .iter()
        .map(|x| S2Point::try_new(g * x.as_dvec3()).unwrap())
        .collect();
    let d = CornerBlend::try_new(moved, 3, 0.3).unwrap();
    for j in 0..=60 {
        let t = c.domain()[1] * f64::from(j) / 60.0;
        assert!(
            (g * c.eval(t).as_dvec3() - d.eval(t).as_dvec3()).length() < 1e-14,
            "equivariant"
        );
    }
}

#[test]
fn corner_blend_bad_input() {
    let pts = algorithm_a_points();
    assert_eq!(
        CornerBlend::try_new(pts[..2].to_vec(), 2, 0.25).unwrap_err(),
        SplineError::TooFewPoints { min: 3, got: 2 }
    );
    for f in [0.0, -0.1, 0.51, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(
                CornerBlend::try_new(pts.clone(), 2, f),
                Err(SplineError::InvalidParameter {
                    name: "fraction",
                    ..
                })
            ),
            "{f}"
        );
    }
    assert!(matches!(
        CornerBlend::try_new(pts.clone(), 11, 0.25),
        Err(SplineError::InvalidParameter {
            name: "smoothness",
            ..
        })
    ));
    let mut dup = pts.clone();
    dup[3] = dup[2];
    assert_eq!(
        CornerBlend::try_new(dup, 2, 0.25).unwrap_err(),
        SplineError::Coincident { index: 2 }
    );
    let mut anti = pts;
    anti[1] = S2Point::try_new(-anti[0].as_dvec3()).unwrap();
    assert_eq!(
        CornerBlend::try_new(anti, 2, 0.25).unwrap_err(),
        SplineError::Antipodal { index: 0 }
    );
}

#[test]
fn smoothing_matches_the_bernstein_definition_up_to_order_10() {
    // §7.5: w1 = Σ_{j=n+1}^{2n+1} j/(2n+1)·b_{j,2n+1}, w2 = Σ_{j=1}^{n} j/(2n+1)·b_{j,2n+1}.
    let binom = |n: u64, k: u64| (0..k).fold(1.0, |c, i| c * (n - i) as f64 / (i + 1) as f64);
    for n in 1..=10_u64 {
        let w = SmoothingPolynomials::try_new(n as usize).unwrap();
        let big = 2 * n + 1;
        for j in 0..=20 {
            let u = f64::from(j) / 20.0;
            let b = |i: u64| binom(big, i) * (1.0 - u).powi((big - i) as i32) * u.powi(i as i32);
            let w1: f64 = (n + 1..=big).map(|i| i as f64 / big as f64 * b(i)).sum();
            let w2: f64 = (1..=n).map(|i| i as f64 / big as f64 * b(i)).sum();
            assert!(
                (w.w1(u) - w1).abs() < 1e-14 && (w.w2(u) - w2).abs() < 1e-14,
                "n = {n}, u = {u}"
            );
        }
    }
}

#[test]
fn corner_blend_backtracking_vertex_stays_finite_and_smooth() {
    // P₂ → P₃ goes back along the great circle of P₁ → P₂ (n̂ = −m̂), and also exactly back
    // to P₁: the corner reverses direction on the great circle, through zero velocity.
    for pts in [
        vec![S2Point::X, S2Point::Y, p(1.0, 1.0, 0.0)],
        vec![S2Point::X, S2Point::Y, S2Point::X],
    ] {
        let c = CornerBlend::try_new(pts, 2, 0.25).unwrap();
        let k = c.knots();
        check_continuity(&c, |t, s, m| c.derivatives(t, s, m), 2, &k[1..k.len() - 1]);
        for j in 0..=200 {
            let jet = c.jet(k[k.len() - 1] * f64::from(j) / 200.0);
            assert!(
                jet.point.as_dvec3().z.abs() < 1e-15,
                "stays on the great circle"
            );
            assert!(
                jet.velocity.is_finite() && jet.acceleration.is_finite(),
                "finite"
            );
        }
    }
}

/// The circle through three points exactly as in §8.2 (eqs. (8.1)–(8.4), with the atan2 form).
fn c3_book(p1: DVec3, p2: DVec3, p3: DVec3) -> (DVec3, f64, f64) {
    let a = (p3 - p2).cross(p1 - p2);
    let axis = a / a.length();
    let c = axis * (p1.dot(p2.cross(p3)) / a.length());
    let (r1, r2, r3) = (p1 - c, p2 - c, p3 - c);
    let ang = |x: DVec3, y: DVec3| {
        let t = x.cross(y).dot(axis).atan2(x.dot(y));
        if t < 0.0 { t + 2.0 * PI } else { t }
    };
    (axis, ang(r1, r2), ang(r2, r3))
}

#[test]
fn arc_blend_matches_an_independent_implementation_of_algorithm_a() {
    // Algorithm 8.1 written directly from the book (Rodrigues rotations, the circle of §8.2,
    // monomial w): the library agrees to 1e-13 everywhere, beyond 9 digits of reference values.
    let pts = algorithm_a_points();
    let x: Vec<DVec3> = pts.iter().map(|q| q.as_dvec3()).collect();
    let tri: Vec<_> = (0..x.len() - 2)
        .map(|j| c3_book(x[j], x[j + 1], x[j + 2]))
        .collect();
    let k = x.len() - 1;
    let mut t = vec![0.0, tri[0].1];
    for i in 1..k {
        let d = (t[i] - t[i - 1]) * tri[i - 1].2 / tri[i - 1].1;
        t.push(t[i] + d);
    }
    let w1 = |u: f64| u * u * u * (6.0 - 8.0 * u + 3.0 * u * u);
    let book = |s: f64| {
        let i = t.windows(2).position(|w| s <= w[1]).unwrap_or(k - 1);
        let u = (s - t[i]) / (t[i + 1] - t[i]);
        if i == 0 {
            rot(tri[0].0, u * tri[0].1, x[0])
        } else if i == k - 1 {
            rot(tri[k - 2].0, u * tri[k - 2].2, x[k - 1])
        } else {
            let inner = rot(tri[i - 1].0, (u - w1(u)) * tri[i - 1].2, x[i]);
            rot(tri[i].0, w1(u) * tri[i].1, inner)
        }
    };
    let c = ArcBlend::try_new(pts, 2).unwrap();
    for (a, b) in c.knots().iter().zip(&t) {
        assert!((a - b).abs() < 1e-14, "knots");
    }
    for j in 0..=400 {
        let s = t[k] * f64::from(j) / 400.0;
        assert!((c.eval(s).as_dvec3() - book(s)).length() < 1e-13, "t = {s}");
    }
}

#[test]
fn corner_blend_matches_an_independent_implementation_of_algorithm_b() {
    // Algorithm 8.2 (corrected (8.21), `docs/derivations.md#pobegailo-8-21`) for one corner with λ
    // = ¼, n = 2.
    let (p1, p2, p3) = (
        p(1.0, 0.2, 0.1).as_dvec3(),
        p(0.1, 1.0, 0.3).as_dvec3(),
        p(-0.4, 0.2, 1.0).as_dvec3(),
    );
    let m = p1.cross(p2).normalize();
    let n = p2.cross(p3).normalize();
    let phi = p1.cross(p2).length().atan2(p1.dot(p2));
    let psi = p2.cross(p3).length().atan2(p2.dot(p3));
    let (phi1, phi2, psi1, psi2) = (0.75 * phi, 0.25 * phi, 0.25 * psi, 0.75 * psi);
    let (t1, t2) = (0.0, phi1);
    let t3 = t2 + (t2 - t1) / phi1 * phi2;
    let t4 = t3 + (t3 - t2) / psi1 * psi2;
    let w1 = |u: f64| u * u * u * (6.0 - 8.0 * u + 3.0 * u * u);
    let q2 = rot(n, psi1, p2);
    let book = |s: f64| {
        if s <= t2 {
            rot(m, (s - t1) / (t2 - t1) * phi1, p1)
        } else if s <= t3 {
            let u = (s - t2) / (t3 - t2);
            rot(n, w1(u) * psi1, rot(m, -w1(1.0 - u) * phi2, p2))
        } else {
            rot(n, (s - t3) / (t4 - t3) * psi2, q2)
        }
    };
    let pts = vec![
        S2Point::try_new(p1).unwrap(),
        S2Point::try_new(p2).unwrap(),
        S2Point::try_new(p3).unwrap(),
    ];
    let c = CornerBlend::try_new(pts, 2, 0.25).unwrap();
    for (a, b) in c.knots().iter().zip([t1, t2, t3, t4]) {
        assert!((a - b).abs() < 1e-14, "knots");
    }
    for j in 0..=300 {
        let s = t4 * f64::from(j) / 300.0;
        assert!((c.eval(s).as_dvec3() - book(s)).length() < 1e-13, "t = {s}");
    }
}
