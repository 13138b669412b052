// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The plot strips: speed (or angular speed), or velocity components, against the parameter,
//! with labelled axes, tick numbers and each curve's joints.

use tiny_skia::{Point, Rect};

use crate::canvas::Rgb;
use crate::stroke::{Cap, Pen};
use crate::surface::{Anchor, Surface};
use crate::text::CAP_HEIGHT;

/// The grey of the frame and the axes.
const GREY: Rgb = [0xc3, 0xc9, 0xd1];
/// The colour of the strip's text.
pub(crate) const INK: Rgb = [0x3a, 0x41, 0x4a];

/// One polyline family of a plot, one polyline per piece (so jumps at joints stay visible).
pub(crate) struct Series {
    pub(crate) color: Rgb,
    /// Dash and gap (pixels at 512 px), or solid.
    pub(crate) dash: Option<[f32; 2]>,
    pub(crate) pieces: Vec<Vec<(f64, f64)>>,
    /// The joints to mark (empty for the second and third component of a curve).
    pub(crate) joints: Vec<f64>,
}

/// One strip: what it plots and its labels.
pub(crate) struct Panel {
    /// The quantity and its unit, above the plot.
    pub(crate) quantity: String,
    /// The time axis's name, right of its numbers.
    pub(crate) time: &'static str,
    /// Whether values may be negative (the zero line is then inside the plot).
    pub(crate) signed: bool,
    pub(crate) series: Vec<Series>,
}

/// The strip's text size in pixels per em at scale 1.
pub(crate) const LABEL_EM: f32 = 14.0;

/// The size of the strip's text (pixels per em) at `scale` (pixels per pixel-at-512).
pub(crate) fn label_px(scale: f32) -> f32 {
    (LABEL_EM * scale).max(8.0)
}

/// Draws the strip's frame into `area` (pixels): a light fill and a thin border. It does not
/// depend on the curves, so it belongs to the backdrop.
pub(crate) fn draw_frame(surface: &mut dyn Surface, area: Rect, scale: f32) {
    surface.fill_rect(area, [0xf6, 0xf7, 0xf9]);
    let (l, t, r, b) = (area.left(), area.top(), area.right(), area.bottom());
    let border = [(l, t), (r, t), (r, b), (l, b), (l, t)].map(|(x, y)| Point::from_xy(x, y));
    surface.polyline(&border, Pen::round(0.8 * scale));
    surface.paint(GREY, 1.0);
}

/// Ticks at round numbers (1, 2 or 5 × 10ⁿ apart, about `target` of them) in `[lo, hi]`, and
/// the decimals they need.
pub(crate) fn ticks(lo: f64, hi: f64, target: f64) -> (Vec<f64>, usize) {
    let span = hi - lo;
    if !(span > 0.0 && span.is_finite()) || target < 1.0 {
        return (vec![lo], 0);
    }
    let raw = span / target;
    let mag = libm::pow(10.0, libm::floor(libm::log10(raw)));
    let n = raw / mag;
    let step = mag
        * if n < 1.5 {
            1.0
        } else if n < 3.5 {
            2.0
        } else if n < 7.5 {
            5.0
        } else {
            10.0
        };
    #[expect(clippy::cast_possible_truncation, reason = "a few ticks")]
    let (first, last) = (
        libm::ceil(lo / step - 1e-9) as i64,
        libm::floor(hi / step + 1e-9) as i64,
    );
    #[expect(clippy::cast_precision_loss, reason = "a few ticks")]
    let values = (first..=last.min(first + 40))
        .map(|k| k as f64 * step)
        .collect();
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a few decimals"
    )]
    let decimals = if step >= 1.0 {
        0
    } else {
        (-libm::floor(libm::log10(step) + 1e-9)).clamp(0.0, 12.0) as usize
    };
    (values, decimals)
}

