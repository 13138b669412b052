// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The scene: reading and validating the JSON, building its curves, sampling them.

use serde::Deserialize;
use serde_json::{Map, Value, json};
use spherekit::{
    DomainError, Extrapolate, FitOptions, S2Point, SmPoint, SplineError, UnitQuat, unflip,
};

use crate::built::{BuiltCurve, ScenePoint};
use crate::error::{SceneError, field_error, in_curve};
use crate::fit;
use crate::json::json_error;
use crate::params::{Params, current_names};
use crate::registry::{KnotRule, Method};
use crate::rotation_loop;
use crate::space::Space;
use crate::timing::{Parametrization, extrapolate_name, parse_extrapolate};
use crate::view::View;

/// The most evaluations a scene may ask for: `samples` (or the number of `eval_at` parameters)
/// times the number of curves. Larger requests are rejected before anything is allocated.
pub const MAX_SAMPLES: usize = 1_000_000;

/// The number of samples when a scene gives neither `samples` nor `eval_at`.
pub const DEFAULT_SAMPLES: usize = 101;

/// The scene as written in JSON, before validation.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a scene object")]
struct RawScene {
    space: String,
    #[serde(default)]
    method: Option<String>,
    #[serde(default)]
    points: Option<Vec<Vec<f64>>>,
    #[serde(default)]
    knots: Option<Vec<f64>>,
    #[serde(default)]
    params: Option<Map<String, Value>>,
    #[serde(default)]
    canonicalize: Option<bool>,
    #[serde(default)]
    closed: Option<bool>,
    #[serde(default)]
    parametrization: Option<String>,
    #[serde(default)]
    extrapolate: Option<String>,
    #[serde(default)]
    color: Option<String>,
    #[serde(default)]
    label: Option<String>,
    #[serde(default)]
    fit: Option<Value>,
    #[serde(default)]
    curves: Option<Vec<RawCurve>>,
    #[serde(default)]
    samples: Option<f64>,
    #[serde(default)]
    eval_at: Option<Vec<f64>>,
    #[serde(default)]
    quaternion_order: Option<String>,
    #[serde(default)]
    view: Option<Value>,
}

/// One curve of a multi-curve scene, as written in JSON.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a curve object")]
struct RawCurve {
    method: String,
    points: Vec<Vec<f64>>,
    #[serde(default)]
    knots: Option<Vec<f64>>,
    #[serde(default)]
    params: Option<Map<String, Value>>,
    #[serde(default)]
    canonicalize: Option<bool>,
    #[serde(default)]
    closed: Option<bool>,
    #[serde(default)]
    parametrization: Option<String>,
    #[serde(default)]
    extrapolate: Option<String>,
    #[serde(default)]
    color: Option<String>,
    #[serde(default)]
    label: Option<String>,
    #[serde(default)]
    fit: Option<Value>,
}

/// Where to evaluate a curve.
#[derive(Clone, Debug, PartialEq)]
pub enum Sampling {
    /// `n ≥ 2` uniform parameters over the domain, both ends included.
    Uniform(usize),
    /// These parameters of the curve's domain (arc length for `"parametrization":
    /// "arclength"`); outside it the curve's `extrapolate` policy applies.
    At(Vec<f64>),
}

/// One curve of a scene: a method and its input.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveSpec {
    /// The construction.
    pub method: &'static Method,
    /// The input points as given (normalised when the curve is built).
    pub points: Vec<Vec<f64>>,
    /// Optional knots.
    pub knots: Option<Vec<f64>>,
    /// Method parameters.
    pub params: Map<String, Value>,
    /// Whether S³ keys are canonicalised with [`unflip`] before construction.
    pub canonicalize: bool,
    /// Whether the curve is a closed loop (after the last point it returns to the first).
    pub closed: bool,
    /// The curve's parameter: the method's own or arc length (`"parametrization"`).
    pub parametrization: Parametrization,
    /// What the curve is outside its domain (`"extrapolate"`, default `"hold"`).
    pub extrapolate: Extrapolate,
    /// The colour to draw it in, `[r, g, b]`, when the scene gives one (`"#rrggbb"`).
    pub color: Option<[u8; 3]>,
    /// The curve's name in the figure's legend, when the scene gives one (default: the method).
    pub label: Option<String>,
    /// `"fit"`: the points are samples at the times `knots`, and the curve is the cubic spline
    /// fitted to them (method `cubic` only; see [`FitRecord`](crate::FitRecord)).
    pub fit: Option<FitOptions>,
}

