// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Claims of the sources that no other test checks, one named test each: nlerp's angular-speed
//! law and the tutorial's five-point example, slerp's "40 % of the way at t = 0.4", the
//! de Casteljau weights at t = 0.4 (tutorial 2022), and Theorems 6–7 of Pobegailo (2019), §7.7
//! (the smoothing polynomials minimise `J_n(f) = ∫₀¹ (f^{(n+1)})² du`).

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::FRAC_PI_2;

use spherekit::glam::DVec3;
use spherekit::{
    Curve, Manifold, NlerpSpline, S2Point, SmoothingPolynomials, UnitQuat, de_casteljau,
};

use crate::support::Rng;

fn on_equator(angle: f64) -> S2Point {
    S2Point::try_new(DVec3::new(angle.cos(), angle.sin(), 0.0)).unwrap()
}

/// Nlerp's angle from p is α(s) = atan2(s sin θ, (1 − s) + s cos θ) and its angular speed is
/// α′(s) = sin θ / ((1 − s)² + 2s(1 − s) cos θ + s²): sin θ at the ends, 2 tan(θ/2) in the middle
/// (the tutorial: "first increases, then decreases after s = 0.5").
#[test]
fn nlerp_angular_speed_law() {
    for theta in [0.1, 0.8, FRAC_PI_2, 2.5] {
        let c = NlerpSpline::try_new(vec![S2Point::X, on_equator(theta)], None).unwrap();
        let (sin, cos) = theta.sin_cos();
        for i in 0..=20 {
            let s = f64::from(i) / 20.0;
            let law = sin / ((1.0 - s).powi(2) + 2.0 * s * (1.0 - s) * cos + s * s);
            let speed = c.jet(s).velocity.length();
            assert!(
                (speed - law).abs() < 1e-13 * law,
                "θ = {theta}, s = {s}: {speed} vs {law}"
            );
            let angle = (s * sin).atan2((1.0 - s) + s * cos);
            assert!((c.eval(s).dist(&S2Point::X) - angle).abs() < 1e-15);
        }
        let mid = c.jet(0.5).velocity.length();
        assert!(
            (mid - 2.0 * (theta / 2.0).tan()).abs() < 1e-13,
            "2 tan(θ/2)"
        );
        assert!(mid > c.jet(0.0).velocity.length(), "faster in the middle");
    }
}

/// The tutorial's example: five parameters 0, ¼, ½, ¾, 1 cut the chord into equal parts but the
/// arc into unequal ones, the outer arcs shorter; at θ = 90° the arcs are 18.43°, 26.57°,
/// 26.57°, 18.43°.
#[test]
fn nlerp_five_point_example() {
    let c = NlerpSpline::try_new(vec![S2Point::X, S2Point::Y], None).unwrap();
    let at: Vec<f64> = (0..5)
        .map(|i| c.eval(f64::from(i) / 4.0).dist(&S2Point::X).to_degrees())
        .collect();
    let arcs: Vec<f64> = at.windows(2).map(|w| w[1] - w[0]).collect();
    for (arc, want) in arcs.iter().zip([18.43, 26.57, 26.57, 18.43]) {
        assert!((arc - want).abs() < 5e-3, "arcs {arcs:?}");
    }
    // Exactly: atan(1/3) and 45° − atan(1/3).
    assert!((arcs[0] - (1.0f64 / 3.0).atan().to_degrees()).abs() < 1e-12);
    assert!(
        arcs[0] < arcs[1],
        "the first arc is shorter than the second"
    );
}

/// The tutorial: at t = 0.4 the slerp of two orientations has turned 40 % of the way — the
/// rotation angle from p to slerp(p, q; 0.4) is 0.4 times that from p to q (for p·q ≥ 0).
#[test]
fn slerp_turns_forty_percent_at_point_four() {
    let mut rng = Rng::new(29);
    for _ in 0..50 {
        let p = rng.quat();
        let mut q = rng.quat();
        if p.to_vector().dot(q.to_vector()) < 0.0 {
            q = -q;
        }
        let r = p.slerp(&q, 0.4);
        let whole = (q * p.inverse()).rotation_angle();
        let part = (r * p.inverse()).rotation_angle();
        assert!((part - 0.4 * whole).abs() < 1e-13, "{part} vs 0.4·{whole}");
    }
    let q = UnitQuat::from_axis_angle(DVec3::Z, 2.0).unwrap();
    let r = UnitQuat::IDENTITY.slerp(&q, 0.4);
    assert!(r.dist(&UnitQuat::from_axis_angle(DVec3::Z, 0.8).unwrap()) < 1e-15);
}

