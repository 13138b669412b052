// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Fitting measured samples: the smoothing spline of the cubic family on every sphere, with the
//! smoothing parameter given, chosen by generalised cross-validation or by a target residual,
//! and key reduction within an error bound.
//!
//! The problem (samples `yᵢ` at times `tᵢ`, weights `wᵢ > 0`): the curve `c` of the
//! [`CubicSpline`] family (keys at key times; closed, or open with natural ends, or with fitted
//! end velocities on fewer keys, [`FitKeys::Count`]) that minimises
//!
//! ```text
//! F(c) = Σ wᵢ·d(c(tᵢ), yᵢ)² + λ·E(c),   E(c) = Σₖ ∫ |vₖ″(t)|² dt,
//! ```
//!
//! with `d` the distance of the sphere (great-circle angle; on S³ the rotation angle, twice the
//! quaternion angle, and `±y` the same sample) and `E` the tangent-space energy of the cubic's
//! segments (`c(t) = Exp_{pₖ}(vₖ(t))`, on S³ scaled by the same factor 4 as `d²`). On a great
//! circle (one rotation axis) both reduce to the Euclidean smoothing spline of the angle along
//! it, `Σ wᵢ(θ(tᵢ) − θᵢ)² + λ∫θ″²` (Reinsch 1967), which is
//! `scipy.interpolate.make_smoothing_spline(t, θ, w, lam)`.
//!
//! - The solver ([`solve`]): Gauss–Newton on the keys with the key velocities as unknowns tied
//!   by the continuity equations, a banded KKT system per step, O(n).
//! - λ by generalised cross-validation (Craven & Wahba 1979): minimise
//!   `GCV(λ) = N·Σwᵢd(c(tᵢ), yᵢ)² / (N − tr A(λ))²` over `ln λ`, with `tr A` the trace of the
//!   hat matrix of the developed (tangent-space) problem, the Euclidean smoothing spline with the
//!   same times and weights ([`reinsch`]): exact on a great circle, where it is scipy's criterion
//!   with unit weights, and computed exactly in O(N). The effective degrees of freedom reported
//!   are `m·tr A` for a curve on S^m (each tangent direction smoothed alike).
//! - λ by a target residual `σ`: the weighted RMS residual grows with λ; `ln λ` is found by a
//!   safeguarded secant (Illinois) iteration to 1e-9 relative.
//! - Key reduction ([`reduce`]): the fewest keys among the sample times within `ε`.
//!
//! Sources: C. H. Reinsch (1967), Smoothing by spline functions, Numer. Math. 10, 177–183;
//! P. Craven, G. Wahba (1979), Smoothing noisy data with spline functions, Numer. Math. 31,
//! 377–403; M. F. Hutchinson, F. R. de Hoog (1985), Smoothing noisy data with spline functions,
//! Numer. Math. 47, 99–106; P. E. Jupp, J. T. Kent (1987), Fitting smooth paths to spherical
//! data, Appl. Statist. 36, 34–46. The derivation: `docs/derivations.md#smoothing-spline`.

mod reduce;
mod reinsch;
mod solve;

use crate::ambient::Ambient;
use crate::cubic::{CubicEnd, CubicSpline};
use crate::error::{PointError, SolveError, SplineError};
use crate::knots::Knots;
use crate::manifold::Manifold;
use crate::math;
use crate::rotation_loop::RotationLoop;
use crate::s3::UnitQuat;
use solve::{Samples, Solved, Start, Until};

/// How much a fit smooths.
#[derive(Clone, Debug, PartialEq)]
pub enum Smoothing {
    /// The smoothing parameter λ ≥ 0 itself (λ = 0: least squares on the keys; with a key at
    /// every sample, interpolation).
    Lambda(f64),
    /// λ by generalised cross-validation (keys at every sample only).
    Gcv,
    /// λ such that the weighted RMS residual `√(Σwᵢdᵢ²/Σwᵢ)` is `σ` radians (the noise level a
    /// user knows; MATLAB `spaps`'s tolerance in RMS form).
    Rms(f64),
}

