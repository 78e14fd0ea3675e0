//! `euler-poincare`: the tangent-lift Euler–Poincaré integrator (eq. 18 of the paper).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::{wrap, BuildError};
use crate::model::{Alg, Model};
use crate::sim::Boxed;
use crate::taus::{with_tau, TauKind, TauVisitor};
use integrators::{EulerPoincare, SolverConfig};
use lie_groups::{CayleyGroup, LieGroup, Tau};

/// The row.
pub const ROW: Row = Row {
    name: "euler-poincare",
    summary: "Tangent-lift Euler–Poincaré integrator, eq. (18), on the velocity ξ",
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
    &families::EULER_POINCARE
}

/// Builds it.
pub fn build<M: Model>(
    options: &Options,
    config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    with_tau(
        options.tau.unwrap_or(TauKind::Cayley),
        Ep {
            system: model.system().clone(),
            options,
            name: ROW.name,
            config,
            kind: model.kind(),
            mu0,
            g0,
        },
    )
}

/// The integrator of the system S with τ = T, from the momentum μ₀ (ξ₀ = ∂h/∂μ(μ₀)).
pub(super) struct Ep<'a, G: LieGroup, S> {
    pub system: S,
    pub options: &'a Options,
    pub name: &'static str,
    pub config: &'a SolverConfig,
    pub kind: &'static str,
    pub mu0: G::Algebra,
    pub g0: Option<G>,
}

impl<G, S> TauVisitor<G> for Ep<'_, G, S>
where
    G: CayleyGroup + 'static,
    S: integrators::System<G> + Clone + 'static,
{
    type Out = Result<Boxed<G>, BuildError>;
    fn visit<T: Tau<G>>(self) -> Self::Out {
        let theta = self.options.theta.unwrap_or(0.0);
        let ep = EulerPoincare::<G, T, S>::from_momentum(
            self.system.clone(),
            theta,
            self.mu0,
            self.g0,
        )?
        .with_solver(*self.config);
        wrap(ep, &self.system, self.options, self.name, self.kind)
    }
}
