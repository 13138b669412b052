// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `spherekit._spherekit`, the native half of the `spherekit` Python package (`python/`).
//!
//! Thin glue: numpy arrays in, numpy arrays out, every curve built and evaluated by the Rust
//! crates. `Curve` (module `curve`) goes through the scene format and its method registry, so
//! every registered method, parameter and error message is the CLI's; the scipy drop-ins
//! (`RotationSpline`, `Slerp` in `python/spherekit/_scipy.py`) use the core's `CubicSpline`
//! and `GeodesicSpline` directly (module `rotation`). Batches are evaluated with the core's
//! batch calls (`eval_many`, `jet_many`, and `CubicSpline::point_velocity_many` for the
//! drop-in's angular rate) with the interpreter lock released, straight into the one buffer
//! numpy then takes over (module `batch`); bad input is a `ValueError` carrying the one-line
//! message of the CLI, never a panic.

mod batch;
mod convert;
mod curve;
mod rotation;
mod scene;

use pyo3::prelude::*;

/// The native module; `python/spherekit/__init__.py` re-exports what users call.
#[pymodule]
fn _spherekit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<curve::PyCurve>()?;
    m.add_class::<rotation::PyCubicRotations>()?;
    m.add_class::<rotation::PySlerpRotations>()?;
    m.add_function(wrap_pyfunction!(scene::sample, m)?)?;
    m.add_function(wrap_pyfunction!(scene::render, m)?)?;
    m.add_function(wrap_pyfunction!(scene::render_png, m)?)?;
    m.add_function(wrap_pyfunction!(scene::methods, m)?)?;
    // The package's version is the crate's (python/pyproject.toml takes it from Cargo.toml).
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
