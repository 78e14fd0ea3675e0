//! Trivialized discretization maps (§3.2): `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))` and their inverses.

use crate::equivariant_map::probe_reversible_increment;
use crate::{Discretization, DiscretizationError};
use core::marker::PhantomData;
use lie_groups::{LieGroup, Operator, Tau, Vector};

/// A family of discretization maps with one parameter θ ∈ [0, 1] — the paper's
/// `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))` on either side — so that integrators can be built from
/// θ alone (`integrators::LiePoisson::new(system, θ, μ₀, g₀)`).
pub trait ThetaFamily: Sized {
    /// The map with parameter θ (an error unless θ ∈ [0, 1]).
    fn with_theta(theta: f64) -> Result<Self, DiscretizationError>;
}

/// Stopping rule of the Newton solve used by [`DiscretizationMap::inverse`] when no closed form
/// exists (τ other than exp and 0 < θ < 1, θ ≠ ½).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonOptions {
    /// Iterations before giving up with [`DiscretizationError::NoConvergence`].
    pub max_iterations: usize,
    /// Converged when `‖τ⁻¹(Δ⁻¹ τ(θξ) τ((1−θ)ξ))‖_max ≤ tolerance · (1 + ‖ξ‖_max)`.
    pub tolerance: f64,
}

impl Default for NewtonOptions {
    /// 50 iterations, tolerance 4·10⁻¹⁶: Newton converges quadratically from the θ = 0 guess, so
    /// round-off is reached in a handful of iterations whenever a solution exists nearby.
    fn default() -> Self {
        Self {
            max_iterations: 50,
            tolerance: 4.0 * f64::EPSILON,
        }
    }
}

/// How [`DiscretizationMap::inverse`] solves `τ(θξ) τ((1−θ)ξ) = g_k⁻¹ g_{k+1}` for ξ.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InverseMethod {
    /// θ ∈ {0, 1}, or τ = exp (one-parameter subgroup: τ(θξ) τ((1−θ)ξ) = τ(ξ)): `ξ = τ⁻¹(Δ)`.
    TauInverse,
    /// θ = ½: τ(ξ/2) is the principal square root of Δ, `ξ = 2 τ⁻¹(exp(½ log Δ))`.
    SquareRoot,
    /// Any other θ: Newton's method from the guess `ξ₀ = τ⁻¹(Δ)`.
    Newton,
}

/// The left-trivialized discretization map of §3.2 built on a τ map `T`:
///
/// `R̃_d: G ⋉ 𝔤 → G × G,  (g, ξ) ↦ (g τ(−θξ), g τ((1−θ)ξ)),  θ ∈ [0, 1]`.
///
/// It satisfies the discretization axioms (i) `R̃_d(g, 0) = (g, g)` and (ii)
/// `d/dt R̃²(g, tξ) − d/dt R̃¹(g, tξ) = g ξ` at t = 0 (trivialized: the body velocities differ by
/// ξ). Its inverse recovers `(g, ξ)` from a pair `(g_k, g_{k+1})`: with `Δ = g_k⁻¹ g_{k+1}`, ξ solves
/// `τ(θξ) τ((1−θ)ξ) = Δ` and `g = g_k τ(θξ)`.
///
/// The map object holds θ and the Newton options; the group is chosen per call, so one map serves
/// every group on which `T` is a τ map:
///
/// ```
/// use discretization::DiscretizationMap;
/// use lie_groups::{Cayley, LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let rd = DiscretizationMap::<Cayley>::new(0.3).unwrap();
/// let g = So3::exp(&Vector3::new(0.1, 0.2, 0.3));
/// let xi = Vector3::new(0.4, -0.1, 0.2);
/// let (gk, gk1) = rd.apply(&g, &xi);
/// let (g_back, xi_back) = rd.inverse(&gk, &gk1).unwrap(); // a Newton solve for Cayley, θ = 0.3
/// assert!((xi_back - xi).norm() < 1e-13);
/// assert!(g_back.matrix_distance(&g) < 1e-13);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiscretizationMap<T> {
    theta: f64,
    newton: NewtonOptions,
    tau: PhantomData<T>,
}

