// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Circles as planar sections of S² and S³ (Pobegailo (2019), §5.3 and §6.3).

use glam::{DQuat, DVec3, DVec4};

use crate::error::SplineError;
use crate::math;
use crate::quaternion::ternary_product;

/// A circle of S² or S³ given as the section of the sphere by a plane: `n·p = d` on S²
/// ([`PlaneSection::s2`]), or the 2-plane `m·p = d₁, n·p = d₂` on S³ ([`PlaneSection::s3`]).
///
/// Source: Pobegailo (2019), §5.3 (S², eqs. (5.4)–(5.9)) and §6.3 (S³, eq. (6.7)). The section
/// is the circle with centre `κ` (the foot of the perpendicular from the origin to the plane) and
/// radius `ρ = √(1 − |κ|²)`, a great circle exactly when the plane passes through the origin:
///
/// ```text
/// S²:  κ = d·n̂,                       ρ = √(1 − d²)
/// S³:  κ = α m + β n  with  [m·m  m·n; m·n  n·n]·(α, β) = (d₁, d₂),   ρ = √(1 − |κ|²)
/// c(θ) = κ + ρ·(cos θ·x̃ + sin θ·ỹ)
/// ```
///
/// with `(x̃, ỹ)` an orthonormal basis of the plane's directions. On S² it is the book's adapted
/// frame (5.6), `x̃ = (e₃ × n̂)/|e₃ × n̂|`, `ỹ = n̂ × x̃`, with the axis of smallest `|nᵢ|` in place of
/// `e₃` where the book's frame is undefined (`n̂ = ±e₃`); on S³ `x̃` is the unit part of a
/// coordinate axis orthogonal to `m, n` and `ỹ = X(m̂, n̂′, x̃)` their ternary product
/// ([`ternary_product`]), `m̂, n̂′` being `m, n` made orthonormal. **Correction**
/// (`docs/derivations.md#pobegailo-5-3`): the book prints the radius of the S² section as
/// `r² − d²`; it is `√(r² − d²)`.
///
/// A plane at distance 1 touches the sphere in one point (radius 0, accepted); a plane farther
/// away misses it (an error).
///
/// # Examples
///
/// The plane `z = 1/2` cuts S² in the circle of radius `√3/2` about `(0, 0, 1/2)`:
///
/// ```
/// use spherekit::PlaneSection;
/// use spherekit::glam::DVec3;
///
/// let c = PlaneSection::s2(DVec3::Z, 0.5).unwrap();
/// assert_eq!(c.center(), DVec3::new(0.0, 0.0, 0.5));
/// assert!((c.radius() - 0.75f64.sqrt()).abs() < 1e-15);
/// let p = c.point(1.0);
/// assert!((p.length() - 1.0).abs() < 1e-15 && (p.z - 0.5).abs() < 1e-15);
/// assert!(PlaneSection::s2(DVec3::Z, 1.5).is_err()); // misses the sphere
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PlaneSection<V> {
    center: V,
    radius: f64,
    x: V,
    y: V,
}

fn distance_error(d: f64) -> SplineError {
    SplineError::InvalidParameter {
        name: "d",
        reason: format!("the plane at distance {d} from the centre misses the unit sphere"),
    }
}

fn normal_error(which: &'static str) -> SplineError {
    SplineError::InvalidParameter {
        name: which,
        reason: "must be a finite non-zero vector".into(),
    }
}

impl PlaneSection<DVec3> {
    /// The circle `{p ∈ S² : n·p = d}`. `n` need not be unit: the plane is `n̂·p = d/|n|`.
    ///
    /// # Errors
    ///
    /// [`SplineError::InvalidParameter`] (`normal`) for a zero or non-finite `n`, (`d`) for a
    /// non-finite `d` or a plane that misses the sphere (`|d|/|n| > 1`).
    pub fn s2(normal: DVec3, d: f64) -> Result<Self, SplineError> {
        let len = normal.length();
        if !(len.is_finite() && len > 0.0) {
            return Err(normal_error("normal"));
        }
        let (n, d) = (normal / len, d / len);
        if !d.is_finite() || d.abs() > 1.0 {
            return Err(distance_error(d));
        }
        // (5.6), with the coordinate axis least aligned with n where e₃ × n vanishes.
        let helper = if n.x.abs().max(n.y.abs()) > 1e-8 {
            DVec3::Z
        } else {
            DVec3::X
        };
        let x = helper.cross(n).normalize();
        let y = n.cross(x);
        Ok(Self {
            center: n * d,
            radius: (1.0 - d * d).max(0.0).sqrt(),
            x,
            y,
        })
    }

