// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The one manifold trait that every construction is written against.

use core::fmt::Debug;

use crate::ambient::Ambient;
use crate::error::PointError;
use crate::math;

/// Two points are treated as antipodal when `|p + q|` is at most this (and `p · q < 0`).
///
/// At that distance from a half great circle the minimising geodesic is decided by rounding
/// noise, so constructions report [`SplineError::Antipodal`](crate::SplineError::Antipodal)
/// instead of picking an arbitrary plane.
pub const ANTIPODAL_TOLERANCE: f64 = 1e-14;

/// A unit sphere S^m ⊂ ℝ^(m+1) with its great-circle geometry.
///
/// Implementors provide only the conversion to and from the ambient vector; distance,
/// logarithm, exponential and geodesic interpolation are provided once for every sphere,
/// so that each spline construction is written once for S², S³ and S^m.
///
/// Tangent vectors are ambient vectors orthogonal to their base point. For
/// [`UnitQuat`](crate::UnitQuat) the ambient space is ℝ⁴ in glam's `x, y, z, w` order; the
/// quaternion view of the same vectors is given by [`UnitQuat`](crate::UnitQuat)'s own methods.
/// [`exp`](Manifold::exp) and [`log`](Manifold::log) here are the sphere's exponential map and
/// its inverse (follow a geodesic from a base point, and back); the quaternion exponential of a
/// pure quaternion is [`UnitQuat::exp_pure`](crate::UnitQuat::exp_pure).
///
/// # Hostile input
///
/// Points are finite unit vectors by construction, so every operation on points alone
/// ([`dist`](Manifold::dist), [`log`](Manifold::log) between two points) is finite. Where a
/// caller also passes a number or a vector, the `try_` form reports a bad one as a typed
/// [`PointError`], and the infallible form returns a documented finite value: a NaN or
/// infinite tangent or parameter is treated as zero (the result is `self`), and antipodal
/// points give `self` (or the zero tangent). Debug and release builds behave the same.
///
/// # Numerics
///
/// The angle between `p` and `q` is `θ = 2·atan2(|p − q|, |p + q|)`, accurate near 0 and near π.
/// The unit direction of the geodesic is formed from `q − p` (near 0) or `q + p` (near π), so it
/// keeps full relative accuracy at both ends. Geodesic interpolation never flips signs. Large
/// angles (a long tangent, a parameter far outside `[0, 1]`) are reduced by the sine and cosine
/// themselves, whose argument reduction is exact, so that a tangent of length 1e300 still
/// gives the point at the angle 1e300 (as rounded to `f64`) along the great circle.
pub trait Manifold: Clone + Debug + PartialEq {
    /// The ambient vector type.
    type Vector: Ambient;

    /// The factor from the ambient speed `|c′(t)|` of a curve to its speed in the sphere's
    /// arc-length measure: the arc length of `c` is `SPEED_SCALE · ∫|c′(t)| dt`.
    ///
    /// `1` for S² and S^m (great-circle arc length in radians). `2` for
    /// [`UnitQuat`](crate::UnitQuat): the arc length is the **rotation angle** turned, and a
    /// quaternion curve moving at `|q′|` on S³ turns the body at `|ω| = 2|q′|` radians per
    /// unit time (the factor 2 of the angular velocity `ω = 2·q′·q̄`). Arc-length
    /// reparametrisation ([`ArcLength`](crate::ArcLength)) makes `SPEED_SCALE·|c′| = 1`.
    const SPEED_SCALE: f64 = 1.0;

    /// The point as a unit vector of the ambient space.
    fn to_vector(&self) -> Self::Vector;

    /// Wraps a vector that is already unit length, without normalising it.
    ///
    /// This is the unchecked escape hatch for constructions that have just computed a unit
    /// vector; use [`try_from_vector`](Manifold::try_from_vector) for data.
    ///
    /// # Panics
    ///
    /// In debug builds, if `v` is not a finite unit vector (to within `1e-12`). Release
    /// builds do not check, and a point made from a non-unit vector breaks the type's
    /// guarantees.
    fn from_vector_unchecked(v: Self::Vector) -> Self;