/// A validated scene: its fields are checked, the curves are built by [`Scene::build`].
///
/// A scene holds one curve (the fields `method`, `points`, `knots`, `params`, `canonicalize`,
/// `color`, `label` at the top level) or several on the same sphere (`"curves": [{ "method",
/// "points", "knots", "params", "canonicalize", "color", "label" }, …]`), for comparing methods on the same keys.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The sphere.
    pub space: Space,
    /// The curves, at least one.
    pub curves: Vec<CurveSpec>,
    /// Where to sample.
    pub sampling: Sampling,
    /// Rendering options (`view`), read and checked with the scene.
    pub view: View,
    /// S³: whether the scene writes quaternions scalar last, `[x, y, z, w]` (scipy's order),
    /// in its points and in the sample output. [`CurveSpec::points`] are always `[w, x, y, z]`.
    pub scalar_last: bool,
    /// Whether the curves came as a `curves` list (errors and output then name `curves[i]`).
    listed: bool,
}

fn samples_count(x: f64) -> Result<usize, SceneError> {
    if x.fract() != 0.0 || !(2.0..=MAX_SAMPLES as f64).contains(&x) {
        return Err(field_error(
            "samples",
            format!("must be a whole number from 2 to {MAX_SAMPLES}, got {x}"),
        ));
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "checked to be a whole number ≤ MAX_SAMPLES"
    )]
    Ok(x as usize)
}

/// Rejects a scene whose curves together would be evaluated more than [`MAX_SAMPLES`] times (a
/// `curves` list multiplies the per-curve count, so a small file could otherwise ask for 10¹⁰
/// evaluations).
fn check_total(curves: usize, sampling: &Sampling) -> Result<(), SceneError> {
    let (field, per_curve) = match sampling {
        Sampling::Uniform(n) => ("samples", *n),
        Sampling::At(ts) => ("eval_at", ts.len()),
    };
    if curves.saturating_mul(per_curve) > MAX_SAMPLES {
        return Err(field_error(
            field,
            format!(
                "{curves} curves × {per_curve} parameters exceed the limit of {MAX_SAMPLES} evaluations per scene"
            ),
        ));
    }
    Ok(())
}

fn parse_color(field: &str, c: Option<String>) -> Result<Option<[u8; 3]>, SceneError> {
    let Some(c) = c else { return Ok(None) };
    let hex = c
        .strip_prefix('#')
        .filter(|h| h.len() == 6 && h.bytes().all(|b| b.is_ascii_hexdigit()));
    let Some(hex) = hex else {
        return Err(field_error(
            field,
            format!("\"{c}\" is not a colour \"#rrggbb\""),
        ));
    };
    let byte = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).unwrap_or(0);
    Ok(Some([byte(0), byte(2), byte(4)]))
}

/// The most characters a curve's `label` may have.
pub const MAX_LABEL_CHARS: usize = 60;

fn parse_label(label: Option<String>) -> Result<Option<String>, SceneError> {
    let Some(l) = label else { return Ok(None) };
    let n = l.chars().count();
    if n == 0 || n > MAX_LABEL_CHARS || l.chars().any(char::is_control) {
        return Err(field_error(
            "label",
            format!("must be 1 to {MAX_LABEL_CHARS} characters on one line"),
        ));
    }
    Ok(Some(l))
}

