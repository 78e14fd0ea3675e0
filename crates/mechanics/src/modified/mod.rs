//! High order at the cost of order 2 by modifying the Hamiltonian the kernel integrates
//! (Chartier–Hairer–Vilmart 2007, "Numerical integrators based on modified differential
//! equations", Math. Comp. 76; for the rigid body McLachlan–Zanna 2005, "The discrete
//! Moser–Veselov algorithm revisited", Found. Comput. Math. 5, and Hairer–Vilmart 2006).
//!
//! A symmetric Poisson kernel Φ_h applied to a Hamiltonian H is the exact flow of a modified
//! Hamiltonian `H + h² H₂ + h⁴ H₄ + …` (only even powers: Φ is symmetric). Applying it instead to
//! `H̃_h = H − h² H₂` gives `H + O(h⁴)`: order 4; to `H̃_h = H − h² H₂ − h⁴ H₄`, with H₄ the h⁴ term
//! of the kernel applied to `H − h²H₂`, it gives `H + O(h⁶)`: order 6 — one kernel step per step
//! either way. The kernels are the Lie–Poisson schemes of [`integrators::LiePoisson`] with τ = exp or
//! Cayley — not the discrete Moser–Veselov algorithm — so H₂ and H₄ were derived for them
//! (`crates/mechanics/tools/modified_lp.py`, sympy; the tables are generated into
//! `coefficients.rs`, and the script checks that the scheme on `H − h²H₂ − h⁴H₄` has no local
//! error through h⁶):
//!
//! - **θ = ½**: symmetric; H₂ in closed form on [`ModifiedTau`], H₄ a cubic in Πᵢ².
//! - **θ = 0**: not symmetric in general, but without a potential the θ = 0 and θ = 1 schemes
//!   coincide, and θ = 1 is θ = 0's adjoint, so on the free body it *is* symmetric: the scheme on
//!   `H − h²H₂` has no h³ (and no h⁴) local error — the h³ term of its modified Hamiltonian is
//!   zero, derived, not assumed (the script asserts it). Its H₂ and H₄ differ from θ = ½'s for
//!   Cayley; for exp the θ = 0 and θ = ½ schemes are the same map (the discretization maps of a
//!   one-parameter subgroup coincide) and so are their tables. The θ = 0 step is the cheaper one
//!   (one τ and one d^{L*}τ per iteration instead of two).
//!
//! Shipped: [`ModifiedLiePoisson`] for the free rigid body (any symmetric 𝕀: the tables are
//! written in the principal frame, which the Ad-equivariance of exp and Cayley on SO(3) makes
//! valid for every quadratic Hamiltonian ½ Π·AΠ, A symmetric) with [`ModifiedScheme`]: θ ∈ {½, 0},
//! order ∈ {4, 6}, τ ∈ {exp, Cayley}. Measured orders: `tests/modified.rs`.
//!
//! Not shipped: other groups. The derivation expands the scheme in SO(3)'s closed forms of τ and
//! d^{L*}τ; on SE(3) or SO(n) the Cayley map depends on the matrix representation and no table
//! was derived or verified there. Systems with a potential: the modified Hamiltonian then involves
//! brackets with V(g) (not derived).

mod coefficients;
mod modified_lie_poisson;
mod modified_rigid_body;

use integrators::IntegratorError;
pub use modified_lie_poisson::ModifiedLiePoisson;
pub use modified_rigid_body::{ModifiedRigidBody, ModifiedTau, CURVATURE_LIMIT};

/// Which modified Hamiltonian the Lie–Poisson kernel integrates: θ ∈ {½, 0} of the kernel and the
/// order 4 (`H − h²H₂`) or 6 (`H − h²H₂ − h⁴H₄`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModifiedScheme {
    theta: f64,
    order: u32,
}

impl ModifiedScheme {
    /// θ ∈ {0, 0.5} and order ∈ {4, 6}; anything else is an
    /// [`IntegratorError::InvalidParameter`] naming the value (only these were derived).
    pub fn new(theta: f64, order: u32) -> Result<Self, IntegratorError> {
        if theta != 0.5 && theta != 0.0 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "the modified Hamiltonian is derived for θ = 0.5 and θ = 0, got θ = {theta}"
                ),
            });
        }
        if order != 4 && order != 6 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "the modified Hamiltonian is derived to order 4 and 6, got order {order}"
                ),
            });
        }
        Ok(Self { theta, order })
    }
    /// θ of the kernel.
    pub fn theta(&self) -> f64 {
        self.theta
    }
    /// The order of the modified method.
    pub fn order(&self) -> u32 {
        self.order
    }
}

/// θ = ½, order 4: the scheme of the first version of this module.
impl Default for ModifiedScheme {
    fn default() -> Self {
        Self {
            theta: 0.5,
            order: 4,
        }
    }
}
