// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The differentiated slerp: the second-order jet of `G[a(t), b(t)](u(t))` when the endpoints
//! and the fraction are themselves moving. This is the building block of the exact derivatives
//! of every de Casteljau / slerp pyramid (spherical Bézier, squad, Catmull-Rom, Beta splines).
//!
//! # Formulation
//!
//! ```text
//! G[a, b](u) = R(1 − u, θ)·a + R(u, θ)·b,     R(σ, θ) = sin(σθ)/sin θ = σ·S(σ²θ²)/S(θ²)
//! S(y)       = sin(√y)/√y = Σₖ (−y)ᵏ/(2k+1)!   (entire in y)
//! ```
//!
//! θ itself is not differentiable where `a = b` (it is a distance), but `x = θ²` is a smooth
//! function of `c = a·b`:
//!
//! ```text
//! x(c) = arccos(c)²,   dx/dc = −2/S(x),   d²x/dc² = −4·S′(x)/S(x)³
//! c′ = a′·b + a·b′,    c″ = a″·b + 2a′·b′ + a·b″
//! ```
//!
//! so the coefficients `A = R(1 − u)`, `B = R(u)` are composed from smooth scalar jets only,
//! and `G′ = A′a + Aa′ + B′b + Bb′`, `G″ = A″a + 2A′a′ + Aa″ + B″b + 2B′b′ + Bb″`.
//! `S`, `S′`, `S″` use their power series for `√y < 1` and closed forms above, so nothing is
//! divided by a small angle: coincident and nearly coincident endpoints give exact, finite
//! jets. The angle θ comes from `2·atan2(|a − b|, |a + b|)` and `sin θ = |a − b|·|a + b|/2`,
//! accurate near 0 and near π.
//!
//! Near π the coefficients grow like `1/sin θ` and `a`, `b` are nearly parallel, so the result
//! carries the problem's own conditioning (errors of order `ε/(π − θ)`); the normal components
//! of `G′` and `G″` are then restored exactly (`G·G′ = 0`, `G·G″ = −|G′|²`). Exactly antipodal
//! endpoints (within [`ANTIPODAL_TOLERANCE`]) have no geodesic: [`slerp_jet`] reports them.

use crate::ambient::Ambient;
use crate::curve::Jet;
use crate::error::PointError;
use crate::manifold::{ANTIPODAL_TOLERANCE, Manifold, geodesic_frame, renormalize};
use crate::math;

/// A scalar function of the curve parameter with its first and second derivatives.
///
/// Used as the fraction `u(t)` of [`slerp_jet`]: for a curve segment on `[t₀, t₀ + h]` with
/// local parameter `τ = (t − t₀)/h`, pass [`ScalarJet::param`]`(τ, 1/h)` and every derivative
/// comes out with respect to the global `t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalarJet {
    /// `u(t)`.
    pub value: f64,
    /// `u′(t)`.
    pub first: f64,
    /// `u″(t)`.
    pub second: f64,
}

impl ScalarJet {
    /// A constant (zero derivatives).
    #[must_use]
    pub const fn constant(value: f64) -> Self {
        Self {
            value,
            first: 0.0,
            second: 0.0,
        }
    }

    /// An affine parameter `u = value` with `u′ = rate`, `u″ = 0`.
    #[must_use]
    pub const fn param(value: f64, rate: f64) -> Self {
        Self {
            value,
            first: rate,
            second: 0.0,
        }
    }

    /// `g ∘ self` for a scalar function with `g(value) = g0`, `g′(value) = g1`, `g″(value) = g2`.
    #[inline]
    #[must_use]
    pub fn compose(self, [g0, g1, g2]: [f64; 3]) -> Self {
        Self {
            value: g0,
            first: g1 * self.first,
            second: g2 * self.first * self.first + g1 * self.second,
        }
    }

    /// `1 − self`.
    #[inline]
    #[must_use]
    pub fn one_minus(self) -> Self {
        Self {
            value: 1.0 - self.value,
            first: -self.first,
            second: -self.second,
        }
    }
}

