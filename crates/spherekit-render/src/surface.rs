// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! What a figure is drawn onto: the pixmap (through the stroker and the text rasterizer) or
//! an SVG document. Both get the same calls in the same order, so the SVG is the same picture
//! as the PNG: strokes of polylines in pixel coordinates, filled rectangles, the shaded sphere
//! and lines of text.

use core::fmt::Write as _;

use tiny_skia::{Pixmap, Point, Rect};

use crate::canvas::{Rgb, shade_disc};
use crate::stroke::{Cap, Pen, Strokes, blend, pixels};
use crate::text::{self, Glyphs};

/// Where a line of text is anchored horizontally.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Anchor {
    Start,
    Middle,
    End,
}

/// A drawing target.
pub(crate) trait Surface {
    /// Adds a polyline to the strokes pending for the next [`Surface::paint`].
    fn polyline(&mut self, pts: &[Point], pen: Pen);
    /// Paints the pending strokes in `color` at opacity `alpha`.
    fn paint(&mut self, color: Rgb, alpha: f32);
    /// Fills `rect` with `color`.
    fn fill_rect(&mut self, rect: Rect, color: Rgb);
    /// The shaded sphere's disc.
    fn sphere(&mut self, cx: f32, cy: f32, r: f32);
    /// A line of text with its baseline at `y`, `px` pixels per em.
    fn text(&mut self, x: f32, y: f32, s: &str, px: f32, color: Rgb, anchor: Anchor);
}

/// The x where a line of text of width `w` anchored at `x` starts.
fn start(x: f32, w: f32, anchor: Anchor) -> f32 {
    match anchor {
        Anchor::Start => x,
        Anchor::Middle => x - 0.5 * w,
        Anchor::End => x - w,
    }
}

/// The pixmap, with the stroker's buffer and the glyph bitmaps.
pub(crate) struct Raster<'a> {
    pub(crate) pixmap: &'a mut Pixmap,
    pub(crate) strokes: &'a mut Strokes,
    pub(crate) glyphs: &'a mut Glyphs,
}

impl Surface for Raster<'_> {
    fn polyline(&mut self, pts: &[Point], pen: Pen) {
        self.strokes.polyline(pts, pen);
    }

    fn paint(&mut self, color: Rgb, alpha: f32) {
        self.strokes.paint(self.pixmap, color, alpha);
    }

    fn fill_rect(&mut self, rect: Rect, color: Rgb) {
        fill_rect(self.pixmap, rect, color);
    }

    fn sphere(&mut self, cx: f32, cy: f32, r: f32) {
        shade_disc(self.pixmap, cx, cy, r);
    }

    fn text(&mut self, x: f32, y: f32, s: &str, px: f32, color: Rgb, anchor: Anchor) {
        let x0 = start(x, text::width(s, px), anchor);
        #[expect(clippy::cast_possible_truncation, reason = "pixel rows")]
        let baseline = (y + 0.5).floor() as i32;
        let (width, height) = (self.pixmap.width() as usize, self.pixmap.height() as usize);
        let data = self.pixmap.data_mut();
        for (c, col, quarter) in text::layout(s, px, x0) {
            let g = self.glyphs.bitmap(c, px, quarter);
            for j in 0..g.height {
                let y = baseline + g.top + i32::try_from(j).unwrap_or(i32::MAX / 2);
                let Ok(y) = usize::try_from(y) else { continue };
                if y >= height {
                    continue;
                }
                for i in 0..g.width {
                    let level = g.coverage[j * g.width + i];
                    if level == 0 {
                        continue;
                    }
                    let x = col + g.left + i32::try_from(i).unwrap_or(i32::MAX / 2);
                    let Ok(x) = usize::try_from(x) else { continue };
                    if x >= width {
                        continue;
                    }
                    let px = &mut data[4 * (y * width + x)..4 * (y * width + x + 1)];
                    blend(px, color, f32::from(level) / 16.0);
                }
            }
        }
    }
}

/// Fills `rect` with `color`, edge pixels by the fraction of them inside.
pub(crate) fn fill_rect(pixmap: &mut Pixmap, rect: Rect, color: Rgb) {
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

/// An SVG document of `width` × `height` pixels.
pub(crate) struct Svg {
    out: String,
    pending: Vec<(Vec<Point>, Pen)>,
    gradients: usize,
}

/// A number for an SVG attribute: two decimals, no trailing zeros.
struct Num(f32);

impl core::fmt::Display for Num {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let s = format!("{:.2}", self.0);
        let s = s.trim_end_matches('0').trim_end_matches('.');
        f.write_str(if s == "-0" { "0" } else { s })
    }
}

