// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The circle through three points of a sphere, traversed in their order.

use core::f64::consts::TAU;

use glam::DVec3;

use crate::ambient::Ambient;
use crate::error::SplineError;
use crate::flow::{Flow, PlaneRotation};
use crate::manifold::{Manifold, renormalize};
use crate::math;
use crate::s2::S2Point;

/// Two points closer than this (Euclidean chord) are treated as coincident.
pub(crate) const COINCIDENT_TOLERANCE: f64 = 1e-14;

/// The circle of a sphere through three points `p₁, p₂, p₃`, oriented so that it meets them in
/// this order, with the arc `p₁ → p₂ → p₃`.
///
/// On S² this is the circle of Pobegailo (2019), §8.2, Procedures 8.1–8.3; on S³ the orientation
/// circle of §9.2, Procedures 9.1–9.2. Both are computed by a planar construction in the ambient
/// space (`docs/derivations.md#pobegailo-9-2`), which works on every sphere and
/// stays accurate when the points are nearly on a great circle (the book's ternary-product
/// construction loses accuracy as `ε/|X|` there):
///
/// ```text
/// f₁ = (p₂ − p₁)/|p₂ − p₁|,  f₂ = normalise(p₃ − p₁ − ((p₃ − p₁)·f₁) f₁)
/// κ  = p₁ − (p₁·f₁) f₁ − (p₁·f₂) f₂          centre (foot of the perpendicular from 0)
/// ρ  = |p₁ − κ|,  a = (p₁ − κ)/ρ,  b ⊥ a in the plane, oriented so that θ(p₂) < θ(p₃)
/// θ(x) = atan2((x − κ)·b, (x − κ)·a) ∈ [0, 2π),   φ = θ(p₂),   ψ = θ(p₃) − θ(p₂)
/// 𝒢(θ)x = x + (cos θ − 1)((x·a)a + (x·b)b) + sin θ((x·a)b − (x·b)a)
/// arc(u) = 𝒢(u(φ + ψ)) p₁,  u ∈ [0, 1]
/// ```
///
/// `𝒢` is the one-parameter rotation group whose orbits include the circle (on S² it is
/// `R(â, θ)` with `â = a × b`, the axis of (8.1); on S³ the reading of
/// `docs/derivations.md#pobegailo-9-3`). `φ` and
/// `ψ` are central angles at the circle's own centre, `0 < φ`, `0 < ψ`, `φ + ψ < 2π`.
///
/// # Degenerate cases
///
/// - Three points on one great circle: `κ = 0`, the great-circle arc (no special case).
/// - Antipodal points among the three: allowed; the circle is then a great circle.
/// - `p₂` diametrically opposite `p₁` on its circle (`φ = π`): handled (`b` is built from `p₃`).
/// - Coincident points: no unique circle, a typed error.
///
/// # Examples
///
/// ```
/// use spherekit::{CircleArc, S2Point, glam::DVec3};
///
/// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// let c = CircleArc::through(&p(1.0, 0.0, 1.0), &p(0.0, 1.0, 1.0), &p(-1.0, 0.0, 1.0)).unwrap();
/// let h = core::f64::consts::FRAC_1_SQRT_2;
/// assert!((c.axis() - DVec3::Z).length() < 1e-15);
/// assert!((c.center() - DVec3::new(0.0, 0.0, h)).length() < 1e-15);
/// assert!((c.radius() - h).abs() < 1e-15);
/// assert!((c.first_angle() - core::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
#[derive(Clone, Debug)]
pub struct CircleArc<P: Manifold> {
    start: P,
    center: P::Vector,
    radius: f64,
    plane: PlaneRotation<P::Vector>,
    first_angle: f64,
    second_angle: f64,
}

