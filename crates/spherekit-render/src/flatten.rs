// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Adaptive flattening of curves on S² into polylines to an angular accuracy.

use spherekit::glam::DVec3;

/// Subdivision stops at this depth whatever the accuracy (2¹² pieces per initial interval).
const MAX_DEPTH: u32 = 12;

/// The longest chord (radians) a polyline segment may span, so that polylines also follow the
/// sphere closely enough to be split at the horizon.
const MAX_STEP: f64 = 0.05;

/// Flattens a curve on `[a, b]` into points on S², starting from `initial` equal pieces and
/// subdividing any piece whose midpoint deviates from the chord's great-circle midpoint by more
/// than `accuracy` radians, or which spans more than [`MAX_STEP`].
///
/// `f(ts, out)` evaluates the curve at increasing parameters into `out` (batch evaluation,
/// [`Curve::eval_many`](spherekit::Curve::eval_many)). The subdivision runs breadth first, one
/// batch of midpoints per level, and gives the points of the depth-first recursion in the same
/// order.
///
/// The parameters in `breaks` (joints of a piecewise curve) are always sample points, so
/// corners are kept sharp.
pub(crate) fn flatten(
    f: &dyn Fn(&[f64], &mut [DVec3]),
    breaks: &[f64],
    initial: usize,
    accuracy: f64,
) -> Vec<DVec3> {
    // The initial grid: each piece's start and `initial` steps to its end.
    let mut ts = Vec::with_capacity(breaks.len().saturating_sub(1) * (initial + 1));
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        ts.push(a);
        for i in 1..=initial {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let t = if i == initial {
                b
            } else {
                a + (b - a) * (i as f64 / initial as f64)
            };
            ts.push(t);
        }
    }
    if ts.is_empty() {
        return Vec::new();
    }
    let mut ps = vec![DVec3::ZERO; ts.len()];
    f(&ts, &mut ps);
    let mut pieces: Vec<Piece> = Vec::with_capacity(ts.len());
    for (k, w) in ts.chunks(initial + 1).enumerate() {
        let p = &ps[k * (initial + 1)..(k + 1) * (initial + 1)];
        for i in 1..w.len() {
            pieces.push(Piece {
                ta: w[i - 1],
                pa: p[i - 1],
                tb: w[i],
                pb: p[i],
                done: false,
            });
        }
    }
    let mut mids = Vec::new();
    let mut pm = Vec::new();
    for _depth in 0..MAX_DEPTH {
        mids.clear();
        mids.extend(
            pieces
                .iter()
                .filter(|q| !q.done)
                .map(|q| 0.5 * (q.ta + q.tb)),
        );
        if mids.is_empty() {
            break;
        }
        pm.clear();
        pm.resize(mids.len(), DVec3::ZERO);
        f(&mids, &mut pm);
        let mut next = Vec::with_capacity(pieces.len() + mids.len());
        let mut m = 0;
        for q in pieces {
            if q.done {
                next.push(q);
                continue;
            }
            let (tm, pmid) = (mids[m], pm[m]);
            m += 1;
            let chord_mid = (q.pa + q.pb).normalize_or_zero();
            let deviation = (pmid - chord_mid).length();
            let span = (q.pb - q.pa).length();
            if deviation > accuracy || span > MAX_STEP {
                next.push(Piece {
                    tb: tm,
                    pb: pmid,
                    ..q
                });
                next.push(Piece {
                    ta: tm,
                    pa: pmid,
                    ..q
                });
            } else {
                next.push(Piece { done: true, ..q });
            }
        }
        pieces = next;
    }
    let mut out = Vec::with_capacity(pieces.len() + 1);
    out.push(ps[0]);
    out.extend(pieces.iter().map(|q| q.pb));
    out
}

/// A piece of the polyline being subdivided: from `(ta, pa)` to `(tb, pb)`.
#[derive(Clone, Copy)]
struct Piece {
    ta: f64,
    pa: DVec3,
    tb: f64,
    pb: DVec3,
    /// Accepted: no further subdivision.
    done: bool,
}

/// Points along the great-circle arc from `a` to `b` (not antipodal), at most [`MAX_STEP`] apart.
pub(crate) fn great_arc(a: DVec3, b: DVec3) -> Vec<DVec3> {
    let theta = 2.0 * libm::atan2((a - b).length(), (a + b).length());
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "small positive count"
    )]
    let n = ((theta / MAX_STEP).ceil() as usize).clamp(1, 200);
    let e = (b - a * a.dot(b)).normalize_or_zero();
    (0..=n)
        .map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let s = theta * i as f64 / n as f64;
            a * libm::cos(s) + e * libm::sin(s)
        })
        .collect()
}

/// A full circle `{cos s·u + sin s·v}` scaled by `radius` around `center`, as a closed polyline.
pub(crate) fn circle(center: DVec3, u: DVec3, v: DVec3, radius: f64) -> Vec<DVec3> {
    let n = 180;
    (0..=n)
        .map(|i| {
            let s = std::f64::consts::TAU * f64::from(i) / f64::from(n);
            center + (u * libm::cos(s) + v * libm::sin(s)) * radius
        })
        .collect()
}
