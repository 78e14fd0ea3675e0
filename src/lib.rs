//! Umbrella crate of the workspace: re-exports the layered crates so that the top-level benchmarks
//! and examples can reach all of them through one dependency.
//!
//! Users depend on the layer they need (`lie-groups`, `trivial-bundles`, `discretization`,
//! `integrators`, `mechanics`); this crate only gathers them.
pub use batch;
pub use discretization;
pub use integrators;
pub use lie_groups;
pub use mechanics;
pub use trivial_bundles;

/// The README's Rust snippet, compiled and run as a doctest (it must work as written).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
