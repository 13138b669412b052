// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Checks of what the page passes in that the scene format does not see: indices, coordinate
//! arrays, field names.

use core::fmt;

use serde_json::{Map, Value};
use spherekit::UnitQuat;
use spherekit::scene::MAX_DIMENSION;

/// A bad argument from the page (the scene's own errors are [`spherekit::scene::SceneError`]).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum InputError {
    /// There is no curve with this index.
    NoCurve(usize),
    /// There is no point with this index.
    NoPoint(usize),
    /// The last curve of a scene cannot be removed.
    LastCurve,
    /// Coordinates are not finite or have the wrong count.
    Coords(String),
    /// A JSON argument could not be read.
    Json(String),
    /// The sample output has no such field.
    Field(String),
    /// The canvas has no 2D context or refused the image.
    NoContext,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoCurve(i) => write!(f, "curves[{i}]: there is no such curve"),
            Self::NoPoint(i) => write!(f, "points[{i}]: there is no such point"),
            Self::LastCurve => write!(f, "curves: the last curve cannot be removed"),
            Self::Coords(m) => write!(f, "coordinates: {m}"),
            Self::Json(m) => write!(f, "invalid JSON: {m}"),
            Self::Field(name) => write!(
                f,
                "field \"{name}\" is not a sample field ({})",
                spherekit::scene::SAMPLE_FIELDS.join(", ")
            ),
            Self::NoContext => write!(f, "canvas: no 2D context"),
        }
    }
}

impl core::error::Error for InputError {}

/// Coordinates of a new point as a JSON list (the scene checks their count and length).
pub(crate) fn point_value(coords: &[f64]) -> Result<Value, InputError> {
    if coords.is_empty() || coords.len() > MAX_DIMENSION + 1 {
        return Err(InputError::Coords(format!(
            "expected 2 to {} numbers, got {}",
            MAX_DIMENSION + 1,
            coords.len()
        )));
    }
    if let Some(i) = coords.iter().position(|x| !x.is_finite()) {
        return Err(InputError::Coords(format!("[{i}] is not a finite number")));
    }
    Ok(Value::from(coords.to_vec()))
}

/// A unit quaternion from `[w, x, y, z]`.
pub(crate) fn quat(c: &[f64]) -> Result<UnitQuat, InputError> {
    match c {
        &[w, x, y, z] => UnitQuat::from_wxyz([w, x, y, z])
            .map_err(|e| InputError::Coords(format!("quaternion {e}"))),
        _ => Err(InputError::Coords(format!(
            "a quaternion has 4 numbers [w, x, y, z], got {}",
            c.len()
        ))),
    }
}

/// A point inserted before, or removed at, an index of a curve's `points`.
#[derive(Clone, Copy, Debug)]
pub(crate) enum PointEdit {
    Insert(usize),
    Remove(usize),
}

/// Keeps a curve's per-point lists in step with an edit of its `count` points, so that adding
/// or deleting a point in the page does not make `knots` or a per-joint parameter list (β₁, β₂,
/// γ) the wrong length. A list of `len ≤ count` numbers is taken to skip `(count − len) / 2`
/// points at each end (Catmull-Rom's steering end points have no knot; Gamma's γ list starts at
/// the second interior knot): the entry at the matching position is removed, or one is inserted
/// there, midway between its neighbours for `knots` (one spacing beyond an end), a copy of its
/// neighbour for a parameter. A parameter list that would become empty becomes its last value
/// (one number for every joint). Longer lists and lists of non-numbers are left for the
/// scene's validation to report.
pub(crate) fn follow_points(curve: &mut Map<String, Value>, count: usize, edit: PointEdit) {
    if let Some(Value::Array(knots)) = curve.get_mut("knots") {
        follow(knots, true, count, edit);
    }
    if let Some(Value::Object(params)) = curve.get_mut("params") {
        for value in params.values_mut() {
            if let Value::Array(list) = value
                && let Some(removed) = follow(list, false, count, edit)
                && list.is_empty()
            {
                *value = Value::from(removed);
            }
        }
    }
}

/// Applies `edit` to one list (see [`follow_points`]); returns the value removed, if any.
fn follow(list: &mut Vec<Value>, is_knots: bool, count: usize, edit: PointEdit) -> Option<f64> {
    let x: Vec<f64> = list.iter().map(Value::as_f64).collect::<Option<_>>()?;
    let len = x.len();
    if len == 0 || len > count {
        return None;
    }
    let skip = (count - len) / 2;
    match edit {
        PointEdit::Insert(index) => {
            let j = index.saturating_sub(skip).min(len);
            // Differences first: no overflow for knots near the largest doubles.
            let value = match (is_knots, len) {
                (false, _) => x[j.min(len - 1)],
                (true, 1) => return None,
                (true, _) if j == 0 => x[0] - (x[1] - x[0]),
                (true, _) if j == len => x[len - 1] + (x[len - 1] - x[len - 2]),
                (true, _) => x[j - 1] + 0.5 * (x[j] - x[j - 1]),
            };
            list.insert(j, Value::from(value));
            None
        }
        PointEdit::Remove(index) => {
            let k = index.saturating_sub(skip).min(len - 1);
            list.remove(k);
            Some(x[k])
        }
    }
}
