// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The cubic spherical Beta spline on S^m with bias β₁ and tension β₂, and its interpolation
//! solvers (Yang, Wang, Chen, Sun & He 2021; see `docs/references.md`).

#[cfg(any(test, not(feature = "compact")))]
use glam::{DVec3, DVec4};

use crate::ambient::{Ambient, VecN, span_basis};
use crate::beta_solve::{Coords, Settings, Shape, System};
use crate::bezier::CubicSegment;
use crate::curve::{Curve, Jet, Side, clamp_param};
use crate::error::{PointError, SolveError, SplineError};
use crate::manifold::Manifold;
#[cfg(any(test, feature = "compact"))]
use crate::recast::{Recast, to_sm};
use crate::slerp_jet::ScalarJet;

/// Two consecutive data points closer than this (radians) are [`SplineError::Coincident`]
/// (an input-hygiene threshold of spherekit, not of the paper).
pub const COINCIDENT_TOLERANCE: f64 = 1e-12;

/// A shape parameter of [`BetaSpline`]: one value for every point, or one value per point.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeParam {
    /// The same value at every point `0 … n`.
    Constant(f64),
    /// One value per point `0 … n` (exactly `n + 1` values).
    PerPoint(Vec<f64>),
}

impl From<f64> for ShapeParam {
    fn from(v: f64) -> Self {
        Self::Constant(v)
    }
}

impl From<Vec<f64>> for ShapeParam {
    fn from(v: Vec<f64>) -> Self {
        Self::PerPoint(v)
    }
}

impl ShapeParam {
    /// The `count` values, validated: finite, and `> 0` (`strict`) or `≥ 0`.
    fn expand(
        &self,
        name: &'static str,
        count: usize,
        strict: bool,
    ) -> Result<Vec<f64>, SplineError> {
        let values = match self {
            Self::Constant(v) => vec![*v; count],
            Self::PerPoint(v) if v.len() == count => v.clone(),
            Self::PerPoint(v) => {
                return Err(SplineError::InvalidParameter {
                    name,
                    reason: format!(
                        "must be one number or a list of {count} numbers (one per point), got a list of {}",
                        v.len()
                    ),
                });
            }
        };
        for (i, &v) in values.iter().enumerate() {
            let at = match self {
                Self::Constant(_) => String::new(),
                Self::PerPoint(_) => format!(" (element [{i}])"),
            };
            if !v.is_finite() {
                return Err(SplineError::InvalidParameter {
                    name,
                    reason: format!("must be finite, got {v}{at}"),
                });
            }
            if strict && v <= 0.0 {
                return Err(SplineError::InvalidParameter {
                    name,
                    reason: format!("must be > 0, got {v}{at}"),
                });
            }
            if !strict && v < 0.0 {
                return Err(SplineError::InvalidParameter {
                    name,
                    reason: format!("must be ≥ 0, got {v}{at}"),
                });
            }
        }
        Ok(values)
    }
}

/// The solver for the auxiliary vertices of an interpolating [`BetaSpline`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum BetaSolver {
    /// Newton's method on the block-tridiagonal system (13) with a line search (the default).
    #[default]
    Newton,
    /// The paper's Jacobi iteration (19), normalised, with its stopping rule.
    Jacobi,
}

impl BetaSolver {
    /// The scene name: `"newton"` or `"jacobi"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Newton => "newton",
            Self::Jacobi => "jacobi",
        }
    }

    /// Parses a scene name (`"newton"`, `"jacobi"`).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "newton" => Some(Self::Newton),
            "jacobi" => Some(Self::Jacobi),
            _ => None,
        }
    }

    fn default_residual_tolerance(self) -> f64 {
        match self {
            Self::Newton => 1e-12,
            Self::Jacobi => 1e-9,
        }
    }

    fn default_max_iterations(self) -> usize {
        match self {
            Self::Newton => 200,
            Self::Jacobi => 10_000,
        }
    }
}

/// The parameters of a [`BetaSpline`] (the scene's `params`).
///
/// | field | scene name | default | valid |
/// |---|---|---|---|
/// | `beta1` | `beta1` | 1 | finite, > 0; one number or `n + 1` numbers |
/// | `beta2` | `beta2` | 0 | finite, ≥ 0; one number or `n + 1` numbers |
/// | `interpolate` | `interpolate` | `true` | `points` are data points (`true`) or the auxiliary vertices |
/// | `solver` | `solver` | `"newton"` | `"newton"` or `"jacobi"` |
/// | `tolerance` | `tolerance` | 1e-26 | Jacobi's stopping threshold on `Σ‖Δdᵢ‖²` (the paper uses 1e-5); finite, > 0 |
/// | `residual_tolerance` | `residual_tolerance` | 1e-12 (Newton), 1e-9 (Jacobi) | largest allowed interpolation error (radians); finite, > 0 |
/// | `max_iterations` | `max_iterations` | 200 (Newton), 10 000 (Jacobi) | ≥ 1 |
#[derive(Clone, Debug, PartialEq)]
pub struct BetaParams {
    /// The bias β₁ (> 0) at each point.
    pub beta1: ShapeParam,
    /// The tension β₂ (≥ 0) at each point.
    pub beta2: ShapeParam,
    /// `true`: the points are data points to interpolate and the auxiliary vertices are
    /// solved for; `false`: the points are the auxiliary vertices `d₀ … dₙ`.
    pub interpolate: bool,
    /// The interpolation solver.
    pub solver: BetaSolver,
    /// Jacobi only: stop when `Σ‖dᵢ⁽ᵏ⁾ − dᵢ⁽ᵏ⁻¹⁾‖² <` this (default 1e-26; the paper's 1e-5
    /// leaves interpolation errors of order 1e-3).
    pub tolerance: Option<f64>,
    /// The largest allowed interpolation error in radians (default 1e-12 for Newton, its
    /// target; 1e-9 for Jacobi, its final check).
    pub residual_tolerance: Option<f64>,
    /// Iteration limit (default 200 for Newton, 10 000 for Jacobi).
    pub max_iterations: Option<usize>,
}

