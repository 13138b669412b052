// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The least-squares cubic on given key times for a given λ: Gauss–Newton on the keys, with the
//! key velocities as unknowns tied by the continuity equations, each step a banded KKT system.
//!
//! Unknowns per key `k`: the step `δpₖ` of the key in its tangent space and the step `δVₖ` of
//! its velocity (coordinates in an orthonormal frame `Eₖ` of `T_{pₖ}`), and the multiplier
//! `μₖ` of the key's continuity row. Residuals: `s·√wᵢ·Log_{yᵢ}(c(tᵢ))` per sample and
//! `s·√λ·(2b + 3c, √3·c)/h^{3/2}` per segment (whose squares sum to `s²λ∫|v″|²`, `s` the speed
//! scale); constraints: the tangential acceleration jump at every interior key (every key of a
//! closed curve), and the tangential acceleration at the two ends of an open curve with a key at
//! every sample (natural ends). On fewer keys an open curve's end velocities may be free
//! ([`Samples::free_ends`]; the least-squares curve among all cubics on the keys, clamped at the
//! fitted velocities): no end rows, and the end velocities' steps are taken with the keys'.
//! Every residual of segment `k` depends on keys `k` and `k + 1` only, every constraint row on
//! keys `k − 1 … k + 1`, so the KKT matrix ordered by key, `[δpₖ, δVₖ, μₖ]`, is block
//! tridiagonal (cyclic when closed) with blocks of `3d` (`d` the tangent dimension), factorised
//! by [`BlockTridiagonal`] in O(n). The Jacobian of each segment's residuals and constraints is
//! taken by central differences in its `4d` unknowns.
//!
//! Each iterate is feasible: the keys are retracted (`pₖ ← Exp_{pₖ}(α·Eₖδpₖ)`) and the
//! velocities re-solved by the cubic's own construction, so the step is the Gauss–Newton step
//! of the objective as a function of the keys alone (with free ends, of the keys and the two end
//! velocities; the KKT elimination of `δV` is the exact derivative of the velocity solve),
//! computed in O(n) without its dense Jacobian. A backtracking line search on the objective
//! keeps every step a descent.

use crate::ambient::Ambient;
use crate::banded::BlockTridiagonal;
use crate::cubic::{CubicEnd, CubicSpline, Segment};
use crate::error::{SolveError, SplineError};
use crate::manifold::{Manifold, exp_vector, geodesic_frame_sin_cos, renormalize};
use crate::math;

/// Gauss–Newton steps at most.
const MAX_ITERATIONS: usize = 100;
/// Converged when the decrease the linear model predicts is at most this fraction of the
/// objective (the squared Newton decrement, relative): below the objective's own rounding.
/// The step is then still taken when it does not increase the objective.
pub(crate) const DECREMENT: f64 = 1e-15;
/// A step that decreases the objective by at most this fraction of it ends the iteration.
const STALL: f64 = 1e-13;

/// How a solve stops.
#[derive(Clone, Copy)]
pub(crate) enum Until {
    /// Converged ([`DECREMENT`]); an error after [`MAX_ITERATIONS`].
    Converged,
    /// After this many Gauss–Newton steps (or converged before): the fits a search for λ tries
    /// from the keys of a nearby λ, whose score needs the objective to about 1e-10 of itself,
    /// which one or two steps from there give; the chosen λ's fit is then finished to
    /// convergence.
    Steps(usize),
}
/// The central-difference step, radians (scaled by the velocity's size for velocities).
const STEP: f64 = 1e-6;
/// A predicted decrease below this fraction of the objective is at the accuracy of the
/// differenced Jacobians: a line search that finds no decrease there ends the iteration (the
/// objective is then within about this fraction of its minimum).
const ROUNDING: f64 = 1e-10;

