// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The point layer under hostile input: every public constructor and operation of `UnitQuat`,
//! `S2Point`, `SmPoint`, the `Manifold` trait, the rotation conversions and the angular-velocity
//! helpers, fed NaN, ±∞, 1e300, `f64::MAX`, 0, 1e-300, subnormals and antipodal pairs. Each
//! either returns a finite (and, for points, unit) result or a typed error; none panics (these
//! tests run with debug assertions on) and none returns a NaN it did not receive.
//!
//! Named edge cases first, then `arbtest` properties over random inputs of every magnitude.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::float_cmp,
    reason = "tests: a panic is the failure report; exact comparisons are intended"
)]

use std::f64::consts::{FRAC_PI_2, PI};

use arbtest::arbitrary::{Result as ArbResult, Unstructured};
use spherekit::glam::{DMat3, DQuat, DVec3, DVec4};
use spherekit::{
    Ambient, Jet, Manifold, PointError, RotationError, S2Point, ScalarJet, SmPoint, UnitQuat, VecN,
    angular_velocity_acceleration, angular_velocity_acceleration_body, exp_so3, rodrigues_compose,
    rotation_derivative, rotation_matrix_from_rodrigues, skew, slerp_jet, unflip,
    velocity_from_angular, velocity_from_angular_body,
};

/// Scalars that break naive code.
const HOSTILE: [f64; 16] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    1e154,
    0.0,
    -0.0,
    1e-300,
    -1e-300,
    5e-324,
    f64::MIN_POSITIVE,
    1.0,
    -0.5,
];

/// Vectors made of the hostile scalars: each one along every axis, splatted, and mixed.
fn hostile_vec3s() -> Vec<DVec3> {
    let mut out = Vec::new();
    for &a in &HOSTILE {
        out.push(DVec3::splat(a));
        out.push(DVec3::new(a, 0.0, 0.0));
        out.push(DVec3::new(0.0, a, 0.0));
        out.push(DVec3::new(1.0, 0.5, a));
        out.push(DVec3::new(a, -a, a));
    }
    out
}

fn hostile_vec4s() -> Vec<DVec4> {
    let mut out: Vec<DVec4> = hostile_vec3s().iter().map(|v| v.extend(0.0)).collect();
    for &a in &HOSTILE {
        out.push(DVec4::new(0.0, 0.0, 0.0, a));
        out.push(DVec4::new(a, a, -a, a));
        out.push(DVec4::new(0.25, -0.5, 0.5, a));
    }
    out
}

/// Points of each sphere, with antipodal partners, tiny and huge inputs normalised.
fn s2_points() -> Vec<S2Point> {
    let mut out = vec![S2Point::X, S2Point::Y, S2Point::Z];
    out.push(S2Point::try_new(-DVec3::X).unwrap());
    out.push(S2Point::try_new(DVec3::new(1e-300, 1e-300, 0.0)).unwrap());
    out.push(S2Point::try_new(DVec3::new(f64::MAX, f64::MAX, -f64::MAX)).unwrap());
    out.push(S2Point::try_new(DVec3::new(-1.0, 1e-17, 0.0)).unwrap());
    out
}

fn quats() -> Vec<UnitQuat> {
    let q = UnitQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5), 2.0).unwrap();
    vec![
        UnitQuat::IDENTITY,
        -UnitQuat::IDENTITY,
        q,
        -q,
        UnitQuat::from_wxyz([0.0, 1.0, 0.0, 0.0]).unwrap(),
        UnitQuat::from_wxyz([1e-300, 0.0, 0.0, 5e-324]).unwrap(),
        UnitQuat::from_wxyz([f64::MAX; 4]).unwrap(),
        UnitQuat::from_wxyz([-1.0, 1e-17, 0.0, 0.0]).unwrap(),
    ]
}

fn sn_points() -> Vec<SmPoint> {
    vec![
        SmPoint::try_new(vec![1.0, 0.0]).unwrap(),
        SmPoint::try_new(vec![-1.0, 0.0]).unwrap(),
        SmPoint::try_new(vec![0.0, 1.0, 0.0, 0.0, 0.0]).unwrap(),
        SmPoint::try_new(vec![0.0, -1.0, 0.0, 0.0, 0.0]).unwrap(),
        SmPoint::try_new(vec![1e-300, 0.0, 2e-300, 0.0]).unwrap(),
        SmPoint::try_new(vec![f64::MAX, -f64::MAX, f64::MAX, 1.0, 0.0, 0.0]).unwrap(),
    ]
}

