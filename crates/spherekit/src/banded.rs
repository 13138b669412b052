// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Block tridiagonal and bordered cyclic block tridiagonal systems: factorised once, solved for
//! as many right-hand sides as needed.
//!
//! Row `k` of the system is
//!
//! ```text
//! Aₖ·x_{k−1} + Dₖ·xₖ + Cₖ·x_{k+1} = bₖ,   k = 0 … n−1,
//! ```
//!
//! with `b × b` blocks (row-major, stored flat: block `k` is `[k·b², (k+1)·b²)`). An **open**
//! system has no `A₀` and no `C_{n−1}` (they are ignored). A **cyclic** one wraps around: `A₀`
//! couples row 0 to `x_{n−1}` and `C_{n−1}` couples row `n−1` to `x₀`.
//!
//! The factorisation is block LU without pivoting between blocks (the systems here are block
//! diagonally dominant or close to it), with the pivot blocks inverted explicitly
//! ([`invert`], Gauss–Jordan with partial pivoting inside the block):
//!
//! ```text
//! D̃₀ = D₀,   Lₖ = Aₖ·D̃ₖ₋₁⁻¹,   D̃ₖ = Dₖ − Lₖ·Cₖ₋₁,
//! ```
//!
//! forward `yₖ = bₖ − Lₖ·yₖ₋₁`, back `xₖ = D̃ₖ⁻¹·(yₖ − Cₖ·xₖ₊₁)`. A cyclic system is solved by
//! **bordering** the last unknown: rows `0 … n−2` form a block tridiagonal system with an extra
//! block column `G` (`G₀ = A₀`, `G_{n−2} = C_{n−2}`, zero between), whose factorisation
//! carries `G̃ₖ = Gₖ − Lₖ·G̃ₖ₋₁` along and gives `Z = T⁻¹G` by the back substitution
//! `Zₖ = D̃ₖ⁻¹·(G̃ₖ − Cₖ·Zₖ₊₁)`; the last unknown then solves the `b × b` Schur complement
//!
//! ```text
//! (D_{n−1} − A_{n−1}·Z_{n−2} − C_{n−1}·Z₀)·x_{n−1} = b_{n−1} − A_{n−1}·w_{n−2} − C_{n−1}·w₀,
//! ```
//!
//! with `w = T⁻¹b`, and `xₖ = wₖ − Zₖ·x_{n−1}`. Both cost O(n·b³) to factorise and O(n·b²) per
//! solve (Golub & Van Loan, *Matrix Computations*, 4th ed., §4.5.1 block tridiagonal LU; the
//! bordering as in §4.3 for periodic tridiagonal systems).
//!
//! The cubic spline's general-dimension solver and the Beta-spline solver factorise through
//! here. The cubic's 3-D solver ([`cubic`](crate::cubic)) runs the same recurrences on
//! `glam` blocks, fused with the evaluation of its equations (its tests compare the two).

/// The factors of a block tridiagonal (open) or bordered cyclic block tridiagonal system.
#[derive(Clone, Debug)]
pub(crate) struct BlockTridiagonal {
    /// Block size `b` and number of block rows `n`.
    b: usize,
    n: usize,
    cyclic: bool,
    /// `D̃ₖ⁻¹`, `Lₖ` and `Cₖ` of the block tridiagonal part (rows `0 … n−1` open, `0 … n−2`
    /// cyclic; `C_{n−2}` of a cyclic system is in the border column).
    dinv: Vec<f64>,
    l: Vec<f64>,
    c: Vec<f64>,
    /// Cyclic: `Zₖ` (rows `0 … n−2`), `A_{n−1}`, `C_{n−1}` and the inverse Schur complement.
    z: Vec<f64>,
    a_last: Vec<f64>,
    c_last: Vec<f64>,
    schur_inv: Vec<f64>,
}

