// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! WebAssembly bindings for the browser playground (`web/index.html`) and the docs widget
//! (`js/widget.js`; both ship in the npm package `spherekit`, docs/web.md): bindings only, over [`spherekit_scene`] (scenes, the method registry,
//! document editing), [`spherekit_render`] (pixels, the camera, picking) and the core's
//! continuity classes.
//!
//! - Free functions evaluate a scene given as JSON text: [`methods`] (the registry, parameter
//!   schemas included), [`validate`], [`sample`] (the `spherekit sample` output), [`sample_at`]
//!   (the same at given parameters),
//!   [`sample_array`] (one field as a `Float64Array`), [`continuity`] and [`render_rgba`].
//! - [`Playground`] is the page's stateful handle on a [`Document`]: it rebuilds only the
//!   curves an edit touched (a camera change only re-renders), and draws into a canvas.
//!
//! Every bad input gives a `JsError` whose message is the line the CLI prints after
//! `error: `; a panic hook reports anything unexpected to the console ([`start`]).
//!
//! Coordinates follow the scene format: S² points `[x, y, z]`, S³ keys `[w, x, y, z]`. Screen
//! positions are pixels of an image `size` pixels wide, as [`spherekit_render::render`] draws it.

use core::fmt;

use serde_json::{Value, json};
use spherekit::glam::DVec3;
use spherekit::{
    Ambient, Jet, PointError, SolveError, UnitQuat, angular_velocity_acceleration,
    angular_velocity_acceleration_body,
};
use spherekit_render::{
    AXIS_COLORS, Camera, PALETTE, PlotAxes, Prepared, RenderCache, camera_of, prepare_with_text,
    render_built, turn_towards,
};
use spherekit_scene::{
    BuiltCurve, Document, EditError, Plot, PlotTime, SAMPLE_FIELDS, SampleOptions, Scene,
    SceneError, Space, continuity_json, registry_json,
};
use tiny_skia::Pixmap;
use wasm_bindgen::prelude::*;

/// A bad argument from the page that the scene format does not see.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum InputError {
    /// Coordinates are not finite or have the wrong count.
    Coords(String),
    /// The sample output has no such field.
    Field(String),
    /// There is no curve with this index.
    NoCurve(usize),
    /// The canvas has no 2D context or refused the image.
    NoContext,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Coords(m) => write!(f, "coordinates: {m}"),
            Self::Field(name) => write!(
                f,
                "field \"{name}\" is not a sample field ({})",
                SAMPLE_FIELDS.join(", ")
            ),
            Self::NoCurve(i) => write!(f, "curves[{i}]: there is no such curve"),
            Self::NoContext => write!(f, "canvas: no 2D context"),
        }
    }
}

impl core::error::Error for InputError {}

/// Installs the panic hook that reports a panic to the browser console (called on load): the
/// message and its location go to `console.error`, then the module aborts (`panic = "abort"`;
/// the browser reports wasm's `unreachable`).
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

