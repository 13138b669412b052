// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The native side of the scipy drop-ins: the cubic (`RotationSpline`) and the geodesic
//! (`Slerp`) spline through unit quaternions at given times, built with the core directly.
//!
//! Quaternions cross this boundary scalar-last (`[x, y, z, w]`, scipy's and glam's order), or
//! scalar-first with `scalar_first=True`, with scipy's signs ([`Signs`]); angular rates are in
//! the body frame (scipy's `RotationSpline`). The scipy-facing argument checks and messages
//! live in `python/spherekit/_scipy.py`.
//!
//! # Extrapolation
//!
//! scipy's `RotationSpline` evaluates its end segments' cubic polynomials outside the key
//! times (its `PPoly` extrapolates): the core's [`Extrapolate::Segment`] on an open
//! [`CubicSpline`]. A closed one is a [`RotationLoop`] (closed in SO(3): a loop of an odd
//! number of full turns ends at `−q₀`) and repeats, [`Extrapolate::Cycle`].

use std::borrow::Cow;

use numpy::PyUntypedArrayMethods;
use pyo3::prelude::*;
use spherekit::glam::{DQuat, DVec4};
use spherekit::{
    CubicEnd, CubicSpline, Curve, Extrapolate, Extrapolated, GeodesicSpline, Knots, Manifold,
    RotationLoop, Side, UnitQuat, angular_velocity_acceleration_body, unflip,
};

use crate::batch;
use crate::convert::{Times, float_repr, numbers, point_array, rows, value_error};
use crate::curve::{What, evaluate_points, write_jets};

/// The keys as unit quaternions from rows `[x, y, z, w]` (`[w, x, y, z]` with `scalar_first`),
/// canonicalised (shortest rotations, [`unflip`]), and which of them [`unflip`] negated.
///
/// The numbers are read as one slice (numpy's own buffer when it is contiguous), so that
/// reading the keys costs what the core's own checks do; a loop over `ndarray` row views
/// costs several times more.
fn keys(quats: &Bound<'_, PyAny>, scalar_first: bool) -> PyResult<(Vec<UnitQuat>, Signs)> {
    let array = point_array(quats, "rotations")?;
    let rows = array.as_array();
    if rows.nrows() > 0 && rows.ncols() != 4 {
        let order = if scalar_first {
            "w, x, y, z"
        } else {
            "x, y, z, w"
        };
        return Err(value_error(format!(
            "rotations: expected quaternions of 4 numbers [{order}], got {} numbers",
            rows.ncols()
        )));
    }
    // Row-major order: numpy's buffer as it is only when C-contiguous (`as_slice` also takes
    // a Fortran-ordered buffer, column by column).
    let numbers: Cow<'_, [f64]> = match array.as_slice() {
        Ok(s) if array.is_c_contiguous() => Cow::Borrowed(s),
        _ => Cow::Owned(rows.iter().copied().collect()),
    };
    let mut keys = Vec::with_capacity(rows.nrows());
    for (i, q) in numbers.chunks_exact(4).enumerate() {
        let q = if scalar_first {
            DQuat::from_xyzw(q[1], q[2], q[3], q[0])
        } else {
            DQuat::from_xyzw(q[0], q[1], q[2], q[3])
        };
        let q = UnitQuat::try_new(q).map_err(|e| value_error(format!("rotations[{i}]: {e}")))?;
        keys.push(q);
    }
    let given = keys.clone();
    unflip(&mut keys);
    let signs = Signs::new(&given, &keys);
    Ok((keys, signs))
}