/// Where a fit's keys are.
#[derive(Clone, Debug, PartialEq, Default)]
pub enum FitKeys {
    /// A key at every sample time: the smoothing spline.
    #[default]
    Samples,
    /// This many keys among the sample times, as evenly spread over the samples as the times
    /// allow (the first and last sample always keys; closed: the first). With fewer keys than
    /// samples and λ given, an open fit's end velocities are fitted too ([`CubicEnd::Clamped`]):
    /// the least-squares curve among all cubics on the keys, where the end segments have
    /// samples between their keys and that fit converges (else natural ends).
    Count(usize),
    /// The fewest keys among the sample times whose fit (as for [`Count`](Self::Count)) stays
    /// within this distance (radians) of every sample and of the samples' geodesic
    /// interpolation midway between samples.
    MaxError(f64),
}

/// What to fit: [`CubicSpline::try_fit`].
#[derive(Clone, Debug, PartialEq, Default)]
pub struct FitOptions {
    /// The smoothing; `None`: [`Smoothing::Gcv`] with a key at every sample, λ = 0 otherwise.
    pub smoothing: Option<Smoothing>,
    /// A positive weight per sample (default 1).
    pub weights: Option<Vec<f64>>,
    /// Where the keys are.
    pub keys: FitKeys,
}

/// What a fit found.
#[derive(Clone, Debug, PartialEq)]
pub struct FitReport {
    /// The smoothing parameter used.
    pub lambda: f64,
    /// The weighted RMS residual `√(Σwᵢdᵢ²/Σwᵢ)`, radians (rotation angle on S³).
    pub rms: f64,
    /// The largest residual `maxᵢ dᵢ`, radians; with [`FitKeys::MaxError`] also over the midpoints
    /// between samples.
    pub max: f64,
    /// The number of keys.
    pub keys: usize,
    /// The key times (closed: and the return time).
    pub key_times: Vec<f64>,
    /// Gauss–Newton iterations of the final fit (of every fit tried, for a chosen λ or keys, or
    /// free ends that gave way to natural ones).
    pub iterations: usize,
    /// The effective degrees of freedom `m·tr A(λ)` (S^m; keys at every sample only).
    pub edf: Option<f64>,
    /// Each sample's distance to the fitted curve, radians (rotation angle on S³).
    pub residuals: Vec<f64>,
}

/// # Fitting samples
impl<P: Manifold> CubicSpline<P> {
    /// The cubic spline fitted to `samples` at the `times` (closed: one more, the time at which
    /// the loop is back at the first sample): the curve of this family minimising
    /// `Σ wᵢ·d(c(tᵢ), yᵢ)² + λ·Σₖ∫|vₖ″|²` (the definitions
    /// below), with λ given, chosen by generalised cross-validation or by a target RMS
    /// residual, and keys at every sample time or as few as an error bound allows.
    ///
    /// On S³ ([`UnitQuat`](crate::UnitQuat)) the samples are rotations: `q` and `−q` are the
    /// same sample (sensors give either), and distances are rotation angles.
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 2 samples (3 closed);
    /// - [`SplineError::InvalidPoint`] for samples of different dimensions;
    /// - the knot errors of [`Knots::try_new`] for the times, and [`SplineError::KnotCount`]
    ///   unless there is one time per sample (closed: one more);
    /// - [`SplineError::InvalidParameter`] `weights` (not one per sample, or not positive and
    ///   finite), `smoothing` (λ negative or not finite, σ not positive and finite, or out of
    ///   reach, or GCV with fewer keys than samples), `max_error` (not positive and finite),
    ///   `keys` (below the minimum or above the samples);
    /// - [`SplineError::Antipodal`] for antipodal consecutive samples (not on S³);
    /// - [`SplineError::Solve`] if Gauss–Newton does not converge.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::glam::DVec3;
    /// use spherekit::{CubicSpline, Curve, FitOptions, Manifold, S2Point, Smoothing};
    ///
    /// // Noisy samples of a circle of latitude.
    /// let times: Vec<f64> = (0..40).map(|i| f64::from(i) * 0.1).collect();
    /// let samples: Vec<S2Point> = times
    ///     .iter()
    ///     .enumerate()
    ///     .map(|(i, &t)| {
    ///         let wobble = 0.01 * (f64::from(i as u32) * 2.3).sin();
    ///         S2Point::try_new(DVec3::new(t.cos(), t.sin(), 0.5 + wobble)).unwrap()
    ///     })
    ///     .collect();
    /// let options = FitOptions { smoothing: Some(Smoothing::Gcv), ..FitOptions::default() };
    /// let (curve, report) = CubicSpline::try_fit(samples.clone(), times, &options, false).unwrap();
    /// assert!(report.rms < 0.01 && report.lambda > 0.0);
    /// assert!(curve.eval(2.0).dist(&samples[20]) < 0.02);
    /// ```
    pub fn try_fit(
        samples: Vec<P>,
        times: Vec<f64>,
        options: &FitOptions,
        closed: bool,
    ) -> Result<(Self, FitReport), SplineError> {
        let fit = fit_points(samples, times, options, closed, None)?;
        let curve = Self::try_new(fit.points, Some(fit.knots), fit.end, closed)?;
        Ok((curve, fit.report))
    }
}

