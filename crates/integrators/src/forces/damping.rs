//! [`LinearDamping`]: viscous damping `F_ext = −D ξ`.

use crate::forces::ExternalForce;
use crate::IntegratorError;
use lie_groups::{LieGroup, Operator, Vector};

/// Viscous damping `F_ext(ξ) = −D ξ` with D symmetric positive semidefinite (checked at
/// construction: finite, symmetric, nonnegative diagonal): the energy decays at the rate
/// `dE/dt = −⟨ξ, D ξ⟩`. With D = c 𝕀 on a free rigid body, F = −cμ and `E(t) = E(0) e^{−2ct}`,
/// `|μ(t)|² = |μ(0)|² e^{−2ct}` exactly.
#[derive(Debug, Clone)]
pub struct LinearDamping<G: LieGroup> {
    d: G::Operator,
}

impl<G: LieGroup> LinearDamping<G> {
    /// The damping with matrix D.
    pub fn new(d: G::Operator) -> Result<Self, IntegratorError> {
        let n = G::dim();
        let e = |i: usize| G::Algebra::from_fn(n, |j| if i == j { 1.0 } else { 0.0 });
        for i in 0..n {
            let di = d.apply(&e(i));
            if !di.is_finite() {
                return Err(IntegratorError::NonFinite {
                    what: "damping matrix D",
                });
            }
            for j in 0..n {
                let (a, b) = (di.get(j), d.apply(&e(j)).get(i));
                if (a - b).abs() > 1e-12 * (a.abs() + b.abs()).max(f64::MIN_POSITIVE) {
                    return Err(IntegratorError::InvalidParameter {
                        reason: format!("damping matrix D is not symmetric: D[{j}][{i}] = {a}, D[{i}][{j}] = {b}"),
                    });
                }
            }
            if di.get(i) < 0.0 {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!(
                        "damping matrix D has a negative diagonal entry D[{i}][{i}] = {}",
                        di.get(i)
                    ),
                });
            }
        }
        Ok(Self { d })
    }
    /// D.
    pub fn matrix(&self) -> &G::Operator {
        &self.d
    }
}

impl<G: LieGroup> ExternalForce<G> for LinearDamping<G> {
    #[inline]
    fn force(&self, _t: f64, _g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        self.d.apply(xi).neg()
    }
    /// The relaxation rate `maxᵢ Dᵢᵢ / Mᵢᵢ`, with `Mᵢᵢ = ⟨∂l/∂ξ(eᵢ), eᵢ⟩` the diagonal of the
    /// system's mass matrix (its Legendre map): a velocity component alone decays as
    /// `e^{−(Dᵢᵢ/Mᵢᵢ) t}`.
    fn characteristic_rate<S: crate::System<G>>(
        &self,
        system: &S,
        _mu: &G::Algebra,
        _g: Option<&G>,
    ) -> f64 {
        let n = G::dim();
        (0..n)
            .map(|i| {
                let e = G::Algebra::basis(n, i);
                self.d.apply(&e).get(i) / system.momentum(&e).get(i)
            })
            .fold(0.0, f64::max)
    }
}