impl CurveSpec {
    fn validate(space: Space, raw: RawCurve) -> Result<Self, SceneError> {
        let method = Method::find(&raw.method)?;
        if !method.spaces.contains(space) {
            return Err(field_error(
                "method",
                format!(
                    "\"{}\" works on {}, not {}",
                    method.id,
                    method.spaces.describe(),
                    space.name()
                ),
            ));
        }
        let n = space.coords();
        for (i, p) in raw.points.iter().enumerate() {
            if p.len() != n {
                return Err(field_error(
                    format!("points[{i}]"),
                    format!(
                        "has {} coordinates, {} points have {n}",
                        p.len(),
                        space.name()
                    ),
                ));
            }
        }
        if raw.canonicalize.is_some() && space != Space::S3 {
            return Err(field_error(
                "canonicalize",
                "applies to S3 (quaternion) scenes only",
            ));
        }
        let closed = raw.closed.unwrap_or(false);
        if closed && !method.closes {
            return Err(field_error(
                "closed",
                format!("method \"{}\" has no closed form", method.id),
            ));
        }
        if raw.knots.is_some() {
            match method.knots {
                KnotRule::PerPoint { .. } => {}
                KnotRule::Computed => {
                    return Err(field_error(
                        "knots",
                        format!(
                            "method \"{}\" computes its own knots (reported in info.knots)",
                            method.id
                        ),
                    ));
                }
                KnotRule::None => {
                    return Err(field_error(
                        "knots",
                        format!(
                            "method \"{}\" takes no knots (its parameter runs over [0, 1])",
                            method.id
                        ),
                    ));
                }
            }
        }
        let fit = raw
            .fit
            .as_ref()
            .map(|f| fit::parse(f, method, raw.points.len()))
            .transpose()?;
        let parametrization = Parametrization::parse(raw.parametrization.as_deref())?;
        let extrapolate = parse_extrapolate(raw.extrapolate.as_deref(), closed)?;
        Ok(Self {
            method,
            points: raw.points,
            knots: raw.knots,
            params: current_names(method, raw.params.unwrap_or_default())?,
            canonicalize: raw.canonicalize.unwrap_or(true),
            closed,
            parametrization,
            extrapolate,
            color: parse_color("color", raw.color)?,
            label: parse_label(raw.label)?,
            fit,
        })
    }

    /// Normalises the points and builds the curve, in its parametrisation and with its
    /// extrapolation policy.
    ///
    /// # Errors
    ///
    /// As [`Scene::build`], without the `curves[i]` prefix and without the check of the
    /// sample parameters.
    pub fn build(&self, space: Space) -> Result<BuiltCurve, SceneError> {
        if let Some(options) = &self.fit {
            let built = fit::build(self, options, space)?;
            return built.retime(self.parametrization, self.extrapolate);
        }
        let points = match space {
            Space::S2 => Points::S2(points(&self.points)?),
            Space::S3 => {
                let mut keys: Vec<UnitQuat> = points(&self.points)?;
                if self.canonicalize {
                    unflip(&mut keys);
                    // A loop of an odd number of full turns: closed in SO(3), at −q₀.
                    if self.closed && spherekit::closes_at_antipode(&keys) {
                        let built = rotation_loop::build(
                            self.method,
                            keys,
                            self.knots.clone(),
                            &self.params,
                        )?;
                        return built.retime(self.parametrization, self.extrapolate);
                    }
                }
                Points::S3(keys)
            }
            Space::Sm(_) => Points::Sm(points(&self.points)?),
        };
        let s3 = space == Space::S3;
        let canonicalized = self.canonicalize;
        let input = Input {
            points,
            knots: self.knots.clone(),
            closed: self.closed,
            params: Params::new(self.method, &self.params),
        };
        let built = (self.method.build)(input).map_err(|e| match e {
            // q and −q are one rotation: say so, and how to have the keys flipped.
            SceneError::Spline(error @ SplineError::Antipodal { .. }) if s3 && !canonicalized => {
                SceneError::Hinted {
                    error,
                    hint: "as quaternions they are q and −q, the same rotation: remove \"canonicalize\": false (or call unflip) to flip them",
                }
            }
            e => e,
        })?;
        built.retime(self.parametrization, self.extrapolate)
    }
}

/// The normalised points of a curve, on its sphere.
#[derive(Clone, Debug)]
pub(crate) enum Points {
    S2(Vec<S2Point>),
    S3(Vec<UnitQuat>),
    Sm(Vec<SmPoint>),
}

/// What a method's build function gets: the points on their sphere, the knots and the
/// parameters (each read through the method's schema).
#[derive(Debug)]
pub(crate) struct Input<'a> {
    pub(crate) points: Points,
    pub(crate) knots: Option<Vec<f64>>,
    pub(crate) closed: bool,
    pub(crate) params: Params<'a>,
}