/// # Fitting a closed loop of rotations
impl CubicSpline<UnitQuat> {
    /// The closed fit of rotation samples as a loop in SO(3): [`try_fit`](Self::try_fit) with
    /// `closed`, except that samples making a loop of an odd number of turns (taken the shorter
    /// way from each to the next, the last is nearer `−q₀` than `q₀`: a 360° orbit) are fitted
    /// by a curve that ends at `−q₀`, the same rotation, as [`RotationLoop`] builds every
    /// closed construction. The fit of such samples is the first half of the closed fit of the
    /// samples followed by their antipodes one period later (weights repeated), which is
    /// antiperiodic (the fit is unique, and the doubled problem is symmetric); λ by GCV uses
    /// the hat matrix of the samples as given, and the report is the first half's.
    ///
    /// # Errors
    ///
    /// As [`try_fit`](Self::try_fit) with `closed`.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::glam::DVec3;
    /// use spherekit::{CubicSpline, Curve, FitOptions, Manifold, Smoothing, UnitQuat};
    ///
    /// // A camera orbiting once about the vertical, measured 24 times with a wobble.
    /// let times: Vec<f64> = (0..=24).map(|i| f64::from(i) * 0.25).collect();
    /// let samples: Vec<UnitQuat> = times[..24]
    ///     .iter()
    ///     .enumerate()
    ///     .map(|(i, &t)| {
    ///         let yaw = UnitQuat::from_axis_angle(DVec3::Z, t * std::f64::consts::TAU / 6.0).unwrap();
    ///         let wobble = 0.01 * (f64::from(i as u32) * 1.7).sin();
    ///         UnitQuat::from_axis_angle(DVec3::X, wobble).unwrap() * yaw
    ///     })
    ///     .collect();
    /// let options = FitOptions { smoothing: Some(Smoothing::Lambda(1e-3)), ..FitOptions::default() };
    /// let (orbit, report) = CubicSpline::try_fit_loop(samples.clone(), times, &options).unwrap();
    /// assert!(orbit.is_antiperiodic() && report.keys == 24);
    /// assert!(orbit.eval(1.0).dist(&samples[4]).min(orbit.eval(1.0).dist(&-samples[4])) < 0.01);
    /// ```
    pub fn try_fit_loop(
        samples: Vec<UnitQuat>,
        times: Vec<f64>,
        options: &FitOptions,
    ) -> Result<(RotationLoop<Self>, FitReport), SplineError> {
        let n = samples.len();
        let mut shortest = samples;
        crate::unflip(&mut shortest);
        let mut report = None;
        let curve = RotationLoop::try_new(shortest, Some(times), |keys, knots| {
            let half = (keys.len() == 2 * n).then_some(n);
            let fit = fit_points(keys, knots.unwrap_or_default(), options, true, half)?;
            report = Some(fit.report);
            Self::try_new(fit.points, Some(fit.knots), fit.end, true)
        })?;
        let report = report.ok_or(SplineError::TooFewPoints { min: 3, got: n })?;
        Ok((curve, report))
    }
}

