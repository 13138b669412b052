// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The rasterizer: anti-aliased strokes of polylines by distance. Every line of a frame (curves,
//! arcs, graticule, silhouette, plot) and every marker (a disc or a square is one thick segment)
//! goes through here.
//!
//! tiny-skia strokes a path by building its outline and filling it with 4 × 4 supersampling;
//! for the long, thin, many-segment polylines of a frame that cost three quarters of the
//! instructions of an 800 px S³ frame, and its rasterizer was a fifth of the wasm binary. Here
//! each segment is a capsule (the points within half the width of it): a pixel's coverage is
//! `clamp(w/2 + 1/2 − d, 0, 1)`, with `d` the distance from the pixel centre to the segment,
//! the usual one-pixel box-filter estimate. A polyline's segments are merged by the *largest*
//! coverage per pixel in a buffer, so joints are round and a translucent line never darkens
//! where its segments overlap; then the buffer is rounded to sixteenths and blended once,
//! source-over, into the pixmap. Butt ends (of dashes) cover the part of the pixel inside.
//!
//! Everything is f32 arithmetic with `sqrt` (correctly rounded in IEEE 754) and integer
//! blending, so native and wasm builds give the same bytes. The buffer costs four bytes per
//! pixel and is kept in the caller's [`RenderCache`](crate::RenderCache) between frames of one
//! size.

use tiny_skia::{Pixmap, Point};

use crate::canvas::Rgb;

/// How a stroke ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Cap {
    /// A half disc beyond the end point.
    Round,
    /// Square at the end point.
    Butt,
}

/// The geometry of a stroke.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pen {
    /// Width in pixels. Lines thinner than a pixel are drawn a pixel wide and fainter.
    pub(crate) width: f32,
    /// The ends of the polyline (joints are always round). Dashes have butt ends.
    pub(crate) cap: Cap,
    /// Dash and gap lengths in pixels, starting with a dash at the first point.
    pub(crate) dash: Option<[f32; 2]>,
}

impl Pen {
    /// A solid line with round ends.
    pub(crate) fn round(width: f32) -> Self {
        Self {
            width,
            cap: Cap::Round,
            dash: None,
        }
    }
}

/// Pending coverage of the strokes added since the last [`Strokes::paint`].
pub(crate) struct Strokes {
    width: usize,
    height: usize,
    /// Row length of `coverage`: `width` rounded up to whole blocks of [`LANES`].
    stride: usize,
    coverage: Vec<f32>,
    /// The touched pixels, as runs `(row, [start, end))`, possibly overlapping.
    runs: Vec<(usize, [usize; 2])>,
    /// Per row, the index in `runs` of its latest run ([`NONE`] if none), so that the runs of
    /// consecutive segments of a line merge instead of being blended over twice.
    latest: Vec<usize>,
    /// The opacity factor of sub-pixel lines (their width), applied when painting so that
    /// faint lines are not lost to the rounding of coverage. Strokes painted together share it.
    fade: f32,
}

/// No run yet on a row.
const NONE: usize = usize::MAX;

/// Pixels computed together (the width of the vector loop).
const LANES: usize = 4;

/// One segment's capsule, in the form the per-pixel loop wants.
struct Capsule {
    /// The start point.
    a: Point,
    /// The unit direction.
    u: (f32, f32),
    /// The nearest point of the centre line is clamped to `[lo, hi]` along it: the segment
    /// (round ends), or the whole line beyond a butt end.
    lo: f32,
    hi: f32,
    /// Butt ends: the positions along the line where coverage is cut (±∞ for round ends).
    cut: [f32; 2],
    reach: f32,
}

