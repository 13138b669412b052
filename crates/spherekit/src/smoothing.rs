// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Pobegailo's smoothing polynomials `w₁,ₙ`, `w₂,ₙ` and the blending operator of two curves on a
//! Lie group.

use core::ops::{Add, Mul};

use glam::{DMat3, DMat4, DQuat};

use crate::error::SplineError;

/// The smoothing polynomials `w₁,ₙ` ("run-up") and `w₂,ₙ` ("braking") of degree `2n + 1`, for a
/// continuity order `n ≥ 1`.
///
/// Source: Pobegailo (2019), §7.5–7.7 (see `docs/references.md`). They are the Bézier functions
/// with ordinates
/// `(0, …, 0, (n+1)/(2n+1), …, 1)` and `(0, 1/(2n+1), …, n/(2n+1), 0, …, 0)` (`n + 1` zeros each):
///
/// ```text
/// w₁,ₙ(u) = Σ_{j=n+1}^{2n+1} j/(2n+1)·b_{j,2n+1}(u) = u·Sₙ(u)
/// w₂,ₙ(u) = Σ_{j=1}^{n}      j/(2n+1)·b_{j,2n+1}(u) = u·(1 − Sₙ(u))
/// Sₙ(u)   = Σ_{i=n}^{2n} b_{i,2n}(u),      b_{i,N}(u) = C(N,i)·(1−u)^{N−i}·uⁱ
/// w₁,ₙ + w₂,ₙ = u                                          (linear precision, derived)
/// Sₙ′(u)  = 2n·C(2n−1, n−1)·u^{n−1}·(1−u)ⁿ
/// w^{(k)} = u·S^{(k)} + k·S^{(k−1)}                       (Leibniz, for w₁; w₂ with 1 − Sₙ)
/// ```
///
/// Boundary behaviour (Pobegailo (2019), §7.6, Theorems 4, 5, with the range of (7.18) corrected
/// to `m = 1…n`; `docs/derivations.md#pobegailo-7-18`):
/// `w₁(0) = 0`, `w₁(1) = 1`, `w₁′(1) = 1`, `w₁^{(m)}(0) = 0` for `m = 1…n` and `w₁^{(m)}(1) = 0` for
/// `m = 2…n`; `w₂(0) = w₂(1) = 0`, `w₂′(0) = 1`, `w₂^{(m)}(0) = 0` for `m = 2…n` and
/// `w₂^{(m)}(1) = 0` for `m = 1…n`. The order-`n+1` end derivatives are non-zero.
///
/// **Correction.** The monograph prints `w₂,₂(u) = (1−u)²u³ + 4(1−u)u⁴`, which violates
/// `w₂′(0) = 1`; the definition gives `(1−u)⁴u + 4(1−u)³u² = u − 6u³ + 8u⁴ − 3u⁵`, used here
/// (`docs/derivations.md#pobegailo-w22`; the identity `w₁ + w₂ = u`:
/// `#pobegailo-linear-precision`).
///
/// # Numerics
///
/// Both tails `Sₙ` and `1 − Sₙ` are summed directly (positive terms, evaluated by a
/// Horner scheme in the ratio `u/(1−u)` or `(1−u)/u`, whichever is ≤ 1), so `w₂` keeps full
/// relative accuracy near `u = 1` where it is `O((1−u)^{n+1})`. Only `+ − × ÷` are used, so
/// results are bit-identical on every target. Orders up to [`MAX_ORDER`](Self::MAX_ORDER) are
/// supported; above that the binomial coefficients leave the range of `f64`.
///
/// # Examples
///
/// ```
/// use spherekit::SmoothingPolynomials;
///
/// let w = SmoothingPolynomials::try_new(2).unwrap();
/// assert!((w.w1(0.5) - 11.0 / 32.0).abs() < 1e-15);
/// assert!((w.w2(0.5) - 5.0 / 32.0).abs() < 1e-15);
/// assert!((w.w2_derivative(0.0, 1) - 1.0).abs() < 1e-15);
/// assert_eq!(w.w1_derivative(0.0, 2), 0.0);
/// assert!((w.w1_derivative(0.0, 3) - 36.0).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothingPolynomials {
    order: usize,
    /// `2n·C(2n−1, n−1)`, the leading factor of `Sₙ′`.
    slope: f64,
    /// `C(2n, i)` for `i = 0…2n` when `2n < TABLE`, else unused (computed on the fly).
    binomials: [f64; TABLE],
}

