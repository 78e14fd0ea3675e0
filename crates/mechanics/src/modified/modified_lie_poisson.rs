//! The Lie–Poisson scheme on the modified Hamiltonian of the free rigid body: order 4 or 6 at the
//! cost of one order-2 step.

use super::{ModifiedRigidBody, ModifiedScheme, ModifiedTau};
use crate::systems::RigidBody;
use integrators::compose::{StateSnapshot, SymmetricMethod};
use integrators::{Integrator, IntegratorError, LiePoisson, MethodInfo, SolverConfig, System};
use lie_groups::So3;
use nalgebra::Vector3;

/// The Lie–Poisson scheme (eq. 19, [`LiePoisson`]) with θ = ½ or θ = 0 applied, at each step h,
/// to the modified Hamiltonian `H̃_h = H − h² H₂ [− h⁴ H₄]` of [`ModifiedRigidBody`]: order 4 or 6
/// ([`ModifiedScheme`]) for the free rigid body at the cost of one order-2 step (the Newton
/// iteration sees a slightly different Hessian).
///
/// - symmetric (H̃_{−h} = H̃_h, and the kernel is symmetric: θ = ½, or θ = 0 without a potential,
///   where it coincides with its adjoint θ = 1), implicit, a Poisson map;
/// - |Π|² and the spatial momentum RΠ conserved to round-off (H̃ is left-invariant);
/// - the energy H (reported by [`Integrator::energy`], not H̃) bounded with no drift: the
///   modified Hamiltonian of the step, H + O(hᵖ), is conserved to O(hᵖ) exponentially long.
///
/// The kernel is rebuilt (a copy of the body, no allocation) only when h changes. Errors as
/// [`LiePoisson`]: a non-finite h, a step beyond τ's domain or without Newton convergence leave
/// the state untouched; and a step beyond [`ModifiedLiePoisson::step_limit`], where the
/// modification no longer is a perturbation of H, is refused
/// ([`IntegratorError::StepTooLarge`], naming h and the limit) with the state untouched.
///
/// ```
/// use mechanics::modified::{ModifiedLiePoisson, ModifiedScheme};
/// use integrators::{Integrator};
/// use mechanics::RigidBody;
/// use lie_groups::{Cayley, LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([1.0, 2.0, 3.0])?;
/// let pi0 = Vector3::new(0.5, 1.0, 0.2);
/// // Order 6 from the cheaper θ = 0 step.
/// let scheme = ModifiedScheme::new(0.0, 6)?;
/// let mut m = ModifiedLiePoisson::<Cayley>::with_scheme(body, scheme, pi0, Some(So3::identity()))?;
/// for _ in 0..100 {
///     m.step(0.1)?;
/// }
/// assert_eq!(m.info().order, 6);
/// assert!((m.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-14);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ModifiedLiePoisson<T: ModifiedTau> {
    body: RigidBody,
    scheme: ModifiedScheme,
    /// [`ModifiedRigidBody::step_limit`] on the orbit of the state set last (|Π|² is kept to
    /// round-off, H to O(hᵖ): the limit holds for the run).
    step_limit: f64,
    kernel: LiePoisson<So3, T, ModifiedRigidBody<T>>,
}

impl<T: ModifiedTau> ModifiedLiePoisson<T> {
    /// The θ = ½, order-4 integrator at t = 0 from Π₀ and optionally R₀. Errors: non-finite Π₀
    /// or R₀.
    pub fn new(
        body: RigidBody,
        pi0: Vector3<f64>,
        r0: Option<So3>,
    ) -> Result<Self, IntegratorError> {
        Self::with_scheme(body, ModifiedScheme::default(), pi0, r0)
    }
    /// The integrator of `scheme` (θ ∈ {½, 0}, order ∈ {4, 6}) at t = 0 from Π₀ and optionally
    /// R₀. Errors: non-finite Π₀ or R₀.
    pub fn with_scheme(
        body: RigidBody,
        scheme: ModifiedScheme,
        pi0: Vector3<f64>,
        r0: Option<So3>,
    ) -> Result<Self, IntegratorError> {
        let modified = ModifiedRigidBody::new(body.clone(), scheme, 0.0)?;
        let step_limit = modified.step_limit(&pi0);
        let kernel = LiePoisson::new(modified, scheme.theta(), pi0, r0)?;
        Ok(Self {
            body,
            scheme,
            step_limit,
            kernel,
        })
    }
    /// The largest |h| a step takes ([`ModifiedRigidBody::step_limit`] on the orbit of the
    /// state given at construction or [`ModifiedLiePoisson::reset`]): beyond it the modification
    /// bends H̃ more than [`super::CURVATURE_LIMIT`] allows and the step is refused.
    pub fn step_limit(&self) -> f64 {
        self.step_limit
    }
    /// The θ and order.
    pub fn scheme(&self) -> ModifiedScheme {
        self.scheme
    }
    /// Replaces the kernel's solver configuration.
    pub fn with_solver(mut self, config: SolverConfig) -> Self {
        self.kernel = self.kernel.with_solver(config);
        self
    }
    /// Resets the state to (t, Π, R), with the checks of [`ModifiedLiePoisson::new`].
    pub fn reset(
        &mut self,
        t: f64,
        pi: Vector3<f64>,
        r: Option<So3>,
    ) -> Result<(), IntegratorError> {
        self.kernel.reset(t, pi, r)?;
        self.step_limit = self.kernel.system().step_limit(&pi);
        Ok(())
    }
    /// The (unmodified) body.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }
    /// The kernel: Lie–Poisson on the Hamiltonian modified for the last step size.
    pub fn kernel(&self) -> &LiePoisson<So3, T, ModifiedRigidBody<T>> {
        &self.kernel
    }
}

