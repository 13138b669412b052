// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Numerical kernel of the spherical Beta-spline interpolation problem (Yang et al. 2021,
//! §4.1–4.2; the system and the solver as stated in `docs/derivations.md#beta-system`).
//!
//! The unknowns are the auxiliary vertices `d₁ … dₙ₋₁`; row `i` of the system says that the
//! junction point
//!
//! ```text
//! q_{i,0} = G[ G[d_{i-1}, d_i](ω_{i-1}),  G[d_i, d_{i+1}](η_i) ](δ_i)
//! ```
//!
//! equals the data point `pᵢ`. Row `i` involves only `d_{i-1}, d_i, d_{i+1}`, so the Jacobian
//! is block tridiagonal with `(r−1)×(r−1)` blocks in tangent coordinates.
//!
//! A **closed** loop has the unknowns `d₀ … d_{m−1}` and the rows `i = 0 … m−1` with indices
//! mod m (row 0 involves `d_{m−1}`, row m−1 involves `d₀`): the Jacobian is block cyclic
//! tridiagonal, solved by bordering in O(m) as well (both factorised by
//! [`BlockTridiagonal`](crate::banded::BlockTridiagonal)).
//!
//! The kernel computes in coordinates of an orthonormal basis of the span of the data (of
//! dimension `r ≤ m + 1`): every slerp keeps its result in the span of its inputs, and a
//! reflection through that span maps the problem to itself, so the solution lies in it and
//! no coordinates beyond it are needed. The coordinate vectors are `DVec3` for `r ≤ 3`,
//! `DVec4` for `r = 4` and [`VecN`] beyond, so S² and S³ run without allocation (without the
//! `compact` feature; with it, as in the browser build, all run in `VecN`, padded to 3 or 4
//! coordinates: the same bits, one copy of the kernel in the binary).

use glam::{DVec3, DVec4};

use crate::ambient::{Ambient, VecN};
use crate::banded::BlockTridiagonal;
use crate::manifold::{exp_vector, geodesic_frame, renormalize, slerp_vector};
use crate::math;

/// Coordinate vectors the kernel computes in.
pub(crate) trait Coords: Ambient {
    /// The vector with the given leading coordinates, zero beyond them; `dim` is the length
    /// for dynamically sized vectors.
    fn from_coords(c: &[f64], dim: usize) -> Self;
    /// Coordinate `j`.
    fn coord(&self, j: usize) -> f64;
}

impl Coords for DVec3 {
    fn from_coords(c: &[f64], _dim: usize) -> Self {
        let mut a = [0.0; 3];
        a[..c.len()].copy_from_slice(c);
        Self::from_array(a)
    }
    fn coord(&self, j: usize) -> f64 {
        self[j]
    }
}

impl Coords for DVec4 {
    fn from_coords(c: &[f64], _dim: usize) -> Self {
        let mut a = [0.0; 4];
        a[..c.len()].copy_from_slice(c);
        Self::from_array(a)
    }
    fn coord(&self, j: usize) -> f64 {
        self[j]
    }
}

impl Coords for VecN {
    fn from_coords(c: &[f64], dim: usize) -> Self {
        let mut a = vec![0.0; dim.max(c.len())];
        a[..c.len()].copy_from_slice(c);
        Self::new(a)
    }
    fn coord(&self, j: usize) -> f64 {
        self.as_slice()[j]
    }
}

/// The shape constants of the system (`docs/derivations.md#beta-system`), all in `(0, 1)`.
#[derive(Clone, Debug)]
pub(crate) struct Shape {
    /// `η_j = γ_j / D_{j+1}` per arc `d_j d_{j+1}`, `j = 0..n−1` (position of `q_{j,1}`).
    pub(crate) eta: Vec<f64>,
    /// `ω_j = (γ_j + 1) / D_{j+1}` per arc (position of `q_{j,2}`).
    pub(crate) omega: Vec<f64>,
    /// `δ_i = 1/(1 + β_{1,i})` per point `i = 0..n` (only `1..n−1` are used).
    pub(crate) delta: Vec<f64>,
}

