// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Scene errors: the core says what is wrong, this layer adds where (`points[3]: …`).

use core::fmt;

use spherekit::SplineError;

/// Why a scene could not be read, built or drawn. The `Display` text is one line naming the
/// field.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SceneError {
    /// The text is not valid JSON or does not have the scene's shape.
    Json(String),
    /// A field has a bad value.
    Field {
        /// The field, as a JSON path such as `points[2]`, `params.gamma` or `view.camera`.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// The curve could not be built; the message names the scene field the error is about.
    Spline(SplineError),
    /// As [`SceneError::Spline`], with a hint on what to do.
    Hinted {
        /// The construction's error.
        error: SplineError,
        /// What to do, one clause.
        hint: &'static str,
    },
    /// An error in one curve of a scene's `curves` list.
    InCurve {
        /// Index into `curves`.
        index: usize,
        /// The error.
        error: Box<SceneError>,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Messages quote the scene's own strings (an unknown field or method name, a colour),
        // which may hold control characters such as a JSON-escaped newline: escape them so that
        // the text stays one line.
        let text = match self {
            Self::Json(m) => format!("invalid scene JSON: {m}"),
            Self::Field { field, message } => format!("{field}: {message}"),
            Self::Spline(e) => spline_message(e),
            Self::Hinted { error, hint } => format!("{}; {hint}", spline_message(error)),
            Self::InCurve { index, error } => format!("curves[{index}].{error}"),
        };
        f.write_str(&one_line(&text))
    }
}

impl core::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            Self::Spline(e) | Self::Hinted { error: e, .. } => Some(e),
            Self::InCurve { error, .. } => Some(&**error),
            _ => None,
        }
    }
}

impl From<SplineError> for SceneError {
    fn from(e: SplineError) -> Self {
        Self::Spline(e)
    }
}

/// A construction error as the scene names it: the core's indices become the fields they
/// index (`points[3]`, `knots[2]`, `params.order`).
fn spline_message(e: &SplineError) -> String {
    match e {
        SplineError::TooFewPoints { min, got } => {
            format!("points: this method needs at least {min} points, got {got}")
        }
        SplineError::InvalidPoint { index, reason } => {
            format!("points[{index}] {}", reason.predicate())
        }
        SplineError::Antipodal { index } => format!(
            "points[{index}] and points[{}] are antipodal: the geodesic between them is not unique",
            index + 1
        ),
        SplineError::Coincident { index } => format!(
            "points[{index}] and points[{}] coincide: this method needs distinct consecutive points",
            index + 1
        ),
        SplineError::InvalidKnot { index } => format!("knots[{index}] is not finite"),
        SplineError::KnotsNotIncreasing { index } => format!(
            "knots[{index}] is not greater than knots[{}]: knots must be strictly increasing",
            index.saturating_sub(1)
        ),
        SplineError::KnotSpacing { index } => format!(
            "knots[{index}] − knots[{}] must be from {:e} to {:e}: derivatives would overflow",
            index.saturating_sub(1),
            spherekit::MIN_KNOT_SPACING,
            spherekit::MAX_KNOT_SPACING
        ),
        SplineError::KnotCount { expected, got } => {
            format!("knots: expected {expected} knots, got {got}")
        }
        SplineError::InvalidParameter { name, reason } => format!("params.{name}: {reason}"),
        SplineError::NoCircle { index } => format!(
            "points[{index}] and points[{}] coincide: no unique circle passes through points[{index}], points[{}] and points[{}]",
            index + 2,
            index + 1,
            index + 2
        ),
        SplineError::Solve(e) => format!("params.solver: {e}"),
        SplineError::TimingNotRepresentable { index, .. } => format!("points[{index}]: {e}"),
        SplineError::InvalidEndVelocity { start, .. } => format!(
            "params.{}_velocity: {e}",
            if *start { "start" } else { "end" }
        ),
        SplineError::InvalidKeyVelocity { index, reason } => {
            format!("params.velocities[{index}]: {reason}")
        }
        SplineError::AntipodalClosing | SplineError::CoincidentClosing => format!("closed: {e}"),
        SplineError::NoCircleAround {
            first,
            middle,
            last,
        } => format!(
            "points[{first}] and points[{last}] coincide: no unique circle passes through points[{first}], points[{middle}] and points[{last}] of the loop"
        ),
        SplineError::TimingNotClosed { .. } => format!("params.timing: {e}"),
        SplineError::ThroughOrigin { index, next } => format!(
            "points[{index}] to points[{next}]: the ambient curve of this segment may pass through the origin, where normalising has no direction (the keys around it are too far apart; for quaternions, canonicalize them)"
        ),
        // Errors added to the core later: its own words, which name no field.
        e => e.to_string(),
    }
}

/// `text` with every control character escaped (`\n` becomes the two characters `\` `n`), so
/// that an error message quoting user input is one line.
///
/// ```
/// assert_eq!(spherekit_scene::one_line("a\nb\tc"), "a\\nb\\tc");
/// ```
#[must_use]
pub fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

pub(crate) fn field_error(field: impl Into<String>, message: impl Into<String>) -> SceneError {
    SceneError::Field {
        field: field.into(),
        message: message.into(),
    }
}

/// Wraps an error with the curve it belongs to in a `curves` list.
pub(crate) fn in_curve(index: Option<usize>, e: SceneError) -> SceneError {
    match index {
        None => e,
        Some(index) => SceneError::InCurve {
            index,
            error: Box::new(e),
        },
    }
}
