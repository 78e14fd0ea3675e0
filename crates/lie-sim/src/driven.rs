//! A run whose steps are chosen as it goes ([`crate::driver::Driver`]: to a tolerance, or with
//! reversible steps), with its system, seen as a [`Simulation`].

use crate::attitude;
use crate::driver::Driver;
use crate::sim::{attitudes_of, power_of};
use crate::sim::{group_side, read_group, read_spatial_momentum, write_row, write_vector};
use crate::sim::{SimGroup, Simulation};
use integrators::adaptive::Stats;
use integrators::MethodInfo;
use lie_groups::LieGroup;

/// A [`Driver`] with its system, seen as a [`Simulation`]: energy and Casimir of rows between
/// steps are evaluated by the system at the partial step's state.
pub struct DrivenSim<G: LieGroup, S> {
    driver: Box<dyn Driver<Group = G>>,
    system: S,
}

impl<G: LieGroup, S> DrivenSim<G, S> {
    /// `driver` advancing `system`.
    pub fn new(driver: Box<dyn Driver<Group = G>>, system: S) -> Self {
        Self { driver, system }
    }
}

impl<G, S> Simulation for DrivenSim<G, S>
where
    G: SimGroup,
    S: integrators::System<G>,
{
    /// A run that chooses its own steps takes them with [`Self::step_towards`].
    fn step(&mut self, _h: f64) -> Result<(), String> {
        Err("this run chooses its own steps (a tolerance or ε), not a step h".into())
    }
    fn step_towards(&mut self, t_end: f64) -> Result<(), String> {
        self.driver.step_towards(t_end).map_err(|e| e.to_string())
    }
    fn stats(&self) -> Option<Stats> {
        Some(self.driver.stats())
    }
    fn time(&self) -> f64 {
        self.driver.current().time()
    }
    fn momentum_dim(&self) -> usize {
        G::dim()
    }
    fn group_side(&self) -> Option<usize> {
        group_side(self.driver.current())
    }
    fn read_momentum(&self, out: &mut [f64]) {
        write_vector(&self.driver.current().momentum(), out);
    }
    fn read_group(&self, out: &mut [f64]) -> bool {
        read_group(self.driver.current(), out)
    }
    fn energy(&self) -> f64 {
        self.driver.current().energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.driver.current().casimir()
    }
    fn read_spatial_momentum(&self, out: &mut [f64]) -> bool {
        read_spatial_momentum(self.driver.current(), out)
    }
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        self.system.conserved_momentum_map()
    }
    fn power(&self) -> Option<f64> {
        let m = self.driver.current();
        power_of(&self.system, m.time(), &m.momentum(), m.configuration())
    }
    fn bodies(&self) -> usize {
        attitudes_of(self.driver.current().configuration())
    }
    fn read_attitudes(&self, out: &mut [f64]) -> bool {
        self.driver
            .current()
            .configuration()
            .map(|g| attitude::write_all(g, out))
            .is_some()
    }
    fn info(&self) -> MethodInfo {
        self.driver.current().info()
    }
    fn read_error(&self) -> Option<String> {
        self.driver.current().read_error().map(|e| e.to_string())
    }
    fn mark(&mut self) {
        self.driver.mark();
    }
    fn read_at(&self, t: f64, row: &mut [f64]) -> Result<(), String> {
        let system = &self.system;
        self.driver
            .at(t, &mut |mu, g| write_row(system, t, mu, g, row))
            .map_err(|e| e.to_string())
    }
}
