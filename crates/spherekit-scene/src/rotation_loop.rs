// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Closed S³ curves whose canonicalised keys turn by an odd number of full turns: built as the
//! loop of rotations they are ([`spherekit::RotationLoop`]), for every method that closes.
//!
//! The method's own build function builds the doubled loop (keys `q₀ … q_{n−1}, −q₀ … −q_{n−1}`,
//! knots continued by one period, every per-joint list and the key velocities twice); the loop
//! keeps its first half, and so do the extras the method derives: its controls and auxiliary
//! vertices, its knots and its per-joint report (the doubled loop's are its own followed by
//! their antipodes).

use serde_json::{Map, Value};
use spherekit::{Curve, RotationLoop, UnitQuat};

use crate::built::{Built, BuiltCurve};
use crate::error::{SceneError, field_error};
use crate::params::Params;
use crate::registry::Method;
use crate::scene::{Input, Points};

type BoxedCurve = Box<dyn Curve<Point = UnitQuat> + Send + Sync>;

/// Builds the closed curve of `method` through `keys` (canonicalised, closing at `−q₀`) as a
/// loop of rotations.
///
/// A per-joint list that does not have one entry per key is passed on as given, with the keys
/// as given (as is a knot list of the wrong length), so that the method reports it in the
/// scene's terms.
pub(crate) fn build(
    method: &'static Method,
    keys: Vec<UnitQuat>,
    knots: Option<Vec<f64>>,
    params: &Map<String, Value>,
) -> Result<BuiltCurve, SceneError> {
    let n = keys.len();
    let Some(doubled) = doubled_params(method, params, n) else {
        return (method.build)(input(method, keys, knots, params));
    };
    let inputs = keys.clone();
    let mut extras = None;
    let curve = RotationLoop::try_new(keys, knots, |keys, knots| {
        let built = (method.build)(input(method, keys, knots, &doubled))?;
        let BuiltCurve::S3(built) = built else {
            return Err(field_error(
                "space",
                "the method built no curve of rotations",
            ));
        };
        let Built {
            curve,
            controls,
            auxiliary,
            info,
            order,
            ..
        } = built;
        extras = Some((controls, auxiliary, info, order));
        Ok::<BoxedCurve, SceneError>(curve)
    })?;
    let Some((mut controls, mut auxiliary, mut info, order)) = extras else {
        return Err(field_error("method", "built no curve"));
    };
    if curve.is_antiperiodic() {
        first_half(&mut controls);
        first_half(&mut auxiliary);
        for list in ["knots", "joints"] {
            if let Some(Value::Array(v)) = info.get_mut(list) {
                first_half(v);
            }
        }
    }
    let mut built = Built::new(curve, inputs)
        .with_controls(controls)
        .with_order(order);
    built.auxiliary = auxiliary;
    built.info = info;
    Ok(BuiltCurve::S3(built))
}

/// The first half of a list the doubled loop derived: `2k` entries (per key or per piece) keep
/// `k`; `2k + 1` (per knot, ends included) keep `k + 1`, up to the end of the loop.
fn first_half<T>(v: &mut Vec<T>) {
    v.truncate(v.len().div_ceil(2));
}

fn input<'a>(
    method: &'static Method,
    keys: Vec<UnitQuat>,
    knots: Option<Vec<f64>>,
    params: &'a Map<String, Value>,
) -> Input<'a> {
    Input {
        points: Points::S3(keys),
        knots,
        closed: true,
        params: Params::new(method, params),
    }
}

/// The parameters for the doubled keys: every list with an entry per key (per-joint lists, the
/// key velocities) twice. `None` when such a list has not one entry per key (the method then
/// reports the count for the keys given). An angular velocity is one of the rotation, the same
/// at `q` and `−q`, so the second copy of the key velocities is the first.
fn doubled_params(
    method: &'static Method,
    params: &Map<String, Value>,
    n: usize,
) -> Option<Map<String, Value>> {
    let mut out = params.clone();
    for param in method.params {
        let (Some(count), Some(Value::Array(list))) =
            (param.per_point_count(n, true), out.get_mut(param.name))
        else {
            continue;
        };
        if list.len() != count {
            return None;
        }
        list.extend_from_within(..);
    }
    Some(out)
}
