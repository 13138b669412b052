// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Arc-length parametrisation of any curve: the length, the maps `t ↦ s` and `s ↦ t`, and the
//! reparametrised curve with exact derivatives by the chain rule.

use crate::ambient::Ambient;
use crate::curve::{Curve, Jet, Side, clamp_param};
use crate::error::ArcLengthError;
use crate::manifold::Manifold;

/// The default accuracy of [`ArcLength`], in radians of arc length (rotation angle on S³).
pub const DEFAULT_ARC_LENGTH_ACCURACY: f64 = 1e-10;

/// Gauss–Legendre nodes per cell.
const NODES: usize = 10;

/// The 10-point Gauss–Legendre nodes on `[−1, 1]`, increasing.
const GL_X: [f64; NODES] = [
    -0.973_906_528_517_171_7,
    -0.865_063_366_688_984_5,
    -0.679_409_568_299_024_4,
    -0.433_395_394_129_247_2,
    -0.148_874_338_981_631_2,
    0.148_874_338_981_631_2,
    0.433_395_394_129_247_2,
    0.679_409_568_299_024_4,
    0.865_063_366_688_984_5,
    0.973_906_528_517_171_7,
];

/// The weights of [`GL_X`].
const GL_W: [f64; NODES] = [
    0.066_671_344_308_688_14,
    0.149_451_349_150_580_6,
    0.219_086_362_515_982_04,
    0.269_266_719_309_996_35,
    0.295_524_224_714_752_87,
    0.295_524_224_714_752_87,
    0.269_266_719_309_996_35,
    0.219_086_362_515_982_04,
    0.149_451_349_150_580_6,
    0.066_671_344_308_688_14,
];

/// Cells are halved at most this many times below a piece.
const MAX_DEPTH: u32 = 50;

/// A piece has at most about this many cells: past it, cells are accepted as they are (and
/// counted in [`ArcLengthInfo::unresolved`]), so that a curve whose speed is rounding noise
/// everywhere (keys 1e-9 apart, a near-antipodal step) cannot make the bisection exponential.
const MAX_CELLS_PER_PIECE: usize = 2048;

/// Cells at least this deep (narrower than 2⁻²⁰ of their piece) mark a place where the speed is
/// not smooth at the scale of the piece: in practice a zero of the speed (a cusp, where `|c′|`
/// has a kink) or a near-zero. They are reported as [`Stall`]s.
const STALL_DEPTH: u32 = 20;

/// A speed below this fraction of its piece's mean speed is reported as a [`Stall`].
const STALL_FRACTION: f64 = 1e-6;

/// Within `NOISE·(t1 − t0)` of a zero of the speed the direction of `c′` is rounding noise and
/// the stall rule of [`ArcLength`] applies.
const NOISE: f64 = 64.0 * f64::EPSILON;

/// Newton iterations of `s ↦ t` (bisection steps included) before giving up on a cell.
const MAX_NEWTON: usize = 60;

/// Where the speed of the curve vanishes (see [`ArcLengthInfo`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stall {
    /// The arc-length parameter of the place: all of `t` maps to (nearly) this `s`.
    pub s: f64,
    /// The interval of the original parameter: a whole piece of zero length, or the narrow
    /// interval around an isolated zero (or near-zero) of the speed, such as a cusp.
    pub t: [f64; 2],
}

/// What the construction of an [`ArcLength`] found and did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ArcLengthInfo {
    /// Where the speed vanishes, in increasing order.
    ///
    /// A piece of length at most `accuracy / 1024` is collapsed to a single `s` (its two joints
    /// have one image). Around an isolated zero of the speed the reparametrised curve stays
    /// finite: see the stall rule of [`ArcLength`].
    pub stalls: Vec<Stall>,
    /// The number of cells of the table (each with its own speed interpolant).
    pub cells: usize,
    /// The number of evaluations of the curve's jet during construction.
    pub evaluations: usize,
    /// Cells accepted at the subdivision limit (50 halvings, or about 2048 cells in a piece)
    /// without meeting the accuracy (zero for curves whose speed is smooth on each piece).
    pub unresolved: usize,
}

/// One cell `[a, b]` of a piece: `t = mid + half·u` for `u ∈ [−1, 1]`, with
/// `s(t) = s0 + Σ integral[j]·P_j(u)` and `ds/du = Σ speed[k]·P_k(u)` (Legendre series).
#[derive(Clone, Debug)]
struct Cell {
    a: f64,
    b: f64,
    mid: f64,
    half: f64,
    s0: f64,
    s1: f64,
    /// Terms of `speed`; `integral` has one more.
    terms: usize,
    speed: [f64; NODES],
    integral: [f64; NODES + 1],
    /// `integral` in the monomial basis (evaluated by Horner's rule, the fast path).
    monomial: [f64; NODES + 1],
    /// Terms of `inverse`.
    inverse_terms: usize,
    /// Legendre series of `u` in `y = 2(s − s0)/(s1 − s0) − 1`: the starting guess of `solve`.
    inverse: [f64; NODES],
    /// The inverse series is accurate enough to be the answer (checked at construction).
    inverse_exact: bool,
    /// `2/(s1 − s0)` (0 for a cell of zero length), so that `solve` does not divide.
    two_over_len: f64,
}

