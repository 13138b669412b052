// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Very long key sequences: seeded random walks of 100 000 directions (S²) and orientations
//! (S³) with steps of 0.05–0.5 rad, for every curve type built from a point list. Each curve
//! must build, give finite unit jets, interpolate where it claims to, and keep its continuity
//! claim at a sample of joints spread over the whole sequence. The book's arc-blend knots do
//! not survive such sequences (they drift exponentially); the arc-blend timings must.
//!
//! [`Bezier`](spherekit::Bezier) and [`BezierKim`](spherekit::BezierKim) are left out: each is a
//! single curve whose degree grows with the number of keys (de Casteljau over 100 000 control
//! points per evaluation), not a spline.

#![allow(
    clippy::unwrap_used,
    clippy::cast_precision_loss,
    reason = "tests unwrap known-valid fixtures; counts are far below 2⁵³"
)]

use spherekit::glam::{DQuat, DVec3};
use spherekit::{
    Ambient, ArcBlend, ArcBlendTiming, BetaParams, BetaSpline, BsplineKim, CatmullRom, CornerBlend,
    CornerBlendRotations, Curve, DEFAULT_CORNER_FRACTION, GammaSpline, Gammas, GeodesicSpline,
    LastEdge, Manifold, NlerpSpline, S2Point, Side, SmPoint, SplineError, Squad, UnitQuat,
};

use crate::support::Rng;

/// Keys per sequence.
const KEYS: usize = 100_000;
/// Joints (and keys) checked per curve, spread evenly over the sequence.
const JOINT_SAMPLES: usize = 50;
/// Largest relative jump of a derivative that a continuity claim allows.
const JUMP_TOLERANCE: f64 = 1e-8;

/// A random walk on S² with steps uniform in [0.05, 0.5) rad in random directions.
fn walk_s2(seed: u64, n: usize) -> Vec<S2Point> {
    let mut g = Rng(seed);
    let mut p = g.s2();
    let mut out = Vec::with_capacity(n);
    out.push(p);
    while out.len() < n {
        let step = g.range(0.05, 0.5);
        let t = p.project_tangent(&g.unit3()).normalize();
        p = p.exp(&(t * step));
        out.push(p);
    }
    out
}

/// A random walk of orientations with steps uniform in [0.05, 0.5) rad on S³ (rotations of
/// 0.1–1 rad) about random axes; consecutive keys have positive dot products.
fn walk_s3(seed: u64, n: usize) -> Vec<UnitQuat> {
    Rng(seed).chain(n, 0.5)
}

/// A random walk on S^m with steps uniform in [0.05, 0.5) rad.
fn walk_sm(seed: u64, n: usize, m: usize) -> Vec<SmPoint> {
    let mut g = Rng(seed);
    let mut p = g.sn(m);
    let mut out = vec![p.clone()];
    while out.len() < n {
        let step = g.range(0.05, 0.5);
        let v = spherekit::VecN::new(g.vec(m + 1));
        let t = p.project_tangent(&v);
        let t = t.clone() * (step / t.length());
        p = p.exp(&t);
        out.push(p.clone());
    }
    out
}

/// `count` indices from `lo` to `hi` (inclusive), evenly spread.
fn spread(lo: usize, hi: usize, count: usize) -> Vec<usize> {
    (0..count)
        .map(|j| lo + (hi - lo) * j / (count - 1).max(1))
        .collect()
}

/// `|a − b| / max(|a|, |b|)` (0 when both vanish).
fn relative<V: Ambient>(a: &V, b: &V) -> f64 {
    let scale = a.length().max(b.length());
    if scale == 0.0 {
        0.0
    } else {
        (a.clone() - b.clone()).length() / scale
    }
}

/// What a method promises.
struct Claims {
    name: &'static str,
    /// Continuity order in its parameter at every joint (0, 1 or 2 checked from the jets).
    order: usize,
    /// The keys are passed at the joints: `eval(joints[i]) = keys[i + offset]`.
    interpolates: bool,
    /// Keys before the first joint's (Catmull-Rom's phantom first point).
    offset: usize,
}

