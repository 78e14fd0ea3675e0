//! `lie-poisson`: the cotangent-lift Lie–Poisson integrator (eq. 19 of the paper; §4 at θ = 0),
//! and with `modified = true` the free rigid body's modified Hamiltonian (`mechanics::modified`).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::{wrap, BuildError};
use crate::model::{Alg, FreeBodyVisitor, Model};
use crate::sim::Boxed;
use crate::taus::{with_tau, TauKind, TauVisitor};
use integrators::{LiePoisson, SolverConfig};
use lie_groups::{Cayley, CayleyGroup, ExpMap, LieGroup, So3, Tau};
use mechanics::modified::{ModifiedLiePoisson, ModifiedRigidBody, ModifiedScheme};
use mechanics::RigidBody;
use nalgebra::Vector3;

/// The row.
pub const ROW: Row = Row {
    name: "lie-poisson",
    summary: "Cotangent-lift Lie–Poisson integrator, eq. (19) (§4 at θ = 0); with `modified = \
              true`, on the free rigid body's modified Hamiltonian H − h²H₂ [− h⁴H₄] \
              (mechanics::modified)",
    takes: Takes {
        tau: TauRule::Any,
        theta: true,
        coefficients: false,
        modified: true,
        wrappers: true,
        stepping: Stepping::Fixed,
    },
    trade: Trade {
        thetas: super::row::THETAS,
        // The cheapest order 4 (3 stages) and the optimised order-6 (9 stages) and order-8
        // (17 stages) schemes: where each order starts to pay for its stages.
        compositions: &["triple-jump-4", "kahan-li-6", "kahan-li-8"],
        // Every modified scheme derived (for τ = exp the θ = 0 and θ = ½ schemes are the same
        // map, θ = 0 the cheaper step).
        modified: &[(0.5, 4), (0.0, 4), (0.5, 6), (0.0, 6)],
        processing: true,
        one_step: false,
        reversible: &[None],
    },
    family,
    second: false,
    marker: None,
    batch: None,
    step_limit: Some(0.5),
};

fn family(m: &Options) -> &'static Family {
    if m.modified.is_some() {
        &families::MODIFIED
    } else if m.composition.is_some() {
        &families::COMPOSITIONS
    } else {
        &families::LIE_POISSON
    }
}

/// What the modified Hamiltonian needs.
const MODIFIED_NEEDS: &str =
    "the modified Hamiltonian (modified = true) is derived for the free rigid body only";

/// Builds it.
pub fn build<M: Model>(
    options: &Options,
    config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    if let Some(order) = options.modified {
        let visitor = Modified {
            options,
            config,
            order,
        };
        return model
            .free_body(visitor, mu0, g0)
            .map_err(|m| BuildError::missing(MODIFIED_NEEDS, m))?;
    }
    let tau = options.tau.unwrap_or(TauKind::Cayley);
    with_tau(
        tau,
        Lp {
            system: model.system().clone(),
            options,
            config,
            kind: model.kind(),
            mu0,
            g0,
        },
    )
}

/// The integrator with τ = T.
struct Lp<'a, G: LieGroup, S> {
    system: S,
    options: &'a Options,
    config: &'a SolverConfig,
    kind: &'static str,
    mu0: G::Algebra,
    g0: Option<G>,
}

impl<G, S> TauVisitor<G> for Lp<'_, G, S>
where
    G: CayleyGroup + 'static,
    S: integrators::System<G> + Clone + 'static,
{
    type Out = Result<Boxed<G>, BuildError>;
    fn visit<T: Tau<G>>(self) -> Self::Out {
        let theta = self.options.theta.unwrap_or(0.0);
        let lp = LiePoisson::<G, T, S>::new(self.system.clone(), theta, self.mu0, self.g0)?
            .with_solver(*self.config);
        wrap(lp, &self.system, self.options, ROW.name, self.kind)
    }
}

