// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Rotation conversions (Pobegailo 2019, chapters 3–4): standard identities, the
//! book's golden values that are correct, and one negative test per corrected misprint.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_8, PI, SQRT_2};

use crate::support::Rng;

use spherekit::glam::{DMat3, DQuat, DVec3};
use spherekit::{
    ROTATION_TOLERANCE, RotationError, UnitQuat, rodrigues_compose, rotation_matrix_from_rodrigues,
};

const TRIALS: usize = 500;

fn mat_err(a: DMat3, b: DMat3) -> f64 {
    (a - b)
        .abs()
        .to_cols_array()
        .into_iter()
        .fold(0.0, f64::max)
}

/// Distance between unit quaternions up to sign.
fn quat_err_pm(a: UnitQuat, b: UnitQuat) -> f64 {
    let (a, b) = (a.as_dquat(), b.as_dquat());
    (a - b).length().min((a + b).length())
}

fn entry(m: DMat3, i: usize, j: usize) -> f64 {
    m.col(j)[i]
}

/// K(a) with K(a)·b = a × b.
fn skew(a: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, a.z, -a.y),
        DVec3::new(-a.z, 0.0, a.x),
        DVec3::new(a.y, -a.x, 0.0),
    )
}

/// exp(K(w)) = I + sinθ/θ·K + (1 − cosθ)/θ²·K² (Pobegailo 2019, §4.6), θ = |w| > 0.
fn exp_skew(w: DVec3) -> DMat3 {
    let t = w.length();
    let k = skew(w);
    DMat3::IDENTITY + k * (t.sin() / t) + (k * k) * ((1.0 - t.cos()) / (t * t))
}

/// Axis–angle matrix by the Rodrigues vector formula (3.10): columns R·eᵢ.
fn rodrigues_vector_formula(n: DVec3, phi: f64) -> DMat3 {
    let rot =
        |v: DVec3| v * phi.cos() + n.cross(v) * phi.sin() + n * (n.dot(v) * (1.0 - phi.cos()));
    DMat3::from_cols(rot(DVec3::X), rot(DVec3::Y), rot(DVec3::Z))
}

fn qa(axis: DVec3, angle: f64) -> UnitQuat {
    UnitQuat::from_axis_angle(axis, angle).expect("valid axis and angle")
}

// ---------------------------------------------------------------------------------------------
// Item 10: R(Q) is a proper rotation, a homomorphism, and the action q p q̄.

#[test]
fn matrix_is_proper_rotation() {
    let mut rng = Rng::new(1);
    for _ in 0..TRIALS {
        let r = rng.quat().to_rotation_matrix();
        assert!(
            mat_err(r.transpose() * r, DMat3::IDENTITY) < 1e-15,
            "RᵀR = I"
        );
        assert!((r.determinant() - 1.0).abs() < 2e-15, "det R = 1");
    }
}

#[test]
fn matrix_sign_conjugate_and_homomorphism() {
    let mut rng = Rng::new(2);
    for _ in 0..TRIALS {
        let (p, q) = (rng.quat(), rng.quat());
        let rq = q.to_rotation_matrix();
        assert_eq!((-q).to_rotation_matrix(), rq, "R(−q) = R(q) exactly");
        assert!(
            mat_err(q.conjugate().to_rotation_matrix(), rq.transpose()) < 1e-16,
            "R(q̄) = Rᵀ"
        );
        let lhs = (p * q).to_rotation_matrix();
        let rhs = p.to_rotation_matrix() * rq;
        assert!(
            mat_err(lhs, rhs) < 1e-15,
            "R(PQ) = R(P)R(Q): {}",
            mat_err(lhs, rhs)
        );
    }
}

#[test]
fn matrix_acts_as_q_p_conj_q() {
    let mut rng = Rng::new(3);
    for _ in 0..TRIALS {
        let q = rng.quat();
        let p = rng.vec3(3.0);
        let by_matrix = q.to_rotation_matrix() * p;
        let by_rotate = q.rotate(p);
        let dq = q.as_dquat();
        let by_product = (dq * DQuat::from_xyzw(p.x, p.y, p.z, 0.0) * dq.conjugate()).xyz();
        assert!(
            (by_matrix - by_rotate).length() < 1e-14,
            "R p = q.rotate(p)"
        );
        assert!(
            (by_matrix - by_product).length() < 1e-14,
            "R p = vec(q p q̄)"
        );
        assert!(
            (by_matrix.length() - p.length()).abs() < 1e-14,
            "|Rp| = |p|"
        );
        // Agrees with glam's own (column-vector, active) convention.
        let glam = DMat3::from_quat(dq);
        assert!(
            mat_err(q.to_rotation_matrix(), glam) < 1e-15,
            "matches glam"
        );
    }
}

