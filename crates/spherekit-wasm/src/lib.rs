// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! WebAssembly bindings for the browser playground (`web/index.html`) and the docs widget
//! (`web/widget.js`): a thin layer over [`spherekit::scene`] and [`spherekit_render`] with no
//! math of its own.
//!
//! - Free functions evaluate a scene given as JSON text: [`methods`], [`validate`],
//!   [`sample`] (the `spherekit sample` output, with derived control points, auxiliary vertices
//!   and solver info), [`sample_array`] (one field as a `Float64Array`), [`continuity`] (jumps
//!   at the joints from one-sided jets) and [`render_rgba`].
//! - [`Playground`] is the page's stateful handle: it keeps the built curves, rebuilds only the
//!   curves an edit touched (a camera change only re-renders), and draws into a canvas.
//!
//! Every bad input gives a `JsError` whose message is the line the CLI prints after
//! `error: `; a panic hook reports anything unexpected to the console.
//!
//! Coordinates follow the scene format: S² points `[x, y, z]`, S³ keys `[w, x, y, z]`. Screen
//! positions are pixels of an image `size` pixels wide, as [`spherekit_render::render`] draws it.

use serde_json::{Map, Value, json};
use spherekit::glam::{DQuat, DVec3};
use spherekit::scene::{BuiltCurve, Method, Scene, SceneError, Space};
use spherekit::{Curve, Jet, Manifold, Side, UnitQuat};
use spherekit_render::{PALETTE, View, render_built, view_of};
use tiny_skia::Pixmap;
use wasm_bindgen::prelude::*;

mod input;

include!(concat!(env!("OUT_DIR"), "/presets.rs"));

pub use input::InputError;
use input::PointEdit;

/// Installs the panic hook that reports a panic to the browser console (called on load).
#[wasm_bindgen(start)]
pub fn start() {
    console_error_panic_hook::set_once();
}