/// How the kernel's iteration ended.
#[derive(Clone, Debug)]
pub(crate) struct Outcome<V> {
    /// `d₀ … dₙ` in kernel coordinates.
    pub(crate) d: Vec<V>,
    /// Iterations performed.
    pub(crate) iterations: usize,
    /// Largest geodesic distance between `q_{i,0}` and `pᵢ`, as computed in kernel coordinates
    /// (`∞` if it could not be evaluated).
    pub(crate) residual: f64,
}

/// Settings of one solve.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Settings {
    /// Jacobi: threshold on `Σ‖dᵢ⁽ᵏ⁾ − dᵢ⁽ᵏ⁻¹⁾‖²`. Newton: unused.
    pub(crate) change_tolerance: f64,
    /// Newton: target for the largest geodesic interpolation error.
    pub(crate) residual_tolerance: f64,
    /// Iteration limit.
    pub(crate) max_iterations: usize,
}

// ---------------------------------------------------------------------------------------------
// Scalar helpers

/// `r(s, θ) = sin(sθ)/sin θ` (`r(s, 0) = s`), for θ ∈ [0, π).
fn ratio_value(s: f64, theta: f64) -> f64 {
    s * math::sinc(s * theta) / math::sinc(theta)
}

/// `r(s, θ) = sin(sθ)/sin θ` (`r(s, 0) = s`) and its derivative in θ, for θ ∈ [0, π).
pub(crate) fn ratio(s: f64, theta: f64) -> (f64, f64) {
    let (a, b) = (math::sinc(s * theta), math::sinc(theta));
    let r = s * a / b;
    let dsinc = |x: f64| math::sinc_deriv(x, math::sin_cos(x));
    let dr = s * (s * dsinc(s * theta) * b - a * dsinc(theta)) / (b * b);
    (r, dr)
}

/// `θ(a, b) = 2·atan2(|a − b|, |a + b|)`.
fn angle<V: Ambient>(a: &V, b: &V) -> f64 {
    2.0 * math::atan2(
        (a.clone() - b.clone()).length(),
        (a.clone() + b.clone()).length(),
    )
}

/// `G[a, b](s)`; `None` for antipodal `a, b`.
fn slerp<V: Ambient>(a: &V, b: &V, s: f64) -> Option<V> {
    slerp_vector(a, b, s).ok()
}

/// `G[a, b](s)` with its derivatives with respect to the end points.
///
/// `G = α·a + β·b` with `α = r(1 − s, θ)`, `β = r(s, θ)`; for tangent perturbations `da ⊥ a`,
/// `db ⊥ b` the angle changes by `dθ = f·db − e·da` (`e`: unit tangent at `a` towards `b`; `f`:
/// unit tangent at `b` away from `a`), so `dG = α·da + β·db + (α_θ·a + β_θ·b)·dθ`.
#[derive(Clone, Debug)]
struct SlerpJet<V> {
    g: V,
    alpha: f64,
    beta: f64,
    c: V,
    e: V,
    f: V,
}