    /// Normalises `v` onto the sphere.
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] or [`PointError::ZeroLength`].
    fn try_from_vector(v: Self::Vector) -> Result<Self, PointError> {
        normalize(v).map(Self::from_vector_unchecked)
    }

    /// Great-circle distance in radians, in `[0, π]`.
    fn dist(&self, other: &Self) -> f64 {
        let (p, q) = (self.to_vector(), other.to_vector());
        2.0 * math::atan2((q.clone() - p.clone()).length(), (q + p).length())
    }

    /// `true` when `self` and `other` are antipodal within [`ANTIPODAL_TOLERANCE`].
    fn is_antipodal(&self, other: &Self) -> bool {
        let (p, q) = (self.to_vector(), other.to_vector());
        p.dot(&q) < 0.0 && (q + p).length() <= ANTIPODAL_TOLERANCE
    }

    /// The tangent at `self` pointing along the minimising geodesic to `other`, of length
    /// [`dist`](Manifold::dist): the inverse of [`exp`](Manifold::exp).
    ///
    /// # Errors
    ///
    /// [`PointError::Antipodal`] if the points are antipodal (within [`ANTIPODAL_TOLERANCE`]).
    fn try_log(&self, other: &Self) -> Result<Self::Vector, PointError> {
        let (theta, e) =
            geodesic_frame(&self.to_vector(), &other.to_vector()).ok_or(PointError::Antipodal)?;
        Ok(e * theta)
    }

    /// Like [`try_log`](Manifold::try_log), but the zero vector for antipodal points.
    fn log(&self, other: &Self) -> Self::Vector {
        self.try_log(other)
            .unwrap_or_else(|_| self.to_vector().zeros_like())
    }

    /// Follows the geodesic from `self` with initial velocity `v` (tangent at `self`) for unit time:
    /// `cos|v|·p + sin|v|/|v|·v`.
    ///
    /// The angle `|v|` may be any finite size (it is reduced exactly by the sine and cosine).
    ///
    /// # Errors
    ///
    /// [`PointError::NonFinite`] if a coordinate of `v` is NaN or infinite.
    fn try_exp(&self, v: &Self::Vector) -> Result<Self, PointError> {
        exp_vector(&self.to_vector(), v).map(Self::from_vector_unchecked)
    }

    /// Like [`try_exp`](Manifold::try_exp), but `self` (the point at `v = 0`) for a tangent
    /// with a NaN or infinite coordinate.
    fn exp(&self, v: &Self::Vector) -> Self {
        self.try_exp(v).unwrap_or_else(|_| self.clone())
    }

    /// The point at fraction `t` of the minimising geodesic from `self` to `other`. Exact at
    /// `t = 0` and `t = 1`; for other `t` outside `[0, 1]` the great circle is continued (any
    /// finite `t·θ` is reduced exactly by the sine and cosine).
    ///
    /// # Errors
    ///
    /// [`PointError::NonFiniteParameter`] if `t` is NaN or infinite, or `t·θ` overflows;
    /// [`PointError::Antipodal`] if the points are antipodal (within [`ANTIPODAL_TOLERANCE`]).
    fn try_slerp(&self, other: &Self, t: f64) -> Result<Self, PointError> {
        if !t.is_finite() {
            return Err(PointError::NonFiniteParameter);
        }
        if t == 0.0 {
            return Ok(self.clone());
        }
        if t == 1.0 {
            return Ok(other.clone());
        }
        slerp_vector(&self.to_vector(), &other.to_vector(), t).map(Self::from_vector_unchecked)
    }

    /// Like [`try_slerp`](Manifold::try_slerp), but `self` (the point at `t = 0`) where that
    /// has no point: for antipodal points, and for a NaN or infinite `t` (or one whose angle
    /// `t·θ` overflows).
    fn slerp(&self, other: &Self, t: f64) -> Self {
        self.try_slerp(other, t).unwrap_or_else(|_| self.clone())
    }

    /// The component of the ambient vector `v` tangent to the sphere at `self`, `v − (p·v)·p`.
    ///
    /// A linear map of `v`: a NaN or infinite coordinate of `v` gives non-finite coordinates
    /// (so that the caller's own check of its vector still sees it). A finite `v` gives a
    /// finite result (no NaN from an intermediate overflow), unless the result itself
    /// overflows `f64`.
    fn project_tangent(&self, v: &Self::Vector) -> Self::Vector {
        let p = self.to_vector();
        let project = |v: Self::Vector| v.clone() - p.clone() * p.dot(&v);
        let r = project(v.clone());
        if r.is_finite() || !v.is_finite() {
            r
        } else {
            // |p·v| ≤ |v|, so v/16 keeps every intermediate finite; scaling back by 16 can
            // only overflow to ±∞, never make a NaN.
            project(v.clone() * (1.0 / 16.0)) * 16.0
        }
    }
}

/// [`Manifold::try_exp`] on ambient vectors: `cos|v|·p + sin|v|·v/|v|`, renormalised.
///
/// # Errors
///
/// [`PointError::NonFinite`] if a coordinate of `v` is NaN or infinite.
pub(crate) fn exp_vector<V: Ambient>(p: &V, v: &V) -> Result<V, PointError> {
    if !v.is_finite() {
        return Err(PointError::NonFinite);
    }
    let theta = v.length();
    let r = if theta.is_finite() {
        let (s, c) = math::sin_cos(theta);
        p.clone() * c + v.clone() * (if theta > 0.0 { s / theta } else { 1.0 })
    } else {
        let (s, c, dir) = sin_cos_direction_huge(v);
        p.clone() * c + dir * s
    };
    Ok(renormalize(r))
}

