// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Orthonormal tangent frames at the keys, parallel transported along the segments.

use super::Segment;
use super::equations::{Geometry, apply_s};
use crate::banded::dot;

/// Orthonormal tangent frames at the keys, in span coordinates, parallel transported along
/// the segments from a frame at the first key.
pub(super) struct Frames {
    r: usize,
    /// `(n + closed) × (r − 1) × r`: frame `k` (the last one, when closed, is the transport of
    /// frame 0 around the loop).
    data: Vec<f64>,
}

/// Calls `$body` with `$d` bound to the dimension `$r`. 4 (the span of keys on S³) has an arm
/// of its own: the callees are inlined by force (natively), so that copy is compiled for the
/// constant 4, with the short loops over coordinates unrolled. The `compact` build has one
/// copy (the same operations, so the same bits).
#[cfg(not(feature = "compact"))]
macro_rules! with_dim {
    ($r:expr, |$d:ident| $body:expr) => {
        match $r {
            4 => {
                let $d: usize = 4;
                $body
            }
            r => {
                let $d: usize = r;
                $body
            }
        }
    };
}
#[cfg(feature = "compact")]
macro_rules! with_dim {
    ($r:expr, |$d:ident| $body:expr) => {{
        let $d: usize = $r;
        $body
    }};
}

impl Frames {
    /// The frames, and the frame coordinates `ê` of each segment's direction (`nseg × (r − 1)`,
    /// the components along `e` that the transport rotates).
    pub(super) fn new(
        xs: &[f64],
        es: &[f64],
        sin_cos: &[(f64, f64)],
        r: usize,
        closed: bool,
    ) -> (Self, Vec<f64>) {
        with_dim!(r, |d| Self::build(d, xs, es, sin_cos, closed))
    }

    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn build(
        r: usize,
        xs: &[f64],
        es: &[f64],
        sin_cos: &[(f64, f64)],
        closed: bool,
    ) -> (Self, Vec<f64>) {
        let m = r - 1;
        let n = xs.len() / r;
        let count = n + usize::from(closed);
        let mut data = Vec::with_capacity(count * m * r);
        // Frame 0: the Householder reflection taking the largest axis to x₀, other columns.
        let x0 = &xs[..r];
        let mut u = x0.to_vec();
        let jmax = (0..r).fold(0, |j, i| if u[i].abs() > u[j].abs() { i } else { j });
        u[jmax] += if u[jmax] >= 0.0 { 1.0 } else { -1.0 };
        let uu = dot(&u, &u);
        for k in (0..r).filter(|&k| k != jmax) {
            let scale = 2.0 * u[k] / uu;
            data.extend(u.iter().enumerate().map(|(j, &uj)| {
                let id = if j == k { 1.0 } else { 0.0 };
                id - scale * uj
            }));
        }
        data.resize(count * m * r, 0.0);
        let mut ehat = vec![0.0; (count - 1) * m];
        let mut e_end = vec![0.0; r];
        for k in 0..count - 1 {
            let (x, e) = (&xs[k * r..(k + 1) * r], &es[k * r..(k + 1) * r]);
            let next = if k + 1 == n { 0 } else { (k + 1) * r };
            let y = &xs[next..next + r];
            let (sn, cs) = sin_cos[k];
            for ((o, xj), ej) in e_end.iter_mut().zip(x).zip(e) {
                *o = -sn * xj + (cs - 1.0) * ej;
            }
            // Frame k + 1: each vector of frame k with its component along e rotated into e′
            // (the parallel transport), then orthogonalised against the next key. The dot
            // products are all taken of frame k (`g·y = f·y + (f·e)(d·y)`), so that the chain
            // from frame to frame is short.
            let (done, rest) = data.split_at_mut((k + 1) * m * r);
            let frame = done[k * m * r..].chunks_exact(r);
            let ehat = &mut ehat[k * m..(k + 1) * m];
            let dy = dot(&e_end, y);
            for ((f, g), fe) in frame.zip(rest.chunks_exact_mut(r)).zip(ehat) {
                *fe = dot(f, e);
                let gy = dot(f, y) + *fe * dy;
                for (((gj, fj), dj), yj) in g.iter_mut().zip(f).zip(&e_end).zip(y) {
                    *gj = fj + *fe * dj - gy * yj;
                }
            }
        }
        (Self { r, data }, ehat)
    }

