// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The golden-image harness: renders each scene of `tests/golden/` and compares it with its
//! committed reference PNG.
//!
//! - A mismatch writes `NAME.new.png` (the new rendering) and `NAME.diff.png` (expected | red
//!   mask of differing pixels | actual) beside the reference, and the error gives the number of
//!   differing pixels at several per-channel thresholds and the command that re-blesses.
//! - `UPDATE_GOLDENS=1` re-blesses failing or missing references, `UPDATE_GOLDENS=force` rewrites
//!   all, and `UPDATE_GOLDENS=a,b` the named ones; the previous reference is kept as
//!   `NAME.old.png`. Blessing is refused when `CI` is set.
//! - Every reference must stay under [`MAX_PNG_BYTES`].

use std::fmt;
use std::path::{Path, PathBuf};

use spherekit_scene::Scene;
use tiny_skia::{Color, FilterQuality, Pixmap, PixmapPaint, Transform};

use crate::{decode_png, encode_png};

/// The size golden scenes are rendered at (the sphere's square, in pixels). 384 px keeps every
/// reference under [`MAX_PNG_BYTES`] while curves and points stay crisp.
pub const GOLDEN_SIZE: u32 = 384;

/// The largest a committed reference PNG may be.
pub const MAX_PNG_BYTES: usize = 64 * 1024;

/// How far a pixel may differ per channel and still count as equal.
pub const PER_CHANNEL: u8 = 0;

/// How many pixels may differ beyond [`PER_CHANNEL`]. Raising it hides real changes: prefer
/// re-blessing after checking the diff image.
pub const MAX_FAILED_PIXELS: usize = 0;

const SWEEP: [u8; 7] = [0, 1, 2, 4, 8, 16, 32];

/// Why a golden check failed.
#[derive(Debug)]
pub enum GoldenError {
    /// The scene file could not be read or is not a valid scene.
    Scene {
        /// Scene name.
        name: String,
        /// What is wrong.
        message: String,
    },
    /// There is no reference image.
    Missing {
        /// Where it should be.
        path: PathBuf,
    },
    /// The rendering differs from the reference.
    Mismatch {
        /// Scene name.
        name: String,
        /// `(threshold, differing pixels)` for a sweep of per-channel thresholds.
        sweep: Vec<(u8, usize)>,
        /// Where the diff image was written.
        diff: PathBuf,
    },
    /// The reference has a different size from the rendering.
    SizeMismatch {
        /// Scene name.
        name: String,
        /// Reference size.
        expected: (u32, u32),
        /// Rendered size.
        actual: (u32, u32),
    },
    /// The reference PNG is larger than [`MAX_PNG_BYTES`].
    TooLarge {
        /// Scene name.
        name: String,
        /// Its size in bytes.
        bytes: usize,
    },
    /// `UPDATE_GOLDENS` is set in CI.
    BlessInCi,
    /// Reading or writing a file failed.
    Io(String),
}

fn bless_command(name: &str) -> String {
    format!(
        "UPDATE_GOLDENS={name} cargo test -p spherekit-cli --test it golden:: (or `./run bless`)"
    )
}

impl fmt::Display for GoldenError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Scene { name, message } => write!(f, "{name}: bad scene: {message}"),
            Self::Missing { path } => write!(
                f,
                "{}: no reference image; look at the .new.png beside it, then create it with {}",
                path.display(),
                bless_command(&stem(path))
            ),
            Self::Mismatch { name, sweep, diff } => {
                let counts: Vec<String> = sweep.iter().map(|(t, n)| format!(">{t}: {n}")).collect();
                write!(
                    f,
                    "{name}: rendering differs from the reference (pixels differing per channel {}); \
                     see {}; if the change is intended: {}",
                    counts.join(", "),
                    diff.display(),
                    bless_command(name)
                )
            }
            Self::SizeMismatch {
                name,
                expected,
                actual,
            } => write!(
                f,
                "{name}: reference is {}×{}, rendering is {}×{}; if intended: {}",
                expected.0,
                expected.1,
                actual.0,
                actual.1,
                bless_command(name)
            ),
            Self::TooLarge { name, bytes } => write!(
                f,
                "{name}: reference PNG is {bytes} bytes, over the {MAX_PNG_BYTES}-byte budget"
            ),
            Self::BlessInCi => {
                f.write_str("UPDATE_GOLDENS is set but CI is too: refusing to bless in CI")
            }
            Self::Io(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for GoldenError {}

fn stem(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// The golden directory, `tests/golden/` at the workspace root.
#[must_use]
pub fn golden_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/golden");
    dir.canonicalize().unwrap_or(dir)
}

/// The names of all golden scenes (the `*.json` files), sorted.
///
/// # Errors
///
/// [`GoldenError::Io`] if the directory cannot be read.
pub fn scene_names() -> Result<Vec<String>, GoldenError> {
    let dir = golden_dir();
    let entries = std::fs::read_dir(&dir)
        .map_err(|e| GoldenError::Io(format!("cannot read {}: {e}", dir.display())))?;
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| stem(&p))
        .collect();
    names.sort();
    Ok(names)
}

