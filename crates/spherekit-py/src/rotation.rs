// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The native side of the scipy drop-ins: the cubic (`RotationSpline`) and the geodesic
//! (`Slerp`) spline through unit quaternions at given times, built with the core directly.
//!
//! Quaternions cross this boundary scalar-last (`[x, y, z, w]`, scipy's and glam's order);
//! angular rates are in the body frame (scipy's `RotationSpline`). The scipy-facing argument
//! checks and messages live in `python/spherekit/_scipy.py`.
//!
//! # Extrapolation
//!
//! scipy's `RotationSpline` evaluates its end segments' cubic polynomials outside the key
//! times (its `PPoly` extrapolates). The core's curves clamp instead (their domain policy), so
//! [`EndSegment`] evaluates the same cubic as [`CubicSpline`]'s first or last segment at a
//! local parameter outside `[0, 1]`: `c(s) = Exp_p(v(s))`, `v(s) = a·s + b·s² + c·s³`, from the
//! keys, times and key velocities the spline exposes (the formulas of the `cubic` module's
//! documentation: `a = V₀h`, `b = 3r − 2V₀h − U₁h`, `c = −2r + V₀h + U₁h`, `U₁ = (dExp_r)⁻¹V₁`).

use pyo3::prelude::*;
use spherekit::glam::{DQuat, DVec4};
use spherekit::{CubicEnd, CubicSpline, Curve, GeodesicSpline, Jet, Manifold, UnitQuat, unflip};

use crate::convert::{Times, float_repr, numbers, point_rows, rows, value_error};
use crate::curve::{What, evaluate, put_jets};

/// The keys as unit quaternions from scalar-last rows, canonicalised (shortest rotations).
fn keys(quats: &Bound<'_, PyAny>) -> PyResult<Vec<UnitQuat>> {
    let rows = point_rows(quats, "rotations")?;
    let mut keys = Vec::with_capacity(rows.len());
    for (i, r) in rows.iter().enumerate() {
        let &[x, y, z, w] = r.as_slice() else {
            return Err(value_error(format!(
                "rotations: expected quaternions of 4 numbers [x, y, z, w], got {} numbers",
                r.len()
            )));
        };
        let q = UnitQuat::try_new(DQuat::from_xyzw(x, y, z, w))
            .map_err(|e| value_error(format!("rotations[{i}]: {e}")))?;
        keys.push(q);
    }
    unflip(&mut keys);
    Ok(keys)
}

/// A body-frame angular rate `[x, y, z]`.
fn rate(v: Option<Vec<f64>>, name: &str) -> PyResult<Option<spherekit::glam::DVec3>> {
    match v.as_deref() {
        None => Ok(None),
        Some(&[x, y, z]) => Ok(Some(spherekit::glam::DVec3::new(x, y, z))),
        Some(v) => Err(value_error(format!(
            "`{name}` must be an angular rate [x, y, z], got {} numbers",
            v.len()
        ))),
    }
}

/// The first or last segment of a [`CubicSpline`], evaluable at any local parameter.
#[derive(Clone, Debug)]
struct EndSegment {
    p: DVec4,
    a: DVec4,
    b: DVec4,
    c: DVec4,
    t_start: f64,
    inv_h: f64,
}

/// `(θ cos θ − sin θ)/θ²`, the derivative of `sin θ/θ`, with its series near 0.
fn sinc_deriv(x: f64) -> f64 {
    if x < 1e-2 {
        let x2 = x * x;
        x * (-1.0 / 3.0 + x2 * (1.0 / 30.0 - x2 / 840.0))
    } else {
        let (s, c) = x.sin_cos();
        (x * c - s) / (x * x)
    }
}