impl Capsule {
    /// Raises the coverage of `row`, whose first pixel is column `first`, on the pixel row
    /// centred at `yc`.
    #[inline(always)]
    fn row<const BUTT: bool>(&self, row: &mut [f32], first: i32, yc: f32) {
        let (ux, uy) = self.u;
        let py = yc - self.a.y;
        for (block, cs) in (0..).zip(row.chunks_exact_mut(LANES)) {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_possible_wrap,
                reason = "short rows"
            )]
            let x0 = first + block * LANES as i32;
            for (x, c) in (x0..).zip(cs) {
                // Columns as i32: a conversion from usize costs several instructions.
                #[expect(clippy::cast_precision_loss, reason = "small column numbers")]
                let px = x as f32 + 0.5 - self.a.x;
                let along = px * ux + py * uy;
                // The nearest point of the segment, or of its line beyond a butt end.
                let t = clamp(along, self.lo, self.hi);
                let (qx, qy) = (px - t * ux, py - t * uy);
                let d = length(qx, qy);
                let mut v = clamp(self.reach - d, 0.0, 1.0);
                if BUTT {
                    v = v
                        * clamp(along - self.cut[0] + 0.5, 0.0, 1.0)
                        * clamp(self.cut[1] - along + 0.5, 0.0, 1.0);
                }
                *c = if v > *c { v } else { *c };
            }
        }
    }
}

impl Strokes {
    /// An empty buffer for a `width` × `height` pixmap.
    pub(crate) fn new(width: u32, height: u32) -> Self {
        let (width, height) = (width as usize, height as usize);
        let stride = width.div_ceil(LANES) * LANES;
        Self {
            width,
            height,
            stride,
            coverage: vec![0.0; stride * height],
            runs: Vec::new(),
            latest: vec![NONE; height],
            fade: 1.0,
        }
    }

    /// Runs `f` with an empty buffer for a `width` × `height` pixmap: the one `kept` holds
    /// when it has that size, which is put back for the next call when `f` leaves it empty
    /// (painting does), so that a frame does not clear megabytes of coverage first.
    pub(crate) fn with<R>(
        kept: &mut Option<Self>,
        width: u32,
        height: u32,
        f: impl FnOnce(&mut Self) -> R,
    ) -> R {
        let mut strokes = kept
            .take()
            .filter(|s| (s.width, s.height) == (width as usize, height as usize))
            .unwrap_or_else(|| Self::new(width, height));
        let out = f(&mut strokes);
        if strokes.runs.is_empty() {
            *kept = Some(strokes);
        }
        out
    }

