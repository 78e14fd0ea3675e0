//! `rkmk4`: the Runge–Kutta–Munthe-Kaas method of order 4 on the group (`integrators::Rkmk4`).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Batched, Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, Model};
use crate::sim::Boxed;
use crate::taus::TauKind;
use integrators::{Rkmk4, SolverConfig};

/// The row.
pub const ROW: Row = Row {
    name: "rkmk4",
    summary: "Runge–Kutta–Munthe-Kaas of order 4 on the group, built on τ = exp (a baseline; any \
              group)",
    takes: Takes {
        tau: TauRule::Only(TauKind::Exp),
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
        one_step: false,
        reversible: &[],
    },
    family,
    second: true,
    marker: None,
    batch: Some(Batched::Rkmk4),
    step_limit: Some(2.0),
};

fn family(_: &Options) -> &'static Family {
    &families::RUNGE_KUTTA
}

/// Builds it.
pub fn build<M: Model>(
    _options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    Ok(Boxed::new(Rkmk4::<M::G, M::S>::new(
        model.system().clone(),
        mu0,
        g0,
    )?))
}