/// The samples of a fit and how distances are measured.
pub(crate) struct Samples<P: Manifold> {
    pub(crate) points: Vec<P::Vector>,
    /// The sample times (closed: one more, the time of the return to the first sample).
    pub(crate) times: Vec<f64>,
    pub(crate) weights: Vec<f64>,
    pub(crate) closed: bool,
    /// The distance's scale (`SPEED_SCALE`: 2 on S³, whose distance is the rotation angle).
    pub(crate) scale: f64,
    /// Samples are rotations: `±y` is the same sample (S³).
    pub(crate) sign_free: bool,
    /// The samples are a doubled antiperiodic loop (the samples given, then their antipodes one
    /// period later) of this many samples given.
    pub(crate) half: Option<usize>,
}

/// Where a solve starts: keys (and whether the end velocities are free, [`Samples::free_ends`]),
/// or a fit on the same keys for another λ (whose curve, residual and energy do not depend on λ,
/// so the search for λ does not rebuild them; its ends free when clamped).
pub(crate) enum Start<P: Manifold> {
    Keys(Vec<P::Vector>, bool),
    Fit(Solved<P>),
}

/// A fit on given key times.
#[derive(Clone)]
pub(crate) struct Solved<P: Manifold> {
    pub(crate) curve: CubicSpline<P>,
    /// `Σ wᵢ d(c(tᵢ), yᵢ)²` and the energy `E` (both in the scaled units).
    pub(crate) rss: f64,
    pub(crate) energy: f64,
    pub(crate) iterations: usize,
}

impl<P: Manifold> Samples<P> {
    /// The sample indices of segment `k` of the keys `idx`, and the segment's time span: the
    /// samples from key `k` up to the next key (the last segment of an open curve includes its
    /// end key).
    fn segment_samples(&self, idx: &[usize], k: usize) -> (core::ops::Range<usize>, f64, f64) {
        let n = idx.len();
        let count = self.points.len();
        let first = idx[k];
        let (last, t1) = if k + 1 < n {
            let last = if !self.closed && k + 2 == n {
                idx[k + 1] + 1
            } else {
                idx[k + 1]
            };
            (last, self.times[idx[k + 1]])
        } else {
            (count, self.times[count])
        };
        (first..last, self.times[first], t1)
    }

    /// The key times of the keys `idx`.
    pub(crate) fn key_times(&self, idx: &[usize]) -> Vec<f64> {
        let mut knots: Vec<f64> = idx.iter().map(|&i| self.times[i]).collect();
        if self.closed {
            knots.push(self.times[self.points.len()]);
        }
        knots
    }

    /// Whether the fit on the keys `idx` may have free end velocities: an open curve whose first
    /// and last segments have samples between their keys, which the end velocities move (two
    /// at least when one segment has both ends), so that the samples determine them: the
    /// least-squares curve among all cubics on the keys. (With a key at every sample the ends
    /// are natural, the smoothing spline's own end condition.)
    pub(crate) fn free_ends(&self, idx: &[usize]) -> bool {
        let m = idx.len();
        let inside = |k: usize| idx[k + 1] - idx[k] - 1;
        !self.closed && m >= 2 && inside(0) >= 1 && inside(m - 2) >= 1 && (m > 2 || inside(0) >= 2)
    }

    /// The cubic through the keys `p` at the key times of `idx`: with the end velocities `ends`
    /// (clamped), or natural ends.
    pub(crate) fn build(
        &self,
        idx: &[usize],
        p: &[P::Vector],
        ends: Option<&(P::Vector, P::Vector)>,
    ) -> Result<CubicSpline<P>, SplineError> {
        let points = p.iter().cloned().map(P::from_vector_unchecked).collect();
        let end = match ends {
            Some((start, end)) => CubicEnd::Clamped {
                start_velocity: start.clone(),
                end_velocity: end.clone(),
            },
            None => CubicEnd::Natural,
        };
        CubicSpline::try_new(points, Some(self.key_times(idx)), end, self.closed)
    }

    /// The scaled residual vector `s·Log_y(c)` of a sample (the sign of `y` nearest `c` for
    /// rotations), without its weight.
    fn residual(&self, y: &P::Vector, c: &P::Vector) -> P::Vector {
        let y = if self.sign_free && y.dot(c) < 0.0 {
            y.clone() * -1.0
        } else {
            y.clone()
        };
        match geodesic_frame_sin_cos(&y, c) {
            Some((theta, e, _)) => e * (theta * self.scale),
            // An antipodal sample (not on S³, where the nearer sign is used): a half turn in
            // some direction; its derivative is undefined, its size is not.
            None => c.zeros_like(),
        }
    }

