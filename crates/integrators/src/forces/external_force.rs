//! [`ExternalForce`]: `F_ext(t, g, ξ) ∈ 𝔤*`, left-trivialized.

use lie_groups::{LieGroup, Vector};

/// An external force or torque `F_ext(t, g, ξ) ∈ 𝔤*` in the body frame (left-trivialized, the
/// convention of the potential's force `F(g) = −T*_e L_g dV`), at time t, configuration g and body
/// velocity ξ. Its power is `⟨F_ext, ξ⟩`.
///
/// Closures `Fn(f64, Option<&G>, &G::Algebra) -> G::Algebra` are forces that may read g (they
/// declare [`Self::needs_configuration`], so g is reconstructed and passed); a pair `(a, b)` is the
/// sum of two forces; an `Option` is the force when `Some` and zero when `None` (optional terms of a
/// configured force, e.g. `(Option<BodyTorque<G>>, Option<LinearDamping<G>>)`).
pub trait ExternalForce<G: LieGroup> {
    /// `F_ext(t, g, ξ)`; `g` is `None` when the run does not reconstruct the configuration (only
    /// allowed when [`Self::needs_configuration`] is false).
    fn force(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> G::Algebra;
    /// Whether the force reads g: integrators then require g and pass it (otherwise they pass
    /// `None` and skip forming the configuration at which the force would act).
    fn needs_configuration(&self) -> bool {
        false
    }
    /// Whether the force reads the velocity ξ (damping, drag). The splittings then solve their
    /// force kick by the implicit midpoint rule (order 2) instead of applying it exactly. The
    /// provided answer is the safe one, `true`.
    fn reads_velocity(&self) -> bool {
        true
    }
}

impl<G, F> ExternalForce<G> for F
where
    G: LieGroup,
    F: Fn(f64, Option<&G>, &G::Algebra) -> G::Algebra,
{
    fn force(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        self(t, g, xi)
    }
    fn needs_configuration(&self) -> bool {
        true
    }
}

/// The sum of two forces.
impl<G: LieGroup, A: ExternalForce<G>, B: ExternalForce<G>> ExternalForce<G> for (A, B) {
    fn force(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        self.0.force(t, g, xi).add(&self.1.force(t, g, xi))
    }
    fn needs_configuration(&self) -> bool {
        self.0.needs_configuration() || self.1.needs_configuration()
    }
    fn reads_velocity(&self) -> bool {
        self.0.reads_velocity() || self.1.reads_velocity()
    }
}

/// A force that may be absent: `F_ext` when `Some`, zero when `None`.
impl<G: LieGroup, F: ExternalForce<G>> ExternalForce<G> for Option<F> {
    fn force(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        match self {
            Some(f) => f.force(t, g, xi),
            None => G::Algebra::zeros(xi.dim()),
        }
    }
    fn needs_configuration(&self) -> bool {
        self.as_ref()
            .is_some_and(ExternalForce::needs_configuration)
    }
    fn reads_velocity(&self) -> bool {
        self.as_ref().is_some_and(ExternalForce::reads_velocity)
    }
}