impl core::ops::Mul for ScalarJet {
    type Output = Self;
    /// The product jet (Leibniz rule).
    #[inline]
    fn mul(self, o: Self) -> Self {
        Self {
            value: self.value * o.value,
            first: self.first * o.value + self.value * o.first,
            second: self.second * o.value + 2.0 * self.first * o.first + self.value * o.second,
        }
    }
}

impl core::ops::Div for ScalarJet {
    type Output = Self;
    /// The quotient jet `self / o` (`o.value ≠ 0`).
    #[inline]
    fn div(self, o: Self) -> Self {
        let inv = 1.0 / o.value;
        let q = self.value * inv;
        let q1 = (self.first - q * o.first) * inv;
        let q2 = (self.second - 2.0 * q1 * o.first - q * o.second) * inv;
        Self {
            value: q,
            first: q1,
            second: q2,
        }
    }
}

/// `(−1)ᵏ/(2k+1)!` for k = 0‥12, the coefficients of `S(y) = sin(√y)/√y`.
const S_COEFFS: [f64; 13] = {
    let mut c = [0.0; 13];
    let mut f = 1.0;
    let mut k = 0;
    while k < 13 {
        if k > 0 {
            f *= ((2 * k) * (2 * k + 1)) as f64;
        }
        c[k] = if k % 2 == 0 { 1.0 / f } else { -1.0 / f };
        k += 1;
    }
    c
};

/// `S(y)`, `S′(y)`, `S″(y)` at `y = φ²` for `S(y) = sin(√y)/√y`, `φ ≥ 0`, given `sin φ`, `cos φ`.
///
/// Power series (Horner, 13 terms, truncation below 1e-20) for `φ < 1`; closed forms above,
/// where their cancellation costs at most a few ulps relative:
///
/// ```text
/// S = sin φ/φ,   S′ = (φ cos φ − sin φ)/(2φ³),   S″ = (3 sin φ − 3φ cos φ − φ² sin φ)/(4φ⁵)
/// ```
#[inline]
fn sinc_sqrt_triple(phi: f64, sin_phi: f64, cos_phi: f64) -> [f64; 3] {
    if phi < 1.0 {
        let y = phi * phi;
        let (mut s0, mut s1, mut s2) = (0.0, 0.0, 0.0);
        for k in (0..13).rev() {
            let c = S_COEFFS[k];
            s0 = s0 * y + c;
            if k >= 1 {
                s1 = s1 * y + c * k as f64;
            }
            if k >= 2 {
                s2 = s2 * y + c * (k * (k - 1)) as f64;
            }
        }
        [s0, s1, s2]
    } else {
        let p2 = phi * phi;
        let p3 = p2 * phi;
        let s0 = sin_phi / phi;
        let s1 = (phi * cos_phi - sin_phi) / (2.0 * p3);
        let s2 = (3.0 * (sin_phi - phi * cos_phi) - p2 * sin_phi) / (4.0 * p3 * p2);
        [s0, s1, s2]
    }
}

/// A point of an ambient curve with its first and second derivatives (internal form of
/// [`Jet`], without the point type).
#[derive(Clone, Debug)]
pub(crate) struct VJet<V> {
    pub(crate) v: V,
    pub(crate) d: V,
    pub(crate) dd: V,
}

impl<V: Ambient> VJet<V> {
    /// A point at rest.
    #[inline]
    pub(crate) fn constant(v: V) -> Self {
        let z = v.zeros_like();
        Self {
            v,
            d: z.clone(),
            dd: z,
        }
    }

    pub(crate) fn from_jet<P: Manifold<Vector = V>>(j: &Jet<P>) -> Self {
        Self {
            v: j.point.to_vector(),
            d: j.velocity.clone(),
            dd: j.acceleration.clone(),
        }
    }

    pub(crate) fn into_jet<P: Manifold<Vector = V>>(self) -> Jet<P> {
        Jet {
            point: P::from_vector_unchecked(self.v),
            velocity: self.d,
            acceleration: self.dd,
        }
    }
}

/// A fixed great-circle arc `G[p, q](s) = cos(sθ)·p + sin(sθ)·e` with its frame precomputed,
/// for the first level of a pyramid whose control points do not move.
#[derive(Clone, Debug)]
pub(crate) struct FixedArc<V> {
    start: V,
    end: V,
    /// Unit tangent at `start` towards `end` (zero for a zero-length arc).
    dir: V,
    theta: f64,
}