impl Default for BetaParams {
    fn default() -> Self {
        Self {
            beta1: ShapeParam::Constant(1.0),
            beta2: ShapeParam::Constant(0.0),
            interpolate: true,
            solver: BetaSolver::Newton,
            tolerance: None,
            residual_tolerance: None,
            max_iterations: None,
        }
    }
}

/// What the interpolation solver did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolveInfo {
    /// The solver used.
    pub solver: BetaSolver,
    /// Iterations performed (Newton: steps, including fallback Jacobi steps).
    pub iterations: usize,
    /// The largest geodesic distance (radians) between the curve at `t = i` and data point `i`.
    pub residual: f64,
}

/// The cubic spherical Beta spline (Yang, Wang, Chen, Sun & He 2021, §3–4) on any
/// sphere, with bias β₁ and tension β₂ per point, built from auxiliary vertices `d₀ … dₙ` or
/// interpolating data points `p₀ … pₙ`.
///
/// # Construction
///
/// With `G[a, b](s)` the slerp and, for `i = 0 … n` (eq. (7)),
///
/// ```text
/// γᵢ = 2(β₁ᵢ + 1) / (β₂ᵢ + 2β₁ᵢ(β₁ᵢ + 1))
/// ```
///
/// each arc `d_{i−1} dᵢ` (`i = 1 … n`) is cut in the angle ratios `γ_{i−1} : 1 : β₁ᵢ²·γᵢ`
/// (eqs. (4)–(5)), and the junctions divide the arcs between neighbouring cuts (eq. (6)):
///
/// ```text
/// Dᵢ        = γ_{i−1} + 1 + β₁ᵢ²·γᵢ
/// q_{i−1,1} = G[d_{i−1}, dᵢ](γ_{i−1} / Dᵢ)
/// q_{i−1,2} = G[d_{i−1}, dᵢ]((γ_{i−1} + 1) / Dᵢ)
/// q_{0,0} = d₀,   q_{i,0} = G[q_{i−1,2}, q_{i,1}](1/(1 + β₁ᵢ))  (i = 1 … n−1),   q_{n,0} = dₙ
/// X(t)      = Q[q_{i−1,0}, q_{i−1,1}, q_{i−1,2}, q_{i,0}](t − i + 1),   t ∈ [i − 1, i]
/// ```
///
/// with `Q` the cubic de Casteljau spherical Bézier curve ([`CubicSegment`], eqs. (2)–(3), with
/// exact derivatives). The curve is
/// analytic inside each segment, passes through `q_{i,0}` at `t = i`, and is **G¹** at every
/// joint: the unit tangents agree and `X′(i⁺) = β₁ᵢ·X′(i⁻)` (C¹ where β₁ᵢ = 1). It is not C² on
/// the sphere in general, even for β₁ = 1, β₂ = 0. On one great circle the angle is the
/// Euclidean cubic Beta spline (β₁ = 1, β₂ = 0: the uniform cubic B-spline).
///
/// # Corrections to the paper (`docs/derivations.md#beta-square` and following)
///
/// - The paper's eq. (14) drops the square of β₁ that eqs. (4)–(5) carry; β₁² is used
///   everywhere (only that reading satisfies the Beta constraints on a great circle).
/// - Theorem 1 and eq. (8) state the speed ratio at joint `i` as β₁,ᵢ₋₁; eq. (6) gives β₁ᵢ,
///   which is what is implemented and tested.
/// - The examples label the parameters 1…4; they are indices 0…3 here.
///
/// # Interpolation (`interpolate = true`)
///
/// The auxiliary vertices solve `q_{i,0}(d_{i−1}, dᵢ, d_{i+1}) = pᵢ`, `i = 1 … n−1`, with
/// `d₀ = p₀`, `dₙ = pₙ` (eq. (13)); the initial guess is `dᵢ = pᵢ`.
///
/// - [`BetaSolver::Newton`] (default): Newton's method in tangent coordinates. Row `i` involves
///   only `d_{i−1}, dᵢ, d_{i+1}`, so the Jacobian (exact, from the derivatives of the slerps and
///   of the logarithm) is block tridiagonal and each iteration costs O(n). A backtracking line
///   search on `Σ dist(q_{i,0}, pᵢ)²` globalises it; when the search fails or the Jacobian is
///   singular, one Jacobi step is taken instead. Target: the largest interpolation error
///   below `residual_tolerance` (1e-12).
/// - [`BetaSolver::Jacobi`]: the paper's iteration (19) in the robust form of
///   `docs/derivations.md#beta-solver`,
///   normalised, stopped by the paper's rule `Σ‖Δdᵢ‖² < tolerance`, with an iteration limit and a
///   final check of the interpolation error against `residual_tolerance`.
///
/// Decisions the paper leaves open (`docs/derivations.md#beta-solver`): the Jacobi update is
/// normalised
/// (the literal update converges to the same points, more slowly); the residual is measured
/// on the original points as the geodesic distance `dist(X(i), pᵢ)`; both solvers start from
/// `dᵢ = pᵢ`. Newton has converged on every random problem where Jacobi did (and on some
/// where Jacobi diverges, test `newton_converges_where_jacobi_does`); the remaining failures
/// are problems without a solution near the data, which multistart experiments did not
/// rescue either. Consecutive data points closer than [`COINCIDENT_TOLERANCE`] are rejected.
/// The solvers compute in coordinates of an orthonormal basis of the span of the data, so
/// data on a low-dimensional great sphere of S^m cost as little as on S².
///
/// Either reports [`solve_info`](Self::solve_info) or fails with
/// [`SplineError::Solve`]`(`[`SolveError::NoConvergence`]`)`; it never returns a curve that
/// does not interpolate. Some data/parameter combinations have no solution (for example the
/// paper's Example 2 with β₁ = 0.1 at the joint t = 2, `docs/derivations.md#beta-examples`).
///
/// The paper's examples (§5; β₁ = 1, β₂ = 0, data normalised), measured
/// (tests `example_1_reference_values`, `paper_stopping_rule_reproduces_iteration_counts`, …):
///
/// | example | solver, stopping rule | iterations | residual (rad) |
/// |---|---|---|---|
/// | 1 | Jacobi, the paper's rule `Σ‖Δd‖² < 1e-5` | 8 | 3.4e-3 (fails the residual check) |
/// | 1 | Jacobi, `Σ‖Δd‖² < 1e-20` | 77 | 2.0e-10 |
/// | 1 | Jacobi, `Σ‖Δd‖² < 1e-26` (default) | 107 | 1.7e-13 |
/// | 1 | Newton (default) | 5 | 1.1e-16 |
/// | 2 | Jacobi, the paper's rule | 4 | 4.5e-4 (fails the residual check) |
/// | 2 | Jacobi, `Σ‖Δd‖² < 1e-20` | 22 | 1.6e-11 |
/// | 2 | Jacobi, default | 29 | 2.1e-14 |
/// | 2 | Newton | 3 | 1.0e-13 |
///
/// Both give the same auxiliary vertices (Example 1: d₁ = (−0.7517, −0.1143, 0.6496),
/// d₂ = (0.2070, 0.8090, 0.5501)). Newton stops as soon as the residual is below a quarter of
/// `residual_tolerance`, hence 1e-13 rather than 1e-16 in Example 2. Both solvers take time
/// linear in n; their iterations and timings on random S² data are in `BENCHMARKS.md` (the
/// `solve` bench; `examples/beta_timing.rs`).
///
/// # Closed loops
///
/// [`try_new_closed`](Self::try_new_closed): the points `p₀ … p_{m−1}` (m ≥ 3) and every
/// index wrap around (`d_m = d₀`, `β₁,m = β₁,₀`): `m` arcs `d_j d_{j+1}` cut as above, a
/// junction `q_{i,0} = G[q_{i−1,2}, q_{i,1}](1/(1 + β₁ᵢ))` at every vertex, `q_{0,0}` included,
/// and `m` segments on `[0, m]` with `X(m) = X(0) = q_{0,0}`. Interpolating, the periodic system
/// `q_{i,0}(d_{i−1}, dᵢ, d_{i+1}) = pᵢ`, `i = 0 … m−1` (indices mod m, every `dᵢ` unknown),
/// is solved by the same Newton method on its block cyclic tridiagonal Jacobian (bordering,
/// O(m)), or by the Jacobi iteration on all vertices. The seam is a joint like the others: G¹
/// with `X′(0⁺) = β₁,₀·X′(m⁻)`.
///
/// # Double cover
///
/// On S³ the points are used as given; canonicalise with [`unflip`](crate::unflip) first.
///
/// # Examples
///
/// ```
/// use spherekit::{BetaParams, BetaSpline, Curve, Manifold, S2Point, Side};
/// use spherekit::glam::DVec3;
///
/// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
/// // Example 2 of the paper, with β₁ = 0.5 at the joint t = 1.
/// let data = vec![p(1.0, 0.0, 0.0), p(0.6852, -0.5424, 0.4861), p(0.7071, 0.0, 0.7071), p(0.0, 1.0, 0.0)];
/// let params = BetaParams { beta1: vec![1.0, 0.5, 1.0, 1.0].into(), ..BetaParams::default() };
/// let curve = BetaSpline::try_new(data.clone(), &params).unwrap();
/// for (i, d) in data.iter().enumerate() {
///     assert!(curve.eval(i as f64).dist(d) < 1e-12);
/// }
/// // G¹ at t = 1 with speed ratio β₁ = 0.5.
/// let (l, r) = (curve.jet_at(1.0, Side::Left).velocity, curve.jet_at(1.0, Side::Right).velocity);
/// assert!((r - l * 0.5).length() < 1e-9);
/// assert!(curve.solve_info().unwrap().residual < 1e-12);
/// ```
#[derive(Clone, Debug)]
pub struct BetaSpline<P: Manifold> {
    points: Vec<P>,
    aux: Vec<P>,
    /// `q_{0,0}, q_{0,1}, q_{0,2}, q_{1,0}, …, q_{n,0}`: `3n + 1` points.
    controls: Vec<P>,
    beta1: Vec<f64>,
    beta2: Vec<f64>,
    gamma: Vec<f64>,
    joints: Vec<f64>,
    info: Option<SolveInfo>,
    segments: Vec<CubicSegment<P>>,
    closed: bool,
}