/// `(2k+1)/(k+1)` and `k/(k+1)` of the Legendre recurrence `P_{k+1} = ((2k+1)u·P_k − k·P_{k−1})/(k+1)`.
const REC: [(f64, f64); NODES + 1] = {
    let mut r = [(0.0, 0.0); NODES + 1];
    let mut k = 0;
    while k <= NODES {
        let kf = k as f64;
        r[k] = ((2.0 * kf + 1.0) / (kf + 1.0), kf / (kf + 1.0));
        k += 1;
    }
    r
};

/// The monomial coefficients of the Legendre series `Σ cₖ·Pₖ` (at most `NODES + 1` terms).
fn to_monomial(c: &[f64]) -> [f64; NODES + 1] {
    // Rows: the monomial coefficients of P_k, by the three-term recurrence.
    let mut p = [[0.0; NODES + 1]; NODES + 1];
    p[0][0] = 1.0;
    p[1][1] = 1.0;
    for k in 1..NODES {
        for j in 0..=NODES {
            let up = if j > 0 { p[k][j - 1] } else { 0.0 };
            p[k + 1][j] = REC[k].0 * up - REC[k].1 * p[k - 1][j];
        }
    }
    let mut out = [0.0; NODES + 1];
    for (k, &ck) in c.iter().enumerate() {
        for (o, &pj) in out.iter_mut().zip(&p[k]) {
            *o += ck * pj;
        }
    }
    out
}

/// `P_0(x) … P_{NODES−1}(x)`.
fn legendre_all(x: f64) -> [f64; NODES] {
    let mut p = [0.0; NODES];
    p[0] = 1.0;
    p[1] = x;
    for k in 1..NODES - 1 {
        p[k + 1] = REC[k].0 * x * p[k] - REC[k].1 * p[k - 1];
    }
    p
}

impl Cell {
    /// `(s(u) − s0, ds/du)` by Horner's rule.
    #[inline]
    fn eval(&self, u: f64) -> (f64, f64) {
        let c = &self.monomial[..=self.terms];
        let mut s = c[c.len() - 1];
        let mut ds = 0.0;
        for &ck in c[..c.len() - 1].iter().rev() {
            ds = ds * u + s;
            s = s * u + ck;
        }
        (s, ds)
    }

    /// Fills `monomial` from `integral`.
    fn finish(&mut self) {
        self.monomial = to_monomial(&self.integral[..=self.terms]);
    }

    /// `s(t)` for `t` in the cell.
    fn s_at(&self, t: f64) -> f64 {
        if t <= self.a {
            return self.s0;
        }
        if t >= self.b {
            return self.s1;
        }
        let u = ((t - self.mid) / self.half).clamp(-1.0, 1.0);
        (self.s0 + self.eval(u).0).clamp(self.s0, self.s1)
    }

    /// The `u` with `s(u) = s0 + target`: Newton's method, safeguarded by bisection.
    #[inline]
    fn solve(&self, target: f64) -> f64 {
        let len = self.s1 - self.s0;
        if target <= 0.0 {
            return -1.0;
        }
        if target >= len {
            return 1.0;
        }
        let u = self.guess(target * self.two_over_len - 1.0);
        if self.inverse_exact {
            return u;
        }
        self.newton(target, u)
    }

    /// Newton's method for `s(u) = s0 + target` from `u`, safeguarded by bisection.
    fn newton(&self, target: f64, mut u: f64) -> f64 {
        let (mut lo, mut hi) = (-1.0_f64, 1.0_f64);
        for _ in 0..MAX_NEWTON {
            let (s, ds) = self.eval(u);
            let r = s - target;
            if r == 0.0 {
                return u;
            }
            if r < 0.0 {
                lo = u;
            } else {
                hi = u;
            }
            let step = r / ds;
            let next = u - step;
            if ds > 0.0 && next > lo && next < hi {
                u = next;
                // Quadratic convergence: after a step this small the error is at rounding level.
                if step.abs() < 1e-9 {
                    return u;
                }
            } else {
                u = 0.5 * (lo + hi);
                if hi - lo < 4.0 * f64::EPSILON {
                    return u;
                }
            }
        }
        u
    }

    /// The inverse series at `y ∈ [−1, 1]`, inside `[−1, 1]` (Horner's rule on the monomial
    /// form in `inverse`).
    #[inline]
    fn guess(&self, y: f64) -> f64 {
        // Estrin's scheme on all ten coefficients (those past `inverse_terms` are zero): the
        // pairs and the powers of y evaluate side by side, half the latency of Horner's rule.
        let c = &self.inverse;
        let y2 = y * y;
        let y4 = y2 * y2;
        let p01 = c[0] + c[1] * y;
        let p23 = c[2] + c[3] * y;
        let p45 = c[4] + c[5] * y;
        let p67 = c[6] + c[7] * y;
        let p89 = c[8] + c[9] * y;
        let u = (p01 + p23 * y2) + (p45 + p67 * y2) * y4 + p89 * (y4 * y4);
        u.clamp(-1.0, 1.0)
    }

