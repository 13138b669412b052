// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! A method's parameters: their schema (one list per method, in the registry) and typed
//! access to a scene's `params` object that checks every key against it.

use serde_json::{Map, Value, json};

use crate::error::{SceneError, field_error};
use crate::registry::{Method, Spaces};

/// One parameter of a method, as the registry describes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Param {
    /// The key in `params`.
    pub name: &'static str,
    /// A short label for controls (`γ`, `β₁ bias`).
    pub label: &'static str,
    /// One line on what it does.
    pub summary: &'static str,
    /// Its type, default and range.
    pub kind: ParamKind,
    /// Whether a list with one value per joint is accepted in place of one number.
    pub per_joint: Option<PerJoint>,
    /// The spaces it applies to.
    pub spaces: Spaces,
    /// A solver setting rather than a shape parameter, or a value too large for a form control
    /// (a list of vectors): the page gives it no control of its own (its "params as JSON" box
    /// edits it).
    pub advanced: bool,
    /// The setting it belongs to: `(parameter, value)` when it applies (and is needed) only
    /// while that choice parameter has that value (the cubic's end velocities with `end`
    /// `"clamped"`). The construction checks it; controls are set and cleared together.
    pub requires: Option<(&'static str, &'static str)>,
    /// Whether it is about the curve's ends, so that a closed loop has no use for it.
    pub open_only: bool,
    /// An earlier name of the key, still read from scenes (and Python keywords) but not listed
    /// in the registry JSON: `params` may give one of the two.
    pub formerly: Option<&'static str>,
}

/// The type of a parameter, its default and its range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamKind {
    /// A finite number. `min..=max` is the range a control offers; the construction checks
    /// validity (and may accept more).
    Number {
        /// The value when the key is absent; NaN (`null` in JSON) when the construction then
        /// chooses its own.
        default: f64,
        /// Lower end of the offered range.
        min: f64,
        /// Upper end of the offered range.
        max: f64,
    },
    /// A whole number in `min..=max` (checked).
    Integer {
        /// The value when the key is absent; below `min` when the construction then chooses
        /// its own (`null` in JSON).
        default: u64,
        /// The smallest value.
        min: u64,
        /// The largest value.
        max: u64,
    },
    /// `true` or `false`.
    Bool {
        /// The value when the key is absent.
        default: bool,
    },
    /// One of a list of names; the first is the default.
    Choice(&'static [&'static str]),
    /// A vector of finite numbers (a velocity); absent by default.
    Vector,
    /// A list of vectors of finite numbers, one per point (the velocity at every key); absent
    /// by default. A closed S³ loop of an odd number of turns, built on its doubled keys,
    /// takes the list twice ([`Param::per_point_count`]).
    Vectors,
}

/// How a per-joint list lines up with the points: it has `points − 2·skip` entries, the first
/// for point `skip`, numbered from `first` in the sources; on a closed curve it has one entry
/// per point (every point is a joint of a loop, the first one at the seam).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PerJoint {
    /// Points at each end without an entry.
    pub skip: usize,
    /// The sources' index of the first entry (the Gamma paper's γ₁).
    pub first: usize,
}

impl PerJoint {
    /// The length of the list for `points` points of an open or closed curve.
    #[must_use]
    pub fn count_for(self, points: usize, closed: bool) -> usize {
        if closed {
            points
        } else {
            points.saturating_sub(2 * self.skip)
        }
    }
}

impl Param {
    /// A parameter of `kind`, for one value only, on every sphere.
    const fn of_kind(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
        kind: ParamKind,
    ) -> Self {
        Self {
            name,
            label,
            summary,
            kind,
            per_joint: None,
            spaces: Spaces::All,
            advanced: false,
            requires: None,
            open_only: false,
            formerly: None,
        }
    }

    /// A number with an offered range `[default, min, max]`.
    pub(crate) const fn number(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
        [default, min, max]: [f64; 3],
    ) -> Self {
        Self::of_kind(
            name,
            label,
            summary,
            ParamKind::Number { default, min, max },
        )
    }

