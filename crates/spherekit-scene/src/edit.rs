// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Editing a scene as a document: the playground's edits (move, insert or delete a point, set
//! a parameter, change a curve's method, add or remove curves, set a view option), each checked
//! like a pasted scene, rebuilding only the curves whose description changed.

use core::fmt;

use serde_json::{Map, Value, json};

use crate::built::BuiltCurve;
use crate::error::SceneError;
use crate::params::ParamKind;
use crate::registry::Method;
use crate::scene::Scene;
use crate::space::MAX_DIMENSION;

/// A bad edit: an index that does not exist, coordinates or JSON that cannot be read, or a
/// scene the edit would make invalid.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum EditError {
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
    /// The edited scene is invalid (the CLI's message).
    Scene(SceneError),
}

impl fmt::Display for EditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoCurve(i) => write!(f, "curves[{i}]: there is no such curve"),
            Self::NoPoint(i) => write!(f, "points[{i}]: there is no such point"),
            Self::LastCurve => write!(f, "curves: the last curve cannot be removed"),
            Self::Coords(m) => write!(f, "coordinates: {m}"),
            Self::Json(m) => write!(f, "invalid JSON: {m}"),
            Self::Scene(e) => write!(f, "{e}"),
        }
    }
}

impl core::error::Error for EditError {}

impl From<SceneError> for EditError {
    fn from(e: SceneError) -> Self {
        Self::Scene(e)
    }
}

/// A scene as an editable JSON document, with the validated [`Scene`] and its built curves.
///
/// Every edit changes a copy of the document and reads it back with [`Scene::from_value`] (so
/// it is checked exactly like a pasted scene), then rebuilds only the curves whose description
/// changed; a failed edit leaves everything as it was.
///
/// ```
/// use spherekit_scene::Document;
///
/// let mut doc = Document::from_json(r#"{"space":"S2","method":"geodesic",
///     "points":[[1,0,0],[0,1,0],[0,0,1]],"knots":[0,1,3]}"#).unwrap();
/// doc.insert_point(0, 1, &[1.0, 1.0, 0.0]).unwrap();
/// // The knots follow: a new one midway between its neighbours.
/// assert_eq!(doc.curve(0).unwrap()["knots"], serde_json::json!([0, 0.5, 1, 3]));
/// assert!(doc.remove_point(0, 9).is_err());
/// ```
#[derive(Debug)]
pub struct Document {
    doc: Map<String, Value>,
    scene: Scene,
    curves: Vec<BuiltCurve>,
    builds: u32,
    /// Counts the edits that change the figure's layout (everything but `view.camera`).
    layout: u64,
}

impl Document {
    /// Reads, checks and builds a scene (its `view` included).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad scene.
    pub fn from_json(text: &str) -> Result<Self, SceneError> {
        let doc = parse_doc(text)?;
        let scene = Scene::from_json(text)?;
        let curves = scene.build()?;
        Ok(Self {
            builds: u32::try_from(curves.len()).unwrap_or(u32::MAX),
            layout: 0,
            doc,
            scene,
            curves,
        })
    }

    /// Replaces the whole scene.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad scene; the previous one stays.
    pub fn set_scene(&mut self, text: &str) -> Result<(), EditError> {
        let doc = parse_doc(text)?;
        self.apply(doc)
    }

    /// The document as compact JSON text.
    #[must_use]
    pub fn to_json(&self) -> String {
        Value::Object(self.doc.clone()).to_string()
    }

    /// The validated scene.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The built curves.
    #[must_use]
    pub fn curves(&self) -> &[BuiltCurve] {
        &self.curves
    }

    /// A number that changes with every edit that changes what a figure of the scene lays out
    /// (the curves, the view but its camera), and only then: an interactive caller keeps a
    /// laid-out figure while it is the same (a turn of the camera keeps it).
    #[must_use]
    pub fn layout_generation(&self) -> u64 {
        self.layout
    }