impl<V: Ambient> FixedArc<V> {
    /// `None` for antipodal endpoints.
    pub(crate) fn try_new(p: V, q: V) -> Option<Self> {
        let (theta, dir) = geodesic_frame(&p, &q)?;
        Some(Self {
            start: p,
            end: q,
            dir,
            theta,
        })
    }

    /// The same arc in the ambient space of `Q` ([`crate::recast`]).
    #[cfg(any(test, feature = "compact"))]
    pub(crate) fn recast<Q: Manifold>(&self, to: &crate::recast::Recast<Q>) -> FixedArc<Q::Vector> {
        FixedArc {
            start: to.vector(&self.start),
            end: to.vector(&self.end),
            dir: to.vector(&self.dir),
            theta: self.theta,
        }
    }

    /// The point at fraction `s`; exact at 0 and 1.
    #[inline]
    pub(crate) fn point(&self, s: f64) -> V {
        if s == 0.0 {
            return self.start.clone();
        }
        if s == 1.0 {
            return self.end.clone();
        }
        renormalize(self.point_unnormalized(s))
    }

    /// `cos(sθ)·p + sin(sθ)·e` without the final rescaling (unit up to a few ulps): for
    /// intermediate points of a pyramid, which [`slerp_point`] renormalises anyway.
    #[inline]
    pub(crate) fn point_unnormalized(&self, s: f64) -> V {
        let (sn, cs) = math::sin_cos(s * self.theta);
        self.start.clone() * cs + self.dir.clone() * sn
    }

    /// The jet at the fraction jet `s`:
    /// `G′ = θs′·T`, `G″ = θs″·T − (θs′)²·G` with `T = −sin(sθ)·p + cos(sθ)·e`.
    #[inline]
    pub(crate) fn jet(&self, s: ScalarJet) -> VJet<V> {
        let (sn, cs) = math::sin_cos(s.value * self.theta);
        let v = self.point(s.value);
        let tangent = self.dir.clone() * cs - self.start.clone() * sn;
        let w = self.theta * s.first;
        VJet {
            d: tangent.clone() * w,
            dd: tangent * (self.theta * s.second) - v.clone() * (w * w),
            v,
        }
    }
}

/// The point `G[a, b](u)` for vectors that are unit up to a few ulps; `None` when antipodal.
///
/// The fast path of the pyramids' point evaluation: as [`Manifold::try_slerp`] but without
/// forming the unit direction separately (`|b − cos θ·a| = sin θ = |a − b|·|a + b|/2`).
#[inline]
pub(crate) fn slerp_point<V: Ambient>(a: V, b: V, u: f64) -> Option<V> {
    let diff = b.clone() - a.clone();
    let sum = b + a.clone();
    let (d, s) = (diff.length(), sum.length());
    // b − cos θ·a without cancellation: from the difference near 0, from the sum near π.
    let w = if d <= s {
        if d == 0.0 {
            return Some(a);
        }
        diff + a.clone() * (0.5 * d * d)
    } else {
        if s <= ANTIPODAL_TOLERANCE {
            return None;
        }
        sum - a.clone() * (0.5 * s * s)
    };
    let theta = 2.0 * math::atan2(d, s);
    let (sn, cs) = math::sin_cos(u * theta);
    Some(renormalize(a * cs + w * (sn / (0.5 * d * s))))
}

