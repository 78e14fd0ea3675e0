//! The exact flow of the free rigid body on SE(3): the free body's rotation with a uniform drift.

use super::FreeBodyFlow;
use crate::systems::RigidBodySe3;
use integrators::splitting::KineticFlow;
use integrators::IntegratorError;
use lie_groups::{LieGroup, Se3, So3};
use nalgebra::Vector6;

/// The exact flow of `h(Π, P) = ½ Π·𝕀⁻¹Π + |P|²/2m` on SE(3), μ = (Π, P), g = (R, x):
///
/// ```text
/// Π̇ = Π × Ω + P × V = Π × Ω   (V = P/m ∥ P),   Ṗ = P × Ω,   Ṙ = R Ω̂,   ẋ = R V,
/// ```
///
/// so Π(t), R(t) are the free rigid body's ([`FreeBodyFlow`]), the spatial momentum p = R P is
/// constant, `P(t) = R(t)ᵀ p` and `x(t) = x₀ + t p/m`. It is the kinetic part of the kinetic–kick
/// splitting of the satellite ([`integrators::splitting::KineticKick`] with
/// [`RigidBodySe3::satellite`]). Without g, P(t) is still computed (from the rotation relative to
/// the start); errors leave μ and g as they were.
#[derive(Debug, Clone)]
pub struct FreeBodySe3Flow {
    flow: FreeBodyFlow,
    mass: f64,
}

impl FreeBodySe3Flow {
    /// The flow of the kinetic part of `system` (free body or satellite).
    pub fn new(system: &RigidBodySe3) -> Self {
        Self {
            flow: FreeBodyFlow::new(system.body()),
            mass: system.mass(),
        }
    }
}

impl KineticFlow<Se3> for FreeBodySe3Flow {
    fn kinetic_flow(
        &self,
        t: f64,
        mu: &mut Vector6<f64>,
        g: Option<&mut Se3>,
    ) -> Result<(), IntegratorError> {
        let pi = mu.fixed_rows::<3>(0).into_owned();
        let p = mu.fixed_rows::<3>(3).into_owned();
        // The rotation relative to the start, Q = R₀ᵀR(t), from the identity: P(t) = Qᵀ P turns P
        // by a rotation orthogonal to round-off, where R(t)ᵀ(R₀P) would also scale it by R₀ᵀR₀, the
        // attitude's accumulated departure from orthogonality, at every call. R(t) = R₀Q is
        // projected back onto SO(3) so that departure does not accumulate either.
        let (pit, q) = self.flow.advance(t, &pi, Some(&So3::identity()))?;
        let q = q.ok_or(IntegratorError::NonFinite {
            what: "attitude R(t) of the exact flow",
        })?;
        let pt = q.as_matrix().tr_mul(&p);
        let moved = g.as_ref().map(|g| {
            let r0 = g.rotation();
            (
                r0.compose(&q).normalize(),
                g.translation() + r0.as_matrix() * p * (t / self.mass),
            )
        });
        let finite = |v: &nalgebra::Vector3<f64>| v.iter().all(|x| x.is_finite());
        if !finite(&pt)
            || moved
                .as_ref()
                .is_some_and(|(r, x)| !r.is_finite() || !finite(x))
        {
            return Err(IntegratorError::NonFinite {
                what: "linear momentum or position of the exact flow",
            });
        }
        *mu = Vector6::new(pit.x, pit.y, pit.z, pt.x, pt.y, pt.z);
        if let (Some(g), Some((r, x))) = (g, moved) {
            *g = Se3::from_parts(r, x);
        }
        Ok(())
    }
}
