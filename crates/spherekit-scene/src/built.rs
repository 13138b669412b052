// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Curves built from a scene, and their samples as the CLI prints them.

use serde_json::{Map, Value, json};
use spherekit::{
    Ambient, Curve, Jet, JointContinuity, Manifold, PointError, S2Point, SmPoint, UnitQuat, VecN,
    angular_velocity_acceleration, angular_velocity_acceleration_body,
};

use crate::fit::FitRecord;
use crate::scene::{SampleOptions, Scene};
use crate::space::Space;

/// A curve built from a scene, with the extras a method derives.
#[derive(Debug)]
pub struct Built<P: Manifold> {
    /// The curve (`Send + Sync`, so that a front end may evaluate it on another thread, e.g.
    /// the Python module with the interpreter lock released).
    pub curve: Box<dyn Curve<Point = P> + Send + Sync>,
    /// The scene's points, normalised (and on S³ canonicalised when the scene asks for it).
    pub inputs: Vec<P>,
    /// Derived control points (empty when the method has none).
    pub controls: Vec<P>,
    /// Auxiliary vertices solved for (empty when the method has none).
    pub auxiliary: Vec<P>,
    /// Method-specific facts, such as solver iterations.
    pub info: Map<String, Value>,
    /// The order of continuity the construction guarantees at its joints (0 for C⁰; the
    /// blend order n for Pobegailo's Cⁿ splines).
    pub order: usize,
    /// With the scene's `"fit"`: the sample times, fitted keys, residuals and the fit's report
    /// (the samples are [`inputs`](Self::inputs)); `None` otherwise.
    pub fit: Option<FitRecord<P>>,
}

impl<P: ScenePoint> Built<P> {
    /// A built curve with no extras, C⁰ at its joints: `curve` through (or near) `inputs`.
    #[must_use]
    pub fn new(curve: impl Curve<Point = P> + Send + Sync + 'static, inputs: Vec<P>) -> Self {
        Self {
            curve: Box::new(curve),
            inputs,
            controls: Vec::new(),
            auxiliary: Vec::new(),
            info: Map::new(),
            order: 0,
            fit: None,
        }
    }

    /// The curve with its derived control points (drawn as squares, joined by a polygon).
    #[must_use]
    pub fn with_controls(mut self, controls: Vec<P>) -> Self {
        self.controls = controls;
        self
    }

    pub(crate) fn with_info(mut self, key: &str, value: Value) -> Self {
        self.info.insert(key.into(), value);
        self
    }

    pub(crate) fn with_order(mut self, order: usize) -> Self {
        self.order = order;
        self
    }

    /// The continuity report of the curve ([`spherekit::continuity`]).
    #[must_use]
    pub fn continuity(&self) -> Vec<JointContinuity> {
        spherekit::continuity(&*self.curve)
    }

    fn sample_into(&self, scene: &Scene, options: SampleOptions, out: &mut Map<String, Value>) {
        let domain = self.curve.domain();
        let ts = scene.parameters(domain);
        let mut rows = Rows {
            quaternions: P::angular(&self.curve.jet(domain[0]), false).is_some(),
            controls: self.controls.iter().map(ScenePoint::coords).collect(),
            auxiliary: self.auxiliary.iter().map(ScenePoint::coords).collect(),
            continuity: options.continuity.then(|| self.continuity()),
            ..Rows::default()
        };
        // Batch evaluation: one call for all parameters, the same values as `jet`/`eval`.
        if options.deriv {
            let mut jets = vec![self.curve.jet(domain[0]); ts.len()];
            self.curve.jet_many(&ts, &mut jets);
            for jet in &jets {
                if let Some(w) = P::angular(jet, options.body_frame) {
                    rows.angular.push(w);
                }
                rows.velocity.push(P::vector_coords(&jet.velocity));
                rows.acceleration.push(P::vector_coords(&jet.acceleration));
                rows.points.push(jet.point.coords());
            }
        } else {
            let mut ps = vec![self.curve.eval(domain[0]); ts.len()];
            self.curve.eval_many(&ts, &mut ps);
            rows.points.extend(ps.iter().map(ScenePoint::coords));
        }
        rows.write(scene, options, domain, ts, &self.info, self.order, out);
    }

    fn sample_field(&self, scene: &Scene, field: &str) -> Option<Vec<f64>> {
        let mut out = self.sample_field_wxyz(scene, field)?;
        let quaternions = P::angular(&self.curve.jet(self.curve.domain()[0]), false).is_some();
        let rows = matches!(
            field,
            "points" | "velocity" | "acceleration" | "controls" | "auxiliary"
        );
        if scene.scalar_last && quaternions && rows {
            for row in out.chunks_exact_mut(4) {
                row.rotate_left(1);
            }
        }
        Some(out)
    }

