//! The processed method `Ψ_h = P_h ∘ K_h ∘ P_h⁻¹`, applied so that P runs only when the state is
//! read.

use super::{ComposedKernel, ProcessingKernel, ProcessingScheme};
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::{Integrator, IntegratorError, MethodInfo};
use lie_groups::{LieGroup, Vector};
use std::sync::OnceLock;

/// A kernel K processed by its processor P: the method `Ψ_h = P_h ∘ K_h ∘ P_h⁻¹`, whose n steps
/// are `P_h ∘ K_hⁿ ∘ P_h⁻¹` (Blanes, Casas & Ros 1999, "Symplectic integration with processing: a
/// general study", SIAM J. Sci. Comput. 21; Blanes, Casas & Murua 2004, SIAM J. Numer. Anal. 42).
///
/// The state is held in kernel coordinates y = P⁻¹(x):
/// - **setting** the state (construction, [`Processed::reset`]) stores x; the first step applies
///   P⁻¹ (`P_{|h|}⁻¹`, h of that step) before K;
/// - **stepping** advances y by K_h only — P is never applied per step;
/// - **reading** (every read of the [`Integrator`] trait: [`Integrator::momentum`],
///   [`Integrator::configuration`], [`Integrator::energy`], …, and [`Processed::output`])
///   returns x = P(y), computed on the first read after a step and kept until the next step. y is
///   never changed by a read, so n steps then a read give bitwise the state of reading after
///   every step, and reading twice never corrects twice.
///
/// The processor is `P_{|h|}`: for a symmetric kernel the processor's logarithm is even in h,
/// so the same P serves steps of both signs, Ψ is symmetric and n steps of h then n of −h return
/// to the start. A step whose |h| differs from the last one re-processes once:
/// `y ← P_{|h'|}⁻¹(P_{|h|}(y))` (the shortened last step of a run does this).
///
/// Errors: a non-finite h is [`IntegratorError::NonFinite`]; a failed kernel stage or processor
/// stage returns the stage's error and leaves the state (y, the processing step, the cached
/// output) exactly as it was. A processor that fails when the state is *read* (an implicit
/// basic method's Newton iteration not converging at one of P's stages — the stages are no
/// larger than the kernel's, so this is not expected where the steps succeed) makes the reads
/// NaN and [`Integrator::read_error`] (and [`Processed::output`]) return the error; the state is
/// untouched and stepping goes on.
///
/// ```
/// use integrators::processing::{Processed, ProcessingScheme};
/// use integrators::{Integrator, splitting::Splitting};
/// use mechanics::RigidBody;
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let body = RigidBody::principal([1.0, 2.0, 3.0])?;
/// let pi0 = Vector3::new(0.5, 1.0, 0.2);
/// let strang = Splitting::new(body, pi0, Some(So3::identity()))?;
/// // Effective order 6 from 11 Strang steps a step (Kahan–Li's order-6 composition takes 9, with a
/// // leading error coefficient 29× larger: tools/processing_conditions.txt).
/// let mut psi = Processed::composition(strang, ProcessingScheme::blanes_casas_murua_6_11())?;
/// for _ in 0..100 {
///     psi.step(0.1)?;
/// }
/// assert_eq!(psi.info().order, 6);
/// assert!((psi.casimir().unwrap() - pi0.norm_squared()).abs() < 1e-13);
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Processed<K: ProcessingKernel> {
    /// y = P⁻¹(x) when `processing` is Some(|h|); x itself before the first step.
    kernel: K,
    /// The |h| of the processor y is taken with.
    processing: Option<f64>,
    /// P(y), computed on the first read after a step.
    output: OnceLock<Result<K, IntegratorError>>,
}

