// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Kim–Kim–Shin cumulative-form quaternion curves: the Bézier quaternion curve of any degree and
//! the uniform cubic B-spline quaternion curve, with the shared product-of-exponentials machinery.
//!
//! Both curves have the form
//!
//! ```text
//! q(t) = q_base · exp(ω₁ β₁(t)) · exp(ω₂ β₂(t)) ⋯ exp(ωₖ βₖ(t)),   ωⱼ = log(qⱼ₋₁⁻¹ qⱼ)
//! ```
//!
//! with scalar cumulative basis functions βⱼ. Their exact derivatives come from the product rule
//! over the factors, organised as a forward recursion on the body-frame angular rate
//! (see [`cumulative_jet`]).

use glam::{DQuat, DVec3, DVec4};

use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::knots::Knots;
use crate::manifold::{Manifold, geodesic_frame, renormalize};
use crate::math;
use crate::s3::UnitQuat;

/// A body-frame logarithm `ω` stored as unit axis and angle, so that `exp(ω β)` costs one
/// `sin_cos` and no normalisation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rate {
    /// `ω/|ω|`, or zero when `ω = 0`.
    axis: DVec3,
    /// `|ω|`.
    angle: f64,
}

impl Rate {
    pub(crate) fn new(omega: DVec3) -> Self {
        let angle = omega.length();
        if angle > 0.0 {
            Self {
                axis: omega / angle,
                angle,
            }
        } else {
            Self {
                axis: DVec3::ZERO,
                angle: 0.0,
            }
        }
    }
}

/// One factor `exp(ω β(t))` of a cumulative product: `ω` and `[β, β′, β″]` at the current
/// parameter (derivatives already scaled to the curve parameter).
pub(crate) type Factor = (Rate, [f64; 3]);

/// The body-frame logarithm `log(a⁻¹ b)` (a pure quaternion as a vector of ℝ³), without sign flips;
/// `None` when `a` and `b` are antipodal.
///
/// It is computed from the ambient geodesic tangent at `a` (formed from `b − a` near 0), so it
/// keeps full relative accuracy for nearly equal points, where the product `a⁻¹ b` would lose
/// digits to cancellation.
pub(crate) fn body_log(a: UnitQuat, b: UnitQuat) -> Option<DVec3> {
    let p = a.to_vector();
    let (theta, e) = geodesic_frame(&p, &b.to_vector())?;
    // a·ω is the tangent at a, so ω = a⁻¹·(θ e); its scalar part vanishes up to rounding.
    Some((a.as_dquat().conjugate() * DQuat::from_vec4(e * theta)).xyz())
}

/// `exp(ω β) = cos(|ω|β) + sin(|ω|β)·ω̂` as `(cos, sin·ω̂)`.
#[inline]
fn exp_factor(rate: Rate, beta: f64) -> (f64, DVec3) {
    let (s, c) = math::sin_cos(rate.angle * beta);
    (c, rate.axis * s)
}

/// `E⁻¹ x E` for the unit quaternion `E = (c, e)`: the rotation of `x` by `(c, −e)`.
#[inline]
fn rotate_inverse(c: f64, e: DVec3, x: DVec3) -> DVec3 {
    let t = 2.0 * x.cross(e); // 2 (−e) × x
    x + c * t - e.cross(t)
}

/// The Hamilton product `p · (c, e)`.
#[inline]
fn mul_quat(p: DQuat, c: f64, e: DVec3) -> DQuat {
    let pv = p.xyz();
    let v = p.w * e + c * pv + pv.cross(e);
    DQuat::from_xyzw(v.x, v.y, v.z, p.w * c - pv.dot(e))
}

/// The Hamilton product `p · (0, v)` as an ambient `x, y, z, w` vector.
#[inline]
fn mul_pure(p: DQuat, v: DVec3) -> DVec4 {
    let pv = p.xyz();
    (p.w * v + pv.cross(v)).extend(-pv.dot(v))
}