    /// Fits the inverse series to Newton's solution at the Gauss–Legendre nodes of `s`, and
    /// marks it exact when it solves `s(u) = s` to `tol` (in `s`) at 41 points of the cell.
    fn fit_inverse(&mut self, tol: f64) {
        self.inverse = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        self.inverse_terms = 2;
        self.inverse_exact = false;
        let len = self.s1 - self.s0;
        self.two_over_len = if len > 0.0 { 2.0 / len } else { 0.0 };
        if self.terms == 1 || len <= 0.0 {
            // Constant speed: u is linear in s.
            self.inverse_exact = true;
            return;
        }
        let mut coef = [0.0; NODES];
        for (&y, &w) in GL_X.iter().zip(&GL_W) {
            let target = 0.5 * (y + 1.0) * len;
            let u = self.newton(target, y);
            let p = legendre_all(y);
            for (k, c) in coef.iter_mut().enumerate() {
                *c += w * u * p[k];
            }
        }
        for (k, c) in coef.iter_mut().enumerate() {
            *c *= (2.0 * k as f64 + 1.0) / 2.0;
        }
        let mut terms = NODES;
        let mut dropped = 0.0;
        while terms > 2 && dropped + coef[terms - 1].abs() <= 1e-15 {
            dropped += coef[terms - 1].abs();
            terms -= 1;
        }
        let m = to_monomial(&coef[..terms]);
        self.inverse.copy_from_slice(&m[..NODES]);
        self.inverse_terms = terms;
        self.inverse_exact = (0..=40).all(|k| {
            let y = f64::from(k) / 20.0 - 1.0;
            let target = 0.5 * (y + 1.0) * len;
            (self.eval(self.guess(y)).0 - target).abs() <= tol
        });
    }

    /// The parameter at `u` (the ends exactly).
    #[inline]
    fn t_at(&self, u: f64) -> f64 {
        if u <= -1.0 {
            self.a
        } else if u >= 1.0 {
            self.b
        } else {
            (self.mid + self.half * u).clamp(self.a, self.b)
        }
    }
}

/// The arc-length parametrisation of a curve: the same trace on `[0, L]` at unit speed.
///
/// `s(t) = SPEED_SCALE · ∫_{t0}^{t} |c′(τ)| dτ` with the speed measure of the sphere
/// ([`Manifold::SPEED_SCALE`]): great-circle arc length on S² and S^m, where the reparametrised
/// curve has `|γ′(s)| = 1`; the **rotation angle** turned on S³, where `|ω| = 2|γ′| = 1` (so
/// `|γ′| = 1/2` in ambient ℝ⁴). `L = s(t1)` is the [`length`](Self::length).
///
/// [`ArcLength`] implements [`Curve`] on `[0, L]`: `γ(s) = c(t(s))` with, by the chain rule
/// (`k = SPEED_SCALE`, `σ = k|c′|`, `c′ = c′(t)`, `c″ = c″(t)`),
///
/// ```text
/// γ′(s) = c′ / σ
/// γ″(s) = (c″ − c′·(c′·c″)/|c′|²) / σ²
/// ```
///
/// Its joints are the images `s(tᵢ)` of the curve's joints (the two joints of a collapsed
/// zero-length piece have one image), and parameters outside `[0, L]` are clamped, as for every
/// curve.
///
/// # Construction and accuracy
///
/// Each piece between joints is cut into cells by adaptive bisection. On a cell the speed is
/// sampled at the 10 Gauss–Legendre nodes and interpolated by its Legendre series, whose integral
/// gives `s(t)` in closed form (the cell's length is the Gauss–Legendre sum). A cell is accepted
/// when the interpolant matches the speed at the nodes of both halves to `accuracy / (t1 − t0)`,
/// so that `s(t)` is within `accuracy` of the true arc length everywhere (as are the positions
/// `γ(s)` along the curve). The table of cumulative lengths at the cell ends gives `s ↦ t` by a
/// lookup (one bin per cell over `[0, L]` narrows the search to the few cells the bin holds)
/// and, on the cell, a fitted series of the inverse map; where that series is not
/// within a quarter of the cell's share of the accuracy, Newton's method on the cell's
/// polynomial, safeguarded by bisection, finishes the solve to rounding. So
/// [`param_at`](Self::param_at) inverts [`arc_length_at`](Self::arc_length_at) to
/// `accuracy / 4` or better (exactly, up to rounding, on pieces of constant speed). The cost is a
/// few cells per piece (one for a piece of constant speed), so construction is `O(pieces)`
/// evaluations of the curve (about 30 to 100 per piece; at most about 2048 cells per piece, see
/// [`ArcLengthInfo::unresolved`]), and evaluation is one jet of the curve plus the lookup, one or
/// two polynomial evaluations and the chain rule (one square root, one division). Batches
/// ([`Curve::jet_many`], [`Curve::eval_many`]) map the parameters first and then call the
/// curve's own batch evaluation, which steps through its pieces. The velocity is exactly unit
/// speed (`σ` uses the curve's exact speed at `t(s)`); the derivatives are those of the exact
/// arc-length curve at the point `c(t(s))`.
///
/// # Stalls
///
/// Where the curve's speed vanishes there is no unit tangent `c′/|c′|`. A piece of length at
/// most `accuracy / 1024` (identical keys) is collapsed. At a parameter where `σ = 0` (a cusp),
/// that is `|c′| ≤ 64ε·(t1 − t0)·|c″|` where the direction of `c′` is rounding noise, or where
/// the formula overflows next to one, the velocity is the one-sided limit
/// `±â/k` with `â` the unit tangential part of `c″` (`+` from the right, `−` from the left) and
/// the acceleration is the normal part `−γ/k²` only (the curvature of the arc-length curve is
/// unbounded at a cusp); if `c″` vanishes too, both are zero. Nothing is NaN. The places are
/// listed in [`ArcLengthInfo::stalls`].
///
/// # Examples
///
/// ```
/// use spherekit::{ArcLength, Curve, Manifold, Squad, UnitQuat};
/// use spherekit::glam::DVec3;
///
/// let keys: Vec<UnitQuat> = (0..4)
///     .map(|i| UnitQuat::from_axis_angle(DVec3::new(1.0, f64::from(i), 2.0), 0.6 * f64::from(i)).unwrap())
///     .collect();
/// let c = ArcLength::try_new(Squad::try_new(keys, None).unwrap()).unwrap();
/// let len = c.length(); // radians of rotation
/// assert_eq!(c.domain(), [0.0, len]);
/// // Unit angular speed everywhere.
/// let j = c.jet(0.3 * len);
/// let (omega, _) = spherekit::angular_velocity_acceleration(j.point, j.velocity, j.acceleration);
/// assert!((omega.length() - 1.0).abs() < 1e-12);
/// // s ↦ t ↦ s.
/// let t = c.param_at(0.3 * len);
/// assert!((c.arc_length_at(t) - 0.3 * len).abs() < spherekit::DEFAULT_ARC_LENGTH_ACCURACY);
/// ```
#[derive(Clone, Debug)]
pub struct ArcLength<C: Curve> {
    curve: C,
    accuracy: f64,
    table: Table,
}