/// Ambient-vector form of [`slerp_jet`]; `None` if `a(t)` and `b(t)` are antipodal.
pub(crate) fn slerp_jet_vec<V: Ambient>(a: &VJet<V>, b: &VJet<V>, u: ScalarJet) -> Option<VJet<V>> {
    let diff = b.v.clone() - a.v.clone();
    let sum = b.v.clone() + a.v.clone();
    let (dl, sl) = (diff.length(), sum.length());
    let c = a.v.dot(&b.v);
    if c < 0.0 && sl <= ANTIPODAL_TOLERANCE {
        return None;
    }
    let theta = 2.0 * math::atan2(dl, sl);
    // Unit vectors: |a − b| = 2 sin(θ/2), |a + b| = 2 cos(θ/2).
    let sin_t = 0.5 * dl * sl;
    let cos_t = if c >= 0.0 {
        1.0 - 0.5 * dl * dl
    } else {
        0.5 * sl * sl - 1.0
    };
    let sx = sinc_sqrt_triple(theta, sin_t, cos_t);

    // c = a·b and x = θ² as jets.
    let c1 = a.d.dot(&b.v) + a.v.dot(&b.d);
    let c2 = a.dd.dot(&b.v) + 2.0 * a.d.dot(&b.d) + a.v.dot(&b.dd);
    let dx_dc = -2.0 / sx[0];
    let d2x_dc2 = -4.0 * sx[1] / (sx[0] * sx[0] * sx[0]);
    let x = ScalarJet {
        value: theta * theta,
        first: dx_dc * c1,
        second: d2x_dc2 * c1 * c1 + dx_dc * c2,
    };
    let s_x = x.compose(sx);

    // R(σ) = σ·S(σ²x)/S(x).
    let ratio = |sigma: ScalarJet| -> ScalarJet {
        let y = sigma * sigma * x;
        let phi = sigma.value.abs() * theta;
        let sy = if sigma.value.abs() == 1.0 {
            sx
        } else {
            let (s, c) = math::sin_cos(phi);
            sinc_sqrt_triple(phi, s, c)
        };
        sigma * (y.compose(sy) / s_x)
    };
    let ca = ratio(u.one_minus());
    let cb = ratio(u);

    let v = if u.value == 0.0 {
        a.v.clone()
    } else if u.value == 1.0 {
        b.v.clone()
    } else {
        renormalize(a.v.clone() * ca.value + b.v.clone() * cb.value)
    };
    let d = a.v.clone() * ca.first
        + a.d.clone() * ca.value
        + b.v.clone() * cb.first
        + b.d.clone() * cb.value;
    let dd = a.v.clone() * ca.second
        + a.d.clone() * (2.0 * ca.first)
        + a.dd.clone() * ca.value
        + b.v.clone() * cb.second
        + b.d.clone() * (2.0 * cb.first)
        + b.dd.clone() * cb.value;
    // Restore the exact normal components (G·G′ = 0, G·G″ = −|G′|²). Analytically a no-op;
    // numerically it removes the cancellation error of the nearly parallel `a`, `b` when they
    // are close to antipodal, where the coefficients grow like 1/sin θ.
    let d = d.clone() - v.clone() * v.dot(&d);
    let dd = dd.clone() - v.clone() * (v.dot(&dd) + d.dot(&d));
    Some(VJet { v, d, dd })
}