impl<T: ModifiedTau> Integrator for ModifiedLiePoisson<T> {
    type Group = So3;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        if h.abs() > self.step_limit {
            return Err(IntegratorError::StepTooLarge {
                step: h,
                reason: format!(
                    "the modified Hamiltonian of order {} is valid for |h| ≤ {:e} on this orbit \
                     (beyond, h²H₂{} bends H̃ by more than {} times H's curvature)",
                    self.scheme.order(),
                    self.step_limit,
                    if self.scheme.order() == 6 {
                        " + h⁴H₄"
                    } else {
                        ""
                    },
                    super::CURVATURE_LIMIT
                ),
            });
        }
        if self.kernel.system().step_size() != h {
            let (t, pi, r) = self.kernel.snapshot();
            let modified = ModifiedRigidBody::new(self.body.clone(), self.scheme, h)?;
            let mut kernel = LiePoisson::new(modified, self.scheme.theta(), pi, r)?
                .with_solver(*self.kernel.solver());
            kernel.set_time(t)?;
            self.kernel = kernel;
        }
        self.kernel.step(h)
    }
    fn time(&self) -> f64 {
        self.kernel.time()
    }
    fn momentum(&self) -> Vector3<f64> {
        self.kernel.momentum()
    }
    /// Ω = 𝕀⁻¹Π (the body's velocity, not the modified one).
    fn velocity(&self) -> Vector3<f64> {
        self.body.velocity(&self.kernel.momentum())
    }
    fn momentum_rate(&self) -> Vector3<f64> {
        integrators::dense_output::momentum_rate(
            &self.body,
            self.time(),
            &self.momentum(),
            self.configuration(),
        )
    }
    fn configuration(&self) -> Option<&So3> {
        self.kernel.configuration()
    }
    /// The body's energy H(Π) (not H̃).
    fn energy(&self) -> f64 {
        self.body.hamiltonian(&self.kernel.momentum())
    }
    fn casimir(&self) -> Option<f64> {
        Some(self.kernel.momentum().norm_squared())
    }
    fn method_name(&self) -> String {
        format!(
            "modified-lie-poisson(order={}, tau={}, theta={})",
            self.scheme.order(),
            <T as lie_groups::Tau<So3>>::NAME,
            self.scheme.theta()
        )
    }
    /// The scheme's order (4 or 6), symmetric, implicit, Poisson, Casimirs and momentum map kept,
    /// on the group.
    fn info(&self) -> MethodInfo {
        MethodInfo {
            order: self.scheme.order(),
            symmetric: true,
            explicit: false,
            poisson: true,
            casimirs: true,
            momentum_map: true,
            energy: false,
            on_group: true,
        }
    }
}

impl<T: ModifiedTau> SymmetricMethod for ModifiedLiePoisson<T> {
    /// Always: H̃ depends on h², and the kernel is θ = ½, or θ = 0 without a potential (which
    /// coincides with its adjoint θ = 1).
    fn is_symmetric(&self) -> bool {
        true
    }
}

impl<T: ModifiedTau> StateSnapshot for ModifiedLiePoisson<T> {
    /// (t, Π, R).
    type State = (f64, Vector3<f64>, Option<So3>);
    fn snapshot(&self) -> Self::State {
        self.kernel.snapshot()
    }
    fn restore(&mut self, state: Self::State) -> Result<(), IntegratorError> {
        self.kernel.restore(state)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        self.kernel.set_time(t)
    }
}
