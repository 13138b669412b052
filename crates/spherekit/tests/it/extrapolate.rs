// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Extrapolation policies on several curve types, at parameters outside the domain, huge, NaN
//! and infinite; and non-finite parameters on every curve (no panics, debug builds included).

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use crate::support::Rng;
use spherekit::{
    Ambient, ArcBlend, ArcLength, BetaParams, BetaSpline, Bezier, BezierKim, BsplineKim,
    CatmullRom, CornerBlend, CubicEnd, CubicSpline, Curve, DEFAULT_CORNER_FRACTION, DomainError,
    Extrapolate, Extrapolated, GammaSpline, Gammas, GeodesicSpline, Jet, LastEdge, Manifold,
    NlerpSpline, Side, Squad, UnitQuat, angular_velocity_acceleration,
};

/// Parameters outside the domain: just outside, one unit out, huge, infinite.
fn outside([t0, t1]: [f64; 2]) -> Vec<f64> {
    vec![
        t0 - 1.0,
        t1 + 1.0,
        t0 - 1e-9,
        t1 + 1e-9,
        -1e300,
        1e300,
        f64::NEG_INFINITY,
        f64::INFINITY,
    ]
}

fn finite_jet<P: Manifold>(j: &Jet<P>) -> bool {
    j.point.to_vector().is_finite() && j.velocity.is_finite() && j.acceleration.is_finite()
}

/// Every policy agrees with the curve on the closed domain, bit for bit.
fn check_inside<C: Curve + Clone>(c: &C) {
    let [t0, t1] = c.domain();
    for policy in [
        Extrapolate::Hold,
        Extrapolate::Extend,
        Extrapolate::Cycle,
        Extrapolate::Error,
    ] {
        let e = Extrapolated::new(c.clone(), policy);
        assert_eq!(e.domain(), c.domain());
        assert_eq!(e.joints(), c.joints());
        for k in 0..=20 {
            let t = t0 + (t1 - t0) * f64::from(k) / 20.0;
            for side in [Side::Left, Side::Right] {
                assert_eq!(e.jet_at(t, side), c.jet_at(t, side), "{policy:?} at {t}");
                assert_eq!(e.try_jet_at(t, side).unwrap(), c.jet_at(t, side));
            }
            assert_eq!(e.eval(t), c.eval(t));
        }
    }
}

fn check_hold<C: Curve + Clone>(c: &C) {
    let e = Extrapolated::new(c.clone(), Extrapolate::Hold);
    let [t0, t1] = c.domain();
    for t in outside(c.domain()) {
        let end = if t > t1 { c.eval(t1) } else { c.eval(t0) };
        for j in [e.jet(t), e.jet_at(t, Side::Left), e.try_jet(t).unwrap()] {
            assert_eq!(j.point, end, "Hold at {t}");
            assert_eq!(j.velocity.length(), 0.0, "Hold velocity at {t}");
            assert_eq!(j.acceleration.length(), 0.0, "Hold acceleration at {t}");
        }
        assert_eq!(e.eval(t), end);
    }
    let j = e.jet(f64::NAN);
    assert_eq!(j.point, c.eval(t0));
    assert_eq!(j.velocity.length(), 0.0);
    assert_eq!(e.try_jet(f64::NAN).unwrap_err(), DomainError::NotANumber);
}

fn check_extend<C: Curve + Clone>(c: &C) {
    let e = Extrapolated::new(c.clone(), Extrapolate::Extend);
    let [t0, t1] = c.domain();
    for (end, side, sign) in [(t1, Side::Left, 1.0), (t0, Side::Right, -1.0)] {
        let start = c.jet_at(end, side);
        let speed = start.velocity.length();
        for dt in [1e-9, 0.1, 0.5, 1.0] {
            let delta = sign * dt;
            if speed * dt >= 3.0 {
                continue; // the distance wraps past π
            }
            let t = end + delta;
            let j = e.try_jet(t).unwrap();
            assert_eq!(e.jet(t), j);
            // Distance travelled = |v|·Δt, on the geodesic from the end with the end velocity.
            let d = start.point.dist(&j.point);
            assert!(
                (d - speed * dt).abs() < 1e-13 * (1.0 + speed),
                "Extend at {t}: {d} vs {}",
                speed * dt
            );
            let expected = start.point.exp(&(start.velocity.clone() * delta));
            assert!(
                expected.dist(&j.point) < 1e-13,
                "Extend at {t}: off the geodesic"
            );
            // Constant speed, zero tangential acceleration.
            assert!((j.velocity.length() - speed).abs() < 1e-12 * (1.0 + speed));
            let normal = j.point.to_vector() * -(speed * speed);
            assert!((j.acceleration.clone() - normal).length() < 1e-12 * (1.0 + speed * speed));
        }
        // Finite (and on the sphere) at huge parameters.
        let far = end + sign * 1e300;
        let j = e.jet(far);
        assert!(finite_jet(&j), "Extend at {far}");
        assert!((j.point.to_vector().length() - 1.0).abs() < 1e-14);
    }
    for t in [f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(e.try_jet(t).unwrap_err(), DomainError::Unbounded { t });
        assert!(finite_jet(&e.jet(t)));
        assert_eq!(e.jet(t), c.jet(t), "the curve's clamped end");
    }
    assert_eq!(e.try_jet(f64::NAN).unwrap_err(), DomainError::NotANumber);
    assert_eq!(e.jet(f64::NAN), c.jet(t0));
}