    /// A whole number `[default, min, max]` (a default below `min`: the construction's own).
    pub(crate) const fn integer(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
        [default, min, max]: [u64; 3],
    ) -> Self {
        Self::of_kind(
            name,
            label,
            summary,
            ParamKind::Integer { default, min, max },
        )
    }

    /// `true` or `false`.
    pub(crate) const fn boolean(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
        default: bool,
    ) -> Self {
        Self::of_kind(name, label, summary, ParamKind::Bool { default })
    }

    /// One of `choices`, the first the default.
    pub(crate) const fn choice(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
        choices: &'static [&'static str],
    ) -> Self {
        Self::of_kind(name, label, summary, ParamKind::Choice(choices))
    }

    /// A vector of finite numbers, absent by default.
    pub(crate) const fn vector(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
    ) -> Self {
        Self::of_kind(name, label, summary, ParamKind::Vector)
    }

    /// A list of vectors of finite numbers, one per point, absent by default.
    pub(crate) const fn vectors(
        name: &'static str,
        label: &'static str,
        summary: &'static str,
    ) -> Self {
        Self::of_kind(name, label, summary, ParamKind::Vectors)
    }

    /// The length of the parameter's list when it has one entry per point or per joint (its
    /// per-joint list, or a list of [`ParamKind::Vectors`]) for `points` points of an open or
    /// closed curve; `None` for a parameter of one value.
    #[must_use]
    pub fn per_point_count(&self, points: usize, closed: bool) -> Option<usize> {
        match (self.per_joint, self.kind) {
            (Some(per_joint), _) => Some(per_joint.count_for(points, closed)),
            (None, ParamKind::Vectors) => Some(points),
            (None, _) => None,
        }
    }

    /// Accepts a per-joint list too.
    pub(crate) const fn per_joint(mut self, skip: usize, first: usize) -> Self {
        self.per_joint = Some(PerJoint { skip, first });
        self
    }

    /// Applies on S³ only.
    pub(crate) const fn s3_only(mut self) -> Self {
        self.spaces = Spaces::S3;
        self
    }

    /// Applies on S² only.
    pub(crate) const fn s2_only(mut self) -> Self {
        self.spaces = Spaces::S2;
        self
    }

    /// Also read under its earlier name `name`.
    pub(crate) const fn formerly(mut self, name: &'static str) -> Self {
        self.formerly = Some(name);
        self
    }

    /// A solver setting, or a value for the "params as JSON" box only.
    pub(crate) const fn advanced(mut self) -> Self {
        self.advanced = true;
        self
    }

    /// Applies to an open curve only (it is about the ends).
    pub(crate) const fn open_only(mut self) -> Self {
        self.open_only = true;
        self
    }

    /// Applies only while choice parameter `param` is `value`.
    pub(crate) const fn requires(mut self, param: &'static str, value: &'static str) -> Self {
        self.requires = Some((param, value));
        self
    }

    /// The parameter as JSON (for `spherekit methods --json` and the page's controls).
    #[must_use]
    pub fn to_json(&self) -> Value {
        let (kind, extra) = match self.kind {
            ParamKind::Number { default, min, max } => (
                "number",
                json!({ "default": default, "min": min, "max": max }),
            ),
            ParamKind::Integer { default, min, max } => (
                "integer",
                json!({ "default": (default >= min).then_some(default), "min": min, "max": max }),
            ),
            ParamKind::Bool { default } => ("bool", json!({ "default": default })),
            ParamKind::Choice(choices) => (
                "choice",
                json!({ "default": choices[0], "choices": choices }),
            ),
            ParamKind::Vector => ("vector", json!({ "default": null })),
            ParamKind::Vectors => ("vectors", json!({ "default": null })),
        };
        let mut out = json!({
            "name": self.name,
            "label": self.label,
            "summary": self.summary,
            "type": kind,
            "spaces": self.spaces.names(),
            "advanced": self.advanced,
            "open_only": self.open_only,
        });
        if let (Value::Object(o), Value::Object(e)) = (&mut out, extra) {
            o.extend(e);
            o.insert(
                "per_joint".into(),
                match self.per_joint {
                    None => Value::Null,
                    Some(p) => json!({ "skip": p.skip, "first": p.first }),
                },
            );
            o.insert(
                "requires".into(),
                match self.requires {
                    None => Value::Null,
                    Some((param, value)) => json!({ "param": param, "value": value }),
                },
            );
        }
        out
    }
}

