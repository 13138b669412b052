// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Adaptive flattening of curves on S² into polylines to an angular accuracy.

use spherekit::glam::DVec3;

/// Subdivision stops at this depth whatever the accuracy (2¹² pieces per initial interval).
const MAX_DEPTH: u32 = 12;

/// The longest chord (radians) a polyline segment may span, so that polylines also follow the
/// sphere closely enough to be split at the horizon.
const MAX_STEP: f64 = 0.05;

/// Flattens `f` on `[a, b]` into points on S², starting from `initial` equal pieces and
/// subdividing any piece whose midpoint deviates from the chord's great-circle midpoint by more
/// than `accuracy` radians, or which spans more than [`MAX_STEP`].
///
/// The parameters in `breaks` (joints of a piecewise curve) are always sample points, so
/// corners are kept sharp.
pub(crate) fn flatten(
    f: &dyn Fn(f64) -> DVec3,
    breaks: &[f64],
    initial: usize,
    accuracy: f64,
) -> Vec<DVec3> {
    let mut out = Vec::new();
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        let mut prev_t = a;
        let mut prev = f(a);
        if out.is_empty() {
            out.push(prev);
        }
        for i in 1..=initial {
            #[expect(clippy::cast_precision_loss, reason = "small counts")]
            let t = if i == initial {
                b
            } else {
                a + (b - a) * (i as f64 / initial as f64)
            };
            let p = f(t);
            subdivide(f, prev_t, prev, t, p, accuracy, 0, &mut out);
            prev_t = t;
            prev = p;
        }
    }
    out
}

#[expect(clippy::too_many_arguments, reason = "a private recursive helper")]
fn subdivide(
    f: &dyn Fn(f64) -> DVec3,
    ta: f64,
    pa: DVec3,
    tb: f64,
    pb: DVec3,
    accuracy: f64,
    depth: u32,
    out: &mut Vec<DVec3>,
) {
    if depth < MAX_DEPTH {
        let tm = 0.5 * (ta + tb);
        let pm = f(tm);
        let chord_mid = (pa + pb).normalize_or_zero();
        let deviation = (pm - chord_mid).length();
        let span = (pb - pa).length();
        if deviation > accuracy || span > MAX_STEP {
            subdivide(f, ta, pa, tm, pm, accuracy, depth + 1, out);
            subdivide(f, tm, pm, tb, pb, accuracy, depth + 1, out);
            return;
        }
    }
    out.push(pb);
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
