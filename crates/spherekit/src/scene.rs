// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The JSON scene format: one description of a curve shared by the `spherekit` CLI, the
//! browser playground and the golden-image tests.
//!
//! ```text
//! { "space": "S2" | "S3" | "S<m>",      S3: quaternions [w, x, y, z]; S2: [x, y, z]; S<m>: m+1 numbers
//!   "method": "<method id>",            see Method
//!   "points": [[...], ...],             normalised on input; a point that cannot be is an error
//!   "knots": [...],                     optional, strictly increasing
//!   "params": { ... },                  optional, method specific
//!   "canonicalize": true | false,       optional; S3 only; default true (see unflip)
//!   "samples": 256,                     optional: uniform parameters over the domain, ends included
//!   "eval_at": [t, ...],                optional: explicit parameters instead of "samples"
//!   "view": { ... } }                   optional, used by rendering
//! ```
//!
//! Unknown fields are rejected, so a misspelt option is an error rather than silently ignored.
//!
//! # Examples
//!
//! ```
//! use spherekit::scene::Scene;
//!
//! let scene = Scene::from_json(r#"{ "space": "S2", "method": "geodesic",
//!     "points": [[1, 0, 0], [0, 2, 0]], "samples": 3 }"#).unwrap();
//! let out = scene.sample_json(&scene.build().unwrap(), false);
//! assert_eq!(out["t"], serde_json::json!([0.0, 0.5, 1.0]));
//! assert_eq!(out["points"][2], serde_json::json!([0.0, 1.0, 0.0]));
//!
//! let err = Scene::from_json(r#"{ "space": "S2", "method": "geodesic",
//!     "points": [[1, 0, 0], [0, 0, 0]] }"#).unwrap().build().unwrap_err();
//! assert_eq!(err.to_string(), "points[1] has zero length and cannot be normalised");
//! ```

use core::fmt;

use serde::Deserialize;
use serde_json::{Map, Value, json};

use crate::{
    Ambient, ArcBlend, BetaParams, BetaSolver, BetaSpline, Bezier, CatmullRom, CornerBlend,
    CornerBlendS3, Curve, DEFAULT_CORNER_FRACTION, GammaSpline, Gammas, GeodesicSpline, KimBSpline,
    KimBezier, LastEdge, MAX_BLEND_ORDER, Manifold, NlerpSpline, PointError, S2Point, ShapeParam,
    SnPoint, SplineError, Squad, UnitQuat, VecN, angular_velocity_acceleration, unflip,
};

/// The most evaluations a scene may ask for: `samples` (or the number of `eval_at` parameters)
/// times the number of curves. Larger requests are rejected before anything is allocated.
pub const MAX_SAMPLES: usize = 1_000_000;

/// The number of samples when a scene gives neither `samples` nor `eval_at`.
pub const DEFAULT_SAMPLES: usize = 101;

/// The largest sphere dimension m accepted in `"S<m>"`.
pub const MAX_DIMENSION: usize = 1024;

/// Why a scene could not be read or built. The `Display` text is one line naming the field.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SceneError {
    /// The text is not valid JSON or does not have the scene's shape.
    Json(String),
    /// A field has a bad value.
    Field {
        /// The field, as a JSON path such as `points[2]` or `params.gamma`.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// The curve could not be built.
    Spline(SplineError),
    /// An error in one curve of a scene's `curves` list.
    InCurve {
        /// Index into `curves`.
        index: usize,
        /// The error.
        error: Box<SceneError>,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Messages quote the scene's own strings (an unknown field or method name, a colour),
        // which may hold control characters such as a JSON-escaped newline: escape them so that
        // the text stays one line.
        let text = match self {
            Self::Json(m) => format!("invalid scene JSON: {m}"),
            Self::Field { field, message } => format!("{field}: {message}"),
            Self::Spline(e) => e.to_string(),
            Self::InCurve { index, error } => format!("curves[{index}].{error}"),
        };
        f.write_str(&one_line(&text))
    }
}

/// `text` with every control character escaped (`\n` becomes the two characters `\` `n`), so
/// that an error message quoting user input is one line.
///
/// ```
/// assert_eq!(spherekit::scene::one_line("a\nb\tc"), "a\\nb\\tc");
/// ```
#[must_use]
pub fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

impl core::error::Error for SceneError {}

impl From<SplineError> for SceneError {
    fn from(e: SplineError) -> Self {
        Self::Spline(e)
    }
}

fn field_error(field: impl Into<String>, message: impl Into<String>) -> SceneError {
    SceneError::Field {
        field: field.into(),
        message: message.into(),
    }
}

/// The sphere a scene lives on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Space {
    /// Directions, points `[x, y, z]`.
    S2,
    /// Orientations, unit quaternions `[w, x, y, z]`.
    S3,
    /// S^m for any other m ≥ 1, points of m + 1 coordinates.
    Sn(usize),
}

