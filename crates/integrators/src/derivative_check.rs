//! Checking a user's [`System`] against finite differences of itself.
//!
//! A hand-derived velocity ∂h/∂μ, Hessian ∂²h/∂μ², Legendre map or potential differential that is
//! wrong does not make an integrator fail: a wrong Hessian only slows the Newton iteration (or
//! breaks Euler–Poincaré's vector field), a wrong `potential_differential` integrates another
//! system whose energy is not `h + V`. [`check_derivatives`] compares each against central
//! differences of the functions it is the derivative of, at states the user picks, and reports the
//! worst relative mismatch of each:
//!
//! - velocity: `∂h/∂μ` against the central differences of h along each basis covector;
//! - Hessian: `∂²h/∂μ²` against the central differences of ∂h/∂μ;
//! - Legendre map: `momentum(velocity(μ))` against μ (the two maps are inverse);
//! - potential differential: `⟨T*_e L_g dV(g), eᵢ⟩` against `d/ds V(g exp(s eᵢ))` (the
//!   left-trivialized convention of [`System::potential_differential`]), where the system has a
//!   potential and the sample has a g.
//!
//! Central differences with the step `δ = ε^{1/3} max(1, ‖x‖)` balance truncation and rounding
//! errors: a correct derivative shows mismatches of 1e-11 … 1e-8 (more where the function varies on
//! scales below δ), a wrong one O(1). [`DerivativeReport::passes`] compares with a tolerance,
//! [`DEFAULT_TOLERANCE`] = 1e-6 being a safe threshold between the two.
//!
//! ```
//! use integrators::derivative_check::check_derivatives;
//! use mechanics::HeavyTop;
//! use lie_groups::{LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
//! let samples = [
//!     (Vector3::new(0.5, 1.0, 0.2), Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)))),
//!     (Vector3::new(-2.0, 0.1, 3.0), Some(So3::exp(&Vector3::new(1.5, 0.2, -0.4)))),
//! ];
//! let report = check_derivatives(&top, &samples);
//! assert!(report.passes(1e-6), "{report}");
//! ```

use crate::System;
use lie_groups::{LieGroup, Operator, Vector};

/// A threshold between the finite-difference noise of correct derivatives (≤ 1e-8) and the
/// mismatch of wrong ones (O(1)).
pub const DEFAULT_TOLERANCE: f64 = 1e-6;

/// `ε^{1/3}`: the relative step of central differences.
const RELATIVE_STEP: f64 = 6.055e-6;

/// The worst relative mismatch of each derivative over the samples (`None` where not checked:
/// no potential, or no sample with a g).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DerivativeReport {
    /// `∂h/∂μ` against differences of h.
    pub velocity: f64,
    /// `∂²h/∂μ²` against differences of ∂h/∂μ.
    pub hessian: f64,
    /// `momentum(velocity(μ))` against μ.
    pub legendre: f64,
    /// `T*_e L_g dV(g)` against differences of `s ↦ V(g exp(s eᵢ))`.
    pub potential_differential: Option<f64>,
    /// The number of samples checked.
    pub samples: usize,
}

impl DerivativeReport {
    /// The largest of the mismatches.
    pub fn worst(&self) -> f64 {
        [
            self.velocity,
            self.hessian,
            self.legendre,
            self.potential_differential.unwrap_or(0.0),
        ]
        .into_iter()
        .fold(0.0, f64::max)
    }
    /// Whether every mismatch is at most `tolerance` (and finite).
    pub fn passes(&self, tolerance: f64) -> bool {
        self.worst() <= tolerance
    }
}

impl std::fmt::Display for DerivativeReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "worst relative mismatch over {} states: ∂h/∂μ {:.1e}, ∂²h/∂μ² {:.1e}, Legendre map {:.1e}",
            self.samples, self.velocity, self.hessian, self.legendre
        )?;
        match self.potential_differential {
            Some(d) => write!(f, ", dV {d:.1e}"),
            None => write!(f, ", dV not checked"),
        }
    }
}

/// `|a − b|_max / max(|b|_max, scale)`; infinite when either is not finite (`f64::max` would
/// drop a NaN, passing it).
fn mismatch<V: Vector>(a: &V, b: &V, scale: f64) -> f64 {
    if !a.is_finite() || !b.is_finite() {
        return f64::INFINITY;
    }
    a.sub(b).norm_max() / b.norm_max().max(scale).max(f64::MIN_POSITIVE)
}

/// Central difference of `f` at x along `e` with the step `δ = ε^{1/3} max(1, ‖x‖)`.
fn central<V: Vector, W: Vector>(x: &V, e: &V, f: impl Fn(&V) -> W) -> W {
    let d = RELATIVE_STEP * x.norm_max().max(1.0);
    f(&x.axpy(d, e)).sub(&f(&x.axpy(-d, e))).scale(0.5 / d)
}

