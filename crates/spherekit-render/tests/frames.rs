// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Properties of rendered frames that callers rely on: they are opaque (the wasm crate hands
//! the bytes to a canvas as straight alpha), and redrawing from the kept backdrop gives the
//! pixels of a fresh drawing.

use spherekit_render::{RenderError, render};
use spherekit_scene::Scene;

fn scene(text: &str) -> Scene {
    Scene::from_json(text).expect("valid scene")
}

const S2: &str = r#"{"space":"S2","method":"catmull-rom",
    "points":[[1,0,0],[0,1,0],[0,0,1],[-1,0,0.2],[0,-1,0]],"view":{"plot":"speed"}}"#;
const S3: &str = r#"{"space":"S3","curves":[
    {"method":"squad","points":[[1,0,0,0],[0.7071,0.7071,0,0],[0,0,1,0],[0.5,0.5,0.5,0.5]]},
    {"method":"bspline-kim","points":[[1,0,0,0],[0.7071,0.7071,0,0],[0,0,1,0],[0.5,0.5,0.5,0.5]]}],
    "view":{"plot":"speed","frames":3}}"#;
const S2_OTHER_CAMERA: &str = r#"{"space":"S2","method":"geodesic",
    "points":[[1,0,0],[0,1,0],[0,0,1]],"view":{"camera":{"yaw":120,"pitch":-40}}}"#;

#[test]
fn frames_are_opaque() {
    // 16 and 17 px: the smallest size, and a width that is not a whole number of the
    // stroker's vector blocks (its rows are padded past the pixmap's edge).
    for size in [200, 16, 17] {
        for text in [S2, S3, S2_OTHER_CAMERA] {
            let pixmap = render(&scene(text), size).expect("renders");
            assert!(
                pixmap.pixels().iter().all(|p| p.alpha() == u8::MAX),
                "a pixel is not opaque in {text} at {size} px"
            );
        }
    }
}

#[test]
fn curves_change_the_pixels_they_cross_and_leave_the_rest() {
    // The same sphere and camera with a point and with an arc from it: the frames differ, but
    // only near the arc and its second marker.
    let bare = r#"{"space":"S2","method":"geodesic","points":[[0,0,1],[0,0,1]],
        "view":{"camera":{"yaw":0,"pitch":0}}}"#;
    let arc = r#"{"space":"S2","method":"geodesic","points":[[0,0,1],[0.6,0,0.8]],
        "view":{"camera":{"yaw":0,"pitch":0}}}"#;
    let (a, b) = (
        render(&scene(bare), 128).expect("renders"),
        render(&scene(arc), 128).expect("renders"),
    );
    let changed = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(p, q)| p != q)
        .count();
    assert!(
        changed > 20,
        "the arc and its markers are drawn ({changed} pixels)"
    );
    assert!(
        changed < 128 * 128 / 10,
        "and little else changes ({changed} pixels)"
    );
}

#[test]
fn kept_backdrop_gives_the_pixels_of_a_fresh_drawing() {
    // Each scene drawn first on a thread of its own (nothing kept), then in one thread in an
    // order that reuses the backdrop (same size and camera twice in a row) and replaces it.
    let fresh: Vec<Vec<u8>> = [S2, S3, S2_OTHER_CAMERA]
        .iter()
        .map(|&text| {
            std::thread::spawn(move || render(&scene(text), 160).expect("renders").take())
                .join()
                .expect("thread")
        })
        .collect();
    for (i, text) in [S2, S2, S3, S3, S2_OTHER_CAMERA, S2, S2_OTHER_CAMERA]
        .iter()
        .enumerate()
    {
        let k = [0, 0, 1, 1, 2, 0, 2][i];
        let again = render(&scene(text), 160).expect("renders").take();
        assert!(again == fresh[k], "draw {i} differs from a fresh drawing");
    }
}

#[test]
fn sizes_outside_the_range_are_errors() {
    let s = scene(S2);
    assert!(matches!(render(&s, 15), Err(RenderError::Size(15))));
    assert!(matches!(render(&s, 4097), Err(RenderError::Size(4097))));
    assert!(render(&s, 16).is_ok());
}