impl Space {
    /// Parses `"S2"`, `"S3"` or `"S<m>"`.
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] on `space` for anything else.
    pub fn parse(s: &str) -> Result<Self, SceneError> {
        let bad = || {
            field_error(
                "space",
                format!(
                    "\"{s}\" is not a sphere: use \"S2\", \"S3\" or \"S<m>\" with 1 ≤ m ≤ {MAX_DIMENSION}"
                ),
            )
        };
        let m: usize = s
            .strip_prefix('S')
            .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
            .and_then(|d| d.parse().ok())
            .ok_or_else(bad)?;
        match m {
            2 => Ok(Self::S2),
            3 => Ok(Self::S3),
            1..=MAX_DIMENSION => Ok(Self::Sn(m)),
            _ => Err(bad()),
        }
    }

    /// The number of coordinates of a point.
    #[must_use]
    pub fn coords(self) -> usize {
        match self {
            Self::S2 => 3,
            Self::S3 => 4,
            Self::Sn(m) => m + 1,
        }
    }

    /// The scene name, `"S2"`, `"S3"` or `"S<m>"`.
    #[must_use]
    pub fn name(self) -> String {
        match self {
            Self::S2 => "S2".into(),
            Self::S3 => "S3".into(),
            Self::Sn(m) => format!("S{m}"),
        }
    }
}

/// The curve constructions a scene can name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Method {
    /// Piecewise geodesic (slerp) through the points.
    Geodesic,
    /// Piecewise normalised-linear interpolation through the points.
    Nlerp,
    /// One spherical Bézier curve by de Casteljau.
    Bezier,
    /// Kim–Kim–Shin's cumulative Bézier quaternion curve.
    BezierKim,
    /// Kim–Kim–Shin's cumulative cubic B-spline quaternion curve.
    BsplineKim,
    /// Shoemake's squad.
    Squad,
    /// Catmull-Rom by slerps.
    CatmullRom,
    /// Gamma quaternion spline.
    Gamma,
    /// Spherical Beta spline.
    Beta,
    /// Pobegailo's interpolating spline by blending circle arcs.
    ArcBlend,
    /// Pobegailo's corner smoothing of a great-circle polyline.
    CornerBlend,
}

/// Which spaces a method supports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Support {
    /// S², S³ and every S^m.
    All,
    /// S³ only.
    S3,
}

impl Method {
    /// Every method, in the order `spherekit methods` lists them.
    pub const ALL: [Self; 11] = [
        Self::Geodesic,
        Self::Nlerp,
        Self::Bezier,
        Self::BezierKim,
        Self::BsplineKim,
        Self::Squad,
        Self::CatmullRom,
        Self::Gamma,
        Self::Beta,
        Self::ArcBlend,
        Self::CornerBlend,
    ];

    /// The scene id.
    #[must_use]
    pub fn id(self) -> &'static str {
        match self {
            Self::Geodesic => "geodesic",
            Self::Nlerp => "nlerp",
            Self::Bezier => "bezier",
            Self::BezierKim => "bezier-kim",
            Self::BsplineKim => "bspline-kim",
            Self::Squad => "squad",
            Self::CatmullRom => "catmull-rom",
            Self::Gamma => "gamma",
            Self::Beta => "beta",
            Self::ArcBlend => "arc-blend",
            Self::CornerBlend => "corner-blend",
        }
    }

    /// A one-line description.
    #[must_use]
    pub fn summary(self) -> &'static str {
        match self {
            Self::Geodesic => "piecewise geodesic (slerp) through the points",
            Self::Nlerp => "piecewise normalised-linear interpolation through the points",
            Self::Bezier => "spherical Bézier curve of any degree by de Casteljau",
            Self::BezierKim => "Kim-Kim-Shin cumulative Bézier quaternion curve",
            Self::BsplineKim => "Kim-Kim-Shin cumulative cubic B-spline quaternion curve (C²)",
            Self::Squad => "Shoemake's squad through keys",
            Self::CatmullRom => "Catmull-Rom spline by slerps",
            Self::Gamma => "Gamma quaternion spline (Boehm's Gamma spline on S³)",
            Self::Beta => "spherical Beta spline with bias and tension, interpolating",
            Self::ArcBlend => "Pobegailo's Cⁿ spline blending circle arcs",
            Self::CornerBlend => "Pobegailo's corner smoothing of a great-circle polyline",
        }
    }

    /// The spaces the method supports.
    #[must_use]
    pub fn support(self) -> Support {
        match self {
            Self::Geodesic
            | Self::Nlerp
            | Self::Bezier
            | Self::Beta
            | Self::CatmullRom
            | Self::ArcBlend
            | Self::CornerBlend => Support::All,
            Self::BezierKim | Self::BsplineKim | Self::Squad | Self::Gamma => Support::S3,
        }
    }

    /// Parses a method id.
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] on `method` listing the known ids.
    pub fn parse(id: &str) -> Result<Self, SceneError> {
        Self::ALL.into_iter().find(|m| m.id() == id).ok_or_else(|| {
            let ids: Vec<_> = Self::ALL.iter().map(|m| m.id()).collect();
            field_error(
                "method",
                format!("unknown method \"{id}\"; known: {}", ids.join(", ")),
            )
        })
    }

    fn supports(self, space: Space) -> bool {
        match self.support() {
            Support::All => true,
            Support::S3 => space == Space::S3,
        }
    }
}

