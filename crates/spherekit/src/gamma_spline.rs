// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The Gamma quaternion spline: Boehm's Gamma spline lifted to S³ with Kim's cubic cumulative
//! Bézier quaternion curves as segments.

use glam::{DQuat, DVec3};

use crate::curve::{Curve, Jet, Side};
use crate::error::SplineError;
use crate::geodesic::{check_chain, check_loop, wrapped};
use crate::kim::{Factor, Rate, body_log, cubic_bezier_basis, cumulative_jet, cumulative_point};
use crate::knots::Knots;
use crate::manifold::Manifold;
use crate::s3::UnitQuat;

/// The shape parameters `γ₁ … γₗ₋₁` of a [`GammaSpline`] (scene field `params.gamma`).
#[derive(Clone, Debug, PartialEq)]
pub enum Gammas {
    /// One value for every interior knot (a number in the scene; the default is `All(1.0)`).
    All(f64),
    /// One value per interior knot, `γ₁ … γₗ₋₁` (a list in the scene).
    Each(Vec<f64>),
}

impl Default for Gammas {
    fn default() -> Self {
        Self::All(1.0)
    }
}

/// Which edge carries the control vertex `b₃ₗ₋₂` of the last segment (scene field
/// `params.last_edge`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LastEdge {
    /// The paper's formula: `b₃ₗ₋₂` on the arc `dₗ dₗ₊₁` (`"formula"`, the default).
    #[default]
    Formula,
    /// The paper's Example 2 table: `b₃ₗ₋₂` on the arc `dₗ₊₁ dₗ₊₂` at the same fraction
    /// (`"paper-example"`); `b₃ₗ₋₃` follows from it. No effect for `l = 1`, where `b₁ = d₁`.
    PaperExample,
}

impl LastEdge {
    /// Parses the scene name: `"formula"` or `"paper-example"`.
    ///
    /// # Errors
    ///
    /// [`SplineError::InvalidParameter`] named `last_edge` for any other name.
    pub fn from_name(name: &str) -> Result<Self, SplineError> {
        match name {
            "formula" => Ok(Self::Formula),
            "paper-example" => Ok(Self::PaperExample),
            other => Err(SplineError::InvalidParameter {
                name: "last_edge",
                reason: format!("must be \"formula\" or \"paper-example\", got {other:?}"),
            }),
        }
    }

    /// The scene name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Formula => "formula",
            Self::PaperExample => "paper-example",
        }
    }
}

/// The second-order behaviour of a [`GammaSpline`] at one interior knot, from
/// [`GammaSpline::joint_report`].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GammaJoint {
    /// The knot index `j` (1..l − 1) of the joint `uⱼ`.
    pub index: usize,
    /// The knot `uⱼ`.
    pub knot: f64,
    /// `|S′(uⱼ⁺) − S′(uⱼ⁻)|` from the exact one-sided jets (0 up to rounding: the curve is C¹).
    pub first_derivative_jump: f64,
    /// `|S″(uⱼ⁺) − S″(uⱼ⁻)|` from the exact one-sided jets.
    pub second_derivative_jump: f64,
    /// The residual of the general-spacing C² condition (`docs/derivations.md#gamma-c2-general`),
    /// `Aᵢ/Δᵢ₋₁² + Rᵢ/Δᵢ₋₂² − Lᵢ/(Δᵢ₋₂Δᵢ₋₁)` with `i = j + 1`; the second-derivative jump is
    /// `6·b₃ⱼ·residual`, so its norm is 6 × this norm.
    pub general_residual: DVec3,
    /// The left side `2 log(b₃ᵢ₋₄⁻¹ b₃ᵢ₋₃)` of the paper's condition (5), `i = j + 1`.
    pub paper_lhs: DVec3,
    /// The right side of (5):
    /// `(Δᵢ₋₁/Wᵢ) log(dᵢ⁻¹dᵢ₊₁) + (Δᵢ₋₂/Wᵢ₋₁) c⁻¹ log(dᵢ₋₁⁻¹dᵢ) c`, `c = b₃ᵢ₋₄⁻¹ b₃ᵢ₋₃`.
    pub paper_rhs: DVec3,
    /// `|paper_lhs − paper_rhs|`. Condition (5) is C² only for equal spacings on both sides
    /// (see [`uniform`](Self::uniform)); then the jump is `6·|residual|/Δ²`.
    pub paper_residual: f64,
    /// `true` when the knot spacings on both sides are equal, where (5) is the right condition.
    pub uniform: bool,
}