impl BlockTridiagonal {
    /// Factorises the system with blocks `a`, `d`, `c` (each `n·b²` long, see the
    /// [module docs](self)); `cyclic` needs `n ≥ 3`. `None` if a pivot block (or the Schur
    /// complement) is singular or not finite, or the lengths do not match.
    pub(crate) fn factor(b: usize, a: &[f64], d: &[f64], c: &[f64], cyclic: bool) -> Option<Self> {
        let bb = b * b;
        let n = d.len().checked_div(bb)?;
        if b == 0 || d.len() != n * bb || a.len() != d.len() || c.len() != d.len() {
            return None;
        }
        if cyclic && n < 3 {
            return None;
        }
        let rows = if cyclic { n - 1 } else { n };
        let mut fac = Self {
            b,
            n,
            cyclic,
            dinv: vec![0.0; rows * bb],
            l: vec![0.0; rows * bb],
            c: vec![0.0; rows * bb],
            z: Vec::new(),
            a_last: Vec::new(),
            c_last: Vec::new(),
            schur_inv: Vec::new(),
        };
        let block = |v: &[f64], k: usize| v[k * bb..(k + 1) * bb].to_vec();
        let mut dk = vec![0.0; bb];
        let mut tmp = vec![0.0; bb];
        let mut tmp2 = vec![0.0; bb];
        // The border column G̃ (cyclic only).
        let mut border = if cyclic {
            vec![0.0; rows * bb]
        } else {
            Vec::new()
        };
        if cyclic {
            border[..bb].copy_from_slice(&a[..bb]);
        }
        for k in 0..rows {
            dk.copy_from_slice(&d[k * bb..(k + 1) * bb]);
            if k > 0 {
                // Lₖ = Aₖ D̃ₖ₋₁⁻¹; D̃ₖ = Dₖ − Lₖ Cₖ₋₁.
                mat_mul(
                    b,
                    &a[k * bb..(k + 1) * bb],
                    &fac.dinv[(k - 1) * bb..k * bb],
                    &mut tmp,
                );
                fac.l[k * bb..(k + 1) * bb].copy_from_slice(&tmp);
                mat_mul(b, &tmp, &fac.c[(k - 1) * bb..k * bb], &mut tmp2);
                for (dv, t) in dk.iter_mut().zip(&tmp2) {
                    *dv -= t;
                }
                if cyclic {
                    // G̃ₖ = Gₖ − Lₖ G̃ₖ₋₁.
                    mat_mul(b, &tmp, &border[(k - 1) * bb..k * bb], &mut tmp2);
                    for (g, t) in border[k * bb..(k + 1) * bb].iter_mut().zip(&tmp2) {
                        *g -= t;
                    }
                }
            }
            let ck = &c[k * bb..(k + 1) * bb];
            if cyclic && k + 1 == rows {
                // The coupling of row n−2 to x_{n−1} belongs to the border column.
                for (g, cv) in border[k * bb..(k + 1) * bb].iter_mut().zip(ck) {
                    *g += cv;
                }
            } else if k + 1 < n {
                fac.c[k * bb..(k + 1) * bb].copy_from_slice(ck);
            }
            if !invert(b, &dk, &mut fac.dinv[k * bb..(k + 1) * bb]) {
                return None;
            }
        }
        if cyclic {
            // Z_{n−2} = D̃⁻¹ G̃; Zₖ = D̃ₖ⁻¹ (G̃ₖ − Cₖ Zₖ₊₁).
            let mut z = vec![0.0; rows * bb];
            for k in (0..rows).rev() {
                tmp.copy_from_slice(&border[k * bb..(k + 1) * bb]);
                if k + 1 < rows {
                    mat_mul(
                        b,
                        &fac.c[k * bb..(k + 1) * bb],
                        &z[(k + 1) * bb..(k + 2) * bb],
                        &mut tmp2,
                    );
                    for (t, s) in tmp.iter_mut().zip(&tmp2) {
                        *t -= s;
                    }
                }
                mat_mul(b, &fac.dinv[k * bb..(k + 1) * bb], &tmp, &mut tmp2);
                z[k * bb..(k + 1) * bb].copy_from_slice(&tmp2);
            }
            // The Schur complement D − A Z_{n−2} − C Z₀.
            let (a_last, c_last) = (block(a, n - 1), block(c, n - 1));
            let mut s = block(d, n - 1);
            mat_mul(b, &a_last, &z[(n - 2) * bb..(n - 1) * bb], &mut tmp);
            mat_mul(b, &c_last, &z[..bb], &mut tmp2);
            for i in 0..bb {
                s[i] -= tmp[i] + tmp2[i];
            }
            let mut schur_inv = vec![0.0; bb];
            if !invert(b, &s, &mut schur_inv) {
                return None;
            }
            fac.z = z;
            fac.a_last = a_last;
            fac.c_last = c_last;
            fac.schur_inv = schur_inv;
        }
        Some(fac)
    }

