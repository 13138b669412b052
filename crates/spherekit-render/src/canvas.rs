// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Orthographic projection of the unit sphere and the drawing primitives, split into the near
//! and the far hemisphere.

use spherekit::glam::DVec3;
use tiny_skia::{Pixmap, Point};

use crate::stroke::{Cap, Pen, blend, length, pixels};
use crate::surface::Surface;

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
    /// A circle with a white halo: the data points of a second, third, … curve through the
    /// same keys, drawn around the first curve's dots (each curve's wider than the last).
    Ring,
    /// A small thin circle without a halo, drawn under the curve: the samples a fitted curve
    /// approximates (its keys, the fitted ones, are dots).
    Sample,
}

enum Item {
    Line(Vec<Point>, LineStyle, bool),
    Marker(Point, Shape, Rgb, f32, bool),
}

/// The marks of a figure on the sphere before projection, in the order they were added: what
/// a [`Canvas`] draws for any camera, so that a figure can be laid out once and projected for
/// each camera of a turning view ([`Sketch::project`] adds them to a canvas in the same order,
/// so the pixels are those of adding them to the canvas directly).
#[derive(Default)]
pub(crate) struct Sketch {
    marks: Vec<Mark>,
}

enum Mark {
    Line(Vec<DVec3>, LineStyle),
    Marker(DVec3, Shape, Rgb, f32),
}

impl Sketch {
    /// Adds a polyline of points on (or near) the sphere (see [`Canvas::polyline`]).
    pub(crate) fn polyline(&mut self, pts: &[DVec3], style: LineStyle) {
        self.marks.push(Mark::Line(pts.to_vec(), style));
    }

    /// Puts the derived points' markers after every line and the keys' markers last, each in
    /// the order it was added (so that with several curves through the same keys no curve's
    /// line or control point hides another's key marks). Sample marks stay among the lines,
    /// under the curve they were added before.
    pub(crate) fn markers_last(&mut self) {
        let rank = |m: &Mark| match m {
            Mark::Line(..) | Mark::Marker(_, Shape::Sample, ..) => 0,
            Mark::Marker(_, Shape::Square | Shape::Diamond, ..) => 1,
            Mark::Marker(_, Shape::Dot | Shape::Ring, ..) => 2,
        };
        self.marks.sort_by_key(rank);
    }

    /// Adds a marker at a point of the sphere (see [`Canvas::marker`]).
    pub(crate) fn marker(&mut self, p: DVec3, shape: Shape, color: Rgb, size: f32) {
        self.marks.push(Mark::Marker(p, shape, color, size));
    }

    /// The marks on a canvas of `size` pixels seen along the camera `axes`.
    pub(crate) fn project(&self, size: u32, axes: [DVec3; 3]) -> Canvas {
        let mut canvas = Canvas::new(size, axes);
        for mark in &self.marks {
            match mark {
                Mark::Line(pts, style) => canvas.polyline(pts, *style),
                Mark::Marker(p, shape, color, size) => canvas.marker(*p, *shape, *color, *size),
            }
        }
        canvas
    }
}

