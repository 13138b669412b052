// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Batch evaluation (`Curve::eval_many`, `Curve::jet_many`) agrees with one-at-a-time
//! evaluation bit for bit, for every method, for sorted, unsorted and out-of-domain parameters.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

#[path = "../../benches/data.rs"]
mod data;

use spherekit::glam::{DVec3, DVec4};
use spherekit::{
    ArcBlend, BetaParams, BetaSolver, BetaSpline, Bezier, BezierKim, BsplineKim, CatmullRom,
    CornerBlend, CornerBlendS3, Curve, DEFAULT_CORNER_FRACTION, GammaSpline, Gammas,
    GeodesicSpline, Jet, LastEdge, Manifold, NlerpSpline, S2Point, Squad, UnitQuat,
};

type Boxed<P> = Box<dyn Curve<Point = P>>;

/// Every method on S², named.
fn s2_curves() -> Vec<(&'static str, Boxed<S2Point>)> {
    let p = data::points_s2(20, 60.0, 3);
    let jacobi = BetaParams {
        solver: BetaSolver::Jacobi,
        ..BetaParams::default()
    };
    vec![
        (
            "geodesic",
            Box::new(GeodesicSpline::try_new(p.clone(), None).unwrap()),
        ),
        (
            "nlerp",
            Box::new(NlerpSpline::try_new(p.clone(), None).unwrap()),
        ),
        (
            "bezier",
            Box::new(Bezier::try_new(p[..4].to_vec()).unwrap()),
        ),
        ("bezier-19", Box::new(Bezier::try_new(p.clone()).unwrap())),
        (
            "catmull-rom",
            Box::new(CatmullRom::try_new(p.clone(), None).unwrap()),
        ),
        (
            "beta",
            Box::new(BetaSpline::try_new(p.clone(), &BetaParams::default()).unwrap()),
        ),
        (
            "beta-jacobi",
            Box::new(BetaSpline::try_new(p.clone(), &jacobi).unwrap()),
        ),
        (
            "arc-blend",
            Box::new(ArcBlend::try_new(p.clone(), 2).unwrap()),
        ),
        (
            "corner-blend",
            Box::new(CornerBlend::try_new(p, 2, DEFAULT_CORNER_FRACTION).unwrap()),
        ),
    ]
}

/// Every method on S³, named.
fn s3_curves() -> Vec<(&'static str, Boxed<UnitQuat>)> {
    let q = data::keys_s3(20);
    let knots: Vec<f64> = (0..20)
        .map(|i| f64::from(i) * 0.7 + 0.01 * f64::from(i * i))
        .collect();
    vec![
        (
            "geodesic",
            Box::new(GeodesicSpline::try_new(q.clone(), Some(knots.clone())).unwrap()),
        ),
        (
            "nlerp",
            Box::new(NlerpSpline::try_new(q.clone(), None).unwrap()),
        ),
        (
            "bezier",
            Box::new(Bezier::try_new(q[..4].to_vec()).unwrap()),
        ),
        (
            "squad",
            Box::new(Squad::try_new(q.clone(), Some(knots)).unwrap()),
        ),
        (
            "squad-uniform",
            Box::new(Squad::try_new(q.clone(), None).unwrap()),
        ),
        (
            "catmull-rom",
            Box::new(CatmullRom::try_new(q.clone(), None).unwrap()),
        ),
        (
            "catmull-rom-quaternion",
            Box::new(CatmullRom::try_new_quaternion(q.clone(), None).unwrap()),
        ),
        (
            "bezier-kim",
            Box::new(BezierKim::try_new(q[..4].to_vec()).unwrap()),
        ),
        (
            "bspline-kim",
            Box::new(BsplineKim::try_new(q.clone()).unwrap()),
        ),
        (
            "gamma",
            Box::new(
                GammaSpline::try_new(q.clone(), None, Gammas::All(1.0), LastEdge::Formula).unwrap(),
            ),
        ),
        (
            "beta",
            Box::new(BetaSpline::try_new(q.clone(), &BetaParams::default()).unwrap()),
        ),
        (
            "arc-blend",
            Box::new(ArcBlend::try_new(q.clone(), 2).unwrap()),
        ),
        (
            "arc-blend-3",
            Box::new(ArcBlend::try_new(q.clone(), 3).unwrap()),
        ),
        (
            "corner-blend",
            Box::new(CornerBlend::try_new(q.clone(), 2, DEFAULT_CORNER_FRACTION).unwrap()),
        ),
        (
            "corner-blend-s3",
            Box::new(CornerBlendS3::try_new(q, 2, DEFAULT_CORNER_FRACTION).unwrap()),
        ),
    ]
}

/// The raw bits of ambient coordinates.
trait Bits {
    fn bits(&self) -> Vec<u64>;
}

impl Bits for DVec3 {
    fn bits(&self) -> Vec<u64> {
        self.to_array().iter().map(|x| x.to_bits()).collect()
    }
}