    fn sample_field_wxyz(&self, scene: &Scene, field: &str) -> Option<Vec<f64>> {
        let domain = self.curve.domain();
        let flat = |ps: &[P]| ps.iter().flat_map(ScenePoint::coords).collect();
        Some(match field {
            "domain" => domain.to_vec(),
            "t" => scene.parameters(domain),
            "controls" => flat(&self.controls),
            "auxiliary" => flat(&self.auxiliary),
            "points" => {
                let ts = scene.parameters(domain);
                let mut ps = vec![self.curve.eval(domain[0]); ts.len()];
                self.curve.eval_many(&ts, &mut ps);
                flat(&ps)
            }
            "angular_velocity" | "angular_acceleration"
                if P::angular(&self.curve.jet(domain[0]), false).is_none() =>
            {
                Vec::new()
            }
            "velocity" | "acceleration" | "angular_velocity" | "angular_acceleration" => {
                let ts = scene.parameters(domain);
                let mut jets = vec![self.curve.jet(domain[0]); ts.len()];
                self.curve.jet_many(&ts, &mut jets);
                let mut out = Vec::with_capacity(3 * jets.len());
                for jet in &jets {
                    match (field, P::angular(jet, false)) {
                        ("velocity", _) => out.extend(P::vector_coords(&jet.velocity)),
                        ("acceleration", _) => out.extend(P::vector_coords(&jet.acceleration)),
                        ("angular_velocity", Some((w, _))) => out.extend(w),
                        ("angular_acceleration", Some((_, a))) => out.extend(a),
                        _ => {}
                    }
                }
                out
            }
            _ => return None,
        })
    }
}

/// The samples of one curve as [`Built::sample_into`] takes them, before they are written as
/// JSON by one copy of the code for every sphere.
#[derive(Default)]
struct Rows {
    /// The curve is on S³ (its rows are quaternions, `w` first).
    quaternions: bool,
    points: Vec<Vec<f64>>,
    velocity: Vec<Vec<f64>>,
    acceleration: Vec<Vec<f64>>,
    /// Angular velocity and acceleration per sample (S³ only).
    angular: Vec<([f64; 3], [f64; 3])>,
    controls: Vec<Vec<f64>>,
    auxiliary: Vec<Vec<f64>>,
    continuity: Option<Vec<JointContinuity>>,
}

impl Rows {
    #[expect(
        clippy::too_many_arguments,
        reason = "the curve's facts besides its samples, passed on from Built"
    )]
    fn write(
        self,
        scene: &Scene,
        options: SampleOptions,
        domain: [f64; 2],
        ts: Vec<f64>,
        info: &Map<String, Value>,
        order: usize,
        out: &mut Map<String, Value>,
    ) {
        // Quaternion rows in the scene's order (`xyzw` moves the scalar last).
        let reorder = scene.scalar_last && self.quaternions;
        let list = |rows: Vec<Vec<f64>>| {
            Value::Array(
                rows.into_iter()
                    .map(|mut c| {
                        if reorder {
                            c.rotate_left(1);
                        }
                        json!(c)
                    })
                    .collect(),
            )
        };
        out.insert("domain".into(), json!(domain));
        out.insert("t".into(), json!(ts));
        out.insert("points".into(), list(self.points));
        if options.deriv {
            out.insert("velocity".into(), list(self.velocity));
            out.insert("acceleration".into(), list(self.acceleration));
            if !self.angular.is_empty() {
                let (omega, alpha): (Vec<Value>, Vec<Value>) = self
                    .angular
                    .iter()
                    .map(|(w, a)| (json!(w), json!(a)))
                    .unzip();
                out.insert("angular_velocity".into(), Value::Array(omega));
                out.insert("angular_acceleration".into(), Value::Array(alpha));
            }
        }
        if !self.controls.is_empty() {
            out.insert("controls".into(), list(self.controls));
        }
        if !self.auxiliary.is_empty() {
            out.insert("auxiliary".into(), list(self.auxiliary));
        }
        if !info.is_empty() {
            out.insert("info".into(), Value::Object(info.clone()));
        }
        if let Some(report) = self.continuity {
            out.insert("continuity".into(), continuity_json(&report, order));
        }
    }
}

/// The tolerance below which a jump counts as zero in the continuity classes.
pub const CONTINUITY_TOLERANCE: f64 = 1e-9;

/// The continuity report as JSON: `[{ "t", "c0", "c1", "c2", "g1", "class" }, …]`, with the
/// class of [`JointContinuity::class`] at [`CONTINUITY_TOLERANCE`] and the construction's
/// guaranteed `order`.
#[must_use]
pub fn continuity_json(report: &[JointContinuity], order: usize) -> Value {
    Value::Array(
        report
            .iter()
            .map(|j| {
                json!({ "t": j.t, "c0": j.c0, "c1": j.c1, "c2": j.c2, "g1": j.g1,
                        "class": j.class(CONTINUITY_TOLERANCE, order).to_string() })
            })
            .collect(),
    )
}

