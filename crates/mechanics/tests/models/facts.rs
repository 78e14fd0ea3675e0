//! The models' facts for tools (`integrators::System::conserved_momentum_map`,
//! `characteristic_rate`, `torque_rate`, and their combination by `Forced`), checked against
//! trajectories of RKMK4 at a small step — a method that keeps none of these quantities by
//! construction, so that what it keeps to its truncation error the flow keeps.
//!
//! - every quantity a model declares conserved (a sum of components of `J = Ad*_{g⁻¹} μ`) drifts
//!   by at most the integrator's error, and a component it does not declare moves by far more
//!   (the declaration is not a blanket "everything");
//! - the rates are the frequencies they claim: the hanging heavy top swinging about its least
//!   principal axis at `√(m g ℓ / λ_min)`, the planar body on a spring at `√(k/m)`, a body spun
//!   about a principal axis with damping D relaxing at `D₁₁/I₁`, a schedule's shortest ramp.

use integrators::forces::{BodyTorque, Forced, LinearDamping, Schedule};
use integrators::{Integrator, Rkmk4, System};
use lie_groups::{LieGroup, Power, PowerAlgebra, Product, ProductAlgebra, Rn, Se2, Se3, So2, So3};
use mechanics::systems::{
    CoupledBodies, Gyrostat, HeavyTop, PlanarBody, Quadrotor, RigidBody, RigidBodySe3, Spring,
    UnderwaterVehicle,
};
use nalgebra::{Matrix3, Matrix6, SVector, Vector2, Vector3, Vector6};

/// Runs RKMK4 with step h for `steps` steps from (μ₀, g₀) and returns the largest drift of each
/// declared quantity and of each single component of J over the run.
fn drifts<G: lie_groups::CayleyGroup, S: System<G> + Clone>(
    system: S,
    mu0: G::Algebra,
    g0: G,
    h: f64,
    steps: usize,
) -> (Vec<Vec<usize>>, Vec<f64>, Vec<f64>) {
    use lie_groups::Vector;
    let parts = system.conserved_momentum_map();
    let j = |m: &G::Algebra, g: &G| g.inverse().coadjoint_apply(m);
    let j0 = j(&mu0, &g0);
    let mut rk = Rkmk4::new(system, mu0, Some(g0)).unwrap();
    let mut worst_parts = vec![0.0f64; parts.len()];
    let mut worst_components = vec![0.0f64; G::dim()];
    for _ in 0..steps {
        rk.step(h).unwrap();
        let jk = j(&rk.momentum(), rk.configuration().unwrap());
        for (w, group) in worst_parts.iter_mut().zip(&parts) {
            let d: f64 = group.iter().map(|&i| jk.get(i) - j0.get(i)).sum();
            *w = w.max(d.abs());
        }
        for (i, w) in worst_components.iter_mut().enumerate() {
            *w = w.max((jk.get(i) - j0.get(i)).abs());
        }
    }
    (parts, worst_parts, worst_components)
}

/// The declared parts drift by less than `kept`; some undeclared component by more than `moved`.
fn check<G: lie_groups::CayleyGroup, S: System<G> + Clone>(
    name: &str,
    system: S,
    mu0: G::Algebra,
    g0: G,
    expected: &[&[usize]],
) {
    let (parts, worst, components) = drifts(system, mu0, g0, 1e-3, 2000);
    let want: Vec<Vec<usize>> = expected.iter().map(|p| p.to_vec()).collect();
    assert_eq!(parts, want, "{name}: declared parts");
    for (p, w) in parts.iter().zip(&worst) {
        // RKMK4 at h = 1e-3 over T = 2 on these O(1) states: its global error is ~1e-12.
        assert!(*w < 1e-9, "{name}: {p:?} drifts by {w:e}");
    }
    let declared: Vec<usize> = parts.iter().flatten().copied().collect();
    let moved = (0..components.len())
        .filter(|i| !declared.contains(i))
        .map(|i| components[i])
        .fold(0.0f64, f64::max);
    if declared.len() < components.len() {
        assert!(
            moved > 1e-4,
            "{name}: no undeclared component moves ({components:?})"
        );
    }
}

fn tilted() -> So3 {
    So3::exp(&Vector3::new(0.4, -0.3, 0.2))
}

