// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! One-parameter rotation groups acting on a sphere, and the blended segment
//! `G_outer(α(u))·G_inner(β(u))·x` shared by the arc-blend and corner-blend curves.

use glam::{DQuat, DVec3, DVec4};

use crate::ambient::Ambient;
use crate::math;
use crate::smoothing::SmoothingPolynomials;

/// A one-parameter group `θ ↦ G(θ) = exp(θK)` of rotations of the ambient space.
pub(crate) trait Flow<V>: Clone + core::fmt::Debug {
    /// `G(θ)·x` given `c = cos θ`, `s = sin θ`.
    fn apply_cs(&self, c: f64, s: f64, x: &V) -> V;
    /// The generator `K·x`, so that `d/dθ G(θ)x = K·G(θ)x`.
    fn generator(&self, x: &V) -> V;
    /// `G(θ)·x`.
    fn apply(&self, theta: f64, x: &V) -> V {
        let (s, c) = math::sin_cos(theta);
        self.apply_cs(c, s, x)
    }
}

/// The simple rotation of ℝ^d in the plane spanned by the orthonormal `a`, `b` (taking `a` towards
/// `b`), fixing the orthogonal complement:
///
/// ```text
/// G(θ)x = x + (cos θ − 1)·((x·a)a + (x·b)b) + sin θ·((x·a)b − (x·b)a),   K x = (x·a)b − (x·b)a
/// ```
///
/// On ℝ³ it is the rotation `R(a × b, θ)` (Pobegailo (2019), §3.3–3.4); on ℝ⁴ it is the simple
/// rotation in the plane `span{a, b}`, a one-parameter subgroup of SO(4) whose orbits include
/// every circle of S³ in a plane parallel to `span{a, b}` (`docs/derivations.md#pobegailo-9-2`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PlaneRotation<V> {
    pub(crate) a: V,
    pub(crate) b: V,
}

impl<V: Ambient> Flow<V> for PlaneRotation<V> {
    #[inline]
    fn apply_cs(&self, c: f64, s: f64, x: &V) -> V {
        let xa = x.dot(&self.a);
        let xb = x.dot(&self.b);
        let cm = c - 1.0;
        x.clone() + self.a.clone() * (cm * xa - s * xb) + self.b.clone() * (cm * xb + s * xa)
    }

    #[inline]
    fn generator(&self, x: &V) -> V {
        self.b.clone() * x.dot(&self.a) - self.a.clone() * x.dot(&self.b)
    }
}

#[cfg(any(test, feature = "compact"))]
impl<V: Ambient> PlaneRotation<V> {
    /// The same rotation in the ambient space of `Q` (the `compact` build's construction on S^m,
    /// [`crate::recast`]).
    pub(crate) fn recast<Q: crate::Manifold>(
        &self,
        to: &crate::recast::Recast<Q>,
    ) -> PlaneRotation<Q::Vector> {
        PlaneRotation {
            a: to.vector(&self.a),
            b: to.vector(&self.b),
        }
    }
}

#[cfg(any(test, feature = "compact"))]
impl<V: Ambient> Segment<V, PlaneRotation<V>> {
    /// The same segment in the ambient space of `Q` ([`crate::recast`]).
    pub(crate) fn recast<Q: crate::Manifold>(
        &self,
        to: &crate::recast::Recast<Q>,
    ) -> Segment<Q::Vector, PlaneRotation<Q::Vector>> {
        Segment {
            base: to.vector(&self.base),
            outer: self.outer.recast(to),
            outer_angle: self.outer_angle,
            inner: self.inner.as_ref().map(|(f, angle)| (f.recast(to), *angle)),
            weights: self.weights,
            width: self.width,
        }
    }
}

/// Left multiplication of unit quaternions by `e_n(θ) = cos θ + sin θ·n` (unit axis `n`): the
/// rotation `Rot(n, 2θ)` applied to an orientation in the base frame. `θ` is the angle on S³.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct LeftMultiplication {
    pub(crate) axis: DVec3,
}

impl Flow<DVec4> for LeftMultiplication {
    #[inline]
    fn apply_cs(&self, c: f64, s: f64, x: &DVec4) -> DVec4 {
        *x * c + self.generator(x) * s
    }

    #[inline]
    fn generator(&self, x: &DVec4) -> DVec4 {
        let n = DQuat::from_xyzw(self.axis.x, self.axis.y, self.axis.z, 0.0);
        DVec4::from(n * DQuat::from_vec4(*x))
    }
}

