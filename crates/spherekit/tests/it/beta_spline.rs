// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Tests of the spherical Beta spline and its interpolation solvers (Yang et al. 2021, §3–5;
//! `docs/derivations.md`).

use spherekit::glam::{DVec3, DVec4};
use spherekit::{
    Ambient, BetaParams, BetaSolver, BetaSpline, Curve, Manifold, S2Point, Side, SmPoint,
    SolveError, SplineError, UnitQuat,
};

use crate::support::Rng;

// ---------------------------------------------------------------------------------------------
// Helpers

fn p(x: f64, y: f64, z: f64) -> S2Point {
    S2Point::try_new(DVec3::new(x, y, z)).expect("non-zero")
}

/// Example 1 of the paper (§5).
fn example1() -> Vec<S2Point> {
    vec![
        p(0.6296, -0.1171, -0.7680),
        p(-0.8142, -0.2856, 0.5055),
        p(-0.4037, 0.6855, 0.6059),
        p(-0.7206, -0.5462, -0.4270),
    ]
}

/// Example 2 of the paper (§5).
#[expect(clippy::approx_constant, reason = "the paper's printed 4-decimal data")]
fn example2() -> Vec<S2Point> {
    vec![
        p(1.0, 0.0, 0.0),
        p(0.6852, -0.5424, 0.4861),
        p(0.7071, 0.0, 0.7071),
        p(0.0, 1.0, 0.0),
    ]
}

fn jacobi() -> BetaParams {
    BetaParams {
        solver: BetaSolver::Jacobi,
        ..BetaParams::default()
    }
}

fn with_beta1(beta1: Vec<f64>) -> BetaParams {
    BetaParams {
        beta1: beta1.into(),
        ..BetaParams::default()
    }
}

fn close3(a: S2Point, b: [f64; 3], tol: f64) -> bool {
    (a.as_dvec3() - DVec3::from_array(b)).abs().max_element() <= tol
}

/// A random walk of `n + 1` points on S^(dim−1) with steps of `lo..hi` radians.
fn walk(rng: &mut Rng, n: usize, dim: usize, lo: f64, hi: f64) -> Vec<Vec<f64>> {
    let mut x = rng.unit(dim);
    let mut out = vec![x.clone()];
    for _ in 0..n {
        let mut t = rng.unit(dim);
        let c: f64 = t.iter().zip(&x).map(|(a, b)| a * b).sum();
        t.iter_mut().zip(&x).for_each(|(a, b)| *a -= c * b);
        let l = t.iter().map(|a| a * a).sum::<f64>().sqrt();
        let ang = rng.range(lo, hi);
        x = x
            .iter()
            .zip(&t)
            .map(|(a, b)| a * ang.cos() + b / l * ang.sin())
            .collect();
        out.push(x.clone());
    }
    out
}

fn s2(v: &[Vec<f64>]) -> Vec<S2Point> {
    v.iter()
        .map(|c| S2Point::try_new(DVec3::new(c[0], c[1], c[2])).expect("unit"))
        .collect()
}

/// The largest distance between the curve at `t = i` and data point `i`.
fn interpolation_error<P: Manifold>(c: &BetaSpline<P>, data: &[P]) -> f64 {
    data.iter()
        .enumerate()
        .map(|(i, d)| c.eval(i as f64).dist(d))
        .fold(0.0, f64::max)
}

/// Checks unit norm and the exact derivatives against central differences inside segments.
fn check_jets<P: Manifold>(c: &BetaSpline<P>) {
    let n = c.segment_count();
    let h = 1e-5;
    for k in 0..(8 * n) {
        let t = (k as f64 + 0.37) / 8.0;
        if t - h < 0.0 || t + h > n as f64 || (t - t.round()).abs() < 2.0 * h {
            continue;
        }
        let jet = c.jet(t);
        let x = jet.point.to_vector();
        assert!((x.length() - 1.0).abs() < 1e-14, "unit norm at {t}");
        let (xp, xm) = (c.eval(t + h).to_vector(), c.eval(t - h).to_vector());
        let d1 = (xp - xm) * (0.5 / h);
        let scale = jet.velocity.length().max(1.0);
        assert!(
            (d1 - jet.velocity.clone()).length() < 1e-6 * scale,
            "first derivative at {t}"
        );
        let (vp, vm) = (c.jet(t + h).velocity, c.jet(t - h).velocity);
        let d2 = (vp - vm) * (0.5 / h);
        let scale = jet.acceleration.length().max(1.0);
        assert!(
            (d2 - jet.acceleration.clone()).length() < 1e-6 * scale,
            "second derivative at {t}"
        );
        assert!(
            jet.velocity.dot(&x).abs() < 1e-12 * scale,
            "velocity tangent at {t}"
        );
    }
}