/// `SPEED_SCALE·|c′(t)|` from the given side: what the table is built from.
type Speed<'a> = dyn Fn(f64, Side) -> f64 + 'a;

/// Builds the cells of one piece. Not generic over the curve (the speed is a `&dyn Fn`): one
/// copy of the construction serves every curve and point type.
struct Builder<'a> {
    speed: &'a Speed<'a>,
    /// The pointwise speed tolerance `accuracy / (t1 − t0)`.
    tol: f64,
    cells: Vec<Cell>,
    depths: Vec<u32>,
    /// The smallest speed seen on each cell (at the nodes and the ends) and its parameter.
    minima: Vec<(f64, f64)>,
    evaluations: usize,
    unresolved: usize,
    /// The index of the first cell of the piece being built.
    piece_start: usize,
    /// `max(1, max(|t₀|, |t₁|)/(t₁ − t₀))` of the piece being built: a parameter of the piece
    /// is known to `ε·|t|`, so its speed, as a function of the position in the piece, carries
    /// rounding noise of about `ε·scale` times this.
    piece_rounding: f64,
}

impl Builder<'_> {
    /// `SPEED_SCALE·|c′|` at the nodes of `[a, b]` (left-sided on the right half, so that a node
    /// rounded onto the end stays on the piece).
    fn speeds(&mut self, a: f64, b: f64) -> Result<[f64; NODES], ArcLengthError> {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        let mut out = [0.0; NODES];
        for (o, &x) in out.iter_mut().zip(&GL_X) {
            let t = (mid + half * x).clamp(a, b);
            let side = if x > 0.0 { Side::Left } else { Side::Right };
            let v = (self.speed)(t, side);
            self.evaluations += 1;
            if !v.is_finite() {
                return Err(ArcLengthError::NonFiniteSpeed { t });
            }
            *o = v;
        }
        Ok(out)
    }

    /// Refines `[a, b]` whose node speeds are `sigma` and appends its cells.
    fn refine(
        &mut self,
        a: f64,
        b: f64,
        sigma: [f64; NODES],
        depth: u32,
    ) -> Result<(), ArcLengthError> {
        // Legendre coefficients of the interpolant of the speed at the nodes.
        let mut coef = [0.0; NODES];
        for (i, (&x, &w)) in GL_X.iter().zip(&GL_W).enumerate() {
            let p = legendre_all(x);
            for (k, c) in coef.iter_mut().enumerate() {
                *c += w * sigma[i] * p[k];
            }
        }
        for (k, c) in coef.iter_mut().enumerate() {
            *c *= (2.0 * k as f64 + 1.0) / 2.0;
        }
        let scale = sigma.iter().fold(0.0_f64, |m, &x| m.max(x));
        let tol = self
            .tol
            .max(64.0 * f64::EPSILON * scale * self.piece_rounding);
        let mid = 0.5 * (a + b);
        let splittable = depth < MAX_DEPTH
            && a < mid
            && mid < b
            && self.cells.len() - self.piece_start < MAX_CELLS_PER_PIECE;
        if splittable {
            let left = self.speeds(a, mid)?;
            let right = self.speeds(mid, b)?;
            let mut err = 0.0_f64;
            for (i, &x) in GL_X.iter().enumerate() {
                for (u, actual) in [(0.5 * (x - 1.0), left[i]), (0.5 * (x + 1.0), right[i])] {
                    let p = legendre_all(u);
                    let approx: f64 = coef.iter().zip(&p).map(|(c, p)| c * p).sum();
                    err = err.max((approx - actual).abs());
                }
            }
            if err > 0.5 * tol || err.is_nan() {
                self.refine(a, mid, left, depth + 1)?;
                return self.refine(mid, b, right, depth + 1);
            }
        } else {
            self.unresolved += 1;
        }
        // Drop trailing coefficients worth at most half the tolerance (|P_k| ≤ 1 on [−1, 1]):
        // a piece of constant speed keeps one term.
        let mut terms = NODES;
        let mut dropped = 0.0;
        while terms > 1 && dropped + coef[terms - 1].abs() <= 0.5 * tol {
            dropped += coef[terms - 1].abs();
            terms -= 1;
        }
        let half = 0.5 * (b - a);
        let mut speed = [0.0; NODES];
        for k in 0..terms {
            speed[k] = coef[k] * half;
        }
        // ∫_{−1}^{u} P_0 = P_1 + P_0, ∫_{−1}^{u} P_k = (P_{k+1} − P_{k−1})/(2k+1).
        let mut integral = [0.0; NODES + 1];
        for k in 0..terms {
            if k == 0 {
                integral[0] += speed[0];
                integral[1] += speed[0];
            } else {
                let d = speed[k] / (2.0 * k as f64 + 1.0);
                integral[k + 1] += d;
                integral[k - 1] -= d;
            }
        }
        // The Gauss–Legendre sum, `half·Σ wᵢσᵢ = 2·speed[0]`.
        let length = 2.0 * speed[0];
        self.cells.push(Cell {
            a,
            b,
            mid,
            half,
            s0: 0.0,
            s1: length,
            terms,
            speed,
            integral,
            monomial: [0.0; NODES + 1],
            inverse_terms: 2,
            inverse: [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            inverse_exact: false,
            two_over_len: 0.0,
        });
        self.depths.push(depth);
        // The smallest speed: at the nodes (sampled) or at the ends (interpolated; a zero of
        // the speed at a cell end is a kink the bisection put there).
        let ends = [-1.0_f64, 1.0].map(|u| {
            let sign_odd = if u < 0.0 { -1.0 } else { 1.0 };
            let v: f64 = coef[..terms]
                .iter()
                .enumerate()
                .map(|(k, c)| if k % 2 == 1 { c * sign_odd } else { *c })
                .sum();
            (v.max(0.0), if u < 0.0 { a } else { b })
        });
        let nodes = GL_X
            .iter()
            .zip(&sigma)
            .map(|(&x, &v)| (v, (mid + half * x).clamp(a, b)));
        let minimum = ends
            .into_iter()
            .chain(nodes)
            .fold((f64::INFINITY, a), |m, x| if x.0 < m.0 { x } else { m });
        self.minima.push(minimum);
        Ok(())
    }
}

