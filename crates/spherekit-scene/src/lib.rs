// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The spherekit scene format: one JSON description of curves on a sphere, shared by the
//! `spherekit` CLI, the renderer, the browser playground and the golden-image tests. This
//! crate parses, validates, builds, samples and edits scenes; [`METHODS`] is the method
//! registry every front end reads.
//!
//! ```text
//! { "space": "S2" | "S3" | "S<m>",      S3: quaternions [w, x, y, z]; S2: [x, y, z]; S<m>: m+1 numbers
//!   "method": "<method id>",            see METHODS (`spherekit methods`)
//!   "points": [[...], ...],             normalised on input; a point that cannot be is an error
//!   "knots": [...],                     optional, strictly increasing (methods that take them)
//!   "params": { ... },                  optional, method specific (Method::params)
//!   "canonicalize": true | false,       optional; S3 only; default true (see spherekit::unflip)
//!   "closed": true | false,             optional; methods that close (Method::closes)
//!   "parametrization": "native" | "arclength",   optional, every method: arclength runs over
//!                                       [0, L] at unit speed (spherekit::ArcLength)
//!   "extrapolate": "hold" | "extend" | "cycle" | "error" | "segment",   optional, every method:
//!                                       outside the domain (spherekit::Extrapolate); default
//!                                       hold; cycle for closed curves, segment the open cubic's
//!   "color": "#rrggbb",                 optional
//!   "samples": 256,                     optional: uniform parameters over the domain, ends included
//!   "eval_at": [t, ...],                optional: explicit parameters instead of "samples"
//!   "fit": { ... },                     optional, method cubic only: the points are samples at the
//!                                       times knots, the curve the spline fitted to them (FitRecord)
//!   "view": { ... } }                   optional, used by rendering (see View)
//! ```
//!
//! Several curves on one sphere: `"curves": [{ "method", "points", "knots", "params",
//! "canonicalize", "closed", "parametrization", "extrapolate", "color", "label", "fit" }, …]` in place
//! of the single-curve fields. Unknown fields are
//! rejected, so a misspelt option is an error rather than silently ignored. Errors name the
//! field (`points[3]: …`, `curves[1].params.order: …`); the library's own errors say what is
//! wrong, this layer says where.
//!
//! # Examples
//!
//! ```
//! use spherekit_scene::Scene;
//!
//! let scene = Scene::from_json(r#"{ "space": "S2", "method": "geodesic",
//!     "points": [[1, 0, 0], [0, 2, 0]], "samples": 3 }"#).unwrap();
//! let out = scene.sample_json(&scene.build().unwrap(), false);
//! assert_eq!(out["t"], serde_json::json!([0.0, 0.5, 1.0]));
//! assert_eq!(out["points"][2], serde_json::json!([0.0, 1.0, 0.0]));
//!
//! let err = Scene::from_json(r#"{ "space": "S2", "method": "geodesic",
//!     "points": [[1, 0, 0], [0, 0, 0]] }"#).unwrap().build().unwrap_err();
//! assert_eq!(err.to_string(), "points[1] has zero length and cannot be normalised");
//! ```
//!
//! # Adding a method
//!
//! Write the construction in the `spherekit` crate, then one file in `src/methods/` with its
//! [`Method`] descriptor (id, summary, spheres, knot rule, minimum points, parameters) and its
//! build function, and list it in [`METHODS`]. The registry test fails until the method has a
//! golden scene in `tests/golden/`, a section in `web/docs.html` and robustness cases.

mod built;
mod edit;
mod error;
mod fit;
mod json;
mod methods;
mod params;
mod registry;
mod rotation_loop;
mod scene;
mod space;
mod timing;
mod view;

pub use built::{
    Built, BuiltCurve, CONTINUITY_TOLERANCE, SAMPLE_FIELDS, ScenePoint, continuity_json,
};
pub use edit::{Document, EditError};
pub use error::{SceneError, one_line};
pub use fit::{FIT_FIELDS, FitRecord, MAX_FIT_SAMPLES};
pub use params::{Param, ParamKind, PerJoint};
pub use registry::{KnotRule, METHODS, MIN_CLOSED_POINTS, Method, Spaces, registry_json};
pub use scene::{
    CurveSpec, DEFAULT_SAMPLES, MAX_LABEL_CHARS, MAX_SAMPLES, SampleOptions, Sampling, Scene,
};
pub use space::{MAX_DIMENSION, Space};
pub use timing::{EXTRAPOLATIONS, PARAMETRIZATIONS, Parametrization, extrapolate_name};
pub use view::{DEFAULT_FLATTENING_ACCURACY, MAX_FRAMES, MAX_TITLE_CHARS, Plot, PlotTime, View};

/// The crate README's examples, run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