fn assert_unit_point<P: Manifold>(p: &P, what: &str) {
    let v = p.to_vector();
    assert!(v.is_finite(), "{what}: not finite: {p:?}");
    assert!((v.length() - 1.0).abs() < 1e-12, "{what}: not unit: {p:?}");
}

fn assert_no_nan<V: Ambient>(v: &V, what: &str) {
    assert!(
        v.as_slice().iter().all(|a| !a.is_nan()),
        "{what}: NaN in {v:?}"
    );
}

fn assert_finite<V: Ambient>(v: &V, what: &str) {
    assert!(v.is_finite(), "{what}: not finite: {v:?}");
}

/// A finite proper rotation matrix.
fn assert_rotation(m: &DMat3, what: &str) {
    assert!(m.is_finite(), "{what}: not finite: {m:?}");
    let dev = (m.transpose() * *m - DMat3::IDENTITY)
        .to_cols_array()
        .iter()
        .fold(0.0_f64, |a, b| a.max(b.abs()));
    assert!(dev < 1e-12, "{what}: not orthogonal ({dev:e}): {m:?}");
    assert!((m.determinant() - 1.0).abs() < 1e-12, "{what}: det {m:?}");
}

/// Every `Manifold` operation on one pair of points, with a tangent and a parameter.
fn check_manifold_ops<P: Manifold>(p: &P, q: &P, v: &P::Vector, t: f64) {
    let d = p.dist(q);
    assert!((0.0..=PI).contains(&d), "dist {d} of {p:?}, {q:?}");
    let _ = p.is_antipodal(q);
    let l = p.log(q);
    assert_finite(&l, "log");
    match p.try_log(q) {
        Ok(l2) => assert_eq!(l2, l, "try_log = log"),
        Err(e) => {
            assert_eq!(e, PointError::Antipodal);
            assert!(p.is_antipodal(q));
        }
    }
    let e = p.exp(v);
    assert_unit_point(&e, "exp");
    match p.try_exp(v) {
        Ok(e2) => {
            assert_eq!(e2, e, "try_exp = exp");
            assert!(v.is_finite());
        }
        Err(err) => {
            assert_eq!(err, PointError::NonFinite);
            assert!(!v.is_finite());
            assert_eq!(&e, p, "exp of a non-finite tangent is self");
        }
    }
    let s = p.slerp(q, t);
    assert_unit_point(&s, "slerp");
    match p.try_slerp(q, t) {
        Ok(s2) => assert_eq!(s2, s, "try_slerp = slerp"),
        Err(PointError::NonFiniteParameter) => {
            assert!(!t.is_finite() || (t * d).abs() > 1e307, "t = {t}, θ = {d}");
            assert_eq!(&s, p, "slerp without a point is self");
        }
        Err(PointError::Antipodal) => {
            assert!(p.is_antipodal(q));
            assert_eq!(&s, p, "slerp without a point is self");
        }
        Err(err) => panic!("unexpected {err:?}"),
    }
    let pt = p.project_tangent(v);
    if v.is_finite() {
        assert_no_nan(&pt, "project_tangent of a finite vector");
    }
    let _ = P::try_from_vector(v.clone()).map(|r| assert_unit_point(&r, "try_from_vector"));
}

#[test]
fn constructors_give_unit_points_or_typed_errors() {
    for v in hostile_vec3s() {
        let expect_err = if !v.is_finite() {
            Some(PointError::NonFinite)
        } else if v.abs().max_element() < f64::MIN_POSITIVE {
            Some(PointError::ZeroLength)
        } else {
            None
        };
        match S2Point::try_new(v) {
            Ok(p) => {
                assert_eq!(expect_err, None, "{v:?}");
                assert_unit_point(&p, "S2Point::try_new");
            }
            Err(e) => assert_eq!(Some(e), expect_err, "{v:?}"),
        }
        match SmPoint::try_new(v.to_array().to_vec()) {
            Ok(p) => assert_unit_point(&p, "SmPoint::try_new"),
            Err(e) => assert_eq!(Some(e), expect_err, "{v:?}"),
        }
    }
    for v in hostile_vec4s() {
        let [x, y, z, w] = v.to_array();
        for r in [
            UnitQuat::try_new(DQuat::from_vec4(v)),
            UnitQuat::from_wxyz([w, x, y, z]),
            UnitQuat::try_from_vector(v),
        ] {
            match r {
                Ok(q) => assert_unit_point(&q, "UnitQuat constructor"),
                Err(e) => assert!(
                    matches!(e, PointError::NonFinite | PointError::ZeroLength),
                    "{v:?}: {e:?}"
                ),
            }
        }
    }
    assert_eq!(
        SmPoint::try_new(vec![f64::NAN]),
        Err(PointError::WrongDimension {
            expected: 2,
            got: 1
        })
    );
}