/// The point `base · ∏ⱼ exp(ωⱼ βⱼ)` alone.
pub(crate) fn cumulative_point(base: DQuat, factors: &[Factor]) -> DQuat {
    let mut p = base;
    for &(rate, [b0, _, _]) in factors {
        let (c, e) = exp_factor(rate, b0);
        p = mul_quat(p, c, e);
    }
    DQuat::from_vec4(renormalize(DVec4::from(p)))
}

/// The point and exact ambient first and second derivatives of
/// `q(t) = base · ∏ⱼ exp(ωⱼ βⱼ(t))`.
///
/// With `Pⱼ = base · E₁ ⋯ Eⱼ`, `Eⱼ = exp(ωⱼ βⱼ)`, and the body rate `Vⱼ = Pⱼ⁻¹ Pⱼ′` (a pure
/// quaternion), the product rule gives, since `ωⱼ` commutes with `Eⱼ`,
///
/// ```text
/// Vⱼ  = Eⱼ⁻¹ Vⱼ₋₁ Eⱼ + ωⱼ βⱼ′                                 V₀ = 0
/// Vⱼ′ = Eⱼ⁻¹ Vⱼ₋₁′ Eⱼ + 2 (Eⱼ⁻¹ Vⱼ₋₁ Eⱼ) × (ωⱼ βⱼ′) + ωⱼ βⱼ″    V₀′ = 0
/// q′  = q · V,   q″ = q · (V² + V′) = q · V′ − |V|² q
/// ```
///
/// (the cross product is the commutator `[x, y] = xy − yx = 2 x × y` of pure quaternions).
/// Returns `(q, q′, q″)` with the derivatives as ambient `x, y, z, w` vectors.
pub(crate) fn cumulative_jet(base: DQuat, factors: &[Factor]) -> (DQuat, DVec4, DVec4) {
    let mut p = base;
    let mut v = DVec3::ZERO;
    let mut a = DVec3::ZERO;
    for &(rate, [b0, b1, b2]) in factors {
        let (c, e) = exp_factor(rate, b0);
        let u = rotate_inverse(c, e, v);
        let w1 = rate.axis * (rate.angle * b1);
        a = rotate_inverse(c, e, a) + 2.0 * u.cross(w1) + rate.axis * (rate.angle * b2);
        v = u + w1;
        p = mul_quat(p, c, e);
    }
    let p = DQuat::from_vec4(renormalize(DVec4::from(p)));
    let dq = mul_pure(p, v);
    let ddq = mul_pure(p, a) - DVec4::from(p) * v.length_squared();
    (p, dq, ddq)
}

/// The cumulative cubic Bernstein basis `B̃ⱼ,₃` (j = 1, 2, 3) with first and second derivatives
/// at `t`, derivatives multiplied by `d = dt/du` and `d²` respectively.
#[inline]
pub(crate) fn cubic_bezier_basis(t: f64, d: f64) -> [[f64; 3]; 3] {
    let t2 = t * t;
    let t3 = t2 * t;
    let u = 1.0 - t;
    let d2 = d * d;
    [
        // 1 − (1 − t)³ = t³ − 3t² + 3t
        [1.0 - u * u * u, 3.0 * u * u * d, -6.0 * u * d2],
        [3.0 * t2 - 2.0 * t3, 6.0 * t * u * d, (6.0 - 12.0 * t) * d2],
        [t3, 3.0 * t2 * d, 6.0 * t * d2],
    ]
}

/// The cumulative uniform cubic B-spline basis `B̃ⱼ` (j = 1, 2, 3) on a unit interval, local
/// parameter `s ∈ [0, 1]`, with first and second derivatives (the parameter step is 1).
#[inline]
fn cubic_bspline_basis(s: f64) -> [[f64; 3]; 3] {
    let s2 = s * s;
    let s3 = s2 * s;
    const SIXTH: f64 = 1.0 / 6.0;
    [
        [
            (5.0 + 3.0 * s - 3.0 * s2 + s3) * SIXTH,
            (3.0 - 6.0 * s + 3.0 * s2) * SIXTH,
            (-6.0 + 6.0 * s) * SIXTH,
        ],
        [
            (1.0 + 3.0 * s + 3.0 * s2 - 2.0 * s3) * SIXTH,
            (3.0 + 6.0 * s - 6.0 * s2) * SIXTH,
            (6.0 - 12.0 * s) * SIXTH,
        ],
        [s3 * SIXTH, 3.0 * s2 * SIXTH, 6.0 * s * SIXTH],
    ]
}

