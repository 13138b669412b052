// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Loops of rotations closed in SO(3) ([`RotationLoop`]): camera orbits of one full turn (and
//! of two) with every construction that closes on S³, with and without wobble, both ways
//! round; the loop ends at `−q₀`, its seam is as smooth as its other joints up to the sign, it
//! interpolates its keys, its derivatives are exact, `Cycle` continues it antiperiodically, and
//! the doubled construction it is cut from is antiperiodic (the symmetry argument, checked).

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    clippy::cast_precision_loss,
    reason = "tests: a panic is the failure report"
)]

use core::f64::consts::TAU;

use spherekit::glam::DVec3;
use spherekit::{
    ArcBlend, BetaParams, BetaSpline, BsplineKim, CatmullRom, CatmullRomNlerp,
    CornerBlendRotations, CubicEnd, CubicSpline, Curve, Extrapolate, Extrapolated, GammaSpline,
    Gammas, GeodesicSpline, Manifold, NlerpSpline, RotationLoop, Side, SplineError, Squad,
    UnitQuat, closes_at_antipode, continuity, unflip,
};

use crate::support::{Rng, check_derivatives};

/// What a construction guarantees at its joints (and so at the seam).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Smooth {
    C0,
    C1,
    C2,
}

/// A closed constructor on S³ as `RotationLoop::try_new` takes it.
type Build =
    fn(Vec<UnitQuat>, Option<Vec<f64>>) -> Result<Box<dyn Curve<Point = UnitQuat>>, SplineError>;

/// Every construction that closes on S³: its name, constructor, whether it interpolates the
/// keys at their knots, whether it takes knots, and its smoothness at joints.
fn constructions() -> Vec<(&'static str, Build, bool, bool, Smooth)> {
    fn boxed<C: Curve<Point = UnitQuat> + 'static>(
        c: Result<C, SplineError>,
    ) -> Result<Box<dyn Curve<Point = UnitQuat>>, SplineError> {
        c.map(|c| Box::new(c) as Box<dyn Curve<Point = UnitQuat>>)
    }
    vec![
        (
            "geodesic",
            |k, t| boxed(GeodesicSpline::try_new_closed(k, t)),
            true,
            true,
            Smooth::C0,
        ),
        (
            "nlerp",
            |k, t| boxed(NlerpSpline::try_new_closed(k, t)),
            true,
            true,
            Smooth::C0,
        ),
        (
            "squad",
            |k, t| boxed(Squad::try_new_closed(k, t)),
            true,
            true,
            Smooth::C1,
        ),
        (
            "catmull-rom",
            |k, t| boxed(CatmullRom::try_new_closed(k, t)),
            true,
            true,
            Smooth::C1,
        ),
        (
            "catmull-rom (quaternion)",
            |k, t| boxed(CatmullRom::try_new_quaternion_closed(k, t)),
            true,
            true,
            Smooth::C1,
        ),
        (
            "catmull-rom-nlerp",
            |k, t| boxed(CatmullRomNlerp::try_new_closed(k, t)),
            true,
            true,
            Smooth::C1,
        ),
        (
            "cubic",
            |k, t| boxed(CubicSpline::try_new(k, t, CubicEnd::Natural, true)),
            true,
            true,
            Smooth::C2,
        ),
        (
            "gamma",
            |k, t| boxed(GammaSpline::try_new_closed(k, t, Gammas::All(1.0))),
            false,
            true,
            Smooth::C1,
        ),
        (
            "bspline-kim",
            |k, _| boxed(BsplineKim::try_new_closed(k)),
            false,
            false,
            Smooth::C2,
        ),
        (
            "beta",
            |k, _| boxed(BetaSpline::try_new_closed(k, &BetaParams::default())),
            true,
            false,
            Smooth::C1,
        ),
        (
            "arc-blend",
            |k, _| boxed(ArcBlend::try_new_closed(k, 2)),
            true,
            false,
            Smooth::C2,
        ),
        (
            "corner-blend",
            |k, _| boxed(CornerBlendRotations::try_new_closed(k, 2, 0.5)),
            false,
            false,
            Smooth::C2,
        ),
    ]
}

