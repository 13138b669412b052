// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Draws spherekit scenes into [`tiny_skia::Pixmap`]s: the shaded sphere with a 30° graticule,
//! curves on S² with their points and derived control points, rotation trajectories of the
//! body axes for curves on S³, and a strip plotting the (angular) speed against the parameter.
//!
//! The native `spherekit render` command, the golden-image tests and the browser playground
//! all call [`render`], so they draw the same pixels: all math runs in f64 through `libm`
//! until projection, and the rasterizer (a distance-based stroker of our own, drawing into the
//! pixmap's premultiplied RGBA) uses only f32 arithmetic and `sqrt`, which are identical on
//! native and wasm targets. There is no text in the images (fonts would make pixels depend on
//! the platform).
//!
//! # Example
//!
//! ```
//! use spherekit_scene::Scene;
//!
//! let scene = Scene::from_json(r#"{"space":"S2","method":"geodesic",
//!     "points":[[1,0,0],[0,1,0],[0,0,1]]}"#).unwrap();
//! let pixmap = spherekit_render::render(&scene, 128).unwrap();
//! assert_eq!((pixmap.width(), pixmap.height()), (128, 128));
//! ```

mod camera;
mod canvas;
mod flatten;
mod plot;
mod stroke;

use core::fmt;
use std::cell::RefCell;

use spherekit::glam::DVec3;
use spherekit::{Ambient, Curve, Manifold, S2Point, Side, SnPoint, UnitQuat};
use spherekit_scene::{Built, BuiltCurve, Plot, Scene, SceneError, View};
use tiny_skia::{Color, Pixmap, Rect};

pub use camera::{Camera, turn_towards, yaw_pitch};
use canvas::{Canvas, LineStyle, Rgb, Shape};

/// The smallest and largest image sizes [`render`] accepts (pixels, the sphere's square).
pub const SIZE_RANGE: (u32, u32) = (16, 4096);

/// The colour-blind-safe palette (Okabe–Ito) curves take in order unless a scene gives one.
pub const PALETTE: [[u8; 3]; 7] = [
    [0x00, 0x72, 0xb2], // blue
    [0xd5, 0x5e, 0x00], // vermillion
    [0x00, 0x9e, 0x73], // bluish green
    [0xcc, 0x79, 0xa7], // reddish purple
    [0xe6, 0x9f, 0x00], // orange
    [0x56, 0xb4, 0xe9], // sky blue
    [0x00, 0x00, 0x00], // black
];

/// The colours of the body x, y and z axes in the rotation-trajectory pictures of a single
/// S³ curve (vermillion, bluish green, blue).
pub const AXIS_COLORS: [[u8; 3]; 3] = [[0xd5, 0x5e, 0x00], [0x00, 0x9e, 0x73], [0x00, 0x72, 0xb2]];

const POINT_COLOR: Rgb = [0x1f, 0x23, 0x28];
const GRATICULE: Rgb = [0x7d, 0x8a, 0x99];

/// Why a scene could not be drawn.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum RenderError {
    /// The scene itself is bad.
    Scene(SceneError),
    /// The requested size is outside [`SIZE_RANGE`].
    Size(u32),
    /// The scene's sphere cannot be drawn.
    Space(String),
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Scene(e) => write!(f, "{e}"),
            Self::Size(s) => write!(
                f,
                "size: {s} is outside {}..={} pixels",
                SIZE_RANGE.0, SIZE_RANGE.1
            ),
            Self::Space(s) => write!(
                f,
                "space: {s} scenes cannot be drawn (rendering shows S1, S2 and S3 scenes)"
            ),
        }
    }
}

impl core::error::Error for RenderError {}

impl From<SceneError> for RenderError {
    fn from(e: SceneError) -> Self {
        Self::Scene(e)
    }
}