#[test]
fn non_unit_quaternion_matrix_divided_by_norm() {
    // vec(Q p Q⁻¹) = R₍₃.₄₆₎(Q) p / N(Q) for non-unit Q: (3.46) is homogeneous of degree 2.
    let mut rng = Rng::new(4);
    for _ in 0..50 {
        let q = rng.quat();
        let s = rng.range(0.5, 3.0);
        let big = q.as_dquat() * s;
        let p = rng.vec3(1.0);
        let conj = big.conjugate() / (s * s);
        let lhs = (big * DQuat::from_xyzw(p.x, p.y, p.z, 0.0) * conj).xyz();
        // (3.46) written out on the non-unit components, divided by N(Q).
        let (w, x, y, z) = (big.w, big.x, big.y, big.z);
        let m346 = DMat3::from_cols_array_2d(&[
            [
                w * w + x * x - y * y - z * z,
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                w * w - x * x + y * y - z * z,
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                w * w - x * x - y * y + z * z,
            ],
        ])
        .transpose(); // rows as printed
        let rhs = m346 * p / big.length_squared();
        assert!(
            mat_err(m346 / big.length_squared(), q.to_rotation_matrix()) < 1e-15,
            "(3.46)"
        );
        assert!((lhs - rhs).length() < 1e-14, "non-unit action");
    }
}

// ---------------------------------------------------------------------------------------------
// Items 11, 14, 15: axis–angle forms and the golden matrix.

#[test]
fn four_axis_angle_forms_agree() {
    let mut rng = Rng::new(5);
    for _ in 0..TRIALS {
        let n = rng.unit3();
        let phi = rng.range(-PI, PI);
        let r = qa(n, phi).to_rotation_matrix();
        assert!(
            mat_err(r, rodrigues_vector_formula(n, phi)) < 1e-15,
            "(3.10)"
        );
        if phi != 0.0 {
            assert!(mat_err(r, exp_skew(n * phi)) < 4e-15, "exp(φK)");
        }
        assert!((r * n - n).length() < 1e-15, "R n = n");
        assert!(
            mat_err(r.transpose(), qa(-n, phi).to_rotation_matrix()) < 1e-15,
            "Rᵀ = R(−n, φ)"
        );
        assert!(
            mat_err(r.transpose(), qa(n, -phi).to_rotation_matrix()) < 1e-15,
            "Rᵀ = R(n, −φ)"
        );
        let psi = rng.range(-PI, PI);
        let sum = qa(n, phi + psi).to_rotation_matrix();
        assert!(
            mat_err(r * qa(n, psi).to_rotation_matrix(), sum) < 4e-15,
            "same-axis additivity"
        );
    }
    for gamma in [0.3, 1.0, 2.5, -1.2] {
        let e = qa(DVec3::Z, gamma).to_rotation_matrix() * DVec3::X;
        assert!(
            (e - DVec3::new(gamma.cos(), gamma.sin(), 0.0)).length() < 1e-15,
            "R(e₃, γ)e₁"
        );
    }
}

#[test]
fn quaternion_composition_formula_of_3_13() {
    // cos(φ/2), sin(φ/2)n of Q₂Q₁ from the halves of Q₁ and Q₂ (§3.13, §4.5).
    let mut rng = Rng::new(6);
    for _ in 0..TRIALS {
        let (n1, n2) = (rng.unit3(), rng.unit3());
        let (f1, f2) = (rng.range(-PI, PI), rng.range(-PI, PI));
        let (s1, c1) = (0.5 * f1).sin_cos();
        let (s2, c2) = (0.5 * f2).sin_cos();
        let w = c2 * c1 - s2 * s1 * n2.dot(n1);
        let v = n1 * (c2 * s1) + n2 * (c1 * s2) + n2.cross(n1) * (s2 * s1);
        let q = (qa(n2, f2) * qa(n1, f1)).as_dquat();
        assert!(
            (q.w - w).abs() < 1e-15 && (q.xyz() - v).length() < 1e-15,
            "(3.13) composition"
        );
    }
}

