// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The trace of the hat matrix of the Euclidean cubic smoothing spline (Reinsch 1967), exact
//! and in O(n) by selected inversion of a banded matrix (Hutchinson & de Hoog 1985).
//!
//! For values `g` at the sample times, second derivatives `γ` at the interior knots (every
//! knot of a periodic spline), `Qᵀg = Rγ` and `∫g″² = γᵀRγ`, with `hᵢ = tᵢ₊₁ − tᵢ`,
//!
//! ```text
//! Q_{j−1,j} = 1/h_{j−1},  Q_{j,j} = −1/h_{j−1} − 1/h_j,  Q_{j+1,j} = 1/h_j,
//! R_{j,j} = (h_{j−1} + h_j)/3,  R_{j,j+1} = h_j/6,
//! ```
//!
//! the minimiser of `Σ wᵢ(yᵢ − gᵢ)² + λ∫g″²` is `g = y − λW⁻¹Qγ` with `Bγ = Qᵀy`,
//! `B = R + λ·QᵀW⁻¹Q` (pentadiagonal, cyclic when periodic), so the hat matrix `A` (`g = Ay`)
//! has `tr(I − A) = λ·tr(B⁻¹·QᵀW⁻¹Q)`, which needs only the five central bands of `B⁻¹`:
//! from `B = LDLᵀ` (`L` unit lower triangular with two subdiagonals), `Z = B⁻¹` satisfies
//! `Z = D⁻¹L⁻¹ + (I − Lᵀ)Z`, so from the last row up
//!
//! ```text
//! Z_{i,i+2} = −l₁ᵢ Z_{i+1,i+2} − l₂ᵢ Z_{i+2,i+2},   Z_{i,i+1} = −l₁ᵢ Z_{i+1,i+1} − l₂ᵢ Z_{i+1,i+2},
//! Z_{i,i}   = 1/Dᵢ − l₁ᵢ Z_{i,i+1} − l₂ᵢ Z_{i,i+2}.
//! ```
//!
//! A periodic `B` is its band plus four corner couplings, `B = B_b + P·S·Pᵀ` (`P` the columns
//! `0, 1, m−2, m−1` of the identity), and `B⁻¹ = B_b⁻¹ − Y·S·(I + PᵀY·S)⁻¹·Yᵀ`, `Y = B_b⁻¹P`
//! (four banded solves). Tiny periodic systems (`m < 7`) are inverted densely.
//!
//! This is the trace scipy's `make_smoothing_spline` computes for its generalised
//! cross-validation (by the same selected inversion, on B-spline coefficients).

use crate::banded::invert;

/// `tr A(λ)` of the smoothing spline with knots at `times` (closed: one more, the return
/// time), weights `w` and smoothing parameter `lambda`. Between `n` (λ = 0) and 2 (open, λ → ∞;
/// 1 when closed).
pub(crate) fn hat_trace(times: &[f64], w: &[f64], lambda: f64, closed: bool) -> f64 {
    let n = w.len();
    if lambda == 0.0 {
        return n as f64;
    }
    let cols = columns(times, closed);
    let m = cols.len();
    if m == 0 {
        return n as f64;
    }
    let h = |i: usize| times[i + 1] - times[i];
    // M = QᵀW⁻¹Q, entry by entry from the columns.
    let m_entry = |a: usize, b: usize| -> f64 {
        cols[a]
            .iter()
            .map(|&(i, qa)| {
                cols[b]
                    .iter()
                    .filter(|&&(k, _)| k == i)
                    .map(|&(_, qb)| qa * qb / w[i])
                    .sum::<f64>()
            })
            .sum()
    };
    if closed && m < 7 {
        return n as f64 - lambda * dense_trace(m, lambda, &h, &m_entry);
    }
    // Bands (offsets 0, 1, 2; wrapping around when closed) of M and of B = R + λM.
    let at = |a: usize, off: usize| {
        if closed {
            Some((a + off) % m)
        } else {
            (a + off < m).then_some(a + off)
        }
    };
    let mut mm = vec![[0.0; 3]; m];
    let mut band = vec![[0.0; 3]; m];
    for a in 0..m {
        let j = knot(a, closed);
        let (hp, hn) = (h(prev(j, n, closed)), h(j));
        for (off, entry) in mm[a].iter_mut().enumerate() {
            if let Some(b) = at(a, off) {
                *entry = m_entry(a, b);
            }
        }
        band[a] = [
            (hp + hn) / 3.0 + lambda * mm[a][0],
            if at(a, 1).is_some() {
                hn / 6.0 + lambda * mm[a][1]
            } else {
                0.0
            },
            lambda * mm[a][2],
        ];
    }
    let t = if closed {
        cyclic_trace(&band, &mm)
    } else {
        let (z, _) = selected_inverse(&band);
        (0..m)
            .map(|i| z[i][0] * mm[i][0] + 2.0 * z[i][1] * mm[i][1] + 2.0 * z[i][2] * mm[i][2])
            .sum()
    };
    n as f64 - lambda * t
}

