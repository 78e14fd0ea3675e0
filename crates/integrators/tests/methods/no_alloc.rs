//! A step of every integrator allocates nothing on the heap for the fixed-size groups (SO(3),
//! SE(3), SE(2)): counted by a global allocator, per thread, over 100 steps after a first one.
//! Every solver kind, both τ maps, θ ∈ {0, ½, 1}, with and without reconstruction, with and
//! without a potential, the RK4 / RKMK4 baselines and the Gragg–Bulirsch–Stoer reference method;
//! the vehicles on SE(3) (underwater vehicle with thrust and drag, quadrotor with thrust and
//! torques) too.

use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::forces::{BodyTorque, Forced, LinearDamping, QuadraticDrag, Schedule};
use integrators::splitting::{CasimirSplitting, Splitting, SplittingScheme};
use integrators::{
    EulerPoincare, GraggBulirschStoer, Integrator, LiePoisson, SolverConfig, SolverKind, System,
};
use lie_groups::testing::{allocations, CountingAllocator};
use lie_groups::{Cayley, CayleyGroup, ExpMap, LieGroup, Se2, Se3, So2, So3, Tau};
use mechanics::systems::{
    HeavyTop, PlanarBody, Quadrotor, RigidBody, RigidBodySe3, UnderwaterVehicle,
};
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
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
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
            CasimirSplitting::new(body.clone(), SplittingScheme::blanes_moan_6(), pi0, g0).unwrap(),
            0.01,
        );
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
    // The vehicles: a full mass matrix with restoring force, thrust (a control input through a
    // body-fixed input map), linear and quadratic drag; a quadrotor's thrust and torques.
    let mut m = nalgebra::Matrix6::from_diagonal(&Vector6::new(0.2, 3.0, 3.0, 30.0, 60.0, 60.0));
    m[(1, 5)] = 1.5;
    m[(5, 1)] = 1.5;
    let vehicle = Forced::new(
        UnderwaterVehicle::new(m)
            .unwrap()
            .with_restoring(
                299.0,
                Vector3::new(0.0, 0.0, -0.02),
                306.0,
                Vector3::zeros(),
            )
            .unwrap(),
        (
            Quadrotor::torques(Schedule::constant(vec![0.0, 0.1, 0.0]).unwrap()).unwrap(),
            (
                LinearDamping::<Se3>::new(nalgebra::Matrix6::identity()).unwrap(),
                QuadraticDrag::<Se3>::new(Vector6::repeat(0.5)).unwrap(),
            ),
        ),
    );
    let mu1 = Vector6::new(0.1, -0.2, 0.05, 15.0, 0.5, -0.3);
    every_method::<Se3, _>(&vehicle, mu1, Some(g0), 0.01);
    assert_steps_allocate_nothing(Rkmk4::new(vehicle, mu1, Some(g0)).unwrap(), 0.01);
    let quad = Forced::new(
        Quadrotor::new(1.5, inertia * 30.0, 9.81).unwrap(),
        (
            Quadrotor::thrust(Schedule::new(vec![0.0, 1.0], vec![vec![15.0], vec![16.0]]).unwrap())
                .unwrap(),
            Quadrotor::torques(Schedule::constant(vec![0.01, 0.0, 0.0]).unwrap()).unwrap(),
        ),
    );
    every_method::<Se3, _>(&quad, mu0, Some(g0), 0.01);
    assert_steps_allocate_nothing(Splitting::new(quad, mu0, Some(g0)).unwrap(), 0.01);
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

/// On the product and power groups the splittings allocate nothing either: the gyrostat on
/// SO(3) × ℝ³ under a wheel-torque schedule and two bodies on a spring on SE(3)². (Lie–Poisson
/// there allocates when it forms its Newton matrix, a heap `DMatrix` by lie-groups' design of
/// `Product`/`Power` operators.)
#[test]
fn product_and_power_splittings_allocate_nothing() {
    use lie_groups::{Power, PowerAlgebra, Product, ProductAlgebra, Rn};
    use mechanics::systems::{CoupledBodies, Gyrostat, Spring};
    use nalgebra::SVector;
    let gyro = Forced::new(
        Gyrostat::<3>::new(
            Matrix3::from_diagonal(&Vector3::new(10.0, 12.0, 9.0)),
            [Vector3::x(), Vector3::y(), Vector3::z()],
            [0.05; 3],
        )
        .unwrap(),
        Gyrostat::<3>::wheel_torques(
            Schedule::new(
                vec![0.0, 1.0],
                vec![vec![0.1, 0.0, 0.0], vec![0.0, 0.2, 0.0]],
            )
            .unwrap(),
        )
        .unwrap(),
    );
    let mu = ProductAlgebra::new(
        Vector3::new(1.0, -0.5, 0.3),
        SVector::<f64, 3>::new(0.1, 0.2, 0.3),
    );
    let g = Product::new(
        So3::exp(&Vector3::new(0.3, -0.5, 0.8)),
        Rn::new(SVector::<f64, 3>::zeros()),
    );
    assert_steps_allocate_nothing(Splitting::new(gyro, mu, Some(g)).unwrap(), 0.01);
    let body = RigidBodySe3::free(1.0, Matrix3::identity()).unwrap();
    let spring = Spring::new([0, 1], [Vector3::x(), Vector3::zeros()], 2.0, 0.5).unwrap();
    let pair = CoupledBodies::new([body.clone(), body], vec![spring]).unwrap();
    let mu = PowerAlgebra::<Se3, 2>::new([
        Vector6::new(0.1, 0.0, 0.2, 0.3, 0.0, 0.0),
        Vector6::new(0.0, 0.1, 0.0, 0.0, 0.2, 0.0),
    ]);
    let g = Power::new([
        Se3::identity(),
        Se3::from_parts(So3::identity(), Vector3::new(2.0, 0.3, 0.0)),
    ]);
    assert_steps_allocate_nothing(Splitting::new(pair, mu, Some(g)).unwrap(), 0.01);
}

/// The counter does see allocations: building a method name allocates a `String`.
#[test]
fn the_allocation_counter_counts() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let lp =
        LiePoisson::<So3, Cayley, _>::new(body, 0.5, Vector3::new(0.5, 1.0, 0.2), None).unwrap();
    assert!(allocations(|| drop(std::hint::black_box(lp.method_name()))) > 0);
}
