//! The lie-sim crate's integration tests, one binary: a module per topic.

#[path = "../common/mod.rs"]
mod common;

mod batched_sweep;
mod choose;
mod cli;
mod dense_output;
mod edges;
mod imports;
mod many_bodies;
mod outputs;
mod reference;
mod results;
mod reversible_steps;
mod trade;
mod vehicles;