/// The Gamma quaternion spline of Chen, Wang, Liu, He and Zhou (2022), §3, with general knot
/// spacings.
///
/// Inputs: auxiliary vertices `d₀ … dₗ₊₂` on S³ (l ≥ 1 segments), knots `u₀ < … < uₗ` with
/// spacings `Δᵢ = uᵢ₊₁ − uᵢ`, shape parameters `γ₁ … γₗ₋₁ > 0`. With `G[p, q](s) =
/// p·exp(s·log(p⁻¹q))` (slerp, no sign flips) and the boundary convention `γ₀Δ₋₁ = γₗΔₗ = 0`:
///
/// ```text
/// Wᵢ    = γᵢ₋₁Δᵢ₋₂ + Δᵢ₋₁ + γᵢΔᵢ                                   i = 1..l
/// b₃ᵢ₋₂ = G[dᵢ, dᵢ₊₁]( γᵢ₋₁Δᵢ₋₂ / Wᵢ )                             (2)
/// b₃ᵢ₋₁ = G[dᵢ, dᵢ₊₁]( (γᵢ₋₁Δᵢ₋₂ + Δᵢ₋₁) / Wᵢ )                    (3)
/// b₃ᵢ   = G[b₃ᵢ₋₁, b₃ᵢ₊₁]( Δᵢ₋₁ / (Δᵢ₋₁ + Δᵢ) )                     (4), i = 1..l − 1
/// b₀ = d₀,  b₃ₗ = dₗ₊₂        (so b₁ = d₁, b₃ₗ₋₁ = dₗ₊₁: the paper's first/last-segment rules)
///
/// S(u) = b₃ᵢ₋₃ · exp(ω₃ᵢ₋₂ B̃₁,₃(τ)) · exp(ω₃ᵢ₋₁ B̃₂,₃(τ)) · exp(ω₃ᵢ B̃₃,₃(τ)),
///        u ∈ [uᵢ₋₁, uᵢ], τ = (u − uᵢ₋₁)/Δᵢ₋₁,  ωₖ = log(bₖ₋₁⁻¹ bₖ)
/// ```
///
/// Each segment is Kim's cubic cumulative Bézier quaternion curve ([`BezierKim`](crate::BezierKim))
/// on `b₃ᵢ₋₃ … b₃ᵢ`; derivatives are exact. `S(u₀) = d₀`, `S(uᵢ) = b₃ᵢ`, `S(uₗ) = dₗ₊₂`.
///
/// # Continuity
///
/// **C¹** at every knot for all `γᵢ > 0` and all spacings (Theorem 1): `b₃ᵢ` divides the arc
/// `b₃ᵢ₋₁b₃ᵢ₊₁` in the ratio `Δᵢ₋₁ : Δᵢ`, and both one-sided derivatives equal
/// `3/(Δᵢ₋₁ + Δᵢ)·b₃ᵢ·log(b₃ᵢ₋₁⁻¹ b₃ᵢ₊₁)`. **Not C² in general**, even for `γ = 1` (unlike the
/// Euclidean Gamma spline); it is C² with `γ = 1` when all `dₖ` lie on one great circle of S³.
/// [`joint_report`](Self::joint_report) gives, per joint, the residual of the paper's C² condition
/// (5) and of the general-spacing condition (`docs/derivations.md#gamma-c2-general`), whose
/// norm × 6 is the jump of S″.
///
/// # Corrections to the paper (`docs/derivations.md#gamma-knots` and following)
///
/// - The paper says "uniform knots" but keeps `Δᵢ` everywhere; general spacings are supported.
///   Its condition (5) is the C² condition only when the two spacings at the joint are equal.
/// - The segment formula's `B̃ⱼ,ₙ` is `B̃ⱼ,₃`; the first/last-segment rules are (2)–(4) under the
///   boundary convention above.
/// - **Example 2's table** prints `b₃` and `b₄` that do not follow the formulas: its `b₄` is
///   `G[d₃, d₄](½)`, i.e. the last-segment rule applied to the edge `dₗ₊₁dₗ₊₂` instead of
///   `dₗdₗ₊₁` (an index shift), and its `b₃` inherits that. The formulas are followed by default
///   ([`LastEdge::Formula`]); [`LastEdge::PaperExample`] reproduces the printed table. With
///   either reading Example 2 is **not** C² (the paper claims it is): the second derivative jumps
///   by 1.97 (formula) or 11.4 (paper's vertices) at `u₁`.
/// - `l = 1` (four vertices, no γ) is not covered by the paper; the boundary convention gives
///   `bₖ = dₖ`, i.e. Kim's cubic on `d₀ … d₃`, which is what is built.
///
/// # Closed loops
///
/// [`try_new_closed`](Self::try_new_closed) takes a periodic polygon `d₀ … d_{m−1}` (m ≥ 3), knots
/// `u₀ < … < u_m` (the last the time of the return) and one `γₖ` per knot `u₀ … u_{m−1}` (`γ₀`
/// at the seam). Segment `k` on `[u_k, u_{k+1}]` lies on the edge `d_k d_{k+1}` and every index
/// wraps around (`Δ₋₁ = Δ_{m−1}`, `d_m = d₀`, `γ_m = γ₀`):
///
/// ```text
/// W_k  = γ_kΔ_{k−1} + Δ_k + γ_{k+1}Δ_{k+1}
/// a_k  = G[d_k, d_{k+1}]( γ_kΔ_{k−1} / W_k ),   c_k = G[d_k, d_{k+1}]( (γ_kΔ_{k−1} + Δ_k) / W_k )
/// J_k  = G[c_{k−1}, a_k]( Δ_{k−1} / (Δ_{k−1} + Δ_k) )
/// segment k: Kim's cubic on J_k, a_k, c_k, J_{k+1}     (J_m = J₀)
/// ```
///
/// the open rules (2)–(4) without the boundary convention. Every joint, the seam included, is
/// then one of Theorem 1's, so the loop is C¹ at the seam as at the other knots (and C² under
/// the same conditions). The controls are `J₀, a₀, c₀, J₁, …, c_{m−1}, J₀`.
///
/// No short-path rule is applied: vertices are used as given (see [`unflip`](crate::unflip)).
///
/// # Examples
///
/// ```
/// use spherekit::{glam::DVec3, Curve, GammaSpline, Gammas, LastEdge, Manifold, UnitQuat};
///
/// let d: Vec<UnitQuat> = [0.0_f64, 0.5, 1.5, 1.8, 2.6, 3.0]
///     .iter()
///     .enumerate()
///     .map(|(k, &a)| UnitQuat::from_axis_angle(DVec3::new(1.0, k as f64 * 0.3, 0.2), a).unwrap())
///     .collect();
/// let s = GammaSpline::try_new(d.clone(), Some(vec![0.0, 1.0, 3.0, 3.5]), Gammas::All(0.7), LastEdge::Formula)
///     .unwrap();
/// assert_eq!(s.controls().len(), 10);
/// assert!(s.eval(0.0).dist(&d[0]) < 1e-15 && s.eval(3.5).dist(&d[5]) < 1e-15);
/// // C¹ at the interior knots for any γ and spacing.
/// for j in s.joint_report() {
///     assert!(j.first_derivative_jump < 1e-12, "{j:?}");
/// }
/// ```
#[derive(Clone, Debug)]
pub struct GammaSpline {
    points: Vec<UnitQuat>,
    closed: bool,
    knots: Knots,
    gamma: Vec<f64>,
    last_edge: LastEdge,
    controls: Vec<UnitQuat>,
    omegas: Vec<DVec3>,
    rates: Vec<Rate>,
}

