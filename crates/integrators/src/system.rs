//! Mechanical systems on a Lie group G (§2 of the paper), described by a reduced Hamiltonian.
//!
//! A [`System`] gives the reduced Hamiltonian h: 𝔤* → ℝ with its derivatives, the Legendre map
//! ξ ↦ μ = ∂l/∂ξ (the inverse of μ ↦ ∂h/∂μ) and, optionally, a potential V: G → ℝ. The equations of
//! motion it defines are, with F(g) = −T*_e L_g dV(g) the left-trivialized force (§2.1):
//!
//! - Lie–Poisson form: `μ̇ = ad*_{∂h/∂μ} μ + F(g) + F_ext(t, g, ξ)`, `ġ = g ∂h/∂μ`;
//! - Euler–Poincaré form: `d/dt ∂l/∂ξ = ad*_ξ ∂l/∂ξ + F(g) + F_ext(t, g, ξ)`, `ġ = g ξ`, i.e.
//!   `ξ̇ = ∂²h/∂μ² (ad*_ξ μ + F(g) + F_ext)` with μ = ∂l/∂ξ.
//!
//! `F_ext` is an optional external force ([`System::external_force`], [`crate::forces`]): zero for
//! a conservative system.
//!
//! Conventions (see `lie-groups`): `ad*_ξ := (ad_ξ)ᵀ`, 𝔤* ≅ ℝⁿ by the Euclidean pairing.

use lie_groups::{LieGroup, Operator, Vector};

/// Which rates of the motion a step density ([`System::step_density`]) counts: what the
/// method it steers follows exactly whatever the step, it need not resolve.
///
/// A method declares its scope ([`crate::SymmetricMethod::density_scope`]); the reversible
/// variable steps ([`crate::adaptive::ReversibleSteps`]) ask its monitor for the density of that
/// scope. Only a model with a rate that some methods follow exactly distinguishes the two (a
/// satellite's spin, `mechanics::RigidBodySe3`); the provided density is the same for both.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DensityScope {
    /// Every rate of the motion: for a method whose step approximates all of it alike
    /// (Lie–Poisson and Euler–Poincaré θ = ½, for either τ: their update τ(ξ) with ξ from an
    /// implicit equation is exact on no rotation with a potential).
    Full,
    /// Every rate but the spin about the body's angular momentum Π: while Π stays put in the
    /// body frame Ω is constant and the body turns about it, a one-parameter subgroup that a
    /// method made of exact flows of the kinetic energy's pieces follows exactly (the
    /// splittings' rotation pieces, kinetic–kick's exact free-body flow, their compositions).
    SpinFollowed,
}