/// An orbit of `turns` full turns about z (negative: the other way) in `n` keys, with a pitch
/// and roll wobble of up to `wobble` radians, as shortest steps (`unflip`).
fn orbit(n: usize, turns: f64, wobble: f64, rng: &mut Rng) -> Vec<UnitQuat> {
    let mut keys: Vec<UnitQuat> = (0..n)
        .map(|k| {
            let yaw =
                UnitQuat::from_axis_angle(DVec3::Z, turns * TAU * k as f64 / n as f64).unwrap();
            let pitch = UnitQuat::from_axis_angle(DVec3::Y, wobble * rng.range(-1.0, 1.0)).unwrap();
            let roll = UnitQuat::from_axis_angle(DVec3::X, wobble * rng.range(-1.0, 1.0)).unwrap();
            yaw * pitch * roll
        })
        .collect();
    unflip(&mut keys);
    keys
}

/// The rotation distance between two quaternions (0 for `q` and `−q`).
fn rotation_distance(a: UnitQuat, b: UnitQuat) -> f64 {
    2.0 * a.as_dquat().dot(b.as_dquat()).abs().min(1.0).acos()
}

/// The checks of a loop of rotations: closed, ends at `∓q₀` as its keys turn by an odd or even
/// number of turns, the seam as smooth as `smooth` (as are the other joints), keys hit,
/// derivatives exact, `Cycle` continues it with the sign of the lap.
#[track_caller]
fn check_rotation_loop(
    name: &str,
    c: &RotationLoop<Box<dyn Curve<Point = UnitQuat>>>,
    keys: &[UnitQuat],
    knots: Option<&[f64]>,
    smooth: Smooth,
) {
    let odd = closes_at_antipode(keys);
    assert!(c.is_closed(), "{name}: closed");
    assert_eq!(
        c.is_antiperiodic(),
        odd,
        "{name}: antiperiodic iff odd turns"
    );
    let [t0, t1] = c.domain();
    if let Some(k) = knots {
        assert_eq!(
            [t0, t1],
            [k[0], k[keys.len()]],
            "{name}: domain is the keys' period"
        );
    }
    // The end is the start's rotation, as the quaternion −q₀ when the turns are odd.
    let (start, end) = (c.eval(t0), c.eval(t1));
    let sign = if odd { -1.0 } else { 1.0 };
    let d = (end.as_dquat() - start.as_dquat() * sign).length();
    assert!(
        d <= 1e-12,
        "{name}: ends at {}q₀: {d:e}",
        if odd { "−" } else { "+" }
    );
    // Every joint and the seam (last) as smooth as the construction promises.
    let report = continuity(c);
    assert_eq!(
        report.len(),
        c.joints().len() - 1,
        "{name}: every joint and the seam"
    );
    assert_eq!(report[report.len() - 1].t, t1, "{name}: seam last");
    for j in &report {
        let l = c.jet_at(j.t, Side::Left);
        let (v, a) = (
            l.velocity.length().max(1e-300),
            l.acceleration.length().max(1e-300),
        );
        let at = if j.t == t1 { "seam" } else { "joint" };
        assert!(
            j.c0 <= 1e-12,
            "{name}: C⁰ at the {at} t = {}: {:e}",
            j.t,
            j.c0
        );
        match smooth {
            Smooth::C0 => {}
            Smooth::C1 => assert!(
                j.c1 / v <= 1e-9,
                "{name}: C¹ at the {at} t = {}: {:e}",
                j.t,
                j.c1 / v
            ),
            Smooth::C2 => assert!(
                j.c1 / v <= 1e-9 && j.c2 / a <= 1e-8,
                "{name}: C² at the {at} t = {}: {:e} {:e}",
                j.t,
                j.c1 / v,
                j.c2 / a
            ),
        }
    }
    if let Some(k) = knots {
        for (i, (q, &t)) in keys.iter().zip(k).enumerate() {
            let d = c.eval(t).dist(q);
            assert!(d <= 1e-11, "{name}: key {i}: {d:e}");
        }
    }
    check_derivatives(c, 24);
    // Cycle: one period on, the same rotations; as quaternions the sign of the lap.
    let cyc = Extrapolated::new(c, Extrapolate::Cycle);
    let period = t1 - t0;
    for k in 1..=3 {
        let t = t0 + 0.3 * period;
        let (here, there) = (c.jet(t), cyc.jet(t + f64::from(k) * period));
        let s = if odd && k % 2 == 1 { -1.0 } else { 1.0 };
        let d = (there.point.as_dquat() - here.point.as_dquat() * s).length()
            + (there.velocity - here.velocity * s).length();
        assert!(d <= 1e-9, "{name}: cycle lap {k}: {d:e}");
        // Continuous across the lap boundary, from either side.
        let b = t0 + f64::from(k) * period;
        let (l, r) = (cyc.jet_at(b, Side::Left), cyc.jet_at(b, Side::Right));
        let d = (l.point.as_dquat() - r.point.as_dquat()).length();
        assert!(d <= 1e-12, "{name}: cycle continuous at lap {k}: {d:e}");
    }
}