#[test]
fn golden_matrix_of_section_2_4() {
    let h = SQRT_2 / 2.0;
    let q = UnitQuat::from_wxyz([h, SQRT_2 / 4.0, SQRT_2 / 4.0, 0.5]).unwrap();
    let expected = DMat3::from_cols_array_2d(&[
        [0.25, 0.25 + h, SQRT_2 / 4.0 - 0.5],
        [0.25 - h, 0.25, SQRT_2 / 4.0 + 0.5],
        [SQRT_2 / 4.0 + 0.5, SQRT_2 / 4.0 - 0.5, 0.5],
    ]); // columns of the printed rows
    let r = q.to_rotation_matrix();
    assert!(mat_err(r, expected) < 1e-15, "golden (3.46): {r:?}");
    let back = UnitQuat::from_rotation_matrix(r).unwrap();
    assert!(quat_err_pm(back, q) < 1e-15, "round trip ±Q");
    let (axis, angle) = q.to_axis_angle();
    assert!((angle - FRAC_PI_2).abs() < 1e-15, "rotation angle π/2");
    assert!(
        (axis - DVec3::new(0.5, 0.5, h)).length() < 1e-15,
        "axis (½, ½, √2/2)"
    );
}

// ---------------------------------------------------------------------------------------------
// Items 12, 13: matrix → quaternion and axis–angle extraction.

/// The single-branch (q₀-only) inversion, the book's Euler-parameter inverse (§4.4, corrected:
/// `docs/derivations.md#pobegailo-4-13`),
/// without normalisation.
fn q0_only_raw(m: DMat3) -> [f64; 4] {
    let w = 0.5 * (1.0 + entry(m, 0, 0) + entry(m, 1, 1) + entry(m, 2, 2)).sqrt();
    let f = 0.25 / w;
    [
        w,
        (entry(m, 2, 1) - entry(m, 1, 2)) * f,
        (entry(m, 0, 2) - entry(m, 2, 0)) * f,
        (entry(m, 1, 0) - entry(m, 0, 1)) * f,
    ]
}

fn q0_only_inverse(m: DMat3) -> UnitQuat {
    UnitQuat::from_wxyz(q0_only_raw(m)).expect("finite away from a half turn")
}

#[test]
fn matrix_round_trip_random() {
    let mut rng = Rng::new(7);
    let mut worst = 0.0_f64;
    for _ in 0..TRIALS {
        let q = rng.quat();
        let back = UnitQuat::from_rotation_matrix(q.to_rotation_matrix()).unwrap();
        assert!(back.scalar() >= 0.0, "canonical sign q₀ ≥ 0");
        worst = worst.max(quat_err_pm(back, q));
    }
    assert!(worst < 1e-15, "worst round-trip error {worst:e}");
}

#[test]
fn matrix_round_trip_edge_angles() {
    let mut rng = Rng::new(8);
    let mut axes = vec![
        DVec3::Z,
        -DVec3::Z,
        DVec3::X,
        -DVec3::Y,
        DVec3::new(1.0, -1.0, 1.0) / 3f64.sqrt(),
    ];
    axes.extend((0..50).map(|_| rng.unit3()));
    for n in axes {
        for phi in [
            0.0,
            1e-12,
            1e-7,
            1.0,
            PI - 1e-7,
            PI - 1e-12,
            PI,
            -PI + 1e-12,
        ] {
            let q = qa(n, phi);
            let back = UnitQuat::from_rotation_matrix(q.to_rotation_matrix()).unwrap();
            let e = quat_err_pm(back, q);
            assert!(e < 1e-15, "n = {n}, φ = {phi}: error {e:e}");
            // The robust route to axis–angle: matrix → quaternion → axis–angle.
            let (axis, angle) = back.to_axis_angle();
            assert!((angle - phi.abs()).abs() < 2e-15, "angle at φ = {phi}");
            if phi != 0.0 {
                let expected = if phi > 0.0 { n } else { -n };
                let e = if phi.abs() == PI {
                    (axis - expected).length().min((axis + expected).length())
                } else {
                    (axis - expected).length()
                };
                assert!(e < 1e-14, "axis at φ = {phi}: {axis} vs {expected}");
            }
        }
    }
}