    /// Adds a polyline (pixel coordinates) to the pending coverage.
    pub(crate) fn polyline(&mut self, pts: &[Point], pen: Pen) {
        if pen.width.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
            return;
        }
        // Sub-pixel lines: one pixel wide at a fraction of the opacity.
        let half = 0.5 * pen.width.max(1.0);
        self.fade = pen.width.min(1.0);
        let butt = pen.cap == Cap::Butt;
        let last = pts.len().saturating_sub(2);
        match pen.dash {
            // Patterns finer than a pixel are drawn solid.
            Some([on, off]) if on > 0.0 && off > 0.0 && on + off >= 1.0 => {
                let mut dashes = Dashes::new(on, off);
                for (i, w) in pts.windows(2).enumerate() {
                    let ends = [butt && i == 0, butt && i == last];
                    dashes.segment(w[0], w[1], ends, |a, b, ends| {
                        self.segment(a, b, half, ends);
                    });
                }
            }
            _ => {
                for (i, w) in pts.windows(2).enumerate() {
                    self.segment(w[0], w[1], half, [butt && i == 0, butt && i == last]);
                }
            }
        }
    }

    /// Adds one segment as a capsule of radius `half`; `butt` squares off its start or end.
    fn segment(&mut self, a: Point, b: Point, half: f32, butt: [bool; 2]) {
        // Pixel centres farther than `reach` from the centre line get nothing.
        let reach = half + 0.5;
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len = length(dx, dy);
        if !len.is_finite() || !a.x.is_finite() || !a.y.is_finite() {
            return;
        }
        let (ux, uy) = if len > 1e-6 {
            (dx / len, dy / len)
        } else {
            (1.0, 0.0)
        };
        // Round ends clamp the nearest point to the segment; butt ends cut the line instead.
        let (lo, hi) = (
            if butt[0] { f32::NEG_INFINITY } else { 0.0 },
            if butt[1] { f32::INFINITY } else { len },
        );
        let cut = [
            if butt[0] { 0.0 } else { f32::NEG_INFINITY },
            if butt[1] { len } else { f32::INFINITY },
        ];
        let cap = Capsule {
            a,
            u: (ux, uy),
            lo,
            hi,
            cut,
            reach,
        };
        let rows = pixels(a.y.min(b.y) - reach, a.y.max(b.y) + reach, self.height);
        // Reciprocals, not divisions per row (a pixel the rounding might leave out of a row's
        // range is one whose coverage rounds to zero anyway).
        let (inv_dy, inv_uy) = (dy.recip(), uy.recip());
        for y in rows {
            #[expect(clippy::cast_precision_loss, reason = "small row numbers")]
            let yc = y as f32 + 0.5;
            // The segment's points within `reach` vertically of this row, widened by `reach`.
            let (t0, t1) = if dy.abs() > 1e-6 {
                let (s0, s1) = ((yc - reach - a.y) * inv_dy, (yc + reach - a.y) * inv_dy);
                (s0.min(s1).max(0.0), s0.max(s1).min(1.0))
            } else {
                (0.0, 1.0)
            };
            if t0 > t1 {
                continue;
            }
            let (x0, x1) = (a.x + dx * t0, a.x + dx * t1);
            let (mut x0, mut x1) = (x0.min(x1) - reach, x0.max(x1) + reach);
            // The capsule also lies in the band within `reach` of the segment's line.
            let py = yc - a.y;
            if uy.abs() > 1e-3 {
                let (b0, b1) = ((py * ux - reach) * inv_uy, (py * ux + reach) * inv_uy);
                x0 = x0.max(a.x + b0.min(b1));
                x1 = x1.min(a.x + b0.max(b1));
            }
            let columns = pixels(x0, x1, self.width);
            if columns.is_empty() {
                continue;
            }
            let (left, right) = (columns.start, columns.end);
            // Whole blocks of `LANES` pixels, so the loop vectorises without a scalar tail: the
            // last block runs past `right` (rows are padded to a multiple of `LANES`), or the
            // first starts before `left` near the row's end.
            let n = (right - left).div_ceil(LANES) * LANES;
            let left = left.min(self.stride - n);
            let right = left + n;
            let row = &mut self.coverage[y * self.stride + left..y * self.stride + right];
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_possible_wrap,
                reason = "columns of a pixmap at most 4096 wide"
            )]
            let first = left as i32;
            if butt == [false, false] {
                cap.row::<false>(row, first, yc);
            } else {
                cap.row::<true>(row, first, yc);
            }
            match self.runs.get_mut(self.latest[y]) {
                Some((_, run)) if left <= run[1] && run[0] <= right => {
                    *run = [run[0].min(left), run[1].max(right)];
                }
                _ => {
                    self.latest[y] = self.runs.len();
                    self.runs.push((y, [left, right]));
                }
            }
        }
    }

    /// Blends the pending coverage in `color` at opacity `alpha` over `pixmap` (source-over,
    /// premultiplied) and clears it.
    pub(crate) fn paint(&mut self, pixmap: &mut Pixmap, color: Rgb, alpha: f32) {
        debug_assert_eq!(
            (pixmap.width() as usize, pixmap.height() as usize),
            (self.width, self.height),
            "a buffer of the pixmap's size"
        );
        // Coverage is rounded to sixteenths (see `LEVELS`): one opacity per level.
        let alpha = alpha * core::mem::replace(&mut self.fade, 1.0);
        let opacity: [u32; LEVELS + 1] = core::array::from_fn(|k| {
            #[expect(clippy::cast_precision_loss, reason = "0 to 16")]
            let c = k as f32 / LEVELS as f32;
            opacity256(c * alpha)
        });
        let src = Packed::new(color);
        let data = pixmap.data_mut();
        // A pixel in several runs is blended at its first visit, which clears it.
        for (y, [left, right]) in self.runs.drain(..) {
            self.latest[y] = NONE;
            let row = y * self.stride;
            let visible = left..right.min(self.width).max(left);
            let pixels = data
                [4 * (y * self.width + visible.start)..4 * (y * self.width + visible.end)]
                .chunks_exact_mut(4);
            for (c, px) in self.coverage[row + visible.start..row + visible.end]
                .iter_mut()
                .zip(pixels)
            {
                if *c <= 0.0 {
                    continue;
                }
                // Truncation is rounding down here (c ≥ 0), and cheaper than `floor`.
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "0 to LEVELS"
                )]
                let level = (core::mem::take(c) * LEVELS as f32 + 0.5) as usize;
                blend_packed(px, src, opacity[level.min(LEVELS)]);
            }
            // The padding past the pixmap's edge.
            self.coverage[row + visible.end..row + right].fill(0.0);
        }
    }
}

