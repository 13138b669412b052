// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The continuity equations in frame coordinates: the scalars of each segment, the nonlinear
//! term `T` and its bilinear form, and the small dense algebra both solvers use.

use crate::banded::{dot, mat_t_vec};
use crate::math;

/// Scalars of one segment used by the solver.
#[derive(Clone, Debug)]
pub(super) struct SegConst {
    pub(super) theta: f64,
    pub(super) h: f64,
    pub(super) sinc: f64,
    pub(super) inv_sinc: f64,
    pub(super) kappa: f64,
    pub(super) dsinc: f64,
    /// `2/h`, `4/h` and `6θ/h²`, the coefficients of the continuity equations.
    pub(super) c2: f64,
    pub(super) c4: f64,
    pub(super) c6: f64,
}

impl SegConst {
    /// The scalars of a segment of angle `theta` (`(sin θ, cos θ)` given) and width `h`.
    pub(super) fn new(theta: f64, h: f64, (sn, cs): (f64, f64)) -> Self {
        if theta.abs() < 0.1 {
            return Self {
                theta,
                h,
                sinc: math::sinc(theta),
                inv_sinc: math::inv_sinc(theta),
                kappa: math::kappa(theta),
                dsinc: math::sinc_deriv(theta, (sn, cs)),
                c2: 2.0 / h,
                c4: 4.0 / h,
                c6: 6.0 * theta / (h * h),
            };
        }
        // Above every series switch: the closed forms from the one `sin_cos`.
        let (inv_t, inv_h) = (1.0 / theta, 1.0 / h);
        let inv_t2 = inv_t * inv_t;
        Self {
            theta,
            h,
            sinc: sn * inv_t,
            inv_sinc: theta / sn,
            kappa: (theta - sn * cs) * inv_t2,
            dsinc: (theta * cs - sn) * inv_t2,
            c2: 2.0 * inv_h,
            c4: 4.0 * inv_h,
            c6: 6.0 * theta * inv_h * inv_h,
        }
    }
}

/// The continuity equations in frame coordinates.
pub(super) struct Geometry {
    pub(super) n: usize,
    pub(super) m: usize,
    pub(super) closed: bool,
    pub(super) seg: Vec<SegConst>,
    /// Frame coordinates of each segment's direction (`nseg × m`).
    pub(super) ehat: Vec<f64>,
    /// Holonomy (closed only, `m × m`).
    pub(super) hol: Vec<f64>,
    /// Fixed velocities at the first and last key (clamped and scipy ends), frame coordinates.
    pub(super) fixed: Option<(Vec<f64>, Vec<f64>)>,
}

impl Geometry {
    pub(super) fn prev(&self, k: usize) -> Option<usize> {
        if k > 0 {
            Some(k - 1)
        } else if self.closed {
            Some(self.n - 1)
        } else {
            None
        }
    }

    pub(super) fn next(&self, k: usize) -> Option<usize> {
        if self.closed || k + 1 < self.n {
            Some(k)
        } else {
            None
        }
    }

    pub(super) fn is_seam(&self, seg: usize) -> bool {
        self.closed && seg + 1 == self.n
    }

    /// The fixed velocity of row `k`, if any.
    pub(super) fn fixed_row(&self, k: usize) -> Option<&[f64]> {
        let (g0, g1) = self.fixed.as_ref()?;
        if k == 0 {
            Some(g0)
        } else if k + 1 == self.n {
            Some(g1)
        } else {
            None
        }
    }

    /// Transported-frame coordinates at the end of segment `seg` of a vector given in the frame
    /// of the end key (`Hᵀ·y` across the seam).
    pub(super) fn to_segment_end(&self, seg: usize, y: &[f64], out: &mut [f64]) {
        let m = self.m;
        if self.is_seam(seg) {
            mat_t_vec(m, &self.hol, y, out);
        } else {
            out.copy_from_slice(y);
        }
    }

    /// The inverse of [`to_segment_end`](Self::to_segment_end) (`H·y` across the seam).
    pub(super) fn back_from_segment_end(&self, seg: usize, y: &[f64], out: &mut [f64]) {
        let m = self.m;
        if self.is_seam(seg) {
            for (o, h) in out.iter_mut().zip(self.hol.chunks_exact(m)) {
                *o = dot(h, y);
            }
        } else {
            out.copy_from_slice(y);
        }
    }

    pub(super) fn ehat(&self, seg: usize) -> &[f64] {
        &self.ehat[seg * self.m..(seg + 1) * self.m]
    }
}

// The small helpers below are inlined by force natively (in the array solver's loops their
// calls cost more than their arithmetic, and with the dimension a constant there the loops
// unroll); the wasm build, optimised for size, leaves inlining to the compiler. Inlining changes
// no result: Rust contracts no float operations. The array solver calls them on flattened
// arrays ([`fixed`](super::fixed)).

/// `T(u)` added to `y` (both m-vectors in segment coordinates); returns `|T(u)|²`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(super) fn add_t(sc: &SegConst, e: &[f64], u: &[f64], y: &mut [f64]) -> f64 {
    let up = dot(u, e);
    let uu = dot(u, u);
    let perp2 = (uu - up * up).max(0.0);
    let c1 = perp2 * sc.kappa;
    let c2 = 2.0 * sc.dsinc * up;
    let mut t2 = 0.0;
    for ((ya, ua), ea) in y.iter_mut().zip(u).zip(e) {
        let ta = c1 * ea + c2 * (ua - up * ea);
        t2 += ta * ta;
        *ya += ta;
    }
    t2
}

#[inline]
pub(super) fn norm(x: &[f64]) -> f64 {
    dot(x, x).sqrt()
}

/// `out = scale·(σ·I + (1 − σ)·ê êᵀ)`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(super) fn s_matrix(e: &[f64], sigma: f64, scale: f64, out: &mut [f64]) {
    let m = e.len();
    for i in 0..m {
        for j in 0..m {
            let id = if i == j { sigma } else { 0.0 };
            out[i * m + j] = scale * (id + (1.0 - sigma) * e[i] * e[j]);
        }
    }
}

/// `x ← S x` with `S = σ·I + (1 − σ)·ê êᵀ` (pass `1/sinc θ` for `S⁻¹`).
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(super) fn apply_s(ehat: &[f64], sigma: f64, x: &mut [f64]) {
    let c = (1.0 - sigma) * dot(ehat, x);
    for (xi, ei) in x.iter_mut().zip(ehat) {
        *xi = sigma * *xi + c * ei;
    }
}
