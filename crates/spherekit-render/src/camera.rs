// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The camera a scene is drawn with, and the screen geometry an interactive caller needs:
//! projecting and unprojecting pixels, picking the point under the pointer, turning the view
//! or a key by a drag.

use spherekit::glam::{DQuat, DVec3};
use spherekit::{SplineError, UnitQuat};
use spherekit_scene::{BuiltCurve, View};

/// The orthographic camera looking at the unit sphere: its body x axis points right on
/// screen, y up, z at the viewer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The camera's orientation.
    pub orientation: UnitQuat,
}

/// The camera looking at the origin from yaw `yaw` and pitch `pitch` (degrees), world z up.
#[must_use]
pub fn yaw_pitch(yaw: f64, pitch: f64) -> UnitQuat {
    View::camera_from_yaw_pitch(yaw, pitch)
}

impl Camera {
    /// The scene's camera, or by default: S² (and S¹) scenes viewed from the direction of the
    /// mean of their points (world z up, at most 60° above or below the equator) so that the
    /// data faces the reader; S³ scenes, and points whose mean is near the centre, from yaw
    /// 35°, pitch 20°.
    #[must_use]
    pub fn of(view: &View, curves: &[BuiltCurve]) -> Self {
        let orientation = view.camera.unwrap_or_else(|| match facing(curves) {
            Some(d) if d.length() > 0.2 => {
                let yaw = libm::atan2(d.y, d.x).to_degrees();
                let pitch = libm::atan2(d.z, d.truncate().length()).to_degrees();
                yaw_pitch(yaw, pitch.clamp(-60.0, 60.0))
            }
            _ => yaw_pitch(35.0, 20.0),
        });
        Self { orientation }
    }

    /// The camera's screen axes in world coordinates: right, up, and towards the viewer.
    #[must_use]
    pub fn axes(&self) -> [DVec3; 3] {
        [DVec3::X, DVec3::Y, DVec3::Z].map(|a| self.orientation.rotate(a))
    }

    /// Pixel position `[x, y]` and depth (positive towards the viewer) of a point of ℝ³ in an
    /// image `size` pixels wide, as the renderer draws it.
    #[must_use]
    pub fn project(&self, p: DVec3, size: u32) -> [f64; 3] {
        let [r, u, z] = self.axes();
        let (c, radius) = sphere_frame(size);
        [c + radius * p.dot(r), c - radius * p.dot(u), p.dot(z)]
    }

    /// The point of the sphere's visible hemisphere drawn at pixel `[x, y]` (the inverse of
    /// [`Camera::project`]); a pixel outside the disc gives the nearest point of the rim.
    #[must_use]
    pub fn unproject(&self, x: f64, y: f64, size: u32) -> DVec3 {
        let [r, u, z] = self.axes();
        let (c, radius) = sphere_frame(size);
        let (dx, dy) = ((x - c) / radius, (c - y) / radius);
        let d2 = dx * dx + dy * dy;
        if d2 >= 1.0 {
            let d = d2.sqrt();
            return r * (dx / d) + u * (dy / d);
        }
        r * dx + u * dy + z * (1.0 - d2).sqrt()
    }

    /// The camera after a drag from pixel `(x0, y0)` to `(x1, y1)`: the sphere point under the
    /// pointer follows it (the camera turns opposite to the drag).
    #[must_use]
    pub fn dragged(&self, [x0, y0]: [f64; 2], [x1, y1]: [f64; 2], size: u32) -> UnitQuat {
        let (a, b) = (self.unproject(x0, y0, size), self.unproject(x1, y1, size));
        let turn = DQuat::from_rotation_arc(b, a);
        UnitQuat::try_new(turn * self.orientation.as_dquat()).unwrap_or(self.orientation)
    }

    /// `key` turned by the rotation taking the sphere point under pixel `(x0, y0)` to the one
    /// under `(x1, y1)` (dragging an S³ key by one of its axis tips).
    ///
    /// # Errors
    ///
    /// A [`SplineError::InvalidPoint`] if the turned key is not a unit quaternion (it always is
    /// for finite pixels).
    pub fn turn_key(
        &self,
        key: UnitQuat,
        [x0, y0]: [f64; 2],
        [x1, y1]: [f64; 2],
        size: u32,
    ) -> Result<UnitQuat, SplineError> {
        let (a, b) = (self.unproject(x0, y0, size), self.unproject(x1, y1, size));
        turn_towards(key, a, b)
    }

    /// The input point (S² and S¹) or key (S³: any tip of its rotated body axes) drawn nearest
    /// to pixel `(x, y)` within `radius` pixels, on the visible side, as `(curve, index)`.
    #[must_use]
    pub fn pick(
        &self,
        curves: &[BuiltCurve],
        [x, y]: [f64; 2],
        size: u32,
        radius: f64,
    ) -> Option<(usize, usize)> {
        let mut best: Option<(f64, usize, usize)> = None;
        for (ci, c) in curves.iter().enumerate() {
            for (pi, tips) in marker_positions(c).into_iter().enumerate() {
                for p in tips {
                    let [px, py, depth] = self.project(p, size);
                    let d = (px - x).hypot(py - y);
                    if depth >= -1e-9 && d <= radius && best.is_none_or(|b| d < b.0) {
                        best = Some((d, ci, pi));
                    }
                }
            }
        }
        best.map(|(_, c, p)| (c, p))
    }
}

/// `key` turned by the rotation taking `a` to `b` (points of ℝ³).
///
/// # Errors
///
/// As [`Camera::turn_key`].
pub fn turn_towards(key: UnitQuat, a: DVec3, b: DVec3) -> Result<UnitQuat, SplineError> {
    let turn = DQuat::from_rotation_arc(a.normalize_or_zero(), b.normalize_or_zero());
    UnitQuat::try_new(turn * key.as_dquat())
        .map_err(|reason| SplineError::InvalidPoint { index: 0, reason })
}

/// The sphere's centre (on both axes) and radius in pixels in an image `size` pixels wide.
pub(crate) fn sphere_frame(size: u32) -> (f64, f64) {
    let s = f64::from(size);
    (0.5 * s, 0.45 * s)
}

/// Where each input point of a curve is drawn: the point (S², S¹) or the tips of the key's
/// rotated body axes (S³).
fn marker_positions(c: &BuiltCurve) -> Vec<Vec<DVec3>> {
    match c {
        BuiltCurve::S2(b) => b.inputs.iter().map(|p| vec![p.as_dvec3()]).collect(),
        BuiltCurve::Sm(b) => b
            .inputs
            .iter()
            .map(|p| vec![DVec3::new(p.coords()[0], p.coords()[1], 0.0)])
            .collect(),
        BuiltCurve::S3(b) => b
            .inputs
            .iter()
            .map(|q| [DVec3::X, DVec3::Y, DVec3::Z].map(|a| q.rotate(a)).to_vec())
            .collect(),
    }
}

/// The mean of the input points of curves on S² or S¹, for the default camera.
fn facing(curves: &[BuiltCurve]) -> Option<DVec3> {
    let mut sum = DVec3::ZERO;
    let mut count = 0.0;
    for c in curves {
        match c {
            BuiltCurve::S2(b) => {
                for p in &b.inputs {
                    sum += p.as_dvec3();
                    count += 1.0;
                }
            }
            BuiltCurve::Sm(b) => {
                for p in &b.inputs {
                    sum += DVec3::new(p.coords()[0], p.coords()[1], 0.0);
                    count += 1.0;
                }
            }
            BuiltCurve::S3(_) => return None,
        }
    }
    (count > 0.0).then(|| sum / count)
}