fn js(e: impl core::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// The curve methods as JSON: `[{ "id", "summary", "spaces" }, …]`, in the order
/// `spherekit methods` lists them.
#[wasm_bindgen]
#[must_use]
pub fn methods() -> String {
    let list: Vec<Value> = Method::ALL
        .iter()
        .map(|m| {
            json!({
                "id": m.id(),
                "summary": m.summary(),
                "spaces": m.support().describe(),
            })
        })
        .collect();
    Value::Array(list).to_string()
}

/// The example scenes (the golden-image scenes of `tests/golden`) as JSON:
/// `[{ "name", "scene" }, …]` with each scene as JSON text.
#[wasm_bindgen]
#[must_use]
pub fn presets() -> String {
    let list: Vec<Value> = PRESETS
        .iter()
        .map(|(name, scene)| json!({ "name": name, "scene": scene }))
        .collect();
    Value::Array(list).to_string()
}

/// The body axes of an orientation `[w, x, y, z]` after rotation: `[x₁, y₁, z₁, x₂, …, z₃]`.
///
/// # Errors
///
/// An [`InputError`] for a quaternion that is not 4 finite numbers of non-zero length.
#[wasm_bindgen]
pub fn key_axes(key: &[f64]) -> Result<Vec<f64>, JsError> {
    let q = input::quat(key)?;
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
    let (axis, angle) = input::quat(key)?.to_axis_angle();
    Ok(vec![angle.to_degrees(), axis.x, axis.y, axis.z])
}

/// The orientation `[w, x, y, z]` turning by `degrees` about `axis`.
///
/// # Errors
///
/// An [`InputError`] for a zero or non-finite axis or angle.
#[wasm_bindgen]
pub fn axis_angle_to_key(degrees: f64, x: f64, y: f64, z: f64) -> Result<Vec<f64>, JsError> {
    let q = UnitQuat::from_axis_angle(DVec3::new(x, y, z), degrees.to_radians())
        .map_err(|e| InputError::Coords(format!("axis {e}")))?;
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
    let (scene, curves) = load(scene).map_err(js)?;
    view_of(&scene, &curves).map_err(js)?;
    Ok(())
}

/// Samples a scene: the JSON object `spherekit sample [--deriv]` prints (`t`, `points`, with
/// `deriv` the derivatives and on S³ angular velocity and acceleration; `controls`,
/// `auxiliary` and `info` — such as the Beta solver's iterations and residual — when the
/// method has them).
///
/// # Errors
///
/// The CLI's message for a bad scene.
#[wasm_bindgen]
pub fn sample(scene: &str, deriv: bool) -> Result<String, JsError> {
    let (scene, curves) = load(scene).map_err(js)?;
    Ok(scene.sample_json(&curves, deriv).to_string())
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
/// `{ "t", "c0", "c1", "c2", "g1", "order", "class" }` with the jumps of point, first and second
/// derivative and unit tangent (ambient norms of left minus right one-sided limits,
/// [`spherekit::continuity`]), the highest order k ≤ 2 whose jumps are all below 1e-9
/// (`null` when the points differ), and `class`: `"C²"`, `"C¹"`, `"G¹"` (direction continuous,
/// speed not), `"C⁰"` or `"broken"`.
///
/// # Errors
///
/// The CLI's message for a bad scene.
#[wasm_bindgen]
pub fn continuity(scene: &str) -> Result<String, JsError> {
    let (_, curves) = load(scene).map_err(js)?;
    Ok(continuity_json(&curves).to_string())
}

/// The tolerance of the continuity readout's `order`.
pub const CONTINUITY_TOLERANCE: f64 = 1e-9;

fn continuity_json(curves: &[BuiltCurve]) -> Value {
    let list = curves.iter().map(|c| {
        let report = match c {
            BuiltCurve::S2(b) => spherekit::continuity(&Dyn(&*b.curve)),
            BuiltCurve::S3(b) => spherekit::continuity(&Dyn(&*b.curve)),
            BuiltCurve::Sn(b) => spherekit::continuity(&Dyn(&*b.curve)),
        };
        Value::Array(
            report
                .iter()
                .map(|j| {
                    let order = j.order(CONTINUITY_TOLERANCE);
                    let class = match order {
                        None => "broken",
                        Some(0) if j.g1 <= CONTINUITY_TOLERANCE => "G¹",
                        Some(0) => "C⁰",
                        Some(1) => "C¹",
                        Some(_) => "C²",
                    };
                    json!({ "t": j.t, "c0": j.c0, "c1": j.c1, "c2": j.c2, "g1": j.g1,
                            "order": order, "class": class })
                })
                .collect(),
        )
    });
    Value::Array(list.collect())
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

/// The page's handle on one scene: the scene's JSON document, the validated scene, its built
/// curves and the last rendered frame.
///
/// Edits change the document and go through [`Scene::from_json`] again (so they are checked
/// exactly like a pasted scene), but only curves whose description changed are rebuilt; a
/// change of `view` re-renders without rebuilding. A failed edit leaves everything as it was.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Playground {
    doc: Map<String, Value>,
    scene: Scene,
    curves: Vec<BuiltCurve>,
    /// Width of the last rendered frame (0 before the first render).
    width: u32,
    rgba: Vec<u8>,
    builds: u32,
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
        let doc = parse_doc(scene).map_err(js)?;
        let (scene, curves) = load(scene).map_err(js)?;
        view_of(&scene, &curves).map_err(js)?;
        Ok(Self {
            builds: u32::try_from(curves.len()).unwrap_or(u32::MAX),
            doc,
            scene,
            curves,
            width: 0,
            rgba: Vec::new(),
        })
    }

    /// Replaces the scene; on error the previous one stays.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad scene.
    pub fn set_scene(&mut self, scene: &str) -> Result<(), JsError> {
        let doc = parse_doc(scene).map_err(js)?;
        self.apply(doc)
    }

    /// The current scene as compact JSON text.
    #[must_use]
    pub fn scene_json(&self) -> String {
        Value::Object(self.doc.clone()).to_string()
    }

    /// The space: `"S2"`, `"S3"` or `"S<m>"`.
    #[must_use]
    pub fn space(&self) -> String {
        self.scene.space.name()
    }

    /// The number of curves.
    #[must_use]
    pub fn curve_count(&self) -> usize {
        self.scene.curves.len()
    }

    /// The colour each curve is drawn in, as `["#rrggbb", …]` JSON.
    #[must_use]
    pub fn colors(&self) -> String {
        let list: Vec<Value> = self
            .scene
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

    /// How many curves have been built since the handle was made (a test of "rebuild only
    /// what changed").
    #[must_use]
    pub fn builds(&self) -> u32 {
        self.builds
    }

    /// Curve `curve`'s description as JSON: `{ "method", "points", "knots"?, "params"?, … }`.
    ///
    /// # Errors
    ///
    /// An [`InputError`] for a curve that does not exist.
    pub fn curve_json(&self, curve: usize) -> Result<String, JsError> {
        let c = self.curve_doc(curve)?;
        Ok(Value::Object(c.clone()).to_string())
    }

    /// Point `index` of curve `curve` as written in the scene.
    ///
    /// # Errors
    ///
    /// An [`InputError`] for a point that does not exist.
    pub fn point(&self, curve: usize, index: usize) -> Result<Vec<f64>, JsError> {
        let c = self.curve_doc(curve)?;
        let p = c
            .get("points")
            .and_then(|p| p.get(index))
            .and_then(Value::as_array)
            .ok_or(InputError::NoPoint(index))?;
        Ok(p.iter().filter_map(Value::as_f64).collect())
    }

    /// Sets point `index` of curve `curve` (normalised when the curve is built).
    ///
    /// # Errors
    ///
    /// The CLI's message when the curve rejects the point; an [`InputError`] for a bad index
    /// or coordinates.
    pub fn set_point(&mut self, curve: usize, index: usize, coords: &[f64]) -> Result<(), JsError> {
        let p = input::point_value(coords)?;
        self.edit_points(curve, |points| {
            let slot = points.get_mut(index).ok_or(InputError::NoPoint(index))?;
            *slot = p;
            Ok(None)
        })
    }

    /// Inserts a point before `index` (`index` = count appends).
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
        let p = input::point_value(coords)?;
        self.edit_points(curve, |points| {
            if index > points.len() {
                return Err(InputError::NoPoint(index));
            }
            points.insert(index, p);
            Ok(Some(PointEdit::Insert(index)))
        })
    }

    /// Removes point `index` of curve `curve`.
    ///
    /// # Errors
    ///
    /// The CLI's message when too few points remain; an [`InputError`] for a bad index.
    pub fn remove_point(&mut self, curve: usize, index: usize) -> Result<(), JsError> {
        self.edit_points(curve, |points| {
            if index >= points.len() {
                return Err(InputError::NoPoint(index));
            }
            points.remove(index);
            Ok(Some(PointEdit::Remove(index)))
        })
    }

    /// Sets `params.<name>` of curve `curve` to a JSON value (`null` removes it).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad parameter; an [`InputError`] for text that is not JSON.
    pub fn set_param(&mut self, curve: usize, name: &str, value: &str) -> Result<(), JsError> {
        let v: Value = serde_json::from_str(value).map_err(|e| InputError::Json(e.to_string()))?;
        let mut doc = self.doc.clone();
        let c = curve_doc_mut(&mut doc, curve)?;
        let params = c
            .entry("params")
            .or_insert_with(|| Value::Object(Map::new()));
        if let Value::Object(p) = params {
            if v.is_null() {
                p.remove(name);
            } else {
                p.insert(name.into(), v);
            }
            if p.is_empty() {
                c.remove("params");
            }
        }
        self.apply(doc)
    }

    /// Replaces curve `curve`'s fields other than `points` by those of a JSON object
    /// (`{ "method", "params", "knots", "canonicalize", "color" }`; absent ones are removed).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad curve.
    pub fn set_curve(&mut self, curve: usize, fields: &str) -> Result<(), JsError> {
        let fields = match serde_json::from_str(fields) {
            Ok(Value::Object(m)) => m,
            Ok(_) => return Err(InputError::Json("expected an object".into()).into()),
            Err(e) => return Err(InputError::Json(e.to_string()).into()),
        };
        let mut doc = self.doc.clone();
        let c = curve_doc_mut(&mut doc, curve)?;
        let points = c.remove("points");
        c.clear();
        c.extend(fields);
        if let Some(p) = points {
            c.insert("points".into(), p);
        }
        self.apply(doc)
    }

    /// Adds a curve with `method` through the same points as curve 0 (a single-curve scene
    /// becomes a `curves` list).
    ///
    /// # Errors
    ///
    /// The CLI's message when the method cannot take these points.
    pub fn add_curve(&mut self, method: &str) -> Result<(), JsError> {
        let mut doc = self.doc.clone();
        let list = to_list(&mut doc)?;
        let points = list
            .first()
            .and_then(|c| c.get("points"))
            .cloned()
            .unwrap_or(Value::Array(Vec::new()));
        list.push(json!({ "method": method, "points": points }));
        self.apply(doc)
    }

    /// Removes curve `curve` (the last one cannot be removed).
    ///
    /// # Errors
    ///
    /// An [`InputError`] for a bad index or the last curve.
    pub fn remove_curve(&mut self, curve: usize) -> Result<(), JsError> {
        let mut doc = self.doc.clone();
        let list = to_list(&mut doc)?;
        if curve >= list.len() {
            return Err(InputError::NoCurve(curve).into());
        }
        if list.len() == 1 {
            return Err(InputError::LastCurve.into());
        }
        list.remove(curve);
        self.apply(doc)
    }

    /// Sets a `view` option (`camera`, `plot`, `frames`, `accuracy`) to a JSON value (`null`
    /// removes it). Re-renders without rebuilding.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad option; an [`InputError`] for text that is not JSON.
    pub fn set_view(&mut self, name: &str, value: &str) -> Result<(), JsError> {
        let v: Value = serde_json::from_str(value).map_err(|e| InputError::Json(e.to_string()))?;
        let mut doc = self.doc.clone();
        let view = doc
            .entry("view")
            .or_insert_with(|| Value::Object(Map::new()));
        if let Value::Object(m) = view {
            if v.is_null() {
                m.remove(name);
            } else {
                m.insert(name.into(), v);
            }
            if m.is_empty() {
                doc.remove("view");
            }
        }
        self.apply(doc)
    }

    /// The camera the scene is drawn with, `[w, x, y, z]` (the default one when the scene has
    /// none).
    #[must_use]
    pub fn camera(&self) -> Vec<f64> {
        self.view().camera.to_wxyz().to_vec()
    }

    /// Rotates the view by a drag from pixel `(x0, y0)` to `(x1, y1)` starting from `camera0`
    /// (`[w, x, y, z]`, the camera when the drag began): the sphere point under the pointer
    /// follows it.
    ///
    /// # Errors
    ///
    /// An [`InputError`] for a camera that is not a quaternion.
    pub fn drag_view(
        &mut self,
        camera0: &[f64],
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        size: u32,
    ) -> Result<(), JsError> {
        let mut view = self.view();
        view.camera = input::quat(camera0)?;
        let (a, b) = (view.unproject(x0, y0, size), view.unproject(x1, y1, size));
        // The camera turns opposite to the drag.
        let turn = DQuat::from_rotation_arc(b, a);
        let camera = UnitQuat::try_new(turn * view.camera.as_dquat()).map_err(js)?;
        self.set_view("camera", &json!(camera.to_wxyz()).to_string())
    }

    /// Fixes the current camera in the scene (so moving points does not move a default camera
    /// that faces their mean).
    ///
    /// # Errors
    ///
    /// Does not fail for a scene that was drawn.
    pub fn pin_camera(&mut self) -> Result<(), JsError> {
        let has_camera = self.doc.get("view").and_then(|v| v.get("camera")).is_some();
        if has_camera {
            return Ok(());
        }
        self.set_view("camera", &json!(self.camera()).to_string())
    }

    /// Pixel position and depth `[x, y, depth]` of a point of ℝ³ in an image `size` wide.
    #[must_use]
    pub fn project(&self, x: f64, y: f64, z: f64, size: u32) -> Vec<f64> {
        self.view().project(DVec3::new(x, y, z), size).to_vec()
    }

    /// The visible sphere point `[x, y, z]` drawn at a pixel (the nearest rim point outside the
    /// disc).
    #[must_use]
    pub fn unproject(&self, x: f64, y: f64, size: u32) -> Vec<f64> {
        self.view().unproject(x, y, size).to_array().to_vec()
    }

    /// The input point (S² and S¹) or key (S³: any tip of its rotated body axes) drawn nearest
    /// to pixel `(x, y)` within `radius` pixels, on the visible side, as `[curve, index]`.
    #[must_use]
    pub fn pick(&self, x: f64, y: f64, size: u32, radius: f64) -> Option<Vec<u32>> {
        let view = self.view();
        let mut best: Option<(f64, usize, usize)> = None;
        for (ci, c) in self.curves.iter().enumerate() {
            for (pi, tips) in marker_positions(c).into_iter().enumerate() {
                for p in tips {
                    let [px, py, depth] = view.project(p, size);
                    let d = (px - x).hypot(py - y);
                    if depth >= -1e-9 && d <= radius && best.is_none_or(|b| d < b.0) {
                        best = Some((d, ci, pi));
                    }
                }
            }
        }
        best.map(|(_, c, p)| {
            vec![
                u32::try_from(c).unwrap_or(u32::MAX),
                u32::try_from(p).unwrap_or(u32::MAX),
            ]
        })
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
        let p = self.view().unproject(x, y, size);
        let coords = self.screen_coords(p);
        self.set_point(curve, index, &coords)
    }

    /// Appends the sphere point drawn at pixel `(x, y)` to S² curve `curve`; on S³ appends the
    /// last key turned by the rotation taking its body z axis to that point.
    ///
    /// # Errors
    ///
    /// As [`Playground::set_point`].
    pub fn add_point_at(&mut self, curve: usize, x: f64, y: f64, size: u32) -> Result<(), JsError> {
        let target = self.view().unproject(x, y, size);
        let coords = if self.scene.space == Space::S3 {
            let spec = self
                .scene
                .curves
                .get(curve)
                .ok_or(InputError::NoCurve(curve))?;
            let last = spec.points.last().ok_or(InputError::NoPoint(0))?;
            let key = input::quat(last)?;
            let turn = DQuat::from_rotation_arc(key.rotate(DVec3::Z), target);
            let q = UnitQuat::try_new(turn * key.as_dquat()).map_err(js)?;
            q.to_wxyz().to_vec()
        } else {
            self.screen_coords(target)
        };
        let count = self.scene.curves.get(curve).map_or(0, |c| c.points.len());
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
        let view = self.view();
        let key = input::quat(key0)?;
        let (a, b) = (view.unproject(x0, y0, size), view.unproject(x1, y1, size));
        let turn = DQuat::from_rotation_arc(a, b);
        let q = UnitQuat::try_new(turn * key.as_dquat()).map_err(js)?;
        self.set_point(curve, index, &q.to_wxyz())
    }

    /// Curve `curve` at the fraction `u` ∈ [0, 1] of its domain: an S³ curve gives its
    /// orientation `[w, x, y, z]` followed by the rotated body axes (9 numbers), another
    /// sphere the point.
    ///
    /// # Errors
    ///
    /// An [`InputError`] for a bad curve.
    pub fn eval(&self, curve: usize, u: f64) -> Result<Vec<f64>, JsError> {
        let c = self.curves.get(curve).ok_or(InputError::NoCurve(curve))?;
        let at = |[t0, t1]: [f64; 2]| t0 + (t1 - t0) * u.clamp(0.0, 1.0);
        Ok(match c {
            BuiltCurve::S2(b) => b
                .curve
                .eval(at(b.curve.domain()))
                .as_dvec3()
                .to_array()
                .to_vec(),
            BuiltCurve::Sn(b) => b.curve.eval(at(b.curve.domain())).coords().to_vec(),
            BuiltCurve::S3(b) => {
                let q = b.curve.eval(at(b.curve.domain()));
                let mut out = q.to_wxyz().to_vec();
                for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
                    out.extend(q.rotate(axis).to_array());
                }
                out
            }
        })
    }

    /// The scene's samples, as [`sample`].
    #[must_use]
    pub fn sample(&self, deriv: bool) -> String {
        self.scene.sample_json(&self.curves, deriv).to_string()
    }

    /// One field of curve `curve`'s samples, as [`sample_array`], from the curves already built.
    ///
    /// # Errors
    ///
    /// An [`InputError`] for an unknown field or curve.
    pub fn sample_array(&self, curve: usize, field: &str) -> Result<Vec<f64>, JsError> {
        field_of(&self.scene, &self.curves, curve, field).map_err(Into::into)
    }

    /// The continuity report, as [`continuity`].
    #[must_use]
    pub fn continuity(&self) -> String {
        continuity_json(&self.curves).to_string()
    }

    /// Renders the built curves into the handle's frame (`size` wide) without rebuilding.
    /// Returns the frame's height.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad view or size.
    pub fn render(&mut self, size: u32) -> Result<u32, JsError> {
        let pixmap = render_built(&self.scene, &self.curves, size).map_err(js)?;
        let h = pixmap.height();
        self.width = pixmap.width();
        self.rgba = straight_rgba(pixmap);
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
    fn view(&self) -> View {
        // The scene's view was checked when it was set.
        view_of(&self.scene, &self.curves).unwrap_or_else(|_| fallback_view())
    }

    /// Sphere coordinates of a point of ℝ³ in the scene's space (S¹ drops z).
    fn screen_coords(&self, p: DVec3) -> Vec<f64> {
        match self.scene.space {
            Space::Sn(1) => vec![p.x, p.y],
            _ => p.to_array().to_vec(),
        }
    }

    fn curve_doc(&self, curve: usize) -> Result<&Map<String, Value>, InputError> {
        match self.doc.get("curves") {
            Some(Value::Array(list)) => list
                .get(curve)
                .and_then(Value::as_object)
                .ok_or(InputError::NoCurve(curve)),
            _ if curve == 0 => Ok(&self.doc),
            _ => Err(InputError::NoCurve(curve)),
        }
    }

    fn edit_points(
        &mut self,
        curve: usize,
        edit: impl FnOnce(&mut Vec<Value>) -> Result<Option<PointEdit>, InputError>,
    ) -> Result<(), JsError> {
        let mut doc = self.doc.clone();
        let c = curve_doc_mut(&mut doc, curve)?;
        let (count, change) = match c.get_mut("points") {
            Some(Value::Array(points)) => (points.len(), edit(points)?),
            _ => return Err(InputError::NoCurve(curve).into()),
        };
        if let Some(change) = change {
            input::follow_points(c, count, change);
        }
        self.apply(doc)
    }

    /// Validates an edited document and rebuilds the curves whose description changed.
    ///
    /// A curve whose JSON is unchanged keeps its built curve and its parsed description (the
    /// document goes back through text, and `serde_json`'s default parser does not always read
    /// back the exact double it wrote, so re-parsing could move an untouched point by an ulp).
    fn apply(&mut self, doc: Map<String, Value>) -> Result<(), JsError> {
        let text = Value::Object(doc.clone()).to_string();
        let mut scene = Scene::from_json(&text).map_err(js)?;
        let same_space = scene.space == self.scene.space;
        let mut fresh: Vec<Option<BuiltCurve>> = Vec::with_capacity(scene.curves.len());
        for i in 0..scene.curves.len() {
            let unchanged = same_space
                && i < self.scene.curves.len()
                && curve_fields(&doc, i) == curve_fields(&self.doc, i);
            if unchanged {
                scene.curves[i] = self.scene.curves[i].clone();
                fresh.push(None);
            } else {
                fresh.push(Some(build_one(&scene, i).map_err(js)?));
            }
        }
        // The view's options do not depend on the curves (only its default camera does).
        View::from_json(
            scene.view.as_ref(),
            scene.space == Space::S3,
            None,
            scene.curves.len() > 1,
        )
        .map_err(js)?;
        let built = fresh.iter().filter(|c| c.is_some()).count();
        let mut old: Vec<Option<BuiltCurve>> = core::mem::take(&mut self.curves)
            .into_iter()
            .map(Some)
            .collect();
        // Every `None` in `fresh` is an unchanged curve, so `old` has it.
        let curves: Vec<BuiltCurve> = fresh
            .into_iter()
            .enumerate()
            .filter_map(|(i, c)| c.or_else(|| old.get_mut(i).and_then(Option::take)))
            .collect();
        self.builds = self
            .builds
            .saturating_add(u32::try_from(built).unwrap_or(u32::MAX));
        self.curves = curves;
        self.scene = scene;
        self.doc = doc;
        Ok(())
    }
}

/// A view for the case that cannot happen (every scene's view is checked when it is set).
fn fallback_view() -> View {
    View {
        camera: UnitQuat::IDENTITY,
        plot: spherekit_render::Plot::None,
        frames: 0,
        accuracy: spherekit_render::DEFAULT_ACCURACY,
        axes: vec![0, 1, 2],
    }
}

/// Builds curve `i` of `scene` alone, with the error message [`Scene::build`] would give.
fn build_one(scene: &Scene, i: usize) -> Result<BuiltCurve, SceneError> {
    let mut one = scene.clone();
    one.curves = scene.curves.get(i).cloned().into_iter().collect();
    let mut built = one.build().map_err(|e| match e {
        SceneError::InCurve { error, .. } => SceneError::InCurve { index: i, error },
        e => e,
    })?;
    built
        .pop()
        .ok_or_else(|| SceneError::Json("missing field `points`".into()))
}

/// Where each input point of a curve is drawn: the point (S², S¹) or the tips of the key's
/// rotated body axes (S³).
fn marker_positions(c: &BuiltCurve) -> Vec<Vec<DVec3>> {
    match c {
        BuiltCurve::S2(b) => b.inputs.iter().map(|p| vec![p.as_dvec3()]).collect(),
        BuiltCurve::Sn(b) => b
            .inputs
            .iter()
            .map(|p| vec![DVec3::new(p.coords()[0], p.coords()[1], 0.0)])
            .collect(),
        BuiltCurve::S3(b) => b
            .inputs
            .iter()
            .map(|q| [DVec3::X, DVec3::Y, DVec3::Z].map(|a| q.rotate(a)).to_vec())
            .collect(),
    }
}

fn parse_doc(text: &str) -> Result<Map<String, Value>, SceneError> {
    // Scene::from_json gives the CLI's message for text that is not a scene object.
    match serde_json::from_str(text) {
        Ok(Value::Object(m)) => Ok(m),
        _ => Err(Scene::from_json(text)
            .err()
            .unwrap_or_else(|| SceneError::Json("expected a JSON object".into()))),
    }
}

fn curve_doc_mut(
    doc: &mut Map<String, Value>,
    curve: usize,
) -> Result<&mut Map<String, Value>, InputError> {
    if doc.contains_key("curves") {
        return match doc.get_mut("curves") {
            Some(Value::Array(list)) => list
                .get_mut(curve)
                .and_then(Value::as_object_mut)
                .ok_or(InputError::NoCurve(curve)),
            _ => Err(InputError::NoCurve(curve)),
        };
    }
    if curve == 0 {
        Ok(doc)
    } else {
        Err(InputError::NoCurve(curve))
    }
}

/// The description of curve `i` in a document (the curve's own fields, wherever they sit).
fn curve_fields(doc: &Map<String, Value>, i: usize) -> Option<Map<String, Value>> {
    let c = match doc.get("curves") {
        Some(Value::Array(list)) => list.get(i)?.as_object()?,
        _ if i == 0 => doc,
        _ => return None,
    };
    Some(
        CURVE_FIELDS
            .iter()
            .filter_map(|k| c.get(*k).map(|v| ((*k).to_owned(), v.clone())))
            .collect(),
    )
}

/// The curve fields a single-curve scene keeps at the top level.
const CURVE_FIELDS: [&str; 6] = [
    "method",
    "points",
    "knots",
    "params",
    "canonicalize",
    "color",
];

/// Turns a single-curve document into a `curves` list and returns the list.
fn to_list(doc: &mut Map<String, Value>) -> Result<&mut Vec<Value>, InputError> {
    if !doc.contains_key("curves") {
        let mut one = Map::new();
        for k in CURVE_FIELDS {
            if let Some(v) = doc.remove(k) {
                one.insert(k.into(), v);
            }
        }
        doc.insert("curves".into(), Value::Array(vec![Value::Object(one)]));
    }
    match doc.get_mut("curves") {
        Some(Value::Array(list)) => Ok(list),
        _ => Err(InputError::NoCurve(0)),
    }
}

/// Delegates [`Curve`] to a boxed curve, for functions generic over sized curves.
#[derive(Debug)]
struct Dyn<'a, P: Manifold>(&'a dyn Curve<Point = P>);

impl<P: Manifold> Curve for Dyn<'_, P> {
    type Point = P;
    fn domain(&self) -> [f64; 2] {
        self.0.domain()
    }
    fn joints(&self) -> &[f64] {
        self.0.joints()
    }
    fn jet_at(&self, t: f64, side: Side) -> Jet<P> {
        self.0.jet_at(t, side)
    }
}