/// # Construction
impl<C: Curve> ArcLength<C> {
    /// The arc-length parametrisation to [`DEFAULT_ARC_LENGTH_ACCURACY`].
    ///
    /// # Errors
    ///
    /// As [`try_with_accuracy`](Self::try_with_accuracy).
    pub fn try_new(curve: C) -> Result<Self, ArcLengthError> {
        Self::try_with_accuracy(curve, DEFAULT_ARC_LENGTH_ACCURACY)
    }

    /// The arc-length parametrisation with `s(t)` within `accuracy` radians of the true arc
    /// length (rotation angle on S³) everywhere.
    ///
    /// Accuracies below about `1e-14·L` are limited by rounding, and so are those below about
    /// `1e-14·L·|t|/h` on a piece of width `h` far from `t = 0`, whose parameters are only
    /// known to `ε·|t|`: there each cell is held to the rounding level instead of being halved
    /// in vain (a 1 000-key cubic at unit spacing, 840 rad long, built in 10 s before this
    /// rule and in milliseconds with it).
    ///
    /// # Errors
    ///
    /// [`ArcLengthError::InvalidAccuracy`] unless `accuracy` is positive and finite;
    /// [`ArcLengthError::ZeroLength`] for a curve of length at most `accuracy / 1024`;
    /// [`ArcLengthError::NonFiniteSpeed`] if the curve's velocity is not finite somewhere.
    pub fn try_with_accuracy(curve: C, accuracy: f64) -> Result<Self, ArcLengthError> {
        let speed =
            |t: f64, side: Side| curve.jet_at(t, side).velocity.length() * C::Point::SPEED_SCALE;
        let table = Table::build(curve.domain(), curve.joints(), accuracy, &speed)?;
        Ok(Self {
            curve,
            accuracy,
            table,
        })
    }
}

/// The table of an [`ArcLength`]: everything but the curve, built without knowing its type.
#[derive(Clone, Debug)]
struct Table {
    cells: Vec<Cell>,
    /// Indices of the cells of positive length, and their `s0` and `s1`.
    live: Vec<usize>,
    live_s0: Vec<f64>,
    live_s1: Vec<f64>,
    /// `bins[b]`: the last live cell starting at or before `b/bin_scale` (one bin per live
    /// cell over `[0, L]`), so that finding the cell of `s` is a search among a few cells.
    bins: Vec<u32>,
    bin_scale: f64,
    joints: Vec<f64>,
    info: ArcLengthInfo,
    /// `NOISE·(t1 − t0)`.
    noise: f64,
    /// `L`.
    length: f64,
}

