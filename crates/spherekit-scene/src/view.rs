// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The scene's `view` object: camera, plot strip, body frames, flattening accuracy. The
//! renderer draws by it; this module only reads and checks it.

use serde_json::{Map, Value};
use spherekit::UnitQuat;
use spherekit::glam::DQuat;

use crate::error::SceneError;
use crate::space::Space;

/// What the strip under the sphere shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plot {
    /// Angular speed |ω(t)| (S³) or speed |p′(t)| (other spheres) against t.
    Speed,
    /// The speed, and under it the components of the angular velocity ω (S³, space frame) or
    /// of the velocity p′ (S²) against t.
    Omega,
    /// No strip.
    None,
}

/// The time axis of the plot strip.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlotTime {
    /// One t axis for all curves, over the union of their domains, in their own units.
    Shared,
    /// Each curve's domain stretched to the full width (t normalized to [0, 1] per curve; the
    /// speeds are then per unit of normalized t).
    Normalized,
}

/// The most characters `view.title` may have.
pub const MAX_TITLE_CHARS: usize = 120;

/// Rendering options read from a scene's `view`.
///
/// ```text
/// "view": { "camera": [w, x, y, z] | { "yaw": deg, "pitch": deg },   default: see below
///           "plot": "speed" | "omega" | "none",  default "speed" on S3, "none" elsewhere
///                                                ("omega": speed and the components of ω or p′;
///                                                S2 and S3)
///           "plot_time": "shared" | "normalized", default "shared": one t axis for all curves
///           "frames": N,                         S3: body triads at N parameters (default 0)
///           "omega_frame": "space" | "body",     S3: the frame of the plotted ω (default "space")
///           "accuracy": radians,                 curve flattening accuracy (default 1e-3)
///           "axes": ["x", "y", "z"],             S3: the body axes whose tips are traced
///                                                (default all three for one curve, ["x"] for several)
///           "legend": true | false,              default: on for several curves, and on S3
///           "title": "text" }                    a line of text above the sphere (default none)
/// ```
///
/// Without `camera` the renderer chooses one (S² scenes are viewed from the direction of the
/// mean of their points, so that the data faces the reader).
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// The camera orientation, when the scene gives one: its body x axis points right on
    /// screen, y up, z at the viewer.
    pub camera: Option<UnitQuat>,
    /// The plot strip.
    pub plot: Plot,
    /// Number of body-axis triads along each S³ curve.
    pub frames: usize,
    /// Largest angular deviation (radians) of the drawn polyline from the curve.
    pub accuracy: f64,
    /// Which body axes (0 = x, 1 = y, 2 = z) S³ curves are drawn by.
    pub axes: Vec<usize>,
    /// The plot strip's time axis.
    pub plot_time: PlotTime,
    /// Whether the figure has a legend.
    pub legend: bool,
    /// A line of text above the sphere.
    pub title: Option<String>,
    /// Whether the plotted angular velocity ω (S³) is in the body frame (ω = 2q̄q′) rather
    /// than the space frame (2q′q̄).
    pub omega_body: bool,
}

/// The default flattening accuracy in radians: a quarter of a pixel at 1 000 px.
pub const DEFAULT_FLATTENING_ACCURACY: f64 = 1e-3;

/// The most triads `view.frames` may ask for.
pub const MAX_FRAMES: usize = 200;

fn bad(field: &str, message: impl Into<String>) -> SceneError {
    SceneError::Field {
        field: if field.is_empty() {
            "view".into()
        } else {
            format!("view.{field}")
        },
        message: message.into(),
    }
}