/// A fitted curve's parts: its keys, their times (closed: and the return time), its end
/// condition, and the report.
struct FitParts<P: Manifold> {
    points: Vec<P>,
    knots: Vec<f64>,
    end: CubicEnd<P::Vector>,
    report: FitReport,
}

/// The fit of `samples` (with the `compact` feature on S^m). `half`: the samples are a doubled
/// antiperiodic loop of `half` samples given.
fn fit_points<P: Manifold>(
    samples: Vec<P>,
    times: Vec<f64>,
    options: &FitOptions,
    closed: bool,
    half: Option<usize>,
) -> Result<FitParts<P>, SplineError> {
    let vectors: Vec<P::Vector> = samples.iter().map(Manifold::to_vector).collect();
    #[cfg(feature = "compact")]
    let (keys, knots, ends, report) = {
        use crate::sm::SmPoint;
        let vectors = vectors
            .iter()
            .map(|v| crate::ambient::VecN::new(v.to_vec()))
            .collect();
        let (keys, knots, ends, report) =
            fit::<SmPoint>(vectors, times, options, closed, P::SPEED_SCALE, half)?;
        let like = samples[0].to_vector();
        let to = |k: &crate::ambient::VecN| like.with_coords(k.as_slice());
        let keys: Vec<P::Vector> = keys.iter().map(to).collect();
        (keys, knots, ends.map(|(a, b)| (to(&a), to(&b))), report)
    };
    #[cfg(not(feature = "compact"))]
    let (keys, knots, ends, report) =
        fit::<P>(vectors, times, options, closed, P::SPEED_SCALE, half)?;
    let points = keys.into_iter().map(P::from_vector_unchecked).collect();
    let end = match ends {
        Some((start_velocity, end_velocity)) => CubicEnd::Clamped {
            start_velocity,
            end_velocity,
        },
        None => CubicEnd::Natural,
    };
    Ok(FitParts {
        points,
        knots,
        end,
        report,
    })
}

/// Fitted keys, their times (closed: and the return time), the fitted end velocities (open,
/// with fewer keys than samples) and the report.
type KeysAndReport<V> = (Vec<V>, Vec<f64>, Option<(V, V)>, FitReport);