#[test]
fn full_turn_orbits_close_in_so3_with_every_construction() {
    let mut rng = Rng::new(34);
    for (name, build, interpolates, takes_knots, smooth) in constructions() {
        for n in [3_usize, 4, 8, 16, 32] {
            for turns in [1.0, -1.0, 2.0] {
                for wobble in [0.0, 5f64.to_radians()] {
                    if turns == 2.0 && n <= 4 {
                        // Two turns in three or four keys are steps of 240° or 180°: no loop of
                        // shortest steps.
                        continue;
                    }
                    let keys = orbit(n, turns, wobble, &mut rng);
                    let knots: Option<Vec<f64>> = takes_knots.then(|| {
                        let mut t = 0.0;
                        (0..=n)
                            .map(|k| {
                                if k > 0 {
                                    t += rng.range(0.6, 1.4);
                                }
                                t
                            })
                            .collect()
                    });
                    let label = format!("{name}, {n} keys, {turns} turns, wobble {wobble:.3}");
                    let c = RotationLoop::try_new(keys.clone(), knots.clone(), build)
                        .unwrap_or_else(|e| panic!("{label}: {e}"));
                    assert_eq!(
                        c.is_antiperiodic(),
                        turns == 1.0 || turns == -1.0,
                        "{label}"
                    );
                    // Without knots an interpolating construction hits the keys at its joints.
                    let knots = knots.or_else(|| interpolates.then(|| c.joints().to_vec()));
                    let knots = if interpolates { knots.as_deref() } else { None };
                    check_rotation_loop(&label, &c, &keys, knots, smooth);
                }
            }
        }
    }
}

/// The doubled construction is antiperiodic, `c(t + T) = −c(t)`: by symmetry, for the local
/// constructions, and for the global solves (cubic, Beta, arc blend) because their solution is
/// unique; measured here on the doubled curve itself.
#[test]
fn the_doubled_loop_is_antiperiodic() {
    let mut rng = Rng::new(35);
    for (name, build, ..) in constructions() {
        let keys = orbit(8, 1.0, 10f64.to_radians(), &mut rng);
        let c = RotationLoop::try_new(keys, None, build).unwrap();
        let doubled = c.inner();
        let [s0, s1] = doubled.domain();
        let period = c.domain()[1] - c.domain()[0];
        assert!(
            (s1 - s0 - 2.0 * period).abs() <= 1e-12 * period,
            "{name}: doubled period"
        );
        let mut worst: f64 = 0.0;
        for k in 0..50 {
            let t = s0 + period * (k as f64 + 0.5) / 50.0;
            let (a, b) = (doubled.jet(t), doubled.jet(t + period));
            let e = (a.point.as_dquat() + b.point.as_dquat()).length()
                + (a.velocity + b.velocity).length() / a.velocity_scale()
                + (a.acceleration + b.acceleration).length() / a.acceleration_scale();
            worst = worst.max(e);
        }
        assert!(worst <= 1e-9, "{name}: c(t + T) + c(t) = {worst:e}");
    }
}

