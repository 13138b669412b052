// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Draws spherekit scenes into [`tiny_skia::Pixmap`]s (and the same pictures as SVG,
//! [`render_svg`]): the shaded sphere with a 30° graticule, curves on S² with their points and
//! derived control points, rotation trajectories of the body axes for curves on S³, strips
//! plotting the (angular) speed, or the velocity components, against the parameter with
//! labelled axes, a legend and an optional title.
//!
//! The native `spherekit render` command, the golden-image tests and the browser playground
//! all call [`render`], so they draw the same pixels: all math runs in f64 through `libm`
//! until projection, and the rasterizer (a distance-based stroker of our own, drawing into the
//! pixmap's premultiplied RGBA) uses only f32 arithmetic and `sqrt`, which are identical on
//! native and wasm targets. Text is drawn from an embedded subset of DejaVu Sans (see
//! `fonts/LICENSE-DejaVu`) by a rasterizer of the same kind (`text.rs`), never from system
//! fonts, so it is the same bytes everywhere too.
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
mod drawing;
mod flatten;
mod legend;
mod plot;
#[cfg(feature = "png")]
pub mod png;
mod stroke;
mod surface;
mod text;

use core::fmt;

use spherekit::glam::DVec3;
use spherekit::{
    Ambient, Curve, Jet, Manifold, S2Point, Side, SmPoint, UnitQuat, angular_velocity_acceleration,
    angular_velocity_acceleration_body,
};
use spherekit_scene::{Built, BuiltCurve, Plot, PlotTime, Scene, SceneError, Space, View};
use tiny_skia::{Color, Pixmap, Rect};

pub use camera::{Camera, turn_towards, yaw_pitch};
use canvas::{Canvas, LineStyle, Rgb, Shape, Sketch};
pub use drawing::Drawing;
use stroke::Strokes;
use surface::{Raster, Surface, Svg};
use text::Glyphs;

/// The smallest and largest image sizes [`render`] accepts (pixels, the sphere's square).
pub const SIZE_RANGE: (u32, u32) = (16, 4096);

/// The colours curves take in order unless a scene gives one. They keep clear of the hues of
/// [`AXIS_COLORS`] (red, green and blue stand for the body x, y and z axes and ω's x, y and z
/// components): wine, ochre, purple, grey, indigo and black (from Paul Tol's muted and
/// high-contrast schemes, readable with the common colour-vision deficiencies).
pub const PALETTE: [[u8; 3]; 6] = [
    [0x88, 0x22, 0x55], // wine
    [0xa6, 0x7c, 0x00], // ochre
    [0xaa, 0x44, 0x99], // purple
    [0x5f, 0x6b, 0x7a], // grey
    [0x33, 0x22, 0x88], // indigo
    [0x00, 0x00, 0x00], // black
];

/// The colours of the body x, y and z axes, and of ω's x, y and z components for one curve:
/// the conventional red, green and blue, as Okabe and Ito's colour-blind-safe vermillion,
/// bluish green and blue.
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
    /// A [`Drawing`] without curves, or with curves on different spheres.
    Drawing(String),
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
            Self::Drawing(s) => f.write_str(s),
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
    render_figure(scene, curves, size).map(|(pixmap, _)| pixmap)
}

/// Where a plot strip's axes are in a frame: the box of the plotted values, in pixels of the
/// frame, with the time at its left and right edges (so that an interactive caller can put a
/// cursor on the time axis, or read a time from a pointer).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlotAxes {
    /// The left edge (pixels), where the time is `time[0]`.
    pub left: f32,
    /// The top edge (pixels).
    pub top: f32,
    /// The right edge (pixels), where the time is `time[1]`.
    pub right: f32,
    /// The bottom edge (pixels).
    pub bottom: f32,
    /// The time (the curves' t, or u with `view.plot_time` `"normalized"`) at the left and
    /// right edges.
    pub time: [f64; 2],
}

/// As [`render_built`], and where the frame's plot strips put their axes (top to bottom).
///
/// # Errors
///
/// As [`render_built`].
pub fn render_figure(
    scene: &Scene,
    curves: &[BuiltCurve],
    size: u32,
) -> Result<(Pixmap, Vec<PlotAxes>), RenderError> {
    prepare(scene, curves, size)?.render(scene, curves)
}

