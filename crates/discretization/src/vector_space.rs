//! The same constructions on a plain vector space M = ℝⁿ, where every bundle is trivial and every
//! Lie bracket vanishes: the discretization map, its tangent and cotangent lifts and their
//! inverses in closed form. They reduce to the familiar one-step methods:
//!
//! - the tangent lift gives the θ-method `z_{k+1} − z_k = t X((1−θ) z_k + θ z_{k+1})` for a vector
//!   field on TM (implicit midpoint rule at θ = ½, explicit and implicit Euler at θ = 0, 1);
//! - the cotangent lift gives the partitioned method with positions evaluated at
//!   `x = (1−θ) x_k + θ x_{k+1}` and momenta at `p = θ p_k + (1−θ) p_{k+1}`: symplectic Euler
//!   `(x_k, p_{k+1})` at θ = 0, its adjoint `(x_{k+1}, p_k)` at θ = 1, the implicit midpoint rule at
//!   θ = ½.
//!
//! Points of TM and T*M are pairs `(x, v)`, `(x, p)`; points of TTM and TT*M are quadruples
//! `(x, v, δx, δv)` and `(x, p, δx, δp)`: the base point followed by the tangent vector.

use crate::DiscretizationError;
use lie_groups::Vector;

/// A point `(x, v)` of TM = ℝⁿ × ℝⁿ (or `(x, p)` of T*M).
pub type Point<V> = (V, V);

/// A point `(x, v, δx, δv)` of TTM (or `(x, p, δx, δp)` of TT*M): the base point and a tangent
/// vector at it.
pub type TangentPoint<V> = (V, V, V, V);

/// The discretization map `R_d(x, v) = (x − θv, x + (1−θ)v)` on ℝⁿ and its lifts (§3.2–3.4 with
/// M = ℝⁿ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VectorSpaceDiscretization {
    theta: f64,
}

impl VectorSpaceDiscretization {
    /// The map with parameter θ; an error unless θ is finite and in [0, 1].
    pub fn new(theta: f64) -> Result<Self, DiscretizationError> {
        if !(0.0..=1.0).contains(&theta) {
            return Err(DiscretizationError::InvalidTheta { theta });
        }
        Ok(Self { theta })
    }

    /// θ.
    #[inline]
    pub fn theta(&self) -> f64 {
        self.theta
    }

    /// `R_d(x, v) = (x − θv, x + (1−θ)v)`.
    #[inline]
    pub fn apply<V: Vector>(&self, x: &V, v: &V) -> Point<V> {
        (x.axpy(-self.theta, v), x.axpy(1.0 - self.theta, v))
    }

    /// `R_d⁻¹(x_k, x_{k+1}) = (x_k + θ (x_{k+1} − x_k), x_{k+1} − x_k)`, defined everywhere.
    #[inline]
    pub fn inverse<V: Vector>(&self, xk: &V, xk1: &V) -> Point<V> {
        let v = xk1.sub(xk);
        (xk.axpy(self.theta, &v), v)
    }

    /// The tangent lift `R_d^T = T R_d ∘ κ` (eq. 12): with κ(x, v, δx, δv) = (x, δx, v, δv),
    ///
    /// `R_d^T(x, v, δx, δv) = ((x − θδx, v − θδv), (x + (1−θ)δx, v + (1−θ)δv))`.
    #[inline]
    pub fn tangent_lift<V: Vector>(&self, p: &TangentPoint<V>) -> (Point<V>, Point<V>) {
        let (x, v, dx, dv) = p;
        let (a, b) = (-self.theta, 1.0 - self.theta);
        (
            (x.axpy(a, dx), v.axpy(a, dv)),
            (x.axpy(b, dx), v.axpy(b, dv)),
        )
    }

    /// `(R_d^T)⁻¹((x_k, v_k), (x_{k+1}, v_{k+1}))
    ///  = (x_k + θΔx, v_k + θΔv, Δx, Δv)` with `Δx = x_{k+1} − x_k`, `Δv = v_{k+1} − v_k`.
    #[inline]
    pub fn tangent_lift_inverse<V: Vector>(&self, k: &Point<V>, k1: &Point<V>) -> TangentPoint<V> {
        let (dx, dv) = (k1.0.sub(&k.0), k1.1.sub(&k.1));
        (k.0.axpy(self.theta, &dx), k.1.axpy(self.theta, &dv), dx, dv)
    }

    /// The cotangent lift `R_d^{T*} = Φ ∘ T*R_d⁻¹ ∘ α` (eq. 14), with α(x, p, δx, δp) =
    /// (x, δx; δp, p) ∈ T*TM and `Φ(x_0, P_0; x_1, P_1) = ((x_0, −P_0), (x_1, P_1))`:
    ///
    /// `R_d^{T*}(x, p, δx, δp) = ((x − θδx, p − (1−θ)δp), (x + (1−θ)δx, p + θδp))`.
    ///
    /// (The transpose of T R_d gives `P_0 + P_1 = δp`, `−θ P_0 + (1−θ) P_1 = p`.)
    #[inline]
    pub fn cotangent_lift<V: Vector>(&self, p: &TangentPoint<V>) -> (Point<V>, Point<V>) {
        let (x, mom, dx, dp) = p;
        let theta = self.theta;
        (
            (x.axpy(-theta, dx), mom.axpy(theta - 1.0, dp)),
            (x.axpy(1.0 - theta, dx), mom.axpy(theta, dp)),
        )
    }

    /// `(R_d^{T*})⁻¹((x_k, p_k), (x_{k+1}, p_{k+1}))
    ///  = (x_k + θΔx, θ p_k + (1−θ) p_{k+1}, Δx, Δp)` with `Δx = x_{k+1} − x_k`, `Δp = p_{k+1} − p_k`.
    #[inline]
    pub fn cotangent_lift_inverse<V: Vector>(
        &self,
        k: &Point<V>,
        k1: &Point<V>,
    ) -> TangentPoint<V> {
        let theta = self.theta;
        let dx = k1.0.sub(&k.0);
        (
            k.0.axpy(theta, &dx),
            k.1.scale(theta).axpy(1.0 - theta, &k1.1),
            dx,
            k1.1.sub(&k.1),
        )
    }
}
