// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `spherekit.Curve`: any registered method on any sphere, built through the scene format.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use serde_json::{Map, Value, json};
use spherekit::{Curve, Extrapolate, Jet, S2Point, SmPoint, UnitQuat};
use spherekit_scene::{Built, BuiltCurve, Scene, ScenePoint, continuity_json};

use crate::batch;
use crate::convert::{Times, from_json, point_rows, rows, to_json, value_error};
use crate::scene::default_order;

/// What to evaluate at each parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum What {
    Point,
    Velocity,
    Acceleration,
    /// S³: the angular velocity, in the body frame when `true`.
    AngularVelocity(bool),
    /// S³: the angular acceleration, in the body frame when `true`.
    AngularAcceleration(bool),
}

impl What {
    /// `curve(t, order)`.
    pub(crate) fn from_order(order: i64) -> PyResult<Self> {
        match order {
            0 => Ok(Self::Point),
            1 => Ok(Self::Velocity),
            2 => Ok(Self::Acceleration),
            _ => Err(value_error("`order` must be 0, 1 or 2.")),
        }
    }
}

/// `"space"` or `"body"`: whether the frame is the body's.
pub(crate) fn body_frame(frame: &str) -> PyResult<bool> {
    match frame {
        "space" => Ok(false),
        "body" => Ok(true),
        _ => Err(value_error(format!(
            "frame: \"{frame}\" is not a frame: use \"space\" or \"body\""
        ))),
    }
}

/// A sphere's points and vectors written as rows of numbers.
pub(crate) trait Flat: ScenePoint {
    /// Writes the point's coordinates into `row` (exactly as many numbers).
    fn write_point(&self, scalar_first: bool, row: &mut [f64]);
    /// Writes an ambient vector's coordinates into `row`.
    fn write_vector(v: &Self::Vector, scalar_first: bool, row: &mut [f64]);
}

impl Flat for S2Point {
    fn write_point(&self, _: bool, row: &mut [f64]) {
        row.copy_from_slice(&self.as_dvec3().to_array());
    }
    fn write_vector(v: &spherekit::glam::DVec3, _: bool, row: &mut [f64]) {
        row.copy_from_slice(&v.to_array());
    }
}

impl Flat for UnitQuat {
    fn write_point(&self, scalar_first: bool, row: &mut [f64]) {
        Self::write_vector(&spherekit::Manifold::to_vector(self), scalar_first, row);
    }
    fn write_vector(v: &spherekit::glam::DVec4, scalar_first: bool, row: &mut [f64]) {
        if scalar_first {
            row.copy_from_slice(&[v.w, v.x, v.y, v.z]);
        } else {
            row.copy_from_slice(&v.to_array());
        }
    }
}

impl Flat for SmPoint {
    fn write_point(&self, _: bool, row: &mut [f64]) {
        row.copy_from_slice(self.coords());
    }
    fn write_vector(v: &spherekit::VecN, _: bool, row: &mut [f64]) {
        row.copy_from_slice(v.as_slice());
    }
}

/// Evaluates `what` at every parameter into rows (`width` numbers each), with the core's batch
/// calls ([`batch`]: large batches split over threads, the values the same bit for bit). NaN
/// parameters give rows of NaN (the library's curves are not evaluated at NaN).
pub(crate) fn evaluate<P: Flat, C: Curve<Point = P> + Sync + ?Sized>(
    curve: &C,
    ts: &[f64],
    what: What,
    width: usize,
    scalar_first: bool,
) -> Vec<f64> {
    if what == What::Point {
        return evaluate_points(curve, ts, width, scalar_first, |_, _| {});
    }
    let t0 = curve.domain()[0];
    batch::split(ts, width, |ts, out| {
        batch::by_chunks(ts, out, width, t0, curve.jet(t0), |chunk, js, rows| {
            curve.jet_many(chunk, js);
            write_jets(js, what, scalar_first, width, rows);
        });
    })
}