impl View {
    /// The camera looking at the origin from yaw `yaw` and pitch `pitch` (degrees), world z up.
    #[must_use]
    pub fn camera_from_yaw_pitch(yaw: f64, pitch: f64) -> UnitQuat {
        let (y, p) = (yaw.to_radians(), pitch.to_radians());
        // Rotate about z by 90° + yaw, then tilt about the camera's x axis by 90° − pitch, so
        // that the camera's z axis points to (cos p cos y, cos p sin y, sin p) and its y axis is
        // the projection of world z.
        let a = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2 + y);
        let b = DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2 - p);
        UnitQuat::try_new(a * b).unwrap_or(UnitQuat::IDENTITY)
    }

    /// Reads a scene's `view` (absent: the defaults) for a scene on `space` with `curves`
    /// curves.
    ///
    /// # Errors
    ///
    /// [`SceneError::Field`] naming the bad field (`view.camera`).
    pub fn from_json(
        view: Option<&Value>,
        space: Space,
        curves: usize,
    ) -> Result<Self, SceneError> {
        let quaternions = space == Space::S3;
        let several = curves > 1;
        let empty = Map::new();
        let map = match view {
            None => &empty,
            Some(Value::Object(m)) => m,
            Some(_) => return Err(bad("", "must be an object")),
        };
        const OPTIONS: [&str; 9] = [
            "camera",
            "plot",
            "plot_time",
            "frames",
            "omega_frame",
            "accuracy",
            "axes",
            "legend",
            "title",
        ];
        if let Some(k) = map.keys().find(|k| !OPTIONS.contains(&k.as_str())) {
            return Err(bad(
                k,
                format!("unknown view option ({})", OPTIONS.join(", ")),
            ));
        }
        let camera = match map.get("camera") {
            None => None,
            Some(Value::Array(a)) => {
                let c: Option<Vec<f64>> = a.iter().map(Value::as_f64).collect();
                match c.as_deref() {
                    Some(&[w, x, y, z]) => Some(
                        UnitQuat::from_wxyz([w, x, y, z])
                            .map_err(|e| bad("camera", format!("quaternion {}", e.predicate())))?,
                    ),
                    _ => {
                        return Err(bad(
                            "camera",
                            "must be a quaternion [w, x, y, z] or {\"yaw\", \"pitch\"}",
                        ));
                    }
                }
            }
            Some(Value::Object(o)) => {
                let angle = |k: &str| -> Result<f64, SceneError> {
                    match o.get(k) {
                        None => Ok(0.0),
                        Some(v) => v.as_f64().filter(|x| x.is_finite()).ok_or_else(|| {
                            bad(&format!("camera.{k}"), "must be a finite number of degrees")
                        }),
                    }
                };
                if let Some(k) = o.keys().find(|k| !["yaw", "pitch"].contains(&k.as_str())) {
                    return Err(bad(
                        &format!("camera.{k}"),
                        "unknown camera option (yaw, pitch)",
                    ));
                }
                Some(Self::camera_from_yaw_pitch(angle("yaw")?, angle("pitch")?))
            }
            Some(_) => {
                return Err(bad(
                    "camera",
                    "must be a quaternion [w, x, y, z] or {\"yaw\", \"pitch\"}",
                ));
            }
        };
        let plot = match map.get("plot") {
            None if quaternions => Plot::Speed,
            None => Plot::None,
            Some(v) => match v.as_str() {
                Some("speed") => Plot::Speed,
                Some("omega") if matches!(space, Space::S2 | Space::S3) => Plot::Omega,
                Some("omega") => {
                    return Err(bad(
                        "plot",
                        "\"omega\" (velocity components) is drawn for S2 and S3 scenes only",
                    ));
                }
                Some("none") => Plot::None,
                _ => return Err(bad("plot", "must be \"speed\", \"omega\" or \"none\"")),
            },
        };
        let plot_time = match map.get("plot_time") {
            None => PlotTime::Shared,
            Some(v) => match v.as_str() {
                Some("shared") => PlotTime::Shared,
                Some("normalized") => PlotTime::Normalized,
                _ => return Err(bad("plot_time", "must be \"shared\" or \"normalized\"")),
            },
        };
        let legend = match map.get("legend") {
            None => several || quaternions,
            Some(v) => v
                .as_bool()
                .ok_or_else(|| bad("legend", "must be true or false"))?,
        };
        let title = match map.get("title") {
            None => None,
            Some(v) => {
                let t = v
                    .as_str()
                    .filter(|t| {
                        let n = t.chars().count();
                        (1..=MAX_TITLE_CHARS).contains(&n) && !t.chars().any(char::is_control)
                    })
                    .ok_or_else(|| {
                        bad(
                            "title",
                            format!(
                                "must be a string of 1 to {MAX_TITLE_CHARS} characters on one line"
                            ),
                        )
                    })?;
                Some(t.to_owned())
            }
        };
        let frames = match map.get("frames") {
            None => 0,
            Some(v) => {
                let n = v
                    .as_u64()
                    .filter(|n| *n <= MAX_FRAMES as u64)
                    .ok_or_else(|| {
                        bad(
                            "frames",
                            format!("must be a whole number from 0 to {MAX_FRAMES}"),
                        )
                    })?;
                if !quaternions && n > 0 {
                    return Err(bad("frames", "body triads are drawn for S3 scenes only"));
                }
                usize::try_from(n).unwrap_or(0)
            }
        };
        let omega_body = match map.get("omega_frame") {
            None => false,
            Some(v) => {
                let body = match v.as_str() {
                    Some("space") => false,
                    Some("body") => true,
                    _ => return Err(bad("omega_frame", "must be \"space\" or \"body\"")),
                };
                if !quaternions {
                    return Err(bad(
                        "omega_frame",
                        "the frame of ω applies to S3 scenes only",
                    ));
                }
                body
            }
        };
        let accuracy = match map.get("accuracy") {
            None => DEFAULT_FLATTENING_ACCURACY,
            Some(v) => v
                .as_f64()
                .filter(|a| (1e-6..=0.1).contains(a))
                .ok_or_else(|| bad("accuracy", "must be a number of radians from 1e-6 to 0.1"))?,
        };
        let axes = match map.get("axes") {
            None if several => vec![0],
            None => vec![0, 1, 2],
            Some(v) => {
                let names = v.as_array().filter(|a| !a.is_empty() && a.len() <= 3);
                let axes: Option<Vec<usize>> = names.and_then(|a| {
                    a.iter()
                        .map(|n| match n.as_str() {
                            Some("x") => Some(0),
                            Some("y") => Some(1),
                            Some("z") => Some(2),
                            _ => None,
                        })
                        .collect()
                });
                axes.ok_or_else(|| {
                    bad("axes", "must be a list of body axes such as [\"x\", \"z\"]")
                })?
            }
        };
        if !quaternions && map.contains_key("axes") {
            return Err(bad("axes", "body axes are drawn for S3 scenes only"));
        }
        Ok(Self {
            camera,
            plot,
            frames,
            accuracy,
            axes,
            plot_time,
            legend,
            title,
            omega_body,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;

    fn view(json: &str, space: Space, curves: usize) -> Result<View, String> {
        let v: Value = serde_json::from_str(json).expect("JSON");
        View::from_json(Some(&v), space, curves).map_err(|e| e.to_string())
    }

    #[test]
    fn figure_options_default_by_the_picture() {
        let one_s2 = view("{}", Space::S2, 1).expect("view");
        assert!(!one_s2.legend, "one S2 curve: no legend");
        assert_eq!(one_s2.plot_time, PlotTime::Shared);
        assert_eq!(one_s2.title, None);
        assert!(
            view("{}", Space::S2, 2).expect("view").legend,
            "several curves"
        );
        assert!(
            view("{}", Space::S3, 1).expect("view").legend,
            "S3 axis colours"
        );
        let v = view(
            r#"{"legend": false, "title": "A", "plot": "omega", "plot_time": "normalized"}"#,
            Space::S3,
            3,
        )
        .expect("view");
        assert!(!v.legend);
        assert_eq!(v.title.as_deref(), Some("A"));
        assert_eq!((v.plot, v.plot_time), (Plot::Omega, PlotTime::Normalized));
    }

    #[test]
    fn the_frame_of_omega_is_space_unless_body_is_asked_for() {
        assert!(!view("{}", Space::S3, 1).expect("view").omega_body);
        let space = view(r#"{"omega_frame": "space"}"#, Space::S3, 1).expect("view");
        assert!(!space.omega_body, "space");
        let body = view(r#"{"omega_frame": "body"}"#, Space::S3, 1).expect("view");
        assert!(body.omega_body, "body");
    }

    #[test]
    fn bad_figure_options_name_the_field() {
        let long = format!(r#"{{"title": "{}"}}"#, "x".repeat(MAX_TITLE_CHARS + 1));
        for (json, space, expected) in [
            (
                r#"{"legend": 1}"#,
                Space::S2,
                "view.legend: must be true or false",
            ),
            (
                r#"{"title": ""}"#,
                Space::S2,
                "view.title: must be a string of 1 to 120",
            ),
            (long.as_str(), Space::S2, "view.title: must be a string"),
            (r#"{"title": "a\nb"}"#, Space::S2, "on one line"),
            (
                r#"{"plot_time": "own"}"#,
                Space::S2,
                "view.plot_time: must be",
            ),
            (r#"{"plot": "omega"}"#, Space::Sm(1), "view.plot: \"omega\""),
            (
                r#"{"plot": "phase"}"#,
                Space::S2,
                "view.plot: must be \"speed\", \"omega\" or \"none\"",
            ),
            (
                r#"{"subtitle": "x"}"#,
                Space::S2,
                "view.subtitle: unknown view option",
            ),
            (
                r#"{"omega_frame": "world"}"#,
                Space::S3,
                "view.omega_frame: must be \"space\" or \"body\"",
            ),
            (
                r#"{"omega_frame": "body"}"#,
                Space::S2,
                "view.omega_frame: the frame of ω applies to S3 scenes only",
            ),
        ] {
            let e = view(json, space, 1).expect_err(json);
            assert!(e.contains(expected), "{json}: {e}");
        }
    }

    #[test]
    fn curve_labels_are_checked_and_kept() {
        let scene = Scene::from_json(
            r#"{"space":"S2","curves":[{"method":"geodesic","points":[[1,0,0],[0,1,0]],"label":"arc"}]}"#,
        )
        .expect("scene");
        assert_eq!(scene.curves[0].label.as_deref(), Some("arc"));
        for (label, expected) in [
            (r#""""#, "curves[0].label: must be 1 to 60 characters"),
            ("3", "label"),
        ] {
            let text = format!(
                r#"{{"space":"S2","curves":[{{"method":"geodesic","points":[[1,0,0],[0,1,0]],"label":{label}}}]}}"#
            );
            let e = Scene::from_json(&text).expect_err(label).to_string();
            assert!(e.contains(expected), "{label}: {e}");
        }
    }
}
