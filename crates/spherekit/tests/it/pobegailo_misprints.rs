// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The printed forms of Pobegailo (2019) that `docs/derivations.md` corrects, each shown to fail
//! the property the corrected form (used by the library) satisfies. The w₂,₂ and (8.21)/(9.20)
//! cases are in `pobegailo_s2.rs` / `pobegailo_s3.rs`.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_possible_truncation,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::PI;

use spherekit::glam::{DQuat, DVec3, DVec4};
use spherekit::{
    ArcBlend, CircleArc, CornerBlend, Curve, Manifold, S2Point, Side, SmoothingPolynomials,
    UnitQuat,
};

fn p(x: f64, y: f64, z: f64) -> S2Point {
    S2Point::try_new(DVec3::new(x, y, z)).unwrap()
}

fn walk() -> Vec<S2Point> {
    vec![
        p(1.0, 0.0, 0.3),
        p(0.6, 0.8, 0.4),
        p(-0.2, 1.0, 0.1),
        p(-0.9, 0.3, -0.2),
        p(-0.7, -0.6, 0.0),
        p(-0.1, -0.9, 0.5),
    ]
}

/// (8.12): θ = arctan(|p₁ × p₂| / p₁·p₂) is wrong for obtuse angles; atan2 is right.
#[test]
fn printed_arctan_angle_fails_for_obtuse_edges() {
    let (a, b) = (S2Point::X, p(-1.0, 1.0, 0.0)); // 135°
    let (cross, dot) = (
        a.as_dvec3().cross(b.as_dvec3()).length(),
        a.as_dvec3().dot(b.as_dvec3()),
    );
    let printed = (cross / dot).atan();
    assert!((printed + PI / 4.0).abs() < 1e-15, "printed gives −45°");
    assert!(
        (cross.atan2(dot) - 3.0 * PI / 4.0).abs() < 1e-15,
        "atan2 gives 135°"
    );
    // The corner blend's first edge (fraction ¼ consumed) lasts ¾ of 135° at unit speed.
    let c = CornerBlend::try_new(vec![a, b, S2Point::Z], 2, 0.25).unwrap();
    assert!(
        (c.knots()[1] - 0.75 * 3.0 * PI / 4.0).abs() < 1e-15,
        "edge angle from atan2"
    );
}

/// §7.10 prints the knot recurrence shifted by one index (`docs/derivations.md#pobegailo-knots`),
/// `Δ_i = (ψ_i/φ_i)·Δ_{i−1}`; Algorithm 8.1's `Δ_i = (ψ_{i−1}/φ_{i−1})·Δ_{i−1}` is C¹ (and Cⁿ).
#[test]
fn printed_knot_recurrence_breaks_continuity() {
    let c = ArcBlend::try_new(walk(), 2).unwrap();
    let (k, circles) = (c.knots(), c.circles());
    let (d0, d1) = (k[1] - k[0], k[2] - k[1]);
    // u-velocities of the two pieces meeting at t₁ (independent of the knots).
    let left_u = c.jet_at(k[1], Side::Left).velocity * d0;
    let right_u = c.jet_at(k[1], Side::Right).velocity * d1;
    assert!(
        (left_u / d0 - right_u / d1).length() < 1e-14,
        "Algorithm 8.1 knots: C¹"
    );
    let printed_d1 = d0 * circles[1].second_angle() / circles[1].first_angle();
    let jump = (left_u / d0 - right_u / printed_d1).length() / (left_u / d0).length();
    assert!(jump > 1e-2, "printed knots: velocity jump {jump}");
}

/// §7.10's prose calls the backward circle (through `p_{i−1}, p_i, p_{i+1}`) the "first" one
/// (`docs/derivations.md#pobegailo-7-10-order`); with it under w₁,ₙ the segment ends following the
/// wrong circle and the joint is not even C¹.
#[test]
fn printed_circle_order_breaks_continuity() {
    let pts = walk();
    let c = ArcBlend::try_new(pts.clone(), 2).unwrap();
    let (k, circles) = (c.knots(), c.circles());
    let w = SmoothingPolynomials::try_new(2).unwrap();
    let i = 2;
    let (fwd, back) = (&circles[i], &circles[i - 1]);
    // Misreading: backward circle (angle ψ_{i−1}) with w₁, forward circle (φ_i) with w₂.
    let wrong = |u: f64| {
        back.rotate(
            w.w1(u) * back.second_angle(),
            &fwd.rotate(w.w2(u) * fwd.first_angle(), &pts[i]),
        )
    };
    let right = |u: f64| c.eval(k[i] + u * (k[i + 1] - k[i]));
    assert!(
        wrong(1.0).dist(&pts[i + 1]) < 1e-14,
        "the misreading still interpolates"
    );
    let h = 1e-6;
    let width = k[i + 1] - k[i];
    let v_wrong = (wrong(1.0).as_dvec3() - wrong(1.0 - h).as_dvec3()) / (h * width);
    let v_right = (right(1.0).as_dvec3() - right(1.0 - h).as_dvec3()) / (h * width);
    let v_next = c.jet_at(k[i + 1], Side::Right).velocity;
    assert!(
        (v_right - v_next).length() < 1e-5 * v_next.length(),
        "library: C¹"
    );
    assert!(
        (v_wrong - v_next).length() > 1e-2 * v_next.length(),
        "misreading: velocity jump"
    );
}

