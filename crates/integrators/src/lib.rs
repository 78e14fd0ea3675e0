//! # integrators
//!
//! Structure-preserving integrators for mechanical systems on a Lie group G (§2–§4 of
//! *Numerical Integrators for Mechanical Systems on Lie Groups*), generic over the group
//! `G: LieGroup`, the τ map `T: Tau<G>` (exp, Cayley) and the parameter θ ∈ [0, 1] of the
//! discretization map `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))`:
//!
//! - [`LiePoisson`]: the cotangent lift, eq. (19), state (g, μ) — the general-θ form of §4's scheme
//!   (with the sign of NOTES.md slip 2 corrected). Keeps μ on its coadjoint orbit: Casimirs are
//!   conserved to round-off.
//! - [`EulerPoincare`]: the tangent lift, eq. (18), state (g, ξ).
//!
//!   Both are assembled from the discretization layer: [`CotangentLiftIntegrator`] and
//!   [`TangentLiftIntegrator`] are written against `discretization::LiftedMap` alone (the fused
//!   components of T*R̃_d⁻¹, R̃_d^{T*} and T R̃_d with their Newton derivatives) and add only the
//!   vector field, the solver and the state; `LiePoisson<G, T, S>` and `EulerPoincare<G, T, S>` are
//!   these for the left-trivialized `DiscretizationMap<T>`; with `RightDiscretizationMap<T>` they
//!   integrate right-invariant systems in the spatial frame (`tests/right_trivialized.rs`). A new
//!   map implementing `LiftedMap` gets
//!   its integrators with no integrator code (`tests/assembled_step.rs` checks the assembled steps
//!   against the hand-derived schemes on SO(3), SE(3), SE(2) and SO(4)).
//! - [`EulerArnold`]: the quadratic-Lagrangian system l(ξ) = ½⟨𝕀ξ, ξ⟩ both integrate.
//! - [`splitting`]: explicit Poisson splittings into pieces with exact flows (Strang, with
//!   [`Composition`] to order 10; exact kinetic flow + kicks with Blanes–Moan coefficients).
//! - [`processing`]: processed methods `P ∘ Kⁿ ∘ P⁻¹` of any symmetric method — effective order
//!   6 and 8 from fewer basic steps than a composition of that order, P applied only when the
//!   state is read ([`processing::Processed`]).
//! - [`baselines`]: classical RK4 on (q, Π) and RKMK4, measured beside the geometric methods.
//! - [`GraggBulirschStoer`] ([`gragg_bulirsch_stoer`]): a reference method — Gragg–Bulirsch–Stoer
//!   extrapolation of order 2k in exponential coordinates, explicit, keeping only g on G — that
//!   shares no discretization with the methods above, so that it can measure them (`lie-sim
//!   trade` refines it until two runs agree to a tolerance).
//! - [`forces`]: external forces and controls `F_ext(t, g, ξ)` ([`forces::Forced`], scheduled body
//!   torques, controls u(t) through an input map `F = B(g)u(t)` ([`forces::ControlInput`]),
//!   damping and quadratic drag), applied by Lie–Poisson, Euler–Poincaré, RK4 and RKMK4 in the discrete
//!   Lagrange–d'Alembert way (`tests/forces.rs`: orders 2/1/4, exact momentum-map balance) and by
//!   the splittings in their kicks (`tests/forced_splitting.rs`: a torque keeps Blanes–Moan 4 at
//!   order 4.0, damping makes every splitting order 2.0, the momentum map moves by the applied
//!   impulse to 1.5e-15 per step).
//! - [`adaptive`]: tolerance-driven runs — embedded pairs (Dormand–Prince 5(4), DOP853) in the
//!   algebra (RKMK, any group) and on (q, Π), run to `rtol`/`atol` by a PI controller, with
//!   output times and events inside the variable steps (see the section below); and variable
//!   steps for the symmetric methods that keep them reversible ([`adaptive::ReversibleSteps`],
//!   Hairer–Söderlind's step-density controller, the density from [`System::step_density`]):
//!   energy without drift where the pairs' energy drifts.
//! - [`dense_output`] and [`events`]: the state between steps by a cubic Hermite interpolant on
//!   G × 𝔤* (`g₀ exp Z(s)`), output at requested times and zero crossings of event functions
//!   located to a tolerance, for any integrator ([`dense_output::integrate_dense`]).
//!
//! Every integrator describes itself ([`Integrator::info`] → [`MethodInfo`]: order, symmetric,
//! explicit, what it keeps). Which to choose, with measured costs per accuracy: `docs/choosing.md`
//! and `docs/work-precision.md` of the repository.
//!
//! A system is anything implementing [`System`] (reduced Hamiltonian h(μ), its derivatives, the
//! Legendre map, an optional potential V(g) and Casimir); the ready-made ones — the rigid bodies,
//! tops, satellites and vehicles of docs/vehicles.md — and the methods that exist for one model
//! only (the exact free rigid body flow, the modified-Hamiltonian steps) are in the `mechanics`
//! crate, above this one, so that a user with a system of their own compiles none of them.
//! [`derivative_check`] compares a hand-written system's derivatives with finite differences (see
//! docs/custom-systems.md and `examples/custom_system.rs` of the repository). Every
//! integrator implements [`Integrator`] (step, time, μ, optional g, energy, Casimir), so one generic
//! function drives any (system, method, τ, θ) combination. Implicit steps are solved by the
//! iteration chosen in [`SolverConfig`]; a failed step returns an [`IntegratorError`] and leaves the
//! state untouched. Reconstruction is optional: pass `None` for g to integrate μ alone.
//!
//! ## Measured orders (free rigid body on SO(3), `tests/order.rs`)
//! | method | τ | θ | order |
//! |---|---|---|---|
//! | Lie–Poisson | exp, Cayley | 0, ½, 1 | 2 |
//! | Euler–Poincaré | exp, Cayley | 0, 1 | 1 |
//! | Euler–Poincaré | exp, Cayley | ½ | 2 |
//!
//! With a potential (`tests/potential.rs`), Lie–Poisson θ = 0 and θ = 1 drop to order 1 and θ = ½
//! stays at order 2.
//!
//! ## Tolerance-driven runs
//!
//! Ask for an accuracy, not a step: [`adaptive::Adaptive`] runs a method with an error
//! estimate to a [`adaptive::Tolerance`] (`rtol`, `atol`, as scipy's `solve_ivp` and diffsol
//! name them), choosing each step by a PI controller, rejecting (and counting) the steps that
//! miss it with the state untouched, and landing exactly on the end time. The methods:
//! [`adaptive::RkmkDopri5`] and [`adaptive::RkmkDop853`] on any group (g on G to round-off, the
//! error measured on the group as log(ĝ⁻¹g)), and the plain baselines
//! [`baselines::QuaternionDopri5`], [`baselines::QuaternionDop853`] on (q, Π). Output at
//! requested times and events are evaluated inside the accepted steps by partial steps, at the
//! method's accuracy ([`adaptive::Adaptive::solve`]). The error at T follows the tolerance
//! (`tests/methods/adaptive_tolerance.rs` prints the table: within 0.9–4.4× on the free body
//! to T = 10, 6–36× on the fast heavy top to T = 5, where the Dormand–Prince pairs' many steps
//! add up).
//!
//! ```
//! use integrators::adaptive::{Adaptive, RkmkDopri5, Tolerance};
//! use integrators::events::{Direction, Event};
//! use integrators::Integrator;
//! use mechanics::HeavyTop;
//! use lie_groups::{LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! let top = HeavyTop::principal([1.0, 1.5, 0.5], 1.0, 9.81, Vector3::new(0.1, 0.0, 1.0))?;
//! let method = RkmkDopri5::new(top, Vector3::new(0.5, 0.3, 10.0), Some(So3::identity()))?;
//! let mut run = Adaptive::new(method, Tolerance::new(1e-8, 1e-10)?);
//! // The body axis e₃ rising through the horizontal plane: (R e₃)·e₃ = R₃₃ crossing 0.9.
//! let tilt = Event::new(|_t, _pi: &Vector3<f64>, r: Option<&So3>| r.unwrap().as_matrix()[(2, 2)] - 0.9)
//!     .direction(Direction::Falling);
//! let mut trace = Vec::new();
//! let out = run.solve(5.0, &[1.0, 2.0, 3.0, 4.0], |t, pi, _r| trace.push((t, pi.z)), &[tilt])?;
//! assert_eq!(run.method().time(), 5.0);
//! assert_eq!(trace.iter().map(|s| s.0).collect::<Vec<_>>(), [1.0, 2.0, 3.0, 4.0]);
//! let stats = run.stats();
//! println!("{} steps accepted, {} rejected, h in [{:.1e}, {:.1e}], {} tilts",
//!     stats.accepted, stats.rejected, stats.min_step, stats.max_step, out.hits.len());
//! # Ok::<(), integrators::IntegratorError>(())
//! ```
//!
//! ## Example: the free rigid body
//! ```
//! use integrators::{integrate, Integrator, LiePoisson};
//! use mechanics::RigidBody;
//! use lie_groups::{Cayley, LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let pi0 = Vector3::new(0.5, 1.0, 0.2);
//! // θ = ½, τ = Cayley, reconstructing R(t) from R(0) = I.
//! let mut lp = LiePoisson::<So3, Cayley, _>::new(body, 0.5, pi0, Some(So3::identity()))?;
//! let e0 = lp.energy();
//! integrate(&mut lp, 0.01, 1000, |_| {})?;
//! assert!((lp.time() - 10.0).abs() < 1e-12);
//! assert!((lp.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-13);
//! assert!((lp.energy() - e0).abs() < 1e-4 * e0);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

