// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Whole scenes from Python: `sample` (the CLI's `sample` output as a dict), `render` (an RGBA
//! array), `render_png`, and the method registry.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyString};
use spherekit_scene::{SampleOptions, Scene, registry_json};

use crate::convert::{from_json, to_json, value_error};
use crate::curve::body_frame;

/// The scene's JSON text: a dict (a scene as Python objects), a `str` or `bytes` of JSON, or a
/// path (`os.PathLike`) of a scene file.
fn scene_text(scene: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = scene.cast::<PyString>() {
        return Ok(s.to_cow()?.into_owned());
    }
    if let Ok(b) = scene.cast::<PyBytes>() {
        return std::str::from_utf8(b.as_bytes())
            .map(str::to_owned)
            .map_err(|e| value_error(format!("the scene is not valid UTF-8 ({e})")));
    }
    if scene.is_instance_of::<PyDict>() {
        return Ok(to_json(scene, 0)?.to_string());
    }
    if let Ok(path) = scene.extract::<std::path::PathBuf>() {
        let display = path.display();
        return std::fs::read_to_string(&path)
            .map_err(|e| value_error(format!("cannot read scene file {display}: {e}")));
    }
    Err(value_error(
        "scene: give a dict, JSON text (str or bytes) or a path to a scene file",
    ))
}

fn parse(scene: &Bound<'_, PyAny>) -> PyResult<Scene> {
    Scene::from_json(&scene_text(scene)?).map_err(|e| value_error(e.to_string()))
}

/// Samples a scene: the dict `spherekit sample` prints.
///
/// `scene` is a dict, JSON text (`str` or `bytes`) or a path (`pathlib.Path`) of a scene file.
/// `deriv`, `continuity`, `frame` and `samples` are the CLI's `--deriv`, `--continuity`,
/// `--frame` and `--samples`. A bad scene raises `ValueError` with the CLI's message.
///
/// ```python
/// >>> import spherekit
/// >>> out = spherekit.sample({"space": "S2", "method": "geodesic",
/// ...                         "points": [[1, 0, 0], [0, 1, 0]], "samples": 3})
/// >>> out["t"]
/// [0.0, 0.5, 1.0]
/// >>> spherekit.sample('{"space": "S2", "method": "geodesic", "points": [[1, 0, 0], [-1, 0, 0]]}')
/// Traceback (most recent call last):
///     ...
/// ValueError: points[0] and points[1] are antipodal: the geodesic between them is not unique
///
/// ```
#[pyfunction]
#[pyo3(signature = (scene, *, deriv=false, continuity=false, frame="space", samples=None))]
pub(crate) fn sample<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    deriv: bool,
    continuity: bool,
    frame: &str,
    samples: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = SampleOptions {
        deriv,
        continuity,
        body_frame: body_frame(frame)?,
    };
    let mut scene = parse(scene)?;
    if let Some(n) = samples {
        scene.set_samples(n).map_err(|e| {
            value_error(format!(
                "samples: {}",
                e.to_string().trim_start_matches("samples: ")
            ))
        })?;
    }
    let out = py.detach(|| {
        scene
            .build()
            .map(|curves| scene.sample_json_with(&curves, options))
    });
    from_json(py, &out.map_err(|e| value_error(e.to_string()))?)
}

fn render_pixels(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    size: i64,
) -> PyResult<tiny_skia::Pixmap> {
    let scene = parse(scene)?;
    let size = u32::try_from(size).map_err(|_| {
        value_error(format!(
            "size: must be a positive number of pixels, got {size}"
        ))
    })?;
    py.detach(|| spherekit_render::render(&scene, size))
        .map_err(|e| value_error(e.to_string()))
}

/// Draws a scene as `spherekit render` does: an `(H, W, 4)` `uint8` RGBA array, `size` pixels
/// wide (the speed plot, when the view has one, adds a strip below the sphere).
///
/// ```python
/// >>> import spherekit
/// >>> img = spherekit.render({"space": "S2", "method": "geodesic",
/// ...                         "points": [[1, 0, 0], [0, 1, 0]]}, size=64)
/// >>> img.dtype, img.shape[1:]
/// (dtype('uint8'), (64, 4))
///
/// ```
#[pyfunction]
#[pyo3(signature = (scene, size=512))]
pub(crate) fn render<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    size: i64,
) -> PyResult<Bound<'py, PyAny>> {
    let pixmap = render_pixels(py, scene, size)?;
    let (w, h) = (pixmap.width() as usize, pixmap.height() as usize);
    let rgba = pixmap.take_demultiplied();
    Ok(PyArray1::from_vec(py, rgba).reshape([h, w, 4])?.into_any())
}

/// Draws a scene into a PNG file at `path` (the bytes of `spherekit render`).
///
/// ```python
/// >>> import os, tempfile, spherekit
/// >>> path = os.path.join(tempfile.mkdtemp(), "arc.png")
/// >>> spherekit.render_png({"space": "S2", "method": "geodesic",
/// ...                       "points": [[1, 0, 0], [0, 1, 0]]}, path, size=64)
/// >>> open(path, "rb").read(4) == b"\x89PNG"
/// True
///
/// ```
#[pyfunction]
#[pyo3(signature = (scene, path, size=512))]
pub(crate) fn render_png(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    path: std::path::PathBuf,
    size: i64,
) -> PyResult<()> {
    let pixmap = render_pixels(py, scene, size)?;
    let png = spherekit_render::png::encode_png(&pixmap)
        .map_err(|e| value_error(format!("cannot encode the PNG: {e}")))?;
    std::fs::write(&path, png).map_err(|e| {
        pyo3::exceptions::PyOSError::new_err(format!("cannot write {}: {e}", path.display()))
    })
}

/// The method registry, as `spherekit methods --json` prints it: a list of dicts with `id`,
/// `type`, `summary`, `continuity`, `spaces`, `knots`, `min_points`, `params`, …
///
/// ```python
/// >>> import spherekit
/// >>> "cubic" in [m["id"] for m in spherekit.methods()]
/// True
///
/// ```
#[pyfunction]
pub(crate) fn methods(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    from_json(py, &registry_json())
}
