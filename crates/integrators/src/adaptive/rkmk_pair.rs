//! Runge–Kutta–Munthe-Kaas with an embedded pair: any explicit pair ([`ButcherPair`]) applied
//! in the algebra, with its error estimate measured on the group, for any system on any Lie
//! group G.
//!
//! With `ġ = g ξ`, ξ = ∂h/∂μ(μ), `μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ)` and g = g_k exp(Θ), the
//! local coordinate obeys `Θ̇ = (d^L exp_Θ)⁻¹ ξ` (see [`crate::baselines::Rkmk4`]), integrated
//! with μ by the pair's tableau (H. Munthe-Kaas, "High order Runge–Kutta methods on manifolds",
//! Appl. Numer. Math. 29 (1999) 115–127):
//!
//! ```text
//! Θᵢ = h Σⱼ aᵢⱼ Kⱼ,   μᵢ = μ_k + h Σⱼ aᵢⱼ Lⱼ,   gᵢ = g_k exp(Θᵢ),
//! ξᵢ = ∂h/∂μ(μᵢ),     Lᵢ = ad*_{ξᵢ} μᵢ + F(gᵢ) + F_ext(t + cᵢh, gᵢ, ξᵢ),
//! Kᵢ = Σ_{m ≤ q} (B_m/m!) ad_{Θᵢ}^m ξᵢ   (= ξᵢ + ½[Θᵢ, ξᵢ] + (1/12)[Θᵢ, [Θᵢ, ξᵢ]] − …),
//! g_{k+1} = g_k exp(h Σ bᵢKᵢ),   μ_{k+1} = μ_k + h Σ bᵢLᵢ.
//! ```
//!
//! **Truncation of (d^L exp_Θ)⁻¹.** Munthe-Kaas (1999, §4; also Iserles, Munthe-Kaas, Nørsett,
//! Zanna, "Lie-group methods", Acta Numerica 9 (2000), §5.3) shows that the series can be cut
//! after the terms in ad^q with q = p − 2 for a method of order p: along the solution
//! Θ(t) = tξ(0) + O(t²) and ξ(t) = ξ(0) + O(t), so `[Θ, ξ] = O(t²)` (the leading parts commute)
//! and `ad_Θ^m ξ = O(t^{m+1})`; dropping the terms m > q changes Θ(h) by
//! `∫₀ʰ O(t^{q+2}) dt = O(h^{q+3})`, within the local error O(h^{p+1}) when q ≥ p − 2. The
//! Bernoulli numbers B₃ = B₅ = 0, so order 5 (Dormand–Prince) keeps the two brackets of ½ ad and
//! (1/12) ad², order 8 (DOP853) the four of ½, 1/12, −1/720 (ad⁴) and 1/30240 (ad⁶), one bracket
//! per power. The sign of the ½ term is that of this crate's g = g_k exp(Θ) (B₁ = +½, see
//! [`crate::baselines::Rkmk4`]). `tests/methods/adaptive_orders.rs` fits the orders on SO(3)
//! (free body and heavy top) and SE(3). Each kept term is needed, as the argument predicts
//! (dropping the term in ad^m leaves a local error O(h^{m+2}), order m + 1): with the ad² term
//! dropped Dormand–Prince was measured at order 3.0, with ad⁴ dropped DOP853 at 5.0, with ad⁶
//! dropped at 7.0, on all three problems.
//!
//! That truncation is asymptotic: at the long steps of loose tolerances (|Θ| of radians) the
//! terms left out exceed the tolerance, and the error estimate cannot see them — both solutions
//! of the pair are built from the same Kᵢ. Under error control the stages therefore sum the
//! series on (through ad¹²) until a term's contribution to Θ falls below 1e-3 of the tolerance,
//! and take the group's closed form of (d^L exp_Θ)⁻¹ where it has not by then (measured on the
//! free body to T = 10 at rtol = atol = 1e-4: RKMK DOP853 was 53× off its tolerance with the q
//! terms alone, 3.1× with the series summed on; `tests/methods/adaptive_tolerance.rs`). Fixed
//! steps ([`Integrator::step`]) keep the q terms.
//!
//! **Error on the group.** The two solutions are `g = g_k exp(Θ)` and `ĝ = g_k exp(Θ̂)`,
//! `Θ − Θ̂ = h Σ eᵢKᵢ` (e = b − b̂); by the Baker–Campbell–Hausdorff formula
//! `log(ĝ⁻¹g) = (Θ − Θ̂) + ½[Θ − Θ̂, Θ] + … = h Σ eᵢKᵢ · (1 + O(h))`, so the estimate is taken as
//! `h Σ eᵢKᵢ` — the distance on the group to leading order, without forming ĝ or a log
//! (`tests/methods/adaptive_pairs.rs` compares it with `log(ĝ⁻¹g)`). Its components are scaled by
//! `atol + rtol` and those of `h Σ eᵢLᵢ` by `atol + rtol·|μᵢ|` ([`Tolerance`]).
//!
//! Without a potential the stages do not need gᵢ: the step evaluates one exponential (the
//! final one). Without reconstruction only μ is integrated (the pair's plain RK on μ). For
//! fixed-size groups every quantity lives on the stack.

