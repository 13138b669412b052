// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Knot sequences: strictly increasing parameters of the joints of a piecewise curve.

use crate::curve::{Side, clamp_param};
use crate::error::SplineError;

/// The smallest spacing of consecutive knots. On a piece of parameter length h the k-th
/// derivative is about θ/hᵏ (θ the piece's angle), times ratios of neighbouring spacings in the
/// non-uniform constructions. Fuzzing found knots 1e-96 apart giving accelerations whose norms
/// overflowed, and 1e-160 apart accelerations that overflowed themselves; with spacings in
/// [`MIN_KNOT_SPACING`, `MAX_KNOT_SPACING`] (ratios up to 1e100) every method stays finite.
pub const MIN_KNOT_SPACING: f64 = 1e-50;

/// The largest spacing of consecutive knots (see [`MIN_KNOT_SPACING`]); it also keeps
/// `knots[i] − knots[i − 1]` finite (`1e308 − (−1e308)` is not).
pub const MAX_KNOT_SPACING: f64 = 1e50;

/// A strictly increasing, finite sequence of at least two parameters, with consecutive spacings
/// from [`MIN_KNOT_SPACING`] to [`MAX_KNOT_SPACING`].
///
/// # Examples
///
/// ```
/// use spherekit::{Knots, Side};
///
/// let k = Knots::try_new(vec![0.0, 1.0, 3.0]).unwrap();
/// assert_eq!(k.locate(2.0, Side::Right), (1, 0.5));
/// assert_eq!(k.locate(1.0, Side::Left), (0, 1.0));
/// assert_eq!(k.locate(1.0, Side::Right), (1, 0.0));
/// assert_eq!(k.locate_from(2.5, Side::Right, 0), k.locate(2.5, Side::Right));
/// assert!(Knots::try_new(vec![0.0, 0.0]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Knots(Vec<f64>);

impl Knots {
    /// The knots `0, 1, …, count − 1`.
    ///
    /// # Panics
    ///
    /// If `count < 2`.
    #[must_use]
    pub fn uniform(count: usize) -> Self {
        assert!(count >= 2, "a knot sequence needs at least two knots");
        Self((0..count).map(|i| i as f64).collect())
    }

    /// Validates a knot sequence.
    ///
    /// # Errors
    ///
    /// [`SplineError::KnotCount`] for fewer than two knots, [`SplineError::InvalidKnot`] for a
    /// non-finite knot, [`SplineError::KnotsNotIncreasing`] where a knot does not exceed its
    /// predecessor, [`SplineError::KnotSpacing`] for a spacing outside
    /// [`MIN_KNOT_SPACING`] ..= [`MAX_KNOT_SPACING`].
    pub fn try_new(knots: Vec<f64>) -> Result<Self, SplineError> {
        if knots.len() < 2 {
            return Err(SplineError::KnotCount {
                expected: 2,
                got: knots.len(),
            });
        }
        if let Some(index) = knots.iter().position(|k| !k.is_finite()) {
            return Err(SplineError::InvalidKnot { index });
        }
        if let Some(i) = knots
            .windows(2)
            .position(|w| w[1] <= w[0] || (w[1] - w[0]) == 0.0)
        {
            return Err(SplineError::KnotsNotIncreasing { index: i + 1 });
        }
        if let Some(i) = knots
            .windows(2)
            .position(|w| !(MIN_KNOT_SPACING..=MAX_KNOT_SPACING).contains(&(w[1] - w[0])))
        {
            return Err(SplineError::KnotSpacing { index: i + 1 });
        }
        Ok(Self(knots))
    }

    /// The given knots if there are exactly `count`, or `0, 1, …, count − 1` when `None`.
    ///
    /// # Errors
    ///
    /// As [`try_new`](Self::try_new), and [`SplineError::KnotCount`] for a wrong count.
    pub fn or_uniform(knots: Option<Vec<f64>>, count: usize) -> Result<Self, SplineError> {
        match knots {
            None => Ok(Self::uniform(count.max(2))),
            Some(k) if k.len() != count => Err(SplineError::KnotCount {
                expected: count,
                got: k.len(),
            }),
            Some(k) => Self::try_new(k),
        }
    }

