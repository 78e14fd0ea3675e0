//! `splitting`: the explicit Strang splitting of h into pieces with exact flows (one-parameter
//! subgroups) and the potential's kick (`integrators::splitting::Splitting`).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Batched, Row, Stepping, TauRule, Takes, Trade};
use super::wrap::{wrap, BuildError};
use crate::model::{Alg, Missing, Model, SplitVisitor};
use crate::sim::Boxed;
use integrators::splitting::{SplitSystem, Splitting};
use integrators::SolverConfig;
use lie_groups::LieGroup;

/// The row.
pub const ROW: Row = Row {
    name: "splitting",
    summary: "Strang splitting of h into pieces with exact flows and the potential's kick \
              (integrators::splitting); explicit",
    takes: Takes {
        tau: TauRule::None,
        theta: false,
        coefficients: false,
        modified: false,
        wrappers: true,
        stepping: Stepping::Fixed,
    },
    trade: Trade {
        thetas: &[],
        // Order 4 (3 and 5 stages) and 6.
        compositions: &["triple-jump-4", "mclachlan-4", "kahan-li-6"],
        modified: &[],
        processing: true,
        one_step: false,
        // The base and its order-6 and order-8 compositions: where variable steps pay, the
        // cost of each order (on the eccentric orbit, order 8 is the cheapest from 1e-9 on).
        reversible: &[None, Some("kahan-li-6"), Some("kahan-li-8")],
    },
    family,
    second: false,
    marker: None,
    batch: Some(Batched::Strang),
    step_limit: None,
};

fn family(_: &Options) -> &'static Family {
    &families::SPLITTING
}

/// Builds it on a system that splits.
pub fn build<M: Model>(
    options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    let visitor = Strang {
        options,
        kind: model.kind(),
    };
    model.split(visitor, mu0, g0).map_err(|m| {
        let why = m.0.unwrap_or_else(|| format!("this {} has none", model.kind()));
        BuildError::missing(
            "splitting needs h = Σ hᵢ with each piece's flow exact and explicit",
            Missing::because(why),
        )
    })?
}

struct Strang<'a> {
    options: &'a Options,
    kind: &'static str,
}

impl<G: LieGroup> SplitVisitor<G> for Strang<'_> {
    type Out = Result<Boxed<G>, BuildError>;
    fn visit<S: SplitSystem<G> + Clone + Sync + 'static>(
        self,
        system: &S,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Self::Out {
        let split = Splitting::new(system.clone(), mu0, g0)?;
        wrap(split, system, self.options, ROW.name, self.kind)
    }
}