/// How the two rotation angles of a segment depend on the local parameter `u ∈ [0, 1]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Weights {
    /// `α = u·outer`, no inner rotation: a plain arc at constant angular speed.
    Linear,
    /// `α = w₁,ₙ(u)·outer`, `β = w₂,ₙ(u)·inner` (arc blend, eq. 8.10 / 9.12).
    ArcBlend,
    /// `α = w₁,ₙ(u)·outer`, `β = −w₁,ₙ(1 − u)·inner` (corner blend, eq. 8.19 / 9.18).
    Corner,
}

/// One piece `x(u) = G_outer(α(u))·G_inner(β(u))·base` on the knot interval `[t0, t0 + width]`.
#[derive(Clone, Debug)]
pub(crate) struct Segment<V, F> {
    pub(crate) base: V,
    pub(crate) outer: F,
    pub(crate) outer_angle: f64,
    pub(crate) inner: Option<(F, f64)>,
    pub(crate) weights: Weights,
    pub(crate) width: f64,
}

impl<V: Ambient, F: Flow<V>> Segment<V, F> {
    /// `(α, α′, α″)` and `(β, β′, β″)` with respect to `u`.
    #[inline]
    fn angles(&self, poly: SmoothingPolynomials, u: f64) -> ([f64; 3], [f64; 3]) {
        let a = self.outer_angle;
        let b = self.inner.as_ref().map_or(0.0, |i| i.1);
        match self.weights {
            Weights::Linear => ([a * u, a, 0.0], [0.0; 3]),
            Weights::ArcBlend => {
                let (w1, w2) = poly.jets(u);
                (
                    [a * w1[0], a * w1[1], a * w1[2]],
                    [b * w2[0], b * w2[1], b * w2[2]],
                )
            }
            Weights::Corner => {
                let (w1, _) = poly.jets(u);
                let (v1, _) = poly.jets(1.0 - u);
                (
                    [a * w1[0], a * w1[1], a * w1[2]],
                    [-b * v1[0], b * v1[1], -b * v1[2]],
                )
            }
        }
    }

    /// The `k`-th `u`-derivatives of the outer and inner angles, any `k`.
    fn angle_derivatives(&self, poly: SmoothingPolynomials, u: f64, k: usize) -> (f64, f64) {
        let a = self.outer_angle;
        let b = self.inner.as_ref().map_or(0.0, |i| i.1);
        match self.weights {
            Weights::Linear => (
                match k {
                    0 => a * u,
                    1 => a,
                    _ => 0.0,
                },
                0.0,
            ),
            Weights::ArcBlend => (a * poly.w1_derivative(u, k), b * poly.w2_derivative(u, k)),
            Weights::Corner => {
                // d^k/du^k [−w₁(1 − u)] = −(−1)^k w₁^{(k)}(1 − u).
                let sign = if k.is_multiple_of(2) { -1.0 } else { 1.0 };
                (
                    a * poly.w1_derivative(u, k),
                    sign * b * poly.w1_derivative(1.0 - u, k),
                )
            }
        }
    }

    /// The point and its first two derivatives with respect to the global parameter.
    ///
    /// With `y = G_inner(β)·base`, `A = G_outer(α)`, `S = A·y`:
    ///
    /// ```text
    /// y′ = β′·K_in y,   y″ = β″·K_in y + β′²·K_in² y
    /// S′ = α′·K_out S + A y′
    /// S″ = α″·K_out S + α′·K_out S′ + α′·K_out (A y′) + A y″
    /// ```
    ///
    /// (`K_out` commutes with `A`, which belongs to its group), then `d/dt = d/du / width`.
    pub(crate) fn jet(&self, poly: SmoothingPolynomials, u: f64) -> (V, V, V) {
        let (al, be) = self.angles(poly, u);
        let (s, c) = math::sin_cos(al[0]);
        let k = 1.0 / self.width;
        match &self.inner {
            None => {
                let p = self.outer.apply_cs(c, s, &self.base);
                let kp = self.outer.generator(&p);
                let d1 = kp.clone() * al[1];
                let d2 = kp * al[2] + self.outer.generator(&d1) * al[1];
                (p, d1 * k, d2 * (k * k))
            }
            Some((inner, _)) => {
                let (sb, cb) = math::sin_cos(be[0]);
                let y = inner.apply_cs(cb, sb, &self.base);
                let ky = inner.generator(&y);
                let k2y = inner.generator(&ky);
                let dy = ky.clone() * be[1];
                let ddy = ky * be[2] + k2y * (be[1] * be[1]);
                let p = self.outer.apply_cs(c, s, &y);
                let z1 = self.outer.apply_cs(c, s, &dy);
                let z2 = self.outer.apply_cs(c, s, &ddy);
                let kp = self.outer.generator(&p);
                let d1 = kp * al[1] + z1.clone();
                let d2 = self.outer.generator(&self.base_free(&p, &d1, &z1, al)) + z2;
                (p, d1 * k, d2 * (k * k))
            }
        }
    }