impl<K: ProcessingKernel> Processed<K> {
    /// Wraps `kernel`, whose current state is taken as the state x. Errors
    /// ([`IntegratorError::InvalidParameter`]) if the kernel is not symmetric, naming it.
    pub fn new(kernel: K) -> Result<Self, IntegratorError> {
        if !kernel.is_symmetric() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "processing needs a symmetric kernel, {} is not",
                    kernel.method_name()
                ),
            });
        }
        Ok(Self {
            kernel,
            processing: None,
            output: OnceLock::new(),
        })
    }

    /// Sets the state x (in the kernel's [`StateSnapshot::State`] form, e.g. (t, μ, g)); the
    /// next step applies P⁻¹. Errors as the kernel's `restore` (non-finite values), leaving the
    /// state as it was.
    pub fn reset(&mut self, state: K::State) -> Result<(), IntegratorError> {
        let mut kernel = self.kernel.clone();
        kernel.restore(state)?;
        self.kernel = kernel;
        self.processing = None;
        self.output = OnceLock::new();
        Ok(())
    }

    /// The state x = P(y) as the kernel type (so every accessor of the kernel reads it), or the
    /// processor's error.
    pub fn output(&self) -> Result<&K, &IntegratorError> {
        match self.processing {
            None => Ok(&self.kernel),
            Some(h) => self
                .output
                .get_or_init(|| {
                    let mut x = self.kernel.clone();
                    x.process(h, false).map(|()| x)
                })
                .as_ref(),
        }
    }

    /// The kernel, in kernel coordinates y = P⁻¹(x) (x itself before the first step).
    pub fn kernel(&self) -> &K {
        &self.kernel
    }

    /// The |h| of the processor the kernel state is taken with (`None` before the first step).
    pub fn processing_step(&self) -> Option<f64> {
        self.processing
    }

    /// NaN of the algebra's dimension: what a read returns when the processor fails.
    fn nan() -> <K::Group as LieGroup>::Algebra {
        <K::Group as LieGroup>::Algebra::zeros(K::Group::dim()).scale(f64::NAN)
    }
}

impl<I: SymmetricMethod + StateSnapshot + Clone> Processed<ComposedKernel<I>> {
    /// The processed composition of `scheme` on the symmetric basic method Φ = `basic`, from
    /// Φ's current state. Errors if Φ is not symmetric (e.g. Lie–Poisson with θ ≠ ½), naming it.
    pub fn composition(basic: I, scheme: ProcessingScheme) -> Result<Self, IntegratorError> {
        Self::new(ComposedKernel::new(basic, scheme)?)
    }
}

impl<K: ProcessingKernel> Integrator for Processed<K> {
    type Group = K::Group;

    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let hp = h.abs();
        if self.processing == Some(hp) {
            self.kernel.step(h)?;
        } else {
            // (Re)processing: x = P_old(y) (or x itself), y' = P_{|h|}⁻¹(x), then K_h — on a
            // copy, so that a failure leaves everything as it was.
            let mut y = match self.output() {
                Ok(x) => x.clone(),
                Err(e) => return Err(e.clone()),
            };
            y.process(hp, true)?;
            y.step(h)?;
            self.kernel = y;
            self.processing = Some(hp);
        }
        self.output = OnceLock::new();
        Ok(())
    }
    fn time(&self) -> f64 {
        self.kernel.time()
    }
    fn momentum(&self) -> <K::Group as LieGroup>::Algebra {
        self.output().map_or_else(|_| Self::nan(), |x| x.momentum())
    }
    fn velocity(&self) -> <K::Group as LieGroup>::Algebra {
        self.output().map_or_else(|_| Self::nan(), |x| x.velocity())
    }
    fn momentum_rate(&self) -> <K::Group as LieGroup>::Algebra {
        self.output()
            .map_or_else(|_| Self::nan(), |x| x.momentum_rate())
    }
    fn configuration(&self) -> Option<&K::Group> {
        self.output().ok().and_then(|x| x.configuration())
    }
    fn energy(&self) -> f64 {
        self.output().map_or(f64::NAN, |x| x.energy())
    }
    fn casimir(&self) -> Option<f64> {
        match self.output() {
            Ok(x) => x.casimir(),
            Err(_) => self.kernel.casimir().map(|_| f64::NAN),
        }
    }
    fn read_error(&self) -> Option<IntegratorError> {
        self.output().err().cloned()
    }
    fn method_name(&self) -> String {
        self.kernel.processed_name()
    }
    /// The effective order, symmetric (P_{|h|} serves both signs of h), and whatever the kernel
    /// keeps: P and K are compositions of the basic method, so every flag of [`MethodInfo`] that
    /// is closed under composition carries over to the output P Kⁿ P⁻¹.
    fn info(&self) -> MethodInfo {
        MethodInfo {
            order: self.kernel.effective_order(),
            symmetric: true,
            ..self.kernel.info()
        }
    }
    fn side(&self) -> discretization::Side {
        self.kernel.side()
    }
}
