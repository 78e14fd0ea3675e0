//! [`ExternalForce`]: `F_ext(t, g, ξ) ∈ 𝔤*`, left-trivialized.

use crate::System;
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
    /// The components of 𝔤* in which the force may act in the body frame, `None` for any of them
    /// (the provided answer): what [`crate::System::conserved_momentum_map_under`] reads to tell
    /// which parts of the spatial momentum map survive the force.
    fn acts_on(&self) -> Option<Vec<usize>> {
        None
    }
    /// The rate the force imposes on the motion of `system` at (μ, g), in the sense of
    /// [`crate::System::characteristic_rate`]: `1/Δt` for the shortest gap Δt between the knots of
    /// a schedule (a longer step smears its ramps), the spin-up rate of its torques
    /// ([`crate::System::torque_rate`]), the relaxation rate of damping. Provided: 0.
    fn characteristic_rate<S: System<G>>(
        &self,
        _system: &S,
        _mu: &G::Algebra,
        _g: Option<&G>,
    ) -> f64 {
        0.0
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
    /// The union of both, `None` when either acts anywhere.
    fn acts_on(&self) -> Option<Vec<usize>> {
        let mut a = self.0.acts_on()?;
        for i in self.1.acts_on()? {
            if !a.contains(&i) {
                a.push(i);
            }
        }
        Some(a)
    }
    /// The larger of the two.
    fn characteristic_rate<S: System<G>>(&self, system: &S, mu: &G::Algebra, g: Option<&G>) -> f64 {
        self.0
            .characteristic_rate(system, mu, g)
            .max(self.1.characteristic_rate(system, mu, g))
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
    /// Nowhere when `None`.
    fn acts_on(&self) -> Option<Vec<usize>> {
        self.as_ref()
            .map_or(Some(Vec::new()), ExternalForce::acts_on)
    }
    fn characteristic_rate<S: System<G>>(&self, system: &S, mu: &G::Algebra, g: Option<&G>) -> f64 {
        self.as_ref()
            .map_or(0.0, |f| f.characteristic_rate(system, mu, g))
    }
}

/// `1/Δt` for the shortest gap Δt between consecutive knots of `schedule` (0 for a constant):
/// the detail a step must resolve (a longer step smears the schedule's ramps).
pub(crate) fn knot_rate(schedule: &crate::forces::Schedule) -> f64 {
    schedule
        .times()
        .windows(2)
        .map(|w| 1.0 / (w[1] - w[0]))
        .fold(0.0, f64::max)
}

/// The largest [`System::torque_rate`] of the covectors `force(u)` over the knot values u of
/// `schedule` (the interpolation is convex, so the knots bound every value in between).
pub(crate) fn peak_torque_rate<G: LieGroup, S: System<G>>(
    system: &S,
    schedule: &crate::forces::Schedule,
    force: impl Fn(&[f64]) -> G::Algebra,
) -> f64 {
    schedule
        .times()
        .iter()
        .map(|&t| schedule.eval_with(t, |u| system.torque_rate(&force(u))))
        .fold(0.0, f64::max)
}