/// The same picture as [`render`] as an SVG document: vector strokes, the sphere as a radial
/// gradient, the legend, axes and title as `<text>` (in DejaVu Sans, the font the PNG's text
/// is drawn with, when the viewer has it).
///
/// # Errors
///
/// [`RenderError`] for a bad scene, view or size.
pub fn render_svg(scene: &Scene, size: u32) -> Result<String, RenderError> {
    let curves = scene.build()?;
    svg_of(&Layers::of_scene(scene, &curves), size)
}

/// The SVG document of a figure's layers.
fn svg_of(layers: &Layers<'_>, size: u32) -> Result<String, RenderError> {
    let prepared = Prepared::new(layers, size, 0.0)?;
    let figure = Figure::new(&prepared, layers);
    let mut svg = Svg::new(size, figure.height);
    let frames: Vec<Rect> = prepared.panels.iter().map(|(r, _)| *r).collect();
    draw_backdrop(&mut svg, size, figure.axes, &frames);
    figure.draw(&mut svg);
    Ok(svg.finish())
}

/// The camera [`render_built`] draws `curves` of `scene` with (its default depends on the
/// points), so that an interactive caller can project and pick what it shows.
#[must_use]
pub fn camera_of(scene: &Scene, curves: &[BuiltCurve]) -> Camera {
    Camera::of(scene.view(), curves)
}

/// A scene's figure laid out at one size, everything of it that does not depend on the
/// camera: the marks on the sphere before projection (flattened curves, points, polygons,
/// frames) and the plot strips. [`Prepared::render`] projects it for the scene's camera, so an
/// interactive caller turning the view lays the figure out once ([`prepare`]) and renders it
/// for each new camera without flattening the curves or sampling the plots again; the pixels
/// are those of [`render_figure`].
pub struct Prepared {
    size: u32,
    /// Pixels per pixel-at-512 of the text, the plots' and the legend's marks (at least the
    /// sphere's scale; more with a text floor, see [`prepare_with_text`]).
    text: f32,
    /// The height of one plot strip.
    strip: u32,
    sketch: Sketch,
    panels: Vec<(Rect, plot::Panel)>,
    time: [f64; 2],
    single: bool,
}

impl fmt::Debug for Prepared {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Prepared")
            .field("size", &self.size)
            .field("plots", &self.panels.len())
            .field("time", &self.time)
            .finish_non_exhaustive()
    }
}

/// Lays out the figure of `curves` (built from `scene`) at `size` for any camera (see
/// [`Prepared`]).
///
/// # Errors
///
/// [`RenderError`] for a bad view or size, or a sphere that cannot be drawn.
pub fn prepare(scene: &Scene, curves: &[BuiltCurve], size: u32) -> Result<Prepared, RenderError> {
    Prepared::new(&Layers::of_scene(scene, curves), size, 0.0)
}

/// As [`prepare`], with text of at least `min_text` pixels per em: the plots' and the
/// legend's text, marks and spacing grow together (the strips up to half as tall again), so
/// that a small figure on a screen stays readable; the sphere keeps its size. With a floor
/// below the figure's own text size the figure is that of [`prepare`].
///
/// # Errors
///
/// As [`prepare`].
pub fn prepare_with_text(
    scene: &Scene,
    curves: &[BuiltCurve],
    size: u32,
    min_text: f32,
) -> Result<Prepared, RenderError> {
    Prepared::new(&Layers::of_scene(scene, curves), size, min_text)
}

/// What a figure draws, from a scene or from a [`Drawing`]: the sphere, the view options, the
/// built curves and how each is drawn.
struct Layers<'a> {
    space: Space,
    view: &'a View,
    curves: &'a [BuiltCurve],
    styles: Vec<Style<'a>>,
}

/// How one curve is drawn: its colour (default: the palette's by position), its name in the
/// legend, and whether its points are joined by a polygon (for curves that do not pass
/// through them).
#[derive(Clone, Debug)]
struct Style<'a> {
    color: Option<Rgb>,
    label: &'a str,
    polygon: bool,
}