    /// `Σ wᵢ d(c(tᵢ), yᵢ)²` for the samples of segment `k`, and each sample's distance.
    fn segment_rss(
        &self,
        idx: &[usize],
        k: usize,
        g: &Segment<P::Vector>,
        end: &P::Vector,
        mut each: impl FnMut(usize, f64),
    ) -> f64 {
        let (range, t0, t1) = self.segment_samples(idx, k);
        let h = t1 - t0;
        let mut sum = 0.0;
        for i in range {
            let c = sample_point(g, end, (self.times[i] - t0) / h);
            let r = self.residual(&self.points[i], &c);
            let d2 = r.dot(&r);
            each(i, d2.sqrt());
            sum += self.weights[i] * d2;
        }
        sum
    }

    /// The objective's two parts at a built curve, and each sample's distance (into `dist`).
    pub(crate) fn evaluate(
        &self,
        idx: &[usize],
        curve: &CubicSpline<P>,
        dist: &mut [f64],
    ) -> (f64, f64) {
        let n = idx.len();
        let segments = curve.segments();
        let (mut rss, mut energy) = (0.0, 0.0);
        for (k, g) in segments.iter().enumerate() {
            let end = curve.points()[(k + 1) % n].to_vector();
            rss += self.segment_rss(idx, k, g, &end, |i, d| dist[i] = d);
            energy += g.energy();
        }
        (rss, energy * self.scale * self.scale)
    }