#[test]
fn negative_q0_only_inverse_loses_accuracy_near_half_turn() {
    let mut rng = Rng::new(9);
    for phi in [PI - 1e-7, PI - 1e-12] {
        let mut worst_raw = 0.0_f64;
        let mut worst_q0 = 0.0_f64;
        let mut worst_four = 0.0_f64;
        for _ in 0..50 {
            let q = qa(rng.unit3(), phi);
            let m = q.to_rotation_matrix();
            let raw = q0_only_raw(m);
            let raw = DQuat::from_xyzw(raw[1], raw[2], raw[3], raw[0]);
            // At π − 1e-12, 1 + tr R can round to a negative number: √ gives NaN (counted as ∞).
            let e_raw = (raw - q.as_dquat()).length();
            worst_raw = worst_raw.max(if e_raw.is_nan() { f64::INFINITY } else { e_raw });
            let e_q0 = UnitQuat::try_new(raw).map_or(f64::INFINITY, |p| quat_err_pm(p, q));
            worst_q0 = worst_q0.max(e_q0);
            worst_four = worst_four.max(quat_err_pm(UnitQuat::from_rotation_matrix(m).unwrap(), q));
        }
        println!(
            "φ = π − {:e}: q₀-only raw {worst_raw:e}, normalised {worst_q0:e}, four-branch {worst_four:e}",
            PI - phi
        );
        assert!(worst_four < 1e-15, "four-branch {worst_four:e}");
        assert!(
            worst_raw > 1e-5,
            "q₀-only raw error {worst_raw:e} should be large"
        );
        assert!(
            worst_q0 > 1e3 * worst_four.max(1e-16),
            "q₀-only normalised error {worst_q0:e}"
        );
    }
    // Away from π the single branch is fine (it is the m = 0 branch).
    let q = qa(DVec3::new(1.0, 2.0, 3.0), 1.0);
    assert!(
        quat_err_pm(q0_only_inverse(q.to_rotation_matrix()), q) < 1e-15,
        "q₀-only at 1 rad"
    );
}

#[test]
fn negative_transposed_3_41_inversion_returns_conjugate() {
    // The book's [M 3.10] inversion q₁ = (r₂₃ − r₃₂)/(4q₀), … is for the transposed matrix (3.41):
    // on the standard matrix it returns q̄, a different rotation.
    let q = qa(DVec3::new(1.0, 2.0, 3.0), 1.0);
    let m = q.to_rotation_matrix();
    let w = 0.5 * (1.0 + entry(m, 0, 0) + entry(m, 1, 1) + entry(m, 2, 2)).sqrt();
    let printed = UnitQuat::from_wxyz([
        w,
        (entry(m, 1, 2) - entry(m, 2, 1)) / (4.0 * w),
        (entry(m, 2, 0) - entry(m, 0, 2)) / (4.0 * w),
        (entry(m, 0, 1) - entry(m, 1, 0)) / (4.0 * w),
    ])
    .unwrap();
    assert!(quat_err_pm(printed, q) > 0.1, "printed inversion is wrong");
    assert!(
        quat_err_pm(printed, q.conjugate()) < 1e-15,
        "it gives the conjugate"
    );
}

#[test]
fn negative_3_16_loses_axis_signs_at_half_turn() {
    // At φ = π, R = 2nnᵀ − I; the printed (3.16) n_i = √((r_ii + 1)/2) drops the signs, while the
    // quaternion route returns ±n.
    let n = DVec3::new(1.0, -2.0, 2.0) / 3.0;
    let m = qa(n, PI).to_rotation_matrix();
    let printed = DVec3::new(
        ((entry(m, 0, 0) + 1.0) / 2.0).sqrt(),
        ((entry(m, 1, 1) + 1.0) / 2.0).sqrt(),
        ((entry(m, 2, 2) + 1.0) / 2.0).sqrt(),
    );
    assert!(
        (printed - n).length().min((printed + n).length()) > 0.5,
        "(3.16) is not ±n"
    );
    let (axis, angle) = UnitQuat::from_rotation_matrix(m).unwrap().to_axis_angle();
    assert!((angle - PI).abs() < 1e-15, "angle π");
    assert!(
        (axis - n).length().min((axis + n).length()) < 1e-15,
        "axis ±n"
    );
}

#[test]
fn matrix_validation() {
    let nan = DMat3::from_diagonal(DVec3::new(1.0, f64::NAN, 1.0));
    assert_eq!(
        UnitQuat::from_rotation_matrix(nan),
        Err(RotationError::NonFinite)
    );
    let inf = DMat3::from_diagonal(DVec3::new(1.0, f64::INFINITY, 1.0));
    assert_eq!(
        UnitQuat::from_rotation_matrix(inf),
        Err(RotationError::NonFinite)
    );
    let scaled = DMat3::IDENTITY * 2.0;
    assert!(matches!(
        UnitQuat::from_rotation_matrix(scaled),
        Err(RotationError::NotOrthogonal { deviation }) if (deviation - 3.0).abs() < 1e-15
    ));
    let shear = DMat3::from_cols(DVec3::X, DVec3::new(0.01, 1.0, 0.0), DVec3::Z);
    assert!(matches!(
        UnitQuat::from_rotation_matrix(shear),
        Err(RotationError::NotOrthogonal { .. })
    ));
    let reflection = qa(DVec3::new(1.0, 1.0, 0.0), 0.7).to_rotation_matrix() * -1.0;
    assert!(matches!(
        UnitQuat::from_rotation_matrix(reflection),
        Err(RotationError::NotProper { det }) if (det + 1.0).abs() < 1e-14
    ));
    assert!(
        UnitQuat::from_rotation_matrix(DMat3::ZERO).is_err(),
        "zero matrix"
    );
    // Within tolerance: a rotation printed to 9 digits is accepted and lands next to it.
    let q = qa(DVec3::new(0.3, -0.2, 0.9), 2.0);
    let mut m = q.to_rotation_matrix();
    m.x_axis.y += 1e-9;
    let back = UnitQuat::from_rotation_matrix(m).unwrap();
    assert!(quat_err_pm(back, q) < 1e-9, "near-rotation accepted");
    assert!(
        (back.as_dquat().length() - 1.0).abs() < 1e-15,
        "unit result"
    );
    m.x_axis.y += 10.0 * ROTATION_TOLERANCE;
    assert!(
        UnitQuat::from_rotation_matrix(m).is_err(),
        "beyond tolerance rejected"
    );
    for e in [
        RotationError::NonFinite,
        RotationError::NotOrthogonal { deviation: 0.5 },
        RotationError::NotProper { det: -1.0 },
        RotationError::NotUnit { norm: 2.0 },
        RotationError::HalfTurn,
    ] {
        assert!(!e.to_string().is_empty(), "Display");
    }
}