    /// How many curves have been built since the document was made (edits rebuild only what
    /// they change).
    #[must_use]
    pub fn builds(&self) -> u32 {
        self.builds
    }

    /// Curve `curve`'s fields as written (`method`, `points`, `knots`, …).
    ///
    /// # Errors
    ///
    /// [`EditError::NoCurve`].
    pub fn curve(&self, curve: usize) -> Result<&Map<String, Value>, EditError> {
        match self.doc.get("curves") {
            Some(Value::Array(list)) => list
                .get(curve)
                .and_then(Value::as_object)
                .ok_or(EditError::NoCurve(curve)),
            _ if curve == 0 => Ok(&self.doc),
            _ => Err(EditError::NoCurve(curve)),
        }
    }

    /// Point `index` of curve `curve` as written (S³ keys always `[w, x, y, z]`, whatever
    /// the scene's `quaternion_order`).
    ///
    /// # Errors
    ///
    /// [`EditError::NoCurve`], [`EditError::NoPoint`].
    pub fn point(&self, curve: usize, index: usize) -> Result<Vec<f64>, EditError> {
        let p = self
            .curve(curve)?
            .get("points")
            .and_then(|p| p.get(index))
            .and_then(Value::as_array)
            .ok_or(EditError::NoPoint(index))?;
        let mut c: Vec<f64> = p.iter().filter_map(Value::as_f64).collect();
        if self.scene.scalar_last && c.len() == 4 {
            c.rotate_right(1);
        }
        Ok(c)
    }

    /// A point given as `[w, x, y, z]` (S³) in the document's own order.
    fn written(&self, coords: &[f64]) -> Result<Value, EditError> {
        let mut c = coords.to_vec();
        if self.scene.scalar_last && c.len() == 4 {
            c.rotate_left(1);
        }
        point_value(&c)
    }

    /// Sets point `index` of curve `curve` (normalised when the curve is built; S³ keys given
    /// as `[w, x, y, z]`).
    ///
    /// # Errors
    ///
    /// The CLI's message when the curve rejects the point; a bad index or coordinates.
    pub fn set_point(
        &mut self,
        curve: usize,
        index: usize,
        coords: &[f64],
    ) -> Result<(), EditError> {
        let p = self.written(coords)?;
        self.edit_points(curve, |points| {
            let slot = points.get_mut(index).ok_or(EditError::NoPoint(index))?;
            *slot = p;
            Ok(None)
        })
    }

    /// Inserts a point before `index` (`index` = count appends). The curve's knots, per-joint
    /// parameter lists and key velocities follow (see [`Document::remove_point`]); the new
    /// point's velocity is zero (a key at rest).
    ///
    /// # Errors
    ///
    /// As [`Document::set_point`].
    pub fn insert_point(
        &mut self,
        curve: usize,
        index: usize,
        coords: &[f64],
    ) -> Result<(), EditError> {
        let p = self.written(coords)?;
        self.edit_points(curve, |points| {
            if index > points.len() {
                return Err(EditError::NoPoint(index));
            }
            points.insert(index, p);
            Ok(Some(PointEdit::Insert(index)))
        })
    }

    /// Removes point `index` of curve `curve`. Its knot goes, and its entry of every
    /// per-joint parameter list, as the method's registry entry lines them up with the points,
    /// and its velocity (`params.velocities`).
    ///
    /// # Errors
    ///
    /// The CLI's message when too few points remain; a bad index.
    pub fn remove_point(&mut self, curve: usize, index: usize) -> Result<(), EditError> {
        self.edit_points(curve, |points| {
            if index >= points.len() {
                return Err(EditError::NoPoint(index));
            }
            points.remove(index);
            Ok(Some(PointEdit::Remove(index)))
        })
    }