impl<P: Manifold> BetaSpline<P> {
    /// Builds the spline from `points` (data points, or auxiliary vertices when
    /// `params.interpolate` is `false`).
    ///
    /// # Errors
    ///
    /// - [`SplineError::TooFewPoints`] for fewer than 2 points;
    /// - [`SplineError::InvalidPoint`] with [`PointError::WrongDimension`] for points of
    ///   spheres of different dimensions ([`SmPoint`](crate::SmPoint));
    /// - [`SplineError::InvalidParameter`] (`beta1`, `beta2`, `tolerance`,
    ///   `residual_tolerance`, `max_iterations`) for values out of range, non-finite, or lists
    ///   of a length other than `n + 1`;
    /// - [`SplineError::Antipodal`] for antipodal consecutive points;
    /// - [`SplineError::Coincident`] for consecutive data points closer than
    ///   [`COINCIDENT_TOLERANCE`] (when interpolating; coincident auxiliary vertices are
    ///   allowed);
    /// - [`SplineError::Solve`] when the interpolation solver does not reach its tolerance.
    pub fn try_new(points: Vec<P>, params: &BetaParams) -> Result<Self, SplineError> {
        Self::build(points, params, false)
    }

    /// Builds the closed loop through `points` (data points, or the periodic polygon of
    /// auxiliary vertices when `params.interpolate` is `false`), m ≥ 3, on `[0, m]` (type docs,
    /// *Closed loops*).
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new), with at least 3 points, and
    /// [`SplineError::AntipodalClosing`] / [`SplineError::CoincidentClosing`] for an antipodal
    /// (or, when interpolating, coincident) last and first point.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{continuity, BetaParams, BetaSpline, Curve, Manifold, S2Point};
    /// use spherekit::glam::DVec3;
    ///
    /// let p = |x, y, z| S2Point::try_new(DVec3::new(x, y, z)).unwrap();
    /// let data = vec![p(1.0, 0.0, 0.2), p(0.0, 1.0, 0.4), p(-1.0, 0.1, 0.3), p(0.1, -1.0, 0.1)];
    /// let c = BetaSpline::try_new_closed(data.clone(), &BetaParams::default()).unwrap();
    /// assert_eq!(c.domain(), [0.0, 4.0]);
    /// for (i, d) in data.iter().enumerate() {
    ///     assert!(c.eval(i as f64).dist(d) < 1e-12);
    /// }
    /// let seam = continuity(&c)[3]; // β₁ = 1: C¹ at the seam
    /// assert!(seam.t == 4.0 && seam.c0 < 1e-12 && seam.c1 < 1e-9);
    /// ```
    pub fn try_new_closed(points: Vec<P>, params: &BetaParams) -> Result<Self, SplineError> {
        Self::build(points, params, true)
    }

    /// The construction of [`try_new`](Self::try_new) and
    /// [`try_new_closed`](Self::try_new_closed): on `P` itself, or with the `compact` feature
    /// once on S^m for every point type ([`crate::recast`]; the same bits,
    /// `tests::the_construction_gives_the_same_bits_on_sm`).
    fn build(points: Vec<P>, params: &BetaParams, closed: bool) -> Result<Self, SplineError> {
        let min = if closed { 3 } else { 2 };
        if points.len() < min {
            return Err(SplineError::TooFewPoints {
                min,
                got: points.len(),
            });
        }
        #[cfg(not(feature = "compact"))]
        return Self::construct(points, params, closed);
        #[cfg(feature = "compact")]
        return Self::construct_on_sm(points, params, closed);
    }

    /// [`construct`](Self::construct) on the points as points of S^m, the result converted
    /// back; `points` is not empty.
    #[cfg(any(test, feature = "compact"))]
    fn construct_on_sm(
        points: Vec<P>,
        params: &BetaParams,
        closed: bool,
    ) -> Result<Self, SplineError> {
        let to = Recast::to(&points[0]);
        let sm = points.iter().map(to_sm).collect();
        let c = BetaSpline::construct(sm, params, closed)?;
        Ok(Self {
            points: to.points(&c.points),
            aux: to.points(&c.aux),
            controls: to.points(&c.controls),
            segments: c.segments.iter().map(|s| s.recast(&to)).collect(),
            beta1: c.beta1,
            beta2: c.beta2,
            gamma: c.gamma,
            joints: c.joints,
            info: c.info,
            closed: c.closed,
        })
    }

    /// The construction of [`build`](Self::build) on `P`, with at least the minimum number of
    /// points.
    fn construct(points: Vec<P>, params: &BetaParams, closed: bool) -> Result<Self, SplineError> {
        let count = points.len();
        let checked = Checked::new(params, count)?;
        let Checked {
            solver,
            tolerance,
            residual_tolerance,
            max_iterations,
            ..
        } = checked;
        let dim = points[0].to_vector().dim();
        if let Some(index) = points.iter().position(|q| q.to_vector().dim() != dim) {
            return Err(SplineError::InvalidPoint {
                index,
                reason: PointError::WrongDimension {
                    expected: dim,
                    got: points[index].to_vector().dim(),
                },
            });
        }
        if let Some(index) = points.windows(2).position(|w| w[0].is_antipodal(&w[1])) {
            return Err(SplineError::Antipodal { index });
        }
        let (first, last) = (&points[0], &points[count - 1]);
        if closed && last.is_antipodal(first) {
            return Err(SplineError::AntipodalClosing);
        }
        if params.interpolate
            && let Some(index) = points
                .windows(2)
                .position(|w| w[0].dist(&w[1]) <= COINCIDENT_TOLERANCE)
        {
            return Err(SplineError::Coincident { index });
        }
        if params.interpolate && closed && last.dist(first) <= COINCIDENT_TOLERANCE {
            return Err(SplineError::CoincidentClosing);
        }
        let (beta1, beta2) = (checked.beta1, checked.beta2);
        let (gamma, shape) = shape_of(&beta1, &beta2, closed)?;
        let (aux, info) = if params.interpolate && count > 2 {
            let settings = Settings {
                change_tolerance: tolerance,
                // The kernel works in coordinates of the data span; aim a little below the
                // tolerance so that the check on the original points passes.
                residual_tolerance: 0.25 * residual_tolerance,
                max_iterations,
            };
            let (aux, iterations) = solve(&points, &shape, solver, settings, closed)?;
            let controls = control_points(&aux, &shape, closed);
            let rows = if closed { 0..count } else { 1..count - 1 };
            let residual = match &controls {
                Ok(c) => rows
                    .map(|i| c[3 * i].dist(&points[i]))
                    .fold(0.0_f64, f64::max),
                Err(_) => f64::INFINITY,
            };
            // The residual on the original points decides, whether the stopping rule or the
            // iteration limit ended the iteration (NaN fails).
            if residual.is_nan() || residual > residual_tolerance {
                return Err(SolveError::NoConvergence {
                    iterations,
                    residual,
                }
                .into());
            }
            (
                aux,
                Some(SolveInfo {
                    solver,
                    iterations,
                    residual,
                }),
            )
        } else if params.interpolate {
            (
                points.clone(),
                Some(SolveInfo {
                    solver,
                    iterations: 0,
                    residual: 0.0,
                }),
            )
        } else {
            (points.clone(), None)
        };
        let controls = control_points(&aux, &shape, closed).map_err(|index| {
            if info.is_some() {
                SplineError::Solve(SolveError::NoConvergence {
                    iterations: info.map_or(0, |i| i.iterations),
                    residual: f64::INFINITY,
                })
            } else if closed && index + 1 == count {
                SplineError::AntipodalClosing
            } else {
                SplineError::Antipodal { index }
            }
        })?;
        let segments = controls
            .windows(4)
            .step_by(3)
            .map(|c| {
                CubicSegment::try_new([c[0].clone(), c[1].clone(), c[2].clone(), c[3].clone()])
            })
            .collect::<Result<Vec<_>, _>>()
            .map_err(|_| {
                SplineError::Solve(SolveError::NoConvergence {
                    iterations: info.map_or(0, |i| i.iterations),
                    residual: f64::INFINITY,
                })
            })?;
        Ok(Self {
            points,
            aux,
            controls,
            segments,
            beta1,
            beta2,
            gamma,
            joints: (0..count + usize::from(closed)).map(|i| i as f64).collect(),
            info,
            closed,
        })
    }

    /// The input points (data points when interpolating, otherwise the auxiliary vertices).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The auxiliary control vertices `d₀ … dₙ` (closed: the periodic polygon, one per point).
    #[must_use]
    pub fn auxiliary(&self) -> &[P] {
        &self.aux
    }

    /// All Bézier control points `q_{i,k}` in order: `q_{0,0}, q_{0,1}, q_{0,2}, q_{1,0}, q_{1,1},
    /// …, q_{n−1,2}, q_{n,0}` (`3n + 1` points; `q_{i,k}` is at index `3i + k`, and segment `i`
    /// uses indices `3(i−1) … 3i`).
    #[must_use]
    pub fn controls(&self) -> &[P] {
        &self.controls
    }

    /// The four control points of segment `i` (`0 ≤ i < n`, on `t ∈ [i, i + 1]`).
    ///
    /// # Panics
    ///
    /// If `i ≥ n`.
    #[must_use]
    pub fn segment_controls(&self, i: usize) -> &[P] {
        &self.controls[3 * i..3 * i + 4]
    }

    /// Segment `i` (`0 ≤ i < n`) as a cubic spherical Bézier curve on `s ∈ [0, 1]`, `s = t − i`.
    ///
    /// # Panics
    ///
    /// If `i ≥ n`.
    #[must_use]
    pub fn segment(&self, i: usize) -> &CubicSegment<P> {
        &self.segments[i]
    }

    /// The number of segments `n` (closed: one per point).
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.points.len() - usize::from(!self.closed)
    }

    /// β₁ at each point.
    #[must_use]
    pub fn beta1(&self) -> &[f64] {
        &self.beta1
    }

    /// β₂ at each point.
    #[must_use]
    pub fn beta2(&self) -> &[f64] {
        &self.beta2
    }

    /// γᵢ of eq. (7) at each point.
    #[must_use]
    pub fn gamma(&self) -> &[f64] {
        &self.gamma
    }

    /// What the interpolation solver did; `None` when built from auxiliary vertices.
    #[must_use]
    pub fn solve_info(&self) -> Option<SolveInfo> {
        self.info
    }
}