fn js(e: impl fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// A unit quaternion from `[w, x, y, z]`.
fn quat(c: &[f64]) -> Result<UnitQuat, InputError> {
    match c {
        &[w, x, y, z] => UnitQuat::from_wxyz([w, x, y, z])
            .map_err(|e| InputError::Coords(format!("quaternion {}", e.predicate()))),
        _ => Err(InputError::Coords(format!(
            "a quaternion has 4 numbers [w, x, y, z], got {}",
            c.len()
        ))),
    }
}

fn json_arg(text: &str) -> Result<Value, EditError> {
    serde_json::from_str(text).map_err(|e| EditError::Json(e.to_string()))
}

/// The method registry as JSON, as `spherekit methods --json` prints it: `[{ "id", "type",
/// "summary", "continuity", "source", "spaces", "knots", "min_points", "interpolates",
/// "params": [{ "name", "label", "summary", "type", "default", "min", "max", "choices",
/// "per_joint", "spaces", "advanced" }, …] }, …]`. The page builds its controls from it.
#[wasm_bindgen]
#[must_use]
pub fn methods() -> String {
    registry_json().to_string()
}

/// The body axes of an orientation `[w, x, y, z]` after rotation: `[x₁, y₁, z₁, x₂, …, z₃]`.
///
/// # Errors
///
/// An [`InputError`] for a quaternion that is not 4 finite numbers of non-zero length.
#[wasm_bindgen]
pub fn key_axes(key: &[f64]) -> Result<Vec<f64>, JsError> {
    let q = quat(key)?;
    Ok([DVec3::X, DVec3::Y, DVec3::Z]
        .iter()
        .flat_map(|a| q.rotate(*a).to_array())
        .collect())
}

/// An orientation `[w, x, y, z]` as `[angle in degrees, axis x, y, z]`: the rotation's unit axis
/// and angle in [0°, 180°] (a key and its negative give the same).
///
/// # Errors
///
/// As [`key_axes`].
#[wasm_bindgen]
pub fn key_to_axis_angle(key: &[f64]) -> Result<Vec<f64>, JsError> {
    let (axis, angle) = quat(key)?.to_axis_angle();
    Ok(vec![angle.to_degrees(), axis.x, axis.y, axis.z])
}

/// The orientation `[w, x, y, z]` turning by `degrees` about `axis`.
///
/// # Errors
///
/// An [`InputError`] for a zero or non-finite axis or angle.
#[wasm_bindgen]
pub fn axis_angle_to_key(degrees: f64, x: f64, y: f64, z: f64) -> Result<Vec<f64>, JsError> {
    let q =
        UnitQuat::from_axis_angle(DVec3::new(x, y, z), degrees.to_radians()).map_err(
            |e| match e {
                PointError::NonFiniteAngle => InputError::Coords(format!("angle: {e}")),
                e => InputError::Coords(format!("axis {}", e.predicate())),
            },
        )?;
    Ok(q.to_wxyz().to_vec())
}

/// Reads and builds a scene.
fn load(scene: &str) -> Result<(Scene, Vec<BuiltCurve>), SceneError> {
    let scene = Scene::from_json(scene)?;
    let curves = scene.build()?;
    Ok((scene, curves))
}

/// Checks that a scene reads, builds and can be drawn.
///
/// # Errors
///
/// The CLI's message for a bad scene or view.
#[wasm_bindgen]
pub fn validate(scene: &str) -> Result<(), JsError> {
    load(scene).map_err(js)?;
    Ok(())
}

/// Samples a scene: the JSON object `spherekit sample [--deriv] [--frame F]` prints (`t`,
/// `points`, with `deriv` the derivatives and on S³ angular velocity and acceleration, in the
/// space frame or with `frame` `"body"` the body frame; `controls`, `auxiliary` and `info` —
/// such as the Beta solver's iterations and residual — when the method has them).
///
/// # Errors
///
/// The CLI's message for a bad scene; a frame other than `"space"` or `"body"`.
#[wasm_bindgen]
pub fn sample(scene: &str, deriv: bool, frame: Option<String>) -> Result<String, JsError> {
    let body = body_frame(frame.as_deref())?;
    let (scene, curves) = load(scene).map_err(js)?;
    Ok(sampled(&scene, &curves, deriv, body))
}

/// Samples a scene at the parameters `ts` (a `Float64Array`) instead of its own `samples` or
/// `eval_at`: what `spherekit sample --at` prints. Outside a curve's domain its
/// `"extrapolate"` policy applies; a parameter that is NaN or infinite, or outside the domain
/// of an `"error"` curve, is an error naming it (`eval_at[k]: …`).
///
/// # Errors
///
/// The CLI's message for a bad scene or parameter; a frame other than `"space"` or `"body"`.
#[wasm_bindgen]
pub fn sample_at(
    scene: &str,
    ts: &[f64],
    deriv: bool,
    frame: Option<String>,
) -> Result<String, JsError> {
    let body = body_frame(frame.as_deref())?;
    let mut scene = Scene::from_json(scene).map_err(js)?;
    scene.set_parameters(ts.to_vec()).map_err(js)?;
    let curves = scene.build().map_err(js)?;
    Ok(sampled(&scene, &curves, deriv, body))
}

fn body_frame(frame: Option<&str>) -> Result<bool, JsError> {
    match frame {
        None | Some("space") => Ok(false),
        Some("body") => Ok(true),
        Some(other) => Err(JsError::new(&format!(
            "frame: \"{other}\" is not a frame: use space or body"
        ))),
    }
}

fn sampled(scene: &Scene, curves: &[BuiltCurve], deriv: bool, body_frame: bool) -> String {
    let options = SampleOptions {
        deriv,
        body_frame,
        ..SampleOptions::default()
    };
    scene.sample_json_with(curves, options).to_string()
}

/// One field of curve `curve`'s samples, flattened row by row into a `Float64Array`: `t`,
/// `points`, `velocity`, `acceleration`, `angular_velocity`, `angular_acceleration` (S³),
/// `controls`, `auxiliary`, `domain`. A field the method does not have gives an empty array.
///
/// # Errors
///
/// The CLI's message for a bad scene; an [`InputError`] for an unknown field or curve.
#[wasm_bindgen]
pub fn sample_array(scene: &str, curve: usize, field: &str) -> Result<Vec<f64>, JsError> {
    let (scene, curves) = load(scene).map_err(js)?;
    field_of(&scene, &curves, curve, field).map_err(Into::into)
}

/// Curve `curve`'s samples of `field`, as [`sample_array`] gives them.
fn field_of(
    scene: &Scene,
    curves: &[BuiltCurve],
    curve: usize,
    field: &str,
) -> Result<Vec<f64>, InputError> {
    curves
        .get(curve)
        .ok_or(InputError::NoCurve(curve))?
        .sample_field(scene, field)
        .ok_or_else(|| InputError::Field(field.into()))
}

/// The continuity report of every curve as JSON: per curve a list of interior joints
/// `{ "t", "c0", "c1", "c2", "g1", "class" }` with the jumps of point, first and second
/// derivative and unit tangent (ambient norms of left minus right one-sided limits,
/// [`spherekit::continuity`]) and the class ([`spherekit::JointContinuity::class`]): `"C⁰"`,
/// `"G¹"` (direction continuous, speed not), `"C¹"`, `"C²"`, up to the `"Cⁿ"` a blend
/// guarantees, or `"broken"` — what `spherekit sample --continuity` prints.
///
/// # Errors
///
/// The CLI's message for a bad scene.
#[wasm_bindgen]
pub fn continuity(scene: &str) -> Result<String, JsError> {
    let (_, curves) = load(scene).map_err(js)?;
    Ok(report(&curves).to_string())
}

fn report(curves: &[BuiltCurve]) -> Value {
    Value::Array(
        curves
            .iter()
            .map(|c| {
                let (joints, order) = c.continuity();
                continuity_json(&joints, order)
            })
            .collect(),
    )
}

/// Renders a scene as [`spherekit_render::render`] does and returns straight-alpha RGBA bytes,
/// row by row (`size` wide; `size` high, plus a quarter of `size` with the speed plot).
///
/// # Errors
///
/// The CLI's message for a bad scene, view or size.
#[wasm_bindgen]
pub fn render_rgba(scene: &str, size: u32) -> Result<Vec<u8>, JsError> {
    let (scene, curves) = load(scene).map_err(js)?;
    let pixmap = render_built(&scene, &curves, size).map_err(js)?;
    Ok(straight_rgba(pixmap))
}

/// tiny-skia keeps premultiplied pixels; canvases take straight alpha. Frames from
/// [`render_built`] are opaque (it paints a white page first), and an opaque premultiplied pixel
/// is its straight value, so the bytes go as they are.
fn straight_rgba(pixmap: Pixmap) -> Vec<u8> {
    debug_assert!(
        pixmap.pixels().iter().all(|p| p.alpha() == u8::MAX),
        "render_built frames are opaque"
    );
    pixmap.take()
}

/// The page's handle on one scene: the edited [`Document`] and the last rendered frame.
///
/// Edits go through [`Document`] (checked exactly like a pasted scene, rebuilding only the
/// curves whose description changed); a change of `view` re-renders without rebuilding. A
/// failed edit leaves everything as it was.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Playground {
    doc: Document,
    /// Width of the last rendered frame (0 before the first render).
    width: u32,
    rgba: Vec<u8>,
    /// Where the last rendered frame's plots put their axes.
    plots: Vec<PlotAxes>,
    /// The last figure laid out, with its key (the document's layout generation and the
    /// size): turning the view renders it again without flattening or sampling.
    prepared: Option<((u64, u32, u32), Prepared)>,
    /// What the last frames left for the next (the backdrop, the stroker's buffer, glyphs).
    cache: RenderCache,
    /// What the last failed edit's solver reported (see [`Playground::failure`]).
    failure: Option<SolveFailure>,
    /// The smallest text, pixels per em (see [`Playground::set_min_text`]).
    min_text: f32,
}

