// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's orientation circles, arc-blend splines and corner smoothing on S³
//! (Pobegailo 2019, chapter 9; corrections in `docs/derivations.md`).

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::PI;

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{
    ArcBlend, CircleArc, CornerBlend, CornerBlendRotations, Curve, Manifold, Side,
    SmoothingPolynomials, SplineError, UnitQuat, angular_velocity_acceleration,
};

use crate::support::{Rng, check_continuity, check_derivatives};

fn q(w: f64, x: f64, y: f64, z: f64) -> UnitQuat {
    UnitQuat::from_wxyz([w, x, y, z]).unwrap()
}

/// An ambient `x, y, z, w` vector written scalar first.
fn wxyz(v: DVec4) -> [f64; 4] {
    [v.w, v.x, v.y, v.z]
}

fn close4(a: DVec4, b: [f64; 4], tol: f64) {
    let a = wxyz(a);
    let err = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(err < tol, "{a:?} vs {b:?} ({err})");
}

fn r2_points() -> Vec<UnitQuat> {
    vec![
        q(1.0, 0.0, 0.0, 0.0),
        q(0.8, 0.5, 0.3, 0.1),
        q(0.4, 0.7, 0.5, 0.3),
        q(0.1, 0.6, 0.8, 0.2),
        q(-0.2, 0.3, 0.9, 0.5),
        q(-0.4, 0.1, 0.6, 0.9),
    ]
}

fn random_quat(rng: &mut Rng) -> UnitQuat {
    q(rng.normal(), rng.normal(), rng.normal(), rng.normal())
}

fn random_walk(rng: &mut Rng, count: usize) -> Vec<UnitQuat> {
    let mut out = vec![random_quat(rng)];
    while out.len() < count {
        let step = DVec3::new(rng.normal(), rng.normal(), rng.normal()) * 0.5;
        let last = out[out.len() - 1];
        out.push(UnitQuat::exp_pure(step) * last);
    }
    out
}

// ------------------------------------------------------------------------ Algorithm 3 (R1)

#[test]
fn orientation_circle_reference_values() {
    let (p1, p2, p3) = (
        q(1.0, 0.0, 0.0, 0.0),
        q(0.0, 1.0, 0.0, 0.0),
        q(0.0, 0.0, 1.0, 0.0),
    );
    let c = CircleArc::through(&p1, &p2, &p3).unwrap();
    let third = 1.0 / 3.0;
    close4(c.center(), [third, third, third, 0.0], 1e-15);
    assert!(
        (c.radius() - (2.0_f64 / 3.0).sqrt()).abs() < 1e-15,
        "radius"
    );
    assert!((c.first_angle() - 2.0 * PI / 3.0).abs() < 1e-14, "φ");
    assert!((c.second_angle() - 2.0 * PI / 3.0).abs() < 1e-14, "ψ");
    let samples = [
        (0.0, [1.0, 0.0, 0.0, 0.0]),
        (0.25, [2.0 / 3.0, 2.0 / 3.0, -1.0 / 3.0, 0.0]),
        (0.5, [0.0, 1.0, 0.0, 0.0]),
        (0.75, [-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.0]),
        (1.0, [0.0, 0.0, 1.0, 0.0]),
    ];
    for (u, want) in samples {
        close4(c.point_at(u).to_vector(), want, 1e-15);
    }
    // |ω| = 2Θ√(2/3) per unit u, i.e. 2√(2/3) per unit angle: the three-point spline is the arc
    // at unit angular rate about the circle's centre.
    let s = ArcBlend::try_new(vec![p1, p2, p3], 2).unwrap();
    for t in [0.3, 1.7, 3.9] {
        let jet = s.jet(t);
        let (omega, _) = angular_velocity_acceleration(jet.point, jet.velocity, jet.acceleration);
        assert!(
            (omega.length() - 2.0 * (2.0_f64 / 3.0).sqrt()).abs() < 1e-14,
            "|ω|"
        );
    }
}