/// Fills `out[j − 1] = [B̃ⱼ,ₙ(t), B̃ⱼ,ₙ′(t), B̃ⱼ,ₙ″(t)]` for j = 1..n, where `n = out.len()`, using
/// `B̃ⱼ,ₙ′ = n·Bⱼ₋₁,ₙ₋₁` and `B̃ⱼ,ₙ″ = n(n − 1)(Bⱼ₋₂,ₙ₋₂ − Bⱼ₋₁,ₙ₋₂)`. `scratch` needs `3(n + 1)`
/// entries.
fn cumulative_bernstein(t: f64, out: &mut [[f64; 3]], scratch: &mut [f64]) {
    let n = out.len();
    let (b, rest) = scratch.split_at_mut(n + 1);
    let (b1, rest) = rest.split_at_mut(n + 1);
    let b2 = &mut rest[..=n];
    let u = 1.0 - t;
    // Bernstein polynomials of increasing degree by the de Casteljau triangle.
    b.fill(0.0);
    b1.fill(0.0);
    b2.fill(0.0);
    b[0] = 1.0;
    for m in 1..=n {
        if m + 1 == n {
            b2[..m].copy_from_slice(&b[..m]);
        }
        if m == n {
            b1[..m].copy_from_slice(&b[..m]);
        }
        b[m] = t * b[m - 1];
        for j in (1..m).rev() {
            b[j] = u * b[j] + t * b[j - 1];
        }
        b[0] *= u;
    }
    let nf = n as f64;
    let c2 = nf * (nf - 1.0);
    let mut cum = 0.0;
    for j in (1..=n).rev() {
        cum += b[j];
        let d1 = nf * b1[j - 1];
        let below = if j >= 2 { b2[j - 2] } else { 0.0 };
        let at = if j < n { b2[j - 1] } else { 0.0 };
        let d2 = if n >= 2 { c2 * (below - at) } else { 0.0 };
        out[j - 1] = [cum, d1, d2];
    }
}

/// Body-frame logarithms `ωⱼ = log(qⱼ₋₁⁻¹ qⱼ)`, j = 1..n, or the first antipodal pair.
fn chain_logs(controls: &[UnitQuat]) -> Result<Vec<DVec3>, SplineError> {
    controls
        .windows(2)
        .enumerate()
        .map(|(index, w)| body_log(w[0], w[1]).ok_or(SplineError::Antipodal { index }))
        .collect()
}

/// Degrees up to this evaluate without heap allocation.
const STACK_DEGREE: usize = 16;