impl<V: Ambient> SlerpJet<V> {
    fn new(a: &V, b: &V, s: f64) -> Option<Self> {
        let (theta, e) = geodesic_frame(a, b)?;
        let (ss, cs) = math::sin_cos(s * theta);
        let g = renormalize(a.clone() * cs + e.clone() * ss);
        let (st, ct) = math::sin_cos(theta);
        let f = e.clone() * ct - a.clone() * st;
        let (alpha, alpha_t, beta, beta_t) = if theta > 1e-3 {
            // From the two sines and cosines already at hand; the cancellation in the
            // derivatives costs at most ~1e-10 relative accuracy at θ = 1e-3.
            let inv = 1.0 / st;
            let s1 = st * cs - ct * ss; // sin((1 − s)θ)
            let c1 = ct * cs + st * ss; // cos((1 − s)θ)
            (
                s1 * inv,
                ((1.0 - s) * c1 * st - s1 * ct) * inv * inv,
                ss * inv,
                (s * cs * st - ss * ct) * inv * inv,
            )
        } else {
            let (alpha, alpha_t) = ratio(1.0 - s, theta);
            let (beta, beta_t) = ratio(s, theta);
            (alpha, alpha_t, beta, beta_t)
        };
        let c = a.clone() * alpha_t + b.clone() * beta_t;
        Some(Self {
            g,
            alpha,
            beta,
            c,
            e,
            f,
        })
    }

    /// `∂G/∂a · da`.
    fn push_a(&self, da: &V) -> V {
        da.clone() * self.alpha - self.c.clone() * self.e.dot(da)
    }

    /// `∂G/∂b · db`.
    fn push_b(&self, db: &V) -> V {
        db.clone() * self.beta + self.c.clone() * self.f.dot(db)
    }
}

/// An orthonormal basis of the tangent space at the unit vector `x`, inside the span of the
/// first `r` coordinates (where `x` lies), by a Householder reflection.
#[cfg(test)]
fn tangent_basis<V: Coords>(x: &V, r: usize, dim: usize) -> Vec<V> {
    let mut out = Vec::with_capacity(r.saturating_sub(1));
    push_tangent_basis(x, r, dim, &mut out);
    out
}

/// [`tangent_basis`], appended to `basis`.
fn push_tangent_basis<V: Coords>(x: &V, r: usize, dim: usize, basis: &mut Vec<V>) {
    let mut buf = [0.0; 16];
    let mut heap;
    let (u, col): (&mut [f64], &mut [f64]) = if r <= 8 {
        let (a, b) = buf.split_at_mut(8);
        (&mut a[..r], &mut b[..r])
    } else {
        heap = vec![0.0; 2 * r];
        heap.split_at_mut(r)
    };
    for (j, uj) in u.iter_mut().enumerate() {
        *uj = x.coord(j);
    }
    let mut jmax = 0;
    for j in 1..r {
        if u[j].abs() > u[jmax].abs() {
            jmax = j;
        }
    }
    u[jmax] += if u[jmax] >= 0.0 { 1.0 } else { -1.0 };
    let uu: f64 = u.iter().map(|a| a * a).sum();
    for k in (0..r).filter(|&k| k != jmax) {
        let scale = 2.0 * u[k] / uu;
        for j in 0..r {
            col[j] = -scale * u[j];
        }
        col[k] += 1.0;
        basis.push(V::from_coords(col, dim));
    }
}

/// `d log_p(q) · dq` for `q = cos θ·p + sin θ·u` (exact derivative of the logarithm).
fn dlog<V: Ambient>(p: &V, theta: f64, u: &V, dq: &V) -> V {
    let tangent = dq.clone() - p.clone() * p.dot(dq);
    if theta < 1e-8 {
        return tangent;
    }
    let (s, c) = math::sin_cos(theta);
    let w = u.clone() * c - p.clone() * s;
    let perp = tangent.clone() - u.clone() * u.dot(&tangent);
    u.clone() * w.dot(dq) + perp * math::inv_sinc(theta)
}

// ---------------------------------------------------------------------------------------------
// The system

/// The data, shape constants and dimensions of one interpolation problem.
#[derive(Debug)]
pub(crate) struct System<'a, V> {
    /// Data points `p₀ … pₙ` in kernel coordinates.
    data: &'a [V],
    shape: &'a Shape,
    /// Number of active coordinates `r` (the dimension of the data span).
    rank: usize,
    /// Length of the coordinate vectors.
    dim: usize,
    /// Tangent bases at the data points, `r − 1` vectors per point, flat.
    data_bases: Vec<V>,
    /// A closed loop: every vertex is unknown and the indices wrap around.
    closed: bool,
}

