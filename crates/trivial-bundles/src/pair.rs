//! Algebra coordinates of a semidirect product: the pair (a, b) ∈ 𝔤 × V, stored side by side and
//! read as one vector of ℝ^{dim a + dim b} by concatenation.

use lie_groups::Vector;

/// Coordinates `(a, b)` of the Lie algebra (or its dual) of a semidirect product such as
/// 𝔤 ⋉ 𝔤 = Lie(G ⋉ 𝔤) or 𝔤 ⋉ 𝔤* = Lie(G ⋉ 𝔤*), as one vector of ℝ^{2n} by concatenation:
/// component `i < n` is `a_i`, component `n + i` is `b_i`.
///
/// `Pair` is `Copy` (and lives on the stack) when both halves are, so a `Pair` of nalgebra
/// `SVector`s allocates nothing. Both halves have the same dimension n in every semidirect product
/// of this crate (the fibre 𝔤 or 𝔤* has the dimension of 𝔤), so [`Vector::zeros`]`(2n)` splits its
/// argument in two equal halves.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Pair<A, B> {
    /// The first half: the coordinate along the base group's algebra 𝔤.
    pub a: A,
    /// The second half: the coordinate along the fibre 𝔤 or 𝔤*.
    pub b: B,
}

impl<A, B> Pair<A, B> {
    /// `(a, b)`.
    #[inline]
    pub const fn new(a: A, b: B) -> Self {
        Self { a, b }
    }
}

impl<A: Vector, B: Vector> Vector for Pair<A, B> {
    /// `(0, 0)` with both halves of dimension `dim / 2`.
    #[inline]
    fn zeros(dim: usize) -> Self {
        debug_assert!(
            dim / 2 * 2 == dim,
            "a Pair has two halves of equal dimension"
        );
        Self::new(A::zeros(dim / 2), B::zeros(dim / 2))
    }
    #[inline]
    fn dim(&self) -> usize {
        self.a.dim() + self.b.dim()
    }
    #[inline]
    fn get(&self, i: usize) -> f64 {
        let n = self.a.dim();
        if i < n {
            self.a.get(i)
        } else {
            self.b.get(i - n)
        }
    }
    #[inline]
    fn set(&mut self, i: usize, value: f64) {
        let n = self.a.dim();
        if i < n {
            self.a.set(i, value)
        } else {
            self.b.set(i - n, value)
        }
    }
    #[inline]
    fn add(&self, other: &Self) -> Self {
        Self::new(self.a.add(&other.a), self.b.add(&other.b))
    }
    #[inline]
    fn sub(&self, other: &Self) -> Self {
        Self::new(self.a.sub(&other.a), self.b.sub(&other.b))
    }
    #[inline]
    fn scale(&self, s: f64) -> Self {
        Self::new(self.a.scale(s), self.b.scale(s))
    }
    #[inline]
    fn dot(&self, other: &Self) -> f64 {
        self.a.dot(&other.a) + self.b.dot(&other.b)
    }
    #[inline]
    fn neg(&self) -> Self {
        Self::new(self.a.neg(), self.b.neg())
    }
    #[inline]
    fn axpy(&self, s: f64, other: &Self) -> Self {
        Self::new(self.a.axpy(s, &other.a), self.b.axpy(s, &other.b))
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.a.is_finite() && self.b.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn components_concatenate_first_then_second_half() {
        let p = Pair::new(Vector3::new(1.0, 2.0, 3.0), Vector3::new(4.0, 5.0, 6.0));
        assert_eq!(p.dim(), 6);
        assert_eq!(p.to_vec(), vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let mut q = Pair::<Vector3<f64>, Vector3<f64>>::zeros(6);
        for i in 0..6 {
            q.set(i, p.get(i));
        }
        assert_eq!(q, p);
        assert_eq!(Pair::<Vector3<f64>, Vector3<f64>>::from_col(&p.to_col()), p);
    }

    #[test]
    fn arithmetic_is_componentwise_and_dot_is_the_euclidean_pairing() {
        let p = Pair::new(Vector3::new(1.0, 2.0, 3.0), Vector3::new(4.0, 5.0, 6.0));
        let q = Pair::new(Vector3::new(-1.0, 0.5, 2.0), Vector3::new(0.0, 1.0, -3.0));
        let by_components: f64 = (0..6).map(|i| p.get(i) * q.get(i)).sum();
        assert_eq!(p.dot(&q), by_components);
        assert_eq!(p.add(&q).sub(&q), p);
        assert_eq!(p.axpy(2.0, &q), p.add(&q.scale(2.0)));
        assert_eq!(p.neg(), p.scale(-1.0));
        let nested = Pair::new(p, q);
        assert_eq!(nested.dim(), 12);
        assert_eq!(nested.get(9), q.get(3));
    }
}
