//! Honest baselines, for comparison in tests, benches and the work-precision table: classical
//! methods that are accurate (order 4) and cheap but preserve less structure than the variational
//! integrators of this crate.
//!
//! - [`QuaternionRk4`]: explicit RK4 on (unit quaternion, body momentum) with renormalisation of
//!   the quaternion after each step, for any system on SO(3). Keeps R orthogonal; lets the energy
//!   and the Casimir |Π|² drift secularly.
//! - [`Rkmk4`]: Runge–Kutta–Munthe-Kaas of order 4 (classical tableau, with the brackets of
//!   `(d^L exp_Θ)⁻¹` that matter to order 4 collected as by Munthe-Kaas and Owren: two a step) on
//!   any Lie group, g ∈ G to round-off; energy and Casimirs drift as with RK4.
//!
//! - [`QuaternionDopri5`] and [`QuaternionDop853`]: the embedded Dormand–Prince 5(4) and DOP853
//!   pairs on (q, Π) with the quaternion renormalized, what a scipy user would run with
//!   `solve_ivp(method="RK45" | "DOP853", rtol, atol)`; they are [`crate::adaptive::EmbeddedPair`]s
//!   run to a tolerance by [`crate::adaptive::Adaptive`] (`benches/adaptive.rs` measures them
//!   against `ode_solvers`' `Dopri5` and `Dop853` on the same right-hand side).
//!
//! All implement [`crate::Integrator`], so any driver runs them next to
//! [`crate::LiePoisson`] and [`crate::EulerPoincare`]. Measured (`tests/baselines.rs`): order 4 for
//! both on the free rigid body and the heavy top, and for `Rkmk4` on SE(3).

mod quaternion_pair;
mod quaternion_state;
mod rk4;
mod rkmk;

pub use quaternion_pair::{QuaternionDop853, QuaternionDopri5, QuaternionPair};
pub use rk4::QuaternionRk4;
pub use rkmk::Rkmk4;
