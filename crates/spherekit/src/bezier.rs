// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Spherical Bézier curves of any degree, evaluated by de Casteljau with geodesic interpolation.

use crate::ambient::Ambient;
use crate::curve::{Curve, Jet, Side, clamp_param};
use crate::error::SplineError;
use crate::geodesic::check_chain;
use crate::manifold::{Manifold, renormalize};
use crate::slerp_jet::{FixedArc, ScalarJet, VJet, slerp_jet_vec, slerp_point};

/// A spherical Bézier curve of degree `n ≥ 1` on any sphere, by de Casteljau's algorithm with
/// geodesic interpolation (Shoemake 1985; in this form also Yang et al. 2021, eqs. (2)–(3)).
///
/// With control points `p₀ … pₙ` and `G[p, q](s)` the slerp (no sign flips):
///
/// ```text
/// pᵢ⁰(t) = pᵢ
/// pᵢᵏ(t) = G[pᵢᵏ⁻¹(t), pᵢ₊₁ᵏ⁻¹(t)](t)      k = 1‥n, i = 0‥n−k
/// Q(t)   = p₀ⁿ(t),  t ∈ [0, 1]
/// ```
///
/// Properties: `Q(0) = p₀`, `Q(1) = pₙ`, `Q′(0) = n·log_{p₀}(p₁)`, `Q′(1) = −n·log_{pₙ}(pₙ₋₁)`;
/// degree 1 is the slerp ([`GeodesicSpline`](crate::GeodesicSpline) on two points); reversing
/// the control points reverses the curve; it commutes with every orthogonal map; on one great
/// circle the angle is the Euclidean Bézier function of the control angles. The curve is
/// analytic on `[0, 1]`. The derivatives are exact: each slerp of the pyramid is differentiated
/// with [`slerp_jet`](crate::slerp_jet), with its moving endpoints. A cubic costs 6 slerps.
///
/// On S³ the keys are used as given (canonicalise with [`unflip`](crate::unflip) for shortest
/// rotations); the curve differs from Kim's cumulative-basis quaternion Bézier curve for `n ≥ 2`.
///
/// Intermediate points of the pyramid can in principle become exactly antipodal for special
/// control polygons even when consecutive control points are not; there (a set of measure zero)
/// the slerp falls back to its first point, so no NaN is produced.
///
/// # Examples
///
/// ```
/// use spherekit::{Bezier, Curve, Manifold, S2Point};
///
/// let c = Bezier::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z]).unwrap();
/// assert_eq!(c.eval(0.0), S2Point::X);
/// assert_eq!(c.eval(1.0), S2Point::Z);
/// // End tangent: degree × the log of the first leg (here 2 · π/2 towards y).
/// let v = c.jet(0.0).velocity;
/// assert!((v - spherekit::glam::DVec3::Y * core::f64::consts::PI).length() < 1e-14);
/// assert!(Bezier::try_new(vec![S2Point::X]).is_err());
/// ```
#[derive(Clone, Debug)]
pub struct Bezier<P: Manifold> {
    ctrl: Vec<P>,
    joints: [f64; 2],
    /// The first de Casteljau level's fixed arcs `G[pᵢ, pᵢ₊₁]`, frames precomputed (`None`
    /// where the frame does not exist; the slerp then falls back to `pᵢ`, as `try_slerp` does).
    first: Vec<Option<FixedArc<P::Vector>>>,
}

impl<P: Manifold> Bezier<P> {
    /// Builds the curve from its `n + 1` control points (degree `n`).
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 2 points, [`SplineError::Antipodal`] if two
    /// consecutive control points are antipodal.
    pub fn try_new(ctrl: Vec<P>) -> Result<Self, SplineError> {
        check_chain(&ctrl, 2)?;
        let first = ctrl
            .windows(2)
            .map(|w| FixedArc::try_new(w[0].to_vector(), w[1].to_vector()))
            .collect();
        Ok(Self {
            ctrl,
            joints: [0.0, 1.0],
            first,
        })
    }

    /// The control points.
    #[must_use]
    pub fn controls(&self) -> &[P] {
        &self.ctrl
    }

