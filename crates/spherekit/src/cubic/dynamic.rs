// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The solver for tangent dimensions above 3, on slices: Newton's method on the block
//! tridiagonal (closed: bordered cyclic) system, every step evaluated and factorised in full.

use super::equations::{
    Geometry, add_t, apply_s, dot, mat_mul, mat_mul_t, mat_vec, norm, s_matrix,
};
use super::{CubicSolveInfo, MAX_ITERATIONS, MAX_RESIDUAL, TARGET_RESIDUAL};
use crate::error::{SolveError, SplineError};

/// The block LU factors of the Jacobian.
struct Factors {
    /// `D̃ₖ⁻¹`.
    dinv: Vec<f64>,
    /// `Lₖ = Aₖ D̃ₖ₋₁⁻¹`.
    l: Vec<f64>,
    /// `Cₖ` (coupling of row k to unknown k + 1).
    c: Vec<f64>,
    /// Closed: `Zₖ` (fill of the border column), `A_{n−1}`, `C_{n−1}` and the inverse Schur
    /// complement of the last unknown.
    z: Vec<f64>,
    a_last: Vec<f64>,
    c_last: Vec<f64>,
    schur_inv: Vec<f64>,
}

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

    /// The Jacobian at `x`, factorised.
    fn factor(&self, x: &[f64]) -> Option<Factors> {
        let m = self.m;
        let mm = m * m;
        let n = self.n;
        let mut a_blk = vec![0.0; mm];
        let mut d_blk = vec![0.0; mm];
        let mut tmp = vec![0.0; mm];
        let mut tmp2 = vec![0.0; mm];
        let mut u = vec![0.0; m];
        let mut fac = Factors {
            dinv: vec![0.0; n * mm],
            l: vec![0.0; n * mm],
            c: vec![0.0; n * mm],
            z: Vec::new(),
            a_last: Vec::new(),
            c_last: Vec::new(),
            schur_inv: Vec::new(),
        };
        let mut border = if self.closed {
            vec![0.0; n * mm]
        } else {
            Vec::new()
        };
        // Rows 0 … n−1 (open) or 0 … n−2 (closed; row n−1 is the border row).
        let last = if self.closed { n - 1 } else { n };
        let mut d_last = vec![0.0; mm];
        let mut a_last = vec![0.0; mm];
        let mut c_last = vec![0.0; mm];
        let mut c_blk = vec![0.0; mm];
        for k in 0..n {
            self.blocks(k, x, &mut a_blk, &mut d_blk, &mut tmp, &mut u);
            // C block: (2/h) S⁻¹ H̃ᵀ.
            c_blk.fill(0.0);
            if let (None, Some(nx)) = (self.fixed_row(k), self.next(k)) {
                {
                    let sc = &self.seg[nx];
                    s_matrix(self.ehat(nx), sc.inv_sinc, 2.0 / sc.h, &mut tmp);
                    if self.is_seam(nx) {
                        mat_mul_t(m, &tmp, &self.hol, &mut c_blk);
                    } else {
                        c_blk.copy_from_slice(&tmp);
                    }
                }
            }
            if k == last {
                d_last.copy_from_slice(&d_blk);
                a_last.copy_from_slice(&a_blk);
                c_last.copy_from_slice(&c_blk);
                break;
            }
            if self.closed && k == 0 {
                border[..mm].copy_from_slice(&a_blk);
            }
            if k > 0 {
                // L = A D̃ₖ₋₁⁻¹; D̃ = D − L Cₖ₋₁.
                mat_mul(m, &a_blk, &fac.dinv[(k - 1) * mm..k * mm], &mut tmp);
                fac.l[k * mm..(k + 1) * mm].copy_from_slice(&tmp);
                mat_mul(m, &tmp, &fac.c[(k - 1) * mm..k * mm], &mut tmp2);
                for (dv, t) in d_blk.iter_mut().zip(&tmp2) {
                    *dv -= t;
                }
                if self.closed {
                    // G̃ₖ = Gₖ − L G̃ₖ₋₁.
                    mat_mul(m, &tmp, &border[(k - 1) * mm..k * mm], &mut tmp2);
                    for (g, t) in border[k * mm..(k + 1) * mm].iter_mut().zip(&tmp2) {
                        *g -= t;
                    }
                }
            }
            if self.closed && k + 2 == n {
                // The coupling of row n−2 to x_{n−1} belongs to the border column.
                for (g, cv) in border[k * mm..(k + 1) * mm].iter_mut().zip(&c_blk) {
                    *g += cv;
                }
                c_blk.fill(0.0);
            }
            fac.c[k * mm..(k + 1) * mm].copy_from_slice(&c_blk);
            if !invert(m, &d_blk, &mut fac.dinv[k * mm..(k + 1) * mm]) {
                return None;
            }
        }
        if self.closed {
            // Z_{n−2} = D̃⁻¹ G̃; Zₖ = D̃ₖ⁻¹ (G̃ₖ − Cₖ Zₖ₊₁).
            let mut z = vec![0.0; (n - 1) * mm];
            for k in (0..n - 1).rev() {
                tmp.copy_from_slice(&border[k * mm..(k + 1) * mm]);
                if k + 2 < n {
                    mat_mul(
                        m,
                        &fac.c[k * mm..(k + 1) * mm],
                        &z[(k + 1) * mm..(k + 2) * mm],
                        &mut tmp2,
                    );
                    for (t, s) in tmp.iter_mut().zip(&tmp2) {
                        *t -= s;
                    }
                }
                mat_mul(m, &fac.dinv[k * mm..(k + 1) * mm], &tmp, &mut tmp2);
                z[k * mm..(k + 1) * mm].copy_from_slice(&tmp2);
            }
            // Schur complement D − A Z_{n−2} − C Z₀.
            mat_mul(m, &a_last, &z[(n - 2) * mm..(n - 1) * mm], &mut tmp);
            mat_mul(m, &c_last, &z[..mm], &mut tmp2);
            for i in 0..mm {
                d_last[i] -= tmp[i] + tmp2[i];
            }
            let mut s_inv = vec![0.0; mm];
            if !invert(m, &d_last, &mut s_inv) {
                return None;
            }
            fac.z = z;
            fac.a_last = a_last;
            fac.c_last = c_last;
            fac.schur_inv = s_inv;
        }
        Some(fac)
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

    /// `x ← J⁻¹ x` with the factors.
    fn substitute(&self, fac: &Factors, x: &mut [f64]) {
        let m = self.m;
        let mm = m * m;
        let n = self.n;
        let rows = if self.closed { n - 1 } else { n };
        let mut t = vec![0.0; m];
        // Forward: yₖ = bₖ − Lₖ yₖ₋₁.
        for k in 1..rows {
            mat_vec(
                m,
                &fac.l[k * mm..(k + 1) * mm],
                &x[(k - 1) * m..k * m],
                &mut t,
            );
            for (xa, ta) in x[k * m..(k + 1) * m].iter_mut().zip(&t) {
                *xa -= ta;
            }
        }
        // Back: wₖ = D̃ₖ⁻¹ (yₖ − Cₖ wₖ₊₁).
        for k in (0..rows).rev() {
            if k + 1 < rows {
                mat_vec(
                    m,
                    &fac.c[k * mm..(k + 1) * mm],
                    &x[(k + 1) * m..(k + 2) * m],
                    &mut t,
                );
                for (xa, ta) in x[k * m..(k + 1) * m].iter_mut().zip(&t) {
                    *xa -= ta;
                }
            }
            t.copy_from_slice(&x[k * m..(k + 1) * m]);
            mat_vec(
                m,
                &fac.dinv[k * mm..(k + 1) * mm],
                &t,
                &mut x[k * m..(k + 1) * m],
            );
        }
        if self.closed {
            // x_{n−1} = S⁻¹ (b_{n−1} − A w_{n−2} − C w₀); xₖ = wₖ − Zₖ x_{n−1}.
            let mut rhs = x[(n - 1) * m..].to_vec();
            mat_vec(m, &fac.a_last, &x[(n - 2) * m..(n - 1) * m], &mut t);
            for (r, ta) in rhs.iter_mut().zip(&t) {
                *r -= ta;
            }
            mat_vec(m, &fac.c_last, &x[..m], &mut t);
            for (r, ta) in rhs.iter_mut().zip(&t) {
                *r -= ta;
            }
            let mut last = vec![0.0; m];
            mat_vec(m, &fac.schur_inv, &rhs, &mut last);
            for k in 0..n - 1 {
                mat_vec(m, &fac.z[k * mm..(k + 1) * mm], &last, &mut t);
                for (xa, ta) in x[k * m..(k + 1) * m].iter_mut().zip(&t) {
                    *xa -= ta;
                }
            }
            x[(n - 1) * m..].copy_from_slice(&last);
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
        let mut fac: Option<Factors> = None;
        let mut fresh = false;
        while residual > TARGET_RESIDUAL && info.iterations < MAX_ITERATIONS {
            if fac.is_none() {
                fac = Some(self.factor(&x).ok_or_else(|| fail(info))?);
                info.factorizations += 1;
                fresh = true;
            }
            let factors = fac.as_ref().expect("factorised above");
            self.substitute(factors, &mut f);
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

/// `out = a⁻¹` by Gauss–Jordan elimination with partial pivoting; `false` if singular.
pub(super) fn invert(m: usize, a: &[f64], out: &mut [f64]) -> bool {
    let mut w = a[..m * m].to_vec();
    out[..m * m].fill(0.0);
    for i in 0..m {
        out[i * m + i] = 1.0;
    }
    for col in 0..m {
        let piv = (col..m).fold(col, |p, r| {
            if w[r * m + col].abs() > w[p * m + col].abs() {
                r
            } else {
                p
            }
        });
        let pv = w[piv * m + col];
        if pv == 0.0 || !pv.is_finite() {
            return false;
        }
        if piv != col {
            for j in 0..m {
                w.swap(piv * m + j, col * m + j);
                out.swap(piv * m + j, col * m + j);
            }
        }
        let inv = 1.0 / pv;
        for j in 0..m {
            w[col * m + j] *= inv;
            out[col * m + j] *= inv;
        }
        for r in 0..m {
            if r != col {
                let f = w[r * m + col];
                if f != 0.0 {
                    for j in 0..m {
                        w[r * m + j] -= f * w[col * m + j];
                        out[r * m + j] -= f * out[col * m + j];
                    }
                }
            }
        }
    }
    true
}