impl<'a> Layers<'a> {
    fn of_scene(scene: &'a Scene, curves: &'a [BuiltCurve]) -> Self {
        Self {
            space: scene.space,
            view: scene.view(),
            curves,
            styles: scene
                .curves
                .iter()
                .map(|spec| Style {
                    color: spec.color,
                    label: spec.label.as_deref().unwrap_or(spec.method.name),
                    polygon: !spec.method.interpolates,
                })
                .collect(),
        }
    }

    fn color(&self, i: usize) -> Rgb {
        self.styles[i].color.unwrap_or(PALETTE[i % PALETTE.len()])
    }
}

impl Prepared {
    fn new(layers: &Layers<'_>, size: u32, min_text: f32) -> Result<Self, RenderError> {
        if !(SIZE_RANGE.0..=SIZE_RANGE.1).contains(&size) {
            return Err(RenderError::Size(size));
        }
        if !layers.space.drawable() {
            return Err(RenderError::Space(layers.space.name()));
        }
        let (view, curves) = (layers.view, layers.curves);
        let mut sketch = Sketch::default();
        let single = curves.len() == 1;
        let normalized = view.plot_time == PlotTime::Normalized;
        let omega = view.plot == Plot::Omega;
        let mut speeds = Vec::new();
        let mut components = Vec::new();
        let mut residuals = Vec::new();
        for (i, (style, curve)) in layers.styles.iter().zip(curves).enumerate() {
            let color = layers.color(i);
            let key = key_marker(i, single, color);
            let polygon = style.polygon;
            let sampled = match curve {
                BuiltCurve::S2(b) => {
                    draw_points(&mut sketch, b, color, key, polygon, view, &|p: &S2Point| {
                        p.as_dvec3()
                    });
                    residuals.extend(residual_series(b, color, normalized));
                    sample(&*b.curve, size, normalized, &|j| {
                        let v = j.velocity;
                        [v.length(), v.x, v.y, v.z]
                    })
                }
                BuiltCurve::Sm(b) => {
                    let embed = |p: &SmPoint| DVec3::new(p.coords()[0], p.coords()[1], 0.0);
                    draw_points(&mut sketch, b, color, key, polygon, view, &embed);
                    residuals.extend(residual_series(b, color, normalized));
                    sample(&*b.curve, size, normalized, &|j| {
                        [j.velocity.length(), 0.0, 0.0, 0.0]
                    })
                }
                BuiltCurve::S3(b) => {
                    draw_rotations(&mut sketch, b, color, key, single, view);
                    residuals.extend(residual_series(b, color, normalized));
                    // |ω| = 2|q′| (the half-angle factor); ω in the space or the body frame.
                    let body = view.omega_body;
                    sample(&*b.curve, size, normalized, &|j| {
                        let w = if body {
                            angular_velocity_acceleration_body(j.point, j.velocity, j.acceleration)
                                .0
                        } else {
                            angular_velocity_acceleration(j.point, j.velocity, j.acceleration).0
                        };
                        [2.0 * j.velocity.length(), w.x, w.y, w.z]
                    })
                }
            };
            speeds.push(sampled.series(0, color, None, true));
            for k in 0..3 {
                let (c, dash) = if single {
                    (AXIS_COLORS[k], None)
                } else {
                    (color, COMPONENT_DASHES[k])
                };
                components.push(sampled.series(k + 1, c, dash, k == 0));
            }
        }
        sketch.markers_last();
        let s3 = layers.space == Space::S3;
        let mut panels_content = Vec::new();
        if view.plot != Plot::None {
            panels_content.push(plot::Panel {
                quantity: speed_label(s3, normalized),
                time: if normalized { "u" } else { "t" },
                signed: false,
                series: speeds,
            });
        }
        if omega {
            panels_content.push(plot::Panel {
                quantity: component_label(s3, view.omega_body, normalized),
                time: if normalized { "u" } else { "t" },
                signed: true,
                series: components,
            });
        }
        if view.plot != Plot::None && !residuals.is_empty() {
            panels_content.push(plot::Panel {
                quantity: residual_label(s3),
                time: if normalized { "u" } else { "t" },
                signed: false,
                series: residuals,
            });
        }
        let time = if normalized {
            [0.0, 1.0]
        } else {
            curves
                .iter()
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[a, b], c| {
                    let [t0, t1] = c.domain();
                    [a.min(t0), b.max(t1)]
                })
        };
        let scale = canvas::scale_of(size);
        let text = scale.max(min_text / plot::LABEL_EM);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            clippy::cast_precision_loss,
            reason = "pixel sizes"
        )]
        let strip = (strip_height(size) as f32 * (text / scale).min(1.5)).round() as u32;
        let panels: Vec<(Rect, plot::Panel)> = panels_content
            .into_iter()
            .enumerate()
            .filter_map(|(i, p)| {
                let top = size + u32::try_from(i).unwrap_or(0) * strip;
                plot_area(size, top, strip).map(|r| (r, p))
            })
            .collect();
        Ok(Self {
            size,
            text,
            strip,
            sketch,
            panels,
            time,
            single,
        })
    }
}