/// `sin θ/θ`, with its series near 0.
fn sinc(x: f64) -> f64 {
    if x < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

impl EndSegment {
    /// Segment `i` of `spline` (open).
    fn new(spline: &CubicSpline<UnitQuat>, i: usize) -> Self {
        let keys = spline.points();
        let knots = spline.knots();
        let v = spline.key_velocities();
        let (p0, p1) = (keys[i], keys[i + 1]);
        let h = knots[i + 1] - knots[i];
        let p = p0.to_vector();
        let r = Manifold::log(&p0, &p1);
        let theta = r.length();
        // U₁ = (dExp_r)⁻¹ V₁: the component along e′ (the transported direction) maps back to
        // e, the orthogonal part is divided by sinc θ.
        let u = if theta > 1e-150 {
            let e = r / theta;
            let (sn, cs) = theta.sin_cos();
            let e_end = e * cs - p * sn;
            let par = v[i + 1].dot(e_end);
            e * par + (v[i + 1] - e_end * par) / sinc(theta)
        } else {
            v[i + 1]
        };
        let vh = v[i] * h;
        let uh = u * h;
        Self {
            p,
            a: vh,
            b: r * 3.0 - vh * 2.0 - uh,
            c: r * -2.0 + vh + uh,
            t_start: knots[i],
            inv_h: 1.0 / h,
        }
    }

    /// The jet at time `t` of this segment's cubic (the same formulas as the core's).
    fn jet(&self, t: f64) -> Jet<UnitQuat> {
        let s = (t - self.t_start) * self.inv_h;
        let (a, b, c, p) = (self.a, self.b, self.c, self.p);
        let v = ((c * s + b) * s + a) * s;
        let w = ((c * (3.0 * s) + b * 2.0) * s + a) * self.inv_h;
        let acc = (c * (6.0 * s) + b * 2.0) * (self.inv_h * self.inv_h);
        let rho = v.length();
        let (sn, cs) = rho.sin_cos();
        let sc = sinc(rho);
        let dsinc = sinc_deriv(rho);
        let e = if rho > 1e-150 { v / rho } else { DVec4::ZERO };
        let q = p * cs + v * sc;
        let e_end = e * cs - p * sn;
        let w_par = w.dot(e);
        let w_perp = w - e * w_par;
        let a_par = acc.dot(e);
        let a_perp = acc - e * a_par;
        let velocity = e_end * w_par + w_perp * sc;
        let perp2 = w_perp.dot(w_perp);
        let acceleration = e_end * a_par
            + a_perp * sc
            + q * (-w_par * w_par)
            + p * (-perp2 * sc)
            + e * (perp2 * dsinc)
            + w_perp * (2.0 * dsinc * w_par);
        let q = q.normalize();
        Jet {
            point: UnitQuat::new_unchecked(DQuat::from_xyzw(q.x, q.y, q.z, q.w)),
            velocity,
            acceleration,
        }
    }
}

/// The cubic spline of scipy's `RotationSpline` (and its natural, clamped and closed kin).
#[pyclass(module = "spherekit._spherekit", name = "_CubicRotations", frozen)]
pub(crate) struct PyCubicRotations {
    spline: CubicSpline<UnitQuat>,
    /// Open curves: the first and last segments, for extrapolation.
    ends: Option<(EndSegment, EndSegment)>,
}

impl PyCubicRotations {
    /// The row for `what` at `t`, where `t` is outside the domain of an open curve.
    fn extrapolate(&self, t: f64, what: What, out: &mut Vec<f64>) {
        let Some((first, last)) = &self.ends else {
            return;
        };
        let segment = if t < self.spline.knots()[1] {
            first
        } else {
            last
        };
        put_jets(&[segment.jet(t)], what, false, out);
    }

    fn values(&self, ts: &[f64], what: What) -> Vec<f64> {
        let width = if what == What::Point { 4 } else { 3 };
        let [t0, t1] = self.spline.domain();
        let outside = |t: f64| t < t0 || t > t1;
        if self.ends.is_none() && ts.iter().any(|&t| outside(t)) {
            // Closed: periodic.
            let period = t1 - t0;
            let wrapped: Vec<f64> = ts
                .iter()
                .map(|&t| {
                    if outside(t) {
                        t0 + (t - t0).rem_euclid(period)
                    } else {
                        t
                    }
                })
                .collect();
            return evaluate(&self.spline, &wrapped, what, width, false);
        }
        let mut out = evaluate(&self.spline, ts, what, width, false);
        let mut row = Vec::with_capacity(width);
        for (k, &t) in ts.iter().enumerate() {
            if outside(t) {
                row.clear();
                self.extrapolate(t, what, &mut row);
                out[k * width..(k + 1) * width].copy_from_slice(&row);
            }
        }
        out
    }
}

/// `order` of scipy's `RotationSpline.__call__`: quaternions, body rates, body accelerations.
fn what(order: i64) -> PyResult<What> {
    match order {
        0 => Ok(What::Point),
        1 => Ok(What::AngularVelocity(true)),
        2 => Ok(What::AngularAcceleration(true)),
        _ => Err(value_error("`order` must be 0, 1 or 2.")),
    }
}

#[pymethods]
impl PyCubicRotations {
    #[new]
    #[pyo3(signature = (times, quats, end="scipy", closed=false, start_rate=None, end_rate=None))]
    fn new(
        py: Python<'_>,
        times: &Bound<'_, PyAny>,
        quats: &Bound<'_, PyAny>,
        end: &str,
        closed: bool,
        start_rate: Option<&Bound<'_, PyAny>>,
        end_rate: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let times = numbers(times, "times")?;
        let keys = keys(quats)?;
        let start_rate = rate(
            start_rate.map(|r| numbers(r, "start_rate")).transpose()?,
            "start_rate",
        )?;
        let end_rate = rate(
            end_rate.map(|r| numbers(r, "end_rate")).transpose()?,
            "end_rate",
        )?;
        let end = match (end, start_rate, end_rate) {
            ("scipy", None, None) => CubicEnd::Scipy,
            ("natural", None, None) => CubicEnd::Natural,
            ("clamped", Some(a), Some(b)) => {
                let (first, last) = (keys[0], keys[keys.len() - 1]);
                CubicEnd::clamped_angular_body(first, a, last, b)
            }
            ("clamped", _, _) => {
                return Err(value_error(
                    "end=\"clamped\" needs start_rate and end_rate (body-frame angular rates [x, y, z])",
                ));
            }
            ("scipy" | "natural", _, _) => {
                return Err(value_error(
                    "start_rate and end_rate apply with end=\"clamped\" only",
                ));
            }
            (other, _, _) => {
                return Err(value_error(format!(
                    "end: \"{other}\" is not an end condition: use \"scipy\", \"natural\" or \"clamped\""
                )));
            }
        };
        if keys.is_empty() {
            return Err(value_error(
                "`rotations` must contain at least 2 rotations.",
            ));
        }
        let spline = py
            .detach(|| CubicSpline::try_new(keys, Some(times), end, closed))
            .map_err(|e| value_error(e.to_string()))?;
        let ends = (!closed).then(|| {
            let n = spline.points().len();
            (EndSegment::new(&spline, 0), EndSegment::new(&spline, n - 2))
        });
        Ok(Self { spline, ends })
    }

    /// Quaternions `[x, y, z, w]` (`order=0`), body angular rates (1) or accelerations (2).
    #[pyo3(signature = (t, order=0))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        order: i64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let what = what(order)?;
        let times = Times::extract(t, "times")?;
        let ts = times.values();
        let data = py.detach(|| self.values(&ts, what));
        rows(
            py,
            data,
            if what == What::Point { 4 } else { 3 },
            times.scalar,
        )
    }

    /// The end segments' cubic at `t` whether inside the domain or not (`order` as in
    /// `__call__`), for testing the extrapolation against the spline itself.
    #[pyo3(signature = (t, order=0))]
    fn _extrapolated<'py>(
        &self,
        py: Python<'py>,
        t: f64,
        order: i64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let what = what(order)?;
        let mut out = Vec::new();
        self.extrapolate(t, what, &mut out);
        rows(py, out, if what == What::Point { 4 } else { 3 }, true)
    }

    /// Newton iterations of the construction and the final relative residual.
    #[getter]
    fn solve_info(&self) -> (usize, f64) {
        let info = self.spline.solve_info();
        (info.iterations, info.residual)
    }

    /// The keys as the spline uses them (normalised, canonicalised), `[x, y, z, w]`.
    #[getter]
    fn keys<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let data: Vec<f64> = self
            .spline
            .points()
            .iter()
            .flat_map(|q| q.to_vector().to_array())
            .collect();
        rows(py, data, 4, false)
    }
}