/// [`ticks`] over `[lo, hi]` drawn across `length` pixels, as many as fit with their numbers
/// (at `px`) apart by at least `gap` pixels.
fn fitting_ticks(lo: f64, hi: f64, length: f64, px: f32, gap: f32) -> (Vec<f64>, usize) {
    let mut target = (length / f64::from(4.0 * px)).max(1.0);
    loop {
        let (t, d) = ticks(lo, hi, target);
        let widest = t
            .iter()
            .map(|&v| crate::text::width(&format_number(v, d), px))
            .fold(0.0, f32::max);
        #[expect(clippy::cast_precision_loss, reason = "a few ticks")]
        let needed = f64::from(widest + gap) * t.len() as f64;
        if needed <= length || target <= 1.0 {
            return (t, d);
        }
        target = (target * 0.7).max(1.0);
    }
}

/// A tick number with `decimals` decimals and a true minus sign.
pub(crate) fn format_number(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        return s.trim_start_matches('-').to_owned();
    }
    s.replace('-', "−")
}

/// Draws `panel` into the strip's `area` (pixels), over the time range `time`. Returns the
/// plot's axes box `[left, top, right, bottom]` (pixels; `left` is `time[0]`, `right`
/// `time[1]`), or `None` for an empty time range (nothing is drawn).
pub(crate) fn draw(
    surface: &mut dyn Surface,
    area: Rect,
    scale: f32,
    panel: &Panel,
    time: [f64; 2],
) -> Option<[f32; 4]> {
    let [t0, t1] = time;
    if t1.partial_cmp(&t0) != Some(core::cmp::Ordering::Greater) {
        return None;
    }
    let (mut vmin, mut vmax) = (0.0_f64, 0.0_f64);
    for s in &panel.series {
        for &(_, v) in s.pieces.iter().flatten() {
            vmin = vmin.min(v);
            vmax = vmax.max(v);
        }
    }
    let (lo, hi) = if panel.signed {
        let m = vmax.max(-vmin);
        let m = if m > 0.0 && m.is_finite() { m } else { 1.0 };
        (-1.08 * m, 1.08 * m)
    } else {
        let m = if vmax > 0.0 && vmax.is_finite() {
            vmax
        } else {
            1.0
        };
        (0.0, 1.08 * m)
    };
    let px = label_px(scale);
    let pad = 6.0 * scale;
    let cap = CAP_HEIGHT * px;
    // The quantity above the plot (smaller where it would not fit), the time numbers below it.
    let room = area.width() - 2.0 * pad;
    let wide = crate::text::width(&panel.quantity, px);
    let qpx = if wide > room { px * room / wide } else { px };
    surface.text(
        area.left() + pad,
        area.top() + pad + cap,
        &panel.quantity,
        qpx,
        INK,
        Anchor::Start,
    );
    let (y1, y0) = (
        area.top() + 2.0 * pad + cap,
        area.bottom() - pad - 1.5 * cap - 4.0 * scale,
    );
    let height = f64::from(y0 - y1);
    let (vticks, vdec) = ticks(lo, hi, (height / f64::from(24.0 * scale)).max(1.0));
    let vlabels: Vec<String> = vticks.iter().map(|&v| format_number(v, vdec)).collect();
    let label_w = vlabels
        .iter()
        .map(|s| crate::text::width(s, px))
        .fold(0.0, f32::max);
    // Room on the right for the time axis's name, and half of the last number.
    let time_w = crate::text::width(panel.time, px);
    let last = crate::text::width(&format_number(t1, 2), px);
    let (x0, x1) = (
        area.left() + pad + label_w + 6.0 * scale,
        area.right() - pad - time_w - 0.5 * last - 6.0 * scale,
    );
    let width = f64::from(x1 - x0);
    #[expect(clippy::cast_possible_truncation, reason = "pixels")]
    let map = |t: f64, v: f64| {
        let x = f64::from(x0) + (t - t0) / (t1 - t0) * width;
        let y = f64::from(y0) - (v - lo) / (hi - lo) * height;
        (x as f32, y as f32)
    };
    let thin = Pen {
        width: 0.8 * scale,
        cap: Cap::Butt,
        dash: None,
    };
    // Value ticks and numbers.
    let mut axis = Vec::new();
    for (v, label) in vticks.iter().zip(&vlabels) {
        let (_, y) = map(t0, *v);
        axis.push([Point::from_xy(x0 - 3.0 * scale, y), Point::from_xy(x0, y)]);
        surface.text(x0 - 4.0 * scale, y + 0.5 * cap, label, px, INK, Anchor::End);
    }
    // The time axis: the zero line (the bottom for speeds), ticks and numbers.
    let (_, yz) = map(t0, 0.0);
    axis.push([Point::from_xy(x0, y0), Point::from_xy(x1, y0)]);
    axis.push([Point::from_xy(x0, y0), Point::from_xy(x0, y1)]);
    if panel.signed {
        axis.push([Point::from_xy(x0, yz), Point::from_xy(x1, yz)]);
    }
    let (tticks, tdec) = fitting_ticks(t0, t1, width, px, 10.0 * scale);
    // Below the value numbers' half height at zero; a number at the left edge starts there
    // rather than reaching back under the value numbers, so that the two zeros stay apart.
    let numbers = y0 + 1.5 * cap + 2.0 * scale;
    for &t in &tticks {
        let (x, _) = map(t, 0.0);
        axis.push([Point::from_xy(x, y0), Point::from_xy(x, y0 + 3.0 * scale)]);
        let anchor = if x - x0 < 0.5 * scale {
            Anchor::Start
        } else {
            Anchor::Middle
        };
        surface.text(x, numbers, &format_number(t, tdec), px, INK, anchor);
    }
    for a in &axis {
        surface.polyline(a, thin);
    }
    surface.paint([0x8a, 0x93, 0x9e], 1.0);
    surface.text(
        area.right() - pad,
        numbers,
        panel.time,
        px,
        INK,
        Anchor::End,
    );
    // Each curve's joints: faint lines in its colour, and a tick on the axis.
    for s in &panel.series {
        if s.joints.is_empty() {
            continue;
        }
        for &j in &s.joints {
            let (x, _) = map(j, 0.0);
            surface.polyline(&[Point::from_xy(x, y0), Point::from_xy(x, y1)], thin);
        }
        surface.paint(s.color, 0.22);
        for &j in &s.joints {
            let (x, _) = map(j, 0.0);
            surface.polyline(
                &[Point::from_xy(x, y0), Point::from_xy(x, y0 - 5.0 * scale)],
                Pen {
                    width: 1.4 * scale,
                    cap: Cap::Butt,
                    dash: None,
                },
            );
        }
        surface.paint(s.color, 1.0);
    }
    let mut pts = Vec::new();
    for s in &panel.series {
        let line = Pen {
            width: 1.6 * scale,
            cap: Cap::Butt,
            dash: s.dash.map(|d| d.map(|x| x * scale)),
        };
        for piece in &s.pieces {
            pts.clear();
            pts.extend(piece.iter().map(|&(t, v)| {
                let (x, y) = map(t, v);
                Point::from_xy(x, y)
            }));
            surface.polyline(&pts, line);
        }
        surface.paint(s.color, 1.0);
    }
    Some([x0, y1, x1, y0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_numbers() {
        let (t, d) = ticks(0.0, 5.5, 6.0);
        assert_eq!(t, [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
        assert_eq!(d, 0);
        let (t, d) = ticks(0.0, 0.93, 4.0);
        assert_eq!(d, 1);
        assert_eq!(t.len(), 5, "{t:?}");
        assert_eq!(format_number(t[2], d), "0.4");
        let (t, _) = ticks(0.0, 27.0, 6.0);
        assert_eq!(t, [0.0, 5.0, 10.0, 15.0, 20.0, 25.0]);
    }

    #[test]
    fn numbers_have_a_true_minus_and_no_negative_zero() {
        assert_eq!(format_number(-1.5, 1), "−1.5");
        assert_eq!(format_number(-0.0001, 2), "0.00");
        assert_eq!(format_number(2.0, 0), "2");
    }
}