/// The sign scipy's quaternions have relative to the curve's: which keys [`unflip`] negated.
///
/// scipy's `RotationSpline` and `Slerp` write the rotation at `t` as the key `rᵢ` *as given*
/// times the quaternion of a rotation vector, `rᵢ·exp(vᵢ(t)/2)` (`from_rotvec`, no
/// canonicalisation: its scalar part is `cos(|vᵢ|/2)`, negative beyond half a turn), with `i`
/// the segment scipy picks for `t`. The curve is built on the canonicalised keys `kᵢ = ±rᵢ`
/// and is continuous, so on segment `i` it is the continuous lift `kᵢ·exp(vᵢ(t)/2)` of the
/// same rotations: scipy's quaternion is the curve's times the sign of `kᵢ` against `rᵢ`. The
/// segment is found as the curves find theirs ([`Knots`]: `O(1)` per sample for increasing
/// times, a binary search otherwise), and nothing is done when no key was negated.
pub(crate) struct Signs {
    /// `negated[i]`: key `i` as given is `−kᵢ`; `None` when no key is.
    negated: Option<Vec<bool>>,
}

impl Signs {
    fn new(given: &[UnitQuat], canonical: &[UnitQuat]) -> Self {
        let negated: Vec<bool> = given
            .iter()
            .zip(canonical)
            .map(|(g, k)| g.as_dquat().dot(k.as_dquat()) < 0.0)
            .collect();
        Self {
            negated: negated.contains(&true).then_some(negated),
        }
    }

    /// Negates the quaternion rows (`rows`, 4 numbers each) at the parameters `ts` whose
    /// segment of `knots` starts at a negated key. With [`Side::Right`] the segment of a knot
    /// is the one it starts (scipy's `RotationSpline`, `searchsorted(side="right") − 1`), with
    /// [`Side::Left`] the one it ends (scipy's `Slerp`); before the first knot the first
    /// segment, after the last one the last.
    fn apply(&self, knots: &Knots, ts: &[f64], side: Side, rows: &mut [f64]) {
        let Some(negated) = &self.negated else {
            return;
        };
        let mut hint = 0;
        for (&t, row) in ts.iter().zip(rows.chunks_exact_mut(4)) {
            // From the previous sample's segment (a step for increasing times, a binary search
            // for a jump).
            (hint, _) = knots.locate_from(t, side, hint);
            if negated[hint] {
                row.iter_mut().for_each(|x| *x = -*x);
            }
        }
    }
}

/// `t` taken into the period `[t0, t1)` as [`Extrapolate::Cycle`] takes it (the same
/// arithmetic, so the same bits; `t1` itself is `t0`); `±∞` as it is (no period: the curve
/// clamps it).
fn into_period(t: f64, t0: f64, t1: f64) -> f64 {
    if (t0 <= t && t < t1) || !t.is_finite() {
        return t;
    }
    let period = t1 - t0;
    let r = (t - t0).rem_euclid(period);
    if r == 0.0 || r >= period {
        t0
    } else {
        (t0 + r).min(t1)
    }
}

/// A body-frame angular rate `[x, y, z]`.
fn angular_velocity(v: Option<Vec<f64>>, name: &str) -> PyResult<Option<spherekit::glam::DVec3>> {
    match v.as_deref() {
        None => Ok(None),
        Some(&[x, y, z]) => Ok(Some(spherekit::glam::DVec3::new(x, y, z))),
        Some(v) => Err(value_error(format!(
            "`{name}` must be an angular velocity [x, y, z], got {} numbers",
            v.len()
        ))),
    }
}

/// The cubic spline of scipy's `RotationSpline` (and its natural, clamped and closed kin).
#[pyclass(module = "spherekit._spherekit", name = "_CubicRotations", frozen)]
pub(crate) struct PyCubicRotations {
    curve: Cubic,
    /// The key times (closed: and the time of the return to the first key).
    knots: Knots,
    /// The number of keys.
    n: usize,
    /// scipy's signs of the quaternions written.
    signs: Signs,
}

/// The spline and what it is outside the key times.
enum Cubic {
    /// Open: the end segments' cubics continued ([`Extrapolate::Segment`], scipy's).
    Open(Extrapolated<CubicSpline<UnitQuat>>),
    /// Closed: a loop of rotations, closed in SO(3) ([`RotationLoop`]: a loop of an odd number
    /// of full turns ends at `−q₀` rather than turning back the long way), repeated
    /// ([`Extrapolate::Cycle`]).
    Closed(Extrapolated<RotationLoop<CubicSpline<UnitQuat>>>),
}

