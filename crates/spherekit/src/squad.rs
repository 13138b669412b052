// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Shoemake's squad (spherical quadrangle interpolation) of unit quaternions.

use glam::DVec4;

use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::geodesic::check_chain;
use crate::knots::Knots;
use crate::manifold::{Manifold, renormalize};
use crate::s3::UnitQuat;
use crate::slerp_jet::{FixedArc, ScalarJet, slerp_jet_vec, slerp_point};

/// Squad through keys `q₀ … qₙ` (n ≥ 1) of S³ at knots `t₀ < … < tₙ` (default `0, 1, …, n`);
/// Shoemake (1987), "Quaternion calculus and fast animation" (see `docs/references.md`).
///
/// With `hᵢ = tᵢ₊₁ − tᵢ`, `L±ᵢ = log(qᵢ⁻¹·qᵢ±₁)` (body-frame logarithms, no half-angle factor):
///
/// ```text
/// sᵢ = qᵢ·exp(Mᵢ),  Mᵢ = −(hᵢ₋₁·L⁺ᵢ + hᵢ·L⁻ᵢ) / (2(hᵢ₋₁ + hᵢ)),   i = 1‥n−1
/// s₀ = q₀,  sₙ = qₙ
/// on [tᵢ, tᵢ₊₁], τ = (t − tᵢ)/hᵢ:
/// c(t) = G[ G[qᵢ, qᵢ₊₁](τ), G[sᵢ, sᵢ₊₁](τ) ]( 2τ(1 − τ) )
/// ```
///
/// For uniform knots `Mᵢ = −(L⁺ᵢ + L⁻ᵢ)/4`, Shoemake's formula. **Non-uniform knots** (our
/// derivation): `d/dτ G[A, B](h) = A′ + A·log(A⁻¹B)·h′` with `h′ = ±2` at the ends gives the
/// one-sided velocities at `tᵢ`, in `t`,
///
/// ```text
/// right: qᵢ(L⁺ᵢ + 2Mᵢ)/hᵢ        left: qᵢ(−L⁻ᵢ − 2Mᵢ)/hᵢ₋₁
/// ```
///
/// and equating them determines `Mᵢ` as above; the common velocity is the central difference
/// `c′(tᵢ) = qᵢ·(L⁺ᵢ − L⁻ᵢ)/(hᵢ₋₁ + hᵢ)`. So the curve is **C¹ in t** for any knots (not C² in
/// general). It interpolates, `c(tᵢ) = qᵢ`, is unit, and the end velocities are
/// `q₀·L⁺₀/h₀` and `−qₙ·L⁻ₙ/hₙ₋₁` (the first and last inner points equal the keys,
/// `docs/derivations.md#squad`).
/// If all keys lie on one great circle `qᵢ = q₀·exp(αᵢ·v)` the curve stays on it and its angle
/// is the scalar squad of the `αᵢ` with inner values `σᵢ = αᵢ + Mᵢ·v` (uniform:
/// `αᵢ − (αᵢ₋₁ − 2αᵢ + αᵢ₊₁)/4`).
///
/// Keys are used as given, with no sign flips anywhere: canonicalise with
/// [`unflip`](crate::unflip) first for shortest rotations (the scene format does).
///
/// # Examples
///
/// ```
/// use spherekit::{continuity, Curve, Manifold, Squad, UnitQuat};
/// use spherekit::glam::DVec3;
///
/// let keys: Vec<UnitQuat> = [0.0, 0.8, 1.1, 2.0]
///     .iter()
///     .enumerate()
///     .map(|(i, &a)| UnitQuat::from_axis_angle(DVec3::new(1.0, i as f64, 0.5), a).unwrap())
///     .collect();
/// let c = Squad::try_new(keys.clone(), Some(vec![0.0, 1.0, 3.0, 3.5])).unwrap();
/// assert_eq!(c.eval(3.0), keys[2]);
/// assert!(continuity(&c).iter().all(|j| j.c0 < 1e-15 && j.c1 < 1e-12));
/// assert_eq!(c.controls()[0], keys[0]);
/// ```
#[derive(Clone, Debug)]
pub struct Squad {
    keys: Vec<UnitQuat>,
    inner: Vec<UnitQuat>,
    knots: Knots,
    /// Per segment: the arcs qᵢ → qᵢ₊₁ and sᵢ → sᵢ₊₁ and `1/hᵢ`.
    segments: Vec<SquadSegment>,
}

