//! `geodesic-so-n`: the Euler–Arnold geodesic on SO(n), the generalised rigid body
//! (`mechanics::GeneralizedRigidBody`), for the n of [`SO_N_SIZES`].
//!
//! `[system]`: `n`, `inertia` (the n diagonal entries of the mass matrix J). `[initial]`:
//! `momentum` (n(n−1)/2 components in lie-groups' SO(n) basis), `attitude = { matrix = … }`
//! (n×n, default the identity).

use super::common::{build_error, SceneSystem, Tag};
use crate::error::SimError;
use crate::fields::{
    identity_flat, momentum_of_len, positive, special_orthogonal, square, FieldError,
    RawAttitude, RawInertia,
};
use crate::model::{Alg, Has, Job, Missing, Model, SplitVisitor};
use faer::{Col, Mat};
use lie_groups::{LieGroup, SoN};
use mechanics::GeneralizedRigidBody;
use serde::Deserialize;

/// The n of SO(n) compiled into the binary (one monomorphized model per n).
pub const SO_N_SIZES: [usize; 8] = [3, 4, 5, 6, 8, 10, 20, 50];

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// n.
    pub n: usize,
    /// The n diagonal entries of J.
    pub inertia: RawInertia,
}

/// `[initial]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// μ₀, n(n−1)/2 components.
    pub momentum: Vec<f64>,
    /// R₀, `{ matrix = … }` (default: the identity).
    pub attitude: Option<RawAttitude>,
}

/// The checked geodesic and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct GeodesicSoN {
    /// n.
    pub n: usize,
    /// The diagonal mass matrix J = diag(j₁, …, jₙ), all positive.
    pub inertia: Vec<f64>,
    /// Initial body momentum μ₀ ∈ 𝔰𝔬(n)*, n(n−1)/2 components in `lie_groups`' SO(n) basis.
    pub momentum: Vec<f64>,
    /// Initial attitude, n×n row-major.
    pub attitude: Vec<f64>,
}

impl SceneSystem for GeodesicSoN {
    const KIND: &'static str = "geodesic-so-n";
    const SUMMARY: &'static str = "The Euler–Arnold geodesic on SO(n), the generalised rigid body \
                                   h = ½⟨M, J⁻¹M⟩ (mechanics::GeneralizedRigidBody)";
    const EXAMPLE: &'static str = include_str!("../../../../examples/scenes/geodesic-so-n.toml");
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let n = params.n;
        if !SO_N_SIZES.contains(&n) {
            return Err((
                "system.n".into(),
                format!(
                    "SO({n}) is not compiled into lie-sim: n must be one of {SO_N_SIZES:?}"
                ),
            ));
        }
        let inertia = match &params.inertia {
            RawInertia::Diagonal(d) if d.len() == n => {
                for &x in d {
                    positive("system.inertia", x)?;
                }
                d.clone()
            }
            _ => {
                return Err((
                    "system.inertia".into(),
                    format!("must be the {n} diagonal entries of the mass matrix J of SO({n})"),
                ))
            }
        };
        momentum_of_len(Self::KIND, &initial.momentum, n * (n - 1) / 2)?;
        let attitude = match &initial.attitude {
            None => identity_flat(n),
            Some(RawAttitude::Matrix(m)) => {
                let flat = square("initial.attitude.matrix", m, n)?;
                special_orthogonal("initial.attitude.matrix", &flat, n)?;
                flat
            }
            Some(_) => {
                return Err((
                    "initial.attitude".into(),
                    format!("must be {{ matrix = … }} ({n}×{n}) for geodesic-so-n"),
                ))
            }
        };
        Ok(Self {
            n,
            inertia,
            momentum: initial.momentum.clone(),
            attitude,
        })
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        fn go<const N: usize, J: Job>(
            p: &GeodesicSoN,
            reconstruct: bool,
            job: J,
        ) -> Result<J::Out, SimError> {
            let built = |e: &dyn std::fmt::Display| build_error(GeodesicSoN::KIND, e);
            let body = GeneralizedRigidBody::<N>::new(&p.inertia).map_err(|e| built(&e))?;
            let mu0 = Col::from_fn(p.momentum.len(), |i| p.momentum[i]);
            let g0 = if reconstruct {
                let m = Mat::from_fn(N, N, |r, c| p.attitude[r * N + c]);
                Some(SoN::<N>::from_matrix(&m).map_err(|e| built(&e))?)
            } else {
                None
            };
            job.run(&Geodesic { body }, mu0, g0)
        }
        match self.n {
            3 => go::<3, J>(self, reconstruct, job),
            4 => go::<4, J>(self, reconstruct, job),
            5 => go::<5, J>(self, reconstruct, job),
            6 => go::<6, J>(self, reconstruct, job),
            8 => go::<8, J>(self, reconstruct, job),
            10 => go::<10, J>(self, reconstruct, job),
            20 => go::<20, J>(self, reconstruct, job),
            50 => go::<50, J>(self, reconstruct, job),
            n => Err(SimError::NotYetAvailable {
                what: Self::KIND.into(),
                why: format!("SO({n}) is not compiled into lie-sim (sizes: {SO_N_SIZES:?})"),
            }),
        }
    }
}

/// The geodesic as the methods see it: no splitting, no kinetic flow of its own.
struct Geodesic<const N: usize> {
    body: GeneralizedRigidBody<N>,
}

impl<const N: usize> Model for Geodesic<N> {
    type G = SoN<N>;
    type S = GeneralizedRigidBody<N>;
    fn kind(&self) -> &'static str {
        GeodesicSoN::KIND
    }
    fn system(&self) -> &GeneralizedRigidBody<N> {
        &self.body
    }
    fn split<V: SplitVisitor<SoN<N>>>(
        &self,
        _v: V,
        _mu0: Alg<SoN<N>>,
        _g0: Option<SoN<N>>,
    ) -> Has<V::Out> {
        Err(Missing::because(
            "the SO(n) geodesic h = ½⟨M, J⁻¹M⟩ has no such splitting here (use lie-poisson or \
             rkmk4)",
        ))
    }
}