/// The knot of column `a`: the interior knots `1 … n−2` of an open spline, every knot of a
/// periodic one.
fn knot(a: usize, closed: bool) -> usize {
    if closed { a } else { a + 1 }
}

fn prev(j: usize, n: usize, closed: bool) -> usize {
    if j == 0 && closed { n - 1 } else { j - 1 }
}

/// The columns of `Q` as `(row, value)` entries.
fn columns(times: &[f64], closed: bool) -> Vec<Vec<(usize, f64)>> {
    let n = if closed { times.len() - 1 } else { times.len() };
    let h = |i: usize| times[i + 1] - times[i];
    let m = if closed { n } else { n.saturating_sub(2) };
    (0..m)
        .map(|a| {
            let j = knot(a, closed);
            let p = prev(j, n, closed);
            let next = (j + 1) % n;
            let (hp, hn) = (h(p), h(j));
            vec![(p, 1.0 / hp), (j, -1.0 / hp - 1.0 / hn), (next, 1.0 / hn)]
        })
        .collect()
}

/// `LDLᵀ` of a symmetric pentadiagonal matrix given by its bands: `(D, l₁, l₂)`.
fn ldl(band: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let m = band.len();
    let mut f = vec![[0.0; 3]; m];
    for i in 0..m {
        let mut d = band[i][0];
        if i >= 1 {
            d -= f[i - 1][1] * f[i - 1][1] * f[i - 1][0];
        }
        if i >= 2 {
            d -= f[i - 2][2] * f[i - 2][2] * f[i - 2][0];
        }
        f[i][0] = d;
        if i + 1 < m {
            let mut b1 = band[i][1];
            if i >= 1 {
                b1 -= f[i - 1][2] * f[i - 1][1] * f[i - 1][0];
            }
            f[i][1] = b1 / d;
        }
        if i + 2 < m {
            f[i][2] = band[i][2] / d;
        }
    }
    f
}

/// The bands `Z_{i,i}, Z_{i,i+1}, Z_{i,i+2}` of the inverse of a symmetric pentadiagonal
/// matrix, and its factors.
fn selected_inverse(band: &[[f64; 3]]) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let m = band.len();
    let f = ldl(band);
    let mut z = vec![[0.0; 3]; m];
    for i in (0..m).rev() {
        let (l1, l2) = (f[i][1], f[i][2]);
        let z11 = if i + 1 < m { z[i + 1][0] } else { 0.0 };
        let z12 = if i + 1 < m { z[i + 1][1] } else { 0.0 };
        let z22 = if i + 2 < m { z[i + 2][0] } else { 0.0 };
        z[i][2] = -l1 * z12 - l2 * z22;
        z[i][1] = -l1 * z11 - l2 * z12;
        z[i][0] = 1.0 / f[i][0] - l1 * z[i][1] - l2 * z[i][2];
    }
    (z, f)
}

