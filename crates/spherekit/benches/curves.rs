// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! The benchmarked methods, built from the shared data (used by the criterion benches and the
//! `bench_json` example).

#![allow(dead_code, reason = "each user takes a subset")]

use spherekit::{
    ArcBlend, BetaParams, BetaSpline, Bezier, BezierKim, BsplineKim, CatmullRom, CornerBlend,
    CornerBlendRotations, CubicEnd, CubicSpline, Curve, DEFAULT_CORNER_FRACTION, GammaSpline,
    Gammas, GeodesicSpline, LastEdge, NlerpSpline, S2Point, Squad, UnitQuat,
};

/// A boxed curve of unit quaternions.
pub(crate) type Boxed = Box<dyn Curve<Point = UnitQuat>>;

/// One benchmarked method on S³.
pub(crate) struct Method {
    /// The name in the tables.
    pub(crate) name: &'static str,
    /// Slerps (or slerp-equivalents: `sin_cos` + `atan2`, an exp or a log) per sample of a
    /// point, the floor of the "within 2× of k slerps" target.
    pub(crate) slerps: u32,
    /// Builds the curve through (or from) the keys.
    pub(crate) build: fn(Vec<UnitQuat>) -> Boxed,
}

/// The methods, all on S³ (unit quaternions), built from `keys`. The Bézier methods take the
/// first 4 keys as the control points of one cubic.
pub(crate) const METHODS: &[Method] = &[
    Method {
        name: "geodesic",
        slerps: 1,
        build: |k| Box::new(GeodesicSpline::try_new(k, None).expect("geodesic")),
    },
    Method {
        name: "nlerp",
        slerps: 0,
        build: |k| Box::new(NlerpSpline::try_new(k, None).expect("nlerp")),
    },
    Method {
        name: "squad",
        slerps: 3,
        build: |k| Box::new(Squad::try_new(k, None).expect("squad")),
    },
    Method {
        name: "catmull-rom",
        slerps: 6,
        build: |k| Box::new(CatmullRom::try_new(k, None).expect("catmull-rom")),
    },
    Method {
        name: "bezier",
        slerps: 6,
        build: |k| Box::new(Bezier::try_new(k[..4].to_vec()).expect("bezier")),
    },
    Method {
        name: "bezier-kim",
        slerps: 3,
        build: |k| Box::new(BezierKim::try_new(k[..4].to_vec()).expect("bezier-kim")),
    },
    Method {
        name: "bspline-kim",
        slerps: 3,
        build: |k| Box::new(BsplineKim::try_new(k).expect("bspline-kim")),
    },
    Method {
        name: "gamma",
        slerps: 3,
        build: |k| {
            Box::new(
                GammaSpline::try_new(k, None, Gammas::All(1.0), LastEdge::Formula).expect("gamma"),
            )
        },
    },
    Method {
        name: "beta",
        slerps: 6,
        build: |k| Box::new(BetaSpline::try_new(k, &BetaParams::default()).expect("beta")),
    },
    Method {
        name: "cubic",
        slerps: 1,
        build: |k| Box::new(CubicSpline::try_new(k, None, CubicEnd::Scipy, false).expect("cubic")),
    },
    Method {
        name: "arc-blend",
        slerps: 3,
        build: |k| Box::new(ArcBlend::try_new(k, 2).expect("arc-blend")),
    },
    Method {
        name: "corner-blend",
        slerps: 3,
        build: |k| {
            Box::new(
                CornerBlendRotations::try_new(k, 2, DEFAULT_CORNER_FRACTION).expect("corner-blend"),
            )
        },
    },
];

/// The S² variants of the methods that are also built on S² (for construction timings of the
/// Beta solver and the Pobegailo blends on directions).
pub(crate) fn build_s2(name: &str, p: Vec<S2Point>) -> Box<dyn Curve<Point = S2Point>> {
    match name {
        "geodesic" => Box::new(GeodesicSpline::try_new(p, None).expect("geodesic")),
        "catmull-rom" => Box::new(CatmullRom::try_new(p, None).expect("catmull-rom")),
        "beta" => Box::new(BetaSpline::try_new(p, &BetaParams::default()).expect("beta")),
        "arc-blend" => Box::new(ArcBlend::try_new(p, 2).expect("arc-blend")),
        _ => Box::new(CornerBlend::try_new(p, 2, DEFAULT_CORNER_FRACTION).expect("corner-blend")),
    }
}