    /// Sets `params.<name>` of curve `curve` (`null` removes it).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad parameter.
    pub fn set_param(&mut self, curve: usize, name: &str, value: Value) -> Result<(), EditError> {
        // The parameter's other spelling (its earlier name, or its name) goes.
        let other = self.scene.curves.get(curve).and_then(|c| {
            c.method.params.iter().find_map(|p| match p.formerly {
                Some(old) if p.name == name => Some(old),
                Some(old) if old == name => Some(p.name),
                _ => None,
            })
        });
        let mut doc = self.doc.clone();
        let c = curve_doc_mut(&mut doc, curve)?;
        let params = c
            .entry("params")
            .or_insert_with(|| Value::Object(Map::new()));
        if let Value::Object(p) = params {
            if let Some(other) = other {
                p.remove(other);
            }
            if value.is_null() {
                p.remove(name);
            } else {
                p.insert(name.into(), value);
            }
            if p.is_empty() {
                c.remove("params");
            }
        }
        self.apply(doc)
    }

    /// Replaces curve `curve`'s fields other than `points` by `fields` (`method`, `params`,
    /// `knots`, `canonicalize`, `closed`, `parametrization`, `extrapolate`, `color`, `label`;
    /// absent ones are removed).
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad curve.
    pub fn set_curve(&mut self, curve: usize, fields: Map<String, Value>) -> Result<(), EditError> {
        let mut doc = self.doc.clone();
        let listed = doc.contains_key("curves");
        let c = curve_doc_mut(&mut doc, curve)?;
        let points = c.remove("points");
        if listed {
            c.clear();
        } else {
            // A single curve's fields share the object with the scene's (`space`, `view`, …).
            for k in CURVE_FIELDS {
                c.remove(k);
            }
        }
        c.extend(fields);
        if let Some(p) = points {
            c.insert("points".into(), p);
        }
        self.apply(doc)
    }

    /// Gives curve `curve` another method: parameters the new method does not have go, knots
    /// go unless the new method takes as many for these points, `"fit"` goes unless the new
    /// method fits samples, and `"extrapolate": "segment"` goes unless the new method's curve
    /// has end segments to continue.
    ///
    /// # Errors
    ///
    /// The CLI's message when the method cannot take the curve's points.
    pub fn set_method(&mut self, curve: usize, id: &str) -> Result<(), EditError> {
        let new = Method::find(id)?;
        let old = self
            .scene
            .curves
            .get(curve)
            .ok_or(EditError::NoCurve(curve))?;
        let (n, closed) = (old.points.len(), old.closed);
        let keep_knots = new.knots.count_for(n, closed).is_some()
            && new.knots.count_for(n, closed) == old.method.knots.count_for(n, closed);
        let mut doc = self.doc.clone();
        let c = curve_doc_mut(&mut doc, curve)?;
        c.insert("method".into(), json!(new.id));
        if !keep_knots {
            c.remove("knots");
        }
        if !crate::fit::applies_to(new) {
            c.remove("fit");
        }
        if let Some(Value::Object(p)) = c.get_mut("params") {
            p.retain(|k, _| {
                new.params
                    .iter()
                    .any(|q| q.name == k || q.formerly == Some(k.as_str()))
            });
            if p.is_empty() {
                c.remove("params");
            }
        }
        let continued = c.get("extrapolate") == Some(&json!("segment"));
        match self.apply(doc.clone()) {
            // `"extrapolate": "segment"` goes when the new method's curve has no end segment
            // to continue (as knots go when it takes other knots).
            Err(e) if continued && names_field(&e, "extrapolate") => {
                if let Ok(c) = curve_doc_mut(&mut doc, curve) {
                    c.remove("extrapolate");
                }
                self.apply(doc)
            }
            result => result,
        }
    }

    /// Adds a curve with `method` through the same points as curve 0 (a single-curve scene
    /// becomes a `curves` list).
    ///
    /// # Errors
    ///
    /// The CLI's message when the method cannot take these points.
    pub fn add_curve(&mut self, method: &str) -> Result<(), EditError> {
        let mut doc = self.doc.clone();
        let list = to_list(&mut doc)?;
        let points = list
            .first()
            .and_then(|c| c.get("points"))
            .cloned()
            .unwrap_or(Value::Array(Vec::new()));
        list.push(json!({ "method": method, "points": points }));
        self.apply(doc)
    }