/// The ternary product `X(P, Q, R)` with the corrected sign of (2.13)
/// (`docs/derivations.md#pobegailo-2-13`).
fn ternary(p: DQuat, q: DQuat, r: DQuat) -> DQuat {
    let (pv, qv, rv) = (p.xyz(), q.xyz(), r.xyz());
    let v = -p.w * qv.cross(rv) - q.w * rv.cross(pv) - r.w * pv.cross(qv);
    DQuat::from_xyzw(v.x, v.y, v.z, pv.dot(qv.cross(rv)))
}

fn rot(a: DVec3, theta: f64, v: DVec3) -> DVec3 {
    let (s, c) = theta.sin_cos();
    a * a.dot(v) + (v - a * a.dot(v)) * c + a.cross(v) * s
}

/// Procedure 9.4 as printed applies circle i−1's rotation in circle i's frame `N_i`
/// (`docs/derivations.md#pobegailo-9-4`): it interpolates but has a velocity jump at t₁; the
/// frame-consistent form (the library) is C².
#[test]
fn printed_procedure_9_4_is_only_c0() {
    let book = ternary(
        DQuat::from_xyzw(2.0, -1.0, 4.0, 1.0),
        DQuat::from_xyzw(-2.0, 3.0, 1.0, 3.0),
        DQuat::from_xyzw(1.0, -2.0, 1.0, 0.0),
    );
    assert!(
        (DVec4::from(book) - DVec4::new(16.0, 3.0, -10.0, 11.0)).length() < 1e-13,
        "book's X example"
    );
    let keys: Vec<UnitQuat> = [
        [1.0, 0.0, 0.0, 0.0],
        [0.8, 0.5, 0.3, 0.1],
        [0.4, 0.7, 0.5, 0.3],
        [0.1, 0.6, 0.8, 0.2],
        [-0.2, 0.3, 0.9, 0.5],
    ]
    .iter()
    .map(|&a| UnitQuat::from_wxyz(a).unwrap())
    .collect();
    let c = ArcBlend::try_new(keys.clone(), 2).unwrap();
    let k = c.knots();
    // Book frames N_j and S² data of triples 0 and 1.
    let frame = |j: usize| {
        let x = ternary(
            keys[j].as_dquat(),
            keys[j + 1].as_dquat(),
            keys[j + 2].as_dquat(),
        );
        let h = x.normalize();
        let m = |q: UnitQuat| S2Point::try_new((q.as_dquat() * h.conjugate()).xyz()).unwrap();
        let circle = CircleArc::through(&m(keys[j]), &m(keys[j + 1]), &m(keys[j + 2])).unwrap();
        (h, circle)
    };
    let ((_, c0), (h1, c1)) = (frame(0), frame(1));
    let w = SmoothingPolynomials::try_new(2).unwrap();
    let r1 = (keys[1].as_dquat() * h1.conjugate()).xyz();
    let literal = |u: f64| {
        let v = rot(
            c1.axis(),
            w.w1(u) * c1.first_angle(),
            rot(c0.axis(), w.w2(u) * c0.second_angle(), r1),
        );
        DVec4::from(DQuat::from_xyzw(v.x, v.y, v.z, 0.0) * h1)
    };
    let width = k[2] - k[1];
    assert!(
        (literal(0.0) - keys[1].to_vector()).length() < 1e-14,
        "interpolates p1"
    );
    assert!(
        (literal(1.0) - keys[2].to_vector()).length() < 1e-14,
        "interpolates p2"
    );
    let h = 1e-7;
    let v_literal = (literal(h) - literal(0.0)) / (h * width);
    let v_left = c.jet_at(k[1], Side::Left).velocity;
    let v_right = c.jet_at(k[1], Side::Right).velocity;
    assert!((v_left - v_right).length() < 1e-13, "library: C¹ at t₁");
    let jump = (v_literal - v_left).length() / v_left.length();
    assert!(jump > 1e-2, "literal Procedure 9.4: velocity jump {jump}");
}

/// (2.13) as printed has `+q₀(r × p)`: it misses the book's own example and is not
/// orthogonal to its factors; the corrected (all-minus) form, the 4×4 determinant's expansion,
/// is both.
#[test]
fn printed_ternary_product_sign_fails() {
    let printed = |p: DQuat, q: DQuat, r: DQuat| {
        let (pv, qv, rv) = (p.xyz(), q.xyz(), r.xyz());
        let v = -p.w * qv.cross(rv) + q.w * rv.cross(pv) - r.w * pv.cross(qv);
        DQuat::from_xyzw(v.x, v.y, v.z, pv.dot(qv.cross(rv)))
    };
    let (p, q, r) = (
        DQuat::from_xyzw(2.0, -1.0, 4.0, 1.0),
        DQuat::from_xyzw(-2.0, 3.0, 1.0, 3.0),
        DQuat::from_xyzw(1.0, -2.0, 1.0, 0.0),
    );
    let wrong = DVec4::from(printed(p, q, r));
    assert!(
        (wrong - DVec4::new(-26.0, -9.0, 8.0, 11.0)).length() < 1e-13,
        "{wrong}"
    );
    let right = DVec4::from(ternary(p, q, r));
    for f in [p, q, r] {
        assert!(
            right.dot(DVec4::from(f)).abs() < 1e-12,
            "corrected ⟂ factors"
        );
    }
    assert!(
        wrong.dot(DVec4::from(q)).abs() > 1.0,
        "printed is not orthogonal"
    );
}