/// A mechanical system on G with reduced Hamiltonian h(μ) and optional potential V(g).
///
/// To write your own, see docs/custom-systems.md and `examples/custom_system.rs`; check the
/// derivatives you derived by hand with [`crate::derivative_check::check_derivatives`].
///
/// Only the kinetic part lives in 𝔤*: the total energy is `E(g, μ) = h(μ) + V(g)`. A system with
/// [`System::has_potential`] `== true` needs the configuration g to be integrated (the force depends
/// on it); without a potential the momentum equation decouples and g is optional.
pub trait System<G: LieGroup> {
    /// The reduced Hamiltonian h(μ) (the kinetic energy for a mechanical system).
    fn hamiltonian(&self, mu: &G::Algebra) -> f64;
    /// `∂h/∂μ ∈ 𝔤`, the body velocity belonging to μ.
    fn velocity(&self, mu: &G::Algebra) -> G::Algebra;
    /// The Hessian `∂²h/∂μ²: 𝔤* → 𝔤` at μ, as an n×n operator (used by Newton's method and by the
    /// Euler–Poincaré vector field). Provided by central differences of [`Self::velocity`]
    /// ([`crate::derivative_check::finite_difference_hessian`]: 2n velocity evaluations per call,
    /// accurate to ~1e-10 relative); give the closed form where there is one — it is cheaper, and
    /// Euler–Poincaré evaluates it in every residual.
    fn hessian(&self, mu: &G::Algebra) -> G::Operator {
        crate::derivative_check::finite_difference_hessian(self, mu)
    }
    /// `‖∂²h/∂μ²‖_max` at μ, the Hessian's largest entry in absolute value: how much it scales
    /// the rounding of a momentum (the Lie–Poisson step's solver measures its residual's rounding
    /// with it). `self.hessian(mu).norm_max()` unless a system gives it without forming an
    /// allocated operator (SO(n), products of bodies, gyrostats).
    fn hessian_norm(&self, mu: &G::Algebra) -> f64 {
        self.hessian(mu).norm_max()
    }
    /// The Legendre map `ξ ↦ μ = ∂l/∂ξ`, the inverse of `μ ↦ ∂h/∂μ`.
    fn momentum(&self, xi: &G::Algebra) -> G::Algebra;
    /// The coefficients a of a diagonal quadratic Hamiltonian `h(μ) = ½ Σ aᵢ μᵢ²`, where h is one
    /// (a rigid body in its principal axes): then `∂h/∂μ(μ) = a ∘ μ`, entry by entry and bitwise
    /// as [`Self::velocity`] computes it. `None` (the default) says nothing about h.
    ///
    /// An explicit integrator reads it once per step and runs its stages on `a ∘ μ`, with no test
    /// of the system's shape inside each stage (a test there keeps both arms of the branch alive
    /// in every stage). A system that returns `Some` must keep the identity, and a system that wraps
    /// another without changing h forwards it (`Forced` does; without it the integrators take
    /// their general path, correct but slower). `tests/diagonal_velocity.rs` checks the identity
    /// on the crate's systems, and that the fast path steps bit for bit as the general one.
    fn diagonal_velocity(&self) -> Option<G::Algebra> {
        None
    }