    /// The least-squares cubic on the key times of `idx` (sample indices; the first sample's
    /// always, and the last's when open) for the smoothing parameter `lambda`, from the keys
    /// `p` (vectors of the points).
    pub(crate) fn solve(
        &self,
        lambda: f64,
        idx: &[usize],
        start: Start<P>,
        until: Until,
    ) -> Result<Solved<P>, SplineError> {
        let mut dist = vec![0.0; self.points.len()];
        let free = match &start {
            Start::Keys(_, free) => *free,
            Start::Fit(s) => matches!(s.curve.end(), CubicEnd::Clamped { .. }),
        };
        let (mut p, mut curve, mut rss, mut energy) = match start {
            Start::Keys(p, _) => {
                // From the natural cubic on the keys.
                let curve = self.build(idx, &p, None)?;
                let (rss, energy) = self.evaluate(idx, &curve, &mut dist);
                (p, curve, rss, energy)
            }
            Start::Fit(s) => {
                let p = s.curve.points().iter().map(Manifold::to_vector).collect();
                (p, s.curve, s.rss, s.energy)
            }
        };
        let dim = p[0].dim();
        let d = dim - 1;
        let mut iterations = 0;
        if d == 0 {
            return Ok(Solved {
                curve,
                rss,
                energy,
                iterations,
            });
        }
        let mut system = Kkt::new(idx.len(), d, self.closed);
        let last = idx.len() - 1;
        loop {
            let objective = rss + lambda * energy;
            let frames: Vec<Vec<P::Vector>> = p.iter().map(tangent_frame).collect();
            let velocities = curve.key_velocities().to_vec();
            system.clear();
            for k in 0..curve.segment_count() {
                self.linearise(lambda, idx, k, &p, &velocities, &frames, free, &mut system);
            }
            if free {
                // No end rows: the end velocities are unknowns like the keys.
                system.no_constraint(0);
                system.no_constraint(last);
            }
            let Some(step) = system.solve() else {
                return Err(no_convergence(iterations, objective));
            };
            // The decrease the linear model predicts, −xᵀJᵀR (≥ 0 for the constrained
            // Gauss–Newton step, up to rounding).
            let predicted = step.predicted;
            if !(predicted.is_finite()) {
                return Err(no_convergence(iterations, objective));
            }
            // The objective's rounding has an absolute part too: residuals of about 1e-13 rad
            // (exact data, a fit through every sample) leave nothing to decrease.
            let floor = 1e-26 * self.weights.iter().sum::<f64>();
            // A free-end step that the model does not predict to descend: the system is too
            // ill-conditioned there (λ's energy swamping the samples with only a few keys),
            // and the caller fits with natural ends instead.
            if free && predicted < -(ROUNDING * objective + floor) {
                return Err(no_convergence(iterations, objective));
            }
            let converged = predicted <= DECREMENT * objective + floor;
            // Backtracking: the full step, then halves, until the objective decreases by a
            // quarter of the predicted amount (once converged, the last step is taken when it
            // does not increase the objective).
            let mut alpha = 1.0;
            let mut accepted = None;
            for _ in 0..40 {
                let trial = retract(&p, &frames, &step.x, alpha);
                let ends = free.then(|| {
                    let moved = |k: usize| {
                        let mut v = velocities[k].clone();
                        for (j, e) in frames[k].iter().enumerate() {
                            v += e.clone() * (alpha * step.x[k * 2 * d + d + j]);
                        }
                        // Tangent at the moved key.
                        let q = &trial[k];
                        v.clone() - q.clone() * q.dot(&v)
                    };
                    (moved(0), moved(last))
                });
                if let Ok(c) = self.build(idx, &trial, ends.as_ref()) {
                    let (r, e) = self.evaluate(idx, &c, &mut dist);
                    let value = r + lambda * e;
                    let target = if converged {
                        objective
                    } else {
                        objective - 0.25 * alpha * predicted
                    };
                    if value <= target {
                        accepted = Some((trial, c, r, e));
                        break;
                    }
                }
                if converged {
                    break;
                }
                alpha *= 0.5;
            }
            iterations += 1;
            let found = accepted.is_some();
            if let Some((trial, c, r, e)) = accepted {
                p = trial;
                curve = c;
                rss = r;
                energy = e;
            }
            // No decrease along the Gauss–Newton direction although the model predicts one
            // above rounding: stuck.
            if !found && !converged && predicted > ROUNDING * objective + floor {
                return Err(no_convergence(iterations, objective));
            }
            // Stalled at the accuracy of the differenced Jacobians: the step taken decreased
            // the objective by less than 1e-13 of itself (the model's prediction is then noise).
            let stalled = found && objective - (rss + lambda * energy) <= STALL * objective;
            if converged || stalled || !found || matches!(until, Until::Steps(k) if iterations >= k)
            {
                break;
            }
            if iterations >= MAX_ITERATIONS {
                return Err(no_convergence(iterations, rss + lambda * energy));
            }
        }
        Ok(Solved {
            curve,
            rss,
            energy,
            iterations,
        })
    }