    /// The degree `n` (number of control points − 1).
    #[must_use]
    pub fn degree(&self) -> usize {
        self.ctrl.len() - 1
    }
}

impl<P: Manifold> Curve for Bezier<P> {
    type Point = P;

    fn domain(&self) -> [f64; 2] {
        [0.0, 1.0]
    }

    fn joints(&self) -> &[f64] {
        &self.joints
    }

    fn jet_at(&self, t: f64, _side: Side) -> Jet<P> {
        let t = clamp_param(t, [0.0, 1.0]);
        self.jet_in(ScalarJet::param(t, 1.0), &mut Vec::new())
    }

    fn eval(&self, t: f64) -> P {
        self.eval_in(clamp_param(t, [0.0, 1.0]), &mut Vec::new())
    }

    /// One scratch buffer per batch (the de Casteljau levels), none per sample.
    fn eval_many(&self, ts: &[f64], out: &mut [P]) {
        crate::knots::check_batch(ts, out);
        let mut level = Vec::with_capacity(self.ctrl.len());
        for (&t, o) in ts.iter().zip(out) {
            *o = self.eval_in(clamp_param(t, [0.0, 1.0]), &mut level);
        }
    }

    /// One scratch buffer per batch (the de Casteljau levels), none per sample.
    fn jet_many(&self, ts: &[f64], out: &mut [Jet<P>]) {
        crate::knots::check_batch(ts, out);
        let mut level = Vec::with_capacity(self.ctrl.len());
        for (&t, o) in ts.iter().zip(out) {
            let t = clamp_param(t, [0.0, 1.0]);
            *o = self.jet_in(ScalarJet::param(t, 1.0), &mut level);
        }
    }
}

impl<P: Manifold> Bezier<P> {
    /// [`de_casteljau`] with the first level from the precomputed arcs: the same operations,
    /// bit for bit (`FixedArc::point` is `try_slerp` with its frame computed once).
    fn eval_in(&self, s: f64, level: &mut Vec<P>) -> P {
        let ctrl = &self.ctrl;
        if s == 0.0 {
            return ctrl[0].clone();
        }
        if s == 1.0 {
            return ctrl[ctrl.len() - 1].clone();
        }
        level.clear();
        level.extend(self.first.iter().zip(ctrl).map(|(arc, p)| match arc {
            Some(arc) => P::from_vector_unchecked(arc.point(s)),
            None => p.clone(),
        }));
        pyramid(level, s)
    }

    /// [`de_casteljau_jet`] with the first level from the precomputed arcs (bit for bit).
    fn jet_in(&self, s: ScalarJet, level: &mut Vec<VJet<P::Vector>>) -> Jet<P> {
        level.clear();
        level.extend(self.first.iter().zip(&self.ctrl).map(|(arc, p)| match arc {
            Some(arc) => arc.jet(s),
            None => VJet::constant(p.to_vector()),
        }));
        pyramid_jet(&self.ctrl, s, level)
    }
}

/// The point `Q[p₀ … pₙ](s)` of the spherical Bézier curve with control points `ctrl` (de
/// Casteljau with slerps, see [`Bezier`]). Exact at `s = 0` and `s = 1`.
///
/// # Panics
///
/// If `ctrl` is empty.
#[must_use]
pub fn de_casteljau<P: Manifold>(ctrl: &[P], s: f64) -> P {
    de_casteljau_in(ctrl, s, &mut Vec::new())
}

/// [`de_casteljau`] with the levels in a caller's scratch buffer (batch evaluation reuses it).
fn de_casteljau_in<P: Manifold>(ctrl: &[P], s: f64, level: &mut Vec<P>) -> P {
    assert!(!ctrl.is_empty(), "de Casteljau needs a control point");
    if s == 0.0 {
        return ctrl[0].clone();
    }
    if s == 1.0 {
        return ctrl[ctrl.len() - 1].clone();
    }
    level.clear();
    level.extend_from_slice(ctrl);
    pyramid(level, s)
}