/// An iterative solver that gave up during an edit: the residual it stopped at (for the Beta
/// interpolation: the largest distance in radians from the curve to a point) and its
/// iterations.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SolveFailure {
    curve: Option<usize>,
    residual: f64,
    iterations: usize,
}

/// The solver failure behind an edit's error, if there is one: the core's
/// [`SolveError::NoConvergence`] found through the error's sources, with the curve index of
/// the scene's `curves[i]` wrapper.
fn solve_failure(e: &EditError) -> Option<SolveFailure> {
    let EditError::Scene(scene) = e else {
        return None;
    };
    let curve = match scene {
        SceneError::InCurve { index, .. } => Some(*index),
        _ => None,
    };
    let mut cause: Option<&(dyn core::error::Error + 'static)> = Some(scene);
    while let Some(err) = cause {
        if let Some(SolveError::NoConvergence {
            iterations,
            residual,
        }) = err.downcast_ref::<SolveError>()
        {
            return Some(SolveFailure {
                curve,
                residual: *residual,
                iterations: *iterations,
            });
        }
        cause = err.source();
    }
    None
}

#[wasm_bindgen]
impl Playground {
    /// A handle showing `scene`.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad scene.
    #[wasm_bindgen(constructor)]
    pub fn new(scene: &str) -> Result<Self, JsError> {
        Ok(Self {
            doc: Document::from_json(scene).map_err(js)?,
            width: 0,
            rgba: Vec::new(),
            plots: Vec::new(),
            prepared: None,
            cache: RenderCache::default(),
            failure: None,
            min_text: 0.0,
        })
    }

    /// Replaces the scene; on error the previous one stays.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad scene.
    pub fn set_scene(&mut self, scene: &str) -> Result<(), JsError> {
        let r = self.doc.set_scene(scene);
        self.edited(r)
    }

    /// What the solver reported when the last edit failed because an iterative solver (the
    /// Beta spline's interpolation) gave up, as JSON `{ "curve", "residual", "iterations" }`
    /// (`residual` in radians: how far the best curve found misses a point; `curve` null when
    /// the scene has one curve), or `null` when the last edit succeeded or failed otherwise.
    #[must_use]
    pub fn failure(&self) -> String {
        self.failure
            .map_or(
                Value::Null,
                |f| json!({ "curve": f.curve, "residual": f.residual, "iterations": f.iterations }),
            )
            .to_string()
    }

    /// The current scene as compact JSON text.
    #[must_use]
    pub fn scene_json(&self) -> String {
        self.doc.to_json()
    }

    /// The space: `"S2"`, `"S3"` or `"S<m>"`.
    #[must_use]
    pub fn space(&self) -> String {
        self.doc.scene().space.name()
    }

    /// The number of curves.
    #[must_use]
    pub fn curve_count(&self) -> usize {
        self.doc.scene().curves.len()
    }

    /// The colour each curve is drawn in, as `["#rrggbb", …]` JSON.
    #[must_use]
    pub fn colors(&self) -> String {
        let list: Vec<Value> = self
            .doc
            .scene()
            .curves
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let [r, g, b] = c.color.unwrap_or(PALETTE[i % PALETTE.len()]);
                json!(format!("#{r:02x}{g:02x}{b:02x}"))
            })
            .collect();
        Value::Array(list).to_string()
    }

    /// The colours of the body x, y and z axes (and of ω's components for one curve), as
    /// `["#rrggbb", …]` JSON.
    #[must_use]
    pub fn axis_colors(&self) -> String {
        let list: Vec<Value> = AXIS_COLORS
            .iter()
            .map(|[r, g, b]| json!(format!("#{r:02x}{g:02x}{b:02x}")))
            .collect();
        Value::Array(list).to_string()
    }

    /// How many curves have been built since the handle was made (a test of "rebuild only
    /// what changed").
    #[must_use]
    pub fn builds(&self) -> u32 {
        self.doc.builds()
    }

    /// Curve `curve`'s description as JSON: `{ "method", "points", "knots"?, "params"?, … }`.
    ///
    /// # Errors
    ///
    /// For a curve that does not exist.
    pub fn curve_json(&self, curve: usize) -> Result<String, JsError> {
        Ok(Value::Object(self.doc.curve(curve).map_err(js)?.clone()).to_string())
    }

    /// Point `index` of curve `curve` as written in the scene.
    ///
    /// # Errors
    ///
    /// For a point that does not exist.
    pub fn point(&self, curve: usize, index: usize) -> Result<Vec<f64>, JsError> {
        self.doc.point(curve, index).map_err(js)
    }

    /// Sets point `index` of curve `curve` (normalised when the curve is built).
    ///
    /// # Errors
    ///
    /// The CLI's message when the curve rejects the point; a bad index or coordinates.
    pub fn set_point(&mut self, curve: usize, index: usize, coords: &[f64]) -> Result<(), JsError> {
        let r = self.doc.set_point(curve, index, coords);
        self.edited(r)
    }

    /// Inserts a point before `index` (`index` = count appends); knots and per-joint lists
    /// follow.
    ///
    /// # Errors
    ///
    /// As [`Playground::set_point`].
    pub fn insert_point(
        &mut self,
        curve: usize,
        index: usize,
        coords: &[f64],
    ) -> Result<(), JsError> {
        let r = self.doc.insert_point(curve, index, coords);
        self.edited(r)
    }

    /// Removes point `index` of curve `curve`; knots and per-joint lists follow.
    ///
    /// # Errors
    ///
    /// The CLI's message when too few points remain; a bad index.
    pub fn remove_point(&mut self, curve: usize, index: usize) -> Result<(), JsError> {
        let r = self.doc.remove_point(curve, index);
        self.edited(r)
    }

    /// Sets `params.<name>` of curve `curve` to a JSON value (`null` removes it).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad parameter; text that is not JSON.
    pub fn set_param(&mut self, curve: usize, name: &str, value: &str) -> Result<(), JsError> {
        let v = json_arg(value).map_err(js)?;
        let r = self.doc.set_param(curve, name, v);
        self.edited(r)
    }

    /// Replaces curve `curve`'s fields other than `points` by those of a JSON object
    /// (`{ "method", "params", "knots", "canonicalize", "closed", "parametrization",
    /// "extrapolate", "color", "label" }`; absent ones are removed).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad curve.
    pub fn set_curve(&mut self, curve: usize, fields: &str) -> Result<(), JsError> {
        let fields = match json_arg(fields).map_err(js)? {
            Value::Object(m) => m,
            _ => return Err(js(EditError::Json("expected an object".into()))),
        };
        let r = self.doc.set_curve(curve, fields);
        self.edited(r)
    }

    /// Gives curve `curve` another method, keeping the parameters and knots it can take.
    ///
    /// # Errors
    ///
    /// The CLI's message when the method cannot take the curve's points.
    pub fn set_method(&mut self, curve: usize, method: &str) -> Result<(), JsError> {
        let r = self.doc.set_method(curve, method);
        self.edited(r)
    }

    /// Adds a curve with `method` through the same points as curve 0 (a single-curve scene
    /// becomes a `curves` list).
    ///
    /// # Errors
    ///
    /// The CLI's message when the method cannot take these points.
    pub fn add_curve(&mut self, method: &str) -> Result<(), JsError> {
        let r = self.doc.add_curve(method);
        self.edited(r)
    }

    /// Removes curve `curve` (the last one cannot be removed).
    ///
    /// # Errors
    ///
    /// A bad index or the last curve.
    pub fn remove_curve(&mut self, curve: usize) -> Result<(), JsError> {
        let r = self.doc.remove_curve(curve);
        self.edited(r)
    }

    /// Sets a `view` option (`camera`, `plot`, `frames`, `accuracy`, `axes`) to a JSON value
    /// (`null` removes it). Re-renders without rebuilding.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad option; text that is not JSON.
    pub fn set_view(&mut self, name: &str, value: &str) -> Result<(), JsError> {
        let v = json_arg(value).map_err(js)?;
        let r = self.doc.set_view(name, v);
        self.edited(r)
    }

    /// The view options the scene is drawn with, defaults filled in, as JSON: `{ "plot":
    /// "speed" | "omega" | "none", "legend", "axes": ["x", …], "frames", "omega_frame":
    /// "space" | "body" }` (the panel's
    /// toggles show these).
    #[must_use]
    pub fn view_options(&self) -> String {
        let view = self.doc.scene().view();
        let plot = match view.plot {
            Plot::Speed => "speed",
            Plot::Omega => "omega",
            Plot::None => "none",
        };
        let axes: Vec<&str> = view.axes.iter().map(|&k| ["x", "y", "z"][k % 3]).collect();
        let omega_frame = if view.omega_body { "body" } else { "space" };
        json!({
            "plot": plot, "legend": view.legend, "axes": axes, "frames": view.frames,
            "omega_frame": omega_frame,
        })
        .to_string()
    }

    /// The camera the scene is drawn with, `[w, x, y, z]` (the default one when the scene has
    /// none).
    #[must_use]
    pub fn camera(&self) -> Vec<f64> {
        self.cam().orientation.to_wxyz().to_vec()
    }

    /// Rotates the view by a drag from pixel `(x0, y0)` to `(x1, y1)` starting from `camera0`
    /// (`[w, x, y, z]`, the camera when the drag began): the sphere point under the pointer
    /// follows it.
    ///
    /// # Errors
    ///
    /// For a camera that is not a quaternion.
    pub fn drag_view(
        &mut self,
        camera0: &[f64],
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        size: u32,
    ) -> Result<(), JsError> {
        let start = Camera {
            orientation: quat(camera0)?,
        };
        let camera = start.dragged([x0, y0], [x1, y1], size);
        self.set_view("camera", &json!(camera.to_wxyz()).to_string())
    }

    /// Fixes the current camera in the scene (so moving points does not move a default camera
    /// that faces their mean).
    ///
    /// # Errors
    ///
    /// Does not fail for a scene that was drawn.
    pub fn pin_camera(&mut self) -> Result<(), JsError> {
        if self.doc.scene().view().camera.is_some() {
            return Ok(());
        }
        self.set_view("camera", &json!(self.camera()).to_string())
    }

    /// Pixel position and depth `[x, y, depth]` of a point of ℝ³ in an image `size` wide.
    #[must_use]
    pub fn project(&self, x: f64, y: f64, z: f64, size: u32) -> Vec<f64> {
        self.cam().project(DVec3::new(x, y, z), size).to_vec()
    }

    /// The visible sphere point `[x, y, z]` drawn at a pixel (the nearest rim point outside the
    /// disc).
    #[must_use]
    pub fn unproject(&self, x: f64, y: f64, size: u32) -> Vec<f64> {
        self.cam().unproject(x, y, size).to_array().to_vec()
    }

    /// The input point (S² and S¹) or key (S³: any tip of its rotated body axes) drawn nearest
    /// to pixel `(x, y)` within `radius` pixels, on the visible side, as `[curve, index]`.
    #[must_use]
    pub fn pick(&self, x: f64, y: f64, size: u32, radius: f64) -> Option<Vec<u32>> {
        let (c, p) = self.cam().pick(self.doc.curves(), [x, y], size, radius)?;
        Some(vec![
            u32::try_from(c).unwrap_or(u32::MAX),
            u32::try_from(p).unwrap_or(u32::MAX),
        ])
    }

    /// Moves S² (or S¹) point `index` to the sphere point drawn at pixel `(x, y)`.
    ///
    /// # Errors
    ///
    /// As [`Playground::set_point`].
    pub fn move_point_to(
        &mut self,
        curve: usize,
        index: usize,
        x: f64,
        y: f64,
        size: u32,
    ) -> Result<(), JsError> {
        let p = self.cam().unproject(x, y, size);
        let coords = self.sphere_coords(p);
        self.set_point(curve, index, &coords)
    }

    /// Appends the sphere point drawn at pixel `(x, y)` to S² curve `curve`; on S³ appends the
    /// last key turned by the rotation taking its body z axis to that point.
    ///
    /// # Errors
    ///
    /// As [`Playground::set_point`].
    pub fn add_point_at(&mut self, curve: usize, x: f64, y: f64, size: u32) -> Result<(), JsError> {
        let target = self.cam().unproject(x, y, size);
        let spec = self
            .doc
            .scene()
            .curves
            .get(curve)
            .ok_or(InputError::NoCurve(curve))?;
        let count = spec.points.len();
        let coords = if self.doc.scene().space == Space::S3 {
            let last = spec.points.last().map_or(&[][..], Vec::as_slice);
            let key = quat(last)?;
            let q = turn_towards(key, key.rotate(DVec3::Z), target).map_err(js)?;
            q.to_wxyz().to_vec()
        } else {
            self.sphere_coords(target)
        };
        self.insert_point(curve, count, &coords)
    }

    /// Turns S³ key `index` (given as `key0` when the drag began) by the rotation that takes
    /// the sphere point under pixel `(x0, y0)` to the one under `(x1, y1)`.
    ///
    /// # Errors
    ///
    /// As [`Playground::set_point`].
    #[expect(clippy::too_many_arguments, reason = "a drag is two pixels and a size")]
    pub fn drag_key(
        &mut self,
        curve: usize,
        index: usize,
        key0: &[f64],
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        size: u32,
    ) -> Result<(), JsError> {
        let q = self
            .cam()
            .turn_key(quat(key0)?, [x0, y0], [x1, y1], size)
            .map_err(js)?;
        self.set_point(curve, index, &q.to_wxyz())
    }

    /// The scene's time axis `[t₀, t₁, normalized]`: the span of every curve's domain in its
    /// own parameter t (what the plots' time axis shows), or `[0, 1, 1]` with `view.plot_time`
    /// `"normalized"` (each curve then runs over u = (t − its t₀)/(its t₁ − its t₀)). The
    /// `time` arguments of [`Playground::eval`] and [`Playground::readout`] are on this axis.
    #[must_use]
    pub fn time_axis(&self) -> Vec<f64> {
        if self.normalized() {
            return vec![0.0, 1.0, 1.0];
        }
        let [a, b] =
            self.doc
                .curves()
                .iter()
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[a, b], c| {
                    let [t0, t1] = c.domain();
                    [a.min(t0), b.max(t1)]
                });
        vec![a, b, 0.0]
    }

    /// Curve `curve` at `time` on the scene's time axis ([`Playground::time_axis`]), clamped to
    /// its domain: an S³ curve gives its orientation `[w, x, y, z]` followed by the rotated
    /// body axes (9 numbers), another sphere the point.
    ///
    /// # Errors
    ///
    /// For a curve that does not exist.
    pub fn eval(&self, curve: usize, time: f64) -> Result<Vec<f64>, JsError> {
        let (c, t) = self.at(curve, time)?;
        Ok(match c {
            BuiltCurve::S2(b) => b.curve.eval(t).as_dvec3().to_array().to_vec(),
            BuiltCurve::Sm(b) => b.curve.eval(t).coords().to_vec(),
            BuiltCurve::S3(b) => {
                let q = b.curve.eval(t);
                let mut out = q.to_wxyz().to_vec();
                for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
                    out.extend(q.rotate(axis).to_array());
                }
                out
            }
        })
    }

    /// What the readout shows of curve `curve` at `time` on the scene's time axis (clamped to
    /// its domain), as JSON: `{ "t", "point", "speed" }`, the curve's own parameter `t`, the
    /// point (`[w, x, y, z]` on S³) and the speed |c′(t)| (on S³ the angular speed |ω|, in
    /// radians per unit t), and on S³ `"omega"` and `"alpha"`, the angular velocity and
    /// acceleration in the space frame or, with `frame` `"body"`, the body frame
    /// ([`spherekit::angular_velocity_acceleration`]). Right-sided at a joint.
    ///
    /// # Errors
    ///
    /// For a curve that does not exist; a frame other than `"space"` or `"body"`.
    pub fn readout(
        &self,
        curve: usize,
        time: f64,
        frame: Option<String>,
    ) -> Result<String, JsError> {
        let body = body_frame(frame.as_deref())?;
        let (c, t) = self.at(curve, time)?;
        let out = match c {
            BuiltCurve::S2(b) => {
                let j = b.curve.jet(t);
                json!({ "t": t, "point": j.point.as_dvec3().to_array(), "speed": j.velocity.length() })
            }
            BuiltCurve::Sm(b) => {
                let j = b.curve.jet(t);
                json!({ "t": t, "point": j.point.coords(), "speed": j.velocity.length() })
            }
            BuiltCurve::S3(b) => {
                let Jet {
                    point,
                    velocity,
                    acceleration,
                    ..
                } = b.curve.jet(t);
                let (w, a) = if body {
                    angular_velocity_acceleration_body(point, velocity, acceleration)
                } else {
                    angular_velocity_acceleration(point, velocity, acceleration)
                };
                json!({
                    "t": t,
                    "point": point.to_wxyz(),
                    "speed": w.length(),
                    "omega": w.to_array(),
                    "alpha": a.to_array(),
                })
            }
        };
        Ok(out.to_string())
    }

    /// Where the last rendered frame's plot strips have their axes, top to bottom, as JSON
    /// `[{ "left", "top", "right", "bottom", "t0", "t1" }, …]` (pixels of that frame; the time
    /// on the scene's time axis at the left and right edges). Empty without plots.
    #[must_use]
    pub fn plot_axes(&self) -> String {
        let list: Vec<Value> = self
            .plots
            .iter()
            .map(|p| {
                json!({
                    "left": p.left, "top": p.top, "right": p.right, "bottom": p.bottom,
                    "t0": p.time[0], "t1": p.time[1],
                })
            })
            .collect();
        Value::Array(list).to_string()
    }

    /// The scene's samples, as [`sample`].
    ///
    /// # Errors
    ///
    /// A frame other than `"space"` or `"body"`.
    pub fn sample(&self, deriv: bool, frame: Option<String>) -> Result<String, JsError> {
        let body = body_frame(frame.as_deref())?;
        Ok(sampled(self.doc.scene(), self.doc.curves(), deriv, body))
    }

    /// The scene's samples at the parameters `ts`, as [`sample_at`], from the curves already
    /// built.
    ///
    /// # Errors
    ///
    /// As [`sample_at`].
    pub fn sample_at(
        &self,
        ts: &[f64],
        deriv: bool,
        frame: Option<String>,
    ) -> Result<String, JsError> {
        let body = body_frame(frame.as_deref())?;
        let mut scene = self.doc.scene().clone();
        scene.set_parameters(ts.to_vec()).map_err(js)?;
        scene.check_parameters(self.doc.curves()).map_err(js)?;
        Ok(sampled(&scene, self.doc.curves(), deriv, body))
    }

    /// One field of curve `curve`'s samples, as [`sample_array`], from the curves already built.
    ///
    /// # Errors
    ///
    /// An [`InputError`] for an unknown field or curve.
    pub fn sample_array(&self, curve: usize, field: &str) -> Result<Vec<f64>, JsError> {
        field_of(self.doc.scene(), self.doc.curves(), curve, field).map_err(Into::into)
    }

    /// The continuity report, as [`continuity`].
    #[must_use]
    pub fn continuity(&self) -> String {
        report(self.doc.curves()).to_string()
    }

    /// Sets the smallest text of the frames rendered from now on, in pixels per em (a page
    /// passes 11 CSS pixels times its device pixel ratio so that a small figure stays
    /// readable); 0, the default, draws the figure as the CLI and the golden images do.
    pub fn set_min_text(&mut self, pixels: f32) {
        self.min_text = if pixels.is_finite() {
            pixels.max(0.0)
        } else {
            0.0
        };
    }

    /// Renders the built curves into the handle's frame (`size` wide) without rebuilding.
    /// Returns the frame's height.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad view or size.
    pub fn render(&mut self, size: u32) -> Result<u32, JsError> {
        let (scene, curves) = (self.doc.scene(), self.doc.curves());
        // The layout is kept while the document's layout generation, the size and the text
        // floor are the same.
        let key = (self.doc.layout_generation(), size, self.min_text.to_bits());
        let prepared = match self.prepared.take() {
            Some((k, p)) if k == key => p,
            _ => prepare_with_text(scene, curves, size, self.min_text).map_err(js)?,
        };
        let rendered = prepared.render_with(scene, curves, &mut self.cache);
        self.prepared = Some((key, prepared));
        let (pixmap, plots) = rendered.map_err(js)?;
        let h = pixmap.height();
        self.width = pixmap.width();
        self.rgba = straight_rgba(pixmap);
        self.plots = plots;
        Ok(h)
    }

    /// The last rendered frame as straight-alpha RGBA bytes (empty before the first render).
    #[must_use]
    pub fn rgba(&self) -> Vec<u8> {
        self.rgba.clone()
    }

    /// Renders at `size` and draws the frame into `canvas`, resizing it to the frame.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad view or size; a canvas without a 2D context.
    pub fn draw(&mut self, canvas: &web_sys::HtmlCanvasElement, size: u32) -> Result<(), JsError> {
        let h = self.render(size)?;
        let w = self.width;
        if canvas.width() != w || canvas.height() != h {
            canvas.set_width(w);
            canvas.set_height(h);
        }
        let ctx = canvas
            .get_context("2d")
            .ok()
            .flatten()
            .and_then(|c| c.dyn_into::<web_sys::CanvasRenderingContext2d>().ok())
            .ok_or(InputError::NoContext)?;
        let data = web_sys::ImageData::new_with_u8_clamped_array_and_sh(
            wasm_bindgen::Clamped(&self.rgba),
            w,
            h,
        )
        .map_err(|_| InputError::NoContext)?;
        ctx.put_image_data(&data, 0.0, 0.0)
            .map_err(|_| InputError::NoContext)?;
        Ok(())
    }
}