/// Orders with `2n < TABLE` (all the spline orders) keep their binomial coefficients.
const TABLE: usize = 2 * crate::arc_blend::MAX_SMOOTHNESS + 1;

impl SmoothingPolynomials {
    /// The largest supported order `n` (degree `2n + 1`).
    pub const MAX_ORDER: usize = 256;

    /// The polynomials of order `n = order` (degree `2n + 1`, blending with Cⁿ joints).
    ///
    /// # Errors
    ///
    /// [`SplineError::InvalidParameter`] (`order`) unless `1 ≤ order ≤ MAX_ORDER`. Order 0 would
    /// give `w₁ = u`, `w₂ = 0` and only C⁰ joints.
    pub fn try_new(order: usize) -> Result<Self, SplineError> {
        if order == 0 || order > Self::MAX_ORDER {
            return Err(SplineError::InvalidParameter {
                name: "order",
                reason: format!(
                    "must be an integer from 1 to {}, got {order}",
                    Self::MAX_ORDER
                ),
            });
        }
        let n = order as f64;
        let mut binomials = [0.0; TABLE];
        if 2 * order < TABLE {
            for (i, b) in binomials.iter_mut().enumerate().take(2 * order + 1) {
                *b = binomial(2 * order, i);
            }
        }
        Ok(Self {
            order,
            slope: 2.0 * n * binomial(2 * order - 1, order - 1),
            binomials,
        })
    }

    /// The continuity order `n`.
    #[must_use]
    pub fn order(self) -> usize {
        self.order
    }

    /// The degree `2n + 1`.
    #[must_use]
    pub fn degree(self) -> usize {
        2 * self.order + 1
    }

    /// `(Sₙ(u), 1 − Sₙ(u))`, both summed directly.
    fn tails(self, u: f64) -> (f64, f64) {
        let n = self.order;
        let big = 2 * n;
        let v = 1.0 - u;
        let table = big < TABLE;
        // Σ_{i} C(N,i) uⁱ v^{N−i} over i ≥ n (hi) and i < n (lo).
        if u <= 0.5 {
            // v^N · Σ C(N,i) rⁱ, r = u/v ≤ 1; Horner from i = N down to 0.
            let r = u / v;
            let (mut hi, mut lo) = (0.0, 0.0);
            let mut c = 1.0; // C(N, i) for i = N
            for i in (0..=big).rev() {
                if table {
                    c = self.binomials[i];
                }
                if i >= n {
                    hi = hi * r + c;
                } else {
                    lo = lo * r + c;
                }
                if i > 0 && !table {
                    c = c * i as f64 / (big - i + 1) as f64;
                }
            }
            let vn = ipow(v, big);
            // hi collected terms i = N…n with r^{i−n}; lo terms i = n−1…0 with rⁱ.
            (hi * ipow(r, n) * vn, lo * vn)
        } else {
            // u^N · Σ C(N,i) r^{N−i}, r = v/u ≤ 1; Horner from i = 0 up to N.
            let r = v / u;
            let (mut hi, mut lo) = (0.0, 0.0);
            let mut c = 1.0; // C(N, i) for i = 0
            for i in 0..=big {
                if table {
                    c = self.binomials[i];
                }
                if i >= n {
                    hi = hi * r + c;
                } else {
                    lo = lo * r + c;
                }
                if !table {
                    c = c * (big - i) as f64 / (i + 1) as f64;
                }
            }
            let un = ipow(u, big);
            // hi: terms i = n…N with r^{N−i}; lo: terms i = 0…n−1 with r^{N−i} = r^{n+1}·r^{n−1−i}.
            (hi * un, lo * ipow(r, big - n + 1) * un)
        }
    }

    /// `Sₙ^{(k)}(u)` for `k ≥ 1`: `slope · D^{k−1}[u^{n−1}(1−u)ⁿ]`.
    fn s_derivative(self, u: f64, k: usize) -> f64 {
        debug_assert!(k >= 1, "k ≥ 1");
        self.slope * monomial_product_derivative(self.order - 1, self.order, k - 1, u)
    }

    /// `w₁,ₙ(u)`.
    #[must_use]
    pub fn w1(self, u: f64) -> f64 {
        u * self.tails(u).0
    }

