//! Your own system: a satellite with a permanent magnet (dipole m, body frame) in a uniform field B
//! (inertial frame), written from scratch as an `integrators::System<So3>`, its hand-derived
//! derivatives checked against finite differences, and integrated by Lie–Poisson. docs/custom-systems.md
//! walks through it.
//!
//! ```sh
//! cargo run --release -p lie-integrators --example custom_system
//! ```
//!
//! The physics: kinetic energy h(Π) = ½ Πᵀ𝕀⁻¹Π, potential V(R) = −(R m)·B, so the body-frame
//! magnetic torque is m × RᵀB and the satellite librates about B like a compass needle. Energy is
//! conserved, and so is the spatial angular momentum about B, B·(RΠ) (rotations about B are a
//! symmetry); |Π|² is not (the potential breaks it).

use integrators::derivative_check::{check_derivatives, DEFAULT_TOLERANCE};
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, LieGroup, So3};
use nalgebra::{Matrix3, Vector3};

/// A rigid body with a magnetic dipole in a uniform field.
#[derive(Clone, Debug)]
struct MagneticSatellite {
    /// 𝕀⁻¹ (the body's inverse inertia tensor).
    inertia_inv: Matrix3<f64>,
    /// 𝕀.
    inertia: Matrix3<f64>,
    /// Dipole m in the body frame (A·m²).
    dipole: Vector3<f64>,
    /// Field B in the inertial frame (T).
    field: Vector3<f64>,
}

impl System<So3> for MagneticSatellite {
    /// h(Π) = ½ Πᵀ𝕀⁻¹Π.
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        0.5 * mu.dot(&(self.inertia_inv * mu))
    }
    /// ∂h/∂Π = 𝕀⁻¹Π = Ω.
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.inertia_inv * mu
    }
    /// ∂²h/∂Π² = 𝕀⁻¹ (constant). Leaving this method out would use central differences of
    /// `velocity` instead: correct, but 6 velocity evaluations per call.
    fn hessian(&self, _mu: &Vector3<f64>) -> Matrix3<f64> {
        self.inertia_inv
    }
    /// The Legendre map Ω ↦ Π = 𝕀Ω (the inverse of `velocity`).
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.inertia * xi
    }
    fn has_potential(&self) -> bool {
        true
    }
    /// V(R) = −(R m)·B.
    fn potential(&self, g: &So3) -> f64 {
        -(g.as_matrix() * self.dipole).dot(&self.field)
    }
    /// `T*_e L_R dV`, defined by ⟨T*_e L_R dV, ζ⟩ = d/ds V(R exp(sζ)) at s = 0:
    /// d/ds −(R exp(sζ̂) m)·B = −(R(ζ × m))·B = −ζ·(m × RᵀB), so it is RᵀB × m (the torque on the
    /// body is its negative, m × RᵀB).
    fn potential_differential(&self, g: &So3) -> Vector3<f64> {
        (g.as_matrix().transpose() * self.field).cross(&self.dipole)
    }
}

fn main() {
    let inertia = Matrix3::from_diagonal(&Vector3::new(12.0, 15.0, 9.0));
    let sat = MagneticSatellite {
        inertia_inv: inertia.try_inverse().expect("positive inertia"),
        inertia,
        dipole: Vector3::new(20.0, 0.0, 5.0),
        field: Vector3::new(0.0, 3e-5, 4e-5) * 1e3, // a strong field, for visible librations
    };

    // 1. Check the hand-derived derivatives at a few states before trusting them.
    let samples = [
        (
            Vector3::new(0.3, -0.2, 0.5),
            Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8))),
        ),
        (
            Vector3::new(-4.0, 1.0, 2.5),
            Some(So3::exp(&Vector3::new(2.0, 0.4, -1.1))),
        ),
    ];
    let report = check_derivatives(&sat, &samples);
    println!("derivative check: {report}");
    assert!(
        report.passes(DEFAULT_TOLERANCE),
        "fix the derivatives first"
    );

    // The mistake this catches: the torque m × RᵀB written as the differential (a sign slip).
    struct SignSlip(MagneticSatellite);
    impl System<So3> for SignSlip {
        fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
            self.0.hamiltonian(mu)
        }
        fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
            self.0.velocity(mu)
        }
        fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
            self.0.hessian(mu)
        }
        fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
            self.0.momentum(xi)
        }
        fn has_potential(&self) -> bool {
            true
        }
        fn potential(&self, g: &So3) -> f64 {
            self.0.potential(g)
        }
        fn potential_differential(&self, g: &So3) -> Vector3<f64> {
            -self.0.potential_differential(g)
        }
    }
    let slip = check_derivatives(&SignSlip(sat.clone()), &samples);
    println!("with a sign slip in dV: {slip}");
    assert!(!slip.passes(DEFAULT_TOLERANCE));

    // 2. Integrate: Lie–Poisson, Cayley, θ = ½ (symmetric, order 2), h = 0.05 over T = 500.
    let (h, steps) = (0.05, 10_000);
    let pi0 = Vector3::new(0.3, -0.2, 0.5);
    let g0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    let mut lp = LiePoisson::<So3, Cayley, _>::new(sat.clone(), 0.5, pi0, Some(g0))
        .expect("valid initial state");
    let e0 = lp.energy();
    let b = sat.field.normalize();
    let l0 = b.dot(&(g0.as_matrix() * pi0));
    let (mut de, mut dl) = (0.0f64, 0.0f64);
    for _ in 0..steps {
        lp.step(h).expect("the step converges");
        let r = lp.configuration().expect("reconstructed").as_matrix();
        de = de.max(((lp.energy() - e0) / e0).abs());
        dl = dl.max((b.dot(&(r * lp.momentum())) - l0).abs());
    }
    println!(
        "Lie–Poisson (Cayley, θ = ½), {steps} steps of h = {h}: max |ΔE/E| = {de:.2e} (bounded, \
         order 2), max |Δ B·RΠ| = {dl:.2e} (the symmetry's momentum, kept to round-off)"
    );
    println!("properties: {:?}", lp.info());
}