#[test]
fn axis_angle_round_trip_and_canonical_range() {
    let mut rng = Rng::new(10);
    for _ in 0..TRIALS {
        let q = rng.quat();
        let (axis, angle) = q.to_axis_angle();
        assert!((0.0..=PI).contains(&angle), "angle in [0, π]");
        assert!((axis.length() - 1.0).abs() < 1e-15, "unit axis");
        assert_eq!((-q).to_axis_angle(), (axis, angle), "independent of sign");
        assert!(
            (angle - q.rotation_angle()).abs() < 1e-15,
            "agrees with rotation_angle"
        );
        assert!(quat_err_pm(qa(axis, angle), q) < 1e-15, "round trip ±q");
        // Rotation vector (s3.rs) of the canonical sign is axis × angle.
        let canon = if q.scalar() < 0.0 { -q } else { q };
        let w = canon.to_rotation_vector();
        assert!(
            (w - axis * angle).length() < 1e-14,
            "rotation vector = angle·axis"
        );
        assert!(
            quat_err_pm(UnitQuat::from_rotation_vector(w).unwrap(), q) < 1e-15,
            "rotation vector round trip"
        );
    }
    // Identity: documented axis e₁, angle 0; tiny angles keep full relative accuracy.
    assert_eq!(UnitQuat::IDENTITY.to_axis_angle(), (DVec3::X, 0.0));
    assert_eq!((-UnitQuat::IDENTITY).to_axis_angle(), (DVec3::X, 0.0));
    let n = DVec3::new(2.0, -1.0, 2.0) / 3.0;
    let (axis, angle) = qa(n, 1e-10).to_axis_angle();
    assert!(
        (angle / 1e-10 - 1.0).abs() < 1e-15 && (axis - n).length() < 1e-15,
        "tiny angle"
    );
}

// ---------------------------------------------------------------------------------------------
// Items 16, 17, 19: Cayley factorization, Rodrigues parameters and their composition.

/// The printed (4.12): signs of the r₃ terms at (1,2) and (2,1) exchanged.
fn printed_4_12(r: DVec3) -> DMat3 {
    let (a, b, c) = (r.x, r.y, r.z);
    let rows = [
        [
            1.0 + a * a - b * b - c * c,
            2.0 * (a * b + c),
            2.0 * (a * c + b),
        ],
        [
            2.0 * (a * b - c),
            1.0 - a * a + b * b - c * c,
            2.0 * (b * c - a),
        ],
        [
            2.0 * (a * c - b),
            2.0 * (b * c + a),
            1.0 - a * a - b * b + c * c,
        ],
    ];
    DMat3::from_cols_array_2d(&rows).transpose() * (1.0 / (1.0 + r.length_squared()))
}

#[test]
fn rodrigues_golden_value() {
    let q = qa(DVec3::Z, FRAC_PI_4);
    let r = q.to_rodrigues().unwrap();
    assert!(
        (r - DVec3::new(0.0, 0.0, SQRT_2 - 1.0)).length() < 1e-16,
        "r = (0, 0, √2 − 1): {r}"
    );
    // The book's [M 4.2] value √2/(4(√2 + 2)) is wrong.
    assert!(
        (r.z - SQRT_2 / (4.0 * (SQRT_2 + 2.0))).abs() > 0.3,
        "book value differs"
    );
    let m = rotation_matrix_from_rodrigues(r).unwrap();
    assert!(
        mat_err(m, q.to_rotation_matrix()) < 1e-16,
        "R(r) = R(e₃, π/4)"
    );
}

