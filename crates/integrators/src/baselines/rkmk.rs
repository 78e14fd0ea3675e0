//! The Runge–Kutta–Munthe-Kaas method of order 4 (RKMK4) on the group: classical RK4 applied to
//! the equation of the local coordinate Θ(t) in g(t) = g_k exp(Θ(t)), a Lie-group method that keeps
//! g on G to round-off but preserves neither energy nor Casimirs.
//!
//! With the left-trivialized equations `ġ = g ξ`, ξ = ∂h/∂μ(μ), and
//! `μ̇ = ad*_ξ μ + F(g)` (F = −T*_e L_g dV), writing g = g_k exp(Θ) gives
//! `ġ = g d^L exp_Θ (Θ̇)` (the crate's convention for d^L exp), hence
//!
//! ```text
//! Θ̇ = (d^L exp_Θ)⁻¹ ξ,     Θ(0) = 0,
//! ```
//!
//! which lives in the vector space 𝔤 and is integrated, together with μ, by the classical RK4
//! tableau (c = 0, ½, ½, 1; b = ⅙, ⅓, ⅓, ⅙) with `(d^L exp_Θ)⁻¹ = I + ½ ad_Θ + (1/12) ad_Θ² + …`
//! (Bernoulli numbers, B₁ = +½ in this left-trivialized convention) truncated where it no longer
//! affects order 4.
//!
//! Written out naively that is two brackets per stage. Munthe-Kaas and Owren ("Computations in
//! a free Lie algebra", Phil. Trans. R. Soc. A 357 (1999); also Iserles, Munthe-Kaas, Nørsett,
//! Zanna, "Lie-group methods", Acta Numerica 2000) expand the stages in the graded free Lie
//! algebra and keep only the brackets of order ≤ 4 that survive: with F_i = h ξ_i,
//!
//! ```text
//! ξ_i = ∂h/∂μ(μ_i),   L_i = ad*_{ξ_i} μ_i + F(g_i),   g_i = g_k exp(Θ_i),   μ_i = μ_k + h Σ_j a_ij L_j,
//! Θ₁ = 0,   Θ₂ = ½F₁,   Θ₃ = ½F₂ + ⅛[F₁, F₂],   Θ₄ = F₃,
//! g_{k+1} = g_k exp(⅙(F₁ + 2F₂ + 2F₃ + F₄) + (1/12)[F₁, F₄]),   μ_{k+1} = μ_k + h Σ b_i L_i.
//! ```
//!
//! The brackets carry + here where Munthe-Kaas and Owren's y = exp(Θ) y₀ form prints −: this
//! crate's g = g_k exp(Θ) is the other trivialization, which reverses the bracket. Both brackets
//! are pinned by `tests/baselines.rs`: with both signs reversed the method is order 2, with the
//! stage-3 sign reversed order 3 on the heavy top (whose force reads g₃); as written, 4.0 on
//! every problem there. Without a potential the stages do not need g_i, so the step evaluates one
//! bracket and one exponential (the final one): its stages never touch the configuration, where
//! an RK4 on (q, Π) forms a stage quaternion and its derivative four times. Without
//! reconstruction only μ is integrated (then the method is plain RK4 on μ). For fixed-size groups
//! every quantity lives on the stack.

use crate::carried_state;
use crate::checks::check_state;
use crate::step_state::{state_accessors, StepState};
use crate::system::lie_poisson_rate;
use crate::{Integrator, IntegratorError, System};
use lie_groups::{LieGroup, Vector};

/// RKMK4 (classical RK4 tableau, Munthe-Kaas–Owren's two brackets) for any system on any Lie group G.
///
/// State: time t, body momentum μ ∈ 𝔤*, and g ∈ G when it is reconstructed (`None` integrates μ
/// alone, only allowed without a potential).
///
/// ```
/// use integrators::{baselines::Rkmk4, Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([1.0, 2.0, 3.0])?;
/// let mut rkmk = Rkmk4::new(body, Vector3::new(0.5, 1.0, 0.2), Some(So3::identity()))?;
/// integrators::integrate(&mut rkmk, 0.01, 100, |_| {})?;
/// let r = rkmk.configuration().unwrap().as_matrix();
/// assert!((r.transpose() * r - nalgebra::Matrix3::identity()).amax() < 1e-14);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Rkmk4<G: LieGroup, S: System<G>> {
    system: S,
    mu: G::Algebra,
    /// t, g and g's renormalization (one product a step).
    state: StepState<G>,
}

impl<G: LieGroup, S: System<G>> Rkmk4<G, S> {
    /// Builds the integrator at t = 0 from μ₀ and optionally g₀. Errors: non-finite μ₀ or g₀, g₀
    /// missing for a system with a potential, μ₀ of the wrong dimension.
    pub fn new(system: S, mu0: G::Algebra, g0: Option<G>) -> Result<Self, IntegratorError> {
        check_state(&system, &mu0, "momentum μ", g0.as_ref())?;
        Ok(Self {
            system,
            mu: mu0,
            state: StepState::new(g0, 1),
        })
    }
    /// The system.
    pub fn system(&self) -> &S {
        &self.system
    }

    /// (ξ, μ̇) = (∂h/∂μ(μ), ad*_ξ μ + F(g) + F_ext(t, g, ξ)) at a stage, ξ = `v(μ)`; g is only
    /// used with a potential or a force that reads it.
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