impl Prepared {
    /// Renders the figure for the camera of `scene`, as [`render_figure`] does. `scene` and
    /// `curves` must be the ones the figure was prepared from, except for `view.camera`.
    ///
    /// # Errors
    ///
    /// [`RenderError::Scene`] for a bad view.
    pub fn render(
        &self,
        scene: &Scene,
        curves: &[BuiltCurve],
    ) -> Result<(Pixmap, Vec<PlotAxes>), RenderError> {
        self.render_with(scene, curves, &mut RenderCache::default())
    }

    /// [`render`](Self::render) with what the last frames left in `cache` (the backdrop of
    /// the same size and camera, the stroker's buffer, the glyph bitmaps): the same pixels,
    /// faster for an interactive caller, which keeps the cache between frames and drops it to
    /// free the memory.
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render).
    pub fn render_with(
        &self,
        scene: &Scene,
        curves: &[BuiltCurve],
        cache: &mut RenderCache,
    ) -> Result<(Pixmap, Vec<PlotAxes>), RenderError> {
        self.render_layers(&Layers::of_scene(scene, curves), cache)
    }

    fn render_layers(
        &self,
        layers: &Layers<'_>,
        cache: &mut RenderCache,
    ) -> Result<(Pixmap, Vec<PlotAxes>), RenderError> {
        let figure = Figure::new(self, layers);
        let size = self.size;
        let frames: Vec<Rect> = self.panels.iter().map(|(r, _)| *r).collect();
        let mut pixmap = cache
            .backdrop(size, figure.height, figure.axes, &frames)
            .ok_or(RenderError::Size(size))?;
        let RenderCache {
            strokes, glyphs, ..
        } = cache;
        let boxes = Strokes::with(strokes, pixmap.width(), pixmap.height(), |strokes| {
            let mut raster = Raster {
                pixmap: &mut pixmap,
                strokes,
                glyphs,
            };
            figure.draw(&mut raster)
        });
        let plots = boxes
            .into_iter()
            .map(|[left, top, right, bottom]| PlotAxes {
                left,
                top,
                right,
                bottom,
                time: self.time,
            })
            .collect();
        Ok((pixmap, plots))
    }
}

/// A prepared figure seen by one camera: the projected marks, the legend and the title.
struct Figure<'a> {
    prepared: &'a Prepared,
    height: u32,
    axes: [DVec3; 3],
    scale: f32,
    canvas: Canvas,
    legend: Vec<legend::Entry>,
    legend_top: f32,
    title: Option<String>,
}

/// The height of one plot strip for a `size` sphere.
fn strip_height(size: u32) -> u32 {
    size * 3 / 10
}

impl<'a> Figure<'a> {
    fn new(prepared: &'a Prepared, layers: &Layers<'_>) -> Self {
        let view = layers.view;
        let size = prepared.size;
        let axes = Camera::of(view, layers.curves).axes();
        let canvas = prepared.sketch.project(size, axes);
        let scale = prepared.text;
        let panels = &prepared.panels;
        let strip = prepared.strip;
        let legend = if view.legend {
            legend_entries(layers, &canvas, prepared.single, !panels.is_empty())
        } else {
            Vec::new()
        };
        let plots = u32::try_from(panels.len()).unwrap_or(0) * strip;
        let legend_h = legend::height(&legend, size, scale);
        #[expect(clippy::cast_precision_loss, reason = "pixel sizes")]
        let legend_top = if plots > 0 {
            (size + plots) as f32
        } else {
            size as f32 * 0.985
        };
        Self {
            prepared,
            height: size + plots + legend_h,
            axes,
            scale,
            canvas,
            legend,
            legend_top,
            title: view.title.clone(),
        }
    }