impl Playground {
    /// Keeps what a failed edit's solver reported (or forgets it) and gives the error.
    fn edited(&mut self, result: Result<(), EditError>) -> Result<(), JsError> {
        self.failure = result.as_ref().err().and_then(solve_failure);
        result.map_err(js)
    }

    fn normalized(&self) -> bool {
        self.doc.scene().view().plot_time == PlotTime::Normalized
    }

    /// Curve `curve` and its parameter at `time` on the scene's time axis, clamped to its
    /// domain (a NaN time is the domain's start).
    fn at(&self, curve: usize, time: f64) -> Result<(&BuiltCurve, f64), InputError> {
        let c = self
            .doc
            .curves()
            .get(curve)
            .ok_or(InputError::NoCurve(curve))?;
        let [t0, t1] = c.domain();
        let t = if self.normalized() {
            t0 + (t1 - t0) * time
        } else {
            time
        };
        let t = if t.is_nan() { t0 } else { t.clamp(t0, t1) };
        Ok((c, t))
    }

    fn cam(&self) -> Camera {
        camera_of(self.doc.scene(), self.doc.curves())
    }

    /// Sphere coordinates of a point of ℝ³ in the scene's space (S¹ drops z).
    fn sphere_coords(&self, p: DVec3) -> Vec<f64> {
        match self.doc.scene().space {
            Space::Sm(1) => vec![p.x, p.y],
            _ => p.to_array().to_vec(),
        }
    }
}
