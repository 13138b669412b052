// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The plot strip: speed (or angular speed) against the parameter, joints marked.

use tiny_skia::{PathBuilder, Pixmap, Rect, Stroke, Transform};

use crate::canvas::{Rgb, solid};

/// One curve's speed samples, one polyline per piece (so jumps at joints stay visible).
pub(crate) struct SpeedSeries {
    pub(crate) color: Rgb,
    pub(crate) pieces: Vec<Vec<(f64, f64)>>,
    pub(crate) joints: Vec<f64>,
}

/// Draws the strip into `area` (pixels). Each curve's parameter is mapped to the strip's full
/// width, so curves with different domains can be compared.
pub(crate) fn draw(pixmap: &mut Pixmap, area: Rect, scale: f32, series: &[SpeedSeries]) {
    let frame = solid([0xf6, 0xf7, 0xf9], 1.0);
    pixmap.fill_rect(area, &frame, Transform::identity(), None);
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
    let thin = Stroke {
        width: 0.8 * scale,
        ..Stroke::default()
    };
    // Axes: the zero line, and a tick line at every joint of every curve.
    let mut grid = PathBuilder::new();
    grid.move_to(x0, y0);
    grid.line_to(x1, y0);
    for s in series {
        for &j in &s.joints {
            let (x, _) = map(j, 0.0);
            grid.move_to(x, y0);
            grid.line_to(x, y1);
        }
    }
    if let Some(p) = grid.finish() {
        pixmap.stroke_path(
            &p,
            &solid([0xc3, 0xc9, 0xd1], 1.0),
            &thin,
            Transform::identity(),
            None,
        );
    }
    let line = Stroke {
        width: 1.6 * scale,
        line_join: tiny_skia::LineJoin::Round,
        ..Stroke::default()
    };
    for s in series {
        let mut pb = PathBuilder::new();
        for piece in &s.pieces {
            for (i, &(t, v)) in piece.iter().enumerate() {
                let (x, y) = map(t, v);
                if i == 0 {
                    pb.move_to(x, y)
                } else {
                    pb.line_to(x, y)
                }
            }
        }
        if let Some(p) = pb.finish() {
            pixmap.stroke_path(&p, &solid(s.color, 1.0), &line, Transform::identity(), None);
        }
    }
    let border = PathBuilder::from_rect(area);
    pixmap.stroke_path(
        &border,
        &solid([0xc3, 0xc9, 0xd1], 1.0),
        &thin,
        Transform::identity(),
        None,
    );
}