#[test]
fn nan_parameter_is_an_error_not_a_panic() {
    let (p, q) = (S2Point::X, S2Point::Y);
    assert_eq!(
        p.try_slerp(&q, f64::NAN),
        Err(PointError::NonFiniteParameter)
    );
    assert_eq!(p.slerp(&q, f64::NAN), p);
    let (a, b) = (UnitQuat::IDENTITY, quats()[2]);
    assert_eq!(
        a.try_slerp(&b, f64::NAN),
        Err(PointError::NonFiniteParameter)
    );
    assert_eq!(a.slerp(&b, f64::NAN), a);
    assert_eq!(b.try_powf(f64::NAN), Err(PointError::NonFiniteParameter));
    assert_eq!(b.powf(f64::NAN), UnitQuat::IDENTITY);
    let s = sn_points();
    assert_eq!(
        s[0].try_slerp(&s[2], f64::NAN),
        Err(PointError::NonFiniteParameter)
    );
    assert_eq!(s[0].slerp(&s[2], f64::NAN), s[0]);
    // The same point twice: no angle, still no NaN.
    assert_eq!(p.slerp(&p, f64::NAN), p);
    let at_rest = |point| Jet {
        point,
        velocity: DVec3::ZERO,
        acceleration: DVec3::ZERO,
    };
    for u in [
        ScalarJet::constant(f64::NAN),
        ScalarJet::param(0.5, f64::INFINITY),
        ScalarJet::param(f64::NEG_INFINITY, 1.0),
    ] {
        assert_eq!(
            slerp_jet(&at_rest(p), &at_rest(q), u).unwrap_err(),
            PointError::NonFiniteParameter
        );
    }
}

#[test]
fn infinite_or_overflowing_parameter_is_an_error_and_huge_finite_is_a_point() {
    let (p, q) = (S2Point::X, S2Point::Y);
    for t in [f64::INFINITY, f64::NEG_INFINITY, f64::MAX, f64::MIN] {
        assert_eq!(
            p.try_slerp(&q, t),
            Err(PointError::NonFiniteParameter),
            "t = {t}"
        );
        assert_eq!(p.slerp(&q, t), p);
    }
    // t·θ = 1e300·π/2 is finite: a point of the great circle through X and Y.
    let far = p.try_slerp(&q, 1e300).unwrap();
    assert_unit_point(&far, "slerp at 1e300");
    assert!(far.as_dvec3().z.abs() < 1e-15, "{far:?}");
    // Coincident points have no angle, so any finite t stays there.
    assert_eq!(p.try_slerp(&p, f64::MAX), Ok(p));
    let b = quats()[2];
    assert_unit_point(&b.try_powf(1e300).unwrap(), "powf 1e300");
    assert_unit_point(&b.try_powf(f64::MAX).unwrap(), "powf f64::MAX");
    assert_eq!(b.powf(f64::INFINITY), UnitQuat::IDENTITY);
    // |log_pure c| = 1.5: the angle 1.5·f64::MAX overflows.
    let c = UnitQuat::from_axis_angle(DVec3::X, 3.0).unwrap();
    assert_eq!(c.try_powf(f64::MAX), Err(PointError::NonFiniteParameter));
    assert_eq!(c.powf(f64::MAX), UnitQuat::IDENTITY);
    assert_eq!(
        UnitQuat::IDENTITY.try_powf(f64::MAX),
        Ok(UnitQuat::IDENTITY)
    );
}

#[test]
fn antipodal_points_are_an_error_or_a_documented_result() {
    let (x, mx) = (S2Point::X, S2Point::try_new(-DVec3::X).unwrap());
    assert_eq!(x.try_log(&mx), Err(PointError::Antipodal));
    assert_eq!(x.log(&mx), DVec3::ZERO);
    assert_eq!(x.try_slerp(&mx, 0.5), Err(PointError::Antipodal));
    assert_eq!(x.slerp(&mx, 0.5), x);
    assert!((x.dist(&mx) - PI).abs() < 1e-15);
    for q in quats() {
        assert_eq!(q.try_slerp(&-q, 0.25), Err(PointError::Antipodal));
        assert_eq!(q.slerp(&-q, 0.25), q);
        assert_eq!(q.log(&-q), DVec4::ZERO);
        // The ends are exact even for antipodal points.
        assert_eq!(q.try_slerp(&-q, 1.0), Ok(-q));
    }
    let s = sn_points();
    assert_eq!(s[2].try_log(&s[3]), Err(PointError::Antipodal));
    assert_eq!(s[2].slerp(&s[3], 0.5), s[2]);
    let a = at_rest_jet(S2Point::X);
    let b = at_rest_jet(mx);
    assert_eq!(
        slerp_jet(&a, &b, ScalarJet::param(0.5, 1.0)).unwrap_err(),
        PointError::Antipodal
    );
}