/// Coverage is rounded to this many levels: as many as tiny-skia's 4 × 4 supersampling gives,
/// which keeps edges smooth and the PNGs small (every extra level is a new colour to
/// compress).
const LEVELS: usize = 16;

/// The pixels (rows or columns, below `end`) that meet the interval `[lo, hi]`; empty when
/// none do, or when a bound is NaN.
pub(crate) fn pixels(lo: f32, hi: f32, end: usize) -> core::ops::Range<usize> {
    if lo.is_nan() || hi.is_nan() {
        return 0..0;
    }
    #[expect(clippy::cast_precision_loss, reason = "pixmap sizes are at most 4096")]
    let end = end as f32;
    let (lo, hi) = (lo.floor().max(0.0), hi.ceil().min(end));
    if lo < hi {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "clamped to the pixmap"
        )]
        let range = lo as usize..hi as usize;
        range
    } else {
        0..0
    }
}

/// The length of `(x, y)`. Not `f32::hypot`, which calls the platform's C library and so may
/// differ between native and wasm builds; `sqrt` is correctly rounded everywhere.
#[expect(clippy::imprecise_flops, reason = "identical bits on every target")]
pub(crate) fn length(x: f32, y: f32) -> f32 {
    (x * x + y * y).sqrt()
}

/// `x` clamped to `[lo, hi]`, written so that it compiles to one max and one min.
fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    let x = if x < lo { lo } else { x };
    if x > hi { hi } else { x }
}

/// Blends `color` at opacity `a` (0 to 1) over a premultiplied RGBA pixel, source-over: per
/// channel `s·a + d·(1 − a)` (with `s = 255` for alpha), `a` in 256ths, rounded to nearest.
pub(crate) fn blend(px: &mut [u8], color: Rgb, a: f32) {
    blend_packed(px, Packed::new(color), opacity256(a));
}

/// An opacity from 0 to 1 in 256ths, rounded to nearest.
fn opacity256(a: f32) -> u32 {
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "in 0..=256"
    )]
    let a = (a.clamp(0.0, 1.0) * 256.0 + 0.5) as u32;
    a
}

/// An opaque colour with its red and blue, and its green and alpha, in the low bytes of the
/// two 16-bit halves of a word each: two channels per multiplication.
#[derive(Clone, Copy)]
struct Packed {
    rb: u32,
    ga: u32,
}

impl Packed {
    fn new(c: Rgb) -> Self {
        Self {
            rb: u32::from(c[0]) | u32::from(c[2]) << 16,
            ga: u32::from(c[1]) | 0xff << 16,
        }
    }
}

