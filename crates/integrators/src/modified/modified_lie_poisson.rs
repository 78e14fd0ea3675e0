//! The θ = ½ Lie–Poisson scheme on the modified Hamiltonian of the free rigid body: order 4.

use super::{ModifiedRigidBody, ModifiedTau};
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::systems::RigidBody;
use crate::{Integrator, IntegratorError, LiePoisson, MethodInfo, SolverConfig, System};
use lie_groups::So3;
use nalgebra::Vector3;

/// The θ = ½ Lie–Poisson scheme (eq. 19, [`LiePoisson`]) applied, at each step h, to the modified
/// Hamiltonian `H̃_h = H − h² H₂` of [`ModifiedRigidBody`]: order 4 for the free rigid body at
/// the cost of one order-2 step (the Newton iteration sees a slightly different Hessian).
///
/// - symmetric (H̃_{−h} = H̃_h and the kernel is symmetric), implicit, a Poisson map;
/// - |Π|² and the spatial momentum RΠ conserved to round-off (H̃ is left-invariant);
/// - the energy H (reported by [`Integrator::energy`], not H̃) bounded with no drift: H̃_h + O(h⁴)
///   is conserved, H = H̃_h + h²H₂.
///
/// The kernel is rebuilt (a copy of the body, no allocation) only when h changes. Errors as
/// [`LiePoisson`]: a non-finite h, a step beyond τ's domain or without Newton convergence leave
/// the state untouched.
///
/// ```
/// use integrators::{modified::ModifiedLiePoisson, Integrator, systems::RigidBody};
/// use lie_groups::{Cayley, LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal(1.0, 2.0, 3.0)?;
/// let pi0 = Vector3::new(0.5, 1.0, 0.2);
/// let mut m = ModifiedLiePoisson::<Cayley>::new(body, pi0, Some(So3::identity()))?;
/// for _ in 0..100 {
///     m.step(0.1)?;
/// }
/// assert_eq!(m.info().order, 4);
/// assert!((m.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-14);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ModifiedLiePoisson<T: ModifiedTau> {
    body: RigidBody,
    kernel: LiePoisson<So3, T, ModifiedRigidBody<T>>,
}

impl<T: ModifiedTau> ModifiedLiePoisson<T> {
    /// The integrator at t = 0 from Π₀ and optionally R₀. Errors: non-finite Π₀ or R₀.
    pub fn new(
        body: RigidBody,
        pi0: Vector3<f64>,
        r0: Option<So3>,
    ) -> Result<Self, IntegratorError> {
        let modified = ModifiedRigidBody::new(body.clone(), 0.0)?;
        let kernel = LiePoisson::new(modified, 0.5, pi0, r0)?;
        Ok(Self { body, kernel })
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
        self.kernel.reset(t, pi, r)
    }
    /// The (unmodified) body.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }
    /// The kernel: θ = ½ Lie–Poisson on the Hamiltonian modified for the last step size.
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
        if self.kernel.system().step_size() != h {
            let (t, pi, r) = self.kernel.snapshot();
            let modified = ModifiedRigidBody::new(self.body.clone(), h)?;
            let mut kernel =
                LiePoisson::new(modified, 0.5, pi, r)?.with_solver(*self.kernel.solver());
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
        crate::dense_output::momentum_rate(
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
            "modified-lie-poisson(order=4, tau={}, theta=0.5)",
            <T as lie_groups::Tau<So3>>::NAME
        )
    }
    /// Order 4, symmetric, implicit, Poisson, Casimirs and momentum map kept, on the group.
    fn info(&self) -> MethodInfo {
        MethodInfo {
            order: 4,
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
    /// Always: the kernel is θ = ½ and H̃ depends on h².
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
