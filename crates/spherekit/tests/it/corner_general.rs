// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Corner smoothing as general as Pobegailo (2019), §8.5–8.8 and §9.5–9.8: cut-backs per corner
//! and per side, the timing (start parameter, speed), and small-circle arcs on S². The same
//! properties as with one global fraction: endpoints kept, the edges followed exactly outside the
//! corner blends, Cⁿ at every joint (and not Cⁿ⁺¹), on S², S³ and S^m.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::PI;

use spherekit::glam::DVec3;
use spherekit::{
    CornerBlend, CornerBlendRotations, CornerCuts, CornerTiming, Curve, Manifold, S2Point,
    SmoothingPolynomials, SplineError, UnitQuat, unflip,
};

use crate::support::*;

/// Random `[incoming, outgoing]` cuts for `corners` corners that never overlap on an edge.
fn random_pairs(rng: &mut Rng, corners: usize) -> Vec<[f64; 2]> {
    (0..corners)
        .map(|_| [rng.range(0.05, 0.6), rng.range(0.05, 0.4)])
        .collect()
}

fn rot(a: DVec3, theta: f64, v: DVec3) -> DVec3 {
    let (s, c) = theta.sin_cos();
    a * a.dot(v) + (v - a * a.dot(v)) * c + a.cross(v) * s
}

/// The pieces alternate edge, corner, (edge), corner, …, edge: the cut points are at the knots.
fn cut_points<P: Manifold>(points: &[P], cuts: &[[f64; 2]]) -> Vec<(P, P)> {
    (1..points.len() - 1)
        .map(|j| {
            let before = points[j].slerp(&points[j - 1], cuts[j - 1][0]);
            let after = points[j].slerp(&points[j + 1], cuts[j - 1][1]);
            (before, after)
        })
        .collect()
}