impl Table {
    /// The construction of [`ArcLength::try_with_accuracy`] for a curve with this domain and
    /// these joints, from its speed.
    fn build(
        domain: [f64; 2],
        curve_joints: &[f64],
        accuracy: f64,
        speed: &Speed<'_>,
    ) -> Result<Self, ArcLengthError> {
        if !(accuracy.is_finite() && accuracy > 0.0) {
            return Err(ArcLengthError::InvalidAccuracy { accuracy });
        }
        let [t0, t1] = domain;
        let collapse = accuracy / 1024.0;
        let mut builder = Builder {
            speed,
            tol: accuracy / (t1 - t0),
            cells: Vec::new(),
            depths: Vec::new(),
            minima: Vec::new(),
            evaluations: 0,
            unresolved: 0,
            piece_start: 0,
            piece_rounding: 1.0,
        };
        let mut stalls = Vec::new();
        let mut joints = vec![0.0];
        let mut s = 0.0_f64;
        for w in curve_joints.windows(2) {
            let (a, b) = (w[0], w[1]);
            let first = builder.cells.len();
            builder.piece_start = first;
            builder.piece_rounding = (a.abs().max(b.abs()) / (b - a)).max(1.0);
            let sigma = builder.speeds(a, b)?;
            builder.refine(a, b, sigma, 0)?;
            let piece_len: f64 = builder.cells[first..].iter().map(|c| c.s1).sum();
            if piece_len <= collapse {
                for c in &mut builder.cells[first..] {
                    c.terms = 1;
                    c.speed = [0.0; NODES];
                    c.integral = [0.0; NODES + 1];
                    c.s0 = s;
                    c.s1 = s;
                }
                stalls.push(Stall { s, t: [a, b] });
                continue;
            }
            let slow = STALL_FRACTION * piece_len / (b - a);
            let mut open: Option<Stall> = None;
            for ((c, &depth), &(low, at)) in builder.cells[first..]
                .iter_mut()
                .zip(&builder.depths[first..])
                .zip(&builder.minima[first..])
            {
                let len = c.s1;
                c.s0 = s;
                s += len;
                c.s1 = s;
                // Deep cells around a kink of the speed, or a near-zero speed in a cell: one
                // stall per run of such cells, spanning the deep cells or the slowest parameter.
                let span = if depth >= STALL_DEPTH {
                    Some([c.a, c.b])
                } else if low <= slow {
                    Some([at, at])
                } else {
                    None
                };
                match (span, &mut open) {
                    (Some(span), Some(st)) => {
                        st.t[0] = st.t[0].min(span[0]);
                        st.t[1] = st.t[1].max(span[1]);
                    }
                    (Some(span), None) => open = Some(Stall { s: 0.0, t: span }),
                    (None, _) => stalls.extend(open.take()),
                }
            }
            stalls.extend(open.take());
            joints.push(s);
        }
        if s <= collapse {
            return Err(ArcLengthError::ZeroLength);
        }
        let Builder {
            cells,
            evaluations,
            unresolved,
            ..
        } = builder;
        // The inverse series stands in for Newton's method where it is within a quarter of the
        // cell's share of the accuracy (the speed interpolant takes at most half).
        let mut cells = cells;
        let per_t = accuracy / (t1 - t0);
        for c in &mut cells {
            c.finish();
            let len = c.s1 - c.s0;
            c.fit_inverse((0.25 * per_t * (c.b - c.a)).max(4.0 * f64::EPSILON * len));
        }
        let live: Vec<usize> = (0..cells.len())
            .filter(|&i| cells[i].s1 > cells[i].s0)
            .collect();
        let live_s0: Vec<f64> = live.iter().map(|&i| cells[i].s0).collect();
        let live_s1 = live.iter().map(|&i| cells[i].s1).collect();
        #[expect(clippy::cast_precision_loss, reason = "cell counts are small")]
        let bin_scale = live.len() as f64 / s;
        let bins = (0..live.len())
            .map(|b| {
                #[expect(clippy::cast_precision_loss, reason = "cell counts are small")]
                let start = b as f64 / bin_scale;
                let j = live_s0.partition_point(|&x| x <= start).saturating_sub(1);
                u32::try_from(j).unwrap_or(u32::MAX)
            })
            .collect();
        // One stall where runs meet at a joint.
        let mut merged: Vec<Stall> = Vec::with_capacity(stalls.len());
        for st in stalls {
            match merged.last_mut() {
                Some(last) if st.t[0] <= last.t[1] => last.t[1] = last.t[1].max(st.t[1]),
                _ => merged.push(st),
            }
        }
        let mut stalls = merged;
        for st in &mut stalls {
            st.s = s_at(&cells, domain, st.t[0]);
        }
        let info = ArcLengthInfo {
            stalls,
            cells: cells.len(),
            evaluations,
            unresolved,
        };
        Ok(Self {
            cells,
            live,
            live_s0,
            live_s1,
            bins,
            bin_scale,
            joints,
            info,
            noise: NOISE * (t1 - t0),
            length: s,
        })
    }
}

/// `s(t)` on the table `cells` of a curve over `domain` (`t` clamped to it).
fn s_at(cells: &[Cell], domain: [f64; 2], t: f64) -> f64 {
    let t = clamp_param(t, domain);
    let j = cells.partition_point(|c| c.a <= t).saturating_sub(1);
    cells[j].s_at(t)
}

/// # Access
impl<C: Curve> ArcLength<C> {
    /// The length `L` of the curve: radians of arc on S² and S^m, the rotation angle turned on
    /// S³.
    #[must_use]
    pub fn length(&self) -> f64 {
        self.table.length
    }

    /// The arc length `s(t)` from the start of the curve to its parameter `t` (clamped to the
    /// curve's domain): non-decreasing, `s(t0) = 0`, `s(t1) = L`.
    #[must_use]
    pub fn arc_length_at(&self, t: f64) -> f64 {
        s_at(&self.table.cells, self.curve.domain(), t)
    }

    /// The curve's parameter `t(s)` at arc length `s` (clamped to `[0, L]`): the inverse of
    /// [`arc_length_at`](Self::arc_length_at) to `accuracy / 4` in `s`, right-sided (past a
    /// collapsed zero-length piece, the start of the next piece).
    #[must_use]
    pub fn param_at(&self, s: f64) -> f64 {
        let (cell, u) = self.locate(s, Side::Right);
        self.table.cells[cell].t_at(u)
    }