/// Kim–Kim–Shin's Bézier quaternion curve of degree `n ≥ 1` in cumulative form, on S³.
///
/// For control quaternions `q₀ … qₙ` and `t ∈ [0, 1]`:
///
/// ```text
/// q(t) = q₀ · exp(ω₁ B̃₁,ₙ(t)) · exp(ω₂ B̃₂,ₙ(t)) ⋯ exp(ωₙ B̃ₙ,ₙ(t)),   ωᵢ = log(qᵢ₋₁⁻¹ qᵢ)
/// B̃ᵢ,ₙ(t) = Σⱼ₌ᵢⁿ C(n, j) (1 − t)ⁿ⁻ʲ tʲ            (cumulative Bernstein basis)
/// ```
///
/// multiplied left to right in increasing `i` (the order matters). `exp` and `log` are the
/// quaternion ones without a half-angle factor (`exp(v) = cos|v| + sin|v|/|v|·v`). Derivatives
/// are exact: `d/dt exp(ω β) = exp(ω β)·ω β′`, combined over the factors by the product rule.
///
/// Properties (Kim, Kim & Shin 1995; Chen et al. 2022, §2.2, Lemma 2): `q(0) = q₀`, `q(1) = qₙ`,
/// `q′(0) = n·q₀ ω₁`, `q′(1) = n·qₙ ωₙ`; `n = 1` is slerp; left and right multiplication of all
/// controls by fixed unit quaternions multiplies the curve the same way. It is **not** the
/// de Casteljau (repeated slerp) spherical Bézier curve in general; the two coincide when all
/// controls lie on one great circle of S³. It is not reversal-symmetric. Controls are used as
/// given (no sign flips; see [`unflip`](crate::unflip)).
///
/// # Examples
///
/// ```
/// use spherekit::{glam::DVec3, Curve, BezierKim, Manifold, UnitQuat};
///
/// let q0 = UnitQuat::IDENTITY;
/// let q1 = UnitQuat::from_axis_angle(DVec3::X, 1.0).unwrap();
/// let q2 = UnitQuat::from_axis_angle(DVec3::Y, 1.0).unwrap();
/// let q3 = UnitQuat::from_axis_angle(DVec3::Z, 1.0).unwrap();
/// let c = BezierKim::try_new(vec![q0, q1, q2, q3]).unwrap();
/// assert_eq!(c.domain(), [0.0, 1.0]);
/// assert!(c.eval(1.0).dist(&q3) < 1e-15);
/// // q′(0) = n·q₀·ω₁ with ω₁ = log(q₀⁻¹ q₁) = (0.5, 0, 0).
/// let v = c.jet(0.0).velocity;
/// assert!((v - 3.0 * 0.5 * spherekit::glam::DVec4::X).length() < 1e-14);
/// ```
#[derive(Clone, Debug)]
pub struct BezierKim {
    controls: Vec<UnitQuat>,
    omegas: Vec<DVec3>,
    rates: Vec<Rate>,
    knots: Knots,
}

impl BezierKim {
    /// Builds the curve of degree `controls.len() − 1` on `[0, 1]`.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 2 controls; [`SplineError::Antipodal`] when
    /// consecutive controls are antipodal (`ωᵢ` undefined).
    pub fn try_new(controls: Vec<UnitQuat>) -> Result<Self, SplineError> {
        if controls.len() < 2 {
            return Err(SplineError::TooFewPoints {
                min: 2,
                got: controls.len(),
            });
        }
        let omegas = chain_logs(&controls)?;
        let rates = omegas.iter().copied().map(Rate::new).collect();
        Ok(Self {
            controls,
            omegas,
            rates,
            knots: Knots::uniform(2),
        })
    }

    /// The control quaternions `q₀ … qₙ`.
    #[must_use]
    pub fn controls(&self) -> &[UnitQuat] {
        &self.controls
    }

    /// The degree `n`.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.omegas.len()
    }

    /// The body-frame logarithms `ωᵢ = log(qᵢ₋₁⁻¹ qᵢ)`, i = 1..n.
    #[must_use]
    pub fn omegas(&self) -> &[DVec3] {
        &self.omegas
    }

    /// Calls `f` with the factors `(ωᵢ, [B̃ᵢ,ₙ, B̃ᵢ,ₙ′, B̃ᵢ,ₙ″](t))`, i = 1..n, without heap
    /// allocation up to degree [`STACK_DEGREE`].
    fn with_factors<R>(&self, t: f64, f: impl FnOnce(&[Factor]) -> R) -> R {
        let n = self.rates.len();
        if n == 3 {
            let [b1, b2, b3] = cubic_bezier_basis(t, 1.0);
            return f(&[
                (self.rates[0], b1),
                (self.rates[1], b2),
                (self.rates[2], b3),
            ]);
        }
        let fill = |basis: &mut [[f64; 3]], scratch: &mut [f64], factors: &mut [Factor]| {
            cumulative_bernstein(t, basis, scratch);
            for (fa, (&r, &b)) in factors.iter_mut().zip(self.rates.iter().zip(basis.iter())) {
                *fa = (r, b);
            }
        };
        if n <= STACK_DEGREE {
            let mut basis = [[0.0; 3]; STACK_DEGREE];
            let mut scratch = [0.0; 3 * (STACK_DEGREE + 1)];
            let mut factors = [(Rate::new(DVec3::ZERO), [0.0; 3]); STACK_DEGREE];
            fill(
                &mut basis[..n],
                &mut scratch[..3 * (n + 1)],
                &mut factors[..n],
            );
            f(&factors[..n])
        } else {
            let mut basis = vec![[0.0; 3]; n];
            let mut scratch = vec![0.0; 3 * (n + 1)];
            let mut factors = vec![(Rate::new(DVec3::ZERO), [0.0; 3]); n];
            fill(&mut basis, &mut scratch, &mut factors);
            f(&factors)
        }
    }

    /// The exact control at the ends, the product elsewhere.
    fn point_at(&self, t: f64, p: DQuat) -> UnitQuat {
        if t == 0.0 {
            self.controls[0]
        } else if t == 1.0 {
            self.controls[self.controls.len() - 1]
        } else {
            UnitQuat::new_unchecked(p)
        }
    }
}