    /// Adds segment `k`'s residuals (Gauss–Newton normal equations) and its parts of the
    /// continuity rows at its two keys to the KKT system.
    #[expect(
        clippy::too_many_arguments,
        reason = "the segment's inputs, each a slice of the iteration's state"
    )]
    fn linearise(
        &self,
        lambda: f64,
        idx: &[usize],
        k: usize,
        p: &[P::Vector],
        v: &[P::Vector],
        frames: &[Vec<P::Vector>],
        free: bool,
        system: &mut Kkt,
    ) {
        let n = idx.len();
        let k1 = (k + 1) % n;
        let d = frames[k].len();
        let (range, t0, t1) = self.segment_samples(idx, k);
        let h = t1 - t0;
        let dim = p[k].dim();
        // The outputs: the samples' residuals (dim each, tangent at the fixed samples), the two
        // energy residuals and the tangential acceleration at the start (d each, in the frame of
        // key k: the ambient coordinates of a vector tangent at the moving key would turn with
        // it, a rotation the Gauss–Newton model would take for curvature of the objective) and
        // at the end (d, in the frame of key k + 1).
        let samples = range.len();
        let nres = samples * dim + 2 * d;
        let nout = nres + 2 * d;
        let sqrt_lambda = lambda.sqrt() * self.scale * math::powf(h, -1.5);
        // Samples are aligned with the current curve once (the sign of a rotation sample stays
        // fixed through the differences).
        let base = Segment::hermite(&p[k], &p[k1], &v[k], &v[k1], h);
        let outputs = |p0: &P::Vector,
                       v0: &P::Vector,
                       p1: &P::Vector,
                       v1: &P::Vector,
                       out: &mut [f64]|
         -> bool {
            let Some(g) = Segment::hermite(p0, p1, v0, v1, h) else {
                return false;
            };
            let mut o = 0;
            for i in range.clone() {
                let c = sample_point(&g, p1, (self.times[i] - t0) / h);
                let r = self.residual(&self.points[i], &c) * self.weights[i].sqrt();
                out[o..o + dim].copy_from_slice(r.as_slice());
                o += dim;
            }
            let e1 = (g.b.clone() * 2.0 + g.c.clone() * 3.0) * sqrt_lambda;
            let e2 = g.c.clone() * (3f64.sqrt() * sqrt_lambda);
            for (j, e) in frames[k].iter().enumerate() {
                out[o + j] = e.dot(&e1);
                out[o + d + j] = e.dot(&e2);
            }
            o += 2 * d;
            let inv_h2 = 1.0 / (h * h);
            let start = g.b.clone() * (2.0 * inv_h2);
            for (j, e) in frames[k].iter().enumerate() {
                out[o + j] = e.dot(&start);
            }
            o += d;
            let local = g.local(1.0);
            let q = renormalize(local.q.clone());
            let (_, acc) = g.velocity_acceleration(1.0, local);
            let acc = acc.clone() - q.clone() * q.dot(&acc);
            for (j, e) in frames[k1].iter().enumerate() {
                out[o + j] = e.dot(&acc);
            }
            true
        };
        let mut value = vec![0.0; nout];
        let ok = base.is_some() && outputs(&p[k], &v[k], &p[k1], &v[k1], &mut value);
        // Derivatives by central differences in the 4d unknowns.
        let m = 4 * d;
        let mut jac = vec![0.0; nout * m];
        let (mut plus, mut minus) = (vec![0.0; nout], vec![0.0; nout]);
        for col in 0..m {
            let (key, is_velocity, j) = (col / (2 * d), (col / d) % 2 == 1, col % d);
            let (pk, vk) = if key == 0 {
                (&p[k], &v[k])
            } else {
                (&p[k1], &v[k1])
            };
            let frame = if key == 0 { &frames[k] } else { &frames[k1] };
            let eps = if is_velocity {
                STEP * vk.length().max(1.0)
            } else {
                STEP
            };
            let perturbed = |sign: f64| -> (P::Vector, P::Vector) {
                if is_velocity {
                    (pk.clone(), vk.clone() + frame[j].clone() * (sign * eps))
                } else {
                    let (s, c) = math::sin_cos(sign * eps);
                    let q = pk.clone() * c + frame[j].clone() * s;
                    // The velocity carried along: projected onto the new tangent space.
                    let w = vk.clone() - q.clone() * q.dot(vk);
                    (q, w)
                }
            };
            let (pp, vp) = perturbed(1.0);
            let (pm, vm) = perturbed(-1.0);
            let good = if key == 0 {
                outputs(&pp, &vp, &p[k1], &v[k1], &mut plus)
                    && outputs(&pm, &vm, &p[k1], &v[k1], &mut minus)
            } else {
                outputs(&p[k], &v[k], &pp, &vp, &mut plus)
                    && outputs(&p[k], &v[k], &pm, &vm, &mut minus)
            };
            if good && ok {
                for r in 0..nout {
                    jac[r * m + col] = (plus[r] - minus[r]) / (2.0 * eps);
                }
            }
        }
        // JᵀJ and JᵀR over the residual rows.
        let mut jtj = vec![0.0; m * m];
        let mut jtr = vec![0.0; m];
        for r in 0..nres {
            let row = &jac[r * m..(r + 1) * m];
            if row.iter().all(|&x| x == 0.0) {
                continue;
            }
            for a in 0..m {
                jtr[a] += row[a] * value[r];
                for b in a..m {
                    jtj[a * m + b] += row[a] * row[b];
                }
            }
        }
        for a in 0..m {
            for b in 0..a {
                jtj[a * m + b] = jtj[b * m + a];
            }
        }
        system.add_segment(k, &jtj, &jtr);
        // The continuity rows: + end acceleration at key k + 1, − start acceleration at key k
        // (natural ends: the start acceleration alone at the first key of an open curve, the end
        // acceleration alone at its last).
        let start_rows = &jac[nres * m..(nres + d) * m];
        let end_rows = &jac[(nres + d) * m..(nres + 2 * d) * m];
        let start_val = &value[nres..nres + d];
        let end_val = &value[nres + d..nres + 2 * d];
        let first = !self.closed && k == 0;
        let last = !self.closed && k1 == n - 1;
        if !(first && free) {
            system.add_constraint(k, k, if first { 1.0 } else { -1.0 }, start_rows, start_val);
        }
        if !(last && free) {
            system.add_constraint(k1, k, 1.0, end_rows, end_val);
        }
    }
}

