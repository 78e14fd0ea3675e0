//! Gragg–Bulirsch–Stoer extrapolation on a Lie group: a **reference method**, explicit and of
//! high order 2k, that shares no discretization with the structure-preserving methods of the crate.
//!
//! It exists to measure the others (`lie-sim trade` refines it until two runs agree to a
//! tolerance, and compares every candidate with the result), not to replace them: it keeps g on G
//! and nothing else — no Casimir, no momentum map, no energy — and costs k(k+1) + 1 evaluations of
//! the vector field per step.
//!
//! **Equations.** The left-trivialized equations of motion (crate page, [`crate::System`])
//!
//! ```text
//! ġ = g ξ,   ξ = ∂h/∂μ(μ),   μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ),   F = −T*_e L_g dV,
//! ```
//!
//! are written over one step, from (t_k, g_k, μ_k), in the exponential coordinates of the first
//! kind centred at g_k and in the increment of μ (Munthe-Kaas' device, as in
//! [`crate::baselines::Rkmk4`], with the exact dexp⁻¹ instead of its truncation):
//!
//! ```text
//! g = g_k exp(Θ),   μ = μ_k + δ,
//! Θ̇ = (d^L exp_Θ)⁻¹ ξ,   δ̇ = ad*_ξ μ + F(g_k exp Θ) + F_ext(t_k + s, g_k exp Θ, ξ),
//! Θ(0) = 0,   δ(0) = 0,
//! ```
//!
//! a smooth ODE on the vector space 𝔤 × 𝔤*, to which the classical theory applies unchanged.
//! The increments are added to μ by compensated summation (the crate's TwoSum, as the
//! Lie–Poisson and Euler–Poincaré steps do; *GNI* §VIII.5), so that over many steps μ carries the
//! rounding of one addition, not of all.
//! `(d^L exp_Θ)⁻¹ ξ = Σ_{m≥0} bₘ ad_Θᵐ ξ` with `x/(1 − e^{−x}) = Σ bₘ xᵐ` (b₀ = 1, b₁ = ½,
//! b₂ₘ = B₂ₘ/(2m)!, odd m > 1 zero) is summed by brackets alone until its terms fall below the
//! rounding of the sum ([`dexp_left_inv_series`]); it converges while the spectral radius of ad_Θ
//! is below 2π, and a step beyond that is refused ([`IntegratorError::StepTooLarge`]). Carrying
//! the increment δ rather than μ keeps the extrapolation's amplification of rounding errors on δ
//! = O(h|μ̇|), not on μ.
//!
//! **Step** (Hairer–Nørsett–Wanner, *Solving ODEs I*, §II.9, eqs. (9.13), (9.10)): for the
//! harmonic sequence n_j = 2j, j = 1 … k (Deuflhard's choice, HNW Table 9.2 ff.), Gragg's
//! modified midpoint rule with n_j substeps of h_j = h/n_j,
//!
//! ```text
//! y₁ = y₀ + h_j f(t₀, y₀),   y_{i+1} = y_{i−1} + 2 h_j f(t₀ + i h_j, y_i),   T_{j,1} = y_{n_j},
//! ```
//!
//! whose error has an expansion in even powers of h_j (Gragg 1964, HNW Thm. 9.1), then the
//! Aitken–Neville extrapolation to h_j → 0,
//!
//! ```text
//! T_{j,l+1} = T_{j,l} + (T_{j,l} − T_{j−1,l}) / ((n_j/n_{j−l})² − 1),
//! ```
//!
//! and the step takes `T_{k,k}` (order 2k): `g_{k+1} = g_k exp(Θ)`, `μ_{k+1} = μ_k + δ`. The
//! Lebesgue constant of the extrapolation (the factor by which it can amplify rounding errors of
//! the T_{j,1}) is Σ|weights| = 3.1, 6.2, 12.7, 26.4, 55.8, 119 for k = 3 … 8; the default
//! [`GraggBulirschStoer::DEFAULT_COLUMNS`] = 6 (order 12, 43 evaluations per step) keeps it at 26.
//!
//! **Forces.** The external force is evaluated at the substeps' times, so a force that is smooth
//! in t keeps order 2k; a kink (a piecewise-linear torque schedule's knot) inside a step lowers
//! the order of that step, and a driver that needs the full order ends its steps on the knots
//! (`lie-sim`'s reference does).
//!
//! Measured (`tests/gragg_bulirsch_stoer.rs`): order 2k (fitted 4.0, 6.0, 8.0 for k = 2, 3, 4) on
//! the symmetric top and on the damped, torqued principal-axis rotation against their closed
//! forms; on SE(3), SE(2) and SO(4) against independent classical RK4 runs. No allocation per step
//! for SO(3), SE(3), SE(2) (`tests/no_alloc.rs`).

