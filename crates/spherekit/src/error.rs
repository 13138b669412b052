// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Typed errors. Messages say what is wrong in the library's terms (point 3, knot 2); a front
//! end that reads points from a document (the scene format) says where, from the indices the
//! variants carry.

use core::fmt;

/// Why a point of a sphere could not be formed: from a vector (the constructors), or by an
/// operation on points (the checked exponentials, powers and geodesic interpolation, the
/// `try_` methods of [`Manifold`](crate::Manifold) and [`UnitQuat`](crate::UnitQuat)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum PointError {
    /// A coordinate of the vector is NaN or infinite.
    NonFinite,
    /// All coordinates are zero (or subnormal), so there is no direction.
    ZeroLength,
    /// The number of coordinates does not match the sphere.
    WrongDimension {
        /// Coordinates the sphere needs.
        expected: usize,
        /// Coordinates given.
        got: usize,
    },
    /// The angle is NaN or infinite
    /// ([`UnitQuat::from_axis_angle`](crate::UnitQuat::from_axis_angle)).
    NonFiniteAngle,
    /// The parameter (the fraction of a geodesic interpolation, the exponent of a power) is NaN
    /// or infinite, or so large that the angle it gives overflows `f64`.
    NonFiniteParameter,
    /// The two points are antipodal (within
    /// [`ANTIPODAL_TOLERANCE`](crate::ANTIPODAL_TOLERANCE)): the minimising geodesic between
    /// them is not unique.
    Antipodal,
}

impl PointError {
    /// What is wrong, as the predicate of a sentence whose subject the caller names (`"has
    /// zero length and cannot be normalised"`): `format!("points[3] {}", e.predicate())`.
    ///
    /// ```
    /// use spherekit::{PointError, S2Point};
    /// use spherekit::glam::DVec3;
    ///
    /// let e = S2Point::try_new(DVec3::ZERO).unwrap_err();
    /// assert_eq!(e, PointError::ZeroLength);
    /// assert_eq!(e.to_string(), "the vector has zero length and cannot be normalised");
    /// assert_eq!(e.predicate(), "has zero length and cannot be normalised");
    /// ```
    #[must_use]
    pub fn predicate(&self) -> String {
        match self {
            Self::NonFinite => "has a non-finite coordinate".into(),
            Self::ZeroLength => "has zero length and cannot be normalised".into(),
            Self::WrongDimension { expected, got } => {
                format!("has {got} coordinates, expected {expected}")
            }
            Self::NonFiniteAngle => "has an angle that is NaN or infinite".into(),
            Self::NonFiniteParameter => {
                "has a parameter that is NaN or infinite, or so large that its angle overflows"
                    .into()
            }
            Self::Antipodal => {
                "is antipodal to the other point: the geodesic between them is not unique".into()
            }
        }
    }
}

impl fmt::Display for PointError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite | Self::ZeroLength | Self::WrongDimension { .. } => {
                write!(f, "the vector {}", self.predicate())
            }
            Self::NonFiniteAngle => f.write_str("the angle is NaN or infinite"),
            Self::NonFiniteParameter => f.write_str(
                "the parameter is NaN or infinite, or so large that the angle it gives overflows",
            ),
            Self::Antipodal => {
                f.write_str("the points are antipodal: the geodesic between them is not unique")
            }
        }
    }
}

impl core::error::Error for PointError {}

