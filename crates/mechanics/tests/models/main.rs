//! The mechanics crate's integration tests, one binary: a module per model (and the exact
//! flow, the modified Hamiltonians). The independent references are the integrators crate's test
//! utilities, shared rather than copied.

#[path = "../../../integrators/tests/common/mod.rs"]
mod common;

mod exact_flow;
mod facts;
mod modified;
mod satellite_orbit;
mod systems_coupled_bodies;
mod systems_gyrostat;
mod systems_heavy_top;
mod systems_pendulum_3d;
mod systems_quadrotor;
mod systems_se2;
mod systems_se3;
mod systems_so_n;
mod systems_underwater_vehicle;