/// The remaining de Casteljau levels from `level` (overwritten), `0 < s < 1`.
fn pyramid<P: Manifold>(level: &mut [P], s: f64) -> P {
    for n in (1..level.len()).rev() {
        for i in 0..n {
            let next = level[i]
                .try_slerp(&level[i + 1], s)
                .unwrap_or_else(|_| level[i].clone());
            level[i] = next;
        }
    }
    level[0].clone()
}

/// The point and exact first and second derivatives of the spherical Bézier curve with control
/// points `ctrl` at the parameter jet `s` (use [`ScalarJet::param`]`(τ, 1/h)` for a segment of
/// width `h` in a global parameter, so that derivatives are with respect to that parameter).
///
/// Cost: `n(n+1)/2` differentiated slerps ([`slerp_jet`](crate::slerp_jet)); a cubic takes 6.
///
/// # Panics
///
/// If `ctrl` is empty.
#[must_use]
pub fn de_casteljau_jet<P: Manifold>(ctrl: &[P], s: ScalarJet) -> Jet<P> {
    de_casteljau_jet_in(ctrl, s, &mut Vec::new())
}

/// [`de_casteljau_jet`] with the levels in a caller's scratch buffer.
fn de_casteljau_jet_in<P: Manifold>(
    ctrl: &[P],
    s: ScalarJet,
    level: &mut Vec<VJet<P::Vector>>,
) -> Jet<P> {
    assert!(!ctrl.is_empty(), "de Casteljau needs a control point");
    // The first level has fixed endpoints: plain arcs.
    level.clear();
    if ctrl.len() == 1 {
        level.push(VJet::constant(ctrl[0].to_vector()));
    } else {
        level.extend(ctrl.windows(2).map(|w| first_level(&w[0], &w[1], s)));
    }
    pyramid_jet(ctrl, s, level)
}

/// The remaining levels of [`de_casteljau_jet`] from the first (in `level`, overwritten).
fn pyramid_jet<P: Manifold>(ctrl: &[P], s: ScalarJet, level: &mut [VJet<P::Vector>]) -> Jet<P> {
    for n in (1..ctrl.len().saturating_sub(1)).rev() {
        for i in 0..n {
            let next =
                slerp_jet_vec(&level[i], &level[i + 1], s).unwrap_or_else(|| level[i].clone());
            level[i] = next;
        }
    }
    let mut top = level[0].clone();
    if s.value == 0.0 {
        top.v = ctrl[0].to_vector();
    } else if s.value == 1.0 {
        top.v = ctrl[ctrl.len() - 1].to_vector();
    }
    top.into_jet()
}

/// The jet of `G[p, q](s)` for fixed `p`, `q` (an arc; antipodal points fall back to `p`).
fn first_level<P: Manifold>(p: &P, q: &P, s: ScalarJet) -> VJet<P::Vector> {
    match FixedArc::try_new(p.to_vector(), q.to_vector()) {
        Some(arc) => arc.jet(s),
        None => VJet::constant(p.to_vector()),
    }
}

/// [`de_casteljau_jet`] for a cubic, without heap allocation: the jet of `Q[p₀, p₁, p₂, p₃](s)`.
#[must_use]
pub fn cubic_jet<P: Manifold>(ctrl: [&P; 4], s: ScalarJet) -> Jet<P> {
    let sl = |a: &VJet<P::Vector>, b: &VJet<P::Vector>| {
        slerp_jet_vec(a, b, s).unwrap_or_else(|| a.clone())
    };
    let f = first_level(ctrl[0], ctrl[1], s);
    let g = first_level(ctrl[1], ctrl[2], s);
    let h = first_level(ctrl[2], ctrl[3], s);
    let m = sl(&f, &g);
    let n = sl(&g, &h);
    let mut top = sl(&m, &n);
    if s.value == 0.0 {
        top.v = ctrl[0].to_vector();
    } else if s.value == 1.0 {
        top.v = ctrl[3].to_vector();
    }
    debug_assert!(top.v.is_finite(), "non-finite cubic jet");
    top.into_jet()
}

