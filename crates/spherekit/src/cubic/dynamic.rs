// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The solver for tangent dimensions above 3, on slices: Newton's method on the block
//! tridiagonal (closed: bordered cyclic) system, every step evaluated and factorised in full.

use super::equations::{Geometry, add_t, apply_s, norm, s_matrix};
use super::{CubicSolveInfo, MAX_ITERATIONS, MAX_RESIDUAL, TARGET_RESIDUAL};
use crate::banded::{BlockTridiagonal, dot, mat_mul, mat_mul_t};
use crate::error::{SolveError, SplineError};

impl Geometry {
    /// The residuals `F(x)` into `f`; returns the largest row residual relative to the size of
    /// the row's terms.
    pub(super) fn residual(&self, x: &[f64], f: &mut [f64]) -> f64 {
        let m = self.m;
        let mut worst = 0.0_f64;
        let mut t1 = [0.0; 16];
        let mut t2 = [0.0; 16];
        let mut heap1;
        let mut heap2;
        let (y, u): (&mut [f64], &mut [f64]) = if m <= 16 {
            (&mut t1[..m], &mut t2[..m])
        } else {
            heap1 = vec![0.0; m];
            heap2 = vec![0.0; m];
            (&mut heap1[..], &mut heap2[..])
        };
        for k in 0..self.n {
            let xk = &x[k * m..(k + 1) * m];
            let fk = &mut f[k * m..(k + 1) * m];
            let mut scale = 0.0;
            if let Some(g) = self.fixed_row(k) {
                let h = if k == 0 {
                    self.seg[0].h
                } else {
                    self.seg[k - 1].h
                };
                let c = 4.0 / h;
                for a in 0..m {
                    fk[a] = c * (xk[a] - g[a]);
                }
                scale = c * (norm(xk) + norm(g));
            } else {
                fk.fill(0.0);
                if let Some(p) = self.prev(k) {
                    let sc = &self.seg[p];
                    let e = self.ehat(p);
                    let xp = &x[p * m..(p + 1) * m];
                    // (2/h) S xₚ + T(S⁻¹ H̃ᵀ xₖ) − 6θ ê/h², in transported coordinates.
                    y.copy_from_slice(xp);
                    apply_s(e, sc.sinc, y);
                    let c2 = 2.0 / sc.h;
                    let mut lin = 0.0;
                    for ya in y.iter_mut() {
                        *ya *= c2;
                        lin += *ya * *ya;
                    }
                    self.to_segment_end(p, xk, u);
                    apply_s(e, sc.inv_sinc, u);
                    let tn = add_t(sc, e, u, y).sqrt();
                    let c6 = 6.0 * sc.theta / (sc.h * sc.h);
                    for (ya, ea) in y.iter_mut().zip(e) {
                        *ya -= c6 * ea;
                    }
                    self.back_from_segment_end(p, y, u);
                    let c4 = 4.0 / sc.h;
                    for a in 0..m {
                        fk[a] += u[a] + c4 * xk[a];
                    }
                    scale += lin.sqrt() + tn + c6 + c4 * norm(xk);
                }
                if let Some(nx) = self.next(k) {
                    let sc = &self.seg[nx];
                    let e = self.ehat(nx);
                    let j = (k + 1) % self.n;
                    self.to_segment_end(nx, &x[j * m..(j + 1) * m], y);
                    apply_s(e, sc.inv_sinc, y);
                    let (c2, c4) = (2.0 / sc.h, 4.0 / sc.h);
                    let c6 = 6.0 * sc.theta / (sc.h * sc.h);
                    for a in 0..m {
                        fk[a] += c2 * y[a] + c4 * xk[a] - c6 * e[a];
                    }
                    scale += c2 * norm(y) + c4 * norm(xk) + c6;
                }
            }
            let fnorm = norm(fk);
            if !fnorm.is_finite() {
                return f64::INFINITY;
            }
            if scale > 0.0 {
                worst = worst.max(fnorm / scale);
            } else if fnorm > 0.0 {
                return f64::INFINITY;
            }
        }
        worst
    }

    /// The Jacobian at `x`, factorised: rows `k` of blocks `Aₖ` (coupling to the unknown
    /// before, across the seam for the first row of a loop), `Dₖ` and `Cₖ` (coupling to the
    /// unknown after), in the layout of [`BlockTridiagonal`].
    fn factor(&self, x: &[f64]) -> Option<BlockTridiagonal> {
        let m = self.m;
        let mm = m * m;
        let n = self.n;
        let mut a = vec![0.0; n * mm];
        let mut d = vec![0.0; n * mm];
        let mut c = vec![0.0; n * mm];
        let mut tmp = vec![0.0; mm];
        let mut u = vec![0.0; m];
        for k in 0..n {
            let blk = k * mm..(k + 1) * mm;
            self.blocks(
                k,
                x,
                &mut a[blk.clone()],
                &mut d[blk.clone()],
                &mut tmp,
                &mut u,
            );
            // C block: (2/h) S⁻¹ H̃ᵀ.
            if let (None, Some(nx)) = (self.fixed_row(k), self.next(k)) {
                let sc = &self.seg[nx];
                s_matrix(self.ehat(nx), sc.inv_sinc, 2.0 / sc.h, &mut tmp);
                if self.is_seam(nx) {
                    mat_mul_t(m, &tmp, &self.hol, &mut c[blk]);
                } else {
                    c[blk].copy_from_slice(&tmp);
                }
            }
        }
        BlockTridiagonal::factor(m, &a, &d, &c, self.closed)
    }

