// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! A fitted curve's figure: its samples and fitted keys marked apart, named in the legend, and
//! the residual plot below the speed plot.

use spherekit_render::{render_figure, render_svg};
use spherekit_scene::Scene;

/// Eight samples along the equator (0.2 rad apart), a little off it, for times 0..7.
fn samples() -> Vec<String> {
    (0..8)
        .map(|i| {
            let a = f64::from(i) * 0.2;
            let z = if i % 2 == 0 { 0.02 } else { -0.02 };
            format!("[{}, {}, {z}]", a.cos(), a.sin())
        })
        .collect()
}

/// A single curve on the [`samples`] at times 0..7, with `extra` fields.
fn scene(extra: &str) -> Scene {
    let points = samples();
    let text = format!(
        r#"{{"space":"S2","method":"cubic","points":[{}],"knots":[0,1,2,3,4,5,6,7],
        "view":{{"plot":"speed","legend":true}}{extra}}}"#,
        points.join(",")
    );
    Scene::from_json(&text).expect("valid scene")
}

#[test]
fn a_fit_has_a_residual_plot_and_names_its_marks() {
    let fitted = scene(r#","fit":{"smoothing":0.5}"#);
    let curves = fitted.build().expect("builds");
    let (_, axes) = render_figure(&fitted, &curves, 300).expect("renders");
    assert_eq!(axes.len(), 2, "speed and residuals");
    assert_eq!(axes[1].time, [0.0, 7.0], "the samples' times");
    let svg = render_svg(&fitted, 300).expect("SVG");
    for text in [
        "residual angle per sample",
        "sample (fitted to)",
        "key (fitted)",
    ] {
        assert!(svg.contains(text), "{text} missing: {svg}");
    }

    let interpolating = scene("");
    let curves = interpolating.build().expect("builds");
    let (_, axes) = render_figure(&interpolating, &curves, 300).expect("renders");
    assert_eq!(axes.len(), 1, "speed only");
    let svg = render_svg(&interpolating, 300).expect("SVG");
    assert!(!svg.contains("sample") && svg.contains(">key<"), "{svg}");
}

#[test]
fn beside_a_curve_through_the_samples_keys_are_not_all_fitted() {
    let curve = |fit: &str| {
        format!(
            r#"{{"method":"cubic","points":[{}],"knots":[0,1,2,3,4,5,6,7]{fit}}}"#,
            samples().join(",")
        )
    };
    let text = format!(
        r#"{{"space":"S2","curves":[{},{}],"view":{{"plot":"speed","legend":true}}}}"#,
        curve(r#","fit":{"smoothing":0.5}"#),
        curve("")
    );
    let s = Scene::from_json(&text).expect("valid scene");
    let svg = render_svg(&s, 300).expect("SVG");
    assert!(
        svg.contains(">key<") && svg.contains("sample (fitted to)"),
        "{svg}"
    );
    assert!(!svg.contains("key (fitted)"), "{svg}");
}

#[test]
fn residuals_are_not_plotted_on_an_arc_length_axis() {
    // The curve runs over [0, L]; the samples' times are the fit's, not on that axis.
    let s = scene(r#","fit":{"smoothing":0.5},"parametrization":"arclength""#);
    let curves = s.build().expect("builds");
    let (_, axes) = render_figure(&s, &curves, 300).expect("renders");
    assert_eq!(axes.len(), 1, "speed only");
    let svg = render_svg(&s, 300).expect("SVG");
    assert!(
        svg.contains("sample (fitted to)"),
        "the samples are still drawn"
    );
}

#[test]
fn no_plot_means_no_residual_plot() {
    let text = r#"{"space":"S2","method":"cubic","points":[[1,0,0.1],[0.8,0.6,-0.1],[0.3,0.9,0.1],[0,1,0]],
        "knots":[0,1,2,3],"fit":{"smoothing":0.1},"view":{"plot":"none"}}"#;
    let s = Scene::from_json(text).expect("valid scene");
    let curves = s.build().expect("builds");
    let (_, axes) = render_figure(&s, &curves, 200).expect("renders");
    assert!(axes.is_empty());
}
