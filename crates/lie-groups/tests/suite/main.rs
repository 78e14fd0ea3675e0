//! The lie-groups crate's integration tests, one binary: a module per topic.

mod adjoint_increment;
mod composite_groups;
mod dual_derivative;
mod extremes;
mod matrix_groups;
mod se3;
mod so2_se2;
mod so3;