impl<P: Manifold> Curve for BetaSpline<P> {
    type Point = P;

    fn domain(&self) -> [f64; 2] {
        [0.0, self.segment_count() as f64]
    }

    fn joints(&self) -> &[f64] {
        &self.joints
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<P> {
        let (i, s) = self.locate(t, side);
        self.segments[i].jet(ScalarJet::param(s, 1.0))
    }

    fn eval(&self, t: f64) -> P {
        let (i, s) = self.locate(t, Side::Right);
        self.segments[i].eval(s)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [P]) {
        crate::knots::check_batch(ts, out);
        for (&t, o) in ts.iter().zip(out) {
            let (i, s) = self.locate(t, Side::Right);
            *o = self.segments[i].eval(s);
        }
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<P>]) {
        crate::knots::check_batch(ts, out);
        for (&t, o) in ts.iter().zip(out) {
            let (i, s) = self.locate(t, Side::Right);
            *o = self.segments[i].jet(ScalarJet::param(s, 1.0));
        }
    }
}

impl<P: Manifold> BetaSpline<P> {
    /// The segment containing `t` (clamped) and the local parameter in `[0, 1]`.
    fn locate(&self, t: f64, side: Side) -> (usize, f64) {
        let n = self.segment_count();
        let t = clamp_param(t, self.domain());
        let f = t.floor();
        // `t` is in [0, n], so the floor fits.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "t is clamped to [0, n]"
        )]
        let mut i = f as usize;
        let mut s = t - f;
        if s == 0.0 && i > 0 && (side == Side::Left || i == n) {
            i -= 1;
            s = 1.0;
        }
        (i.min(n - 1), s)
    }
}

