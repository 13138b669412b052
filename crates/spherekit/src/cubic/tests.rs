// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

use super::equations::{Geometry, SegConst, norm};
use super::fixed::{FixedSolver, Vf, invertf, vf};
use super::*;
use crate::banded::dot;
use crate::banded::{invert, mat_mul};
use crate::recast::keys;
use glam::DMat3;

/// The `compact` build constructs on S^m and converts back; every field (and every error) must
/// be what the construction on the point type itself gives, bit for bit (`{:?}` prints
/// each `f64` in the shortest form that reads back to the same bits).
#[test]
fn the_construction_gives_the_same_bits_on_sm() {
    fn check<P: Manifold>(points: &[P]) -> usize {
        let mut built = 0;
        let n = points.len();
        // A tangent velocity at each end key, and one that is not tangent.
        let tangent = |p: &P, s: f64| {
            let v = p.to_vector();
            let raw = v.with_coords(
                &(0..v.dim())
                    .map(|i| s * (1.0 + i as f64))
                    .collect::<Vec<_>>(),
            );
            p.project_tangent(&raw)
        };
        let ends = [
            CubicEnd::Natural,
            CubicEnd::Scipy,
            CubicEnd::Clamped {
                start_velocity: tangent(&points[0], 0.3),
                end_velocity: tangent(&points[n - 1], -0.7),
            },
            CubicEnd::Clamped {
                start_velocity: points[0].to_vector(),
                end_velocity: tangent(&points[n - 1], 0.2),
            },
        ];
        for closed in [false, true] {
            let count = n + usize::from(closed);
            let uneven: Vec<f64> = (0..count)
                .map(|i| (i * i) as f64 * 0.7 + i as f64)
                .collect();
            for knots in [None, Some(uneven)] {
                for end in &ends {
                    let native = CubicSpline::construct(
                        points.to_vec(),
                        knots.clone(),
                        end.clone(),
                        closed,
                        None,
                    );
                    let on_sm = CubicSpline::construct_on_sm(
                        points.to_vec(),
                        knots.clone(),
                        end.clone(),
                        closed,
                        None,
                    );
                    built += keys::same_bits(&native, &on_sm, &points);
                }
                // Hermite: a velocity given at every key.
                let given: Vec<P::Vector> = points
                    .iter()
                    .enumerate()
                    .map(|(k, p)| tangent(p, 0.2 * (k as f64 + 1.0)))
                    .collect();
                let end = CubicEnd::Natural;
                let native = CubicSpline::construct(
                    points.to_vec(),
                    knots.clone(),
                    end.clone(),
                    closed,
                    Some(given.clone()),
                );
                let on_sm = CubicSpline::construct_on_sm(
                    points.to_vec(),
                    knots.clone(),
                    end,
                    closed,
                    Some(given),
                );
                built += keys::same_bits(&native, &on_sm, &points);
            }
        }
        built
    }
    let built = keys::built(check, check);
    assert!(built > 50, "{built} curves built");
}

/// A random system of continuity equations: `n` keys, tangent dimension `m`, segment
/// angles up to 2 rad and widths from 0.05 to 5 (spacings 100 apart), random directions,
/// a random holonomy when closed, random fixed end velocities when `fixed`.
fn random_geometry(seed: u64, n: usize, m: usize, closed: bool, fixed: bool) -> Geometry {
    let mut state = seed;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let unit = |next: &mut dyn FnMut() -> f64| {
        let v: Vec<f64> = (0..m).map(|_| next() - 0.5).collect();
        let l = norm(&v);
        v.into_iter().map(|a| a / l).collect::<Vec<_>>()
    };
    let nseg = n - usize::from(!closed);
    let mut seg = Vec::new();
    let mut ehat = Vec::new();
    for _ in 0..nseg {
        let theta = 0.01 + 1.99 * next();
        let h = 0.05 + 4.95 * next();
        seg.push(SegConst::new(theta, h, theta.sin_cos()));
        ehat.extend(unit(&mut next));
    }
    // An orthogonal holonomy: Gram–Schmidt of random columns.
    let mut hol = Vec::new();
    if closed {
        let mut cols: Vec<Vec<f64>> = Vec::new();
        while cols.len() < m {
            let mut v = unit(&mut next);
            for c in &cols {
                let d = dot(c, &v);
                v.iter_mut().zip(c).for_each(|(a, b)| *a -= d * b);
            }
            let l = norm(&v);
            cols.push(v.into_iter().map(|a| a / l).collect());
        }
        hol = (0..m * m).map(|i| cols[i % m][i / m]).collect();
    }
    let fixed = fixed.then(|| {
        let g0: Vec<f64> = unit(&mut next).into_iter().map(|a| 0.7 * a).collect();
        let g1: Vec<f64> = unit(&mut next).into_iter().map(|a| 1.3 * a).collect();
        (g0, g1)
    });
    Geometry {
        n,
        m,
        closed,
        seg,
        ehat,
        hol,
        fixed,
    }
}

