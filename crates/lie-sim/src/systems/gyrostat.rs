//! `gyrostat`: a spacecraft with K reaction wheels on SO(3) × ℝᴷ (`mechanics::Gyrostat`), for
//! the K of [`WHEEL_COUNTS`]; with `[forces]` wheel-motor torques and a platform torque.
//!
//! `[system]`: `inertia` 𝕀 (locked: the whole spacecraft), `wheel_axes` (K × 3, body frame),
//! `wheel_inertia` (K). `[initial]`: `momentum` (Π, p) (3 + K), `attitude`, `wheel_angles` (K,
//! default 0).

use super::common::{build_error, SceneSystem, Splits, Tag};
use crate::error::SimError;
use crate::fields::{
    attitude3, finite_all, inertia3, momentum_of_len, positive, FieldError, RawAttitude,
    RawInertia,
};
use crate::forces::Forces;
use crate::model::Job;
use integrators::forces::Forced;
use lie_groups::{LieGroup, Product, ProductAlgebra, Rn, So3};
use mechanics::Gyrostat as GyrostatModel;
use nalgebra::{Matrix3, SVector, Vector3};
use serde::Deserialize;

/// The wheel counts K compiled into lie-sim.
pub const WHEEL_COUNTS: [usize; 4] = [1, 2, 3, 4];

/// `[system]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    /// The tag (read first, to choose this type).
    #[serde(rename = "kind")]
    _kind: Tag,
    /// 𝕀, wheels locked.
    pub inertia: RawInertia,
    /// Accept principal moments that break the triangle inequality of a rigid body
    /// (`fields::inertia3`); false by default.
    #[serde(default)]
    pub generalized_inertia: bool,
    /// The wheels' axes, one `[x, y, z]` each.
    pub wheel_axes: Vec<[f64; 3]>,
    /// The wheels' axial inertias.
    pub wheel_inertia: Vec<f64>,
}

/// `[initial]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// (Π₀, p₀).
    pub momentum: Vec<f64>,
    /// R₀ (default: the identity).
    pub attitude: Option<RawAttitude>,
    /// φ₀ (default 0).
    pub wheel_angles: Option<Vec<f64>>,
}

/// The checked gyrostat and its initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct Gyrostat {
    /// 𝕀, the whole spacecraft with the wheels locked.
    pub inertia: Matrix3<f64>,
    /// The unit wheel axes aᵢ (body frame).
    pub axes: Vec<Vector3<f64>>,
    /// The axial wheel inertias Jᵢ.
    pub wheel_inertia: Vec<f64>,
    /// Initial (Π, p), 3 + K components.
    pub momentum: Vec<f64>,
    /// Initial attitude R₀.
    pub attitude: Matrix3<f64>,
    /// Initial wheel angles φ₀.
    pub wheel_angles: Vec<f64>,
    /// Wheel torques and a platform torque (`[forces]`).
    pub forces: Option<Forces>,
}

