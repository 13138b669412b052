// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The general corner-blend parameters: `fraction` (one number or one per corner),
//! `fraction_out`, `start`, `speed` and, on S², `bend`, mapped to the core's `CornerCuts`,
//! `CornerTiming` and small-circle legs, with errors that name the field.

use serde_json::Value;
use spherekit::glam::DVec3;
use spherekit::{CornerBlend, CornerCuts, CornerTiming, Curve, S2Point};
use spherekit_scene::Scene;

const POINTS: &str = "[[1,0,0.2],[0.3,1,0.5],[-0.5,0.3,1],[-1,-0.6,0.1],[-0.2,-1,-0.6]]";

fn points() -> Vec<S2Point> {
    [
        [1.0, 0.0, 0.2],
        [0.3, 1.0, 0.5],
        [-0.5, 0.3, 1.0],
        [-1.0, -0.6, 0.1],
        [-0.2, -1.0, -0.6],
    ]
    .iter()
    .map(|&p| S2Point::try_new(DVec3::from_array(p)).expect("point"))
    .collect()
}

/// The knots the scene reports in `info`.
fn knots(params: &str) -> Result<Vec<f64>, String> {
    let text = format!(
        r#"{{"space":"S2","method":"corner-blend","points":{POINTS},"params":{params},"samples":2}}"#
    );
    let scene = Scene::from_json(&text).map_err(|e| e.to_string())?;
    let curves = scene.build().map_err(|e| e.to_string())?;
    let json = scene.sample_json(&curves, false);
    Ok(json["info"]["knots"]
        .as_array()
        .expect("knots")
        .iter()
        .map(|k| Value::as_f64(k).expect("number"))
        .collect())
}

fn core(cuts: CornerCuts, timing: CornerTiming, bends: Option<&[f64]>) -> Vec<f64> {
    let c = match bends {
        None => CornerBlend::try_with(points(), 2, &cuts, timing),
        Some(b) => CornerBlend::try_with_arcs(points(), 2, &cuts, timing, b),
    }
    .expect("builds");
    assert_eq!(c.domain()[0], timing.start, "starts at the start");
    c.knots().to_vec()
}

#[test]
fn the_forms_of_the_cuts_and_the_timing_reach_the_core() {
    let t = CornerTiming::default();
    assert_eq!(knots("{}"), Ok(core(CornerCuts::Uniform(0.25), t, None)));
    assert_eq!(
        knots(r#"{"fraction":[0.1,0.45,0.3]}"#),
        Ok(core(CornerCuts::PerCorner(vec![0.1, 0.45, 0.3]), t, None))
    );
    assert_eq!(
        knots(r#"{"fraction":[0.1,0.45,0.3],"fraction_out":0.2}"#),
        Ok(core(
            CornerCuts::Pairs(vec![[0.1, 0.2], [0.45, 0.2], [0.3, 0.2]]),
            t,
            None
        ))
    );
    assert_eq!(
        knots(r#"{"fraction":0.3,"fraction_out":[0.5,0.1,0.6]}"#),
        Ok(core(
            CornerCuts::Pairs(vec![[0.3, 0.5], [0.3, 0.1], [0.3, 0.6]]),
            t,
            None
        ))
    );
    assert_eq!(
        knots(r#"{"fraction":0.3,"fraction_out":0.6}"#),
        Ok(core(CornerCuts::Pairs(vec![[0.3, 0.6]; 3]), t, None))
    );
    let timing = CornerTiming {
        start: -2.0,
        speed: 3.0,
    };
    assert_eq!(
        knots(r#"{"start":-2,"speed":3}"#),
        Ok(core(CornerCuts::Uniform(0.25), timing, None))
    );
    assert_eq!(
        knots(r#"{"bend":0.4}"#),
        Ok(core(CornerCuts::Uniform(0.25), t, Some(&[0.4; 4])))
    );
    assert_eq!(
        knots(r#"{"bend":[0.4,-0.2,0,0.9]}"#),
        Ok(core(
            CornerCuts::Uniform(0.25),
            t,
            Some(&[0.4, -0.2, 0.0, 0.9])
        ))
    );
}

#[test]
fn bad_corner_parameters_name_the_field() {
    let err = |params: &str| knots(params).expect_err("an error");
    assert_eq!(
        err(r#"{"fraction":[0.1,0.2],"fraction_out":[0.1,0.2,0.3]}"#),
        "params.fraction_out: has 3 entries but fraction has 2: one per corner each"
    );
    assert_eq!(
        err(r#"{"fraction":[0.1,0.2]}"#),
        "params.fraction: expected 3 entries (one per corner, the points 1 to 3), got 2"
    );
    assert!(
        err(r#"{"fraction":0.2,"fraction_out":[0.9,0.9,0.2]}"#).starts_with(
            "params.fraction: entries 0 and 1 overlap on the edge from point 1 to point 2"
        )
    );
    assert!(err(r#"{"speed":-1}"#).starts_with("params.speed: must be a positive number"));
    assert!(err(r#"{"fraction_out":"x"}"#).starts_with("params.fraction_out: must be a number"));
    assert_eq!(
        err(r#"{"bend":[0.1,0.2]}"#),
        "params.bend: expected 4 values (one per edge), got 2"
    );
    assert!(err(r#"{"bend":-1}"#).starts_with("params.bend: entry 0 (the edge from point 0)"));
    let s3 = r#"{"space":"S3","method":"corner-blend","points":[[1,0,0,0],[0,1,0,0],[0,0,1,0]],"params":{"bend":0.2}}"#;
    let e = Scene::from_json(s3)
        .and_then(|s| s.build().map(|_| ()))
        .expect_err("bend is S2 only");
    assert_eq!(
        e.to_string(),
        r#"params.bend: unknown parameter for method "corner-blend""#
    );
}
