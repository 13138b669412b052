// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The solver for tangent dimensions 1 to 3, on glam's `DVec3` and `DMat3`.

use glam::{DMat3, DVec3};

use super::equations::{Geometry, SegConst, add_t, apply_s};
use super::{CubicSolveInfo, MAX_ITERATIONS, MAX_RESIDUAL, TARGET_RESIDUAL};
use crate::error::{SolveError, SplineError};

// The solver's small helpers are inlined by force natively, as those of `equations` (the wasm
// build leaves inlining to the compiler: forcing it there cost 15.5 KB of the .wasm).

/// The tangent dimension of this solver (a smaller one is padded with zeros,
/// [`FixedSolver::new`]).
const M: usize = 3;

/// A vector and a block of the solver: glam's `DVec3` and `DMat3` (column-major; `b.col(j)[i]`
/// is the entry in row `i`, column `j`).
pub(super) type Vf = DVec3;
type Bf = DMat3;

/// `[f(0), f(1), f(2)]`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(super) fn vf(f: impl Fn(usize) -> f64) -> Vf {
    DVec3::new(f(0), f(1), f(2))
}

/// The block with entry `f(i, j)` in row `i`, column `j`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn bf(f: impl Fn(usize, usize) -> f64) -> Bf {
    DMat3::from_cols(vf(|i| f(i, 0)), vf(|i| f(i, 1)), vf(|i| f(i, 2)))
}

/// The symmetric bilinear form of `T` (`T(u) = B(u, u)`, [`add_t`]):
/// `B(a, b) = κ(a·b − (a·ê)(b·ê))·ê + (sinc′ θ)·((a·ê)·b + (b·ê)·a − 2(a·ê)(b·ê)·ê)`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn bilinear_t(sc: &SegConst, e: Vf, a: Vf, b: Vf) -> Vf {
    let (ae, be) = (a.dot(e), b.dot(e));
    let c1 = sc.kappa * (a.dot(b) - ae * be) - 2.0 * sc.dsinc * ae * be;
    vf(|i| c1 * e[i] + sc.dsinc * (ae * b[i] + be * a[i]))
}

/// `zₖ ← zₖ − l·zₖ₋₁`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn eliminate_with(l: &Bf, k: usize, z: &mut [Vf]) {
    let t = *l * z[k - 1];
    z[k] -= t;
}

/// `v[k] = value`, or `v.push(value)` when `k == v.len()`: the first factorisation fills the
/// solver's rows in order, so they are not zeroed first.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn put<T>(v: &mut Vec<T>, k: usize, value: T) {
    if let Some(slot) = v.get_mut(k) {
        *slot = value;
    } else {
        debug_assert_eq!(k, v.len(), "rows are filled in order");
        v.push(value);
    }
}

/// `worst² = max(worst², |f|²/scale²)`, the division only for a row that raises it (infinite
/// for a non-finite residual).
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn raise_worst(f: Vf, scale2: f64, worst2: &mut f64) {
    let fn2 = f.dot(f);
    if fn2 > *worst2 * scale2 || !fn2.is_finite() {
        *worst2 = if fn2.is_finite() && scale2 > 0.0 {
            fn2 / scale2
        } else {
            f64::INFINITY
        };
    }
}

/// `S·x` with `S = σ·I + (1 − σ)·ê êᵀ` (pass `1/sinc θ` for `S⁻¹`), [`apply_s`] on a `DVec3`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_vec(e: Vf, sigma: f64, mut x: Vf) -> Vf {
    apply_s(e.as_ref(), sigma, x.as_mut());
    x
}

/// `scale·S·x` for a block `x`, `S = σ·I + (1 − σ)·ê êᵀ`, without forming `S`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_left(e: Vf, sigma: f64, scale: f64, x: &Bf) -> Bf {
    let ex = x.transpose() * e;
    let (a, be) = (scale * sigma, e * (scale * (1.0 - sigma)));
    DMat3::from_cols(
        x.x_axis * a + be * ex.x,
        x.y_axis * a + be * ex.y,
        x.z_axis * a + be * ex.z,
    )
}

/// `scale·x·S` for a block `x`, as [`s_left`].
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_right(x: &Bf, e: Vf, sigma: f64, scale: f64) -> Bf {
    let (a, bxe) = (scale * sigma, (*x * e) * (scale * (1.0 - sigma)));
    DMat3::from_cols(
        x.x_axis * a + bxe * e.x,
        x.y_axis * a + bxe * e.y,
        x.z_axis * a + bxe * e.z,
    )
}

