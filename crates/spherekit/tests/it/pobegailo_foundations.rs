// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The foundation primitives of Pobegailo (2019) as public API, each with the book's worked
//! examples: quaternion algebra of chapter 2 (§2.3 product, §2.7 inverse, §2.8 quotient of
//! orthogonal quaternions — with its misprinted example failing as printed —, §2.9 ternary
//! product, §2.11 orthonormal complement), the 4×4 multiplication matrices (§2.1, §6.5), the
//! so(3) exponential and the derivative of `R(n, ωt)` (§4.6), circles as planar sections of S²
//! and S³ (§5.3, §6.3), and the Bernstein examples of §7.2–7.4.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_4, PI};

use spherekit::glam::{DMat3, DMat4, DQuat, DVec3, DVec4};
use spherekit::quaternion::{
    left_matrix, orthogonal_complement, orthogonal_quotient, right_matrix, ternary_product,
};
use spherekit::{
    PlaneSection, SplineError, UnitQuat, bernstein, exp_so3, rotation_derivative, skew,
};

use crate::support::Rng;

/// The book's scalar-first quaternion `q₀ + q₁i + q₂j + q₃k`.
fn h(q0: f64, q1: f64, q2: f64, q3: f64) -> DQuat {
    DQuat::from_xyzw(q1, q2, q3, q0)
}

fn random_quat(rng: &mut Rng) -> DQuat {
    h(rng.normal(), rng.normal(), rng.normal(), rng.normal())
}

fn close(a: DQuat, b: DQuat, tol: f64) -> bool {
    (DVec4::from(a) - DVec4::from(b)).length() < tol
}

/// §2.3: (1 + i + 2j + 3k)(5 − 4i + 3j − k) = 6 − 10i + 2j + 25k; §2.7:
/// (1 − 4i + 3j − k)⁻¹ = (1 + 4i − 3j + k)/27. Both through the library's multiplication
/// matrices.
#[test]
fn section_2_product_and_inverse_examples() {
    let (p, q) = (h(1.0, 1.0, 2.0, 3.0), h(5.0, -4.0, 3.0, -1.0));
    assert_eq!(p * q, h(6.0, -10.0, 2.0, 25.0));
    assert_eq!(
        left_matrix(p) * DVec4::from(q),
        DVec4::from(h(6.0, -10.0, 2.0, 25.0))
    );
    assert_eq!(
        right_matrix(q) * DVec4::from(p),
        DVec4::from(h(6.0, -10.0, 2.0, 25.0))
    );
    let r = h(1.0, -4.0, 3.0, -1.0);
    // (2.9) Q⁻¹ = Q*/N(Q) (glam's `inverse` assumes a unit quaternion).
    let inv = h(1.0, 4.0, -3.0, 1.0) * (1.0 / 27.0);
    assert!(close(
        r.conjugate() * (1.0 / r.length_squared()),
        inv,
        1e-16
    ));
    let one = left_matrix(r) * DVec4::from(inv);
    assert!((one - DVec4::W).length() < 1e-15, "Q Q⁻¹ = 1");
    // N(Q) = Q Q*: the matrix of Q times that of Q* is N(Q)·I.
    let n = left_matrix(r) * left_matrix(r.conjugate());
    assert!(n.abs_diff_eq(DMat4::IDENTITY * 27.0, 1e-13));
}