/// Builds nothing itself: checks `curve` against `claims` on the `keys`.
fn check<C: Curve>(curve: &C, keys: &[C::Point], claims: &Claims) {
    let name = claims.name;
    let joints = curve.joints();
    let [t0, t1] = curve.domain();
    assert!(
        t0.is_finite() && t1.is_finite() && t0 < t1,
        "{name}: domain"
    );
    // Finite unit jets at parameters spread over the whole domain.
    let ts: Vec<f64> = (0..=2000)
        .map(|j| t0 + (t1 - t0) * (j as f64 + 0.31) / 2001.0)
        .collect();
    let mut jets = vec![curve.jet(t0); ts.len()];
    curve.jet_many(&ts, &mut jets);
    for (t, j) in ts.iter().zip(&jets) {
        let p = j.point.to_vector();
        assert!(
            p.is_finite() && j.velocity.is_finite() && j.acceleration.is_finite(),
            "{name}: jet at t = {t} is not finite"
        );
        assert!((p.length() - 1.0).abs() < 1e-13, "{name}: unit at t = {t}");
    }
    // Interpolation and continuity at joints spread over the sequence.
    if claims.interpolates {
        let o = claims.offset;
        assert_eq!(
            joints.len(),
            keys.len() - 2 * o,
            "{name}: one joint per key"
        );
        for i in spread(0, joints.len() - 1, JOINT_SAMPLES) {
            let d = curve.eval(joints[i]).dist(&keys[i + o]);
            assert!(d < 1e-12, "{name}: key {i} missed by {d:e}");
        }
    }
    for i in spread(1, joints.len() - 2, JOINT_SAMPLES) {
        let t = joints[i];
        let (l, r) = (curve.jet_at(t, Side::Left), curve.jet_at(t, Side::Right));
        let jumps = [
            (l.point.to_vector() - r.point.to_vector()).length(),
            relative(&l.velocity, &r.velocity),
            relative(&l.acceleration, &r.acceleration),
        ];
        for (k, jump) in jumps.iter().enumerate().take(claims.order.min(2) + 1) {
            assert!(
                *jump <= JUMP_TOLERANCE,
                "{name}: order-{k} jump {jump:e} at joint {i} (t = {t})"
            );
        }
    }
}

/// Cⁿ of an arc-blend at sampled joints from its exact derivatives of every order up to `n`.
fn check_arc_blend_cn<P: Manifold>(curve: &ArcBlend<P>, what: &str) {
    let n = curve.smoothness();
    let knots = curve.knots();
    for i in spread(1, knots.len() - 2, JOINT_SAMPLES) {
        let t = knots[i];
        let (l, r) = (
            curve.derivatives(t, Side::Left, n),
            curve.derivatives(t, Side::Right, n),
        );
        for (k, (a, b)) in l.iter().zip(&r).enumerate() {
            let jump = relative(a, b);
            assert!(
                jump <= JUMP_TOLERANCE,
                "{what}: order-{k} jump {jump:e} at key {i} (t = {t}, n = {n})"
            );
        }
    }
}

fn arc_blends<P: Manifold>(keys: &[P], space: &str) {
    for n in [2, 4] {
        let c = ArcBlend::try_new(keys.to_vec(), n).unwrap();
        assert_ne!(
            c.timing(),
            ArcBlendTiming::Book,
            "{space}: book knots drift"
        );
        check(
            &c,
            keys,
            &Claims {
                name: "arc-blend",
                order: n,
                interpolates: true,
                offset: 0,
            },
        );
        check_arc_blend_cn(&c, &format!("arc-blend {space}"));
    }
    let u = ArcBlend::try_with(keys.to_vec(), 3, ArcBlendTiming::Uniform).unwrap();
    check_arc_blend_cn(&u, &format!("arc-blend uniform {space}"));
}

#[test]
fn hundred_thousand_directions() {
    let keys = walk_s2(1, KEYS);
    let claims = |name, order, interpolates| Claims {
        name,
        order,
        interpolates,
        offset: 0,
    };
    check(
        &GeodesicSpline::try_new(keys.clone(), None).unwrap(),
        &keys,
        &claims("geodesic", 0, true),
    );
    check(
        &NlerpSpline::try_new(keys.clone(), None).unwrap(),
        &keys,
        &claims("nlerp", 0, true),
    );
    check(
        &CatmullRom::try_new(keys.clone(), None).unwrap(),
        &keys,
        &Claims {
            offset: 1,
            ..claims("catmull-rom", 1, true)
        },
    );
    check(
        &CornerBlend::try_new(keys.clone(), 2, DEFAULT_CORNER_FRACTION).unwrap(),
        &keys,
        &claims("corner-blend", 2, false),
    );
    arc_blends(&keys, "S2");
}

