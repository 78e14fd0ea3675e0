//! [`QuadraticDrag`]: drag quadratic in the body velocity, `F_ext = −(dᵢ |ξᵢ| ξᵢ)ᵢ`.

use crate::forces::ExternalForce;
use crate::IntegratorError;
use lie_groups::{LieGroup, Vector};

/// Quadratic drag `F_ext(ξ)ᵢ = −dᵢ |ξᵢ| ξᵢ`, component by component in the basis of the algebra's
/// `vee`, with coefficients dᵢ ≥ 0: the diagonal quadratic damping of a body moving through a
/// fluid at high Reynolds number (Fossen, *Handbook of Marine Craft Hydrodynamics and Motion
/// Control*, 2011, §6.4: `D_n(ν) ν = diag(dᵢ |νᵢ|) ν`; on SE(3) in lie-groups' (ω, v) ordering,
/// d = (d_p, d_q, d_r, d_u, d_v, d_w) — rotational first). Linear drag is
/// [`crate::forces::LinearDamping`].
///
/// Its power `⟨F_ext, ξ⟩ = −Σᵢ dᵢ |ξᵢ|³ ≤ 0`: the energy decays. A body translating along a
/// principal axis of a diagonal mass matrix, `m v̇ = −d |v| v`, slows as `v(t) = v₀/(1 + d v₀ t/m)`
/// (`tests/systems_underwater_vehicle.rs` checks this closed form).
#[derive(Debug, Clone)]
pub struct QuadraticDrag<G: LieGroup> {
    d: G::Algebra,
}

impl<G: LieGroup> QuadraticDrag<G> {
    /// The drag with coefficients `d` (one per algebra component, finite and ≥ 0).
    pub fn new(d: G::Algebra) -> Result<Self, IntegratorError> {
        if d.dim() != G::dim() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "quadratic drag has one coefficient per component: {} for {}, got {}",
                    G::dim(),
                    G::name(),
                    d.dim()
                ),
            });
        }
        if let Some(i) = (0..d.dim()).find(|&i| !(d.get(i).is_finite() && d.get(i) >= 0.0)) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "quadratic drag coefficient d[{i}] = {} must be finite and ≥ 0",
                    d.get(i)
                ),
            });
        }
        Ok(Self { d })
    }
    /// The coefficients dᵢ.
    pub fn coefficients(&self) -> &G::Algebra {
        &self.d
    }
}

impl<G: LieGroup> ExternalForce<G> for QuadraticDrag<G> {
    #[inline]
    fn force(&self, _t: f64, _g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        G::Algebra::from_fn(G::dim(), |i| {
            let x = xi.get(i);
            -self.d.get(i) * x.abs() * x
        })
    }
    /// The drag's rate at the velocity ξ = ∂h/∂μ(μ), `maxᵢ dᵢ |ξᵢ| / Mᵢᵢ` (the linear damping
    /// it acts as there; Mᵢᵢ as for [`crate::forces::LinearDamping`]).
    fn characteristic_rate<S: crate::System<G>>(
        &self,
        system: &S,
        mu: &G::Algebra,
        _g: Option<&G>,
    ) -> f64 {
        let n = G::dim();
        let xi = system.velocity(mu);
        (0..n)
            .map(|i| {
                let e = G::Algebra::basis(n, i);
                self.d.get(i) * xi.get(i).abs() / system.momentum(&e).get(i)
            })
            .fold(0.0, f64::max)
    }
}
