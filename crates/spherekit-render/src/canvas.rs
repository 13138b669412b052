// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Orthographic projection of the unit sphere and the drawing primitives, split into the near
//! and the far hemisphere.

use spherekit::glam::DVec3;
use tiny_skia::{
    Color, FillRule, GradientStop, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Point,
    RadialGradient, SpreadMode, Stroke, StrokeDash, Transform,
};

/// An opaque colour.
pub(crate) type Rgb = [u8; 3];

/// How a polyline is stroked.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LineStyle {
    pub(crate) color: Rgb,
    /// Width in pixels at a 512 px sphere.
    pub(crate) width: f32,
    /// Opacity on the near side.
    pub(crate) alpha: f32,
    /// Opacity on the far side (seen through the sphere).
    pub(crate) back_alpha: f32,
    /// Whether the far side is dashed.
    pub(crate) back_dashed: bool,
}

/// Marker shapes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Shape {
    /// Filled disc with a white rim: data points.
    Dot,
    /// Hollow square: derived control points.
    Square,
    /// Hollow diamond: auxiliary vertices.
    Diamond,
}

enum Item {
    Line(Vec<Point>, LineStyle, bool),
    Marker(Point, Shape, Rgb, f32, bool),
}

/// The sphere's frame on the pixmap and the list of things to draw, sorted by hemisphere.
pub(crate) struct Canvas {
    center: (f64, f64),
    radius: f64,
    /// Pixels per pixel-at-512.
    pub(crate) scale: f32,
    axes: [DVec3; 3],
    back: Vec<Item>,
    front: Vec<Item>,
}

impl Canvas {
    pub(crate) fn new(size: u32, axes: [DVec3; 3]) -> Self {
        let s = f64::from(size);
        #[expect(clippy::cast_possible_truncation, reason = "pixel scale")]
        let scale = (s / 512.0) as f32;
        let (c, radius) = crate::view::sphere_frame(size);
        Self {
            center: (c, c),
            radius,
            scale,
            axes,
            back: Vec::new(),
            front: Vec::new(),
        }
    }

    /// Screen position and depth (positive towards the viewer) of a point of ℝ³.
    pub(crate) fn project(&self, p: DVec3) -> (Point, f64) {
        let [r, u, z] = self.axes;
        let x = self.center.0 + self.radius * p.dot(r);
        let y = self.center.1 - self.radius * p.dot(u);
        #[expect(clippy::cast_possible_truncation, reason = "tiny-skia works in f32")]
        let pt = Point::from_xy(x as f32, y as f32);
        (pt, p.dot(z))
    }