    /// The accuracy the table was built for.
    #[must_use]
    pub fn accuracy(&self) -> f64 {
        self.accuracy
    }

    /// What the construction found: stalls, cells, evaluations.
    #[must_use]
    pub fn info(&self) -> &ArcLengthInfo {
        &self.table.info
    }

    /// The original curve.
    #[must_use]
    pub fn curve(&self) -> &C {
        &self.curve
    }

    /// Unwraps the original curve.
    #[must_use]
    pub fn into_inner(self) -> C {
        self.curve
    }

    /// The cell and local parameter of `s` (clamped); at a cell boundary `side` chooses the cell
    /// that ends there (`Left`) or starts there (`Right`).
    #[inline]
    fn locate(&self, s: f64, side: Side) -> (usize, f64) {
        let s = clamp_param(s, [0.0, self.length()]);
        let n = self.table.live.len();
        // The bin of `s` bounds the search: the last cell starting at or before `s` is in
        // `[lo, hi)` (each end checked, so that rounding of the bin edges cannot matter). Live
        // cells are consecutive, `live_s1[j] = live_s0[j + 1]`, both strictly increasing.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "s ≥ 0; the cast saturates and the bin is clamped"
        )]
        let b = ((s * self.table.bin_scale) as usize).min(self.table.bins.len() - 1);
        let mut lo = self.table.bins[b] as usize;
        let mut hi = self
            .table
            .bins
            .get(b + 1)
            .map_or(n, |&x| x as usize + 1)
            .min(n);
        if self.table.live_s0[lo] > s {
            lo = 0;
        }
        if hi < n && self.table.live_s0[hi] <= s {
            hi = n;
        }
        let j = match side {
            // The largest j with live_s0[j] ≤ s (live_s0[0] = 0 ≤ s).
            Side::Right => lo + self.table.live_s0[lo..hi].partition_point(|&x| x <= s) - 1,
            // The smallest j with live_s1[j] ≥ s (every j < lo − 1 has live_s1[j] < s).
            Side::Left => {
                let l = lo.saturating_sub(1);
                (l + self.table.live_s1[l..hi].partition_point(|&x| x < s)).min(n - 1)
            }
        };
        let cell = self.table.live[j];
        let c = &self.table.cells[cell];
        (cell, c.solve(s - c.s0))
    }
}

impl<C: Curve> Curve for ArcLength<C> {
    type Point = C::Point;

    fn domain(&self) -> [f64; 2] {
        [0.0, self.length()]
    }

    fn joints(&self) -> &[f64] {
        &self.table.joints
    }

    fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }

    fn is_antiperiodic(&self) -> bool {
        self.curve.is_antiperiodic()
    }

    fn jet_at(&self, s: f64, side: Side) -> Jet<C::Point> {
        let (t, inner) = self.curve_param(s, side);
        reparametrise(self.curve.jet_at(t, inner), side, self.table.noise)
    }

    fn eval(&self, s: f64) -> C::Point {
        match self.curve_param(s, Side::Right) {
            (t, Side::Right) => self.curve.eval(t),
            (t, Side::Left) => self.curve.jet_at(t, Side::Left).point,
        }
    }

    /// The curve's parameters of a chunk of `ss` at a time, then the curve's own batch
    /// evaluation (which steps through its pieces instead of searching for each sample), then
    /// the chain rule: the same values as [`jet`](Curve::jet), bit for bit, and no allocation.
    fn jet_many(&self, ss: &[f64], out: &mut [Jet<C::Point>]) {
        crate::knots::check_batch(ss, out);
        let mut ts = [0.0; BATCH];
        let mut left = [false; BATCH];
        for (ss, out) in ss.chunks(BATCH).zip(out.chunks_mut(BATCH)) {
            for (k, &s) in ss.iter().enumerate() {
                let (t, inner) = self.curve_param(s, Side::Right);
                ts[k] = t;
                left[k] = inner == Side::Left;
            }
            self.curve.jet_many(&ts[..ss.len()], out);
            for (k, o) in out.iter_mut().enumerate() {
                if left[k] {
                    *o = self.curve.jet_at(ts[k], Side::Left);
                }
                *o = reparametrise(o.clone(), Side::Right, self.table.noise);
            }
        }
    }

    /// As [`jet_many`](Self::jet_many), for points ([`eval`](Curve::eval), bit for bit).
    fn eval_many(&self, ss: &[f64], out: &mut [C::Point]) {
        crate::knots::check_batch(ss, out);
        let mut ts = [0.0; BATCH];
        let mut left = [false; BATCH];
        for (ss, out) in ss.chunks(BATCH).zip(out.chunks_mut(BATCH)) {
            for (k, &s) in ss.iter().enumerate() {
                let (t, inner) = self.curve_param(s, Side::Right);
                ts[k] = t;
                left[k] = inner == Side::Left;
            }
            self.curve.eval_many(&ts[..ss.len()], out);
            for (k, o) in out.iter_mut().enumerate() {
                if left[k] {
                    *o = self.curve.jet_at(ts[k], Side::Left).point;
                }
            }
        }
    }
}

/// Samples per chunk of [`ArcLength`]'s batch evaluation (its parameters live on the stack).
const BATCH: usize = 256;