use crate::compensated::two_sum;
use crate::step_state::{state_accessors, StepState, RENORMALIZE_AFTER};
use crate::system::force;
use crate::{Integrator, IntegratorError, System};
use lie_groups::{LieGroup, Vector};

/// `B₂ₘ/(2m)!` for m = 0 … 30, the even coefficients of `x/(1 − e^{−x}) = 1 + x/2 + Σ_{m≥1}
/// B₂ₘ/(2m)! x^{2m}` (b₀ = 1, b₂ = 1/12, b₄ = −1/720, …), the correctly rounded doubles of the
/// exact rationals (Python `fractions`: B_n from `Σ_{j<n+1} C(n+1, j) B_j = 0`, then
/// `float(B[2m] / factorial(2m))`). Checked in the unit tests against the exact first four and
/// against `(−1)^{m+1} 2 ζ(2m)/(2π)^{2m}` for every m.
pub const BERNOULLI_EVEN: [f64; 31] = [
    1.0,
    0.08333333333333333,
    -0.001388888888888889,
    3.306878306878307e-05,
    -8.267195767195768e-07,
    2.08767569878681e-08,
    -5.284190138687493e-10,
    1.3382536530684679e-11,
    -3.3896802963225827e-13,
    8.586062056277845e-15,
    -2.174868698558062e-16,
    5.5090028283602295e-18,
    -1.3954464685812522e-19,
    3.534707039629467e-21,
    -8.953517427037546e-23,
    2.267952452337683e-24,
    -5.744790668872202e-26,
    1.455172475614865e-27,
    -3.6859949406653103e-29,
    9.336734257095045e-31,
    -2.36502241570063e-32,
    5.990671762482134e-34,
    -1.5174548844682903e-35,
    3.843758125454189e-37,
    -9.736353072646691e-39,
    2.466247044200681e-40,
    -6.247076741820743e-42,
    1.5824030244644914e-43,
    -4.008273685948936e-45,
    1.0153075855569557e-46,
    -2.5718041582418717e-48,
];

/// `(d^L exp_Θ)⁻¹ ξ = ξ + ½[Θ, ξ] + Σ_{m≥1} B₂ₘ/(2m)! ad_Θ^{2m} ξ`, summed by brackets until two
/// consecutive even terms are below ε‖sum‖_∞ (or exactly zero). The terms fall like
/// `2 (ρ/2π)^{2m}` with ρ the spectral radius of ad_Θ (|Θ| on 𝔰𝔬(3)): ~8 terms at ρ = 0.1,
/// ~20 at ρ = 1. `None` when the series has not converged after [`BERNOULLI_EVEN`]'s 30 terms
/// (ρ ≳ 0.55 · 2π): the step is too large for exponential coordinates. No allocation for
/// fixed-size algebras.
pub fn dexp_left_inv_series<G: LieGroup>(
    theta: &G::Algebra,
    xi: &G::Algebra,
) -> Option<G::Algebra> {
    let odd = G::bracket(theta, xi);
    let mut sum = xi.axpy(0.5, &odd);
    let mut power = odd; // ad_Θ^{2m−1} ξ
    let mut small = 0;
    for &b in &BERNOULLI_EVEN[1..] {
        let even = G::bracket(theta, &power);
        let term = even.scale(b);
        sum = sum.add(&term);
        let size = term.norm_max();
        if size <= f64::EPSILON * sum.norm_max() {
            small += 1;
            if small == 2 {
                return sum.is_finite().then_some(sum);
            }
        } else {
            small = 0;
        }
        power = G::bracket(theta, &even);
    }
    None
}

