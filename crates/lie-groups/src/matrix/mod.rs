//! Dense matrix functions on faer: inverse, exponential, logarithm.

pub mod dense;
pub mod logm;