/// Checks G¹ at every interior joint: equal unit tangents and speed ratio β₁ᵢ.
fn check_g1<P: Manifold>(c: &BetaSpline<P>) {
    for i in 1..c.segment_count() {
        let t = i as f64;
        let (l, r) = (c.jet_at(t, Side::Left), c.jet_at(t, Side::Right));
        assert!(l.point.dist(&r.point) < 1e-15, "C⁰ at joint {i}");
        let (sl, sr) = (l.velocity.length(), r.velocity.length());
        let ratio = sr / sl;
        let b = c.beta1()[i];
        assert!(
            (ratio - b).abs() < 1e-9 * b.max(1.0),
            "speed ratio {ratio} ≠ β₁[{i}] = {b}"
        );
        let ul = l.velocity.clone() * (1.0 / sl);
        let ur = r.velocity * (1.0 / sr);
        assert!((ul - ur).length() < 1e-10, "unit tangents at joint {i}");
    }
    // The continuity report says the same: g1 vanishes, c1 only where β₁ = 1.
    for (j, report) in spherekit::continuity(c).iter().enumerate() {
        assert!(report.g1 < 1e-10, "report: G¹ at joint {}", j + 1);
        let b = c.beta1()[j + 1];
        assert_eq!(
            report.c1 < 1e-9,
            (b - 1.0).abs() < 1e-12,
            "report: C¹ iff β₁ = 1 (joint {})",
            j + 1
        );
    }
}

/// Signed geodesic curvature on S² and the speed.
fn geodesic_curvature(c: &BetaSpline<S2Point>, t: f64, side: Side) -> (f64, f64) {
    let j = c.jet_at(t, side);
    let (x, v, a) = (j.point.as_dvec3(), j.velocity, j.acceleration);
    let s = v.length();
    (x.dot(v.cross(a)) / (s * s * s), s)
}

