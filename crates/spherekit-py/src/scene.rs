// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Whole scenes from Python: `sample` (the CLI's `sample` output as a dict), `render` (an RGBA
//! array), `render_png`, and the method registry.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyString};
use serde_json::{Map, Value};
use spherekit_scene::{SampleOptions, Scene, Space, registry_json};

use crate::convert::{from_json, to_json, value_error};
use crate::curve::body_frame;

/// Python's quaternion order, one rule for every entry point: an S3 scene object that does not
/// say `quaternion_order` gets `"xyzw"` (scalar last, scipy's order), or `"wxyz"` with
/// `scalar_first`. A scene's own `quaternion_order` wins; other spheres have no order.
pub(crate) fn default_order(scene: &mut Map<String, Value>, scalar_first: bool) {
    if scene.contains_key("quaternion_order") || !is_s3(scene) {
        return;
    }
    let order = if scalar_first { "wxyz" } else { "xyzw" };
    scene.insert("quaternion_order".into(), Value::from(order));
}

/// Whether the scene object's `space` names S3 (a bad `space` is left to the scene parser).
fn is_s3(scene: &Map<String, Value>) -> bool {
    scene
        .get("space")
        .and_then(Value::as_str)
        .is_some_and(|s| matches!(Space::parse(s), Ok(Space::S3)))
}

/// The JSON text of a scene given as text or a file, in the quaternion order the caller means
/// (a dict is read by [`parse`] as a value, in Python's order: scalar last unless it says
/// `quaternion_order` or `scalar_first` is `True`, [`default_order`]).
///
/// - A `str` or `bytes` of JSON, or a path (`os.PathLike`) of a scene file, is the scene format
///   as the CLI reads it: scalar first unless it says `quaternion_order`. `scalar_first=False`
///   reads such a text scalar last when it does not say.
fn scene_text(scene: &Bound<'_, PyAny>, scalar_first: Option<bool>) -> PyResult<String> {
    let text = if let Ok(s) = scene.cast::<PyString>() {
        s.to_cow()?.into_owned()
    } else if let Ok(b) = scene.cast::<PyBytes>() {
        std::str::from_utf8(b.as_bytes())
            .map(str::to_owned)
            .map_err(|e| value_error(format!("the scene is not valid UTF-8 ({e})")))?
    } else if let Ok(path) = scene.extract::<std::path::PathBuf>() {
        let display = path.display();
        std::fs::read_to_string(&path)
            .map_err(|e| value_error(format!("cannot read scene file {display}: {e}")))?
    } else {
        return Err(value_error(
            "scene: give a dict, JSON text (str or bytes) or a path to a scene file",
        ));
    };
    Ok(match scalar_first {
        Some(false) => scalar_last_unless_said(text),
        // The text's own order (scalar first is the format's default).
        None | Some(true) => text,
    })
}

/// A scene text read scalar last unless it says `quaternion_order`: the member
/// `"quaternion_order": "xyzw"` put first into an S3 scene object that has none. The rest of
/// the text is kept byte for byte (a duplicate field is still the parser's error); a text that
/// is not a JSON object is left to the parser to report.
fn scalar_last_unless_said(text: String) -> String {
    let Ok(Value::Object(map)) = serde_json::from_str::<Value>(&text) else {
        return text;
    };
    if map.contains_key("quaternion_order") || !is_s3(&map) {
        return text;
    }
    // The text parsed as an object, so its first non-blank character is its `{`.
    let brace = text.find('{').unwrap_or(0);
    let (head, tail) = text.split_at(brace + 1);
    format!("{head}\"quaternion_order\": \"xyzw\", {tail}")
}

/// Reads a scene: a dict as a JSON value (no text in between), text and files as the CLI does.
fn parse(scene: &Bound<'_, PyAny>, scalar_first: Option<bool>) -> PyResult<Scene> {
    let scene = if scene.is_instance_of::<PyDict>() {
        let mut value = to_json(scene, 0)?;
        if let Value::Object(map) = &mut value {
            default_order(map, scalar_first.unwrap_or(false));
        }
        Scene::from_value(&value)
    } else {
        Scene::from_json(&scene_text(scene, scalar_first)?)
    };
    scene.map_err(|e| value_error(e.to_string()))
}

