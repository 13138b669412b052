// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Embeds the golden scenes (`tests/golden/*.json`) as the playground's presets.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let golden = manifest.join("../../tests/golden");
    println!("cargo::rerun-if-changed={}", golden.display());
    let mut names: Vec<String> = std::fs::read_dir(&golden)
        .map(|dir| {
            dir.filter_map(Result::ok)
                .filter_map(|e| e.file_name().into_string().ok())
                .filter(|n| n.ends_with(".json"))
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    let mut code = String::from(
        "/// The golden scenes: (name, JSON text).\npub(crate) const PRESETS: &[(&str, &str)] = &[\n",
    );
    for n in &names {
        let path = golden.join(n);
        let _ = writeln!(
            code,
            "    ({:?}, include_str!({:?})),",
            n.trim_end_matches(".json"),
            path.display().to_string()
        );
    }
    code.push_str("];\n");
    let out = PathBuf::from(std::env::var_os("OUT_DIR").unwrap_or_default()).join("presets.rs");
    if let Err(e) = std::fs::write(&out, code) {
        println!("cargo::error=cannot write {}: {e}", out.display());
    }
}