/// `params` with every key given by its earlier name ([`Param::formerly`]) under its name.
///
/// # Errors
///
/// A [`SceneError::Field`] on `params.<earlier name>` when both names are given.
pub(crate) fn current_names(
    method: &Method,
    mut params: Map<String, Value>,
) -> Result<Map<String, Value>, SceneError> {
    for p in method.params {
        let Some(old) = p.formerly else { continue };
        let Some(value) = params.remove(old) else {
            continue;
        };
        if params.contains_key(p.name) {
            return Err(field_error(
                format!("params.{old}"),
                format!("is the earlier name of params.{}: give one of them", p.name),
            ));
        }
        params.insert(p.name.into(), value);
    }
    Ok(params)
}

/// A parameter given as one number for every point or joint, or as a list.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum NumberOrList {
    One(f64),
    List(Vec<f64>),
}

/// Typed access to a curve's `params`, by the method's schema; keys the method does not
/// have (or that do not apply on this sphere) are an error at [`Params::finish`].
#[derive(Debug)]
pub(crate) struct Params<'a> {
    method: &'static Method,
    map: &'a Map<String, Value>,
    used: Vec<&'static str>,
}

impl<'a> Params<'a> {
    pub(crate) fn new(method: &'static Method, map: &'a Map<String, Value>) -> Self {
        Self {
            method,
            map,
            used: Vec::new(),
        }
    }