/// The points at every parameter as rows (`width` numbers each), as [`evaluate`]; each chunk's
/// rows are then passed to `fix(parameters, rows)` (on the thread that wrote them, while they
/// are in cache).
pub(crate) fn evaluate_points<P: Flat, C: Curve<Point = P> + Sync + ?Sized>(
    curve: &C,
    ts: &[f64],
    width: usize,
    scalar_first: bool,
    fix: impl Fn(&[f64], &mut [f64]) + Sync,
) -> Vec<f64> {
    let t0 = curve.domain()[0];
    batch::split(ts, width, |ts, out| {
        batch::by_chunks(ts, out, width, t0, curve.eval(t0), |chunk, ps, rows| {
            curve.eval_many(chunk, ps);
            for (p, row) in ps.iter().zip(rows.chunks_exact_mut(width)) {
                p.write_point(scalar_first, row);
            }
            fix(chunk, rows);
        });
    })
}

/// The rows of `what` for these jets: row `k` of `rows` (`width` numbers each) for jet `k`.
pub(crate) fn write_jets<P: Flat>(
    jets: &[Jet<P>],
    what: What,
    scalar_first: bool,
    width: usize,
    rows: &mut [f64],
) {
    for (jet, row) in jets.iter().zip(rows.chunks_exact_mut(width)) {
        match what {
            What::Point => jet.point.write_point(scalar_first, row),
            What::Velocity => P::write_vector(&jet.velocity, scalar_first, row),
            What::Acceleration => P::write_vector(&jet.acceleration, scalar_first, row),
            What::AngularVelocity(body) => {
                if let Some((w, _)) = P::angular(jet, body) {
                    row.copy_from_slice(&w);
                }
            }
            What::AngularAcceleration(body) => {
                if let Some((_, a)) = P::angular(jet, body) {
                    row.copy_from_slice(&a);
                }
            }
        }
    }
}

/// A curve of any registered method on any sphere, evaluated from numpy arrays.
///
/// `Curve(method, points, *, space=None, knots=None, closed=False, scalar_first=False,
/// canonicalize=None, parametrization=None, extrapolate=None, fit=None, **params)` builds the
/// curve a scene `{"space", "method", "points", "knots", "closed", "canonicalize",
/// "parametrization", "extrapolate", "fit", "params"}` describes (see `spherekit.methods()` for the methods and their
/// parameters), with the CLI's validation and error messages.
///
/// - `points`: an `(n, d)` array. The sphere is inferred from `d` (3: S2, 4: S3 quaternions,
///   otherwise S(d-1)) unless `space` ("S2", "S3", "S<m>") is given. Quaternions are
///   scalar-last `[x, y, z, w]` as scipy's `Rotation.as_quat()`, or `[w, x, y, z]` with
///   `scalar_first=True` (as scipy's `from_quat(..., scalar_first=True)`); the same order is
///   used for the points, velocities and accelerations returned and for `points`, `controls`
///   and `auxiliary` (a dict given to `spherekit.sample` follows the same rule).
/// - `knots`: the parameter of each point (methods that take knots), strictly increasing.
/// - `closed`: a closed loop (every method whose `methods()` entry has `closes`): the curve
///   returns to its first point, as smooth at the seam as at the other joints; `knots` then has
///   one entry per point and one more, the time of the return.
/// - `parametrization="arclength"`: the same curve at unit speed over `[0, L]` (the rotation
///   angle on S3); `extrapolate`: `"hold"` (default), `"extend"`, `"cycle"` (closed),
///   `"error"` or `"segment"` (the open cubic), what the curve is outside `domain`.
/// - `fit`: with `"cubic"`, the points are samples at the times `knots` and the curve is the
///   cubic spline fitted to them: a dict of the scene's `"fit"` (`smoothing`: λ, `"gcv"` or
///   `{"rms": σ}`; `weights`; `max_error` or `keys`), numpy arrays accepted; `fit_info` then
///   reports the fit.
/// - `**params`: the method's parameters (`gamma=0.3`, `end="scipy"`, `timing="arc-length"`,
///   `smoothness=3` for the Cⁿ blends, `velocities=rates` with `frame="body"` for the cubic
///   through keys with rates…); arrays are taken as nested lists.
///
/// `curve(t)` gives the points at the parameters `t` (a number or a 1-D array), `curve(t, 1)`
/// and `curve(t, 2)` the first and second derivatives (ambient vectors). Outside `domain` the
/// `extrapolate` policy applies (by default the end point at rest); a NaN parameter is a
/// `ValueError`. A curve pickles and deep-copies (rebuilt from its arguments: the same
/// samples, bit for bit).
///
/// ```python
/// >>> import numpy as np, spherekit
/// >>> c = spherekit.Curve("geodesic", [[1, 0, 0], [0, 1, 0]])
/// >>> c.domain
/// (0.0, 1.0)
/// >>> np.round(c(0.5), 6).tolist()
/// [0.707107, 0.707107, 0.0]
/// >>> c([0.0, 1.0], 1).shape
/// (2, 3)
///
/// ```
#[pyclass(module = "spherekit._spherekit", name = "Curve", frozen, subclass)]
pub(crate) struct PyCurve {
    built: BuiltCurve,
    /// The one-curve scene, for checking parameters under `extrapolate="error"`.
    scene: Scene,
    method: &'static str,
    space: String,
    width: usize,
    scalar_first: bool,
    /// The constructor's arguments, for pickling.
    args: Args,
}