/// A curve built from a scene, on its space.
#[derive(Debug)]
pub enum BuiltCurve {
    /// A curve on S².
    S2(Built<S2Point>),
    /// A curve of orientations.
    S3(Built<UnitQuat>),
    /// A curve on S^m.
    Sm(Built<SmPoint>),
}

/// Builds the same expression on every sphere: `on_every_sphere!(points, |p| expr)` matches
/// [`Points`](crate::scene::Points) and wraps `expr` (a [`Built`]) in the [`BuiltCurve`] of
/// the same sphere, so a method's build function is written once for S², S³ and S^m. (The
/// core's `compact` feature, which the browser build turns on, is what keeps one copy of the
/// constructions that do the same arithmetic on every sphere.)
macro_rules! on_every_sphere {
    ($points:expr, |$p:ident| $body:expr) => {
        match $points {
            $crate::scene::Points::S2($p) => $crate::built::BuiltCurve::S2($body),
            $crate::scene::Points::S3($p) => $crate::built::BuiltCurve::S3($body),
            $crate::scene::Points::Sm($p) => $crate::built::BuiltCurve::Sm($body),
        }
    };
}
pub(crate) use on_every_sphere;

/// The fields [`BuiltCurve::sample_field`] gives, as [`Scene::sample_json`] names them.
pub const SAMPLE_FIELDS: [&str; 9] = [
    "t",
    "points",
    "velocity",
    "acceleration",
    "angular_velocity",
    "angular_acceleration",
    "controls",
    "auxiliary",
    "domain",
];

impl BuiltCurve {
    /// One field of [`Scene::sample_json`] for this curve, its rows one after another, without
    /// building JSON: `t`, `points`, `velocity`, `acceleration`, `angular_velocity` and
    /// `angular_acceleration` (S³; empty elsewhere), `controls`, `auxiliary` (empty when the
    /// method has none) or `domain`. `None` for any other name (see [`SAMPLE_FIELDS`]).
    ///
    /// ```
    /// use spherekit_scene::Scene;
    ///
    /// let scene = Scene::from_json(r#"{"space":"S2","method":"geodesic","samples":3,
    ///     "points":[[1,0,0],[0,1,0]]}"#).unwrap();
    /// let curves = scene.build().unwrap();
    /// let points = curves[0].sample_field(&scene, "points").unwrap();
    /// assert_eq!(points.len(), 3 * 3);
    /// assert!((points[3] - 0.5_f64.sqrt()).abs() < 1e-15); // the middle sample, x
    /// assert!(curves[0].sample_field(&scene, "speed").is_none());
    /// ```
    #[must_use]
    pub fn sample_field(&self, scene: &Scene, field: &str) -> Option<Vec<f64>> {
        match self {
            Self::S2(b) => b.sample_field(scene, field),
            Self::S3(b) => b.sample_field(scene, field),
            Self::Sm(b) => b.sample_field(scene, field),
        }
    }

    pub(crate) fn sample_into(
        &self,
        scene: &Scene,
        options: SampleOptions,
        out: &mut Map<String, Value>,
    ) {
        match self {
            Self::S2(b) => b.sample_into(scene, options, out),
            Self::S3(b) => b.sample_into(scene, options, out),
            Self::Sm(b) => b.sample_into(scene, options, out),
        }
    }

    /// [`Built::with_info`] on the curve of any sphere: one copy of the code for the three
    /// (for the facts a method's build function adds after `on_every_sphere!`).
    pub(crate) fn with_info(mut self, key: &str, value: Value) -> Self {
        let info = match &mut self {
            Self::S2(b) => &mut b.info,
            Self::S3(b) => &mut b.info,
            Self::Sm(b) => &mut b.info,
        };
        info.insert(key.into(), value);
        self
    }

    /// [`Built::with_order`] on the curve of any sphere.
    pub(crate) fn with_order(mut self, order: usize) -> Self {
        match &mut self {
            Self::S2(b) => b.order = order,
            Self::S3(b) => b.order = order,
            Self::Sm(b) => b.order = order,
        }
        self
    }

    /// The continuity report and the construction's guaranteed order at the joints.
    #[must_use]
    pub fn continuity(&self) -> (Vec<JointContinuity>, usize) {
        match self {
            Self::S2(b) => (b.continuity(), b.order),
            Self::S3(b) => (b.continuity(), b.order),
            Self::Sm(b) => (b.continuity(), b.order),
        }
    }

