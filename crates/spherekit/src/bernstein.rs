// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Bernstein polynomials `b_{m,N}(u) = C(N, m)·(1 − u)^{N−m}·uᵐ`, their derivatives and
//! integrals, and the Bernstein coefficients of a polynomial (Pobegailo (2019), §7.1–7.4), the
//! basis the smoothing polynomials ([`SmoothingPolynomials`](crate::SmoothingPolynomials)) are
//! written in.
//!
//! `b_{m,N}` is taken as 0 for `m > N`, which makes the formulas hold without case splits. Only
//! `+ − × ÷` are used (bit-identical on every target); the binomial coefficients are exact while
//! they fit in 53 bits (`N ≤ 56`).

use crate::smoothing::{binomial, ipow};

/// `b_{m,N}(u) = C(N, m)·(1 − u)^{N−m}·uᵐ` (0 for `m > N`).
///
/// ```
/// use spherekit::bernstein::value;
///
/// assert_eq!(value(1, 2, 0.5), 0.5); // 2(1 − u)u
/// assert_eq!(value(3, 2, 0.5), 0.0);
/// ```
#[must_use]
pub fn value(m: usize, big_n: usize, u: f64) -> f64 {
    if m > big_n {
        return 0.0;
    }
    binomial(big_n, m) * ipow(1.0 - u, big_n - m) * ipow(u, m)
}

/// The `k`-th derivative, by (7.4) of Pobegailo (2019), §7.2, which with `b_{i,N} = 0` outside
/// `0 ≤ i ≤ N` holds for every `k` (the book states it for `k ≤ min(m, N − m)`):
///
/// ```text
/// b_{m,N}^{(k)} = N(N−1)…(N−k+1) · Σ_{i=0}^{k} (−1)^i C(k, i) · b_{m−k+i, N−k}
/// ```
///
/// The book's Example 1: `b′_{2,5} = 5(b_{1,4} − b_{2,4}) = 20(1−u)³u − 30(1−u)²u²`.
///
/// ```
/// use spherekit::bernstein::derivative;
///
/// let u: f64 = 0.3;
/// let want = 20.0 * (1.0 - u).powi(3) * u - 30.0 * (1.0 - u).powi(2) * u * u;
/// assert!((derivative(2, 5, 1, u) - want).abs() < 1e-14);
/// ```
#[must_use]
pub fn derivative(m: usize, big_n: usize, k: usize, u: f64) -> f64 {
    if k > big_n {
        return 0.0;
    }
    let falling: f64 = (0..k).map(|i| (big_n - i) as f64).product();
    let mut sum = 0.0;
    for i in 0..=k {
        // Index m − k + i, skipped when negative.
        if m + i < k {
            continue;
        }
        let term = binomial(k, i) * value(m + i - k, big_n - k, u);
        sum += if i % 2 == 0 { term } else { -term };
    }
    falling * sum
}

/// The integral `∫₀ᵘ b_{m,N}(s) ds = (1/(N + 1))·Σ_{i=m+1}^{N+1} b_{i,N+1}(u)`, the antiderivative
/// (7.13) of Pobegailo (2019), §7.3 with its constant fixed by the value 0 at `u = 0`; it is
/// `1/(N + 1)` at `u = 1`.
///
/// ```
/// use spherekit::bernstein::integral;
///
/// assert!((integral(2, 5, 1.0) - 1.0 / 6.0).abs() < 1e-16);
/// ```
#[must_use]
pub fn integral(m: usize, big_n: usize, u: f64) -> f64 {
    if m > big_n {
        return 0.0;
    }
    let sum: f64 = (m + 1..=big_n + 1).map(|i| value(i, big_n + 1, u)).sum();
    sum / (big_n + 1) as f64
}

/// The Bernstein coefficients `c₀ … c_N` of the polynomial `p` of degree ≤ `N` whose derivatives
/// at 0 are `derivatives_at_zero = [p(0), p′(0), …, p^{(N)}(0)]` (`N + 1` values), so that
/// `p = Σ c_j b_{j,N}`: (7.15) of Pobegailo (2019), §7.4, with `c₀ = p(0)/b_{0,N}(0) = p(0)`
/// (the book prints `b_{1,n}(0)` there, a division by zero):
///
/// ```text
/// c_j = (p^{(j)}(0) − Σ_{i<j} c_i·b_{i,N}^{(j)}(0)) / b_{j,N}^{(j)}(0),   b_{j,N}^{(j)}(0) = N!/(N−j)!
/// ```
///
/// The book's example: `1 + 2u + 3u² = 1·b_{0,2} + 2·b_{1,2} + 6·b_{2,2}`.
///
/// ```
/// use spherekit::bernstein::coefficients;
///
/// assert_eq!(coefficients(&[1.0, 2.0, 6.0]), vec![1.0, 2.0, 6.0]);
/// ```
#[must_use]
pub fn coefficients(derivatives_at_zero: &[f64]) -> Vec<f64> {
    let Some(big_n) = derivatives_at_zero.len().checked_sub(1) else {
        return Vec::new();
    };
    let mut c: Vec<f64> = Vec::with_capacity(big_n + 1);
    for (j, &pj) in derivatives_at_zero.iter().enumerate() {
        let known: f64 = c
            .iter()
            .enumerate()
            .map(|(i, ci)| ci * derivative(i, big_n, j, 0.0))
            .sum();
        c.push((pj - known) / derivative(j, big_n, j, 0.0));
    }
    c
}
