//! The trivial-bundles crate's integration tests, one binary: a module per topic.

mod higher_products;
mod no_alloc;
mod suites;
mod trivialization;
mod tulczyjew;