/// [`blend`] with the opacity in 256ths (0 to 256). Each half-word holds at most
/// `255·256 + 128 < 2¹⁶`, so channels never carry into each other; 256 gives the colour exactly
/// and 0 leaves the pixel.
fn blend_packed(px: &mut [u8], src: Packed, a: u32) {
    let d = u32::from_le_bytes([px[0], px[1], px[2], px[3]]);
    let (rb, ga) = (d & 0x00ff_00ff, (d >> 8) & 0x00ff_00ff);
    let mix = |s: u32, d: u32| ((s * a + d * (256 - a) + 0x0080_0080) >> 8) & 0x00ff_00ff;
    px.copy_from_slice(&(mix(src.rb, rb) | mix(src.ga, ga) << 8).to_le_bytes());
}

/// Splits a polyline into dashes as it is walked segment by segment.
struct Dashes {
    on: f32,
    off: f32,
    /// Whether the pattern is in a dash, and the length left of the current dash or gap.
    in_dash: bool,
    left: f32,
}

impl Dashes {
    fn new(on: f32, off: f32) -> Self {
        Self {
            on,
            off,
            in_dash: true,
            left: on,
        }
    }

    /// Calls `emit(a, b, butt)` for the dashed parts of `a`–`b`, with butt ends where a dash
    /// starts or stops, and where the polyline does (`ends`: whether this segment starts or
    /// ends it with a butt cap) inside a dash.
    fn segment(
        &mut self,
        a: Point,
        b: Point,
        ends: [bool; 2],
        mut emit: impl FnMut(Point, Point, [bool; 2]),
    ) {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len = length(dx, dy);
        if !len.is_finite() || len <= 0.0 {
            return;
        }
        // A segment that would take more than `MAX_DASHES` dashes is drawn solid: a pattern
        // that fine is a faint solid line to the eye, and walking it would take seconds.
        if len > MAX_DASHES * (self.on + self.off) {
            emit(a, b, ends);
            return;
        }
        let at = |s: f32| Point::from_xy(a.x + dx * (s / len), a.y + dy * (s / len));
        let mut s = 0.0;
        while s < len {
            let step = self.left.min(len - s);
            // Pieces much shorter than a pixel (a dash ending just past a vertex) add nothing.
            if self.in_dash && step > 1e-3 {
                // A dash starts where its pattern length is whole, and ends where it runs out.
                let butt = [
                    self.left == self.on || (ends[0] && s == 0.0),
                    step == self.left || (ends[1] && s + step >= len),
                ];
                emit(at(s), at(s + step), butt);
            }
            s += step;
            self.left -= step;
            if self.left <= 0.0 {
                self.in_dash = !self.in_dash;
                self.left = if self.in_dash { self.on } else { self.off };
            }
        }
    }
}

/// The most dashes a segment is split into (see [`Dashes::segment`]).
const MAX_DASHES: f32 = 1e5;

#[cfg(test)]
mod tests {
    use super::*;

    fn coverage_after(pts: &[Point], pen: Pen) -> Strokes {
        let mut s = Strokes::new(64, 64);
        s.polyline(pts, pen);
        s
    }

    fn pen(width: f32) -> Pen {
        Pen {
            width,
            cap: Cap::Round,
            dash: None,
        }
    }

    #[test]
    fn horizontal_line_covers_its_width() {
        let s = coverage_after(
            &[Point::from_xy(10.0, 32.0), Point::from_xy(50.0, 32.0)],
            pen(3.0),
        );
        let at = |x: usize, y: usize| s.coverage[y * 64 + x];
        // Centres at 30.5 and 33.5 are 1.5 px away (on the edge): half covered; 31.5 and 32.5
        // fully.
        assert_eq!(at(30, 29), 0.0);
        assert_eq!(at(30, 30), 0.5);
        assert_eq!(at(30, 31), 1.0);
        assert_eq!(at(30, 32), 1.0);
        assert_eq!(at(30, 33), 0.5);
        assert_eq!(at(30, 34), 0.0);
        // The total coverage of a column is the width.
        let column: f32 = (0..64).map(|y| at(30, y)).sum();
        assert!((column - 3.0).abs() < 1e-6, "{column}");
    }