#[test]
fn hundred_thousand_orientations() {
    let keys = walk_s3(2, KEYS);
    let claims = |name, order, interpolates| Claims {
        name,
        order,
        interpolates,
        offset: 0,
    };
    check(
        &GeodesicSpline::try_new(keys.clone(), None).unwrap(),
        &keys,
        &claims("geodesic", 0, true),
    );
    check(
        &NlerpSpline::try_new(keys.clone(), None).unwrap(),
        &keys,
        &claims("nlerp", 0, true),
    );
    check(
        &CatmullRom::try_new(keys.clone(), None).unwrap(),
        &keys,
        &Claims {
            offset: 1,
            ..claims("catmull-rom", 1, true)
        },
    );
    check(
        &Squad::try_new(keys.clone(), None).unwrap(),
        &keys,
        &claims("squad", 1, true),
    );
    check(
        &BsplineKim::try_new(keys.clone()).unwrap(),
        &keys,
        &claims("bspline-kim", 2, false),
    );
    check(
        &GammaSpline::try_new(keys.clone(), None, Gammas::All(1.0), LastEdge::Formula).unwrap(),
        &keys,
        &claims("gamma", 1, false),
    );
    check(
        &CornerBlend::try_new(keys.clone(), 2, DEFAULT_CORNER_FRACTION).unwrap(),
        &keys,
        &claims("corner-blend", 2, false),
    );
    check(
        &CornerBlendRotations::try_new(keys.clone(), 2, DEFAULT_CORNER_FRACTION).unwrap(),
        &keys,
        &claims("corner-blend S3", 2, false),
    );
    arc_blends(&keys, "S3");
}

/// The interpolating Beta spline solves a block-tridiagonal Newton system over all keys.
#[test]
fn hundred_thousand_keys_beta() {
    let claims = Claims {
        name: "beta",
        order: 1,
        interpolates: true,
        offset: 0,
    };
    let keys = walk_s2(3, KEYS);
    let c = BetaSpline::try_new(keys.clone(), &BetaParams::default()).unwrap();
    check(&c, &keys, &claims);
    let keys = walk_s3(4, KEYS);
    let c = BetaSpline::try_new(keys.clone(), &BetaParams::default()).unwrap();
    check(&c, &keys, &claims);
}

#[test]
fn arc_blend_long_sequence_on_s5() {
    let keys = walk_sm(5, 20_000, 5);
    let c = ArcBlend::try_new(keys.clone(), 3).unwrap();
    check(
        &c,
        &keys,
        &Claims {
            name: "arc-blend S5",
            order: 3,
            interpolates: true,
            offset: 0,
        },
    );
    check_arc_blend_cn(&c, "arc-blend S5");
}

/// The case of the issue: 10 000 directions failed with `knots[2083] is not greater than …`.
#[test]
fn arc_blend_ten_thousand_directions_used_to_fail() {
    let keys = walk_s2(7, 10_000);
    let err = ArcBlend::try_with(keys.clone(), 2, ArcBlendTiming::Book).unwrap_err();
    assert!(
        matches!(
            err,
            SplineError::TimingNotRepresentable { timing: "book", .. }
        ),
        "{err:?}"
    );
    let c = ArcBlend::try_new(keys.clone(), 2).unwrap();
    assert_eq!(c.timing(), ArcBlendTiming::ArcLength);
    check(
        &c,
        &keys,
        &Claims {
            name: "arc-blend 10 000",
            order: 2,
            interpolates: true,
            offset: 0,
        },
    );
    check_arc_blend_cn(&c, "arc-blend 10 000");
    // Arc-length timing: the speed averages about 1 and never stalls (module docs).
    let [t0, t1] = c.domain();
    let mut speeds: Vec<f64> = (0..=20_000)
        .map(|j| {
            c.jet(t0 + (t1 - t0) * f64::from(j) / 20_000.0)
                .velocity
                .length()
        })
        .collect();
    speeds.sort_by(f64::total_cmp);
    let (lo, median, hi) = (speeds[0], speeds[10_000], speeds[20_000]);
    assert!(lo > 1e-4 && hi < 10.0, "speeds from {lo} to {hi}");
    assert!((0.8..1.25).contains(&median), "median speed {median}");
}

