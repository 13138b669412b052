// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Quaternion algebra that the S³ constructions of Pobegailo (2019) build on: the ternary
//! (vector) product of three quaternions and the orthonormal basis it completes, the quotient of
//! two orthogonal quaternions, and the 4×4 matrices of left and right multiplication.
//!
//! These work on general (not necessarily unit) [`DQuat`]s. Quaternions are glam's `x, y, z, w`
//! (vector part, then scalar); the book writes them scalar first, `q₀ + q₁i + q₂j + q₃k`.
//!
//! Source: Pobegailo (2019), §2.8–2.9, §2.11 and §6.5 (`docs/references.md`). The printed sign of
//! the `q₀` term of (2.13) and the numeric example of §2.8 are wrong; the corrected forms are used
//! (`docs/derivations.md#pobegailo-2-13`, `docs/derivations.md#pobegailo-2-8`).

use glam::{DMat4, DQuat, DVec3, DVec4};

/// The ternary (vector) product `X = P × Q × R` (Pobegailo (2019), §2.9): the formal 4×4
/// determinant with the rows `(1, i, j, k)`, `P`, `Q`, `R`, expanded along the first row,
///
/// ```text
/// P × Q × R = [p q r] − p₀(q × r) − q₀(r × p) − r₀(p × q),   [p q r] = p·(q × r)
/// ```
///
/// with `p₀` the scalar part and `p` the vector part of `P`. It is trilinear and alternating
/// (a transposition of two factors changes its sign), orthogonal to each factor, zero exactly when
/// the factors are linearly dependent, and `|X|²` is the Gram determinant of the factors. For
/// orthonormal factors `{P, Q, R, X}` is an orthonormal basis of ℝ⁴ (§2.11).
///
/// **Correction** (`docs/derivations.md#pobegailo-2-13`): the printed (2.13) has `+q₀(r × p)`;
/// the minus sign is the determinant's, and the only one that reproduces the book's example.
///
/// # Examples
///
/// The book's example, `(1 + 2i − j + 4k) × (3 − 2i + 3j + k) × (i − 2j + k) = 11 + 16i + 3j − 10k`:
///
/// ```
/// use spherekit::glam::DQuat;
/// use spherekit::quaternion::ternary_product;
///
/// let x = ternary_product(
///     DQuat::from_xyzw(2.0, -1.0, 4.0, 1.0),
///     DQuat::from_xyzw(-2.0, 3.0, 1.0, 3.0),
///     DQuat::from_xyzw(1.0, -2.0, 1.0, 0.0),
/// );
/// assert_eq!(x, DQuat::from_xyzw(16.0, 3.0, -10.0, 11.0));
/// ```
#[must_use]
pub fn ternary_product(p: DQuat, q: DQuat, r: DQuat) -> DQuat {
    let (pv, qv, rv) = (p.xyz(), q.xyz(), r.xyz());
    let v = -p.w * qv.cross(rv) - q.w * rv.cross(pv) - r.w * pv.cross(qv);
    DQuat::from_xyzw(v.x, v.y, v.z, pv.dot(qv.cross(rv)))
}

/// The unit quaternion orthogonal to the linearly independent `p`, `q`, `r`, oriented so that
/// the determinant with the rows `h, p, q, r` (in the book's `(q₀, q₁, q₂, q₃)` coordinates) is
/// positive: the ternary product
/// normalised (Pobegailo (2019), §2.11, the fourth vector of an orthonormal basis).
///
/// Returns `None` when the three are linearly dependent (within rounding: `|X|` at most
/// `1e-14·|p|·|q|·|r|`) or not finite, where the complement is not a single direction.
///
/// # Examples
///
/// ```
/// use spherekit::glam::DQuat;
/// use spherekit::quaternion::orthogonal_complement;
///
/// // The complement of 1, i, j is −k (1 × i × j = −k).
/// let h = orthogonal_complement(DQuat::IDENTITY, DQuat::from_xyzw(1.0, 0.0, 0.0, 0.0),
///     DQuat::from_xyzw(0.0, 1.0, 0.0, 0.0)).unwrap();
/// assert_eq!(h, DQuat::from_xyzw(0.0, 0.0, -1.0, 0.0));
/// assert!(orthogonal_complement(DQuat::IDENTITY, DQuat::IDENTITY, DQuat::IDENTITY).is_none());
/// ```
#[must_use]
pub fn orthogonal_complement(p: DQuat, q: DQuat, r: DQuat) -> Option<DQuat> {
    let x = ternary_product(p, q, r);
    let len = x.length();
    let scale = p.length() * q.length() * r.length();
    (len.is_finite() && len > 1e-14 * scale).then(|| x * (1.0 / len))
}

