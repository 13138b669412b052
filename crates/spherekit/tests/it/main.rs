// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The integration tests of `spherekit`, one module per subject, linked as one test binary
//! (one link instead of one per file). `tests/batch_alloc.rs` stays a binary of its own: it
//! has `harness = false` and a counting global allocator.

mod support;

mod batch;
mod beta_spline;
mod bezier;
mod catmull_rom;
mod classic_stress;
mod continuity;
mod cubic;
mod gamma_spline;
mod geodesic;
mod kim;
mod long_sequences;
mod manifold;
mod pobegailo_misprints;
mod pobegailo_s2;
mod pobegailo_s3;
mod rotation;
mod squad;