impl<T> DiscretizationMap<T> {
    /// The map with parameter θ; an error unless θ is finite and in [0, 1].
    pub fn new(theta: f64) -> Result<Self, DiscretizationError> {
        if !(0.0..=1.0).contains(&theta) {
            return Err(DiscretizationError::InvalidTheta { theta });
        }
        Ok(Self {
            theta,
            newton: NewtonOptions::default(),
            tau: PhantomData,
        })
    }

    /// The same map with other Newton options.
    pub fn with_newton(self, newton: NewtonOptions) -> Self {
        Self { newton, ..self }
    }

    /// θ.
    #[inline]
    pub fn theta(&self) -> f64 {
        self.theta
    }

    /// The Newton options.
    #[inline]
    pub fn newton(&self) -> NewtonOptions {
        self.newton
    }

    /// How [`Self::inverse`] solves for ξ with this θ and τ map.
    pub fn inverse_method<G: LieGroup>(&self) -> InverseMethod
    where
        T: Tau<G>,
    {
        // Only for a one-parameter subgroup (exp) is τ(θξ) τ((1−θ)ξ) = τ(ξ) for every θ.
        if self.theta == 0.0 || self.theta == 1.0 || T::ONE_PARAMETER_SUBGROUP {
            InverseMethod::TauInverse
        } else if self.theta == 0.5 {
            InverseMethod::SquareRoot
        } else {
            InverseMethod::Newton
        }
    }

    /// `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))`.
    #[inline]
    pub fn apply<G: LieGroup>(&self, g: &G, xi: &G::Algebra) -> (G, G)
    where
        T: Tau<G>,
    {
        (
            g.compose(&T::tau(&xi.scale(-self.theta))),
            g.compose(&T::tau(&xi.scale(1.0 - self.theta))),
        )
    }

    /// `R̃_d⁻¹(g_k, g_{k+1}) = (g, ξ)`: ξ solves `τ(θξ) τ((1−θ)ξ) = g_k⁻¹ g_{k+1}` (see
    /// [`Self::solve_increment`]) and `g = g_k τ(θξ)`.
    pub fn inverse<G: LieGroup>(
        &self,
        gk: &G,
        gk1: &G,
    ) -> Result<(G, G::Algebra), DiscretizationError>
    where
        T: Tau<G>,
    {
        let xi = self.solve_increment(&gk.inverse().compose(gk1))?;
        Ok((gk.compose(&T::tau(&xi.scale(self.theta))), xi))
    }

    /// The ξ with `τ(θξ) τ((1−θ)ξ) = Δ`, the solution continuous from ξ = 0 at Δ = e:
    /// - θ ∈ {0, 1}, or τ = exp: `ξ = τ⁻¹(Δ)` (for exp, τ(θξ) τ((1−θ)ξ) = exp(ξ) for every θ);
    /// - θ = ½: `τ(ξ/2)² = Δ`, so `ξ = 2 τ⁻¹(√Δ)` with the principal root `√Δ = exp(½ log Δ)`;
    /// - otherwise Newton on `r(ξ) = τ⁻¹(Δ⁻¹ τ(θξ) τ((1−θ)ξ))` from `ξ₀ = τ⁻¹(Δ)`, with the exact
    ///   Jacobian `(d^L τ_r)⁻¹ Ad_{τ(−(1−θ)ξ)} M_θ(ξ)` ([`Self::split_tangent`]).
    ///
    /// Errors: τ⁻¹ or log undefined at the point ([`DiscretizationError::Lie`]), a singular Jacobian
    /// ([`DiscretizationError::SingularTangent`]), or no convergence.
    pub fn solve_increment<G: LieGroup>(&self, delta: &G) -> Result<G::Algebra, DiscretizationError>
    where
        T: Tau<G>,
    {
        let xi = match self.inverse_method::<G>() {
            InverseMethod::TauInverse => T::tau_inv(delta)?,
            InverseMethod::SquareRoot => T::tau_inv(&G::exp(&delta.log()?.scale(0.5)))?.scale(2.0),
            InverseMethod::Newton => self.newton_increment(delta)?,
        };
        if xi.is_finite() {
            Ok(xi)
        } else {
            Err(DiscretizationError::NonFinite {
                what: "g_k⁻¹ g_{k+1}",
            })
        }
    }

