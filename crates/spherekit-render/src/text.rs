// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Text: the outlines of an embedded DejaVu Sans subset (`fonts/`, Bitstream Vera licence),
//! laid out by their advances and rasterized here by exact signed-area accumulation.
//!
//! The rasterizer is the accumulation method of font-rs (Raph Levien, 2016: each line segment
//! adds the signed area it covers to the cells of its rows; a prefix sum along each row gives
//! the coverage). It uses f32 `+ − × ÷`, `sqrt`, `floor` and `ceil` only, in a fixed order, so
//! the glyph bitmaps, like the strokes, are the same bytes natively and in wasm. Quadratic
//! outline pieces are flattened into a number of lines that depends on their size only.
//!
//! No hinting: glyphs are placed with their baseline on a whole pixel and their origin on a
//! quarter pixel, and their bitmaps are kept by character, size and quarter in the caller's
//! [`RenderCache`](crate::RenderCache).

use std::collections::BTreeMap;

/// The subset's outlines (see `scripts/font_subset.py` for the format).
static GLYPHS: &[u8] = include_bytes!("../fonts/glyphs.bin");

const HEADER: usize = 12;
const ENTRY: usize = 7;

fn u16_at(b: &[u8], i: usize) -> u16 {
    u16::from_le_bytes([b[i], b[i + 1]])
}

/// The font's units per em.
fn units_per_em() -> f32 {
    f32::from(u16_at(GLYPHS, 4))
}

/// The height of a capital letter as a fraction of the em (DejaVu Sans: 1493 / 2048).
pub(crate) const CAP_HEIGHT: f32 = 0.729;

/// A glyph of the subset: its advance (font units) and its encoded outline.
struct Glyph {
    advance: u16,
    commands: &'static [u8],
}

/// The glyph for `c`, or for `?` when the subset does not have it.
fn glyph(c: char) -> Glyph {
    lookup(c).or_else(|| lookup('?')).unwrap_or(Glyph {
        advance: 0,
        commands: &[],
    })
}

fn count() -> usize {
    usize::from(u16_at(GLYPHS, 10))
}

/// The glyph at `index` of the table (`None` past its end).
fn entry(index: usize) -> Option<Glyph> {
    let n = count();
    if index >= n {
        return None;
    }
    let stream = HEADER + n * ENTRY;
    let e = HEADER + index * ENTRY;
    let off = stream + usize::from(u16_at(GLYPHS, e + 5));
    let end = if index + 1 < n {
        stream + usize::from(u16_at(GLYPHS, e + ENTRY + 5))
    } else {
        GLYPHS.len()
    };
    Some(Glyph {
        advance: u16_at(GLYPHS, e + 3),
        commands: GLYPHS.get(off..end)?,
    })
}

fn lookup(c: char) -> Option<Glyph> {
    let (mut lo, mut hi) = (0, count());
    while lo < hi {
        let mid = (lo + hi) / 2;
        let e = HEADER + mid * ENTRY;
        let cp = u32::from_le_bytes([GLYPHS[e], GLYPHS[e + 1], GLYPHS[e + 2], 0]);
        match cp.cmp(&u32::from(c)) {
            core::cmp::Ordering::Less => lo = mid + 1,
            core::cmp::Ordering::Greater => hi = mid,
            core::cmp::Ordering::Equal => return entry(mid),
        }
    }
    None
}

/// Whether the font has a glyph for `c`.
#[cfg(test)]
pub(crate) fn has_glyph(c: char) -> bool {
    lookup(c).is_some()
}

/// The advance of `c` at `px` pixels per em.
pub(crate) fn advance(c: char, px: f32) -> f32 {
    f32::from(glyph(c).advance) * px / units_per_em()
}

/// The width of `s` at `px` pixels per em.
pub(crate) fn width(s: &str, px: f32) -> f32 {
    s.chars().map(|c| advance(c, px)).sum()
}

/// A glyph's coverage bitmap, placed relative to its origin on the baseline.
#[derive(Debug)]
pub(crate) struct Bitmap {
    /// Offset of the bitmap's top-left pixel from the origin's pixel.
    pub(crate) left: i32,
    pub(crate) top: i32,
    pub(crate) width: usize,
    pub(crate) height: usize,
    /// Coverage in sixteenths (rounded to even ones: eighths, which keeps the PNGs small),
    /// row by row.
    pub(crate) coverage: Vec<u8>,
}

/// The font units a stored coordinate counts (see `scripts/font_subset.py`).
const QUANTUM: f32 = 2.0;