/// The tutorial pictures de Casteljau's construction at t = 0.4; its cubic weights are the
/// Bernstein values 0.216, 0.432, 0.288, 0.064. On one great circle the spherical construction
/// reduces to the Euclidean one of the angles, so each weight is read off the library's
/// de Casteljau by moving one control point.
#[test]
fn de_casteljau_weights_at_point_four() {
    let base = [0.0, 0.0, 0.0, 0.0];
    for (k, want) in [0.216, 0.432, 0.288, 0.064].into_iter().enumerate() {
        let mut angles = base;
        angles[k] = 0.5;
        let ctrl: Vec<S2Point> = angles.iter().map(|&a| on_equator(a)).collect();
        let p = de_casteljau(&ctrl, 0.4).as_dvec3();
        let weight = p.y.atan2(p.x) / 0.5;
        assert!((weight - want).abs() < 1e-14, "weight {k}: {weight}");
    }
}

/// Gauss–Legendre nodes and weights on [0, 1] (8 points: exact for degree ≤ 15).
fn gauss(f: impl Fn(f64) -> f64) -> f64 {
    const X: [f64; 4] = [
        0.183_434_642_495_649_8,
        0.525_532_409_916_329,
        0.796_666_477_413_626_7,
        0.960_289_856_497_536_3,
    ];
    const W: [f64; 4] = [
        0.362_683_783_378_362,
        0.313_706_645_877_887_3,
        0.222_381_034_453_374_5,
        0.101_228_536_290_376_3,
    ];
    X.iter()
        .zip(W)
        .map(|(&x, w)| 0.5 * w * (f(0.5 * (1.0 + x)) + f(0.5 * (1.0 - x))))
        .sum()
}

/// `d^k/du^k` of the polynomial with monomial coefficients `c` (from u⁰ up).
fn poly_derivative(c: &[f64], k: usize, u: f64) -> f64 {
    let mut sum = 0.0;
    for (j, &cj) in c.iter().enumerate().skip(k) {
        let falling: f64 = (0..k).map(|i| (j - i) as f64).product();
        sum += cj * falling * (0..j - k).map(|_| u).product::<f64>();
    }
    sum
}

/// Monomial coefficients of u^{n+1}(1 − u)^{n+1}·u^e, a perturbation that keeps every boundary
/// condition of Theorems 6 and 7.
fn bump(n: usize, e: usize) -> Vec<f64> {
    let mut c = vec![0.0; 2 * n + 3 + e];
    let mut binom = 1.0;
    for i in 0..=n + 1 {
        c[n + 1 + e + i] = if i % 2 == 0 { binom } else { -binom };
        binom = binom * (n + 1 - i) as f64 / (i + 1) as f64;
    }
    c
}

/// Theorems 6 and 7 (§7.7): w₁,ₙ and w₂,ₙ minimise `J_n(f) = ∫₀¹ (f^{(n+1)})² du` under their
/// boundary conditions. The minima are J = 4, 192, 25 920, 6 451 200 for n = 1…4 (the same for
/// both), the first variation vanishes along every admissible perturbation
/// h = u^{n+1}(1 − u)^{n+1}q(u) (q = 1, u, u²), and J grows in every such direction.
#[test]
fn smoothing_polynomials_minimise_the_functional() {
    for (n, want) in [(1, 4.0), (2, 192.0), (3, 25_920.0), (4, 6_451_200.0)] {
        let w = SmoothingPolynomials::try_new(n).unwrap();
        let w1 = |u: f64| w.w1_derivative(u, n + 1);
        let w2 = |u: f64| w.w2_derivative(u, n + 1);
        let (j1, j2) = (gauss(|u| w1(u).powi(2)), gauss(|u| w2(u).powi(2)));
        assert!((j1 - want).abs() < 1e-9 * want, "J(w₁,{n}) = {j1}");
        assert!((j2 - want).abs() < 1e-9 * want, "J(w₂,{n}) = {j2}");
        for e in 0..=2 {
            let h = bump(n, e);
            let hk = |u: f64| poly_derivative(&h, n + 1, u);
            let scale = gauss(|u| hk(u).powi(2)).sqrt() * want.sqrt();
            for wk in [&w1 as &dyn Fn(f64) -> f64, &w2] {
                let first = gauss(|u| wk(u) * hk(u));
                assert!(
                    first.abs() < 1e-10 * scale,
                    "stationary (n = {n}, q = u^{e}): {first}"
                );
                for eps in [-0.1, 0.1] {
                    let j = gauss(|u| (wk(u) + eps * hk(u)).powi(2));
                    assert!(
                        j > want,
                        "J grows away from the minimiser (n = {n}, q = u^{e})"
                    );
                }
            }
        }
    }
}
