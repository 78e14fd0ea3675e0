//! The long-horizon measures of a run: how far the energy, the Casimir and the conserved part of
//! the spatial momentum map drift from their initial values, sampled along the run without storing
//! it.
//!
//! For samples k (every [`crate::trade::ENERGY_SAMPLE`] steps in a timed run, and at T):
//!
//! - energy: `max_k |E_k − E₀| / |E₀|` (absolute when E₀ = 0), E = h(μ) + V(g);
//! - Casimir: `max_k |C_k − C₀| / |C₀|` for the Casimir the system reports (|Π|² on SO(3),
//!   |P|² on SE(2) and SE(3)), where it has one;
//! - momentum map: `max_k ‖P(J_k − J₀)‖₂ / ‖J₀‖₂` (absolute when J₀ = 0), with
//!   `J = Ad*_{g⁻¹} μ` the spatial momentum map ([`crate::sim::Simulation::spatial_momentum`]) and
//!   P the linear map onto the quantities the flow conserves ([`conserved_momentum_map`]: each a
//!   component of J or, for coupled bodies, a sum of components); on the free rigid body
//!   `|R Π − R₀Π₀| / |R₀Π₀|`, on the heavy top `|e₃·(R Π − R₀Π₀)| / |R₀Π₀|`. Only where g is
//!   reconstructed and the system keeps some part of J.

use crate::run::relative_error;
use crate::scene::System;
use crate::sim::Simulation;

/// The quantities conserved by the exact flow of `system`, each the sum of the listed components
/// of the spatial momentum map `J = Ad*_{g⁻¹} μ` (in the basis of μ), or `None` when it conserves
/// none:
///
/// - free rigid body, free SE(3) body, free SE(2) body, SO(n) geodesic: all of J (the
///   Hamiltonian is left-invariant);
/// - heavy top (and 3D pendulum): `J₃ = e₃·R Π`, the angular momentum about the vertical (gravity
///   is −g e₃, the potential is invariant under rotations about e₃);
/// - satellite (SE(3) in a central field): the angular momentum about the centre,
///   `R Π + x × R P` (components 1–3; the field is invariant under rotations about the origin);
/// - planar body on a spring attached at the origin, without gravity: the angular momentum about
///   the origin (component 1); with gravity: none kept as a whole component;
/// - gyrostat: `R Π` (components 1–3) under wheel torques alone (internal: they act on p), all of
///   J = (RΠ, p) unforced; a platform torque keeps none;
/// - underwater vehicle and quadrotor (gravity along −e₃): the vertical angular momentum L₃ and
///   the horizontal linear momentum p₁, p₂ (components 3, 4, 5), also p₃ for a neutrally buoyant
///   vehicle (W = B) and everything for a quadrotor without gravity; none under thrust or drag;
/// - coupled bodies: the total spatial momentum Σ_k J_k, component by component (the springs are
///   invariant under moving every body together).
///
/// Forces keep none of it, except the gyrostat's wheel torques.
pub fn conserved_momentum_map(system: &System) -> Option<Vec<Vec<usize>>> {
    let each = |parts: &[usize]| Some(parts.iter().map(|&i| vec![i]).collect());
    let all = |n: usize| Some((0..n).map(|i| vec![i]).collect());
    if let System::Gyrostat(p) = system {
        return match &p.forces {
            None => all(3 + p.axes.len()),
            Some(f) if f.torque.is_none() => each(&[0, 1, 2]),
            Some(_) => None,
        };
    }
    if system.forces().is_some() {
        return None;
    }
    match system {
        System::FreeRigidBody(_) => each(&[0, 1, 2]),
        System::HeavyTop(_) => each(&[2]),
        System::RigidBodySe3(p) if p.gravitational_parameter > 0.0 => each(&[0, 1, 2]),
        System::RigidBodySe3(_) => all(6),
        System::PlanarBodySe2(p) if p.gravity != nalgebra::Vector2::zeros() => None,
        System::PlanarBodySe2(p) if p.stiffness != 0.0 => each(&[0]),
        System::PlanarBodySe2(_) => all(3),
        System::GeodesicSoN(p) => all(p.n * (p.n - 1) / 2),
        System::UnderwaterVehicle(p) if p.weight() == p.buoyancy => each(&[2, 3, 4, 5]),
        System::UnderwaterVehicle(_) => each(&[2, 3, 4]),
        System::Quadrotor(p) if p.gravity == 0.0 => all(6),
        System::Quadrotor(_) => each(&[2, 3, 4]),
        System::CoupledBodies(p) => Some(
            (0..6)
                .map(|i| (0..p.bodies.len()).map(|k| 6 * k + i).collect())
                .collect(),
        ),
        System::Gyrostat(_) => None,
    }
}

