//! The discretization crate's integration tests, one binary: a module per topic.

#[path = "../common/mod.rs"]
mod common;

mod composed_lift;
mod flows;
mod lifted_map;
mod maps;
mod right_map;
mod vector_space;
