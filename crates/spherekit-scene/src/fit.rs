// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! A curve's `"fit"`: the scene's `points` are measured samples at the times `knots`, and the
//! curve is the cubic spline fitted to them ([`CubicSpline::try_fit`]: the smoothing spline, or
//! a spline on fewer keys): closed, or open with natural ends or (on fewer keys, λ given) fitted
//! end velocities.
//!
//! ```text
//! "fit": { "smoothing": λ | "gcv" | { "rms": σ },   optional; default "gcv" with a key at every
//!                                                    sample, λ = 0 with keys or max_error
//!          "weights": [w₀, …],                       optional; one positive number per sample
//!          "max_error": ε,                           optional; radians: the fewest keys within ε
//!          "keys": m }                               optional; m keys (not with max_error)
//! ```
//!
//! Only `"method": "cubic"` fits, and the fit sets the ends: the fit's `params` may give the
//! cubic's default `"end": "natural"` and nothing else. On S³ the samples are rotations (`q` and `−q` the same
//! sample) and every distance is a rotation angle; a closed S³ fit is a loop in SO(3)
//! ([`CubicSpline::try_fit_loop`]): samples that, taken the shorter way round, end on the far
//! side of the first (a loop of an odd number of turns, [`spherekit::closes_at_antipode`]) are
//! fitted by a curve that ends at `−q₀`, the same rotation.
//!
//! The built curve keeps a [`FitRecord`]: the sample times, the fitted keys, each sample's
//! residual and the core's [`FitReport`]; `info.fit` reports the same numbers as JSON
//! (without the keys, which are the curve's values at `key_times`).

use serde_json::{Map, Value, json};
use spherekit::{CubicSpline, FitKeys, FitOptions, FitReport, Smoothing, SplineError, UnitQuat};

use crate::built::{Built, BuiltCurve, ScenePoint, on_every_sphere};
use crate::error::{SceneError, field_error};
use crate::methods::cubic;
use crate::registry::Method;
use crate::scene::{CurveSpec, Points, points};
use crate::space::Space;

/// The keys of a `fit` object, with what each does (the registry lists them for the methods
/// that fit).
pub const FIT_FIELDS: [(&str, &str); 4] = [
    (
        "smoothing",
        "λ ≥ 0, \"gcv\" (generalised cross-validation) or {\"rms\": σ} (the weighted RMS residual σ, radians); default \"gcv\" with a key at every sample, λ = 0 with keys or max_error",
    ),
    ("weights", "one positive weight per sample (default 1)"),
    (
        "max_error",
        "ε, radians: the fewest keys among the sample times within ε of every sample",
    ),
    ("keys", "the number of keys among the sample times"),
];

/// The most samples a fit takes. Every solve is O(N), but "gcv" and `{"rms": σ}` solve for
/// dozens of λ and key reduction (`max_error`) refits once per key it tries: a scene of more
/// samples is refused with an error on `points` rather than left to run for minutes.
pub const MAX_FIT_SAMPLES: usize = 100_000;

/// Whether `method` takes a `fit` field.
pub(crate) fn applies_to(method: &Method) -> bool {
    core::ptr::eq(method, &cubic::METHOD)
}

/// What a fit found, kept with the built curve ([`Built::fit`]) for drawing the samples and
/// showing the residuals.
///
/// The samples themselves are the curve's [`Built::inputs`], one per scene point and in the
/// same order (on S³ canonicalised as the scene asks, which changes no rotation).
#[derive(Clone, Debug, PartialEq)]
pub struct FitRecord<P> {
    /// The time of each sample (the scene's `knots`; closed: and the return time last), in
    /// the curve's own parameter (before an arc-length reparametrisation).
    pub times: Vec<f64>,
    /// The fitted keys, at [`FitReport::key_times`] (closed: without the return).
    pub keys: Vec<P>,
    /// The core's report: λ, RMS and largest residual, key count and times, iterations, EDF,
    /// and each sample's residual (its distance to the curve at its time, radians: the
    /// great-circle angle, on S³ the rotation angle).
    pub report: FitReport,
}

