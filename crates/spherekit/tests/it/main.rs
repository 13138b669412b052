// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The integration tests of `spherekit`, one module per subject, linked as one test binary
//! (one link instead of one per file). The batch-evaluation and allocation checks of every
//! method live with the registry, in `crates/spherekit-scene/tests/`.

mod support;

mod arclength;
mod beta_spline;
mod bezier;
mod catmull_rom;
mod catmull_rom_nlerp;
mod classic_stress;
mod closed;
mod continuity;
mod corner_general;
mod cubic;
mod extrapolate;
mod fit;
mod gamma_spline;
mod geodesic;
mod hermite;
mod hostile_inputs;
mod kim;
mod long_sequences;
mod manifold;
mod pobegailo_foundations;
mod pobegailo_misprints;
mod pobegailo_s2;
mod pobegailo_s3;
mod rotation;
mod rotation_loop;
mod source_claims;
mod squad;