    /// Whether the system has a potential V(g) (then integrators require g).
    fn has_potential(&self) -> bool {
        false
    }
    /// The potential V(g); 0 without one.
    fn potential(&self, _g: &G) -> f64 {
        0.0
    }
    /// The left-trivialized differential `T*_e L_g dV(g) ∈ 𝔤*`, defined by
    /// `⟨T*_e L_g dV(g), ζ⟩ = d/ds V(g exp(sζ))|_{s=0}`; zero without a potential.
    ///
    /// The force entering the equations of motion is its negative, `F(g) = −T*_e L_g dV(g)`.
    fn potential_differential(&self, _g: &G) -> G::Algebra {
        G::Algebra::zeros(G::dim())
    }
    /// The derivative of the force along the group, `K(g): ζ ↦ d/ds F(g exp(sζ))|_{s=0}` with
    /// `F = −T*_e L_g dV` (minus the left-trivialized Hessian of V), for the Newton matrix of the
    /// implicit steps. The provided form takes central differences of
    /// [`System::potential_differential`] along `g exp(±dζ)` (2n evaluations, accurate to
    /// ~1e-10 relative; [`crate::derivative_check::finite_difference_force_derivative`]); a
    /// system may give the closed form. Zero without a potential.
    fn force_derivative(&self, g: &G) -> G::Operator {
        crate::derivative_check::finite_difference_force_derivative(self, g)
    }
    /// Whether an external (non-conservative) force `F_ext(t, g, ξ)` acts on the system (see
    /// [`crate::forces`]); integrators then apply it in the discrete Lagrange–d'Alembert way.
    fn is_forced(&self) -> bool {
        false
    }
    /// The external force or torque `F_ext(t, g, ξ) ∈ 𝔤*`, left-trivialized (body frame), at time t,
    /// configuration g (`None` when the run does not reconstruct it) and body velocity ξ; zero for
    /// an unforced system.
    fn external_force(&self, _t: f64, _g: Option<&G>, _xi: &G::Algebra) -> G::Algebra {
        G::Algebra::zeros(G::dim())
    }
    /// Whether the external force reads the body velocity ξ ([`crate::forces::ExternalForce::reads_velocity`]);
    /// `false` for an unforced system.
    fn external_force_reads_velocity(&self) -> bool {
        self.is_forced()
    }
    /// Whether integrators need the configuration g: a potential, or an external force that reads
    /// g.
    fn needs_configuration(&self) -> bool {
        self.has_potential()
    }
    /// A Casimir function C(μ) of the Lie–Poisson bracket, where the system has one it wants
    /// monitored (|Π|² for the free rigid body). Conserved exactly by the flow when there is no
    /// potential.
    fn casimir(&self, _mu: &G::Algebra) -> Option<f64> {
        None
    }
    /// The step density ρ(μ, g) > 0: the rate, in 1/time, at which the motion changes here, so
    /// that a step of the variable-step drivers is h = ε/ρ for a fixed ε
    /// ([`crate::adaptive::ReversibleSteps`], after Hairer–Söderlind 2005, where ρ = 1/σ and σ
    /// is their step size function), for a method whose step follows what `scope` says
    /// ([`DensityScope`], declared by the method: [`crate::SymmetricMethod::density_scope`]).
    ///
    /// The provided form is `|∂h/∂μ| + ω_V(g)` for either scope: the size of the body velocity
    /// (|Ω| for a rigid body) and the potential's frequency `ω_V² = ‖∂²h/∂μ² K(g)‖_max`, K the
    /// force derivative of [`System::force_derivative`] (for a pendulum of length l, ω_V² =
    /// (g/l)|cos θ|), which is 0 without a potential or without g. A model overrides it where it
    /// knows its own rate (an orbit's √(GM/r³)) or a rate that a [`DensityScope::SpinFollowed`]
    /// method need not resolve. For the reversibility of the drivers it must be even in μ,
    /// ρ(−μ, g) = ρ(μ, g), as the provided form is for a Hamiltonian even in μ.
    fn step_density(&self, mu: &G::Algebra, g: Option<&G>, _scope: DensityScope) -> f64 {
        let mut rho = self.velocity(mu).norm();
        if let Some(g) = g.filter(|_| self.has_potential()) {
            let k = self.hessian(mu).compose(&self.force_derivative(g));
            rho += k.norm_max().sqrt();
        }
        rho
    }
    /// `G = (1/ρ) dρ/dt` along the flow of the conservative system, `μ̇ = ad*_ξ μ + F(g)`,
    /// `ġ = g ξ` (ξ = ∂h/∂μ), for the density of the same `scope`: the right-hand side
    /// `dρ/dτ = G` of the step density in the fictitious time τ of Hairer–Söderlind's
    /// controller ([`crate::adaptive::ReversibleSteps`]). Odd in μ when ρ is even and h is even
    /// in μ.
    ///
    /// Provided by central differences of [`System::step_density`] along the flow
    /// ([`crate::derivative_check::finite_difference_step_density_rate`]: two density
    /// evaluations); a model gives the closed form where ρ is its own.
    fn step_density_rate(&self, mu: &G::Algebra, g: Option<&G>, scope: DensityScope) -> f64 {
        crate::derivative_check::finite_difference_step_density_rate(self, mu, g, scope)
    }
    /// The total energy `E = h(μ) + V(g)`; `g = None` counts V as 0 (only meaningful without a
    /// potential).
    fn energy(&self, mu: &G::Algebra, g: Option<&G>) -> f64 {
        self.hamiltonian(mu) + g.map_or(0.0, |g| self.potential(g))
    }

    // Facts about the model, for tools that choose steps and monitor invariants (`lie-sim`'s
    // ladders and monitors; a step density for step-size control). They do not enter any step.