/// Points on one circle: the book's knots (the cumulative angles) stay the default, however
/// many, and the curve is that circle at unit angular speed.
#[test]
fn arc_blend_co_circular_long_sequence_is_the_circle() {
    let axis = DVec3::new(0.3, -0.5, 0.8).normalize();
    let p0 = DVec3::new(0.9, 0.1, -0.2).normalize();
    let rot = |a: f64| {
        let q = DQuat::from_axis_angle(axis, a);
        S2Point::try_new(q * p0).unwrap()
    };
    let mut g = Rng(11);
    let mut angles = vec![0.0];
    for _ in 1..20_000 {
        let a = angles[angles.len() - 1] + g.range(0.05, 0.5);
        angles.push(a);
    }
    let keys: Vec<S2Point> = angles.iter().map(|&a| rot(a)).collect();
    let c = ArcBlend::try_new(keys, 2).unwrap();
    assert_eq!(c.timing(), ArcBlendTiming::Book);
    for i in spread(0, angles.len() - 1, 200) {
        let k = c.knots()[i];
        assert!(
            (k - angles[i]).abs() < 1e-10 * angles[i].max(1.0),
            "knot {i} = {k}, angle {}",
            angles[i]
        );
    }
    let speed = axis.cross(p0).length();
    let [t0, t1] = c.domain();
    for j in 0..=500 {
        let t = t0 + (t1 - t0) * f64::from(j) / 500.0;
        let jet = c.jet(t);
        // The knots carry the rounding of 20 000 circle constructions: about 1e-11 relative.
        let d = jet.point.dist(&rot(t));
        assert!(
            d < 1e-10 * t.max(1.0),
            "at the circle's angle t = {t}: {d:e}"
        );
        let off = (jet.point.as_dvec3().dot(axis) - p0.dot(axis)).abs();
        assert!(off < 1e-13, "on the circle's plane at t = {t}: {off:e}");
        assert!(
            (jet.velocity.length() - speed).abs() < 1e-9,
            "unit angular speed"
        );
    }
}

/// Explicitly requested book knots that cannot be represented: an error in the user's terms.
#[test]
fn arc_blend_book_timing_error_message() {
    let keys = walk_s2(7, 10_000);
    let err = ArcBlend::try_with(keys, 2, ArcBlendTiming::Book).unwrap_err();
    let SplineError::TimingNotRepresentable {
        index,
        spacing,
        ratio,
        knot,
        ..
    } = err
    else {
        panic!("unexpected error {err:?}");
    };
    assert!(index > 100, "fails late: {index}");
    assert!(spacing > 0.0 && ratio > 0.0 && knot > 0.0, "{err:?}");
    let message = err.to_string();
    assert!(
        message.starts_with(&format!(
            "the book's arc-blend knots cannot be represented at point {index}"
        )),
        "{message}"
    );
    assert!(message.contains("ψ/φ"), "{message}");
    assert!(
        message.contains("arc-length or uniform timing"),
        "{message}"
    );
    assert!(!message.contains("knots["), "{message}");
}

/// Explicit arc-length knots with a step too short to add to the length before it.
#[test]
fn arc_blend_arc_length_timing_error_message() {
    let mut keys = walk_s2(8, 20_000);
    let last = keys[keys.len() - 1];
    let tiny = last.exp(
        &(last
            .project_tangent(&DVec3::new(0.3, 0.7, -0.2))
            .normalize()
            * 3e-14),
    );
    keys.push(tiny);
    let err = ArcBlend::try_with(keys.clone(), 2, ArcBlendTiming::ArcLength).unwrap_err();
    assert!(
        matches!(
            err,
            SplineError::TimingNotRepresentable {
                timing: "arc-length",
                index: 20_000,
                ..
            }
        ),
        "{err:?}"
    );
    let message = err.to_string();
    assert!(
        message.starts_with("the arc-length knots cannot be represented at point 20000"),
        "{message}"
    );
    assert!(message.contains("uniform timing"), "{message}");
    // The default falls back to uniform knots and works. (The circle through the last three
    // points, two of them 3e-14 apart, is ill-conditioned in any timing: no continuity check.)
    let c = ArcBlend::try_new(keys.clone(), 2).unwrap();
    assert_eq!(c.timing(), ArcBlendTiming::Uniform);
    for (t, p) in c.knots().iter().zip(&keys).skip(19_990) {
        assert!(c.eval(*t).dist(p) < 1e-15, "interpolates at t = {t}");
    }
}