/// The parameters of [`BetaParams`] checked and expanded for `count` points. Not generic over
/// the point type (one copy for every sphere).
struct Checked {
    beta1: Vec<f64>,
    beta2: Vec<f64>,
    solver: BetaSolver,
    tolerance: f64,
    residual_tolerance: f64,
    max_iterations: usize,
}

impl Checked {
    fn new(params: &BetaParams, count: usize) -> Result<Self, SplineError> {
        let beta1 = params.beta1.expand("beta1", count, true)?;
        let beta2 = params.beta2.expand("beta2", count, false)?;
        let solver = params.solver;
        let tolerance = positive(params.tolerance, "tolerance", 1e-26)?;
        let residual_tolerance = positive(
            params.residual_tolerance,
            "residual_tolerance",
            solver.default_residual_tolerance(),
        )?;
        let max_iterations = params
            .max_iterations
            .unwrap_or(solver.default_max_iterations());
        if max_iterations == 0 {
            return Err(SplineError::InvalidParameter {
                name: "max_iterations",
                reason: "must be at least 1".into(),
            });
        }
        Ok(Self {
            beta1,
            beta2,
            solver,
            tolerance,
            residual_tolerance,
            max_iterations,
        })
    }
}

/// `γ` per point and the shape constants, or the error when `β₁` is so large that they
/// overflow. Not generic over the point type.
fn shape_of(beta1: &[f64], beta2: &[f64], closed: bool) -> Result<(Vec<f64>, Shape), SplineError> {
    let gamma: Vec<f64> = beta1
        .iter()
        .zip(beta2)
        .map(|(&b1, &b2)| gamma(b1, b2))
        .collect();
    let shape = shape_constants(beta1, &gamma, closed);
    let in_unit = |v: &f64| (0.0..=1.0).contains(v);
    if !(shape.eta.iter().all(in_unit)
        && shape.omega.iter().all(in_unit)
        && shape.delta.iter().all(in_unit))
    {
        // Only for extreme values (β₁ beyond about 1e150), where β₁²·γ overflows.
        return Err(SplineError::InvalidParameter {
            name: "beta1",
            reason: "is too large: the arc ratios of eqs. (4)–(5) overflow".into(),
        });
    }
    Ok((gamma, shape))
}

