// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The curve trait: a parametrised curve on a sphere with exact derivatives.

use crate::manifold::Manifold;

/// Which one-sided limit to take at a joint of a piecewise curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Side {
    /// The piece that ends at the joint.
    Left,
    /// The piece that starts at the joint (the default).
    #[default]
    Right,
}

/// A point of a curve with its first and second derivatives.
///
/// The derivatives are taken with respect to the curve's own parameter `t` and are vectors of
/// the ambient space: `velocity` is tangent to the sphere at `point`, `acceleration` is the full
/// ambient second derivative (its normal part is `−|velocity|²·point`).
#[derive(Clone, Debug, PartialEq)]
pub struct Jet<P: Manifold> {
    /// The point `c(t)`.
    pub point: P,
    /// `c′(t)`.
    pub velocity: P::Vector,
    /// `c″(t)`.
    pub acceleration: P::Vector,
}

/// A parametrised curve on a sphere with analytic first and second derivatives.
///
/// # Domain policy
///
/// Every curve is defined on a closed interval [`domain`](Curve::domain) `= [t0, t1]`.
/// Parameters outside it are **clamped**: `eval(t)` for `t < t0` is `eval(t0)` (likewise
/// `t = −∞`), and the jet there is the one-sided jet at `t0`. The derivatives are **not**
/// zeroed: a clamped jet keeps reporting the end velocity, which is wrong for physics code
/// that integrates it outside the domain. A NaN parameter is treated as `t0`, in release and
/// debug builds alike, so that evaluation never panics and never produces a NaN.
///
/// For another policy outside the domain (hold the end at rest, continue along the end's
/// geodesic, repeat periodically, or a typed error) wrap the curve in
/// [`Extrapolated`](crate::Extrapolated) with an [`Extrapolate`](crate::Extrapolate) policy.
pub trait Curve: core::fmt::Debug {
    /// The sphere the curve lies on.
    type Point: Manifold;

    /// The parameter interval `[t0, t1]`, `t0 < t1`.
    fn domain(&self) -> [f64; 2];

    /// The parameters where the curve is made of different pieces, including both ends of the
    /// domain, increasing. A one-piece curve returns `[t0, t1]`.
    fn joints(&self) -> &[f64];

    /// Whether the curve is a closed loop: it ends where it starts, `c(t1) = c(t0)`, and the
    /// seam `t1 ≡ t0` is a joint like the others, as smooth as the construction is at its
    /// interior joints ([`continuity`](crate::continuity) reports it last). `false` unless the
    /// curve was built closed.
    fn is_closed(&self) -> bool {
        false
    }

    /// Whether the curve is a closed loop that ends at the antipode of its start,
    /// `c(t1) = −c(t0)`, and continues antiperiodically, `c(t + T) = −c(t)`: a loop of
    /// rotations that turns by an odd number of full turns, whose quaternions end at `−q₀`, the
    /// same rotation ([`RotationLoop`](crate::RotationLoop)). Its seam is a joint like the
    /// others up to that sign: [`continuity`](crate::continuity) compares the end with the
    /// antipode of the start, and [`Extrapolate::Cycle`](crate::Extrapolate::Cycle) negates
    /// every other lap. `false` unless the curve was built so.
    fn is_antiperiodic(&self) -> bool {
        false
    }

    /// The point and derivatives at `t`; at a joint, the one-sided limit from `side`.
    fn jet_at(&self, t: f64, side: Side) -> Jet<Self::Point>;

    /// The point and derivatives at `t` (right-sided at joints).
    fn jet(&self, t: f64) -> Jet<Self::Point> {
        self.jet_at(t, Side::Right)
    }

    /// The point at `t`.
    fn eval(&self, t: f64) -> Self::Point {
        self.jet(t).point
    }