/// Why a curve could not be built.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SplineError {
    /// The construction needs at least `min` points.
    TooFewPoints {
        /// The minimum.
        min: usize,
        /// Points given.
        got: usize,
    },
    /// Input point `index` is not a valid point of the sphere.
    InvalidPoint {
        /// Index into the input points.
        index: usize,
        /// What is wrong with it.
        reason: PointError,
    },
    /// Points `index` and `index + 1` are antipodal: the geodesic between them is not unique.
    Antipodal {
        /// Index of the first of the two points.
        index: usize,
    },
    /// Points `index` and `index + 1` coincide where the construction needs distinct points.
    Coincident {
        /// Index of the first of the two points.
        index: usize,
    },
    /// Knot `index` is not finite.
    InvalidKnot {
        /// Index into the knots.
        index: usize,
    },
    /// Knot `index` is not greater than the one before it.
    KnotsNotIncreasing {
        /// Index into the knots.
        index: usize,
    },
    /// The spacing `knots[index] − knots[index − 1]` is outside
    /// [`MIN_KNOT_SPACING`](crate::MIN_KNOT_SPACING) ..= [`MAX_KNOT_SPACING`](crate::MAX_KNOT_SPACING):
    /// derivatives (which scale as 1/spacing²) or the spacing itself would overflow.
    KnotSpacing {
        /// Index into the knots.
        index: usize,
    },
    /// The number of knots does not fit the number of points.
    KnotCount {
        /// Knots the construction needs.
        expected: usize,
        /// Knots given.
        got: usize,
    },
    /// A method parameter is out of its range.
    InvalidParameter {
        /// The parameter's name as in the scene's `params`.
        name: &'static str,
        /// What is wrong, for example `"must be positive"`.
        reason: String,
    },
    /// Points `index` and `index + 2` coincide, so no unique circle passes through points
    /// `index`, `index + 1`, `index + 2` (circle-blending methods).
    NoCircle {
        /// Index of the first point of the triple.
        index: usize,
    },
    /// An iterative solver (for example the interpolation solver of
    /// [`BetaSpline`](crate::BetaSpline)) did not reach its tolerance.
    Solve(SolveError),
    /// The requested [`ArcBlendTiming`](crate::ArcBlendTiming) (`"book"` or `"arc-length"`)
    /// gives point `index` no knot of its own in `f64`: the spacing before it is lost to
    /// rounding next to the previous knot, or is outside
    /// [`MIN_KNOT_SPACING`](crate::MIN_KNOT_SPACING) ..= [`MAX_KNOT_SPACING`](crate::MAX_KNOT_SPACING).
    /// The other timings trace the same curve.
    TimingNotRepresentable {
        /// `"book"` or `"arc-length"`.
        timing: &'static str,
        /// Index of the point (its knot would be `knots[index]`).
        index: usize,
        /// The spacing `t_index − t_{index−1}` the timing asks for.
        spacing: f64,
        /// That spacing over the first one; for the book's knots, the product of the ratios
        /// `ψ/φ` of the circles through the points before `index`.
        ratio: f64,
        /// The knot `t_{index−1}` of the previous point.
        knot: f64,
    },
    /// The last and the first point of a closed curve are antipodal: the closing geodesic is
    /// not unique.
    AntipodalClosing,
    /// The last and the first point of a closed curve coincide where the construction needs
    /// distinct consecutive points.
    CoincidentClosing,
    /// Points `first` and `last` of the triple `first, middle, last` of a closed loop (whose
    /// indices wrap around the end) coincide, so no unique circle passes through the triple
    /// (circle-blending methods; [`SplineError::NoCircle`] for a triple that does not wrap).
    NoCircleAround {
        /// The first point of the triple.
        first: usize,
        /// The middle point.
        middle: usize,
        /// The last point (equal to the first).
        last: usize,
    },
    /// The requested [`ArcBlendTiming`](crate::ArcBlendTiming) has no knots that close a loop:
    /// the book's spacings, carried around by the ratios `ψ/φ`, come back to the first spacing
    /// multiplied by `ratio` instead of 1 (they close only when the ratios multiply to 1, for
    /// example for points on one circle). The other timings close every loop.
    TimingNotClosed {
        /// `"book"`.
        timing: &'static str,
        /// The product of the ratios `ψ_j/φ_j` around the loop.
        ratio: f64,
    },
    /// A clamped end velocity cannot be used.
    InvalidEndVelocity {
        /// `true` for the velocity at the first key, `false` for the one at the last key.
        start: bool,
        /// What is wrong, for example `"is not tangent to the first key"`.
        reason: &'static str,
    },
    /// A given key velocity ([`CubicSpline::try_hermite`](crate::CubicSpline::try_hermite))
    /// cannot be used.
    InvalidKeyVelocity {
        /// Index of the key (and of its velocity).
        index: usize,
        /// What is wrong, for example `"is not tangent to its key"`.
        reason: &'static str,
    },
    /// The ambient (unnormalised) curve of the segment that starts at point `index` may pass
    /// through the origin, where normalising it has no direction
    /// ([`CatmullRomNlerp`](crate::CatmullRomNlerp): keys about a half turn apart or more).
    ThroughOrigin {
        /// Index of the segment's first key in the input points.
        index: usize,
        /// Index of its last key (`index + 1`, or 0 for the closing segment of a loop).
        next: usize,
    },
}

