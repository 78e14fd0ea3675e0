//! The long-horizon measures of a run: how far the energy, the Casimir and the conserved part of
//! the spatial momentum map drift from their initial values, sampled along the run without storing
//! it.
//!
//! For samples k (every [`crate::measure::ENERGY_SAMPLE`] steps in a timed run, and at T):
//!
//! - energy: `max_k |E_k − E₀| / |E₀|` (absolute when E₀ = 0), E = h(μ) + V(g);
//! - Casimir: `max_k |C_k − C₀| / |C₀|` for the Casimir the system reports (|Π|² on SO(3),
//!   |P|² on SE(2) and SE(3)), where it has one;
//! - momentum map: `max_k ‖P(J_k − J₀)‖₂ / ‖J₀‖₂` (absolute when J₀ = 0), with
//!   `J = Ad*_{g⁻¹} μ` the spatial momentum map ([`crate::sim::Simulation::read_spatial_momentum`])
//!   and P the linear map onto the quantities the flow conserves (each a component of J or, for
//!   coupled bodies, a sum of components: the model's own declaration,
//!   `integrators::System::conserved_momentum_map`); on the free rigid body
//!   `|R Π − R₀Π₀| / |R₀Π₀|`, on the heavy top `|e₃·(R Π − R₀Π₀)| / |R₀Π₀|`. Only where g is
//!   reconstructed and the system keeps some part of J.

use crate::sim::Simulation;

/// |x − x₀| / |x₀|, or |x − x₀| when x₀ = 0.
pub fn relative_error(x: f64, x0: f64) -> f64 {
    let d = (x - x0).abs();
    if x0 == 0.0 {
        d
    } else {
        d / x0.abs()
    }
}

/// The running maxima of the relative drifts (see the module page), from the state a monitor was
/// made at. Sampling reads the state in place: no allocation.
#[derive(Debug, Clone)]
pub struct Monitor {
    e0: f64,
    c0: Option<f64>,
    j0: Vec<f64>,
    j_scale: f64,
    parts: Vec<Vec<usize>>,
    /// J at the latest sample.
    j: Vec<f64>,
    /// max |E − E₀|/|E₀| so far.
    pub energy: f64,
    /// max |C − C₀|/|C₀| so far, where the system has a Casimir.
    pub casimir: Option<f64>,
    /// max ‖P(J − J₀)‖/‖J₀‖ so far, where g is reconstructed and the system keeps part of J.
    pub momentum_map: Option<f64>,
}

impl Monitor {
    /// A monitor of `sim` from its current state.
    pub fn new(sim: &dyn Simulation) -> Self {
        let parts = sim.conserved_momentum_map();
        let mut j0 = vec![0.0; sim.momentum_dim()];
        let tracked = !parts.is_empty() && sim.read_spatial_momentum(&mut j0);
        let j_scale = j0.iter().map(|x| x * x).sum::<f64>().sqrt();
        let c0 = sim.casimir();
        Self {
            e0: sim.energy(),
            c0,
            j: j0.clone(),
            j0,
            j_scale,
            parts: if tracked { parts } else { Vec::new() },
            energy: 0.0,
            casimir: c0.map(|_| 0.0),
            momentum_map: tracked.then_some(0.0),
        }
    }

    /// Takes a sample of `sim`'s current state. Returns the energy, so that the caller can stop
    /// a run that is no longer finite.
    pub fn sample(&mut self, sim: &dyn Simulation) -> f64 {
        let e = sim.energy();
        self.energy = self.energy.max(relative_error(e, self.e0));
        if let (Some(c0), Some(m), Some(c)) = (self.c0, self.casimir.as_mut(), sim.casimir()) {
            *m = m.max(relative_error(c, c0));
        }
        if let Some(m) = self.momentum_map.as_mut() {
            if sim.read_spatial_momentum(&mut self.j) {
                let d2: f64 = self
                    .parts
                    .iter()
                    .map(|group| {
                        let d: f64 = group.iter().map(|&i| self.j[i] - self.j0[i]).sum();
                        d * d
                    })
                    .sum();
                let d = d2.sqrt();
                *m = m.max(if self.j_scale > 0.0 {
                    d / self.j_scale
                } else {
                    d
                });
            }
        }
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::mock::Spin;

    #[test]
    fn a_uniform_rotation_keeps_everything_and_nothing_is_monitored_without_g() {
        let mut sim = Spin {
            t: 0.0,
            omega: 2.0,
            reconstruct: true,
            fail_after: None,
            steps: 0,
        };
        let mut m = Monitor::new(&sim);
        for _ in 0..5 {
            sim.step(0.3).unwrap();
            m.sample(&sim);
        }
        assert_eq!(
            (m.energy, m.casimir, m.momentum_map),
            (0.0, Some(0.0), Some(0.0))
        );
        sim.reconstruct = false;
        assert_eq!(Monitor::new(&sim).momentum_map, None);
    }

    /// A state whose J, C and E each move by a known amount, keeping the parts `parts`.
    struct Drift(f64, Vec<Vec<usize>>);
    impl Simulation for Drift {
        fn step(&mut self, h: f64) -> Result<(), String> {
            self.0 += h;
            Ok(())
        }
        fn time(&self) -> f64 {
            self.0
        }
        fn momentum_dim(&self) -> usize {
            3
        }
        fn read_momentum(&self, out: &mut [f64]) {
            out[..3].copy_from_slice(&[0.0, 0.0, 2.0]);
        }
        fn group_side(&self) -> Option<usize> {
            Some(3)
        }
        fn read_group(&self, _out: &mut [f64]) -> bool {
            false
        }
        fn energy(&self) -> f64 {
            -4.0 + self.0
        }
        fn casimir(&self) -> Option<f64> {
            Some(4.0 * (1.0 + self.0))
        }
        fn read_spatial_momentum(&self, out: &mut [f64]) -> bool {
            out[..3].copy_from_slice(&[3.0 * self.0, 0.0, 2.0 + 4.0 * self.0]);
            true
        }
        fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
            self.1.clone()
        }
        fn info(&self) -> integrators::MethodInfo {
            integrators::MethodInfo::plain(4)
        }
    }

    #[test]
    fn drifts_are_relative_and_only_the_kept_parts_are_measured() {
        let all = vec![vec![0], vec![1], vec![2]];
        let mut sim = Drift(0.0, all);
        let mut m = Monitor::new(&sim);
        sim.step(0.5).unwrap();
        m.sample(&sim);
        sim.step(-0.25).unwrap();
        m.sample(&sim);
        // E: |0.5|/4; C: 4·0.5/4; J: |(1.5, 0, 2)|/|(0, 0, 2)| = 2.5/2.
        assert_eq!(m.energy, 0.125);
        assert_eq!(m.casimir, Some(0.5));
        assert_eq!(m.momentum_map, Some(1.25));
        // The heavy top keeps e₃·J only: |2|/|(0, 0, 2)| = 1; a sum of two parts is one quantity.
        for (parts, want) in [(vec![vec![2]], 1.0), (vec![vec![0, 2]], 3.5 / 2.0)] {
            let mut sim = Drift(0.0, parts);
            let mut m = Monitor::new(&sim);
            sim.step(0.5).unwrap();
            m.sample(&sim);
            assert_eq!(m.momentum_map, Some(want));
        }
        // Nothing kept: nothing measured.
        assert_eq!(Monitor::new(&Drift(0.0, Vec::new())).momentum_map, None);
    }
}