#[test]
fn every_model_keeps_the_parts_of_the_momentum_map_it_declares() {
    let inertia = Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, -0.2, 0.0, -0.2, 4.0);
    let body = RigidBody::new(inertia).unwrap();
    check(
        "free body",
        body.clone(),
        Vector3::new(0.3, 1.0, -0.5),
        tilted(),
        &[&[0], &[1], &[2]],
    );
    let top = HeavyTop::new(inertia, 1.5, 9.81, Vector3::new(0.1, 0.0, 0.5)).unwrap();
    check(
        "heavy top",
        top,
        Vector3::new(0.3, 1.0, -0.5),
        tilted(),
        &[&[2]],
    );
    let sat = RigidBodySe3::satellite(2.0, inertia, 50.0).unwrap();
    let g_sat = Se3::from_parts(tilted(), Vector3::new(3.0, 0.5, -0.2));
    let mu_sat = Vector6::new(0.1, 0.3, -0.2, 0.0, 8.0, 1.0);
    check("satellite", sat, mu_sat, g_sat, &[&[0], &[1], &[2]]);
    let planar = PlanarBody::free(2.0, 0.5)
        .unwrap()
        .with_spring(3.0, Vector2::new(0.2, 0.1))
        .unwrap();
    let g_planar = Se2::new(So2::from_angle(0.3), Vector2::new(1.0, -0.5));
    check(
        "planar spring",
        planar,
        Vector3::new(0.4, 0.5, -0.3),
        g_planar,
        &[&[0]],
    );
    let falling = PlanarBody::free(2.0, 0.5)
        .unwrap()
        .with_gravity(Vector2::new(0.0, -9.81))
        .unwrap();
    check(
        "planar gravity",
        falling,
        Vector3::new(0.4, 0.5, -0.3),
        g_planar,
        &[],
    );
    // Wheel torques push p only: R Π stays. A platform torque pushes R Π only: p stays.
    let gyro = Gyrostat::<2>::new(
        inertia,
        [Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0)],
        [0.05, 0.05],
    )
    .unwrap();
    let mu_gyro = ProductAlgebra::new(Vector3::new(0.3, 1.0, -0.5), SVector::from([0.1, 0.0]));
    let g_gyro = Product::new(tilted(), Rn::new(SVector::from([0.0, 0.0])));
    let wheels =
        Gyrostat::<2>::wheel_torques(Schedule::constant(vec![0.2, -0.1]).unwrap()).unwrap();
    check(
        "gyrostat, wheel torques",
        Forced::new(gyro.clone(), wheels),
        mu_gyro,
        g_gyro,
        &[&[0], &[1], &[2]],
    );
    let platform =
        Gyrostat::<2>::body_torque(Schedule::constant(vec![0.2, -0.1, 0.1]).unwrap()).unwrap();
    check(
        "gyrostat, platform torque",
        Forced::new(gyro, platform),
        mu_gyro,
        g_gyro,
        &[&[3], &[4]],
    );
    // A vehicle slightly heavier than it is buoyant, centre of gravity below the origin.
    let m =
        UnderwaterVehicle::rigid_body_mass_matrix(20.0, &inertia, &Vector3::new(0.0, 0.0, -0.05))
            + Matrix6::from_diagonal(&Vector6::new(0.1, 0.2, 0.2, 1.0, 5.0, 5.0));
    let auv = UnderwaterVehicle::new(m)
        .unwrap()
        .with_restoring(
            200.0,
            Vector3::new(0.0, 0.0, -0.05),
            190.0,
            Vector3::zeros(),
        )
        .unwrap();
    let mu_auv = Vector6::new(0.1, 0.3, -0.2, 10.0, 1.0, -0.5);
    check(
        "underwater vehicle",
        auv,
        mu_auv,
        Se3::from_parts(tilted(), Vector3::new(0.0, 0.0, -10.0)),
        &[&[2], &[3], &[4]],
    );
    let quad = Quadrotor::new(1.5, inertia, 9.81).unwrap();
    check(
        "quadrotor",
        quad,
        mu_auv,
        Se3::from_parts(tilted(), Vector3::zeros()),
        &[&[2], &[3], &[4]],
    );
    let bodies = [
        RigidBodySe3::free(1.0, inertia).unwrap(),
        RigidBodySe3::free(2.0, inertia * 1.5).unwrap(),
    ];
    let spring = Spring::new(
        [0, 1],
        [Vector3::new(0.1, 0.0, 0.0), Vector3::new(0.0, -0.1, 0.0)],
        4.0,
        0.5,
    )
    .unwrap();
    let chain = CoupledBodies::new(bodies, vec![spring]).unwrap();
    let mu_chain = PowerAlgebra::<Se3, 2>::from_parts_fn(|k| {
        Vector6::new(0.1, -0.2, 0.3, 1.0 - k as f64, 0.5, 0.0)
    });
    let g_chain = Power::new([
        Se3::from_parts(tilted(), Vector3::zeros()),
        Se3::from_parts(So3::identity(), Vector3::new(1.0, 0.0, 0.0)),
    ]);
    check(
        "coupled bodies",
        chain,
        mu_chain,
        g_chain,
        &[&[0, 6], &[1, 7], &[2, 8], &[3, 9], &[4, 10], &[5, 11]],
    );
    // A torque or damping breaks everything on the free body.
    let damped = Forced::new(
        body,
        LinearDamping::<So3>::new(Matrix3::identity() * 0.1).unwrap(),
    );
    check(
        "damped body",
        damped,
        Vector3::new(0.3, 1.0, -0.5),
        tilted(),
        &[],
    );
}

