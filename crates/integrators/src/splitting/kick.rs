//! The kick of a splitting: the flow of the forces with g held fixed.

use crate::system::force;
use crate::{IntegratorError, System};
use lie_groups::{LieGroup, Vector};

/// Fixed-point iterations allowed to the implicit-midpoint kick of a velocity-dependent force.
pub const KICK_MAX_ITERATIONS: usize = 50;

/// The kick `K_s` at time t: the flow for a time s of `μ̇ = F(g) + F_ext(t, g, ξ(μ))` with g (and t)
/// held fixed, `F(g) = −T*_e L_g dV(g)` the potential's force and F_ext the external force
/// ([`crate::forces`]); in place, μ left as it was on error.
///
/// - Without an external force, or with one that does not read the velocity
///   ([`System::external_force_reads_velocity`]): the exact flow `μ + s (F(g) + F_ext(t, g))` (for an
///   unforced system exactly the arithmetic `μ + sF(g)` of the unforced splittings).
/// - With a velocity-dependent force (damping, drag): the implicit midpoint rule
///   `μ' = μ + s (F(g) + F_ext(t, g, ξ(½(μ + μ'))))`, solved by fixed-point iteration — order 2 and
///   symmetric (`K_{−s} ∘ K_s = id`), so a palindromic splitting stays symmetric. It converges
///   for `|s| ‖∂F_ext/∂μ‖ < 1`; otherwise [`IntegratorError::NoConvergence`].
///
/// In both cases the momentum changes by `s (F(g) + F_ext)` with g fixed, so the spatial momentum
/// map `Ad*_{g⁻¹} μ` changes by exactly the applied spatial impulse `s Ad*_{g⁻¹}(F + F_ext)`.
pub(crate) fn kick<G: LieGroup, S: System<G>>(
    system: &S,
    t: f64,
    s: f64,
    mu: &mut G::Algebra,
    g: Option<&G>,
) -> Result<(), IntegratorError> {
    let base = match force(system, g) {
        Some(f) => mu.axpy(s, &f),
        None if system.is_forced() => mu.clone(),
        None => return Ok(()),
    };
    if !system.is_forced() {
        *mu = base;
        return Ok(());
    }
    let f_ext = |m: &G::Algebra| system.external_force(t, g, &system.velocity(m));
    let mut next = base.axpy(s, &f_ext(mu));
    if system.external_force_reads_velocity() {
        let mut last = f64::INFINITY;
        let mut converged = false;
        for _ in 0..KICK_MAX_ITERATIONS {
            let mid = mu.add(&next).scale(0.5);
            let new = base.axpy(s, &f_ext(&mid));
            let change = new.sub(&next).norm_max();
            next = new;
            let scale = next.norm_max().max(mu.norm_max());
            // Done at round-off of the data, or when the iteration has stopped contracting at
            // that level (a walk of roundings).
            if change <= 4.0 * f64::EPSILON * scale || (change >= last && change <= 1e-13 * scale) {
                converged = true;
                break;
            }
            last = change;
        }
        if !converged || !next.is_finite() {
            return Err(IntegratorError::NoConvergence {
                iterations: KICK_MAX_ITERATIONS,
                residual: last,
            });
        }
    }
    *mu = next;
    Ok(())
}
