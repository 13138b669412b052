// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Shoemake's squad (spherical quadrangle interpolation) of unit quaternions.

use glam::DVec4;

use crate::curve::Jet;
use crate::error::SplineError;
use crate::geodesic::{MIN_LOOP_POINTS, check_chain, check_loop, wrapped};
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
/// **Closed loops** ([`try_new_closed`](Self::try_new_closed)): keys `q₀ … qₙ₋₁` and knots
/// `t₀ … tₙ` (the last the time of the return to `q₀`); the keys wrap around, `q₋₁ = qₙ₋₁`,
/// `qₙ = q₀`, `h₋₁ = hₙ₋₁`, so every key, the first included, gets an inner point `sᵢ` by the
/// formula above and `sₙ = s₀`: the loop is C¹ at the seam as at the other keys.
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
    /// The keys, and for a closed loop the first one again at the end.
    keys: Vec<UnitQuat>,
    closed: bool,
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
            let (hm, hp) = (knots.width(i - 1), knots.width(i));
            inner.push(inner_point(keys[i - 1], keys[i], keys[i + 1], hm, hp));
        }
        inner.push(keys[n]);
        Self::build(keys, inner, knots, false)
    }

    /// Builds the closed loop through `keys = q₀ … qₙ₋₁` (n ≥ 3) with periodic neighbours
    /// (type docs); `knots` are `n + 1` times, the last the time of the return to `q₀`
    /// (default `0, 1, …, n`).
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 3 keys; [`SplineError::Antipodal`] for
    /// antipodal consecutive keys (or antipodal inner points, as [`try_new`](Self::try_new));
    /// [`SplineError::AntipodalClosing`] for an antipodal last and first key; the knot errors
    /// of [`Knots::or_uniform`] (`n + 1` knots).
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, Curve, Squad, UnitQuat};
    /// use spherekit::glam::DVec3;
    ///
    /// let q = |x: f64, y: f64| UnitQuat::from_axis_angle(DVec3::new(x, y, 1.0), 0.8).unwrap();
    /// let c = Squad::try_new_closed(vec![q(1.0, 0.0), q(0.0, 1.0), q(-1.0, 0.0), q(0.0, -1.0)], None)
    ///     .unwrap();
    /// assert_eq!(c.domain(), [0.0, 4.0]);
    /// assert_eq!(c.eval(4.0), q(1.0, 0.0));
    /// let seam = continuity(&c)[3];
    /// assert!(seam.t == 4.0 && seam.c0 < 1e-15 && seam.c1 < 1e-12);
    /// ```
    pub fn try_new_closed(
        keys: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
    ) -> Result<Self, SplineError> {
        check_loop(&keys, MIN_LOOP_POINTS)?;
        let n = keys.len();
        let knots = Knots::or_uniform(knots, n + 1)?;
        let mut inner: Vec<UnitQuat> = (0..n)
            .map(|i| {
                let prev = (i + n - 1) % n;
                let (hm, hp) = (knots.width(prev), knots.width(i));
                inner_point(keys[prev], keys[i], keys[(i + 1) % n], hm, hp)
            })
            .collect();
        inner.push(inner[0]);
        Self::build(wrapped(&keys), inner, knots, true)
    }

    /// The segments through `keys` (wrapped, for a loop) with the inner points `inner`.
    fn build(
        keys: Vec<UnitQuat>,
        inner: Vec<UnitQuat>,
        knots: Knots,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let n = keys.len() - 1;
        let segments = (0..n)
            .map(|i| {
                let arc = |a: UnitQuat, b: UnitQuat| {
                    FixedArc::try_new(a.to_vector(), b.to_vector()).ok_or(if closed && i + 1 == n {
                        SplineError::AntipodalClosing
                    } else {
                        SplineError::Antipodal { index: i }
                    })
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
            closed,
            inner,
            knots,
            segments,
        })
    }

    /// The keys `q₀ … qₙ` (for a closed loop without the repeated first one).
    #[must_use]
    pub fn keys(&self) -> &[UnitQuat] {
        &self.keys[..self.keys.len() - usize::from(self.closed)]
    }

    /// The inner control points `s₀ … sₙ` (open: `s₀ = q₀`, `sₙ = qₙ`; closed: one per segment
    /// end, `sₙ = s₀`).
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

crate::curve::piecewise_curve! {
    impl for Squad {
        type Point = UnitQuat;
    }
}

/// `sᵢ = qᵢ·exp(Mᵢ)`, `Mᵢ = −(hᵢ₋₁·L⁺ᵢ + hᵢ·L⁻ᵢ) / (2(hᵢ₋₁ + hᵢ))` for the key `q = qᵢ` between
/// `prev = qᵢ₋₁` and `next = qᵢ₊₁`, `hm = hᵢ₋₁`, `hp = hᵢ`.
fn inner_point(prev: UnitQuat, q: UnitQuat, next: UnitQuat, hm: f64, hp: f64) -> UnitQuat {
    let qc = q.conjugate();
    let lp = (qc * next).log_pure();
    let lm = (qc * prev).log_pure();
    let m = (lp * hm + lm * hp) * (-0.5 / (hm + hp));
    q * UnitQuat::exp_pure(m)
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