/// Solves `LDLᵀx = b` in place.
fn ldl_solve(f: &[[f64; 3]], x: &mut [f64]) {
    let m = f.len();
    for i in 0..m {
        if i >= 1 {
            x[i] -= f[i - 1][1] * x[i - 1];
        }
        if i >= 2 {
            x[i] -= f[i - 2][2] * x[i - 2];
        }
    }
    for i in 0..m {
        x[i] /= f[i][0];
    }
    for i in (0..m).rev() {
        if i + 1 < m {
            x[i] -= f[i][1] * x[i + 1];
        }
        if i + 2 < m {
            x[i] -= f[i][2] * x[i + 2];
        }
    }
}

/// `tr(B⁻¹M)` for cyclic pentadiagonal `B` and `M` (bands with wrap-around), `m ≥ 7`.
fn cyclic_trace(band: &[[f64; 3]], mm: &[[f64; 3]]) -> f64 {
    let m = band.len();
    // The band part without the wrap-around couplings, and the corners S on P = {0,1,m−2,m−1}.
    let mut open = band.to_vec();
    open[m - 2][2] = 0.0;
    open[m - 1][1] = 0.0;
    open[m - 1][2] = 0.0;
    let idx = [0, 1, m - 2, m - 1];
    let mut s = [0.0; 16];
    // Wrap-around entries: (m−2, 0) = band[m−2][2], (m−1, 0) = band[m−1][1], (m−1, 1) = band[m−1][2].
    for &(i, j, v) in &[
        (m - 2, 0, band[m - 2][2]),
        (m - 1, 0, band[m - 1][1]),
        (m - 1, 1, band[m - 1][2]),
    ] {
        let a = idx.iter().position(|&x| x == i).expect("a corner index");
        let b = idx.iter().position(|&x| x == j).expect("a corner index");
        s[a * 4 + b] = v;
        s[b * 4 + a] = v;
    }
    let (zb, f) = selected_inverse(&open);
    let mut y = vec![[0.0; 4]; m];
    for (c, &col) in idx.iter().enumerate() {
        let mut e = vec![0.0; m];
        e[col] = 1.0;
        ldl_solve(&f, &mut e);
        for i in 0..m {
            y[i][c] = e[i];
        }
    }
    // K = S·(I + PᵀY·S)⁻¹.
    let mut t = [0.0; 16];
    for a in 0..4 {
        for b in 0..4 {
            let mut v = if a == b { 1.0 } else { 0.0 };
            for c in 0..4 {
                v += y[idx[a]][c] * s[c * 4 + b];
            }
            t[a * 4 + b] = v;
        }
    }
    let mut ti = [0.0; 16];
    if !invert(4, &t, &mut ti) {
        return f64::NAN;
    }
    let mut k = [0.0; 16];
    for a in 0..4 {
        for b in 0..4 {
            k[a * 4 + b] = (0..4).map(|c| s[a * 4 + c] * ti[c * 4 + b]).sum();
        }
    }
    // Z_b(i, j) for |i − j| ≤ 2 cyclically: the band, or (wrapping) a column of Y.
    let zb_at = |i: usize, j: usize| -> f64 {
        let (lo, hi) = (i.min(j), i.max(j));
        if hi - lo <= 2 {
            zb[lo][hi - lo]
        } else {
            let c = idx
                .iter()
                .position(|&x| x == j)
                .expect("a wrapping index is a corner");
            y[i][c]
        }
    };
    let z_at = |i: usize, j: usize| -> f64 {
        let mut corr = 0.0;
        for a in 0..4 {
            for b in 0..4 {
                corr += y[i][a] * k[a * 4 + b] * y[j][b];
            }
        }
        zb_at(i, j) - corr
    };
    let mut trace = 0.0;
    for (i, row) in mm.iter().enumerate() {
        trace += z_at(i, i) * row[0];
        trace += 2.0 * z_at(i, (i + 1) % m) * row[1];
        trace += 2.0 * z_at(i, (i + 2) % m) * row[2];
    }
    trace
}