    /// Vector `a` of frame `k`.
    #[inline]
    pub(super) fn vector(&self, k: usize, a: usize) -> &[f64] {
        let m = self.r - 1;
        &self.data[(k * m + a) * self.r..(k * m + a + 1) * self.r]
    }

    /// The key velocities `Vₖ` and the segments, from the solution `x` in frame coordinates:
    /// with the end velocity `Uᵢ = Nᵢ Vᵢ₊₁` and `lᵢ = θᵢ·eᵢ` (`es`: span coordinates of the
    /// directions), `a = hV`, `b = 3l − 2hV − hU` and `c = −2l + hV + hU`, formed in span
    /// coordinates and made ambient vectors by `ambient`.
    pub(super) fn output<V: Clone>(
        &self,
        geo: &Geometry,
        x: &[f64],
        es: &[f64],
        keys: &[V],
        ambient: impl Fn(&[f64]) -> V,
    ) -> (Vec<V>, Vec<Segment<V>>) {
        with_dim!(self.r, |d| self.output_in(d, geo, x, es, keys, &ambient))
    }

    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn output_in<V: Clone>(
        &self,
        r: usize,
        geo: &Geometry,
        x: &[f64],
        es: &[f64],
        keys: &[V],
        ambient: impl Fn(&[f64]) -> V,
    ) -> (Vec<V>, Vec<Segment<V>>) {
        let m = r - 1;
        let nseg = geo.seg.len();
        let mut velocities = Vec::with_capacity(geo.n);
        let mut segments = Vec::with_capacity(nseg);
        let (mut v, mut big_u, mut coef) = (vec![0.0; r], vec![0.0; r], vec![0.0; r]);
        let mut u = vec![0.0; m];
        for k in 0..geo.n {
            self.combine_in(r, k, &x[k * m..(k + 1) * m], &mut v);
            velocities.push(ambient(&v));
            if k == nseg {
                break;
            }
            // `U = S⁻¹·(Vₖ₊₁ transported back)`, with `S⁻¹ = I/sinc θ + (1 − 1/sinc θ)·e eᵀ` in
            // span coordinates.
            let next = if k + 1 == geo.n {
                geo.to_segment_end(k, &x[..m], &mut u);
                &u[..]
            } else {
                &x[(k + 1) * m..(k + 2) * m]
            };
            self.combine_in(r, k, next, &mut big_u);
            let (sc, e) = (&geo.seg[k], &es[k * r..(k + 1) * r]);
            apply_s(e, sc.inv_sinc, &mut big_u[..r]);
            let (h, theta) = (sc.h, sc.theta);
            for (o, va) in coef[..r].iter_mut().zip(&v) {
                *o = va * h;
            }
            let a = ambient(&coef);
            for (o, ((va, ua), ea)) in coef[..r].iter_mut().zip(v.iter().zip(&big_u).zip(e)) {
                *o = ea * theta * 3.0 - va * (2.0 * h) - ua * h;
            }
            let b = ambient(&coef);
            for (o, ((va, ua), ea)) in coef[..r].iter_mut().zip(v.iter().zip(&big_u).zip(e)) {
                *o = ea * theta * -2.0 + va * h + ua * h;
            }
            let c = ambient(&coef);
            segments.push(Segment {
                start: keys[k].clone(),
                a,
                b,
                c,
                inv_h: 1.0 / h,
            });
        }
        (velocities, segments)
    }

    /// `out = Σₐ cₐ·(frame k)ₐ`.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn combine_in(&self, r: usize, k: usize, c: &[f64], out: &mut [f64]) {
        let out = &mut out[..r];
        out.fill(0.0);
        let frame = &self.data[k * c.len() * r..(k + 1) * c.len() * r];
        for (&ca, f) in c.iter().zip(frame.chunks_exact(r)) {
            for (o, fj) in out.iter_mut().zip(f) {
                *o += ca * fj;
            }
        }
    }

    /// `H[a][b] = (frame 0)ₐ · (frame n)_b`: frame-0 coordinates of the transported frame.
    pub(super) fn holonomy(&self) -> Vec<f64> {
        let m = self.r - 1;
        let last = self.data.len() / (m * self.r) - 1;
        let mut h = Vec::with_capacity(m * m);
        for a in 0..m {
            for b in 0..m {
                h.push(dot(self.vector(0, a), self.vector(last, b)));
            }
        }
        h
    }
}