#[derive(Clone, Debug)]
struct SquadSegment {
    keys: FixedArc<DVec4>,
    inner: FixedArc<DVec4>,
    rate: f64,
}

impl Squad {
    /// Builds the curve; `knots` (one per key) default to `0, 1, …, n`.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 2 keys; [`SplineError::Antipodal`] for
    /// antipodal consecutive keys, or (index `i`) when the derived inner points `sᵢ`, `sᵢ₊₁` are
    /// antipodal (possible only for keys that are not canonicalised); the knot errors of
    /// [`Knots::or_uniform`].
    pub fn try_new(keys: Vec<UnitQuat>, knots: Option<Vec<f64>>) -> Result<Self, SplineError> {
        check_chain(&keys, 2)?;
        let knots = Knots::or_uniform(knots, keys.len())?;
        let n = keys.len() - 1;
        let mut inner = Vec::with_capacity(n + 1);
        inner.push(keys[0]);
        for i in 1..n {
            let q = keys[i];
            let qc = q.conjugate();
            let lp = qc.mul(keys[i + 1]).log();
            let lm = qc.mul(keys[i - 1]).log();
            let (hm, hp) = (knots.width(i - 1), knots.width(i));
            let m = (lp * hm + lm * hp) * (-0.5 / (hm + hp));
            inner.push(q.mul(UnitQuat::exp(m)));
        }
        inner.push(keys[n]);
        let segments = (0..n)
            .map(|i| {
                let arc = |a: UnitQuat, b: UnitQuat| {
                    FixedArc::try_new(a.to_vector(), b.to_vector())
                        .ok_or(SplineError::Antipodal { index: i })
                };
                Ok(SquadSegment {
                    keys: arc(keys[i], keys[i + 1])?,
                    inner: arc(inner[i], inner[i + 1])?,
                    rate: 1.0 / knots.width(i),
                })
            })
            .collect::<Result<_, SplineError>>()?;
        Ok(Self {
            keys,
            inner,
            knots,
            segments,
        })
    }

    /// The keys `q₀ … qₙ`.
    #[must_use]
    pub fn keys(&self) -> &[UnitQuat] {
        &self.keys
    }

    /// The inner control points `s₀ … sₙ` (`s₀ = q₀`, `sₙ = qₙ`).
    #[must_use]
    pub fn controls(&self) -> &[UnitQuat] {
        &self.inner
    }

    /// The knots.
    #[must_use]
    pub fn knots(&self) -> &Knots {
        &self.knots
    }
}

impl Curve for Squad {
    type Point = UnitQuat;

    fn domain(&self) -> [f64; 2] {
        self.knots.domain()
    }

    fn joints(&self) -> &[f64] {
        self.knots.as_slice()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        let (i, tau) = self.knots.locate(t, side);
        self.jet_local(i, tau)
    }

    fn eval(&self, t: f64) -> UnitQuat {
        let (i, tau) = self.knots.locate(t, Side::Right);
        self.eval_local(i, tau)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.eval_local(i, s));
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        self.knots
            .map_into(ts, Side::Right, out, |i, s| self.jet_local(i, s));
    }
}

impl Squad {
    fn jet_local(&self, i: usize, tau: f64) -> Jet<UnitQuat> {
        let seg = &self.segments[i];
        let u = ScalarJet::param(tau, seg.rate);
        let a = seg.keys.jet(u);
        let b = seg.inner.jet(u);
        let h = ScalarJet {
            value: 2.0 * tau * (1.0 - tau),
            first: (2.0 - 4.0 * tau) * seg.rate,
            second: -4.0 * seg.rate * seg.rate,
        };
        let mut j = slerp_jet_vec(&a, &b, h).unwrap_or(a);
        if tau == 0.0 {
            j.v = self.keys[i].to_vector();
        } else if tau == 1.0 {
            j.v = self.keys[i + 1].to_vector();
        }
        j.into_jet()
    }

    fn eval_local(&self, i: usize, tau: f64) -> UnitQuat {
        if tau == 0.0 {
            return self.keys[i];
        }
        if tau == 1.0 {
            return self.keys[i + 1];
        }
        let seg = &self.segments[i];
        let a = seg.keys.point_unnormalized(tau);
        let b = seg.inner.point_unnormalized(tau);
        let p = slerp_point(a, b, 2.0 * tau * (1.0 - tau)).unwrap_or_else(|| renormalize(a));
        UnitQuat::from_vector_unchecked(p)
    }
}