    /// Draws the figure over its backdrop; returns the plots' axes boxes (see [`PlotAxes`]).
    fn draw(&self, surface: &mut dyn Surface) -> Vec<[f32; 4]> {
        self.canvas.draw(surface);
        let prepared = self.prepared;
        let boxes = prepared
            .panels
            .iter()
            .filter_map(|(area, panel)| {
                plot::draw(surface, *area, self.scale, panel, prepared.time)
            })
            .collect();
        legend::draw(
            surface,
            &self.legend,
            self.legend_top,
            prepared.size,
            self.scale,
        );
        if let Some(title) = &self.title {
            #[expect(clippy::cast_precision_loss, reason = "pixel sizes")]
            let s = prepared.size as f32;
            let mut px = (17.0 * self.scale).max(9.0);
            let w = text::width(title, px);
            if w > 0.96 * s {
                px *= 0.96 * s / w;
            }
            let baseline = 0.025 * s + 0.5 * text::CAP_HEIGHT * px;
            surface.text(
                0.5 * s,
                baseline,
                title,
                px,
                POINT_COLOR,
                surface::Anchor::Middle,
            );
        }
        boxes
    }
}

/// The dash patterns of the y and z components when several curves share the component plot
/// (x is solid).
const COMPONENT_DASHES: [Option<[f32; 2]>; 3] = [None, Some([7.0, 3.0]), Some([2.0, 2.5])];

fn speed_label(s3: bool, normalized: bool) -> String {
    let unit = if normalized {
        "rad per unit u, u = t normalized per curve"
    } else {
        "rad per unit t"
    };
    if s3 {
        format!("angular speed |ω| ({unit})")
    } else {
        format!("speed |p′| ({unit})")
    }
}

/// The residual plot's title: the angle (on S³ the rotation angle) from each sample to the
/// curve.
fn residual_label(s3: bool) -> String {
    let kind = if s3 {
        "rotation residual"
    } else {
        "residual angle"
    };
    format!("{kind} per sample (degrees, dashed: rms)")
}

fn component_label(s3: bool, body: bool, normalized: bool) -> String {
    let unit = if normalized { "u" } else { "t" };
    let frame = if body { "body" } else { "space" };
    if s3 {
        format!("angular velocity ω, {frame} frame (rad per unit {unit})")
    } else {
        format!("velocity p′ in x, y, z (per unit {unit})")
    }
}

/// The legend: the curves (or, for one S³ curve, its traced body axes), the triads, the
/// velocity components, and the kinds of marks in the picture.
fn legend_entries(
    layers: &Layers<'_>,
    canvas: &Canvas,
    single: bool,
    plotted: bool,
) -> Vec<legend::Entry> {
    use legend::{Entry, Swatch};
    let entry = |swatch, label: &str, group| Entry {
        swatch,
        label: label.to_owned(),
        group,
    };
    let (view, s3) = (layers.view, layers.space == Space::S3);
    let name = |i: usize| layers.styles[i].label;
    let axis = ["x", "y", "z"];
    let mut out = Vec::new();
    if s3 && single {
        out.push(entry(Swatch::None, &format!("{}:", name(0)), 0));
        for &k in &view.axes {
            out.push(entry(
                Swatch::Line(AXIS_COLORS[k], None, 1.0),
                &format!("body {} axis", axis[k]),
                0,
            ));
        }
    } else {
        for i in 0..layers.styles.len() {
            out.push(entry(Swatch::Line(layers.color(i), None, 1.0), name(i), 0));
        }
        if s3 {
            let traced: Vec<&str> = view.axes.iter().map(|&k| axis[k]).collect();
            out.push(entry(
                Swatch::None,
                &format!("(traced: tip of body {})", traced.join(", ")),
                0,
            ));
        }
    }
    // (One curve's triads are in the body axes' colours, already in the legend.)
    if s3 && view.frames > 0 && !single {
        for (k, a) in axis.iter().enumerate() {
            out.push(entry(
                Swatch::Line(AXIS_COLORS[k], None, 1.0),
                &format!("triad {a}"),
                1,
            ));
        }
    }
    if view.plot == Plot::Omega {
        let symbol = if s3 { "ω" } else { "p′" };
        for (k, a) in axis.iter().enumerate() {
            let swatch = if single {
                Swatch::Line(AXIS_COLORS[k], None, 1.0)
            } else {
                Swatch::Line(POINT_COLOR, COMPONENT_DASHES[k], 1.0)
            };
            out.push(entry(swatch, &format!("{symbol} {a}"), 2));
        }
    }
    let kinds = canvas.kinds();
    let mark = POINT_COLOR;
    if kinds.dot {
        // With a curve through the samples beside a fitted one, keys are of both kinds.
        let fitted = layers.curves.iter().all(|c| c.fit_report().is_some());
        let key = if fitted { "key (fitted)" } else { "key" };
        out.push(entry(Swatch::Marker(Shape::Dot, mark), key, 3));
    }
    if kinds.sample {
        out.push(entry(
            Swatch::Marker(Shape::Sample, mark),
            "sample (fitted to)",
            3,
        ));
    }
    if kinds.square {
        out.push(entry(
            Swatch::Marker(Shape::Square, mark),
            "control point",
            3,
        ));
    }
    if kinds.diamond {
        out.push(entry(
            Swatch::Marker(Shape::Diamond, mark),
            "derived point",
            3,
        ));
    }
    if kinds.far_dashed {
        out.push(entry(
            Swatch::Line(mark, Some([5.0, 4.0]), 0.6),
            "far side",
            3,
        ));
    }
    if plotted {
        out.push(entry(Swatch::Tick(mark), "joint", 3));
    }
    out
}