impl GammaSpline {
    /// Builds the spline from `l + 3 ≥ 4` auxiliary vertices `d₀ … dₗ₊₂`.
    ///
    /// `knots` are `u₀ … uₗ` (default `0, 1, …, l`); `gamma` gives `γ₁ … γₗ₋₁`.
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 4 vertices;
    /// - [`SplineError::Antipodal`] for antipodal consecutive vertices `dₖ, dₖ₊₁` (every edge is
    ///   used by a geodesic or a logarithm);
    /// - the knot errors of [`Knots::or_uniform`] (`l + 1` knots, finite, strictly increasing);
    /// - [`SplineError::InvalidParameter`] named `gamma` for a non-finite or non-positive γ, a
    ///   list whose length is not `l − 1`, or when the resulting control vertices `b₃ᵢ₋₁` and
    ///   `b₃ᵢ₊₁` are antipodal (no geodesic for (4)).
    pub fn try_new(
        points: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
        gamma: Gammas,
        last_edge: LastEdge,
    ) -> Result<Self, SplineError> {
        check_chain(&points, 4)?;
        let l = points.len() - 3;
        let knots = Knots::or_uniform(knots, l + 1)?;
        let gamma = expand_gammas(gamma, l - 1, "one value per interior knot")?;
        let controls = control_vertices(&points, &knots, &gamma, last_edge)?;
        Self::finish(points, knots, gamma, last_edge, controls, false)
    }