/// The first time after 0 at which `f` (sampled every h along an RKMK4 run) changes sign, by
/// linear interpolation between the samples.
fn first_zero<G: lie_groups::CayleyGroup, S: System<G>>(
    system: S,
    mu0: G::Algebra,
    g0: G,
    h: f64,
    f: impl Fn(&G::Algebra, &G) -> f64,
) -> f64 {
    let mut rk = Rkmk4::new(system, mu0, Some(g0)).unwrap();
    let mut prev = f(&rk.momentum(), rk.configuration().unwrap());
    loop {
        rk.step(h).unwrap();
        let now = f(&rk.momentum(), rk.configuration().unwrap());
        if prev.signum() != now.signum() {
            return rk.time() - h * now / (now - prev);
        }
        prev = now;
    }
}

/// The quadrotor's rate is its potential's frequency: the square root of the largest singular
/// value of the force derivative K(g) (`force_derivative`, checked against finite differences in
/// `systems_quadrotor.rs`) normalized by the mass matrix 𝕄 = diag(𝕀, m I₃), the largest over
/// attitudes (reached where the vertical Γ is normal to the least principal axis), or the spin
/// |Ω| where that is faster.
#[test]
fn the_quadrotors_rate_is_its_force_derivatives_frequency() {
    let (m, g) = (4.34, 9.81);
    let inertia = Matrix3::new(0.09, 0.004, 0.0, 0.004, 0.0845, 0.002, 0.0, 0.002, 0.1377);
    let quad = Quadrotor::new(m, inertia, g).unwrap();
    let mut half = Matrix6::zeros();
    let root = inertia.symmetric_eigen();
    let inv_sqrt = root.eigenvectors
        * Matrix3::from_diagonal(&root.eigenvalues.map(|l| 1.0 / l.sqrt()))
        * root.eigenvectors.transpose();
    half.fixed_view_mut::<3, 3>(0, 0).copy_from(&inv_sqrt);
    half.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(Matrix3::identity() / m.sqrt()));
    let mut largest = 0.0f64;
    for k in 0..400 {
        let a = k as f64 * 0.37;
        let attitude = So3::exp(&Vector3::new(a.sin() * 2.0, (1.3 * a).cos(), 0.5 * a));
        let at = Se3::from_parts(attitude, Vector3::zeros());
        let k = half * quad.force_derivative(&at) * half;
        largest = largest.max(k.singular_values().max());
    }
    let rate = quad.characteristic_rate(&Vector6::zeros(), None);
    let frequency = largest.sqrt();
    assert!(
        (rate - frequency).abs() < 1e-3 * frequency && rate >= frequency,
        "{rate} vs {frequency}"
    );
    // Spinning faster than that: the spin.
    let pi = inertia * Vector3::new(0.0, 0.0, 40.0);
    let spin = Vector6::new(pi.x, pi.y, pi.z, 1.0, 0.0, 0.0);
    let fast = quad.characteristic_rate(&spin, None);
    assert!((fast - 40.0).abs() < 1e-6, "{fast}");
    // Without gravity, the spin alone (the free body's |Ω|).
    let free = Quadrotor::new(m, inertia, 0.0).unwrap();
    assert_eq!(free.characteristic_rate(&Vector6::zeros(), None), 0.0);
}