/// §2.8, (2.12): for orthogonal P, Q the quotient R = PQ⁻¹ is pure and P = RQ. The book's example
/// P = 1 + 2i − j + 4k, Q = 3 − 2i + 3j + k has R = (21i + 4j + 7k)/23.
#[test]
fn orthogonal_quotient_of_section_2_8() {
    let (p, q) = (h(1.0, 2.0, -1.0, 4.0), h(3.0, -2.0, 3.0, 1.0));
    assert_eq!(DVec4::from(p).dot(DVec4::from(q)), 0.0, "orthogonal");
    let r = orthogonal_quotient(p, q).unwrap();
    assert!((r - DVec3::new(21.0, 4.0, 7.0) / 23.0).length() < 1e-15);
    let rq = h(0.0, r.x, r.y, r.z) * q;
    assert!(close(rq, p, 1e-14), "P = R Q");
    assert!(
        close(
            p * (q.conjugate() * (1.0 / q.length_squared())),
            h(0.0, r.x, r.y, r.z),
            1e-15
        ),
        "R = P Q⁻¹"
    );
    // (2.16): unit orthogonal P, Q give a unit n with P = n Q.
    let mut rng = Rng::new(5);
    for _ in 0..50 {
        let q = random_quat(&mut rng).normalize();
        let x = random_quat(&mut rng);
        let p = (DVec4::from(x) - DVec4::from(q) * DVec4::from(x).dot(DVec4::from(q))).normalize();
        let p = DQuat::from_vec4(p);
        let n = orthogonal_quotient(p, q).unwrap();
        assert!((n.length() - 1.0).abs() < 1e-14, "unit n");
        assert!(close(h(0.0, n.x, n.y, n.z) * q, p, 1e-14), "P = n Q");
    }
    assert!(orthogonal_quotient(p, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).is_none());
}

/// Failing as printed: §2.8 prints R = PQ⁻¹ = (−9i − 10j + 18k)/23 for the example above. It is
/// not PQ⁻¹ and R·Q misses P (`docs/derivations.md#pobegailo-2-8`).
#[test]
fn printed_section_2_8_quotient_fails() {
    let (p, q) = (h(1.0, 2.0, -1.0, 4.0), h(3.0, -2.0, 3.0, 1.0));
    let printed = h(0.0, -9.0, -10.0, 18.0) * (1.0 / 23.0);
    let miss = DVec4::from(printed * q - p).length();
    assert!(miss > 1.0, "printed R·Q misses P by {miss}");
    let right = orthogonal_quotient(p, q).unwrap();
    assert!(
        (DVec4::from(printed).truncate() - right).length() > 0.5,
        "printed ≠ corrected"
    );
}

/// §2.9, §2.11: the ternary product — the book's example, orthogonality to the factors,
/// antisymmetry, the Gram determinant, and a unit complement of an orthonormal triple.
#[test]
fn ternary_product_and_orthogonal_complement() {
    let (p, q, r) = (
        h(1.0, 2.0, -1.0, 4.0),
        h(3.0, -2.0, 3.0, 1.0),
        h(0.0, 1.0, -2.0, 1.0),
    );
    assert_eq!(ternary_product(p, q, r), h(11.0, 16.0, 3.0, -10.0));
    let mut rng = Rng::new(9);
    for _ in 0..50 {
        let (a, b, c) = (
            random_quat(&mut rng),
            random_quat(&mut rng),
            random_quat(&mut rng),
        );
        let x = ternary_product(a, b, c);
        let scale = DVec4::from(a).length() * DVec4::from(b).length() * DVec4::from(c).length();
        for f in [a, b, c] {
            assert!(
                DVec4::from(x).dot(DVec4::from(f)).abs() < 1e-13 * scale,
                "⊥ factor"
            );
        }
        assert!(
            close(ternary_product(b, a, c), -x, 1e-13 * scale),
            "alternating"
        );
        assert!(close(ternary_product(b, c, a), x, 1e-13 * scale), "cyclic");
        // |X|² = det of the Gram matrix of a, b, c.
        let (va, vb, vc) = (DVec4::from(a), DVec4::from(b), DVec4::from(c));
        let g = DMat3::from_cols(
            DVec3::new(va.dot(va), va.dot(vb), va.dot(vc)),
            DVec3::new(vb.dot(va), vb.dot(vb), vb.dot(vc)),
            DVec3::new(vc.dot(va), vc.dot(vb), vc.dot(vc)),
        );
        let gram = g.determinant();
        assert!(
            (x.length_squared() - gram).abs() < 1e-11 * gram.abs().max(1.0),
            "Gram"
        );
        // The complement of an orthonormal triple completes an orthonormal basis.
        let e = DMat4::from_cols(va, vb, vc, DVec4::X);
        let (o1, o2, o3) = gram_schmidt(e);
        let hq = orthogonal_complement(o1, o2, o3).unwrap();
        assert!((hq.length() - 1.0).abs() < 1e-14, "unit");
        assert!(
            close(hq, ternary_product(o1, o2, o3), 1e-14),
            "already unit for orthonormal"
        );
    }
    // Dependent factors have no complement.
    assert!(orthogonal_complement(p, q, p * 2.0 - q).is_none());
}

