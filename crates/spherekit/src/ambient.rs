// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Vectors of the ambient Euclidean space ℝ^(m+1) that contains S^m.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Mul, Neg, Sub};

use glam::{DVec3, DVec4};

/// A vector of the Euclidean space that contains a sphere.
///
/// Points, tangent vectors and derivatives of curves are all expressed in these ambient
/// coordinates: a tangent vector at `p` is an ambient vector `v` with `p · v = 0`.
pub trait Ambient:
    Clone
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<f64, Output = Self>
    + Neg<Output = Self>
    + AddAssign
{
    /// The Euclidean dot product.
    fn dot(&self, other: &Self) -> f64;

    /// The zero vector of the same dimension as `self`.
    #[must_use]
    fn zeros_like(&self) -> Self;

    /// The number of coordinates.
    fn dim(&self) -> usize;

    /// Coordinates in storage order (for `DVec4` ambient quaternions: `x, y, z, w`).
    fn to_vec(&self) -> Vec<f64>;

    /// The coordinates of [`to_vec`](Self::to_vec), borrowed.
    fn as_slice(&self) -> &[f64];

    /// The vector of `self`'s dimension with the coordinates `coords` (in storage order).
    ///
    /// # Panics
    ///
    /// If `coords` has fewer than [`dim`](Self::dim) coordinates.
    #[must_use]
    fn with_coords(&self, coords: &[f64]) -> Self;

    /// The Euclidean length. Finite for every finite vector: when the sum of squares overflows
    /// (a coordinate above about 1e154, such as a second derivative over a tiny knot spacing),
    /// the coordinates are rescaled by the largest one first.
    #[inline]
    fn length(&self) -> f64 {
        let d = self.dot(self);
        if d.is_finite() || !self.is_finite() {
            return d.sqrt();
        }
        rescaled_length(&self.to_vec())
    }

    /// `true` when every coordinate is finite.
    fn is_finite(&self) -> bool;
}

impl Ambient for DVec3 {
    #[inline]
    fn dot(&self, other: &Self) -> f64 {
        DVec3::dot(*self, *other)
    }
    #[inline]
    fn zeros_like(&self) -> Self {
        Self::ZERO
    }
    fn dim(&self) -> usize {
        3
    }
    fn to_vec(&self) -> Vec<f64> {
        self.to_array().to_vec()
    }
    #[inline]
    fn as_slice(&self) -> &[f64] {
        AsRef::<[f64; 3]>::as_ref(self)
    }
    #[inline]
    fn with_coords(&self, coords: &[f64]) -> Self {
        Self::from_slice(coords)
    }
    #[inline]
    fn is_finite(&self) -> bool {
        DVec3::is_finite(*self)
    }
}

impl Ambient for DVec4 {
    #[inline]
    fn dot(&self, other: &Self) -> f64 {
        DVec4::dot(*self, *other)
    }
    #[inline]
    fn zeros_like(&self) -> Self {
        Self::ZERO
    }
    fn dim(&self) -> usize {
        4
    }
    fn to_vec(&self) -> Vec<f64> {
        self.to_array().to_vec()
    }
    #[inline]
    fn as_slice(&self) -> &[f64] {
        AsRef::<[f64; 4]>::as_ref(self)
    }
    #[inline]
    fn with_coords(&self, coords: &[f64]) -> Self {
        Self::from_slice(coords)
    }
    #[inline]
    fn is_finite(&self) -> bool {
        DVec4::is_finite(*self)
    }
}

/// A vector of ℝⁿ whose dimension is chosen at run time: the ambient space of [`SmPoint`](crate::SmPoint).
///
/// Vectors of different lengths combine as if the shorter one were padded with zeros (ℝᵐ ⊂ ℝⁿ
/// as the first m coordinates): a sum or difference has the longer length, and the dot product
/// runs over the common coordinates. So points of spheres of different dimensions (S^m ⊂ S^n)
/// have a distance, a logarithm and a geodesic, and no operation panics on a mismatch.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct VecN(Vec<f64>);

impl VecN {
    /// Wraps the coordinates.
    #[must_use]
    pub fn new(coords: Vec<f64>) -> Self {
        Self(coords)
    }

    /// The coordinates.
    #[must_use]
    pub fn as_slice(&self) -> &[f64] {
        &self.0
    }

    /// `f` coordinate by coordinate, the shorter vector padded with zeros.
    #[inline]
    fn zip_with(mut self, other: &Self, f: impl Fn(f64, f64) -> f64) -> Self {
        if self.0.len() < other.0.len() {
            self.0.resize(other.0.len(), 0.0);
        }
        let n = other.0.len();
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a = f(*a, *b);
        }
        for a in self.0.iter_mut().skip(n) {
            *a = f(*a, 0.0);
        }
        self
    }
}

impl From<Vec<f64>> for VecN {
    fn from(v: Vec<f64>) -> Self {
        Self(v)
    }
}

impl Add for VecN {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        self.zip_with(&rhs, |a, b| a + b)
    }
}

impl AddAssign for VecN {
    fn add_assign(&mut self, rhs: Self) {
        if self.0.len() < rhs.0.len() {
            self.0.resize(rhs.0.len(), 0.0);
        }
        for (a, b) in self.0.iter_mut().zip(rhs.0) {
            *a += b;
        }
    }
}

impl Sub for VecN {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        self.zip_with(&rhs, |a, b| a - b)
    }
}

impl Mul<f64> for VecN {
    type Output = Self;
    fn mul(mut self, rhs: f64) -> Self {
        for a in &mut self.0 {
            *a *= rhs;
        }
        self
    }
}

impl Neg for VecN {
    type Output = Self;
    fn neg(self) -> Self {
        self * -1.0
    }
}

impl Ambient for VecN {
    fn dot(&self, other: &Self) -> f64 {
        self.0.iter().zip(&other.0).map(|(a, b)| a * b).sum()
    }
    fn zeros_like(&self) -> Self {
        Self(vec![0.0; self.0.len()])
    }
    fn dim(&self) -> usize {
        self.0.len()
    }
    fn to_vec(&self) -> Vec<f64> {
        self.0.clone()
    }
    fn as_slice(&self) -> &[f64] {
        &self.0
    }
    fn with_coords(&self, coords: &[f64]) -> Self {
        Self(coords[..self.0.len()].to_vec())
    }
    fn is_finite(&self) -> bool {
        self.0.iter().all(|a| a.is_finite())
    }
}

/// An orthonormal basis of the span of `vectors` (modified Gram–Schmidt, twice, on the
/// normalised vectors; zero vectors are skipped).
pub(crate) fn span_basis<'a, V: Ambient + 'a>(
    dim: usize,
    vectors: impl IntoIterator<Item = &'a V>,
) -> Vec<V> {
    let mut basis: Vec<V> = Vec::with_capacity(dim);
    for p in vectors {
        if basis.len() == dim {
            break;
        }
        let l = p.length();
        if l == 0.0 {
            continue;
        }
        let mut v = p.clone() * (1.0 / l);
        for _ in 0..2 {
            for b in &basis {
                let c = b.dot(&v);
                v = v - b.clone() * c;
            }
        }
        let l = v.length();
        if l > 1e-13 {
            basis.push(v * (1.0 / l));
        }
    }
    basis
}

/// The length of a finite vector whose sum of squares overflows: rescaled by its largest
/// coordinate (the rare path of [`Ambient::length`], kept out of line so that the common one
/// inlines).
#[cold]
#[inline(never)]
fn rescaled_length(v: &[f64]) -> f64 {
    let m = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    m * v.iter().map(|x| (x / m) * (x / m)).sum::<f64>().sqrt()
}