    fn schema(&self, name: &str) -> Option<&'static Param> {
        let p = self.method.params.iter().find(|p| p.name == name);
        debug_assert!(
            p.is_some(),
            "{} reads an unregistered parameter {name}",
            self.method.id
        );
        p
    }

    fn get(&mut self, name: &'static str) -> Option<&'a Value> {
        self.used.push(name);
        self.map.get(name)
    }

    /// A number (the schema's default when absent).
    pub(crate) fn number(&mut self, name: &'static str) -> Result<f64, SceneError> {
        let default = match self.schema(name).map(|p| p.kind) {
            Some(ParamKind::Number { default, .. }) => default,
            _ => 0.0,
        };
        match self.get(name) {
            None => Ok(default),
            Some(v) => v
                .as_f64()
                .filter(|x| x.is_finite())
                .ok_or_else(|| field_error(format!("params.{name}"), "must be a finite number")),
        }
    }

    /// A number, a list of numbers, or the schema's default. Ranges and list lengths are
    /// checked by the construction, which knows them.
    pub(crate) fn number_or_list(
        &mut self,
        name: &'static str,
    ) -> Result<NumberOrList, SceneError> {
        let default = match self.schema(name).map(|p| p.kind) {
            Some(ParamKind::Number { default, .. }) => default,
            _ => 0.0,
        };
        match self.get(name) {
            None => Ok(NumberOrList::One(default)),
            Some(Value::Array(a)) => a
                .iter()
                .enumerate()
                .map(|(i, v)| {
                    v.as_f64().ok_or_else(|| {
                        field_error(format!("params.{name}[{i}]"), "must be a number")
                    })
                })
                .collect::<Result<_, _>>()
                .map(NumberOrList::List),
            Some(v) => v.as_f64().map(NumberOrList::One).ok_or_else(|| {
                field_error(
                    format!("params.{name}"),
                    "must be a number or a list of numbers",
                )
            }),
        }
    }

    /// A positive number, or `None` when absent.
    pub(crate) fn positive(&mut self, name: &'static str) -> Result<Option<f64>, SceneError> {
        let _ = self.schema(name);
        match self.get(name) {
            None => Ok(None),
            Some(v) => v
                .as_f64()
                .filter(|x| x.is_finite() && *x > 0.0)
                .map(Some)
                .ok_or_else(|| field_error(format!("params.{name}"), "must be a positive number")),
        }
    }

    /// A whole number in the schema's range; `None` when absent and the schema has no default.
    pub(crate) fn integer(&mut self, name: &'static str) -> Result<usize, SceneError> {
        let (default, min, max) = match self.schema(name).map(|p| p.kind) {
            Some(ParamKind::Integer { default, min, max }) => (default, min, max),
            _ => (0, 0, u64::MAX),
        };
        let n = match self.get(name) {
            None => default,
            Some(v) => v.as_u64().ok_or_else(|| {
                field_error(
                    format!("params.{name}"),
                    format!("must be a whole number from {min} to {max}"),
                )
            })?,
        };
        (min..=max)
            .contains(&n)
            .then(|| usize::try_from(n).ok())
            .flatten()
            .ok_or_else(|| {
                field_error(
                    format!("params.{name}"),
                    format!("must be a whole number from {min} to {max}, got {n}"),
                )
            })
    }

    /// A whole number in the schema's range, or `None` when absent.
    pub(crate) fn optional_integer(
        &mut self,
        name: &'static str,
    ) -> Result<Option<usize>, SceneError> {
        if self.map.contains_key(name) {
            self.integer(name).map(Some)
        } else {
            self.used.push(name);
            Ok(None)
        }
    }

    /// `true` or `false` (the schema's default when absent).
    pub(crate) fn boolean(&mut self, name: &'static str) -> Result<bool, SceneError> {
        let default = matches!(
            self.schema(name).map(|p| p.kind),
            Some(ParamKind::Bool { default: true })
        );
        match self.get(name) {
            None => Ok(default),
            Some(v) => v
                .as_bool()
                .ok_or_else(|| field_error(format!("params.{name}"), "must be true or false")),
        }
    }

    /// One of the schema's choices (the first when absent).
    pub(crate) fn choice(&mut self, name: &'static str) -> Result<&'static str, SceneError> {
        let choices: &'static [&'static str] = match self.schema(name).map(|p| p.kind) {
            Some(ParamKind::Choice(c)) => c,
            _ => &[""],
        };
        match self.get(name) {
            None => Ok(choices[0]),
            Some(v) => v
                .as_str()
                .and_then(|s| choices.iter().find(|c| **c == s).copied())
                .ok_or_else(|| {
                    field_error(
                        format!("params.{name}"),
                        format!("must be one of: {}", choices.join(", ")),
                    )
                }),
        }
    }

    /// A list of finite numbers, or `None` when absent.
    pub(crate) fn vector(&mut self, name: &'static str) -> Result<Option<Vec<f64>>, SceneError> {
        let _ = self.schema(name);
        self.get(name)
            .map(|v| finite_numbers(v, &format!("params.{name}")))
            .transpose()
    }

    /// A list of lists of finite numbers (one vector per point; the count is the
    /// construction's to check), or `None` when absent.
    pub(crate) fn vectors(
        &mut self,
        name: &'static str,
    ) -> Result<Option<Vec<Vec<f64>>>, SceneError> {
        let _ = self.schema(name);
        let Some(v) = self.get(name) else {
            return Ok(None);
        };
        let list = v.as_array().ok_or_else(|| {
            field_error(
                format!("params.{name}"),
                "must be a list of vectors, one per point",
            )
        })?;
        list.iter()
            .enumerate()
            .map(|(i, x)| finite_numbers(x, &format!("params.{name}[{i}]")))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// Rejects keys no accessor asked for.
    pub(crate) fn finish(self) -> Result<(), SceneError> {
        match self.map.keys().find(|k| !self.used.contains(&k.as_str())) {
            None => Ok(()),
            Some(k) => Err(field_error(
                format!("params.{k}"),
                format!("unknown parameter for method \"{}\"", self.method.id),
            )),
        }
    }
}

/// `value` as a list of finite numbers, or an error on `field`.
fn finite_numbers(value: &Value, field: &str) -> Result<Vec<f64>, SceneError> {
    let bad = || field_error(field, "must be a list of finite numbers");
    value
        .as_array()
        .ok_or_else(bad)?
        .iter()
        .map(|x| x.as_f64().filter(|x| x.is_finite()).ok_or_else(bad))
        .collect()
}
