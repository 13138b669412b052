// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Native side of spherekit's rendering: PNG files for the `spherekit render` command and the
//! golden-image harness ([`golden`]).

pub mod golden;

pub use spherekit_render::png::{decode_png, encode_png};