/// `scale·(σ·I + (1 − σ)·ê êᵀ)`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
fn s_block(e: Vf, sigma: f64, scale: f64) -> Bf {
    bf(|i, j| {
        let id = if i == j { sigma } else { 0.0 };
        scale * (id + (1.0 - sigma) * e[i] * e[j])
    })
}

/// `a⁻¹` for the pivot blocks of the Jacobian: the adjugate over the determinant (branch-free,
/// one division; the blocks are diagonally dominant, and a less accurate inverse would only
/// slow Newton's convergence, never change the residual it stops at); `None` if singular.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(super) fn invertf(m: &Bf) -> Option<Bf> {
    // The rows of `m`.
    let a = m.transpose().to_cols_array_2d();
    let c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    let c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    let c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    let det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    let r = 1.0 / det;
    // Column by column: the adjugate is the transpose of the cofactors.
    let out = DMat3::from_cols(
        DVec3::new(c00, c01, c02) * r,
        DVec3::new(
            a[0][2] * a[2][1] - a[0][1] * a[2][2],
            a[0][0] * a[2][2] - a[0][2] * a[2][0],
            a[0][1] * a[2][0] - a[0][0] * a[2][1],
        ) * r,
        DVec3::new(
            a[0][1] * a[1][2] - a[0][2] * a[1][1],
            a[0][2] * a[1][0] - a[0][0] * a[1][2],
            a[0][0] * a[1][1] - a[0][1] * a[1][0],
        ) * r,
    );
    (det != 0.0 && r.is_finite() && out.is_finite()).then_some(out)
}

/// The solver for tangent dimensions up to 3: the continuity equations of [`Geometry`] with
/// arrays for vectors and blocks, and a workspace allocated once per solve.
///
/// Each Newton or chord step is two sweeps over the keys. The forward sweep evaluates the
/// residual row by row and eliminates it at once with the block LU factors (when the step
/// refactorises, the same sweep builds the Jacobian's row and the factors first), so the
/// arithmetic of the residual overlaps the dependent chain of the elimination. The backward
/// sweep substitutes, one block product deep per key (`δₖ = D̃ₖ⁻¹zₖ − Gₖ δₖ₊₁`).
pub(super) struct FixedSolver<'g> {
    g: &'g Geometry,
    e: Vec<Vf>,
    hol: Bf,
    fixed: Option<(Vf, Vf)>,
    /// Per row of the block tridiagonal part, its factors.
    fac: Vec<RowFactors>,
    /// Per row, from the last evaluation of the equations (the factorising sweep): the squared
    /// size of the row's terms, and `Wₖ`, the end velocity `S⁻¹H̃ᵀ(xₖ − x̄ₖ)` of the row's
    /// nonlinear term at the deviation of `x` from the point `x̄` of the factorisation.
    scale2: Vec<f64>,
    dev: Vec<Vf>,
    /// From the last evaluation, the largest `Lₖ²/scale2ₖ` and `Qₖ²/scale2ₖ`, where
    /// `Lₖω + Qₖω²` bounds how much the row's terms can move when no unknown moves by more
    /// than `ω` (see [`bound`](Self::bound)), and since then the largest `|Wₖ|²`, which bounds
    /// `ω²`.
    sens2: f64,
    quad2: f64,
    dev2: f64,
    /// Closed: the border column (eliminated in the forward sweep, then `Zₖ`), `A_{n−1}`,
    /// `D_{n−1}`, `C_{n−1}`, the inverse Schur complement of the last unknown.
    border: Vec<Bf>,
    a_last: Bf,
    d_last: Bf,
    c_last: Bf,
    schur_inv: Bf,
}

/// One row of the continuity equations: its residual, the squared size of its terms, and its
/// diagonal Jacobian block.
struct Row {
    f: Vf,
    scale2: f64,
    /// `Lₖ` and `Qₖ`: the row's terms move by at most `Lₖω + Qₖω²` when no unknown moves by
    /// more than `ω`.
    lip: f64,
    quad: f64,
    d: Bf,
}

/// The block LU factors of one row: `Lₖ = Aₖ D̃ₖ₋₁⁻¹`, `D̃ₖ⁻¹` and `Gₖ = D̃ₖ⁻¹ Cₖ`.
struct RowFactors {
    l: Bf,
    dinv: Bf,
    gm: Bf,
}

/// The factorisation met a singular pivot block.
pub(super) struct Singular;