fn hex(c: Rgb) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// `s` with the characters XML gives a meaning to escaped.
pub(crate) fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

impl Svg {
    pub(crate) fn new(width: u32, height: u32) -> Self {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" \
             width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\">\n\
             <rect width=\"{width}\" height=\"{height}\" fill=\"#ffffff\"/>"
        );
        Self {
            out,
            pending: Vec::new(),
            gradients: 0,
        }
    }

    /// The finished document.
    pub(crate) fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

impl Surface for Svg {
    fn polyline(&mut self, pts: &[Point], pen: Pen) {
        if pts.len() >= 2 && pen.width > 0.0 {
            self.pending.push((pts.to_vec(), pen));
        }
    }

    fn paint(&mut self, color: Rgb, alpha: f32) {
        let pending = core::mem::take(&mut self.pending);
        // One path per run of polylines with the same pen.
        let mut i = 0;
        while i < pending.len() {
            let pen = pending[i].1;
            let mut d = String::new();
            let mut j = i;
            while j < pending.len() && same_pen(pending[j].1, pen) {
                for (k, p) in pending[j].0.iter().enumerate() {
                    let _ = write!(
                        d,
                        "{}{} {}",
                        if k == 0 { "M" } else { "L" },
                        Num(p.x),
                        Num(p.y)
                    );
                }
                j += 1;
            }
            let _ = write!(
                self.out,
                "<path d=\"{d}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" \
                 stroke-linecap=\"{}\" stroke-linejoin=\"round\"",
                hex(color),
                Num(pen.width),
                if pen.cap == Cap::Butt {
                    "butt"
                } else {
                    "round"
                }
            );
            if alpha < 1.0 {
                let _ = write!(self.out, " stroke-opacity=\"{}\"", Num(alpha));
            }
            if let Some([on, off]) = pen.dash {
                let _ = write!(self.out, " stroke-dasharray=\"{} {}\"", Num(on), Num(off));
            }
            self.out.push_str("/>\n");
            i = j;
        }
    }

    fn fill_rect(&mut self, rect: Rect, color: Rgb) {
        let _ = writeln!(
            self.out,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>",
            Num(rect.left()),
            Num(rect.top()),
            Num(rect.width()),
            Num(rect.height()),
            hex(color)
        );
    }

    fn sphere(&mut self, cx: f32, cy: f32, r: f32) {
        let id = format!("sphere{}", self.gradients);
        self.gradients += 1;
        let [fill, limb] = [crate::canvas::SPHERE_FILL, crate::canvas::SPHERE_LIMB].map(hex);
        let _ = writeln!(
            self.out,
            "<defs><radialGradient id=\"{id}\" gradientUnits=\"userSpaceOnUse\" cx=\"{x}\" \
             cy=\"{y}\" r=\"{r}\"><stop offset=\"{start}\" stop-color=\"{fill}\"/><stop \
             offset=\"1\" stop-color=\"{limb}\"/></radialGradient></defs>\n<circle cx=\"{x}\" \
             cy=\"{y}\" r=\"{r}\" fill=\"url(#{id})\"/>",
            x = Num(cx),
            y = Num(cy),
            r = Num(r),
            start = Num(crate::canvas::LIMB_START),
        );
    }

    fn text(&mut self, x: f32, y: f32, s: &str, px: f32, color: Rgb, anchor: Anchor) {
        let _ = writeln!(
            self.out,
            "<text x=\"{}\" y=\"{}\" font-family=\"DejaVu Sans, Verdana, sans-serif\" \
             font-size=\"{}\" fill=\"{}\"{}>{}</text>",
            Num(x),
            Num((y + 0.5).floor()),
            Num(px),
            hex(color),
            match anchor {
                Anchor::Start => "",
                Anchor::Middle => " text-anchor=\"middle\"",
                Anchor::End => " text-anchor=\"end\"",
            },
            escape(s)
        );
    }
}

fn same_pen(a: Pen, b: Pen) -> bool {
    a.width.to_bits() == b.width.to_bits()
        && a.cap == b.cap
        && a.dash.map(|d| d.map(f32::to_bits)) == b.dash.map(|d| d.map(f32::to_bits))
}