#[test]
fn rodrigues_parameters_round_trip() {
    let mut rng = Rng::new(11);
    for _ in 0..TRIALS {
        let n = rng.unit3();
        let phi = rng.range(-3.1, 3.1);
        let q = qa(n, phi);
        let r = q.to_rodrigues().unwrap();
        assert!(
            (r - n * (0.5 * phi).tan()).length() < 1e-13 * (1.0 + r.length()),
            "r = tan(φ/2)n"
        );
        assert_eq!((-q).to_rodrigues().unwrap(), r, "independent of sign");
        let back = UnitQuat::from_rodrigues(r).unwrap();
        assert!(back.scalar() > 0.0, "q₀ > 0");
        assert!(quat_err_pm(back, q) < 1e-15, "round trip");
    }
    // Half turn and near half turn.
    // from_axis_angle(n, π) has q₀ = cos(π/2) ≈ 6e-17, not 0: its r is huge but finite.
    let exact_half_turn = UnitQuat::from_wxyz([0.0, 0.0, 1.0, 0.0]).unwrap();
    assert_eq!(exact_half_turn.to_rodrigues(), Err(RotationError::HalfTurn));
    assert!(
        qa(DVec3::Y, PI).to_rodrigues().unwrap().y > 1e16,
        "angle π in floating point"
    );
    let near = qa(DVec3::Y, PI - 1e-9).to_rodrigues().unwrap();
    assert!(
        (near.y * 5e-10 - 1.0).abs() < 1e-6,
        "tan(π/2 − 5e-10) ≈ 2e9: {near}"
    );
    let huge = UnitQuat::from_rodrigues(DVec3::new(1e300, -1e300, 0.0)).unwrap();
    assert!(
        (huge.rotation_angle() - PI).abs() < 1e-15,
        "huge r is almost a half turn"
    );
    assert_eq!(
        UnitQuat::from_rodrigues(DVec3::new(f64::NAN, 0.0, 0.0)),
        Err(RotationError::NonFinite)
    );
    assert_eq!(
        UnitQuat::from_rodrigues(DVec3::ZERO).unwrap(),
        UnitQuat::IDENTITY
    );
}

#[test]
fn rodrigues_matrix_and_cayley_factorization() {
    let mut rng = Rng::new(12);
    for _ in 0..TRIALS {
        let n = rng.unit3();
        let phi = rng.range(-3.0, 3.0);
        let r = n * (0.5 * phi).tan();
        let m = rotation_matrix_from_rodrigues(r).unwrap();
        let exact = qa(n, phi).to_rotation_matrix();
        assert!(mat_err(m, exact) < 1e-14, "corrected (4.12) = R(n, φ)");
        assert!(
            mat_err(m.transpose() * m, DMat3::IDENTITY) < 1e-14,
            "orthogonal"
        );
        assert!((m.determinant() - 1.0).abs() < 1e-14, "det 1");
        let k = skew(r);
        let (i_minus, i_plus) = (DMat3::IDENTITY - k, DMat3::IDENTITY + k);
        assert!(
            mat_err(i_minus.inverse() * i_plus, m) < 1e-13,
            "(I − K)⁻¹(I + K)"
        );
        assert!(
            mat_err(i_plus * i_minus.inverse(), m) < 1e-13,
            "(I + K)(I − K)⁻¹"
        );
        let printed_inverse = (DMat3::IDENTITY + DMat3::from_cols(r * r.x, r * r.y, r * r.z) + k)
            * (1.0 / (1.0 + r.length_squared()));
        assert!(
            mat_err(printed_inverse, i_minus.inverse()) < 1e-13,
            "(I − K)⁻¹ as printed"
        );
        let scale = 1.0 + r.length_squared();
        assert!(
            (i_minus.determinant() - scale).abs() < 1e-12 * scale,
            "det(I − K) = 1 + |r|²"
        );
        let c = (0.5 * phi).cos();
        assert!(
            ((m + DMat3::IDENTITY).determinant() - 8.0 * c * c).abs() < 1e-13,
            "det(R + I)"
        );
        assert!(
            mat_err((m - DMat3::IDENTITY) * (m + DMat3::IDENTITY).inverse(), k) < 1e-11 * scale,
            "(R − I)(R + I)⁻¹ = K(r)"
        );
        let v = rng.vec3(2.0);
        let vt = m * v;
        assert!(
            (vt - (v + r.cross(v + vt))).length() < 1e-13 * scale,
            "ṽ = v + r × (v + ṽ)"
        );
        // Inverse formula of §4.3 (sign corrected): r = (r₃₂ − r₂₃, r₁₃ − r₃₁, r₂₁ − r₁₂)/(1 + tr
        // R).
        let tr1 = 1.0 + entry(m, 0, 0) + entry(m, 1, 1) + entry(m, 2, 2);
        let inv = DVec3::new(
            entry(m, 2, 1) - entry(m, 1, 2),
            entry(m, 0, 2) - entry(m, 2, 0),
            entry(m, 1, 0) - entry(m, 0, 1),
        ) / tr1;
        assert!(
            (inv - r).length() < 1e-12 * scale,
            "inverse formula returns r"
        );
        // r = q/q₀.
        let q = qa(n, phi).as_dquat();
        assert!((q.xyz() / q.w - r).length() < 1e-13 * scale, "r = q/q₀");
    }
    // Huge r (next to a half turn) stays finite and orthogonal.
    let m = rotation_matrix_from_rodrigues(DVec3::new(3e200, 4e200, 0.0)).unwrap();
    assert!(m.is_finite(), "no overflow");
    assert!(
        mat_err(m, qa(DVec3::new(3.0, 4.0, 0.0), PI).to_rotation_matrix()) < 1e-15,
        "half turn limit"
    );
}

