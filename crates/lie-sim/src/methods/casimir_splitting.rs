//! `casimir-splitting`: the free rigid body as its Casimir part |Π|²/2I_r (the middle moment),
//! flowed once a step, plus two principal-axis rotations split with the coefficients of
//! `splitting = …` (`integrators::splitting::CasimirSplitting`); a composition of its Strang form
//! is folded into one scheme (`SplittingScheme::strang_composed`), so that the Casimir part's
//! flow stays once a composite step.

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::{wrap, BuildError};
use crate::model::{Alg, FreeBodyVisitor, Missing, Model};
use crate::sim::Boxed;
use integrators::splitting::{CasimirSplitting, SplittingScheme};
use integrators::SolverConfig;
use lie_groups::{LieGroup, So3};
use mechanics::RigidBody;
use nalgebra::Vector3;

/// The row.
pub const ROW: Row = Row {
    name: "casimir-splitting",
    summary: "The free rigid body's Casimir part |Π|²/2I_r flowed once a step, its two \
              principal-axis rotations split with Strang or Blanes–Moan 4, 6 or a folded \
              composition of Strang (integrators::splitting::CasimirSplitting); explicit",
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
        // Order 8 of the Strang form, folded: the cheapest of this row at the tightest errors,
        // Blanes–Moan 6 (a set of coefficients) at the looser ones. At order 6 Blanes–Moan's
        // optimised error constant beats Kahan–Li 6 folded, whose step has about as many flows.
        compositions: &["kahan-li-8"],
        modified: &[],
        processing: false,
        one_step: false,
        reversible: &[],
    },
    family,
    second: false,
    marker: None,
    batch: None,
    step_limit: None,
};

fn family(_: &Options) -> &'static Family {
    &families::CASIMIR_SPLITTING
}

/// Builds it on the unforced free rigid body.
pub fn build<M: Model>(
    options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    let visitor = Casimir {
        options,
        kind: model.kind(),
    };
    model.free_body(visitor, mu0, g0).map_err(|m| {
        let why = m.0.unwrap_or_else(|| {
            format!(
                "this {} is another system (use splitting, whose pieces take a potential)",
                model.kind()
            )
        });
        BuildError::missing(
            "casimir-splitting needs a free system whose Hamiltonian is a Casimir part plus two \
             pieces with explicit flows (the free rigid body)",
            Missing::because(why),
        )
    })?
}

struct Casimir<'a> {
    options: &'a Options,
    kind: &'static str,
}

impl FreeBodyVisitor for Casimir<'_> {
    type Out<G: LieGroup> = Result<Boxed<G>, BuildError>;
    fn visit(self, body: &RigidBody, mu0: Vector3<f64>, g0: Option<So3>) -> Self::Out<So3> {
        let scheme = self
            .options
            .splitting
            .clone()
            .unwrap_or_else(SplittingScheme::strang);
        // A composition of the Strang form is the same map as one scheme with the Casimir flow
        // once a step (`SplittingScheme::strang_composed`); of another scheme, a composition.
        let (scheme, options) = match &self.options.composition {
            Some(c) if scheme == SplittingScheme::strang() => (
                SplittingScheme::strang_composed(c)?,
                Options {
                    composition: None,
                    ..self.options.clone()
                },
            ),
            _ => (scheme, self.options.clone()),
        };
        let split = CasimirSplitting::new(body.clone(), scheme, mu0, g0)?;
        wrap(split, body, &options, ROW.name, self.kind)
    }
}
