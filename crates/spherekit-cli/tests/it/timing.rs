// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `spherekit sample` with the timing fields, on every registered method: each
//! `"extrapolate"` policy at `t0 − 1`, `t1 + 1`, `±1e300` and NaN (`--at`), and
//! `"parametrization": "arclength"` (the domain `[0, L]`, unit speed at the samples).

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use std::io::Write;
use std::process::{Command, Output, Stdio};

use serde_json::{Value, json};
use spherekit_scene::{METHODS, Spaces};

fn spherekit(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_spherekit"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    if let Err(e) = child.stdin.take().unwrap().write_all(stdin.as_bytes()) {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().unwrap()
}

/// `sample - --deriv [extra]`: the JSON, or the one error line (status 2, nothing on stdout).
fn sample(scene: &Value, extra: &[&str]) -> Result<Value, String> {
    let mut args = vec!["sample", "-", "--deriv"];
    args.extend_from_slice(extra);
    let out = spherekit(&args, &scene.to_string());
    if out.status.success() {
        return Ok(serde_json::from_slice(&out.stdout).unwrap());
    }
    assert_eq!(out.status.code(), Some(2), "{scene}");
    assert!(out.stdout.is_empty(), "no output on error");
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    Err(stderr.trim_end().trim_start_matches("error: ").to_owned())
}

fn scene(m: &spherekit_scene::Method, extra: &Value) -> Value {
    let (space, points) = if m.spaces == Spaces::S3 {
        (
            "S3",
            json!([
                [1, 0, 0, 0],
                [0.95, 0.3, 0, 0],
                [0.9, 0.3, 0.3, 0],
                [0.85, 0.3, 0.3, 0.3],
                [0.8, 0, 0.4, 0.4]
            ]),
        )
    } else {
        (
            "S2",
            json!([
                [1, 0, 0],
                [0.8, 0.6, 0],
                [0.6, 0.6, 0.5],
                [0.3, 0.6, 0.7],
                [0, 0.6, 0.8]
            ]),
        )
    };
    let mut s = json!({ "space": space, "method": m.id, "points": points });
    for (k, v) in extra.as_object().unwrap() {
        s[k] = v.clone();
    }
    s
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn norm(v: &Value) -> f64 {
    numbers(v).iter().map(|x| x * x).sum::<f64>().sqrt()
}

#[test]
fn every_policy_on_every_method_at_the_probe_parameters() {
    for m in METHODS {
        let mut policies = vec!["hold", "extend", "error"];
        if m.closes {
            policies.push("cycle");
        }
        if m.id == "cubic" {
            policies.push("segment");
        }
        for policy in policies {
            let mut extra = json!({ "extrapolate": policy });
            if policy == "cycle" {
                extra["closed"] = json!(true);
            }
            let s = scene(m, &extra);
            let domain = numbers(&sample(&s, &["--samples", "2"]).unwrap()["domain"]);
            let (t0, t1) = (domain[0], domain[1]);
            let probes = [(t0 - 1.0, t0), (t1 + 1.0, t1), (-1e300, t0), (1e300, t1)];
            for (t, end) in probes {
                let at = format!("{t:e},{end:e}");
                let out = sample(&s, &["--at", &at]);
                let far = t.abs() == 1e300;
                match (policy, out) {
                    ("error", Err(e)) => {
                        assert!(
                            e.starts_with("eval_at[0]: ") && e.contains("outside the domain"),
                            "{}: {e}",
                            m.id
                        );
                    }
                    ("segment", Err(e)) if far => assert!(e.contains("overflows"), "{e}"),
                    (_, Ok(out)) if policy != "error" => {
                        for k in ["points", "velocity", "acceleration"] {
                            assert!(
                                numbers(&out[k][0]).iter().all(|x| x.is_finite()),
                                "{} {policy} {t}: {k}",
                                m.id
                            );
                        }
                        assert!(
                            (norm(&out["points"][0]) - 1.0).abs() < 1e-12,
                            "{} on the sphere",
                            m.id
                        );
                        if policy == "hold" {
                            assert_eq!(
                                out["points"][0], out["points"][1],
                                "{} held at the end",
                                m.id
                            );
                            assert_eq!(norm(&out["velocity"][0]), 0.0, "{} at rest", m.id);
                        }
                        if policy == "extend" && !far {
                            // Constant speed: the end's.
                            let (a, b) = (norm(&out["velocity"][0]), norm(&out["velocity"][1]));
                            assert!((a - b).abs() <= 1e-12 * b.max(1.0), "{} {a} vs {b}", m.id);
                        }
                    }
                    (_, out) => panic!("{} {policy} at {t}: {out:?}", m.id),
                }
            }
            let e = sample(&s, &["--at", "0,nan"]).unwrap_err();
            assert_eq!(
                e, "eval_at[1]: NaN is not a finite number",
                "{} {policy}",
                m.id
            );
            let e = sample(&s, &["--at", "-inf"]).unwrap_err();
            assert_eq!(
                e, "eval_at[0]: -inf is not a finite number",
                "{} {policy}",
                m.id
            );
        }
    }
}

#[test]
fn arclength_on_every_method_samples_over_its_length_at_unit_speed() {
    for m in METHODS {
        let s = scene(m, &json!({ "parametrization": "arclength", "samples": 17 }));
        let out = sample(&s, &[]).unwrap();
        let length = out["info"]["arclength"]["length"].as_f64().unwrap();
        assert_eq!(out["domain"], json!([0.0, length]), "{}", m.id);
        let t = numbers(&out["t"]);
        for (k, w) in t.windows(2).enumerate() {
            assert!(
                (w[1] - w[0] - length / 16.0).abs() < 1e-12 * length,
                "{} step {k}",
                m.id
            );
        }
        // |ω| = 1 on S³, |c′| = 1 elsewhere.
        let field = if m.spaces == Spaces::S3 {
            "angular_velocity"
        } else {
            "velocity"
        };
        for v in out[field].as_array().unwrap() {
            assert!((norm(v) - 1.0).abs() < 1e-9, "{}: speed {}", m.id, norm(v));
        }
    }
}

#[test]
fn sample_options_are_checked() {
    let s = json!({ "space": "S2", "method": "geodesic", "points": [[1, 0, 0], [0, 1, 0]] });
    assert_eq!(
        sample(&s, &["--at", "0,x"]).unwrap_err(),
        "--at: \"x\" is not a number"
    );
    assert_eq!(
        sample(&s, &["--at", "0", "--samples", "3"]).unwrap_err(),
        "give either --samples or --at, not both"
    );
    let out = sample(&s, &["--at", "0.5,2"]).unwrap();
    assert_eq!(out["t"], json!([0.5, 2.0]));
    let help = String::from_utf8(spherekit(&["help"], "").stdout).unwrap();
    assert!(
        help.contains("--at T,…") && help.contains("\"arclength\""),
        "{help}"
    );
}