impl Support {
    /// A human-readable list of the spaces.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Self::All => "S2, S3, S<m>",
            Self::S3 => "S3",
        }
    }
}

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
    color: Option<String>,
    #[serde(default)]
    curves: Option<Vec<RawCurve>>,
    #[serde(default)]
    samples: Option<f64>,
    #[serde(default)]
    eval_at: Option<Vec<f64>>,
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
    color: Option<String>,
}

/// Where to evaluate a curve.
#[derive(Clone, Debug, PartialEq)]
pub enum Sampling {
    /// `n ≥ 2` uniform parameters over the domain, both ends included.
    Uniform(usize),
    /// These parameters (clamped to the domain by the curve).
    At(Vec<f64>),
}

/// One curve of a scene: a method and its input.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveSpec {
    /// The construction.
    pub method: Method,
    /// The input points as given (normalised when the curve is built).
    pub points: Vec<Vec<f64>>,
    /// Optional knots.
    pub knots: Option<Vec<f64>>,
    /// Method parameters.
    pub params: Map<String, Value>,
    /// Whether S³ keys are canonicalised with [`unflip`] before construction.
    pub canonicalize: bool,
    /// The colour to draw it in, `[r, g, b]`, when the scene gives one (`"#rrggbb"`).
    pub color: Option<[u8; 3]>,
}

/// A validated scene: its fields are checked, the curves are built by [`Scene::build`].
///
/// A scene holds one curve (the fields `method`, `points`, `knots`, `params`, `canonicalize`,
/// `color` at the top level) or several on the same sphere (`"curves": [{ "method", "points",
/// "knots", "params", "canonicalize", "color" }, …]`), for comparing methods on the same keys.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The sphere.
    pub space: Space,
    /// The curves, at least one.
    pub curves: Vec<CurveSpec>,
    /// Where to sample.
    pub sampling: Sampling,
    /// Rendering options, passed through to the renderer.
    pub view: Option<Value>,
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

/// Wraps an error with the curve it belongs to in a `curves` list.
fn in_curve(index: Option<usize>, e: SceneError) -> SceneError {
    match index {
        None => e,
        Some(index) => SceneError::InCurve {
            index,
            error: Box::new(e),
        },
    }
}

