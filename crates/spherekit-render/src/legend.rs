// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The legend under the figure: what each colour, marker and line style means, set in rows
//! that wrap at the figure's width.

use tiny_skia::Point;

use crate::canvas::{Rgb, Shape, draw_marker};
use crate::plot::INK;
use crate::stroke::{Cap, Pen};
use crate::surface::{Anchor, Surface};
use crate::text::{CAP_HEIGHT, width};

/// What an entry shows before its text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Swatch {
    /// A curve's line: colour, dashed (the far side), opacity.
    Line(Rgb, Option<[f32; 2]>, f32),
    /// A marker as drawn on the sphere.
    Marker(Shape, Rgb),
    /// A joint tick of the plot.
    Tick(Rgb),
    /// Text alone.
    None,
}

/// One legend entry. Entries of a new group start a new row.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Entry {
    pub(crate) swatch: Swatch,
    pub(crate) label: String,
    pub(crate) group: u8,
}

/// The legend's text size at `scale`.
pub(crate) fn px(scale: f32) -> f32 {
    crate::plot::label_px(scale)
}

struct Geometry {
    left: f32,
    right: f32,
    swatch: f32,
    gap: f32,
    spacing: f32,
    row: f32,
    pad: f32,
}

fn geometry(size: u32, scale: f32) -> Geometry {
    let s = f32::from(u16::try_from(size).unwrap_or(u16::MAX));
    let px = px(scale);
    Geometry {
        left: 0.04 * s,
        right: 0.96 * s,
        swatch: 20.0 * scale,
        gap: 5.0 * scale,
        spacing: 14.0 * scale,
        row: 1.6 * px,
        pad: 5.0 * scale,
    }
}

/// Each entry's x and row.
fn place(entries: &[Entry], size: u32, scale: f32) -> Vec<(f32, usize)> {
    let g = geometry(size, scale);
    let px = px(scale);
    let (mut x, mut row) = (g.left, 0);
    let mut group = entries.first().map_or(0, |e| e.group);
    entries
        .iter()
        .map(|e| {
            let w = if e.swatch == Swatch::None {
                0.0
            } else {
                g.swatch + g.gap
            } + width(&e.label, px);
            if x > g.left && (e.group != group || x + w > g.right) {
                row += 1;
                x = g.left;
            }
            group = e.group;
            let at = (x, row);
            x += w + g.spacing;
            at
        })
        .collect()
}

/// The height of the legend in pixels (0 without entries).
pub(crate) fn height(entries: &[Entry], size: u32, scale: f32) -> u32 {
    let Some(&(_, rows)) = place(entries, size, scale).last() else {
        return 0;
    };
    let g = geometry(size, scale);
    #[expect(clippy::cast_precision_loss, reason = "a few rows")]
    let h = 2.0 * g.pad + (rows + 1) as f32 * g.row;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a few hundred pixels"
    )]
    let h = h.ceil() as u32;
    h
}

/// Draws the legend with its top at `top`.
pub(crate) fn draw(surface: &mut dyn Surface, entries: &[Entry], top: f32, size: u32, scale: f32) {
    let g = geometry(size, scale);
    let px = px(scale);
    let cap = CAP_HEIGHT * px;
    for (e, (x, row)) in entries.iter().zip(place(entries, size, scale)) {
        #[expect(clippy::cast_precision_loss, reason = "a few rows")]
        let baseline = top + g.pad + (row as f32 + 0.5) * g.row + 0.5 * cap;
        let yc = baseline - 0.5 * cap;
        let text_x = if e.swatch == Swatch::None {
            x
        } else {
            x + g.swatch + g.gap
        };
        match e.swatch {
            Swatch::Line(color, dash, alpha) => {
                let pen = Pen {
                    width: if dash.is_some() { 1.9 } else { 2.4 } * scale,
                    cap: if dash.is_some() {
                        Cap::Butt
                    } else {
                        Cap::Round
                    },
                    dash: dash.map(|d| d.map(|v| v * scale)),
                };
                let inset = if dash.is_some() { 0.0 } else { 1.2 * scale };
                surface.polyline(
                    &[
                        Point::from_xy(x + inset, yc),
                        Point::from_xy(x + g.swatch - inset, yc),
                    ],
                    pen,
                );
                surface.paint(color, alpha);
            }
            Swatch::Marker(shape, color) => {
                let size = match shape {
                    Shape::Dot | Shape::Ring => 8.0,
                    Shape::Square | Shape::Sample => 6.0,
                    Shape::Diamond => 7.0,
                } * scale;
                draw_marker(
                    surface,
                    Point::from_xy(x + 0.5 * g.swatch, yc),
                    shape,
                    color,
                    size,
                    true,
                );
            }
            Swatch::Tick(color) => {
                let c = x + 0.5 * g.swatch;
                surface.polyline(
                    &[
                        Point::from_xy(c, yc + 0.6 * cap),
                        Point::from_xy(c, yc - 0.6 * cap),
                    ],
                    Pen {
                        width: 1.4 * scale,
                        cap: Cap::Butt,
                        dash: None,
                    },
                );
                surface.paint(color, 1.0);
            }
            Swatch::None => {}
        }
        surface.text(text_x, baseline, &e.label, px, INK, Anchor::Start);
    }
}
