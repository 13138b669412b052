// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The integration tests of the `spherekit` tool, one module per subject, linked as one test
//! binary: run one subject with a name filter, e.g. `cargo test -p spherekit-cli --test it
//! golden`.

// `tests/support/robust.rs` is shared with the cargo-fuzz targets (`fuzz/fuzz_targets/`),
// which include it by path too; it reaches `arbitrary` through its parent as `super::arb`.
use arbtest::arbitrary as arb;
#[path = "../support/robust.rs"]
mod robust;

mod cli;
mod golden;
mod robust_properties;
mod robustness;
mod timing;