/// Builds the scene's curves and draws them on a `size`-pixel square sphere view, with the
/// plot strip (a quarter of `size` high) below it when the view asks for one.
///
/// # Errors
///
/// [`RenderError`] for a bad scene, view or size.
pub fn render(scene: &Scene, size: u32) -> Result<Pixmap, RenderError> {
    let curves = scene.build()?;
    render_built(scene, &curves, size)
}

/// Draws curves already built from `scene` (so an interactive caller can rebuild only what
/// changed).
///
/// # Errors
///
/// [`RenderError`] for a bad view or size, or a sphere that cannot be drawn.
pub fn render_built(
    scene: &Scene,
    curves: &[BuiltCurve],
    size: u32,
) -> Result<Pixmap, RenderError> {
    if !(SIZE_RANGE.0..=SIZE_RANGE.1).contains(&size) {
        return Err(RenderError::Size(size));
    }
    if !scene.space.drawable() {
        return Err(RenderError::Space(scene.space.name()));
    }
    let view = scene.view()?;
    let camera = Camera::of(&view, curves);
    let strip = if view.plot == Plot::Speed {
        size / 4
    } else {
        0
    };
    let axes = camera.axes();
    let mut pixmap = backdrop(size, strip, axes).ok_or(RenderError::Size(size))?;
    let mut canvas = Canvas::new(size, axes);
    let single = curves.len() == 1;
    let mut series = Vec::new();
    for (i, (spec, curve)) in scene.curves.iter().zip(curves).enumerate() {
        let color = spec.color.unwrap_or(PALETTE[i % PALETTE.len()]);
        let polygon = !spec.method.interpolates;
        let s = match curve {
            BuiltCurve::S2(b) => {
                draw_points(&mut canvas, b, color, polygon, &view, &|p: &S2Point| {
                    p.as_dvec3()
                });
                speed_series(&*b.curve, 1.0, color, size)
            }
            BuiltCurve::Sn(b) => {
                let embed = |p: &SnPoint| DVec3::new(p.coords()[0], p.coords()[1], 0.0);
                draw_points(&mut canvas, b, color, polygon, &view, &embed);
                speed_series(&*b.curve, 1.0, color, size)
            }
            BuiltCurve::S3(b) => {
                draw_rotations(&mut canvas, b, color, single, &view);
                // |ω| = 2|q′| (the half-angle factor).
                speed_series(&*b.curve, 2.0, color, size)
            }
        };
        series.push(s);
    }
    stroke::Strokes::with(pixmap.width(), pixmap.height(), |strokes| {
        canvas.draw(&mut pixmap, strokes);
        if let Some(area) = plot_area(size, strip) {
            plot::draw(&mut pixmap, strokes, area, canvas.scale, &series);
        }
    });
    Ok(pixmap)
}

/// The camera [`render_built`] draws `curves` of `scene` with (its default depends on the
/// points), so that an interactive caller can project and pick what it shows.
///
/// # Errors
///
/// [`RenderError::Scene`] for a bad `view`.
pub fn camera_of(scene: &Scene, curves: &[BuiltCurve]) -> Result<Camera, RenderError> {
    Ok(Camera::of(&scene.view()?, curves))
}

/// Where the plot strip goes in a frame of `size` with a strip `strip` pixels high, if any.
fn plot_area(size: u32, strip: u32) -> Option<Rect> {
    if strip == 0 {
        return None;
    }
    let s = f64::from(size);
    #[expect(clippy::cast_possible_truncation, reason = "pixels")]
    let (x, w) = ((0.04 * s) as f32, (0.92 * s) as f32);
    #[expect(clippy::cast_precision_loss, reason = "pixel sizes")]
    let (y, h) = (size as f32 - 0.02 * size as f32, strip as f32 * 0.92);
    Rect::from_xywh(x, y, w, h)
}