#[test]
fn negative_printed_4_12_is_not_orthogonal() {
    let r = DVec3::new(0.3, -0.4, 0.5);
    let printed = printed_4_12(r);
    assert!(
        mat_err(printed.transpose() * printed, DMat3::IDENTITY) > 0.1,
        "printed (4.12) not orthogonal"
    );
    let corrected = rotation_matrix_from_rodrigues(r).unwrap();
    assert!(
        mat_err(corrected.transpose() * corrected, DMat3::IDENTITY) < 1e-15,
        "corrected is"
    );
    // The book's inverse r₃ = (r₁₂ − r₂₁)/(1 + tr R) has the wrong sign.
    let m = corrected;
    let tr1 = 1.0 + entry(m, 0, 0) + entry(m, 1, 1) + entry(m, 2, 2);
    assert!(
        ((entry(m, 0, 1) - entry(m, 1, 0)) / tr1 + r.z).abs() < 1e-15,
        "printed r₃ is −r₃"
    );
}

#[test]
fn rodrigues_composition_law() {
    let mut rng = Rng::new(13);
    for _ in 0..TRIALS {
        let (q1, q2) = (rng.quat(), rng.quat());
        let (r1, r2) = (q1.to_rodrigues().unwrap(), q2.to_rodrigues().unwrap());
        let Some(r) = rodrigues_compose(r1, r2) else {
            panic!("generic composition is not a half turn");
        };
        let q = q1 * q2;
        let scale = 1.0 + r.length() + r1.length() * r2.length();
        let expected = q.to_rodrigues().unwrap();
        assert!(
            (r - expected).length() < 1e-12 * scale * scale,
            "r = vec(q₁q₂)/scal(q₁q₂)"
        );
        let lhs = rotation_matrix_from_rodrigues(r).unwrap();
        let rhs = rotation_matrix_from_rodrigues(r1).unwrap()
            * rotation_matrix_from_rodrigues(r2).unwrap();
        assert!(mat_err(lhs, rhs) < 1e-10, "R(r) = R(r₁)R(r₂)");
        // scal(q₁q₂) = c₁c₂(1 − r₁·r₂) with c = q₀.
        let (c1, c2) = (q1.scalar(), q2.scalar());
        assert!(
            (q.scalar() - c1 * c2 * (1.0 - r1.dot(r2))).abs() < 1e-15,
            "scalar part"
        );
    }
    // Singular: r₁·r₂ = 1 (two quarter turns about x make a half turn).
    assert_eq!(rodrigues_compose(DVec3::X, DVec3::X), None);
    assert_eq!(
        rodrigues_compose(DVec3::new(f64::NAN, 0.0, 0.0), DVec3::X),
        None
    );
    assert_eq!(
        rodrigues_compose(DVec3::ZERO, DVec3::Y),
        Some(DVec3::Y),
        "identity is neutral"
    );
}

#[test]
fn negative_printed_composition_denominator_fails() {
    let r1 = DVec3::new(0.3, 0.2, -0.1);
    let r2 = DVec3::new(0.5, -0.4, 0.6);
    let printed = (r1 + r2 + r1.cross(r2)) / (1.0 + r1.dot(r2));
    let exact = (UnitQuat::from_rodrigues(r1).unwrap() * UnitQuat::from_rodrigues(r2).unwrap())
        .to_rodrigues()
        .unwrap();
    assert!(
        (printed - exact).length() > 1e-2,
        "printed 1 + r₁·r₂ is wrong"
    );
    assert!(
        (rodrigues_compose(r1, r2).unwrap() - exact).length() < 1e-15,
        "1 − r₁·r₂ is right"
    );
}