/// The report as `info.fit`: `lambda`, `rms`, `max`, `keys`, `key_times`, `iterations`, `edf`
/// when the fit has one, and `residuals`, one per sample.
fn fit_json(report: &FitReport) -> Value {
    let mut out = Map::new();
    out.insert("lambda".into(), json!(report.lambda));
    out.insert("rms".into(), json!(report.rms));
    out.insert("max".into(), json!(report.max));
    out.insert("keys".into(), json!(report.keys));
    out.insert("key_times".into(), json!(report.key_times));
    out.insert("iterations".into(), json!(report.iterations));
    if let Some(edf) = report.edf {
        out.insert("edf".into(), json!(edf));
    }
    out.insert("residuals".into(), json!(report.residuals));
    Value::Object(out)
}

/// Reads a curve's `fit` object for `method` and `samples` points.
///
/// # Errors
///
/// A [`SceneError::Field`] on `fit` (not an object, a method other than the cubic, both `keys`
/// and `max_error`), `fit.<key>` (an unknown key, a value of the wrong type) or
/// `fit.weights[i]` (not a positive finite number). Ranges the core checks (λ ≥ 0, σ > 0,
/// ε > 0, the key count) are reported when the curve is built.
pub(crate) fn parse(
    value: &Value,
    method: &Method,
    samples: usize,
) -> Result<FitOptions, SceneError> {
    if !applies_to(method) {
        return Err(field_error(
            "fit",
            format!(
                "method \"{}\" does not fit samples: use \"method\": \"cubic\"",
                method.id
            ),
        ));
    }
    let Value::Object(map) = value else {
        return Err(field_error(
            "fit",
            "must be an object such as {\"smoothing\": \"gcv\"}",
        ));
    };
    if let Some(k) = map
        .keys()
        .find(|k| !FIT_FIELDS.iter().any(|(name, _)| name == k))
    {
        let known: Vec<_> = FIT_FIELDS.iter().map(|(name, _)| *name).collect();
        return Err(field_error(
            format!("fit.{k}"),
            format!("unknown fit option; known: {}", known.join(", ")),
        ));
    }
    let smoothing = map.get("smoothing").map(smoothing).transpose()?;
    let weights = map
        .get("weights")
        .map(|w| weights(w, samples))
        .transpose()?;
    let keys = match (map.get("keys"), map.get("max_error")) {
        (Some(_), Some(_)) => {
            return Err(field_error(
                "fit",
                "give \"keys\" or \"max_error\", not both",
            ));
        }
        (Some(m), None) => FitKeys::Count(
            m.as_u64()
                .and_then(|m| usize::try_from(m).ok())
                .ok_or_else(|| field_error("fit.keys", "must be a whole number of keys"))?,
        ),
        (None, Some(e)) => FitKeys::MaxError(
            e.as_f64()
                .ok_or_else(|| field_error("fit.max_error", "must be a number of radians"))?,
        ),
        (None, None) => FitKeys::Samples,
    };
    Ok(FitOptions {
        smoothing,
        weights,
        keys,
    })
}

fn smoothing(v: &Value) -> Result<Smoothing, SceneError> {
    let bad = || {
        field_error(
            "fit.smoothing",
            "must be a number λ ≥ 0, \"gcv\" or {\"rms\": σ}",
        )
    };
    match v {
        Value::Number(x) => x.as_f64().map(Smoothing::Lambda).ok_or_else(bad),
        Value::String(s) if s == "gcv" => Ok(Smoothing::Gcv),
        Value::Object(o) => match (o.len(), o.get("rms")) {
            (1, Some(Value::Number(s))) => s.as_f64().map(Smoothing::Rms).ok_or_else(bad),
            _ => Err(bad()),
        },
        _ => Err(bad()),
    }
}

fn weights(v: &Value, samples: usize) -> Result<Vec<f64>, SceneError> {
    let Value::Array(list) = v else {
        return Err(field_error(
            "fit.weights",
            "must be a list of positive numbers, one per sample",
        ));
    };
    if list.len() != samples {
        return Err(field_error(
            "fit.weights",
            format!(
                "must have one weight per sample: {samples} points, got {}",
                list.len()
            ),
        ));
    }
    list.iter()
        .enumerate()
        .map(|(i, w)| {
            w.as_f64()
                .filter(|w| w.is_finite() && *w > 0.0)
                .ok_or_else(|| {
                    field_error(
                        format!("fit.weights[{i}]"),
                        format!("must be a positive finite number, got {w}"),
                    )
                })
        })
        .collect()
}