/// The geodesic spline of scipy's `Slerp`.
#[pyclass(module = "spherekit._spherekit", name = "_SlerpRotations", frozen)]
pub(crate) struct PySlerpRotations {
    spline: GeodesicSpline<UnitQuat>,
}

#[pymethods]
impl PySlerpRotations {
    #[new]
    fn new(py: Python<'_>, times: &Bound<'_, PyAny>, quats: &Bound<'_, PyAny>) -> PyResult<Self> {
        let times = numbers(times, "times")?;
        let keys = keys(quats)?;
        let spline = py
            .detach(|| GeodesicSpline::try_new(keys, Some(times)))
            .map_err(|e| value_error(e.to_string()))?;
        Ok(Self { spline })
    }

    /// Quaternions `[x, y, z, w]` at `t`; a `ValueError` (scipy's message) outside the times.
    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let times = Times::extract(t, "times")?;
        let ts = times.values();
        let [t0, t1] = self.spline.domain();
        if !ts.iter().all(|t| (t0..=t1).contains(t)) {
            return Err(value_error(format!(
                "Interpolation times must be within the range [{}, {}], both inclusive.",
                float_repr(py, t0),
                float_repr(py, t1)
            )));
        }
        let data = py.detach(|| evaluate(&self.spline, &ts, What::Point, 4, false));
        rows(py, data, 4, times.scalar)
    }
}