/// [`Manifold::try_slerp`] on ambient vectors, for a finite `t` (without its shortcuts at
/// `t = 0` and `t = 1`): `cos(tθ)·p + sin(tθ)·e` with `θ, e` from [`geodesic_frame`].
///
/// # Errors
///
/// [`PointError::Antipodal`] for antipodal points; [`PointError::NonFiniteParameter`] if `t·θ`
/// overflows.
pub(crate) fn slerp_vector<V: Ambient>(p: &V, q: &V, t: f64) -> Result<V, PointError> {
    let (theta, e) = geodesic_frame(p, q).ok_or(PointError::Antipodal)?;
    let angle = t * theta;
    if !angle.is_finite() {
        return Err(PointError::NonFiniteParameter);
    }
    let (s, c) = math::sin_cos(angle);
    Ok(renormalize(p.clone() * c + e * s))
}

/// `(sin θ, cos θ, v/θ)` for a finite vector `v` whose length `θ` overflows even when computed
/// by rescaling ([`Ambient::length`]): `v` is halved `k` times until its length `θ/2ᵏ` is
/// finite, and the sine and cosine are doubled back `k` times. The angle is meaningless to the
/// last turn at that size (a rounding of `θ` is far more than 2π), but the result is a finite
/// point of the great circle. Also used below the overflow, where it is exact.
#[cold]
pub(crate) fn sin_cos_direction_huge<V: Ambient>(v: &V) -> (f64, f64, V) {
    let mut w = v.clone();
    let mut theta = w.length();
    let mut halvings = 0;
    while !theta.is_finite() && halvings < 64 {
        w = w * 0.5;
        theta = w.length();
        halvings += 1;
    }
    let dir = if theta > 0.0 {
        w * (1.0 / theta)
    } else {
        w.zeros_like()
    };
    let (mut s, mut c) = math::sin_cos(theta);
    for _ in 0..halvings {
        (s, c) = (2.0 * s * c, (c - s) * (c + s));
    }
    (s, c, dir)
}

/// The angle θ ∈ [0, π) from `p` to `q` and the unit tangent `e` at `p` with
/// `q = cos θ·p + sin θ·e` (`e = 0` when θ = 0). `None` when antipodal.
pub(crate) fn geodesic_frame<V: Ambient>(p: &V, q: &V) -> Option<(f64, V)> {
    geodesic_frame_sin_cos(p, q).map(|(theta, e, _)| (theta, e))
}

/// [`geodesic_frame`] with `(sin θ, cos θ)`, formed from the same two lengths instead of a
/// trigonometric call: with `d = |q − p| = 2 sin(θ/2)` and `s = |q + p| = 2 cos(θ/2)`,
/// `sin θ = 2ds/(d² + s²)` and `cos θ = (s² − d²)/(d² + s²)` (the denominator, 4 for unit
/// vectors, absorbs their rounding).
#[cfg_attr(not(target_arch = "wasm32"), inline(always))]
pub(crate) fn geodesic_frame_sin_cos<V: Ambient>(p: &V, q: &V) -> Option<(f64, V, (f64, f64))> {
    let diff = q.clone() - p.clone();
    let sum = q.clone() + p.clone();
    let (d, s) = (diff.length(), sum.length());
    let theta = 2.0 * math::atan2(d, s);
    // q − cos θ·p, formed without cancellation: from the difference near 0, the sum near π.
    let w = if p.dot(q) >= 0.0 {
        diff + p.clone() * (0.5 * d * d)
    } else {
        if s <= ANTIPODAL_TOLERANCE {
            return None;
        }
        sum - p.clone() * (0.5 * s * s)
    };
    // One Gram–Schmidt step removes the normal component left by rounding (which 1/sin θ
    // would otherwise amplify for small θ).
    let w = w.clone() - p.clone() * p.dot(&w);
    let wl = w.length();
    if wl == 0.0 {
        return Some((0.0, p.zeros_like(), (0.0, 1.0)));
    }
    let inv = 1.0 / (d * d + s * s);
    let sin_cos = (2.0 * d * s * inv, (s * s - d * d) * inv);
    Some((theta, w * (1.0 / wl), sin_cos))
}

/// Scales a non-zero finite vector to unit length, guarding against overflow and underflow.
pub(crate) fn normalize<V: Ambient>(v: V) -> Result<V, PointError> {
    if !v.is_finite() {
        return Err(PointError::NonFinite);
    }
    let m = v.to_vec().iter().fold(0.0_f64, |m, a| m.max(a.abs()));
    if m < f64::MIN_POSITIVE {
        return Err(PointError::ZeroLength);
    }
    let v = v * (1.0 / m);
    let l = v.length();
    Ok(v * (1.0 / l))
}

/// Removes the rounding drift of a vector that is unit up to a few ulps.
#[inline]
pub(crate) fn renormalize<V: Ambient>(v: V) -> V {
    let l2 = v.dot(&v);
    v * (1.0 / l2.sqrt())
}
