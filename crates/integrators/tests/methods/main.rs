//! The integrators crate's integration tests, one binary: a module per topic.

#[path = "../common/mod.rs"]
mod common;

mod adaptive_orders;
mod adaptive_pairs;
mod adaptive_tableaux;
mod adaptive_tolerance;
mod assembled_step;
mod baselines;
mod casimir_drift;
mod casimir_splitting;
mod compose;
mod control_input;
mod controller;
mod dense_output;
mod derivative_check;
mod diagonal_velocity;
mod ensemble;
mod error_floor;
mod euler_arnold_field;
mod forced_splitting;
mod forces;
mod gragg_bulirsch_stoer;
mod invariants;
mod lifted_maps;
mod newton_jacobian;
mod no_alloc;
mod order;
mod potential;
mod processing;
mod product_groups;
mod reversible_steps;
mod right_trivialized;
mod robustness;
mod rod_separatrix;
mod splitting;
mod time_exact;
mod user_map;
mod warm_start;