    /// `x ← J⁻¹x` for a right-hand side `x` of `n·b` entries.
    pub(crate) fn solve(&self, x: &mut [f64]) {
        let (b, n) = (self.b, self.n);
        let bb = b * b;
        debug_assert_eq!(x.len(), n * b, "right-hand side length");
        let rows = if self.cyclic { n - 1 } else { n };
        let mut t = vec![0.0; b];
        // Forward: yₖ = bₖ − Lₖ yₖ₋₁.
        for k in 1..rows {
            mat_vec(
                b,
                &self.l[k * bb..(k + 1) * bb],
                &x[(k - 1) * b..k * b],
                &mut t,
            );
            for (xa, ta) in x[k * b..(k + 1) * b].iter_mut().zip(&t) {
                *xa -= ta;
            }
        }
        // Back: wₖ = D̃ₖ⁻¹ (yₖ − Cₖ wₖ₊₁).
        for k in (0..rows).rev() {
            if k + 1 < rows {
                mat_vec(
                    b,
                    &self.c[k * bb..(k + 1) * bb],
                    &x[(k + 1) * b..(k + 2) * b],
                    &mut t,
                );
                for (xa, ta) in x[k * b..(k + 1) * b].iter_mut().zip(&t) {
                    *xa -= ta;
                }
            }
            t.copy_from_slice(&x[k * b..(k + 1) * b]);
            mat_vec(
                b,
                &self.dinv[k * bb..(k + 1) * bb],
                &t,
                &mut x[k * b..(k + 1) * b],
            );
        }
        if self.cyclic {
            // x_{n−1} = S⁻¹ (b_{n−1} − A w_{n−2} − C w₀); xₖ = wₖ − Zₖ x_{n−1}.
            let mut rhs = x[(n - 1) * b..].to_vec();
            mat_vec(b, &self.a_last, &x[(n - 2) * b..(n - 1) * b], &mut t);
            for (r, ta) in rhs.iter_mut().zip(&t) {
                *r -= ta;
            }
            mat_vec(b, &self.c_last, &x[..b], &mut t);
            for (r, ta) in rhs.iter_mut().zip(&t) {
                *r -= ta;
            }
            let mut last = vec![0.0; b];
            mat_vec(b, &self.schur_inv, &rhs, &mut last);
            for k in 0..n - 1 {
                mat_vec(b, &self.z[k * bb..(k + 1) * bb], &last, &mut t);
                for (xa, ta) in x[k * b..(k + 1) * b].iter_mut().zip(&t) {
                    *xa -= ta;
                }
            }
            x[(n - 1) * b..].copy_from_slice(&last);
        }
    }
}

// The dense block algebra, inlined by force natively (in the cubic's 3-D solver loops the
// calls cost more than their arithmetic, and with the dimension a constant there the loops
// unroll); the wasm build, optimised for size, leaves inlining to the compiler. Inlining changes
// no result: Rust contracts no float operations.

/// `out = a·b` for `m × m` row-major blocks.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(crate) fn mat_mul(m: usize, a: &[f64], b: &[f64], out: &mut [f64]) {
    for i in 0..m {
        for j in 0..m {
            let mut s = 0.0;
            for l in 0..m {
                s += a[i * m + l] * b[l * m + j];
            }
            out[i * m + j] = s;
        }
    }
}

/// `out = a·bᵀ`, entry by entry the [`dot`] of a row of `a` and a row of `b`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(crate) fn mat_mul_t(m: usize, a: &[f64], b: &[f64], out: &mut [f64]) {
    for i in 0..m {
        for j in 0..m {
            out[i * m + j] = dot(&a[i * m..(i + 1) * m], &b[j * m..(j + 1) * m]);
        }
    }
}

/// `out = a·x`.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(crate) fn mat_vec(m: usize, a: &[f64], x: &[f64], out: &mut [f64]) {
    for i in 0..m {
        let mut s = 0.0;
        for l in 0..m {
            s += a[i * m + l] * x[l];
        }
        out[i] = s;
    }
}

/// `out = aᵀ·x`, summed as [`dot`].
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(crate) fn mat_t_vec(m: usize, a: &[f64], x: &[f64], out: &mut [f64]) {
    for (j, o) in out[..m].iter_mut().enumerate() {
        *o = (0..m).map(|l| a[l * m + j] * x[l]).sum();
    }
}