impl Curve for BezierKim {
    type Point = UnitQuat;

    fn domain(&self) -> [f64; 2] {
        [0.0, 1.0]
    }

    fn joints(&self) -> &[f64] {
        self.knots.as_slice()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        let (_, t) = self.knots.locate(t, side);
        let base = self.controls[0].as_dquat();
        let (p, velocity, acceleration) = self.with_factors(t, |f| cumulative_jet(base, f));
        Jet {
            point: self.point_at(t, p),
            velocity,
            acceleration,
        }
    }

    fn eval(&self, t: f64) -> UnitQuat {
        let (_, t) = self.knots.locate(t, Side::Right);
        let base = self.controls[0].as_dquat();
        let p = self.with_factors(t, |f| cumulative_point(base, f));
        self.point_at(t, p)
    }
}

/// Kim–Kim–Shin's uniform cubic B-spline quaternion curve in cumulative form, on S³.
///
/// For control quaternions `q₀ … qₙ` (n ≥ 3) the domain is `[0, n − 2]`. On piece
/// `[i, i + 1]` (i = 0..n − 3), with `s = t − i`:
///
/// ```text
/// q(t) = qᵢ · exp(ωᵢ₊₁ B̃₁(s)) · exp(ωᵢ₊₂ B̃₂(s)) · exp(ωᵢ₊₃ B̃₃(s)),   ωⱼ = log(qⱼ₋₁⁻¹ qⱼ)
/// B̃₁(s) = (5 + 3s − 3s² + s³)/6,  B̃₂(s) = (1 + 3s + 3s² − 2s³)/6,  B̃₃(s) = s³/6
/// ```
///
/// the cumulative sums of the uniform cubic B-spline basis. Because `B̃₁(1) = 1`,
/// `B̃₂(1) = B̃₁(0) = 5/6`, `B̃₃(1) = B̃₂(0) = 1/6` with matching first and second derivatives, and
/// `qᵢ exp(ωᵢ₊₁) = qᵢ₊₁`, neighbouring pieces agree to second order: the curve is **C²
/// everywhere**. It approximates the controls (it does not pass through them in general).
/// Derivatives are exact (product rule over the three factors). Controls are used as given (no
/// sign flips; see [`unflip`](crate::unflip)).
///
/// **Closed loops** ([`try_new_closed`](Self::try_new_closed)): the periodic control polygon
/// `q₀ … qₙ₋₁, q₀, q₁, q₂` (n ≥ 3) gives `n` pieces on `[0, n]`; the piece after the last would
/// start at `qₙ = q₀` with the factors of piece 0, so the loop is C² at the seam `t = n ≡ 0`
/// as everywhere else. Like the open curve it approximates the controls.
///
/// Source: Kim, Kim & Shin (1995), "A general construction scheme for unit quaternion curves with
/// simple high order derivatives", SIGGRAPH '95, doi:10.1145/218380.218486.
///
/// # Examples
///
/// ```
/// use spherekit::{glam::DVec3, Curve, BsplineKim, Manifold, Side, UnitQuat};
///
/// let q = |a: f64| UnitQuat::from_axis_angle(DVec3::Z, a).unwrap();
/// let c = BsplineKim::try_new(vec![q(0.0), q(0.4), q(1.0), q(1.2), q(2.0)]).unwrap();
/// assert_eq!(c.domain(), [0.0, 2.0]);
/// // C² at the joint t = 1.
/// let (l, r) = (c.jet_at(1.0, Side::Left), c.jet_at(1.0, Side::Right));
/// assert!(l.point.dist(&r.point) < 1e-15);
/// assert!((l.acceleration - r.acceleration).length() < 1e-13);
/// // On one rotation axis it is the scalar B-spline of the angles: at t = 0 the rotation angle
/// // is (0 + 4·0.4 + 1.0)/6.
/// assert!(c.eval(0.0).dist(&q(2.6 / 6.0)) < 1e-15);
/// ```
#[derive(Clone, Debug)]
pub struct BsplineKim {
    /// The controls; for a closed loop followed by the first three again.
    controls: Vec<UnitQuat>,
    omegas: Vec<DVec3>,
    rates: Vec<Rate>,
    knots: Knots,
    closed: bool,
}

