// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Figures of curves built in code: any [`Curve`] on S², S³ or S¹ with its keys, controls and
//! label, drawn without a scene (the scene path draws through the same layers).

use spherekit::Curve;
use spherekit_scene::{Built, BuiltCurve, ScenePoint, Space, View};
use tiny_skia::Pixmap;

use crate::canvas::Rgb;
use crate::{Layers, PlotAxes, Prepared, RenderCache, RenderError, Style};

/// A figure of curves built in code, drawn as a scene's figure is (the same sphere, legend,
/// plot strips and pixels), without writing the curves as JSON.
///
/// Every curve of one drawing is on one sphere: S², S³ (drawn by the traces of the body
/// axes) or S¹. The view options are the scene format's `view` ([`View`]); without
/// [`with_view`](Self::with_view) they are its defaults for the sphere and the number of
/// curves.
///
/// # Examples
///
/// A cubic spline built in code and the great-circle arcs through the same points, drawn to
/// PNG (with the crate's `png` feature) and SVG:
///
/// ```
/// use spherekit::{CubicEnd, CubicSpline, GeodesicSpline, S2Point};
/// use spherekit::glam::DVec3;
/// use spherekit_render::Drawing;
///
/// let p = |x: f64, y: f64, z: f64| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let keys = vec![p(1.0, 0.0, 0.2), p(0.3, 1.0, 0.4), p(-0.6, 0.5, 0.9), p(-1.0, -0.4, 0.3)];
/// let times = vec![0.0, 1.0, 2.5, 3.0];
/// let cubic = CubicSpline::try_new(keys.clone(), Some(times.clone()), CubicEnd::Natural, false)
///     .unwrap();
/// let arcs = GeodesicSpline::try_new(keys.clone(), Some(times)).unwrap();
/// let drawing = Drawing::new()
///     .curve(cubic, keys.clone(), Vec::new(), "natural cubic")
///     .curve(arcs, keys, Vec::new(), "great-circle arcs");
/// let pixmap = drawing.render(256).unwrap();
/// assert_eq!(pixmap.width(), 256);
/// # #[cfg(feature = "png")]
/// let png: Vec<u8> = spherekit_render::png::encode_png(&pixmap).unwrap();
/// let svg: String = drawing.render_svg(256).unwrap();
/// assert!(svg.contains("natural cubic"));
/// ```
#[derive(Debug, Default)]
pub struct Drawing {
    curves: Vec<BuiltCurve>,
    styles: Vec<(Option<Rgb>, String, bool)>,
    view: Option<View>,
}

impl Drawing {
    /// An empty drawing.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds `curve`, drawn with its `keys` (dots), `controls` (squares joined by a polygon; may
    /// be empty) and `label` (its name in the legend), in the next colour of the palette.
    #[must_use]
    pub fn curve<P: ScenePoint>(
        mut self,
        curve: impl Curve<Point = P> + Send + Sync + 'static,
        keys: Vec<P>,
        controls: Vec<P>,
        label: &str,
    ) -> Self {
        let built = Built::new(curve, keys).with_controls(controls);
        self.curves.push(P::into_built_curve(built));
        self.styles.push((None, label.to_owned(), false));
        self
    }

    /// The last curve added in `color` instead of the palette's.
    #[must_use]
    pub fn color(mut self, color: [u8; 3]) -> Self {
        if let Some(style) = self.styles.last_mut() {
            style.0 = Some(color);
        }
        self
    }

    /// The last curve's keys joined by a polygon (for a curve that does not pass through them,
    /// such as a B-spline's control points).
    #[must_use]
    pub fn polygon(mut self) -> Self {
        if let Some(style) = self.styles.last_mut() {
            style.2 = true;
        }
        self
    }

    /// The view options (camera, plot strips, frames, legend, title) instead of the defaults.
    #[must_use]
    pub fn with_view(mut self, view: View) -> Self {
        self.view = Some(view);
        self
    }

    /// The sphere of the drawing's curves.
    ///
    /// # Errors
    ///
    /// [`RenderError::Drawing`] for a drawing without curves or with curves on different
    /// spheres.
    fn space(&self) -> Result<Space, RenderError> {
        let spaces: Vec<Space> = self.curves.iter().map(space_of).collect();
        let Some(&first) = spaces.first() else {
            return Err(RenderError::Drawing("a drawing needs a curve".into()));
        };
        match spaces.iter().position(|&s| s != first) {
            Some(i) => Err(RenderError::Drawing(format!(
                "curve {i} is on {}, curve 0 on {}: one drawing is on one sphere",
                spaces[i].name(),
                first.name()
            ))),
            None => Ok(first),
        }
    }

    fn layers<'a>(&'a self, space: Space, view: &'a View) -> Layers<'a> {
        Layers {
            space,
            view,
            curves: &self.curves,
            styles: self
                .styles
                .iter()
                .map(|(color, label, polygon)| Style {
                    color: *color,
                    label,
                    polygon: *polygon,
                })
                .collect(),
        }
    }

    fn with_layers<R>(
        &self,
        f: impl FnOnce(&Layers<'_>) -> Result<R, RenderError>,
    ) -> Result<R, RenderError> {
        let space = self.space()?;
        let defaults;
        let view = match &self.view {
            Some(view) => view,
            None => {
                defaults = View::from_json(None, space, self.curves.len())?;
                &defaults
            }
        };
        f(&self.layers(space, view))
    }

    /// The figure at `size` pixels wide.
    ///
    /// # Errors
    ///
    /// [`RenderError::Drawing`] for no curves or curves on different spheres,
    /// [`RenderError::Size`] and [`RenderError::Space`] as for a scene.
    pub fn render(&self, size: u32) -> Result<Pixmap, RenderError> {
        self.render_figure(size).map(|(pixmap, _)| pixmap)
    }

    /// As [`render`](Self::render), and where the plot strips put their axes.
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render).
    pub fn render_figure(&self, size: u32) -> Result<(Pixmap, Vec<PlotAxes>), RenderError> {
        self.with_layers(|layers| {
            Prepared::new(layers, size, 0.0)?.render_layers(layers, &mut RenderCache::default())
        })
    }

    /// The same figure as an SVG document (see [`render_svg`](crate::render_svg)).
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render).
    pub fn render_svg(&self, size: u32) -> Result<String, RenderError> {
        self.with_layers(|layers| crate::svg_of(layers, size))
    }
}

fn space_of(curve: &BuiltCurve) -> Space {
    match curve {
        BuiltCurve::S2(_) => Space::S2,
        BuiltCurve::S3(_) => Space::S3,
        BuiltCurve::Sm(b) => b.inputs.first().map_or_else(
            || b.curve.eval(b.curve.domain()[0]).space(),
            ScenePoint::space,
        ),
    }
}