fn at_rest_jet(point: S2Point) -> Jet<S2Point> {
    Jet {
        point,
        velocity: DVec3::ZERO,
        acceleration: DVec3::ZERO,
    }
}

#[test]
fn nan_tangent_is_an_error_not_a_panic() {
    for p in s2_points() {
        for v in hostile_vec3s() {
            if v.is_finite() {
                assert_unit_point(&p.try_exp(&v).unwrap(), "exp of a finite tangent");
            } else {
                assert_eq!(p.try_exp(&v), Err(PointError::NonFinite));
                assert_eq!(p.exp(&v), p);
            }
        }
    }
}

/// Reference values of `cos x`, `sin x` for the `f64` values `x` below, computed with 5000-bit
/// arithmetic (Python's `mpmath`, `mp.prec = 5000; cos(mpf(x)), sin(mpf(x))`), independently
/// of the sine and cosine the crate calls. A reduction modulo the `f64` value of 2π (`fmod`,
/// `rem_euclid`) gives, for 5e299, `cos = −0.935…, sin = 0.354…` instead: wrong in every digit.
const COS_SIN_HALF_1E300: (f64, f64) = (0.460_767_776_674_134_93, -0.887_520_735_520_457_8);
const COS_SIN_1E300: (f64, f64) = (-0.575_386_111_957_549_1, -0.817_881_912_115_908_5);
/// `x = 5·2⁹⁸⁹`, half the length of the rotation vector `(3·2⁹⁹⁰, 4·2⁹⁹⁰, 0)`.
const COS_SIN_5_2_989: (f64, f64) = (0.077_013_044_872_153_75, 0.997_030_085_262_987_2);

#[test]
fn huge_rotation_vector_reduces_the_angle() {
    // 1e300 rad about x: the quaternion cos(5e299) + sin(5e299)·i.
    let q = UnitQuat::from_rotation_vector(DVec3::new(1e300, 0.0, 0.0)).unwrap();
    let (c, s) = COS_SIN_HALF_1E300;
    let expected = UnitQuat::from_wxyz([c, s, 0.0, 0.0]).unwrap();
    assert!(q.dist(&expected) < 1e-15, "{q:?} vs {expected:?}");
    // The same rotation from the axis and the angle, and from the half rotation vector.
    let a = UnitQuat::from_axis_angle(DVec3::X, 1e300).unwrap();
    assert!(a.dist(&expected) < 1e-15, "{a:?}");
    let h = UnitQuat::exp_pure(DVec3::new(5e299, 0.0, 0.0));
    assert!(h.dist(&expected) < 1e-15, "{h:?}");
    // A rotation vector whose squared length overflows: the length 5·2⁹⁹⁰ is still exact.
    let w = DVec3::new(3.0, 4.0, 0.0) * 2f64.powi(990);
    let q = UnitQuat::from_rotation_vector(w).unwrap();
    let (c, s) = COS_SIN_5_2_989;
    let expected = UnitQuat::from_wxyz([c, 0.6 * s, 0.8 * s, 0.0]).unwrap();
    assert!(q.dist(&expected) < 1e-15, "{q:?} vs {expected:?}");
    // The rotation matrix of so(3) agrees.
    let m = exp_so3(w).unwrap();
    assert_rotation(&m, "exp_so3 of a huge vector");
    assert!(m.abs_diff_eq(q.to_rotation_matrix(), 1e-14), "{m:?}");
    // A negative vector is the inverse rotation.
    let qi = UnitQuat::from_rotation_vector(-w).unwrap();
    assert!(qi.dist(&q.inverse()) < 1e-15);
    // Beyond f64::MAX in length: no NaN, still about the right axis.
    let q = UnitQuat::exp_pure(DVec3::new(f64::MAX, f64::MAX, 0.0));
    assert_unit_point(&q, "exp_pure beyond f64::MAX");
    assert!((q.vector().x - q.vector().y).abs() < 1e-15 && q.vector().z == 0.0);
}

