//! Concrete mechanical systems, each implementing [`integrators::System`].
//!
//! | system | group | potential | conserved |
//! |---|---|---|---|
//! | [`RigidBody`] | SO(3) | — | energy, \|Π\|² |
//! | [`HeavyTop`] (= [`Pendulum3d`]) | SO(3) | `m g ⟨Rχ, e₃⟩` | energy, `⟨RΠ, e₃⟩` (Lagrange top: also Π₃) |
//! | [`RigidBodySe3`] | SE(3) | free, or MacCullagh central gravity | energy, `RΠ + x × RP` |
//! | [`PlanarBody`] | SE(2) | spring `½k\|x + Rc\|²`, gravity `−m⟨γ, x⟩` | energy, momentum maps |
//! | [`GeneralizedRigidBody`] | SO(n) | — | energy, `tr(M^{2k})` |
//! | [`Gyrostat`] | SO(3) × ℝᴷ | — (wheel torques: inputs) | `RΠ` and \|Π\|² under any wheel torque |
//! | [`UnderwaterVehicle`] | SE(3) | restoring `(W − B)x₃ + (W r_G − B r_B)·Rᵀe₃` | energy, `L₃`, `(RP)₁,₂` |
//! | [`Quadrotor`] | SE(3) | `m g x₃` (thrust, torques: inputs) | energy, `L₃`, `(RP)₁,₂` unforced |
//! | [`CoupledBodies`] | SE(3)ᴺ | springs between attachment points | energy, total momentum |

pub mod coupled_bodies;
pub mod geodesic_so_n;
pub mod gyrostat;
pub mod heavy_top;
pub mod pendulum_3d;
pub mod planar_body_se2;
pub mod quadrotor;
mod rigid_body;
pub mod rigid_body_se3;
pub mod underwater_vehicle;

pub use coupled_bodies::{CoupledBodies, Spring};
pub use geodesic_so_n::GeneralizedRigidBody;
pub use gyrostat::{Gyrostat, GyrostatAlgebra, GyrostatGroup};
pub use heavy_top::HeavyTop;
pub use pendulum_3d::Pendulum3d;
pub use planar_body_se2::PlanarBody;
pub use quadrotor::Quadrotor;
pub use rigid_body::RigidBody;
pub use rigid_body_se3::RigidBodySe3;
pub use underwater_vehicle::UnderwaterVehicle;
