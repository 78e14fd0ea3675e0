//! Compensated summation of a state and its per-step increment (Knuth's TwoSum, as in Vilmart,
//! "Reducing round-off errors in rigid body dynamics", J. Comput. Phys. 227, 2008): the
//! integrators in increment form add `x_{k+1} = x_k + (Δx + e_k)` and keep the rounding error
//! `e_{k+1}` of that sum exactly, so that the state follows the sum of the increments to O(ε²)
//! instead of collecting one rounding of |x| per step.

use lie_groups::Vector;

/// `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly, componentwise (TwoSum: no
/// assumption on the relative sizes of a and b; six flops per component).
#[inline(always)]
pub(crate) fn two_sum<V: Vector>(a: &V, b: &V) -> (V, V) {
    let s = a.add(b);
    let bb = s.sub(a);
    let e = a.sub(&s.sub(&bb)).add(&b.sub(&bb));
    (s, e)
}
