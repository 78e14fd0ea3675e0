//! Tolerance-driven runs: ask for an accuracy, not a step.
//!
//! A user states the accuracy as tolerances — scipy's `solve_ivp(rtol, atol)`, diffsol's
//! `rtol`/`atol` — and the step follows from them. This module gives the one-step methods with
//! an error estimate that:
//!
//! - [`RkmkDopri5`] and [`RkmkDop853`]: Runge–Kutta–Munthe-Kaas with the Dormand–Prince 5(4)
//!   and DOP853 pairs ([`ButcherPair`], [`DormandPrince54`], [`Dop853`]) in the algebra, for any
//!   system on any group; the error is the distance on the group `log(ĝ⁻¹g)` and on μ
//!   ([`rkmk_pair`]). g stays on G to round-off.
//! - [`crate::baselines::QuaternionDopri5`] and [`crate::baselines::QuaternionDop853`]: the same
//!   pairs on (q, Π) with the quaternion renormalized, what a scipy user would write.
//!
//! Each implements [`EmbeddedPair`] (a step to a given time with its scaled error, leaving the
//! state untouched when it is rejected) and is run by [`Adaptive`] with a [`Tolerance`] and a
//! PI [`Controller`] (Gustafsson; safety factor, growth and shrink limits; the pair's own
//! defaults from Hairer's codes). [`Adaptive::advance_to`] lands exactly on the end time,
//! counts accepted and rejected steps and the smallest and largest step ([`Stats`]);
//! [`Adaptive::solve`] adds output at requested times and events, evaluated inside the accepted
//! steps by partial steps of the method (the method's accuracy, no interpolation error; the
//! step sequence does not depend on them). Bad input is refused with an error that names it:
//! `rtol` or `atol` not finite and > 0, `rtol` below 100 ε ([`Tolerance::new`]); a step the
//! controller shrinks below the minimum ([`crate::IntegratorError::StepSizeUnderflow`]), with
//! the state at the last accepted step.
//!
//! The pairs' steps are chosen from the past, so a symmetric method run with them is no longer
//! symmetric and its energy drifts. For the symmetric methods (the splittings and their
//! compositions, kinetic–kick, Lie–Poisson and Euler–Poincaré θ = ½) [`ReversibleSteps`] gives
//! variable steps that keep them symmetric and reversible: the explicit step-density controller
//! of Hairer–Söderlind (2005), h_n = ε/ρ_{n+½} with ρ driven by the system's density
//! ([`crate::System::step_density`], [`crate::System::step_density_rate`]); no error estimate,
//! ε is the accuracy knob; energy without drift, Casimirs and momentum maps as the method keeps
//! them ([`reversible_steps`]: the formulas, why they are reversible, how T and output times are
//! reached without feeding back into the steps).
//!
//! The controller is independent of the method ([`Controller::decide`] takes a scaled error and
//! returns accept/reject and the step factor), so other methods with an error estimate can use
//! it.
//!
//! # Example: the free rigid body to 1e-10
//!
//! ```
//! use integrators::adaptive::{Adaptive, RkmkDop853, Tolerance};
//! use integrators::Integrator;
//! use mechanics::RigidBody;
//! use lie_groups::{LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! let body = RigidBody::principal([2.0, 3.0, 4.0])?;
//! let pi0 = Vector3::new(1.0, 0.5, -0.3);
//! let method = RkmkDop853::new(body, pi0, Some(So3::identity()))?;
//! let mut run = Adaptive::new(method, Tolerance::new(1e-10, 1e-10)?);
//! let mut samples = Vec::new();
//! run.solve(10.0, &[2.5, 5.0, 7.5], |t, pi, _r| samples.push((t, *pi)), &[])?;
//! assert_eq!(run.method().time(), 10.0); // the last step lands on T
//! assert_eq!(samples[1].0, 5.0);         // output exactly at the requested times
//! let stats = run.stats();
//! println!(
//!     "{} steps ({} rejected), h in [{:.3}, {:.3}]",
//!     stats.accepted, stats.rejected, stats.min_step, stats.max_step
//! );
//! assert!((run.method().casimir().unwrap() - pi0.norm_squared()).abs() < 1e-9);
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

mod controller;
mod driver;
pub(crate) mod embedded_pair;
pub mod reversible_steps;
pub mod rkmk_pair;
mod tableau;
mod tolerance;

pub use controller::{Controller, Decision};
pub use driver::{Adaptive, Stats};
pub use embedded_pair::{starting_step, EmbeddedPair};
pub use reversible_steps::ReversibleSteps;
pub use rkmk_pair::{RkmkDop853, RkmkDopri5, RkmkPair};
pub use tableau::{ButcherPair, Dop853, DormandPrince54};
pub use tolerance::Tolerance;