/// Reads an unsigned LEB128 number at `*i`.
fn varint(b: &[u8], i: &mut usize) -> u32 {
    let (mut v, mut shift) = (0_u32, 0);
    while let Some(&byte) = b.get(*i) {
        *i += 1;
        v |= u32::from(byte & 0x7f) << shift;
        shift += 7;
        if byte < 0x80 || shift > 28 {
            break;
        }
    }
    v
}

/// A zigzag-coded difference.
fn unzigzag(z: u32) -> i32 {
    #[expect(clippy::cast_possible_wrap, reason = "zigzag decoding")]
    let v = (z >> 1) as i32 ^ -((z & 1) as i32);
    v
}

/// The outline of `c` at `px` pixels per em in pixel coordinates (y down), the origin at
/// `(dx, 0)`, as closed polylines.
fn outline(c: char, px: f32, dx: f32) -> Vec<Vec<(f32, f32)>> {
    let mut out = Vec::new();
    outline_into(glyph(c).commands, px, (dx, 0.0), 0, &mut out);
    out
}

/// The contours of the glyph data `b` with its origin at `origin` (pixels), appended to
/// `out`; a composite glyph's components at their offsets (nested at most a few deep, as the
/// accents of the subset are).
fn outline_into(
    b: &[u8],
    px: f32,
    origin: (f32, f32),
    depth: usize,
    out: &mut Vec<Vec<(f32, f32)>>,
) {
    let mut i = 0;
    let head = varint(b, &mut i);
    if head & 1 == 1 {
        let s = px / units_per_em();
        for _ in 0..head >> 1 {
            let index = varint(b, &mut i) as usize;
            let ox = unzigzag(varint(b, &mut i));
            let oy = unzigzag(varint(b, &mut i));
            if let Some(g) = entry(index).filter(|_| depth < 4) {
                #[expect(clippy::cast_precision_loss, reason = "small font coordinates")]
                let at = (origin.0 + ox as f32 * s, origin.1 - oy as f32 * s);
                outline_into(g.commands, px, at, depth + 1, out);
            }
        }
        return;
    }
    let k = QUANTUM * px / units_per_em();
    let (dx, dy) = origin;
    let mut last = [0_i32; 2];
    // The next point; with `flagged`, also whether the piece it starts is a quadratic.
    let mut point = |i: &mut usize, flagged: bool| {
        let zx = varint(b, i);
        let (zx, quad) = if flagged {
            (zx >> 1, zx & 1 == 1)
        } else {
            (zx, false)
        };
        last[0] += unzigzag(zx);
        last[1] += unzigzag(varint(b, i));
        #[expect(clippy::cast_precision_loss, reason = "small font coordinates")]
        let y = -(last[1] as f32) * k;
        // (A component's offset only where it has one: −0 stays −0 at the top level.)
        let p = (dx + last[0] as f32 * k, if dy == 0.0 { y } else { y + dy });
        (p, quad)
    };
    for _ in 0..head >> 1 {
        let pieces = varint(b, &mut i);
        let (start, _) = point(&mut i, false);
        let mut contour = vec![start];
        for _ in 0..pieces {
            let (p, quad) = point(&mut i, true);
            if quad {
                let (end, _) = point(&mut i, false);
                let p0 = *contour.last().unwrap_or(&start);
                flatten_quad(&mut contour, p0, p, end);
            } else {
                contour.push(p);
            }
        }
        out.push(contour);
    }
}

/// Appends the quadratic from `p0` through control `p1` to `p2` as lines (enough that they
/// stay within about a tenth of a pixel of it).
fn flatten_quad(out: &mut Vec<(f32, f32)>, p0: (f32, f32), p1: (f32, f32), p2: (f32, f32)) {
    let (ddx, ddy) = (p0.0 - 2.0 * p1.0 + p2.0, p0.1 - 2.0 * p1.1 + p2.1);
    let dev = ddx * ddx + ddy * ddy;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a small positive count"
    )]
    let n = if dev < 0.1 {
        1
    } else {
        1 + (3.0 * dev).sqrt().sqrt().floor().min(64.0) as usize
    };
    for i in 1..=n {
        #[expect(clippy::cast_precision_loss, reason = "small counts")]
        let t = i as f32 / n as f32;
        let u = 1.0 - t;
        out.push((
            u * u * p0.0 + 2.0 * u * t * p1.0 + t * t * p2.0,
            u * u * p0.1 + 2.0 * u * t * p1.1 + t * t * p2.1,
        ));
    }
}