    /// Removes curve `curve` (the last one cannot be removed).
    ///
    /// # Errors
    ///
    /// A bad index or the last curve.
    pub fn remove_curve(&mut self, curve: usize) -> Result<(), EditError> {
        let mut doc = self.doc.clone();
        let list = to_list(&mut doc)?;
        if curve >= list.len() {
            return Err(EditError::NoCurve(curve));
        }
        if list.len() == 1 {
            return Err(EditError::LastCurve);
        }
        list.remove(curve);
        self.apply(doc)
    }

    /// Sets a `view` option to a value (`null` removes it); rebuilds nothing.
    ///
    /// # Errors
    ///
    /// The CLI's message for a bad option.
    pub fn set_view(&mut self, name: &str, value: Value) -> Result<(), EditError> {
        let mut doc = self.doc.clone();
        let view = doc
            .entry("view")
            .or_insert_with(|| Value::Object(Map::new()));
        if let Value::Object(m) = view {
            if value.is_null() {
                m.remove(name);
            } else {
                m.insert(name.into(), value);
            }
            if m.is_empty() {
                doc.remove("view");
            }
        }
        self.apply(doc)
    }

    fn edit_points(
        &mut self,
        curve: usize,
        edit: impl FnOnce(&mut Vec<Value>) -> Result<Option<PointEdit>, EditError>,
    ) -> Result<(), EditError> {
        let method = self.scene.curves.get(curve).map(|c| (c.method, c.closed));
        let mut doc = self.doc.clone();
        let c = curve_doc_mut(&mut doc, curve)?;
        let (count, change) = match c.get_mut("points") {
            Some(Value::Array(points)) => (points.len(), edit(points)?),
            _ => return Err(EditError::NoCurve(curve)),
        };
        if let (Some(change), Some((method, closed))) = (change, method) {
            follow_points(c, method, closed, count, change);
        }
        self.apply(doc)
    }

    /// Validates an edited document and rebuilds the curves whose description changed.
    ///
    /// A curve whose JSON is unchanged keeps its built curve and its parsed description.
    fn apply(&mut self, doc: Map<String, Value>) -> Result<(), EditError> {
        let mut scene = Scene::from_value(&Value::Object(doc.clone()))?;
        // The scene-level fields that say how every curve's points are read: the sphere, and
        // on S³ the quaternion order (a curve's own `canonicalize` is one of its fields).
        let same_reading =
            scene.space == self.scene.space && scene.scalar_last == self.scene.scalar_last;
        let mut fresh: Vec<Option<BuiltCurve>> = Vec::with_capacity(scene.curves.len());
        for i in 0..scene.curves.len() {
            let unchanged = same_reading
                && i < self.scene.curves.len()
                && curve_fields(&doc, i) == curve_fields(&self.doc, i);
            if unchanged {
                scene.curves[i] = self.scene.curves[i].clone();
                fresh.push(None);
            } else {
                fresh.push(Some(build_one(&scene, i)?));
            }
        }
        let all: Vec<&BuiltCurve> = fresh
            .iter()
            .enumerate()
            .filter_map(|(i, c)| c.as_ref().or_else(|| self.curves.get(i)))
            .collect();
        scene.check_parameters_of(&all)?;
        let built = fresh.iter().filter(|c| c.is_some()).count();
        let mut old: Vec<Option<BuiltCurve>> = core::mem::take(&mut self.curves)
            .into_iter()
            .map(Some)
            .collect();
        // Every `None` in `fresh` is an unchanged curve, so `old` has it.
        self.curves = fresh
            .into_iter()
            .enumerate()
            .filter_map(|(i, c)| c.or_else(|| old.get_mut(i).and_then(Option::take)))
            .collect();
        self.builds = self
            .builds
            .saturating_add(u32::try_from(built).unwrap_or(u32::MAX));
        if without_camera(&doc) != without_camera(&self.doc) {
            self.layout += 1;
        }
        self.scene = scene;
        self.doc = doc;
        Ok(())
    }
}

