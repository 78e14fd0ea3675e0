//! [`Forced`]: a system with an external force attached.

use crate::forces::ExternalForce;
use crate::splitting::SplitSystem;
use crate::System;
use lie_groups::LieGroup;

/// The system `S` acted on by the external force `F`: the same Hamiltonian, potential and
/// Casimir, with [`System::external_force`] = `F`. The energy `h(μ) + V(g)` is no longer conserved
/// (it changes by the work of F), nor, in general, are the Casimir and the momentum map.
#[derive(Debug, Clone)]
pub struct Forced<S, F> {
    system: S,
    force: F,
}

impl<S, F> Forced<S, F> {
    /// `system` with `force` attached.
    pub fn new(system: S, force: F) -> Self {
        Self { system, force }
    }
    /// The unforced system.
    pub fn system(&self) -> &S {
        &self.system
    }
    /// The force.
    pub fn force(&self) -> &F {
        &self.force
    }
}

impl<G: LieGroup, S: System<G>, F: ExternalForce<G>> System<G> for Forced<S, F> {
    fn hamiltonian(&self, mu: &G::Algebra) -> f64 {
        self.system.hamiltonian(mu)
    }
    fn velocity(&self, mu: &G::Algebra) -> G::Algebra {
        self.system.velocity(mu)
    }
    fn hessian(&self, mu: &G::Algebra) -> G::Operator {
        self.system.hessian(mu)
    }
    fn hessian_norm(&self, mu: &G::Algebra) -> f64 {
        self.system.hessian_norm(mu)
    }
    fn momentum(&self, xi: &G::Algebra) -> G::Algebra {
        self.system.momentum(xi)
    }
    /// The unforced system's: F_ext does not enter h.
    fn diagonal_velocity(&self) -> Option<G::Algebra> {
        self.system.diagonal_velocity()
    }
    fn has_potential(&self) -> bool {
        self.system.has_potential()
    }
    fn potential(&self, g: &G) -> f64 {
        self.system.potential(g)
    }
    fn potential_differential(&self, g: &G) -> G::Algebra {
        self.system.potential_differential(g)
    }
    fn is_forced(&self) -> bool {
        true
    }
    fn external_force_reads_velocity(&self) -> bool {
        self.force.reads_velocity()
    }
    fn external_force(&self, t: f64, g: Option<&G>, xi: &G::Algebra) -> G::Algebra {
        self.force.force(t, g, xi)
    }
    fn needs_configuration(&self) -> bool {
        self.system.needs_configuration() || self.force.needs_configuration()
    }
    fn casimir(&self, mu: &G::Algebra) -> Option<f64> {
        self.system.casimir(mu)
    }
    fn energy(&self, mu: &G::Algebra, g: Option<&G>) -> f64 {
        self.system.energy(mu, g)
    }
    /// The larger of the system's rate and the force's
    /// ([`ExternalForce::characteristic_rate`]).
    fn characteristic_rate(&self, mu: &G::Algebra, g: Option<&G>) -> f64 {
        self.system
            .characteristic_rate(mu, g)
            .max(self.force.characteristic_rate(&self.system, mu, g))
    }
    fn torque_rate(&self, force: &G::Algebra) -> f64 {
        self.system.torque_rate(force)
    }
    /// What the system keeps when the force pushes where it acts
    /// ([`System::conserved_momentum_map_under`] of [`ExternalForce::acts_on`]; nothing when the
    /// force may act anywhere).
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        match self.force.acts_on() {
            Some(pushed) => self.system.conserved_momentum_map_under(&pushed),
            None => Vec::new(),
        }
    }
    fn conserved_momentum_map_under(&self, pushed: &[usize]) -> Vec<Vec<usize>> {
        match self.force.acts_on() {
            Some(mut own) => {
                own.extend_from_slice(pushed);
                self.system.conserved_momentum_map_under(&own)
            }
            None => Vec::new(),
        }
    }
}

/// The kinetic pieces of the unforced system: the splittings then apply the force in their kicks
/// ([`crate::splitting`]).
impl<G: LieGroup, S: SplitSystem<G>, F: ExternalForce<G>> SplitSystem<G> for Forced<S, F> {
    fn pieces(&self) -> usize {
        self.system.pieces()
    }
    fn piece_velocity(&self, i: usize, mu: &G::Algebra) -> G::Algebra {
        self.system.piece_velocity(i, mu)
    }
    #[inline]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut G::Algebra, g: Option<&mut G>) {
        self.system.piece_flow(i, t, mu, g)
    }
}