impl CurveSpec {
    fn validate(space: Space, raw: RawCurve) -> Result<Self, SceneError> {
        let method = Method::parse(&raw.method)?;
        if !method.supports(space) {
            return Err(field_error(
                "method",
                format!(
                    "\"{}\" works on {}, not {}",
                    method.id(),
                    method.support().describe(),
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
        Ok(Self {
            method,
            points: raw.points,
            knots: raw.knots,
            params: raw.params.unwrap_or_default(),
            canonicalize: raw.canonicalize.unwrap_or(true),
            color: parse_color("color", raw.color)?,
        })
    }

    fn build(&self, space: Space) -> Result<BuiltCurve, SceneError> {
        let params = Params::new(self.method, &self.params);
        Ok(match space {
            Space::S2 => BuiltCurve::S2(build_any(self, points(&self.points)?, params)?),
            Space::S3 => {
                let mut keys: Vec<UnitQuat> = points(&self.points)?;
                if self.canonicalize {
                    unflip(&mut keys);
                }
                BuiltCurve::S3(build_s3(self, keys, params)?)
            }
            Space::Sn(_) => BuiltCurve::Sn(build_any(self, points(&self.points)?, params)?),
        })
    }
}

/// A parse error's text, prefixed by the JSON path where it happened (`points[1][0]: number
/// out of range at line 1 column 31`) when the error is inside the document.
fn json_error(text: &str, e: &serde_json::Error) -> String {
    if e.line() == 0 {
        return e.to_string();
    }
    let line_start: usize = text
        .split_inclusive('\n')
        .take(e.line() - 1)
        .map(str::len)
        .sum();
    // serde_json's column counts the bytes of the line read so far; a syntax error is found
    // at the byte after the culprit (`[1 2]` stops at `2`), so that byte is not scanned.
    let mut offset = line_start + e.column();
    if e.classify() == serde_json::error::Category::Syntax {
        offset = offset.saturating_sub(1);
    }
    // An unknown key is named by the message: the path is the object holding it.
    let path = json_path_at(text, offset, e.to_string().starts_with("unknown field"));
    if path.is_empty() {
        e.to_string()
    } else {
        format!("{path}: {e}")
    }
}

/// The JSON path (`curves[0].points[2]`) of the value being read at byte `offset` of `text`,
/// found by scanning the brackets, keys and commas before it; empty at the top level. With
/// `parent`, the path of the object whose key is being read (without that key).
fn json_path_at(text: &str, offset: usize, parent: bool) -> String {
    enum Frame {
        Object {
            key: Option<String>,
            expecting_key: bool,
        },
        Array(usize),
    }
    let bytes = &text.as_bytes()[..offset.min(text.len())];
    let mut stack: Vec<Frame> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                let start = i + 1;
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                if let Some(Frame::Object { key, expecting_key }) = stack.last_mut()
                    && *expecting_key
                    && i < bytes.len()
                {
                    *key = Some(String::from_utf8_lossy(&bytes[start..i]).into_owned());
                    *expecting_key = false;
                }
            }
            b'{' => stack.push(Frame::Object {
                key: None,
                expecting_key: true,
            }),
            b'[' => stack.push(Frame::Array(0)),
            b'}' | b']' => {
                stack.pop();
            }
            b',' => match stack.last_mut() {
                Some(Frame::Array(index)) => *index += 1,
                Some(Frame::Object { key, expecting_key }) => {
                    *key = None;
                    *expecting_key = true;
                }
                None => {}
            },
            _ => {}
        }
        i += 1;
    }
    if parent && matches!(stack.last(), Some(Frame::Object { .. })) {
        stack.pop();
    }
    let mut path = String::new();
    for (depth, frame) in stack.iter().enumerate() {
        if depth == 12 {
            path.push('…');
            break;
        }
        match frame {
            Frame::Object { key: Some(key), .. } => {
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
            }
            Frame::Object { key: None, .. } => break,
            Frame::Array(index) => path.push_str(&format!("[{index}]")),
        }
    }
    one_line(&path)
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
        let space = Space::parse(&raw.space)?;
        let listed = raw.curves.is_some();
        let curves = match (raw.curves, raw.method, raw.points) {
            (Some(curves), None, None) => {
                if raw.knots.is_some()
                    || raw.params.is_some()
                    || raw.canonicalize.is_some()
                    || raw.color.is_some()
                {
                    return Err(field_error(
                        "curves",
                        "with \"curves\", give knots, params, canonicalize and color inside each curve",
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
                    color: raw.color,
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
        Ok(Self {
            space,
            curves,
            sampling,
            view: raw.view,
            listed,
        })
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

    /// Normalises the points and builds every curve.
    ///
    /// # Errors
    ///
    /// [`SceneError::Spline`] when a construction rejects its input, [`SceneError::Field`] for
    /// bad `params`; in a
    /// multi-curve scene the message is prefixed with `curves[i]`.
    pub fn build(&self) -> Result<Vec<BuiltCurve>, SceneError> {
        self.curves
            .iter()
            .enumerate()
            .map(|(i, c)| {
                c.build(self.space)
                    .map_err(|e| in_curve(self.listed.then_some(i), e))
            })
            .collect()
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
                continuity: false,
            },
        )
    }

    /// [`sample_json`](Self::sample_json) with every option; `continuity` adds
    /// `continuity: [{ "t", "c0", "c1", "c2", "g1" }, …]`, the jumps of the point, of the first
    /// and second derivatives and of the unit tangent at each interior joint (see
    /// [`continuity`](crate::continuity)).
    #[must_use]
    pub fn sample_json_with(&self, curves: &[BuiltCurve], options: SampleOptions) -> Value {
        let one = |spec: &CurveSpec, curve: &BuiltCurve| {
            let mut out = Map::new();
            out.insert("method".into(), json!(spec.method.id()));
            match curve {
                BuiltCurve::S2(b) => b.sample_into(self, options, &mut out),
                BuiltCurve::S3(b) => b.sample_into(self, options, &mut out),
                BuiltCurve::Sn(b) => b.sample_into(self, options, &mut out),
            }
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

/// What [`Scene::sample_json_with`] reports besides the points.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SampleOptions {
    /// Velocity and acceleration (and angular ones on S3).
    pub deriv: bool,
    /// Jumps at the joints.
    pub continuity: bool,
}

/// A curve built from a scene, with the extras a method derives.
#[derive(Debug)]
pub struct Built<P: Manifold> {
    /// The curve.
    pub curve: Box<dyn Curve<Point = P>>,
    /// The scene's points, normalised (and on S³ canonicalised when the scene asks for it).
    pub inputs: Vec<P>,
    /// Derived control points (empty when the method has none).
    pub controls: Vec<P>,
    /// Auxiliary vertices solved for (empty when the method has none).
    pub auxiliary: Vec<P>,
    /// Method-specific facts, such as solver iterations.
    pub info: Map<String, Value>,
}

impl<P: ScenePoint> Built<P> {
    fn with_controls(mut self, controls: Vec<P>) -> Self {
        self.controls = controls;
        self
    }

    fn with_info(mut self, key: &str, value: Value) -> Self {
        self.info.insert(key.into(), value);
        self
    }

    fn new(curve: impl Curve<Point = P> + 'static, inputs: Vec<P>) -> Self {
        Self {
            curve: Box::new(curve),
            inputs,
            controls: Vec::new(),
            auxiliary: Vec::new(),
            info: Map::new(),
        }
    }

    fn sample_into(&self, scene: &Scene, options: SampleOptions, out: &mut Map<String, Value>) {
        let deriv = options.deriv;
        let domain = self.curve.domain();
        let ts = scene.parameters(domain);
        let mut points = Vec::with_capacity(ts.len());
        let mut velocity = Vec::new();
        let mut acceleration = Vec::new();
        let mut omega = Vec::new();
        let mut alpha = Vec::new();
        // Batch evaluation: one call for all parameters, the same values as `jet`/`eval`.
        if deriv {
            let mut jets = vec![self.curve.jet(domain[0]); ts.len()];
            self.curve.jet_many(&ts, &mut jets);
            for jet in &jets {
                if let Some((w, a)) = P::angular(jet) {
                    omega.push(json!(w));
                    alpha.push(json!(a));
                }
                velocity.push(json!(P::vector_coords(&jet.velocity)));
                acceleration.push(json!(P::vector_coords(&jet.acceleration)));
                points.push(json!(jet.point.coords()));
            }
        } else {
            let mut ps = vec![self.curve.eval(domain[0]); ts.len()];
            self.curve.eval_many(&ts, &mut ps);
            points.extend(ps.iter().map(|p| json!(p.coords())));
        }
        out.insert("domain".into(), json!(domain));
        out.insert("t".into(), json!(ts));
        out.insert("points".into(), Value::Array(points));
        if deriv {
            out.insert("velocity".into(), Value::Array(velocity));
            out.insert("acceleration".into(), Value::Array(acceleration));
            if !omega.is_empty() {
                out.insert("angular_velocity".into(), Value::Array(omega));
                out.insert("angular_acceleration".into(), Value::Array(alpha));
            }
        }
        let list = |ps: &[P]| Value::Array(ps.iter().map(|p| json!(p.coords())).collect());
        if !self.controls.is_empty() {
            out.insert("controls".into(), list(&self.controls));
        }
        if !self.auxiliary.is_empty() {
            out.insert("auxiliary".into(), list(&self.auxiliary));
        }
        if !self.info.is_empty() {
            out.insert("info".into(), Value::Object(self.info.clone()));
        }
        if options.continuity {
            let joints: Vec<Value> = crate::continuity(&*self.curve)
                .iter()
                .map(|j| json!({ "t": j.t, "c0": j.c0, "c1": j.c1, "c2": j.c2, "g1": j.g1 }))
                .collect();
            out.insert("continuity".into(), Value::Array(joints));
        }
    }
}

/// A curve built from a scene, on its space.
#[derive(Debug)]
pub enum BuiltCurve {
    /// A curve on S².
    S2(Built<S2Point>),
    /// A curve of orientations.
    S3(Built<UnitQuat>),
    /// A curve on S^m.
    Sn(Built<SnPoint>),
}

/// The fields [`BuiltCurve::sample_field`] gives, as [`Scene::sample_json`] names them.
pub const SAMPLE_FIELDS: [&str; 9] = [
    "t",
    "points",
    "velocity",
    "acceleration",
    "angular_velocity",
    "angular_acceleration",
    "controls",
    "auxiliary",
    "domain",
];

impl BuiltCurve {
    /// One field of [`Scene::sample_json`] for this curve, its rows one after another, without
    /// building JSON: `t`, `points`, `velocity`, `acceleration`, `angular_velocity` and
    /// `angular_acceleration` (S³; empty elsewhere), `controls`, `auxiliary` (empty when the
    /// method has none) or `domain`. `None` for any other name (see [`SAMPLE_FIELDS`]).
    ///
    /// ```
    /// use spherekit::scene::Scene;
    ///
    /// let scene = Scene::from_json(r#"{"space":"S2","method":"geodesic","samples":3,
    ///     "points":[[1,0,0],[0,1,0]]}"#).unwrap();
    /// let curves = scene.build().unwrap();
    /// let points = curves[0].sample_field(&scene, "points").unwrap();
    /// assert_eq!(points.len(), 3 * 3);
    /// assert!((points[3] - 0.5_f64.sqrt()).abs() < 1e-15); // the middle sample, x
    /// assert!(curves[0].sample_field(&scene, "speed").is_none());
    /// ```
    #[must_use]
    pub fn sample_field(&self, scene: &Scene, field: &str) -> Option<Vec<f64>> {
        match self {
            Self::S2(b) => b.sample_field(scene, field),
            Self::S3(b) => b.sample_field(scene, field),
            Self::Sn(b) => b.sample_field(scene, field),
        }
    }
}

impl<P: ScenePoint> Built<P> {
    fn sample_field(&self, scene: &Scene, field: &str) -> Option<Vec<f64>> {
        let domain = self.curve.domain();
        let flat = |ps: &[P]| ps.iter().flat_map(ScenePoint::coords).collect();
        Some(match field {
            "domain" => domain.to_vec(),
            "t" => scene.parameters(domain),
            "controls" => flat(&self.controls),
            "auxiliary" => flat(&self.auxiliary),
            "points" => {
                let ts = scene.parameters(domain);
                let mut ps = vec![self.curve.eval(domain[0]); ts.len()];
                self.curve.eval_many(&ts, &mut ps);
                flat(&ps)
            }
            "angular_velocity" | "angular_acceleration"
                if P::angular(&self.curve.jet(domain[0])).is_none() =>
            {
                Vec::new()
            }
            "velocity" | "acceleration" | "angular_velocity" | "angular_acceleration" => {
                let ts = scene.parameters(domain);
                let mut jets = vec![self.curve.jet(domain[0]); ts.len()];
                self.curve.jet_many(&ts, &mut jets);
                let mut out = Vec::with_capacity(3 * jets.len());
                for jet in &jets {
                    match (field, P::angular(jet)) {
                        ("velocity", _) => out.extend(P::vector_coords(&jet.velocity)),
                        ("acceleration", _) => out.extend(P::vector_coords(&jet.acceleration)),
                        ("angular_velocity", Some((w, _))) => out.extend(w),
                        ("angular_acceleration", Some((_, a))) => out.extend(a),
                        _ => {}
                    }
                }
                out
            }
            _ => return None,
        })
    }
}

/// The conversions between a sphere's points and the scene's number lists.
pub trait ScenePoint: Manifold + 'static {
    /// Builds a point from scene coordinates (normalising).
    ///
    /// # Errors
    ///
    /// As the point type's `try_new`.
    fn from_coords(c: &[f64]) -> Result<Self, PointError>;
    /// The scene coordinates.
    fn coords(&self) -> Vec<f64>;
    /// An ambient vector in the scene's coordinate order.
    fn vector_coords(v: &Self::Vector) -> Vec<f64>;
    /// Angular velocity and acceleration (space frame) where the space has them.
    fn angular(_jet: &crate::Jet<Self>) -> Option<([f64; 3], [f64; 3])> {
        None
    }
}

impl ScenePoint for S2Point {
    fn from_coords(c: &[f64]) -> Result<Self, PointError> {
        Self::try_new(glam::DVec3::from_slice(c))
    }
    fn coords(&self) -> Vec<f64> {
        self.as_dvec3().to_array().to_vec()
    }
    fn vector_coords(v: &glam::DVec3) -> Vec<f64> {
        v.to_array().to_vec()
    }
}

impl ScenePoint for UnitQuat {
    fn from_coords(c: &[f64]) -> Result<Self, PointError> {
        Self::from_wxyz([c[0], c[1], c[2], c[3]])
    }
    fn coords(&self) -> Vec<f64> {
        self.to_wxyz().to_vec()
    }
    fn vector_coords(v: &glam::DVec4) -> Vec<f64> {
        vec![v.w, v.x, v.y, v.z]
    }
    fn angular(jet: &crate::Jet<Self>) -> Option<([f64; 3], [f64; 3])> {
        let (w, a) = angular_velocity_acceleration(jet.point, jet.velocity, jet.acceleration);
        Some((w.to_array(), a.to_array()))
    }
}

impl ScenePoint for SnPoint {
    fn from_coords(c: &[f64]) -> Result<Self, PointError> {
        Self::try_new(c.to_vec())
    }
    fn coords(&self) -> Vec<f64> {
        SnPoint::coords(self).to_vec()
    }
    fn vector_coords(v: &VecN) -> Vec<f64> {
        v.to_vec()
    }
}

fn points<P: ScenePoint>(raw: &[Vec<f64>]) -> Result<Vec<P>, SceneError> {
    raw.iter()
        .enumerate()
        .map(|(index, c)| {
            P::from_coords(c).map_err(|reason| SplineError::InvalidPoint { index, reason }.into())
        })
        .collect()
}

/// A parameter given as one number for every point or joint, or as a list.
enum NumberOrList {
    One(f64),
    List(Vec<f64>),
}

/// Typed access to a method's `params`; unknown keys are an error.
struct Params<'a> {
    method: Method,
    map: &'a Map<String, Value>,
    used: Vec<&'static str>,
}

#[allow(
    dead_code,
    reason = "accessors are used by the methods as they are wired in"
)]
impl<'a> Params<'a> {
    fn new(method: Method, map: &'a Map<String, Value>) -> Self {
        Self {
            method,
            map,
            used: Vec::new(),
        }
    }

    fn get(&mut self, name: &'static str) -> Option<&'a Value> {
        self.used.push(name);
        self.map.get(name)
    }

    fn number(&mut self, name: &'static str, default: f64) -> Result<f64, SceneError> {
        match self.get(name) {
            None => Ok(default),
            Some(v) => v
                .as_f64()
                .filter(|x| x.is_finite())
                .ok_or_else(|| field_error(format!("params.{name}"), "must be a finite number")),
        }
    }

    /// A number, a list of numbers, or absent (`None`). Ranges and list lengths are checked by
    /// the construction, which knows them.
    fn number_or_list(&mut self, name: &'static str) -> Result<Option<NumberOrList>, SceneError> {
        match self.get(name) {
            None => Ok(None),
            Some(Value::Array(a)) => a
                .iter()
                .enumerate()
                .map(|(i, v)| {
                    v.as_f64().ok_or_else(|| {
                        field_error(format!("params.{name}[{i}]"), "must be a number")
                    })
                })
                .collect::<Result<_, _>>()
                .map(|list| Some(NumberOrList::List(list))),
            Some(v) => v
                .as_f64()
                .map(|x| Some(NumberOrList::One(x)))
                .ok_or_else(|| {
                    field_error(
                        format!("params.{name}"),
                        "must be a number or a list of numbers",
                    )
                }),
        }
    }

    fn integer(&mut self, name: &'static str, default: u64) -> Result<u64, SceneError> {
        match self.get(name) {
            None => Ok(default),
            Some(v) => v
                .as_u64()
                .ok_or_else(|| field_error(format!("params.{name}"), "must be a whole number ≥ 0")),
        }
    }

    fn boolean(&mut self, name: &'static str, default: bool) -> Result<bool, SceneError> {
        match self.get(name) {
            None => Ok(default),
            Some(v) => v
                .as_bool()
                .ok_or_else(|| field_error(format!("params.{name}"), "must be true or false")),
        }
    }

    /// One of `choices` (the first is the default).
    fn choice(
        &mut self,
        name: &'static str,
        choices: &[&'static str],
    ) -> Result<&'static str, SceneError> {
        match self.get(name) {
            None => Ok(choices[0]),
            Some(v) => v
                .as_str()
                .and_then(|s| choices.iter().find(|c| **c == s).copied())
                .ok_or_else(|| {
                    field_error(
                        format!("params.{name}"),
                        format!("must be one of: {}", choices.join(", ")),
                    )
                }),
        }
    }

    /// `params.order`, the continuity order n of Pobegailo's blends (default 2).
    fn order(&mut self) -> Result<usize, SceneError> {
        let n = self.integer("order", 2)?;
        usize::try_from(n)
            .ok()
            .filter(|n| (1..=MAX_BLEND_ORDER).contains(n))
            .ok_or_else(|| {
                field_error(
                    "params.order",
                    format!("must be a whole number from 1 to {MAX_BLEND_ORDER}, got {n}"),
                )
            })
    }

    /// Rejects keys no accessor asked for.
    fn finish(self) -> Result<(), SceneError> {
        match self.map.keys().find(|k| !self.used.contains(&k.as_str())) {
            None => Ok(()),
            Some(k) => Err(field_error(
                format!("params.{k}"),
                format!("unknown parameter for method \"{}\"", self.method.id()),
            )),
        }
    }
}

/// Methods that work on every sphere.
fn build_any<P: ScenePoint>(
    spec: &CurveSpec,
    points: Vec<P>,
    mut params: Params<'_>,
) -> Result<Built<P>, SceneError> {
    let knots = spec.knots.clone();
    Ok(match spec.method {
        Method::Geodesic => {
            params.finish()?;
            Built::new(GeodesicSpline::try_new(points.clone(), knots)?, points)
        }
        Method::Nlerp => {
            params.finish()?;
            Built::new(NlerpSpline::try_new(points.clone(), knots)?, points)
        }
        Method::Bezier => {
            params.finish()?;
            no_knots(spec)?;
            Built::new(Bezier::try_new(points.clone())?, points)
        }
        Method::CatmullRom => {
            params.finish()?;
            let curve = CatmullRom::try_new(points.clone(), knots)?;
            let controls = curve.controls().to_vec();
            Built::new(curve, points).with_controls(controls)
        }
        Method::Beta => {
            no_knots(spec)?;
            let shape = |params: &mut Params<'_>, name: &'static str, default: f64| {
                Ok::<_, SceneError>(match params.number_or_list(name)? {
                    None => ShapeParam::Constant(default),
                    Some(NumberOrList::One(x)) => ShapeParam::Constant(x),
                    Some(NumberOrList::List(v)) => ShapeParam::PerPoint(v),
                })
            };
            let positive = |params: &mut Params<'_>, name: &'static str| match params.get(name) {
                None => Ok(None),
                Some(v) => v
                    .as_f64()
                    .filter(|x| x.is_finite() && *x > 0.0)
                    .map(Some)
                    .ok_or_else(|| {
                        field_error(format!("params.{name}"), "must be a positive number")
                    }),
            };
            let beta = BetaParams {
                beta1: shape(&mut params, "beta1", 1.0)?,
                beta2: shape(&mut params, "beta2", 0.0)?,
                interpolate: params.boolean("interpolate", true)?,
                solver: BetaSolver::from_name(params.choice("solver", &["newton", "jacobi"])?)
                    .unwrap_or_default(),
                tolerance: positive(&mut params, "tolerance")?,
                residual_tolerance: positive(&mut params, "residual_tolerance")?,
                max_iterations: match params.get("max_iterations") {
                    None => None,
                    Some(v) => Some(
                        v.as_u64()
                            .filter(|n| (1..=1_000_000).contains(n))
                            .and_then(|n| usize::try_from(n).ok())
                            .ok_or_else(|| {
                                field_error(
                                    "params.max_iterations",
                                    "must be a whole number from 1 to 1000000",
                                )
                            })?,
                    ),
                },
            };
            params.finish()?;
            let curve = BetaSpline::try_new(points.clone(), &beta)?;
            let mut built =
                Built::new(curve.clone(), points).with_controls(curve.controls().to_vec());
            built.auxiliary = curve.auxiliary().to_vec();
            if let Some(info) = curve.solve_info() {
                built = built
                    .with_info("solver", json!(info.solver.name()))
                    .with_info("iterations", json!(info.iterations))
                    .with_info("residual", json!(info.residual));
            }
            built
        }
        Method::ArcBlend => {
            let order = params.order()?;
            params.finish()?;
            no_knots(spec)?;
            let curve = ArcBlend::try_new(points.clone(), order)?;
            let knots = curve.knots().to_vec();
            Built::new(curve, points).with_info("knots", json!(knots))
        }
        Method::CornerBlend => {
            let order = params.order()?;
            let fraction = params.number("fraction", DEFAULT_CORNER_FRACTION)?;
            params.finish()?;
            no_knots(spec)?;
            let curve = CornerBlend::try_new(points.clone(), order, fraction)?;
            let knots = curve.knots().to_vec();
            Built::new(curve, points).with_info("knots", json!(knots))
        }
        // Unreachable: `CurveSpec::validate` checks the method's spaces.
        m => {
            return Err(field_error(
                "method",
                format!("\"{}\" is not available on this sphere", m.id()),
            ));
        }
    })
}

/// Methods with their own S³ form, falling back to [`build_any`].
fn build_s3(
    spec: &CurveSpec,
    keys: Vec<UnitQuat>,
    mut params: Params<'_>,
) -> Result<Built<UnitQuat>, SceneError> {
    let knots = spec.knots.clone();
    Ok(match spec.method {
        Method::BezierKim => {
            params.finish()?;
            no_knots(spec)?;
            Built::new(KimBezier::try_new(keys.clone())?, keys)
        }
        Method::BsplineKim => {
            params.finish()?;
            no_knots(spec)?;
            Built::new(KimBSpline::try_new(keys.clone())?, keys)
        }
        Method::Squad => {
            params.finish()?;
            let curve = Squad::try_new(keys.clone(), knots)?;
            let controls = curve.controls().to_vec();
            Built::new(curve, keys).with_controls(controls)
        }
        Method::CatmullRom => {
            let tangent = params.choice("tangent", &["quaternion", "intrinsic"])?;
            params.finish()?;
            let curve = if tangent == "quaternion" {
                CatmullRom::try_new_quaternion(keys.clone(), knots)?
            } else {
                CatmullRom::try_new(keys.clone(), knots)?
            };
            let controls = curve.controls().to_vec();
            Built::new(curve, keys).with_controls(controls)
        }
        Method::Gamma => {
            let gamma = match params.number_or_list("gamma")? {
                None => Gammas::All(1.0),
                Some(NumberOrList::One(x)) => Gammas::All(x),
                Some(NumberOrList::List(v)) => Gammas::Each(v),
            };
            let last_edge =
                LastEdge::from_name(params.choice("last_edge", &["formula", "paper-example"])?)?;
            params.finish()?;
            let curve = GammaSpline::try_new(keys.clone(), knots, gamma, last_edge)?;
            let controls = curve.controls().to_vec();
            let report = curve.joint_report();
            Built::new(curve, keys).with_controls(controls).with_info(
                "joints",
                serde_json::to_value(report).unwrap_or(Value::Null),
            )
        }
        Method::CornerBlend => {
            // The book's orientation construction (rotations act by left multiplication).
            let order = params.order()?;
            let fraction = params.number("fraction", DEFAULT_CORNER_FRACTION)?;
            params.finish()?;
            no_knots(spec)?;
            let curve = CornerBlendS3::try_new(keys.clone(), order, fraction)?;
            let knots = curve.knots().to_vec();
            Built::new(curve, keys).with_info("knots", json!(knots))
        }
        _ => build_any(spec, keys, params)?,
    })
}

/// Rejects `knots` for methods that compute their own.
fn no_knots(spec: &CurveSpec) -> Result<(), SceneError> {
    match spec.knots {
        None => Ok(()),
        Some(_) => Err(field_error(
            "knots",
            format!(
                "method \"{}\" computes its own knots (reported in info.knots)",
                spec.method.id()
            ),
        )),
    }
}