    /// The knots.
    #[must_use]
    pub fn as_slice(&self) -> &[f64] {
        &self.0
    }

    /// The number of pieces, one less than the number of knots.
    #[must_use]
    pub fn segment_count(&self) -> usize {
        self.0.len() - 1
    }

    /// `[first, last]`.
    #[must_use]
    pub fn domain(&self) -> [f64; 2] {
        [self.0[0], self.0[self.0.len() - 1]]
    }

    /// The width of piece `i`.
    #[must_use]
    pub fn width(&self, i: usize) -> f64 {
        self.0[i + 1] - self.0[i]
    }

    /// The piece containing `t` (clamped to the domain) and the local parameter `s ∈ [0, 1]`
    /// on it. At an interior knot, `side` chooses the piece that ends there (`Left`, `s = 1`)
    /// or the one that starts there (`Right`, `s = 0`).
    #[must_use]
    pub fn locate(&self, t: f64, side: Side) -> (usize, f64) {
        let t = clamp_param(t, self.domain());
        let k = &self.0;
        let above = match side {
            Side::Left => k.partition_point(|&x| x < t),
            Side::Right => k.partition_point(|&x| x <= t),
        };
        let i = above.saturating_sub(1).min(k.len() - 2);
        self.local(i, t)
    }

    /// [`locate`](Self::locate) starting the search at piece `hint`: the same result, bit for
    /// bit, found by stepping forward from `hint` (cheap when parameters arrive in increasing
    /// order, a piece or two at a time) and by binary search otherwise (a parameter before the
    /// hint's piece or more than two pieces after it). Returns the piece, which is the hint to pass
    /// with the next (larger) parameter.
    #[must_use]
    pub fn locate_from(&self, t: f64, side: Side, hint: usize) -> (usize, f64) {
        let t = clamp_param(t, self.domain());
        let k = &self.0;
        let last = k.len() - 2;
        let mut i = hint.min(last);
        // `locate` picks the largest i ≤ last with k[i] ≤ t (Right) or k[i] < t (Left), or 0.
        let before = |x: f64| match side {
            Side::Left => x < t,
            Side::Right => x <= t,
        };
        if i > 0 && !before(k[i]) {
            return self.locate(t, side);
        }
        // A step or two forward (increasing parameters); a longer jump searches.
        for _ in 0..2 {
            if i < last && before(k[i + 1]) {
                i += 1;
            } else {
                return self.local(i, t);
            }
        }
        if i < last && before(k[i + 1]) {
            return self.locate(t, side);
        }
        self.local(i, t)
    }

    /// The local parameter of clamped `t` on piece `i`.
    #[inline]
    fn local(&self, i: usize, t: f64) -> (usize, f64) {
        let k = &self.0;
        let s = (t - k[i]) / (k[i + 1] - k[i]);
        (i, s.clamp(0.0, 1.0))
    }

    /// Calls `f(i, s)` for each parameter of `ts` (as located by [`locate`](Self::locate) with
    /// `side`) and stores the results in `out`; sorted parameters need no search.
    pub(crate) fn map_into<T>(
        &self,
        ts: &[f64],
        side: Side,
        out: &mut [T],
        mut f: impl FnMut(usize, f64) -> T,
    ) {
        check_batch(ts, out);
        let mut hint = 0;
        for (&t, o) in ts.iter().zip(out) {
            let (i, s) = self.locate_from(t, side, hint);
            hint = i;
            *o = f(i, s);
        }
    }
}

/// Panics unless the batch buffers have equal lengths.
#[inline]
pub(crate) fn check_batch<T>(ts: &[f64], out: &[T]) {
    assert_eq!(
        ts.len(),
        out.len(),
        "batch evaluation needs one output slot per parameter"
    );
}