/// The fit on `Q`'s vectors: the fitted keys, their times and the report.
fn fit<Q: Manifold>(
    mut vectors: Vec<Q::Vector>,
    times: Vec<f64>,
    options: &FitOptions,
    closed: bool,
    scale: f64,
    half: Option<usize>,
) -> Result<KeysAndReport<Q::Vector>, SplineError> {
    let n = vectors.len();
    // The samples as given (the first half of a doubled loop).
    let given = half.unwrap_or(n);
    let min = if closed { 3 } else { 2 };
    if n < min {
        return Err(SplineError::TooFewPoints { min, got: n });
    }
    let dim = vectors[0].dim();
    if let Some(index) = vectors.iter().position(|v| v.dim() != dim) {
        return Err(SplineError::InvalidPoint {
            index,
            reason: PointError::WrongDimension {
                expected: dim,
                got: vectors[index].dim(),
            },
        });
    }
    let knots = Knots::try_new(times)?;
    let expected = n + usize::from(closed);
    if knots.as_slice().len() != expected {
        return Err(SplineError::KnotCount {
            expected,
            got: knots.as_slice().len(),
        });
    }
    let weights = match &options.weights {
        None => vec![1.0; n],
        Some(w) if w.len() != given => {
            return Err(invalid(
                "weights",
                format!(
                    "must have one weight per sample: {given} samples, got {}",
                    w.len()
                ),
            ));
        }
        Some(w) => {
            if let Some(i) = w.iter().position(|x| !(x.is_finite() && *x > 0.0)) {
                return Err(invalid(
                    "weights",
                    format!("weights[{i}] must be positive and finite, got {}", w[i]),
                ));
            }
            w.iter().cycle().take(n).copied().collect()
        }
    };
    let smoothing = match (&options.smoothing, &options.keys) {
        (Some(s), _) => s.clone(),
        (None, FitKeys::Samples) => Smoothing::Gcv,
        (None, _) => Smoothing::Lambda(0.0),
    };
    match smoothing {
        Smoothing::Lambda(l) if !(l.is_finite() && l >= 0.0) => {
            return Err(invalid(
                "smoothing",
                format!("λ must be a finite number ≥ 0, got {l}"),
            ));
        }
        Smoothing::Rms(s) if !(s.is_finite() && s > 0.0) => {
            return Err(invalid(
                "smoothing",
                format!("the target rms must be a positive finite number of radians, got {s}"),
            ));
        }
        Smoothing::Gcv if options.keys != FitKeys::Samples => {
            return Err(invalid(
                "smoothing",
                "\"gcv\" needs a key at every sample (no keys or max_error); give λ or an rms"
                    .into(),
            ));
        }
        _ => {}
    }
    match options.keys {
        FitKeys::Count(m) if m < min || m > given => {
            return Err(invalid(
                "keys",
                format!("must be between {min} and the number of samples, {given}; got {m}"),
            ));
        }
        FitKeys::MaxError(e) if !(e.is_finite() && e > 0.0) => {
            return Err(invalid(
                "max_error",
                format!("must be a positive finite number of radians, got {e}"),
            ));
        }
        _ => {}
    }
    // Rotations: each sample's sign nearest the previous one's (the fit does not depend on the
    // signs; the starting keys do).
    let sign_free = scale != 1.0;
    if sign_free {
        for i in 1..n {
            if vectors[i - 1].dot(&vectors[i]) < 0.0 {
                vectors[i] = vectors[i].clone() * -1.0;
            }
        }
    }
    let problem = Samples::<Q> {
        points: vectors,
        times: knots.as_slice().to_vec(),
        weights,
        closed,
        scale,
        sign_free,
        half,
    };
    let fitted = match options.keys {
        FitKeys::Samples => {
            let idx: Vec<usize> = (0..n).collect();
            problem.fitted(&idx, &smoothing, None)?
        }
        FitKeys::Count(m) => {
            let idx = reduce::even_keys(&problem, m * n / given);
            problem.fitted(&idx, &smoothing, None)?
        }
        FitKeys::MaxError(eps) => reduce::reduce(&problem, eps, &smoothing)?,
    };
    let knots = fitted.knots;
    let mut report = fitted.report;
    if half.is_some() {
        // The first half's: its keys, their times and the return time, its residuals.
        report.keys /= 2;
        report.key_times.truncate(report.keys);
        report.key_times.push(problem.times[given]);
        report.residuals.truncate(given);
    }
    Ok((fitted.keys, knots, fitted.ends, report))
}

fn invalid(name: &'static str, reason: String) -> SplineError {
    SplineError::InvalidParameter { name, reason }
}

/// A fit on given keys, with its report.
pub(crate) struct Fitted<V> {
    pub(crate) keys: Vec<V>,
    /// The end velocities of an open curve with fewer keys than samples (fitted too), else
    /// `None` (natural ends).
    pub(crate) ends: Option<(V, V)>,
    pub(crate) report: FitReport,
    /// The key times (closed: and the return time).
    pub(crate) knots: Vec<f64>,
    /// Each sample's distance to the curve.
    pub(crate) dist: Vec<f64>,
}

impl<Q: Manifold> Samples<Q> {
    /// The number of samples as given (the first half of a doubled loop).
    pub(crate) fn given(&self) -> usize {
        self.half.unwrap_or(self.points.len())
    }