#[test]
fn orientation_circle_on_a_great_circle() {
    // Linearly dependent triple (the book's ternary product vanishes,
    // `docs/derivations.md#pobegailo-9-2`): the great-circle arc through the three points.
    let a = q(1.0, 0.0, 0.0, 0.0).to_vector();
    let b = q(0.0, 0.6, 0.0, 0.8).to_vector();
    let on = |t: f64| UnitQuat::from_vector_unchecked(a * t.cos() + b * t.sin());
    let c = CircleArc::through(&on(0.2), &on(1.1), &on(2.9)).unwrap();
    assert!(
        c.center().length() < 1e-15 && (c.radius() - 1.0).abs() < 1e-15,
        "great circle"
    );
    assert!(
        (c.first_angle() - 0.9).abs() < 1e-14 && (c.second_angle() - 1.8).abs() < 1e-14,
        "angles"
    );
    // Nearly dependent (|X| ≈ 1e-14): still interpolates to rounding.
    let off = DVec4::new(0.0, 1.0, 0.0, 0.0) * 1e-14;
    let p2 = UnitQuat::try_new(DQuat::from_vec4(on(1.1).to_vector() + off)).unwrap();
    let c = CircleArc::through(&on(0.2), &p2, &on(2.9)).unwrap();
    let u = c.first_angle() / (c.first_angle() + c.second_angle());
    assert!(
        c.point_at(u).dist(&p2) < 1e-14 && c.point_at(1.0).dist(&on(2.9)) < 1e-14,
        "interpolates"
    );
}

// ------------------------------------------------------------------------ Algorithm 5 (R2)

#[test]
fn orientation_spline_reference_values() {
    let pts = r2_points();
    let per_triple = [
        (0.477612813417, 0.728587389046, 0.614964364273),
        (0.851909961099, 1.06516556012, 0.871157396854),
        (0.886471937837, 0.995535226004, 1.13255481797),
        (0.768304193411, 0.796674194239, 0.81567051982),
    ];
    let knots = [
        0.0,
        0.728587389046,
        1.34355175332,
        1.84650713865,
        2.41868633434,
        3.00450887678,
    ];
    let mids: [[[f64; 4]; 5]; 2] = [
        [
            [
                0.949345477839,
                0.274447427585,
                0.150662941237,
                0.0268784548883,
            ],
            [
                0.629755583554,
                0.639529057438,
                0.383457274994,
                0.21764881789,
            ],
            [
                0.256030857154,
                0.679814345759,
                0.644310152257,
                0.239092206447,
            ],
            [
                -0.06014077944,
                0.429524298931,
                0.850253324764,
                0.298263720563,
            ],
            [
                -0.289512513397,
                0.153912552773,
                0.708587680343,
                0.624817517321,
            ],
        ],
        [
            [
                0.949345477839,
                0.274447427585,
                0.150662941237,
                0.0268784548883,
            ],
            [
                0.629947313405,
                0.638454043197,
                0.387542906144,
                0.212963172773,
            ],
            [
                0.253500804819,
                0.680080827614,
                0.642501825254,
                0.245802388948,
            ],
            [
                -0.0627220728306,
                0.43022335438,
                0.850447860617,
                0.296162528518,
            ],
            [
                -0.289512513397,
                0.153912552773,
                0.708587680343,
                0.624817517321,
            ],
        ],
    ];
    for (n, rows) in (1..=2).zip(mids) {
        let c = ArcBlend::try_new(pts.clone(), n).unwrap();
        for (circle, (d, phi, psi)) in c.circles().iter().zip(per_triple) {
            assert!((circle.center().length() - d).abs() < 1e-11, "|κ| = |d|");
            assert!(
                (circle.first_angle() - phi).abs() < 1e-11
                    && (circle.second_angle() - psi).abs() < 1e-11,
                "angles"
            );
        }
        for (a, b) in c.knots().iter().zip(knots) {
            assert!((a - b).abs() < 1e-11, "knot {a} vs {b}");
        }
        let k = c.knots();
        for (i, want) in rows.into_iter().enumerate() {
            close4(c.eval(0.5 * (k[i] + k[i + 1])).to_vector(), want, 1e-11);
        }
        for side in [Side::Left, Side::Right] {
            close4(
                c.jet_at(k[2], side).velocity,
                [
                    -0.736283243359,
                    0.0263288805497,
                    0.527522329723,
                    0.0410730536576,
                ],
                1e-11,
            );
        }
    }
}