    #[test]
    fn overlapping_segments_take_the_larger_coverage() {
        // A polyline doubling back on itself covers no pixel more than fully.
        let p = [
            Point::from_xy(10.0, 20.0),
            Point::from_xy(40.0, 20.0),
            Point::from_xy(10.0, 20.5),
        ];
        let s = coverage_after(&p, pen(2.0));
        assert!(s.coverage.iter().all(|&c| (0.0..=1.0).contains(&c)));
        assert_eq!(s.coverage.iter().copied().fold(0.0, f32::max), 1.0);
    }

    #[test]
    fn dashes_follow_the_pattern() {
        // 40 px at dash 5, gap 5: dashes over [0,5], [10,15], ..., [30,35].
        let p = [Point::from_xy(0.0, 10.5), Point::from_xy(40.0, 10.5)];
        let s = coverage_after(
            &p,
            Pen {
                width: 1.0,
                cap: Cap::Butt,
                dash: Some([5.0, 5.0]),
            },
        );
        let row: Vec<f32> = (0..40).map(|x| s.coverage[10 * 64 + x]).collect();
        assert_eq!(&row[0..5], &[1.0; 5]);
        assert_eq!(&row[5..10], &[0.0; 5]);
        assert_eq!(&row[30..35], &[1.0; 5]);
        assert_eq!(&row[35..40], &[0.0; 5]);
    }

    #[test]
    fn dashes_continue_across_segments() {
        let mut d = Dashes::new(3.0, 2.0);
        let mut out = Vec::new();
        for w in [[0.0, 4.0], [4.0, 9.0]] {
            d.segment(
                Point::from_xy(w[0], 0.0),
                Point::from_xy(w[1], 0.0),
                [false, false],
                |a, b, ends| out.push((a.x, b.x, ends)),
            );
        }
        assert_eq!(out, [(0.0, 3.0, [true, true]), (5.0, 8.0, [true, true])]);
    }

    #[test]
    fn bad_points_and_widths_draw_nothing() {
        for (p, w) in [
            ([f32::NAN, 1.0], 2.0),
            ([f32::INFINITY, 1.0], 2.0),
            ([1.0, 1.0], 0.0),
            ([1.0, 1.0], f32::NAN),
            ([-1e30, 1e30], 2.0),
        ] {
            let s = coverage_after(
                &[Point::from_xy(p[0], p[1]), Point::from_xy(20.0, 20.0)],
                pen(w),
            );
            assert!(
                s.coverage
                    .iter()
                    .all(|&c| c.is_finite() && (0.0..=1.0).contains(&c))
            );
        }
    }

    #[test]
    fn a_zero_length_segment_is_a_disc() {
        // Markers are drawn this way: coverage sums to the disc's area.
        let p = Point::from_xy(30.3, 31.7);
        let s = coverage_after(&[p, p], pen(12.0));
        let area: f32 = s.coverage.iter().sum();
        let exact = core::f32::consts::PI * 36.0;
        assert!((area - exact).abs() < 0.01 * exact, "{area} vs {exact}");
    }

    #[test]
    fn butt_ends_cover_the_part_of_the_pixel_inside() {
        // A dash from x = 0 to x = 5.25: the pixel centred at 5.5 is 0.25 px past the end, so
        // a quarter of it is inside; the one at 4.5 is whole.
        let p = [Point::from_xy(0.0, 10.5), Point::from_xy(5.25, 10.5)];
        let butt = Pen {
            width: 1.0,
            cap: Cap::Butt,
            dash: None,
        };
        let s = coverage_after(&p, butt);
        let row = &s.coverage[10 * 64..11 * 64];
        assert_eq!((row[4], row[5], row[6]), (1.0, 0.25, 0.0));
        // A round end reaches half the width (0.5) further: to 5.75, three quarters of pixel 5.
        let s = coverage_after(&p, pen(1.0));
        assert_eq!(s.coverage[10 * 64 + 5], 0.75);
    }