fn check_cycle<C: Curve + Clone>(c: &C) {
    let e = Extrapolated::new(c.clone(), Extrapolate::Cycle);
    let [t0, t1] = c.domain();
    let period = t1 - t0;
    // (At r = 0, `t0 + k·period` rounds to either side of a period boundary, where an open
    // curve jumps; the boundary itself is checked below.)
    for r in [0.13, 0.5, 0.77] {
        let base = t0 + r * period;
        for k in [-3.0, -1.0, 1.0, 2.0] {
            let t = base + k * period;
            if (t0..=t1).contains(&t) {
                continue; // inside: the curve itself
            }
            let j = e.try_jet(t).unwrap();
            // Equals the curve at t mod period (up to the rounding of t itself).
            let reduced = t0 + (t - t0).rem_euclid(period);
            let reduced = if reduced >= t1 { t0 } else { reduced };
            assert_eq!(j, c.jet(reduced), "Cycle at {t}");
            let d = j.point.dist(&c.eval(base));
            assert!(d < 1e-12, "Cycle at {t}: {d:e} from the curve at {base}");
        }
    }
    // A whole number of periods past the end: the start from the right, the end from the left.
    assert_eq!(e.jet(t1 + period), c.jet(t0));
    assert_eq!(e.jet_at(t1 + period, Side::Left), c.jet_at(t1, Side::Left));
    for t in [1e300, -1e300] {
        let j = e.try_jet(t).unwrap();
        assert!(finite_jet(&j));
        let reduced = t0 + (t - t0).rem_euclid(period);
        let reduced = if reduced >= t1 { t0 } else { reduced };
        assert_eq!(j, c.jet(reduced), "Cycle at {t}");
    }
    for t in [f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(e.try_jet(t).unwrap_err(), DomainError::Unbounded { t });
        assert!(finite_jet(&e.jet(t)));
    }
    assert_eq!(e.try_jet(f64::NAN).unwrap_err(), DomainError::NotANumber);
}

fn check_error<C: Curve + Clone>(c: &C) {
    let e = Extrapolated::new(c.clone(), Extrapolate::Error);
    let domain = c.domain();
    for t in outside(domain) {
        let err = e.try_jet(t).unwrap_err();
        assert_eq!(err, DomainError::Outside { t, domain });
        assert!(err.to_string().contains(&format!("{t}")), "{err}");
        assert!(e.try_eval(t).is_err());
        // The infallible interface clamps, as the curve does.
        assert_eq!(e.jet(t), c.jet(t));
    }
    assert_eq!(e.try_jet(f64::NAN).unwrap_err(), DomainError::NotANumber);
    assert_eq!(e.jet(f64::NAN), c.jet(domain[0]));
}

fn check_all<C: Curve + Clone>(c: &C) {
    check_inside(c);
    check_hold(c);
    check_extend(c);
    check_cycle(c);
    check_error(c);
}

#[test]
fn policies_on_s2_curves() {
    let mut rng = Rng::new(21);
    let p = rng.walk_s2(6, 0.6);
    check_all(&GeodesicSpline::try_new(p.clone(), Some(rng.knots(5))).unwrap());
    check_all(&CatmullRom::try_new(p.clone(), None).unwrap());
    check_all(&ArcBlend::try_new(p.clone(), 2).unwrap());
    check_all(&BetaSpline::try_new(p.clone(), &BetaParams::default()).unwrap());
    check_all(&CubicSpline::try_new(p.clone(), None, CubicEnd::Natural, false).unwrap());
    check_all(&Bezier::try_new(p[..4].to_vec()).unwrap());
    check_all(&ArcLength::try_new(CatmullRom::try_new(p, None).unwrap()).unwrap());
}

