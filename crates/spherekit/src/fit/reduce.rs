// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Key reduction: the fewest keys among the sample times whose fit stays within `ε` of every
//! sample and of the samples' geodesic interpolation midway between samples.
//!
//! Greedy refinement, then a removal pass:
//! 1. start from the end samples (closed: three samples evenly spread) and a key wherever the
//!    track has turned by a radian since the last key, halving every segment while the
//!    least-squares fit does not converge from the samples at the keys;
//! 2. fit on the keys; in every segment whose largest error (at its samples and midpoints)
//!    exceeds `ε`, make the sample nearest the worst point a key; repeat until no segment
//!    exceeds `ε` (each round at least halves the violating segments' spans, so the rounds are
//!    O(log N), each an O(N) fit);
//! 3. for the keys whose neighbouring segments have the smallest errors (at most 48 of them,
//!    each trial a fit), drop a key if the fit without it is still within `ε`;
//! 4. the same removal from the fewest evenly spread keys whose fit is within `ε` (bisection on
//!    their count, between a third of the keys found and that many), when that ends with fewer.
//!
//! The fit at each step is the least-squares cubic on the keys (λ = 0 unless given).

use super::solve::Samples;
use super::{Fitted, Smoothing};
use crate::ambient::Ambient;
use crate::curve::Curve;
use crate::error::SplineError;
use crate::manifold::{Manifold, slerp_vector};

/// The removal pass tries at most this many keys (each trial is a fit of all samples): the
/// pass stays O(N) fits' worth of work.
const REMOVAL_TRIALS: usize = 48;

/// The starting keys are at most this far apart (radians of turn).
const START_TURN: f64 = 1.0;

/// `m` keys among the samples, spread as evenly as the sample indices allow.
pub(super) fn even_keys<Q: Manifold>(problem: &Samples<Q>, m: usize) -> Vec<usize> {
    let n = problem.points.len();
    let mut idx: Vec<usize> = if problem.closed {
        (0..m).map(|j| (j * n) / m).collect()
    } else {
        // The nearest integer to j(n − 1)/(m − 1), in integers.
        (0..m)
            .map(|j| (2 * j * (n - 1) + (m - 1)) / (2 * (m - 1)))
            .collect()
    };
    idx.dedup();
    idx
}

/// The keys with, for a doubled loop, each key's mirror half a loop away, sorted and distinct.
fn symmetric<Q: Manifold>(problem: &Samples<Q>, mut idx: Vec<usize>) -> Vec<usize> {
    if let Some(half) = problem.half {
        let mirrors: Vec<usize> = idx.iter().map(|&i| (i + half) % (2 * half)).collect();
        idx.extend(mirrors);
    }
    idx.sort_unstable();
    idx.dedup();
    idx
}

/// The starting keys: the ends (closed: three evenly spread samples) and a sample wherever the
/// track has turned by a radian since the last key.
fn start_keys<Q: Manifold>(problem: &Samples<Q>) -> Vec<usize> {
    let n = problem.points.len();
    let mut idx = even_keys(problem, if problem.closed { 3 } else { 2 });
    let mut last = 0;
    for i in 1..n {
        let (a, b) = (&problem.points[last], &problem.points[i]);
        let turn = Q::from_vector_unchecked(a.clone()).dist(&Q::from_vector_unchecked(b.clone()))
            * problem.scale;
        if turn > START_TURN {
            idx.push(i);
            last = i;
        }
    }
    symmetric(problem, idx)
}

/// The largest error of the fit on `idx` in each segment (samples and midpoints), and where.
fn segment_errors<Q: Manifold>(
    problem: &Samples<Q>,
    idx: &[usize],
    fitted: &Fitted<Q::Vector>,
) -> Result<Vec<(f64, usize)>, SplineError> {
    let n = problem.points.len();
    let curve = problem.build(idx, &fitted.keys, fitted.ends.as_ref())?;
    let mut worst = vec![(0.0_f64, 0_usize); idx.len()];
    let mut seg = 0;
    for i in 0..n {
        while seg + 1 < idx.len() && idx[seg + 1] <= i {
            seg += 1;
        }
        // The last sample of an open curve belongs to the last segment.
        let s = if !problem.closed && i == n - 1 {
            idx.len() - 2
        } else {
            seg
        };
        let mut consider = |d: f64, at: usize| {
            if d > worst[s].0 {
                worst[s] = (d, at);
            }
        };
        consider(fitted.dist[i], i);
        let next = if i + 1 < n {
            Some(i + 1)
        } else if problem.closed {
            Some(0)
        } else {
            None
        };
        if let Some(j) = next {
            let (a, b) = (&problem.points[i], &problem.points[j]);
            let b = if problem.sign_free && a.dot(b) < 0.0 {
                b.clone() * -1.0
            } else {
                b.clone()
            };
            let t = 0.5 * (problem.times[i] + problem.times[i + 1]);
            if let Ok(mid) = slerp_vector(a, &b, 0.5) {
                let c = curve.eval(t).to_vector();
                let c = if problem.sign_free && c.dot(&mid) < 0.0 {
                    c * -1.0
                } else {
                    c
                };
                let d = Q::from_vector_unchecked(c).dist(&Q::from_vector_unchecked(mid))
                    * problem.scale;
                let at = if fitted.dist[i] >= fitted.dist[j] {
                    i
                } else {
                    j
                };
                consider(d, at);
            }
        }
    }
    Ok(worst)
}

