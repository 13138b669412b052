// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The point types from and to arrays (and mint, with the feature): round trips, normalisation
//! and typed errors for bad input.

use spherekit::{PointError, S2Point, SmPoint, UnitQuat};

/// A vector of `n` components in [-10, 10], not all tiny.
fn vector<const N: usize>(
    u: &mut arbtest::arbitrary::Unstructured<'_>,
) -> arbtest::arbitrary::Result<[f64; N]> {
    let mut v = [0.0; N];
    for x in &mut v {
        *x = f64::from(u.int_in_range(-10_000_i32..=10_000)?) / 1000.0;
    }
    if v.iter().all(|x| x.abs() < 1e-3) {
        v[0] = 1.0;
    }
    Ok(v)
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-14)
}

fn normalized(v: &[f64]) -> Vec<f64> {
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    v.iter().map(|x| x / n).collect()
}

#[test]
fn arrays_round_trip_through_the_point_types() {
    arbtest::arbtest(|u| {
        let v3: [f64; 3] = vector(u)?;
        let p = S2Point::from_array(v3).unwrap();
        assert!(
            close(&p.to_array(), &normalized(&v3)),
            "S2Point normalises {v3:?}"
        );
        assert_eq!(S2Point::try_from(v3), Ok(p), "TryFrom is from_array");
        assert!(
            close(
                &S2Point::from_array(p.to_array()).unwrap().to_array(),
                &p.to_array()
            ),
            "a unit vector comes back as itself"
        );
        assert_eq!(
            <[f64; 3]>::from(p),
            p.to_array(),
            "From<S2Point> for [f64; 3]"
        );

        let v4: [f64; 4] = vector(u)?;
        let q = UnitQuat::from_xyzw(v4).unwrap();
        assert!(
            close(&q.to_xyzw(), &normalized(&v4)),
            "UnitQuat normalises {v4:?}"
        );
        let [x, y, z, w] = v4;
        assert_eq!(
            UnitQuat::from_wxyz([w, x, y, z]),
            Ok(q),
            "the two orders name the same quaternion"
        );
        assert_eq!(
            q.to_wxyz(),
            [
                q.to_xyzw()[3],
                q.to_xyzw()[0],
                q.to_xyzw()[1],
                q.to_xyzw()[2]
            ],
            "to_wxyz is to_xyzw rotated"
        );

        let v6: [f64; 6] = vector(u)?;
        let s = SmPoint::try_from(v6).unwrap();
        assert_eq!(s.dim(), 5, "six coordinates are S^5");
        assert!(
            close(s.coords(), &normalized(&v6)),
            "SmPoint normalises {v6:?}"
        );
        assert_eq!(
            SmPoint::try_from(&v6[..]),
            Ok(s.clone()),
            "slices and arrays agree"
        );
        assert!(
            close(
                SmPoint::from_slice(s.coords()).unwrap().coords(),
                s.coords()
            ),
            "a unit vector comes back as itself"
        );
        Ok(())
    });
}

#[test]
fn bad_arrays_are_typed_errors() {
    assert_eq!(
        S2Point::from_array([0.0; 3]),
        Err(PointError::ZeroLength),
        "zero vector"
    );
    assert_eq!(
        S2Point::from_array([1.0, f64::INFINITY, 0.0]),
        Err(PointError::NonFinite),
        "infinite component"
    );
    assert_eq!(
        UnitQuat::from_xyzw([0.0, 0.0, f64::NAN, 1.0]),
        Err(PointError::NonFinite),
        "NaN component"
    );
    assert_eq!(
        UnitQuat::from_xyzw([0.0; 4]),
        Err(PointError::ZeroLength),
        "zero quaternion"
    );
    assert_eq!(
        SmPoint::try_from([2.0]),
        Err(PointError::WrongDimension {
            expected: 2,
            got: 1
        }),
        "S^0 is not a sphere here"
    );
    assert_eq!(
        SmPoint::from_slice(&[]),
        Err(PointError::WrongDimension {
            expected: 2,
            got: 0
        }),
        "no coordinates"
    );
    assert_eq!(
        SmPoint::try_from([0.0, f64::NAN, 1.0]),
        Err(PointError::NonFinite),
        "NaN coordinate"
    );
}

#[cfg(feature = "mint")]
#[test]
fn mint_values_convert_as_arrays_do() {
    arbtest::arbtest(|u| {
        let v3: [f64; 3] = vector(u)?;
        let p = S2Point::try_from(mint::Vector3::from(v3)).unwrap();
        assert_eq!(Ok(p), S2Point::from_array(v3), "mint f64 vector");
        assert_eq!(
            mint::Vector3::<f64>::from(p),
            mint::Vector3::from(p.to_array()),
            "back to mint"
        );
        #[expect(
            clippy::cast_possible_truncation,
            reason = "f32 input, as an f32 application has it"
        )]
        let v3f = v3.map(|x| x as f32);
        let pf = S2Point::try_from(mint::Vector3::from(v3f)).unwrap();
        assert_eq!(
            Ok(pf),
            S2Point::from_array(v3f.map(f64::from)),
            "mint f32 vector, widened"
        );

        let v4: [f64; 4] = vector(u)?;
        let q = UnitQuat::try_from(mint::Quaternion::from(v4)).unwrap();
        assert_eq!(
            Ok(q),
            UnitQuat::from_xyzw(v4),
            "mint quaternion is scalar last"
        );
        let back = mint::Quaternion::<f64>::from(q);
        assert_eq!(<[f64; 4]>::from(back), q.to_xyzw(), "back to mint");
        #[expect(
            clippy::cast_possible_truncation,
            reason = "f32 input, as an f32 application has it"
        )]
        let v4f = v4.map(|x| x as f32);
        let qf = UnitQuat::try_from(mint::Quaternion::from(v4f)).unwrap();
        assert_eq!(
            Ok(qf),
            UnitQuat::from_xyzw(v4f.map(f64::from)),
            "mint f32 quaternion, widened"
        );
        Ok(())
    });
    assert_eq!(
        S2Point::try_from(mint::Vector3 {
            x: 0.0_f32,
            y: 0.0,
            z: 0.0
        }),
        Err(PointError::ZeroLength),
        "a zero mint vector"
    );
    assert_eq!(
        UnitQuat::try_from(mint::Quaternion {
            v: mint::Vector3 {
                x: f64::NAN,
                y: 0.0,
                z: 0.0
            },
            s: 1.0
        }),
        Err(PointError::NonFinite),
        "a NaN mint quaternion"
    );
}