fn gram_schmidt(m: DMat4) -> (DQuat, DQuat, DQuat) {
    let a = m.x_axis.normalize();
    let b = (m.y_axis - a * m.y_axis.dot(a)).normalize();
    let c = (m.z_axis - a * m.z_axis.dot(a) - b * m.z_axis.dot(b)).normalize();
    (
        DQuat::from_vec4(a),
        DQuat::from_vec4(b),
        DQuat::from_vec4(c),
    )
}

/// §2.1, §6.5: the right multiplication matrix is the book's matrix (rows acting on row vectors
/// in scalar-first order), transposed and reordered; both matrices are homomorphisms (anti- for
/// the right one), orthogonal up to N(q), with det N(q)², and every orbit of a unit right or left
/// multiplication is a great circle.
#[test]
fn multiplication_matrices_of_section_6_5() {
    let r = h(0.5, -1.0, 2.0, 0.25);
    let (r0, r1, r2, r3) = (0.5, -1.0, 2.0, 0.25);
    // The book's M_R(r), rows in (q₀, q₁, q₂, q₃) order: p_row · M = p r.
    let book = [
        [r0, r1, r2, r3],
        [-r1, r0, -r3, r2],
        [-r2, r3, r0, -r1],
        [-r3, -r2, r1, r0],
    ];
    let ours = right_matrix(r);
    // index of the book's coordinate k in glam's xyzw order.
    let at = [3usize, 0, 1, 2];
    for (i, row) in book.iter().enumerate() {
        for (j, &v) in row.iter().enumerate() {
            // Book: out_j = Σ_i p_i M[i][j]; ours: out[at j] = Σ ours[at j][at i] p[at i].
            assert_eq!(ours.col(at[i])[at[j]], v, "M_R entry ({i}, {j})");
        }
    }
    let mut rng = Rng::new(13);
    for _ in 0..30 {
        let (a, b, p) = (
            random_quat(&mut rng),
            random_quat(&mut rng),
            random_quat(&mut rng),
        );
        assert!(
            (left_matrix(a * b) - left_matrix(a) * left_matrix(b)).abs_diff_eq(DMat4::ZERO, 1e-12)
        );
        assert!(
            (right_matrix(a * b) - right_matrix(b) * right_matrix(a))
                .abs_diff_eq(DMat4::ZERO, 1e-12)
        );
        let n = a.length_squared();
        for m in [left_matrix(a), right_matrix(a)] {
            assert!((m.transpose() * m).abs_diff_eq(DMat4::IDENTITY * n, 1e-12 * n));
            assert!((m.determinant() - n * n).abs() < 1e-11 * n * n);
        }
        // Orbits θ ↦ p·e_n(θ), e_n(θ)·p of a unit p are great circles: in span{p, p·n}.
        let (pu, axis) = (p.normalize(), rng.unit3());
        for theta in [0.3f64, 1.7, 3.0] {
            let e = DQuat::from_xyzw(
                axis.x * theta.sin(),
                axis.y * theta.sin(),
                axis.z * theta.sin(),
                theta.cos(),
            );
            let nq = DQuat::from_xyzw(axis.x, axis.y, axis.z, 0.0);
            let orbit = right_matrix(e) * DVec4::from(pu);
            let plane = DVec4::from(pu) * theta.cos() + DVec4::from(pu * nq) * theta.sin();
            assert!(
                (orbit - plane).length() < 1e-14,
                "right orbit is a great circle"
            );
            let orbit = left_matrix(e) * DVec4::from(pu);
            let plane = DVec4::from(pu) * theta.cos() + DVec4::from(nq * pu) * theta.sin();
            assert!(
                (orbit - plane).length() < 1e-14,
                "left orbit is a great circle"
            );
        }
    }
}