/// `tr(B⁻¹M)` by dense inversion (tiny periodic systems, `3 ≤ m < 7`).
fn dense_trace(
    m: usize,
    lambda: f64,
    h: &dyn Fn(usize) -> f64,
    m_entry: &dyn Fn(usize, usize) -> f64,
) -> f64 {
    let mut b = vec![0.0; m * m];
    let mut mat = vec![0.0; m * m];
    for a in 0..m {
        let next = (a + 1) % m;
        b[a * m + a] += (h((a + m - 1) % m) + h(a)) / 3.0;
        b[a * m + next] += h(a) / 6.0;
        b[next * m + a] += h(a) / 6.0;
        for c in 0..m {
            mat[a * m + c] = m_entry(a, c);
        }
    }
    for (x, y) in b.iter_mut().zip(&mat) {
        *x += lambda * y;
    }
    let mut inv = vec![0.0; m * m];
    if !invert(m, &b, &mut inv) {
        return f64::NAN;
    }
    (0..m)
        .map(|i| (0..m).map(|j| inv[i * m + j] * mat[j * m + i]).sum::<f64>())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The hat matrix by brute force: `A = (W + λK)⁻¹W`, `K = Q R⁻¹ Qᵀ`, dense.
    fn dense_hat_trace(times: &[f64], w: &[f64], lambda: f64, closed: bool) -> f64 {
        let n = w.len();
        let cols = columns(times, closed);
        let m = cols.len();
        let h = |i: usize| times[i + 1] - times[i];
        let mut q = vec![0.0; n * m];
        let mut r = vec![0.0; m * m];
        for (a, col) in cols.iter().enumerate() {
            for &(i, v) in col {
                q[i * m + a] += v;
            }
            let j = knot(a, closed);
            r[a * m + a] += (h(prev(j, n, closed)) + h(j)) / 3.0;
            let b = if closed { (a + 1) % m } else { a + 1 };
            if b < m {
                r[a * m + b] += h(j) / 6.0;
                r[b * m + a] += h(j) / 6.0;
            }
        }
        let mut ri = vec![0.0; m * m];
        assert!(invert(m, &r, &mut ri));
        let mut sys = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                let mut k = 0.0;
                for a in 0..m {
                    for b in 0..m {
                        k += q[i * m + a] * ri[a * m + b] * q[j * m + b];
                    }
                }
                sys[i * n + j] = lambda * k + if i == j { w[i] } else { 0.0 };
            }
        }
        let mut si = vec![0.0; n * n];
        assert!(invert(n, &sys, &mut si));
        (0..n).map(|i| si[i * n + i] * w[i]).sum()
    }

    fn data(n: usize, closed: bool) -> (Vec<f64>, Vec<f64>) {
        let mut t = vec![0.0];
        for i in 0..n - 1 + usize::from(closed) {
            t.push(t[i] + 0.3 + 0.2 * ((i as f64) * 1.7).sin().abs());
        }
        let w = (0..n)
            .map(|i| 0.5 + ((i as f64) * 0.9).cos().abs())
            .collect();
        (t, w)
    }

    #[test]
    fn the_trace_equals_the_dense_hat_matrix() {
        for closed in [false, true] {
            for n in [3, 4, 5, 6, 7, 8, 9, 12, 20] {
                if closed && n < 3 {
                    continue;
                }
                let (t, w) = data(n, closed);
                for lambda in [1e-4, 0.01, 1.0, 100.0, 1e5] {
                    let fast = hat_trace(&t, &w, lambda, closed);
                    let dense = dense_hat_trace(&t, &w, lambda, closed);
                    assert!(
                        (fast - dense).abs() < 1e-8 * n as f64,
                        "closed {closed} n {n} λ {lambda}: {fast} vs {dense}"
                    );
                }
            }
        }
    }
}