impl<C: Curve> ArcLength<C> {
    /// The curve's parameter `t(s)` and the side of the curve's jet there: at a cell end the
    /// limit from inside the cell (the ends may be joints).
    #[inline]
    fn curve_param(&self, s: f64, side: Side) -> (f64, Side) {
        let (cell, u) = self.locate(s, side);
        let t = self.table.cells[cell].t_at(u);
        let inner = if u >= 1.0 {
            Side::Left
        } else if u <= -1.0 {
            Side::Right
        } else {
            side
        };
        (t, inner)
    }
}

/// The jet of the arc-length curve from the curve's jet (see the stall rule of [`ArcLength`]).
///
/// `noise` is the parameter distance from a zero of the velocity within which its direction is
/// rounding noise: `|c′| ≤ noise·|c″|`.
fn reparametrise<P: Manifold>(jet: Jet<P>, side: Side, noise: f64) -> Jet<P> {
    let k = P::SPEED_SCALE;
    let Jet {
        point,
        velocity: v,
        acceleration: a,
    } = jet;
    // While the squared norms are normal numbers: `γ′ = c′/σ` with `1/σ = |c′|/(k·|c′|²)` and
    // `γ″ = (c″ − c′·(c′·c″)/|c′|²)/σ²`, one square root and one division side by side (the
    // latency of this chain is most of the adapter's cost); from the lengths otherwise
    // (overflow, underflow), as written in the type's documentation.
    let (v2, a2, va) = (v.dot(&v), a.dot(&a), v.dot(&a));
    if v2 >= f64::MIN_POSITIVE && v2.is_finite() && a2.is_finite() {
        if v2 > noise * noise * a2 {
            let r = 1.0 / v2;
            let inv = r * v2.sqrt() * (1.0 / k);
            let velocity = v.clone() * inv;
            let acceleration = (a.clone() - v.clone() * (va * r)) * (r * (1.0 / (k * k)));
            if velocity.is_finite() && acceleration.is_finite() {
                return Jet {
                    point,
                    velocity,
                    acceleration,
                };
            }
        }
    } else {
        let vl = v.length();
        let sigma = k * vl;
        if sigma > 0.0 && vl > noise * a.length() {
            let inv = 1.0 / sigma;
            let velocity = v.clone() * inv;
            let acceleration =
                (a.clone() - v.clone() * (velocity.dot(&a) * (k * k * inv))) * (inv * inv);
            if velocity.is_finite() && acceleration.is_finite() {
                return Jet {
                    point,
                    velocity,
                    acceleration,
                };
            }
        }
    }
    // A stall: the direction of the tangential acceleration, the one-sided limit of c′/|c′|.
    let tangential = point.project_tangent(&a);
    let tl = tangential.length();
    let p = point.to_vector();
    if tl > 0.0 && tl.is_finite() {
        let sign = match side {
            Side::Right => 1.0,
            Side::Left => -1.0,
        };
        Jet {
            velocity: tangential * (sign / (k * tl)),
            acceleration: p * (-1.0 / (k * k)),
            point,
        }
    } else {
        let zero = p.zeros_like();
        Jet {
            point,
            velocity: zero.clone(),
            acceleration: zero,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_is_exact_to_degree_19() {
        let sum: f64 = GL_W.iter().sum();
        assert!((sum - 2.0).abs() < 1e-15, "weights sum to {sum}");
        for deg in 0..20_i32 {
            let q: f64 = GL_X.iter().zip(&GL_W).map(|(x, w)| w * x.powi(deg)).sum();
            let exact = if deg % 2 == 0 {
                2.0 / f64::from(deg + 1)
            } else {
                0.0
            };
            assert!((q - exact).abs() < 1e-15, "x^{deg}: {q} vs {exact}");
        }
    }

    #[test]
    fn legendre_integral_of_a_cubic() {
        // ds/du = 1 + u + u² + u³ on one cell of half-width 1; s(u) = ∫_{−1}^{u}.
        let f = |u: f64| 1.0 + u + u * u + u * u * u;
        let mut coef = [0.0; NODES];
        for (i, (&x, &w)) in GL_X.iter().zip(&GL_W).enumerate() {
            let p = legendre_all(x);
            for (k, c) in coef.iter_mut().enumerate() {
                *c += w * f(GL_X[i]) * p[k] * (2.0 * k as f64 + 1.0) / 2.0;
            }
        }
        let mut integral = [0.0; NODES + 1];
        integral[0] += coef[0];
        integral[1] += coef[0];
        for k in 1..NODES {
            let d = coef[k] / (2.0 * k as f64 + 1.0);
            integral[k + 1] += d;
            integral[k - 1] -= d;
        }
        let cell = Cell {
            a: -1.0,
            b: 1.0,
            mid: 0.0,
            half: 1.0,
            s0: 0.0,
            s1: 2.0 * coef[0],
            terms: NODES,
            speed: coef,
            integral,
            monomial: to_monomial(&integral),
            inverse_terms: 2,
            inverse: [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            inverse_exact: false,
            two_over_len: 1.0 / coef[0],
        };
        let big_f = |u: f64| u + u * u / 2.0 + u.powi(3) / 3.0 + u.powi(4) / 4.0;
        for u in [-1.0, -0.3, 0.2, 0.9, 1.0] {
            let (s, ds) = cell.eval(u);
            assert!((s - (big_f(u) - big_f(-1.0))).abs() < 1e-14, "s({u}) = {s}");
            assert!((ds - f(u)).abs() < 1e-13, "ds({u}) = {ds}");
            let back = cell.solve(s);
            assert!((back - u).abs() < 1e-13, "solve({s}) = {back}, not {u}");
        }
    }
}