/// §4.6: exp(φK(n)) = R(n, φ), the book's example R(e₃, π/4) with l = (0, 0, π/4) and its matrix
/// of §3.4, the power identities of K, near 0 and near a half turn, and d/dt R(n, ωt) =
/// ωK(n)R(n, ωt) against finite differences.
#[test]
fn so3_exponential_and_the_derivative_of_r_n_omega_t() {
    let r = exp_so3(DVec3::new(0.0, 0.0, FRAC_PI_4)).unwrap();
    let book = DMat3::from_cols(
        DVec3::new(FRAC_1_SQRT_2, FRAC_1_SQRT_2, 0.0),
        DVec3::new(-FRAC_1_SQRT_2, FRAC_1_SQRT_2, 0.0),
        DVec3::Z,
    );
    assert!(r.abs_diff_eq(book, 1e-15), "{r}");
    let mut rng = Rng::new(17);
    for angle in [1e-12, 1e-5, 1e-4, 0.3, 2.0, PI - 1e-9, PI] {
        let n = rng.unit3();
        let k = skew(n);
        let m = DMat3::from_cols(n * n.x, n * n.y, n * n.z);
        // K² = −(I − M), K³ = −K, KM = 0.
        assert!((k * k).abs_diff_eq(-(DMat3::IDENTITY - m), 1e-15));
        assert!((k * k * k).abs_diff_eq(-k, 1e-15));
        assert!((k * m).abs_diff_eq(DMat3::ZERO, 1e-15));
        let closed = DMat3::IDENTITY * angle.cos() + k * angle.sin() + m * (1.0 - angle.cos());
        let e = exp_so3(n * angle).unwrap();
        assert!(e.abs_diff_eq(closed, 2e-16 * 8.0), "exp at {angle}");
        let q = UnitQuat::from_rotation_vector(n * angle)
            .unwrap()
            .to_rotation_matrix();
        assert!(e.abs_diff_eq(q, 1e-15), "matches the quaternion at {angle}");
    }
    let (n, omega) = (DVec3::new(1.0, -2.0, 0.5), 1.7);
    let (_, d0) = rotation_derivative(n, omega, 0.0).unwrap();
    assert!(d0.abs_diff_eq(skew(n.normalize()) * omega, 1e-15), "(4.27)");
    for t in [-0.4, 0.2, 1.3] {
        let (r, d) = rotation_derivative(n, omega, t).unwrap();
        let step = 1e-6;
        let rot = |s: f64| exp_so3(n.normalize() * (omega * s)).unwrap();
        let fd = (rot(t + step) - rot(t - step)) * (0.5 / step);
        assert!(d.abs_diff_eq(fd, 1e-9), "finite differences at {t}");
        assert!(r.abs_diff_eq(rot(t), 1e-15));
    }
    assert!(rotation_derivative(DVec3::ZERO, 1.0, 0.0).is_none());
    assert!(rotation_derivative(DVec3::X, f64::NAN, 0.0).is_none());
}

