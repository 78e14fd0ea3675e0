//! A step of every integrator allocates nothing on the heap for the fixed-size groups (SO(3),
//! SE(3), SE(2)): counted by a global allocator, per thread, over 100 steps after a first one.
//! Every solver kind, both τ maps, θ ∈ {0, ½, 1}, with and without reconstruction, with and
//! without a potential, the RK4 / RKMK4 baselines and the Gragg–Bulirsch–Stoer reference method.

use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::forces::{BodyTorque, Forced, LinearDamping, Schedule};
use integrators::systems::{HeavyTop, PlanarBody, RigidBody, RigidBodySe3};
use integrators::{
    EulerPoincare, GraggBulirschStoer, Integrator, LiePoisson, SolverConfig, SolverKind, System,
};
use lie_groups::testing::{allocations, CountingAllocator};
use lie_groups::{Cayley, CayleyGroup, ExpMap, LieGroup, Se2, Se3, So2, So3, Tau};
use nalgebra::{Matrix3, Vector2, Vector3, Vector6};

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

/// One step, then 100 counted steps of size h.
fn assert_steps_allocate_nothing<I: Integrator>(mut integ: I, h: f64) {
    integ.step(h).unwrap();
    let n = allocations(|| {
        for _ in 0..100 {
            integ.step(std::hint::black_box(h)).unwrap();
        }
    });
    assert_eq!(
        n,
        0,
        "{}: {n} allocations in 100 steps",
        integ.method_name()
    );
}

const KINDS: [SolverKind; 4] = [
    SolverKind::SimplifiedNewton,
    SolverKind::Newton,
    SolverKind::NewtonFiniteDifference,
    SolverKind::FixedPoint,
];

/// Lie–Poisson and Euler–Poincaré for every θ, solver kind and τ ∈ {exp, Cayley}.
fn every_method<G, S>(system: &S, mu0: G::Algebra, g0: Option<G>, h: f64)
where
    G: CayleyGroup,
    S: System<G> + Clone,
{
    fn with_tau<G: LieGroup, T: Tau<G>, S: System<G> + Clone>(
        system: &S,
        mu0: &G::Algebra,
        g0: &Option<G>,
        h: f64,
    ) {
        for theta in [0.0, 0.5, 1.0] {
            for kind in KINDS {
                let config = SolverConfig {
                    kind,
                    ..SolverConfig::default()
                };
                let lp = LiePoisson::<G, T, _>::new(system.clone(), theta, mu0.clone(), g0.clone())
                    .unwrap()
                    .with_solver(config);
                assert_steps_allocate_nothing(lp, h);
                let ep = EulerPoincare::<G, T, _>::from_momentum(
                    system.clone(),
                    theta,
                    mu0.clone(),
                    g0.clone(),
                )
                .unwrap()
                .with_solver(config);
                assert_steps_allocate_nothing(ep, h);
            }
        }
    }
    with_tau::<G, ExpMap, S>(system, &mu0, &g0, h);
    with_tau::<G, Cayley, S>(system, &mu0, &g0, h);
}

#[test]
fn so3_steps_allocate_nothing() {
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let r0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    every_method::<So3, _>(&body, pi0, Some(r0), 0.01);
    every_method::<So3, _>(&body, pi0, None, 0.01);
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 1.0, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    every_method::<So3, _>(&top, pi0, Some(r0), 0.01);
    for g0 in [Some(r0), None] {
        assert_steps_allocate_nothing(QuaternionRk4::new(body.clone(), pi0, g0).unwrap(), 0.01);
        assert_steps_allocate_nothing(Rkmk4::new(body.clone(), pi0, g0).unwrap(), 0.01);
        assert_steps_allocate_nothing(
            GraggBulirschStoer::new(body.clone(), pi0, g0).unwrap(),
            0.01,
        );
    }
    assert_steps_allocate_nothing(
        GraggBulirschStoer::new(top.clone(), pi0, Some(r0)).unwrap(),
        0.01,
    );
    assert_steps_allocate_nothing(
        QuaternionRk4::new(top.clone(), pi0, Some(r0)).unwrap(),
        0.01,
    );
    assert_steps_allocate_nothing(Rkmk4::new(top, pi0, Some(r0)).unwrap(), 0.01);
    // forced: a scheduled body torque and damping
    let schedule = Schedule::new(
        vec![0.0, 1.0],
        vec![vec![0.1, 0.0, -0.2], vec![0.3, 0.1, 0.0]],
    )
    .unwrap();
    let forced = Forced::new(
        body.clone(),
        (
            BodyTorque::<So3>::new(schedule).unwrap(),
            LinearDamping::<So3>::new(Matrix3::identity() * 0.1).unwrap(),
        ),
    );
    every_method::<So3, _>(&forced, pi0, Some(r0), 0.01);
    assert_steps_allocate_nothing(
        QuaternionRk4::new(forced.clone(), pi0, Some(r0)).unwrap(),
        0.01,
    );
    assert_steps_allocate_nothing(
        GraggBulirschStoer::new(forced.clone(), pi0, Some(r0)).unwrap(),
        0.01,
    );
    assert_steps_allocate_nothing(Rkmk4::new(forced, pi0, Some(r0)).unwrap(), 0.01);
}

#[test]
fn se3_steps_allocate_nothing() {
    let inertia = Matrix3::new(1.0, 0.1, 0.0, 0.1, 1.5, 0.2, 0.0, 0.2, 2.0) * 1e-3;
    let satellite = RigidBodySe3::satellite(1.0, inertia, 1.0).unwrap();
    let r0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    let p = r0.as_matrix().tr_mul(&Vector3::new(0.0, 1.1, 0.1));
    let mu0 = Vector6::new(0.5e-3, 1.0e-3, 2.0e-3, p.x, p.y, p.z);
    let g0 = Se3::from_parts(r0, Vector3::new(1.0, 0.0, 0.0));
    every_method::<Se3, _>(&satellite, mu0, Some(g0), 0.01);
    let free = RigidBodySe3::free(2.0, inertia).unwrap();
    every_method::<Se3, _>(&free, mu0, None, 0.01);
    assert_steps_allocate_nothing(
        GraggBulirschStoer::new(satellite.clone(), mu0, Some(g0)).unwrap(),
        0.01,
    );
    assert_steps_allocate_nothing(Rkmk4::new(satellite, mu0, Some(g0)).unwrap(), 0.01);
}

#[test]
fn se2_steps_allocate_nothing() {
    let body = PlanarBody::free(1.5, 0.2)
        .unwrap()
        .with_spring(4.0, Vector2::new(0.3, -0.1))
        .unwrap();
    let g0 = Se2::new(So2::from_angle(0.4), Vector2::new(1.0, 0.5));
    let mu0 = Vector3::new(0.3, 0.5, 1.2);
    every_method::<Se2, _>(&body, mu0, Some(g0), 0.01);
    assert_steps_allocate_nothing(
        GraggBulirschStoer::new(body.clone(), mu0, Some(g0)).unwrap(),
        0.01,
    );
    assert_steps_allocate_nothing(Rkmk4::new(body, mu0, Some(g0)).unwrap(), 0.01);
}

/// The counter does see allocations: building a method name allocates a `String`.
#[test]
fn the_allocation_counter_counts() {
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let lp =
        LiePoisson::<So3, Cayley, _>::new(body, 0.5, Vector3::new(0.5, 1.0, 0.2), None).unwrap();
    assert!(allocations(|| drop(std::hint::black_box(lp.method_name()))) > 0);
}