impl BsplineKim {
    /// Builds the curve on `[0, n − 2]` from `n + 1 ≥ 4` controls.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 4 controls; [`SplineError::Antipodal`] when
    /// consecutive controls are antipodal.
    pub fn try_new(controls: Vec<UnitQuat>) -> Result<Self, SplineError> {
        if controls.len() < 4 {
            return Err(SplineError::TooFewPoints {
                min: 4,
                got: controls.len(),
            });
        }
        let omegas = chain_logs(&controls)?;
        let knots = Knots::uniform(controls.len() - 2);
        let rates = omegas.iter().copied().map(Rate::new).collect();
        Ok(Self {
            controls,
            omegas,
            rates,
            knots,
            closed: false,
        })
    }

    /// Builds the closed loop of the periodic control polygon `q₀ … qₙ₋₁` (n ≥ 3) on `[0, n]`
    /// (type docs).
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 3 controls; [`SplineError::Antipodal`] when
    /// consecutive controls are antipodal, [`SplineError::AntipodalClosing`] when the last and
    /// the first are.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, glam::DVec3, Curve, BsplineKim, UnitQuat};
    ///
    /// let q = |x: f64, y: f64| UnitQuat::from_axis_angle(DVec3::new(x, y, 1.0), 0.8).unwrap();
    /// let c = BsplineKim::try_new_closed(vec![q(1.0, 0.0), q(0.0, 1.0), q(-1.0, 0.0), q(0.0, -1.0)])
    ///     .unwrap();
    /// assert_eq!(c.domain(), [0.0, 4.0]);
    /// let seam = continuity(&c)[3];
    /// assert!(seam.t == 4.0 && seam.c0 < 1e-15 && seam.c1 < 1e-14 && seam.c2 < 1e-13);
    /// ```
    pub fn try_new_closed(controls: Vec<UnitQuat>) -> Result<Self, SplineError> {
        crate::geodesic::check_loop(&controls, 3)?;
        let n = controls.len();
        let mut cyclic = controls;
        cyclic.extend_from_within(..3);
        let omegas = chain_logs(&cyclic)?;
        let rates = omegas.iter().copied().map(Rate::new).collect();
        Ok(Self {
            controls: cyclic,
            omegas,
            rates,
            knots: Knots::uniform(n + 1),
            closed: true,
        })
    }

    /// The control quaternions `q₀ … qₙ` (for a closed loop the periodic polygon, without the
    /// repeated first three).
    #[must_use]
    pub fn controls(&self) -> &[UnitQuat] {
        &self.controls[..self.controls.len() - if self.closed { 3 } else { 0 }]
    }

    /// The body-frame logarithms `ωⱼ = log(qⱼ₋₁⁻¹ qⱼ)`, j = 1..n (for a closed loop every edge
    /// of the periodic polygon, the closing one last).
    #[must_use]
    pub fn omegas(&self) -> &[DVec3] {
        &self.omegas[..self.omegas.len() - if self.closed { 2 } else { 0 }]
    }
}

