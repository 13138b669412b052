// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The plot strip: speed (or angular speed) against the parameter, joints marked.

use tiny_skia::{Pixmap, Point, Rect};

use crate::canvas::Rgb;
use crate::stroke::{Cap, Pen, Strokes, blend, pixels};

/// The grey of the frame and the axes.
const GREY: Rgb = [0xc3, 0xc9, 0xd1];

/// One curve's speed samples, one polyline per piece (so jumps at joints stay visible).
pub(crate) struct SpeedSeries {
    pub(crate) color: Rgb,
    pub(crate) pieces: Vec<Vec<(f64, f64)>>,
    pub(crate) joints: Vec<f64>,
}

/// Draws the strip's frame into `area` (pixels): a light fill and a thin border. It does not
/// depend on the curves, so it belongs to the backdrop.
pub(crate) fn draw_frame(pixmap: &mut Pixmap, area: Rect, scale: f32) {
    fill_rect(pixmap, area, [0xf6, 0xf7, 0xf9]);
    let (l, t, r, b) = (area.left(), area.top(), area.right(), area.bottom());
    let border = [(l, t), (r, t), (r, b), (l, b), (l, t)].map(|(x, y)| Point::from_xy(x, y));
    Strokes::with(pixmap.width(), pixmap.height(), |strokes| {
        strokes.polyline(&border, Pen::round(0.8 * scale));
        strokes.paint(pixmap, GREY, 1.0);
    });
}

/// Fills `rect` with `color`, edge pixels by the fraction of them inside.
fn fill_rect(pixmap: &mut Pixmap, rect: Rect, color: Rgb) {
    let (width, height) = (pixmap.width() as usize, pixmap.height() as usize);
    let data = pixmap.data_mut();
    // The part of the pixel interval [i, i + 1] inside [lo, hi].
    let inside = |i: usize, lo: f32, hi: f32| {
        #[expect(clippy::cast_precision_loss, reason = "small pixel numbers")]
        let i = i as f32;
        (hi.min(i + 1.0) - lo.max(i)).clamp(0.0, 1.0)
    };
    let opaque = [color[0], color[1], color[2], 0xff];
    for y in pixels(rect.top(), rect.bottom(), height) {
        let cy = inside(y, rect.top(), rect.bottom());
        for x in pixels(rect.left(), rect.right(), width) {
            let px = &mut data[4 * (y * width + x)..4 * (y * width + x + 1)];
            // Inside pixels are the colour itself (what `blend` gives at full opacity).
            match cy * inside(x, rect.left(), rect.right()) {
                1.0 => px.copy_from_slice(&opaque),
                a => blend(px, color, a),
            }
        }
    }
}

/// Draws the curves' speeds into the strip's `area` (pixels). Each curve's parameter is mapped to the strip's full
/// width, so curves with different domains can be compared.
pub(crate) fn draw(
    pixmap: &mut Pixmap,
    strokes: &mut Strokes,
    area: Rect,
    scale: f32,
    series: &[SpeedSeries],
) {
    let (mut t0, mut t1, mut vmax) = (f64::INFINITY, f64::NEG_INFINITY, 0.0_f64);
    for s in series {
        for piece in &s.pieces {
            for &(t, v) in piece {
                t0 = t0.min(t);
                t1 = t1.max(t);
                vmax = vmax.max(v);
            }
        }
    }
    if t1.partial_cmp(&t0) != Some(core::cmp::Ordering::Greater) {
        return;
    }
    if vmax <= 0.0 || !vmax.is_finite() {
        vmax = 1.0;
    }
    let pad = 8.0 * scale;
    let (x0, x1) = (area.left() + pad, area.right() - pad);
    let (y0, y1) = (area.bottom() - pad, area.top() + pad);
    #[expect(clippy::cast_possible_truncation, reason = "pixels")]
    let map = |t: f64, v: f64| {
        let x = f64::from(x0) + (t - t0) / (t1 - t0) * f64::from(x1 - x0);
        let y = f64::from(y0) + v / (1.08 * vmax) * f64::from(y1 - y0);
        (x as f32, y as f32)
    };
    let thin = Pen {
        width: 0.8 * scale,
        cap: Cap::Butt,
        dash: None,
    };
    // Axes: the zero line, and a tick line at every joint of every curve.
    strokes.polyline(&[Point::from_xy(x0, y0), Point::from_xy(x1, y0)], thin);
    for s in series {
        for &j in &s.joints {
            let (x, _) = map(j, 0.0);
            strokes.polyline(&[Point::from_xy(x, y0), Point::from_xy(x, y1)], thin);
        }
    }
    strokes.paint(pixmap, GREY, 1.0);
    let line = Pen {
        width: 1.6 * scale,
        cap: Cap::Butt,
        dash: None,
    };
    let mut pts = Vec::new();
    for s in series {
        for piece in &s.pieces {
            pts.clear();
            pts.extend(piece.iter().map(|&(t, v)| {
                let (x, y) = map(t, v);
                Point::from_xy(x, y)
            }));
            strokes.polyline(&pts, line);
        }
        strokes.paint(pixmap, s.color, 1.0);
    }
}
