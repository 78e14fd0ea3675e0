//! `dopri5`: the Dormand–Prince 5(4) pair on (unit quaternion, Π), renormalised each step, run to a
//! tolerance (`integrators::baselines::QuaternionDopri5`): what a scipy `solve_ivp(method="RK45")` user
//! runs.

use super::families::{self, Family};
use super::options::Options;
use super::row::{Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, Model};
use crate::plot::Marker;
use crate::sim::Boxed;
use integrators::adaptive::DormandPrince54;
use integrators::SolverConfig;

/// The row.
pub const ROW: Row = Row {
    name: "dopri5",
    summary: "Dormand–Prince 5(4) on (unit quaternion, Π), renormalised each step, steps to a \
              tolerance (scipy's RK45; a baseline; SO(3))",
    takes: Takes {
        tau: TauRule::None,
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
    second: false,
    marker: Some(Marker::Circle),
    batch: None,
    step_limit: Some(3.0),
};

fn family(_: &Options) -> &'static Family {
    &families::ADAPTIVE
}

/// Builds it on a system on SO(3).
pub fn build<M: Model>(
    _options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    super::quaternion_pair::build::<DormandPrince54, 7, M>(ROW.name, model, mu0, g0)
}