/// The point of a segment at `s` (its end key at `s = 1`, its start at `s = 0`).
fn sample_point<V: Ambient>(g: &Segment<V>, end: &V, s: f64) -> V {
    if s == 0.0 {
        g.start.clone()
    } else if s == 1.0 {
        end.clone()
    } else {
        renormalize(g.local(s).q)
    }
}

/// The keys moved by `alpha` times the step's `δpₖ` (frame coordinates), along geodesics.
fn retract<V: Ambient>(p: &[V], frames: &[Vec<V>], x: &[f64], alpha: f64) -> Vec<V> {
    let d = frames.first().map_or(0, Vec::len);
    p.iter()
        .zip(frames)
        .enumerate()
        .map(|(k, (pk, frame))| {
            let mut v = pk.zeros_like();
            for (j, e) in frame.iter().enumerate() {
                v += e.clone() * (alpha * x[k * 2 * d + j]);
            }
            exp_vector(pk, &v).unwrap_or_else(|_| pk.clone())
        })
        .collect()
}

fn no_convergence(iterations: usize, residual: f64) -> SplineError {
    SplineError::Solve(SolveError::NoConvergence {
        iterations,
        residual,
    })
}

/// An orthonormal frame of the tangent space at `p`: the columns `i ≠ j` of the Householder
/// reflection that maps `p` to `∓e_j`, `j` the largest coordinate of `p`.
pub(crate) fn tangent_frame<V: Ambient>(p: &V) -> Vec<V> {
    let c = p.as_slice();
    let dim = c.len();
    let j = (0..dim)
        .max_by(|&a, &b| c[a].abs().total_cmp(&c[b].abs()))
        .unwrap_or(0);
    let sigma = if c[j] >= 0.0 { 1.0 } else { -1.0 };
    let mut u = c.to_vec();
    u[j] += sigma;
    let uu: f64 = u.iter().map(|x| x * x).sum();
    (0..dim)
        .filter(|&i| i != j)
        .map(|i| {
            let coords: Vec<f64> = (0..dim)
                .map(|a| f64::from(u8::from(a == i)) - 2.0 * u[a] * u[i] / uu)
                .collect();
            p.with_coords(&coords)
        })
        .collect()
}

/// The KKT system of a Gauss–Newton step, block tridiagonal by key with blocks
/// `[δpₖ, δVₖ, μₖ]` of `3d`.
struct Kkt {
    n: usize,
    d: usize,
    closed: bool,
    a: Vec<f64>,
    diag: Vec<f64>,
    c: Vec<f64>,
    rhs: Vec<f64>,
    /// `JᵀR` of the unknowns, for the predicted decrease.
    jtr: Vec<f64>,
}

/// A solved Gauss–Newton step: `[δpₖ, δVₖ]` per key, and the predicted decrease `−xᵀJᵀR`.
struct Step {
    x: Vec<f64>,
    predicted: f64,
}

