// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Golden images: every scene in `tests/golden/` renders to exactly its reference PNG.
//! See `spherekit_cli::golden` for re-blessing.

use spherekit_cli::golden::{check, check_svg, golden_dir, scene_names, svg_names};

#[test]
fn every_golden_scene_matches_its_reference() {
    let names = scene_names().unwrap_or_default();
    assert!(
        !names.is_empty(),
        "no golden scenes found in {}",
        golden_dir().display()
    );
    let failures: Vec<String> = names
        .iter()
        .filter_map(|n| check(n).err().map(|e| e.to_string()))
        .collect();
    assert!(
        failures.is_empty(),
        "{} of {} golden scenes failed:\n{}",
        failures.len(),
        names.len(),
        failures.join("\n")
    );
}

#[test]
fn every_reference_has_a_scene() {
    let names = scene_names().unwrap_or_default();
    let entries =
        std::fs::read_dir(golden_dir()).map(|d| d.filter_map(Result::ok).collect::<Vec<_>>());
    for entry in entries.unwrap_or_default() {
        let file = entry.file_name().to_string_lossy().into_owned();
        if let Some(stem) = file.strip_suffix(".png") {
            if stem.contains('.') || stem == "contact-sheet" {
                continue;
            }
            assert!(
                names.iter().any(|n| n == stem),
                "{file} has no scene {stem}.json"
            );
        }
    }
}

#[test]
fn every_svg_golden_matches_its_reference_text() {
    let names = svg_names().unwrap_or_default();
    assert!(!names.is_empty(), "no SVG goldens in tests/golden/svg");
    let failures: Vec<String> = names
        .iter()
        .filter_map(|n| check_svg(n).err().map(|e| e.to_string()))
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
