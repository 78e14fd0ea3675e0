//! `kinetic-kick`: the exact flow of the kinetic energy between kicks of the potential and the
//! forces (`integrators::splitting::KineticKick`), with the coefficients of `splitting = …`
//! (Strang, Blanes–Moan 4 and 6).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::{wrap, BuildError};
use crate::model::{Alg, KineticVisitor, Missing, Model};
use crate::sim::Boxed;
use integrators::splitting::{KineticFlow, KineticKick, SplittingScheme};
use integrators::{SolverConfig, System};
use lie_groups::LieGroup;

/// The row.
pub const ROW: Row = Row {
    name: "kinetic-kick",
    summary: "The exact flow of the kinetic energy (the free rigid body's, mechanics::exact) \
              between kicks of the potential and forces; coefficients Strang or Blanes–Moan 4, 6",
    takes: Takes {
        tau: TauRule::None,
        theta: false,
        coefficients: true,
        modified: false,
        wrappers: true,
        stepping: Stepping::Fixed,
    },
    trade: Trade {
        thetas: &[],
        compositions: &[],
        modified: &[],
        processing: true,
        one_step: false,
        // Each set of coefficients (`candidates`): Blanes–Moan's, optimised for a kinetic +
        // potential split, reach a given error in fewer stages than the Kahan–Li compositions
        // of Strang (docs/work-precision.md, the eccentric orbit's table).
        reversible: &[None],
    },
    family,
    second: true,
    marker: None,
    batch: None,
    step_limit: None,
};

fn family(_: &Options) -> &'static Family {
    &families::SPLITTING
}

/// Builds it on a system whose kinetic flow is known.
pub fn build<M: Model>(
    options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    let visitor = Kicks {
        options,
        kind: model.kind(),
    };
    model.kinetic_flow(visitor, mu0, g0).map_err(|m| {
        let why = m
            .0
            .unwrap_or_else(|| format!("this {} declares none; use splitting", model.kind()));
        BuildError::missing(
            "kinetic-kick needs the exact flow of the kinetic energy (known for the rigid body)",
            Missing::because(why),
        )
    })?
}

struct Kicks<'a> {
    options: &'a Options,
    kind: &'static str,
}

impl<G: LieGroup> KineticVisitor<G> for Kicks<'_> {
    type Out = Result<Boxed<G>, BuildError>;
    fn visit<S, K>(self, system: &S, flow: K, mu0: G::Algebra, g0: Option<G>) -> Self::Out
    where
        S: System<G> + Clone + Sync + 'static,
        K: KineticFlow<G> + Clone + Sync + 'static,
    {
        let scheme = self
            .options
            .splitting
            .clone()
            .unwrap_or_else(SplittingScheme::strang);
        let kk = KineticKick::new(system.clone(), flow, scheme, mu0, g0)?;
        wrap(kk, system, self.options, ROW.name, self.kind)
    }
}
