// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! PNG files of the renderer's pixmaps (feature `png`): the one encoder of `spherekit render`,
//! the golden-image tests and the Python module's `render_png`, so that they write the same
//! bytes for the same pixels.

use tiny_skia::Pixmap;

/// Encodes a pixmap as a compact PNG: RGB when every pixel is opaque (the renderer's images
/// are), RGBA otherwise, with the strongest deflate setting of the `png` crate and whichever
/// of its row filter strategies gives the smallest file.
///
/// # Errors
///
/// The encoder's error (it only fails on I/O, which a `Vec` does not have).
pub fn encode_png(pixmap: &Pixmap) -> Result<Vec<u8>, png::EncodingError> {
    let rgba = pixmap.clone().take_demultiplied();
    let opaque = rgba.chunks_exact(4).all(|p| p[3] == 0xff);
    let (data, color) = if opaque {
        let rgb: Vec<u8> = rgba
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        (rgb, png::ColorType::Rgb)
    } else {
        (rgba, png::ColorType::Rgba)
    };
    let mut best: Option<Vec<u8>> = None;
    for filter in [
        png::Filter::Adaptive,
        png::Filter::MinEntropy,
        png::Filter::Paeth,
        png::Filter::Sub,
        png::Filter::Up,
    ] {
        let mut out = Vec::new();
        {
            let mut encoder = png::Encoder::new(&mut out, pixmap.width(), pixmap.height());
            encoder.set_color(color);
            encoder.set_depth(png::BitDepth::Eight);
            encoder.set_compression(png::Compression::High);
            encoder.set_filter(filter);
            let mut writer = encoder.write_header()?;
            writer.write_image_data(&data)?;
        }
        if best.as_ref().is_none_or(|b| out.len() < b.len()) {
            best = Some(out);
        }
    }
    Ok(best.unwrap_or_default())
}

/// Decodes a PNG (8-bit RGB or RGBA) into a pixmap.
///
/// # Errors
///
/// A message naming what is wrong with the data.
pub fn decode_png(bytes: &[u8]) -> Result<Pixmap, String> {
    Pixmap::decode_png(bytes).map_err(|e| e.to_string())
}
