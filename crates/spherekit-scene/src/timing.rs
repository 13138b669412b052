// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! A curve's timing, the same for every method: its parameter (`"parametrization"`: the
//! method's own, or arc length) and what it is outside its domain (`"extrapolate"`). Both are
//! curve-level fields of the scene, read here and applied here to whatever curve a method
//! builds ([`spherekit::ArcLength`], then [`spherekit::Extrapolated`]), so that no method's
//! file knows about them.

use serde_json::{Value, json};
use spherekit::{ArcLength, ArcLengthInfo, Curve, DomainError, Extrapolate, Extrapolated};

use crate::built::{Built, BuiltCurve, ScenePoint};
use crate::error::{SceneError, field_error};

/// The parameter a scene's curve runs over (`"parametrization"`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Parametrization {
    /// The method's own parameter `t` (its knots, or `[0, 1]`): `"native"`, the default.
    #[default]
    Native,
    /// Arc length `s ∈ [0, L]` ([`spherekit::ArcLength`] at its default accuracy, 1e-10 rad):
    /// great-circle arc length on S² and S^m, the rotation angle on S³, so that the curve moves
    /// at unit speed (`|ω| = 1` on S³): `"arclength"`.
    ArcLength,
}

/// The names of [`Parametrization`] in a scene, default first.
pub const PARAMETRIZATIONS: [&str; 2] = ["native", "arclength"];

/// The names of the extrapolation policies in a scene, default first.
pub const EXTRAPOLATIONS: [&str; 5] = ["hold", "extend", "cycle", "error", "segment"];

impl Parametrization {
    /// The name in a scene.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Native => "native",
            Self::ArcLength => "arclength",
        }
    }

    pub(crate) fn parse(raw: Option<&str>) -> Result<Self, SceneError> {
        match raw {
            None | Some("native") => Ok(Self::Native),
            Some("arclength") => Ok(Self::ArcLength),
            Some(other) => Err(field_error(
                "parametrization",
                format!(
                    "\"{other}\" is not a parametrization: use \"native\" (the method's own parameter, the default) or \"arclength\" (unit speed)"
                ),
            )),
        }
    }
}

/// The name of an extrapolation policy in a scene.
#[must_use]
pub fn extrapolate_name(policy: Extrapolate) -> &'static str {
    match policy {
        Extrapolate::Hold => "hold",
        Extrapolate::Extend => "extend",
        Extrapolate::Cycle => "cycle",
        Extrapolate::Error => "error",
        Extrapolate::Segment => "segment",
    }
}

/// Reads `"extrapolate"`; `cycle` needs a closed curve.
pub(crate) fn parse_extrapolate(
    raw: Option<&str>,
    closed: bool,
) -> Result<Extrapolate, SceneError> {
    let policy = match raw {
        None | Some("hold") => Extrapolate::Hold,
        Some("extend") => Extrapolate::Extend,
        Some("cycle") => Extrapolate::Cycle,
        Some("error") => Extrapolate::Error,
        Some("segment") => Extrapolate::Segment,
        Some(other) => {
            return Err(field_error(
                "extrapolate",
                format!(
                    "\"{other}\" is not an extrapolation policy: use {}",
                    EXTRAPOLATIONS.map(|e| format!("\"{e}\"")).join(", ")
                ),
            ));
        }
    };
    if policy == Extrapolate::Cycle && !closed {
        return Err(field_error(
            "extrapolate",
            "\"cycle\" repeats a closed curve, and this curve is open (give \"closed\": true, or use \"hold\", \"extend\" or \"error\")",
        ));
    }
    Ok(policy)
}

/// `info.arclength`: what the arc-length table did (not generic: one copy for every sphere).
fn arclength_json(length: f64, accuracy: f64, info: &ArcLengthInfo) -> Value {
    let stalls: Vec<Value> = info
        .stalls
        .iter()
        .map(|s| json!({ "s": s.s, "t": s.t }))
        .collect();
    json!({
        "length": length,
        "accuracy": accuracy,
        "cells": info.cells,
        "unresolved": info.unresolved,
        "stalls": stalls,
    })
}

impl<P: ScenePoint> Built<P> {
    /// The curve reparametrised and wrapped in its extrapolation policy; `info.arclength` says
    /// what the arc-length table did (length, cells, and the stalls where the speed vanishes).
    fn retime(
        mut self,
        parametrization: Parametrization,
        policy: Extrapolate,
    ) -> Result<Self, SceneError> {
        let curve = match parametrization {
            Parametrization::Native => self.curve,
            Parametrization::ArcLength => {
                let arc = ArcLength::try_new(self.curve)
                    .map_err(|e| field_error("parametrization", e.to_string()))?;
                self.info.insert(
                    "arclength".into(),
                    arclength_json(arc.length(), arc.accuracy(), arc.info()),
                );
                Box::new(arc)
            }
        };
        if policy == Extrapolate::Segment {
            let [t0, t1] = curve.domain();
            if curve.jet_beyond(t1 + (t1 - t0)).is_none() {
                let why = if parametrization == Parametrization::ArcLength {
                    "\"segment\" continues a method's own formula in its parameter t, and an arc-length curve has none (use \"extend\")"
                } else {
                    "\"segment\" continues the end segments' formula of an open cubic (scipy's RotationSpline); this curve has none (use \"hold\", \"extend\" or \"error\")"
                };
                return Err(field_error("extrapolate", why));
            }
        }
        self.curve = Box::new(Extrapolated::new(curve, policy));
        Ok(self)
    }

    /// Why `t` cannot be evaluated under `policy`, if it cannot.
    fn check(&self, policy: Extrapolate, t: f64) -> Result<(), DomainError> {
        Extrapolated::new(&*self.curve, policy).try_jet(t).map(drop)
    }
}

impl BuiltCurve {
    /// Applies a curve's parametrisation and extrapolation policy (see the module docs).
    pub(crate) fn retime(
        self,
        parametrization: Parametrization,
        policy: Extrapolate,
    ) -> Result<Self, SceneError> {
        Ok(match self {
            Self::S2(b) => Self::S2(b.retime(parametrization, policy)?),
            Self::S3(b) => Self::S3(b.retime(parametrization, policy)?),
            Self::Sm(b) => Self::Sm(b.retime(parametrization, policy)?),
        })
    }

    /// Whether the curve has a value at `t` under `policy` (the policy it was built with).
    pub(crate) fn check_parameter(&self, policy: Extrapolate, t: f64) -> Result<(), DomainError> {
        match self {
            Self::S2(b) => b.check(policy, t),
            Self::S3(b) => b.check(policy, t),
            Self::Sm(b) => b.check(policy, t),
        }
    }
}
