// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The scene crate's integration tests, one binary.

#![allow(
    clippy::unwrap_used,
    clippy::missing_assert_message,
    reason = "tests: a panic is the failure report"
)]

mod batch;
mod closed;
mod corner_params;
mod edit;
mod fit;
mod hermite;
mod names;
mod registry;
mod scene_sample;
#[path = "../support/cases.rs"]
mod support_cases;
mod timing;

mod support {
    pub(crate) use super::support_cases as cases;
}