/// Checks the system's derivatives at the samples `(μ, g)` (see the module page).
pub fn check_derivatives<G: LieGroup, S: System<G>>(
    system: &S,
    samples: &[(G::Algebra, Option<G>)],
) -> DerivativeReport {
    let n = G::dim();
    let mut report = DerivativeReport {
        velocity: 0.0,
        hessian: 0.0,
        legendre: 0.0,
        potential_differential: None,
        samples: samples.len(),
    };
    for (mu, g) in samples {
        let fd_velocity = G::Algebra::from_fn(n, |i| {
            let e = G::Algebra::basis(n, i);
            let d = RELATIVE_STEP * mu.norm_max().max(1.0);
            (system.hamiltonian(&mu.axpy(d, &e)) - system.hamiltonian(&mu.axpy(-d, &e))) * 0.5 / d
        });
        report.velocity = report
            .velocity
            .max(mismatch(&system.velocity(mu), &fd_velocity, 0.0));
        // the Hessian column by column, relative to its largest entry
        let hessian = system.hessian(mu);
        let columns: Vec<_> = (0..n)
            .map(|i| hessian.apply(&G::Algebra::basis(n, i)))
            .collect();
        let scale = columns.iter().map(Vector::norm_max).fold(0.0, f64::max);
        for (i, col) in columns.iter().enumerate() {
            let fd = central(mu, &G::Algebra::basis(n, i), |m| system.velocity(m));
            report.hessian = report.hessian.max(mismatch(col, &fd, scale));
        }
        let xi = system.velocity(mu);
        report.legendre = report
            .legendre
            .max(mismatch(&system.momentum(&xi), mu, 0.0));
        if let (Some(g), true) = (g, system.has_potential()) {
            let dv = system.potential_differential(g);
            let fd = G::Algebra::from_fn(n, |i| {
                let e = G::Algebra::basis(n, i);
                let d = RELATIVE_STEP;
                (system.potential(&g.compose(&G::exp(&e.scale(d))))
                    - system.potential(&g.compose(&G::exp(&e.scale(-d)))))
                    * 0.5
                    / d
            });
            let r = mismatch(&dv, &fd, 0.0);
            report.potential_differential =
                Some(report.potential_differential.unwrap_or(0.0).max(r));
        }
    }
    report
}

/// `K(g): ζ ↦ d/ds F(g exp(sζ))|_{s=0}`, `F = −T*_e L_g dV`, by central differences of the
/// system's dV along `g exp(±dζ)` (2n evaluations, error ~1e-10 relative): the provided
/// [`System::force_derivative`]; zero without a potential.
pub fn finite_difference_force_derivative<G: LieGroup, S: System<G> + ?Sized>(
    system: &S,
    g: &G,
) -> G::Operator {
    let n = G::dim();
    if !system.has_potential() {
        return G::Operator::identity(n).scale(0.0);
    }
    let d = RELATIVE_STEP;
    lie_groups::matrix_path::operator_from_column_fn::<G>(|j| {
        let e = G::Algebra::basis(n, j);
        let plus = system.potential_differential(&g.compose(&G::exp(&e.scale(d))));
        let minus = system.potential_differential(&g.compose(&G::exp(&e.scale(-d))));
        minus.sub(&plus).scale(0.5 / d)
    })
}

/// `(1/ρ) dρ/dt` of the system's step density of `scope` ([`System::step_density`]) along the
/// conservative flow `μ̇ = ad*_ξ μ + F(g)`, `ġ = g ξ`, ξ = ∂h/∂μ, by the central difference
/// `(ρ(μ + sμ̇, g exp(sξ)) − ρ(μ − sμ̇, g exp(−sξ))) / (2sρ)` with `s = ε^{1/3}/ρ`: the provided
/// [`System::step_density_rate`] (error ~1e-10 relative for a smooth density). With ρ even in μ
/// and h even in μ, the difference is odd in μ as G is. NaN where ρ is not finite and > 0.
pub fn finite_difference_step_density_rate<G: LieGroup, S: System<G> + ?Sized>(
    system: &S,
    mu: &G::Algebra,
    g: Option<&G>,
    scope: crate::DensityScope,
) -> f64 {
    let rho = system.step_density(mu, g, scope);
    if !(rho.is_finite() && rho > 0.0) {
        return f64::NAN;
    }
    let s = RELATIVE_STEP / rho;
    let xi = system.velocity(mu);
    let mut mu_dot = G::ad_dual_apply(&xi, mu);
    if let Some(force) = crate::system::force(system, g) {
        mu_dot = mu_dot.add(&force);
    }
    let at = |sign: f64| {
        let m = mu.axpy(sign * s, &mu_dot);
        let g = g.map(|g| G::exp_compose(g, &xi.scale(sign * s)));
        system.step_density(&m, g.as_ref(), scope)
    };
    (at(1.0) - at(-1.0)) / (2.0 * s * rho)
}

/// `∂²h/∂μ²` by central differences of ∂h/∂μ (2n velocity evaluations, error ~1e-10 relative):
/// the provided [`System::hessian`] for systems that do not give theirs.
pub fn finite_difference_hessian<G: LieGroup, S: System<G> + ?Sized>(
    system: &S,
    mu: &G::Algebra,
) -> G::Operator {
    let n = G::dim();
    lie_groups::matrix_path::operator_from_column_fn::<G>(|j| {
        central(mu, &G::Algebra::basis(n, j), |m| system.velocity(m))
    })
}