    /// The trace of the hat matrix of the Euclidean smoothing spline of the samples as given.
    fn trace(&self, lambda: f64) -> f64 {
        let n = self.given();
        reinsch::hat_trace(
            &self.times[..n + usize::from(self.closed)],
            &self.weights[..n],
            lambda,
            self.closed,
        )
    }

    /// The fit on the keys `idx` with the given smoothing, its report and the per-sample
    /// distances, from starting keys `start` (default: the samples at the keys). With λ given,
    /// free end velocities where [`free_ends`](Self::free_ends) allows them, and natural ends
    /// when that fit fails (a cubic segment cannot follow the samples, or λ's energy swamps
    /// them); natural ends with λ searched for (a search's one-step trials need the better
    /// conditioned problem).
    pub(crate) fn fitted(
        &self,
        idx: &[usize],
        smoothing: &Smoothing,
        start: Option<Vec<Q::Vector>>,
    ) -> Result<Fitted<Q::Vector>, SplineError> {
        let start = start.unwrap_or_else(|| idx.iter().map(|&i| self.points[i].clone()).collect());
        let mut tried = 0;
        if matches!(smoothing, Smoothing::Lambda(_)) && self.free_ends(idx) {
            match self.fitted_with(idx, smoothing, Start::Keys(start.clone(), true)) {
                Ok(f) => return Ok(f),
                Err(SplineError::Solve(SolveError::NoConvergence { iterations, .. })) => {
                    tried = iterations;
                }
                Err(_) => {}
            }
        }
        let mut fitted = self.fitted_with(idx, smoothing, Start::Keys(start, false))?;
        fitted.report.iterations += tried;
        Ok(fitted)
    }

    /// [`fitted`](Self::fitted) from `start`.
    fn fitted_with(
        &self,
        idx: &[usize],
        smoothing: &Smoothing,
        start: Start<Q>,
    ) -> Result<Fitted<Q::Vector>, SplineError> {
        let all = idx.len() == self.points.len();
        let mut iterations = 0;
        let (lambda, solved) = match *smoothing {
            Smoothing::Lambda(l) => (l, self.solve(l, idx, start, Until::Converged)?),
            Smoothing::Gcv => self.gcv(idx, start, &mut iterations)?,
            Smoothing::Rms(sigma) => self.rms_target(idx, start, sigma, &mut iterations)?,
        };
        iterations += solved.iterations;
        let mut dist = vec![0.0; self.points.len()];
        let (rss, _) = self.evaluate(idx, &solved.curve, &mut dist);
        let total: f64 = self.weights.iter().sum();
        let dim = start_dim(&solved.curve);
        let edf = all.then(|| (dim - 1) as f64 * self.trace(lambda));
        let keys: Vec<Q::Vector> = solved
            .curve
            .points()
            .iter()
            .map(Manifold::to_vector)
            .collect();
        let velocities = solved.curve.key_velocities();
        let free = matches!(solved.curve.end(), CubicEnd::Clamped { .. });
        let ends = match (free, velocities.first(), velocities.last()) {
            (true, Some(start), Some(end)) => Some((start.clone(), end.clone())),
            _ => None,
        };
        Ok(Fitted {
            keys,
            ends,
            report: FitReport {
                lambda,
                rms: (rss / total).sqrt(),
                max: dist.iter().fold(0.0, |m: f64, &d| m.max(d)),
                keys: idx.len(),
                key_times: self.key_times(idx),
                iterations,
                edf,
                residuals: dist.clone(),
            },
            knots: self.key_times(idx),
            dist,
        })
    }

    /// One trial of a search for λ: a Gauss–Newton step from the previous trial's fit (or the
    /// starting keys), which it replaces; its residual.
    fn trial(
        &self,
        lambda: f64,
        idx: &[usize],
        warm: &mut Start<Q>,
        iterations: &mut usize,
    ) -> Result<f64, SplineError> {
        let start = core::mem::replace(warm, Start::Keys(Vec::new(), false));
        let s = self.solve(lambda, idx, start, Until::Steps(1))?;
        *iterations += s.iterations;
        let rss = s.rss;
        *warm = Start::Fit(s);
        Ok(rss)
    }