    /// Builds the closed loop of the periodic polygon `points = d₀ … d_{m−1}` (m ≥ 3; type docs,
    /// *Closed loops*); `knots` are `u₀ … u_m` (default `0, 1, …, m`), `gamma` gives
    /// `γ₀ … γ_{m−1}`, one per knot, `γ₀` at the seam.
    ///
    /// # Errors
    ///
    /// [`SplineError::TooFewPoints`] for fewer than 3 vertices; [`SplineError::Antipodal`] /
    /// [`SplineError::AntipodalClosing`] for antipodal consecutive vertices or an antipodal last
    /// and first; the knot errors of [`Knots::or_uniform`] (`m + 1` knots);
    /// [`SplineError::InvalidParameter`] named `gamma` as for [`try_new`](Self::try_new), with
    /// `m` values in a list.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, glam::DVec3, Curve, GammaSpline, Gammas, UnitQuat};
    ///
    /// let q = |x: f64, y: f64| UnitQuat::from_axis_angle(DVec3::new(x, y, 1.0), 0.8).unwrap();
    /// let d = vec![q(1.0, 0.0), q(0.0, 1.0), q(-1.0, 0.0), q(0.0, -1.0)];
    /// let s = GammaSpline::try_new_closed(d, None, Gammas::All(0.7)).unwrap();
    /// assert_eq!(s.domain(), [0.0, 4.0]);
    /// let seam = continuity(&s)[3];
    /// assert!(seam.t == 4.0 && seam.c0 < 1e-15 && seam.c1 < 1e-12);
    /// ```
    pub fn try_new_closed(
        points: Vec<UnitQuat>,
        knots: Option<Vec<f64>>,
        gamma: Gammas,
    ) -> Result<Self, SplineError> {
        check_loop(&points, 3)?;
        let m = points.len();
        let knots = Knots::or_uniform(knots, m + 1)?;
        let gamma = expand_gammas(gamma, m, "one value per knot but the last")?;
        let controls = closed_control_vertices(&wrapped(&points), &knots, &gamma)?;
        Self::finish(points, knots, gamma, LastEdge::Formula, controls, true)
    }