#[test]
fn huge_tangent_follows_the_great_circle_to_the_reduced_angle() {
    // 1e300 rad along the great circle from X towards Y.
    let p = S2Point::X.exp(&DVec3::new(0.0, 1e300, 0.0));
    let (c, s) = COS_SIN_1E300;
    assert!(
        (p.as_dvec3() - DVec3::new(c, s, 0.0)).length() < 1e-15,
        "{p:?}"
    );
    // Beyond f64::MAX in length: a finite point of the same great circle.
    for p in s2_points() {
        let v = p.project_tangent(&DVec3::new(f64::MAX, -f64::MAX, f64::MAX));
        let e = p.exp(&v);
        assert_unit_point(&e, "exp beyond f64::MAX");
    }
    let s = sn_points();
    let v = VecN::new(vec![0.0, f64::MAX, f64::MAX, f64::MAX, f64::MAX, f64::MAX]);
    assert_unit_point(&s[0].exp(&v), "S^m exp beyond f64::MAX");
}

#[test]
fn from_axis_angle_names_the_angle() {
    for angle in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = UnitQuat::from_axis_angle(DVec3::X, angle).unwrap_err();
        assert_eq!(e, PointError::NonFiniteAngle);
        assert!(e.to_string().contains("angle"), "{e}");
        assert!(!e.to_string().contains("vector"), "{e}");
    }
    assert_eq!(
        UnitQuat::from_axis_angle(DVec3::new(f64::NAN, 0.0, 0.0), 1.0),
        Err(PointError::NonFinite)
    );
    assert_eq!(
        UnitQuat::from_axis_angle(DVec3::ZERO, 1.0),
        Err(PointError::ZeroLength)
    );
    // Huge and tiny axes are directions.
    for axis in [DVec3::splat(f64::MAX), DVec3::new(1e-300, 0.0, 0.0)] {
        assert_unit_point(
            &UnitQuat::from_axis_angle(axis, f64::MAX).unwrap(),
            "from_axis_angle",
        );
    }
}

#[test]
fn quaternion_exponentials_never_return_nan() {
    for v in hostile_vec3s() {
        let q = UnitQuat::exp_pure(v);
        assert_unit_point(&q, "exp_pure");
        if !v.is_finite() {
            assert_eq!(q, UnitQuat::IDENTITY, "exp_pure of a non-finite vector");
        }
        match UnitQuat::from_rotation_vector(v) {
            Ok(r) => {
                assert!(v.is_finite());
                assert_unit_point(&r, "from_rotation_vector");
            }
            Err(e) => {
                assert_eq!(e, PointError::NonFinite);
                assert!(!v.is_finite());
            }
        }
        for &angle in &HOSTILE {
            if let Ok(r) = UnitQuat::from_axis_angle(v, angle) {
                assert_unit_point(&r, "from_axis_angle");
            }
        }
    }
    for q in quats() {
        assert_finite(&q.log_pure(), "log_pure");
        assert!(q.log_pure().length() <= PI);
        assert_finite(&q.to_rotation_vector(), "to_rotation_vector");
        assert!((0.0..=PI).contains(&q.rotation_angle()));
        for &t in &HOSTILE {
            assert_unit_point(&q.powf(t), "powf");
            if let Ok(r) = q.try_powf(t) {
                assert_eq!(r, q.powf(t));
            }
        }
    }
}

#[test]
fn every_manifold_operation_on_hostile_pairs() {
    let mut tangents3 = hostile_vec3s();
    tangents3.push(DVec3::ZERO);
    for p in s2_points() {
        for q in s2_points() {
            for (k, v) in tangents3.iter().enumerate() {
                check_manifold_ops(&p, &q, v, HOSTILE[k % HOSTILE.len()]);
            }
        }
    }
    for p in quats() {
        for q in quats() {
            for (k, v) in hostile_vec4s().iter().enumerate() {
                check_manifold_ops(&p, &q, v, HOSTILE[k % HOSTILE.len()]);
                check_manifold_ops(&p, &-q, v, HOSTILE[(k + 3) % HOSTILE.len()]);
            }
        }
    }
    for p in sn_points() {
        for q in sn_points() {
            for (k, &a) in HOSTILE.iter().enumerate() {
                // Tangents of the point's own dimension and of others.
                let v = VecN::new(vec![a, 1.0, -a]);
                check_manifold_ops(&p, &q, &v, HOSTILE[(k + 5) % HOSTILE.len()]);
                let w = VecN::new(vec![0.0; p.coords().len()]).with_coords(&[a; 8]);
                check_manifold_ops(&p, &q, &w, a);
            }
        }
    }
}

