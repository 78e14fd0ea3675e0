//! External forces (discrete Lagrange–d'Alembert, `integrators::forces`): a force derived from a
//! potential reproduces the potential's path; a spatially fixed torque changes the spatial
//! momentum by exactly the applied impulse; damping decays energy and Casimir at the exact rate
//! to the method's order; forced runs converge with the designed orders against an independent
//! fine RK4 written here; θ = ½ is reversible for a force of g alone; bad input is refused.

use crate::common::{fitted_order, r0};
use integrators::forces::{BodyTorque, ExternalForce, Forced, LinearDamping, Schedule};
use integrators::{
    EulerPoincare, Integrator, IntegratorError, LiePoisson, QuaternionRk4, Rkmk4, System,
};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{Matrix3, Vector3};

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

fn g0() -> So3 {
    So3::from_matrix(&r0()).unwrap()
}

const PI0: Vector3<f64> = Vector3::new(0.4, 1.0, 0.3);

/// A torque schedule used by the convergence tests: ramps and holds on each axis.
fn schedule() -> BodyTorque<So3> {
    BodyTorque::new(
        Schedule::new(
            vec![0.0, 0.7, 1.5],
            vec![
                vec![0.0, 0.2, -0.1],
                vec![0.5, -0.3, 0.2],
                vec![0.1, 0.1, 0.4],
            ],
        )
        .unwrap(),
    )
    .unwrap()
}

/// The force of a potential, F = −T*_e L_g dV, given as an external force: the Lie–Poisson and
/// Euler–Poincaré paths are those of the potential to round-off (same evaluation points).
#[test]
fn a_force_derived_from_a_potential_gives_the_potential_path() {
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    let top_for_force = top.clone();
    let gravity = move |_t: f64, g: Option<&So3>, _xi: &Vector3<f64>| {
        -top_for_force.potential_differential(g.unwrap())
    };
    let forced = Forced::new(body(), gravity);
    for theta in [0.0, 0.3, 0.5, 1.0] {
        let mut a = LiePoisson::<So3, Cayley, _>::new(top.clone(), theta, PI0, Some(g0())).unwrap();
        let mut b =
            LiePoisson::<So3, Cayley, _>::new(forced.clone(), theta, PI0, Some(g0())).unwrap();
        let xi0 = body().velocity(&PI0);
        let mut c =
            EulerPoincare::<So3, ExpMap, _>::new(top.clone(), theta, xi0, Some(g0())).unwrap();
        let mut d =
            EulerPoincare::<So3, ExpMap, _>::new(forced.clone(), theta, xi0, Some(g0())).unwrap();
        for _ in 0..200 {
            a.step(0.01).unwrap();
            b.step(0.01).unwrap();
            c.step(0.01).unwrap();
            d.step(0.01).unwrap();
        }
        let lp = (a.momentum() - b.momentum()).amax().max(
            a.configuration()
                .unwrap()
                .matrix_distance(b.configuration().unwrap()),
        );
        let ep = (c.velocity() - d.velocity()).amax().max(
            c.configuration()
                .unwrap()
                .matrix_distance(d.configuration().unwrap()),
        );
        assert!(
            lp < 1e-13 && ep < 1e-13,
            "θ = {theta}: LP {lp:e}, EP {ep:e}"
        );
    }
}