    fn finish(
        points: Vec<UnitQuat>,
        knots: Knots,
        gamma: Vec<f64>,
        last_edge: LastEdge,
        controls: Vec<UnitQuat>,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let omegas = controls
            .windows(2)
            .enumerate()
            .map(|(k, w)| {
                body_log(w[0], w[1]).ok_or_else(|| SplineError::InvalidParameter {
                    name: "gamma",
                    reason: format!(
                        "gives antipodal control vertices b{k} and b{}; change gamma, knots or points",
                        k + 1
                    ),
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let rates = omegas.iter().copied().map(Rate::new).collect();
        Ok(Self {
            points,
            closed,
            knots,
            gamma,
            last_edge,
            controls,
            omegas,
            rates,
        })
    }

    /// The auxiliary vertices `d₀ … dₗ₊₂` (closed: the periodic polygon `d₀ … d_{m−1}`).
    #[must_use]
    pub fn points(&self) -> &[UnitQuat] {
        &self.points
    }

    /// The control vertices `b₀ … b₃ₗ` (closed: `J₀, a₀, c₀, J₁, …, c_{m−1}, J₀`).
    #[must_use]
    pub fn controls(&self) -> &[UnitQuat] {
        &self.controls
    }

    /// The knots `u₀ … uₗ`.
    #[must_use]
    pub fn knots(&self) -> &Knots {
        &self.knots
    }

    /// The shape parameters `γ₁ … γₗ₋₁` (closed: `γ₀ … γ_{m−1}`).
    #[must_use]
    pub fn gamma(&self) -> &[f64] {
        &self.gamma
    }

    /// The reading of the last-segment rule in use ([`LastEdge::Formula`] for a closed loop,
    /// which has no last segment).
    #[must_use]
    pub fn last_edge(&self) -> LastEdge {
        self.last_edge
    }

    /// The number of segments `l`.
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.knots.segment_count()
    }

    /// Continuity data at every interior knot `u₁ … uₗ₋₁` (closed: at `u₁ … u_{m−1}` and at the
    /// seam `u_m ≡ u₀`, last): measured first- and second-derivative jumps, the residual of the
    /// general-spacing C² condition and of the paper's condition (5).
    #[must_use]
    pub fn joint_report(&self) -> Vec<GammaJoint> {
        let l = self.segment_count();
        let b = &self.controls;
        let d = &self.points;
        // Per segment s (0-based): its weight W and the edge of d it lies on.
        let (w, edge): (Vec<f64>, Vec<usize>) = if self.closed {
            (closed_weights(&self.knots, &self.gamma), (0..l).collect())
        } else {
            let w = weights(&self.knots, &self.gamma);
            (w[1..].to_vec(), (1..=l).collect())
        };
        let m = d.len();
        let log_d = |k: usize| body_log(d[k], d[(k + 1) % m]).unwrap_or(DVec3::ZERO);
        let [t0, t1] = self.domain();
        // (left segment, right segment, knot index).
        let mut joints: Vec<(usize, usize, usize)> = (1..l).map(|j| (j - 1, j, j)).collect();
        if self.closed {
            joints.push((l - 1, 0, l));
        }
        joints
            .into_iter()
            .map(|(sa, sb, j)| {
                let u = self.knots.as_slice()[j];
                let (dl, dr) = (self.knots.width(sa), self.knots.width(sb));
                let left = self.jet_at(u, Side::Left);
                let right = self.jet_at(if j == l { t0 } else { u }, Side::Right);
                debug_assert!(j < l || u == t1, "the seam is at the end");
                // c = b₃ᵢ₋₄⁻¹ b₃ᵢ₋₃ with b₃ᵢ₋₄ = c_a (the last inner control of the left segment)
                // and b₃ᵢ₋₃ the joint; c⁻¹ x c is the rotation of x by c̄.
                let cbar = (b[3 * sa + 2].conjugate() * b[3 * sa + 3]).conjugate();
                let big_l = body_log(b[3 * sa + 2], b[3 * sb + 1]).unwrap_or(DVec3::ZERO);
                let a = self.omegas[3 * sb + 1]; // log(a_b⁻¹ c_b)
                let bb = self.omegas[3 * sa + 1]; // log(a_a⁻¹ c_a)
                let r = cbar.rotate(bb);
                let general = a / (dr * dr) + r / (dl * dl) - big_l / (dl * dr);
                let paper_lhs = 2.0 * self.omegas[3 * sa + 2];
                let paper_rhs =
                    dr / w[sb] * log_d(edge[sb]) + dl / w[sa] * cbar.rotate(log_d(edge[sa]));
                GammaJoint {
                    index: j,
                    knot: u,
                    first_derivative_jump: (right.velocity - left.velocity).length(),
                    second_derivative_jump: (right.acceleration - left.acceleration).length(),
                    general_residual: general,
                    paper_lhs,
                    paper_rhs,
                    paper_residual: (paper_lhs - paper_rhs).length(),
                    uniform: dl == dr,
                }
            })
            .collect()
    }
}

/// The validated shape parameters, `count` of them (`what` says how many a list needs).
fn expand_gammas(gamma: Gammas, count: usize, what: &str) -> Result<Vec<f64>, SplineError> {
    let gamma = match gamma {
        Gammas::All(g) if !(g.is_finite() && g > 0.0) => {
            return Err(SplineError::InvalidParameter {
                name: "gamma",
                reason: format!("must be finite and positive, got {g}"),
            });
        }
        Gammas::All(g) => vec![g; count],
        Gammas::Each(v) if v.len() != count => {
            return Err(SplineError::InvalidParameter {
                name: "gamma",
                reason: format!("must have {what} ({count}), got {}", v.len()),
            });
        }
        Gammas::Each(v) => v,
    };
    if let Some((k, g)) = gamma
        .iter()
        .enumerate()
        .find(|(_, g)| !(g.is_finite() && **g > 0.0))
    {
        return Err(SplineError::InvalidParameter {
            name: "gamma",
            reason: format!("must be finite and positive, got γ{} = {g}", k + 1),
        });
    }
    Ok(gamma)
}

/// `W₀ … W_{m−1}` of a closed loop, `W_k = γ_kΔ_{k−1} + Δ_k + γ_{k+1}Δ_{k+1}` (indices mod m).
fn closed_weights(knots: &Knots, gamma: &[f64]) -> Vec<f64> {
    let m = knots.segment_count();
    (0..m)
        .map(|k| {
            let (prev, next) = ((k + m - 1) % m, (k + 1) % m);
            gamma[k] * knots.width(prev) + knots.width(k) + gamma[next] * knots.width(next)
        })
        .collect()
}

/// The control vertices `J₀, a₀, c₀, J₁, …, c_{m−1}, J₀` of a closed loop (type docs) from the
/// wrapped polygon `d₀ … d_{m−1}, d₀`.
fn closed_control_vertices(
    d: &[UnitQuat],
    knots: &Knots,
    gamma: &[f64],
) -> Result<Vec<UnitQuat>, SplineError> {
    let m = knots.segment_count();
    let w = closed_weights(knots, gamma);
    let inner: Vec<(UnitQuat, UnitQuat)> = (0..m)
        .map(|k| {
            let lw = gamma[k] * knots.width((k + m - 1) % m);
            (
                d[k].slerp(&d[k + 1], lw / w[k]),
                d[k].slerp(&d[k + 1], (lw + knots.width(k)) / w[k]),
            )
        })
        .collect();
    let mut b = Vec::with_capacity(3 * m + 1);
    for k in 0..m {
        let prev = (k + m - 1) % m;
        let (h0, h1) = (knots.width(prev), knots.width(k));
        let joint = inner[prev]
            .1
            .try_slerp(&inner[k].0, h0 / (h0 + h1))
            .map_err(|_| SplineError::InvalidParameter {
                name: "gamma",
                reason: format!(
                    "gives antipodal control vertices around knots[{k}]; change gamma, knots or points"
                ),
            })?;
        b.extend([joint, inner[k].0, inner[k].1]);
    }
    b.push(b[0]);
    Ok(b)
}

/// `W₁ … Wₗ` (index 0 unused) with the boundary convention `γ₀Δ₋₁ = γₗΔₗ = 0`.
fn weights(knots: &Knots, gamma: &[f64]) -> Vec<f64> {
    let l = knots.segment_count();
    let mut w = vec![0.0; l + 1];
    for (i, wi) in w.iter_mut().enumerate().skip(1) {
        *wi = left_weight(knots, gamma, i) + knots.width(i - 1) + right_weight(knots, gamma, i);
    }
    w
}

/// `γᵢ₋₁Δᵢ₋₂` (0 for i = 1).
fn left_weight(knots: &Knots, gamma: &[f64], i: usize) -> f64 {
    if i >= 2 {
        gamma[i - 2] * knots.width(i - 2)
    } else {
        0.0
    }
}

/// `γᵢΔᵢ` (0 for i = l).
fn right_weight(knots: &Knots, gamma: &[f64], i: usize) -> f64 {
    if i < knots.segment_count() {
        gamma[i - 1] * knots.width(i)
    } else {
        0.0
    }
}

/// The control vertices `b₀ … b₃ₗ` (eqs. (2)–(4) with the boundary convention `γ₀Δ₋₁ = γₗΔₗ = 0`).
/// The edges `dₖdₖ₊₁` are known not to be antipodal.
fn control_vertices(
    d: &[UnitQuat],
    knots: &Knots,
    gamma: &[f64],
    last_edge: LastEdge,
) -> Result<Vec<UnitQuat>, SplineError> {
    let l = knots.segment_count();
    let w = weights(knots, gamma);
    let mut b = vec![UnitQuat::IDENTITY; 3 * l + 1];
    b[0] = d[0];
    b[3 * l] = d[l + 2];
    for i in 1..=l {
        let lw = left_weight(knots, gamma, i);
        let (p, q) = if i == l && l >= 2 && last_edge == LastEdge::PaperExample {
            (d[l + 1], d[l + 2])
        } else {
            (d[i], d[i + 1])
        };
        b[3 * i - 2] = if i == 1 { d[1] } else { p.slerp(&q, lw / w[i]) };
        b[3 * i - 1] = if i == l {
            d[l + 1]
        } else {
            d[i].slerp(&d[i + 1], (lw + knots.width(i - 1)) / w[i])
        };
    }
    for i in 1..l {
        let (h0, h1) = (knots.width(i - 1), knots.width(i));
        b[3 * i] = b[3 * i - 1]
            .try_slerp(&b[3 * i + 1], h0 / (h0 + h1))
            .map_err(|_| SplineError::InvalidParameter {
                name: "gamma",
                reason: format!(
                    "gives antipodal control vertices b{} and b{} around knots[{i}]; change gamma, knots or points",
                    3 * i - 1,
                    3 * i + 1
                ),
            })?;
    }
    Ok(b)
}

crate::curve::piecewise_curve! {
    impl for GammaSpline {
        type Point = UnitQuat;
    }
}

impl GammaSpline {
    fn jet_local(&self, i: usize, s: f64) -> Jet<UnitQuat> {
        let (p, velocity, acceleration) =
            cumulative_jet(self.controls[3 * i].as_dquat(), &self.factors(i, s));
        Jet {
            point: self.point_at(i, s, p),
            velocity,
            acceleration,
        }
    }

    fn eval_local(&self, i: usize, s: f64) -> UnitQuat {
        let p = cumulative_point(self.controls[3 * i].as_dquat(), &self.factors(i, s));
        self.point_at(i, s, p)
    }
}

impl GammaSpline {
    /// The three factors of segment `i` at local parameter `s`.
    fn factors(&self, i: usize, s: f64) -> [Factor; 3] {
        let [b1, b2, b3] = cubic_bezier_basis(s, 1.0 / self.knots.width(i));
        [
            (self.rates[3 * i], b1),
            (self.rates[3 * i + 1], b2),
            (self.rates[3 * i + 2], b3),
        ]
    }

    /// The exact control vertex at the ends of segment `i`, the product elsewhere.
    fn point_at(&self, i: usize, s: f64, p: DQuat) -> UnitQuat {
        if s == 0.0 {
            self.controls[3 * i]
        } else if s == 1.0 {
            self.controls[3 * i + 3]
        } else {
            UnitQuat::new_unchecked(p)
        }
    }
}