impl<'a, V: Coords> System<'a, V> {
    /// The system for `data` (unit vectors in the first `rank` of `dim` coordinates).
    pub(crate) fn new(
        data: &'a [V],
        shape: &'a Shape,
        rank: usize,
        dim: usize,
        closed: bool,
    ) -> Self {
        let mut data_bases = Vec::with_capacity(data.len() * (rank - 1));
        for p in data {
            push_tangent_basis(p, rank, dim, &mut data_bases);
        }
        Self {
            data,
            shape,
            rank,
            dim,
            data_bases,
            closed,
        }
    }

    fn n(&self) -> usize {
        self.data.len() - 1
    }

    /// The rows, which are also the unknown vertices: `1 … n−1` open, `0 … m−1` closed.
    fn rows(&self) -> core::ops::Range<usize> {
        if self.closed {
            0..self.data.len()
        } else {
            1..self.n()
        }
    }

    /// The block of unknown vertex `v`, if it is one.
    fn unknown(&self, v: usize) -> Option<usize> {
        let rows = self.rows();
        rows.contains(&v).then(|| v - rows.start)
    }

    /// The neighbours `i − 1`, `i + 1` of vertex `i` (mod m when closed).
    fn neighbours(&self, i: usize) -> (usize, usize) {
        let m = self.data.len();
        if self.closed {
            ((i + m - 1) % m, (i + 1) % m)
        } else {
            (i - 1, i + 1)
        }
    }

    /// The junction point `q_{i,0}` of row `i`.
    fn junction(&self, d: &[V], i: usize) -> Option<V> {
        let (prev, next) = self.neighbours(i);
        let a = slerp(&d[prev], &d[i], self.shape.omega[prev])?;
        let b = slerp(&d[i], &d[next], self.shape.eta[i])?;
        slerp(&a, &b, self.shape.delta[i])
    }

    /// Largest and squared-sum geodesic interpolation errors; `None` if a junction cannot be
    /// formed (antipodal points) or is not finite.
    pub(crate) fn residual(&self, d: &[V]) -> Option<(f64, f64)> {
        let (mut max, mut sum) = (0.0_f64, 0.0);
        for i in self.rows() {
            let q = self.junction(d, i)?;
            if !q.is_finite() {
                return None;
            }
            let t = angle(&q, &self.data[i]);
            max = max.max(t);
            sum += t * t;
        }
        Some((max, sum))
    }

    /// One Jacobi update of eq. (19) in the robust form of `docs/derivations.md#beta-solver`,
    /// normalised.
    pub(crate) fn jacobi_step(&self, d: &[V]) -> Option<Vec<V>> {
        let sh = self.shape;
        let mut out = d.to_vec();
        for i in self.rows() {
            let (prev, next) = self.neighbours(i);
            let phi0 = angle(&d[prev], &d[i]);
            let phi1 = angle(&d[i], &d[next]);
            let a = slerp(&d[prev], &d[i], sh.omega[prev])?;
            let b = slerp(&d[i], &d[next], sh.eta[i])?;
            let psi = angle(&a, &b);
            let rl = ratio_value(1.0 - sh.delta[i], psi);
            let rr = ratio_value(sh.delta[i], psi);
            let num = self.data[i].clone()
                - d[prev].clone() * (rl * ratio_value(1.0 - sh.omega[prev], phi0))
                - d[next].clone() * (rr * ratio_value(sh.eta[i], phi1));
            let den =
                rl * ratio_value(sh.omega[prev], phi0) + rr * ratio_value(1.0 - sh.eta[i], phi1);
            if !(den > 0.0 && den.is_finite()) {
                return None;
            }
            let v = num * (1.0 / den);
            let l = v.length();
            if !(l > 0.0 && l.is_finite()) {
                return None;
            }
            out[i] = v * (1.0 / l);
        }
        Some(out)
    }

