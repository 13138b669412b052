// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The method registry: one [`Method`] descriptor per curve construction (in `methods/`, one
//! file each), listed once in [`METHODS`]. Everything that enumerates methods reads this list:
//! the scene parser, `spherekit methods [--json]`, the renderer, the wasm `methods()` and the
//! page's parameter controls, knot-following when points are edited, and the tests.

use core::fmt;

use serde_json::{Value, json};

use crate::built::BuiltCurve;
use crate::error::{SceneError, field_error};
use crate::methods;
use crate::params::Param;
use crate::scene::Input;
use crate::space::Space;

/// The fewest points of a closed curve (`"closed": true`), for every method that closes.
pub const MIN_CLOSED_POINTS: usize = 3;

/// Every registered method, in the order `spherekit methods` lists them.
pub static METHODS: &[&Method] = &[
    &methods::geodesic::METHOD,
    &methods::nlerp::METHOD,
    &methods::bezier::METHOD,
    &methods::bezier_kim::METHOD,
    &methods::bspline_kim::METHOD,
    &methods::squad::METHOD,
    &methods::catmull_rom::METHOD,
    &methods::catmull_rom_nlerp::METHOD,
    &methods::gamma::METHOD,
    &methods::beta::METHOD,
    &methods::arc_blend::METHOD,
    &methods::corner_blend::METHOD,
    &methods::cubic::METHOD,
];

/// A curve construction as scenes name it: what it is, what it takes, and how to build it.
pub struct Method {
    /// The scene id (`"squad"`).
    pub id: &'static str,
    /// Its name for people (menus, legends): `"Catmull–Rom"`.
    pub name: &'static str,
    /// The library type that implements it (`"Squad"`).
    pub type_name: &'static str,
    /// One line on what it is.
    pub summary: &'static str,
    /// Its continuity at the joints, as the construction guarantees it (`"C¹"`, `"Cⁿ"`).
    pub continuity: &'static str,
    /// The publication it follows.
    pub source: &'static str,
    /// The spaces it works on (the registry JSON's `spaces`).
    pub spaces: Spaces,
    /// Whether and how it takes `knots`.
    pub knots: KnotRule,
    /// The fewest points it accepts.
    pub min_points: usize,
    /// Whether the curve passes through its points (otherwise the renderer draws their polygon).
    pub interpolates: bool,
    /// Whether it has a closed form (`"closed": true`: after the last point the curve returns
    /// to the first, as smooth at the seam as at the other joints). A closed curve needs at
    /// least [`MIN_CLOSED_POINTS`] points, every point is a key (Catmull-Rom's and Gamma's end
    /// points steer nothing: the neighbours wrap around), and [`KnotRule::count_for`] gives its
    /// knots.
    pub closes: bool,
    /// Whether the curve is one piece whose degree grows with the number of points (Bézier
    /// curves: an evaluation costs O(n²)), rather than pieces between consecutive points.
    pub single_piece: bool,
    /// Its parameters, the keys of `params`.
    pub params: &'static [Param],
    pub(crate) build: fn(Input<'_>) -> Result<BuiltCurve, SceneError>,
}

impl fmt::Debug for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Method")
            .field("id", &self.id)
            .finish_non_exhaustive()
    }
}

impl PartialEq for Method {
    fn eq(&self, other: &Self) -> bool {
        self.id == other.id
    }
}

/// Which spaces (the scene's `space`: S², S³, S^m) a method or a parameter works on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spaces {
    /// S², S³ and every S^m.
    All,
    /// S³ only.
    S3,
    /// S² only.
    S2,
}

impl Spaces {
    /// The spheres by name, as the registry JSON lists them (`"S<m>"`: every other S^m).
    #[must_use]
    pub fn names(self) -> &'static [&'static str] {
        match self {
            Self::All => &["S2", "S3", "S<m>"],
            Self::S3 => &["S3"],
            Self::S2 => &["S2"],
        }
    }

    /// A human-readable list of the spheres.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Self::All => "S2, S3, S<m>",
            Self::S3 => "S3",
            Self::S2 => "S2",
        }
    }

    /// Whether `space` is one of them.
    #[must_use]
    pub fn contains(self, space: Space) -> bool {
        match self {
            Self::All => true,
            Self::S3 => space == Space::S3,
            Self::S2 => space == Space::S2,
        }
    }
}