/// γ of eq. (7).
fn gamma(b1: f64, b2: f64) -> f64 {
    2.0 * (b1 + 1.0) / (b2 + 2.0 * b1 * (b1 + 1.0))
}

/// `η, ω` per arc and `δ` per point (`docs/derivations.md#beta-system`); a closed loop has the
/// arc `d_{m−1} d₀` too.
fn shape_constants(beta1: &[f64], gamma: &[f64], closed: bool) -> Shape {
    let m = beta1.len();
    let arcs = if closed { m } else { m - 1 };
    let (mut eta, mut omega) = (Vec::with_capacity(arcs), Vec::with_capacity(arcs));
    for j in 0..arcs {
        let k = (j + 1) % m;
        let den = gamma[j] + 1.0 + beta1[k] * beta1[k] * gamma[k];
        eta.push(gamma[j] / den);
        omega.push((gamma[j] + 1.0) / den);
    }
    let delta = beta1.iter().map(|b| 1.0 / (1.0 + b)).collect();
    Shape { eta, omega, delta }
}

/// The `3n + 1` control points from the auxiliary vertices (closed: `3m + 1`, the last equal to
/// the first); `Err(index)` of the first antipodal pair of auxiliary vertices (or of a junction
/// whose neighbours are antipodal).
fn control_points<P: Manifold>(d: &[P], shape: &Shape, closed: bool) -> Result<Vec<P>, usize> {
    let m = d.len();
    let n = if closed { m } else { m - 1 };
    let mut inner = Vec::with_capacity(2 * n);
    for i in 0..n {
        let next = &d[(i + 1) % m];
        let a = d[i].try_slerp(next, shape.eta[i]).map_err(|_| i)?;
        let b = d[i].try_slerp(next, shape.omega[i]).map_err(|_| i)?;
        inner.push([a, b]);
    }
    let junction = |i: usize| {
        let prev = (i + n - 1) % n;
        inner[prev][1]
            .try_slerp(&inner[i][0], shape.delta[i])
            .map_err(|_| i)
    };
    let first = if closed { junction(0)? } else { d[0].clone() };
    let mut out = Vec::with_capacity(3 * n + 1);
    out.push(first.clone());
    for (i, [a, b]) in inner.iter().enumerate() {
        out.push(a.clone());
        out.push(b.clone());
        if i + 1 < n {
            out.push(junction(i + 1)?);
        }
    }
    out.push(if closed { first } else { d[n].clone() });
    Ok(out)
}

