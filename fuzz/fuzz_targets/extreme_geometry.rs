// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Structured, valid-but-extreme geometry (repeated, nearly repeated, antipodal and
//! near-antipodal points, great circles, 1e±300 scaling, knot spacings 1e-6 … 1e6, extreme
//! shape parameters, parameters far outside the domain), built from the fuzzer's bytes with
//! `arbitrary` by the generator the stable property tests share.

#![no_main]

use libfuzzer_sys::fuzz_target;

use arbitrary as arb;
#[path = "../../crates/spherekit-cli/tests/support/robust.rs"]
mod robust;

fuzz_target!(|data: &[u8]| {
    let mut u = arbitrary::Unstructured::new(data);
    let Ok(scene) = robust::extreme_scene(&mut u) else {
        return;
    };
    let text = scene.to_string();
    if let Err(e) = robust::check_scene_capped(&text, Some(16), 64) {
        panic!("{e}\nscene: {text}");
    }
});