    /// The points at every parameter of `ts`, written to `out[k] = eval(ts[k])`.
    ///
    /// Batch evaluation: the same values as [`eval`](Curve::eval), bit for bit, for any order
    /// of `ts`. Increasing parameters are fastest: the curves built from knots step through
    /// their pieces instead of searching for each sample, and the call is dispatched once per
    /// batch rather than once per sample. Nothing is allocated for points of S² and S³.
    ///
    /// # Panics
    ///
    /// If `out.len() != ts.len()`.
    ///
    /// # Examples
    ///
    /// ```
    /// use spherekit::{Curve, Jet, Squad, UnitQuat};
    /// use spherekit::glam::DVec3;
    ///
    /// let keys: Vec<UnitQuat> = (0..5)
    ///     .map(|i| UnitQuat::from_axis_angle(DVec3::new(1.0, f64::from(i), 2.0), 0.3 * f64::from(i)).unwrap())
    ///     .collect();
    /// let c = Squad::try_new(keys, None).unwrap();
    /// let ts: Vec<f64> = (0..=400).map(|k| f64::from(k) / 100.0).collect();
    /// let mut points = vec![UnitQuat::IDENTITY; ts.len()];
    /// c.eval_many(&ts, &mut points);
    /// let mut jets: Vec<Jet<UnitQuat>> = vec![c.jet(0.0); ts.len()];
    /// c.jet_many(&ts, &mut jets);
    /// for (k, &t) in ts.iter().enumerate() {
    ///     assert_eq!(points[k], c.eval(t)); // bit for bit
    ///     assert_eq!(jets[k], c.jet(t));
    /// }
    /// ```
    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        crate::knots::check_batch(ts, out);
        for (&t, o) in ts.iter().zip(out) {
            *o = self.eval(t);
        }
    }

    /// The jets at every parameter of `ts`, written to `out[k] = jet(ts[k])` (right-sided at
    /// joints); the same values as [`jet`](Curve::jet), bit for bit (see
    /// [`eval_many`](Curve::eval_many)).
    ///
    /// # Panics
    ///
    /// If `out.len() != ts.len()`.
    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        crate::knots::check_batch(ts, out);
        for (&t, o) in ts.iter().zip(out) {
            *o = self.jet(t);
        }
    }

    /// The curve's own continuation at a parameter `t` outside its domain, where its
    /// construction has one: the formula of the first piece (for `t < t0`) or the last piece
    /// (for `t > t1`) evaluated beyond the piece. This is what
    /// [`Extrapolate::Segment`](crate::Extrapolate::Segment) evaluates.
    ///
    /// `None` (the default) for a curve without such a continuation, at every `t`. A curve
    /// with one gives `Some` at every finite `t` outside the domain except where the formula
    /// overflows (far outside), and `None` inside the domain, for NaN and `±∞`.
    ///
    /// [`CubicSpline`](crate::CubicSpline) (open) continues its end segments' cubics in the
    /// tangent space of their first keys, as scipy's `RotationSpline` does.
    fn jet_beyond(&self, t: f64) -> Option<Jet<Self::Point>> {
        let _ = t;
        None
    }
}

/// A borrowed curve is the curve (so that an adapter can wrap a curve it does not own).
impl<C: Curve + ?Sized> Curve for &C {
    type Point = C::Point;

    fn domain(&self) -> [f64; 2] {
        (**self).domain()
    }

    fn joints(&self) -> &[f64] {
        (**self).joints()
    }

    fn is_closed(&self) -> bool {
        (**self).is_closed()
    }

    fn is_antiperiodic(&self) -> bool {
        (**self).is_antiperiodic()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<Self::Point> {
        (**self).jet_at(t, side)
    }

    fn jet(&self, t: f64) -> Jet<Self::Point> {
        (**self).jet(t)
    }

    fn eval(&self, t: f64) -> Self::Point {
        (**self).eval(t)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        (**self).eval_many(ts, out);
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        (**self).jet_many(ts, out);
    }

    fn jet_beyond(&self, t: f64) -> Option<Jet<Self::Point>> {
        (**self).jet_beyond(t)
    }
}

/// A boxed curve is the curve (so that adapters such as [`ArcLength`](crate::ArcLength) and
/// [`Extrapolated`](crate::Extrapolated) can own a `Box<dyn Curve>`).
impl<C: Curve + ?Sized> Curve for Box<C> {
    type Point = C::Point;