/// A torque fixed in space, F(g) = Rᵀτ_s: Lie–Poisson changes the spatial momentum RΠ by exactly
/// h τ_s per step (m_{k+1} = m_k + h Ad*_{ḡ⁻¹} F), so after N steps by N h τ_s, for every θ and
/// τ, to round-off.
#[test]
fn a_spatial_torque_changes_the_momentum_map_by_the_applied_impulse() {
    let tau_s = Vector3::new(0.3, -0.2, 0.5);
    let torque = move |_t: f64, g: Option<&So3>, _xi: &Vector3<f64>| {
        g.unwrap().as_matrix().transpose() * tau_s
    };
    fn run<T: Tau<So3>>(
        f: impl ExternalForce<So3> + Clone,
        theta: f64,
        tau_s: Vector3<f64>,
    ) -> f64 {
        let mut lp =
            LiePoisson::<So3, T, _>::new(Forced::new(body(), f), theta, PI0, Some(g0())).unwrap();
        let m0 = g0().as_matrix() * PI0;
        let (h, n) = (0.01, 2000);
        for _ in 0..n {
            lp.step(h).unwrap();
        }
        let m = lp.configuration().unwrap().as_matrix() * lp.momentum();
        (m - m0 - tau_s * (h * n as f64)).amax()
    }
    for theta in [0.0, 0.5, 1.0] {
        let e = run::<ExpMap>(torque, theta, tau_s).max(run::<Cayley>(torque, theta, tau_s));
        assert!(e < 2e-13, "θ = {theta}: momentum-map balance off by {e:e}");
    }
}

/// Damping F = −c𝕀ξ = −cμ on the free body: E(t) = E₀e^{−2ct} and |μ|² = |μ₀|²e^{−2ct} exactly;
/// the integrators reach them with their orders (2 for θ = ½, 4 for RK4 and RKMK4).
#[test]
fn damping_decays_energy_at_the_exact_rate_to_the_methods_order() {
    let c = 0.4;
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0));
    let system = Forced::new(body(), LinearDamping::<So3>::new(inertia * c).unwrap());
    let t_end = 2.0;
    let e0 = body().hamiltonian(&PI0);
    let decay = (-2.0 * c * t_end).exp();
    let errors = |make: &dyn Fn() -> Box<dyn Integrator<Group = So3>>| {
        let hs = [0.1, 0.05, 0.025];
        let errs: Vec<f64> = hs
            .iter()
            .map(|&h| {
                let mut integ = make();
                for _ in 0..(t_end / h).round() as usize {
                    integ.step(h).unwrap();
                }
                let de = (integ.energy() / (e0 * decay) - 1.0).abs();
                let dc =
                    (integ.momentum().norm_squared() / (PI0.norm_squared() * decay) - 1.0).abs();
                de.max(dc)
            })
            .collect();
        (fitted_order(&hs, &errs), errs[2])
    };
    let s = system.clone();
    let lp = errors(&|| {
        Box::new(LiePoisson::<So3, ExpMap, _>::new(s.clone(), 0.5, PI0, Some(g0())).unwrap())
    });
    let ep = errors(&|| {
        Box::new(
            EulerPoincare::<So3, Cayley, _>::from_momentum(s.clone(), 0.5, PI0, Some(g0()))
                .unwrap(),
        )
    });
    let rk = errors(&|| Box::new(QuaternionRk4::new(s.clone(), PI0, Some(g0())).unwrap()));
    let mk = errors(&|| Box::new(Rkmk4::<So3, _>::new(s.clone(), PI0, Some(g0())).unwrap()));
    println!(
        "decay errors (order, error at h = 0.025): LP {lp:?}, EP {ep:?}, RK4 {rk:?}, RKMK4 {mk:?}"
    );
    assert!(
        (1.8..2.3).contains(&lp.0) && (1.8..2.3).contains(&ep.0),
        "{lp:?} {ep:?}"
    );
    assert!(
        (3.7..4.5).contains(&rk.0) && (3.7..4.5).contains(&mk.0),
        "{rk:?} {mk:?}"
    );
}

