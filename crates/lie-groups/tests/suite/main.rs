//! The lie-groups crate's integration tests, one binary: a module per topic.

mod actions;
mod adjoint_increment;
mod composite_groups;
mod dual_derivative;
mod extremes;
mod manif_names;
#[cfg(feature = "faer")]
mod matrix_groups;
mod se3;
mod so2_se2;
mod so3;