/// Builds the fitted curve of `spec` (which has a `fit`) on `space`, before its
/// parametrisation and extrapolation are applied.
pub(crate) fn build(
    spec: &CurveSpec,
    options: &FitOptions,
    space: Space,
) -> Result<BuiltCurve, SceneError> {
    check_params(&spec.params)?;
    if spec.points.len() > MAX_FIT_SAMPLES {
        return Err(field_error(
            "points",
            format!(
                "a fit takes at most {MAX_FIT_SAMPLES} samples, got {}",
                spec.points.len()
            ),
        ));
    }
    let Some(times) = spec.knots.clone() else {
        return Err(field_error(
            "knots",
            if spec.closed {
                "are needed with \"fit\": the time of each point (sample), and the time the loop returns to the first"
            } else {
                "are needed with \"fit\": the time of each point (sample)"
            },
        ));
    };
    let samples = match space {
        Space::S2 => Points::S2(points(&spec.points)?),
        Space::S3 => {
            let mut samples: Vec<UnitQuat> = points(&spec.points)?;
            if spec.canonicalize {
                spherekit::unflip(&mut samples);
            }
            // Rotation samples: `q` and `−q` are one sample, distances are rotation angles
            // (not the fit of S^m, so not through `on_every_sphere!`).
            return if spec.closed {
                fitted_loop(samples, times, options)
            } else {
                fitted(samples, times, options, false)
            }
            .map(BuiltCurve::S3);
        }
        Space::Sm(_) => Points::Sm(points(&spec.points)?),
    };
    let closed = spec.closed;
    let built = on_every_sphere!(samples, |p| fitted(p, times.clone(), options, closed)?);
    Ok(built)
}

/// Only the cubic's default ends: the fit sets its ends.
fn check_params(params: &Map<String, Value>) -> Result<(), SceneError> {
    for (k, v) in params {
        if k == "end" && v.as_str() == Some("natural") {
            continue;
        }
        return Err(field_error(
            format!("params.{k}"),
            "does not apply with \"fit\": the fit sets the ends (natural, or fitted velocities on fewer keys)",
        ));
    }
    Ok(())
}

fn fitted<P: ScenePoint>(
    samples: Vec<P>,
    times: Vec<f64>,
    options: &FitOptions,
    closed: bool,
) -> Result<Built<P>, SceneError> {
    let (curve, report) =
        CubicSpline::try_fit(samples.clone(), times.clone(), options, closed).map_err(fit_error)?;
    let keys = curve.points().to_vec();
    let info = fit_json(&report);
    let mut built = cubic::finish(curve, samples, 2).with_info("fit", info);
    built.fit = Some(FitRecord {
        times,
        keys,
        report,
    });
    Ok(built)
}

/// The closed fit of rotations, a loop in SO(3) ([`CubicSpline::try_fit_loop`]: a loop of an
/// odd number of turns ends at `−q₀`).
fn fitted_loop(
    samples: Vec<UnitQuat>,
    times: Vec<f64>,
    options: &FitOptions,
) -> Result<Built<UnitQuat>, SceneError> {
    let (curve, report) =
        CubicSpline::try_fit_loop(samples.clone(), times.clone(), options).map_err(fit_error)?;
    let keys: Vec<UnitQuat> = report.key_times[..report.keys]
        .iter()
        .map(|&t| spherekit::Curve::eval(&curve, t))
        .collect();
    let info = fit_json(&report);
    let mut built = Built::new(curve, samples)
        .with_info("knots", json!(report.key_times))
        .with_info("fit", info)
        .with_order(2);
    built.fit = Some(FitRecord {
        times,
        keys,
        report,
    });
    Ok(built)
}

/// The core's parameter errors on the scene's fields (`fit.smoothing`, `fit.keys`, …); the
/// solver's as a failed fit.
fn fit_error(e: SplineError) -> SceneError {
    match e {
        SplineError::InvalidParameter { name, reason } => {
            field_error(format!("fit.{name}"), reason)
        }
        SplineError::Solve(e) => field_error("fit", format!("the fit did not converge ({e})")),
        e => SceneError::Spline(e),
    }
}