impl SceneSystem for Gyrostat {
    const KIND: &'static str = "gyrostat";
    const SUMMARY: &'static str = "A spacecraft with reaction wheels on SO(3) × ℝᴷ \
                                   (mechanics::Gyrostat)";
    const EXAMPLE: &'static str =
        include_str!("../../../../examples/scenes/reaction-wheel-slew.toml");
    const FORCE_KEYS: &'static [&'static str] = &["torque", "wheel_torque"];
    type Params = Params;
    type Initial = Initial;

    fn check(params: &Params, initial: &Initial) -> Result<Self, FieldError> {
        let inertia = inertia3("system.inertia", &params.inertia, params.generalized_inertia)?;
        let k = params.wheel_axes.len();
        if !WHEEL_COUNTS.contains(&k) {
            return Err((
                "system.wheel_axes".into(),
                format!("gives {k} wheels; lie-sim is compiled for {WHEEL_COUNTS:?} wheels"),
            ));
        }
        let mut axes = Vec::with_capacity(k);
        for (i, a) in params.wheel_axes.iter().enumerate() {
            let field = format!("system.wheel_axes[{i}]");
            finite_all(&field, a)?;
            let v = Vector3::from(*a);
            if v.norm() == 0.0 {
                return Err((
                    field,
                    "is the zero vector: a wheel axis needs a direction".into(),
                ));
            }
            axes.push(v.normalize());
        }
        let wheel_inertia = params.wheel_inertia.clone();
        if wheel_inertia.len() != k {
            return Err((
                "system.wheel_inertia".into(),
                format!(
                    "needs one inertia per wheel ({k}), got {}",
                    wheel_inertia.len()
                ),
            ));
        }
        for &j in &wheel_inertia {
            positive("system.wheel_inertia", j)?;
        }
        let platform = axes
            .iter()
            .zip(&wheel_inertia)
            .fold(inertia, |m, (a, j)| m - a * a.transpose() * *j);
        if platform.cholesky().is_none() {
            return Err((
                "system.wheel_inertia".into(),
                "exceeds the body: 𝕀 − Σ Jᵢ aᵢaᵢᵀ is not positive definite (𝕀 is the whole \
                 spacecraft's inertia, wheels included)"
                    .into(),
            ));
        }
        momentum_of_len(Self::KIND, &initial.momentum, 3 + k)?;
        let wheel_angles = initial
            .wheel_angles
            .clone()
            .unwrap_or_else(|| vec![0.0; k]);
        if wheel_angles.len() != k {
            return Err((
                "initial.wheel_angles".into(),
                format!(
                    "needs one angle per wheel ({k}), got {}",
                    wheel_angles.len()
                ),
            ));
        }
        finite_all("initial.wheel_angles", &wheel_angles)?;
        Ok(Self {
            inertia,
            axes,
            wheel_inertia,
            momentum: initial.momentum.clone(),
            attitude: attitude3(&initial.attitude)?,
            wheel_angles,
            forces: None,
        })
    }
    fn force_sizes(&self) -> (usize, usize) {
        (3 + self.axes.len(), self.axes.len())
    }
    fn forces(&self) -> Option<&Forces> {
        self.forces.as_ref()
    }
    fn set_forces(&mut self, forces: Forces) {
        self.forces = Some(forces);
    }
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
        fn go<const K: usize, J: Job>(
            p: &Gyrostat,
            reconstruct: bool,
            job: J,
        ) -> Result<J::Out, SimError> {
            let built = |e: &dyn std::fmt::Display| build_error(Gyrostat::KIND, e);
            let gyro = GyrostatModel::<K>::new(
                p.inertia,
                core::array::from_fn(|i| p.axes[i]),
                core::array::from_fn(|i| p.wheel_inertia[i]),
            )
            .map_err(|e| built(&e))?;
            let mu0 = ProductAlgebra::<So3, Rn<K>>::new(
                Vector3::from_column_slice(&p.momentum[..3]),
                SVector::<f64, K>::from_column_slice(&p.momentum[3..]),
            );
            let g0 = if reconstruct {
                Some(Product::new(
                    So3::from_matrix(&p.attitude).map_err(|e| built(&e))?,
                    Rn::new(SVector::<f64, K>::from_column_slice(&p.wheel_angles)),
                ))
            } else {
                None
            };
            match &p.forces {
                None => job.run(&Splits::new(Gyrostat::KIND, gyro, Ok(())), mu0, g0),
                Some(f) => {
                    let force = (
                        f.torque
                            .clone()
                            .map(GyrostatModel::<K>::body_torque)
                            .transpose()
                            .map_err(|e| built(&e))?,
                        f.wheel_torque
                            .clone()
                            .map(GyrostatModel::<K>::wheel_torques)
                            .transpose()
                            .map_err(|e| built(&e))?,
                    );
                    let forced = Forced::new(gyro, force);
                    job.run(&Splits::new(Gyrostat::KIND, forced, Ok(())), mu0, g0)
                }
            }
        }
        match self.axes.len() {
            1 => go::<1, J>(self, reconstruct, job),
            2 => go::<2, J>(self, reconstruct, job),
            3 => go::<3, J>(self, reconstruct, job),
            4 => go::<4, J>(self, reconstruct, job),
            k => Err(SimError::NotYetAvailable {
                what: Self::KIND.into(),
                why: format!("{k} wheels are not compiled into lie-sim (counts: {WHEEL_COUNTS:?})"),
            }),
        }
    }
}