/// A document without its `view.camera` (what a figure's layout depends on).
fn without_camera(doc: &Map<String, Value>) -> Map<String, Value> {
    let mut doc = doc.clone();
    if let Some(Value::Object(view)) = doc.get_mut("view") {
        view.remove("camera");
    }
    doc
}

/// Whether an edit failed on a curve's `field` (`extrapolate`, or `curves[i].extrapolate`).
fn names_field(e: &EditError, name: &str) -> bool {
    let mut e = match e {
        EditError::Scene(e) => e,
        _ => return false,
    };
    while let SceneError::InCurve { error, .. } = e {
        e = error;
    }
    matches!(e, SceneError::Field { field, .. } if field == name)
}

/// Builds curve `i` of `scene` alone, with the error message [`Scene::build`] would give.
fn build_one(scene: &Scene, i: usize) -> Result<BuiltCurve, SceneError> {
    let spec = &scene.curves[i];
    spec.build(scene.space).map_err(|e| {
        if scene.is_listed() {
            SceneError::InCurve {
                index: i,
                error: Box::new(e),
            }
        } else {
            e
        }
    })
}

fn parse_doc(text: &str) -> Result<Map<String, Value>, SceneError> {
    // Scene::from_json gives the CLI's message for text that is not a scene object.
    match serde_json::from_str(text) {
        Ok(Value::Object(m)) => Ok(m),
        _ => Err(Scene::from_json(text)
            .err()
            .unwrap_or_else(|| SceneError::Json("expected a JSON object".into()))),
    }
}

fn curve_doc_mut(
    doc: &mut Map<String, Value>,
    curve: usize,
) -> Result<&mut Map<String, Value>, EditError> {
    if doc.contains_key("curves") {
        return match doc.get_mut("curves") {
            Some(Value::Array(list)) => list
                .get_mut(curve)
                .and_then(Value::as_object_mut)
                .ok_or(EditError::NoCurve(curve)),
            _ => Err(EditError::NoCurve(curve)),
        };
    }
    if curve == 0 {
        Ok(doc)
    } else {
        Err(EditError::NoCurve(curve))
    }
}

/// The curve fields a single-curve scene keeps at the top level.
const CURVE_FIELDS: [&str; 11] = [
    "method",
    "points",
    "knots",
    "params",
    "canonicalize",
    "closed",
    "parametrization",
    "extrapolate",
    "color",
    "label",
    "fit",
];

/// The description of curve `i` in a document (the curve's own fields, wherever they sit).
fn curve_fields(doc: &Map<String, Value>, i: usize) -> Option<Map<String, Value>> {
    let c = match doc.get("curves") {
        Some(Value::Array(list)) => list.get(i)?.as_object()?,
        _ if i == 0 => doc,
        _ => return None,
    };
    Some(
        CURVE_FIELDS
            .iter()
            .filter_map(|k| c.get(*k).map(|v| ((*k).to_owned(), v.clone())))
            .collect(),
    )
}

/// Turns a single-curve document into a `curves` list and returns the list.
fn to_list(doc: &mut Map<String, Value>) -> Result<&mut Vec<Value>, EditError> {
    if !doc.contains_key("curves") {
        let mut one = Map::new();
        for k in CURVE_FIELDS {
            if let Some(v) = doc.remove(k) {
                one.insert(k.into(), v);
            }
        }
        doc.insert("curves".into(), Value::Array(vec![Value::Object(one)]));
    }
    match doc.get_mut("curves") {
        Some(Value::Array(list)) => Ok(list),
        _ => Err(EditError::NoCurve(0)),
    }
}