#[allow(
    clippy::needless_range_loop,
    reason = "element loops over the fixed-size blocks, indexed like the formulas"
)]
impl<'g> FixedSolver<'g> {
    /// The solver for `g`, of tangent dimension `g.m ≤ M`: a smaller dimension is padded with
    /// zero coordinates (zero directions, fixed velocities and unknowns, an identity holonomy),
    /// on which the equations decouple into `σ·0 = 0`; the padded unknowns stay exactly 0.
    pub(super) fn new(g: &'g Geometry) -> Self {
        let m = g.m;
        debug_assert!(m <= M, "tangent dimension {m} above {M}");
        let arr = |s: &[f64]| -> Vf { vf(|a| if a < m { s[a] } else { 0.0 }) };
        let e = g.ehat.chunks_exact(m).map(arr).collect();
        let hol = if g.closed {
            bf(|a, b| {
                if a < m && b < m {
                    g.hol[a * m + b]
                } else if a == b {
                    1.0
                } else {
                    0.0
                }
            })
        } else {
            DMat3::ZERO
        };
        let fixed = g.fixed.as_ref().map(|(g0, g1)| (arr(g0), arr(g1)));
        let n = g.n;
        let zero = DMat3::ZERO;
        // The rows are filled in order by the first factorisation ([`put`]).
        Self {
            g,
            e,
            hol,
            fixed,
            fac: Vec::with_capacity(n),
            scale2: Vec::with_capacity(n),
            dev: Vec::with_capacity(n),
            sens2: 0.0,
            quad2: 0.0,
            dev2: 0.0,
            border: if g.closed {
                Vec::with_capacity(n)
            } else {
                Vec::new()
            },
            a_last: zero,
            d_last: zero,
            c_last: zero,
            schur_inv: zero,
        }
    }

