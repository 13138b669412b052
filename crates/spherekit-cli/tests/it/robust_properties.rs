// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Property tests over the fuzz targets' generators, with a fixed budget, so that stable CI
//! catches regressions without nightly or libFuzzer (see ROBUSTNESS.md). A failure prints the
//! arbtest seed; rerun it with `.seed(0x…)`.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

use std::sync::atomic::{AtomicUsize, Ordering};

use crate::robust::{Outcome, check_scene_capped, extreme_scene};

/// Prints how many cases a property ran and how many built (visible with `--nocapture`).
fn report(name: &str, cases: &AtomicUsize, built: &AtomicUsize) {
    eprintln!(
        "{name}: {} cases, {} built, the rest rejected with one line",
        cases.load(Ordering::Relaxed),
        built.load(Ordering::Relaxed)
    );
}

/// Milliseconds per property (two properties: about 3 s in all); `SPHEREKIT_PROPTEST_MS`
/// overrides it for a longer soak (`SPHEREKIT_PROPTEST_MS=300000 cargo test --release …`).
fn budget_ms() -> u64 {
    std::env::var("SPHEREKIT_PROPTEST_MS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1500)
}

/// Valid-but-extreme geometry: every scene either builds with finite unit results everywhere
/// (including parameters far outside the domain) or is rejected with one line.
#[test]
fn extreme_geometry_is_finite_or_rejected() {
    let (cases, built) = (AtomicUsize::new(0), AtomicUsize::new(0));
    arbtest::arbtest(|u| {
        let scene = extreme_scene(u)?;
        let text = scene.to_string();
        cases.fetch_add(1, Ordering::Relaxed);
        match check_scene_capped(&text, Some(16), 64) {
            Ok(Outcome::Ok) => _ = built.fetch_add(1, Ordering::Relaxed),
            Ok(Outcome::Rejected(_)) => {}
            Err(e) => panic!("{e}\nscene: {text}"),
        }
        Ok(())
    })
    .budget_ms(budget_ms())
    .run();
    report("extreme geometry", &cases, &built);
}

/// Arbitrary scene text: a mutated valid scene (bytes replaced, cut or spliced) never panics,
/// and every rejection is one line.
#[test]
fn mutated_scene_text_never_panics() {
    const SEEDS: [&str; 3] = [
        r#"{"space":"S2","method":"beta","points":[[1,0,0],[0,1,0],[0,0,1],[1,1,1]],"params":{"beta1":2,"beta2":3},"samples":9}"#,
        r#"{"space":"S3","method":"gamma","points":[[1,0,0,0],[0.9,0.1,0,0],[0.8,0.2,0.1,0],[0.7,0.3,0.2,0.1]],"knots":[0,1],"eval_at":[-1,0.5,9]}"#,
        r#"{"space":"S2","curves":[{"method":"corner-blend","points":[[1,0,0],[0,1,0],[0,0,1]],"params":{"order":3,"fraction":0.5}},{"method":"arc-blend","points":[[1,0,0],[0,1,0],[0,0,1]]}],"samples":5}"#,
    ];
    const TOKENS: [&str; 12] = [
        "0", "-1", "1e-9", "1e300", "[", "]", ",", "{", "}", "\"", "null", "[1,0,0]",
    ];
    let (cases, built) = (AtomicUsize::new(0), AtomicUsize::new(0));
    arbtest::arbtest(|u| {
        let mut text = (*u.choose(&SEEDS)?).to_owned();
        for _ in 0..u.int_in_range(1_u8..=4)? {
            let at = u.int_in_range(0..=text.len())?;
            let at = (0..=at).rev().find(|&i| text.is_char_boundary(i)).unwrap();
            match u.int_in_range(0_u8..=2)? {
                0 => text.insert_str(at, u.choose(&TOKENS)?),
                1 => text.truncate(at),
                _ => {
                    let end = u.int_in_range(at..=text.len())?;
                    let end = (end..=text.len())
                        .find(|&i| text.is_char_boundary(i))
                        .unwrap();
                    text.replace_range(at..end, "");
                }
            }
        }
        cases.fetch_add(1, Ordering::Relaxed);
        match check_scene_capped(&text, Some(16), 64) {
            Ok(Outcome::Ok) => _ = built.fetch_add(1, Ordering::Relaxed),
            Ok(Outcome::Rejected(_)) => {}
            Err(e) => panic!("{e}\nscene: {text}"),
        }
        Ok(())
    })
    .budget_ms(budget_ms())
    .run();
    report("mutated scene text", &cases, &built);
}