/// The Gragg–Bulirsch–Stoer reference method of the module page, with k columns (order 2k), for
/// any system S (potential, external forces included) on any Lie group G.
///
/// State: time t, body momentum μ ∈ 𝔤*, and g ∈ G when reconstructed (`None` integrates μ alone,
/// only without a potential).
///
/// ```
/// use integrators::{GraggBulirschStoer, Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// // A body spinning about its principal axis e₃: Π constant, R(t) = exp(t Π₃/I₃ ê₃).
/// let body = RigidBody::principal([1.0, 2.0, 3.0])?;
/// let mut gbs = GraggBulirschStoer::new(body, Vector3::new(0.0, 0.0, 3.0), Some(So3::identity()))?;
/// for _ in 0..10 {
///     gbs.step(0.1)?;
/// }
/// let exact = So3::exp(&Vector3::new(0.0, 0.0, 1.0));
/// assert!(gbs.configuration().unwrap().matrix_distance(&exact) < 1e-15);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct GraggBulirschStoer<G: LieGroup, S: System<G>> {
    system: S,
    mu: G::Algebra,
    /// The rounding error of the last `μ + δ`, added to the next increment (TwoSum).
    mu_err: G::Algebra,
    /// t, g, and g projected onto G at every step: a reference run takes few, costly steps, so
    /// the projection is free and keeps ‖gᵀg − I‖ at ε whatever the step count.
    state: StepState<G>,
    /// k: the extrapolation columns (order 2k).
    columns: usize,
    /// Scratch: the last row of the extrapolation tableau, (Θ, δ) per column; allocated once.
    table: Vec<(G::Algebra, G::Algebra)>,
}

impl<G: LieGroup, S: System<G>> GraggBulirschStoer<G, S> {
    /// The default number of columns k = 6: order 12, 43 evaluations of the vector field per step
    /// (see the module page for the choice).
    pub const DEFAULT_COLUMNS: usize = 6;
    /// The most columns accepted: k = 10 (order 20) already amplifies rounding errors 550-fold.
    pub const MAX_COLUMNS: usize = 10;

    /// The method with [`Self::DEFAULT_COLUMNS`] columns at t = 0 from μ₀ and optionally g₀.
    /// Errors: as [`Self::with_columns`].
    pub fn new(system: S, mu0: G::Algebra, g0: Option<G>) -> Result<Self, IntegratorError> {
        Self::with_columns(system, mu0, g0, Self::DEFAULT_COLUMNS)
    }

    /// The method with k = `columns` extrapolation columns (order 2k). Errors: k outside
    /// 1 ..= [`Self::MAX_COLUMNS`], a non-finite μ₀ or g₀, μ₀ of the wrong dimension, g₀ missing
    /// for a system that needs it.
    pub fn with_columns(
        system: S,
        mu0: G::Algebra,
        g0: Option<G>,
        columns: usize,
    ) -> Result<Self, IntegratorError> {
        if !(1..=Self::MAX_COLUMNS).contains(&columns) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "Gragg–Bulirsch–Stoer needs 1 to {} extrapolation columns, got {columns}",
                    Self::MAX_COLUMNS
                ),
            });
        }
        crate::checks::check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        let n = G::dim();
        Ok(Self {
            system,
            mu: mu0,
            mu_err: G::Algebra::zeros(n),
            state: StepState::new(g0, RENORMALIZE_AFTER),
            columns,
            table: vec![(G::Algebra::zeros(n), G::Algebra::zeros(n)); columns],
        })
    }

    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }

    /// The number of columns k (the order is 2k).
    pub fn columns(&self) -> usize {
        self.columns
    }
}

/// The vector field of the step's local ODE at (s, Θ, δ): `(Θ̇, δ̇)` of the module page.
struct LocalField<'a, G: LieGroup, S> {
    system: &'a S,
    /// The step h (for the error of a Θ outside the series' domain).
    h: f64,
    t0: f64,
    mu0: &'a G::Algebra,
    /// g_k, `None` when g is not reconstructed (then Θ is not integrated: Θ̇ is ξ, unused).
    g0: Option<&'a G>,
    /// Whether the forces read g (a potential, or an external force), so that g_k exp Θ is
    /// formed at each stage.
    needs_g: bool,
}