    /// Adds a polyline of points on (or near) the sphere, split where it crosses the horizon.
    pub(crate) fn polyline(&mut self, pts: &[DVec3], style: LineStyle) {
        let Some(&first) = pts.first() else { return };
        let z = self.axes[2];
        let mut run = vec![self.project(first).0];
        let mut front = first.dot(z) >= 0.0;
        for w in pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            let (da, db) = (a.dot(z), b.dot(z));
            let b_front = db >= 0.0;
            if b_front != front {
                let f = da / (da - db);
                let c = (a + (b - a) * f).normalize_or_zero();
                let pc = self.project(c).0;
                run.push(pc);
                self.push_line(std::mem::take(&mut run), style, front);
                run.push(pc);
                front = b_front;
            }
            run.push(self.project(b).0);
        }
        self.push_line(run, style, front);
    }

    fn push_line(&mut self, run: Vec<Point>, style: LineStyle, front: bool) {
        if run.len() < 2 {
            return;
        }
        let item = Item::Line(run, style, front);
        if front {
            self.front.push(item)
        } else {
            self.back.push(item)
        }
    }

    /// Adds a marker at a point of the sphere.
    pub(crate) fn marker(&mut self, p: DVec3, shape: Shape, color: Rgb, size: f32) {
        let (pt, depth) = self.project(p);
        let front = depth >= 0.0;
        let item = Item::Marker(pt, shape, color, size, front);
        if front {
            self.front.push(item)
        } else {
            self.back.push(item)
        }
    }

    /// The sphere's disc in pixels: centre x, centre y, radius.
    fn disc(&self) -> (f32, f32, f32) {
        #[expect(clippy::cast_possible_truncation, reason = "pixels")]
        let disc = (
            self.center.0 as f32,
            self.center.1 as f32,
            self.radius as f32,
        );
        disc
    }

    /// Draws the shaded sphere and then every item, without the silhouette: the backdrop that
    /// [`Canvas::draw`] draws on (see `render_built`).
    pub(crate) fn draw_backdrop(&self, pixmap: &mut Pixmap) {
        let (cx, cy, r) = self.disc();
        // Flat light fill with a darker limb: concentric, so it compresses well in PNG
        // (a gradient over the whole disc costs ~40 KiB per 512 px image). The gradient
        // is painted on the outer ring only: the shader costs ~20× a solid fill per pixel.
        if let Some(disc) = PathBuilder::from_circle(cx, cy, r) {
            pixmap.fill_path(
                &disc,
                &solid(SPHERE_FILL, 1.0),
                FillRule::Winding,
                Transform::identity(),
                None,
            );
        }
        let ring = {
            let mut pb = PathBuilder::new();
            pb.push_circle(cx, cy, r);
            pb.push_circle(cx, cy, LIMB_START * r);
            pb.finish()
        };
        let shader = RadialGradient::new(
            Point::from_xy(cx, cy),
            0.0,
            Point::from_xy(cx, cy),
            r,
            vec![
                GradientStop::new(LIMB_START, rgb(SPHERE_FILL)),
                GradientStop::new(1.0, rgb(SPHERE_LIMB)),
            ],
            SpreadMode::Pad,
            Transform::identity(),
        );
        if let (Some(ring), Some(shader)) = (ring, shader) {
            let paint = Paint {
                shader,
                ..Paint::default()
            };
            pixmap.fill_path(
                &ring,
                &paint,
                FillRule::EvenOdd,
                Transform::identity(),
                None,
            );
        }
        for item in self.back.iter().chain(&self.front) {
            self.draw_item(pixmap, item);
        }
    }

    /// Draws everything on the far side, the silhouette, then the near side.
    pub(crate) fn draw(&self, pixmap: &mut Pixmap) {
        for item in &self.back {
            self.draw_item(pixmap, item);
        }
        let (cx, cy, r) = self.disc();
        if let Some(disc) = PathBuilder::from_circle(cx, cy, r) {
            let mut rim = Paint::default();
            rim.set_color_rgba8(0x5b, 0x66, 0x73, 0xff);
            let stroke = Stroke {
                width: 1.4 * self.scale,
                ..Stroke::default()
            };
            pixmap.stroke_path(&disc, &rim, &stroke, Transform::identity(), None);
        }
        for item in &self.front {
            self.draw_item(pixmap, item);
        }
    }

    fn draw_item(&self, pixmap: &mut Pixmap, item: &Item) {
        match item {
            Item::Line(pts, style, front) => self.draw_line(pixmap, pts, *style, *front),
            Item::Marker(p, shape, color, size, front) => {
                draw_marker(pixmap, *p, *shape, *color, *size * self.scale, *front);
            }
        }
    }

    fn draw_line(&self, pixmap: &mut Pixmap, pts: &[Point], style: LineStyle, front: bool) {
        let mut pb = PathBuilder::new();
        pb.move_to(pts[0].x, pts[0].y);
        for p in &pts[1..] {
            pb.line_to(p.x, p.y);
        }
        let Some(path) = pb.finish() else { return };
        let alpha = if front { style.alpha } else { style.back_alpha };
        if alpha <= 0.0 {
            return;
        }
        let paint = solid(style.color, alpha);
        let width = style.width * self.scale * if front { 1.0 } else { 0.8 };
        let dash = (!front && style.back_dashed)
            .then(|| StrokeDash::new(vec![5.0 * self.scale, 4.0 * self.scale], 0.0))
            .flatten();
        let stroke = Stroke {
            width,
            line_cap: if dash.is_some() {
                LineCap::Butt
            } else {
                LineCap::Round
            },
            line_join: LineJoin::Bevel,
            dash,
            ..Stroke::default()
        };
        pixmap.stroke_path(&path, &paint, &stroke, Transform::identity(), None);
    }
}

/// The sphere's fill and the colour it darkens to at the limb.
const SPHERE_FILL: Rgb = [0xf1, 0xf4, 0xf8];
const SPHERE_LIMB: Rgb = [0xcd, 0xd5, 0xdf];
/// Where the limb shading starts, as a fraction of the radius.
const LIMB_START: f32 = 0.93;

fn rgb(c: Rgb) -> Color {
    Color::from_rgba8(c[0], c[1], c[2], 0xff)
}

/// A solid paint of `color` at opacity `alpha`.
pub(crate) fn solid(color: Rgb, alpha: f32) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color(
        Color::from_rgba(
            f32::from(color[0]) / 255.0,
            f32::from(color[1]) / 255.0,
            f32::from(color[2]) / 255.0,
            alpha,
        )
        .unwrap_or(Color::BLACK),
    );
    paint.anti_alias = true;
    paint
}

fn draw_marker(pixmap: &mut Pixmap, p: Point, shape: Shape, color: Rgb, size: f32, front: bool) {
    let alpha = if front { 1.0 } else { 0.35 };
    let h = 0.5 * size;
    let path = match shape {
        Shape::Dot => PathBuilder::from_circle(p.x, p.y, h),
        Shape::Square => {
            let mut pb = PathBuilder::new();
            pb.move_to(p.x - h, p.y - h);
            pb.line_to(p.x + h, p.y - h);
            pb.line_to(p.x + h, p.y + h);
            pb.line_to(p.x - h, p.y + h);
            pb.close();
            pb.finish()
        }
        Shape::Diamond => {
            let k = 1.3 * h;
            let mut pb = PathBuilder::new();
            pb.move_to(p.x, p.y - k);
            pb.line_to(p.x + k, p.y);
            pb.line_to(p.x, p.y + k);
            pb.line_to(p.x - k, p.y);
            pb.close();
            pb.finish()
        }
    };
    let Some(path) = path else { return };
    let rim = Stroke {
        width: (0.3 * size).max(1.0),
        ..Stroke::default()
    };
    if shape == Shape::Dot {
        pixmap.fill_path(
            &path,
            &solid(color, alpha),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
        pixmap.stroke_path(
            &path,
            &solid([0xff; 3], alpha),
            &rim,
            Transform::identity(),
            None,
        );
    } else {
        pixmap.fill_path(
            &path,
            &solid([0xff; 3], 0.8 * alpha),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
        pixmap.stroke_path(
            &path,
            &solid(color, alpha),
            &rim,
            Transform::identity(),
            None,
        );
    }
}
