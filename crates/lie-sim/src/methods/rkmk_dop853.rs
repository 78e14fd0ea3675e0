//! `rkmk-dop853`: Runge–Kutta–Munthe-Kaas with the DOP853 (8(5,3)) pair in the algebra, run to a tolerance
//! (`integrators::adaptive::RkmkDop853`).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, Model};
use crate::plot::Marker;
use crate::sim::Boxed;
use crate::taus::TauKind;
use integrators::adaptive::RkmkDop853;
use integrators::SolverConfig;

/// The row.
pub const ROW: Row = Row {
    name: "rkmk-dop853",
    summary: "Runge–Kutta–Munthe-Kaas with the DOP853 pair (Hairer) in the algebra, steps to a \
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
    marker: Some(Marker::Diamond),
    batch: None,
    step_limit: Some(3.0),
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
    Ok(Boxed::pair(RkmkDop853::<M::G, M::S>::new(
        model.system().clone(),
        mu0,
        g0,
    )?))
}