/// Rasterizes `c` at `px` pixels per em with its origin `dx` (0 ≤ dx < 1) right of a pixel's
/// left edge; the baseline is the top edge of the pixel row below it.
fn rasterize(c: char, px: f32, dx: f32) -> Bitmap {
    let contours = outline(c, px, dx);
    let (mut x0, mut y0, mut x1, mut y1) = (f32::MAX, f32::MAX, f32::MIN, f32::MIN);
    for &(x, y) in contours.iter().flatten() {
        x0 = x0.min(x);
        y0 = y0.min(y);
        x1 = x1.max(x);
        y1 = y1.max(y);
    }
    if x0 > x1 {
        return Bitmap {
            left: 0,
            top: 0,
            width: 0,
            height: 0,
            coverage: Vec::new(),
        };
    }
    let (left, top) = (x0.floor(), y0.floor());
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "glyphs are a few hundred pixels at most"
    )]
    let (w, h) = (
        (x1.ceil() - left) as usize + 1,
        (y1.ceil() - top) as usize + 1,
    );
    // One spare cell per row for the area that spills past the last pixel.
    let stride = w + 2;
    let mut acc = vec![0.0_f32; stride * h];
    for contour in &contours {
        for (i, &a) in contour.iter().enumerate() {
            let b = contour[(i + 1) % contour.len()];
            line(
                &mut acc,
                stride,
                h,
                (a.0 - left, a.1 - top),
                (b.0 - left, b.1 - top),
            );
        }
    }
    let mut coverage = vec![0_u8; w * h];
    for y in 0..h {
        let mut sum = 0.0_f32;
        for x in 0..w {
            sum += acc[y * stride + x];
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "0 to 8"
            )]
            let level = 2 * (sum.abs().min(1.0) * 8.0 + 0.5) as u8;
            coverage[y * w + x] = level;
        }
    }
    #[expect(clippy::cast_possible_truncation, reason = "small offsets")]
    let (left, top) = (left as i32, top as i32);
    Bitmap {
        left,
        top,
        width: w,
        height: h,
        coverage,
    }
}

/// Adds the signed area of the line `a`–`b` (pixels, inside the bitmap) to `acc`.
fn line(acc: &mut [f32], stride: usize, h: usize, a: (f32, f32), b: (f32, f32)) {
    if a.1 == b.1 {
        return;
    }
    let (dir, p0, p1) = if a.1 < b.1 {
        (1.0_f32, a, b)
    } else {
        (-1.0, b, a)
    };
    let dxdy = (p1.0 - p0.0) / (p1.1 - p0.1);
    let mut x = p0.0;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "inside the bitmap"
    )]
    let (ystart, yend) = (
        p0.1.max(0.0).floor() as usize,
        (p1.1.ceil().max(0.0) as usize).min(h),
    );
    for y in ystart..yend {
        #[expect(clippy::cast_precision_loss, reason = "small rows")]
        let yf = y as f32;
        let row = y * stride;
        let dy = (yf + 1.0).min(p1.1) - yf.max(p0.1);
        let xnext = x + dxdy * dy;
        let d = dy * dir;
        let (xa, xb) = if x < xnext { (x, xnext) } else { (xnext, x) };
        let xa_floor = xa.floor();
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "inside the bitmap"
        )]
        let (ia, ib) = (xa_floor.max(0.0) as usize, xb.ceil().max(0.0) as usize);
        let ib = ib.min(stride - 1);
        let ia = ia.min(stride - 2);
        if ib <= ia + 1 {
            let xm = 0.5 * (x + xnext) - xa_floor;
            acc[row + ia] += d - d * xm;
            acc[row + ia + 1] += d * xm;
        } else {
            let s = 1.0 / (xb - xa);
            let fa = xa - xa_floor;
            let a0 = 0.5 * s * (1.0 - fa) * (1.0 - fa);
            #[expect(clippy::cast_precision_loss, reason = "small columns")]
            let fb = xb - ib as f32 + 1.0;
            let am = 0.5 * s * fb * fb;
            acc[row + ia] += d * a0;
            if ib == ia + 2 {
                acc[row + ia + 1] += d * (1.0 - a0 - am);
            } else {
                let a1 = s * (1.5 - fa);
                acc[row + ia + 1] += d * (a1 - a0);
                for cell in &mut acc[row + ia + 2..row + ib - 1] {
                    *cell += d * s;
                }
                #[expect(clippy::cast_precision_loss, reason = "small columns")]
                let a2 = a1 + (ib - ia - 3) as f32 * s;
                acc[row + ib - 1] += d * (1.0 - a2 - am);
            }
            acc[row + ib] += d * am;
        }
        x = xnext;
    }
}

