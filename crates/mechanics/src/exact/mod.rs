//! Exact flows: the axisymmetric body ([`AxisymmetricFlow`]), the free rigid body in closed form ([`FreeBodyFlow`], with the elliptic functions
//! of [`elliptic`]; on SE(3), [`FreeBodySe3Flow`]) and the integrator that steps with it ([`ExactFreeBody`]).
//!
//! The exact flow is a method of its own (no truncation error, cost independent of the step), the
//! kinetic part of the splittings [`integrators::splitting::KineticKick`] for forced bodies (heavy top,
//! satellite), and the reference of work-precision measurements on free-body scenes.

mod axisymmetric_flow;
pub mod elliptic;
mod exact_free_body;
mod free_body_flow;
mod free_body_se3_flow;

pub use axisymmetric_flow::AxisymmetricFlow;
pub use exact_free_body::ExactFreeBody;
pub use free_body_flow::{EllipticOrbit, FreeBodyFlow};
pub use free_body_se3_flow::FreeBodySe3Flow;