/// An independent fine RK4 on (R, Π) with the scheduled torque.
fn reference(t_end: f64) -> (Matrix3<f64>, Vector3<f64>) {
    let torque = schedule();
    let iinv = Matrix3::from_diagonal(&Vector3::new(1.0, 0.5, 1.0 / 3.0));
    let f = |t: f64, r: &Matrix3<f64>, p: &Vector3<f64>| {
        let om = iinv * p;
        (
            r * om.cross_matrix(),
            p.cross(&om) + torque.force(t, None, &om),
        )
    };
    let n = 20_000;
    let h = t_end / n as f64;
    let (mut r, mut p) = (r0(), PI0);
    for k in 0..n {
        let t = k as f64 * h;
        let (a1, b1) = f(t, &r, &p);
        let (a2, b2) = f(t + h / 2.0, &(r + a1 * (h / 2.0)), &(p + b1 * (h / 2.0)));
        let (a3, b3) = f(t + h / 2.0, &(r + a2 * (h / 2.0)), &(p + b2 * (h / 2.0)));
        let (a4, b4) = f(t + h, &(r + a3 * h), &(p + b3 * h));
        r += (a1 + (a2 + a3) * 2.0 + a4) * (h / 6.0);
        p += (b1 + (b2 + b3) * 2.0 + b4) * (h / 6.0);
    }
    (r, p)
}

/// Forced runs converge to the independent reference with the designed orders: Lie–Poisson and
/// Euler–Poincaré θ = ½ order 2, θ = 0.3 order 1, RK4 and RKMK4 order 4.
#[test]
fn forced_runs_converge_with_the_designed_orders() {
    let t_end = 2.0;
    let (rr, pr) = reference(t_end);
    let system = Forced::new(body(), schedule());
    let order = |make: &dyn Fn() -> Box<dyn Integrator<Group = So3>>, hs: &[f64]| {
        let errs: Vec<f64> = hs
            .iter()
            .map(|&h| {
                let mut integ = make();
                for _ in 0..(t_end / h).round() as usize {
                    integ.step(h).unwrap();
                }
                (integ.momentum() - pr)
                    .amax()
                    .max((integ.configuration().unwrap().as_matrix() - rr).amax())
            })
            .collect();
        fitted_order(hs, &errs)
    };
    let s = system.clone();
    let hs = [0.05, 0.025, 0.0125];
    let xi0 = body().velocity(&PI0);
    let lp = |theta: f64| {
        let s = s.clone();
        move || -> Box<dyn Integrator<Group = So3>> {
            Box::new(LiePoisson::<So3, ExpMap, _>::new(s.clone(), theta, PI0, Some(g0())).unwrap())
        }
    };
    let ep = |theta: f64| {
        let s = s.clone();
        move || -> Box<dyn Integrator<Group = So3>> {
            Box::new(
                EulerPoincare::<So3, Cayley, _>::new(s.clone(), theta, xi0, Some(g0())).unwrap(),
            )
        }
    };
    let orders = [
        ("LP θ = ½", order(&lp(0.5), &hs), 2.0),
        ("LP θ = 0.3", order(&lp(0.3), &hs), 1.0),
        ("EP θ = ½", order(&ep(0.5), &hs), 2.0),
        ("EP θ = 0.3", order(&ep(0.3), &hs), 1.0),
        (
            "RK4",
            order(
                &|| Box::new(QuaternionRk4::new(s.clone(), PI0, Some(g0())).unwrap()),
                &[0.1, 0.05, 0.025],
            ),
            4.0,
        ),
        (
            "RKMK4",
            order(
                &|| Box::new(Rkmk4::<So3, _>::new(s.clone(), PI0, Some(g0())).unwrap()),
                &[0.1, 0.05, 0.025],
            ),
            4.0,
        ),
    ];
    println!("fitted orders: {orders:?}");
    for (name, got, want) in orders {
        assert!(
            (got - want).abs() < 0.35,
            "{name}: order {got:.3}, want {want}"
        );
    }
}

