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
/// the same sphere, so a method's build function is written once for S², S³ and S^m. Without
/// the `compact` feature `expr` is compiled for each sphere (`on_each_sphere!`); with it (the
/// browser build, for size) once, on S^m (`on_s_m!`; the unit tests have both,
/// `on_sm::ROUTE` choosing, for `on_sm::tests` to compare them).
#[cfg(not(feature = "compact"))]
macro_rules! on_every_sphere {
    ($points:expr, |$p:ident| $body:expr) => {
        $crate::built::on_each_sphere!($points, |$p| $body)
    };
}
#[cfg(all(feature = "compact", not(test)))]
macro_rules! on_every_sphere {
    ($points:expr, |$p:ident| $body:expr) => {
        $crate::built::on_s_m!($points, |$p| $body)
    };
}
#[cfg(all(feature = "compact", test))]
macro_rules! on_every_sphere {
    ($points:expr, |$p:ident| $body:expr) => {
        if $crate::built::on_sm::ROUTE.get() {
            $crate::built::on_s_m!($points, |$p| $body)
        } else {
            $crate::built::on_each_sphere!($points, |$p| $body)
        }
    };
}

/// `on_every_sphere!` with `expr` compiled for each sphere.
#[cfg(any(not(feature = "compact"), test))]
macro_rules! on_each_sphere {
    ($points:expr, |$p:ident| $body:expr) => {
        match $points {
            $crate::scene::Points::S2($p) => $crate::built::BuiltCurve::S2($body),
            $crate::scene::Points::S3($p) => $crate::built::BuiltCurve::S3($body),
            $crate::scene::Points::Sm($p) => $crate::built::BuiltCurve::Sm($body),
        }
    };
}
#[cfg(any(not(feature = "compact"), test))]
pub(crate) use on_each_sphere;

/// `on_every_sphere!` with `expr` compiled once, on S^m: the keys of an S² or S³ scene become
/// points of S^m, and the built curve is wrapped back onto their sphere ([`on_sm`]).
#[cfg(feature = "compact")]
macro_rules! on_s_m {
    ($points:expr, |$p:ident| $body:expr) => {{
        let ($p, back) = $crate::built::on_sm::to_sm($points);
        let built: $crate::built::Built<spherekit::SmPoint> = $body;
        back.wrap(built)
    }};
}
pub(crate) use on_every_sphere;
#[cfg(feature = "compact")]
pub(crate) use on_s_m;

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

/// The `compact` feature: the every-sphere methods built and evaluated once, on S^m.
///
/// A method written with [`on_every_sphere!`] would otherwise be compiled three times (for
/// [`S2Point`], [`UnitQuat`] and [`SmPoint`]), its construction and its evaluation; the core's
/// own `compact` feature (which this one turns on) compiles only the constructions once. Here
/// the keys of an S² or S³ scene become points of S^m with the same ambient coordinates, the
/// method builds there, and [`OnSm`] wraps the curve so that the rest of the code sees a curve
/// on S² or S³. Every [`Manifold`] operation is a default method over [`Ambient`], whose
/// implementations do the same arithmetic coordinate by coordinate for `DVec3`, `DVec4` and
/// [`VecN`] (the core's `recast.rs`), so the curve and its samples have the same bits as
/// without the feature (`tests::curves_on_s_m_have_the_same_bits`; `just unit` also renders the
/// golden images with it and without it). The fit of rotations is not written for every sphere
/// (its distances are rotation angles) and stays on [`UnitQuat`]. The cost is in evaluation, a point of S^m allocates its coordinates: the browser build turns the
/// feature on for its size (BENCHMARKS.md section 6 has the frame times), the CLI and Python
/// leave it off.
#[cfg(feature = "compact")]
pub(crate) mod on_sm {
    use spherekit::glam::{DVec3, DVec4};
    use spherekit::{Ambient, Curve, Jet, Manifold, Side, SmPoint, VecN};

    use super::{Built, BuiltCurve, ScenePoint};
    use crate::fit::FitRecord;
    use crate::scene::Points;

    /// The sphere a curve built on S^m goes back to.
    pub(crate) enum Back {
        S2,
        S3,
        Sm,
    }

    /// A point of S^m with the ambient coordinates of `p`.
    fn point<P: Manifold>(p: &P) -> SmPoint {
        SmPoint::from_vector_unchecked(VecN::new(p.to_vector().as_slice().to_vec()))
    }

    /// The scene's points as points of S^m, and the sphere to go back to.
    pub(crate) fn to_sm(points: Points) -> (Vec<SmPoint>, Back) {
        match points {
            Points::S2(p) => (p.iter().map(point).collect(), Back::S2),
            Points::S3(p) => (p.iter().map(point).collect(), Back::S3),
            Points::Sm(p) => (p, Back::Sm),
        }
    }

    impl Back {
        /// `built` on the sphere of the scene.
        pub(crate) fn wrap(self, built: Built<SmPoint>) -> BuiltCurve {
            match self {
                Self::S2 => BuiltCurve::S2(recast(built, DVec3::ZERO)),
                Self::S3 => BuiltCurve::S3(recast(built, DVec4::ZERO)),
                Self::Sm => BuiltCurve::Sm(built),
            }
        }
    }