    /// λ minimising the generalised cross-validation score, and the fit there.
    fn gcv(
        &self,
        idx: &[usize],
        start: Start<Q>,
        iterations: &mut usize,
    ) -> Result<(f64, Solved<Q>), SplineError> {
        let n = self.given() as f64;
        // A doubled loop's residual is twice the samples'.
        let share = n / self.points.len() as f64;
        let (lo, hi) = self.lambda_range();
        let mut warm = start;
        let mut score = |u: f64, warm: &mut Start<Q>| -> Result<f64, SplineError> {
            let lambda = math::exp(u);
            let rss = share * self.trial(lambda, idx, warm, iterations)?;
            let tr = self.trace(lambda);
            let denom = (n - tr).max(f64::MIN_POSITIVE);
            Ok(n * rss / (denom * denom))
        };
        // A grid of decades over the range, from the interpolating end (each trial starting
        // from the previous one's fit), then Brent's method between the neighbours of the best
        // grid point, to 1e-4 in ln λ.
        let step = core::f64::consts::LN_10;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a count of decades between finite logarithms, at most a few hundred"
        )]
        let count = (((hi - lo) / step).ceil() as usize).max(2);
        let mut grid = Vec::with_capacity(count + 1);
        let mut best: Option<(usize, f64, Start<Q>)> = None;
        for j in 0..=count {
            let u = lo + (hi - lo) * j as f64 / count as f64;
            let g = score(u, &mut warm)?;
            grid.push(u);
            if best.as_ref().is_none_or(|b| g < b.1)
                && let Start::Fit(s) = &warm
            {
                best = Some((j, g, Start::Fit(s.clone())));
            }
        }
        let Some((j, grid_g, Start::Fit(grid_fit))) = best else {
            unreachable!("a trial leaves its fit, and the grid has points")
        };
        let (a, b) = (grid[j.saturating_sub(1)], grid[(j + 1).min(grid.len() - 1)]);
        let mut warm = Start::Fit(grid_fit.clone());
        let (u, g) = brent_min(a, b, grid[j], grid_g, 1e-4, |u| score(u, &mut warm))?;
        // Brent's search stays inside its bracket; keep the grid's best if it is better.
        let (u, start) = if g <= grid_g {
            (u, warm)
        } else {
            (grid[j], Start::Fit(grid_fit))
        };
        let lambda = math::exp(u);
        let s = self.solve(lambda, idx, start, Until::Converged)?;
        Ok((lambda, s))
    }

    /// λ whose weighted RMS residual is `sigma`, and the fit there.
    fn rms_target(
        &self,
        idx: &[usize],
        start: Start<Q>,
        sigma: f64,
        iterations: &mut usize,
    ) -> Result<(f64, Solved<Q>), SplineError> {
        let total: f64 = self.weights.iter().sum();
        let (lo, hi) = self.lambda_range();
        // The range widened: below it the fit interpolates, above it it is the limit geodesic.
        let (mut a, mut b) = (
            lo - 4.0 * core::f64::consts::LN_10,
            hi + 8.0 * core::f64::consts::LN_10,
        );
        let mut warm = start;
        let mut rms_at = |u: f64, warm: &mut Start<Q>| -> Result<f64, SplineError> {
            Ok((self.trial(math::exp(u), idx, warm, iterations)? / total).sqrt())
        };
        let ra = rms_at(a, &mut warm)?;
        let Start::Fit(low) = &warm else {
            unreachable!("a trial leaves its fit")
        };
        let low = Start::Fit(low.clone());
        let rb = rms_at(b, &mut warm)?;
        if sigma < ra {
            return Err(invalid(
                "smoothing",
                format!(
                    "the target rms {sigma:e} rad is below the residual of the least-squares fit on these keys, {ra:e} rad"
                ),
            ));
        }
        if sigma > rb {
            return Err(invalid(
                "smoothing",
                format!(
                    "the target rms {sigma:e} rad is above the residual of the best constant-speed geodesic, {rb:e} rad"
                ),
            ));
        }
        // Illinois on f(u) = ln rms(u) − ln σ, bracketed.
        let target = math::ln(sigma);
        let (mut fa, mut fb) = (
            math::ln(ra.max(f64::MIN_POSITIVE)) - target,
            math::ln(rb) - target,
        );
        warm = low;
        let mut side = 0;
        for _ in 0..200 {
            let u = if fa.is_finite() && fa != fb {
                (a * fb - b * fa) / (fb - fa)
            } else {
                0.5 * (a + b)
            };
            let u = if u > a && u < b { u } else { 0.5 * (a + b) };
            let r = rms_at(u, &mut warm)?;
            let f = math::ln(r.max(f64::MIN_POSITIVE)) - target;
            if f.abs() <= 1e-10 || b - a <= 1e-13 * (1.0 + u.abs()) {
                let s = self.solve(math::exp(u), idx, warm, Until::Converged)?;
                return Ok((math::exp(u), s));
            }
            if f < 0.0 {
                a = u;
                fa = f;
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            } else {
                b = u;
                fb = f;
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            }
        }
        Err(SplineError::Solve(SolveError::NoConvergence {
            iterations: 200,
            residual: f64::NAN,
        }))
    }

    /// A range of `ln λ` over which the fit goes from nearly interpolating (`tr A ≥ N − 0.1`)
    /// to nearly the limit geodesic (`tr A ≤ 2.01`, closed `1.01`), from the hat matrix's
    /// trace alone.
    fn lambda_range(&self) -> (f64, f64) {
        let n = self.given() as f64;
        let tr = |u: f64| self.trace(math::exp(u));
        // The natural scale: λ ~ w·h³ for a sample spacing h.
        let span = self.times[self.times.len() - 1] - self.times[0];
        let h = span / n;
        let wmean = self.weights.iter().sum::<f64>() / n;
        let mut lo = math::ln(wmean * h * h * h);
        while tr(lo) < n - 0.1 && lo > -700.0 {
            lo -= core::f64::consts::LN_10;
        }
        let floor = if self.closed { 1.01 } else { 2.01 };
        let mut hi = lo + core::f64::consts::LN_10;
        while tr(hi) > floor && hi < 700.0 {
            hi += core::f64::consts::LN_10;
        }
        (lo, hi)
    }
}