#[test]
fn policies_on_s3_curves() {
    let mut rng = Rng::new(22);
    let q = rng.chain(6, 0.8);
    check_all(&GeodesicSpline::try_new(q.clone(), None).unwrap());
    check_all(&Squad::try_new(q.clone(), Some(rng.knots(5))).unwrap());
    check_all(&CatmullRom::try_new(q.clone(), None).unwrap());
    check_all(&BsplineKim::try_new(q.clone()).unwrap());
    check_all(&GammaSpline::try_new(q.clone(), None, Gammas::All(1.0), LastEdge::Formula).unwrap());
    check_all(&ArcLength::try_new(Squad::try_new(q, None).unwrap()).unwrap());
}

/// On S³, `Extend` turns at the end's constant angular velocity with zero angular acceleration.
#[test]
fn extend_on_s3_is_constant_angular_velocity() {
    let mut rng = Rng::new(23);
    let c = Squad::try_new(rng.chain(5, 0.8), None).unwrap();
    let [_, t1] = c.domain();
    let end = c.jet_at(t1, Side::Left);
    let (omega_end, _) = angular_velocity_acceleration(end.point, end.velocity, end.acceleration);
    let e = Extrapolated::new(c, Extrapolate::Extend);
    for dt in [0.01, 0.3, 1.0, 2.5] {
        let j = e.jet(t1 + dt);
        let (omega, alpha) = angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
        assert!((omega - omega_end).length() < 1e-12, "ω at +{dt}");
        assert!(alpha.length() < 1e-12, "α at +{dt}");
        // The rotation turned is |ω|·Δt.
        let turned = 2.0 * end.point.dist(&j.point);
        let expected = omega_end.length() * dt;
        if expected < core::f64::consts::PI {
            assert!((turned - expected).abs() < 1e-12, "{turned} vs {expected}");
        }
    }
}

/// `Cycle` on a closed curve is continuous across the period.
#[test]
fn cycle_on_a_closed_curve_is_continuous() {
    let mut rng = Rng::new(24);
    let c = CubicSpline::try_new(rng.walk_s2(6, 0.6), None, CubicEnd::Natural, true).unwrap();
    let e = Extrapolated::new(c, Extrapolate::Cycle);
    let [t0, t1] = e.domain();
    for k in [-2.0, 1.0, 3.0] {
        let shift = k * (t1 - t0);
        let (l, r) = (e.jet(t1 + shift - 1e-9), e.jet(t1 + shift + 1e-9));
        assert!(l.point.dist(&r.point) < 1e-8, "at the period boundary {k}");
        assert!((l.velocity - r.velocity).length() < 1e-6);
    }
}

/// A NaN or infinite parameter never panics on any curve (these tests run in debug builds):
/// the clamped value, NaN as the start.
#[test]
fn non_finite_parameters_never_panic() {
    let mut rng = Rng::new(25);
    let p = rng.walk_s2(6, 0.6);
    let q: Vec<UnitQuat> = rng.chain(6, 0.8);
    let s2: Vec<Box<dyn Curve<Point = spherekit::S2Point>>> = vec![
        Box::new(GeodesicSpline::try_new(p.clone(), None).unwrap()),
        Box::new(NlerpSpline::try_new(p.clone(), None).unwrap()),
        Box::new(CatmullRom::try_new(p.clone(), None).unwrap()),
        Box::new(ArcBlend::try_new(p.clone(), 2).unwrap()),
        Box::new(BetaSpline::try_new(p.clone(), &BetaParams::default()).unwrap()),
        Box::new(CubicSpline::try_new(p.clone(), None, CubicEnd::Scipy, false).unwrap()),
        Box::new(CornerBlend::try_new(p.clone(), 2, DEFAULT_CORNER_FRACTION).unwrap()),
        Box::new(Bezier::try_new(p[..4].to_vec()).unwrap()),
    ];
    let s3: Vec<Box<dyn Curve<Point = UnitQuat>>> = vec![
        Box::new(Squad::try_new(q.clone(), None).unwrap()),
        Box::new(BezierKim::try_new(q[..4].to_vec()).unwrap()),
        Box::new(BsplineKim::try_new(q.clone()).unwrap()),
        Box::new(GammaSpline::try_new(q, None, Gammas::All(1.0), LastEdge::Formula).unwrap()),
    ];
    let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300, -1e300];
    fn check<P: Manifold>(c: &dyn Curve<Point = P>, bad: &[f64]) {
        let [t0, t1] = c.domain();
        for &t in bad {
            for side in [Side::Left, Side::Right] {
                let j = c.jet_at(t, side);
                assert!(finite_jet(&j), "{c:?} at {t}");
            }
            let expected = if t > t1 { c.eval(t1) } else { c.eval(t0) };
            assert_eq!(c.eval(t), expected, "clamped at {t}");
        }
        let mut out = vec![c.eval(t0); bad.len()];
        c.eval_many(bad, &mut out);
        let mut jets = vec![c.jet(t0); bad.len()];
        c.jet_many(bad, &mut jets);
        assert!(jets.iter().all(finite_jet));
    }
    for c in &s2 {
        check(c.as_ref(), &bad);
    }
    for c in &s3 {
        check(c.as_ref(), &bad);
    }
}