/// Whether a method takes `knots`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KnotRule {
    /// Optional knots, one per point except `skip` points at each end (Catmull-Rom's steering
    /// end points have none); uniform `0, 1, 2, …` when absent.
    PerPoint {
        /// Points at each end without a knot.
        skip: usize,
    },
    /// The method computes its own parametrisation (reported in `info.knots`).
    Computed,
    /// The method has a single parameter interval `[0, 1]`.
    None,
}

impl KnotRule {
    /// The number of knots for `points` points of an open curve, where the method takes
    /// knots (a closed curve has more, see [`count_for`](Self::count_for)).
    #[must_use]
    pub fn count(self, points: usize) -> Option<usize> {
        self.count_for(points, false)
    }

    /// The number of knots for `points` points of an open or closed curve, where the method
    /// takes knots: open, one per point but `skip` at each end; closed, one per point (every
    /// point is a key of a loop) and one more, the time at which it returns to the first point.
    #[must_use]
    pub fn count_for(self, points: usize, closed: bool) -> Option<usize> {
        match self {
            Self::PerPoint { .. } if closed => Some(points + 1),
            Self::PerPoint { skip } => Some(points.saturating_sub(2 * skip)),
            Self::Computed | Self::None => None,
        }
    }
}

impl Method {
    /// Finds a method by its scene id. Ids are kebab-case (`"arc-blend"`); the id with
    /// underscores for hyphens (`"arc_blend"`, as the golden files and the modules are named)
    /// is accepted too.
    ///
    /// # Errors
    ///
    /// A [`SceneError::Field`] on `method` listing the known ids.
    pub fn find(id: &str) -> Result<&'static Self, SceneError> {
        let same = |m: &&Self| {
            m.id.len() == id.len()
                && m.id
                    .bytes()
                    .zip(id.bytes())
                    .all(|(a, b)| a == b || (a, b) == (b'-', b'_'))
        };
        METHODS.iter().copied().find(same).ok_or_else(|| {
            let ids: Vec<_> = METHODS.iter().map(|m| m.id).collect();
            field_error(
                "method",
                format!("unknown method \"{id}\"; known: {}", ids.join(", ")),
            )
        })
    }

    /// The descriptor as JSON: `{ "id", "name", "type", "summary", "continuity", "source", "spaces",
    /// "knots", "min_points", "interpolates", "single_piece", "closes", "params": [...], "fit" }`
    /// (a closed curve has at least [`MIN_CLOSED_POINTS`] points and
    /// [`KnotRule::count_for`] knots), where `knots` is
    /// `{ "skip": k }` for methods that take one knot per point but `k` at each end, or
    /// `"computed"` / `"none"`, and `fit` is `null`, or for a method that fits samples (the
    /// scene's `"fit"`) the fit object's keys, `[{ "name", "summary" }, …]`.
    #[must_use]
    pub fn to_json(&self) -> Value {
        json!({
            "id": self.id,
            "name": self.name,
            "type": self.type_name,
            "summary": self.summary,
            "continuity": self.continuity,
            "source": self.source,
            "spaces": self.spaces.names(),
            "knots": match self.knots {
                KnotRule::PerPoint { skip } => json!({ "skip": skip }),
                KnotRule::Computed => json!("computed"),
                KnotRule::None => json!("none"),
            },
            "min_points": self.min_points,
            "interpolates": self.interpolates,
            "single_piece": self.single_piece,
            "closes": self.closes,
            "params": self.params.iter().map(Param::to_json).collect::<Vec<_>>(),
            "fit": crate::fit::applies_to(self).then(|| {
                crate::fit::FIT_FIELDS
                    .iter()
                    .map(|(name, summary)| json!({ "name": name, "summary": summary }))
                    .collect::<Vec<_>>()
            }),
        })
    }
}

/// The whole registry as JSON, a list of [`Method::to_json`].
#[must_use]
pub fn registry_json() -> Value {
    Value::Array(METHODS.iter().map(|m| m.to_json()).collect())
}