    fn newton_increment<G: LieGroup>(&self, delta: &G) -> Result<G::Algebra, DiscretizationError>
    where
        T: Tau<G>,
    {
        let theta = self.theta;
        let delta_inv = delta.inverse();
        let mut xi = T::tau_inv(delta)?;
        let mut residual = f64::INFINITY;
        for _ in 0..self.newton.max_iterations {
            let second = T::tau(&xi.scale(1.0 - theta));
            let product = T::tau(&xi.scale(theta)).compose(&second);
            let r = T::tau_inv(&delta_inv.compose(&product))?;
            residual = r.norm_max();
            if !residual.is_finite() {
                break;
            }
            if residual <= self.newton.tolerance * (1.0 + xi.norm_max()) {
                return Ok(xi);
            }
            // left-trivialized derivative of ξ ↦ τ(θξ) τ((1−θ)ξ) is Ad_{τ((1−θ)ξ)⁻¹} M_θ(ξ)
            let jp = second
                .inverse()
                .adjoint()
                .compose(&self.split_tangent::<G>(&xi));
            let jp_inv = jp
                .try_inverse()
                .ok_or(DiscretizationError::SingularTangent { xi_norm: xi.norm() })?;
            let step = jp_inv.apply(&T::dtau_left(&r).apply(&r));
            xi = xi.sub(&step);
        }
        Err(DiscretizationError::NoConvergence {
            iterations: self.newton.max_iterations,
            residual,
        })
    }

    /// `M_θ(ξ) = θ d^L τ_{θξ} + (1−θ) d^R τ_{(1−θ)ξ}`, the derivative of ξ ↦ τ(θξ) τ((1−θ)ξ)
    /// trivialized between its two factors: `τ(θξ)⁻¹ · δ[τ(θξ) τ((1−θ)ξ)] · τ((1−θ)ξ)⁻¹ = M_θ(ξ) δξ`.
    ///
    /// It is the operator every lifted inverse has to invert; it is invertible exactly where R̃_d is a
    /// local diffeomorphism, and `M_θ(0) = id`.
    pub fn split_tangent<G: LieGroup>(&self, xi: &G::Algebra) -> G::Operator
    where
        T: Tau<G>,
    {
        let theta = self.theta;
        T::dtau_left(&xi.scale(theta))
            .scale(theta)
            .add(&T::dtau_right(&xi.scale(1.0 - theta)).scale(1.0 - theta))
    }

    /// `M_θ(ξ)⁻¹`, by the closed-form inverse tangents of τ at θ ∈ {0, 1}
    /// (`M_0 = d^R τ_ξ`, `M_1 = d^L τ_ξ`) and a dense inverse otherwise; an error where singular.
    pub fn split_tangent_inv<G: LieGroup>(
        &self,
        xi: &G::Algebra,
    ) -> Result<G::Operator, DiscretizationError>
    where
        T: Tau<G>,
    {
        let singular = || DiscretizationError::SingularTangent { xi_norm: xi.norm() };
        let inv = if self.theta == 0.0 {
            T::dtau_right_inv(xi)
        } else if self.theta == 1.0 {
            T::dtau_left_inv(xi)
        } else {
            self.split_tangent::<G>(xi)
                .try_inverse()
                .ok_or_else(singular)?
        };
        // a singular d^L τ gives non-finite entries; probe them without allocating
        let probe = inv.apply(&G::Algebra::from_fn(xi.dim(), |i| 1.0 + i as f64));
        if probe.is_finite() {
            Ok(inv)
        } else {
            Err(singular())
        }
    }
}

impl<T> ThetaFamily for DiscretizationMap<T> {
    fn with_theta(theta: f64) -> Result<Self, DiscretizationError> {
        Self::new(theta)
    }
}