/// §5.3: a plane n·p = d cuts S² in the circle of centre d·n and radius √(1 − d²). The book's
/// example (the sphere of radius √10 cut by z = 1: centre (0, 0, 1), radius 3) scaled to the unit
/// sphere; the frame (5.6) where it is defined and where it is not (n = ±e₃); a tangent plane;
/// a plane that misses.
#[test]
fn s2_planar_sections() {
    let r = 10f64.sqrt();
    let c = PlaneSection::s2(DVec3::Z, 1.0 / r).unwrap();
    assert!(
        (c.center() * r - DVec3::Z).length() < 1e-15,
        "centre (0, 0, 1)"
    );
    assert!((c.radius() * r - 3.0).abs() < 1e-14, "radius 3");
    let mut rng = Rng::new(19);
    for _ in 0..30 {
        let (n, d) = (rng.vec3(2.0), rng.range(-0.99, 0.99));
        let c = PlaneSection::s2(n, d * n.length()).unwrap();
        assert!((c.normal() - n.normalize()).length() < 1e-14, "normal");
        for theta in [0.0, 1.0, 2.5, 5.0] {
            let p = c.point(theta);
            assert!((p.length() - 1.0).abs() < 1e-14, "on the sphere");
            assert!((p.dot(n.normalize()) - d).abs() < 1e-14, "on the plane");
            assert!(
                ((p - c.center()).length() - c.radius()).abs() < 1e-14,
                "radius"
            );
        }
        // The book's frame (5.6): x̃ = e₃ × n / |e₃ × n|.
        let (x, _) = c.basis();
        assert!(
            (x - DVec3::Z.cross(n).normalize()).length() < 1e-14,
            "(5.6)"
        );
    }
    for n in [DVec3::Z, -DVec3::Z] {
        let c = PlaneSection::s2(n, 0.3).unwrap();
        let (x, y) = c.basis();
        assert!(x.dot(n).abs() < 1e-16 && y.dot(n).abs() < 1e-16 && x.dot(y).abs() < 1e-16);
        assert!((c.point(1.0).length() - 1.0).abs() < 1e-15);
    }
    let great = PlaneSection::s2(DVec3::X, 0.0).unwrap();
    assert_eq!((great.center(), great.radius()), (DVec3::ZERO, 1.0));
    let touch = PlaneSection::s2(DVec3::Y, 1.0).unwrap();
    assert_eq!((touch.radius(), touch.point(2.0)), (0.0, DVec3::Y));
    let e = PlaneSection::s2(DVec3::Y, 1.0 + 1e-9).unwrap_err();
    assert!(
        matches!(e, SplineError::InvalidParameter { name: "d", .. }),
        "{e}"
    );
    let e = PlaneSection::s2(DVec3::ZERO, 0.0).unwrap_err();
    assert!(
        matches!(e, SplineError::InvalidParameter { name: "normal", .. }),
        "{e}"
    );
    assert!(PlaneSection::s2(DVec3::X, f64::NAN).is_err());
}

/// §6.3: two hyperplanes m·p = d₁, n·p = d₂ with orthonormal m, n cut S³ in the circle of radius
/// √(1 − d₁² − d₂²) (6.7), a great circle exactly when d₁ = d₂ = 0; also for normals that are
/// not orthonormal.
#[test]
fn s3_planar_sections() {
    let mut rng = Rng::new(23);
    for trial in 0..30 {
        let (m, n) = (
            DVec4::from(random_quat(&mut rng)),
            DVec4::from(random_quat(&mut rng)),
        );
        let (d1, d2) = (rng.range(-0.6, 0.6), rng.range(-0.6, 0.6));
        if trial % 2 == 0 {
            let (mh, nh) = (
                m.normalize(),
                (n - m.normalize() * n.dot(m.normalize())).normalize(),
            );
            let c = PlaneSection::s3([mh, nh], [d1, d2]).unwrap();
            assert!(
                (c.radius() - (1.0 - d1 * d1 - d2 * d2).sqrt()).abs() < 1e-14,
                "(6.7)"
            );
        }
        let c = PlaneSection::s3([m, n], [d1, d2]).unwrap();
        let (x, y) = c.basis();
        assert!(x.dot(y).abs() < 1e-14 && (x.length() - 1.0).abs() < 1e-14);
        for theta in [0.0, 0.7, 3.1, 4.4] {
            let p = c.point(theta);
            assert!((p.length() - 1.0).abs() < 1e-13, "on S³");
            assert!(
                (p.dot(m) - d1).abs() < 1e-13 && (p.dot(n) - d2).abs() < 1e-13,
                "on both"
            );
        }
    }
    let great = PlaneSection::s3([DVec4::X, DVec4::Y], [0.0, 0.0]).unwrap();
    assert_eq!(great.radius(), 1.0);
    assert_eq!(great.center(), DVec4::ZERO);
    let e = PlaneSection::s3([DVec4::X, DVec4::X * 2.0], [0.0, 0.0]).unwrap_err();
    assert!(
        matches!(
            e,
            SplineError::InvalidParameter {
                name: "normals",
                ..
            }
        ),
        "{e}"
    );
    let e = PlaneSection::s3([DVec4::X, DVec4::Y], [0.8, 0.8]).unwrap_err();
    assert!(
        matches!(e, SplineError::InvalidParameter { name: "d", .. }),
        "{e}"
    );
    assert!(PlaneSection::s3([DVec4::X, DVec4::NAN], [0.0, 0.0]).is_err());
}