    /// `w₂,ₙ(u) = u − w₁,ₙ(u)`, computed without cancellation.
    #[must_use]
    pub fn w2(self, u: f64) -> f64 {
        u * self.tails(u).1
    }

    /// The `k`-th derivative of `w₁,ₙ` at `u` (`k = 0` is the value; zero for `k > 2n + 1`).
    #[must_use]
    pub fn w1_derivative(self, u: f64, k: usize) -> f64 {
        match k {
            0 => self.w1(u),
            _ if k > self.degree() => 0.0,
            1 => self.tails(u).0 + u * self.s_derivative(u, 1),
            _ => u * self.s_derivative(u, k) + k as f64 * self.s_derivative(u, k - 1),
        }
    }

    /// The `k`-th derivative of `w₂,ₙ` at `u` (`k = 0` is the value; zero for `k > 2n + 1`).
    #[must_use]
    pub fn w2_derivative(self, u: f64, k: usize) -> f64 {
        match k {
            0 => self.w2(u),
            _ if k > self.degree() => 0.0,
            1 => self.tails(u).1 - u * self.s_derivative(u, 1),
            _ => -(u * self.s_derivative(u, k) + k as f64 * self.s_derivative(u, k - 1)),
        }
    }

    /// `[w₁, w₁′, w₁″]` and `[w₂, w₂′, w₂″]` at `u`, sharing the work.
    #[must_use]
    pub fn jets(self, u: f64) -> ([f64; 3], [f64; 3]) {
        let (hi, lo) = self.tails(u);
        let n = self.order;
        let v = 1.0 - u;
        // S′ = c·u^{n−1}vⁿ, S″ = c·((n−1)u^{n−2}vⁿ − n·u^{n−1}v^{n−1}).
        let (s1, s2) = if n == 1 {
            (self.slope * v, -self.slope)
        } else {
            let un2 = ipow(u, n - 2);
            let vn1 = ipow(v, n - 1);
            let (un1, vn) = (un2 * u, vn1 * v);
            let nf = n as f64;
            (
                self.slope * un1 * vn,
                self.slope * ((nf - 1.0) * un2 * vn - nf * un1 * vn1),
            )
        };
        let w1 = [u * hi, hi + u * s1, u * s2 + 2.0 * s1];
        let w2 = [u * lo, lo - u * s1, -w1[2]];
        (w1, w2)
    }

    /// The blending operator of two curves on a (matrix or quaternion) Lie group, Theorem 8 of
    /// Pobegailo (2019), §7.8, eq. (7.25), with exact first and second derivatives:
    ///
    /// ```text
    /// g(u)  = A·B,   A = g₁(w₁,ₙ(u)),   B = g₂(w₂,ₙ(u))
    /// A′ = g₁′·w₁′,  A″ = g₁″·w₁′² + g₁′·w₁″      (same for B with g₂, w₂)
    /// g′ = A′B + AB′,  g″ = A″B + 2A′B′ + AB″
    /// ```
    ///
    /// `g1` and `g2` return the jets of the two curves (value, first and second derivative with
    /// respect to their own parameter) and must start at the identity, `g₁(0) = g₂(0) = e`. Then
    /// `g(0) = e`, `g(1) = g₁(1)`, and the derivatives of orders `1…n` of `g` equal those of `g₂`
    /// at `u = 0` and those of `g₁` at `u = 1`. The **end** follower `g₁` is the left factor.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{GroupJet, SmoothingPolynomials};
    /// use spherekit::glam::{DQuat, DVec3};
    ///
    /// // Two one-parameter subgroups of unit quaternions, exp(u·X).
    /// let subgroup = |x: DVec3| move |s: f64| {
    ///     let q = DQuat::from_scaled_axis(2.0 * s * x);
    ///     let xq = DQuat::from_xyzw(x.x, x.y, x.z, 0.0);
    ///     GroupJet { value: q, d1: xq * q, d2: xq * xq * q }
    /// };
    /// let (g1, g2) = (subgroup(DVec3::new(0.3, 0.0, 0.1)), subgroup(DVec3::new(0.0, 0.5, 0.0)));
    /// let w = SmoothingPolynomials::try_new(2).unwrap();
    /// let start = w.blend(&g1, &g2, 0.0);
    /// let end = w.blend(&g1, &g2, 1.0);
    /// assert!((start.d1 - g2(0.0).d1).length() < 1e-15); // starts like g₂
    /// assert!((end.value - g1(1.0).value).length() < 1e-15); // ends at g₁(1)
    /// assert!((end.d2 - g1(1.0).d2).length() < 1e-14); // with g₁'s acceleration
    /// ```
    pub fn blend<G: GroupAlgebra>(
        self,
        g1: impl Fn(f64) -> GroupJet<G>,
        g2: impl Fn(f64) -> GroupJet<G>,
        u: f64,
    ) -> GroupJet<G> {
        let (w1, w2) = self.jets(u);
        let a = g1(w1[0]);
        let b = g2(w2[0]);
        let (a0, a1, a2) = (a.value, a.d1 * w1[1], a.d2 * (w1[1] * w1[1]) + a.d1 * w1[2]);
        let (b0, b1, b2) = (b.value, b.d1 * w2[1], b.d2 * (w2[1] * w2[1]) + b.d1 * w2[2]);
        GroupJet {
            value: a0.product(b0),
            d1: a1.product(b0) + a0.product(b1),
            d2: a2.product(b0) + a1.product(b1) * 2.0 + a0.product(b2),
        }
    }
}

