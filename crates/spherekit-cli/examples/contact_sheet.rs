// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Writes `tests/golden/contact-sheet.png`: thumbnails of every golden reference, for review.
//! Run with `./run contact-sheet`.

use spherekit_cli::golden::{contact_sheet, golden_dir};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let sheet = contact_sheet(6, 128)?;
    let path = golden_dir().join("contact-sheet.png");
    std::fs::write(&path, spherekit_cli::encode_png(&sheet)?)?;
    println!("wrote {}", path.display());
    Ok(())
}