    /// `Hᵀ·y`.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn hol_t(&self, y: Vf) -> Vf {
        self.hol.transpose() * y
    }

    /// The block `Aₖ` of a non-fixed row (the coupling to the unknown before; `seam`: the first
    /// row of a loop, coupled across the seam).
    fn a_block(&self, k: usize, seam: bool) -> Bf {
        let p = if seam { self.g.n - 1 } else { k - 1 };
        let sc = &self.g.seg[p];
        let s = s_block(self.e[p], sc.sinc, sc.c2);
        if seam { self.hol * s } else { s }
    }

    /// The block `Cₖ` of a non-fixed row (the coupling to the unknown after; `seam`: the last
    /// row of a loop).
    fn c_block(&self, k: usize, seam: bool) -> Bf {
        let sc = &self.g.seg[k];
        let c = s_block(self.e[k], sc.inv_sinc, sc.c2);
        if seam { c * self.hol.transpose() } else { c }
    }

    /// `S⁻¹ H̃ᵀ x_{seg+1}` (the end velocity of segment `seg` in its transported frame; the
    /// holonomy only across the seam).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn end_velocity(&self, seg: usize, seam: bool, x: &[Vf]) -> Vf {
        let u = if seam { self.hol_t(x[0]) } else { x[seg + 1] };
        s_vec(self.e[seg], self.g.seg[seg].inv_sinc, u)
    }

    /// Row `k` at `x`, given the end velocities of the segments before (`w_prev`) and after
    /// (`w_next`) the key; `first` and `last` say whether `k` is the first or last key (the
    /// callers pass constants, so the interior rows have no branches).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn row(&self, k: usize, first: bool, last: bool, x: &[Vf], w_prev: Vf, w_next: Vf) -> Row {
        let g = self.g;
        let n = g.n;
        let mut row = Row {
            f: DVec3::ZERO,
            scale2: 0.0,
            lip: 0.0,
            quad: 0.0,
            d: DMat3::ZERO,
        };
        let xk = x[k];
        if (first || last)
            && let Some((g0, g1)) = self.fixed
        {
            let (gk, c4) = if first {
                (g0, g.seg[0].c4)
            } else {
                (g1, g.seg[k - 1].c4)
            };
            row.f = (xk - gk) * c4;
            row.scale2 = c4 * c4 * (xk.dot(xk) + gk.dot(gk));
            row.d = DMat3::from_diagonal(DVec3::splat(c4));
            return row;
        }
        let mut diag = 0.0;
        // The segment before the key (across the seam for the first key of a loop).
        if !first || g.closed {
            let (p, seam) = if first { (n - 1, true) } else { (k - 1, false) };
            let sc = &g.seg[p];
            let e = self.e[p];
            let mut y = s_vec(e, sc.sinc, x[p]) * sc.c2;
            let lin2 = y.dot(y);
            let t2 = add_t(sc, e.as_ref(), w_prev.as_ref(), y.as_mut());
            y -= e * sc.c6;
            row.f += if seam { self.hol * y } else { y };
            row.scale2 += lin2 + t2 + sc.c6 * sc.c6;
            diag += sc.c4;
            // `c₂S·x_{k−1}` moves by at most `c₂ω`; `T(w)` by `|B(W, W + 2w)| ≤ c_B·ω(ω + 2|w|)`
            // (`|B(a, b)| ≤ (|κ| + |sinc′|)·|a||b|`, `W = S⁻¹Δxₖ`, `|Δxₖ| ≤ |W| ≤ ω`).
            let c_b = sc.kappa.abs() + sc.dsinc.abs();
            row.lip += sc.c2 + 2.0 * c_b * w_prev.length();
            row.quad = c_b;
            // DT·S⁻¹ at the end velocity `w_prev` (the derivative of T(S⁻¹ H̃ᵀ xₖ)):
            // β·I + ê qᵀ + γ·w⊥ êᵀ with q = α·w⊥ − β·ê.
            let u = w_prev;
            let up = u.dot(e);
            let w_perp = u - e * up;
            let alpha = 2.0 * sc.inv_sinc * sc.kappa;
            let beta = 2.0 * sc.inv_sinc * sc.dsinc * up;
            let gamma = 2.0 * sc.dsinc;
            let q = w_perp * alpha - e * beta;
            let dt = bf(|i, j| {
                let v = e[i] * q[j] + gamma * w_perp[i] * e[j];
                if i == j { v + beta } else { v }
            });
            row.d = if seam {
                self.hol * dt * self.hol.transpose()
            } else {
                dt
            };
        }
        // The segment after the key (for the last key of a loop, the closing segment).
        if !last || g.closed {
            let sc = &g.seg[k];
            let e = self.e[k];
            row.f += w_next * sc.c2 - e * sc.c6;
            row.scale2 += sc.c2 * sc.c2 * w_next.dot(w_next) + sc.c6 * sc.c6;
            diag += sc.c4;
            row.lip += sc.c2 * sc.inv_sinc;
        }
        row.lip += diag;
        row.f += xk * diag;
        row.scale2 += diag * diag * xk.dot(xk);
        row.d.x_axis.x += diag;
        row.d.y_axis.y += diag;
        row.d.z_axis.z += diag;
        row
    }

    /// The forward sweep at `x`: the Jacobian's rows are built and factorised, and row `k`'s
    /// residual is eliminated into `z[k]`. Returns the largest row residual relative to the
    /// size of the row's terms (infinite for a non-finite residual).
    ///
    /// With `ul`, `x` is first corrected ([`correct`](Self::correct)), one row ahead of the
    /// sweep, from the right-hand side in `z` that [`linear_step`](Self::linear_step) left.
    pub(super) fn sweep(
        &mut self,
        x: &mut [Vf],
        z: &mut [Vf],
        ul: Option<&[f64]>,
    ) -> Result<f64, Singular> {
        let g = self.g;
        let n = g.n;
        let mut worst2 = 0.0_f64;
        (self.sens2, self.quad2, self.dev2) = (0.0, 0.0, 0.0);
        let mut w_prev = if g.closed {
            self.end_velocity(n - 1, true, x)
        } else {
            DVec3::ZERO
        };
        let mut prev = DVec3::ZERO;
        if let Some(ul) = ul {
            self.correct(0, x, z, ul, &mut prev);
            self.correct(1, x, z, ul, &mut prev);
        }
        self.edge_row(0, true, x, z, &mut w_prev, &mut worst2)?;
        for k in 1..n - 1 {
            if let Some(ul) = ul {
                self.correct(k + 1, x, z, ul, &mut prev);
            }
            self.sweep_row(k, false, false, x, z, &mut w_prev, &mut worst2)?;
        }
        self.edge_row(n - 1, false, x, z, &mut w_prev, &mut worst2)?;
        if g.closed {
            self.finish_border()?;
        }
        Ok(worst2.sqrt())
    }

    /// The first or last row: [`sweep_row`](Self::sweep_row) out of line (the interior rows
    /// are inlined into the sweep's loop, specialised for their position).
    #[inline(never)]
    fn edge_row(
        &mut self,
        k: usize,
        first: bool,
        x: &[Vf],
        z: &mut [Vf],
        w_prev: &mut Vf,
        worst2: &mut f64,
    ) -> Result<(), Singular> {
        self.sweep_row(k, first, !first, x, z, w_prev, worst2)
    }

    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    #[allow(
        clippy::too_many_arguments,
        reason = "the state carried from row to row"
    )]
    fn sweep_row(
        &mut self,
        k: usize,
        first: bool,
        last: bool,
        x: &[Vf],
        z: &mut [Vf],
        w_prev: &mut Vf,
        worst2: &mut f64,
    ) -> Result<(), Singular> {
        let g = self.g;
        let n = g.n;
        let w_next = if !last {
            self.end_velocity(k, false, x)
        } else if g.closed {
            self.end_velocity(n - 1, true, x)
        } else {
            DVec3::ZERO
        };
        let row = self.row(k, first, last, x, *w_prev, w_next);
        *w_prev = w_next;
        raise_worst(row.f, row.scale2, worst2);
        // (Rows without the nonlinear term are solved exactly by a chord step.)
        if !first || g.closed {
            for (c, max2) in [(row.lip, &mut self.sens2), (row.quad, &mut self.quad2)] {
                if c * c > *max2 * row.scale2 {
                    *max2 = if row.scale2 > 0.0 {
                        c * c / row.scale2
                    } else {
                        f64::INFINITY
                    };
                }
            }
        }
        put(&mut self.scale2, k, row.scale2);
        put(&mut self.dev, k, DVec3::ZERO);
        if g.closed && last {
            // The Schur row: kept whole, eliminated in `back`.
            z[k] = row.f;
            self.a_last = self.a_block(k, false);
            self.d_last = row.d;
            self.c_last = self.c_block(k, true);
            return Ok(());
        }
        // A fixed row has no coupling; the others couple to both neighbours (the first key of
        // an open curve has no row before it).
        let fixed = (first || last) && self.fixed.is_some();
        let coupled_prev = !fixed && (!first || g.closed);
        let mut d = row.d;
        let l = if coupled_prev && !first {
            let (e, sc, prev) = (self.e[k - 1], &g.seg[k - 1], &self.fac[k - 1]);
            d -= s_left(e, sc.sinc, sc.c2, &prev.gm);
            s_left(e, sc.sinc, sc.c2, &prev.dinv)
        } else {
            DMat3::ZERO
        };
        let dinv = invertf(&d).ok_or(Singular)?;
        let merge = g.closed && k + 2 == n;
        if g.closed {
            let mut b = if first {
                self.a_block(k, true)
            } else {
                -(l * self.border[k - 1])
            };
            if merge {
                b += self.c_block(k, false);
            }
            put(&mut self.border, k, b);
        }
        let gm = if fixed || merge || last {
            DMat3::ZERO
        } else {
            let (e, sc) = (self.e[k], &g.seg[k]);
            s_right(&dinv, e, sc.inv_sinc, sc.c2)
        };
        // The elimination with the row's own `l` (not read back from `fac`, just stored).
        z[k] = row.f;
        if !first {
            eliminate_with(&l, k, z);
        }
        put(&mut self.fac, k, RowFactors { l, dinv, gm });
        Ok(())
    }

    /// `zₖ ← zₖ − Lₖ zₖ₋₁`.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn eliminate_row(&self, k: usize, z: &mut [Vf]) {
        eliminate_with(&self.fac[k].l, k, z);
    }

    /// The forward elimination of a chord step: `z` holds the residual `F(x)` (from
    /// [`back`](Self::back)'s update), and is overwritten by `L⁻¹F(x)` (the last row of a loop
    /// is the Schur row, kept whole).
    fn eliminate(&self, z: &mut [Vf]) {
        let rows = self.g.n - usize::from(self.g.closed);
        for k in 1..rows {
            self.eliminate_row(k, z);
        }
    }

    /// The residual of row `k` after the chord step `x ← x − d` (`d = dₖ`, the step of the
    /// row's unknown), from the residual `F(x) + J(x̄)(−d) = 0` that the step solves: the
    /// equations are linear in `x` except for the term `T(wₖ)` of the segment before the key,
    /// a quadratic form `B(w, w)` in the end velocity `wₖ = S⁻¹H̃ᵀxₖ`, so with `Wₖ = wₖ(x − x̄)`
    /// and `s = wₖ(d)`,
    ///
    /// ```text
    /// F(x − d)ₖ = T(w − s) − T(w) + DT(w̄)s = B(s − 2W, s)   (H̃ applied across the seam)
    /// ```
    ///
    /// exactly; `Wₖ` becomes `W − s`. Rows without the term (a fixed row, the first row of an
    /// open curve) are linear and solved exactly: 0.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn update(&mut self, k: usize, d: &Vf) -> Vf {
        let g = self.g;
        let (p, seam) = if k > 0 {
            (k - 1, false)
        } else if g.closed {
            (g.n - 1, true)
        } else {
            // No nonlinear term: `dev` keeps the deviation of the unknown itself (for `dev2`).
            let w = &mut self.dev[0];
            *w -= *d;
            self.dev2 = self.dev2.max(w.dot(*w));
            return DVec3::ZERO;
        };
        if self.fixed.is_some() && k + 1 == g.n {
            return DVec3::ZERO;
        }
        let (sc, e) = (&g.seg[p], self.e[p]);
        let s = s_vec(e, sc.inv_sinc, if seam { self.hol_t(*d) } else { *d });
        let w = &mut self.dev[k];
        let a = s - *w * 2.0;
        *w -= s;
        let w2 = w.dot(*w);
        if w2 > self.dev2 {
            self.dev2 = w2;
        }
        let f = bilinear_t(sc, e, a, s);
        if seam { self.hol * f } else { f }
    }

    /// The first step of an open curve, `x ← −J(0)⁻¹F(0)`, from `x = 0`; returns the relative
    /// residual at `0`.
    ///
    /// At `x = 0` the end velocities vanish, so `T` and its derivative do too: the Jacobian is
    /// the linear part, whose blocks are `Aₖ = (2/hₖ₋₁)Sₖ₋₁`, `Dₖ = dₖ·I` and
    /// `Cₖ = (2/hₖ)Sₖ⁻¹`. Since `Aₖ₊₁Cₖ = (2/hₖ)²·I`, every pivot block of its LU factorisation is
    /// a multiple of the identity, `δₖ = dₖ − (2/hₖ₋₁)²/δₖ₋₁` (a fixed end row has no coupling),
    /// and the step costs two sweeps of `S`-products (the Euclidean spline's recurrence); `piv`
    /// receives `1/δₖ`.
    ///
    /// The backward sweep also prepares the correction ([`correct`](Self::correct)): as each
    /// `xₖ` comes out, the residual there, `T(wₖ)`, is eliminated from the last row up (the
    /// pivots of that direction, `πₖ = dₖ − (2/hₖ)²/πₖ₊₁`, are scalars too) into `z`, and
    /// `ul` receives `1/πₖ` (the forward sweep leaves the diagonal `dₖ` there).
    pub(super) fn linear_step(
        &self,
        x: &mut [Vf],
        piv: &mut [f64],
        z: &mut [Vf],
        ul: &mut [f64],
    ) -> f64 {
        let g = self.g;
        let n = g.n;
        let fixed = self.fixed;
        let mut worst2 = 0.0_f64;
        let mut z_prev = DVec3::ZERO;
        let mut inv_prev = 1.0;
        for k in 0..n {
            let mut f = DVec3::ZERO;
            let mut scale2 = 0.0;
            let mut d = 0.0;
            let mut z;
            match fixed {
                Some((g0, g1)) if k == 0 || k + 1 == n => {
                    let (gk, c4) = if k == 0 {
                        (g0, g.seg[0].c4)
                    } else {
                        (g1, g.seg[k - 1].c4)
                    };
                    f = gk * -c4;
                    scale2 = c4 * c4 * gk.dot(gk);
                    d = c4;
                    ul[k] = d;
                    z = f;
                }
                _ => {
                    for seg in [k.checked_sub(1), (k + 1 < n).then_some(k)]
                        .into_iter()
                        .flatten()
                    {
                        let sc = &g.seg[seg];
                        f -= self.e[seg] * sc.c6;
                        scale2 += sc.c6 * sc.c6;
                        d += sc.c4;
                    }
                    z = f;
                    ul[k] = d;
                    if k > 0 {
                        let sc = &g.seg[k - 1];
                        let az = s_vec(self.e[k - 1], sc.sinc, z_prev);
                        let c = sc.c2 * inv_prev;
                        z -= az * c;
                        if fixed.is_none() || k > 1 {
                            d -= sc.c2 * c;
                        }
                    }
                }
            }
            let fn2 = f.dot(f);
            if fn2 > worst2 * scale2 || !fn2.is_finite() {
                worst2 = if fn2.is_finite() && scale2 > 0.0 {
                    fn2 / scale2
                } else {
                    f64::INFINITY
                };
            }
            let inv = 1.0 / d;
            piv[k] = inv;
            x[k] = z;
            z_prev = z;
            inv_prev = inv;
        }
        let mut next = x[n - 1] * piv[n - 1];
        x[n - 1] = -next;
        // The correction's right-hand side `T(wₖ)` (the residual at the new x) and its
        // elimination from the last row up, as each `xₖ` comes out (see `correct`).
        let is_fixed = |k: usize| fixed.is_some() && (k == 0 || k + 1 == n);
        let mut zeta = self.tee(n - 1, x[n - 1]);
        let mut pi = ul[n - 1];
        z[n - 1] = zeta;
        ul[n - 1] = 1.0 / pi;
        for k in (0..n - 1).rev() {
            let mut t = x[k];
            let coupled_next = fixed.is_none() || k > 0;
            if coupled_next {
                let sc = &g.seg[k];
                t -= s_vec(self.e[k], sc.inv_sinc, next) * sc.c2;
            }
            next = t * piv[k];
            x[k] = -next;
            let mut r = self.tee(k, x[k]);
            let mut d = ul[k];
            if coupled_next {
                let sc = &g.seg[k];
                let c = sc.c2 * ul[k + 1];
                zeta = s_vec(self.e[k], sc.inv_sinc, zeta);
                r -= zeta * c;
                if !is_fixed(k + 1) {
                    d -= sc.c2 * c;
                }
            }
            zeta = r;
            pi = d;
            z[k] = zeta;
            ul[k] = 1.0 / pi;
        }
        worst2.sqrt()
    }

    /// The nonlinear term `T(wₖ)` of row `k` of an open curve at `xₖ` (0 for the rows without
    /// it: the first and the fixed ones).
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn tee(&self, k: usize, xk: Vf) -> Vf {
        let mut f = DVec3::ZERO;
        if k > 0 && !(self.fixed.is_some() && k + 1 == self.g.n) {
            let (sc, e) = (&self.g.seg[k - 1], self.e[k - 1]);
            let w = s_vec(e, sc.inv_sinc, xk);
            add_t(sc, e.as_ref(), w.as_ref(), f.as_mut());
        }
        f
    }

    /// Row `k` of the correction `x ← x − J(0)⁻¹T(w(x))` after
    /// [`linear_step`](Self::linear_step) (an open curve), which leaves the right-hand side
    /// eliminated from the last row up in `z` and those pivots in `ul`: the forward
    /// substitution, `prev` the correction of the row before. The linear part is solved at
    /// the linear step's `x`, so the residual there is the nonlinear term; this step with the
    /// linear Jacobian (scalar pivots, as in the linear step) takes `x` about 30× closer to the
    /// solution before Newton's first factorisation.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
    fn correct(&self, k: usize, x: &mut [Vf], z: &[Vf], ul: &[f64], prev: &mut Vf) {
        let g = self.g;
        let mut t = z[k];
        if k > 0 && !(self.fixed.is_some() && k + 1 == g.n) {
            let sc = &g.seg[k - 1];
            *prev = s_vec(self.e[k - 1], sc.sinc, *prev);
            t -= *prev * sc.c2;
        }
        *prev = t * ul[k];
        x[k] -= *prev;
    }

    /// Closed: `Zₖ` from the eliminated border column, and the inverse Schur complement.
    fn finish_border(&mut self) -> Result<(), Singular> {
        let n = self.g.n;
        let rows = n - 1;
        let mut next = self.fac[rows - 1].dinv * self.border[rows - 1];
        self.border[rows - 1] = next;
        for k in (0..rows - 1).rev() {
            let zk = self.fac[k].dinv * self.border[k] - self.fac[k].gm * next;
            self.border[k] = zk;
            next = zk;
        }
        let t1 = self.a_last * self.border[n - 2];
        let t2 = self.c_last * self.border[0];
        let s = self.d_last - (t1 + t2);
        self.schur_inv = invertf(&s).ok_or(Singular)?;
        Ok(())
    }

    /// The updated residual `worst` (each row relative to the size of its terms at the last
    /// evaluation, [`back`](Self::back)) as a bound of the relative residual at the new `x`:
    /// no unknown has moved by more than `ω` (`ω² ≤ dev2`) since, so the size of row `k`'s
    /// terms is at least `√scale2ₖ − Lₖω − Qₖω² ≥ √scale2ₖ·(1 − δ)` with
    /// `δ = ω·√sens2 + ω²·√quad2`, and the relative residual at most `worst/(1 − δ)`.
    /// Infinite (no bound) unless `δ < 1`.
    fn bound(&self, worst: f64) -> f64 {
        let delta = (self.sens2 * self.dev2).sqrt() + self.dev2 * self.quad2.sqrt();
        if delta < 1.0 {
            worst / (1.0 - delta)
        } else {
            f64::INFINITY
        }
    }

    /// The backward sweep: `x ← x − J⁻¹F` from the eliminated residual `z`, which is
    /// overwritten by the residual at the new `x` ([`update`](Self::update)). Returns its
    /// largest row relative to the size of the row's terms at the last evaluation.
    fn back(&mut self, z: &mut [Vf], x: &mut [Vf]) -> f64 {
        let n = self.g.n;
        let mut worst2 = 0.0_f64;
        if !self.g.closed {
            let mut next = self.fac[n - 1].dinv * z[n - 1];
            x[n - 1] -= next;
            z[n - 1] = self.update(n - 1, &next);
            raise_worst(z[n - 1], self.scale2[n - 1], &mut worst2);
            for k in (0..n - 1).rev() {
                let f = &self.fac[k];
                let d = f.dinv * z[k] - f.gm * next;
                x[k] -= d;
                z[k] = self.update(k, &d);
                raise_worst(z[k], self.scale2[k], &mut worst2);
                next = d;
            }
            return worst2.sqrt();
        }
        let rows = n - 1;
        let mut next = self.fac[rows - 1].dinv * z[rows - 1];
        z[rows - 1] = next;
        for k in (0..rows - 1).rev() {
            let f = &self.fac[k];
            next = f.dinv * z[k] - f.gm * next;
            z[k] = next;
        }
        let rhs = z[n - 1] - (self.a_last * z[n - 2] + self.c_last * z[0]);
        let last = self.schur_inv * rhs;
        for k in 0..rows {
            let d = z[k] - self.border[k] * last;
            x[k] -= d;
            z[k] = self.update(k, &d);
            raise_worst(z[k], self.scale2[k], &mut worst2);
        }
        x[n - 1] -= last;
        z[n - 1] = self.update(n - 1, &last);
        raise_worst(z[n - 1], self.scale2[n - 1], &mut worst2);
        worst2.sqrt()
    }

    /// [`Geometry::solve`] for the fixed dimension: with the correction of the linear step
    /// ([`correct`](Self::correct)), and without it if that fails (far from the linear
    /// solution the correction can lead Newton's method astray, as on keys of alternating signs
    /// on S³, where the uncorrected iteration still converges).
    pub(super) fn solve(mut self) -> Result<(Vec<f64>, CubicSolveInfo), SplineError> {
        self.run(true).or_else(|_| self.run(false))
    }

    fn run(&mut self, correct: bool) -> Result<(Vec<f64>, CubicSolveInfo), SplineError> {
        let n = self.g.n;
        let mut x = vec![DVec3::ZERO; n];
        let mut z = vec![DVec3::ZERO; n];
        let fail = |info: CubicSolveInfo| {
            SplineError::Solve(SolveError::NoConvergence {
                iterations: info.iterations,
                residual: info.residual,
            })
        };
        let mut info = CubicSolveInfo {
            iterations: 0,
            factorizations: 1,
            residual: f64::INFINITY,
        };
        // The Jacobian at x = 0 is the linear part: the first step is scipy's first iterate.
        let mut residual;
        if self.g.closed {
            residual = self.sweep(&mut x, &mut z, None).map_err(|_| fail(info))?;
        } else {
            let (mut piv, mut ul) = (vec![0.0; n], vec![0.0; n]);
            residual = self.linear_step(&mut x, &mut piv, &mut z, &mut ul);
            if residual > TARGET_RESIDUAL {
                info.iterations = 1;
                info.factorizations = 2;
                let new = self
                    .sweep(&mut x, &mut z, correct.then_some(&ul[..]))
                    .map_err(|_| fail(info))?;
                if !new.is_finite() || new >= residual {
                    info.residual = new;
                    return Err(fail(info));
                }
                residual = new;
            } else {
                x.fill(DVec3::ZERO);
            }
        }
        info.residual = residual;
        // Whether the factors were built at the current `x` (and `residual` evaluated there).
        let mut fresh = true;
        while residual > TARGET_RESIDUAL && info.iterations < MAX_ITERATIONS {
            let updated = self.back(&mut z, &mut x);
            info.iterations += 1;
            // Refactorise after the first step of a loop (from x = 0).
            let refactor = info.iterations == 1;
            let mut new = if refactor {
                info.factorizations += 1;
                self.sweep(&mut x, &mut z, None).map_err(|_| fail(info))?
            } else {
                updated
            };
            info.residual = new;
            if !new.is_finite() {
                return Err(fail(info));
            }
            if new >= residual && fresh {
                // No progress with a fresh Jacobian: rounding level reached.
                residual = new;
                break;
            }
            fresh = refactor;
            if !refactor {
                // The updated residual is relative to the terms at the last evaluation.
                new = self.bound(new);
                info.residual = new;
            }
            if !refactor && new > TARGET_RESIDUAL {
                if new > 0.1 * residual {
                    // Slow convergence: refactorise at this x (the sweep again, with the factors).
                    info.factorizations += 1;
                    new = self.sweep(&mut x, &mut z, None).map_err(|_| fail(info))?;
                    fresh = true;
                } else if info.iterations < MAX_ITERATIONS {
                    // The next chord step (not needed once the residual meets the target).
                    self.eliminate(&mut z);
                }
            }
            residual = new;
        }
        info.residual = residual;
        let flat: Vec<f64> = x
            .iter()
            .flat_map(|v| v.to_array().into_iter().take(self.g.m))
            .collect();
        if residual.is_nan() || residual > MAX_RESIDUAL || flat.iter().any(|v| !v.is_finite()) {
            return Err(fail(info));
        }
        Ok((flat, info))
    }
}
