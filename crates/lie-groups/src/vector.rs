//! Algebra coordinates: the vector space ℝⁿ ≅ 𝔤 (by `hat`/`vee`) and ℝⁿ ≅ 𝔤* (by the Euclidean
//! pairing ⟨μ, ξ⟩ = μ·ξ).
//!
//! Fixed-size groups use nalgebra's stack vectors [`SVector`]; the composite groups pair or array
//! them ([`crate::ProductAlgebra`], [`crate::PowerAlgebra`]); with the `faer` feature, groups whose
//! dimension is only known through a large `n` (SO(n), GL(n)) use faer's `Col`. Bundles pair two
//! such vectors (`trivial_bundles::Pair`). Everything generic in the workspace goes through this
//! trait.

use core::fmt::Debug;
use nalgebra::SVector;

/// An element of ℝⁿ used as coordinates of 𝔤 or 𝔤*.
///
/// All operations are by value and allocate nothing for stack types.
pub trait Vector: Clone + Debug + PartialEq + Send + Sync + 'static {
    /// The zero vector of dimension `dim` (fixed-size types ignore `dim` but check it in debug).
    fn zeros(dim: usize) -> Self;
    /// Dimension n.
    fn dim(&self) -> usize;
    /// Component `i`.
    fn get(&self, i: usize) -> f64;
    /// Sets component `i`.
    fn set(&mut self, i: usize, value: f64);
    /// `self + other`.
    fn add(&self, other: &Self) -> Self;
    /// `self − other`.
    fn sub(&self, other: &Self) -> Self;
    /// `s · self`.
    fn scale(&self, s: f64) -> Self;
    /// Euclidean pairing `self · other` (the pairing ⟨μ, ξ⟩ of 𝔤* with 𝔤).
    fn dot(&self, other: &Self) -> f64;

    /// `−self`.
    fn neg(&self) -> Self {
        self.scale(-1.0)
    }
    /// `self + s · other`.
    fn axpy(&self, s: f64, other: &Self) -> Self {
        self.add(&other.scale(s))
    }
    /// Euclidean norm.
    fn norm(&self) -> f64 {
        self.dot(self).sqrt()
    }
    /// Largest absolute component.
    fn norm_max(&self) -> f64 {
        (0..self.dim()).fold(0.0, |m, i| f64::max(m, self.get(i).abs()))
    }
    /// Whether every component is finite.
    fn is_finite(&self) -> bool {
        (0..self.dim()).all(|i| self.get(i).is_finite())
    }
    /// The i-th unit vector eᵢ of dimension `dim`.
    fn basis(dim: usize, i: usize) -> Self {
        let mut e = Self::zeros(dim);
        e.set(i, 1.0);
        e
    }
    /// Builds a vector of dimension `dim` from its components.
    fn from_fn(dim: usize, mut f: impl FnMut(usize) -> f64) -> Self {
        let mut v = Self::zeros(dim);
        for i in 0..dim {
            v.set(i, f(i));
        }
        v
    }
    /// The components as a faer column (for dense linear algebra; feature `faer`).
    #[cfg(feature = "faer")]
    fn to_col(&self) -> faer::Col<f64> {
        faer::Col::from_fn(self.dim(), |i| self.get(i))
    }
    /// The components as a `Vec` (for output and tests).
    fn to_vec(&self) -> Vec<f64> {
        (0..self.dim()).map(|i| self.get(i)).collect()
    }
    /// Builds a vector from a faer column (feature `faer`).
    #[cfg(feature = "faer")]
    fn from_col(c: &faer::Col<f64>) -> Self {
        Self::from_fn(c.nrows(), |i| c[i])
    }
}

impl<const N: usize> Vector for SVector<f64, N> {
    #[inline]
    fn zeros(dim: usize) -> Self {
        debug_assert_eq!(
            dim, N,
            "fixed-size vector of dimension {N} asked for dimension {dim}"
        );
        SVector::zeros()
    }
    #[inline]
    fn dim(&self) -> usize {
        N
    }
    #[inline]
    fn get(&self, i: usize) -> f64 {
        self[i]
    }
    #[inline]
    fn set(&mut self, i: usize, value: f64) {
        self[i] = value;
    }
    #[inline]
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    #[inline]
    fn sub(&self, other: &Self) -> Self {
        self - other
    }
    #[inline]
    fn scale(&self, s: f64) -> Self {
        self * s
    }
    #[inline]
    fn dot(&self, other: &Self) -> f64 {
        nalgebra::Matrix::dot(self, other)
    }
    #[inline]
    fn neg(&self) -> Self {
        -self
    }
    #[inline]
    fn norm(&self) -> f64 {
        nalgebra::Matrix::norm(self)
    }
    /// Unrolled, without `f64::max`'s NaN branches (a NaN entry is skipped, as `f64::max` does).
    #[inline]
    fn norm_max(&self) -> f64 {
        self.iter().fold(0.0, |m, x| {
            let a = x.abs();
            if a > m {
                a
            } else {
                m
            }
        })
    }
    /// Branch-free: the AND of the entries' own tests, each independent of the others (a sum of
    /// `x − x` would chain one dependent addition per entry).
    #[inline]
    fn is_finite(&self) -> bool {
        self.iter().fold(true, |ok, x| ok & x.is_finite())
    }
}

#[cfg(feature = "faer")]
impl Vector for faer::Col<f64> {
    fn zeros(dim: usize) -> Self {
        faer::Col::zeros(dim)
    }
    fn dim(&self) -> usize {
        self.nrows()
    }
    fn get(&self, i: usize) -> f64 {
        self[i]
    }
    fn set(&mut self, i: usize, value: f64) {
        self[i] = value;
    }
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    fn sub(&self, other: &Self) -> Self {
        self - other
    }
    fn scale(&self, s: f64) -> Self {
        faer::Col::from_fn(self.nrows(), |i| s * self[i])
    }
    fn dot(&self, other: &Self) -> f64 {
        (0..self.nrows()).map(|i| self[i] * other[i]).sum()
    }
    fn to_col(&self) -> faer::Col<f64> {
        self.clone()
    }
    fn from_col(c: &faer::Col<f64>) -> Self {
        c.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::Vector;
    use nalgebra::{SVector, Vector3};

    /// The stack vectors' unrolled `is_finite` and `norm_max` agree with the element-wise
    /// definitions (the trait's provided forms) for NaN and ±∞ in every position and for huge,
    /// tiny and signed entries.
    #[test]
    fn fixed_size_is_finite_and_norm_max_match_the_definitions() {
        let specials = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        for i in 0..3 {
            for x in specials {
                let mut v = Vector3::new(1.0, -2.0, f64::MAX);
                v[i] = x;
                assert!(!Vector::is_finite(&v), "{v:?}");
            }
        }
        for v in [
            Vector3::new(f64::MAX, -f64::MAX, f64::MIN_POSITIVE),
            Vector3::new(-0.0, 5e-324, -3.0),
            Vector3::zeros(),
        ] {
            assert!(Vector::is_finite(&v));
            let plain = (0..3).fold(0.0, |m, i| f64::max(m, v[i].abs()));
            assert_eq!(v.norm_max(), plain);
        }
        let six = SVector::<f64, 6>::from_fn(|i, _| (i as f64 - 2.5) * 1e3);
        assert_eq!(six.norm_max(), 2500.0);
        let with_nan = Vector3::new(f64::NAN, -4.0, 1.0);
        assert_eq!(
            with_nan.norm_max(),
            4.0,
            "a NaN entry is skipped, as f64::max does"
        );
    }
}