/// The running maxima of the relative drifts (see the module page), from the state a monitor was
/// made at.
#[derive(Debug, Clone)]
pub struct Monitor {
    e0: f64,
    c0: Option<f64>,
    j0: Option<Vec<f64>>,
    j_scale: f64,
    parts: Option<Vec<Vec<usize>>>,
    /// max |E − E₀|/|E₀| so far.
    pub energy: f64,
    /// max |C − C₀|/|C₀| so far, where the system has a Casimir.
    pub casimir: Option<f64>,
    /// max ‖P(J − J₀)‖/‖J₀‖ so far, where g is reconstructed and the system keeps part of J.
    pub momentum_map: Option<f64>,
}

impl Monitor {
    /// A monitor of `sim` from its current state; `system` says which part of J is kept.
    pub fn new(sim: &dyn Simulation, system: &System) -> Self {
        let parts = conserved_momentum_map(system);
        let j0 = parts.as_ref().and_then(|_| sim.spatial_momentum());
        let j_scale = j0
            .as_ref()
            .map_or(0.0, |j| j.iter().map(|x| x * x).sum::<f64>().sqrt());
        let c0 = sim.casimir();
        Self {
            e0: sim.energy(),
            c0,
            momentum_map: j0.as_ref().map(|_| 0.0),
            j0,
            j_scale,
            parts,
            energy: 0.0,
            casimir: c0.map(|_| 0.0),
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
        if let (Some(j0), Some(m), Some(parts), Some(j)) = (
            &self.j0,
            self.momentum_map.as_mut(),
            &self.parts,
            sim.spatial_momentum(),
        ) {
            let d2: f64 = parts
                .iter()
                .map(|group| {
                    let d: f64 = group.iter().map(|&i| j[i] - j0[i]).sum();
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
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Overrides, Scene};
    use crate::sim::mock::Spin;

    fn free_body() -> System {
        Scene::default_scene(Overrides::default()).unwrap().system
    }

    #[test]
    fn a_uniform_rotation_keeps_everything_and_nothing_is_monitored_without_g() {
        let mut sim = Spin {
            t: 0.0,
            omega: 2.0,
            reconstruct: true,
            fail_after: None,
            steps: 0,
        };
        let system = free_body();
        let mut m = Monitor::new(&sim, &system);
        for _ in 0..5 {
            sim.step(0.3).unwrap();
            m.sample(&sim);
        }
        assert_eq!(
            (m.energy, m.casimir, m.momentum_map),
            (0.0, Some(0.0), Some(0.0))
        );
        sim.reconstruct = false;
        assert_eq!(Monitor::new(&sim, &system).momentum_map, None);
    }

    /// A state whose J, C and E each move by a known amount.
    struct Drift(f64);
    impl Simulation for Drift {
        fn step(&mut self, h: f64) -> Result<(), String> {
            self.0 += h;
            Ok(())
        }
        fn time(&self) -> f64 {
            self.0
        }
        fn momentum(&self) -> Vec<f64> {
            vec![0.0, 0.0, 2.0]
        }
        fn group_side(&self) -> Option<usize> {
            Some(3)
        }
        fn group_matrix(&self) -> Option<Vec<f64>> {
            None
        }
        fn energy(&self) -> f64 {
            -4.0 + self.0
        }
        fn casimir(&self) -> Option<f64> {
            Some(4.0 * (1.0 + self.0))
        }
        fn velocity(&self) -> Vec<f64> {
            vec![0.0; 3]
        }
        fn spatial_momentum(&self) -> Option<Vec<f64>> {
            Some(vec![3.0 * self.0, 0.0, 2.0 + 4.0 * self.0])
        }
        fn info(&self) -> integrators::MethodInfo {
            Spin {
                t: 0.0,
                omega: 0.0,
                reconstruct: false,
                fail_after: None,
                steps: 0,
            }
            .info()
        }
    }

    /// The coupled bodies keep the sums over the bodies; the gyrostat keeps R Π under wheel
    /// torques and nothing under a platform torque; a neutrally buoyant vehicle keeps p₃ as well.
    #[test]
    fn vehicles_keep_their_parts_of_the_momentum_map() {
        let example = |file: &str, extra: &str| {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../examples/scenes")
                .join(file);
            let text = std::fs::read_to_string(path)
                .unwrap()
                .replace("[forces]\n", &format!("[forces]\n{extra}"));
            Scene::parse(&text, file, file, Overrides::default())
                .unwrap()
                .system
        };
        let chain = conserved_momentum_map(&example("coupled-bodies.toml", "")).unwrap();
        assert_eq!(chain.len(), 6);
        assert_eq!(chain[1], vec![1, 7, 13]);
        let wheels = example("reaction-wheel-slew.toml", "");
        assert_eq!(
            conserved_momentum_map(&wheels),
            Some(vec![vec![0], vec![1], vec![2]])
        );
        let pushed = example("reaction-wheel-slew.toml", "torque = [0.0, 0.0, 0.01]\n");
        assert_eq!(conserved_momentum_map(&pushed), None);
        let auv = |b: &str| {
            let text = std::fs::read_to_string(
                std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join("../../examples/scenes/underwater-vehicle.toml"),
            )
            .unwrap();
            let text = text[..text.find("\n[forces]").unwrap()]
                .replace("gravity = 9.81", "gravity = 10.0")
                .replace("buoyancy = 306.0", b);
            conserved_momentum_map(
                &Scene::parse(&text, "auv", "auv", Overrides::default())
                    .unwrap()
                    .system,
            )
            .unwrap()
            .len()
        };
        // W = 30.5 × 10 = 305: heavier than B = 306 keeps (L₃, p₁, p₂), W = B keeps p₃ too.
        assert_eq!(auv("buoyancy = 306.0"), 3);
        assert_eq!(auv("buoyancy = 305.0"), 4);
    }

    #[test]
    fn drifts_are_relative_and_the_heavy_top_sees_only_the_vertical_component() {
        let mut sim = Drift(0.0);
        let system = free_body();
        let mut m = Monitor::new(&sim, &system);
        sim.step(0.5).unwrap();
        m.sample(&sim);
        sim.step(-0.25).unwrap();
        m.sample(&sim);
        // E: |0.5|/4; C: 4·0.5/4; J: |(1.5, 0, 2)|/|(0, 0, 2)| = 2.5/2.
        assert_eq!(m.energy, 0.125);
        assert_eq!(m.casimir, Some(0.5));
        assert_eq!(m.momentum_map, Some(1.25));
        let top = Scene::parse(
            r#"
[system]
kind = "heavy-top"
inertia = [1.0, 1.0, 2.0]
mass = 1.0
center_of_mass = [0.0, 0.0, 0.5]
gravity = 9.81
[initial]
momentum = [0.0, 0.0, 2.0]
[integrator]
method = "lie-poisson"
tau = "exp"
theta = 0.5
step = 0.1
duration = 1.0
"#,
            "top",
            "top",
            Overrides::default(),
        )
        .unwrap()
        .system;
        let mut sim = Drift(0.0);
        let mut m = Monitor::new(&sim, &top);
        sim.step(0.5).unwrap();
        m.sample(&sim);
        // Only e₃·J: |2|/|(0, 0, 2)| = 1.
        assert_eq!(m.momentum_map, Some(1.0));
    }
}
