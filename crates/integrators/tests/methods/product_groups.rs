//! Integrators on a product group, unchanged: a free rigid body and a free particle as one system on
//! SO(3) × ℝ³, `h(Π, p) = ½ Π·𝕀⁻¹Π + |p|²/2m`.
//!
//! The system decouples, so the Lie–Poisson run (τ = exp, θ = ½) on the product must equal, factor
//! by factor, the run of the rigid body alone on SO(3) (`systems::RigidBody`, an independent code
//! path through the stack group `So3`) and the exact straight-line motion `x(t) = x₀ + t p/m`,
//! `p(t) = p₀` on ℝ³; the Casimir |Π|² is kept to round-off. The same for τ = Cayley.

use integrators::derivative_check::check_derivatives;
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, Product, ProductAlgebra, Rn, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{DMatrix, Matrix3, Vector3};

type Body = Product<So3, Rn<3>>;
type Mu = ProductAlgebra<So3, Rn<3>>;

/// A free rigid body (inertia 𝕀) and a free particle (mass m) on SO(3) × ℝ³:
/// `h(Π, p) = ½ Π·𝕀⁻¹Π + |p|²/2m`, `∂h/∂μ = (𝕀⁻¹Π, p/m)`, `∂²h/∂μ² = diag(𝕀⁻¹, I/m)`,
/// Legendre map `(Ω, v) ↦ (𝕀Ω, m v)`, Casimir |Π|².
#[derive(Debug, Clone)]
struct BodyAndParticle {
    body: RigidBody,
    mass: f64,
}

impl System<Body> for BodyAndParticle {
    fn hamiltonian(&self, mu: &Mu) -> f64 {
        self.body.hamiltonian(&mu.a) + mu.b.norm_squared() / (2.0 * self.mass)
    }
    fn velocity(&self, mu: &Mu) -> Mu {
        Mu::new(self.body.velocity(&mu.a), mu.b / self.mass)
    }
    fn hessian(&self, mu: &Mu) -> DMatrix<f64> {
        let ib = self.body.hessian(&mu.a);
        DMatrix::from_fn(6, 6, |i, j| match (i < 3, j < 3) {
            (true, true) => ib[(i, j)],
            (false, false) if i == j => 1.0 / self.mass,
            _ => 0.0,
        })
    }
    fn momentum(&self, xi: &Mu) -> Mu {
        Mu::new(self.body.momentum(&xi.a), xi.b * self.mass)
    }
    fn casimir(&self, mu: &Mu) -> Option<f64> {
        Some(mu.a.norm_squared())
    }
}

fn setup() -> (BodyAndParticle, Mu, Body) {
    let inertia = Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.5);
    let system = BodyAndParticle {
        body: RigidBody::new(inertia).unwrap(),
        mass: 1.7,
    };
    let mu0 = Mu::new(Vector3::new(0.4, 1.1, -0.6), Vector3::new(0.8, -0.3, 1.2));
    let g0 = Body::new(
        So3::exp(&Vector3::new(0.3, -0.5, 0.2)),
        Rn::new(Vector3::new(1.0, 2.0, -1.0)),
    );
    (system, mu0, g0)
}

/// The hand-written derivatives are right (central differences, the library's check).
#[test]
fn body_and_particle_derivatives_match_finite_differences() {
    let (system, mu0, g0) = setup();
    let samples = [
        (mu0, Some(g0)),
        (
            Mu::new(Vector3::new(-1.0, 0.2, 0.3), Vector3::new(0.0, 2.0, -0.5)),
            None,
        ),
    ];
    let report = check_derivatives::<Body, _>(&system, &samples);
    assert!(report.passes(1e-8), "{report:?}");
}

/// Lie–Poisson (τ = exp, θ = ½) on SO(3) × ℝ³ equals the rigid body's run on SO(3) and the exact
/// straight line on ℝ³, at every step, to ≤ 1e-12; |Π|² is kept to round-off.
#[test]
fn lie_poisson_on_so3_x_r3_is_the_rigid_body_run_and_the_straight_line() {
    product_run_is_the_factors_runs::<ExpMap>();
}

/// The same with τ = Cayley (the product is a `CayleyGroup` because both factors are; on ℝ³
/// cay = exp, so the particle still moves on the exact straight line).
#[test]
fn lie_poisson_cayley_on_so3_x_r3_is_the_rigid_body_run_and_the_straight_line() {
    product_run_is_the_factors_runs::<Cayley>();
}

fn product_run_is_the_factors_runs<T: Tau<So3> + Tau<Body>>() {
    let (system, mu0, g0) = setup();
    let (h, steps) = (0.01, 2000);
    let mut product = LiePoisson::<Body, T, _>::new(system.clone(), 0.5, mu0, Some(g0)).unwrap();
    let mut alone =
        LiePoisson::<So3, T, _>::new(system.body.clone(), 0.5, mu0.a, Some(g0.g)).unwrap();
    let c0 = mu0.a.norm_squared();
    let (x0, p0, m) = (g0.h.vector(), mu0.b, system.mass);
    let (mut worst_pi, mut worst_r, mut worst_x, mut worst_p, mut worst_c) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for k in 1..=steps {
        product.step(h).unwrap();
        alone.step(h).unwrap();
        let t = k as f64 * h;
        assert!((product.time() - t).abs() < 1e-12);
        let mu = product.momentum();
        let g = product.configuration().unwrap();
        worst_pi = worst_pi.max((mu.a - alone.momentum()).amax());
        worst_r = worst_r.max(g.g.matrix_distance(alone.configuration().unwrap()));
        worst_x = worst_x.max((g.h.vector() - (x0 + p0 * (t / m))).amax());
        worst_p = worst_p.max((mu.b - p0).amax());
        worst_c = worst_c.max((product.casimir().unwrap() - c0).abs());
    }
    eprintln!(
        "τ = {}, over {steps} steps: |ΔΠ| {worst_pi:.2e}, |ΔR| {worst_r:.2e}, |Δx| {worst_x:.2e}, \
         |Δp| {worst_p:.2e}, |Δ|Π|²| {worst_c:.2e}",
        <T as Tau<Body>>::NAME
    );
    assert!(
        worst_pi <= 1e-12,
        "Π differs from the SO(3) run by {worst_pi:.3e}"
    );
    assert!(
        worst_r <= 1e-12,
        "R differs from the SO(3) run by {worst_r:.3e}"
    );
    assert!(
        worst_x <= 1e-12,
        "x differs from x₀ + t p/m by {worst_x:.3e}"
    );
    assert!(worst_p <= 1e-12, "p changed by {worst_p:.3e}");
    assert!(worst_c <= 1e-13 * c0, "|Π|² drifted by {worst_c:.3e}");
    // the energy of the product run is the sum of the parts
    let e = product.energy();
    let e_parts = alone.energy() + p0.norm_squared() / (2.0 * m);
    assert!((e - e_parts).abs() <= 1e-12, "{e} vs {e_parts}");
}