    fn domain(&self) -> [f64; 2] {
        (**self).domain()
    }

    fn joints(&self) -> &[f64] {
        (**self).joints()
    }

    fn is_closed(&self) -> bool {
        (**self).is_closed()
    }

    fn is_antiperiodic(&self) -> bool {
        (**self).is_antiperiodic()
    }

    fn jet_at(&self, t: f64, side: Side) -> Jet<Self::Point> {
        (**self).jet_at(t, side)
    }

    fn jet(&self, t: f64) -> Jet<Self::Point> {
        (**self).jet(t)
    }

    fn eval(&self, t: f64) -> Self::Point {
        (**self).eval(t)
    }

    fn eval_many(&self, ts: &[f64], out: &mut [Self::Point]) {
        (**self).eval_many(ts, out);
    }

    fn jet_many(&self, ts: &[f64], out: &mut [Jet<Self::Point>]) {
        (**self).jet_many(ts, out);
    }

    fn jet_beyond(&self, t: f64) -> Option<Jet<Self::Point>> {
        (**self).jet_beyond(t)
    }
}

impl<P: Manifold> Jet<P> {
    /// The jet of the antipodal curve `−c` at the same parameter: every vector negated.
    #[must_use]
    pub fn antipode(self) -> Self {
        Self {
            point: P::from_vector_unchecked(-self.point.to_vector()),
            velocity: -self.velocity,
            acceleration: -self.acceleration,
        }
    }
}

/// Clamps `t` to `[t0, t1]`, mapping NaN to `t0` (see the domain policy of [`Curve`]); never
/// panics.
#[inline]
pub(crate) fn clamp_param(t: f64, [t0, t1]: [f64; 2]) -> f64 {
    if t.is_nan() { t0 } else { t.clamp(t0, t1) }
}

/// The [`Curve`] impl of a curve made of pieces between its knots, written once: the type has
/// the fields `knots: Knots` and `closed: bool` and the inherent methods `eval_local(i, s)` and
/// `jet_local(i, s)`, which evaluate piece `i` at the local parameter [`Knots::locate`] gives
/// (the batch calls step through the pieces with `Knots::map_into`). Further trait items of
/// the type follow the point type.
///
/// [`Knots::locate`]: crate::Knots::locate
macro_rules! piecewise_curve {
    (impl $([$($generics:tt)*])? for $ty:ty { type Point = $point:ty; $($extra:tt)* }) => {
        impl $(<$($generics)*>)? $crate::Curve for $ty {
            type Point = $point;

            fn domain(&self) -> [f64; 2] {
                self.knots.domain()
            }

            fn joints(&self) -> &[f64] {
                self.knots.as_slice()
            }

            fn is_closed(&self) -> bool {
                self.closed
            }

            fn jet_at(&self, t: f64, side: $crate::Side) -> $crate::Jet<$point> {
                let (i, s) = self.knots.locate(t, side);
                self.jet_local(i, s)
            }

            fn eval(&self, t: f64) -> $point {
                let (i, s) = self.knots.locate(t, $crate::Side::Right);
                self.eval_local(i, s)
            }

            fn eval_many(&self, ts: &[f64], out: &mut [$point]) {
                self.knots
                    .map_into(ts, $crate::Side::Right, out, |i, s| self.eval_local(i, s));
            }

            fn jet_many(&self, ts: &[f64], out: &mut [$crate::Jet<$point>]) {
                self.knots
                    .map_into(ts, $crate::Side::Right, out, |i, s| self.jet_local(i, s));
            }

            $($extra)*
        }
    };
}
pub(crate) use piecewise_curve;
