//! `rk4`: the explicit RK4 baseline on (quaternion, Π), renormalised (`integrators::QuaternionRk4`).

use super::families::{self, Family};
use super::options::Options;
use super::row::{Batched, Row, Stepping, TauRule, Takes, Trade};
use super::wrap::BuildError;
use crate::model::{Alg, Model, So3Visitor};
use crate::sim::Boxed;
use integrators::{QuaternionRk4, SolverConfig, System};
use lie_groups::{LieGroup, So3};
use nalgebra::Vector3;

/// The row.
pub const ROW: Row = Row {
    name: "rk4",
    summary: "Classical RK4 on (unit quaternion, Π), renormalised each step (a baseline; SO(3))",
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
        one_step: false,
        reversible: &[],
    },
    family,
    second: false,
    marker: None,
    batch: Some(Batched::Rk4),
    step_limit: Some(2.5),
};

fn family(_: &Options) -> &'static Family {
    &families::RUNGE_KUTTA
}

/// Builds it on a system on SO(3).
pub fn build<M: Model>(
    _options: &Options,
    _config: &SolverConfig,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    model.so3(Quaternions, mu0, g0).map_err(|m| {
        BuildError::unavailable(
            "rk4 integrates quaternions, so only systems on SO(3); use rkmk4 on other groups",
            m,
        )
    })?
}

struct Quaternions;

impl So3Visitor for Quaternions {
    type Out<G: LieGroup> = Result<Boxed<G>, BuildError>;
    fn visit<S: System<So3> + Clone + Sync + 'static>(
        self,
        system: &S,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Self::Out<So3> {
        Ok(Boxed::new(QuaternionRk4::new(system.clone(), mu0, g0)?))
    }
}
