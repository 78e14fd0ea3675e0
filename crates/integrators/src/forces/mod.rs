//! External forces and controls: `F_ext(t, g, ξ) ∈ 𝔤*` acting on a [`crate::System`], applied by
//! the integrators in the discrete Lagrange–d'Alembert way.
//!
//! A force is an [`ExternalForce`]: a left-trivialized (body-frame) covector depending on time t,
//! configuration g and body velocity ξ. [`Forced`] attaches one to any system; forces add up as
//! pairs `(a, b)`. Built in: [`BodyTorque`] (a constant or piecewise-linear [`Schedule`] of body
//! torque/force), [`ControlInput`] (a control u(t) through an input map, `F = B(g) u(t)`: wheel
//! motors, thrust, body torques; [`BodyInputMap`] for actuators fixed to the body),
//! [`LinearDamping`] (`F = −D ξ`, viscous damping or linear drag) and [`QuadraticDrag`]
//! (`Fᵢ = −dᵢ |ξᵢ| ξᵢ`).
//!
//! ## How each integrator applies the force
//! The forced equations are `μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ)`, `ġ = gξ`, ξ = ∂h/∂μ.
//! - **Lie–Poisson** (eq. 19): the impulse `h F_ext(t_k + θh, ḡ, η/h)` joins the potential's
//!   `h F(ḡ)` at the base point `ḡ` of the discretization map, with η the step's algebra vector:
//!   the discrete Lagrange–d'Alembert principle with the force at the map's base point and the
//!   velocity η/h it defines. θ = ½ stays symmetric for forces of g alone. The spatial momentum
//!   map changes by exactly the applied spatial impulse `h Ad*_{ḡ⁻¹} F_ext` per step.
//! - **Euler–Poincaré** (eq. 18): F_ext joins F(g) in the field `ξ̇ = ∂²h/∂μ² (ad*_ξ μ + F + F_ext)`
//!   evaluated at `(t_k + θh, ḡ, ξ)`.
//! - **RK4, RKMK4**: F_ext at each stage's time, configuration and velocity.
//! - **Splittings** ([`crate::splitting`]): F_ext joins the kick at the kick's time, exactly for
//!   forces of (t, g) ([`ExternalForce::reads_velocity`] false: the scheme keeps its order) and by the
//!   implicit midpoint rule for forces that read ξ (order 2, symmetric). [`Forced`] is a
//!   `SplitSystem` when its system is.
//! - The exact free-body flow as a method takes the free body alone.
//!
//! The Newton matrix of the implicit steps omits `∂F_ext/∂ξ` (as it omits the potential's
//! derivative): strong forcing (`h ‖∂F_ext/∂ξ‖ ≳ 1`) slows or stops the iteration, which then
//! fails with an error and leaves the state as it was.
//!
//! ```
//! use integrators::forces::{BodyTorque, Forced, LinearDamping};
//! use integrators::{Integrator, LiePoisson};
//! use mechanics::RigidBody;
//! use lie_groups::{ExpMap, LieGroup, So3};
//! use nalgebra::{Matrix3, Vector3};
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! // a torque of 0.1 about the body's first axis, and viscous damping F = −0.05 ξ
//! let force = (
//!     BodyTorque::<So3>::constant(Vector3::new(0.1, 0.0, 0.0))?,
//!     LinearDamping::<So3>::new(Matrix3::identity() * 0.05)?,
//! );
//! let system = Forced::new(body, force);
//! let mut lp = LiePoisson::<So3, ExpMap, _>::new(system, 0.5, Vector3::new(0.0, 1.0, 0.0),
//!                                               Some(So3::identity()))?;
//! for _ in 0..100 {
//!     lp.step(0.01)?;
//! }
//! assert!(lp.momentum()[0] > 0.09); // the torque's impulse, less the damping
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

mod body_torque;
mod control_input;
mod damping;
mod external_force;
mod forced;
mod quadratic_drag;
mod schedule;

pub use body_torque::BodyTorque;
pub use control_input::{BodyInputMap, ControlInput, InputMap};
pub use damping::LinearDamping;
pub use external_force::ExternalForce;
pub use forced::Forced;
pub use quadratic_drag::QuadraticDrag;
pub use schedule::Schedule;