impl<G: LieGroup, S: System<G>> LocalField<'_, G, S> {
    fn eval(
        &self,
        s: f64,
        theta: &G::Algebra,
        delta: &G::Algebra,
    ) -> Result<(G::Algebra, G::Algebra), IntegratorError> {
        let mu = self.mu0.add(delta);
        let xi = self.system.velocity(&mu);
        if !xi.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "body velocity ξ at a substep",
            });
        }
        let stage_g = match self.g0 {
            Some(g) if self.needs_g => Some(G::exp_compose(g, theta)),
            _ => None,
        };
        let mut rate = G::ad_dual_apply(&xi, &mu);
        if let Some(f) = force(self.system, stage_g.as_ref()) {
            rate = rate.add(&f);
        }
        if self.system.is_forced() {
            rate = rate.add(
                &self
                    .system
                    .external_force(self.t0 + s, stage_g.as_ref(), &xi),
            );
        }
        let dtheta = match self.g0 {
            Some(_) => dexp_left_inv_series::<G>(theta, &xi).ok_or_else(|| {
                IntegratorError::StepTooLarge {
                    step: self.h,
                    reason: format!(
                        "the exponential coordinates Θ (|Θ|∞ = {:.3e}) leave the domain of the \
                         series of (d^L exp_Θ)⁻¹ (spectral radius of ad_Θ below 2π)",
                        theta.norm_max()
                    ),
                }
            })?,
            None => xi,
        };
        Ok((dtheta, rate))
    }
}