    /// The Jacobi iteration with the paper's stopping rule `Σ‖Δd‖² < ε`.
    pub(crate) fn solve_jacobi(&self, settings: Settings) -> Outcome<V> {
        let mut d = self.data.to_vec();
        let mut iterations = 0;
        while iterations < settings.max_iterations {
            let Some(next) = self.jacobi_step(&d) else {
                break;
            };
            iterations += 1;
            let change: f64 = next
                .iter()
                .zip(&d)
                .map(|(a, b)| {
                    let v = a.clone() - b.clone();
                    v.dot(&v)
                })
                .sum();
            d = next;
            // Non-finite changes stop too; the caller's residual check then fails.
            if !change.is_finite() || change < settings.change_tolerance {
                break;
            }
        }
        let residual = self.residual(&d).map_or(f64::INFINITY, |r| r.0);
        Outcome {
            d,
            iterations,
            residual,
        }
    }

    /// Newton's method on the block-tridiagonal system, globalised by a backtracking line
    /// search on `½ Σ θᵢ²` (θᵢ = geodesic interpolation error), with a Jacobi step as fallback
    /// when the search fails or the Jacobian is singular.
    pub(crate) fn solve_newton(&self, settings: Settings) -> Outcome<V> {
        let n = self.n();
        let mut d = self.data.to_vec();
        let mut iterations = 0;
        let Some((mut residual, mut merit2)) = self.residual(&d) else {
            return Outcome {
                d,
                iterations,
                residual: f64::INFINITY,
            };
        };
        let mut converged = residual <= settings.residual_tolerance;
        while !converged && iterations < settings.max_iterations {
            iterations += 1;
            let step = self
                .newton_direction(&d)
                .and_then(|(bases, x)| self.line_search(&d, &bases, &x, merit2));
            let (next, (r, m2)) = match step {
                Some(found) => found,
                None => {
                    // Fallback: one step of the paper's iteration.
                    let Some(next) = self.jacobi_step(&d) else {
                        break;
                    };
                    let Some(res) = self.residual(&next) else {
                        break;
                    };
                    (next, res)
                }
            };
            d = next;
            residual = r;
            merit2 = m2;
            converged = residual <= settings.residual_tolerance;
        }
        debug_assert_eq!(d.len(), n + 1, "vertex count");
        debug_assert!(self.rows().len() <= n + 1, "row count");
        Outcome {
            d,
            iterations,
            residual,
        }
    }

    /// The Newton step: tangent bases at the unknown vertices (`b = r − 1` per vertex, flat)
    /// and the step coordinates in them (flat).
    fn newton_direction(&self, d: &[V]) -> Option<(Vec<V>, Vec<f64>)> {
        let (r, dim) = (self.rank, self.dim);
        let b = r - 1;
        let (bb, rows) = (b * b, self.rows().len());
        let mut bases = Vec::with_capacity(rows * b);
        for x in &d[self.rows()] {
            push_tangent_basis(x, r, dim, &mut bases);
        }
        let sh = self.shape;
        let mut lower = vec![0.0; rows * bb];
        let mut diag = vec![0.0; rows * bb];
        let mut upper = vec![0.0; rows * bb];
        let mut rhs = vec![0.0; rows * b];
        for i in self.rows() {
            let (prev, next) = self.neighbours(i);
            let row = i - self.rows().start;
            let ja = SlerpJet::new(&d[prev], &d[i], sh.omega[prev])?;
            let jb = SlerpJet::new(&d[i], &d[next], sh.eta[i])?;
            let jq = SlerpJet::new(&ja.g, &jb.g, sh.delta[i])?;
            let p = &self.data[i];
            let (theta, u) = geodesic_frame(p, &jq.g)?;
            // Residual and Jacobian rows in the tangent basis at pᵢ.
            let pb = &self.data_bases[i * b..(i + 1) * b];
            for (k, e) in pb.iter().enumerate() {
                rhs[row * b + k] = -theta * e.dot(&u);
            }
            let put = |block: &mut [f64], l: usize, dq: &V| {
                let g = dlog(p, theta, &u, dq);
                for (k, e) in pb.iter().enumerate() {
                    block[k * b + l] = e.dot(&g);
                }
            };
            let blk = row * bb..(row + 1) * bb;
            for l in 0..b {
                if let Some(at) = self.unknown(prev) {
                    let t = &bases[at * b + l];
                    put(&mut lower[blk.clone()], l, &jq.push_a(&ja.push_a(t)));
                }
                let t = &bases[row * b + l];
                put(
                    &mut diag[blk.clone()],
                    l,
                    &(jq.push_a(&ja.push_b(t)) + jq.push_b(&jb.push_a(t))),
                );
                if let Some(at) = self.unknown(next) {
                    let t = &bases[at * b + l];
                    put(&mut upper[blk.clone()], l, &jq.push_b(&jb.push_b(t)));
                }
            }
        }
        let mut x = rhs;
        BlockTridiagonal::factor(b, &lower, &diag, &upper, self.closed)?.solve(&mut x);
        x.iter().all(|v| v.is_finite()).then_some((bases, x))
    }