/// Pixels per pixel-at-512 of a `size`-pixel sphere view (line widths and text scale with it).
pub(crate) fn scale_of(size: u32) -> f32 {
    #[expect(clippy::cast_possible_truncation, reason = "pixel scale")]
    let scale = (f64::from(size) / 512.0) as f32;
    scale
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
        let scale = scale_of(size);
        let (c, radius) = crate::camera::sphere_frame(size);
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
        #[expect(clippy::cast_possible_truncation, reason = "pixel coordinates are f32")]
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
    pub(crate) fn draw_backdrop(&self, surface: &mut dyn Surface) {
        let (cx, cy, r) = self.disc();
        surface.sphere(cx, cy, r);
        for item in self.back.iter().chain(&self.front) {
            self.draw_item(surface, item);
        }
    }

    /// Which kinds of marks there are: discs, squares, diamonds, and dashed lines on the far
    /// side (for the legend).
    pub(crate) fn kinds(&self) -> Kinds {
        let mut k = Kinds::default();
        for item in self.back.iter().chain(&self.front) {
            match item {
                Item::Marker(_, Shape::Dot | Shape::Ring, ..) => k.dot = true,
                Item::Marker(_, Shape::Square, ..) => k.square = true,
                Item::Marker(_, Shape::Diamond, ..) => k.diamond = true,
                Item::Marker(_, Shape::Sample, ..) => k.sample = true,
                Item::Line(_, style, false) => {
                    k.far_dashed |= style.back_dashed && style.back_alpha > 0.0;
                }
                Item::Line(..) => {}
            }
        }
        k
    }

    /// Draws everything on the far side, the silhouette, then the near side.
    pub(crate) fn draw(&self, surface: &mut dyn Surface) {
        for item in &self.back {
            self.draw_item(surface, item);
        }
        // The silhouette.
        let (cx, cy, r) = self.disc();
        let rim: Vec<Point> = (0..=360)
            .map(|i| {
                let a = std::f32::consts::TAU * (i % 360) as f32 / 360.0;
                Point::from_xy(cx + r * libm::cosf(a), cy + r * libm::sinf(a))
            })
            .collect();
        surface.polyline(&rim, Pen::round(1.4 * self.scale));
        surface.paint([0x5b, 0x66, 0x73], 1.0);
        for item in &self.front {
            self.draw_item(surface, item);
        }
    }

    fn draw_item(&self, surface: &mut dyn Surface, item: &Item) {
        match item {
            Item::Line(pts, style, front) => {
                let alpha = if *front {
                    style.alpha
                } else {
                    style.back_alpha
                };
                if alpha <= 0.0 {
                    return;
                }
                let dashed = !front && style.back_dashed;
                let pen = Pen {
                    width: style.width * self.scale * if *front { 1.0 } else { 0.8 },
                    cap: if dashed { Cap::Butt } else { Cap::Round },
                    dash: dashed.then_some([5.0 * self.scale, 4.0 * self.scale]),
                };
                surface.polyline(pts, pen);
                surface.paint(style.color, alpha);
            }
            Item::Marker(p, shape, color, size, front) => {
                let size = *size * self.scale;
                draw_marker(surface, *p, *shape, *color, size, *front);
            }
        }
    }
}

/// The kinds of marks on a canvas (see [`Canvas::kinds`]).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Kinds {
    pub(crate) dot: bool,
    pub(crate) square: bool,
    pub(crate) diamond: bool,
    pub(crate) sample: bool,
    pub(crate) far_dashed: bool,
}

/// The sphere's fill and the colour it darkens to at the limb.
pub(crate) const SPHERE_FILL: Rgb = [0xf1, 0xf4, 0xf8];
pub(crate) const SPHERE_LIMB: Rgb = [0xcd, 0xd5, 0xdf];
/// Where the limb shading starts, as a fraction of the radius.
pub(crate) const LIMB_START: f32 = 0.93;

/// Paints the sphere's disc centred at `(cx, cy)` with radius `r`: a flat light fill that
/// darkens linearly to the limb over the outer ring, with an anti-aliased edge. Flat inside,
/// so it compresses well in PNG (a gradient over the whole disc costs ~40 KiB per 512 px
/// image) and most rows are a run of one colour.
pub(crate) fn shade_disc(pixmap: &mut Pixmap, cx: f32, cy: f32, r: f32) {
    let (width, height) = (pixmap.width() as usize, pixmap.height() as usize);
    let data = pixmap.data_mut();
    let reach = r + 0.5;
    let inner = LIMB_START * r;
    let fill = [SPHERE_FILL[0], SPHERE_FILL[1], SPHERE_FILL[2], 0xff];
    for y in 0..height {
        #[expect(clippy::cast_precision_loss, reason = "small row numbers")]
        let py = y as f32 + 0.5 - cy;
        if py.abs() >= reach {
            continue;
        }
        let half = (reach * reach - py * py).sqrt();
        // The flat part of the row: pixels whose centres are inside the inner circle.
        let flat = if py.abs() < inner {
            (inner * inner - py * py).sqrt()
        } else {
            0.0
        };
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            clippy::cast_precision_loss,
            reason = "clamped to the pixmap"
        )]
        let column = |x: f32| x.max(0.0).min(width as f32) as usize;
        let (left, right) = {
            let columns = pixels(cx - half, cx + half, width);
            (columns.start, columns.end)
        };
        let (flat_left, flat_right) = (column((cx - flat).ceil()), column((cx + flat).floor()));
        let row = &mut data[4 * y * width..4 * (y + 1) * width];
        // (The flat part lies inside [left, right); an empty one sits at `left`.)
        let (flat_left, flat_right) = (flat_left.max(left), flat_right.min(right));
        let (flat_left, flat_right) = if flat_left < flat_right {
            (flat_left, flat_right)
        } else {
            (left, left)
        };
        for px in row[4 * flat_left..4 * flat_right].chunks_exact_mut(4) {
            px.copy_from_slice(&fill);
        }
        for x in (left..flat_left).chain(flat_right..right) {
            let px = &mut row[4 * x..4 * x + 4];
            #[expect(clippy::cast_precision_loss, reason = "small column numbers")]
            let dx = x as f32 + 0.5 - cx;
            let d = length(dx, py);
            let s = ((d - inner) / (r - inner)).clamp(0.0, 1.0);
            let color: Rgb = core::array::from_fn(|k| {
                let (a, b) = (f32::from(SPHERE_FILL[k]), f32::from(SPHERE_LIMB[k]));
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "between two bytes"
                )]
                let c = (a + (b - a) * s + 0.5) as u8;
                c
            });
            blend(px, color, (reach - d).clamp(0.0, 1.0));
        }
    }
}