/// The white page with the shaded sphere, its graticule and the plot strip's frame for one
/// size and camera: the part of a frame that does not depend on the curves. The last one drawn is kept (per thread), so
/// that redrawing after an edit that leaves the camera alone, such as dragging a point in the
/// playground, starts from a copy. A copy and a fresh drawing are the same pixels.
fn backdrop(size: u32, strip: u32, axes: [DVec3; 3]) -> Option<Pixmap> {
    type Key = (u32, u32, [DVec3; 3]);
    thread_local! {
        static LAST: RefCell<Option<(Key, Pixmap)>> = const { RefCell::new(None) };
    }
    let key = (size, strip, axes);
    LAST.with_borrow_mut(|last| {
        if let Some((k, pixmap)) = last.as_ref()
            && *k == key
        {
            return Some(pixmap.clone());
        }
        let mut pixmap = Pixmap::new(size, size + strip)?;
        pixmap.fill(Color::WHITE);
        let mut canvas = Canvas::new(size, axes);
        graticule(&mut canvas);
        canvas.draw_backdrop(&mut pixmap);
        if let Some(area) = plot_area(size, strip) {
            plot::draw_frame(&mut pixmap, area, canvas.scale);
        }
        *last = Some((key, pixmap.clone()));
        Some(pixmap)
    })
}

fn graticule(canvas: &mut Canvas) {
    let style = LineStyle {
        color: GRATICULE,
        width: 0.7,
        alpha: 0.5,
        back_alpha: 0.0,
        back_dashed: false,
    };
    for k in 0..6 {
        let a = f64::from(k) * std::f64::consts::PI / 6.0;
        let u = DVec3::new(libm::cos(a), libm::sin(a), 0.0);
        canvas.polyline(&flatten::circle(DVec3::ZERO, u, DVec3::Z, 1.0), style);
    }
    for lat in [-60.0_f64, -30.0, 0.0, 30.0, 60.0] {
        let l = lat.to_radians();
        let c = DVec3::new(0.0, 0.0, libm::sin(l));
        canvas.polyline(&flatten::circle(c, DVec3::X, DVec3::Y, libm::cos(l)), style);
    }
}

fn curve_style(color: Rgb) -> LineStyle {
    LineStyle {
        color,
        width: 2.4,
        alpha: 1.0,
        back_alpha: 0.45,
        back_dashed: true,
    }
}

fn polygon_style(color: Rgb) -> LineStyle {
    LineStyle {
        color,
        width: 0.9,
        alpha: 0.7,
        back_alpha: 0.25,
        back_dashed: true,
    }
}

fn arcs(canvas: &mut Canvas, pts: &[DVec3], style: LineStyle) {
    for w in pts.windows(2) {
        if (w[0] + w[1]).length() > 1e-9 {
            canvas.polyline(&flatten::great_arc(w[0], w[1]), style);
        }
    }
}

/// A curve on S² (or S¹ on the equator): the curve, its points, derived points and polygons.
fn draw_points<P: Manifold>(
    canvas: &mut Canvas,
    b: &Built<P>,
    color: Rgb,
    polygon: bool,
    view: &View,
    embed: &dyn Fn(&P) -> DVec3,
) {
    let f = |ts: &[f64], out: &mut [DVec3]| {
        let mut ps = vec![b.curve.eval(ts[0]); ts.len()];
        b.curve.eval_many(ts, &mut ps);
        for (o, p) in out.iter_mut().zip(&ps) {
            *o = embed(p);
        }
    };
    let pts = flatten::flatten(&f, b.curve.joints(), 8, view.accuracy);
    let input: Vec<DVec3> = b.inputs.iter().map(embed).collect();
    let controls: Vec<DVec3> = b.controls.iter().map(embed).collect();
    let aux: Vec<DVec3> = b.auxiliary.iter().map(embed).collect();
    if polygon {
        arcs(canvas, &input, polygon_style(POINT_COLOR));
    }
    arcs(canvas, &controls, polygon_style(color));
    arcs(canvas, &aux, polygon_style(color));
    canvas.polyline(&pts, curve_style(color));
    for p in &controls {
        canvas.marker(*p, Shape::Square, color, 6.0);
    }
    for p in &aux {
        canvas.marker(*p, Shape::Diamond, color, 7.0);
    }
    for p in &input {
        canvas.marker(*p, Shape::Dot, POINT_COLOR, 8.0);
    }
}