/// Where the plot strip starting at row `top` (pixels) of a frame of `size` goes.
fn plot_area(size: u32, top: u32, strip: u32) -> Option<Rect> {
    let s = f64::from(size);
    #[expect(clippy::cast_possible_truncation, reason = "pixels")]
    let (x, w) = ((0.04 * s) as f32, (0.92 * s) as f32);
    #[expect(clippy::cast_precision_loss, reason = "pixel sizes")]
    let (y, h) = (top as f32 - 0.02 * size as f32, strip as f32 * 0.92);
    Rect::from_xywh(x, y, w, h)
}

/// What the rasterizer keeps from one frame for the next, owned by the caller
/// ([`Prepared::render_with`]); dropping it frees the memory (the backdrop alone is a frame's
/// pixels).
#[derive(Default)]
pub struct RenderCache {
    /// The last backdrop drawn, by size, height, camera axes and plot frames.
    backdrop: Option<(BackdropKey, Pixmap)>,
    /// The stroker's coverage buffer of the last frame's size.
    strokes: Option<Strokes>,
    glyphs: Glyphs,
}

type BackdropKey = (u32, u32, [DVec3; 3], Vec<[u32; 4]>);

impl fmt::Debug for RenderCache {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("RenderCache")
            .field(
                "backdrop",
                &self.backdrop.as_ref().map(|(_, p)| (p.width(), p.height())),
            )
            .field("strokes", &self.strokes.is_some())
            .field("glyph_bytes", &self.glyphs.bytes())
            .finish()
    }
}

impl RenderCache {
    /// The white page with the shaded sphere, its graticule and the plot strips' frames for
    /// one size and camera: the part of a frame that does not depend on the curves. The last
    /// one drawn is kept, so that redrawing after an edit that leaves the camera alone, such
    /// as dragging a point in the playground, starts from a copy. A copy and a fresh drawing
    /// are the same pixels.
    fn backdrop(
        &mut self,
        size: u32,
        height: u32,
        axes: [DVec3; 3],
        frames: &[Rect],
    ) -> Option<Pixmap> {
        let rects = frames
            .iter()
            .map(|r| [r.left(), r.top(), r.width(), r.height()].map(f32::to_bits))
            .collect();
        let key = (size, height, axes, rects);
        if let Some((k, pixmap)) = &self.backdrop
            && *k == key
        {
            return Some(pixmap.clone());
        }
        let mut pixmap = Pixmap::new(size, height)?;
        pixmap.fill(Color::WHITE);
        Strokes::with(&mut self.strokes, size, height, |strokes| {
            let mut raster = Raster {
                pixmap: &mut pixmap,
                strokes,
                glyphs: &mut self.glyphs,
            };
            draw_backdrop(&mut raster, size, axes, frames);
        });
        self.backdrop = Some((key, pixmap.clone()));
        Some(pixmap)
    }
}