/// A value of a curve in a matrix or quaternion Lie group with its first two derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroupJet<G> {
    /// `g(u)`.
    pub value: G,
    /// `g′(u)`.
    pub d1: G,
    /// `g″(u)`.
    pub d2: G,
}

/// The associative algebra a matrix or quaternion Lie group lives in: the group product
/// extended bilinearly, so that derivatives of products follow the Leibniz rule.
pub trait GroupAlgebra: Copy + Add<Output = Self> + Mul<f64, Output = Self> {
    /// The (non-commutative) product `self · rhs`.
    #[must_use]
    fn product(self, rhs: Self) -> Self;
}

impl GroupAlgebra for DQuat {
    fn product(self, rhs: Self) -> Self {
        self * rhs
    }
}

impl GroupAlgebra for DMat3 {
    fn product(self, rhs: Self) -> Self {
        self * rhs
    }
}

impl GroupAlgebra for DMat4 {
    fn product(self, rhs: Self) -> Self {
        self * rhs
    }
}

/// `xᵉ` by binary exponentiation (only multiplications, bit-identical on every target).
#[inline]
pub(crate) fn ipow(mut x: f64, mut e: usize) -> f64 {
    let mut r = 1.0;
    while e > 0 {
        if e & 1 == 1 {
            r *= x;
        }
        x *= x;
        e >>= 1;
    }
    r
}

/// `C(n, k)` as `f64` (exact while it fits in 53 bits).
pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    let mut c = 1.0;
    for i in 0..k {
        c = c * (n - i) as f64 / (i + 1) as f64;
    }
    c
}

/// `d^m/du^m [u^a (1−u)^b]` by the Leibniz rule.
fn monomial_product_derivative(a: usize, b: usize, m: usize, u: f64) -> f64 {
    let v = 1.0 - u;
    let mut sum = 0.0;
    // term j: C(m,j) · a^{(j)} u^{a−j} · (−1)^{m−j} b^{(m−j)} v^{b−m+j}
    for j in 0..=m {
        let l = m - j;
        if j > a || l > b {
            continue;
        }
        let mut coef = binomial(m, j);
        for i in 0..j {
            coef *= (a - i) as f64;
        }
        for i in 0..l {
            coef *= (b - i) as f64;
        }
        if !l.is_multiple_of(2) {
            coef = -coef;
        }
        sum += coef * ipow(u, a - j) * ipow(v, b - l);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials() {
        assert_eq!(binomial(10, 3), 120.0, "C(10,3)");
        assert_eq!(binomial(20, 10), 184_756.0, "C(20,10)");
    }

    #[test]
    fn monomial_derivatives() {
        // d²/du² [u²(1−u)³] at u = 0.3 by the expanded polynomial u² − 3u³ + 3u⁴ − u⁵.
        let u: f64 = 0.3;
        let want = 2.0 - 18.0 * u + 36.0 * u * u - 20.0 * u * u * u;
        assert!(
            (monomial_product_derivative(2, 3, 2, u) - want).abs() < 1e-14,
            "second derivative"
        );
    }
}