/// `$body` with `$c` the spline, open or closed, as an `Extrapolated` curve.
macro_rules! with_cubic {
    ($curve:expr, |$c:ident| $body:expr) => {
        match &$curve {
            Cubic::Open($c) => $body,
            Cubic::Closed($c) => $body,
        }
    };
}

impl Cubic {
    /// The cubic spline built (closed and antiperiodic: through the doubled keys, of which
    /// the loop is the first half).
    fn spline(&self) -> &CubicSpline<UnitQuat> {
        match self {
            Self::Open(c) => c.curve(),
            Self::Closed(c) => c.curve().inner(),
        }
    }

    fn domain(&self) -> [f64; 2] {
        with_cubic!(self, |c| c.domain())
    }

    /// Whether every time of `ts` is one where the spline built is the curve: the key times
    /// (closed: short of the return, where an antiperiodic loop ends at `−q₀`).
    fn spline_holds(&self, ts: &[f64]) -> bool {
        let [t0, t1] = self.domain();
        // Folds rather than `all`: no early exit, so the check is vectorised.
        match self {
            Self::Open(_) => ts
                .iter()
                .fold(true, |inside, &t| inside & (t0 <= t) & (t <= t1)),
            Self::Closed(_) => ts
                .iter()
                .fold(true, |inside, &t| inside & (t0 <= t) & (t < t1)),
        }
    }
}

/// `order` of scipy's `RotationSpline.__call__`: quaternions, body rates, body accelerations.
fn what(order: i64) -> PyResult<What> {
    match order {
        0 => Ok(What::Point),
        1 => Ok(What::AngularVelocity(true)),
        2 => Ok(What::AngularAcceleration(true)),
        _ => Err(value_error("`order` must be 0, 1 or 2.")),
    }
}

impl PyCubicRotations {
    /// The quaternions at `ts`, with scipy's signs: the key as given at each key time, the
    /// segment's key composed with the rotation from it (see [`Signs`]) between and outside
    /// them. A closed spline's quaternions are periodic: `t` is taken into `[t₀, t_n)` first
    /// (as [`Extrapolate::Cycle`] does, the same bits) and its segment found there.
    fn quaternions(&self, ts: &[f64], scalar_first: bool) -> Vec<f64> {
        let fix =
            |ts: &[f64], rows: &mut [f64]| self.signs.apply(&self.knots, ts, Side::Right, rows);
        match &self.curve {
            Cubic::Open(c) => evaluate_points(c, ts, 4, scalar_first, fix),
            Cubic::Closed(c) => {
                let [t0, t1] = c.domain();
                let taken: Vec<f64> = ts.iter().map(|&t| into_period(t, t0, t1)).collect();
                evaluate_points(c, &taken, 4, scalar_first, fix)
            }
        }
    }

    /// The body-frame angular rates `2·q̄·q′` at `ts`, from the point and velocity alone
    /// ([`CubicSpline::point_velocity_many`]: the jet's bits without its acceleration). A
    /// chunk with a parameter outside the key times goes through the extrapolation's jets.
    fn body_rates(&self, ts: &[f64]) -> Vec<f64> {
        let spline = self.curve.spline();
        let t0 = self.curve.domain()[0];
        batch::split(ts, 3, |ts, out| {
            let slot = spline.point_velocity(t0);
            batch::by_chunks(ts, out, 3, t0, slot, |chunk, pvs, rows| {
                if self.curve.spline_holds(chunk) {
                    spline.point_velocity_many(chunk, pvs);
                } else {
                    for (&t, pv) in chunk.iter().zip(pvs.iter_mut()) {
                        let jet = with_cubic!(self.curve, |c| c.jet(t));
                        *pv = (jet.point, jet.velocity);
                    }
                }
                for (&(q, dq), row) in pvs.iter().zip(rows.chunks_exact_mut(3)) {
                    let (w, _) = angular_velocity_acceleration_body(q, dq, DVec4::ZERO);
                    row.copy_from_slice(&w.to_array());
                }
            });
        })
    }