impl<G: LieGroup, S: System<G>> Integrator for GraggBulirschStoer<G, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let n = G::dim();
        let field = LocalField {
            system: &self.system,
            h,
            t0: self.state.now(),
            mu0: &self.mu,
            g0: self.state.g.as_ref(),
            needs_g: self.system.needs_configuration() || self.system.is_forced(),
        };
        let zero = G::Algebra::zeros(n);
        // f(t₀, y₀), shared by every row.
        let (k0, l0) = field.eval(0.0, &zero, &zero)?;
        for j in 0..self.columns {
            let substeps = 2 * (j + 1);
            let hj = h / substeps as f64;
            // Gragg's modified midpoint rule: (prev, cur) = (y_{i−1}, y_i).
            let mut prev = (zero.clone(), zero.clone());
            let mut cur = (k0.scale(hj), l0.scale(hj));
            for i in 1..substeps {
                let (dk, dl) = field.eval(i as f64 * hj, &cur.0, &cur.1)?;
                let next = (prev.0.axpy(2.0 * hj, &dk), prev.1.axpy(2.0 * hj, &dl));
                prev = core::mem::replace(&mut cur, next);
            }
            // Aitken–Neville: self.table[c] holds T_{j−1,c+1} on entry and T_{j,c+1} on exit.
            for c in 0..j {
                let ratio = (substeps as f64 / (2 * (j - c)) as f64).powi(2) - 1.0;
                let (pt, pd) = &self.table[c];
                let next = (
                    cur.0.axpy(1.0 / ratio, &cur.0.sub(pt)),
                    cur.1.axpy(1.0 / ratio, &cur.1.sub(pd)),
                );
                self.table[c] = core::mem::replace(&mut cur, next);
            }
            self.table[j] = cur;
        }
        let (theta, delta) = &self.table[self.columns - 1];
        if !theta.is_finite() || !delta.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "extrapolated step (Θ, δ)",
            });
        }
        let g1 = self
            .state
            .next_configuration(|g| G::exp_compose(g, theta))?;
        // μ_{k+1} = μ_k + (δ + e_k) by TwoSum (crate::compensated): the bits of δ that the
        // addition rounds away are carried into the next step instead of lost, so μ does not
        // random-walk by ε|μ| per step (which a fast spin turns into a phase drift ∝ T).
        let (sum, err) = two_sum(&self.mu, &delta.add(&self.mu_err));
        self.mu_err = err;
        self.mu = sum;
        self.state.commit(h, g1);
        Ok(())
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        format!(
            "gragg-bulirsch-stoer(k={}, order {})",
            self.columns,
            2 * self.columns
        )
    }
    /// Order 2k, explicit, not symmetric; g_{k+1} = g_k exp(Θ) stays on G, nothing else is kept.
    fn info(&self) -> crate::MethodInfo {
        crate::MethodInfo::plain(2 * self.columns as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lie_groups::{Operator, Se2, Se3, So3, SoN};
    use nalgebra::{Vector3, Vector6};

    #[test]
    fn bernoulli_coefficients_are_the_exact_rationals_and_the_zeta_values() {
        assert_eq!(BERNOULLI_EVEN[0], 1.0);
        assert_eq!(BERNOULLI_EVEN[1], 1.0 / 12.0);
        assert_eq!(BERNOULLI_EVEN[2], -1.0 / 720.0);
        assert_eq!(BERNOULLI_EVEN[3], 1.0 / 30240.0);
        assert_eq!(BERNOULLI_EVEN[4], -1.0 / 1209600.0);
        // B₂ₘ/(2m)! = (−1)^{m+1} 2 ζ(2m) / (2π)^{2m}, with ζ(s) = Σ_{k<N} k^{−s} plus the
        // Euler–Maclaurin tail N^{1−s}/(s−1) + N^{−s}/2 + s N^{−s−1}/12 (error O(s³ N^{−s−3})).
        let zeta = |s: i32| {
            let n = 1000.0f64;
            let sf = f64::from(s);
            (1..1000).rev().map(|k| f64::from(k).powi(-s)).sum::<f64>()
                + n.powf(1.0 - sf) / (sf - 1.0)
                + 0.5 * n.powi(-s)
                + sf * n.powi(-s - 1) / 12.0
        };
        for (m, &b) in BERNOULLI_EVEN.iter().enumerate().skip(1) {
            let zeta = zeta(2 * m as i32);
            let sign = if m % 2 == 1 { 1.0 } else { -1.0 };
            let expected = sign * 2.0 * zeta / (2.0 * core::f64::consts::PI).powi(2 * m as i32);
            assert!(
                (b - expected).abs() <= 1e-14 * expected.abs(),
                "m = {m}: {b:e} vs {expected:e}"
            );
        }
    }

    /// The bracket series equals the closed forms of (d^L exp_Θ)⁻¹ on SO(3), SE(3), SE(2), and the
    /// provided (block-exponential) form on SO(4), for |Θ| up to 3.
    #[test]
    fn the_series_equals_the_closed_forms_of_dexp_inverse() {
        let eta3 = Vector3::new(0.3, -1.1, 0.7);
        for scale in [1e-8, 0.1, 1.0, 2.0, 3.0] {
            let w = Vector3::new(0.6, -0.48, 0.64) * scale; // |w| = scale
            let s = dexp_left_inv_series::<So3>(&w, &eta3).unwrap();
            let c = So3::dexp_left_inv(&w) * eta3;
            assert!((s - c).amax() <= 1e-14 * c.amax(), "SO(3) {scale}: {s} {c}");
            let xi6 = Vector6::new(0.6, -0.48, 0.64, 1.0, -2.0, 0.5) * scale;
            let eta6 = Vector6::new(0.3, -1.1, 0.7, 0.2, 0.9, -0.4);
            let s = dexp_left_inv_series::<Se3>(&xi6, &eta6).unwrap();
            let c = Se3::dexp_left_inv(&xi6) * eta6;
            assert!((s - c).amax() <= 1e-14 * c.amax(), "SE(3) {scale}");
            let xi2 = Vector3::new(1.0, 0.4, -0.7) * scale;
            let s = dexp_left_inv_series::<Se2>(&xi2, &eta3).unwrap();
            let c = Se2::dexp_left_inv(&xi2) * eta3;
            assert!((s - c).amax() <= 1e-14 * c.amax(), "SE(2) {scale}");
            let xi4 = faer::Col::from_fn(6, |i| scale * [0.5, -0.2, 0.3, 0.6, -0.4, 0.1][i]);
            let eta4 = faer::Col::from_fn(6, |i| [0.3, 1.0, -0.5, 0.2, 0.8, -0.6][i]);
            let s = dexp_left_inv_series::<SoN<4>>(&xi4, &eta4).unwrap();
            let c = SoN::<4>::dexp_left_inv(&xi4).apply(&eta4);
            assert!(
                s.sub(&c).norm_max() <= 1e-13 * c.norm_max(),
                "SO(4) {scale}"
            );
        }
    }

    /// Beyond the series' radius (|Θ| = 5 on SO(3), the spectral radius of ad_Θ) the series is
    /// refused rather than summed wrongly.
    #[test]
    fn the_series_is_refused_outside_its_domain() {
        let w = Vector3::new(0.6, -0.48, 0.64) * 5.0;
        assert!(dexp_left_inv_series::<So3>(&w, &Vector3::new(1.0, 0.0, 0.0)).is_none());
    }
}