#[test]
fn view_axes_choose_the_traced_body_axes() {
    let with_axes = |axes: &str| {
        format!(
            r#"{{"space":"S3","method":"squad","points":[[1,0,0,0],[0.7071,0.7071,0,0],[0,0,1,0]],
                "view":{{"plot":"none"{axes}}}}}"#
        )
    };
    let draw = |axes: &str| {
        render(&scene(&with_axes(axes)), 160)
            .expect("renders")
            .take()
    };
    let all = draw("");
    assert!(
        all == draw(r#","axes":["x","y","z"]"#),
        "default: all three"
    );
    let (x, z) = (draw(r#","axes":["x"]"#), draw(r#","axes":["z"]"#));
    assert!(
        x != all && z != all && x != z,
        "each choice draws other trajectories"
    );
    for (axes, message) in [
        (r#","axes":[]"#, "view.axes: must be a list of body axes"),
        (r#","axes":["w"]"#, "view.axes: must be a list of body axes"),
        (r#","axes":"x""#, "view.axes: must be a list of body axes"),
    ] {
        // The view is checked with the scene, before anything is drawn.
        let text = with_axes(axes);
        let err = Scene::from_json(&text).expect_err(axes).to_string();
        assert!(err.contains(message), "{axes}: {err}");
    }
    let s2 =
        r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]],"view":{"axes":["x"]}}"#;
    let err = Scene::from_json(s2).expect_err("S2").to_string();
    assert!(
        err.contains("view.axes: body axes are drawn for S3 scenes only"),
        "{err}"
    );
}

#[test]
fn a_prepared_figure_renders_the_pixels_of_a_fresh_one_for_every_camera() {
    // Laid out once (at the scene's camera), rendered for other cameras: the same pixels and
    // plot axes as laying the figure out for each camera.
    for text in [S2, S3] {
        let base = scene(text);
        let curves = base.build().expect("builds");
        let prepared = spherekit_render::prepare(&base, &curves, 200).expect("lays out");
        for (yaw, pitch) in [(0.0, 0.0), (35.0, 20.0), (200.0, -70.0), (90.0, 89.0)] {
            let mut v: serde_json::Value = serde_json::from_str(text).expect("JSON");
            v["view"]["camera"] = serde_json::json!({ "yaw": yaw, "pitch": pitch });
            let turned = scene(&v.to_string());
            let (pixmap, axes) = prepared.render(&turned, &curves).expect("renders");
            let (fresh, fresh_axes) =
                spherekit_render::render_figure(&turned, &curves, 200).expect("renders");
            assert!(
                pixmap.data() == fresh.data(),
                "{text} at yaw {yaw}, pitch {pitch}: the prepared figure's pixels differ"
            );
            assert_eq!(axes, fresh_axes, "the same plot axes");
            assert_eq!(axes.len(), 1, "one plot strip");
            let a = axes[0];
            assert!(
                a.left < a.right && a.top < a.bottom && a.top > 200.0,
                "{a:?}"
            );
        }
    }
}

#[test]
fn plot_axes_span_the_time_axis() {
    let s = scene(
        r#"{"space":"S2","method":"geodesic","knots":[0,2,5],
        "points":[[1,0,0],[0,1,0],[0,0,1]],"view":{"plot":"omega"}}"#,
    );
    let curves = s.build().expect("builds");
    let (_, axes) = spherekit_render::render_figure(&s, &curves, 300).expect("renders");
    assert_eq!(axes.len(), 2, "speed and components");
    for a in &axes {
        assert_eq!(a.time, [0.0, 5.0], "t from the first to the last knot");
    }
    assert!(axes[0].bottom < axes[1].top, "top to bottom");
    let none = scene(r#"{"space":"S2","method":"geodesic","points":[[1,0,0],[0,1,0]]}"#);
    let curves = none.build().expect("builds");
    let (_, axes) = spherekit_render::render_figure(&none, &curves, 100).expect("renders");
    assert!(axes.is_empty(), "no plot, no axes");
}
