// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Curves built in code and drawn without a scene ([`Drawing`]) are the figure of the scene that
//! describes them, pixel for pixel; a drawing of nothing or of two spheres is an error.

use spherekit::glam::DVec3;
use spherekit::{CubicEnd, CubicSpline, S2Point, Squad, UnitQuat};
use spherekit_render::{Drawing, RenderError, render, render_svg};
use spherekit_scene::Scene;

fn p(x: f64, y: f64, z: f64) -> S2Point {
    S2Point::try_new(DVec3::new(x, y, z)).expect("a point")
}

#[test]
fn a_drawing_is_the_figure_of_its_scene() {
    let keys = vec![
        p(1.0, 0.0, 0.2),
        p(0.3, 1.0, 0.4),
        p(-0.6, 0.5, 0.9),
        p(-1.0, -0.4, 0.3),
    ];
    let knots = vec![0.0, 1.0, 2.5, 3.0];
    let curve = CubicSpline::try_new(keys.clone(), Some(knots), CubicEnd::Natural, false)
        .expect("a spline");
    let drawing = Drawing::new().curve(curve, keys.clone(), Vec::new(), "cubic");
    let coords: Vec<[f64; 3]> = keys.iter().map(|k| k.as_dvec3().to_array()).collect();
    let text =
        format!(r#"{{"space":"S2","method":"cubic","points":{coords:?},"knots":[0,1,2.5,3]}}"#);
    let scene = Scene::from_json(&text).expect("a scene");
    let (a, b) = (
        drawing.render(200).expect("draws"),
        render(&scene, 200).expect("renders"),
    );
    assert!(a.data() == b.data(), "the same pixels");
    assert_eq!(
        drawing.render_svg(200).expect("an SVG"),
        render_svg(&scene, 200).expect("an SVG")
    );
}

#[test]
fn rotations_draw_with_their_label_and_controls() {
    let keys: Vec<UnitQuat> = (0..4)
        .map(|k| {
            UnitQuat::from_axis_angle(DVec3::new(1.0, 0.5, f64::from(k)), 0.6 * f64::from(k))
                .expect("a key")
        })
        .collect();
    let squad = Squad::try_new(keys.clone(), None).expect("squad");
    let controls = squad.controls().to_vec();
    let drawing = Drawing::new()
        .curve(squad, keys, controls, "my squad")
        .color([200, 30, 30]);
    let svg = drawing.render_svg(240).expect("an SVG");
    assert!(svg.contains("my squad"), "the label in the legend");
    assert!(svg.contains("#c81e1e"), "drawn in its colour");
    let bare = Drawing::new().curve(
        Squad::try_new(
            vec![
                UnitQuat::IDENTITY,
                UnitQuat::from_axis_angle(DVec3::Z, 1.0).expect("a key"),
            ],
            None,
        )
        .expect("squad"),
        Vec::new(),
        Vec::new(),
        "bare",
    );
    assert!(drawing.render(240).expect("draws").data() != bare.render(240).expect("draws").data());
}

#[test]
fn nothing_or_two_spheres_is_an_error() {
    let e = Drawing::new().render(100).expect_err("empty");
    assert!(matches!(e, RenderError::Drawing(_)), "{e}");
    let on_s2 = CubicSpline::try_new(
        vec![p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
        None,
        CubicEnd::Natural,
        false,
    )
    .expect("a spline");
    let on_s3 = Squad::try_new(
        vec![
            UnitQuat::IDENTITY,
            UnitQuat::from_axis_angle(DVec3::Z, 1.0).expect("a key"),
        ],
        None,
    )
    .expect("squad");
    let e = Drawing::new()
        .curve(on_s2, Vec::new(), Vec::new(), "a")
        .curve(on_s3, Vec::new(), Vec::new(), "b")
        .render(100)
        .expect_err("two spheres");
    assert_eq!(
        e.to_string(),
        "curve 1 is on S3, curve 0 on S2: one drawing is on one sphere"
    );
}

#[test]
fn the_omega_plot_names_its_frame_and_curves_are_named_by_method() {
    let text = |frame: &str| {
        format!(
            r#"{{"space":"S3","curves":[{{"method":"squad","points":[[1,0,0,0],[0.9,0.3,0.3,0],[0.7,0,0.7,0],[0.5,0.5,0.5,0.5]]}},
            {{"method":"catmull-rom","points":[[1,0,0,0],[0.9,0.3,0.3,0],[0.7,0,0.7,0],[0.5,0.5,0.5,0.5]]}}],
            "view":{{"plot":"omega"{frame}}}}}"#
        )
    };
    let space = render_svg(&Scene::from_json(&text("")).expect("scene"), 300).expect("SVG");
    let body = render_svg(
        &Scene::from_json(&text(r#","omega_frame":"body""#)).expect("scene"),
        300,
    )
    .expect("SVG");
    assert!(space.contains("angular velocity ω, space frame"), "{space}");
    assert!(body.contains("angular velocity ω, body frame"), "{body}");
    assert!(
        space.contains(">Squad<") && space.contains(">Catmull–Rom<"),
        "the legend names the methods: {space}"
    );
}