impl fmt::Display for SplineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::TooFewPoints { min, got } => {
                write!(f, "this method needs at least {min} points, got {got}")
            }
            Self::InvalidPoint { index, reason } => {
                write!(f, "point {index} {}", reason.predicate())
            }
            Self::Antipodal { index } => write!(
                f,
                "points {index} and {} are antipodal: the geodesic between them is not unique (for quaternions, q and −q are the same rotation: unflip the keys)",
                index + 1
            ),
            Self::Coincident { index } => write!(
                f,
                "points {index} and {} coincide: this method needs distinct consecutive points",
                index + 1
            ),
            Self::InvalidKnot { index } => write!(f, "knot {index} is not finite"),
            Self::KnotsNotIncreasing { index } => write!(
                f,
                "knot {index} is not greater than knot {}: knots must be strictly increasing",
                index.saturating_sub(1)
            ),
            Self::KnotSpacing { index } => write!(
                f,
                "the spacing of knots {} and {index} must be from {:e} to {:e}: derivatives would overflow",
                index.saturating_sub(1),
                crate::MIN_KNOT_SPACING,
                crate::MAX_KNOT_SPACING
            ),
            Self::KnotCount { expected, got } => {
                write!(f, "expected {expected} knots, got {got}")
            }
            Self::InvalidParameter { name, reason } => write!(f, "parameter {name}: {reason}"),
            Self::NoCircle { index } => write!(
                f,
                "points {index} and {} coincide: no unique circle passes through points {index}, {} and {}",
                index + 2,
                index + 1,
                index + 2
            ),
            Self::Solve(e) => write!(f, "{e}"),
            Self::TimingNotRepresentable {
                timing,
                index,
                spacing,
                ratio,
                knot,
            } => {
                let why = if !spacing.is_finite() || *spacing > crate::MAX_KNOT_SPACING {
                    format!("above the largest spacing {:e}", crate::MAX_KNOT_SPACING)
                } else if *spacing < crate::MIN_KNOT_SPACING {
                    format!("below the smallest spacing {:e}", crate::MIN_KNOT_SPACING)
                } else {
                    format!(
                        "lost to rounding next to the knot {knot:.6e} of point {}",
                        index.saturating_sub(1)
                    )
                };
                if *timing == "book" {
                    write!(
                        f,
                        "the book's arc-blend knots cannot be represented at point {index}: the ratios ψ/φ of the circles before this point multiply to {ratio:.1e}, a knot spacing of {spacing:.1e}, {why}; use the arc-length or uniform timing, which trace the same curve"
                    )
                } else {
                    write!(
                        f,
                        "the {timing} knots cannot be represented at point {index}: the segment from point {} has length {spacing:.1e}, {why}; use the uniform timing, which traces the same curve",
                        index.saturating_sub(1)
                    )
                }
            }
            Self::AntipodalClosing => f.write_str(
                "the last and the first point are antipodal: the closing geodesic is not unique",
            ),
            Self::CoincidentClosing => f.write_str(
                "the last and the first point coincide: this method needs distinct consecutive points, the closing pair of a loop included",
            ),
            Self::NoCircleAround {
                first,
                middle,
                last,
            } => write!(
                f,
                "points {first} and {last} coincide: no unique circle passes through points {first}, {middle} and {last} of the loop"
            ),
            Self::TimingNotClosed { timing, ratio } => write!(
                f,
                "the {timing} knots do not close the loop: the ratios ψ/φ of the circles around it multiply to {ratio:.6} instead of 1 (only points on one circle close); use the auto, arc-length or uniform timing, which trace the same curve"
            ),
            Self::InvalidEndVelocity { start, reason } => {
                let which = if *start { "start" } else { "end" };
                write!(f, "the {which} velocity {reason}")
            }
            Self::InvalidKeyVelocity { index, reason } => {
                write!(f, "the velocity at point {index} {reason}")
            }
            Self::ThroughOrigin { index, next } => write!(
                f,
                "the segment from point {index} to point {next}: its ambient curve may pass through the origin, where normalising has no direction (the keys around it are too far apart; for quaternions, unflip them)"
            ),
        }
    }
}

