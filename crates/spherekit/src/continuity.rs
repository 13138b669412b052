// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Continuity report of a piecewise curve at its joints, from the exact one-sided jets.

use crate::ambient::Ambient;
use crate::curve::{Curve, Jet, Side};
use crate::manifold::Manifold;

/// The jumps of a curve at one interior joint.
///
/// Each jump is the ambient Euclidean norm of the difference between the one-sided limits
/// ([`Side::Left`] minus [`Side::Right`]): `c0` of the point, `c1` of the first derivative, `c2`
/// of the second derivative, all with respect to the curve parameter. A curve is Cᵏ at the joint
/// when `c0 … ck` vanish (to rounding; typically below 1e-12 for exact constructions). `g1` is
/// the jump of the unit tangent: a curve that is continuous with `g1` ≈ 0 but `c1` > 0 is G¹
/// (its direction is continuous, its speed jumps), as Beta splines with β₁ ≠ 1 are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointContinuity {
    /// The joint parameter.
    pub t: f64,
    /// `|c(t⁻) − c(t⁺)|`.
    pub c0: f64,
    /// `|c′(t⁻) − c′(t⁺)|`.
    pub c1: f64,
    /// `|c″(t⁻) − c″(t⁺)|`.
    pub c2: f64,
    /// `|c′(t⁻)/|c′(t⁻)| − c′(t⁺)/|c′(t⁺)||`, between 0 and 2; equal to `c1` where a one-sided
    /// velocity vanishes (no direction to compare).
    pub g1: f64,
}

impl JointContinuity {
    /// The highest order `k ≤ 2` such that all jumps up to order `k` are at most `tol`; `None`
    /// if even the points differ by more than `tol`.
    #[must_use]
    pub fn order(&self, tol: f64) -> Option<u8> {
        if self.c0 > tol {
            None
        } else if self.c1 > tol {
            Some(0)
        } else if self.c2 > tol {
            Some(1)
        } else {
            Some(2)
        }
    }
}

/// How smooth a curve is at a joint, as [`JointContinuity::class`] reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContinuityClass {
    /// The one-sided points differ.
    Broken,
    /// Continuous, with a corner.
    C0,
    /// Continuous with a continuous direction, the speed jumps (geometric continuity).
    G1,
    /// `Cᵏ`, k ≥ 1: derivatives up to order k agree.
    C(usize),
}

impl core::fmt::Display for ContinuityClass {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
        match *self {
            Self::Broken => f.write_str("broken"),
            Self::C0 => f.write_str("C⁰"),
            Self::G1 => f.write_str("G¹"),
            Self::C(k) => {
                f.write_str("C")?;
                let digits: Vec<char> = k
                    .to_string()
                    .bytes()
                    .map(|b| DIGITS[usize::from(b - b'0')])
                    .collect();
                f.write_str(&digits.into_iter().collect::<String>())
            }
        }
    }
}

impl JointContinuity {
    /// The continuity class at tolerance `tol`: [`ContinuityClass::Broken`], `C0`, `G1`,
    /// `C(1)` or `C(2)` from the measured jumps; where they show C² and the construction
    /// guarantees a higher order `guaranteed` (Pobegailo's Cⁿ blends), `C(guaranteed)`. The
    /// jets carry two derivatives, so orders above 2 are the construction's theorem, checked
    /// to order 2 here.
    ///
    /// ```
    /// use spherekit::{ContinuityClass, JointContinuity};
    ///
    /// let j = JointContinuity { t: 1.0, c0: 0.0, c1: 0.0, c2: 1e-13, g1: 0.0 };
    /// assert_eq!(j.class(1e-9, 0), ContinuityClass::C(2));
    /// assert_eq!(j.class(1e-9, 6).to_string(), "C⁶");
    /// let g1 = JointContinuity { t: 1.0, c0: 0.0, c1: 0.3, c2: 0.1, g1: 1e-14 };
    /// assert_eq!(g1.class(1e-9, 6).to_string(), "G¹");
    /// ```
    #[must_use]
    pub fn class(&self, tol: f64, guaranteed: usize) -> ContinuityClass {
        match self.order(tol) {
            None => ContinuityClass::Broken,
            Some(0) if self.g1 <= tol => ContinuityClass::G1,
            Some(0) => ContinuityClass::C0,
            Some(1) => ContinuityClass::C(1),
            Some(_) => ContinuityClass::C(guaranteed.max(2)),
        }
    }
}

/// The jumps of point, velocity and acceleration at every interior joint of `curve` (the
/// entries of [`Curve::joints`] other than the two ends), from [`Curve::jet_at`] on both sides.
/// A closed curve ([`Curve::is_closed`]) has one more joint, the seam, reported last with
/// `t = t1`: the end from the left, `c(t1⁻)`, against the start from the right, `c(t0⁺)`
/// (against `−c(t0⁺)` for a loop that ends at the antipode, [`Curve::is_antiperiodic`]).
///
/// # Examples
///
/// ```
/// use spherekit::{continuity, GeodesicSpline, S2Point};
///
/// let c = GeodesicSpline::try_new(vec![S2Point::X, S2Point::Y, S2Point::Z], None).unwrap();
/// let report = continuity(&c);
/// assert_eq!(report.len(), 1);
/// assert_eq!(report[0].t, 1.0);
/// assert!(report[0].c0 < 1e-15); // continuous …
/// assert!(report[0].c1 > 1.0); // … with a corner
/// assert!(report[0].g1 > 1.0); // the direction turns by 90°: not even G¹
/// assert_eq!(report[0].order(1e-12), Some(0));
/// // Closed: the seam at t = 3 is the last joint.
/// let loop_ = GeodesicSpline::try_new_closed(vec![S2Point::X, S2Point::Y, S2Point::Z], None).unwrap();
/// let report = continuity(&loop_);
/// assert_eq!(report.len(), 3);
/// assert_eq!(report[2].t, 3.0);
/// assert!(report[2].c0 < 1e-15 && report[2].c1 > 1.0);
/// ```
#[must_use]
pub fn continuity<C: Curve + ?Sized>(curve: &C) -> Vec<JointContinuity> {
    let joints = curve.joints();
    let (first, last) = (joints[0], joints[joints.len() - 1]);
    let mut out: Vec<JointContinuity> = joints[1..joints.len() - 1]
        .iter()
        .map(|&t| jumps(t, curve.jet_at(t, Side::Left), curve.jet_at(t, Side::Right)))
        .collect();
    if curve.is_closed() {
        let start = curve.jet_at(first, Side::Right);
        let start = if curve.is_antiperiodic() {
            start.antipode()
        } else {
            start
        };
        out.push(jumps(last, curve.jet_at(last, Side::Left), start));
    }
    out
}

/// The jumps between the one-sided jets `l` and `r` at `t`.
fn jumps<P: Manifold>(t: f64, l: Jet<P>, r: Jet<P>) -> JointContinuity {
    let c1 = (l.velocity.clone() - r.velocity.clone()).length();
    let (sl, sr) = (l.velocity.length(), r.velocity.length());
    let g1 = if sl > 0.0 && sr > 0.0 {
        (l.velocity * (1.0 / sl) - r.velocity * (1.0 / sr)).length()
    } else {
        c1
    };
    JointContinuity {
        t,
        c0: (l.point.to_vector() - r.point.to_vector()).length(),
        c1,
        c2: (l.acceleration - r.acceleration).length(),
        g1,
    }
}