/// The quotient `R = P·Q⁻¹` of two orthogonal quaternions (`P·Q = 0`), which is a pure
/// quaternion (Pobegailo (2019), §2.8, eq. (2.12)):
///
/// ```text
/// R = P Q⁻¹ = (−p₀ q + q₀ p − p × q) / N(Q),   P = R Q
/// ```
///
/// For unit `P`, `Q` it is the unit vector `n` of (2.16) with `P = n·Q`: a half turn about `n`.
/// Returned as the vector part; the scalar part `P·Q/N(Q)` is zero for orthogonal inputs (and is
/// dropped otherwise). `None` when `Q = 0` or the result is not finite.
///
/// **Correction** (`docs/derivations.md#pobegailo-2-8`): the book's example prints
/// `(−9i − 10j + 18k)/23`; the value is `(21i + 4j + 7k)/23`.
///
/// # Examples
///
/// ```
/// use spherekit::glam::{DQuat, DVec3};
/// use spherekit::quaternion::orthogonal_quotient;
///
/// let (p, q) = (DQuat::from_xyzw(2.0, -1.0, 4.0, 1.0), DQuat::from_xyzw(-2.0, 3.0, 1.0, 3.0));
/// let r = orthogonal_quotient(p, q).unwrap();
/// assert!((r - DVec3::new(21.0, 4.0, 7.0) / 23.0).length() < 1e-15);
/// ```
#[must_use]
pub fn orthogonal_quotient(p: DQuat, q: DQuat) -> Option<DVec3> {
    let n = q.length_squared();
    let (pv, qv) = (p.xyz(), q.xyz());
    let r = (-p.w * qv + q.w * pv - pv.cross(qv)) / n;
    (n > 0.0 && r.is_finite()).then_some(r)
}

/// The matrix `L(q)` of left multiplication, `L(q)·p = q·p`, acting on column 4-vectors in
/// glam's `x, y, z, w` order (the library's ambient coordinates of S³, as in
/// [`Manifold::to_vector`](crate::Manifold::to_vector)).
///
/// `L(p·q) = L(p)·L(q)`, `L(q)ᵀ·L(q) = N(q)·I`, `det L(q) = N(q)²`; for a unit `q`, `L(q)` is
/// in SO(4) and its orbits on S³ are great circles (Pobegailo (2019), §6.5, §6.7).
///
/// # Examples
///
/// ```
/// use spherekit::glam::{DQuat, DVec4};
/// use spherekit::quaternion::{left_matrix, right_matrix};
///
/// let (q, p) = (DQuat::from_xyzw(1.0, 2.0, 3.0, 1.0), DQuat::from_xyzw(-4.0, 3.0, -1.0, 5.0));
/// assert_eq!(left_matrix(q) * DVec4::from(p), DVec4::from(q * p));
/// assert_eq!(right_matrix(q) * DVec4::from(p), DVec4::from(p * q));
/// ```
#[must_use]
pub fn left_matrix(q: DQuat) -> DMat4 {
    let (x, y, z, w) = (q.x, q.y, q.z, q.w);
    // Columns: q·i, q·j, q·k, q·1.
    DMat4::from_cols(
        DVec4::new(w, z, -y, -x),
        DVec4::new(-z, w, x, -y),
        DVec4::new(y, -x, w, -z),
        DVec4::new(x, y, z, w),
    )
}

/// The matrix `M(q)` of right multiplication, `M(q)·p = p·q`, on column 4-vectors in glam's
/// `x, y, z, w` order.
///
/// This is the book's matrix of §2.1 and §6.5 (Pobegailo (2019), (6.16)): there it acts on row
/// vectors in the order `(q₀, q₁, q₂, q₃)`, `p·M_R(q) = p·q`, so the book's matrix is the
/// transpose of this one with the rows and columns reordered scalar first. `M(p·q) = M(q)·M(p)`,
/// and for a unit `q` every orbit of `p ↦ p·q` on S³ is a great circle.
///
/// See [`left_matrix`] for an example.
#[must_use]
pub fn right_matrix(q: DQuat) -> DMat4 {
    let (x, y, z, w) = (q.x, q.y, q.z, q.w);
    // Columns: i·q, j·q, k·q, 1·q.
    DMat4::from_cols(
        DVec4::new(w, -z, y, -x),
        DVec4::new(z, w, -x, -y),
        DVec4::new(-y, x, w, -z),
        DVec4::new(x, y, z, w),
    )
}