/// The point, velocity and acceleration of `G[a(t), b(t)](u(t))`: geodesic interpolation
/// (slerp, no sign flips) between two moving points of a sphere at a moving fraction.
///
/// `a` and `b` are jets of points on the same sphere (velocities tangent, accelerations the full
/// ambient second derivatives), `u` the jet of the fraction. Coincident or nearly coincident `a`
/// and `b` are fine: see the module formulation (everything is a smooth function of `θ²`).
///
/// ```text
/// G  = R(1 − u)·a + R(u)·b,            R(σ) = sin(σθ)/sin θ
/// G′ = A′a + Aa′ + B′b + Bb′,          A = R(1 − u), B = R(u) (as jets in t)
/// G″ = A″a + 2A′a′ + Aa″ + B″b + 2B′b′ + Bb″
/// ```
///
/// # Errors
///
/// - [`PointError::NonFinite`] if a velocity or acceleration of `a` or `b` has a NaN or
///   infinite coordinate;
/// - [`PointError::NonFiniteParameter`] if a component of `u` is NaN or infinite, or the
///   fraction is so far outside `[0, 1]` that the jet overflows;
/// - [`PointError::Antipodal`] if `a` and `b` are antipodal (within [`ANTIPODAL_TOLERANCE`]),
///   where the geodesic is not unique.
///
/// # Examples
///
/// ```
/// use spherekit::{Ambient, Jet, Manifold, S2Point, ScalarJet, slerp_jet};
/// use spherekit::glam::DVec3;
///
/// let a = Jet { point: S2Point::X, velocity: DVec3::ZERO, acceleration: DVec3::ZERO };
/// let b = Jet { point: S2Point::Y, velocity: DVec3::ZERO, acceleration: DVec3::ZERO };
/// // u = t at t = 0.5: the midpoint, moving at the constant angular speed π/2.
/// let j = slerp_jet(&a, &b, ScalarJet::param(0.5, 1.0)).unwrap();
/// assert!(j.point.dist(&S2Point::X.slerp(&S2Point::Y, 0.5)) < 1e-15);
/// assert!((j.velocity.length() - core::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// // Same start and end: the jet of a point at rest, no NaN.
/// let j = slerp_jet(&a, &a, ScalarJet::param(0.3, 1.0)).unwrap();
/// assert_eq!(j.point, S2Point::X);
/// assert!(j.velocity.length() < 1e-15 && j.acceleration.length() < 1e-15);
/// ```
pub fn slerp_jet<P: Manifold>(a: &Jet<P>, b: &Jet<P>, u: ScalarJet) -> Result<Jet<P>, PointError> {
    let finite = |j: &VJet<P::Vector>| j.d.is_finite() && j.dd.is_finite();
    let (a, b) = (VJet::from_jet(a), VJet::from_jet(b));
    if !(finite(&a) && finite(&b)) {
        return Err(PointError::NonFinite);
    }
    if !(u.value.is_finite() && u.first.is_finite() && u.second.is_finite()) {
        return Err(PointError::NonFiniteParameter);
    }
    let j = slerp_jet_vec(&a, &b, u).ok_or(PointError::Antipodal)?;
    if j.v.is_finite() && finite(&j) {
        Ok(j.into_jet())
    } else {
        Err(PointError::NonFiniteParameter)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn series_and_closed_forms_agree_at_the_switch() {
        for phi in [1.0_f64 - 1e-12, 1.0 + 1e-12] {
            let (s, c) = phi.sin_cos();
            let t = sinc_sqrt_triple(phi, s, c);
            let p = phi;
            let exact = [
                p.sin() / p,
                (p * p.cos() - p.sin()) / (2.0 * p.powi(3)),
                (3.0 * p.sin() - 3.0 * p * p.cos() - p * p * p.sin()) / (4.0 * p.powi(5)),
            ];
            for k in 0..3 {
                assert!(
                    (t[k] - exact[k]).abs() < 1e-13,
                    "{k}: {} {}",
                    t[k],
                    exact[k]
                );
            }
        }
        let z = sinc_sqrt_triple(0.0, 0.0, 1.0);
        assert_eq!(z, [1.0, -1.0 / 6.0, 2.0 / 120.0], "values at 0");
    }

    /// Moving endpoints: compare with central differences of the point and the velocity.
    #[test]
    fn moving_endpoints_match_finite_differences() {
        let curve_a = |t: f64| DVec3::new(t.cos(), t.sin() * 0.6, t.sin() * 0.8);
        let curve_b = |t: f64| {
            let v = DVec3::new(0.3 + 0.2 * t * t, 1.0 - t, 0.5 * t);
            v / v.length()
        };
        let fu = |t: f64| 0.3 + 0.4 * t + 0.2 * t * t;
        let jet_of = |f: &dyn Fn(f64) -> DVec3, t: f64| {
            let h = 1e-4;
            VJet {
                v: f(t),
                d: (f(t + h) - f(t - h)) / (2.0 * h),
                dd: (f(t + h) - 2.0 * f(t) + f(t - h)) / (h * h),
            }
        };
        let g = |t: f64| {
            // exact endpoint jets are not needed for the value
            let a = VJet::constant(curve_a(t));
            let b = VJet::constant(curve_b(t));
            slerp_jet_vec(&a, &b, ScalarJet::constant(fu(t))).unwrap().v
        };
        let t = 0.37;
        let a = jet_of(&curve_a, t);
        let b = jet_of(&curve_b, t);
        let u = ScalarJet {
            value: fu(t),
            first: 0.4 + 0.4 * t,
            second: 0.4,
        };
        let j = slerp_jet_vec(&a, &b, u).unwrap();
        let h = 1e-4;
        let d_fd = (g(t + h) - g(t - h)) / (2.0 * h);
        let dd_fd = (g(t + h) - 2.0 * g(t) + g(t - h)) / (h * h);
        assert!((j.d - d_fd).length() < 1e-6, "{:?} {:?}", j.d, d_fd);
        assert!((j.dd - dd_fd).length() < 1e-5, "{:?} {:?}", j.dd, dd_fd);
    }

    /// Fixed endpoints at angles across the whole range (series, switch, closed form, near π):
    /// the moving-endpoint formula must reduce to the arc `G′ = θu′T`, `G″ = −(θu′)²G`.
    #[test]
    fn fixed_endpoints_at_all_angles() {
        for theta in [
            0.0_f64,
            1e-12,
            1e-9,
            1e-5,
            0.3,
            0.999_999,
            1.0,
            1.000_001,
            2.0,
            3.0,
            core::f64::consts::PI - 2.65e-6,
        ] {
            let a = DVec3::X;
            let b = DVec3::new(theta.cos(), theta.sin(), 0.0);
            let arc = FixedArc::try_new(a, b).unwrap();
            for u in [0.0, 0.25, 0.5, 0.9, 1.0] {
                let uj = ScalarJet {
                    value: u,
                    first: 1.3,
                    second: -0.7,
                };
                let j = slerp_jet_vec(&VJet::constant(a), &VJet::constant(b), uj).unwrap();
                let r = arc.jet(uj);
                // Near π the problem itself is ill-conditioned: errors grow like ε/(π − θ).
                let scale = 1.0 + 1.0 / (theta - core::f64::consts::PI).abs();
                assert!(
                    (j.v - r.v).length() < 4e-16 * scale,
                    "point θ={theta} u={u}"
                );
                assert!(
                    (j.d - r.d).length() < 1e-15 * scale,
                    "velocity θ={theta} u={u}: {:?} {:?}",
                    j.d,
                    r.d
                );
                assert!(
                    (j.dd - r.dd).length() < 1e-14 * scale,
                    "acceleration θ={theta} u={u}: {:?} vs {:?}",
                    j.dd,
                    r.dd
                );
            }
        }
    }

    /// Endpoints moving along geodesics at separations from 1e-8 to nearly π.
    #[test]
    fn moving_endpoints_at_all_separations() {
        let geo = |p: DVec3, v: DVec3, t: f64| {
            let n = v.length();
            p * (n * t).cos() + v / n * (n * t).sin()
        };
        let geo_jet = |p: DVec3, v: DVec3| VJet {
            v: p,
            d: v,
            dd: -p * v.length_squared(),
        };
        for theta in [1e-8_f64, 1e-4, 0.5, 1.0, 2.5, 3.1] {
            let a0 = DVec3::X;
            let b0 = DVec3::new(theta.cos(), theta.sin(), 0.0);
            let va = DVec3::new(0.0, 0.3, -0.8);
            let vb = DVec3::new(-0.2 * theta.sin(), 0.2 * theta.cos(), 0.5);
            let u = ScalarJet {
                value: 0.35,
                first: 0.6,
                second: 0.2,
            };
            let ut = |t: f64| 0.35 + 0.6 * t + 0.1 * t * t;
            let g = |t: f64| {
                let (a, b) = (geo(a0, va, t), geo(b0, vb, t));
                slerp_jet_vec(
                    &VJet::constant(a),
                    &VJet::constant(b),
                    ScalarJet::constant(ut(t)),
                )
                .unwrap()
                .v
            };
            let j = slerp_jet_vec(&geo_jet(a0, va), &geo_jet(b0, vb), u).unwrap();
            let h = 2e-5;
            let d = (g(h) - g(-h)) / (2.0 * h);
            let dd = (g(h) - 2.0 * g(0.0) + g(-h)) / (h * h);
            assert!(
                (j.d - d).length() < 1e-7 * j.d.length().max(1.0),
                "θ={theta}: {:?} {d:?}",
                j.d
            );
            assert!(
                (j.dd - dd).length() < 1e-5 * j.dd.length().max(1.0),
                "θ={theta}: {:?} {dd:?}",
                j.dd
            );
        }
    }
}
