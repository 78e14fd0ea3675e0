//! The exact flow of an axisymmetric free rigid body, in closed form.

use crate::systems::RigidBody;
use integrators::splitting::KineticFlow;
use integrators::IntegratorError;
use lie_groups::{LieGroup, So3};
use nalgebra::Vector3;

/// The exact flow of `h(Π) = ½ Π·𝕀⁻¹Π` for a body with two equal principal moments I (the third
/// Iₐ about the symmetry axis a): with `h = |Π|²/2I + ½(1/Iₐ − 1/I)(a·Π)²`, the two terms Poisson
/// commute (the first is a Casimir), so the flow is the product of their flows:
///
/// ```text
/// Π(t) = exp(−tωₐ â) Π,    R(t) = R exp(t Π̂/I) exp(tωₐ â),    ωₐ = (1/Iₐ − 1/I)(a·Π)
/// ```
///
/// (the first factor leaves Π fixed; `Π` in it is the initial one, which equals its rotation by
/// the second factor up to a rotation about a that commutes with it). Exact for any t: a fast
/// spin is integrated to round-off in one call. The heavy Lagrange top's kinetic part.
#[derive(Debug, Clone)]
pub struct AxisymmetricFlow {
    axis: Vector3<f64>,
    inv_i: f64,
    omega_factor: f64,
}

impl AxisymmetricFlow {
    /// The flow of `body`; [`IntegratorError::InvalidParameter`] unless two principal moments are
    /// equal (to 4 ulps relative).
    pub fn new(body: &RigidBody) -> Result<Self, IntegratorError> {
        let (axes, moments) = body.principal_frame();
        let close = |x: f64, y: f64| (x - y).abs() <= 4.0 * f64::EPSILON * x.max(y);
        let distinct = (0..3).find(|&d| close(moments[(d + 1) % 3], moments[(d + 2) % 3]));
        let Some(d) = distinct else {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "the closed-form kinetic flow needs an axisymmetric body, the principal moments are {:?}",
                    moments.as_slice()
                ),
            });
        };
        let i = 0.5 * (moments[(d + 1) % 3] + moments[(d + 2) % 3]);
        Ok(Self {
            axis: axes.column(d).into_owned(),
            inv_i: 1.0 / i,
            omega_factor: 1.0 / moments[d] - 1.0 / i,
        })
    }
}

impl KineticFlow<So3> for AxisymmetricFlow {
    fn kinetic_flow(
        &self,
        t: f64,
        mu: &mut Vector3<f64>,
        g: Option<&mut So3>,
    ) -> Result<(), IntegratorError> {
        let turn = self.axis * (t * self.omega_factor * self.axis.dot(mu));
        let e = So3::exp(&turn);
        let pi = e.coadjoint_apply(mu);
        let g1 = g
            .as_deref()
            .map(|g| g.compose(&So3::exp(&(*mu * (t * self.inv_i)))).compose(&e));
        if !pi.iter().all(|x| x.is_finite()) || g1.as_ref().is_some_and(|g| !g.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "kinetic flow of the axisymmetric body",
            });
        }
        *mu = pi;
        if let (Some(g), Some(g1)) = (g, g1) {
            *g = g1;
        }
        Ok(())
    }
}