impl core::error::Error for SplineError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            Self::Solve(e) => Some(e),
            _ => None,
        }
    }
}

impl From<SolveError> for SplineError {
    fn from(e: SolveError) -> Self {
        Self::Solve(e)
    }
}

/// Why an iterative solver gave up.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SolveError {
    /// The iteration stopped (iteration limit, stalled, or a non-finite or degenerate value)
    /// without meeting its tolerance; the result would not satisfy the equations.
    NoConvergence {
        /// Iterations performed.
        iterations: usize,
        /// The residual when it stopped (for interpolation: the largest geodesic distance in
        /// radians between the curve at a knot and its data point; infinite when it could not
        /// be evaluated).
        residual: f64,
    },
}

impl fmt::Display for SolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoConvergence {
                iterations,
                residual,
            } => write!(
                f,
                "the solver did not converge: residual {residual:.3e} after {iterations} iterations"
            ),
        }
    }
}

impl core::error::Error for SolveError {}

/// Why an arc-length parametrisation ([`ArcLength`](crate::ArcLength)) could not be built.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ArcLengthError {
    /// The accuracy is not a positive finite number of radians.
    InvalidAccuracy {
        /// The accuracy given.
        accuracy: f64,
    },
    /// The curve has zero length (within the accuracy): it stays at one point, so there is no
    /// arc-length parameter.
    ZeroLength,
    /// The curve's speed is not finite at the parameter `t`.
    NonFiniteSpeed {
        /// The parameter of the curve.
        t: f64,
    },
}

impl fmt::Display for ArcLengthError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidAccuracy { accuracy } => write!(
                f,
                "the arc-length accuracy {accuracy:e} must be a positive finite number of radians"
            ),
            Self::ZeroLength => f.write_str(
                "the curve has zero length: it stays at one point and has no arc-length parameter",
            ),
            Self::NonFiniteSpeed { t } => write!(f, "the curve's speed is not finite at t = {t:e}"),
        }
    }
}

impl core::error::Error for ArcLengthError {}

/// Why a checked evaluation ([`Extrapolated::try_jet`](crate::Extrapolated::try_jet)) has no
/// value at a parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum DomainError {
    /// The parameter `t` is outside the curve's domain and the policy is
    /// [`Extrapolate::Error`](crate::Extrapolate::Error).
    Outside {
        /// The parameter.
        t: f64,
        /// The curve's domain `[t0, t1]`.
        domain: [f64; 2],
    },
    /// The parameter is NaN (under every policy).
    NotANumber,
    /// The parameter `t` is infinite, or so far outside the domain that the extension angle
    /// overflows, and the policy ([`Extend`](crate::Extrapolate::Extend) or
    /// [`Cycle`](crate::Extrapolate::Cycle)) has no value there.
    Unbounded {
        /// The parameter.
        t: f64,
    },
}

impl fmt::Display for DomainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Outside { t, domain } => write!(
                f,
                "the parameter {t} is outside the curve's domain [{}, {}]",
                domain[0], domain[1]
            ),
            Self::NotANumber => f.write_str("the parameter is NaN"),
            Self::Unbounded { t } => write!(
                f,
                "the parameter {t} is too far outside the domain: the curve has no value there under this extrapolation policy"
            ),
        }
    }
}

impl core::error::Error for DomainError {}