/// §7.2–7.4: the derivative examples b′₂,₅ (Example 1) and b‴₃,₆ (Example 2), the integration
/// example ∫b₂,₅ = c − (1/6)((1−u)⁶ + 6(1−u)⁵u + 15(1−u)⁴u²), and the basis example
/// 1 + 2u + 3u² = b₀,₂ + 2b₁,₂ + 6b₂,₂ with its intermediate derivatives.
#[test]
fn bernstein_examples_of_sections_7_2_to_7_4() {
    for u in [0.0, 0.13, 0.5, 0.77, 1.0] {
        let v: f64 = 1.0 - u;
        let d1 = 20.0 * v.powi(3) * u - 30.0 * v * v * u * u;
        assert!(
            (bernstein::derivative(2, 5, 1, u) - d1).abs() < 1e-13,
            "Example 1 at {u}"
        );
        let five = 5.0 * (bernstein::value(1, 4, u) - bernstein::value(2, 4, u));
        assert!(
            (bernstein::derivative(2, 5, 1, u) - five).abs() < 1e-13,
            "(7.3) at {u}"
        );
        let d3 = 120.0 * v.powi(3) - 1080.0 * v * v * u + 1080.0 * v * u * u - 120.0 * u.powi(3);
        assert!(
            (bernstein::derivative(3, 6, 3, u) - d3).abs() < 1e-11,
            "Example 2 at {u}"
        );
        // The antiderivative, its constant fixed at u = 0 (where the bracket is 1).
        let bracket = v.powi(6) + 6.0 * v.powi(5) * u + 15.0 * v.powi(4) * u * u;
        assert!(
            (bernstein::integral(2, 5, u) - (1.0 - bracket) / 6.0).abs() < 1e-15,
            "∫ at {u}"
        );
        let p = 1.0 + 2.0 * u + 3.0 * u * u;
        let basis = bernstein::value(0, 2, u)
            + 2.0 * bernstein::value(1, 2, u)
            + 6.0 * bernstein::value(2, 2, u);
        assert!((p - basis).abs() < 1e-15, "basis example at {u}");
        // Partition of unity and symmetry (B1), (B2).
        let sum: f64 = (0..=7).map(|m| bernstein::value(m, 7, u)).sum();
        assert!((sum - 1.0).abs() < 1e-15);
        assert_eq!(bernstein::value(2, 7, u), bernstein::value(5, 7, 1.0 - u));
    }
    // The intermediate data of the basis example.
    let d = |m, k| bernstein::derivative(m, 2, k, 0.0);
    assert_eq!(
        [d(0, 1), d(1, 1), d(0, 2), d(1, 2), d(2, 2)],
        [-2.0, 2.0, 2.0, -4.0, 2.0]
    );
    assert_eq!(
        bernstein::coefficients(&[1.0, 2.0, 6.0]),
        vec![1.0, 2.0, 6.0]
    );
    // Derivatives against finite differences, and the corrected vanishing ranges (7.9)/(7.10):
    // b_{m,N}^{(k)}(0) = 0 for k < m, b_{m,N}^{(k)}(1) = 0 for k < N − m.
    for big_n in 1..=8 {
        for m in 0..=big_n {
            for k in 0..big_n {
                if k < m {
                    assert_eq!(bernstein::derivative(m, big_n, k, 0.0), 0.0);
                }
                if k < big_n - m {
                    assert!(bernstein::derivative(m, big_n, k, 1.0).abs() < 1e-12);
                }
                let (u, s) = (0.37, 1e-6);
                let fd = (bernstein::derivative(m, big_n, k, u + s)
                    - bernstein::derivative(m, big_n, k, u - s))
                    / (2.0 * s);
                let exact = bernstein::derivative(m, big_n, k + 1, u);
                assert!(
                    (fd - exact).abs() < 1e-5 * exact.abs().max(1.0),
                    "b^({}) {m},{big_n}",
                    k + 1
                );
            }
        }
    }
    // The printed range k ≤ min(N − (m − 1), m − 1) fails at u = 1: b′₂,₃(1) = −3.
    assert_eq!(bernstein::derivative(2, 3, 1, 1.0), -3.0);
}