/// Endpoints, cut points at the knots, Cⁿ at every joint with a jump of order n + 1.
fn check_general<P: Manifold>(c: &CornerBlend<P>, pts: &[P], cuts: &[[f64; 2]], n: usize) {
    let k = c.knots().to_vec();
    let [t0, t1] = c.domain();
    assert!(c.eval(t0).dist(&pts[0]) < 1e-15, "starts at P₀");
    assert!(c.eval(t1).dist(pts.last().unwrap()) < 1e-14, "ends at P_M");
    check_continuity(c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
    // Corner j spans the knots whose pieces start at Q_j⁻ and end at Q_j⁺.
    let cps = cut_points(pts, cuts);
    for (before, after) in &cps {
        let hit = |q: &P| k.iter().any(|&t| c.eval(t).dist(q) < 1e-13);
        assert!(hit(before) && hit(after), "cut points at knots");
    }
}

#[test]
fn per_corner_cuts_keep_endpoints_and_are_cn_on_every_sphere() {
    let mut rng = Rng::new(31);
    for n in 1..=4 {
        let pts = rng.walk_s2(6, 0.9);
        let cuts = random_pairs(&mut rng, 4);
        let c = CornerBlend::try_with(
            pts.clone(),
            n,
            &CornerCuts::Pairs(cuts.clone()),
            CornerTiming::default(),
        )
        .unwrap();
        assert_eq!(c.cuts(), &cuts[..]);
        check_general(&c, &pts, &cuts, n);
        let keys = rng.walk_quat(5, 0.7);
        let cuts = random_pairs(&mut rng, 3);
        let c = CornerBlend::try_with(
            keys.clone(),
            n,
            &CornerCuts::Pairs(cuts.clone()),
            CornerTiming::default(),
        )
        .unwrap();
        check_general(&c, &keys, &cuts, n);
        let pts = rng.walk_sm(5, 4, 0.8);
        let per: Vec<f64> = (0..3).map(|_| rng.range(0.05, 0.5)).collect();
        let c = CornerBlend::try_with(
            pts.clone(),
            n,
            &CornerCuts::PerCorner(per.clone()),
            CornerTiming::default(),
        )
        .unwrap();
        let pairs: Vec<[f64; 2]> = per.iter().map(|&f| [f, f]).collect();
        check_general(&c, &pts, &pairs, n);
    }
}

/// The orientation construction (left multiplication) with per-corner cuts and a timing: the
/// same knots as the simple-rotation construction, Cⁿ, constant angular velocity on the edges.
#[test]
fn orientation_corners_with_per_corner_cuts() {
    let mut rng = Rng::new(37);
    for n in 1..=3 {
        let mut keys = rng.walk_quat(5, 0.8);
        unflip(&mut keys);
        let cuts = CornerCuts::Pairs(random_pairs(&mut rng, 3));
        let timing = CornerTiming {
            start: -1.5,
            speed: 0.7,
        };
        let c = CornerBlendRotations::try_with(keys.clone(), n, &cuts, timing).unwrap();
        let d = CornerBlend::try_with(keys.clone(), n, &cuts, timing).unwrap();
        for (a, b) in c.knots().iter().zip(d.knots()) {
            assert!((a - b).abs() < 1e-14, "same knots");
        }
        let k = c.knots();
        assert_eq!(k[0], -1.5);
        check_continuity(&c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
        assert!(
            c.eval(k[k.len() - 1]).dist(&keys[4]) < 1e-14,
            "ends at the last key"
        );
        // First edge at speed 0.7 on S³.
        assert!((c.jet(0.5 * (k[0] + k[1])).velocity.length() - 0.7).abs() < 1e-14);
    }
}

/// The three forms of the cuts agree; the uniform form keeps its (0, 0.5] range (the old
/// `fraction`), the lists may cut up to the whole of an edge between two corners.
#[test]
fn uniform_per_corner_and_pair_cuts_agree() {
    let pts = Rng::new(41).walk_s2(5, 0.8);
    let t = CornerTiming::default();
    let a = CornerBlend::try_new(pts.clone(), 2, 0.3).unwrap();
    let b = CornerBlend::try_with(pts.clone(), 2, &CornerCuts::PerCorner(vec![0.3; 3]), t).unwrap();
    let c =
        CornerBlend::try_with(pts.clone(), 2, &CornerCuts::Pairs(vec![[0.3, 0.3]; 3]), t).unwrap();
    assert_eq!(a.knots(), b.knots());
    assert_eq!(a.knots(), c.knots());
    for i in 0..=50 {
        let s = a.domain()[1] * f64::from(i) / 50.0;
        assert_eq!(a.eval(s), c.eval(s));
    }
    // Cuts that use a whole middle edge: the two corner blends meet directly.
    let full = CornerCuts::Pairs(vec![[0.3, 0.6], [0.4, 0.5], [0.2, 0.2]]);
    let d = CornerBlend::try_with(pts.clone(), 3, &full, t).unwrap();
    // Pieces: edge, corner, corner, (edge 2 of 0.3), corner, edge: 6 pieces.
    assert_eq!(d.knots().len(), 7, "{:?}", d.knots());
    check_continuity(&d, |t, s, m| d.derivatives(t, s, m), 3, &d.knots()[1..6]);
}

/// Timing: the curve with start s and speed v is the unit-speed curve reparametrised,
/// `c_{s,v}(t) = c(v·(t − s))`; the speed after corner j is the speed before it times `β_j/α_j`
/// (the book's t₃, t₄ rule), so equal cut angles keep the speed.
#[test]
fn timing_start_and_speed() {
    let pts = Rng::new(43).walk_s2(5, 0.8);
    let cuts = CornerCuts::Pairs(vec![[0.2, 0.4], [0.3, 0.1], [0.25, 0.25]]);
    let base = CornerBlend::try_with(pts.clone(), 2, &cuts, CornerTiming::default()).unwrap();
    let timing = CornerTiming {
        start: 3.0,
        speed: 2.5,
    };
    let fast = CornerBlend::try_with(pts.clone(), 2, &cuts, timing).unwrap();
    for (a, b) in base.knots().iter().zip(fast.knots()) {
        assert!((3.0 + a / 2.5 - b).abs() < 1e-14, "knots scale");
    }
    for i in 0..=40 {
        let t = base.domain()[1] * f64::from(i) / 40.0;
        let (p, q) = (base.jet(t), fast.jet(3.0 + t / 2.5));
        assert!(p.point.dist(&q.point) < 1e-14);
        assert!(
            (p.velocity * 2.5 - q.velocity).length() < 1e-12,
            "velocity ×2.5"
        );
    }
    // Speeds on the edges: ω₀ = 2.5, then ×β/α at each corner.
    let angles: Vec<f64> = pts.windows(2).map(|w| w[0].dist(&w[1])).collect();
    let pairs = [[0.2, 0.4], [0.3, 0.1], [0.25, 0.25]];
    let mut omega = 2.5;
    let k = fast.knots();
    let mut piece = 0;
    for j in 0..4 {
        let mid = 0.5 * (k[piece] + k[piece + 1]);
        let speed = fast.jet(mid).velocity.length();
        assert!(
            (speed - omega).abs() < 1e-12 * omega,
            "edge {j}: {speed} vs {omega}"
        );
        if j < 3 {
            omega *= pairs[j][1] * angles[j + 1] / (pairs[j][0] * angles[j]);
            piece += 2;
        }
    }
}

/// Algorithm 8.2 with different cuts on the two sides (λ₁ ≠ λ₂) and free knots t₁ < t₂,
/// against an independent implementation of (8.19)–(8.22) with the corrected base point.
#[test]
fn single_corner_with_free_cut_points_matches_algorithm_8_2() {
    let p = |x: f64, y: f64, z: f64| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
    let (p1, p2, p3) = (p(1.0, 0.2, 0.1), p(0.1, 1.0, 0.3), p(-0.2, 0.3, 1.0));
    let (l1, l2) = (0.35, 0.15);
    let (t1, t2) = (0.5, 1.75);
    let (a, b, c) = (p1.as_dvec3(), p2.as_dvec3(), p3.as_dvec3());
    let m = a.cross(b).normalize();
    let nn = b.cross(c).normalize();
    let (big_phi, big_psi) = (p1.dist(&p2), p2.dist(&p3));
    let (phi2, psi1) = (l1 * big_phi, l2 * big_psi);
    let phi1 = big_phi - phi2;
    let t3 = t2 + (t2 - t1) / phi1 * phi2;
    let t4 = t3 + (t3 - t2) / psi1 * (big_psi - psi1);
    let timing = CornerTiming {
        start: t1,
        speed: phi1 / (t2 - t1),
    };
    for n in 1..=3 {
        let curve = CornerBlend::try_with(
            vec![p1, p2, p3],
            n,
            &CornerCuts::Pairs(vec![[l1, l2]]),
            timing,
        )
        .unwrap();
        let k = curve.knots();
        for (got, want) in k.iter().zip([t1, t2, t3, t4]) {
            assert!((got - want).abs() < 1e-14, "knots {k:?}");
        }
        let w = SmoothingPolynomials::try_new(n).unwrap();
        for u in [0.25, 0.5, 0.75] {
            let book = rot(nn, w.w1(u) * psi1, rot(m, -w.w1(1.0 - u) * phi2, b));
            let got = curve.eval(t2 + u * (t3 - t2)).as_dvec3();
            assert!(
                (got - book).length() < 1e-15,
                "(8.19) at u = {u}: {got} vs {book}"
            );
        }
    }
}

/// Each corner blend stays in the cap about its corner through its cut points: a rotation by
/// an angle x moves no point farther than x, so the distance from `P_j` is at most
/// `w₁(1 − u)α_j + w₁(u)β_j ≤ (1 − u)α_j + uβ_j`.
#[test]
fn corner_blend_stays_between_its_cut_points() {
    let mut rng = Rng::new(47);
    for _ in 0..10 {
        let pts = rng.walk_s2(5, 1.0);
        let pairs = random_pairs(&mut rng, 3);
        let c = CornerBlend::try_with(
            pts.clone(),
            2,
            &CornerCuts::Pairs(pairs.clone()),
            CornerTiming::default(),
        )
        .unwrap();
        let k = c.knots();
        for j in 1..4 {
            let (alpha, beta) = (
                pairs[j - 1][0] * pts[j].dist(&pts[j - 1]),
                pairs[j - 1][1] * pts[j].dist(&pts[j + 1]),
            );
            // Corner j is piece 2j − 1.
            let (a, b) = (k[2 * j - 1], k[2 * j]);
            for i in 0..=20 {
                let u = f64::from(i) / 20.0;
                let d = c.eval(a + u * (b - a)).dist(&pts[j]);
                assert!(
                    d <= (1.0 - u) * alpha + u * beta + 1e-14,
                    "corner {j}, u = {u}"
                );
            }
        }
    }
}

/// Small-circle edges (S²): endpoints kept, the straight parts on the edges' circles, Cⁿ at
/// every joint; bend 0 is the great-circle construction; positive bend bows to the right.
#[test]
fn small_circle_arcs_are_cn_and_followed_exactly() {
    let mut rng = Rng::new(53);
    for n in 1..=3 {
        let pts = rng.walk_s2(5, 0.9);
        let bends = [0.4, -0.7, 0.2, 0.9];
        let pairs = random_pairs(&mut rng, 3);
        let cuts = CornerCuts::Pairs(pairs.clone());
        let c = CornerBlend::try_with_arcs(pts.clone(), n, &cuts, CornerTiming::default(), &bends)
            .unwrap();
        let k = c.knots().to_vec();
        assert!(c.eval(k[0]).dist(&pts[0]) < 1e-15, "start");
        assert!(c.eval(k[k.len() - 1]).dist(&pts[4]) < 1e-14, "end");
        check_continuity(&c, |t, s, m| c.derivatives(t, s, m), n, &k[1..k.len() - 1]);
        // Edge j's circle: the plane m_j·x = b_j cos(Θ_j/2); the straight parts lie on it.
        for j in 0..4 {
            let (p, q) = (pts[j].as_dvec3(), pts[j + 1].as_dvec3());
            let b = bends[j];
            let axis = p.cross(q).normalize() * (1.0 - b * b).sqrt() + (p + q).normalize() * b;
            let d = axis.dot(p);
            assert!((d - b * (pts[j].dist(&pts[j + 1]) / 2.0).cos()).abs() < 1e-15);
            let piece = 2 * j;
            let x = c.eval(0.5 * (k[piece] + k[piece + 1])).as_dvec3();
            assert!((axis.dot(x) - d).abs() < 1e-14, "edge {j} on its circle");
        }
    }
    let pts = vec![S2Point::X, S2Point::Y, S2Point::Z];
    let cuts = CornerCuts::Uniform(0.25);
    let t = CornerTiming::default();
    let flat = CornerBlend::try_with_arcs(pts.clone(), 2, &cuts, t, &[0.0, 0.0]).unwrap();
    let plain = CornerBlend::try_with(pts.clone(), 2, &cuts, t).unwrap();
    assert_eq!(flat.knots(), plain.knots());
    // Bend 0.6 on X → Y: the arc bows towards −z (right of travel seen from outside).
    let bowed = CornerBlend::try_with_arcs(pts.clone(), 2, &cuts, t, &[0.6, 0.0]).unwrap();
    assert!(bowed.eval(0.3 * bowed.knots()[1]).as_dvec3().z < -0.05);
    // |b| → 1: the edge becomes a half circle of a tiny circle (φ → π).
    let tight = CornerBlend::try_with_arcs(pts, 2, &cuts, t, &[1.0 - 1e-12, 0.0]).unwrap();
    assert!(
        (tight.knots()[1] - 0.75 * PI).abs() < 1e-5,
        "{:?}",
        tight.knots()
    );
    check_derivatives(&tight, 41);
}

/// An edge a hair short of a half turn with a corner cut of 10⁻⁶ of it, and a cut of nearly a
/// whole edge: finite, and C² to the accuracy the tiny pieces allow (a width of 10⁻⁶ amplifies
/// the rounding of the knots by its inverse; relative jumps stay below 10⁻⁸).
#[test]
fn extreme_cuts_and_near_half_turn_edges() {
    let pts = vec![
        S2Point::X,
        S2Point::try_new(DVec3::new((PI - 1e-6).cos(), (PI - 1e-6).sin(), 0.0)).unwrap(),
        S2Point::Z,
    ];
    for cuts in [[1e-6, 1e-6], [0.5, 0.999_999]] {
        let c = CornerBlend::try_with(
            pts.clone(),
            2,
            &CornerCuts::Pairs(vec![cuts]),
            CornerTiming::default(),
        )
        .unwrap();
        let k = c.knots().to_vec();
        for &t in &k[1..k.len() - 1] {
            let (l, r) = (
                c.derivatives(t, spherekit::Side::Left, 2),
                c.derivatives(t, spherekit::Side::Right, 2),
            );
            for (order, (a, b)) in l.iter().zip(&r).enumerate() {
                let jump = (*a - *b).length() / a.length().max(1.0);
                assert!(jump < 1e-8, "order {order} at {t}: {jump:e}");
            }
        }
        assert!(c.eval(k[k.len() - 1]).dist(&S2Point::Z) < 1e-14);
        for i in 0..=100 {
            let j = c.jet(k[k.len() - 1] * f64::from(i) / 100.0);
            assert!(j.velocity.is_finite() && j.acceleration.is_finite());
        }
    }
}

#[test]
fn bad_cuts_timing_and_bends_are_typed_errors() {
    let pts = Rng::new(59).walk_s2(5, 0.8);
    let t = CornerTiming::default();
    let err = |cuts: CornerCuts, timing: CornerTiming| {
        CornerBlend::try_with(pts.clone(), 2, &cuts, timing).unwrap_err()
    };
    let msg = |e: SplineError| match e {
        SplineError::InvalidParameter { name, reason } => format!("{name}: {reason}"),
        e => panic!("{e}"),
    };
    assert_eq!(
        msg(err(CornerCuts::PerCorner(vec![0.2; 2]), t)),
        "fraction: expected 3 entries (one per corner, the points 1 to 3), got 2"
    );
    for bad in [0.0, 1.0, -0.1, f64::NAN] {
        let e = msg(err(
            CornerCuts::Pairs(vec![[0.2, 0.2], [0.2, bad], [0.2, 0.2]]),
            t,
        ));
        assert!(
            e.starts_with("fraction: entry 1 (the corner at point 2): the outgoing cut"),
            "{e}"
        );
    }
    let e = msg(err(
        CornerCuts::Pairs(vec![[0.2, 0.6], [0.5, 0.2], [0.2, 0.2]]),
        t,
    ));
    assert!(
        e.starts_with("fraction: entries 0 and 1 overlap on the edge from point 1 to point 2"),
        "{e}"
    );
    assert!(msg(err(CornerCuts::Uniform(0.6), t)).starts_with("fraction: must be in (0, 0.5]"));
    for speed in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        let e = msg(err(
            CornerCuts::Uniform(0.2),
            CornerTiming { start: 0.0, speed },
        ));
        assert!(e.starts_with("speed: must be a positive number"), "{e}");
    }
    let e = msg(err(
        CornerCuts::Uniform(0.2),
        CornerTiming {
            start: f64::NAN,
            speed: 1.0,
        },
    ));
    assert!(e.starts_with("start: must be a finite number"), "{e}");
    // A speed so small that the knots overflow is a typed error naming the speed, not a NaN; so
    // are cuts so lopsided that the speed they give a later edge cannot be timed.
    let e = msg(err(
        CornerCuts::Uniform(0.2),
        CornerTiming {
            start: 0.0,
            speed: 1e-300,
        },
    ));
    assert!(
        e.starts_with("speed: piece 0 of the curve (from t = 0e0) cannot be timed"),
        "{e}"
    );
    let lopsided = CornerCuts::Pairs(vec![[1e-9, 0.5], [1e-9, 0.5], [1e-9, 0.5]]);
    let e = msg(err(lopsided, t));
    assert!(e.starts_with("fraction: piece"), "{e}");
    let arcs = |bends: &[f64]| {
        msg(
            CornerBlend::try_with_arcs(pts.clone(), 2, &CornerCuts::Uniform(0.2), t, bends)
                .unwrap_err(),
        )
    };
    assert_eq!(
        arcs(&[0.1; 3]),
        "bend: expected 4 values (one per edge), got 3"
    );
    for bad in [1.0, -1.0, f64::NAN] {
        let e = arcs(&[0.1, 0.1, bad, 0.1]);
        assert!(
            e.starts_with("bend: entry 2 (the edge from point 2): must be in (−1, 1)"),
            "{e}"
        );
    }
    let dup = vec![S2Point::X, S2Point::X, S2Point::Y];
    assert_eq!(
        CornerBlend::try_with_arcs(dup, 2, &CornerCuts::Uniform(0.2), t, &[0.1, 0.1]).unwrap_err(),
        SplineError::Coincident { index: 0 }
    );
}

/// The former name still names the type (deprecated).
#[test]
#[allow(deprecated, reason = "the test of the former name")]
fn corner_blend_s3_is_the_former_name_of_corner_blend_rotations() {
    let q1 = UnitQuat::from_axis_angle(DVec3::X, 1.0).unwrap();
    let keys = vec![UnitQuat::IDENTITY, q1, UnitQuat::IDENTITY];
    let c: spherekit::CornerBlendS3 = CornerBlendRotations::try_new(keys, 2, 0.25).unwrap();
    assert!(c.eval(c.domain()[1]).dist(&UnitQuat::IDENTITY) < 1e-15);
}
