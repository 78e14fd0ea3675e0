//! `exact`: the exact free rigid body flow (`mechanics::exact::ExactFreeBody`): Jacobi elliptic
//! functions, any step, cost independent of h.

use super::families::{self, Family};
use super::options::Options;
use super::row::{Batched, Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, FreeBodyVisitor, Missing, Model};
use crate::plot::Marker;
use crate::sim::Boxed;
use integrators::SolverConfig;
use lie_groups::{LieGroup, So3};
use mechanics::exact::ExactFreeBody;
use mechanics::RigidBody;
use nalgebra::Vector3;

/// The row.
pub const ROW: Row = Row {
    name: "exact",
    summary: "The exact free rigid body flow (Jacobi elliptic functions, mechanics::exact): any \
              step, cost independent of h",
    takes: Takes {
        tau: TauRule::None,
        theta: false,
        coefficients: false,
        modified: false,
        wrappers: false,
        stepping: Stepping::Fixed,
    },
    trade: Trade {
        thetas: &[],
        compositions: &[],
        modified: &[],
        processing: false,
        one_step: true,
        reversible: &[],
    },
    family,
    second: false,
    marker: Some(Marker::Diamond),
    batch: Some(Batched::Exact),
    step_limit: None,
};

fn family(_: &Options) -> &'static Family {
    &families::EXACT
}

/// Builds it on the free rigid body.
pub fn build<M: Model>(
    _options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    model.free_body(Flow, mu0, g0).map_err(|m| {
        let why = m.0.unwrap_or_else(|| {
            format!(
                "this {} is another system (kinetic-kick steps a rigid body with a potential by \
                 the free body's flow)",
                model.kind()
            )
        });
        BuildError::missing(
            "the exact flow is known in closed form only for the free rigid body",
            Missing::because(why),
        )
    })?
}

struct Flow;

impl FreeBodyVisitor for Flow {
    type Out<G: LieGroup> = Result<Boxed<G>, BuildError>;
    fn visit(self, body: &RigidBody, mu0: Vector3<f64>, g0: Option<So3>) -> Self::Out<So3> {
        Ok(Boxed::new(ExactFreeBody::new(body.clone(), mu0, g0)?))
    }
}