    /// The body-frame angular accelerations `2·q̄·q″` at `ts`.
    fn body_accelerations(&self, ts: &[f64]) -> Vec<f64> {
        let t0 = self.curve.domain()[0];
        batch::split(ts, 3, |ts, out| {
            let slot = self.curve.spline().jet(t0);
            batch::by_chunks(ts, out, 3, t0, slot, |chunk, jets, rows| {
                with_cubic!(self.curve, |c| c.jet_many(chunk, jets));
                for (jet, row) in jets.iter().zip(rows.chunks_exact_mut(3)) {
                    let (_, a) = angular_velocity_acceleration_body(
                        jet.point,
                        jet.velocity,
                        jet.acceleration,
                    );
                    row.copy_from_slice(&a.to_array());
                }
            });
        })
    }
}

#[pymethods]
impl PyCubicRotations {
    #[new]
    #[pyo3(signature = (times, quats, end="scipy", closed=false, start_velocity=None, end_velocity=None, scalar_first=false))]
    #[expect(clippy::too_many_arguments, reason = "the Python signature")]
    fn new(
        py: Python<'_>,
        times: &Bound<'_, PyAny>,
        quats: &Bound<'_, PyAny>,
        end: &str,
        closed: bool,
        start_velocity: Option<&Bound<'_, PyAny>>,
        end_velocity: Option<&Bound<'_, PyAny>>,
        scalar_first: bool,
    ) -> PyResult<Self> {
        let times = numbers(times, "times")?;
        let (keys, signs) = keys(quats, scalar_first)?;
        let start_velocity = angular_velocity(
            start_velocity
                .map(|r| numbers(r, "start_velocity"))
                .transpose()?,
            "start_velocity",
        )?;
        let end_velocity = angular_velocity(
            end_velocity
                .map(|r| numbers(r, "end_velocity"))
                .transpose()?,
            "end_velocity",
        )?;
        let end = match (end, start_velocity, end_velocity) {
            ("scipy", None, None) => CubicEnd::Scipy,
            ("natural", None, None) => CubicEnd::Natural,
            ("clamped", Some(a), Some(b)) => {
                let (first, last) = (keys[0], keys[keys.len() - 1]);
                CubicEnd::clamped_angular_body(first, a, last, b)
            }
            ("clamped", _, _) => {
                return Err(value_error(
                    "end=\"clamped\" needs start_velocity and end_velocity (body-frame angular velocities [x, y, z])",
                ));
            }
            ("scipy" | "natural", _, _) => {
                return Err(value_error(
                    "start_velocity and end_velocity apply with end=\"clamped\" only",
                ));
            }
            (other, _, _) => {
                return Err(value_error(format!(
                    "end: \"{other}\" is not an end condition: use \"scipy\", \"natural\" or \"clamped\""
                )));
            }
        };
        if keys.is_empty() {
            return Err(value_error(
                "`rotations` must contain at least 2 rotations.",
            ));
        }
        let n = keys.len();
        let knots = times.clone();
        let built = py
            .detach(|| {
                if closed {
                    let build = |keys, knots| CubicSpline::try_new(keys, knots, end, true);
                    RotationLoop::try_new(keys, Some(knots), build)
                        .map(|c| Cubic::Closed(Extrapolated::new(c, Extrapolate::Cycle)))
                } else {
                    CubicSpline::try_new(keys, Some(knots), end, false)
                        .map(|c| Cubic::Open(Extrapolated::new(c, Extrapolate::Segment)))
                }
            })
            .map_err(|e| value_error(e.to_string()))?;
        Ok(Self {
            curve: built,
            knots: Knots::try_new(times).map_err(|e| value_error(e.to_string()))?,
            n,
            signs,
        })
    }

