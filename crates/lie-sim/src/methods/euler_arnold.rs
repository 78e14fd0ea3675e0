//! `euler-arnold`: the Euler–Poincaré integrator of the quadratic Lagrangian l(ξ) = ½⟨𝕀ξ, ξ⟩,
//! with 𝕀 = (∂²h/∂μ²)⁻¹ taken from the system ([`EulerArnoldOf`]): for purely kinetic systems.

use super::euler_poincare::Ep;
use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, Missing, Model};
use crate::sim::Boxed;
use crate::taus::{with_tau, TauKind};
use integrators::{EulerArnold, IntegratorError, SolverConfig, System};
use lie_groups::{LieGroup, Operator, Vector};

/// The row.
pub const ROW: Row = Row {
    name: "euler-arnold",
    summary: "Euler–Poincaré integrator of the Euler–Arnold system l(ξ) = ½⟨𝕀ξ, ξ⟩ (§2.3), 𝕀 the \
              inverse Hessian of the system's kinetic energy; purely kinetic systems only",
    takes: Takes {
        tau: TauRule::Any,
        theta: true,
        coefficients: false,
        modified: false,
        wrappers: true,
        stepping: Stepping::Fixed,
    },
    trade: Trade {
        thetas: super::row::THETAS,
        compositions: &[],
        modified: &[],
        processing: false,
        one_step: false,
        reversible: &[],
    },
    family,
    second: false,
    marker: None,
    batch: None,
    step_limit: Some(1.0),
};

fn family(_: &Options) -> &'static Family {
    &families::EULER_ARNOLD
}

/// Builds it, on a system without potential and forces.
pub fn build<M: Model>(
    options: &Options,
    config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    let s = model.system();
    let lacks = if s.has_potential() {
        Some("a potential V(g)")
    } else if s.is_forced() {
        Some("external forces ([forces])")
    } else {
        None
    };
    if let Some(what) = lacks {
        return Err(BuildError::missing(
            "euler-arnold needs a purely kinetic Lagrangian l(ξ) = ½⟨𝕀ξ, ξ⟩",
            Missing::because(format!(
                "this {} has {what}; use lie-poisson or euler-poincare",
                model.kind()
            )),
        ));
    }
    let system = EulerArnoldOf::new(s.clone(), &mu0)?;
    with_tau(
        options.tau.unwrap_or(TauKind::Cayley),
        Ep {
            system,
            options,
            name: ROW.name,
            config,
            kind: model.kind(),
            mu0,
            g0,
        },
    )
}

/// The Euler–Arnold system of a purely kinetic system S: l(ξ) = ½⟨𝕀ξ, ξ⟩ with
/// 𝕀 = (∂²h/∂μ²)⁻¹ (constant for the quadratic h(μ) = ½⟨μ, 𝕀⁻¹μ⟩ of the free rigid body, the free
/// SE(3) and SE(2) bodies and the SO(n) geodesics), symmetrised as ½(𝕀 + 𝕀ᵀ) against the
/// rounding of the inversion. The dynamics are `integrators::EulerArnold`'s; the Casimir
/// monitored is S's (it depends on μ only), so that `euler-arnold` runs report it like the others.
#[derive(Debug, Clone)]
pub struct EulerArnoldOf<G: LieGroup, S> {
    ea: EulerArnold<G>,
    original: S,
}

/// Relative agreement required between S's h and the Euler–Arnold h at the probe momenta: a
/// quadratic h agrees to a few ulps (the only rounding is the inversion of a well-conditioned
/// inertia), a non-quadratic one (or one with a hidden potential term in h) by far more.
const EULER_ARNOLD_AGREEMENT: f64 = 1e-10;

impl<G: LieGroup, S: integrators::System<G>> EulerArnoldOf<G, S> {
    /// Builds 𝕀 from S's Hessian at μ₀ and checks that h_S(μ) = ½⟨μ, 𝕀⁻¹μ⟩ at μ₀ and at
    /// μ = (1, …, 1), to [`EULER_ARNOLD_AGREEMENT`] relative.
    pub fn new(original: S, mu0: &G::Algebra) -> Result<Self, IntegratorError> {
        if original.has_potential() {
            return Err(IntegratorError::InvalidParameter {
                reason: "Euler–Arnold needs a purely kinetic Lagrangian: the system has a \
                         potential V(g)"
                    .into(),
            });
        }
        let inv = original.hessian(mu0).try_inverse().ok_or_else(|| {
            IntegratorError::InvalidParameter {
                reason: "the Hessian ∂²h/∂μ² is singular: no inertia operator".into(),
            }
        })?;
        let inertia = inv.add(&inv.transpose()).scale(0.5);
        let ea = EulerArnold::<G>::new(inertia)?;
        let ones = G::Algebra::from_fn(G::dim(), |_| 1.0);
        for mu in [mu0, &ones] {
            let (a, b) = (
                integrators::System::<G>::hamiltonian(&ea, mu),
                original.hamiltonian(mu),
            );
            if (a - b).abs() > EULER_ARNOLD_AGREEMENT * b.abs() {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!(
                        "Euler–Arnold needs a quadratic kinetic energy: h(μ) = {b} but \
                         ½⟨μ, 𝕀⁻¹μ⟩ = {a}"
                    ),
                });
            }
        }
        Ok(Self { ea, original })
    }
}

impl<G: LieGroup, S: integrators::System<G>> integrators::System<G> for EulerArnoldOf<G, S> {
    fn hamiltonian(&self, mu: &G::Algebra) -> f64 {
        self.ea.hamiltonian(mu)
    }
    fn velocity(&self, mu: &G::Algebra) -> G::Algebra {
        self.ea.velocity(mu)
    }
    fn hessian(&self, mu: &G::Algebra) -> G::Operator {
        self.ea.hessian(mu)
    }
    fn hessian_norm(&self, mu: &G::Algebra) -> f64 {
        self.ea.hessian_norm(mu)
    }
    fn momentum(&self, xi: &G::Algebra) -> G::Algebra {
        self.ea.momentum(xi)
    }
    fn casimir(&self, mu: &G::Algebra) -> Option<f64> {
        self.original.casimir(mu)
    }
}