use super::embedded_pair::check_end_time;
use super::Tolerance;
use super::{starting_step, ButcherPair, Controller, Dop853, DormandPrince54, EmbeddedPair};
use crate::carried_state;
use crate::checks::check_state;
use crate::step_state::{state_accessors, StepState};
use crate::system::lie_poisson_rate;
use crate::unroll::unroll;
use crate::{Integrator, IntegratorError, MethodInfo, System};
use core::marker::PhantomData;
use lie_groups::{LieGroup, Operator, Vector};

/// RKMK with the Dormand–Prince 5(4) pair (order 5, embedded 4, 6 evaluations a step).
pub type RkmkDopri5<G, S> = RkmkPair<G, S, DormandPrince54, 7>;
/// RKMK with the DOP853 pair (order 8, error estimators of orders 5 and 3, 12 evaluations a step).
pub type RkmkDop853<G, S> = RkmkPair<G, S, Dop853, 12>;

/// The coefficients `B_m/m!` of `(d^L exp_Θ)⁻¹ = Σ (B_m/m!) ad_Θ^m` in this crate's convention
/// (B₁ = +½), m = 0 … 12.
const DEXP_INV: [f64; 13] = [
    1.0,
    0.5,
    1.0 / 12.0,
    0.0,
    -1.0 / 720.0,
    0.0,
    1.0 / 30240.0,
    0.0,
    -1.0 / 1_209_600.0,
    0.0,
    1.0 / 47_900_160.0,
    0.0,
    -691.0 / 1_307_674_368_000.0,
];

/// The highest power of ad kept for a method of order p: q = p − 2, lowered to the last nonzero
/// coefficient (B₃ = B₅ = 0).
const fn dexp_inv_terms(order: u32) -> usize {
    let mut q = if order >= 2 { order as usize - 2 } else { 0 };
    if q > 6 {
        q = 6;
    }
    while q > 0 && DEXP_INV[q] == 0.0 {
        q -= 1;
    }
    q
}

/// An RKMK method with an embedded pair (see the module page) for any system on any group G.
///
/// ```
/// use integrators::adaptive::{Adaptive, RkmkDopri5, Tolerance};
/// use integrators::Integrator;
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([2.0, 3.0, 4.0])?;
/// let method = RkmkDopri5::new(body, Vector3::new(1.0, 0.5, -0.3), Some(So3::identity()))?;
/// let mut run = Adaptive::new(method, Tolerance::new(1e-8, 1e-8)?);
/// run.advance_to(10.0)?;
/// assert_eq!(run.method().time(), 10.0);
/// println!("{} steps accepted, {} rejected", run.stats().accepted, run.stats().rejected);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct RkmkPair<G: LieGroup, S: System<G>, P: ButcherPair<N>, const N: usize> {
    system: S,
    mu: G::Algebra,
    /// t, g and g's renormalization (one product a step).
    state: StepState<G>,
    /// (ξ, μ̇) at the current state where already evaluated (the last stage of a first-same-
    /// as-last pair, or a rejected attempt's first stage).
    first: Option<(G::Algebra, G::Algebra)>,
    pair: PhantomData<P>,
}