/// `Curve`'s arguments as given (the points before normalising or reordering, the parameters
/// as JSON).
struct Args {
    method: String,
    points: Vec<Vec<f64>>,
    space: Option<String>,
    knots: Option<Vec<f64>>,
    closed: bool,
    scalar_first: bool,
    canonicalize: Option<bool>,
    parametrization: Option<String>,
    extrapolate: Option<String>,
    fit: Option<Value>,
    params: Option<Value>,
}

/// Calls `f` with the `Built` of whatever sphere the curve is on.
macro_rules! with_built {
    ($curve:expr, |$b:ident| $body:expr) => {
        match &$curve.built {
            BuiltCurve::S2($b) => $body,
            BuiltCurve::S3($b) => $body,
            BuiltCurve::Sm($b) => $body,
        }
    };
}

impl PyCurve {
    fn rows_of<'py, P: Flat>(
        &self,
        py: Python<'py>,
        ps: &[P],
    ) -> PyResult<Option<Bound<'py, PyAny>>> {
        if ps.is_empty() {
            return Ok(None);
        }
        let mut out = vec![0.0; ps.len() * self.width];
        for (p, row) in ps.iter().zip(out.chunks_exact_mut(self.width)) {
            p.write_point(self.scalar_first, row);
        }
        rows(py, out, self.width, false).map(Some)
    }

    fn run<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        what: What,
    ) -> PyResult<Bound<'py, PyAny>> {
        let times = Times::extract(t, "t")?;
        let ts = times.values_not_nan("t", "parameter")?;
        if self.scene.curves[0].extrapolate == Extrapolate::Error {
            // The scene format's check.
            let mut scene = self.scene.clone();
            if !ts.is_empty() {
                scene
                    .set_parameters(ts.to_vec())
                    .and_then(|()| scene.check_parameters(core::slice::from_ref(&self.built)))
                    .map_err(|e| value_error(e.to_string()))?;
            }
        }
        let width = match what {
            What::AngularVelocity(_) | What::AngularAcceleration(_) => 3,
            _ => self.width,
        };
        let scalar_first = self.scalar_first;
        let data = py.detach(|| {
            with_built!(self, |b| evaluate(
                &*b.curve,
                &ts,
                what,
                width,
                scalar_first
            ))
        });
        rows(py, data, width, times.scalar)
    }

    fn angular<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        frame: &str,
        acceleration: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let body = body_frame(frame)?;
        if !matches!(self.built, BuiltCurve::S3(_)) {
            return Err(value_error(format!(
                "angular rates are defined on S3 (rotations), this curve is on {}",
                self.space
            )));
        }
        let what = if acceleration {
            What::AngularAcceleration(body)
        } else {
            What::AngularVelocity(body)
        };
        self.run(py, t, what)
    }
}