/// Samples a scene: the dict `spherekit sample` prints.
///
/// `scene` is a dict, JSON text (`str` or `bytes`) or a path (`pathlib.Path`) of a scene file.
/// `deriv`, `continuity`, `frame` and `samples` are the CLI's `--deriv`, `--continuity`,
/// `--frame` and `--samples`. A bad scene raises `ValueError` with the CLI's message.
///
/// Quaternions (S3 scenes), in the points and in the output: a **dict** is Python's
/// convention, scalar last `[x, y, z, w]` as scipy's `Rotation.as_quat()`, or `[w, x, y, z]`
/// with `scalar_first=True`; a **string, bytes or path** is the scene format as the CLI reads
/// it, `[w, x, y, z]`, or `[x, y, z, w]` with `scalar_first=False`. A scene's own
/// `"quaternion_order"` (`"xyzw"` or `"wxyz"`) wins over both.
///
/// ```python
/// >>> import spherekit
/// >>> out = spherekit.sample({"space": "S2", "method": "geodesic",
/// ...                         "points": [[1, 0, 0], [0, 1, 0]], "samples": 3})
/// >>> out["t"]
/// [0.0, 0.5, 1.0]
/// >>> half_turn = {"space": "S3", "method": "geodesic", "samples": 2,
/// ...              "points": [[0, 0, 0, 1], [0, 0, 1, 0]]}  # [x, y, z, w]: identity, 180° about z
/// >>> spherekit.sample(half_turn, deriv=True)["angular_velocity"][0]
/// [0.0, 0.0, 3.141592653589793]
/// >>> spherekit.sample('{"space": "S2", "method": "geodesic", "points": [[1, 0, 0], [-1, 0, 0]]}')
/// Traceback (most recent call last):
///     ...
/// ValueError: points[0] and points[1] are antipodal: the geodesic between them is not unique
///
/// ```
#[pyfunction]
#[pyo3(signature = (scene, *, deriv=false, continuity=false, frame="space", samples=None, scalar_first=None))]
pub(crate) fn sample<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    deriv: bool,
    continuity: bool,
    frame: &str,
    samples: Option<usize>,
    scalar_first: Option<bool>,
) -> PyResult<Bound<'py, PyAny>> {
    let options = SampleOptions {
        deriv,
        continuity,
        body_frame: body_frame(frame)?,
    };
    let mut scene = parse(scene, scalar_first)?;
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
    scalar_first: Option<bool>,
) -> PyResult<tiny_skia::Pixmap> {
    let scene = parse(scene, scalar_first)?;
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
/// `scene` and `scalar_first` as in `sample`: a dict's quaternions are `[x, y, z, w]` (or
/// `[w, x, y, z]` with `scalar_first=True`), a text's or file's `[w, x, y, z]` (or
/// `[x, y, z, w]` with `scalar_first=False`), unless the scene says `"quaternion_order"`.
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
#[pyo3(signature = (scene, size=512, *, scalar_first=None))]
pub(crate) fn render<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    size: i64,
    scalar_first: Option<bool>,
) -> PyResult<Bound<'py, PyAny>> {
    let pixmap = render_pixels(py, scene, size, scalar_first)?;
    let (w, h) = (pixmap.width() as usize, pixmap.height() as usize);
    let rgba = pixmap.take_demultiplied();
    Ok(PyArray1::from_vec(py, rgba).reshape([h, w, 4])?.into_any())
}

/// Draws a scene into a PNG file at `path` (the bytes of `spherekit render`).
///
/// `scene` and `scalar_first` as in `sample`: a dict's quaternions are `[x, y, z, w]` (or
/// `[w, x, y, z]` with `scalar_first=True`), a text's or file's `[w, x, y, z]` (or
/// `[x, y, z, w]` with `scalar_first=False`), unless the scene says `"quaternion_order"`.
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
#[pyo3(signature = (scene, path, size=512, *, scalar_first=None))]
pub(crate) fn render_png(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    path: std::path::PathBuf,
    size: i64,
    scalar_first: Option<bool>,
) -> PyResult<()> {
    let pixmap = render_pixels(py, scene, size, scalar_first)?;
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