impl Bits for DVec4 {
    fn bits(&self) -> Vec<u64> {
        self.to_array().iter().map(|x| x.to_bits()).collect()
    }
}

fn jet_bits<P: Manifold>(j: &Jet<P>) -> Vec<u64>
where
    P::Vector: Bits,
{
    let mut v = j.point.to_vector().bits();
    v.extend(j.velocity.bits());
    v.extend(j.acceleration.bits());
    v
}

/// Sorted samples with every joint, points just beside the joints, both ends and parameters
/// outside the domain; then the same shuffled.
fn parameter_sets(c: &dyn Curve<Point = impl Manifold>) -> [Vec<f64>; 2] {
    let [t0, t1] = c.domain();
    let mut ts = data::params([t0, t1], 997);
    for &k in c.joints() {
        ts.extend([k, k.next_down(), k.next_up()]);
    }
    ts.extend([t0 - 1.0, t1 + 1.0, f64::NEG_INFINITY, f64::INFINITY]);
    ts.sort_by(f64::total_cmp);
    let mut shuffled = ts.clone();
    let mut rng = data::Rng(11);
    for i in (1..shuffled.len()).rev() {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "an index below i + 1"
        )]
        let j = (rng.next_f64() * (i + 1) as f64) as usize;
        shuffled.swap(i, j);
    }
    [ts, shuffled]
}

fn check<P: Manifold>(name: &str, c: &dyn Curve<Point = P>)
where
    P::Vector: Bits,
{
    for ts in parameter_sets(c) {
        let first = c.jet(ts[0]);
        let mut points = vec![first.point.clone(); ts.len()];
        let mut jets = vec![first; ts.len()];
        c.eval_many(&ts, &mut points);
        c.jet_many(&ts, &mut jets);
        for (k, &t) in ts.iter().enumerate() {
            assert_eq!(
                points[k].to_vector().bits(),
                c.eval(t).to_vector().bits(),
                "{name}: eval_many differs from eval at t = {t}"
            );
            assert_eq!(
                jet_bits(&jets[k]),
                jet_bits(&c.jet(t)),
                "{name}: jet_many differs from jet at t = {t}"
            );
        }
    }
}

#[test]
fn batch_matches_scalar_bit_for_bit_s2() {
    for (name, c) in s2_curves() {
        check(name, c.as_ref());
    }
}

#[test]
fn batch_matches_scalar_bit_for_bit_s3() {
    for (name, c) in s3_curves() {
        check(name, c.as_ref());
    }
}

#[test]
fn empty_batch_is_fine() {
    for (_, c) in s3_curves() {
        c.eval_many(&[], &mut []);
        c.jet_many(&[], &mut []);
    }
}

#[test]
#[should_panic(expected = "one output slot per parameter")]
fn mismatched_buffer_panics() {
    let c = Squad::try_new(data::keys_s3(5), None).unwrap();
    let mut out = vec![UnitQuat::IDENTITY; 2];
    c.eval_many(&[0.0, 1.0, 2.0], &mut out);
}

/// The geodesic spline evaluates slerp from a precomputed frame: still slerp, bit for bit.
#[test]
fn geodesic_is_slerp_bit_for_bit() {
    let q = data::keys_s3(20);
    let c = GeodesicSpline::try_new(q.clone(), None).unwrap();
    let knots = spherekit::Knots::uniform(20);
    for t in data::params(c.domain(), 5003) {
        let (i, s) = knots.locate(t, spherekit::Side::Right);
        let expected = q[i].slerp(&q[i + 1], s);
        assert_eq!(
            c.eval(t).to_vector().bits(),
            expected.to_vector().bits(),
            "t = {t}"
        );
        assert_eq!(
            c.jet(t).point.to_vector().bits(),
            expected.to_vector().bits(),
            "t = {t}"
        );
    }
}

/// `Bezier` evaluates its first de Casteljau level from precomputed arcs: still
/// `de_casteljau` and `de_casteljau_jet`, bit for bit.
#[test]
fn bezier_is_de_casteljau_bit_for_bit() {
    let q = data::keys_s3(7);
    for ctrl in [q[..2].to_vec(), q[..4].to_vec(), q.clone()] {
        let c = Bezier::try_new(ctrl.clone()).unwrap();
        for t in data::params([0.0, 1.0], 1001).into_iter().chain([0.0, 1.0]) {
            let p = spherekit::de_casteljau(&ctrl, t);
            let j = spherekit::de_casteljau_jet(&ctrl, spherekit::ScalarJet::param(t, 1.0));
            assert_eq!(
                c.eval(t).to_vector().bits(),
                p.to_vector().bits(),
                "t = {t}"
            );
            assert_eq!(jet_bits(&c.jet(t)), jet_bits(&j), "t = {t}");
        }
    }
}