/// Draws a marker of `size` pixels centred at `p`: discs and squares are single thick segments
/// (round and butt ended), outlines closed polylines.
pub(crate) fn draw_marker(
    surface: &mut dyn Surface,
    p: Point,
    shape: Shape,
    color: Rgb,
    size: f32,
    front: bool,
) {
    let alpha = if front { 1.0 } else { 0.35 };
    let h = 0.5 * size;
    let rim = (0.3 * size).max(1.0);
    let at = |x: f32, y: f32| Point::from_xy(p.x + x, p.y + y);
    if shape == Shape::Dot {
        // A white disc under the coloured one: a dot with a white rim.
        surface.polyline(&[p, p], Pen::round(2.0 * h + rim));
        surface.paint([0xff; 3], alpha);
        surface.polyline(&[p, p], Pen::round(2.0 * h - rim));
        surface.paint(color, alpha);
        return;
    }
    if matches!(shape, Shape::Ring | Shape::Sample) {
        // Two open halves, painted one by one: the stroke of a closed loop would fill its
        // inside. A sample's circle is small, so its line is a larger part of it.
        let share = if shape == Shape::Ring { 0.12 } else { 0.2 };
        let width = (share * size).max(1.0);
        let half = |from: usize| -> Vec<Point> {
            (from..=from + 16)
                .map(|k| {
                    #[expect(clippy::cast_precision_loss, reason = "a small index")]
                    let a = k as f32 * core::f32::consts::TAU / 32.0;
                    at(h * libm::cosf(a), h * libm::sinf(a))
                })
                .collect()
        };
        let halves = [half(0), half(16)];
        let halo = (Pen::round(3.0 * width), [0xff; 3], alpha);
        let line = (Pen::round(width), color, alpha);
        let pens = if shape == Shape::Ring {
            &[halo, line][..]
        } else {
            &[line][..]
        };
        for &(pen, color, alpha) in pens {
            for arc in &halves {
                surface.polyline(arc, pen);
                surface.paint(color, alpha);
            }
        }
        return;
    }
    // A square (or a square turned by 45°: the diamond) is a butt-ended segment as wide as
    // it is long, through its centre.
    let (corners, fill) = if shape == Shape::Square {
        (
            [at(-h, -h), at(h, -h), at(h, h), at(-h, h)],
            [at(-h, 0.0), at(h, 0.0)],
        )
    } else {
        let k = 1.3 * h;
        (
            [at(0.0, -k), at(k, 0.0), at(0.0, k), at(-k, 0.0)],
            [at(-0.5 * k, -0.5 * k), at(0.5 * k, 0.5 * k)],
        )
    };
    let side = length(fill[1].x - fill[0].x, fill[1].y - fill[0].y);
    surface.polyline(
        &fill,
        Pen {
            width: side,
            cap: Cap::Butt,
            dash: None,
        },
    );
    surface.paint([0xff; 3], 0.8 * alpha);
    let mut outline = corners.to_vec();
    outline.push(corners[0]);
    surface.polyline(&outline, Pen::round(rim));
    surface.paint(color, alpha);
}