impl<P: Manifold> CircleArc<P> {
    /// The circle through `p1`, `p2`, `p3` in this order.
    ///
    /// # Errors
    ///
    /// [`SplineError::Coincident`] with `index` 0 (`p1 = p2`) or 1 (`p2 = p3`), and
    /// [`SplineError::NoCircle`] with `index` 0 when `p1 = p3`, within a chord of `1e-14`.
    pub fn through(p1: &P, p2: &P, p3: &P) -> Result<Self, SplineError> {
        let (x1, x2, x3) = (p1.to_vector(), p2.to_vector(), p3.to_vector());
        let d12 = x2.clone() - x1.clone();
        let d13 = x3.clone() - x1.clone();
        let l12 = d12.length();
        if l12 <= COINCIDENT_TOLERANCE {
            return Err(SplineError::Coincident { index: 0 });
        }
        if (x3.clone() - x2.clone()).length() <= COINCIDENT_TOLERANCE {
            return Err(SplineError::Coincident { index: 1 });
        }
        if d13.length() <= COINCIDENT_TOLERANCE {
            return Err(SplineError::NoCircle { index: 0 });
        }
        let f1 = d12 * (1.0 / l12);
        let w = d13.clone() - f1.clone() * d13.dot(&f1);
        let lw = w.length();
        if lw == 0.0 {
            // Three distinct points of a sphere are never collinear; only rounding of nearly
            // coincident points can get here.
            return Err(SplineError::NoCircle { index: 0 });
        }
        let f2 = w * (1.0 / lw);
        let center = x1.clone() - f1.clone() * x1.dot(&f1) - f2.clone() * x1.dot(&f2);
        let r1 = x1.clone() - center.clone();
        let radius = r1.length();
        let a = r1 * (1.0 / radius);
        let (r2, r3) = (x2 - center.clone(), x3 - center.clone());
        // b: the unit vector of the plane ⊥ a, from whichever of r₂, r₃ is better conditioned.
        let o2 = r2.clone() - a.clone() * r2.dot(&a);
        let o3 = r3.clone() - a.clone() * r3.dot(&a);
        let (l2, l3) = (o2.length(), o3.length());
        let mut b = if l2 >= l3 {
            o2 * (1.0 / l2)
        } else {
            o3 * (1.0 / l3)
        };
        let angle = |r: &P::Vector, b: &P::Vector| {
            let t = math::atan2(r.dot(b), r.dot(&a));
            if t < 0.0 { t + TAU } else { t }
        };
        let (mut t2, mut t3) = (angle(&r2, &b), angle(&r3, &b));
        if t3 < t2 {
            b = -b;
            t2 = angle(&r2, &b);
            t3 = angle(&r3, &b);
        }
        let (first_angle, second_angle) = (t2, t3 - t2);
        if first_angle <= 0.0 || !first_angle.is_finite() {
            return Err(SplineError::Coincident { index: 0 });
        }
        if second_angle <= 0.0 || !second_angle.is_finite() {
            return Err(SplineError::Coincident { index: 1 });
        }
        Ok(Self {
            start: p1.clone(),
            center,
            radius,
            plane: PlaneRotation { a, b },
            first_angle,
            second_angle,
        })
    }

    /// The centre `κ` of the circle (inside the ball; `0` for a great circle).
    #[must_use]
    pub fn center(&self) -> P::Vector {
        self.center.clone()
    }

    /// The radius `ρ = √(1 − |κ|²)` (1 for a great circle).
    #[must_use]
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The orthonormal basis `(a, b)` of the circle's plane: `a` points from the centre to `p₁`,
    /// and the circle is traversed from `a` towards `b`.
    #[must_use]
    pub fn plane_basis(&self) -> (P::Vector, P::Vector) {
        (self.plane.a.clone(), self.plane.b.clone())
    }

    /// The central angle `φ ∈ (0, 2π)` from `p₁` to `p₂`.
    #[must_use]
    pub fn first_angle(&self) -> f64 {
        self.first_angle
    }

    /// The central angle `ψ ∈ (0, 2π)` from `p₂` to `p₃`.
    #[must_use]
    pub fn second_angle(&self) -> f64 {
        self.second_angle
    }

    /// `𝒢(θ)·x`: any point of the sphere moved by the one-parameter rotation group of the circle
    /// (points of the circle move along it by the central angle `θ`).
    #[must_use]
    pub fn rotate(&self, theta: f64, x: &P) -> P {
        P::from_vector_unchecked(renormalize(self.plane.apply(theta, &x.to_vector())))
    }

    /// The point of the arc `p₁ → p₂ → p₃` at `u ∈ [0, 1]` (uniform in angle; not clamped).
    #[must_use]
    pub fn point_at(&self, u: f64) -> P {
        self.rotate(u * (self.first_angle + self.second_angle), &self.start)
    }

    pub(crate) fn flow(&self) -> &PlaneRotation<P::Vector> {
        &self.plane
    }
}

#[cfg(any(test, feature = "compact"))]
impl CircleArc<crate::SmPoint> {
    /// The same arc on the point type `Q` ([`crate::recast`]).
    pub(crate) fn recast<Q: Manifold>(&self, to: &crate::recast::Recast<Q>) -> CircleArc<Q> {
        CircleArc {
            start: to.point(&self.start),
            center: to.vector(&self.center),
            radius: self.radius,
            plane: self.plane.recast(to),
            first_angle: self.first_angle,
            second_angle: self.second_angle,
        }
    }
}

impl CircleArc<S2Point> {
    /// The unit axis `â = a × b` of (8.1): the circle is traversed counter-clockwise about it,
    /// and its plane is `â·x = â·p₁`.
    #[must_use]
    pub fn axis(&self) -> DVec3 {
        self.plane.a.cross(self.plane.b).normalize()
    }
}