pub(crate) fn points<P: ScenePoint>(raw: &[Vec<f64>]) -> Result<Vec<P>, SceneError> {
    raw.iter()
        .enumerate()
        .map(|(index, c)| {
            P::from_coords(c).map_err(|reason| SplineError::InvalidPoint { index, reason }.into())
        })
        .collect()
}

impl Scene {
    /// Parses and validates a scene (everything but the curve constructions themselves).
    ///
    /// # Errors
    ///
    /// [`SceneError::Json`] for text that is not a scene, [`SceneError::Field`] for a bad field.
    pub fn from_json(text: &str) -> Result<Self, SceneError> {
        let raw: RawScene =
            serde_json::from_str(text).map_err(|e| SceneError::Json(json_error(text, &e)))?;
        Self::from_raw(raw)
    }

    /// [`from_json`](Self::from_json) of a JSON value already parsed (a front end's object,
    /// an edited document), without writing it as text.
    ///
    /// # Errors
    ///
    /// As [`from_json`](Self::from_json), with the same messages: a value that is not a scene
    /// is written as text once, for the JSON path of what is wrong.
    pub fn from_value(value: &Value) -> Result<Self, SceneError> {
        match RawScene::deserialize(value) {
            Ok(raw) => Self::from_raw(raw),
            Err(_) => Self::from_json(&value.to_string()),
        }
    }

    fn from_raw(raw: RawScene) -> Result<Self, SceneError> {
        let space = Space::parse(&raw.space)?;
        let scalar_last = match raw.quaternion_order.as_deref() {
            None | Some("wxyz") => false,
            Some("xyzw") => true,
            Some(other) => {
                return Err(field_error(
                    "quaternion_order",
                    format!(
                        "\"{other}\" is not an order: use \"wxyz\" (scalar first, the default) or \"xyzw\" (scalar last, as scipy)"
                    ),
                ));
            }
        };
        if raw.quaternion_order.is_some() && space != Space::S3 {
            return Err(field_error(
                "quaternion_order",
                "applies to S3 (quaternion) scenes only",
            ));
        }
        let listed = raw.curves.is_some();
        let curves = match (raw.curves, raw.method, raw.points) {
            (Some(curves), None, None) => {
                if raw.knots.is_some()
                    || raw.params.is_some()
                    || raw.canonicalize.is_some()
                    || raw.closed.is_some()
                    || raw.parametrization.is_some()
                    || raw.extrapolate.is_some()
                    || raw.color.is_some()
                    || raw.label.is_some()
                    || raw.fit.is_some()
                {
                    return Err(field_error(
                        "curves",
                        "with \"curves\", give knots, params, canonicalize, closed, parametrization, extrapolate, color, label and fit inside each curve",
                    ));
                }
                if curves.is_empty() {
                    return Err(field_error("curves", "must list at least one curve"));
                }
                curves
                    .into_iter()
                    .enumerate()
                    .map(|(i, c)| CurveSpec::validate(space, c).map_err(|e| in_curve(Some(i), e)))
                    .collect::<Result<Vec<_>, _>>()?
            }
            (Some(_), _, _) => {
                return Err(field_error(
                    "curves",
                    "give either \"curves\" or a single curve's \"method\" and \"points\", not both",
                ));
            }
            (None, Some(method), Some(points)) => {
                let raw_curve = RawCurve {
                    method,
                    points,
                    knots: raw.knots,
                    params: raw.params,
                    canonicalize: raw.canonicalize,
                    closed: raw.closed,
                    parametrization: raw.parametrization,
                    extrapolate: raw.extrapolate,
                    color: raw.color,
                    label: raw.label,
                    fit: raw.fit,
                };
                vec![CurveSpec::validate(space, raw_curve)?]
            }
            (None, None, _) => return Err(SceneError::Json("missing field `method`".into())),
            (None, Some(_), None) => {
                return Err(SceneError::Json("missing field `points`".into()));
            }
        };
        let sampling = match (raw.samples, raw.eval_at) {
            (Some(_), Some(_)) => {
                return Err(field_error(
                    "eval_at",
                    "give either samples or eval_at, not both",
                ));
            }
            (Some(s), None) => Sampling::Uniform(samples_count(s)?),
            (None, Some(ts)) => {
                if ts.is_empty() || ts.len() > MAX_SAMPLES {
                    return Err(field_error(
                        "eval_at",
                        format!("must have 1 to {MAX_SAMPLES} parameters, got {}", ts.len()),
                    ));
                }
                Sampling::At(ts)
            }
            (None, None) => Sampling::Uniform(DEFAULT_SAMPLES),
        };
        check_total(curves.len(), &sampling)?;
        let mut curves = curves;
        if scalar_last {
            for c in &mut curves {
                for p in &mut c.points {
                    p.rotate_right(1);
                }
            }
        }
        let view = View::from_json(raw.view.as_ref(), space, curves.len())?;
        Ok(Self {
            space,
            curves,
            sampling,
            view,
            scalar_last,
            listed,
        })
    }

