//! The families of methods the work-precision plot colours alike.

use plotters::style::RGBColor;

/// A family of methods, drawn in one colour.
#[derive(Debug, PartialEq, Eq)]
pub struct Family {
    /// Its name in the plot's legend order.
    pub name: &'static str,
    /// Its colour.
    pub color: RGBColor,
}

/// Lie–Poisson.
pub const LIE_POISSON: Family = Family {
    name: "lie-poisson",
    color: RGBColor(31, 119, 180),
};
/// The compositions of Lie–Poisson.
pub const COMPOSITIONS: Family = Family {
    name: "compositions",
    color: RGBColor(44, 160, 44),
};
/// The modified Hamiltonians.
pub const MODIFIED: Family = Family {
    name: "modified",
    color: RGBColor(227, 119, 194),
};
/// Every processed method.
pub const PROCESSED: Family = Family {
    name: "processed",
    color: RGBColor(23, 190, 207),
};
/// Euler–Poincaré.
pub const EULER_POINCARE: Family = Family {
    name: "euler-poincare",
    color: RGBColor(255, 127, 14),
};
/// Euler–Arnold.
pub const EULER_ARNOLD: Family = Family {
    name: "euler-arnold",
    color: RGBColor(140, 86, 75),
};
/// The splittings (Strang, its compositions, the kinetic–kick).
pub const SPLITTING: Family = Family {
    name: "splitting",
    color: RGBColor(148, 103, 189),
};
/// The Casimir splitting of the free body (its coefficients and folded compositions).
pub const CASIMIR_SPLITTING: Family = Family {
    name: "casimir-splitting",
    color: RGBColor(127, 127, 127),
};
/// The exact flow.
pub const EXACT: Family = Family {
    name: "exact",
    color: RGBColor(0, 0, 0),
};
/// The Runge–Kutta baselines.
pub const RUNGE_KUTTA: Family = Family {
    name: "rk4/rkmk4",
    color: RGBColor(214, 39, 40),
};
/// The embedded pairs run to a tolerance.
pub const ADAPTIVE: Family = Family {
    name: "tolerance-driven",
    color: RGBColor(188, 189, 34),
};