/// Renders the golden scene `name` at [`GOLDEN_SIZE`].
///
/// # Errors
///
/// [`GoldenError::Scene`] for a missing or bad scene.
pub fn render_scene(name: &str) -> Result<Pixmap, GoldenError> {
    render_scene_file(&golden_dir().join(format!("{name}.json")))
}

/// Renders the scene file at `path` at [`GOLDEN_SIZE`] (the error names it by its file stem).
///
/// # Errors
///
/// [`GoldenError::Scene`] for a missing or bad scene.
pub fn render_scene_file(path: &Path) -> Result<Pixmap, GoldenError> {
    let name = stem(path);
    let bad = |message: String| GoldenError::Scene {
        name: name.clone(),
        message,
    };
    let text =
        std::fs::read_to_string(path).map_err(|e| bad(format!("{}: {e}", path.display())))?;
    let scene = Scene::from_json(&text).map_err(|e| bad(e.to_string()))?;
    spherekit_render::render(&scene, GOLDEN_SIZE).map_err(|e| bad(e.to_string()))
}

/// How `check` treats a mismatch, from `UPDATE_GOLDENS`.
enum Mode {
    Test,
    UpdateFailing,
    UpdateAll,
    UpdateNamed(Vec<String>),
}

impl Mode {
    fn from_env() -> Self {
        match std::env::var("UPDATE_GOLDENS").as_deref() {
            Err(_) | Ok("" | "0") => Self::Test,
            Ok("1") => Self::UpdateFailing,
            Ok("force") => Self::UpdateAll,
            Ok(list) => Self::UpdateNamed(list.split(',').map(str::to_owned).collect()),
        }
    }

    fn blesses(&self, name: &str, failing: bool) -> bool {
        match self {
            Self::Test => false,
            Self::UpdateFailing => failing,
            Self::UpdateAll => true,
            Self::UpdateNamed(names) => names.iter().any(|n| n == name),
        }
    }
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), GoldenError> {
    std::fs::write(path, bytes)
        .map_err(|e| GoldenError::Io(format!("cannot write {}: {e}", path.display())))
}

fn bless(reference: &Path, png: &[u8]) -> Result<(), GoldenError> {
    if std::env::var_os("CI").is_some() {
        return Err(GoldenError::BlessInCi);
    }
    if png.len() > MAX_PNG_BYTES {
        return Err(GoldenError::TooLarge {
            name: stem(reference),
            bytes: png.len(),
        });
    }
    if reference.exists() {
        let old = reference.with_extension("old.png");
        std::fs::rename(reference, &old).map_err(|e| GoldenError::Io(e.to_string()))?;
    }
    write(reference, png)
}