    /// Quaternions `[x, y, z, w]` (`[w, x, y, z]` with `scalar_first`; `order=0`) with scipy's
    /// signs, body angular rates (1) or accelerations (2). A NaN time is a `ValueError`.
    #[pyo3(signature = (t, order=0, scalar_first=false))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        order: i64,
        scalar_first: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let what = what(order)?;
        let times = Times::extract(t, "times")?;
        let ts = times.values_not_nan("times", "time")?;
        let (data, width) = py.detach(|| match what {
            What::AngularVelocity(_) => (self.body_rates(&ts), 3),
            What::AngularAcceleration(_) => (self.body_accelerations(&ts), 3),
            _ => (self.quaternions(&ts, scalar_first), 4),
        });
        rows(py, data, width, times.scalar)
    }

    /// The end segments' cubic at `t` whether inside the domain or not (`order` as in
    /// `__call__`), for testing the extrapolation against the spline itself (NaN for a closed
    /// spline, which has no ends).
    #[pyo3(signature = (t, order=0))]
    fn _extrapolated<'py>(
        &self,
        py: Python<'py>,
        t: f64,
        order: i64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let what = what(order)?;
        let width = if what == What::Point { 4 } else { 3 };
        let mut out = vec![f64::NAN; width];
        if let Cubic::Open(c) = &self.curve
            && let Some(jet) = c.curve().continued_jet(t)
        {
            write_jets(&[jet], what, false, width, &mut out);
            if what == What::Point {
                self.signs.apply(&self.knots, &[t], Side::Right, &mut out);
            }
        }
        rows(py, out, width, true)
    }

    /// Newton iterations of the construction and the final relative residual.
    #[getter]
    fn solve_info(&self) -> (usize, f64) {
        let info = self.curve.spline().solve_info();
        (info.iterations, info.residual)
    }

    /// The keys as the spline uses them (normalised, canonicalised), `[x, y, z, w]`.
    #[getter]
    fn keys<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let data: Vec<f64> = self.curve.spline().points()[..self.n]
            .iter()
            .flat_map(|q| q.to_vector().to_array())
            .collect();
        rows(py, data, 4, false)
    }
}

/// The geodesic spline of scipy's `Slerp`.
#[pyclass(module = "spherekit._spherekit", name = "_SlerpRotations", frozen)]
pub(crate) struct PySlerpRotations {
    spline: GeodesicSpline<UnitQuat>,
    /// The key times.
    knots: Knots,
    /// scipy's signs of the quaternions written.
    signs: Signs,
}

#[pymethods]
impl PySlerpRotations {
    #[new]
    #[pyo3(signature = (times, quats, scalar_first=false))]
    fn new(
        py: Python<'_>,
        times: &Bound<'_, PyAny>,
        quats: &Bound<'_, PyAny>,
        scalar_first: bool,
    ) -> PyResult<Self> {
        let times = numbers(times, "times")?;
        let (keys, signs) = keys(quats, scalar_first)?;
        let spline = py
            .detach(|| GeodesicSpline::try_new(keys, Some(times.clone())))
            .map_err(|e| value_error(e.to_string()))?;
        let knots = Knots::try_new(times).map_err(|e| value_error(e.to_string()))?;
        Ok(Self {
            spline,
            knots,
            signs,
        })
    }

    /// Quaternions `[x, y, z, w]` (`[w, x, y, z]` with `scalar_first`) at `t` with scipy's
    /// signs (the key as given composed with the rotation from it, the segment ending at a key
    /// time); a `ValueError` (scipy's message) outside the times, NaN included.
    #[pyo3(signature = (t, scalar_first=false))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        scalar_first: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let times = Times::extract(t, "times")?;
        let ts = times.values();
        let [t0, t1] = self.spline.domain();
        if !ts.iter().all(|t| (t0..=t1).contains(t)) {
            return Err(value_error(format!(
                "Interpolation times must be within the range [{}, {}], both inclusive.",
                float_repr(py, t0),
                float_repr(py, t1)
            )));
        }
        let data = py.detach(|| {
            let fix = |ts: &[f64], rows: &mut [f64]| {
                self.signs.apply(&self.knots, ts, Side::Left, rows);
            };
            evaluate_points(&self.spline, &ts, 4, scalar_first, fix)
        });
        rows(py, data, 4, times.scalar)
    }
}