    /// `α″·S + α′·S′ + α′·A y′`, to which `K_out` is applied once (it is linear).
    #[inline]
    fn base_free(&self, p: &V, d1: &V, z1: &V, al: [f64; 3]) -> V {
        p.clone() * al[2] + (d1.clone() + z1.clone()) * al[1]
    }

    /// The derivatives of orders `0…=order` with respect to the global parameter, exactly, by
    /// truncated Taylor series: with `G(θ) = I + (cos θ − 1)·P + sin θ·K` and `P = −K²`, the
    /// series of `cos α(u)`, `sin α(u)` follow from `s′ = c·α′`, `c′ = −s·α′`.
    pub(crate) fn derivatives(&self, poly: SmoothingPolynomials, u: f64, order: usize) -> Vec<V> {
        let m = order;
        let angle_series = |weights: &dyn Fn(usize) -> f64| -> (Vec<f64>, Vec<f64>) {
            // Taylor coefficients of α, then of cos α − 1 and sin α.
            let mut fact = 1.0;
            let mut a = Vec::with_capacity(m + 1);
            for k in 0..=m {
                if k > 0 {
                    fact *= k as f64;
                }
                a.push(weights(k) / fact);
            }
            let (s0, c0) = math::sin_cos(a[0]);
            let (mut sn, mut cs) = (vec![s0], vec![c0]);
            for k in 1..=m {
                let (mut sk, mut ck) = (0.0, 0.0);
                for j in 1..=k {
                    sk += j as f64 * a[j] * cs[k - j];
                    ck -= j as f64 * a[j] * sn[k - j];
                }
                sn.push(sk / k as f64);
                cs.push(ck / k as f64);
            }
            cs[0] -= 1.0;
            (cs, sn)
        };
        // Apply the series of G(α(u)) to a vector series x_k: Σ_j (c_j P + s_j K) x_{k−j} + x_k.
        let apply = |flow: &F, (cm, sn): &(Vec<f64>, Vec<f64>), x: &[V]| -> Vec<V> {
            let kx: Vec<V> = x.iter().map(|v| flow.generator(v)).collect();
            let px: Vec<V> = kx.iter().map(|v| -flow.generator(v)).collect();
            (0..=m)
                .map(|k| {
                    let mut acc = x[k].clone();
                    for j in 0..=k {
                        acc += px[k - j].clone() * cm[j] + kx[k - j].clone() * sn[j];
                    }
                    acc
                })
                .collect()
        };
        let outer_w = |k: usize| self.angle_derivatives(poly, u, k).0;
        let inner_w = |k: usize| self.angle_derivatives(poly, u, k).1;
        let zero = self.base.zeros_like();
        let mut x: Vec<V> = vec![zero; m + 1];
        x[0] = self.base.clone();
        if let Some((inner, _)) = &self.inner {
            x = apply(inner, &angle_series(&inner_w), &x);
        }
        let series = apply(&self.outer, &angle_series(&outer_w), &x);
        // Derivative k = k!·coefficient / widthᵏ.
        let mut scale = 1.0;
        series
            .into_iter()
            .enumerate()
            .map(|(k, v)| {
                if k > 0 {
                    scale *= k as f64 / self.width;
                }
                v * scale
            })
            .collect()
    }

    /// The point only.
    pub(crate) fn point(&self, poly: SmoothingPolynomials, u: f64) -> V {
        let (al, be) = self.angles(poly, u);
        let y = match &self.inner {
            None => self.base.clone(),
            Some((inner, _)) => inner.apply(be[0], &self.base),
        };
        self.outer.apply(al[0], &y)
    }
}