#[pymethods]
impl PyCurve {
    #[new]
    #[pyo3(signature = (method, points, *, space=None, knots=None, closed=false, scalar_first=false, canonicalize=None, parametrization=None, extrapolate=None, fit=None, **params))]
    #[expect(clippy::too_many_arguments, reason = "the Python signature")]
    fn new(
        py: Python<'_>,
        method: &str,
        points: &Bound<'_, PyAny>,
        space: Option<&str>,
        knots: Option<&Bound<'_, PyAny>>,
        closed: bool,
        scalar_first: bool,
        canonicalize: Option<bool>,
        parametrization: Option<&str>,
        extrapolate: Option<&str>,
        fit: Option<&Bound<'_, PyAny>>,
        params: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let rows = point_rows(points, "points")?;
        let width = rows.first().map_or(0, Vec::len);
        let given_space = space;
        let space = match space {
            Some(s) => s.to_owned(),
            None => match width {
                3 => "S2".to_owned(),
                0 => return Err(value_error("points: must have at least one point")),
                d => format!("S{}", d - 1),
            },
        };
        let knots = knots
            .map(|k| crate::convert::numbers(k, "knots"))
            .transpose()?;
        let params = match params {
            Some(p) if !p.is_empty() => Some(to_json(p.as_any(), 0)?),
            _ => None,
        };
        let fit = fit.map(|f| to_json(f, 0)).transpose()?;
        let args = Args {
            method: method.to_owned(),
            points: rows,
            space: given_space.map(str::to_owned),
            knots,
            closed,
            scalar_first,
            canonicalize,
            parametrization: parametrization.map(str::to_owned),
            extrapolate: extrapolate.map(str::to_owned),
            fit,
            params,
        };
        let mut scene = Map::new();
        scene.insert("space".into(), json!(space));
        scene.insert("method".into(), json!(method));
        scene.insert("points".into(), json!(args.points));
        // Quaternions as given: `[x, y, z, w]`, or `[w, x, y, z]` with `scalar_first`.
        default_order(&mut scene, scalar_first);
        if let Some(k) = &args.knots {
            scene.insert("knots".into(), json!(k));
        }
        if closed {
            scene.insert("closed".into(), json!(true));
        }
        if let Some(c) = canonicalize {
            scene.insert("canonicalize".into(), json!(c));
        }
        if let Some(p) = parametrization {
            scene.insert("parametrization".into(), json!(p));
        }
        if let Some(e) = extrapolate {
            scene.insert("extrapolate".into(), json!(e));
        }
        if let Some(p) = &args.params {
            scene.insert("params".into(), p.clone());
        }
        if let Some(f) = &args.fit {
            scene.insert("fit".into(), f.clone());
        }
        let text = Value::Object(scene).to_string();
        let scene = Scene::from_json(&text).map_err(|e| value_error(e.to_string()))?;
        let mut built = py
            .detach(|| scene.build())
            .map_err(|e| value_error(e.to_string()))?;
        let built = built.remove(0);
        Ok(Self {
            built,
            method: scene.curves[0].method.id,
            space: scene.space.name(),
            scene,
            width,
            scalar_first,
            args,
        })
    }