/// The θ-map as a [`Discretization`]: `a(ξ) = τ(−θξ)`, `b(ξ) = τ((1−θ)ξ)`, with the closed-form
/// tangents of τ and its descriptors exactly.
impl<G: LieGroup, T: Tau<G>> Discretization<G> for DiscretizationMap<T> {
    /// `a(ξ) = τ(−θξ)`.
    fn first_factor(&self, xi: &G::Algebra) -> G {
        T::tau(&xi.scale(-self.theta))
    }
    /// `b(ξ) = τ((1−θ)ξ)`.
    fn second_factor(&self, xi: &G::Algebra) -> G {
        T::tau(&xi.scale(1.0 - self.theta))
    }
    /// `d^L a_ξ = −θ d^Lτ_{−θξ}`.
    fn first_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        T::dtau_left(&xi.scale(-self.theta)).scale(-self.theta)
    }
    /// `d^L b_ξ = (1−θ) d^Lτ_{(1−θ)ξ}`.
    fn second_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        let b = 1.0 - self.theta;
        T::dtau_left(&xi.scale(b)).scale(b)
    }
    fn label(&self) -> String {
        format!("tau={}", T::NAME)
    }
    #[inline]
    fn theta(&self) -> f64 {
        self.theta
    }
    /// The adjoint of θ is 1 − θ: symmetric iff θ = ½.
    fn symmetric(&self) -> bool {
        self.theta == 0.5
    }
    /// `log(b(−ξ)⁻¹ a(ξ)) = log(τ((1−θ)ξ) τ(−θξ)) = (1 − 2θ) ξ + O(|ξ|³)` (τ(ξ)τ(−ξ) = e makes
    /// log τ odd, and brackets of parallel vectors vanish): order 2 iff θ = ½.
    fn order(&self) -> u32 {
        if self.theta == 0.5 {
            2
        } else {
            1
        }
    }
    /// `c(ξ) = τ(θξ) τ((1−θ)ξ)`: `τ(ξ)` at θ ∈ {0, 1}, `τ(ξ/2)²` at θ = ½ and `exp(ξ)` for exp —
    /// reversible at once; otherwise reversible where the two factors commute (Cayley: both are
    /// rational functions of ξ̂), which is measured ([`crate::probe_reversible_increment`]).
    fn reversible_increment(&self) -> bool {
        let th = self.theta;
        th == 0.0
            || th == 0.5
            || th == 1.0
            || T::ONE_PARAMETER_SUBGROUP
            || probe_reversible_increment::<G, Self>(self)
    }
    /// `τ(ξ) τ(−ξ) = e` makes log τ odd, `τ(ξ) = exp(ξ + O(|ξ|³))`, so by BCH (the brackets of
    /// parallel vectors vanish) `c(ξ) = exp(ξ + O(|ξ|³))`: 2 for every θ.
    fn increment_order(&self) -> u32 {
        2
    }
    /// `a ≡ e` iff θ = 0.
    #[inline]
    fn base_is_first_point(&self) -> bool {
        self.theta == 0.0
    }
    /// `τ⁻¹(τ(η)) = η` to `1e-8 (1 + ‖η‖)`; skipped inside `Tau::INVERTIBLE_RADIUS` (compared
    /// squared: no square root on the step's path).
    #[inline]
    fn check_domain(&self, eta: &G::Algebra) -> Result<(), DiscretizationError> {
        if eta.dot(eta) <= T::INVERTIBLE_RADIUS * T::INVERTIBLE_RADIUS {
            Ok(())
        } else {
            tau_round_trip::<G, T>(eta)
        }
    }
}

#[cold]
fn tau_round_trip<G: LieGroup, T: Tau<G>>(eta: &G::Algebra) -> Result<(), DiscretizationError> {
    let outside = || DiscretizationError::OutsideTauDomain {
        tau: T::NAME,
        xi_norm: eta.norm(),
    };
    let back = T::tau_inv(&T::tau(eta)).map_err(|_| outside())?;
    if back.sub(eta).norm_max() <= 1e-8 * (1.0 + eta.norm_max()) {
        Ok(())
    } else {
        Err(outside())
    }
}
