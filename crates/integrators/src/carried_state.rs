//! Reading the state an integrator carries from one step to the next, one scalar at a time.
//!
//! A step ends by storing its new state (Π, q, μ, …) into the integrator and the next step begins
//! by loading it back. The compiler picks the widths of those stores and loads independently: it
//! may store Π = (Π₁, Π₂, Π₃) as a 16-byte pair and an 8-byte scalar, then load (Π₂, Π₃) as one
//! 16-byte vector straddling both stores. The processor cannot forward such a load from its store
//! buffer and waits for the stores to retire. Loads of single f64s are always contained in one
//! store, so they are forwarded whatever the stores were. On a step as short as an RK4 step of the
//! free rigid body that wait is a large part of the step (`benches/splitting.rs` times the
//! library's steps against a hand-written one in the same run).
//!
//! [`read`] loads each entry on its own and passes it through an empty `asm!` block that takes
//! and returns it in a register: the compiler can neither merge the loads nor load the entries
//! again later (on other targets, [`core::hint::black_box`]). `black_box` alone is not enough: it
//! moves each entry through a stack slot of its own, and the compiler is free to reload those
//! slots two at a time — the straddling load again, one level down. On other targets the
//! fallback is `black_box`, not measured there.
//!
//! [`read`] is used once per step or residual, on the state the previous step wrote: by the
//! explicit steps short enough for the stall to matter, by the Lie–Poisson residual (μ_k), and
//! by the warm start on the solution the last step recorded (`WarmStart::predict`). Not
//! everywhere: read so, ξ_k in the Euler–Poincaré residual made its heavy-top steps slower, not
//! faster — the same barrier that helps one step's code can cost another's, so each use is kept
//! only where the benches show it helps.

use lie_groups::Vector;

/// The entries of `v`, each loaded on its own (see the module docs): bitwise `v.clone()`.
#[inline(always)]
pub(crate) fn read<V: Vector>(v: &V) -> V {
    V::from_fn(v.dim(), |i| opaque(v.get(i)))
}

/// `x`, which the compiler must hold in a register it cannot see through: an empty `asm!` block
/// that takes and returns it in one SSE register.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn opaque(mut x: f64) -> f64 {
    // SAFETY: the template is a comment: no instruction runs, no memory, stack or flag is
    // touched (as the options declare), and x comes back unchanged in the same register.
    unsafe {
        core::arch::asm!(
            "/* {0} */",
            inout(xmm_reg) x,
            options(pure, nomem, nostack, preserves_flags)
        )
    };
    x
}
/// `x` through [`core::hint::black_box`] where the register barrier is not written.
#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn opaque(x: f64) -> f64 {
    core::hint::black_box(x)
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