/// Glyph bitmaps rasterized so far (a figure draws the same few characters at a few sizes).
#[derive(Debug, Default)]
pub(crate) struct Glyphs(BTreeMap<(char, u32, u8), Bitmap>);

impl Glyphs {
    /// The bitmap of `c` at `px` pixels per em with its origin `quarter` quarters of a pixel
    /// right of a pixel edge, rasterized on first use.
    pub(crate) fn bitmap(&mut self, c: char, px: f32, quarter: u8) -> &Bitmap {
        if self.0.len() > 4096 {
            self.0.clear();
        }
        self.0
            .entry((c, px.to_bits(), quarter))
            .or_insert_with(|| rasterize(c, px, 0.25 * f32::from(quarter)))
    }

    /// The bytes of coverage held.
    pub(crate) fn bytes(&self) -> usize {
        self.0.values().map(|b| b.coverage.len()).sum()
    }
}

/// The glyphs of `s` set at `px` pixels per em from the pen position `x` (pixels): each
/// character with its pixel column and quarter-pixel offset.
pub(crate) fn layout(s: &str, px: f32, x: f32) -> Vec<(char, i32, u8)> {
    let mut pen = x;
    s.chars()
        .map(|c| {
            let q = (pen * 4.0 + 0.5).floor();
            let col = (q / 4.0).floor();
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "pixels and quarters"
            )]
            let placed = (c, col as i32, (q - 4.0 * col) as u8);
            pen += advance(c, px);
            placed
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Most accented letters are stored as their base letter and an accent at an offset: their
    /// outline is the base's contours, unmoved, and the accent's above (or below) them.
    #[test]
    fn accented_letters_are_the_base_letter_and_an_accent() {
        let top =
            |cs: &[Vec<(f32, f32)>]| cs.iter().flatten().map(|p| p.1).fold(f32::MAX, f32::min);
        let bottom =
            |cs: &[Vec<(f32, f32)>]| cs.iter().flatten().map(|p| p.1).fold(f32::MIN, f32::max);
        for (accented, base, above) in [('é', 'e', true), ('Ä', 'A', true), ('ç', 'c', false)] {
            let (a, b) = (outline(accented, 40.0, 1.25), outline(base, 40.0, 1.25));
            assert!(a.len() > b.len(), "{accented:?}: {} contours", a.len());
            assert_eq!(
                a[..b.len()],
                b[..],
                "{accented:?}: the base letter first, unmoved"
            );
            if above {
                assert!(
                    top(&a) < top(&b) - 2.0,
                    "{accented:?}: the accent above the letter"
                );
            } else {
                assert!(
                    bottom(&a) > bottom(&b) + 2.0,
                    "{accented:?}: the cedilla below"
                );
            }
        }
        // The accents alone are not characters.
        assert_eq!(outline('\u{301}', 40.0, 0.0), outline('?', 40.0, 0.0));
    }

    #[test]
    fn the_subset_has_the_characters_the_figures_use() {
        for c in "0123456789.−·ω²³¹⁰ azAZ()|/°πθ′–…".chars() {
            assert!(has_glyph(c), "{c:?}");
        }
        assert!(!has_glyph('€'), "not in the subset");
        // A character outside the subset is drawn as '?'.
        assert_eq!(advance('€', 10.0), advance('?', 10.0));
    }

    #[test]
    fn a_filled_glyph_covers_its_area() {
        // 'l' in DejaVu Sans is a bar 184 units wide and 1556 high: at 2048 px per em, about
        // that many pixels.
        let b = rasterize('l', 2048.0 / 8.0, 0.0);
        let area: f32 = b.coverage.iter().map(|&c| f32::from(c) / 16.0).sum();
        let exact = 184.0 * 1556.0 / 64.0;
        assert!((area - exact).abs() < 0.02 * exact, "{area} vs {exact}");
        assert!(
            b.coverage.iter().all(|&c| c <= 16),
            "coverage in sixteenths"
        );
    }

    #[test]
    fn layout_advances_by_the_font() {
        let l = layout("11", 20.0, 3.3);
        assert_eq!(l.len(), 2);
        assert_eq!((l[0].1, l[0].2), (3, 1));
        let w = width("11", 20.0);
        assert!((w - 2.0 * advance('1', 20.0)).abs() < 1e-6, "{w}");
    }
}