/// Total absolute geodesic curvature of segment `i` (`∫|κ_g| ds`, composite Simpson).
fn total_curvature(c: &BetaSpline<S2Point>, i: usize) -> f64 {
    let m = 400;
    let h = 1.0 / m as f64;
    let f = |k: usize| {
        let t = i as f64 + k as f64 * h;
        let side = if k == m { Side::Left } else { Side::Right };
        let (kg, s) = geodesic_curvature(c, t, side);
        kg.abs() * s
    };
    let mut sum = f(0) + f(m);
    for k in 1..m {
        sum += f(k) * if k % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

// ---------------------------------------------------------------------------------------------
// The paper's examples

#[test]
fn example_1_reference_values() {
    let data = example1();
    for params in [BetaParams::default(), jacobi()] {
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        let info = c.solve_info().unwrap();
        assert!(interpolation_error(&c, &data) < 1e-9, "{params:?}");
        let d = c.auxiliary();
        // Reference values (4 decimals), computed independently in higher precision.
        assert!(close3(d[1], [-0.7517, -0.1143, 0.6496], 1e-4), "d₁");
        assert!(close3(d[2], [0.2070, 0.8090, 0.5501], 1e-4), "d₂");
        let q = c.controls();
        assert_eq!(q.len(), 10, "3n + 1 control points");
        let inner = [
            (1, [-0.0583, -0.7170, -0.6946]),
            (2, [-0.6973, -0.7157, -0.0388]),
            (4, [-0.5281, 0.2858, 0.7996]),
            (5, [-0.1817, 0.6195, 0.7637]),
            (7, [-0.5940, 0.6977, 0.4005]),
            (8, [-0.9932, 0.1144, -0.0200]),
        ];
        for (k, v) in inner {
            assert!(close3(q[k], v, 1e-4), "control point {k}");
        }
        assert!(
            close3(c.eval(0.5), [-0.4060, -0.8039, -0.4346], 1e-4),
            "X(0.5)"
        );
        assert!(
            close3(c.eval(1.5), [-0.4592, 0.4138, 0.7861], 1e-4),
            "X(1.5)"
        );
        assert!(
            close3(c.eval(2.5), [-0.9073, 0.3765, 0.1872], 1e-4),
            "X(2.5)"
        );
        match params.solver {
            BetaSolver::Newton => {
                assert!(
                    info.iterations <= 6,
                    "Newton iterations {}",
                    info.iterations
                );
                assert!(info.residual < 1e-12, "Newton residual");
            }
            BetaSolver::Jacobi => {
                assert!((90..=120).contains(&info.iterations), "{info:?}");
                assert!(info.residual < 1e-9, "Jacobi residual");
            }
        }
        check_g1(&c);
        check_jets(&c);
    }
}

#[test]
fn example_2_reference_values() {
    let data = example2();
    for params in [BetaParams::default(), jacobi()] {
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        let info = c.solve_info().unwrap();
        assert!(interpolation_error(&c, &data) < 1e-9, "{params:?}");
        let d = c.auxiliary();
        assert!(close3(d[1], [0.5029, -0.7029, 0.5031], 1e-4), "d₁");
        assert!(close3(d[2], [0.6933, -0.1966, 0.6933], 1e-4), "d₂");
        assert!(
            close3(c.eval(0.5), [0.8809, -0.3789, 0.2837], 1e-4),
            "X(0.5)"
        );
        assert!(
            close3(c.eval(1.5), [0.6525, -0.4249, 0.6275], 1e-4),
            "X(1.5)"
        );
        assert!(
            close3(c.eval(2.5), [0.5357, 0.6527, 0.5357], 1e-4),
            "X(2.5)"
        );
        match params.solver {
            BetaSolver::Newton => {
                assert!(info.iterations <= 5 && info.residual < 1e-12, "{info:?}")
            }
            BetaSolver::Jacobi => assert!((20..=40).contains(&info.iterations), "{info:?}"),
        }
        check_g1(&c);
    }
}

/// The paper's stopping rule `Σ‖Δd‖² < 1e-5` stops early with interpolation errors of order
/// 1e-3: 8 and 4 iterations. With the default residual check that is an error.
#[test]
fn paper_stopping_rule_reproduces_iteration_counts() {
    for (data, iterations, residual) in [(example1(), 8, 3.4e-3), (example2(), 4, 4.5e-4)] {
        let loose = BetaParams {
            tolerance: Some(1e-5),
            residual_tolerance: Some(1e-2),
            ..jacobi()
        };
        let info = BetaSpline::try_new(data.clone(), &loose)
            .unwrap()
            .solve_info()
            .unwrap();
        assert_eq!(info.iterations, iterations, "iterations");
        assert!(
            (info.residual - residual).abs() < 0.05 * residual,
            "{} vs {residual}",
            info.residual
        );
        let strict = BetaParams {
            tolerance: Some(1e-5),
            ..jacobi()
        };
        match BetaSpline::try_new(data, &strict) {
            Err(SplineError::Solve(SolveError::NoConvergence {
                iterations: k,
                residual: r,
            })) => {
                assert_eq!(k, iterations, "iterations in the error");
                assert!(
                    (r - residual).abs() < 0.05 * residual,
                    "residual in the error"
                );
            }
            other => panic!("expected NoConvergence, got {other:?}"),
        }
    }
}

/// The tight rule Σ‖Δd‖² < 1e-20 takes 77 and 22 iterations.
#[test]
fn tight_stopping_rule_iteration_counts() {
    for (data, iterations) in [(example1(), 77), (example2(), 22)] {
        let params = BetaParams {
            tolerance: Some(1e-20),
            ..jacobi()
        };
        let info = BetaSpline::try_new(data, &params)
            .unwrap()
            .solve_info()
            .unwrap();
        assert_eq!(info.iterations, iterations, "{info:?}");
    }
}

/// Example 2 with "β₁,₂" (1-based label: β₁ at the joint t = 1) set to 1, 0.5, 0.1: the first
/// segment gets more curved, the second less (1-based labels, `docs/derivations.md#beta-examples`),
/// measured by the total absolute geodesic curvature. Pointwise, the peak curvature in the second
/// half of segment 1
/// rises from 6.57 (β₁ = 1) to 7.53 (β₁ = 0.5); at β₁ = 0.1 the bend moves away from the
/// joint (peak 6.75 at t ≈ 0.6, only 2.4 on [0.75, 1]), so "near the joint" holds for the
/// first step only.
#[test]
fn example_2_beta1_trend() {
    let data = example2();
    let mut near_joint = Vec::new();
    let mut seg1 = Vec::new();
    let mut seg2 = Vec::new();
    for b in [1.0, 0.5, 0.1] {
        let c = BetaSpline::try_new(data.clone(), &with_beta1(vec![1.0, b, 1.0, 1.0])).unwrap();
        assert!(interpolation_error(&c, &data) < 1e-12, "β = {b}");
        check_g1(&c);
        let left = c.jet_at(1.0, Side::Left).velocity.length();
        let right = c.jet_at(1.0, Side::Right).velocity.length();
        assert!((right / left - b).abs() < 1e-9, "speed ratio β₁ at t = 1");
        near_joint.push(
            (0..=200)
                .map(|k| {
                    geodesic_curvature(&c, 0.5 + k as f64 / 400.0, Side::Left)
                        .0
                        .abs()
                })
                .fold(0.0, f64::max),
        );
        seg1.push(total_curvature(&c, 0));
        seg2.push(total_curvature(&c, 1));
        if b == 0.5 {
            assert!(
                close3(c.auxiliary()[1], [0.5783, -0.7262, 0.3718], 1e-4),
                "d₁"
            );
            assert!(
                close3(c.auxiliary()[2], [0.6732, -0.2230, 0.7050], 1e-4),
                "d₂"
            );
        }
        if b == 0.1 {
            assert!(
                close3(c.auxiliary()[1], [0.1722, -0.8732, -0.4558], 1e-4),
                "d₁"
            );
            assert!(
                close3(c.auxiliary()[2], [0.6649, -0.2416, 0.7068], 1e-4),
                "d₂"
            );
        }
    }
    assert!(near_joint[0] < near_joint[1], "{near_joint:?}");
    assert!(
        (near_joint[0] - 6.57).abs() < 0.01 && (near_joint[1] - 7.53).abs() < 0.01,
        "{near_joint:?}"
    );
    assert!(
        seg1[0] < seg1[1] && seg1[1] < seg1[2],
        "segment 1: {seg1:?}"
    );
    assert!(
        seg2[0] > seg2[1] && seg2[1] > seg2[2],
        "segment 2: {seg2:?}"
    );
    // Reference: 0.61 → 1.40 → 2.44 and 1.62 → 0.89 → 0.44.
    for (got, want) in seg1.iter().zip([0.61, 1.40, 2.44]) {
        assert!(
            (got - want).abs() < 0.01,
            "segment 1 total curvature {got} vs {want}"
        );
    }
    for (got, want) in seg2.iter().zip([1.62, 0.89, 0.44]) {
        assert!(
            (got - want).abs() < 0.01,
            "segment 2 total curvature {got} vs {want}"
        );
    }
}

/// β₁ = 0.1 at the joint t = 2 of Example 2 has no solution (`docs/derivations.md#beta-examples`):
/// both solvers report failure instead of returning a curve that does not interpolate.
#[test]
fn infeasible_problem_is_an_error() {
    for solver in [BetaSolver::Newton, BetaSolver::Jacobi] {
        let params = BetaParams {
            solver,
            ..with_beta1(vec![1.0, 1.0, 0.1, 1.0])
        };
        match BetaSpline::try_new(example2(), &params) {
            Err(SplineError::Solve(SolveError::NoConvergence { residual, .. })) => {
                assert!(residual > 0.1, "{solver:?}: residual {residual}");
            }
            other => panic!("{solver:?}: expected NoConvergence, got {other:?}"),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Properties

#[test]
fn gamma_values() {
    let c = |b1: f64, b2: f64| {
        let params = BetaParams {
            beta1: b1.into(),
            beta2: b2.into(),
            interpolate: false,
            ..BetaParams::default()
        };
        BetaSpline::try_new(example2(), &params).unwrap().gamma()[0]
    };
    assert!((c(1.0, 0.0) - 1.0).abs() < 1e-15, "γ(1, 0)");
    assert!((c(0.5, 0.0) - 2.0).abs() < 1e-15, "γ(0.5, 0)");
    assert!((c(0.1, 0.0) - 10.0).abs() < 1e-13, "γ(0.1, 0)");
    assert!((c(1.0, 4.0) - 0.5).abs() < 1e-15, "γ(1, 4)");
}

#[test]
fn auxiliary_vertices_mode() {
    let d = example1();
    let params = BetaParams {
        interpolate: false,
        beta1: vec![0.7, 1.3, 2.0, 0.4].into(),
        beta2: 2.5.into(),
        ..BetaParams::default()
    };
    let c = BetaSpline::try_new(d.clone(), &params).unwrap();
    assert!(c.solve_info().is_none(), "no solve");
    assert_eq!(c.auxiliary(), &d[..], "auxiliary = points");
    assert_eq!(c.domain(), [0.0, 3.0], "domain");
    assert_eq!(c.joints(), &[0.0, 1.0, 2.0, 3.0], "joints");
    assert_eq!(c.eval(0.0), d[0], "X(0) = d₀");
    assert_eq!(c.eval(3.0), d[3], "X(n) = dₙ");
    for i in 0..=3 {
        assert_eq!(c.eval(i as f64), c.controls()[3 * i], "X(i) = q_(i,0)");
    }
    // Clamping outside the domain.
    assert_eq!(c.eval(-1.0), d[0], "clamped below");
    assert_eq!(c.eval(7.0), d[3], "clamped above");
    check_g1(&c);
    check_jets(&c);
    // The control points lie on the arcs d_(i−1) d_i in the ratios γ_(i−1) : 1 : β₁ᵢ²γᵢ.
    let g = c.gamma();
    let b1 = c.beta1();
    for i in 1..=3 {
        let (a, b) = (d[i - 1], d[i]);
        let phi = a.dist(&b);
        let den = g[i - 1] + 1.0 + b1[i] * b1[i] * g[i];
        let q = c.segment_controls(i - 1);
        assert!(
            (a.dist(&q[1]) - phi * g[i - 1] / den).abs() < 1e-14,
            "q_(i−1,1)"
        );
        assert!(
            (q[2].dist(&b) - phi * b1[i] * b1[i] * g[i] / den).abs() < 1e-14,
            "q_(i−1,2)"
        );
    }
}

/// On one great circle the angle function is the Euclidean cubic Beta spline: at every joint
/// a′₊ = β₁a′₋ and a″₊ = β₁²a″₋ + β₂a′₋ (the classical Beta constraints). This holds only with
/// β₁² in eqs. (4)–(5) and (14) (`docs/derivations.md#beta-square`).
#[test]
fn great_circle_reduction_satisfies_beta_constraints() {
    let mut rng = Rng(7);
    for trial in 0..5 {
        let n = 5;
        let mut a = 0.0_f64;
        let mut d = Vec::new();
        for _ in 0..=n {
            d.push(p(a.cos(), a.sin(), 0.0));
            a += rng.range(0.2, 1.5);
        }
        let b1: Vec<f64> = (0..=n).map(|_| rng.range(0.3, 3.0)).collect();
        let b2: Vec<f64> = (0..=n).map(|_| rng.range(0.0, 5.0)).collect();
        for interpolate in [false, true] {
            let params = BetaParams {
                beta1: b1.clone().into(),
                beta2: b2.clone().into(),
                interpolate,
                ..BetaParams::default()
            };
            let c = BetaSpline::try_new(d.clone(), &params).unwrap();
            for i in 1..n {
                let angle_derivs = |side| {
                    let j = c.jet_at(i as f64, side);
                    let x = j.point.as_dvec3();
                    assert!(x.z.abs() < 1e-15, "stays on the circle");
                    let tangent = DVec3::new(-x.y, x.x, 0.0);
                    (j.velocity.dot(tangent), j.acceleration.dot(tangent))
                };
                let (d1m, d2m) = angle_derivs(Side::Left);
                let (d1p, d2p) = angle_derivs(Side::Right);
                let scale = d1m.abs() + d2m.abs() + 1.0;
                assert!(
                    (d1p - b1[i] * d1m).abs() < 1e-9 * scale,
                    "trial {trial}: a′ at {i}"
                );
                assert!(
                    (d2p - (b1[i] * b1[i] * d2m + b2[i] * d1m)).abs() < 1e-8 * scale,
                    "trial {trial}: a″ at {i}: {d2p} vs {}",
                    b1[i] * b1[i] * d2m + b2[i] * d1m
                );
            }
        }
    }
}

/// With β₁ = 1, β₂ = 0 and data on a great circle the solved angles satisfy the uniform cubic
/// B-spline system a_(i−1) + 4aᵢ + a_(i+1) = 6αᵢ.
#[test]
fn great_circle_bspline_interpolation() {
    let alpha: [f64; 7] = [0.0, 0.4, 1.1, 1.5, 2.3, 2.9, 3.6];
    let data: Vec<S2Point> = alpha.iter().map(|a| p(a.cos(), a.sin(), 0.0)).collect();
    for params in [BetaParams::default(), jacobi()] {
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        let a: Vec<f64> = {
            let mut prev = 0.0_f64;
            c.auxiliary()
                .iter()
                .map(|d| {
                    let x = d.as_dvec3();
                    let mut t = x.y.atan2(x.x);
                    while t < prev - std::f64::consts::PI {
                        t += std::f64::consts::TAU;
                    }
                    prev = t;
                    t
                })
                .collect()
        };
        for i in 1..alpha.len() - 1 {
            let lhs = a[i - 1] + 4.0 * a[i] + a[i + 1];
            assert!(
                (lhs - 6.0 * alpha[i]).abs() < 1e-11,
                "row {i}: {lhs} vs {}",
                6.0 * alpha[i]
            );
        }
    }
}

#[test]
fn random_data_on_s2_s3_and_s5() {
    let mut rng = Rng(11);
    for trial in 0..4 {
        let n = 6;
        let b1: Vec<f64> = (0..=n).map(|_| rng.range(0.5, 2.0)).collect();
        let b2: Vec<f64> = (0..=n).map(|_| rng.range(0.0, 3.0)).collect();
        let params = BetaParams {
            beta1: b1.into(),
            beta2: b2.into(),
            ..BetaParams::default()
        };
        // S²
        let data = s2(&walk(&mut rng, n, 3, 0.2, 0.9));
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        assert!(interpolation_error(&c, &data) < 1e-12, "S² trial {trial}");
        check_g1(&c);
        check_jets(&c);
        // S³ (unit quaternions, used as given)
        let data: Vec<UnitQuat> = walk(&mut rng, n, 4, 0.2, 0.9)
            .iter()
            .map(|v| UnitQuat::from_wxyz([v[0], v[1], v[2], v[3]]).unwrap())
            .collect();
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        assert!(interpolation_error(&c, &data) < 1e-12, "S³ trial {trial}");
        check_g1(&c);
        check_jets(&c);
        let _: DVec4 = c.jet(0.5).velocity;
        // S⁵
        let data: Vec<SmPoint> = walk(&mut rng, n, 6, 0.2, 0.9)
            .into_iter()
            .map(|v| SmPoint::try_new(v).unwrap())
            .collect();
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        assert!(interpolation_error(&c, &data) < 1e-12, "S⁵ trial {trial}");
        check_g1(&c);
        check_jets(&c);
    }
}

/// Data on a great 2-sphere inside S⁵ (the kernel works in the 3-dimensional span).
#[test]
fn low_rank_data_in_high_dimension() {
    let mut rng = Rng(5);
    let base = walk(&mut rng, 5, 3, 0.3, 0.8);
    let embed = |v: &Vec<f64>| SmPoint::try_new(vec![0.0, v[0], 0.0, v[1], v[2], 0.0]).unwrap();
    let data: Vec<SmPoint> = base.iter().map(embed).collect();
    let c = BetaSpline::try_new(data.clone(), &BetaParams::default()).unwrap();
    let reference = BetaSpline::try_new(s2(&base), &BetaParams::default()).unwrap();
    assert!(interpolation_error(&c, &data) < 1e-12, "interpolates");
    for t in [0.3, 1.7, 4.2] {
        let x = c.eval(t);
        let y = reference.eval(t).as_dvec3();
        let want = embed(&vec![y.x, y.y, y.z]);
        assert!(x.dist(&want) < 1e-12, "same curve as on S² at {t}");
    }
}

#[test]
fn rotation_equivariance() {
    let data = example1();
    let rot = UnitQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5), 0.83).unwrap();
    let rotated: Vec<S2Point> = data
        .iter()
        .map(|d| S2Point::try_new(rot.rotate(d.as_dvec3())).unwrap())
        .collect();
    let params = with_beta1(vec![1.2, 0.8, 1.3, 1.0]);
    let c = BetaSpline::try_new(data, &params).unwrap();
    let r = BetaSpline::try_new(rotated, &params).unwrap();
    for t in [0.0, 0.4, 1.0, 1.6, 2.9, 3.0] {
        let a = S2Point::try_new(rot.rotate(c.eval(t).as_dvec3())).unwrap();
        assert!(a.dist(&r.eval(t)) < 1e-12, "at {t}");
    }
}

/// Newton converges whenever the Jacobi iteration does, and in cases where it does not.
#[test]
fn newton_converges_where_jacobi_does() {
    let mut rng = Rng(2024);
    let (mut both, mut newton_only, mut jacobi_only, mut neither) = (0, 0, 0, 0);
    for trial in 0..100 {
        // Half with β₁ ∈ [0.3, 3], β₂ ∈ [0, 5], half with wider ones (where many problems have
        // no solution and Jacobi often diverges).
        let (b1, b2) = if trial < 50 {
            ((0.5, 2.0), 3.0)
        } else {
            ((0.2, 5.0), 3.0)
        };
        let n = 6;
        // Random walk with Gaussian steps of scale 0.8.
        let mut data = Vec::new();
        let mut x = DVec3::from_array(rng.unit(3).try_into().unwrap());
        data.push(S2Point::try_new(x).unwrap());
        for _ in 0..n {
            let v = DVec3::new(rng.normal(), rng.normal(), rng.normal()) * 0.8;
            let v = v - x * x.dot(v);
            x = (x * v.length().cos() + v.normalize_or_zero() * v.length().sin()).normalize();
            data.push(S2Point::try_new(x).unwrap());
        }
        let params = BetaParams {
            beta1: (0..=n)
                .map(|_| rng.range(b1.0, b1.1))
                .collect::<Vec<_>>()
                .into(),
            beta2: (0..=n)
                .map(|_| rng.range(0.0, b2))
                .collect::<Vec<_>>()
                .into(),
            ..BetaParams::default()
        };
        let newton = BetaSpline::try_new(data.clone(), &params);
        let jac = BetaSpline::try_new(
            data.clone(),
            &BetaParams {
                solver: BetaSolver::Jacobi,
                ..params
            },
        );
        if let Ok(c) = &newton {
            assert!(
                interpolation_error(c, &data) < 1e-12,
                "Newton result interpolates"
            );
        }
        match (newton.is_ok(), jac.is_ok()) {
            (true, true) => both += 1,
            (true, false) => newton_only += 1,
            (false, true) => jacobi_only += 1,
            (false, false) => neither += 1,
        }
    }
    assert_eq!(jacobi_only, 0, "Jacobi converged where Newton did not");
    assert!(
        both > 30,
        "both {both}, newton only {newton_only}, neither {neither}"
    );
    assert!(
        newton_only > 0,
        "Newton converges in more cases: {newton_only}"
    );
}

#[test]
fn newton_large_problem_converges_quickly() {
    let mut rng = Rng(99);
    let data = s2(&walk(&mut rng, 1000, 3, 0.1, 60f64.to_radians()));
    let c = BetaSpline::try_new(data.clone(), &BetaParams::default()).unwrap();
    let info = c.solve_info().unwrap();
    assert!(info.iterations <= 8, "{info:?}");
    assert!(info.residual < 1e-12, "{info:?}");
    assert!(interpolation_error(&c, &data) < 1e-12, "interpolates");
}

// ---------------------------------------------------------------------------------------------
// Edge cases and bad input

#[test]
fn two_points() {
    let data = vec![p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)];
    for interpolate in [true, false] {
        let params = BetaParams {
            interpolate,
            ..BetaParams::default()
        };
        let c = BetaSpline::try_new(data.clone(), &params).unwrap();
        assert_eq!(c.eval(0.0), data[0], "start");
        assert_eq!(c.eval(1.0), data[1], "end");
        assert_eq!(
            c.solve_info().map(|i| i.iterations),
            interpolate.then_some(0),
            "no iterations"
        );
        // With β = (1, 0) the arc is cut in thirds: the cubic is the constant-speed slerp.
        let x = c.eval(0.25).as_dvec3();
        assert!(
            (x.y.atan2(x.x) - std::f64::consts::FRAC_PI_8).abs() < 1e-14,
            "slerp"
        );
        check_jets(&c);
    }
}

#[test]
fn close_and_near_antipodal_points_stay_finite() {
    // Points 1e-9 apart.
    let e = 1e-9_f64;
    let data = vec![
        p(1.0, 0.0, 0.0),
        p(e.cos(), e.sin(), 0.0),
        p((2.0 * e).cos(), (2.0 * e).sin(), 1e-9),
        p(0.0, 1.0, 0.0),
    ];
    for params in [BetaParams::default(), jacobi()] {
        match BetaSpline::try_new(data.clone(), &params) {
            Ok(c) => {
                assert!(interpolation_error(&c, &data) < 1e-9, "interpolates");
                for k in 0..=30 {
                    let j = c.jet(k as f64 * 0.1);
                    assert!(j.point.as_dvec3().is_finite(), "finite point");
                    assert!(
                        j.velocity.is_finite() && j.acceleration.is_finite(),
                        "finite jet"
                    );
                }
            }
            Err(e) => assert!(matches!(e, SplineError::Solve(_)), "typed error: {e}"),
        }
    }
    // Consecutive data almost antipodal.
    let a = 1e-6_f64;
    let data = vec![
        p(1.0, 0.0, 0.0),
        p(-a.cos(), a.sin(), 0.0),
        p(0.0, 0.0, 1.0),
    ];
    for params in [BetaParams::default(), jacobi()] {
        match BetaSpline::try_new(data.clone(), &params) {
            Ok(c) => {
                assert!(interpolation_error(&c, &data) < 1e-9, "interpolates");
                for k in 0..=20 {
                    let j = c.jet(k as f64 * 0.1);
                    assert!(
                        j.point.as_dvec3().is_finite() && j.velocity.is_finite(),
                        "finite"
                    );
                }
            }
            Err(e) => assert!(matches!(e, SplineError::Solve(_)), "typed error: {e}"),
        }
    }
    // Coincident auxiliary vertices are allowed: a degenerate but finite curve.
    let d = vec![p(1.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)];
    let params = BetaParams {
        interpolate: false,
        ..BetaParams::default()
    };
    let c = BetaSpline::try_new(d, &params).unwrap();
    for k in 0..=20 {
        let j = c.jet(k as f64 * 0.1);
        assert!(
            j.point.as_dvec3().is_finite() && j.acceleration.is_finite(),
            "finite"
        );
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let data = example2();
    let err = |params: BetaParams| BetaSpline::try_new(data.clone(), &params).unwrap_err();
    let name_of = |e: SplineError| match e {
        SplineError::InvalidParameter { name, .. } => name,
        other => panic!("expected InvalidParameter, got {other:?}"),
    };
    assert!(
        matches!(
            BetaSpline::try_new(vec![p(1.0, 0.0, 0.0)], &BetaParams::default()),
            Err(SplineError::TooFewPoints { min: 2, got: 1 })
        ),
        "one point"
    );
    assert!(
        matches!(
            BetaSpline::<S2Point>::try_new(vec![], &BetaParams::default()),
            Err(SplineError::TooFewPoints { min: 2, got: 0 })
        ),
        "no points"
    );
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(
            name_of(err(with_beta1(vec![1.0, bad, 1.0, 1.0]))),
            "beta1",
            "β₁ = {bad}"
        );
        assert_eq!(
            name_of(err(BetaParams {
                beta1: bad.into(),
                ..BetaParams::default()
            })),
            "beta1",
            "β₁ = {bad}"
        );
    }
    for bad in [-1e-9, f64::NAN, f64::NEG_INFINITY] {
        assert_eq!(
            name_of(err(BetaParams {
                beta2: bad.into(),
                ..BetaParams::default()
            })),
            "beta2",
            "β₂ = {bad}"
        );
    }
    assert_eq!(
        name_of(err(with_beta1(vec![1.0, 1.0, 1.0]))),
        "beta1",
        "list too short"
    );
    assert_eq!(
        name_of(err(BetaParams {
            beta2: vec![0.0; 5].into(),
            ..BetaParams::default()
        })),
        "beta2",
        "list too long"
    );
    for bad in [0.0, -1.0, f64::NAN] {
        assert_eq!(
            name_of(err(BetaParams {
                tolerance: Some(bad),
                ..BetaParams::default()
            })),
            "tolerance",
            "tolerance"
        );
        assert_eq!(
            name_of(err(BetaParams {
                residual_tolerance: Some(bad),
                ..BetaParams::default()
            })),
            "residual_tolerance",
            "residual_tolerance"
        );
    }
    assert_eq!(
        name_of(err(BetaParams {
            max_iterations: Some(0),
            ..BetaParams::default()
        })),
        "max_iterations",
        "max_iterations"
    );
    // Messages name the parameter and the entry.
    let msg = err(with_beta1(vec![1.0, -2.0, 1.0, 1.0])).to_string();
    assert!(msg.starts_with("parameter beta1"), "{msg}");
    assert!(msg.contains("[1]"), "{msg}");
    // Coincident consecutive data points.
    let dup = vec![
        p(1.0, 0.0, 0.0),
        p(0.0, 1.0, 0.0),
        p(0.0, 1.0, 0.0),
        p(0.0, 0.0, 1.0),
    ];
    assert!(
        matches!(
            BetaSpline::try_new(dup, &BetaParams::default()),
            Err(SplineError::Coincident { index: 1 })
        ),
        "coincident"
    );
    // Antipodal consecutive points.
    let anti = vec![p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, -1.0, 0.0)];
    for interpolate in [true, false] {
        assert!(
            matches!(
                BetaSpline::try_new(
                    anti.clone(),
                    &BetaParams {
                        interpolate,
                        ..BetaParams::default()
                    }
                ),
                Err(SplineError::Antipodal { index: 1 })
            ),
            "antipodal"
        );
    }
    // Iteration limit.
    let limited = BetaParams {
        max_iterations: Some(1),
        ..BetaParams::default()
    };
    match BetaSpline::try_new(example1(), &limited) {
        Err(SplineError::Solve(SolveError::NoConvergence {
            iterations: 1,
            residual,
        })) => {
            assert!(
                residual.is_finite() && residual > 1e-12,
                "residual {residual}"
            );
        }
        other => panic!("expected NoConvergence, got {other:?}"),
    }
    let msg = BetaSpline::try_new(example1(), &limited)
        .unwrap_err()
        .to_string();
    assert!(msg.starts_with("the solver did not converge"), "{msg}");
}

#[test]
fn solver_names() {
    for s in [BetaSolver::Newton, BetaSolver::Jacobi] {
        assert_eq!(BetaSolver::from_name(s.name()), Some(s), "round trip");
    }
    assert_eq!(BetaSolver::from_name("gauss"), None, "unknown");
    assert_eq!(BetaSolver::default(), BetaSolver::Newton, "default");
}

/// On S¹ (the smallest sphere) the interpolating spline with β = (1, 0) is the uniform cubic
/// B-spline of the angles.
#[test]
fn circle_s1() {
    let alpha: [f64; 5] = [0.2, 0.9, 1.3, 2.2, 2.6];
    let data: Vec<SmPoint> = alpha
        .iter()
        .map(|a| SmPoint::try_new(vec![a.cos(), a.sin()]).unwrap())
        .collect();
    let c = BetaSpline::try_new(data.clone(), &BetaParams::default()).unwrap();
    assert!(interpolation_error(&c, &data) < 1e-12, "interpolates");
    let a: Vec<f64> = c
        .auxiliary()
        .iter()
        .map(|d| d.coords()[1].atan2(d.coords()[0]))
        .collect();
    for i in 1..alpha.len() - 1 {
        let lhs = a[i - 1] + 4.0 * a[i] + a[i + 1];
        assert!((lhs - 6.0 * alpha[i]).abs() < 1e-11, "row {i}");
    }
    check_g1(&c);
    check_jets(&c);
}

#[test]
fn extreme_parameters_never_give_nan() {
    let data = example1();
    for (b1, b2) in [
        (1e300, 0.0),
        (1e-300, 0.0),
        (1.0, f64::MAX),
        (1e-300, f64::MAX),
        (1e150, 1e300),
        (1e-8, 1e8),
    ] {
        for interpolate in [false, true] {
            for solver in [BetaSolver::Newton, BetaSolver::Jacobi] {
                let params = BetaParams {
                    beta1: b1.into(),
                    beta2: b2.into(),
                    interpolate,
                    solver,
                    max_iterations: Some(50),
                    ..BetaParams::default()
                };
                match BetaSpline::try_new(data.clone(), &params) {
                    Ok(c) => {
                        assert!(
                            c.controls().iter().all(|q| q.as_dvec3().is_finite()),
                            "finite"
                        );
                        for k in 0..=30 {
                            let j = c.jet(k as f64 * 0.1);
                            assert!(
                                j.point.as_dvec3().is_finite()
                                    && j.velocity.is_finite()
                                    && j.acceleration.is_finite(),
                                "finite jet for β = ({b1}, {b2})"
                            );
                        }
                        if interpolate {
                            assert!(interpolation_error(&c, &data) < 1e-9, "interpolates");
                        }
                    }
                    Err(
                        SplineError::InvalidParameter { name: "beta1", .. } | SplineError::Solve(_),
                    ) => {}
                    Err(e) => panic!("unexpected error {e:?}"),
                }
            }
        }
    }
}

#[test]
fn mixed_dimensions_are_rejected() {
    let data = vec![
        SmPoint::try_new(vec![1.0, 0.0, 0.0]).unwrap(),
        SmPoint::try_new(vec![0.0, 1.0, 0.0, 0.0]).unwrap(),
    ];
    assert!(
        matches!(
            BetaSpline::try_new(data, &BetaParams::default()),
            Err(SplineError::InvalidPoint { index: 1, .. })
        ),
        "different spheres"
    );
}

/// Random configurations with tiny, ordinary, large and nearly antipodal steps, random shape
/// parameters, both solvers and both modes: either a finite interpolating curve or a typed
/// error, never NaN or a panic.
#[test]
fn random_configurations_are_finite_or_typed_errors() {
    let mut rng = Rng(31337);
    for trial in 0..120 {
        let step = [1e-9, 1e-6, 0.3, 1.0, 2.0, 3.1][trial % 6];
        let n = 2 + trial % 5;
        let data = s2(&walk(&mut rng, n, 3, 0.5 * step, step));
        let params = BetaParams {
            beta1: (0..=n)
                .map(|_| 10f64.powf(rng.range(-2.0, 2.0)))
                .collect::<Vec<_>>()
                .into(),
            beta2: (0..=n)
                .map(|_| {
                    if rng.uniform() < 0.5 {
                        0.0
                    } else {
                        10f64.powf(rng.range(-3.0, 3.0))
                    }
                })
                .collect::<Vec<_>>()
                .into(),
            interpolate: trial % 3 != 0,
            solver: if (trial / 6) % 2 == 0 {
                BetaSolver::Newton
            } else {
                BetaSolver::Jacobi
            },
            max_iterations: Some(300),
            ..BetaParams::default()
        };
        let result = BetaSpline::try_new(data.clone(), &params);
        if params.interpolate && params.solver == BetaSolver::Jacobi && result.is_ok() {
            let newton = BetaParams {
                solver: BetaSolver::Newton,
                ..params.clone()
            };
            assert!(
                BetaSpline::try_new(data.clone(), &newton).is_ok(),
                "trial {trial}: Jacobi converged, Newton did not"
            );
        }
        match result {
            Ok(c) => {
                for k in 0..=40 {
                    let t = n as f64 * k as f64 / 40.0;
                    let j = c.jet(t);
                    let x = j.point.as_dvec3();
                    assert!(
                        x.is_finite() && j.velocity.is_finite() && j.acceleration.is_finite(),
                        "trial {trial}: finite jet at {t}"
                    );
                    assert!(
                        (x.length() - 1.0).abs() < 1e-14,
                        "trial {trial}: unit at {t}"
                    );
                }
                if params.interpolate {
                    let tol = if params.solver == BetaSolver::Newton {
                        1e-12
                    } else {
                        1e-9
                    };
                    assert!(
                        interpolation_error(&c, &data) <= tol,
                        "trial {trial}: interpolates"
                    );
                }
            }
            Err(SplineError::Solve(SolveError::NoConvergence { residual, .. })) => {
                assert!(!residual.is_nan(), "trial {trial}: residual is a number");
            }
            Err(SplineError::Coincident { .. } | SplineError::Antipodal { .. }) => {}
            Err(e) => panic!("trial {trial}: unexpected error {e:?}"),
        }
    }
}