    /// Whether the curves came as a `curves` list (errors and output then name `curves[i]`).
    #[must_use]
    pub fn is_listed(&self) -> bool {
        self.listed
    }

    /// The scene's `view` options (checked when the scene was read).
    #[must_use]
    pub fn view(&self) -> &View {
        &self.view
    }

    /// Replaces the sampling by `n` uniform samples.
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] on `samples` unless `2 ≤ n ≤ MAX_SAMPLES` and the curves together
    /// stay within [`MAX_SAMPLES`] evaluations.
    pub fn set_samples(&mut self, n: usize) -> Result<(), SceneError> {
        #[expect(
            clippy::cast_precision_loss,
            reason = "only compared against a small limit"
        )]
        let sampling = Sampling::Uniform(samples_count(n as f64)?);
        check_total(self.curves.len(), &sampling)?;
        self.sampling = sampling;
        Ok(())
    }

    /// Replaces the sampling by these parameters (as `eval_at`; checked against the curves by
    /// [`Scene::build`]).
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] on `eval_at` for no parameters, or more than the curves together
    /// may be evaluated at ([`MAX_SAMPLES`]).
    pub fn set_parameters(&mut self, ts: Vec<f64>) -> Result<(), SceneError> {
        if ts.is_empty() || ts.len() > MAX_SAMPLES {
            return Err(field_error(
                "eval_at",
                format!("must have 1 to {MAX_SAMPLES} parameters, got {}", ts.len()),
            ));
        }
        let sampling = Sampling::At(ts);
        check_total(self.curves.len(), &sampling)?;
        self.sampling = sampling;
        Ok(())
    }

    /// Normalises the points and builds every curve, then checks the sample parameters
    /// against them ([`Scene::check_parameters`]).
    ///
    /// # Errors
    ///
    /// [`SceneError::Spline`] when a construction rejects its input, [`SceneError::Field`] for
    /// bad `params`, `parametrization` or `extrapolate`; in a multi-curve scene the message is
    /// prefixed with `curves[i]`. A bad sample parameter as [`Scene::check_parameters`].
    pub fn build(&self) -> Result<Vec<BuiltCurve>, SceneError> {
        let curves = self
            .curves
            .iter()
            .enumerate()
            .map(|(i, c)| {
                c.build(self.space)
                    .map_err(|e| in_curve(self.listed.then_some(i), e))
            })
            .collect::<Result<Vec<_>, _>>()?;
        self.check_parameters(&curves)?;
        Ok(curves)
    }

    /// Checks the explicit sample parameters (`eval_at`) against built curves: every one must
    /// be a finite number, and have a value under each curve's `extrapolate` policy (inside the
    /// domain under `"error"`; not so far out that the extension overflows).
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] naming the parameter, `eval_at[k]`, and the curve.
    pub fn check_parameters(&self, curves: &[BuiltCurve]) -> Result<(), SceneError> {
        self.check_parameters_of(&curves.iter().collect::<Vec<_>>())
    }

    /// [`Scene::check_parameters`] over borrowed curves.
    pub(crate) fn check_parameters_of(&self, curves: &[&BuiltCurve]) -> Result<(), SceneError> {
        let Sampling::At(ts) = &self.sampling else {
            return Ok(());
        };
        for (k, &t) in ts.iter().enumerate() {
            if !t.is_finite() {
                return Err(field_error(
                    format!("eval_at[{k}]"),
                    format!("{} is not a finite number", number(t)),
                ));
            }
            for (i, (spec, curve)) in self.curves.iter().zip(curves).enumerate() {
                let Err(e) = curve.check_parameter(spec.extrapolate, t) else {
                    continue;
                };
                let whose = if self.listed {
                    format!("curves[{i}]")
                } else {
                    "the curve".to_owned()
                };
                let policy = extrapolate_name(spec.extrapolate);
                let t = number(t);
                let message = match e {
                    DomainError::Outside { domain, .. } => format!(
                        "{t} is outside the domain [{}, {}] of {whose}, whose \"extrapolate\" is \"{policy}\"",
                        number(domain[0]),
                        number(domain[1])
                    ),
                    _ if spec.extrapolate == Extrapolate::Segment => format!(
                        "{t} is so far outside the domain of {whose} that its continued end segment overflows"
                    ),
                    _ => format!(
                        "{t} is so far outside the domain of {whose} that \"extrapolate\": \"{policy}\" has no value there"
                    ),
                };
                return Err(field_error(format!("eval_at[{k}]"), message));
            }
        }
        Ok(())
    }

    /// The parameters to sample a curve with the given domain at.
    #[must_use]
    pub fn parameters(&self, [t0, t1]: [f64; 2]) -> Vec<f64> {
        match &self.sampling {
            Sampling::At(ts) => ts.clone(),
            Sampling::Uniform(n) => {
                #[expect(clippy::cast_precision_loss, reason = "n ≤ MAX_SAMPLES")]
                let last = (n - 1) as f64;
                (0..*n)
                    .map(|i| {
                        #[expect(clippy::cast_precision_loss, reason = "i < MAX_SAMPLES")]
                        let u = i as f64 / last;
                        if i + 1 == *n { t1 } else { t0 + (t1 - t0) * u }
                    })
                    .collect()
            }
        }
    }

    /// Samples built curves into the JSON object printed by `spherekit sample`: `space`,
    /// `method`, `domain`, `t`, `points`, with `deriv` also `velocity`, `acceleration` and (S3)
    /// `angular_velocity`, `angular_acceleration`; `controls`, `auxiliary` and `info` when the
    /// method has them. A scene of several curves gives `space` and `curves`, a list of such
    /// objects without `space`.
    #[must_use]
    pub fn sample_json(&self, curves: &[BuiltCurve], deriv: bool) -> Value {
        self.sample_json_with(
            curves,
            SampleOptions {
                deriv,
                ..SampleOptions::default()
            },
        )
    }

    /// [`sample_json`](Self::sample_json) with every option; `continuity` adds
    /// `continuity: [{ "t", "c0", "c1", "c2", "g1" }, …]`, the jumps of the point, of the first
    /// and second derivatives and of the unit tangent at each interior joint (see
    /// [`spherekit::continuity`]).
    #[must_use]
    pub fn sample_json_with(&self, curves: &[BuiltCurve], options: SampleOptions) -> Value {
        let one = |spec: &CurveSpec, curve: &BuiltCurve| {
            let mut out = Map::new();
            out.insert("method".into(), json!(spec.method.id));
            curve.sample_into(self, options, &mut out);
            out
        };
        let mut out = Map::new();
        out.insert("space".into(), json!(self.space.name()));
        if let ([spec], [curve], false) = (self.curves.as_slice(), curves, self.listed) {
            out.extend(one(spec, curve));
        } else {
            let list = self
                .curves
                .iter()
                .zip(curves)
                .map(|(s, c)| Value::Object(one(s, c)));
            out.insert("curves".into(), Value::Array(list.collect()));
        }
        Value::Object(out)
    }
}

/// A parameter as an error message shows it: plain digits for ordinary sizes, an exponent for
/// very large and very small ones (`1e300`, not three hundred digits).
fn number(t: f64) -> String {
    if t != 0.0 && t.is_finite() && !(1e-5..1e16).contains(&t.abs()) {
        format!("{t:e}")
    } else {
        format!("{t}")
    }
}

/// What [`Scene::sample_json_with`] reports besides the points.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SampleOptions {
    /// Velocity and acceleration (and angular ones on S3).
    pub deriv: bool,
    /// Jumps at the joints.
    pub continuity: bool,
    /// S³: report angular velocity and acceleration in the body frame (`ω_body = q̄·ω·q`, as
    /// scipy's `RotationSpline` does) instead of the space frame.
    pub body_frame: bool,
}
