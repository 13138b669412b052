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
//! times (its `PPoly` extrapolates): the core's [`Extrapolate::Segment`] on an open
//! [`CubicSpline`] (a closed one repeats, [`Extrapolate::Cycle`]).

use std::borrow::Cow;

use numpy::PyUntypedArrayMethods;
use pyo3::prelude::*;
use spherekit::glam::{DQuat, DVec4};
use spherekit::{
    CubicEnd, CubicSpline, Curve, Extrapolate, Extrapolated, GeodesicSpline, Manifold, UnitQuat,
    angular_velocity_acceleration_body, unflip,
};

use crate::batch;
use crate::convert::{Times, float_repr, numbers, point_array, rows, value_error};
use crate::curve::{What, evaluate, write_jets};

/// The keys as unit quaternions from scalar-last rows, canonicalised (shortest rotations).
///
/// The numbers are read as one slice (numpy's own buffer when it is contiguous): the loop over
/// `ndarray` rows calling `UnitQuat::try_new` took 54 µs for 1 000 keys where this one takes
/// 15 µs (measured in the Python process, 2026-12-02).
fn keys(quats: &Bound<'_, PyAny>) -> PyResult<Vec<UnitQuat>> {
    let array = point_array(quats, "rotations")?;
    let rows = array.as_array();
    if rows.nrows() > 0 && rows.ncols() != 4 {
        return Err(value_error(format!(
            "rotations: expected quaternions of 4 numbers [x, y, z, w], got {} numbers",
            rows.ncols()
        )));
    }
    // Row-major order: numpy's buffer as it is only when C-contiguous (`as_slice` also takes
    // a Fortran-ordered buffer, column by column).
    let numbers: Cow<'_, [f64]> = match array.as_slice() {
        Ok(s) if array.is_c_contiguous() => Cow::Borrowed(s),
        _ => Cow::Owned(rows.iter().copied().collect()),
    };
    let mut keys = Vec::with_capacity(rows.nrows());
    for (i, q) in numbers.chunks_exact(4).enumerate() {
        let q = UnitQuat::try_new(DQuat::from_xyzw(q[0], q[1], q[2], q[3]))
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

/// The cubic spline of scipy's `RotationSpline` (and its natural, clamped and closed kin).
#[pyclass(module = "spherekit._spherekit", name = "_CubicRotations", frozen)]
pub(crate) struct PyCubicRotations {
    /// The spline, continuing its end segments outside the key times (closed: periodic).
    curve: Extrapolated<CubicSpline<UnitQuat>>,
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

impl PyCubicRotations {
    /// The body-frame angular rates `2·q̄·q′` at `ts`, from the point and velocity alone
    /// ([`CubicSpline::point_velocity_many`]: the jet's bits without its acceleration). A
    /// chunk with a parameter outside the key times goes through the extrapolation's jets.
    fn body_rates(&self, ts: &[f64]) -> Vec<f64> {
        let spline = self.curve.curve();
        let [t0, t1] = spline.domain();
        batch::split(ts, 3, |ts, out| {
            let slot = spline.point_velocity(t0);
            batch::by_chunks(ts, out, 3, t0, slot, |chunk, pvs, rows| {
                // A fold rather than `all`: no early exit, so the check is vectorised.
                if chunk
                    .iter()
                    .fold(true, |inside, &t| inside & (t0 <= t) & (t <= t1))
                {
                    spline.point_velocity_many(chunk, pvs);
                } else {
                    for (&t, pv) in chunk.iter().zip(pvs.iter_mut()) {
                        let jet = self.curve.jet(t);
                        *pv = (jet.point, jet.velocity);
                    }
                }
                for (&(q, dq), row) in pvs.iter().zip(rows.chunks_exact_mut(3)) {
                    let (w, _) = angular_velocity_acceleration_body(q, dq, DVec4::ZERO);
                    row.copy_from_slice(&w.to_array());
                }
            });
        })
    }

    /// The body-frame angular accelerations `2·q̄·q″` at `ts`.
    fn body_accelerations(&self, ts: &[f64]) -> Vec<f64> {
        let t0 = self.curve.domain()[0];
        batch::split(ts, 3, |ts, out| {
            let slot = self.curve.jet(t0);
            batch::by_chunks(ts, out, 3, t0, slot, |chunk, jets, rows| {
                self.curve.jet_many(chunk, jets);
                for (jet, row) in jets.iter().zip(rows.chunks_exact_mut(3)) {
                    let (_, a) = angular_velocity_acceleration_body(
                        jet.point,
                        jet.velocity,
                        jet.acceleration,
                    );
                    row.copy_from_slice(&a.to_array());
                }
            });
        })
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
        let policy = if closed {
            Extrapolate::Cycle
        } else {
            Extrapolate::Segment
        };
        Ok(Self {
            curve: Extrapolated::new(spline, policy),
        })
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
        let (data, width) = py.detach(|| match what {
            What::AngularVelocity(_) => (self.body_rates(&ts), 3),
            What::AngularAcceleration(_) => (self.body_accelerations(&ts), 3),
            _ => (evaluate(&self.curve, &ts, What::Point, 4, false), 4),
        });
        rows(py, data, width, times.scalar)
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
        let width = if what == What::Point { 4 } else { 3 };
        let mut out = vec![f64::NAN; width];
        if let Some(jet) = self.curve.curve().continued_jet(t) {
            write_jets(&[jet], what, false, width, &mut out);
        }
        rows(py, out, width, true)
    }

    /// Newton iterations of the construction and the final relative residual.
    #[getter]
    fn solve_info(&self) -> (usize, f64) {
        let info = self.curve.curve().solve_info();
        (info.iterations, info.residual)
    }

    /// The keys as the spline uses them (normalised, canonicalised), `[x, y, z, w]`.
    #[getter]
    fn keys<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let data: Vec<f64> = self
            .curve
            .curve()
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