impl Kkt {
    fn new(n: usize, d: usize, closed: bool) -> Self {
        let b = 3 * d;
        Self {
            n,
            d,
            closed,
            a: vec![0.0; n * b * b],
            diag: vec![0.0; n * b * b],
            c: vec![0.0; n * b * b],
            rhs: vec![0.0; n * b],
            jtr: vec![0.0; n * 2 * d],
        }
    }

    fn clear(&mut self) {
        for v in [
            &mut self.a,
            &mut self.diag,
            &mut self.c,
            &mut self.rhs,
            &mut self.jtr,
        ] {
            v.fill(0.0);
        }
    }

    /// The block of row key `row`, column key `col` (`row == col`, `col = row ± 1` cyclically).
    fn block(&mut self, row: usize, col: usize) -> &mut [f64] {
        let b = 3 * self.d;
        let n = self.n;
        let start = row * b * b;
        let after = if self.closed { (row + 1) % n } else { row + 1 };
        let which = if col == row {
            &mut self.diag
        } else if col == after {
            &mut self.c
        } else {
            &mut self.a
        };
        &mut which[start..start + b * b]
    }

    /// Segment `k`'s `JᵀJ` and `JᵀR` over `[x_k, x_{k+1}]` (`x = [δp, δV]`, 2d each).
    fn add_segment(&mut self, k: usize, jtj: &[f64], jtr: &[f64]) {
        let d2 = 2 * self.d;
        let b = 3 * self.d;
        let m = 2 * d2;
        let keys = [k, (k + 1) % self.n];
        for (bi, &ri) in keys.iter().enumerate() {
            for (bj, &cj) in keys.iter().enumerate() {
                let block = self.block(ri, cj);
                for r in 0..d2 {
                    for c in 0..d2 {
                        block[r * b + c] += jtj[(bi * d2 + r) * m + bj * d2 + c];
                    }
                }
            }
            for r in 0..d2 {
                self.rhs[ri * b + r] -= jtr[bi * d2 + r];
                self.jtr[ri * d2 + r] += jtr[bi * d2 + r];
            }
        }
    }

    /// Adds `sign·rows` (d rows over segment `seg`'s unknowns `[x_seg, x_{seg+1}]`) and
    /// `sign·value` to the continuity row of key `row`, and the transposed columns.
    fn add_constraint(&mut self, row: usize, seg: usize, sign: f64, rows: &[f64], value: &[f64]) {
        let d = self.d;
        let d2 = 2 * d;
        let b = 3 * d;
        let m = 2 * d2;
        let keys = [seg, (seg + 1) % self.n];
        for (bi, &col) in keys.iter().enumerate() {
            for r in 0..d {
                for c in 0..d2 {
                    let g = sign * rows[r * m + bi * d2 + c];
                    self.block(row, col)[(d2 + r) * b + c] += g;
                    self.block(col, row)[c * b + d2 + r] += g;
                }
            }
        }
        for (r, v) in value.iter().enumerate() {
            self.rhs[row * b + d2 + r] -= sign * v;
        }
    }

    /// No continuity row at key `k` (its multiplier fixed at 0): a free end.
    fn no_constraint(&mut self, k: usize) {
        let (d, b) = (self.d, 3 * self.d);
        let block = self.block(k, k);
        for r in 0..d {
            block[(2 * d + r) * b + 2 * d + r] = 1.0;
        }
    }

    fn solve(&self) -> Option<Step> {
        let b = 3 * self.d;
        let d2 = 2 * self.d;
        let factors = BlockTridiagonal::factor(b, &self.a, &self.diag, &self.c, self.closed)?;
        let mut x = self.rhs.clone();
        factors.solve(&mut x);
        if !x.iter().all(|v| v.is_finite()) {
            return None;
        }
        let mut out = Vec::with_capacity(self.n * d2);
        let mut predicted = 0.0;
        for k in 0..self.n {
            let xs = &x[k * b..k * b + d2];
            predicted -= xs
                .iter()
                .zip(&self.jtr[k * d2..(k + 1) * d2])
                .map(|(a, g)| a * g)
                .sum::<f64>();
            out.extend_from_slice(xs);
        }
        Some(Step { x: out, predicted })
    }
}