/// One cubic spherical Bézier segment `Q[p₀, p₁, p₂, p₃]` with the three fixed arcs of its
/// first de Casteljau level precomputed: the building block of piecewise-cubic constructions
/// ([`CatmullRom`](crate::CatmullRom), Beta splines). Same curve as [`Bezier`] of degree 3.
///
/// # Examples
///
/// ```
/// use spherekit::{Bezier, Curve, CubicSegment, Manifold, S2Point, ScalarJet};
///
/// let p = [S2Point::X, S2Point::Y, S2Point::Z, S2Point::X];
/// let seg = CubicSegment::try_new(p).unwrap();
/// let whole = Bezier::try_new(p.to_vec()).unwrap();
/// assert!(seg.eval(0.3).dist(&whole.eval(0.3)) < 1e-15);
/// // Derivatives with respect to a global parameter t = 2 + 0.5·s (segment width 0.5):
/// let j = seg.jet(ScalarJet::param(0.3, 2.0));
/// assert!((j.velocity - whole.jet(0.3).velocity * 2.0).length() < 1e-14);
/// ```
#[derive(Clone, Debug)]
pub struct CubicSegment<P: Manifold> {
    ctrl: [P; 4],
    arcs: [FixedArc<P::Vector>; 3],
}

#[cfg(any(test, feature = "compact"))]
impl CubicSegment<crate::SmPoint> {
    /// The same segment on the point type `Q` ([`crate::recast`]).
    pub(crate) fn recast<Q: Manifold>(&self, to: &crate::recast::Recast<Q>) -> CubicSegment<Q> {
        CubicSegment {
            ctrl: self.ctrl.each_ref().map(|p| to.point(p)),
            arcs: self.arcs.each_ref().map(|a| a.recast(to)),
        }
    }
}

impl<P: Manifold> CubicSegment<P> {
    /// Precomputes the segment.
    ///
    /// # Errors
    ///
    /// [`SplineError::Antipodal`] with the index (0, 1 or 2) of the first of two antipodal
    /// consecutive control points.
    pub fn try_new(ctrl: [P; 4]) -> Result<Self, SplineError> {
        let arc = |i: usize| {
            FixedArc::try_new(ctrl[i].to_vector(), ctrl[i + 1].to_vector())
                .ok_or(SplineError::Antipodal { index: i })
        };
        let arcs = [arc(0)?, arc(1)?, arc(2)?];
        Ok(Self { ctrl, arcs })
    }

    /// The control points.
    #[must_use]
    pub fn controls(&self) -> &[P; 4] {
        &self.ctrl
    }

    /// The point at `s ∈ [0, 1]` (6 slerps, 3 of them with precomputed frames).
    #[must_use]
    pub fn eval(&self, s: f64) -> P {
        if s == 0.0 {
            return self.ctrl[0].clone();
        }
        if s == 1.0 {
            return self.ctrl[3].clone();
        }
        let [f, g, h] = [0, 1, 2].map(|i| self.arcs[i].point_unnormalized(s));
        let sl = |a: &P::Vector, b: &P::Vector| {
            slerp_point(a.clone(), b.clone(), s).unwrap_or_else(|| renormalize(a.clone()))
        };
        let m = sl(&f, &g);
        let n = sl(&g, &h);
        P::from_vector_unchecked(sl(&m, &n))
    }

    /// The point and exact derivatives at the parameter jet `s` (see [`de_casteljau_jet`]).
    #[must_use]
    pub fn jet(&self, s: ScalarJet) -> Jet<P> {
        let [f, g, h] = [0, 1, 2].map(|i| self.arcs[i].jet(s));
        let sl = |a: &VJet<P::Vector>, b: &VJet<P::Vector>| {
            slerp_jet_vec(a, b, s).unwrap_or_else(|| a.clone())
        };
        let m = sl(&f, &g);
        let n = sl(&g, &h);
        let mut top = sl(&m, &n);
        if s.value == 0.0 {
            top.v = self.ctrl[0].to_vector();
        } else if s.value == 1.0 {
            top.v = self.ctrl[3].to_vector();
        }
        top.into_jet()
    }
}
