// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Constructions run once, on S^m: the `compact` feature.
//!
//! Every [`Manifold`] operation is a default method over [`Ambient`], and the ambient types do
//! the same arithmetic coordinate by coordinate: glam's `DVec3::dot`/`DVec4::dot` is
//! `x·x′ + y·y′ + z·z′ (+ w·w′)` from left to right, [`VecN`]'s the same sum starting from
//! −0.0 (`−0.0 + a = a` exactly); sums, differences and scalings are per coordinate in both.
//! So a construction whose arithmetic never leaves the `Manifold`/`Ambient` operations gives
//! the same bits on [`SmPoint`] as on [`S2Point`](crate::S2Point) or
//! [`UnitQuat`](crate::UnitQuat) with the same coordinates. With the `compact` feature (which
//! the browser build turns on, to keep the .wasm small) such constructions are compiled once
//! instead of once per point type: the keys are converted to `SmPoint`, the curve is built
//! there and converted back ([`Recast`]), so it is evaluated on its own point type (a `VecN`
//! jet would allocate). Without the feature the constructions run on the point type itself
//! (no conversions). Each construction that does this has a test that both paths give the
//! same bits, compiled whether the feature is on or not.

use crate::ambient::{Ambient, VecN};
use crate::manifold::Manifold;
use crate::sm::SmPoint;

/// The point `p` as a point of S^m with the same coordinates.
pub(crate) fn to_sm<P: Manifold>(p: &P) -> SmPoint {
    SmPoint::from_vector_unchecked(VecN::new(p.to_vector().to_vec()))
}

/// Converts vectors and points to the point type `Q`, coordinate by coordinate.
pub(crate) struct Recast<Q: Manifold> {
    /// A vector of `Q`'s ambient space (its coordinates are not used, only its dimension).
    like: Q::Vector,
}

impl<Q: Manifold> Recast<Q> {
    /// Conversions to the point type of `like`.
    pub(crate) fn to(like: &Q) -> Self {
        Self {
            like: like.to_vector(),
        }
    }

    /// The vector of `Q`'s ambient space with the coordinates of `v`.
    pub(crate) fn vector<V: Ambient>(&self, v: &V) -> Q::Vector {
        self.like.with_coords(v.as_slice())
    }

    /// The point of `Q` with the coordinates of `p`.
    pub(crate) fn point(&self, p: &SmPoint) -> Q {
        Q::from_vector_unchecked(self.like.with_coords(p.coords()))
    }

    /// [`point`](Self::point) of every point of `ps`.
    pub(crate) fn points(&self, ps: &[SmPoint]) -> Vec<Q> {
        ps.iter().map(|p| self.point(p)).collect()
    }
}

/// Key sets for the tests that a construction gives the same bits on S^m.
#[cfg(test)]
pub(crate) mod keys {
    use glam::{DQuat, DVec3, DVec4};

    use core::fmt::Debug;

    use crate::{S2Point, UnitQuat};

    /// `1` if `native` is a built curve, after asserting that the construction on S^m gave the
    /// same curve or error, bit for bit (`{:?}` prints each `f64` in the shortest form that reads
    /// back to the same bits); `context` is printed when they differ.
    pub(crate) fn same_bits<T: Debug, E: Debug>(
        native: &Result<T, E>,
        on_sm: &Result<T, E>,
        context: &dyn Debug,
    ) -> usize {
        assert_eq!(format!("{native:?}"), format!("{on_sm:?}"), "{context:?}");
        usize::from(native.is_ok())
    }

    /// The curves built by a test's `check` over every key set of [`on_s2`] and [`on_s3`].
    pub(crate) fn built(s2: fn(&[S2Point]) -> usize, s3: fn(&[UnitQuat]) -> usize) -> usize {
        on_s2().iter().map(|p| s2(p)).sum::<usize>() + on_s3().iter().map(|p| s3(p)).sum::<usize>()
    }

    fn s2(v: [f64; 3]) -> S2Point {
        S2Point::try_new(DVec3::from_array(v)).unwrap_or_else(|e| panic!("{e}"))
    }

    fn s3(v: [f64; 4]) -> UnitQuat {
        UnitQuat::try_new(DQuat::from_vec4(DVec4::from_array(v))).unwrap_or_else(|e| panic!("{e}"))
    }

    /// Key sequences on S²: a generic one, keys 1e-9 rad apart (near 0), steps close to a
    /// half turn, keys on one great circle, a repeated key and a key repeated two apart.
    pub(crate) fn on_s2() -> Vec<Vec<S2Point>> {
        let near_pi = |a: f64| s2([a.cos(), a.sin(), 1e-3 * a]);
        vec![
            vec![
                s2([1.0, 0.0, 0.3]),
                s2([0.6, 0.8, 0.4]),
                s2([-0.2, 1.0, 0.1]),
                s2([-0.9, 0.3, -0.2]),
                s2([-0.4, -0.8, 0.5]),
            ],
            vec![
                s2([1.0, 0.0, 0.0]),
                s2([1.0, 1e-9, 0.0]),
                s2([1.0, 2e-9, 1e-9]),
                s2([1.0, 2e-9, 3e-9]),
            ],
            vec![near_pi(0.0), near_pi(3.1), near_pi(6.2), near_pi(9.3)],
            vec![
                s2([1.0, 0.0, 0.0]),
                s2([0.0, 1.0, 0.0]),
                s2([-1.0, 0.0, 0.0]),
                s2([0.0, -1.0, 0.0]),
            ],
            vec![
                s2([1.0, 0.0, 0.3]),
                s2([0.6, 0.8, 0.4]),
                s2([0.6, 0.8, 0.4]),
                s2([-0.9, 0.3, -0.2]),
            ],
            vec![
                s2([1.0, 0.0, 0.3]),
                s2([0.6, 0.8, 0.4]),
                s2([1.0, 0.0, 0.3]),
                s2([-0.9, 0.3, -0.2]),
            ],
        ]
    }

    /// Key sequences on S³: a generic one, keys 1e-9 apart, and steps close to a half turn.
    pub(crate) fn on_s3() -> Vec<Vec<UnitQuat>> {
        let near_pi = |a: f64| s3([a.cos(), a.sin(), 1e-3 * a, 0.2]);
        vec![
            vec![
                s3([1.0, 0.0, 0.0, 0.1]),
                s3([0.9, 0.4, 0.0, 0.2]),
                s3([0.5, 0.5, 0.5, -0.5]),
                s3([0.0, 0.3, 0.9, 0.2]),
                s3([-0.4, 0.1, 0.5, 0.7]),
            ],
            vec![
                s3([0.0, 0.0, 0.0, 1.0]),
                s3([1e-9, 0.0, 0.0, 1.0]),
                s3([2e-9, 1e-9, 0.0, 1.0]),
                s3([2e-9, 3e-9, 1e-9, 1.0]),
            ],
            vec![near_pi(0.0), near_pi(3.1), near_pi(6.2), near_pi(9.3)],
        ]
    }
}
