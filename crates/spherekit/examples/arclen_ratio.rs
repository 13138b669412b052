// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The cost of the arc-length adapter per sample against the curve's own `jet`, for every
//! method of the criterion bench `arclen` (S³, the same 20 keys, behind a `Box<dyn Curve>`):
//! one `jet` per sample at 20 000 increasing parameters, and the adapter's batch `jet_many`.
//!
//! Each figure is the fastest of 41 runs of the whole loop (a run takes a few milliseconds, less
//! than a scheduler time slice), so that it stays meaningful on a loaded machine where
//! criterion's means move by tens of percent:
//!
//! `cargo run --release -p spherekit --example arclen_ratio`

#![allow(missing_docs, reason = "an example")]

#[path = "../benches/curves.rs"]
mod curves;
#[path = "../benches/data.rs"]
mod data;

use std::hint::black_box;
use std::time::Instant;

use spherekit::{ArcLength, Curve, Jet, Side, UnitQuat};

/// A boxed method as a sized curve, so that the adapter can own it.
#[derive(Debug)]
struct Dyn(curves::Boxed);

impl Curve for Dyn {
    type Point = UnitQuat;
    fn domain(&self) -> [f64; 2] {
        self.0.domain()
    }
    fn joints(&self) -> &[f64] {
        self.0.joints()
    }
    fn jet_at(&self, t: f64, side: Side) -> Jet<UnitQuat> {
        self.0.jet_at(t, side)
    }
    fn jet_many(&self, ts: &[f64], out: &mut [Jet<UnitQuat>]) {
        self.0.jet_many(ts, out);
    }
}

/// The fastest of 41 runs of `f`, in seconds.
fn fastest(mut f: impl FnMut()) -> f64 {
    (0..41)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    const SAMPLES: usize = 20_000;
    let keys = data::keys_s3(20);
    println!(
        "| method | curve jet (ns) | arc-length jet (ns) | ratio | arc-length jet_many (ns) |"
    );
    println!("|---|---|---|---|---|");
    for m in curves::METHODS {
        let curve = Dyn((m.build)(keys.clone()));
        let ts = data::params(curve.domain(), SAMPLES);
        let mut jets = vec![curve.jet(ts[0]); SAMPLES];
        let own = fastest(|| {
            for (o, &t) in jets.iter_mut().zip(&ts) {
                *o = curve.jet(black_box(t));
            }
            black_box(&jets);
        });
        let arc = ArcLength::try_new(curve).expect("arc length");
        let ss = data::params(arc.domain(), SAMPLES);
        let single = fastest(|| {
            for (o, &s) in jets.iter_mut().zip(&ss) {
                *o = arc.jet(black_box(s));
            }
            black_box(&jets);
        });
        let batch = fastest(|| {
            arc.jet_many(black_box(&ss), &mut jets);
            black_box(&jets);
        });
        #[expect(clippy::cast_precision_loss, reason = "a small count")]
        let per = 1e9 / SAMPLES as f64;
        println!(
            "| {} | {:.0} | {:.0} | {:.2} | {:.0} |",
            m.name,
            own * per,
            single * per,
            single / own,
            batch * per
        );
    }
}