#[test]
fn rates_are_the_frequencies_of_the_motion() {
    // The hanging top (χ = −ℓ e₃ below the pivot) swinging about its least principal axis e₁:
    // θ̈ = −(m g ℓ / I₁) θ, so Π₁ = I₁θ̇ first vanishes at a quarter period π/(2ω).
    let (i1, m, g, ell) = (2.0, 1.5, 9.81, 0.4);
    let top = HeavyTop::new(
        Matrix3::from_diagonal(&Vector3::new(i1, 5.0, 6.0)),
        m,
        g,
        Vector3::new(0.0, 0.0, -ell),
    )
    .unwrap();
    let omega = top.characteristic_rate(&Vector3::zeros(), Some(&So3::identity()));
    assert_eq!(omega, (m * g * ell / i1).sqrt());
    // Small amplitude (Π₁ = 1e-4 I₁ω: 1e-4 rad): the pendulum's period departs from 2π/ω by θ²/16.
    let pi0 = Vector3::new(1e-4 * i1 * omega, 0.0, 0.0);
    let quarter = first_zero(top, pi0, So3::identity(), 1e-4, |pi, _| pi[0]);
    let want = core::f64::consts::FRAC_PI_2 / omega;
    assert!((quarter - want).abs() < 1e-8 * want, "{quarter} vs {want}");

    // The planar body on a spring at its centre: x = x₀ cos(√(k/m) t) (J, c = 0: no turning).
    let (k, mass) = (3.0, 2.0);
    let planar = PlanarBody::free(mass, 0.5)
        .unwrap()
        .with_spring(k, Vector2::zeros())
        .unwrap();
    let rate = planar.characteristic_rate(&Vector3::zeros(), None);
    assert_eq!(rate, (k / mass).sqrt());
    let start = Se2::new(So2::from_angle(0.0), Vector2::new(1.0, 0.0));
    let quarter = first_zero(planar, Vector3::zeros(), start, 1e-4, |_, g| {
        g.translation().x
    });
    let want = core::f64::consts::FRAC_PI_2 / rate;
    assert!((quarter - want).abs() < 1e-8 * want, "{quarter} vs {want}");

    // Spin about e₁ of a principal body with damping D = diag(d): Π₁ = Π₁(0) e^{−(d₁/I₁) t}; the
    // declared rate is the largest dᵢ/Iᵢ (here axis 1's), or the body's |Ω| when larger.
    let body = RigidBody::principal([2.0, 3.0, 4.0]).unwrap();
    let damping =
        LinearDamping::<So3>::new(Matrix3::from_diagonal(&Vector3::new(1.0, 0.3, 0.4))).unwrap();
    let damped = Forced::new(body.clone(), damping);
    let pi0 = Vector3::new(0.01, 0.0, 0.0);
    let rate = damped.characteristic_rate(&pi0, None);
    assert_eq!(rate, 0.5);
    let mut rk = Rkmk4::new(damped, pi0, None).unwrap();
    for _ in 0..1000 {
        rk.step(1e-3).unwrap();
    }
    let measured = -(rk.momentum()[0] / pi0[0]).ln() / rk.time();
    assert!((measured - rate).abs() < 1e-10, "{measured}");

    // A schedule's shortest gap (0.05) sets 1/Δt = 20, above the torque's spin-up
    // √(|τ|/λ_min) = √(0.3/2); a constant torque sets only its spin-up.
    let ramp = Schedule::new(vec![0.0, 1.0, 1.05], vec![vec![0.0, 0.0, 0.3]; 3]).unwrap();
    let pushed = Forced::new(body.clone(), BodyTorque::<So3>::new(ramp).unwrap());
    assert_eq!(
        pushed.characteristic_rate(&Vector3::zeros(), None),
        1.0 / (1.05 - 1.0)
    );
    let steady = Forced::new(
        body,
        BodyTorque::<So3>::constant(Vector3::new(0.0, 0.0, 0.3)).unwrap(),
    );
    assert_eq!(
        steady.characteristic_rate(&Vector3::zeros(), None),
        (0.3f64 / 2.0).sqrt()
    );
}

/// The free body's closed-form G = (1/ρ) dρ/dt (ρ = |Ω|) agrees with central differences of ρ
/// along the flow (the provided form) on asymmetric, near-axisymmetric and stiff bodies, and is
/// odd in Π. A wrong sign of Π̇ (Ω × Π for Π × Ω) flips G and fails here.
#[test]
fn rigid_body_step_density_rate_is_the_closed_form() {
    use integrators::derivative_check::finite_difference_step_density_rate;
    let bodies = [
        RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
        RigidBody::principal([1.0, 1.0001, 1.5]).unwrap(),
        RigidBody::principal([1e-3, 1.0, 1.0005]).unwrap(),
    ];
    let states = [
        Vector3::new(0.3, -1.2, 0.8),
        Vector3::new(1e-3, 1.0, 1e-3),
        Vector3::new(-2.0, 0.5, 4.0),
    ];
    for body in &bodies {
        for mu in &states {
            let scope = integrators::DensityScope::Full;
            let closed = body.step_density_rate(mu, None, scope);
            let fd = finite_difference_step_density_rate(body, mu, None, scope);
            let scale = body.step_density(mu, None, scope);
            assert!(
                (closed - fd).abs() <= 1e-6 * scale.max(fd.abs()),
                "G = {closed:e}, central differences {fd:e}"
            );
            assert_eq!(body.step_density_rate(&-mu, None, scope), -closed);
        }
    }
}
