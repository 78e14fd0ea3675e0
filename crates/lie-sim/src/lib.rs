//! The machinery of the `lie-sim` command as a library: scenes ([`scene`]), the method registry
//! ([`methods`]), the systems ([`systems`]), building a scene's simulation ([`build`]) and running
//! it ([`run`]), `trade`, `sweep`, `choose` and `plot`. The command itself (`src/main.rs`) parses
//! its arguments and calls these; the library exists so that benchmarks (the workspace's `benches/run_loop.rs`)
//! and tools can drive the same code path. It is not a stable API: depend on the layered crates
//! (`lieflow-integrators`, `lieflow-mechanics`, …) for that.
//!
//! The scene format is documented in [`scene`]; examples live in `examples/scenes/`.

pub mod attitude;
pub mod batched;
pub mod body_stats;
pub mod bounds;
pub mod build;
pub mod choose;
pub mod columns;
pub mod driven;
pub mod driver;
pub mod error;
#[cfg(test)]
pub mod extremes;
pub mod fields;
pub mod forces;
#[cfg(test)]
pub mod harness;
pub mod input;
pub mod invariants;
pub mod ladder;
pub mod listing;
pub mod many_bodies;
pub mod measure;
pub mod methods;
pub mod model;
pub mod output;
pub mod plot;
pub mod reference;
pub mod run;
pub mod scene;
pub mod sim;
pub mod stepping;
pub mod sweep;
pub mod systems;
pub mod taus;
pub mod trade;