/// The fewest keys within `eps` (module docs), and the fit on them.
pub(super) fn reduce<Q: Manifold>(
    problem: &Samples<Q>,
    eps: f64,
    smoothing: &Smoothing,
) -> Result<Fitted<Q::Vector>, SplineError> {
    let n = problem.points.len();
    let idx = start_keys(problem);
    let mut iterations = 0;
    let (mut idx, mut fitted) = fit_or_halve(problem, idx, smoothing)?;
    iterations += fitted.report.iterations;
    loop {
        let worst = segment_errors(problem, &idx, &fitted)?;
        let mut added: Vec<usize> = worst
            .iter()
            .filter(|(d, at)| *d > eps && !idx.contains(at))
            .map(|&(_, at)| at)
            .collect();
        if added.is_empty() {
            // Every violating segment's worst point is a key (cannot be refined further there):
            // refine at its neighbours.
            for (s, &(d, at)) in worst.iter().enumerate() {
                if d > eps {
                    let (lo, hi) = (idx[s], if s + 1 < idx.len() { idx[s + 1] } else { n });
                    if hi > lo + 1 {
                        added.push((lo + hi) / 2);
                    }
                    let _ = at;
                }
            }
        }
        if added.is_empty() {
            break;
        }
        idx.extend(added);
        idx = symmetric(problem, idx);
        (idx, fitted) = fit_or_halve(problem, idx, smoothing)?;
        iterations += fitted.report.iterations;
        if idx.len() == n {
            break;
        }
    }
    let (mut idx, mut fitted) =
        removal_pass(problem, eps, smoothing, idx, fitted, &mut iterations)?;
    // Least squares on evenly spread keys sometimes needs fewer: the fewest such keys within ε,
    // by bisection on their count below the refinement's, then their removal pass; the fewer
    // keys win.
    let per = n / problem.given();
    let mut hi = idx.len() / per;
    // (Below a third of the refinement's keys a fit converges slowly, and never suffices.)
    let mut lo = (if problem.closed { 3 } else { 2 }).max(hi / 3);
    let mut even_best = None;
    while lo < hi {
        let mid = (lo + hi) / 2;
        let even = even_keys(problem, mid * per);
        let within = match problem.fitted(&even, smoothing, None) {
            Ok(f) => {
                iterations += f.report.iterations;
                let within = segment_errors(problem, &even, &f)?
                    .iter()
                    .all(|&(d, _)| d <= eps);
                if within {
                    even_best = Some((even, f));
                }
                within
            }
            Err(_) => false,
        };
        if within {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    if let Some((even, f)) = even_best {
        let (even, f) = removal_pass(problem, eps, smoothing, even, f, &mut iterations)?;
        if even.len() < idx.len() {
            (idx, fitted) = (even, f);
        }
    }
    let worst = segment_errors(problem, &idx, &fitted)?;
    fitted.report.max = worst.iter().fold(fitted.report.max, |m, &(d, _)| m.max(d));
    fitted.report.iterations = iterations;
    Ok(fitted)
}

/// The removal pass: for the keys whose neighbouring segments have the most room (at most
/// [`REMOVAL_TRIALS`]), drop a key when the fit without it stays within `eps`.
fn removal_pass<Q: Manifold>(
    problem: &Samples<Q>,
    eps: f64,
    smoothing: &Smoothing,
    mut idx: Vec<usize>,
    mut fitted: Fitted<Q::Vector>,
    iterations: &mut usize,
) -> Result<(Vec<usize>, Fitted<Q::Vector>), SplineError> {
    // The removal pass, from the keys whose neighbouring segments have the most room.
    let worst = segment_errors(problem, &idx, &fitted)?;
    let first_removable = 1;
    let last_removable = if problem.closed {
        idx.len()
    } else {
        idx.len() - 1
    };
    let mut order: Vec<(f64, usize)> = (first_removable..last_removable)
        .map(|k| (worst[k - 1].0.max(worst[k].0), idx[k]))
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    let min = (if problem.closed { 3 } else { 2 }) * if problem.half.is_some() { 2 } else { 1 };
    for (_, key) in order.into_iter().take(REMOVAL_TRIALS) {
        if idx.len() <= min {
            break;
        }
        // A doubled loop drops a key and its mirror together.
        let mirror = problem.half.map_or(key, |h| (key + h) % (2 * h));
        if mirror == idx[0] {
            continue;
        }
        let trial: Vec<usize> = idx
            .iter()
            .copied()
            .filter(|&i| i != key && i != mirror)
            .collect();
        let start = trial.iter().map(|&i| problem.points[i].clone()).collect();
        let Ok(f) = problem.fitted(&trial, smoothing, Some(start)) else {
            continue;
        };
        *iterations += f.report.iterations;
        let w = segment_errors(problem, &trial, &f)?;
        if w.iter().all(|&(d, _)| d <= eps) {
            idx = trial;
            fitted = f;
        }
    }
    Ok((idx, fitted))
}

/// The fit on the keys `idx`; while it does not converge from the samples at the keys (keys far
/// apart), every segment halved.
fn fit_or_halve<Q: Manifold>(
    problem: &Samples<Q>,
    mut idx: Vec<usize>,
    smoothing: &Smoothing,
) -> Result<(Vec<usize>, Fitted<Q::Vector>), SplineError> {
    let n = problem.points.len();
    loop {
        match problem.fitted(&idx, smoothing, None) {
            Ok(f) => return Ok((idx, f)),
            Err(e) if idx.len() == n => return Err(e),
            Err(_) => {
                let mids: Vec<usize> = idx
                    .windows(2)
                    .map(|w| (w[0] + w[1]) / 2)
                    .chain(idx.last().map(|&l| (l + n) / 2).filter(|_| problem.closed))
                    .collect();
                idx.extend(mids);
                idx = symmetric(problem, idx);
            }
        }
    }
}