    /// The unit normal `n̂` of the plane (the circle is traversed counter-clockwise about it).
    #[must_use]
    pub fn normal(&self) -> DVec3 {
        self.x.cross(self.y)
    }

    /// The point `c(θ) = κ + ρ(cos θ·x̃ + sin θ·ỹ)`.
    #[must_use]
    pub fn point(&self, theta: f64) -> DVec3 {
        let (s, c) = math::sin_cos(theta);
        self.center + (self.x * c + self.y * s) * self.radius
    }
}

impl PlaneSection<DVec4> {
    /// The circle `{p ∈ S³ : m·p = d₁, n·p = d₂}` for linearly independent `m`, `n` (4-vectors in
    /// the library's `x, y, z, w` order).
    ///
    /// # Errors
    ///
    /// [`SplineError::InvalidParameter`] (`normals`) for non-finite or linearly dependent
    /// normals, (`d`) for non-finite distances or a plane that misses the sphere.
    pub fn s3(normals: [DVec4; 2], d: [f64; 2]) -> Result<Self, SplineError> {
        let [m, n] = normals;
        if !(m.is_finite() && n.is_finite()) {
            return Err(normal_error("normals"));
        }
        // Gram–Schmidt: m̂, n̂′ orthonormal, with the distances carried along.
        let lm = m.length();
        if lm == 0.0 {
            return Err(normal_error("normals"));
        }
        let (mh, d1) = (m / lm, d[0] / lm);
        let w = n - mh * n.dot(mh);
        let lw = w.length();
        if lw.is_nan() || lw <= 1e-12 * n.length() {
            return Err(SplineError::InvalidParameter {
                name: "normals",
                reason: "must be linearly independent".into(),
            });
        }
        let (nh, d2) = (w / lw, (d[1] - d1 * n.dot(mh)) / lw);
        let dist2 = d1 * d1 + d2 * d2;
        if !dist2.is_finite() || dist2 > 1.0 {
            return Err(distance_error(dist2.sqrt()));
        }
        // x̃: the coordinate axis with the largest part orthogonal to m̂, n̂′, made unit.
        let x = [DVec4::X, DVec4::Y, DVec4::Z, DVec4::W]
            .into_iter()
            .map(|e| e - mh * e.dot(mh) - nh * e.dot(nh))
            .max_by(|a, b| a.length_squared().total_cmp(&b.length_squared()))
            .unwrap_or(DVec4::X)
            .normalize();
        let q = |v: DVec4| DQuat::from_vec4(v);
        let y = DVec4::from(ternary_product(q(mh), q(nh), q(x)));
        Ok(Self {
            center: mh * d1 + nh * d2,
            radius: (1.0 - dist2).max(0.0).sqrt(),
            x,
            y,
        })
    }

    /// The point `c(θ) = κ + ρ(cos θ·x̃ + sin θ·ỹ)`.
    #[must_use]
    pub fn point(&self, theta: f64) -> DVec4 {
        let (s, c) = math::sin_cos(theta);
        self.center + (self.x * c + self.y * s) * self.radius
    }
}

impl<V: Clone> PlaneSection<V> {
    /// The centre `κ` (inside the ball; `0` for a great circle).
    #[must_use]
    pub fn center(&self) -> V {
        self.center.clone()
    }

    /// The radius `ρ = √(1 − |κ|²)`.
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The orthonormal basis `(x̃, ỹ)` of the plane's directions; the circle runs from `x̃`
    /// towards `ỹ`.
    #[must_use]
    pub fn basis(&self) -> (V, V) {
        (self.x.clone(), self.y.clone())
    }
}