/// A step computed but not yet taken.
struct Candidate<G: LieGroup> {
    h: f64,
    /// g_{k+1} = g_k exp(Θ), where g is reconstructed.
    g1: Option<G>,
    mu1: G::Algebra,
    /// Σ (estimate/scale)² of the estimator E, and of E_LOW.
    sum: f64,
    sum_low: f64,
    /// Components in the norm.
    n: usize,
    /// (ξ, μ̇) of the last stage where it is at (t + h, g_{k+1}, μ_{k+1}).
    last: Option<(G::Algebra, G::Algebra)>,
    /// Whether every stage's (d^L exp)⁻¹ series reached its threshold (always, without one).
    series_converged: bool,
}

/// `a ∘ μ`, entry by entry: ∂h/∂μ of the diagonal quadratic `h = ½ Σ aᵢ μᵢ²`.
#[inline(always)]
fn hadamard<V: Vector>(a: &V, mu: &V) -> V {
    V::from_fn(mu.dim(), |i| a.get(i) * mu.get(i))
}

impl<G: LieGroup, S: System<G>, P: ButcherPair<N>, const N: usize> RkmkPair<G, S, P, N> {
    /// The power of ad up to which (d^L exp)⁻¹ is summed (module page).
    const TERMS: usize = dexp_inv_terms(P::ORDER);

    /// Builds the method at t = 0 from μ₀ and optionally g₀. Errors: non-finite μ₀ or g₀, g₀
    /// missing for a system that needs it, μ₀ of the wrong dimension.
    pub fn new(system: S, mu0: G::Algebra, g0: Option<G>) -> Result<Self, IntegratorError> {
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        Ok(Self {
            system,
            mu: mu0,
            state: StepState::new(g0, 1),
            first: None,
            pair: PhantomData,
        })
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }

    /// (ξ, μ̇) at a stage, ξ = `v(μ)`.
    #[inline(always)]
    fn rates(
        &self,
        v: &impl Fn(&G::Algebra) -> G::Algebra,
        t: f64,
        g: Option<&G>,
        mu: &G::Algebra,
    ) -> (G::Algebra, G::Algebra) {
        let xi = v(mu);
        let dmu = lie_poisson_rate(&self.system, t, g, mu, &xi);
        (xi, dmu)
    }

    /// `Σ_{m ≤ q} (B_m/m!) ad_Θ^m ξ`, the truncated `(d^L exp_Θ)⁻¹ ξ`, and with `threshold`
    /// the further terms (through m = 12) until one is at most `threshold` in max norm; where
    /// the series has not got there by m = 12 (it converges for |Θ| < 2π only, and slowly
    /// near it), the group's closed form [`LieGroup::dexp_left_inv`]. Returns false where that
    /// is not finite either (|Θ| at a singularity of d^L exp).
    #[inline(always)]
    fn dexp_inv(theta: &G::Algebra, xi: &G::Algebra, threshold: Option<f64>) -> (G::Algebra, bool) {
        let mut term = xi.clone();
        let mut sum = xi.clone();
        for &coefficient in &DEXP_INV[1..=Self::TERMS] {
            term = G::bracket(theta, &term);
            if coefficient != 0.0 {
                sum = sum.axpy(coefficient, &term);
            }
        }
        let Some(threshold) = threshold else {
            return (sum, true);
        };
        for &coefficient in &DEXP_INV[Self::TERMS + 1..] {
            term = G::bracket(theta, &term);
            if coefficient != 0.0 {
                let added = term.scale(coefficient);
                sum = sum.add(&added);
                if added.norm_max() <= threshold {
                    return (sum, true);
                }
            }
        }
        let exact = G::dexp_left_inv(theta).apply(xi);
        let finite = exact.is_finite();
        (if finite { exact } else { sum }, finite)
    }

