// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Arbitrary bytes as a scene: parsing, curve construction, evaluation at the scene's (at most 64) and at
//! extreme parameters, sampling to JSON, rendering at 16 px. Any panic, non-finite or non-unit
//! result, or multi-line error message is a crash.

#![no_main]

use libfuzzer_sys::fuzz_target;

use arbitrary as arb;
#[path = "../../crates/spherekit-cli/tests/support/robust.rs"]
mod robust;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Err(e) = robust::check_scene_capped(text, Some(16), 64) {
        panic!("{e}\nscene: {text}");
    }
});