// ---------------------------------------------------------------------------------------------
// Item 18: Euler parameters.

#[test]
fn euler_parameters() {
    let q = qa(DVec3::Z, FRAC_PI_4);
    let e = q.to_euler_parameters();
    let golden = [
        (2.0 + SQRT_2).sqrt() / 2.0,
        0.0,
        0.0,
        (2.0 - SQRT_2).sqrt() / 2.0,
    ];
    for i in 0..4 {
        assert!(
            (e[i] - golden[i]).abs() < 1e-16,
            "golden (cos π/8, 0, 0, sin π/8)"
        );
    }
    assert!(
        (golden[0] - FRAC_PI_8.cos()).abs() < 1e-16,
        "√(2 + √2)/2 = cos π/8"
    );
    // The m = 0 inverse of §4.4 (with the division by q₀ and the corrected q₃ sign) returns Q.
    assert!(
        quat_err_pm(q0_only_inverse(q.to_rotation_matrix()), q) < 1e-16,
        "Euler inverse"
    );
    // The book's inverse (no division by q₀, q₃ sign flipped) does not.
    let m = q.to_rotation_matrix();
    let book_q3 = (entry(m, 0, 1) - entry(m, 1, 0)) / 4.0;
    assert!(
        (book_q3 - golden[3]).abs() > 0.1,
        "printed inverse q₃ is wrong"
    );

    let mut rng = Rng::new(14);
    for _ in 0..TRIALS {
        let q = rng.quat();
        let e = q.to_euler_parameters();
        assert!(e[0] >= 0.0, "q₀ ≥ 0");
        assert_eq!(e, (-q).to_euler_parameters(), "independent of sign");
        let back = UnitQuat::from_euler_parameters(e).unwrap();
        assert!(quat_err_pm(back, q) < 4e-16, "round trip");
        let (axis, angle) = q.to_axis_angle();
        let (s, c) = (0.5 * angle).sin_cos();
        assert!((e[0] - c).abs() < 1e-15, "q₀ = cos(φ/2)");
        assert!(
            (DVec3::new(e[1], e[2], e[3]) - axis * s).length() < 1e-15,
            "q = sin(φ/2)n"
        );
    }
    assert!(matches!(
        UnitQuat::from_euler_parameters([1.0, 1.0, 0.0, 0.0]),
        Err(RotationError::NotUnit { norm }) if (norm - SQRT_2).abs() < 1e-15
    ));
    assert_eq!(
        UnitQuat::from_euler_parameters([f64::NAN, 0.0, 0.0, 0.0]),
        Err(RotationError::NonFinite)
    );
    let kept = UnitQuat::from_euler_parameters([-1.0, 0.0, 0.0, 0.0]).unwrap();
    assert_eq!(kept.scalar(), -1.0, "sign kept");
}

// ---------------------------------------------------------------------------------------------
// Item 24: exp and log.

#[test]
fn exp_log_identities() {
    let mut rng = Rng::new(15);
    for _ in 0..TRIALS {
        let q = rng.quat();
        let l = q.log_pure();
        assert!(l.length() <= PI, "|log q| ≤ π");
        let back = UnitQuat::exp_pure(l);
        assert!(
            (back.as_dquat() - q.as_dquat()).length() < 1e-15,
            "exp(log q) = q"
        );
        let canon = if q.scalar() < 0.0 { -q } else { q };
        assert!(
            canon.log_pure().length() <= FRAC_PI_2,
            "|log q| ≤ π/2 for q₀ ≥ 0"
        );

        let v = rng.unit3() * rng.range(0.0, PI - 1e-6);
        let lv = UnitQuat::exp_pure(v).log_pure();
        assert!(
            (lv - v).length() < 1e-9 * (1.0 + 1.0 / (PI - v.length())),
            "log(exp v) = v"
        );

        let w = rng.unit3() * rng.range(1e-6, 6.0);
        let lhs = UnitQuat::exp_pure(0.5 * w).to_rotation_matrix();
        assert!(mat_err(lhs, exp_skew(w)) < 1e-14, "R(exp(w/2)) = exp(K(w))");
    }
    for eps in [1e-3_f64, 1e-8] {
        for _ in 0..50 {
            let n = rng.unit3();
            let (s, c) = eps.sin_cos();
            let q = UnitQuat::from_wxyz([c, s * n.x, s * n.y, s * n.z]).unwrap();
            let l = q.log_pure();
            let rel = (l - n * eps).length() / eps;
            assert!(
                rel < 1e-12,
                "log near identity, ε = {eps}: relative {rel:e}"
            );
        }
    }
}