    /// The stages of a step of size h from the current state, with (ξ, μ̇) there given, and the
    /// solution of the weights `b` (the pair's B, or an embedded solution's b̂ for the order
    /// tests).
    #[inline(always)]
    fn stages(
        &self,
        v: &impl Fn(&G::Algebra) -> G::Algebra,
        h: f64,
        first: &(G::Algebra, G::Algebra),
        b: &[f64; N],
        tolerance: Option<&Tolerance>,
    ) -> Candidate<G> {
        let n = G::dim();
        let mu = &carried_state::read(&self.mu);
        let gk = self.state.g.as_ref();
        let needs_g = self.system.needs_configuration();
        let mut ks: [G::Algebra; N] = core::array::from_fn(|_| G::Algebra::zeros(n));
        let mut ls: [G::Algebra; N] = core::array::from_fn(|_| G::Algebra::zeros(n));
        ks[0] = first.0.clone();
        ls[0] = first.1.clone();
        let mut last = None;
        // Under error control the series of (d^L exp_Θ)⁻¹ is summed on past the q terms that
        // give the order, until a term's contribution h·term to Θ is below 1e-3 of the
        // tolerance: the estimate compares two solutions built from the same Kᵢ, so it cannot
        // see their truncation, which at the long steps of loose tolerances (|Θ| of radians)
        // exceeds the tolerance (measured: RKMK DOP853 on the free body at rtol = 1e-4 was 53×
        // off its tolerance with the q terms alone, 3.1× with the series summed on).
        let threshold = tolerance.map(|tol| 1e-3 * (tol.atol + tol.rtol) / h.abs());
        let mut series_converged = true;
        // Written out stage by stage (crate::unroll): the aᵢⱼ are literals, the zero ones gone.
        unroll!(I in 1..N => {
            let mut theta = G::Algebra::zeros(n);
            let mut dmu = G::Algebra::zeros(n);
            unroll!(J < I => {
                let a = P::A[I][J];
                if a != 0.0 {
                    theta = theta.axpy(a, &ks[J]);
                    dmu = dmu.axpy(a, &ls[J]);
                }
            });
            let theta = theta.scale(h);
            let mu_i = mu.axpy(h, &dmu);
            let g_i = match gk {
                Some(gk) if needs_g => Some(G::exp_compose(gk, &theta)),
                _ => None,
            };
            let (xi, l) = self.rates(v, self.state.now() + P::C[I] * h, g_i.as_ref(), &mu_i);
            if P::FSAL && I == N - 1 && *b == P::B {
                last = Some((xi.clone(), l.clone()));
            }
            ks[I] = if gk.is_some() {
                let (k, converged) = Self::dexp_inv(&theta, &xi, threshold);
                series_converged &= converged;
                k
            } else {
                xi
            };
            ls[I] = l;
        });
        // The solution and the estimates: Σ bᵢKᵢ, Σ eᵢKᵢ, … (zero weights skipped).
        let mut theta = G::Algebra::zeros(n);
        let mut dmu = G::Algebra::zeros(n);
        let mut e_theta = G::Algebra::zeros(n);
        let mut e_mu = G::Algebra::zeros(n);
        let mut low_theta = G::Algebra::zeros(n);
        let mut low_mu = G::Algebra::zeros(n);
        unroll!(I < N => {
            if b[I] != 0.0 {
                theta = theta.axpy(b[I], &ks[I]);
                dmu = dmu.axpy(b[I], &ls[I]);
            }
            if tolerance.is_some() {
                if P::E[I] != 0.0 {
                    e_theta = e_theta.axpy(P::E[I], &ks[I]);
                    e_mu = e_mu.axpy(P::E[I], &ls[I]);
                }
                if let Some(e_low) = P::E_LOW {
                    if e_low[I] != 0.0 {
                        low_theta = low_theta.axpy(e_low[I], &ks[I]);
                        low_mu = low_mu.axpy(e_low[I], &ls[I]);
                    }
                }
            }
        });
        let mu1 = mu.axpy(h, &dmu);
        let g1 = gk.map(|gk| G::exp_compose(gk, &theta.scale(h)));
        let (mut sum, mut sum_low, mut count) = (0.0, 0.0, n);
        if let Some(tol) = tolerance {
            for i in 0..n {
                let w = h / tol.scale(mu.get(i), mu1.get(i));
                sum += (e_mu.get(i) * w).powi(2);
                if P::E_LOW.is_some() {
                    sum_low += (low_mu.get(i) * w).powi(2);
                }
            }
            if gk.is_some() {
                let w = h / (tol.atol + tol.rtol);
                for i in 0..n {
                    sum += (e_theta.get(i) * w).powi(2);
                    if P::E_LOW.is_some() {
                        sum_low += (low_theta.get(i) * w).powi(2);
                    }
                }
                count += n;
            }
        }
        Candidate {
            h,
            g1,
            mu1,
            sum,
            sum_low,
            n: count,
            last,
            series_converged,
        }
    }