#[test]
fn sn_points_of_different_dimensions_meet_in_the_larger_sphere() {
    let p = SmPoint::try_new(vec![1.0, 0.0]).unwrap();
    let q = SmPoint::try_new(vec![0.0, 0.0, 0.0, 1.0]).unwrap();
    assert!((p.dist(&q) - FRAC_PI_2).abs() < 1e-15);
    let m = p.slerp(&q, 0.5);
    assert_eq!(m.dim(), 3);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let expected = [h, 0.0, 0.0, h];
    for (a, b) in m.coords().iter().zip(expected) {
        assert!((a - b).abs() < 1e-15, "{m:?}");
    }
    assert_eq!(p.log(&q).dim(), 4);
}

#[test]
fn rotation_conversions_survive_hostile_input() {
    // Matrices: every hostile entry in every position, and whole hostile matrices.
    let mut mats = Vec::new();
    for &a in &HOSTILE {
        for i in 0..9 {
            let mut e = DMat3::IDENTITY.to_cols_array();
            e[i] = a;
            mats.push(DMat3::from_cols_array(&e));
        }
        mats.push(DMat3::from_cols_array(&[a; 9]));
        mats.push(DMat3::from_diagonal(DVec3::new(a, -a, a)));
        mats.push(DMat3::from_cols_array(&[a, -a, a, -a, a, -a, a, -a, a]));
    }
    for m in mats {
        match UnitQuat::from_rotation_matrix(m) {
            Ok(q) => assert_unit_point(&q, "from_rotation_matrix"),
            Err(e) => assert!(
                matches!(
                    e,
                    RotationError::NonFinite
                        | RotationError::NotOrthogonal { .. }
                        | RotationError::NotProper { .. }
                ),
                "{e:?}"
            ),
        }
    }
    for v in hostile_vec3s() {
        match UnitQuat::from_rodrigues(v) {
            Ok(q) => assert_unit_point(&q, "from_rodrigues"),
            Err(e) => assert_eq!(e, RotationError::NonFinite, "{v:?}"),
        }
        match rotation_matrix_from_rodrigues(v) {
            Ok(m) => assert_rotation(&m, "rotation_matrix_from_rodrigues"),
            Err(e) => assert_eq!(e, RotationError::NonFinite, "{v:?}"),
        }
        match exp_so3(v) {
            Ok(m) => assert_rotation(&m, "exp_so3"),
            Err(e) => assert_eq!(e, RotationError::NonFinite, "{v:?}"),
        }
        if v.is_finite() {
            assert!(!skew(v).is_nan());
        }
        for w in hostile_vec3s().into_iter().step_by(7) {
            if let Some(r) = rodrigues_compose(v, w) {
                assert_finite(&r, "rodrigues_compose");
            }
        }
        for &a in &HOSTILE {
            if let Some((r, dr)) = rotation_derivative(v, a, 0.5) {
                assert_rotation(&r, "rotation_derivative");
                assert!(!dr.is_nan(), "{v:?} {a}");
            }
        }
    }
    for v in hostile_vec4s() {
        let [x, y, z, w] = v.to_array();
        match UnitQuat::from_euler_parameters([w, x, y, z]) {
            Ok(q) => assert_unit_point(&q, "from_euler_parameters"),
            Err(e) => assert!(
                matches!(e, RotationError::NonFinite | RotationError::NotUnit { .. }),
                "{e:?}"
            ),
        }
    }
    for q in quats() {
        assert_rotation(&q.to_rotation_matrix(), "to_rotation_matrix");
        let (axis, angle) = q.to_axis_angle();
        assert!(axis.is_finite() && (0.0..=PI).contains(&angle));
        if let Ok(r) = q.to_rodrigues() {
            assert_finite(&r, "to_rodrigues");
        }
        let e = q.to_euler_parameters();
        assert!(e.iter().all(|a| a.is_finite()) && e[0] >= 0.0);
    }
}

#[test]
fn angular_velocity_helpers_make_no_nan_from_finite_input() {
    let mut derivs = hostile_vec4s();
    derivs.push(DVec4::splat(f64::MAX));
    derivs.push(DVec4::new(f64::MAX, f64::MIN, f64::MAX, f64::MIN));
    for q in quats() {
        for &d in &derivs {
            let outs = [
                angular_velocity_acceleration(q, d, d),
                angular_velocity_acceleration_body(q, d, d),
            ];
            for (w, a) in outs {
                if d.is_finite() {
                    assert_no_nan(&w, "ω");
                    assert_no_nan(&a, "α");
                } else {
                    // Non-finite in, non-finite out: a caller's check still sees it.
                    assert!(!w.is_finite() && !a.is_finite(), "{d:?} gave {w:?}, {a:?}");
                }
            }
            let omega = d.truncate();
            for v in [
                velocity_from_angular(q, omega),
                velocity_from_angular_body(q, omega),
            ] {
                if omega.is_finite() {
                    assert_no_nan(&v, "q′ from ω");
                } else {
                    assert!(!v.is_finite(), "non-finite ω must stay visible: {v:?}");
                }
            }
            let r = q.rotate(omega);
            if omega.is_finite() {
                assert_no_nan(&r, "rotate");
            }
        }
    }
    // A finite huge ω is rotated without losing its length.
    let q = quats()[2];
    let v = DVec3::new(f64::MAX, -f64::MAX, 0.0) * 0.5;
    let r = q.rotate(v);
    assert_finite(&r, "rotate of a huge vector");
}