/// Coordinates of a new point as a JSON list (the scene checks their count and length).
fn point_value(coords: &[f64]) -> Result<Value, EditError> {
    if coords.is_empty() || coords.len() > MAX_DIMENSION + 1 {
        return Err(EditError::Coords(format!(
            "expected 2 to {} numbers, got {}",
            MAX_DIMENSION + 1,
            coords.len()
        )));
    }
    if let Some(i) = coords.iter().position(|x| !x.is_finite()) {
        return Err(EditError::Coords(format!("[{i}] is not a finite number")));
    }
    Ok(Value::from(coords.to_vec()))
}

/// A point inserted before, or removed at, an index of a curve's `points`.
#[derive(Clone, Copy, Debug)]
enum PointEdit {
    Insert(usize),
    Remove(usize),
}

/// Keeps a curve's per-point lists in step with an edit of its `count` points, so that adding
/// or deleting a point does not make `knots` or a per-joint parameter list (β₁, β₂, γ) the wrong
/// length. The method's registry entry says how each list lines up with the points: `skip`
/// points at each end have no entry (Catmull-Rom's steering end points have no knot; Gamma's γ
/// list starts at the second inner point), except on a closed curve, whose lists have one entry
/// per point and its knots one more (the time it returns to the first point). The entry at the matching position is removed, or
/// one is inserted there: midway between its neighbours for `knots` (one spacing beyond an
/// end), a copy of its neighbour for a parameter. A parameter list that would become empty
/// becomes its last value (one number for every joint). A list of vectors, one per point (the
/// key velocities), loses the removed point's vector or gains a zero vector (of its neighbour's
/// length) for the inserted one: zero is a velocity at every point. A fit's `weights` (one per
/// point) follow as a parameter list does. Lists of another length, or of other values, are
/// left for the scene's validation to report.
fn follow_points(
    curve: &mut Map<String, Value>,
    method: &Method,
    closed: bool,
    count: usize,
    edit: PointEdit,
) {
    // A closed curve's last knot is the time it returns to the first point: the list follows
    // as if that were one more point at the end.
    let extra = usize::from(closed);
    if let (Some(Value::Array(knots)), Some(len)) = (
        curve.get_mut("knots"),
        method.knots.count_for(count, closed),
    ) {
        follow(knots, true, len, count + extra, edit);
    }
    if let Some(Value::Object(params)) = curve.get_mut("params") {
        for p in method.params {
            let (Some(expected), Some(value)) =
                (p.per_point_count(count, closed), params.get_mut(p.name))
            else {
                continue;
            };
            let Value::Array(list) = value else { continue };
            if p.kind == ParamKind::Vectors {
                follow_vectors(list, count, edit);
            } else if let Some(removed) = follow(list, false, expected, count, edit)
                && list.is_empty()
            {
                *value = Value::from(removed);
            }
        }
    }
    if let Some(Value::Object(fit)) = curve.get_mut("fit")
        && let Some(Value::Array(weights)) = fit.get_mut("weights")
    {
        follow(weights, false, count, count, edit);
    }
}

/// Applies `edit` to a list of one vector per point, `count` of them (see [`follow_points`]).
fn follow_vectors(list: &mut Vec<Value>, count: usize, edit: PointEdit) {
    if list.len() != count {
        return;
    }
    match edit {
        PointEdit::Insert(index) => {
            let Some(Value::Array(near)) = list.get(index.min(count.saturating_sub(1))) else {
                return;
            };
            let zero = Value::from(vec![0.0; near.len()]);
            list.insert(index.min(count), zero);
        }
        PointEdit::Remove(index) if index < count => {
            list.remove(index);
        }
        PointEdit::Remove(_) => {}
    }
}

/// Applies `edit` to one list that should have `expected` entries for `count` points (see
/// [`follow_points`]); returns the value removed, if any.
fn follow(
    list: &mut Vec<Value>,
    is_knots: bool,
    expected: usize,
    count: usize,
    edit: PointEdit,
) -> Option<f64> {
    let x: Vec<f64> = list.iter().map(Value::as_f64).collect::<Option<_>>()?;
    let len = x.len();
    if len == 0 || len != expected {
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