    /// The characteristic rate ω(μ, g) ≥ 0 of the motion through (μ, g), in radians per unit of
    /// time: the fastest of the rotation rates and the frequencies of the potential and forces, so
    /// that a step resolves the motion when hω ≲ 1 (1/ω is the motion's time scale). `g = None`
    /// (a run that does not reconstruct g) leaves out what depends on the configuration.
    ///
    /// Provided: the Euclidean norm of the body velocity's coordinates, `|ξ|₂ = |∂h/∂μ(μ)|₂`,
    /// which bounds the fastest rotation of a body on SO(3) or SO(n) (for a velocity with linear
    /// parts it is not a rate: a length is missing). Models override it: the angular part alone
    /// on SE(2) and SE(3), plus the frequencies of the potential (the heavy top's pendulum
    /// `√(m g |χ| / λ_min(𝕀))`, a satellite's orbit `√(GM / |x|³)`, a spring's `√(k/m)`);
    /// [`crate::forces::Forced`] adds its force's ([`crate::forces::ExternalForce::characteristic_rate`]).
    fn characteristic_rate(&self, mu: &G::Algebra, _g: Option<&G>) -> f64 {
        euclidean_norm(&self.velocity(mu), 0..G::dim())
    }
    /// The rate `√(|τ|₂ / λ_min(𝕀))` at which a constant body-frame covector F (a generalized
    /// force; τ its torque part, 𝕀 the rotational inertia it acts on) turns the body through a
    /// radian: from rest, `θ(t) = ½ (|τ|/I) t²` reaches 1 after `√2 · √(I/|τ|)`. A torque sets
    /// a time scale, a force alone does not (a length is missing). Provided: 0, no rotational
    /// inertia declared; the rigid-body models override it.
    fn torque_rate(&self, _force: &G::Algebra) -> f64 {
        0.0
    }
    /// The quantities of the spatial momentum map `J = Ad*_{g⁻¹} μ` (in the basis of μ) that
    /// the exact flow conserves, each the sum of the listed components of J; empty when none is
    /// known to be.
    ///
    /// Provided: Noether's theorem for a left-invariant Hamiltonian — every component, each on
    /// its own, when there is no potential and no external force; nothing otherwise. A model whose
    /// potential is invariant under a subgroup lists what that symmetry keeps (the heavy top
    /// `J₃ = e₃·RΠ`, the angular momentum about the vertical).
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        if self.has_potential() || self.is_forced() {
            Vec::new()
        } else {
            (0..G::dim()).map(|i| vec![i]).collect()
        }
    }
    /// What [`Self::conserved_momentum_map`] keeps when, in addition, an external force acts in
    /// the body-frame components `pushed` of 𝔤* only (the force's
    /// [`crate::forces::ExternalForce::acts_on`]). Provided: all of it when nothing is pushed,
    /// nothing otherwise (the spatial image `Ad*_{g⁻¹} F` of a body force reaches, in general,
    /// every component). A model on a product with an abelian factor overrides it: a gyrostat's
    /// wheel torques move the wheel momenta p and leave `R Π`.
    fn conserved_momentum_map_under(&self, pushed: &[usize]) -> Vec<Vec<usize>> {
        if pushed.is_empty() {
            self.conserved_momentum_map()
        } else {
            Vec::new()
        }
    }
}

/// `(Σ_{i ∈ parts} vᵢ²)^{1/2}`: the Euclidean norm of some components of v, summed in index order
/// (the models' [`System::characteristic_rate`] read the angular part of a velocity with it).
pub fn euclidean_norm<V: Vector>(v: &V, parts: core::ops::Range<usize>) -> f64 {
    parts.map(|i| v.get(i) * v.get(i)).sum::<f64>().sqrt()
}

/// The trivialized force `F(g) = −T*_e L_g dV(g)`, zero when the system has no potential or no g.
#[inline]
pub(crate) fn force<G: LieGroup, S: System<G> + ?Sized>(
    system: &S,
    g: Option<&G>,
) -> Option<G::Algebra> {
    match g {
        Some(g) if system.has_potential() => Some(system.potential_differential(g).neg()),
        _ => None,
    }
}

/// The Lie–Poisson right-hand side `μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ)` at a state whose
/// velocity ξ = ∂h/∂μ(μ) the caller has already evaluated (the RKMK stages of
/// [`crate::Rkmk4`] and of the embedded pairs).
#[inline(always)]
pub(crate) fn lie_poisson_rate<G: LieGroup, S: System<G> + ?Sized>(
    system: &S,
    t: f64,
    g: Option<&G>,
    mu: &G::Algebra,
    xi: &G::Algebra,
) -> G::Algebra {
    let mut dmu = G::ad_dual_apply(xi, mu);
    if let Some(f) = force(system, g) {
        dmu = dmu.add(&f);
    }
    if system.is_forced() {
        dmu = dmu.add(&system.external_force(t, g, xi));
    }
    dmu
}