    /// (ξ, μ̇) at the current state, from the cache where a stage already evaluated it.
    fn first_stage(&mut self) -> (G::Algebra, G::Algebra) {
        if let Some(first) = &self.first {
            return first.clone();
        }
        let first = self.rates(
            &|mu: &G::Algebra| self.system.velocity(mu),
            self.state.now(),
            self.state.g.as_ref(),
            &self.mu,
        );
        self.first = Some(first.clone());
        first
    }

    /// The candidate step of size h with the weights b (with its error sums where `tolerance`
    /// is given).
    #[inline(always)]
    fn candidate(&mut self, h: f64, b: &[f64; N], tolerance: Option<&Tolerance>) -> Candidate<G> {
        let first = self.first_stage();
        // The system's shape is tested once per step, not in each stage.
        match self.system.diagonal_velocity() {
            Some(a) => self.stages(&|mu: &G::Algebra| hadamard(&a, mu), h, &first, b, tolerance),
            None => self.stages(
                &|mu: &G::Algebra| self.system.velocity(mu),
                h,
                &first,
                b,
                tolerance,
            ),
        }
    }

    /// Whether the candidate is finite.
    fn finite(c: &Candidate<G>) -> bool {
        c.mu1.is_finite() && c.g1.as_ref().is_none_or(G::is_finite)
    }

    /// Takes the candidate, the time becoming `t1` (an adaptive step's chosen end), or
    /// advanced by its h on the compensated clock (a fixed step).
    fn commit(&mut self, c: Candidate<G>, t1: Option<f64>) -> Result<(), IntegratorError> {
        let mut g1 = c.g1;
        self.state.finish_configuration(&mut g1)?;
        match t1 {
            Some(t1) => self.state.commit_to(t1, g1),
            None => self.state.commit(c.h, g1),
        }
        self.mu = c.mu1;
        self.first = c.last;
        Ok(())
    }

    /// A fixed step of the *embedded* solution ŷ = y₀ + h Σ b̂ᵢkᵢ (b̂ = b − e), or of the
    /// second estimator's `b − e_low` with `low`: for measuring the embedded orders
    /// (`tests/methods/adaptive_orders.rs`).
    pub fn step_embedded(&mut self, h: f64, low: bool) -> Result<(), IntegratorError> {
        let b_hat = P::embedded_weights(low)?;
        let c = self.candidate(h, &b_hat, None);
        if !Self::finite(&c) {
            return Err(IntegratorError::NonFinite {
                what: "embedded step (Θ̂, μ̂)",
            });
        }
        self.commit(c, None)
    }
}

impl<G: LieGroup, S: System<G>, P: ButcherPair<N>, const N: usize> Integrator
    for RkmkPair<G, S, P, N>
{
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let c = self.candidate(h, &P::B, None);
        if !Self::finite(&c) {
            return Err(IntegratorError::NonFinite {
                what: "RKMK stage (Θ, μ)",
            });
        }
        self.commit(c, None)
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        format!("rkmk-{}(exp)", P::NAME)
    }
    /// Order p of the pair's advanced solution, explicit; g stays on G, nothing else is kept.
    fn info(&self) -> MethodInfo {
        MethodInfo::plain(P::ORDER)
    }
}