/// The point sets of the arc-blend golden scenes keep the book's knots (their images depend on
/// them).
#[test]
#[allow(clippy::approx_constant, reason = "the scenes' literal coordinates")]
fn arc_blend_golden_scenes_keep_the_book_knots() {
    let s2: Vec<S2Point> = [
        [1.0, 0.0, 0.3],
        [0.6, 0.8, 0.4],
        [-0.2, 1.0, 0.1],
        [-0.9, 0.3, -0.2],
        [-0.7, -0.6, 0.0],
    ]
    .iter()
    .map(|&[x, y, z]| S2Point::try_new(DVec3::new(x, y, z)).unwrap())
    .collect();
    assert_eq!(
        ArcBlend::try_new(s2, 2).unwrap().timing(),
        ArcBlendTiming::Book
    );
    let q: Vec<UnitQuat> = [
        [1.0, 0.0, 0.0, 0.0],
        [0.9239, 0.0, 0.0, 0.3827],
        [0.7071, 0.5, 0.5, 0.0],
        [0.5, -0.5, 0.5, 0.5],
        [0.0, 0.0, 1.0, 0.0],
        [0.3, 0.8, 0.1, -0.5],
    ]
    .iter()
    .map(|&w| UnitQuat::from_wxyz(w).unwrap())
    .collect();
    for (keys, n) in [(q[..5].to_vec(), 3), (q.clone(), 2)] {
        assert_eq!(
            ArcBlend::try_new(keys, n).unwrap().timing(),
            ArcBlendTiming::Book
        );
    }
}

/// The distance from `p` to `curve` on `[lo, hi]`: the nearest of 200 samples, refined by a
/// golden-section search (the distance is unimodal near a point of a smooth simple arc).
fn distance_to<C: Curve>(curve: &C, lo: f64, hi: f64, p: &C::Point) -> f64 {
    let d = |t: f64| curve.eval(t).dist(p);
    let step = (hi - lo) / 200.0;
    let best = (0..=200)
        .map(|j| lo + step * f64::from(j))
        .fold(
            (lo, f64::MAX),
            |b, t| if d(t) < b.1 { (t, d(t)) } else { b },
        );
    let (mut a, mut b) = ((best.0 - step).max(lo), (best.0 + step).min(hi));
    let r = 0.5 * (5.0_f64.sqrt() - 1.0);
    for _ in 0..120 {
        let (x, y) = (b - r * (b - a), a + r * (b - a));
        if d(x) < d(y) {
            b = y;
        } else {
            a = x;
        }
    }
    d(0.5 * (a + b)).min(best.1)
}

/// All timings trace the same curve: the points of every timing lie on the book's segment
/// between the same keys.
#[test]
fn arc_blend_timings_trace_the_same_curve() {
    let keys = walk_s2(9, 40);
    let book = ArcBlend::try_with(keys.clone(), 2, ArcBlendTiming::Book).unwrap();
    let times: Vec<f64> = (0..keys.len()).map(|i| (i as f64).powf(1.3)).collect();
    for timing in [
        ArcBlendTiming::ArcLength,
        ArcBlendTiming::Uniform,
        ArcBlendTiming::Knots(times),
    ] {
        let c = ArcBlend::try_with(keys.clone(), 2, timing.clone()).unwrap();
        assert_eq!(c.timing(), timing, "timing reported");
        let (a, b) = (book.knots(), c.knots());
        for i in 0..keys.len() - 1 {
            for j in 1..6 {
                let p = c.eval(b[i] + (b[i + 1] - b[i]) * f64::from(j) / 6.0);
                let gap = distance_to(&book, a[i], a[i + 1], &p);
                assert!(
                    gap < 1e-10,
                    "{timing:?} segment {i}: {gap:e} off the book's curve"
                );
            }
        }
        check_arc_blend_cn(&c, "arc-blend timing");
    }
}
