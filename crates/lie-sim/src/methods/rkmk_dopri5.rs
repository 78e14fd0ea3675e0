//! `rkmk-dopri5`: Runge–Kutta–Munthe-Kaas with the Dormand–Prince 5(4) pair in the algebra, run to a tolerance
//! (`integrators::adaptive::RkmkDopri5`).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, Model};
use crate::plot::Marker;
use crate::sim::Boxed;
use crate::taus::TauKind;
use integrators::adaptive::RkmkDopri5;
use integrators::SolverConfig;

/// The row.
pub const ROW: Row = Row {
    name: "rkmk-dopri5",
    summary: "Runge–Kutta–Munthe-Kaas with the Dormand–Prince 5(4) pair in the algebra, steps to a \
              tolerance (error on the group log(ĝ⁻¹g) and on μ; any group)",
    takes: Takes {
        tau: TauRule::Only(TauKind::Exp),
        theta: false,
        coefficients: false,
        modified: false,
        wrappers: false,
        stepping: Stepping::Tolerance,
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
    marker: Some(Marker::Circle),
    batch: None,
    step_limit: Some(2.0),
};

fn family(_: &Options) -> &'static Family {
    &families::ADAPTIVE
}

/// Builds it.
pub fn build<M: Model>(
    _options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    Ok(Boxed::pair(RkmkDopri5::<M::G, M::S>::new(
        model.system().clone(),
        mu0,
        g0,
    )?))
}