/// Validates an optional positive tolerance.
fn positive(v: Option<f64>, name: &'static str, default: f64) -> Result<f64, SplineError> {
    let v = v.unwrap_or(default);
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(SplineError::InvalidParameter {
            name,
            reason: format!("must be a finite number > 0, got {v}"),
        })
    }
}

/// Solves for the auxiliary vertices; returns them and the iteration count.
fn solve<P: Manifold>(
    points: &[P],
    shape: &Shape,
    solver: BetaSolver,
    settings: Settings,
    closed: bool,
) -> Result<(Vec<P>, usize), SplineError> {
    let vectors: Vec<P::Vector> = points.iter().map(Manifold::to_vector).collect();
    let basis = span_basis(points[0].to_vector().dim(), &vectors);
    let rank = basis.len();
    if rank < 2 {
        // Unreachable after the coincidence and antipodality checks; never index with r − 1 < 0.
        return Err(SolveError::NoConvergence {
            iterations: 0,
            residual: f64::INFINITY,
        }
        .into());
    }
    let coords: Vec<Vec<f64>> = vectors
        .iter()
        .map(|v| basis.iter().map(|b| b.dot(v)).collect())
        .collect();
    // S² and S³ solve in `DVec3` and `DVec4`, without allocation. The `compact` build runs
    // every rank in `VecN` (one copy of the kernel instead of three): padded to
    // the same 3 or 4 coordinates, it does the same operations on the same numbers in the same
    // order, so the result is the same bits (`tests::the_kernel_gives_the_same_bits_in_vecn`).
    #[cfg(not(feature = "compact"))]
    let (d, iterations, residual) = match rank {
        0..=3 => run::<DVec3>(&coords, rank, 3, shape, solver, settings, closed),
        4 => run::<DVec4>(&coords, rank, 4, shape, solver, settings, closed),
        _ => run::<VecN>(&coords, rank, rank, shape, solver, settings, closed),
    };
    #[cfg(feature = "compact")]
    let (d, iterations, residual) =
        run::<VecN>(&coords, rank, rank.max(3), shape, solver, settings, closed);
    let fail = SolveError::NoConvergence {
        iterations,
        residual,
    };
    // Open curves keep their end points; every vertex of a loop was solved for.
    let n = points.len() - 1;
    let mut aux = Vec::with_capacity(n + 1);
    for (i, c) in d.iter().enumerate() {
        if !closed && (i == 0 || i == n) {
            aux.push(points[i].clone());
            continue;
        }
        let mut v = vectors[0].zeros_like();
        for (b, &x) in basis.iter().zip(c) {
            v += b.clone() * x;
        }
        aux.push(P::try_from_vector(v).map_err(|_| fail.clone())?);
    }
    Ok((aux, iterations))
}