crate::curve::piecewise_curve! {
    impl for BsplineKim {
        type Point = UnitQuat;
    }
}

impl BsplineKim {
    fn jet_local(&self, i: usize, s: f64) -> Jet<UnitQuat> {
        let [b1, b2, b3] = cubic_bspline_basis(s);
        let factors = [
            (self.rates[i], b1),
            (self.rates[i + 1], b2),
            (self.rates[i + 2], b3),
        ];
        let (p, dq, ddq) = cumulative_jet(self.controls[i].as_dquat(), &factors);
        Jet {
            point: UnitQuat::new_unchecked(p),
            velocity: dq,
            acceleration: ddq,
        }
    }

    fn eval_local(&self, i: usize, s: f64) -> UnitQuat {
        let [b1, b2, b3] = cubic_bspline_basis(s);
        let factors = [
            (self.rates[i], b1),
            (self.rates[i + 1], b2),
            (self.rates[i + 2], b3),
        ];
        UnitQuat::new_unchecked(cumulative_point(self.controls[i].as_dquat(), &factors))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn binom(n: usize, k: usize) -> f64 {
        (0..k).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64)
    }

    fn pw(x: f64, k: usize) -> f64 {
        (0..k).fold(1.0, |a, _| a * x)
    }

    /// `B_{j,n}(t)`, zero for `j` outside `0..=n` (`None` stands for a negative index).
    fn bern(n: usize, j: Option<usize>, t: f64) -> f64 {
        match j {
            Some(j) if j <= n => binom(n, j) * pw(1.0 - t, n - j) * pw(t, j),
            _ => 0.0,
        }
    }

    #[test]
    fn cumulative_bernstein_matches_direct_sums() {
        for n in 1..=7 {
            for &t in &[0.0, 0.13, 0.5, 0.77, 1.0] {
                let mut out = vec![[0.0; 3]; n];
                let mut scratch = vec![0.0; 3 * (n + 1)];
                cumulative_bernstein(t, &mut out, &mut scratch);
                for i in 1..=n {
                    let cum: f64 = (i..=n).map(|j| bern(n, Some(j), t)).sum();
                    let d1 = n as f64 * bern(n - 1, i.checked_sub(1), t);
                    let d2 = if n >= 2 {
                        (n * (n - 1)) as f64
                            * (bern(n - 2, i.checked_sub(2), t) - bern(n - 2, i.checked_sub(1), t))
                    } else {
                        0.0
                    };
                    let got = out[i - 1];
                    assert!((got[0] - cum).abs() < 1e-14, "n={n} i={i} t={t}");
                    assert!((got[1] - d1).abs() < 1e-13, "n={n} i={i} t={t}");
                    assert!((got[2] - d2).abs() < 1e-12, "n={n} i={i} t={t}");
                }
                if n == 3 {
                    let c = cubic_bezier_basis(t, 1.0);
                    for i in 0..3 {
                        for k in 0..3 {
                            assert!((c[i][k] - out[i][k]).abs() < 1e-14, "cubic {i} {k}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn bspline_basis_derivatives() {
        let h = 1e-6;
        for &s in &[0.1, 0.5, 0.9] {
            let (m, p, c) = (
                cubic_bspline_basis(s - h),
                cubic_bspline_basis(s + h),
                cubic_bspline_basis(s),
            );
            for j in 0..3 {
                assert!(
                    ((p[j][0] - m[j][0]) / (2.0 * h) - c[j][1]).abs() < 1e-9,
                    "d1"
                );
                assert!(
                    ((p[j][1] - m[j][1]) / (2.0 * h) - c[j][2]).abs() < 1e-9,
                    "d2"
                );
            }
        }
    }

    #[test]
    fn body_log_is_accurate_for_close_points() {
        let a = UnitQuat::from_wxyz([0.3, -0.5, 0.7, 0.4]).unwrap();
        let w = DVec3::new(1e-10, -3e-10, 2e-10);
        let b = a * UnitQuat::exp_pure(w);
        let l = body_log(a, b).unwrap();
        assert!((l - w).length() < 1e-6 * w.length(), "{l:?} vs {w:?}");
    }
}