#![warn(missing_docs)]

pub mod adaptive;
pub mod baselines;
mod carried_state;
pub mod checks;
pub mod clock;
mod compensated;
pub mod compose;
pub mod dense_output;
pub mod derivative_check;
pub mod ensemble;
mod error;
pub mod euler_arnold;
pub mod euler_poincare;
pub mod events;
pub mod forces;
pub mod gragg_bulirsch_stoer;
mod integrator;
pub mod lie_poisson;
pub mod processing;
pub mod solver;
pub mod splitting;
pub(crate) mod step_state;
mod system;
mod unroll;
pub mod warm_start;

pub use baselines::{QuaternionRk4, Rkmk4};
pub use clock::Clock;
pub use compose::{Composition, CompositionScheme, StateSnapshot, SymmetricMethod};
pub use error::IntegratorError;
pub use euler_arnold::{EulerArnold, EulerArnoldEulerPoincare, EulerArnoldLiePoisson};
pub use euler_poincare::{EulerPoincare, TangentLiftIntegrator};
pub use gragg_bulirsch_stoer::GraggBulirschStoer;
pub use integrator::{integrate, Integrator, MethodInfo};
/// The layer below, and nalgebra through it, re-exported: depending on this crate alone is
/// enough to write a system and integrate it (`integrators::lie_groups::So3`,
/// `integrators::nalgebra::Vector3`).
pub use lie_groups::{self, nalgebra};
pub use lie_poisson::{CotangentLiftIntegrator, LiePoisson};
pub use solver::{SolverConfig, SolverKind};
pub use step_state::RENORMALIZE_AFTER;
pub use system::{euclidean_norm, DensityScope, System};
pub use warm_start::WarmStart;

/// The README's example (the crate's page on crates.io), compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
