//! Building an embedded pair on (unit quaternion, Π) (`integrators::baselines::QuaternionPair`)
//! on a scene's model: the one constructor of the `dopri5` and `dop853` rows, which differ only by
//! their Butcher pair.

use super::wrap::BuildError;
use crate::model::{Alg, Model, So3Visitor};
use crate::sim::Boxed;
use integrators::adaptive::ButcherPair;
use integrators::baselines::QuaternionPair;
use integrators::System;
use lie_groups::{LieGroup, So3};
use nalgebra::Vector3;
use std::marker::PhantomData;

/// The pair P on (q, Π) for the row `name`, on a system on SO(3) (refused elsewhere, pointing to
/// `rkmk-<name>`).
pub fn build<P: ButcherPair<N> + 'static, const N: usize, M: Model>(
    name: &str,
    model: &M,
    mu0: Alg<M::G>,
    g0: Option<M::G>,
) -> Result<Boxed<M::G>, BuildError> {
    model
        .so3(Quaternions::<P, N>(PhantomData), mu0, g0)
        .map_err(|m| {
            BuildError::unavailable(
                format!(
                    "{name} integrates quaternions, so only systems on SO(3); use rkmk-{name} on \
                     other groups"
                ),
                m,
            )
        })?
}

struct Quaternions<P, const N: usize>(PhantomData<P>);

impl<P: ButcherPair<N> + 'static, const N: usize> So3Visitor for Quaternions<P, N> {
    type Out<G: LieGroup> = Result<Boxed<G>, BuildError>;
    fn visit<S: System<So3> + Clone + Sync + 'static>(
        self,
        system: &S,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Self::Out<So3> {
        Ok(Boxed::pair(QuaternionPair::<S, P, N>::new(
            system.clone(),
            mu0,
            g0,
        )?))
    }
}