#[test]
fn orientation_spline_interpolates_and_is_cn() {
    let mut rng = Rng(0x5eed_0003);
    for n in 1..=10 {
        for _ in 0..4 {
            let pts = random_walk(&mut rng, 7);
            let c = ArcBlend::try_new(pts.clone(), n).unwrap();
            for (t, p) in c.knots().iter().zip(&pts) {
                assert!(c.eval(*t).dist(p) < 1e-14, "interpolation");
            }
            let k = c.knots();
            check_continuity(&c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
        }
    }
    check_derivatives(&ArcBlend::try_new(r2_points(), 2).unwrap(), 60);
    check_derivatives(&ArcBlend::try_new(r2_points(), 3).unwrap(), 60);
}

#[test]
fn orientation_spline_reproduces_a_small_circle() {
    // κ + ρ(cos θ a + sin θ b) with κ ⊥ a, b.
    let kappa = DVec4::new(0.3, -0.2, 0.1, 0.4);
    let a = DVec4::new(0.5, 0.5, -0.5, 0.0);
    let a = (a - kappa * (a.dot(kappa) / kappa.length_squared())).normalize();
    let b = DVec4::new(0.1, -0.7, 0.2, 0.3);
    let b = b - kappa * (b.dot(kappa) / kappa.length_squared());
    let b = (b - a * b.dot(a)).normalize();
    let rho = (1.0 - kappa.length_squared()).sqrt();
    let at = |t: f64| kappa + (a * t.cos() + b * t.sin()) * rho;
    let angles = [0.0, 0.5, 1.4, 2.0, 3.3, 4.1];
    let pts: Vec<UnitQuat> = angles
        .iter()
        .map(|&t| UnitQuat::from_vector_unchecked(at(t)))
        .collect();
    for n in 1..=3 {
        let c = ArcBlend::try_new(pts.clone(), n).unwrap();
        for (k, t) in c.knots().iter().zip(angles) {
            assert!((k - t).abs() < 1e-13, "knots = angles");
        }
        for j in 0..=80 {
            let t = 4.1 * f64::from(j) / 80.0;
            let jet = c.jet(t);
            assert!(
                (jet.point.to_vector() - at(t)).length() < 1e-14,
                "on the circle"
            );
            assert!((jet.velocity.length() - rho).abs() < 1e-14, "uniform speed");
        }
    }
}

#[test]
fn orientation_spline_equivariance() {
    let pts = r2_points();
    let c = ArcBlend::try_new(pts.clone(), 2).unwrap();
    let alpha = UnitQuat::from_axis_angle(DVec3::new(0.3, 1.0, -0.4), 0.9).unwrap();
    let beta = UnitQuat::from_axis_angle(DVec3::new(-1.0, 0.2, 0.5), 2.1).unwrap();
    // x ↦ αxβ (SO(4)) and x ↦ x̄ (a reflection of ℝ⁴).
    let maps: [&dyn Fn(UnitQuat) -> UnitQuat; 2] = [&|x| alpha * x * beta, &|x| x.conjugate()];
    for g in maps {
        let d = ArcBlend::try_new(pts.iter().map(|&x| g(x)).collect(), 2).unwrap();
        for (a, b) in c.knots().iter().zip(d.knots()) {
            assert!((a - b).abs() < 1e-13, "identical knots");
        }
        for j in 0..=60 {
            let t = c.domain()[1] * f64::from(j) / 60.0;
            assert!(g(c.eval(t)).dist(&d.eval(t)) < 1e-14, "equivariant");
        }
    }
}

#[test]
fn orientation_spline_bad_input() {
    let pts = r2_points();
    assert_eq!(
        ArcBlend::try_new(pts[..2].to_vec(), 2).unwrap_err(),
        SplineError::TooFewPoints { min: 3, got: 2 }
    );
    let mut anti = pts.clone();
    anti[2] = -anti[1];
    assert_eq!(
        ArcBlend::try_new(anti, 2).unwrap_err(),
        SplineError::Antipodal { index: 1 }
    );
    let mut dup = pts.clone();
    dup[4] = dup[3];
    assert_eq!(
        ArcBlend::try_new(dup, 2).unwrap_err(),
        SplineError::Coincident { index: 3 }
    );
    let mut back = pts;
    back[3] = back[1];
    assert_eq!(
        ArcBlend::try_new(back, 2).unwrap_err(),
        SplineError::NoCircle { index: 1 }
    );
}

// ------------------------------------------------------------------------ Algorithm 6 (R3)

fn r3_points() -> Vec<UnitQuat> {
    let p2 = UnitQuat::from_axis_angle(DVec3::X, PI / 2.0).unwrap();
    let p3 = UnitQuat::from_axis_angle(DVec3::Y, PI / 2.0).unwrap() * p2;
    vec![UnitQuat::IDENTITY, p2, p3]
}

#[test]
fn orientation_corner_reference_values() {
    let pts = r3_points();
    close4(pts[2].to_vector(), [0.5, 0.5, 0.5, -0.5], 1e-15);
    // The reference values use knots t1 = 0, t2 = 1; ours start with unit speed on S³, t2 = 3π/16,
    // so ref(t) = ours(σt) and reference derivatives are σᵏ times ours.
    let sigma = 3.0 * PI / 16.0;
    let samples = [
        [
            [
                0.797506897704,
                0.60292753461,
                0.0171296771534,
                -0.0129503005485,
            ],
            [
                0.755157156334,
                0.651403042839,
                0.0557037383471,
                -0.048050375147,
            ],
            [
                0.715257205008,
                0.685177227306,
                0.0993793698496,
                -0.0951999932447,
            ],
        ],
        [
            [
                0.798664468359,
                0.60163945047,
                0.0102610781135,
                -0.00772974088872,
            ],
            [
                0.751471842898,
                0.656308911295,
                0.0507978698911,
                -0.0443650617112,
            ],
            [
                0.709147368916,
                0.691156549914,
                0.0997781775569,
                -0.0972468403321,
            ],
        ],
    ];
    for (n, rows) in (1..=2).zip(samples) {
        let c = CornerBlendRotations::try_new(pts.clone(), n, 0.25).unwrap();
        let k = c.knots();
        for (a, b) in k.iter().zip([0.0, 1.0, 4.0 / 3.0, 7.0 / 3.0]) {
            assert!((a - sigma * b).abs() < 1e-14, "knots");
        }
        close4(
            c.eval(k[1]).to_vector(),
            [0.831469612303, 0.55557023302, 0.0, 0.0],
            1e-11,
        );
        close4(
            c.eval(k[2]).to_vector(),
            [
                0.693519922661,
                0.693519922661,
                0.137949689641,
                -0.137949689641,
            ],
            1e-11,
        );
        for (i, want) in rows.into_iter().enumerate() {
            let t = sigma * (1.0 + (i as f64 + 1.0) / 12.0);
            close4(c.eval(t).to_vector(), want, 1e-11);
        }
        for side in [Side::Left, Side::Right] {
            close4(
                c.jet_at(k[1], side).velocity * sigma,
                [-0.327257880489, 0.489776029817, 0.0, 0.0],
                1e-11,
            );
        }
        close4(
            c.jet_at(k[1], Side::Left).acceleration * (sigma * sigma),
            [-0.288501895721, -0.19277080372, 0.0, 0.0],
            1e-11,
        );
        let right = c.jet_at(k[1], Side::Right).acceleration * (sigma * sigma);
        if n == 2 {
            close4(right, [-0.288501895721, -0.19277080372, 0.0, 0.0], 1e-11);
        } else {
            close4(
                right,
                [-2.25204917865, 2.74588537518, 5.87731235781, -3.92709456587],
                1e-10,
            );
        }
    }
}

#[test]
fn orientation_corner_printed_formula_misses_the_cut_points() {
    // (9.20) as printed applies the rotations to Q₁ instead of P₂
    // (`docs/derivations.md#pobegailo-8-21`).
    let pts = r3_points();
    let c = CornerBlendRotations::try_new(pts.clone(), 2, 0.25).unwrap();
    let k = c.knots();
    let (q1, q2) = (c.eval(k[1]), c.eval(k[2]));
    let e = |axis: DVec3, s: f64| UnitQuat::exp_pure(axis * s);
    let (phi2, psi1) = (PI / 16.0, PI / 16.0); // S³ angles: a quarter of each 45° edge
    let w = SmoothingPolynomials::try_new(2).unwrap();
    let corner = |base: UnitQuat, u: f64| {
        e(DVec3::Y, w.w1(u) * psi1) * e(DVec3::X, -w.w1(1.0 - u) * phi2) * base
    };
    assert!(
        corner(q1, 0.0).dist(&q1) > 0.1 && corner(q1, 1.0).dist(&q2) > 0.1,
        "printed misses Q1, Q2"
    );
    assert!(
        corner(pts[1], 0.0).dist(&q1) < 1e-15 && corner(pts[1], 1.0).dist(&q2) < 1e-15,
        "corrected hits them"
    );
    for u in [0.2, 0.5, 0.9] {
        assert!(
            c.eval(k[1] + u * (k[2] - k[1])).dist(&corner(pts[1], u)) < 1e-15,
            "library = corrected"
        );
    }
    // The corner avoids P₂.
    assert!(
        c.eval(0.5 * (k[1] + k[2])).dist(&pts[1]) > 0.05,
        "misses P2"
    );
}

#[test]
fn orientation_corner_is_cn_with_constant_angular_velocity_on_edges() {
    let mut rng = Rng(0xabcd);
    for n in 1..=10 {
        for fraction in [0.15, 0.25, 0.5] {
            let pts = random_walk(&mut rng, 5);
            let c = CornerBlendRotations::try_new(pts.clone(), n, fraction).unwrap();
            let k = c.knots();
            assert!(
                c.eval(0.0).dist(&pts[0]) < 1e-15 && c.eval(k[k.len() - 1]).dist(&pts[4]) < 1e-14,
                "ends"
            );
            check_continuity(&c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
            // The first edge: angular velocity constant, magnitude 2 (unit speed on S³).
            let w0 = {
                let j = c.jet(0.0);
                angular_velocity_acceleration(j.point, j.velocity, j.acceleration)
            };
            assert!(
                (w0.0.length() - 2.0).abs() < 1e-14 && w0.1.length() < 1e-13,
                "edge 0"
            );
            let j = c.jet(0.7 * k[1]);
            let (omega, alpha) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
            assert!(
                (omega - w0.0).length() < 1e-14 && alpha.length() < 1e-13,
                "constant ω on the edge"
            );
        }
    }
    let c = CornerBlendRotations::try_new(random_walk(&mut rng, 6), 3, 0.3).unwrap();
    check_derivatives(&c, 80);
    let d = CornerBlend::try_new(random_walk(&mut rng, 6), 3, 0.3).unwrap();
    check_derivatives(&d, 80);
}

#[test]
fn orientation_corner_equivariance_and_bad_input() {
    let mut rng = Rng(77);
    let pts = random_walk(&mut rng, 5);
    let c = CornerBlendRotations::try_new(pts.clone(), 2, 0.25).unwrap();
    let (alpha, beta) = (random_quat(&mut rng), random_quat(&mut rng));
    let d = CornerBlendRotations::try_new(pts.iter().map(|&x| alpha * x * beta).collect(), 2, 0.25)
        .unwrap();
    for j in 0..=50 {
        let t = c.domain()[1] * f64::from(j) / 50.0;
        assert!(
            (alpha * c.eval(t) * beta).dist(&d.eval(t)) < 1e-14,
            "equivariant"
        );
    }
    assert!(matches!(
        CornerBlendRotations::try_new(pts.clone(), 0, 0.25),
        Err(SplineError::InvalidParameter {
            name: "smoothness",
            ..
        })
    ));
    assert!(matches!(
        CornerBlendRotations::try_new(pts.clone(), 2, 0.75),
        Err(SplineError::InvalidParameter {
            name: "fraction",
            ..
        })
    ));
    let mut anti = pts.clone();
    anti[3] = -anti[2];
    assert_eq!(
        CornerBlendRotations::try_new(anti, 2, 0.25).unwrap_err(),
        SplineError::Antipodal { index: 2 }
    );
    let mut dup = pts;
    dup[1] = dup[0];
    assert_eq!(
        CornerBlendRotations::try_new(dup, 2, 0.25).unwrap_err(),
        SplineError::Coincident { index: 0 }
    );
    // Near-antipodal and nearly coincident keys: finite unit results.
    let near = vec![
        UnitQuat::IDENTITY,
        q(1.0, 1e-9, 0.0, 0.0),
        q(-1.0, 1e-7, 0.0, 1e-9),
        q(0.0, 1.0, 0.0, 0.0),
    ];
    for c in [CornerBlendRotations::try_new(near.clone(), 2, 0.25).unwrap()] {
        for j in 0..=100 {
            let jet = c.jet(c.domain()[1] * f64::from(j) / 100.0);
            assert!(
                jet.velocity.is_finite() && jet.acceleration.is_finite(),
                "finite"
            );
            assert!((jet.point.to_vector().length() - 1.0).abs() < 1e-14, "unit");
        }
    }
}