/// `Segment` continues an open cubic's end segments (scipy's `RotationSpline` extrapolation):
/// smooth through the ends (the same polynomial), derivatives that match finite differences
/// outside, a typed error far out, and no continuation for a closed cubic or another curve.
#[test]
fn segment_continues_the_open_cubic_end_segments() {
    let mut rng = Rng::new(26);
    let keys = rng.chain(6, 0.8);
    let c = CubicSpline::try_new(keys, Some(rng.knots(5)), CubicEnd::Scipy, false).unwrap();
    let e = Extrapolated::new(c.clone(), Extrapolate::Segment);
    let [t0, t1] = c.domain();
    // Inside the end segments the continued formula is the curve.
    for t in [t0, t0 + 0.1 * (c.knots()[1] - t0), t1 - 1e-3, t1] {
        let (a, b) = (c.continued_jet(t).unwrap(), c.jet_at(t, Side::Left));
        assert!(a.point.dist(&b.point) < 1e-14, "point at {t}");
        assert!(
            (a.velocity - b.velocity).length() < 1e-12,
            "velocity at {t}"
        );
        assert!(
            (a.acceleration - b.acceleration).length() < 1e-10,
            "acceleration at {t}"
        );
    }
    // C² through both ends.
    for (inside, outside) in [(t0, t0 - 1e-7), (t1, t1 + 1e-7)] {
        let (a, b) = (c.jet_at(inside, Side::Right), e.jet(outside));
        assert!(
            (a.velocity - b.velocity).length() < 1e-5,
            "velocity through {inside}"
        );
        assert!((a.acceleration - b.acceleration).length() < 1e-4);
    }
    // Finite differences outside.
    for t in [t0 - 0.7, t1 + 0.4, t1 + 1.0] {
        let h = 1e-6;
        let (m, j, p) = (e.jet(t - h), e.jet(t), e.jet(t + h));
        let v = (p.point.to_vector() - m.point.to_vector()) * (0.5 / h);
        let a = (p.velocity - m.velocity) * (0.5 / h);
        assert!((v - j.velocity).length() < 1e-7, "velocity at {t}");
        assert!((a - j.acceleration).length() < 1e-6, "acceleration at {t}");
        assert_eq!(e.try_jet(t).unwrap(), j);
    }
    for t in [-1e300, 1e300, f64::INFINITY] {
        assert_eq!(e.try_jet(t).unwrap_err(), DomainError::Unbounded { t });
        assert!(finite_jet(&e.jet(t)), "the clamped jet at {t}");
    }
    assert_eq!(e.try_jet(f64::NAN).unwrap_err(), DomainError::NotANumber);
    assert!(c.continued_jet(f64::NAN).is_none());
    // No continuation: a closed cubic, another curve.
    let closed = CubicSpline::try_new(rng.chain(5, 0.8), None, CubicEnd::Natural, true).unwrap();
    let [_, c1] = closed.domain();
    assert!(closed.jet_beyond(c1 + 1.0).is_none());
    let geodesic = GeodesicSpline::try_new(rng.chain(3, 0.8), None).unwrap();
    let g = Extrapolated::new(geodesic, Extrapolate::Segment);
    assert_eq!(
        g.try_jet(3.0).unwrap_err(),
        DomainError::Unbounded { t: 3.0 }
    );
}