    /// The A and D blocks of row `k` at `x` (`tmp`, `u` scratch).
    #[allow(
        clippy::too_many_arguments,
        reason = "scratch buffers passed down to avoid allocation per row"
    )]
    fn blocks(
        &self,
        k: usize,
        x: &[f64],
        a_blk: &mut [f64],
        d_blk: &mut [f64],
        tmp: &mut [f64],
        u: &mut [f64],
    ) {
        let m = self.m;
        a_blk.fill(0.0);
        d_blk.fill(0.0);
        if self.fixed_row(k).is_some() {
            let h = if k == 0 {
                self.seg[0].h
            } else {
                self.seg[k - 1].h
            };
            for i in 0..m {
                d_blk[i * m + i] = 4.0 / h;
            }
            return;
        }
        let mut diag = 0.0;
        if let Some(p) = self.prev(k) {
            let sc = &self.seg[p];
            let e = self.ehat(p);
            diag += 4.0 / sc.h;
            // A = (2/h) H̃ S.
            s_matrix(e, sc.sinc, 2.0 / sc.h, tmp);
            self.left_h(p, tmp, a_blk);
            // D += H̃ (DT(u) S⁻¹) H̃ᵀ, u = S⁻¹ H̃ᵀ xₖ.
            self.to_segment_end(p, &x[k * m..(k + 1) * m], u);
            apply_s(e, sc.inv_sinc, u);
            let up: f64 = dot(u, e);
            let mut wp = [0.0; 16];
            let mut wheap;
            let w_perp: &mut [f64] = if m <= 16 {
                &mut wp[..m]
            } else {
                wheap = vec![0.0; m];
                &mut wheap
            };
            for i in 0..m {
                w_perp[i] = u[i] - up * e[i];
            }
            let (k1, sp, si) = (sc.kappa, sc.dsinc, sc.inv_sinc);
            // DT = 2κ ê w⊥ᵀ + 2σ′ w∥ (I − êêᵀ) + 2σ′ w⊥ êᵀ;  DT S⁻¹ = σ⁻¹ DT + (1 − σ⁻¹) 2σ′ w⊥ êᵀ.
            for i in 0..m {
                for j in 0..m {
                    let id = if i == j { 1.0 } else { 0.0 };
                    let dt = 2.0 * k1 * e[i] * w_perp[j]
                        + 2.0 * sp * up * (id - e[i] * e[j])
                        + 2.0 * sp * w_perp[i] * e[j];
                    tmp[i * m + j] = si * dt + (1.0 - si) * 2.0 * sp * w_perp[i] * e[j];
                }
            }
            if self.is_seam(p) {
                // H tmp Hᵀ. (`mat_mul` accumulates from +0, where a sum from −0 once stood here:
                // they differ only in the sign of an entry that is exactly zero, and adding
                // `H tmp Hᵀ` to `d_blk`, all +0 until then, erases that sign.)
                let mut t2 = vec![0.0; m * m];
                mat_mul(m, &self.hol, tmp, &mut t2);
                let mut t3 = vec![0.0; m * m];
                mat_mul_t(m, &t2, &self.hol, &mut t3);
                for (dv, t) in d_blk.iter_mut().zip(&t3) {
                    *dv += t;
                }
            } else {
                for (dv, t) in d_blk.iter_mut().zip(tmp.iter()) {
                    *dv += t;
                }
            }
        }
        if let Some(nx) = self.next(k) {
            diag += 4.0 / self.seg[nx].h;
        }
        for i in 0..m {
            d_blk[i * m + i] += diag;
        }
    }

    /// `out = H̃·mat` (`H` across the seam, identity otherwise).
    fn left_h(&self, seg: usize, mat: &[f64], out: &mut [f64]) {
        let m = self.m;
        if self.is_seam(seg) {
            mat_mul(m, &self.hol, mat, out);
        } else {
            out[..m * m].copy_from_slice(&mat[..m * m]);
        }
    }

    /// Newton's method from `x = 0`, reusing a factorisation while it converges fast.
    pub(super) fn solve(&self) -> Result<(Vec<f64>, CubicSolveInfo), SplineError> {
        let m = self.m;
        let mut x = vec![0.0; self.n * m];
        let mut f = vec![0.0; self.n * m];
        let mut residual = self.residual(&x, &mut f);
        let mut info = CubicSolveInfo {
            iterations: 0,
            factorizations: 0,
            residual,
        };
        let fail = |info: CubicSolveInfo| {
            SplineError::Solve(SolveError::NoConvergence {
                iterations: info.iterations,
                residual: info.residual,
            })
        };
        let mut fac: Option<BlockTridiagonal> = None;
        let mut fresh = false;
        while residual > TARGET_RESIDUAL && info.iterations < MAX_ITERATIONS {
            if fac.is_none() {
                fac = Some(self.factor(&x).ok_or_else(|| fail(info))?);
                info.factorizations += 1;
                fresh = true;
            }
            let factors = fac.as_ref().expect("factorised above");
            factors.solve(&mut f);
            for (xa, fa) in x.iter_mut().zip(&f) {
                *xa -= fa;
            }
            info.iterations += 1;
            let new = self.residual(&x, &mut f);
            info.residual = new;
            if !new.is_finite() {
                return Err(fail(info));
            }
            if new >= residual && fresh {
                // No progress with a fresh Jacobian: rounding level reached.
                residual = new;
                break;
            }
            // Refactorise after the first (linear) step and whenever convergence is slow.
            if info.iterations == 1 || new > 0.1 * residual {
                fac = None;
            }
            fresh = false;
            residual = new;
        }
        info.residual = residual;
        if residual.is_nan() || residual > MAX_RESIDUAL || x.iter().any(|v| !v.is_finite()) {
            return Err(fail(info));
        }
        Ok((x, info))
    }
}