#[test]
fn slerp_jet_reports_bad_jets_and_never_returns_nan() {
    let pts = s2_points();
    for a in &pts {
        for b in &pts {
            for v in hostile_vec3s().into_iter().step_by(3) {
                for &u in HOSTILE.iter().step_by(2) {
                    let ja = Jet {
                        point: *a,
                        velocity: v,
                        acceleration: DVec3::ZERO,
                    };
                    let jb = at_rest_jet(*b);
                    match slerp_jet(&ja, &jb, ScalarJet::param(u, 1.0)) {
                        Ok(j) => {
                            assert_unit_point(&j.point, "slerp_jet point");
                            assert_finite(&j.velocity, "slerp_jet velocity");
                            assert_finite(&j.acceleration, "slerp_jet acceleration");
                        }
                        Err(e) => assert!(
                            matches!(
                                e,
                                PointError::NonFinite
                                    | PointError::NonFiniteParameter
                                    | PointError::Antipodal
                            ),
                            "{e:?}"
                        ),
                    }
                }
            }
        }
    }
}

#[test]
fn unflip_handles_antipodal_keys_and_empty_slices() {
    let mut none: [UnitQuat; 0] = [];
    assert_eq!(unflip(&mut none), 0);
    let mut keys = quats();
    unflip(&mut keys);
    for w in keys.windows(2) {
        assert!(w[0].as_dquat().dot(w[1].as_dquat()) >= 0.0);
        assert_unit_point(&w[1], "unflip");
    }
}

#[test]
fn debug_and_display_state_the_component_order() {
    let q = UnitQuat::from_wxyz([0.5, -0.5, 0.5, -0.5]).unwrap();
    assert_eq!(
        format!("{q:?}"),
        "UnitQuat { w: 0.5, x: -0.5, y: 0.5, z: -0.5 }"
    );
    assert_eq!(format!("{q}"), "0.5 - 0.5i + 0.5j - 0.5k");
    assert_eq!(
        format!("{:.1}", UnitQuat::IDENTITY),
        "1.0 + 0.0i + 0.0j + 0.0k"
    );
    assert_eq!(
        format!("{:?}", UnitQuat::IDENTITY),
        "UnitQuat { w: 1.0, x: 0.0, y: 0.0, z: 0.0 }"
    );
}

/// Any `f64`: the special values, or a random sign, mantissa and binary exponent over the
/// whole range (subnormals to `f64::MAX`), or raw bits.
fn any_f64(u: &mut Unstructured<'_>) -> ArbResult<f64> {
    Ok(match u.int_in_range(0_u8..=9)? {
        0 => *u.choose(&HOSTILE)?,
        1 => f64::from_bits(u.arbitrary()?),
        _ => {
            let m = u.int_in_range(0_u64..=(1 << 53))? as f64 / (1_u64 << 52) as f64;
            let e = u.int_in_range(-1074_i32..=1023)?;
            let sign = if u.arbitrary()? { -1.0 } else { 1.0 };
            sign * m * 2f64.powi(e)
        }
    })
}

/// Like [`any_f64`], but finite.
fn finite_f64(u: &mut Unstructured<'_>) -> ArbResult<f64> {
    let x = any_f64(u)?;
    Ok(if x.is_finite() { x } else { 1e300 })
}