/// A curve on S³ as the trajectories of the tips of its rotated body axes.
fn draw_rotations(canvas: &mut Canvas, b: &Built<UnitQuat>, color: Rgb, single: bool, view: &View) {
    for &k in &view.axes {
        let axis = [DVec3::X, DVec3::Y, DVec3::Z][k];
        let c = if single { AXIS_COLORS[k] } else { color };
        let f = |ts: &[f64], out: &mut [DVec3]| {
            let mut qs = vec![UnitQuat::IDENTITY; ts.len()];
            b.curve.eval_many(ts, &mut qs);
            for (o, q) in out.iter_mut().zip(&qs) {
                *o = q.rotate(axis);
            }
        };
        let pts = flatten::flatten(&f, b.curve.joints(), 8, view.accuracy);
        canvas.polyline(&pts, curve_style(c));
        for q in &b.controls {
            canvas.marker(q.rotate(axis), Shape::Square, c, 5.0);
        }
        for q in &b.inputs {
            canvas.marker(q.rotate(axis), Shape::Dot, c, 8.0);
        }
    }
    if view.frames > 0 {
        let [t0, t1] = b.curve.domain();
        let diagonal = DVec3::ONE.normalize();
        for i in 0..view.frames {
            #[expect(clippy::cast_precision_loss, reason = "few frames")]
            let u = if view.frames == 1 {
                0.5
            } else {
                i as f64 / (view.frames - 1) as f64
            };
            let q = b.curve.eval(t0 + (t1 - t0) * u);
            let base = q.rotate(diagonal);
            for (k, axis) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
                let tip = base + q.rotate(axis) * 0.14;
                let style = LineStyle {
                    color: AXIS_COLORS[k],
                    width: 1.6,
                    alpha: 1.0,
                    back_alpha: 0.3,
                    back_dashed: false,
                };
                canvas.polyline(&[base, tip], style);
            }
        }
    }
}

/// Samples the speed of one curve for the plot, piece by piece, with one-sided values at the
/// joints, against its parameter mapped to [0, 1].
fn speed_series<P: Manifold>(
    curve: &dyn Curve<Point = P>,
    factor: f64,
    color: Rgb,
    size: u32,
) -> plot::SpeedSeries {
    let joints = curve.joints();
    let [t0, t1] = [joints[0], joints[joints.len() - 1]];
    // The strip shows every curve over its whole domain, mapped to [0, 1].
    let unit = |t: f64| (t - t0) / (t1 - t0);
    let total = f64::from(size).max(64.0);
    let finite = |v: f64| if v.is_finite() { v } else { 0.0 };
    let pieces = joints
        .windows(2)
        .map(|w| {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "small positive count"
            )]
            let n = ((w[1] - w[0]) / (t1 - t0) * total)
                .ceil()
                .clamp(2.0, 4096.0) as usize;
            // Right-sided jets in one batch, then the piece's end from the left.
            let ts: Vec<f64> = (0..n)
                .map(|i| {
                    #[expect(clippy::cast_precision_loss, reason = "small counts")]
                    let t = w[0] + (w[1] - w[0]) * (i as f64 / n as f64);
                    t
                })
                .collect();
            let mut jets = vec![curve.jet(w[0]); n];
            curve.jet_many(&ts, &mut jets);
            let end = factor * curve.jet_at(w[1], Side::Left).velocity.length();
            ts.iter()
                .zip(&jets)
                .map(|(&t, j)| (unit(t), finite(factor * j.velocity.length())))
                .chain(core::iter::once((unit(w[1]), finite(end))))
                .collect()
        })
        .collect();
    plot::SpeedSeries {
        color,
        pieces,
        joints: joints.iter().map(|&t| unit(t)).collect(),
    }
}