    #[test]
    fn lines_thinner_than_a_pixel_fade_but_stay_visible() {
        // Drawn a pixel wide at a quarter of the opacity: a pixel row fully covered by a
        // quarter-pixel line is a quarter of the way from white to black.
        let mut pixmap = Pixmap::new(64, 64).expect("pixmap");
        pixmap.fill(tiny_skia::Color::WHITE);
        let mut s = Strokes::new(64, 64);
        s.polyline(
            &[Point::from_xy(0.0, 20.5), Point::from_xy(40.0, 20.5)],
            pen(0.25),
        );
        let column: f32 = (0..64).map(|y| s.coverage[y * 64 + 30]).sum();
        assert!((column - 1.0).abs() < 1e-6, "{column}");
        s.paint(&mut pixmap, [0, 0, 0], 1.0);
        assert_eq!(pixmap.pixel(30, 20).expect("pixel").red(), 191);
        // A twentieth of a pixel on the boundary between two rows: half of it in each, still
        // drawn (faintly) rather than rounded away.
        s.polyline(
            &[Point::from_xy(0.0, 40.0), Point::from_xy(40.0, 40.0)],
            pen(0.05),
        );
        s.paint(&mut pixmap, [0, 0, 0], 1.0);
        let [a, b] = [39, 40].map(|y| pixmap.pixel(30, y).expect("pixel").red());
        assert!(a == b && a < 255 && a > 245, "{a} {b}");
    }

    #[test]
    fn the_last_dash_of_a_butt_ended_line_is_butt_ended() {
        // Dash 3, gap 2 on 0 → 4 → 6.5: the second dash is cut by the line's end at 6.5.
        let mut d = Dashes::new(3.0, 2.0);
        let mut out = Vec::new();
        for (i, w) in [[0.0, 4.0], [4.0, 6.5]].into_iter().enumerate() {
            d.segment(
                Point::from_xy(w[0], 0.0),
                Point::from_xy(w[1], 0.0),
                [i == 0, i == 1],
                |a, b, ends| out.push((a.x, b.x, ends)),
            );
        }
        assert_eq!(out, [(0.0, 3.0, [true, true]), (5.0, 6.5, [true, true])]);
    }

    #[test]
    fn patterns_too_fine_to_walk_are_drawn_solid() {
        let mut d = Dashes::new(1e-3, 1e-3);
        let mut out = Vec::new();
        let (a, b) = (Point::from_xy(0.0, 0.0), Point::from_xy(1e9, 0.0));
        d.segment(a, b, [false, false], |a, b, ends| {
            out.push((a.x, b.x, ends))
        });
        assert_eq!(out, [(0.0, 1e9, [false, false])]);
        // An infinite segment gives nothing.
        d.segment(
            a,
            Point::from_xy(f32::INFINITY, 0.0),
            [false, false],
            |_, _, _| panic!("nothing to draw"),
        );
    }

    #[test]
    fn nan_bounds_give_no_pixels() {
        assert_eq!(pixels(f32::NAN, 5.0, 10), 0..0);
        assert_eq!(pixels(2.0, f32::NAN, 10), 0..0);
        assert_eq!(pixels(-3.0, 4.5, 10), 0..5);
        assert_eq!(pixels(8.5, 30.0, 10), 8..10);
    }