fn vec3(
    u: &mut Unstructured<'_>,
    f: fn(&mut Unstructured<'_>) -> ArbResult<f64>,
) -> ArbResult<DVec3> {
    Ok(DVec3::new(f(u)?, f(u)?, f(u)?))
}

fn vec4(
    u: &mut Unstructured<'_>,
    f: fn(&mut Unstructured<'_>) -> ArbResult<f64>,
) -> ArbResult<DVec4> {
    Ok(DVec4::new(f(u)?, f(u)?, f(u)?, f(u)?))
}

/// Milliseconds per property; `SPHEREKIT_PROPTEST_MS` overrides it for a longer soak.
fn budget_ms() -> u64 {
    std::env::var("SPHEREKIT_PROPTEST_MS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(400)
}

#[test]
fn random_inputs_of_every_magnitude_never_panic_or_return_nan() {
    arbtest::arbtest(|u| {
        let fallback_s2 = S2Point::try_new(DVec3::new(0.3, -0.2, 0.9)).unwrap();
        let p = S2Point::try_new(vec3(u, any_f64)?).unwrap_or(fallback_s2);
        let q = if u.arbitrary()? {
            S2Point::try_new(-p.as_dvec3()).unwrap()
        } else {
            S2Point::try_new(vec3(u, any_f64)?).unwrap_or(S2Point::Y)
        };
        check_manifold_ops(&p, &q, &vec3(u, any_f64)?, any_f64(u)?);
        check_manifold_ops(
            &p,
            &q,
            &p.project_tangent(&vec3(u, finite_f64)?),
            finite_f64(u)?,
        );

        let a =
            UnitQuat::try_new(DQuat::from_vec4(vec4(u, any_f64)?)).unwrap_or(UnitQuat::IDENTITY);
        let b = if u.arbitrary()? {
            -a
        } else {
            UnitQuat::try_new(DQuat::from_vec4(vec4(u, any_f64)?)).unwrap_or(-UnitQuat::IDENTITY)
        };
        check_manifold_ops(&a, &b, &vec4(u, any_f64)?, any_f64(u)?);
        let v = vec3(u, any_f64)?;
        assert_unit_point(&UnitQuat::exp_pure(v), "exp_pure");
        if let Ok(r) = UnitQuat::from_rotation_vector(v) {
            assert_unit_point(&r, "from_rotation_vector");
        }
        if let Ok(r) = UnitQuat::from_axis_angle(v, any_f64(u)?) {
            assert_unit_point(&r, "from_axis_angle");
        }
        let t = any_f64(u)?;
        assert_unit_point(&a.powf(t), "powf");
        assert_unit_point(&(a * b), "product");
        assert_finite(&a.log_pure(), "log_pure");
        let fv = vec3(u, finite_f64)?;
        assert_no_nan(&a.rotate(fv), "rotate");
        let (w, al) = angular_velocity_acceleration(a, vec4(u, finite_f64)?, vec4(u, finite_f64)?);
        assert_no_nan(&w, "ω");
        assert_no_nan(&al, "α");
        let (w, al) =
            angular_velocity_acceleration_body(a, vec4(u, finite_f64)?, vec4(u, finite_f64)?);
        assert_no_nan(&w, "ω body");
        assert_no_nan(&al, "α body");
        assert_no_nan(&velocity_from_angular(a, fv), "q′");
        assert_no_nan(&velocity_from_angular_body(a, fv), "q′ body");
        if let Ok(m) = exp_so3(v) {
            assert_rotation(&m, "exp_so3");
        }
        if let Ok(m) = rotation_matrix_from_rodrigues(v) {
            assert_rotation(&m, "rotation_matrix_from_rodrigues");
        }
        let m = DMat3::from_cols(vec3(u, any_f64)?, vec3(u, any_f64)?, vec3(u, any_f64)?);
        if let Ok(r) = UnitQuat::from_rotation_matrix(m) {
            assert_unit_point(&r, "from_rotation_matrix");
        }
        let e = vec4(u, any_f64)?;
        if let Ok(r) = UnitQuat::from_euler_parameters(e.to_array()) {
            assert_unit_point(&r, "from_euler_parameters");
        }

        let dim = u.int_in_range(2_usize..=6)?;
        let coords: Vec<f64> = (0..dim).map(|_| any_f64(u)).collect::<ArbResult<_>>()?;
        let sp =
            SmPoint::try_new(coords).unwrap_or_else(|_| SmPoint::try_new(vec![1.0, 0.0]).unwrap());
        let dim2 = u.int_in_range(2_usize..=6)?;
        let coords: Vec<f64> = (0..dim2).map(|_| finite_f64(u)).collect::<ArbResult<_>>()?;
        let sq =
            SmPoint::try_new(coords).unwrap_or_else(|_| SmPoint::try_new(vec![0.0, 1.0]).unwrap());
        let tangent: Vec<f64> = (0..dim).map(|_| any_f64(u)).collect::<ArbResult<_>>()?;
        check_manifold_ops(&sp, &sq, &VecN::new(tangent), any_f64(u)?);
        Ok(())
    })
    .budget_ms(budget_ms())
    .run();
}