/// The chord steps' residuals come from the exact quadratic update, not from evaluating
/// the equations: the reported residual must bound the one the equations give at the
/// solution (evaluated by a fresh sweep) and be close to it, and the solution must be the
/// slice solver's (which evaluates every step).
#[test]
fn chord_residual_updates_equal_the_evaluated_residual() {
    let (mut checked, mut compared) = (0, 0);
    for case in 0..40_usize {
        let m = 1 + case % 3;
        let closed = case % 4 == 3;
        let fixed = !closed && case % 2 == 1;
        let n = 3 + (case * 7) % 40;
        let seed = case as u64;
        let geo = random_geometry(seed, n, m, closed, fixed);
        let Ok((x, info)) = FixedSolver::new(&geo).solve() else {
            continue;
        };
        let xv: Vec<Vf> = x
            .chunks_exact(m)
            .map(|c| vf(|a| if a < m { c[a] } else { 0.0 }))
            .collect();
        let mut z = vec![Vf::ZERO; n];
        let evaluated = FixedSolver::new(&geo)
            .sweep(&mut xv.clone(), &mut z, None)
            .unwrap_or(f64::INFINITY);
        assert!(
            info.residual <= TARGET_RESIDUAL && evaluated <= TARGET_RESIDUAL,
            "seed {seed}: reported {:e}, evaluated {evaluated:e}",
            info.residual
        );
        // The reported residual of a chord step bounds the evaluated one (up to the rounding
        // of the solve, which the update leaves out); it is about as large (within 3× on
        // these systems, 0.1–12 % on most).
        assert!(
            evaluated <= 1.25 * info.residual + 1e-15 && info.residual <= 4.0 * evaluated + 1e-15,
            "seed {seed}: reported {:e}, evaluated {evaluated:e}",
            info.residual
        );
        checked += 1;
        // (The slice solver, without the correction step, fails on a few systems that
        // this one solves.)
        let Ok((y, _)) = geo.solve() else {
            continue;
        };
        let scale = y.iter().fold(1.0_f64, |s, v| s.max(v.abs()));
        for (a, b) in x.iter().zip(&y) {
            assert!((a - b).abs() <= 1e-11 * scale, "seed {seed}: {a} vs {b}");
        }
        compared += 1;
    }
    assert!(checked >= 30, "only {checked} of 40 systems converged");
    assert!(compared >= 25, "only {compared} of 40 systems compared");
}

/// The correction after the linear step ([`FixedSolver::correct`]) brings the first
/// iterate closer: the residual where Newton's first factorisation is evaluated falls.
#[test]
fn the_correction_brings_the_first_iterate_closer() {
    let mut ratios = Vec::new();
    for case in 0..40_usize {
        let (m, fixed, n) = (1 + case % 3, case % 2 == 1, 3 + (case * 7) % 40);
        let geo = random_geometry(100 + case as u64, n, m, false, fixed);
        let residual_at = |correct: bool| {
            let mut solver = FixedSolver::new(&geo);
            let (mut x, mut z) = (vec![Vf::ZERO; n], vec![Vf::ZERO; n]);
            let (mut piv, mut ul) = (vec![0.0; n], vec![0.0; n]);
            solver.linear_step(&mut x, &mut piv, &mut z, &mut ul);
            let ul = correct.then_some(&ul[..]);
            solver.sweep(&mut x, &mut z, ul).unwrap_or(f64::INFINITY)
        };
        let (plain, corrected) = (residual_at(false), residual_at(true));
        if plain > 1e-12 {
            ratios.push(corrected / plain);
        }
    }
    // On these systems (angles to 2 rad, widths 0.05–5: far from the linear solution) it
    // halves the residual typically, by 5× at best, 13 % worse at worst; on the benchmarks'
    // keys by 30× (`BENCHMARKS.md`).
    ratios.sort_by(f64::total_cmp);
    assert!(ratios.len() >= 20, "{ratios:?}");
    assert!(ratios[ratios.len() / 2] < 0.6, "{ratios:?}");
    assert!(
        ratios[0] < 0.25 && ratios[ratios.len() - 1] < 1.2,
        "{ratios:?}"
    );
}

#[test]
fn invert_roundtrip() {
    let a = [4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.1, 0.3, 2.0];
    let mut inv = [0.0; 9];
    assert!(invert(3, &a, &mut inv), "invertible");
    let mut id = [0.0; 9];
    mat_mul(3, &a, &inv, &mut id);
    // The fixed solver's adjugate inverse agrees to rounding, and refuses singular blocks.
    // (`from_cols_array_2d` reads columns: the transpose of the rows is the block.)
    let block = |rows: [[f64; 3]; 3]| DMat3::from_cols_array_2d(&rows).transpose();
    let rows = [[a[0], a[1], a[2]], [a[3], a[4], a[5]], [a[6], a[7], a[8]]];
    let adj = invertf(&block(rows)).expect("invertible");
    for (x, y) in adj.transpose().to_cols_array().iter().zip(&inv) {
        assert!((x - y).abs() < 1e-15, "adjugate {x} vs {y}");
    }
    assert!(
        invertf(&block([[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 0.0, 1.0]])).is_none(),
        "singular, rank 2"
    );
    assert!(invertf(&DMat3::ZERO).is_none(), "zero block");
    for i in 0..3 {
        for j in 0..3 {
            let e = if i == j { 1.0 } else { 0.0 };
            assert!((id[i * 3 + j] - e).abs() < 1e-15, "A·A⁻¹ = I");
        }
    }
}
