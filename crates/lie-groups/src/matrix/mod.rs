//! The matrix groups of any size on faer, SO(n) and GL(n) (feature `faer`), with the dense
//! functions on faer matrices they are built on.

pub mod dense;
pub mod gl_n;
pub mod so_n;

pub use gl_n::GlN;
pub use so_n::SoN;
