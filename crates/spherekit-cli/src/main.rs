// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! `spherekit`: sample curves described by JSON scenes.
//!
//! ```text
//! spherekit sample SCENE.json|- [--deriv] [--frame space|body] [--continuity] [--samples N | --at T,…]
//! spherekit render SCENE.json|- -o OUT.png|OUT.svg [--format png|svg] [--size N]
//! spherekit methods [--json]
//! ```
//!
//! Bad input exits with status 2 and one line on stderr naming the offending field.

use std::io::{Read, Write};
use std::process::ExitCode;

use spherekit_scene::{METHODS, SampleOptions, Scene, registry_json};

const USAGE: &str = "\
usage: spherekit <command> [options]

commands:
  sample SCENE.json [--deriv] [--frame space|body] [--continuity] [--samples N | --at T,…]
      Sample the curve a scene describes and print one JSON object
      (`-` reads the scene from standard input).
      --deriv        also print velocity, acceleration (and angular velocity on S3)
      --frame F      S3 angular velocity and acceleration in the space frame
                     (default; ω = 2q′q̄) or the body frame (2q̄q′, scipy's)
      --continuity   also print the jumps of point, velocity and acceleration
                     at every joint (c0, c1, c2; g1 of the unit tangent) and
                     its class (C⁰, G¹, C¹, C², … Cⁿ)
      --samples N    N uniform samples over the domain (overrides the scene);
                     the domain is [0, L] for \"parametrization\": \"arclength\",
                     so the samples are equally far apart along the curve
      --at T,…       sample at these parameters instead (overrides the scene's
                     samples and eval_at); outside the domain the curve's
                     \"extrapolate\" policy applies, and a parameter that is not
                     finite (nan, inf) is an error naming it
  render SCENE.json -o OUT.png|OUT.svg [--format png|svg] [--size N]
      Draw the scene (sphere, curves, plots, legend) into a PNG, or the same
      picture as SVG (vector strokes, text as <text>), N pixels wide (default
      512). The format follows the file's extension (.png or .svg) or
      --format; any other extension is an error. No file is written when the
      scene is bad.
  methods [--json]
      List the curve methods and the spaces each supports; with --json the
      whole registry: knots, minimum points, parameters with type, range
      and default.
  help
      Show this text.";

/// A failure with its exit status: 2 for bad input, 1 for an I/O failure writing output.
struct Failure {
    status: u8,
    message: String,
}

fn bad(message: impl Into<String>) -> Failure {
    Failure {
        status: 2,
        message: message.into(),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            eprintln!("error: {}", f.message);
            ExitCode::from(f.status)
        }
    }
}

fn run(args: &[String]) -> Result<(), Failure> {
    match args.first().map(String::as_str) {
        Some("sample") => sample(&args[1..]),
        Some("render") => render(&args[1..]),
        Some("methods") if args.len() == 1 => {
            methods();
            Ok(())
        }
        Some("methods") if args.len() == 2 && args[1] == "--json" => {
            println!("{}", registry_json());
            Ok(())
        }
        Some("help" | "--help" | "-h") => {
            println!("{USAGE}");
            Ok(())
        }
        Some(other) => Err(bad(format!(
            "unknown command or arguments \"{}\" (try `spherekit help`)",
            if other == "methods" {
                args.join(" ")
            } else {
                other.to_owned()
            }
        ))),
        None => Err(bad("no command given (try `spherekit help`)")),
    }
}

fn methods() {
    for m in METHODS {
        println!("{:<14} {:<14} {}", m.id, m.spaces.describe(), m.summary);
    }
    println!(
        "\nEvery method samples on the spheres listed; `render` draws S1, S2 and S3 scenes \
         (S<m> for m >= 4 is refused)."
    );
}

fn read_scene(path: &str) -> Result<String, Failure> {
    if path == "-" {
        let mut s = String::new();
        std::io::stdin()
            .read_to_string(&mut s)
            .map_err(|e| bad(format!("cannot read the scene from standard input: {e}")))?;
        Ok(s)
    } else {
        std::fs::read_to_string(path)
            .map_err(|e| bad(format!("cannot read scene file {path}: {e}")))
    }
}