    /// `(functools.partial(Curve, **keywords), (method, points))`: `pickle` (every protocol)
    /// and `copy.deepcopy` rebuild the curve from the constructor's arguments (the same
    /// construction, the same bits).
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let a = &slf.get().args;
        let width = a.points.first().map_or(0, Vec::len);
        let flat: Vec<f64> = a.points.iter().flatten().copied().collect();
        let points = PyArray1::from_vec(py, flat).reshape([a.points.len(), width])?;
        let kwargs = PyDict::new(py);
        kwargs.set_item("space", &a.space)?;
        kwargs.set_item("knots", &a.knots)?;
        kwargs.set_item("closed", a.closed)?;
        kwargs.set_item("scalar_first", a.scalar_first)?;
        kwargs.set_item("canonicalize", a.canonicalize)?;
        kwargs.set_item("parametrization", &a.parametrization)?;
        kwargs.set_item("extrapolate", &a.extrapolate)?;
        if let Some(fit) = &a.fit {
            kwargs.set_item("fit", from_json(py, fit)?)?;
        }
        if let Some(params) = &a.params {
            kwargs.update(from_json(py, params)?.cast::<PyDict>()?.as_mapping())?;
        }
        let rebuild = py
            .import("functools")?
            .getattr("partial")?
            .call((slf.get_type(),), Some(&kwargs))?;
        Ok((rebuild, (a.method.as_str(), points).into_pyobject(py)?))
    }

    /// The points (`order=0`), velocities (1) or accelerations (2) at the parameters `t`.
    #[pyo3(signature = (t, order=0))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        order: i64,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.run(py, t, What::from_order(order)?)
    }

    /// S3: the angular velocity `(m, 3)` at `t`, in the space frame (`ω = 2q′q̄`) or the body
    /// frame (`2q̄q′`, scipy's `RotationSpline(t, 1)`).
    #[pyo3(signature = (t, frame="space"))]
    fn angular_velocity<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        frame: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.angular(py, t, frame, false)
    }

    /// S3: the angular acceleration `(m, 3)` at `t`, in the space or the body frame.
    #[pyo3(signature = (t, frame="space"))]
    fn angular_acceleration<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        frame: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.angular(py, t, frame, true)
    }

    /// The parameter interval `(t0, t1)`.
    #[getter]
    fn domain(&self) -> (f64, f64) {
        let [a, b] = self.built.domain();
        (a, b)
    }

    /// The parameters where the curve's pieces meet, both ends included.
    #[getter]
    fn joints<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let joints = with_built!(self, |b| b.curve.joints().to_vec());
        rows(py, joints, 1, true)
    }

    /// The method id (`"squad"`).
    #[getter]
    fn method(&self) -> &'static str {
        self.method
    }

    /// The sphere: `"S2"`, `"S3"` or `"S<m>"`.
    #[getter]
    fn space(&self) -> String {
        self.space.clone()
    }

    /// The input points as the curve uses them: normalised, and on S3 canonicalised (consecutive
    /// quaternions with non-negative dot products) unless `canonicalize=False`.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        with_built!(self, |b| self.rows_of(py, &b.inputs))
    }

    /// The derived control points, `None` when the method has none.
    #[getter]
    fn controls<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        with_built!(self, |b| self.rows_of(py, &b.controls))
    }

    /// The auxiliary vertices a method solves for (Beta, Gamma), `None` when it has none.
    #[getter]
    fn auxiliary<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        with_built!(self, |b| self.rows_of(py, &b.auxiliary))
    }

    /// Method-specific facts (solver iterations, computed knots…), a dict, empty when none.
    #[getter]
    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let info = with_built!(self, |b| info_of(b));
        from_json(py, &Value::Object(info))
    }

    /// The fit of a curve built with `fit`, `None` otherwise: a dict of `lambda`, `rms` and
    /// `max` (radians; rotation angles on S3), `keys`, `key_times` (an array), `iterations`,
    /// `edf` (the effective degrees of freedom, `None` with fewer keys than samples) and
    /// `residuals` (each sample's distance to the curve, an array).
    #[getter]
    fn fit_info<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let residuals = with_built!(self, |b| b.fit.as_ref().map(|f| f.report.residuals.clone()));
        let (Some(report), Some(residuals)) = (self.built.fit_report(), residuals) else {
            return Ok(None);
        };
        let out = PyDict::new(py);
        out.set_item("lambda", report.lambda)?;
        out.set_item("rms", report.rms)?;
        out.set_item("max", report.max)?;
        out.set_item("keys", report.keys)?;
        out.set_item("key_times", PyArray1::from_slice(py, &report.key_times))?;
        out.set_item("iterations", report.iterations)?;
        out.set_item("edf", report.edf)?;
        out.set_item("residuals", PyArray1::from_vec(py, residuals))?;
        Ok(Some(out))
    }

    /// The jumps at each interior joint, as `spherekit sample --continuity` reports them:
    /// a list of `{"t", "c0", "c1", "c2", "g1", "class"}`.
    fn continuity<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (report, order) = py.detach(|| self.built.continuity());
        from_json(py, &continuity_json(&report, order))
    }

    fn __repr__(&self) -> String {
        let [a, b] = self.built.domain();
        format!(
            "spherekit.Curve({:?} on {}, domain [{a}, {b}])",
            self.method, self.space
        )
    }
}

fn info_of<P: ScenePoint>(b: &Built<P>) -> Map<String, Value> {
    b.info.clone()
}