impl<G: LieGroup, S: System<G> + Clone, P: ButcherPair<N>, const N: usize> EmbeddedPair
    for RkmkPair<G, S, P, N>
{
    fn orders(&self) -> (u32, u32) {
        (P::ORDER, P::EMBEDDED_ORDER)
    }
    fn controller(&self) -> Controller {
        P::controller()
    }
    fn error_exponent(&self) -> u32 {
        P::ERROR_EXPONENT
    }
    fn try_step_to(&mut self, t1: f64, tolerance: &Tolerance) -> Result<f64, IntegratorError> {
        let h = check_end_time(self.state.now(), t1)?;
        let c = self.candidate(h, &P::B, Some(tolerance));
        let err = P::error_norm(c.sum, c.sum_low, c.n);
        if !Self::finite(&c) || !err.is_finite() {
            return Ok(f64::INFINITY);
        }
        if !c.series_converged {
            // |Θ| at a singularity of d^L exp: a rejection by a moderate factor.
            return Ok(err.max(10.0));
        }
        if err <= 1.0 {
            self.commit(c, Some(t1))?;
        }
        Ok(err)
    }
    fn step_to(&mut self, t1: f64) -> Result<(), IntegratorError> {
        let h = check_end_time(self.state.now(), t1)?;
        let c = self.candidate(h, &P::B, None);
        if !Self::finite(&c) {
            return Err(IntegratorError::NonFinite {
                what: "RKMK stage (Θ, μ)",
            });
        }
        self.commit(c, Some(t1))
    }
    fn starting_step(&mut self, direction: f64, tolerance: &Tolerance) -> f64 {
        let (xi0, l0) = self.first_stage();
        let n = G::dim();
        let reconstruct = self.state.g.is_some();
        let count = if reconstruct { 2 * n } else { n } as f64;
        let group_scale = tolerance.atol + tolerance.rtol;
        let mu0 = self.mu.clone();
        // ‖y₀‖: μ against its own scale, g as an element of unit size.
        let mut d0 = (0..n)
            .map(|i| (mu0.get(i) / tolerance.scale(mu0.get(i), 0.0)).powi(2))
            .sum::<f64>();
        let mut d1 = (0..n)
            .map(|i| (l0.get(i) / tolerance.scale(mu0.get(i), 0.0)).powi(2))
            .sum::<f64>();
        if reconstruct {
            d0 += n as f64 * (1.0 / group_scale).powi(2);
            d1 += (0..n)
                .map(|i| (xi0.get(i) / group_scale).powi(2))
                .sum::<f64>();
        }
        let (d0, d1) = ((d0 / count).sqrt(), (d1 / count).sqrt());
        let sign = if direction < 0.0 { -1.0 } else { 1.0 };
        let d2 = |h0: f64| {
            let h = sign * h0;
            let mu1 = mu0.axpy(h, &l0);
            let g1 = self
                .state
                .g
                .as_ref()
                .map(|g| G::exp_compose(g, &xi0.scale(h)));
            let (xi1, l1) = self.rates(
                &|mu: &G::Algebra| self.system.velocity(mu),
                self.state.now() + h,
                g1.as_ref(),
                &mu1,
            );
            let mut d2 = (0..n)
                .map(|i| ((l1.get(i) - l0.get(i)) / tolerance.scale(mu0.get(i), 0.0)).powi(2))
                .sum::<f64>();
            if reconstruct {
                d2 += (0..n)
                    .map(|i| ((xi1.get(i) - xi0.get(i)) / group_scale).powi(2))
                    .sum::<f64>();
            }
            (d2 / count).sqrt() / h0
        };
        starting_step(P::ERROR_EXPONENT, d0, d1, d2)
    }
}
