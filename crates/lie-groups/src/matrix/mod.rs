//! Dense matrix functions on faer (inverse, exponential, logarithm) and the matrix groups of any
//! size built on them: SO(n) and GL(n).

pub mod dense;
pub mod gl_n;
pub mod logm;
pub mod so_n;

pub use gl_n::GlN;
pub use so_n::SoN;