/// On an evenly spaced orbit the cubic turns at a constant rate, 2π/T, all the way round,
/// seam included (the acceptance: within 1 %).
#[test]
fn evenly_spaced_orbit_cubic_turns_at_a_constant_rate() {
    let mut rng = Rng::new(36);
    for n in [3_usize, 4, 8, 16, 32] {
        let keys = orbit(n, 1.0, 0.0, &mut rng);
        let period = 2.0 * n as f64;
        let knots: Vec<f64> = (0..=n).map(|k| period * k as f64 / n as f64).collect();
        let c = RotationLoop::try_new(keys, Some(knots), |k, t| {
            CubicSpline::try_new(k, t, CubicEnd::Natural, true)
        })
        .unwrap();
        let target = TAU / period;
        let (mut lo, mut hi) = (f64::MAX, 0.0_f64);
        for k in 0..=400 {
            let w = 2.0 * c.jet(period * f64::from(k) / 400.0).velocity.length();
            lo = lo.min(w);
            hi = hi.max(w);
        }
        assert!(
            (hi / target - 1.0).abs() <= 0.01 && (lo / target - 1.0).abs() <= 0.01,
            "{n} keys: angular speed in [{lo}, {hi}], 2π/T = {target}"
        );
    }
}

/// Keys that close at `+q₀` (an even number of turns, or no turn) are built as they are: the
/// loop is the closed curve itself, bit for bit.
#[test]
fn even_turn_loops_are_the_closed_curve_itself() {
    let mut rng = Rng::new(37);
    let keys = orbit(8, 2.0, 5f64.to_radians(), &mut rng);
    let plain = CubicSpline::try_new(keys.clone(), None, CubicEnd::Natural, true).unwrap();
    let looped = RotationLoop::try_new(keys, None, |k, t| {
        CubicSpline::try_new(k, t, CubicEnd::Natural, true)
    })
    .unwrap();
    assert!(!looped.is_antiperiodic());
    assert_eq!(looped.domain(), plain.domain());
    for k in 0..=80 {
        let t = 8.0 * f64::from(k) / 80.0;
        assert_eq!(looped.jet(t), plain.jet(t));
    }
}

/// The batch calls give the single calls' values bit for bit, the end of the loop (where the
/// doubled curve goes on) included.
#[test]
fn batch_evaluation_matches_single_calls_up_to_the_end() {
    let mut rng = Rng::new(38);
    let keys = orbit(5, 1.0, 0.1, &mut rng);
    let c = RotationLoop::try_new(keys, None, Squad::try_new_closed).unwrap();
    for ts in [
        (0..50)
            .map(|k| 5.0 * f64::from(k) / 50.0)
            .collect::<Vec<_>>(),
        (0..=50).map(|k| 5.0 * f64::from(k) / 50.0).collect(),
        vec![-1.0, 5.0, 7.0, f64::NAN, 2.5],
    ] {
        let mut points = vec![UnitQuat::IDENTITY; ts.len()];
        c.eval_many(&ts, &mut points);
        let mut jets = vec![c.jet(0.0); ts.len()];
        c.jet_many(&ts, &mut jets);
        for (k, &t) in ts.iter().enumerate() {
            assert_eq!(points[k], c.eval(t), "eval at {t}");
            assert_eq!(jets[k], c.jet(t), "jet at {t}");
        }
    }
    // Past the end: the end from the left, −q₀ (not the doubled curve's second half).
    assert!(rotation_distance(c.eval(9.0), c.eval(0.0)) <= 1e-12);
    assert!((c.eval(9.0).as_dquat() + c.eval(0.0).as_dquat()).length() <= 1e-12);
}

/// A wrong knot count reaches the constructor as given, so that its error is the caller's
/// count, not the doubled one.
#[test]
fn wrong_knot_count_is_reported_for_the_keys_given() {
    let mut rng = Rng::new(39);
    let keys = orbit(4, 1.0, 0.0, &mut rng);
    let e = RotationLoop::try_new(keys, Some(vec![0.0, 1.0, 2.0]), |k, t| {
        CubicSpline::try_new(k, t, CubicEnd::Natural, true)
    })
    .unwrap_err();
    assert!(
        e.to_string().contains('5'),
        "names the count the keys need: {e}"
    );
}

/// Velocity and acceleration sizes with a floor, for relative errors.
trait Scales {
    fn velocity_scale(&self) -> f64;
    fn acceleration_scale(&self) -> f64;
}

impl Scales for spherekit::Jet<UnitQuat> {
    fn velocity_scale(&self) -> f64 {
        self.velocity.length().max(1.0)
    }

    fn acceleration_scale(&self) -> f64 {
        self.acceleration.length().max(1.0)
    }
}