/// Renders scene `name` and compares it with `tests/golden/NAME.png`.
///
/// # Errors
///
/// A [`GoldenError`] describing the failure and how to fix it.
pub fn check(name: &str) -> Result<(), GoldenError> {
    let mode = Mode::from_env();
    let dir = golden_dir();
    let reference = dir.join(format!("{name}.png"));
    let new_path = dir.join(format!("{name}.new.png"));
    let actual = render_scene(name)?;
    let png = encode_png(&actual).map_err(|e| GoldenError::Io(e.to_string()))?;
    let Ok(bytes) = std::fs::read(&reference) else {
        if mode.blesses(name, true) {
            return bless(&reference, &png);
        }
        write(&new_path, &png)?;
        return Err(GoldenError::Missing { path: reference });
    };
    let expected =
        decode_png(&bytes).map_err(|e| GoldenError::Io(format!("{}: {e}", reference.display())))?;
    if (expected.width(), expected.height()) != (actual.width(), actual.height()) {
        if mode.blesses(name, true) {
            return bless(&reference, &png);
        }
        write(&new_path, &png)?;
        return Err(GoldenError::SizeMismatch {
            name: name.to_owned(),
            expected: (expected.width(), expected.height()),
            actual: (actual.width(), actual.height()),
        });
    }
    let sweep: Vec<(u8, usize)> = SWEEP
        .iter()
        .map(|&t| (t, count_diff(&expected, &actual, t)))
        .collect();
    let failed = count_diff(&expected, &actual, PER_CHANNEL) > MAX_FAILED_PIXELS;
    if mode.blesses(name, failed) {
        return bless(&reference, &png);
    }
    if failed {
        write(&new_path, &png)?;
        let diff = dir.join(format!("{name}.diff.png"));
        let image = diff_image(&expected, &actual);
        write(
            &diff,
            &encode_png(&image).map_err(|e| GoldenError::Io(e.to_string()))?,
        )?;
        return Err(GoldenError::Mismatch {
            name: name.to_owned(),
            sweep,
            diff,
        });
    }
    if bytes.len() > MAX_PNG_BYTES {
        return Err(GoldenError::TooLarge {
            name: name.to_owned(),
            bytes: bytes.len(),
        });
    }
    Ok(())
}

fn rgba(p: &Pixmap) -> Vec<u8> {
    p.clone().take_demultiplied()
}

/// Pixels where some channel differs by more than `threshold` (pixels transparent in both
/// images are skipped).
fn count_diff(a: &Pixmap, b: &Pixmap, threshold: u8) -> usize {
    rgba(a)
        .chunks_exact(4)
        .zip(rgba(b).chunks_exact(4))
        .filter(|(x, y)| {
            !(x[3] == 0 && y[3] == 0)
                && x.iter()
                    .zip(y.iter())
                    .any(|(u, v)| u.abs_diff(*v) > threshold)
        })
        .count()
}

/// Three panels side by side: expected, a red mask of differing pixels, actual.
fn diff_image(expected: &Pixmap, actual: &Pixmap) -> Pixmap {
    let (w, h) = (expected.width(), expected.height());
    let mut out = Pixmap::new(3 * w, h)
        .unwrap_or_else(|| Pixmap::new(1, 1).unwrap_or_else(|| unreachable!()));
    out.fill(Color::WHITE);
    let paint = PixmapPaint::default();
    out.draw_pixmap(0, 0, expected.as_ref(), &paint, Transform::identity(), None);
    out.draw_pixmap(
        i32::try_from(2 * w).unwrap_or(0),
        0,
        actual.as_ref(),
        &paint,
        Transform::identity(),
        None,
    );
    let (e, a) = (rgba(expected), rgba(actual));
    let mut mask = Pixmap::new(w, h).unwrap_or_else(|| unreachable!());
    for (i, (x, y)) in e.chunks_exact(4).zip(a.chunks_exact(4)).enumerate() {
        let px = if x != y {
            [0xff, 0x00, 0x00, 0xff]
        } else {
            [0xf0, 0xf0, 0xf0, 0xff]
        };
        mask.data_mut()[4 * i..4 * i + 4].copy_from_slice(&px);
    }
    out.draw_pixmap(
        i32::try_from(w).unwrap_or(0),
        0,
        mask.as_ref(),
        &paint,
        Transform::identity(),
        None,
    );
    out
}

/// The SVG goldens: `tests/golden/svg/NAME.svg` is the SVG of scene `tests/golden/NAME.json`
/// at [`GOLDEN_SIZE`], compared as text. Their names, sorted.
///
/// # Errors
///
/// [`GoldenError::Io`] if the directory cannot be read.
pub fn svg_names() -> Result<Vec<String>, GoldenError> {
    let dir = golden_dir().join("svg");
    let entries = std::fs::read_dir(&dir)
        .map_err(|e| GoldenError::Io(format!("cannot read {}: {e}", dir.display())))?;
    let mut names: Vec<String> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.extension().is_some_and(|x| x == "svg") && !p.to_string_lossy().ends_with(".new.svg")
        })
        .map(|p| stem(&p))
        .collect();
    names.sort();
    Ok(names)
}