/// `a·b` for slices of equal length.
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `out = a⁻¹` for an `m × m` row-major block, by Gauss–Jordan elimination with partial
/// pivoting; `false` if a pivot is zero or not finite.
pub(crate) fn invert(m: usize, a: &[f64], out: &mut [f64]) -> bool {
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
    out[..m * m].iter().all(|v| v.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic pseudo-random number in [−1, 1).
    fn noise(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// Random blocks, the diagonal ones made dominant.
    fn system(b: usize, n: usize, seed: u64) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) {
        let mut s = seed;
        let mut draw = |len: usize| (0..len).map(|_| noise(&mut s)).collect::<Vec<_>>();
        let (a, mut d, c, rhs) = (
            draw(n * b * b),
            draw(n * b * b),
            draw(n * b * b),
            draw(n * b),
        );
        for k in 0..n {
            for i in 0..b {
                d[k * b * b + i * b + i] += 4.0 * b as f64;
            }
        }
        (a, d, c, rhs)
    }

    /// The dense matrix of the system.
    fn dense(b: usize, n: usize, a: &[f64], d: &[f64], c: &[f64], cyclic: bool) -> Vec<f64> {
        let size = n * b;
        let mut m = vec![0.0; size * size];
        let mut put = |row: usize, col: usize, blk: &[f64]| {
            for i in 0..b {
                for j in 0..b {
                    m[(row * b + i) * size + col * b + j] += blk[i * b + j];
                }
            }
        };
        let bb = b * b;
        for k in 0..n {
            put(k, k, &d[k * bb..(k + 1) * bb]);
            if k > 0 {
                put(k, k - 1, &a[k * bb..(k + 1) * bb]);
            } else if cyclic {
                put(0, n - 1, &a[..bb]);
            }
            if k + 1 < n {
                put(k, k + 1, &c[k * bb..(k + 1) * bb]);
            } else if cyclic {
                put(n - 1, 0, &c[k * bb..(k + 1) * bb]);
            }
        }
        m
    }

    fn residual(m: &[f64], x: &[f64], rhs: &[f64]) -> f64 {
        let size = rhs.len();
        (0..size)
            .map(|i| {
                let row: f64 = (0..size).map(|j| m[i * size + j] * x[j]).sum();
                (row - rhs[i]).abs()
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn open_and_cyclic_solves_match_the_dense_system() {
        for cyclic in [false, true] {
            for b in 1..=4 {
                for n in [3, 4, 7, 20] {
                    let (a, d, c, rhs) = system(b, n, (b * 31 + n) as u64);
                    let fac = BlockTridiagonal::factor(b, &a, &d, &c, cyclic).unwrap();
                    let mut x = rhs.clone();
                    fac.solve(&mut x);
                    let m = dense(b, n, &a, &d, &c, cyclic);
                    let r = residual(&m, &x, &rhs);
                    assert!(r < 1e-13, "cyclic {cyclic}, b {b}, n {n}: residual {r:e}");
                }
            }
        }
    }

    #[test]
    fn factors_are_reused_for_many_right_hand_sides() {
        let (b, n) = (3, 9);
        let (a, d, c, _) = system(b, n, 7);
        let fac = BlockTridiagonal::factor(b, &a, &d, &c, true).unwrap();
        let m = dense(b, n, &a, &d, &c, true);
        for seed in 0..5 {
            let (_, _, _, rhs) = system(b, n, 100 + seed);
            let mut x = rhs.clone();
            fac.solve(&mut x);
            assert!(residual(&m, &x, &rhs) < 1e-13);
        }
    }

    #[test]
    fn singular_pivots_and_bad_shapes_are_refused() {
        let (b, n) = (2, 4);
        let (a, mut d, c, _) = system(b, n, 3);
        assert!(BlockTridiagonal::factor(b, &a, &d, &c[..c.len() - 1], false).is_none());
        assert!(BlockTridiagonal::factor(b, &a[..2 * 4], &d[..2 * 4], &c[..2 * 4], true).is_none());
        d[..4].fill(0.0);
        let zero = vec![0.0; a.len()];
        assert!(BlockTridiagonal::factor(b, &zero, &d, &zero, false).is_none());
        d[0] = f64::NAN;
        assert!(BlockTridiagonal::factor(b, &a, &d, &c, false).is_none());
    }

    #[test]
    fn invert_is_the_inverse() {
        let mut s = 11;
        for m in 1..=6 {
            let mut a: Vec<f64> = (0..m * m).map(|_| noise(&mut s)).collect();
            for i in 0..m {
                a[i * m + i] += 2.0;
            }
            let mut inv = vec![0.0; m * m];
            assert!(invert(m, &a, &mut inv));
            let mut prod = vec![0.0; m * m];
            mat_mul(m, &a, &inv, &mut prod);
            for i in 0..m {
                for j in 0..m {
                    let id = if i == j { 1.0 } else { 0.0 };
                    assert!((prod[i * m + j] - id).abs() < 1e-14, "m {m}");
                }
            }
        }
        assert!(!invert(2, &[1.0, 2.0, 2.0, 4.0], &mut [0.0; 4]));
    }
}