/// Brent's minimisation of `f` on `[a, b]` from the point `x` inside with value `fx`
/// (golden-section steps and parabolic interpolation; Brent 1973, *Algorithms for Minimization
/// without Derivatives*, ch. 5), to the absolute tolerance `tol`: the best point and value.
fn brent_min(
    mut a: f64,
    mut b: f64,
    x0: f64,
    fx0: f64,
    tol: f64,
    mut f: impl FnMut(f64) -> Result<f64, SplineError>,
) -> Result<(f64, f64), SplineError> {
    const GOLD: f64 = 0.381_966_011_250_105_1;
    let (mut x, mut w, mut v) = (x0, x0, x0);
    let (mut fx, mut fw, mut fv) = (fx0, fx0, fx0);
    let (mut d, mut e) = (0.0_f64, 0.0_f64);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        let tol1 = tol;
        let tol2 = 2.0 * tol1;
        if (x - m).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol1 {
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            let mut q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            if p.abs() < (0.5 * q * e).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = if x < m { tol1 } else { -tol1 };
                }
                golden = false;
            }
        }
        if golden {
            e = if x < m { b - x } else { a - x };
            d = GOLD * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let fu = f(u)?;
        if fu <= fx {
            if u < x {
                b = x;
            } else {
                a = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Ok((x, fx))
}

fn start_dim<Q: Manifold>(c: &CubicSpline<Q>) -> usize {
    c.points()[0].to_vector().dim()
}
