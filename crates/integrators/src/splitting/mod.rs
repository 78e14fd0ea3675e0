//! Explicit splitting integrators: the Lie–Poisson system `μ̇ = ad*_{∂h/∂μ} μ + F(g)`, `ġ = g ∂h/∂μ`
//! (§2 of the paper) with `h = Σᵢ hᵢ` split into pieces whose flows are exact and explicit, and the
//! potential V(g) as a kick (McLachlan 1993, "Explicit Lie–Poisson integration and the Euler
//! equations", Phys. Rev. Lett. 71; Touma–Wisdom 1994; Dullweber–Leimkuhler–McLachlan 1997,
//! "Symplectic splitting methods for rigid body molecular dynamics", J. Chem. Phys. 107).
//!
//! - A **kinetic piece** hᵢ with an explicit flow, declared by [`SplitSystem`]: when its velocity
//!   `ξᵢ = ∂hᵢ/∂μ` is constant along its own flow, the one-parameter subgroup
//!   `μ(t) = Ad*_{exp(tξᵢ)} μ`, `g(t) = g exp(tξᵢ)` (a rotation about a principal axis aᵢ,
//!   `hᵢ = (aᵢ·Π)²/2Iᵢ`; a translation); otherwise a closed form the system provides (the free
//!   body's axisymmetric piece `|Π|²/2I_r + ½(1/I_s − 1/I_r)(a_s·Π)²`, the product of two
//!   commuting one-parameter flows: `mechanics::RigidBody`).
//! - The **potential piece** V(g): g is fixed, so its flow is the kick `μ ↦ μ + t F(g)`,
//!   `F(g) = −T*_e L_g dV(g)`.
//! - **External forces** ([`crate::forces::Forced`] systems): F_ext(t, g, ξ) joins the kick at the
//!   kick's time (the kinetic flows advance t). Forces of (t, g) alone — body torques, control
//!   schedules — are kicked exactly, so the schemes keep their order; forces that read ξ (damping,
//!   drag) are kicked by the implicit midpoint rule (a fixed-point iteration, still explicit in the
//!   sense of no Newton matrix), symmetric and of order 2.
//! - A whole **exact kinetic flow** ([`KineticFlow`]): the flow of h itself, when it is known in
//!   closed form (in the `mechanics` crate: the axisymmetric body, `mechanics::exact::AxisymmetricFlow`;
//!   the general free body, `mechanics::exact::FreeBodyFlow`).
//!
//! Every piece's flow is a Poisson map that maps each coadjoint orbit to itself, so every splitting
//! is a Poisson integrator, keeps the Casimirs of an invariant system to round-off, and keeps the
//! spatial momentum map `Ad*_{g⁻¹} μ` (each piece's flow does: `g exp(tξ)` and `Ad*_{exp(tξ)} μ`).
//! Integrators: [`Splitting`] (Strang over all pieces: order 2, symmetric, so that
//! [`crate::Composition`] raises it to order 4, 6, 8, 10), [`KineticKick`] (exact kinetic flow
//! and kicks with the coefficients of a [`SplittingScheme`]: Strang, Blanes–Moan order 4 and 6)
//! and [`CasimirSplitting`] (a free system `h = C + h_A + h_B` with C a Casimir function,
//! declared by [`CasimirSplit`]: C's flow commutes with the others, so it is applied once a step
//! and a [`SplittingScheme`] splits `h_A + h_B` alone).
//!
//! ## Which splitting
//! - **The free rigid body**: [`CasimirSplitting`], C = |Π|²/2I_r with the middle moment, A and B
//!   rotations about the two other principal axes. With the Strang scheme it is the same map as
//!   [`Splitting`]; of higher order, Blanes–Moan 6 or a composition of Strang folded into one
//!   scheme ([`SplittingScheme::strang_composed`], e.g. Kahan–Li 8) apply the one Rodrigues
//!   product of C once a step, where [`crate::Composition`] of [`Splitting`] applies it at every
//!   stage — every other flow being a plane rotation, that product is much of a stage's cost.
//! - **A body in a potential or under forces** (the heavy top, the SE(3) body): [`Splitting`]
//!   and its compositions, or [`KineticKick`] where the kinetic flow is known in closed form
//!   (the kick is then the only discretised part). C no longer commutes with the potential.
//!
//! Systems without such a splitting (the generalized rigid body on SO(n): its pieces' velocities
//! are not constant along their flows, and no closed form is known) do not implement
//! [`SplitSystem`]; a scene that asks for a splitting of one is refused by name.
//!
//! ## Example: the splitting of the free rigid body, composed to order 6
//! ```
//! use integrators::{splitting::Splitting, Composition, CompositionScheme, Integrator};
//! use mechanics::RigidBody;
//! use lie_groups::{LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let pi0 = Vector3::new(0.5, 1.0, 0.2);
//! let strang = Splitting::new(body, pi0, Some(So3::identity()))?;
//! let mut psi = Composition::new(strang, CompositionScheme::kahan_li_6())?;
//! for _ in 0..100 {
//!     psi.step(0.05)?;
//! }
//! assert!((psi.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-14);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

mod casimir_split;
mod casimir_splitting;
mod kick;
mod kinetic_kick;
mod scheme;
mod split_system;
mod strang;

pub use kick::KICK_MAX_ITERATIONS;

/// The rounded products a splitting step forms g_{k+1} in, as far as its renormalization is
/// concerned (crate::step_state): each piece's flow multiplies g by an exact group element — three
/// rotations and one Rodrigues product for the free body — so g leaves the group by a random walk
/// of about this many roundings a step.
pub(crate) const PRODUCTS_PER_STEP: u32 = 4;

/// A splitting renormalizes g onto the group every this many steps: once
/// [`crate::RENORMALIZE_AFTER`] rounded products have accumulated (four a step),
/// ‖gᵀg − I‖ ≈ ε√(4k) ≲ 1e-14 in between.
pub const RENORMALIZE_EVERY: u32 = crate::step_state::renormalize_every(PRODUCTS_PER_STEP);
pub use casimir_split::CasimirSplit;
pub use casimir_splitting::CasimirSplitting;
pub use kinetic_kick::{KineticFlow, KineticKick};
pub use scheme::SplittingScheme;
pub use split_system::SplitSystem;
pub use strang::Splitting;