    /// Backtracking (Armijo) line search along the Newton step: the new vertices with their
    /// [`residual`](Self::residual); `None` if no sufficient decrease is found.
    fn line_search(
        &self,
        d: &[V],
        bases: &[V],
        x: &[f64],
        merit2: f64,
    ) -> Option<(Vec<V>, (f64, f64))> {
        /// No vertex moves more than this many radians in one step.
        const MAX_STEP: f64 = 1.0;
        let b = self.rank - 1;
        let rows = self.rows();
        let mut steps: Vec<V> = Vec::with_capacity(rows.len());
        let mut longest = 0.0_f64;
        for (row, j) in rows.clone().enumerate() {
            let mut v = d[j].zeros_like();
            for l in 0..b {
                v += bases[row * b + l].clone() * x[row * b + l];
            }
            longest = longest.max(v.length());
            steps.push(v);
        }
        let mut lambda = if longest > MAX_STEP {
            MAX_STEP / longest
        } else {
            1.0
        };
        while lambda >= 1e-6 {
            let mut next = d.to_vec();
            for (row, j) in rows.clone().enumerate() {
                next[j] = exp(&d[j], &(steps[row].clone() * lambda));
            }
            if let Some((max, m2)) = self.residual(&next) {
                // φ = ½ Σθ² has directional derivative −2φ along the full Newton step.
                if m2 <= merit2 * (1.0 - 2e-4 * lambda) {
                    return Some((next, (max, m2)));
                }
            }
            lambda *= 0.5;
        }
        None
    }
}