    /// The fit's report when the curve was fitted to samples (the scene's `"fit"`); the
    /// samples, their times and residuals are in the [`Built::fit`] record of each sphere.
    #[must_use]
    pub fn fit_report(&self) -> Option<&spherekit::FitReport> {
        match self {
            Self::S2(b) => b.fit.as_ref().map(|f| &f.report),
            Self::S3(b) => b.fit.as_ref().map(|f| &f.report),
            Self::Sm(b) => b.fit.as_ref().map(|f| &f.report),
        }
    }

    /// The parameter interval of the curve.
    #[must_use]
    pub fn domain(&self) -> [f64; 2] {
        match self {
            Self::S2(b) => b.curve.domain(),
            Self::S3(b) => b.curve.domain(),
            Self::Sm(b) => b.curve.domain(),
        }
    }
}

/// The conversions between a sphere's points and the scene's number lists.
///
/// Points and vectors are `Send + Sync`, so that built curves are too.
pub trait ScenePoint: Manifold<Vector: Send + Sync> + Send + Sync + 'static {
    /// Builds a point from scene coordinates (normalising).
    ///
    /// # Errors
    ///
    /// As the point type's `try_new`.
    fn from_coords(c: &[f64]) -> Result<Self, PointError>;
    /// The scene coordinates.
    fn coords(&self) -> Vec<f64>;
    /// An ambient vector in the scene's coordinate order.
    fn vector_coords(v: &Self::Vector) -> Vec<f64>;
    /// An ambient vector from scene coordinates; `None` for the wrong count.
    fn vector_from_coords(c: &[f64]) -> Option<Self::Vector>;
    /// Angular velocity and acceleration where the space has them, in the space frame or
    /// (`body`) the body frame.
    fn angular(_jet: &Jet<Self>, _body: bool) -> Option<([f64; 3], [f64; 3])> {
        None
    }
    /// The sphere the point is on (of S^m, its dimension).
    fn space(&self) -> Space;
    /// The built curve of this sphere, as the rest of the scene code takes it.
    fn into_built_curve(built: Built<Self>) -> BuiltCurve;
}

impl ScenePoint for S2Point {
    fn from_coords(c: &[f64]) -> Result<Self, PointError> {
        Self::try_new(spherekit::glam::DVec3::from_slice(c))
    }
    fn coords(&self) -> Vec<f64> {
        self.as_dvec3().to_array().to_vec()
    }
    fn vector_coords(v: &spherekit::glam::DVec3) -> Vec<f64> {
        v.to_array().to_vec()
    }
    fn vector_from_coords(c: &[f64]) -> Option<spherekit::glam::DVec3> {
        (c.len() == 3).then(|| spherekit::glam::DVec3::from_slice(c))
    }
    fn space(&self) -> Space {
        Space::S2
    }
    fn into_built_curve(built: Built<Self>) -> BuiltCurve {
        BuiltCurve::S2(built)
    }
}

impl ScenePoint for UnitQuat {
    fn from_coords(c: &[f64]) -> Result<Self, PointError> {
        Self::from_wxyz([c[0], c[1], c[2], c[3]])
    }
    fn coords(&self) -> Vec<f64> {
        self.to_wxyz().to_vec()
    }
    fn vector_coords(v: &spherekit::glam::DVec4) -> Vec<f64> {
        vec![v.w, v.x, v.y, v.z]
    }
    fn vector_from_coords(c: &[f64]) -> Option<spherekit::glam::DVec4> {
        match c {
            &[w, x, y, z] => Some(spherekit::glam::DVec4::new(x, y, z, w)),
            _ => None,
        }
    }
    fn angular(jet: &Jet<Self>, body: bool) -> Option<([f64; 3], [f64; 3])> {
        let (w, a) = if body {
            angular_velocity_acceleration_body(jet.point, jet.velocity, jet.acceleration)
        } else {
            angular_velocity_acceleration(jet.point, jet.velocity, jet.acceleration)
        };
        Some((w.to_array(), a.to_array()))
    }
    fn space(&self) -> Space {
        Space::S3
    }
    fn into_built_curve(built: Built<Self>) -> BuiltCurve {
        BuiltCurve::S3(built)
    }
}

impl ScenePoint for SmPoint {
    fn from_coords(c: &[f64]) -> Result<Self, PointError> {
        Self::try_new(c.to_vec())
    }
    fn coords(&self) -> Vec<f64> {
        SmPoint::coords(self).to_vec()
    }
    fn vector_coords(v: &VecN) -> Vec<f64> {
        v.to_vec()
    }
    fn vector_from_coords(c: &[f64]) -> Option<VecN> {
        Some(VecN::from(c.to_vec()))
    }
    fn space(&self) -> Space {
        Space::Sm(self.coords().len().saturating_sub(1))
    }
    fn into_built_curve(built: Built<Self>) -> BuiltCurve {
        BuiltCurve::Sm(built)
    }
}
