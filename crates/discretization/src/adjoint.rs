//! [`Adjoint`]: the adjoint of a discretization map, its points swapped and ξ reversed.

use crate::{Discretization, DiscretizationError, LiftedMap, Side};
use lie_groups::{LieGroup, Operator, Vector};

/// The adjoint `R̃_d*(g, ξ) = (R̃_d²(g, −ξ), R̃_d¹(g, −ξ))` of a map M: factors
/// `a*(ξ) = b(−ξ)`, `b*(ξ) = a(−ξ)`. Its lifted integrators at step −h undo those of M at h (see
/// the page of [`Discretization`]); M is symmetric iff it equals its adjoint. The adjoint of the
/// θ-map is the (1−θ)-map. Its lift components are the composed ones ([`LiftedMap`]'s provided
/// forms), whatever M overrides.
///
/// ```
/// use discretization::{Adjoint, Discretization, DiscretizationMap};
/// use lie_groups::{Cayley, LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let m = DiscretizationMap::<Cayley>::new(0.3).unwrap();
/// let adjoint = Adjoint(m);
/// let xi = Vector3::new(0.2, -0.1, 0.4);
/// let other = DiscretizationMap::<Cayley>::new(0.7).unwrap();
/// let a: So3 = adjoint.first_factor(&xi);
/// let b: So3 = other.first_factor(&xi);
/// assert!(a.matrix_distance(&b) < 1e-15);
/// assert!((Discretization::<So3>::theta(&adjoint) - 0.7).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adjoint<M>(pub M);

impl<G: LieGroup, M: Discretization<G>> Discretization<G> for Adjoint<M> {
    /// `a*(ξ) = b(−ξ)`.
    fn first_factor(&self, xi: &G::Algebra) -> G {
        self.0.second_factor(&xi.neg())
    }
    /// `b*(ξ) = a(−ξ)`.
    fn second_factor(&self, xi: &G::Algebra) -> G {
        self.0.first_factor(&xi.neg())
    }
    /// `d^L a*_ξ = −d^L b_{−ξ}`.
    fn first_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        self.0.second_factor_tangent(&xi.neg()).scale(-1.0)
    }
    /// `d^L b*_ξ = −d^L a_{−ξ}`.
    fn second_factor_tangent(&self, xi: &G::Algebra) -> G::Operator {
        self.0.first_factor_tangent(&xi.neg()).scale(-1.0)
    }
    fn label(&self) -> String {
        format!("adjoint of {}", self.0.label())
    }
    fn side(&self) -> Side {
        self.0.side()
    }
    /// `a*(ξ) = b(−ξ) = exp(−(1−θ)ξ + …)`: 1 − θ.
    fn theta(&self) -> f64 {
        1.0 - self.0.theta()
    }
    /// R̃_d** = R̃_d, so M equals its adjoint iff the adjoint equals its own.
    fn symmetric(&self) -> bool {
        self.0.symmetric()
    }
    /// The defect `log(b*(−ξ)⁻¹ a*(ξ)) = log(a(ξ)⁻¹ b(−ξ))` is M's reversed: the same order.
    fn order(&self) -> u32 {
        self.0.order()
    }
    /// `c*(ξ) = b(−ξ)⁻¹ a(−ξ) = c(−ξ)⁻¹`: reversible iff c is.
    fn reversible_increment(&self) -> bool {
        self.0.reversible_increment()
    }
    /// `c*(ξ) c*(−ξ) = c(−ξ)⁻¹ c(ξ)⁻¹ = (c(ξ) c(−ξ))⁻¹`: the same defect.
    fn increment_order(&self) -> u32 {
        self.0.increment_order()
    }
    /// R̃_d*(g, ξ) is inverted where R̃_d(g, −ξ) is.
    fn check_domain(&self, eta: &G::Algebra) -> Result<(), DiscretizationError> {
        self.0.check_domain(&eta.neg())
    }
}

impl<G: LieGroup, M: Discretization<G>> LiftedMap<G> for Adjoint<M> {}