/// `exp_x(v)` ([`Manifold::try_exp`](crate::Manifold::try_exp)); `x` itself for a
/// non-finite `v`.
fn exp<V: Ambient>(x: &V, v: &V) -> V {
    exp_vector(x, v).unwrap_or_else(|_| x.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_derivative_matches_differences() {
        for &(s, t) in &[(0.3, 1.2), (0.7, 1e-5), (0.5, 0.0), (0.9, 3.0), (0.2, 2e-3)] {
            let (r, dr) = ratio(s, t);
            let h = 1e-6;
            let fd = (ratio(s, t + h).0 - ratio(s, (t - h).abs()).0) / (t + h - (t - h).abs());
            let exact = if t > 0.0 { (s * t).sin() / t.sin() } else { s };
            assert!((r - exact).abs() < 1e-14, "r({s},{t})");
            if t > h {
                assert!((dr - fd).abs() < 1e-7, "r_θ({s},{t}): {dr} vs {fd}");
            } else {
                assert!(dr.abs() < 1e-4, "r_θ near 0");
            }
        }
    }

    #[test]
    fn slerp_jet_matches_differences() {
        let a = DVec3::new(0.3, -0.2, 0.9).normalize();
        let b = DVec3::new(-0.5, 0.7, 0.2).normalize();
        let s = 0.37;
        let jet = SlerpJet::new(&a, &b, s).unwrap();
        let ta = tangent_basis(&a, 3, 3);
        let tb = tangent_basis(&b, 3, 3);
        let h = 1e-6;
        for t in &ta {
            let fd = (slerp(&exp(&a, &(*t * h)), &b, s).unwrap()
                - slerp(&exp(&a, &(*t * -h)), &b, s).unwrap())
                / (2.0 * h);
            assert!((jet.push_a(t) - fd).length() < 1e-8, "∂G/∂a");
        }
        for t in &tb {
            let fd = (slerp(&a, &exp(&b, &(*t * h)), s).unwrap()
                - slerp(&a, &exp(&b, &(*t * -h)), s).unwrap())
                / (2.0 * h);
            assert!((jet.push_b(t) - fd).length() < 1e-8, "∂G/∂b");
        }
    }

    #[test]
    fn slerp_jet_small_angle_branch_matches_large() {
        let a = DVec3::new(0.3, -0.2, 0.9).normalize();
        for theta in [0.999e-3_f64, 1.001e-3] {
            let e = DVec3::new(1.0, 0.0, 0.0);
            let e = (e - a * a.dot(e)).normalize();
            let b = a * theta.cos() + e * theta.sin();
            let jet = SlerpJet::new(&a, &b, 0.3).unwrap();
            let t = tangent_basis(&a, 3, 3)[0];
            let h = 1e-7;
            let fd = (slerp(&exp(&a, &(t * h)), &b, 0.3).unwrap()
                - slerp(&exp(&a, &(t * -h)), &b, 0.3).unwrap())
                / (2.0 * h);
            assert!((jet.push_a(&t) - fd).length() < 1e-7, "θ = {theta}");
        }
    }

    #[test]
    fn dlog_matches_differences() {
        let p = DVec3::new(0.1, 0.2, 0.97).normalize();
        let q = DVec3::new(0.8, -0.3, 0.4).normalize();
        let (theta, u) = geodesic_frame(&p, &q).unwrap();
        let h = 1e-6;
        for t in tangent_basis(&q, 3, 3) {
            let lp = {
                let qq = exp(&q, &(t * h));
                let (th, uu) = geodesic_frame(&p, &qq).unwrap();
                uu * th
            };
            let lm = {
                let qq = exp(&q, &(t * -h));
                let (th, uu) = geodesic_frame(&p, &qq).unwrap();
                uu * th
            };
            let fd = (lp - lm) / (2.0 * h);
            assert!((dlog(&p, theta, &u, &t) - fd).length() < 1e-8, "dlog");
        }
    }

    #[test]
    fn tangent_basis_is_orthonormal() {
        for x in [
            DVec4::new(0.5, -0.5, 0.5, 0.5),
            DVec4::new(0.0, 0.0, -1.0, 0.0),
            DVec4::new(0.6, 0.8, 0.0, 0.0),
        ] {
            let r = if x.z == 0.0 && x.w == 0.0 { 2 } else { 4 };
            let t = tangent_basis(&x, r, 4);
            assert_eq!(t.len(), r - 1, "count");
            for (i, a) in t.iter().enumerate() {
                assert!(DVec4::dot(*a, x).abs() < 1e-15, "tangent");
                for (j, b) in t.iter().enumerate() {
                    let want = if i == j { 1.0 } else { 0.0 };
                    assert!((DVec4::dot(*a, *b) - want).abs() < 1e-15, "orthonormal");
                }
                if r == 2 {
                    assert!(a.z == 0.0 && a.w == 0.0, "stays in the active span");
                }
            }
        }
    }
}
