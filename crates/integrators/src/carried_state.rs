//! Reading the state an integrator carries from one step to the next, one scalar at a time.
//!
//! A step ends by storing its new state (Π, q, μ, …) into the integrator and the next step begins
//! by loading it back. The compiler picks the widths of those stores and loads independently: it
//! may store Π = (Π₁, Π₂, Π₃) as a 16-byte pair and an 8-byte scalar, then load (Π₂, Π₃) as one
//! 16-byte vector straddling both stores. The processor cannot forward such a load from its store
//! buffer and waits for the stores to retire. Loads of single f64s are always contained in one
//! store, so they are forwarded whatever the stores were. Measured in criterion (free rigid body,
//! h = 0.01, with the attitude, same runs): `QuaternionRk4` 62.7 → 48–52 ns per step, `Rkmk4`
//! 72.5 → 62.0; a hand-written RK4 with a time variable added, 50.2 → 46.6 (43.9 with volatile
//! reads, which would need `unsafe`).
//!
//! [`read`] is used once per step, on the state the previous step wrote, by the explicit steps
//! short enough for the stall to matter, and by the implicit steps' warm start on the solution the
//! last step recorded (`WarmStart::predict`: Lie–Poisson Cayley θ = 0 with R 69 → 62 ns).
//! Where the load is not what stalls, the extra round trip through the stack costs instead: read
//! entry by entry, g_k made the Lie–Poisson step 3 ns slower.

use core::hint::black_box;
use lie_groups::Vector;

/// The entries of `v`, each loaded on its own (see the module docs): bitwise `v.clone()`.
///
/// Each entry passes through [`black_box`], so the compiler can neither merge the loads into
/// wider ones nor move them past one another.
#[inline(always)]
pub(crate) fn read<V: Vector>(v: &V) -> V {
    V::from_fn(v.dim(), |i| black_box(v.get(i)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector3, Vector4};

    #[test]
    fn reads_are_bitwise_copies() {
        let v = Vector3::new(-0.0, f64::MIN_POSITIVE / 3.0, 1e300);
        let r = read(&v);
        for i in 0..3 {
            assert_eq!(r[i].to_bits(), v[i].to_bits());
        }
        let q = Vector4::new(0.1, -0.2, f64::NAN, -0.4);
        assert_eq!(read(&q)[2].to_bits(), q[2].to_bits());
    }
}