    /// `built` as a curve of the point type whose ambient vectors are like `like`.
    fn recast<Q: ScenePoint>(built: Built<SmPoint>, like: Q::Vector) -> Built<Q> {
        let to = OnSm::<Q> {
            curve: built.curve,
            like,
        };
        let points = |ps: &[SmPoint]| ps.iter().map(|p| to.point(p)).collect();
        Built {
            inputs: points(&built.inputs),
            controls: points(&built.controls),
            auxiliary: points(&built.auxiliary),
            info: built.info,
            order: built.order,
            fit: built.fit.map(|f| FitRecord {
                keys: points(&f.keys),
                times: f.times,
                report: f.report,
            }),
            curve: Box::new(to),
        }
    }

    /// A curve on S^m seen as a curve of `Q` (S² or S³), its points and vectors converted
    /// coordinate by coordinate (every method of [`Curve`] forwarded, so that none falls back
    /// to a default the inner curve overrides).
    #[derive(Debug)]
    pub(crate) struct OnSm<Q: Manifold> {
        curve: Box<dyn Curve<Point = SmPoint> + Send + Sync>,
        like: Q::Vector,
    }

    impl<Q: Manifold> OnSm<Q> {
        fn vector(&self, v: &VecN) -> Q::Vector {
            self.like.with_coords(v.as_slice())
        }

        fn point(&self, p: &SmPoint) -> Q {
            Q::from_vector_unchecked(self.like.with_coords(p.coords()))
        }

        fn jet(&self, j: &Jet<SmPoint>) -> Jet<Q> {
            Jet {
                point: self.point(&j.point),
                velocity: self.vector(&j.velocity),
                acceleration: self.vector(&j.acceleration),
            }
        }
    }

    impl<Q: Manifold> Curve for OnSm<Q> {
        type Point = Q;

        fn domain(&self) -> [f64; 2] {
            self.curve.domain()
        }

        fn joints(&self) -> &[f64] {
            self.curve.joints()
        }

        fn is_closed(&self) -> bool {
            self.curve.is_closed()
        }

        fn is_antiperiodic(&self) -> bool {
            self.curve.is_antiperiodic()
        }

        fn jet_at(&self, t: f64, side: Side) -> Jet<Q> {
            self.jet(&self.curve.jet_at(t, side))
        }

        fn jet(&self, t: f64) -> Jet<Q> {
            self.jet(&self.curve.jet(t))
        }

        fn eval(&self, t: f64) -> Q {
            self.point(&self.curve.eval(t))
        }

        fn jet_beyond(&self, t: f64) -> Option<Jet<Q>> {
            self.curve.jet_beyond(t).map(|j| self.jet(&j))
        }

        fn eval_many(&self, ts: &[f64], out: &mut [Q]) {
            let mut ps = vec![self.curve.eval(self.curve.domain()[0]); out.len()];
            self.curve.eval_many(ts, &mut ps);
            for (o, p) in out.iter_mut().zip(&ps) {
                *o = self.point(p);
            }
        }

        fn jet_many(&self, ts: &[f64], out: &mut [Jet<Q>]) {
            let mut js = vec![self.curve.jet(self.curve.domain()[0]); out.len()];
            self.curve.jet_many(ts, &mut js);
            for (o, j) in out.iter_mut().zip(&js) {
                *o = self.jet(j);
            }
        }
    }

    #[cfg(test)]
    std::thread_local! {
        /// Whether the unit tests' `on_every_sphere!` builds on S^m, as the feature's builds
        /// outside the unit tests do.
        pub(crate) static ROUTE: std::cell::Cell<bool> = const { std::cell::Cell::new(true) };
    }

    #[cfg(test)]
    mod tests {
        use std::path::Path;

        use super::ROUTE;
        use crate::scene::{SampleOptions, Scene};

        /// Every golden scene (every method, S² and S³, open and closed, with parameters, fits)
        /// and every scene of the degenerate-input corpus (near and exactly coincident keys,
        /// near half turns, parameters at and outside the domain under every extrapolation
        /// policy), sampled with derivatives and the continuity report: the same JSON (`f64`s
        /// printed in the shortest form that reads back to the same bits), or the same error,
        /// built on each sphere and on S^m.
        #[test]
        fn curves_on_s_m_have_the_same_bits() {
            let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests");
            let (mut compared, mut differ) = (0, Vec::new());
            let dirs = [root.join("golden"), root.join("robustness/degenerate")];
            let paths = dirs
                .iter()
                .flat_map(|d| std::fs::read_dir(d).expect("scenes"));
            for entry in paths {
                let path = entry.expect("entry").path();
                if path.extension().is_none_or(|e| e != "json") {
                    continue;
                }
                let text = std::fs::read_to_string(&path).expect("scene");
                let Ok(scene) = Scene::from_json(&text) else {
                    continue;
                };
                let options = SampleOptions {
                    deriv: true,
                    continuity: true,
                    body_frame: false,
                };
                let sample = |on_sm: bool| {
                    ROUTE.set(on_sm);
                    let curves = scene.build();
                    ROUTE.set(true);
                    curves
                        .map(|c| scene.sample_json_with(&c, options).to_string())
                        .map_err(|e| e.to_string())
                };
                if sample(false) != sample(true) {
                    differ.push(path.display().to_string());
                }
                compared += 1;
            }
            assert!(differ.is_empty(), "{differ:#?}");
            assert!(compared >= 400, "{compared} scenes");
        }
    }
}
