// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The Gamma quaternion spline (Chen et al. 2022, §3–4; corrections in `docs/derivations.md`).

#![allow(clippy::unwrap_used, reason = "tests: a panic is the failure report")]

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{
    BezierKim, Curve, GammaSpline, Gammas, LastEdge, Manifold, Side, SplineError, UnitQuat,
};

use crate::support::Rng;

fn q(wxyz: [f64; 4]) -> UnitQuat {
    UnitQuat::from_wxyz(wxyz).unwrap()
}

fn v4(q: UnitQuat) -> DVec4 {
    q.to_vector()
}

/// Max-norm distance of a quaternion from printed scalar-first values.
fn off(a: UnitQuat, wxyz: [f64; 4]) -> f64 {
    a.to_wxyz()
        .iter()
        .zip(wxyz)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn example2() -> Vec<UnitQuat> {
    vec![
        q([-0.9632, -0.1086, 0.2011, 0.1414]),
        q([0.9023, 0.1049, 0.3609, -0.2112]),
        q([-0.7944, -0.6025, -0.0430, -0.0640]),
        q([0.9937, -0.0996, 0.0468, -0.0206]),
        q([0.2584, -0.4570, -0.5905, -0.6130]),
    ]
}

fn example1() -> Vec<UnitQuat> {
    vec![
        q([0.3321, -0.4426, 0.3958, 0.7329]),
        q([0.5000, 0.5001, 0.6725, 0.2185]),
        q([-0.5325, -0.6129, -0.0252, -0.5833]),
        q([-0.6030, 0.7937, -0.0134, 0.0785]),
        q([0.3321, -0.4426, 0.3958, 0.7329]),
        q([-0.7944, -0.6025, -0.0430, -0.0640]),
    ]
}

fn gamma(d: Vec<UnitQuat>, knots: Option<Vec<f64>>, g: Gammas) -> GammaSpline {
    GammaSpline::try_new(d, knots, g, LastEdge::Formula).unwrap()
}

#[test]
fn example2_formula_reading() {
    let s = gamma(example2(), None, Gammas::default());
    let b = s.controls();
    assert_eq!(b.len(), 7);
    // Recomputed from the paper's formulas (`docs/derivations.md#gamma-example-2`).
    let expected = [
        [-0.9632, -0.1086, 0.2011, 0.1414],
        [0.9023, 0.1049, 0.3609, -0.2112],
        [0.1634, -0.7536, 0.4814, -0.4168],
        [0.2282, -0.8971, 0.2554, -0.2792],
        [0.2713, -0.9556, 0.0052, -0.1151],
        [0.9937, -0.0996, 0.0468, -0.0206],
        [0.2584, -0.4570, -0.5905, -0.6130],
    ];
    for (k, e) in expected.iter().enumerate() {
        assert!(off(b[k], *e) < 1e-4, "b{k} = {:?}", b[k].to_wxyz());
    }
    // Reference curve values.
    assert!(
        off(s.eval(0.5), [0.4973, -0.4759, 0.6906, -0.2221]) < 1e-4,
        "S(0.5)"
    );
    assert_eq!(s.eval(1.0), b[3]);
    assert!(
        off(s.eval(1.5), [0.7021, -0.6921, -0.0890, -0.1422]) < 1e-4,
        "S(1.5)"
    );
    // C² is not reproduced: (5) has residual 0.329 and S″ jumps by 1.973 = 6 × 0.329.
    let r = s.joint_report();
    assert_eq!(r.len(), 1);
    let j = &r[0];
    assert_eq!((j.index, j.knot, j.uniform), (1, 1.0, true));
    assert!(j.first_derivative_jump < 1e-12, "{j:?}");
    assert!(
        (j.paper_lhs - DVec3::new(0.1083, -0.4707, -0.3860))
            .abs()
            .max_element()
            < 1e-4,
        "{j:?}"
    );
    assert!(
        (j.paper_rhs - DVec3::new(0.0297, -0.2221, -0.1854))
            .abs()
            .max_element()
            < 1e-4,
        "{j:?}"
    );
    assert!((j.paper_residual - 0.329).abs() < 1e-3, "{j:?}");
    assert!((j.second_derivative_jump - 1.973).abs() < 1e-3, "{j:?}");
    assert!(
        (6.0 * j.general_residual.length() - j.second_derivative_jump).abs() < 1e-12,
        "{j:?}"
    );
}

#[test]
fn example2_paper_reading_reproduces_the_table() {
    let s =
        GammaSpline::try_new(example2(), None, Gammas::All(1.0), LastEdge::PaperExample).unwrap();
    assert_eq!(s.last_edge(), LastEdge::PaperExample);
    let printed = [
        [-0.9632, -0.1086, 0.2011, 0.1414],
        [0.9023, 0.1049, 0.3609, -0.2112],
        [0.1634, -0.7536, 0.4814, -0.4168],
        [0.5659, -0.6599, 0.0855, -0.4867],
        [0.7803, -0.3469, -0.3388, -0.3949],
        [0.9937, -0.0996, 0.0468, -0.0206],
        [0.2584, -0.4570, -0.5905, -0.6130],
    ];
    for (k, e) in printed.iter().enumerate() {
        assert!(
            off(s.controls()[k], *e) < 1e-4,
            "b{k} = {:?}",
            s.controls()[k].to_wxyz()
        );
    }
    // Unrounded values of the shifted reading (`docs/derivations.md#gamma-example-2`).
    assert!(
        off(s.controls()[4], [0.78035, -0.34688, -0.33884, -0.39486]) < 1e-5,
        "b4"
    );
    assert!(
        off(s.controls()[3], [0.56596, -0.65991, 0.08551, -0.48672]) < 1e-5,
        "b3"
    );
    // Still C¹, and not C²: jump 11.42 and (5) residual 0.994.
    let j = &s.joint_report()[0];
    assert!(j.first_derivative_jump < 1e-12, "{j:?}");
    assert!((j.second_derivative_jump - 11.42).abs() < 1e-2, "{j:?}");
    assert!(
        (6.0 * j.general_residual.length() - j.second_derivative_jump).abs() < 1e-12,
        "{j:?}"
    );
    assert!((j.paper_residual - 0.994).abs() < 1e-3, "{j:?}");
}

#[test]
fn example1_reference_values() {
    let s = gamma(example1(), None, Gammas::Each(vec![1.0, 1.0]));
    let expected = [
        [0.3321, -0.4426, 0.3958, 0.7329],
        [0.5000, 0.5001, 0.6725, 0.2185],
        [-0.0432, -0.1500, 0.8605, -0.4850],
        [-0.5599, -0.1735, 0.5190, -0.6222],
        [-0.8509, -0.1271, -0.0316, -0.5087],
        [-0.8775, 0.4023, -0.0272, -0.2596],
        [-0.7545, 0.4950, 0.2333, 0.3622],
        [-0.2707, 0.3509, 0.3822, 0.8109],
        [0.3321, -0.4426, 0.3958, 0.7329],
        [-0.7944, -0.6025, -0.0430, -0.0640],
    ];
    for (k, e) in expected.iter().enumerate() {
        assert!(
            off(s.controls()[k], *e) < 1e-4,
            "b{k} = {:?}",
            s.controls()[k].to_wxyz()
        );
    }
    assert!(
        off(s.eval(0.5), [0.2977, 0.0830, 0.9408, -0.1388]) < 1e-4,
        "S(0.5)"
    );
    assert!(
        off(s.eval(1.5), [-0.9290, 0.1454, 0.0612, -0.3347]) < 1e-4,
        "S(1.5)"
    );
    assert!(
        off(s.eval(2.5), [-0.1684, -0.1248, 0.3206, 0.9237]) < 1e-4,
        "S(2.5)"
    );
    let r = s.joint_report();
    assert_eq!(r.len(), 2);
    for (j, (jump, res)) in r.iter().zip([(1.209, 0.2015), (0.691, 0.1152)]) {
        assert!(j.first_derivative_jump < 1e-12, "{j:?}");
        assert!((j.second_derivative_jump - jump).abs() < 1e-3, "{j:?}");
        assert!((j.paper_residual - res).abs() < 1e-4, "{j:?}");
        // Uniform unit spacing: the general residual is (5)'s.
        assert!(
            (j.general_residual.length() - j.paper_residual).abs() < 1e-12,
            "{j:?}"
        );
    }
}

/// Random vertices, knots and shape parameters.
fn random_spline(rng: &mut Rng, l: usize) -> GammaSpline {
    let d = rng.chain(l + 3, 2.0);
    let knots = rng.knots(l);
    let g = (1..l).map(|_| rng.range(0.3, 3.0)).collect();
    gamma(d, Some(knots), Gammas::Each(g))
}

#[test]
fn c1_at_every_joint_for_any_gamma_and_spacing() {
    let mut rng = Rng(0xfeed);
    for l in 2..=6 {
        for _ in 0..4 {
            let s = random_spline(&mut rng, l);
            let b = s.controls();
            let u = s.knots().as_slice().to_vec();
            for i in 1..l {
                let (lj, rj) = (s.jet_at(u[i], Side::Left), s.jet_at(u[i], Side::Right));
                assert_eq!(lj.point, b[3 * i], "C0 at u{i}");
                assert_eq!(rj.point, b[3 * i], "C0 at u{i}");
                let jump = (lj.velocity - rj.velocity).length();
                assert!(
                    jump < 1e-9 * rj.velocity.length().max(1.0),
                    "C1 at u{i}: {jump}"
                );
                // Theorem 1: 3/(Δᵢ₋₁ + Δᵢ)·b₃ᵢ·log(b₃ᵢ₋₁⁻¹ b₃ᵢ₊₁).
                let w = (b[3 * i - 1].conjugate() * b[3 * i + 1]).log_pure();
                let expected = DVec4::from(b[3 * i].as_dquat() * DQuat::from_vec4(w.extend(0.0)))
                    * (3.0 / (u[i + 1] - u[i - 1]));
                assert!(
                    (rj.velocity - expected).length() < 1e-9,
                    "Theorem 1 at u{i}"
                );
                // The second-derivative jump is 6·b₃ᵢ·(general residual).
                let rep = &s.joint_report()[i - 1];
                let jump2 = rj.acceleration - lj.acceleration;
                let predicted = DVec4::from(
                    b[3 * i].as_dquat() * DQuat::from_vec4(rep.general_residual.extend(0.0)),
                ) * 6.0;
                assert!(
                    (jump2 - predicted).length() < 1e-9 * jump2.length().max(1.0),
                    "S'' jump at u{i}: {jump2:?} vs {predicted:?}"
                );
            }
        }
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let mut rng = Rng(31337);
    let s = random_spline(&mut rng, 5);
    let h = 1e-5;
    let u = s.knots().as_slice().to_vec();
    for w in u.windows(2) {
        for k in 1..8 {
            let t = w[0] + (w[1] - w[0]) * f64::from(k) / 8.0;
            let j = s.jet(t);
            let fd1 = (v4(s.eval(t + h)) - v4(s.eval(t - h))) / (2.0 * h);
            let fd2 = (s.jet(t + h).velocity - s.jet(t - h).velocity) / (2.0 * h);
            let e1 = (fd1 - j.velocity).length() / j.velocity.length().max(1.0);
            let e2 = (fd2 - j.acceleration).length() / j.acceleration.length().max(1.0);
            assert!(e1 < 1e-6, "d1 at {t}: {e1}");
            assert!(e2 < 1e-6, "d2 at {t}: {e2}");
            assert!((v4(j.point).length() - 1.0).abs() < 1e-15, "unit at {t}");
        }
    }
}

#[test]
fn endpoints_and_segments_are_kim_cubics() {
    let mut rng = Rng(4242);
    let s = random_spline(&mut rng, 4);
    let d = s.points().to_vec();
    let u = s.knots().as_slice().to_vec();
    assert_eq!(s.eval(u[0]), d[0]);
    assert_eq!(s.eval(u[4]), d[6]);
    assert_eq!(s.controls()[1], d[1]);
    assert_eq!(s.controls()[11], d[5]);
    assert_eq!(s.segment_count(), 4);
    assert_eq!(s.gamma().len(), 3);
    for i in 0..4 {
        let seg = BezierKim::try_new(s.controls()[3 * i..=3 * i + 3].to_vec()).unwrap();
        let h = u[i + 1] - u[i];
        for k in 0..=10 {
            let tau = f64::from(k) / 10.0;
            let side = if k == 10 { Side::Left } else { Side::Right };
            let (a, b) = (s.jet_at(u[i] + h * tau, side), seg.jet(tau));
            assert!(a.point.dist(&b.point) < 1e-14, "segment {i} at {tau}");
            assert!(
                (a.velocity * h - b.velocity).length() < 1e-12,
                "velocity {i} {tau}"
            );
            assert!(
                (a.acceleration * (h * h) - b.acceleration).length() < 1e-11,
                "acceleration {i} {tau}"
            );
        }
    }
    // Clamping outside the domain.
    assert_eq!(s.eval(u[0] - 5.0), d[0]);
    assert_eq!(s.eval(u[4] + 5.0), d[6]);
}

/// The Euclidean (scalar) Gamma spline control points (Chen et al. 2022, §2.3; Boehm 1987).
fn scalar_gamma(v: &[f64], knots: &[f64], g: &[f64]) -> Vec<f64> {
    let l = knots.len() - 1;
    let dl = |i: usize| knots[i + 1] - knots[i];
    let left = |i: usize| if i >= 2 { g[i - 2] * dl(i - 2) } else { 0.0 };
    let right = |i: usize| if i < l { g[i - 1] * dl(i) } else { 0.0 };
    let mut p = vec![0.0; 3 * l + 1];
    p[0] = v[0];
    p[3 * l] = v[l + 2];
    for i in 1..=l {
        let w = left(i) + dl(i - 1) + right(i);
        p[3 * i - 2] = ((dl(i - 1) + right(i)) * v[i] + left(i) * v[i + 1]) / w;
        p[3 * i - 1] = (right(i) * v[i] + (left(i) + dl(i - 1)) * v[i + 1]) / w;
    }
    for i in 1..l {
        p[3 * i] = (dl(i) * p[3 * i - 1] + dl(i - 1) * p[3 * i + 1]) / (dl(i - 1) + dl(i));
    }
    p
}

#[test]
fn common_axis_reduces_to_the_euclidean_gamma_spline() {
    let q0 = q([0.2, -0.4, 0.8, 0.1]);
    let axis = DVec3::new(0.6, -0.2, 0.5).normalize();
    let alpha = [0.1, 0.9, 0.4, 1.6, 2.3, 1.9, 2.8];
    let d: Vec<UnitQuat> = alpha
        .iter()
        .map(|&a| q0 * UnitQuat::exp_pure(axis * a))
        .collect();
    let knots = vec![0.0, 0.7, 2.0, 2.4, 3.9];
    for g in [vec![1.0, 1.0, 1.0], vec![0.5, 2.0, 1.3]] {
        let s = gamma(d.clone(), Some(knots.clone()), Gammas::Each(g.clone()));
        let p = scalar_gamma(&alpha, &knots, &g);
        for (k, (&b, &pk)) in s.controls().iter().zip(&p).enumerate() {
            assert!(
                b.dist(&(q0 * UnitQuat::exp_pure(axis * pk))) < 1e-14,
                "b{k}"
            );
        }
        let c2 = s
            .joint_report()
            .iter()
            .all(|j| j.second_derivative_jump < 1e-9);
        // γ = 1 gives C² on a great circle; other γ do not.
        assert_eq!(c2, g.iter().all(|&x| x == 1.0), "{:?}", s.joint_report());
    }
}

#[test]
fn non_uniform_knots_need_the_general_condition() {
    // With unequal spacings (5) is not the C² condition: its residual differs from the jump/6.
    let mut rng = Rng(555);
    let d = rng.chain(5, 1.5);
    let s = gamma(d, Some(vec![0.0, 1.0, 3.0]), Gammas::All(1.0));
    let j = &s.joint_report()[0];
    assert!(!j.uniform, "{j:?}");
    assert!(
        (6.0 * j.general_residual.length() - j.second_derivative_jump).abs() < 1e-9,
        "{j:?}"
    );
}

#[test]
fn left_multiplication_is_equivariant() {
    let mut rng = Rng(9);
    let s = random_spline(&mut rng, 3);
    let r = rng.quat();
    let rd: Vec<UnitQuat> = s.points().iter().map(|&x| r * x).collect();
    let rs = gamma(
        rd,
        Some(s.knots().as_slice().to_vec()),
        Gammas::Each(s.gamma().to_vec()),
    );
    for (a, b) in rs.controls().iter().zip(s.controls()) {
        assert!(a.dist(&(r * *b)) < 1e-14, "controls");
    }
    let [t0, t1] = s.domain();
    for k in 0..=30 {
        let t = t0 + (t1 - t0) * f64::from(k) / 30.0;
        assert!(rs.eval(t).dist(&(r * s.eval(t))) < 1e-14, "t={t}");
    }
}

#[test]
fn one_segment_is_kims_cubic_on_the_vertices() {
    let mut rng = Rng(12);
    let d = rng.chain(4, 1.5);
    let s = gamma(d.clone(), None, Gammas::Each(vec![]));
    assert_eq!(s.controls(), &d[..]);
    let k = BezierKim::try_new(d).unwrap();
    for i in 0..=10 {
        let t = f64::from(i) / 10.0;
        assert!(s.eval(t).dist(&k.eval(t)) < 1e-15, "t={t}");
    }
    assert!(s.joint_report().is_empty(), "no interior joints");
}

#[test]
fn near_identical_and_identical_vertices_are_finite() {
    let p = q([0.3, 0.5, -0.2, 0.7]);
    let tiny = |e: f64| p * UnitQuat::exp_pure(DVec3::new(e, -e, 0.5 * e));
    for d in [
        vec![p; 6],
        vec![p, tiny(1e-9), tiny(2e-9), p, tiny(1e-12), tiny(3e-9)],
    ] {
        let s = gamma(
            d,
            Some(vec![0.0, 0.5, 2.0, 2.1]),
            Gammas::Each(vec![0.2, 5.0]),
        );
        for k in 0..=42 {
            let t = 2.1 * f64::from(k) / 42.0;
            let j = s.jet(t);
            assert!(
                j.velocity.is_finite() && j.acceleration.is_finite(),
                "t={t}"
            );
            assert!((v4(j.point).length() - 1.0).abs() < 1e-15, "t={t}");
            assert!(j.point.dist(&p) < 1e-8, "t={t}");
        }
        for j in s.joint_report() {
            assert!(
                j.general_residual.is_finite() && j.paper_residual.is_finite(),
                "{j:?}"
            );
        }
    }
}

#[test]
fn near_antipodal_vertices_are_finite() {
    let p = q([0.3, 0.5, -0.2, 0.7]);
    let near = -p * UnitQuat::exp_pure(DVec3::new(1e-6, 0.0, 0.0));
    let d = vec![p, near, p, near, p];
    let s = gamma(d, None, Gammas::All(1.0));
    for k in 0..=20 {
        let j = s.jet(2.0 * f64::from(k) / 20.0);
        assert!(
            j.velocity.is_finite() && j.acceleration.is_finite(),
            "k={k}"
        );
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let d = example1(); // l = 3
    let err = |d: Vec<UnitQuat>, k: Option<Vec<f64>>, g: Gammas| {
        GammaSpline::try_new(d, k, g, LastEdge::Formula).unwrap_err()
    };
    assert_eq!(
        err(d[..3].to_vec(), None, Gammas::default()),
        SplineError::TooFewPoints { min: 4, got: 3 }
    );
    for g in [
        Gammas::All(0.0),
        Gammas::All(-1.0),
        Gammas::All(f64::NAN),
        Gammas::All(f64::INFINITY),
        Gammas::Each(vec![1.0, 0.0]),
        Gammas::Each(vec![f64::NAN, 1.0]),
        Gammas::Each(vec![1.0]),
        Gammas::Each(vec![1.0, 1.0, 1.0]),
    ] {
        let e = err(d.clone(), None, g.clone());
        assert!(
            matches!(e, SplineError::InvalidParameter { name: "gamma", .. }),
            "{g:?}: {e}"
        );
        assert!(e.to_string().starts_with("parameter gamma: "), "{e}");
    }
    // A scalar γ is validated even when there are no interior knots.
    assert!(matches!(
        err(d[..4].to_vec(), None, Gammas::All(-2.0)),
        SplineError::InvalidParameter { name: "gamma", .. }
    ));
    assert_eq!(
        err(d.clone(), Some(vec![0.0, 1.0, 1.0, 2.0]), Gammas::default()),
        SplineError::KnotsNotIncreasing { index: 2 }
    );
    assert_eq!(
        err(d.clone(), Some(vec![0.0, 1.0, 2.0]), Gammas::default()),
        SplineError::KnotCount {
            expected: 4,
            got: 3
        }
    );
    assert_eq!(
        err(
            d.clone(),
            Some(vec![0.0, 1.0, f64::NAN, 3.0]),
            Gammas::default()
        ),
        SplineError::InvalidKnot { index: 2 }
    );
    let mut anti = d.clone();
    anti[3] = -anti[2];
    assert_eq!(
        err(anti, None, Gammas::default()),
        SplineError::Antipodal { index: 2 }
    );
    let mut anti = d;
    anti[1] = -anti[0];
    assert_eq!(
        err(anti, None, Gammas::default()),
        SplineError::Antipodal { index: 0 }
    );
    assert!(matches!(
        LastEdge::from_name("paper"),
        Err(SplineError::InvalidParameter {
            name: "last_edge",
            ..
        })
    ));
    for e in [LastEdge::Formula, LastEdge::PaperExample] {
        assert_eq!(LastEdge::from_name(e.name()), Ok(e));
    }
}

#[test]
fn c1_with_extreme_gamma_and_spacing() {
    let mut rng = Rng(0xabc);
    let d = rng.chain(8, 2.5);
    let knots = vec![0.0, 1e-3, 1.0, 1e3, 1e3 + 1e-2, 2e3];
    for g in [
        vec![1e-3, 1e3, 1.0, 2.0],
        vec![1e3, 1e-3, 1e-3, 1e3],
        vec![1e-6, 1e6, 1e-6, 1e6],
    ] {
        let s = gamma(d.clone(), Some(knots.clone()), Gammas::Each(g.clone()));
        for j in s.joint_report() {
            let v = s.jet(j.knot).velocity.length().max(1.0);
            assert!(j.first_derivative_jump < 1e-9 * v, "{g:?}: {j:?}");
            assert!(j.second_derivative_jump.is_finite(), "{g:?}: {j:?}");
        }
        for k in 0..=100 {
            let j = s.jet(2e3 * f64::from(k) / 100.0);
            assert!((v4(j.point).length() - 1.0).abs() < 1e-15, "{g:?}");
            assert!(
                j.velocity.is_finite() && j.acceleration.is_finite(),
                "{g:?}"
            );
        }
    }
}