/// The modified Lie–Poisson step on the free body. Its coefficients are derived per τ
/// (`mechanics::modified::ModifiedTau`), so a τ without them is refused here.
struct Modified<'a> {
    options: &'a Options,
    config: &'a SolverConfig,
    order: u32,
}

impl FreeBodyVisitor for Modified<'_> {
    type Out<G: LieGroup> = Result<Boxed<G>, BuildError>;
    fn visit(self, body: &RigidBody, mu0: Vector3<f64>, g0: Option<So3>) -> Self::Out<So3> {
        let scheme = ModifiedScheme::new(self.options.theta.unwrap_or(0.5), self.order)?;
        let body = body.clone();
        let c = *self.config;
        // A τ added to `crate::taus` reaches the last arm until its coefficients exist.
        #[allow(unreachable_patterns)]
        Ok(match self.options.tau.unwrap_or(TauKind::Cayley) {
            TauKind::Exp => Boxed::new(
                ModifiedLiePoisson::<ExpMap>::with_scheme(body, scheme, mu0, g0)?.with_solver(c),
            ),
            TauKind::Cayley => Boxed::new(
                ModifiedLiePoisson::<Cayley>::with_scheme(body, scheme, mu0, g0)?.with_solver(c),
            ),
            other => {
                return Err(BuildError::unavailable(
                    format!(
                        "the modified Hamiltonian's coefficients are derived for τ = exp and \
                         cayley, not {other}"
                    ),
                    crate::model::Missing::default(),
                ))
            }
        })
    }
}

/// The step limit of the free body's modified Hamiltonian for this configuration
/// (`mechanics::modified::ModifiedRigidBody::step_limit` at μ₀): with `modified`, its own
/// scheme's, where the step refuses beyond it; otherwise (`kernel`) the order-4 scheme of the
/// Lie–Poisson kernel's τ and θ (θ = 1 read as θ = 0, its adjoint, which has the same even
/// modified Hamiltonian on the free body), whose inverse is the rate ω_K the kernel's error
/// grows with: its h² term bends H by (hω_K)² (on a thin rod far above |Ω|). `None` off the
/// free body, for another τ or θ, or without `modified` unless `kernel`.
pub(crate) fn modified_step_limit<M: Model>(
    options: &Options,
    model: &M,
    mu0: Alg<M::G>,
    kernel: bool,
) -> Option<f64> {
    let (theta, order) = match options.modified {
        Some(order) => (options.theta.unwrap_or(0.5), order),
        None if kernel => {
            let theta = options.theta.unwrap_or(0.0);
            if theta == 0.5 {
                (0.5, 4)
            } else if theta == 0.0 || theta == 1.0 {
                (0.0, 4)
            } else {
                return None;
            }
        }
        None => return None,
    };
    let scheme = ModifiedScheme::new(theta, order).ok()?;
    let visitor = ModifiedLimit {
        tau: options.tau.unwrap_or(TauKind::Cayley),
        scheme,
    };
    model.free_body(visitor, mu0, None).ok().flatten()
}

/// The step limit of a modified Hamiltonian on the free body.
struct ModifiedLimit {
    tau: TauKind,
    scheme: ModifiedScheme,
}

impl FreeBodyVisitor for ModifiedLimit {
    type Out<G: LieGroup> = Option<f64>;
    fn visit(self, body: &RigidBody, mu0: Vector3<f64>, _g0: Option<So3>) -> Option<f64> {
        let body = body.clone();
        #[allow(unreachable_patterns)]
        match self.tau {
            TauKind::Exp => Some(
                ModifiedRigidBody::<ExpMap>::new(body, self.scheme, 0.0)
                    .ok()?
                    .step_limit(&mu0),
            ),
            TauKind::Cayley => Some(
                ModifiedRigidBody::<Cayley>::new(body, self.scheme, 0.0)
                    .ok()?
                    .step_limit(&mu0),
            ),
            _ => None,
        }
    }
}