    #[test]
    fn blending_is_exact_at_both_ends() {
        let mut px = [10, 200, 30, 255];
        blend(&mut px, [90, 80, 70], 0.0);
        assert_eq!(px, [10, 200, 30, 255]);
        blend(&mut px, [90, 80, 70], 1.0);
        assert_eq!(px, [90, 80, 70, 255]);
        // Over a transparent pixel the result is the premultiplied colour.
        let mut px = [0, 0, 0, 0];
        blend(&mut px, [200, 100, 0], 0.5);
        assert_eq!(px, [100, 50, 0, 128]);
    }

    #[test]
    fn packed_blending_rounds_every_channel_to_nearest() {
        // Two channels share a multiplication; none may carry into its neighbour.
        for a in 0..=256_u32 {
            for s in (0..=255_u8).step_by(5) {
                for d in (0..=255_u8).step_by(3) {
                    let mut px = [d, 255 - d, d / 2, d];
                    blend_packed(&mut px, Packed::new([s, 255 - s, s / 3]), a);
                    let want = |s: u8, d: u8| {
                        let x = u32::from(s) * a + u32::from(d) * (256 - a);
                        u8::try_from((x + 128) / 256).expect("a byte")
                    };
                    let expected = [want(s, d), want(255 - s, 255 - d), want(s / 3, d / 2)];
                    assert_eq!(&px[..3], &expected, "s {s} d {d} a {a}");
                    assert_eq!(px[3], want(255, d), "alpha, s {s} d {d} a {a}");
                }
            }
        }
    }

    #[test]
    fn lines_off_the_edge_leave_the_buffer_clean() {
        // Width 10 is padded to 12 columns; a line running off the right edge touches the
        // padding, which painting must clear too.
        let mut pixmap = Pixmap::new(10, 10).expect("pixmap");
        let mut s = Strokes::new(10, 10);
        s.polyline(
            &[Point::from_xy(2.0, 5.0), Point::from_xy(30.0, 5.0)],
            pen(3.0),
        );
        assert!(
            s.coverage[5 * s.stride + 10..6 * s.stride]
                .iter()
                .any(|&c| c > 0.0)
        );
        s.paint(&mut pixmap, [0, 0, 0], 1.0);
        assert!(s.coverage.iter().all(|&c| c == 0.0));
        assert!(s.runs.is_empty());
        assert_eq!(pixmap.pixel(9, 5).expect("pixel").alpha(), 255);
    }

    #[test]
    fn the_kept_buffer_is_empty_and_of_the_asked_size() {
        let dims = |s: &mut Strokes| (s.width, s.height, s.coverage.iter().all(|&c| c == 0.0));
        let mut kept = None;
        assert_eq!(Strokes::with(&mut kept, 20, 30, dims), (20, 30, true));
        assert!(kept.is_some(), "kept for the next call");
        Strokes::with(&mut kept, 20, 30, |s| {
            s.polyline(&[Point::from_xy(1.0, 1.0); 2], pen(4.0))
        });
        // Left with pending coverage, the buffer is not kept.
        assert!(kept.is_none());
        assert_eq!(Strokes::with(&mut kept, 20, 30, dims), (20, 30, true));
        assert_eq!(Strokes::with(&mut kept, 8, 9, dims), (8, 9, true));
    }

    #[test]
    fn paint_blends_once_and_clears() {
        let mut pixmap = Pixmap::new(8, 8).expect("pixmap");
        pixmap.fill(tiny_skia::Color::WHITE);
        let mut s = Strokes::new(8, 8);
        s.polyline(
            &[Point::from_xy(0.0, 4.0), Point::from_xy(8.0, 4.0)],
            pen(2.0),
        );
        s.paint(&mut pixmap, [0, 0, 0], 0.5);
        // Rows 3 and 4 are fully covered: white at half black (255·128/256 rounded).
        let px = pixmap.pixel(3, 3).expect("pixel");
        assert_eq!((px.red(), px.alpha()), (128, 255));
        assert_eq!(pixmap.pixel(3, 1).expect("pixel").red(), 255);
        assert!(s.coverage.iter().all(|&c| c == 0.0));
    }
}
