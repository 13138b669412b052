// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Conversions between Python objects, numpy arrays and the Rust side's numbers and JSON.

use std::borrow::Cow;

use numpy::{
    AllowTypeChange, PyArray1, PyArrayLike2, PyArrayLikeDyn, PyArrayMethods, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Value};

/// A `ValueError` with this message.
pub(crate) fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}

/// Evaluation parameters: a number or a 1-D array of numbers, borrowed from numpy when they are
/// contiguous `float64` already.
pub(crate) struct Times<'py> {
    array: PyArrayLikeDyn<'py, f64, AllowTypeChange>,
    /// Whether a single number was given (the result then has one dimension less).
    pub(crate) scalar: bool,
}

impl<'py> Times<'py> {
    /// Reads `times` (named `name` in errors).
    pub(crate) fn extract(times: &Bound<'py, PyAny>, name: &str) -> PyResult<Self> {
        let array: PyArrayLikeDyn<'py, f64, AllowTypeChange> = times.extract().map_err(|_| {
            value_error(format!("`{name}` must be a number or an array of numbers"))
        })?;
        let ndim = array.ndim();
        if ndim > 1 {
            return Err(value_error(format!(
                "`{name}` must be at most 1-dimensional."
            )));
        }
        Ok(Self {
            array,
            scalar: ndim == 0,
        })
    }

    /// The parameters as one slice.
    pub(crate) fn values(&self) -> Cow<'_, [f64]> {
        match self.array.as_slice() {
            Ok(s) => Cow::Borrowed(s),
            Err(_) => Cow::Owned(self.array.as_array().iter().copied().collect()),
        }
    }

    /// The parameters as one slice, a `ValueError` naming the first NaN (`t[3]: NaN is not a
    /// parameter`; `name` and `what` as in the message) rather than rows of NaN.
    pub(crate) fn values_not_nan(&self, name: &str, what: &str) -> PyResult<Cow<'_, [f64]>> {
        let ts = self.values();
        // A fold rather than `any`: no early exit, so the check is vectorised.
        if ts.iter().fold(false, |nan, t| nan | t.is_nan()) {
            let at = if self.scalar {
                String::new()
            } else {
                format!("[{}]", ts.iter().position(|t| t.is_nan()).unwrap_or(0))
            };
            return Err(value_error(format!("{name}{at}: NaN is not a {what}")));
        }
        Ok(ts)
    }
}

/// `data` (rows of `width` numbers) as a numpy array: `(rows, width)`, or `(width,)` for a
/// single parameter given as a number. No copy: numpy takes over the vector.
pub(crate) fn rows<'py>(
    py: Python<'py>,
    data: Vec<f64>,
    width: usize,
    scalar: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let n = data.len() / width.max(1);
    let flat = PyArray1::from_vec(py, data);
    if scalar {
        Ok(flat.into_any())
    } else {
        Ok(flat.reshape([n, width])?.into_any())
    }
}

/// An `(n, d)` array of points (any array-like of numbers), borrowed from numpy when it is a
/// `float64` array already.
pub(crate) fn point_array<'py>(
    points: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<PyArrayLike2<'py, f64, AllowTypeChange>> {
    points.extract().map_err(|_| {
        value_error(format!(
            "`{name}` must be an (n, d) array of numbers (n points of d coordinates)"
        ))
    })
}

/// An `(n, d)` array of points (any array-like of numbers), as rows.
pub(crate) fn point_rows(points: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Vec<f64>>> {
    Ok(point_array(points, name)?
        .as_array()
        .rows()
        .into_iter()
        .map(|r| r.to_vec())
        .collect())
}

/// A 1-D array-like of numbers.
pub(crate) fn numbers(values: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    let t = Times::extract(values, name)?;
    if t.scalar {
        return Err(value_error(format!("`{name}` must be 1-dimensional.")));
    }
    Ok(t.values().into_owned())
}

/// A Python object as JSON: `None`, booleans, numbers, strings, lists and tuples, dicts with
/// string keys, and anything with a `tolist()` (numpy arrays and scalars).
pub(crate) fn to_json(obj: &Bound<'_, PyAny>, depth: usize) -> PyResult<Value> {
    if depth > 64 {
        return Err(value_error("params: nested too deeply"));
    }
    if obj.is_none() {
        return Ok(Value::Null);
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if obj.is_instance_of::<PyInt>() {
        if let Ok(i) = obj.extract::<i64>() {
            return Ok(Value::from(i));
        }
        return Ok(Value::from(obj.extract::<f64>()?));
    }
    if obj.is_instance_of::<PyFloat>() {
        let x: f64 = obj.extract()?;
        // JSON has no NaN or infinity; the scene layer then names the field.
        return Ok(serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Value::String(s.to_cow()?.into_owned()));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        let mut map = Map::new();
        for (k, v) in d.iter() {
            let key: String = k
                .extract()
                .map_err(|_| value_error("params: dictionary keys must be strings"))?;
            map.insert(key, to_json(&v, depth + 1)?);
        }
        return Ok(Value::Object(map));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let items = obj
            .try_iter()?
            .map(|x| to_json(&x?, depth + 1))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(Value::Array(items));
    }
    if obj.hasattr("tolist")? {
        return to_json(&obj.call_method0("tolist")?, depth + 1);
    }
    Err(value_error(format!(
        "params: cannot pass a {} to the scene format",
        obj.get_type().name()?
    )))
}

/// JSON as Python objects (through the `json` module, so numbers and strings are exactly
/// what `json.loads` gives for the CLI's output).
pub(crate) fn from_json<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?
        .call_method1("loads", (value.to_string(),))
}

/// `repr(x)` of a Python float, for messages that quote scipy's.
pub(crate) fn float_repr(py: Python<'_>, x: f64) -> String {
    PyFloat::new(py, x)
        .repr()
        .map_or_else(|_| x.to_string(), |r| r.to_string())
}