/// Renders scene `name` as SVG and compares it, as text, with `tests/golden/svg/NAME.svg`
/// (blessed like the PNGs, by `UPDATE_GOLDENS`; a mismatch writes `NAME.new.svg`).
///
/// # Errors
///
/// A [`GoldenError`] naming the first differing line.
pub fn check_svg(name: &str) -> Result<(), GoldenError> {
    let mode = Mode::from_env();
    let dir = golden_dir();
    let reference = dir.join("svg").join(format!("{name}.svg"));
    let new_path = dir.join("svg").join(format!("{name}.new.svg"));
    let text = std::fs::read_to_string(dir.join(format!("{name}.json")))
        .map_err(|e| GoldenError::Io(format!("{name}.json: {e}")))?;
    let scene = Scene::from_json(&text).map_err(|e| GoldenError::Scene {
        name: name.to_owned(),
        message: e.to_string(),
    })?;
    let actual =
        spherekit_render::render_svg(&scene, GOLDEN_SIZE).map_err(|e| GoldenError::Scene {
            name: name.to_owned(),
            message: e.to_string(),
        })?;
    let expected = std::fs::read_to_string(&reference).unwrap_or_default();
    let failed = expected != actual;
    if mode.blesses(name, failed) {
        if std::env::var_os("CI").is_some() {
            return Err(GoldenError::BlessInCi);
        }
        return write(&reference, actual.as_bytes());
    }
    if failed {
        write(&new_path, actual.as_bytes())?;
        let line = expected
            .lines()
            .zip(actual.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| expected.lines().count().min(actual.lines().count()));
        return Err(GoldenError::Io(format!(
            "svg/{name}.svg: the SVG differs from line {} on; see {}; if intended: {}",
            line + 1,
            new_path.display(),
            bless_command(name)
        )));
    }
    Ok(())
}

/// One PNG of thumbnails of every golden reference, `columns` across, each `thumb` pixels wide.
///
/// # Errors
///
/// [`GoldenError::Io`] if a reference cannot be read.
pub fn contact_sheet(columns: u32, thumb: u32) -> Result<Pixmap, GoldenError> {
    let names = scene_names()?;
    let images: Vec<Pixmap> = names
        .iter()
        .map(|n| {
            let path = golden_dir().join(format!("{n}.png"));
            let bytes = std::fs::read(&path)
                .map_err(|e| GoldenError::Io(format!("{}: {e}", path.display())))?;
            decode_png(&bytes).map_err(GoldenError::Io)
        })
        .collect::<Result<_, _>>()?;
    let count = u32::try_from(images.len()).unwrap_or(u32::MAX).max(1);
    let rows = count.div_ceil(columns);
    let gap = 6;
    // As tall as the tallest thumbnail (figures with plots and legends are taller than wide).
    let cell_h = images
        .iter()
        .map(|img| {
            (u64::from(img.height()) * u64::from(thumb)).div_ceil(u64::from(img.width().max(1)))
        })
        .max()
        .map_or(thumb, |h| u32::try_from(h).unwrap_or(thumb));
    let mut sheet = Pixmap::new(columns * (thumb + gap) + gap, rows * (cell_h + gap) + gap)
        .ok_or_else(|| GoldenError::Io("contact sheet too large".into()))?;
    sheet.fill(Color::WHITE);
    let paint = PixmapPaint {
        quality: FilterQuality::Bicubic,
        ..PixmapPaint::default()
    };
    for (i, img) in images.iter().enumerate() {
        let i = u32::try_from(i).unwrap_or(0);
        let (col, row) = (i % columns, i / columns);
        #[expect(clippy::cast_precision_loss, reason = "pixel sizes")]
        let s = thumb as f32 / img.width() as f32;
        let x = i32::try_from(gap + col * (thumb + gap)).unwrap_or(0);
        let y = i32::try_from(gap + row * (cell_h + gap)).unwrap_or(0);
        #[expect(clippy::cast_precision_loss, reason = "pixel offsets")]
        let t = Transform::from_row(s, 0.0, 0.0, s, x as f32, y as f32);
        sheet.draw_pixmap(0, 0, img.as_ref(), &paint, t, None);
    }
    Ok(sheet)
}