/// θ = ½ with a force of g alone is symmetric: h then −h returns to the start to round-off.
#[test]
fn midpoint_with_a_configuration_force_is_reversible() {
    let tau_s = Vector3::new(0.3, -0.2, 0.5);
    let torque = move |_t: f64, g: Option<&So3>, _xi: &Vector3<f64>| {
        g.unwrap().as_matrix().transpose() * tau_s
    };
    let mut lp =
        LiePoisson::<So3, Cayley, _>::new(Forced::new(body(), torque), 0.5, PI0, Some(g0()))
            .unwrap();
    assert!(lp.info().symmetric && !lp.info().momentum_map && !lp.info().casimirs);
    lp.step(0.1).unwrap();
    lp.step(-0.1).unwrap();
    let e = (lp.momentum() - PI0)
        .amax()
        .max(lp.configuration().unwrap().matrix_distance(&g0()));
    assert!(e < 1e-14, "{e:e}");
}

/// A force that reads g needs g; a failed step leaves the state as it was.
#[test]
fn a_force_that_reads_g_requires_it_and_failures_leave_the_state() {
    #[derive(Clone)]
    struct Gravity;
    impl ExternalForce<So3> for Gravity {
        fn force(&self, _t: f64, g: Option<&So3>, _xi: &Vector3<f64>) -> Vector3<f64> {
            g.map_or(Vector3::zeros(), |g| {
                g.as_matrix().transpose() * Vector3::z()
            })
        }
        fn needs_configuration(&self) -> bool {
            true
        }
    }
    let forced = Forced::new(body(), Gravity);
    assert!(matches!(
        LiePoisson::<So3, Cayley, _>::new(forced.clone(), 0.5, PI0, None),
        Err(IntegratorError::MissingConfiguration)
    ));
    assert!(matches!(
        QuaternionRk4::new(forced.clone(), PI0, None),
        Err(IntegratorError::MissingConfiguration)
    ));
    // a body torque does not need g
    let torque = BodyTorque::<So3>::constant(Vector3::new(0.0, 0.0, 1.0)).unwrap();
    let mut lp =
        LiePoisson::<So3, Cayley, _>::new(Forced::new(body(), torque), 0.5, PI0, None).unwrap();
    lp.step(0.1).unwrap();
    let before = lp.momentum();
    assert!(lp.step(f64::NAN).is_err());
    assert_eq!(lp.momentum(), before);
    // a torque of the wrong dimension, a non-symmetric or negative damping: refused
    assert!(BodyTorque::<So3>::new(Schedule::constant(vec![1.0, 2.0]).unwrap()).is_err());
    let mut d = Matrix3::identity();
    d[(0, 1)] = 0.5;
    assert!(LinearDamping::<So3>::new(d).is_err());
    assert!(LinearDamping::<So3>::new(-Matrix3::identity()).is_err());
    assert!(LinearDamping::<So3>::new(Matrix3::identity() * f64::NAN).is_err());
}

#[test]
fn optional_terms_sum_to_the_present_ones() {
    let xi = Vector3::new(0.3, -1.2, 0.7);
    let damping =
        LinearDamping::<So3>::new(Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0))).unwrap();
    let both = (Some(schedule()), Some(damping.clone()));
    let only_damping: (Option<BodyTorque<So3>>, _) = (None, Some(damping.clone()));
    for t in [0.0, 0.4, 1.7, 9.0] {
        let sum = schedule().force(t, None, &xi) + damping.force(t, None, &xi);
        assert!((both.force(t, None, &xi) - sum).norm() < 1e-15);
        assert!((only_damping.force(t, None, &xi) - damping.force(t, None, &xi)).norm() == 0.0);
    }
    let none: (Option<BodyTorque<So3>>, Option<LinearDamping<So3>>) = (None, None);
    assert_eq!(none.force(1.0, None, &xi), Vector3::zeros());
    assert!(!none.needs_configuration() && !both.needs_configuration());
    let reads_g =
        Some(|_: f64, g: Option<&So3>, _: &Vector3<f64>| g.unwrap().matrix().column(0).into());
    assert!(reads_g.needs_configuration());
}