fn sample(args: &[String]) -> Result<(), Failure> {
    let mut path = None;
    let mut options = SampleOptions::default();
    let mut samples = None;
    let mut at = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--deriv" => options.deriv = true,
            "--continuity" => options.continuity = true,
            "--frame" => match it.next().map(String::as_str) {
                Some("space") => options.body_frame = false,
                Some("body") => options.body_frame = true,
                other => {
                    return Err(bad(format!(
                        "--frame: \"{}\" is not a frame: use space or body",
                        other.unwrap_or("")
                    )));
                }
            },
            "--samples" => {
                let v = it.next().ok_or_else(|| bad("--samples needs a number"))?;
                let n: usize = v
                    .parse()
                    .map_err(|_| bad(format!("--samples: \"{v}\" is not a whole number")))?;
                samples = Some(n);
            }
            "--at" => {
                let v = it
                    .next()
                    .ok_or_else(|| bad("--at needs parameters, such as --at 0,0.5,1"))?;
                let ts = v
                    .split(',')
                    .map(|x| {
                        x.trim()
                            .parse::<f64>()
                            .map_err(|_| bad(format!("--at: \"{x}\" is not a number")))
                    })
                    .collect::<Result<Vec<f64>, _>>()?;
                at = Some(ts);
            }
            s if s.starts_with("--") => return Err(bad(format!("unknown option {s}"))),
            s if path.is_none() => path = Some(s.to_owned()),
            s => return Err(bad(format!("unexpected argument \"{s}\""))),
        }
    }
    let path = path.ok_or_else(|| bad("sample: give a scene file, or - for standard input"))?;
    if samples.is_some() && at.is_some() {
        return Err(bad("give either --samples or --at, not both"));
    }
    let text = read_scene(&path)?;
    let mut scene = Scene::from_json(&text).map_err(|e| bad(e.to_string()))?;
    if let Some(ts) = at {
        scene.set_parameters(ts).map_err(|e| {
            bad(format!(
                "--at: {}",
                e.to_string().trim_start_matches("eval_at: ")
            ))
        })?;
    }
    if let Some(n) = samples {
        scene.set_samples(n).map_err(|e| {
            bad(format!(
                "--samples: {}",
                e.to_string().trim_start_matches("samples: ")
            ))
        })?;
    }
    let curves = scene.build().map_err(|e| bad(e.to_string()))?;
    let out = scene.sample_json_with(&curves, options);
    let mut stdout = std::io::stdout().lock();
    serde_json::to_writer(&mut stdout, &out)
        .map_err(std::io::Error::from)
        .and_then(|()| writeln!(stdout))
        .map_err(|e| Failure {
            status: 1,
            message: format!("cannot write the output: {e}"),
        })
}

/// The image formats `render` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Png,
    Svg,
}

impl Format {
    fn parse(name: &str) -> Option<Self> {
        match name.to_ascii_lowercase().as_str() {
            "png" => Some(Self::Png),
            "svg" => Some(Self::Svg),
            _ => None,
        }
    }
}

/// The format to write `out` in: its extension's, or `--format`'s; they must agree.
fn output_format(out: &str, format: Option<Format>) -> Result<Format, Failure> {
    let extension = std::path::Path::new(out)
        .extension()
        .map(|e| e.to_string_lossy().into_owned());
    match (extension, format) {
        (None, f) => Ok(f.unwrap_or(Format::Png)),
        (Some(e), f) => match (Format::parse(&e), f) {
            (Some(from_name), None) => Ok(from_name),
            (Some(from_name), Some(f)) if from_name == f => Ok(f),
            (Some(_), Some(f)) => Err(bad(format!(
                "-o {out}: the extension .{e} does not match --format {}",
                if f == Format::Png { "png" } else { "svg" }
            ))),
            (None, _) => Err(bad(format!(
                "-o {out}: cannot write .{e} files (render writes .png and .svg)"
            ))),
        },
    }
}

fn render(args: &[String]) -> Result<(), Failure> {
    let mut path = None;
    let mut out = None;
    let mut format = None;
    let mut size = 512_u32;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "-o" | "--output" => {
                out = Some(
                    it.next()
                        .ok_or_else(|| bad("-o needs a file name"))?
                        .clone(),
                );
            }
            "--format" => {
                let v = it.next().ok_or_else(|| bad("--format needs png or svg"))?;
                format = Some(Format::parse(v).ok_or_else(|| {
                    bad(format!("--format: \"{v}\" is not a format: use png or svg"))
                })?);
            }
            "--size" => {
                let v = it.next().ok_or_else(|| bad("--size needs a number"))?;
                size = v
                    .parse()
                    .map_err(|_| bad(format!("--size: \"{v}\" is not a whole number")))?;
            }
            s if s.starts_with("--") => return Err(bad(format!("unknown option {s}"))),
            s if path.is_none() => path = Some(s.to_owned()),
            s => return Err(bad(format!("unexpected argument \"{s}\""))),
        }
    }
    let path = path.ok_or_else(|| bad("render: give a scene file, or - for standard input"))?;
    let out = out.ok_or_else(|| bad("render: give the output file with -o OUT.png or OUT.svg"))?;
    let format = output_format(&out, format)?;
    let text = read_scene(&path)?;
    let scene = Scene::from_json(&text).map_err(|e| bad(e.to_string()))?;
    let bytes = match format {
        Format::Png => {
            let pixmap = spherekit_render::render(&scene, size).map_err(|e| bad(e.to_string()))?;
            spherekit_cli::encode_png(&pixmap).map_err(|e| Failure {
                status: 1,
                message: format!("cannot encode the PNG: {e}"),
            })?
        }
        Format::Svg => spherekit_render::render_svg(&scene, size)
            .map_err(|e| bad(e.to_string()))?
            .into_bytes(),
    };
    std::fs::write(&out, bytes).map_err(|e| Failure {
        status: 1,
        message: format!("cannot write {out}: {e}"),
    })
}