/// Draws the backdrop (see [`backdrop`]) onto `surface`.
fn draw_backdrop(surface: &mut dyn Surface, size: u32, axes: [DVec3; 3], frames: &[Rect]) {
    let mut canvas = Canvas::new(size, axes);
    graticule(&mut canvas);
    canvas.draw_backdrop(surface);
    for area in frames {
        plot::draw_frame(surface, *area, canvas.scale);
    }
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

fn arcs(canvas: &mut Sketch, pts: &[DVec3], style: LineStyle) {
    for w in pts.windows(2) {
        if (w[0] + w[1]).length() > 1e-9 {
            canvas.polyline(&flatten::great_arc(w[0], w[1]), style);
        }
    }
}

/// How curve `i`'s keys are marked (shape, colour, size): dark dots for a single curve; with
/// several, the first curve's dots and the others' rings, each wider than the last, in the
/// curve's colour, so that a key the curves share shows every curve's mark.
fn key_marker(i: usize, single: bool, color: Rgb) -> (Shape, Rgb, f32) {
    if single {
        (Shape::Dot, POINT_COLOR, 8.0)
    } else if i == 0 {
        (Shape::Dot, color, 9.0)
    } else {
        #[expect(clippy::cast_precision_loss, reason = "a few curves")]
        let step = i.min(5) as f32;
        (Shape::Ring, color, 9.0 + 6.0 * step)
    }
}

/// The size of a fitted curve's sample marks (pixels at 512 px).
const SAMPLE_SIZE: f32 = 6.0;

/// A fitted curve's key marks: `key` at most [`FITTED_KEY_SIZE`] pixels (at 512 px), since a
/// fit usually has a key at every sample, close together.
const FITTED_KEY_SIZE: f32 = 4.5;

fn fitted_key(key: (Shape, Rgb, f32)) -> (Shape, Rgb, f32) {
    (key.0, key.1, key.2.min(FITTED_KEY_SIZE))
}

/// The residual plot's series of a fitted curve: a stem from zero to each sample's residual
/// (degrees) at its time, and its rms as a dashed line across the samples' times; none for a
/// curve without a fit, or one whose parameter is not the fit's time (an arc-length
/// reparametrisation), where the samples have no place on the plot's time axis.
fn residual_series<P: Manifold>(b: &Built<P>, color: Rgb, normalized: bool) -> Vec<plot::Series> {
    let Some(fit) = &b.fit else {
        return Vec::new();
    };
    let [t0, t1] = b.curve.domain();
    let (Some(&first), Some(&last)) = (fit.times.first(), fit.times.last()) else {
        return Vec::new();
    };
    if first != t0 || last != t1 || t1 <= t0 {
        return Vec::new();
    }
    let unit = |t: f64| if normalized { (t - t0) / (t1 - t0) } else { t };
    let stems = fit
        .times
        .iter()
        .zip(&fit.report.residuals)
        .map(|(&t, &r)| vec![(unit(t), 0.0), (unit(t), r.to_degrees())])
        .collect();
    let rms = fit.report.rms.to_degrees();
    vec![
        plot::Series {
            color,
            dash: None,
            pieces: stems,
            joints: Vec::new(),
        },
        plot::Series {
            color,
            dash: Some([5.0, 3.0]),
            pieces: vec![vec![(unit(first), rms), (unit(last), rms)]],
            joints: Vec::new(),
        },
    ]
}

/// A curve on S² (or S¹ on the equator): the curve, its points (`key`: how they are marked),
/// derived points and polygons.
fn draw_points<P: Manifold>(
    canvas: &mut Sketch,
    b: &Built<P>,
    color: Rgb,
    key: (Shape, Rgb, f32),
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
    // A fitted curve passes near its points, the samples, and through its fitted keys.
    let keys: Vec<DVec3> = b
        .fit
        .as_ref()
        .map_or_else(|| input.clone(), |fit| fit.keys.iter().map(embed).collect());
    let controls: Vec<DVec3> = b.controls.iter().map(embed).collect();
    let aux: Vec<DVec3> = b.auxiliary.iter().map(embed).collect();
    // A closed curve's polygons close too (its controls already end where they start).
    let closing = |v: &[DVec3]| -> Vec<DVec3> {
        let mut out = v.to_vec();
        if b.curve.is_closed()
            && let Some(&first) = v.first()
        {
            out.push(first);
        }
        out
    };
    if polygon {
        arcs(canvas, &closing(&input), polygon_style(POINT_COLOR));
    }
    arcs(canvas, &controls, polygon_style(color));
    arcs(canvas, &closing(&aux), polygon_style(color));
    if b.fit.is_some() {
        for p in &input {
            canvas.marker(*p, Shape::Sample, key.1, SAMPLE_SIZE);
        }
    }
    canvas.polyline(&pts, curve_style(color));
    for p in &controls {
        canvas.marker(*p, Shape::Square, color, 6.0);
    }
    for p in &aux {
        canvas.marker(*p, Shape::Diamond, color, 7.0);
    }
    let key = if b.fit.is_some() {
        fitted_key(key)
    } else {
        key
    };
    for p in &keys {
        canvas.marker(*p, key.0, key.1, key.2);
    }
}

/// A curve on S³ as the trajectories of the tips of its rotated body axes (`key`: how its keys
/// are marked, drawn in the axis colour for a single curve).
fn draw_rotations(
    canvas: &mut Sketch,
    b: &Built<UnitQuat>,
    color: Rgb,
    key: (Shape, Rgb, f32),
    single: bool,
    view: &View,
) {
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
        if b.fit.is_some() {
            for q in &b.inputs {
                canvas.marker(q.rotate(axis), Shape::Sample, c, SAMPLE_SIZE);
            }
        }
        canvas.polyline(&pts, curve_style(c));
        for q in &b.controls {
            canvas.marker(q.rotate(axis), Shape::Square, c, 5.0);
        }
        match &b.fit {
            Some(fit) => {
                let key = fitted_key(key);
                for q in &fit.keys {
                    canvas.marker(q.rotate(axis), key.0, c, key.2);
                }
            }
            None => {
                for q in &b.inputs {
                    canvas.marker(q.rotate(axis), key.0, c, key.2);
                }
            }
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

/// One curve's plotted quantities (speed and three components), sampled piece by piece with
/// one-sided values at the joints.
struct Sampled {
    pieces: Vec<Vec<(f64, [f64; 4])>>,
    joints: Vec<f64>,
}

impl Sampled {
    /// Quantity `k` as a plot series.
    fn series(&self, k: usize, color: Rgb, dash: Option<[f32; 2]>, joints: bool) -> plot::Series {
        plot::Series {
            color,
            dash,
            pieces: self
                .pieces
                .iter()
                .map(|p| p.iter().map(|&(t, v)| (t, v[k])).collect())
                .collect(),
            joints: if joints {
                self.joints.clone()
            } else {
                Vec::new()
            },
        }
    }
}

/// Samples `values` of the jets of `curve` for the plot: against its own t, or with
/// `normalized` against u = (t − t₀)/(t₁ − t₀), the rates then per unit u.
fn sample<P: Manifold>(
    curve: &dyn Curve<Point = P>,
    size: u32,
    normalized: bool,
    values: &dyn Fn(&Jet<P>) -> [f64; 4],
) -> Sampled {
    let joints = curve.joints();
    let [t0, t1] = [joints[0], joints[joints.len() - 1]];
    let (unit, rate): (Box<dyn Fn(f64) -> f64>, f64) = if normalized {
        (Box::new(move |t| (t - t0) / (t1 - t0)), t1 - t0)
    } else {
        (Box::new(|t| t), 1.0)
    };
    let total = f64::from(size).max(64.0);
    let finite = |v: [f64; 4]| v.map(|x| if x.is_finite() { rate * x } else { 0.0 });
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
            let end = values(&curve.jet_at(w[1], Side::Left));
            ts.iter()
                .zip(&jets)
                .map(|(&t, j)| (unit(t), finite(values(j))))
                .chain(core::iter::once((unit(w[1]), finite(end))))
                .collect()
        })
        .collect();
    Sampled {
        pieces,
        joints: joints.iter().map(|&t| unit(t)).collect(),
    }
}

/// The crate README's examples, run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