/// Runs the kernel in coordinate type `V`; returns the coordinates of `d₀ … dₙ`, the iteration
/// count and the kernel's residual.
fn run<V: Coords>(
    coords: &[Vec<f64>],
    rank: usize,
    dim: usize,
    shape: &Shape,
    solver: BetaSolver,
    settings: Settings,
    closed: bool,
) -> (Vec<Vec<f64>>, usize, f64) {
    let data: Vec<V> = coords
        .iter()
        .map(|c| {
            let v = V::from_coords(c, dim);
            let l = v.length();
            v * (1.0 / l)
        })
        .collect();
    let system = System::new(&data, shape, rank, dim, closed);
    let out = match solver {
        BetaSolver::Newton => system.solve_newton(settings),
        BetaSolver::Jacobi => system.solve_jacobi(settings),
    };
    let d = out
        .d
        .iter()
        .map(|v| (0..rank).map(|j| v.coord(j)).collect())
        .collect();
    (d, out.iterations, out.residual)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recast::keys;

    /// The `compact` build constructs on S^m and converts back; every field (and every error) must
    /// be what the construction on the point type itself gives, bit for bit (`{:?}` prints
    /// each `f64` in the shortest form that reads back to the same bits). (Without `compact` the
    /// S^m construction of these keys runs the `DVec3`/`DVec4` kernel; that the `compact`
    /// build's `VecN` kernel gives the same bits is `the_kernel_gives_the_same_bits_in_vecn`.)
    #[test]
    fn the_construction_gives_the_same_bits_on_sm() {
        fn check<P: Manifold>(points: &[P]) -> usize {
            let mut built = 0;
            let m = points.len();
            let per_point: Vec<f64> = (0..m).map(|i| 0.6 + 0.3 * i as f64).collect();
            for closed in [false, true] {
                for (beta1, beta2) in [
                    (ShapeParam::Constant(1.0), ShapeParam::Constant(0.0)),
                    (
                        ShapeParam::PerPoint(per_point.clone()),
                        ShapeParam::Constant(2.0),
                    ),
                ] {
                    for interpolate in [true, false] {
                        for solver in [BetaSolver::Newton, BetaSolver::Jacobi] {
                            let params = BetaParams {
                                beta1: beta1.clone(),
                                beta2: beta2.clone(),
                                interpolate,
                                solver,
                                ..BetaParams::default()
                            };
                            let native = BetaSpline::construct(points.to_vec(), &params, closed);
                            let on_sm =
                                BetaSpline::construct_on_sm(points.to_vec(), &params, closed);
                            built += keys::same_bits(&native, &on_sm, &(points, &params, closed));
                        }
                    }
                }
            }
            built
        }
        let built = keys::built(check, check);
        assert!(built > 50, "{built} curves built");
    }

    /// The `compact` build solves S² and S³ in `VecN` padded to 3 and 4 coordinates; it must give
    /// exactly what the native `DVec3` and `DVec4` kernels give.
    #[test]
    fn the_kernel_gives_the_same_bits_in_vecn() {
        let s2 = vec![
            vec![1.0, 0.0, 0.2],
            vec![0.3, 1.0, 0.1],
            vec![-0.7, 0.4, 0.6],
            vec![-0.2, -0.9, 0.3],
            vec![0.5, -0.5, -0.7],
        ];
        // On one great circle: rank 2, a zero third coordinate (closed, no solution: 200
        // iterations that must agree too).
        let circle = vec![
            vec![1.0, 0.0],
            vec![0.6, 0.8],
            vec![-0.28, 0.96],
            vec![-0.8, 0.6],
        ];
        let s3 = vec![
            vec![1.0, 0.0, 0.0, 0.1],
            vec![0.9, 0.4, 0.0, 0.2],
            vec![0.5, 0.5, 0.5, -0.5],
            vec![0.0, 0.3, 0.9, 0.2],
            vec![-0.4, 0.1, 0.5, 0.7],
        ];
        let settings = Settings {
            change_tolerance: 1e-14,
            residual_tolerance: 1e-14,
            max_iterations: 200,
        };
        let bits = |(d, i, r): (Vec<Vec<f64>>, usize, f64)| {
            let d: Vec<Vec<u64>> = d
                .iter()
                .map(|v| v.iter().map(|x| x.to_bits()).collect())
                .collect();
            (d, i, r.to_bits())
        };
        for closed in [false, true] {
            for solver in [BetaSolver::Newton, BetaSolver::Jacobi] {
                for (coords, dim) in [(&s2, 3), (&circle, 3), (&s3, 4)] {
                    let m = coords.len();
                    let beta1: Vec<f64> = (0..m).map(|i| 0.6 + 0.2 * i as f64).collect();
                    let gamma: Vec<f64> = beta1.iter().map(|&b| gamma(b, 1.5)).collect();
                    let shape = shape_constants(&beta1, &gamma, closed);
                    let rank = coords[0].len();
                    let native = if dim == 3 {
                        run::<DVec3>(coords, rank, 3, &shape, solver, settings, closed)
                    } else {
                        run::<DVec4>(coords, rank, 4, &shape, solver, settings, closed)
                    };
                    let compact =
                        run::<VecN>(coords, rank, rank.max(3), &shape, solver, settings, closed);
                    assert!(native.1 >= 1, "{solver:?} iterates");
                    assert_eq!(
                        bits(native),
                        bits(compact),
                        "{solver:?}, closed {closed}, rank {rank}"
                    );
                }
            }
        }
    }
}