    /// The four stages from (g_k, μ_k): (Θ, μ_{k+1}) with g_{k+1} = g_k exp(Θ), ξ = `v(μ)` at
    /// every stage.
    #[inline(always)]
    fn stages(
        &self,
        v: &impl Fn(&G::Algebra) -> G::Algebra,
        h: f64,
        gk: &G,
        mu: &G::Algebra,
    ) -> (G::Algebra, G::Algebra) {
        let half = 0.5 * h;
        let t0 = self.state.now();
        let (tm, t1) = (t0 + half, t0 + h);
        let potential = self.system.needs_configuration();
        // g_i = g_k exp(Θ_i), only evaluated where a force reads it.
        let stage_g = |theta: &G::Algebra| potential.then(|| G::exp_compose(gk, theta));

        // Stage 1 at Θ₁ = 0.
        let (x1, l1) = self.rates(v, t0, Some(gk), mu);
        // Stage 2 at Θ₂ = h/2 ξ₁.
        let (x2, l2) = self.rates(
            v,
            tm,
            stage_g(&x1.scale(half)).as_ref(),
            &mu.axpy(half, &l1),
        );
        // Stage 3 at Θ₃ = h/2 ξ₂ + h²/8 [ξ₁, ξ₂] (the bracket only where g₃ is read).
        let g3 = potential.then(|| {
            let t3 = x2.axpy(0.25 * h, &G::bracket(&x1, &x2)).scale(half);
            G::exp_compose(gk, &t3)
        });
        let (x3, l3) = self.rates(v, tm, g3.as_ref(), &mu.axpy(half, &l2));
        // Stage 4 at Θ₄ = h ξ₃.
        let (x4, l4) = self.rates(v, t1, stage_g(&x3.scale(h)).as_ref(), &mu.axpy(h, &l3));

        // Θ = h/6 (ξ₁ + 2ξ₂ + 2ξ₃ + ξ₄) + h²/12 [ξ₁, ξ₄].
        let sum = x1.add(&x2.add(&x3).scale(2.0)).add(&x4);
        let theta = sum.axpy(0.5 * h, &G::bracket(&x1, &x4)).scale(h / 6.0);
        let mu1 = mu.axpy(h / 6.0, &l1.add(&l2.add(&l3).scale(2.0)).add(&l4));
        (theta, mu1)
    }
}

/// `a ∘ μ`, entry by entry: ∂h/∂μ of the diagonal quadratic `h = ½ Σ aᵢ μᵢ²`.
#[inline(always)]
fn hadamard<V: Vector>(a: &V, mu: &V) -> V {
    V::from_fn(mu.dim(), |i| a.get(i) * mu.get(i))
}

impl<G: LieGroup, S: System<G>> Integrator for Rkmk4<G, S> {
    type Group = G;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let half = 0.5 * h;
        let t0 = self.state.now();
        let (tm, t1) = (t0 + half, t0 + h);
        // μ as the last step stored it, entry by entry (crate::carried_state).
        let mu = &carried_state::read(&self.mu);
        let Some(gk) = self.state.g.as_ref() else {
            // μ alone: plain RK4 on μ̇ = ad*_ξ μ (no potential, checked at construction).
            let v = |mu: &G::Algebra| self.system.velocity(mu);
            let (_, l1) = self.rates(&v, t0, None, mu);
            let (_, l2) = self.rates(&v, tm, None, &mu.axpy(half, &l1));
            let (_, l3) = self.rates(&v, tm, None, &mu.axpy(half, &l2));
            let (_, l4) = self.rates(&v, t1, None, &mu.axpy(h, &l3));
            let mu1 = mu.axpy(h / 6.0, &l1.add(&l2.add(&l3).scale(2.0)).add(&l4));
            if !mu1.is_finite() {
                return Err(IntegratorError::NonFinite {
                    what: "momentum μ_{k+1}",
                });
            }
            self.mu = mu1;
            self.state.commit(h, None);
            return Ok(());
        };
        // The system's shape is tested once per step, not in each stage (see
        // `System::diagonal_velocity`).
        let (theta, mu1) = match self.system.diagonal_velocity() {
            Some(a) => self.stages(&|mu: &G::Algebra| hadamard(&a, mu), h, gk, mu),
            None => self.stages(&|mu: &G::Algebra| self.system.velocity(mu), h, gk, mu),
        };
        if !theta.is_finite() || !mu1.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "RKMK4 stage (Θ, μ)",
            });
        }
        // g_k exp(Θ) in increment form, g_k + g_k (exp Θ − I): g stays on G up to a random walk
        // of roundings, renormalized rarely (crate::step_state: a polar step at each would be
        // a sizeable part of the free body's step, and would round g a second time).
        let mut g1 = Some(G::exp_compose(gk, &theta));
        self.state.finish_configuration(&mut g1)?;
        self.mu = mu1;
        self.state.commit(h, g1);
        Ok(())
    }
    state_accessors!(mu);
    fn method_name(&self) -> String {
        "rkmk4(exp)".into()
    }
    /// RKMK4: order 4, explicit; g_{k+1} = g_k exp(Θ) stays on G, and nothing else is kept.
    fn info(&self) -> crate::MethodInfo {
        crate::MethodInfo::plain(4)
    }
}
