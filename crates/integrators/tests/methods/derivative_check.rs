//! `derivative_check`: the built-in systems pass it, deliberately wrong derivatives are flagged in
//! the field that is wrong (and only there), and the provided finite-difference Hessian serves an
//! integrator like the closed form.

use integrators::derivative_check::{
    check_derivatives, finite_difference_hessian, DEFAULT_TOLERANCE,
};
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, LieGroup, Operator, Se2, Se3, So3, SoN};
use mechanics::systems::{GeneralizedRigidBody, HeavyTop, PlanarBody, RigidBody, RigidBodySe3};
use nalgebra::{Matrix3, Vector2, Vector3, Vector6};

fn so3_samples() -> Vec<(Vector3<f64>, Option<So3>)> {
    vec![
        (
            Vector3::new(0.5, 1.0, 0.2),
            Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8))),
        ),
        (
            Vector3::new(-30.0, 4.0, 12.0),
            Some(So3::exp(&Vector3::new(2.0, 1.0, -0.4))),
        ),
        (Vector3::new(1e-3, -2e-3, 5e-4), Some(So3::identity())),
    ]
}

fn top() -> HeavyTop {
    HeavyTop::principal([1.0, 2.0, 3.0], 1.5, 9.81, Vector3::new(0.1, 0.2, 0.5)).unwrap()
}

/// Every built-in system: all mismatches below 1e-7 (measured ≤ 1e-10, printed).
#[test]
fn the_built_in_systems_pass() {
    let reports = [
        (
            "rigid body",
            check_derivatives(
                &RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
                &so3_samples(),
            ),
        ),
        ("heavy top", check_derivatives(&top(), &so3_samples())),
        (
            "satellite on SE(3)",
            check_derivatives(
                &RigidBodySe3::satellite(
                    2.0,
                    Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
                    5.0,
                )
                .unwrap(),
                &[
                    (
                        Vector6::new(0.5, 1.0, 0.2, 0.3, -0.1, 0.4),
                        Some(Se3::exp(&Vector6::new(0.3, -0.5, 0.8, 2.0, 1.0, -1.5))),
                    ),
                    (
                        Vector6::new(-3.0, 0.1, 2.0, 1.0, 1.0, 0.0),
                        Some(Se3::exp(&Vector6::new(1.0, 0.5, 0.2, -3.0, 0.5, 2.0))),
                    ),
                ],
            ),
        ),
        (
            "planar body with spring and gravity",
            check_derivatives(
                &PlanarBody::free(1.5, 0.2)
                    .unwrap()
                    .with_spring(3.0, Vector2::new(0.1, -0.2))
                    .unwrap()
                    .with_gravity(Vector2::new(0.0, -9.81))
                    .unwrap(),
                &[(
                    Vector3::new(0.3, -1.0, 2.0),
                    Some(Se2::exp(&Vector3::new(0.7, 1.0, -0.5))),
                )],
            ),
        ),
        (
            "SO(4) geodesic",
            check_derivatives(
                &GeneralizedRigidBody::<4>::new(&[1.0, 1.5, 2.0, 3.0]).unwrap(),
                &[(
                    <SoN<4> as LieGroup>::Algebra::from_fn(6, |i| 0.3 * i as f64 - 0.7),
                    None,
                )],
            ),
        ),
    ];
    for (name, r) in reports {
        println!("{name}: {r}");
        assert!(r.passes(1e-7), "{name}: {r}");
    }
    assert!(check_derivatives(&top(), &so3_samples())
        .potential_differential
        .is_some());
    assert!(check_derivatives(
        &RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
        &so3_samples()
    )
    .potential_differential
    .is_none());
}

/// The heavy top with one of its derivatives broken on purpose.
#[derive(Clone, Copy)]
enum Broken {
    Velocity,
    Hessian,
    Legendre,
    PotentialDifferential,
}

struct Wrong(HeavyTop, Broken);

impl System<So3> for Wrong {
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.0.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        let v = self.0.velocity(mu);
        match self.1 {
            Broken::Velocity => v * 1.01,
            _ => v,
        }
    }
    fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
        let h = self.0.hessian(mu);
        match self.1 {
            // a transposition error: the (0, 1) entry misplaced
            Broken::Hessian => h + Matrix3::new(0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
            _ => h,
        }
    }
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        let m = self.0.momentum(xi);
        match self.1 {
            Broken::Legendre => Vector3::new(m.x, m.z, m.y),
            _ => m,
        }
    }
    fn has_potential(&self) -> bool {
        true
    }
    fn potential(&self, g: &So3) -> f64 {
        self.0.potential(g)
    }
    fn potential_differential(&self, g: &So3) -> Vector3<f64> {
        let d = self.0.potential_differential(g);
        match self.1 {
            // the right-trivialized differential instead of the left one
            Broken::PotentialDifferential => g.as_matrix() * d,
            _ => d,
        }
    }
}

#[test]
fn a_wrong_derivative_is_flagged_where_it_is_wrong() {
    for broken in [
        Broken::Velocity,
        Broken::Hessian,
        Broken::Legendre,
        Broken::PotentialDifferential,
    ] {
        let r = check_derivatives(&Wrong(top(), broken), &so3_samples());
        println!("{r}");
        assert!(!r.passes(DEFAULT_TOLERANCE), "{r}");
        let flagged = [
            r.velocity,
            r.hessian,
            r.legendre,
            r.potential_differential.unwrap(),
        ];
        let expected = broken as usize;
        for (i, m) in flagged.iter().enumerate() {
            if i == expected {
                assert!(*m > 1e-3, "field {i} not flagged: {r}");
            } else if !(expected == 0 && i != 0) {
                // a wrong velocity also shows in the Hessian and Legendre checks (they use it)
                assert!(*m < 1e-7, "field {i} flagged for field {expected}: {r}");
            }
        }
    }
    // NaN is a failure, not a pass
    struct NanHessian;
    impl System<So3> for NanHessian {
        fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
            0.5 * mu.norm_squared()
        }
        fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
            *mu
        }
        fn hessian(&self, _: &Vector3<f64>) -> Matrix3<f64> {
            Matrix3::from_element(f64::NAN)
        }
        fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
            *xi
        }
    }
    assert!(!check_derivatives(&NanHessian, &so3_samples()).passes(1.0));
}

/// A system that gives no Hessian: the provided central differences of ∂h/∂μ.
struct NoHessian(HeavyTop);

impl System<So3> for NoHessian {
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.0.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.0.velocity(mu)
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
        self.0.potential_differential(g)
    }
}

/// The finite-difference Hessian is the closed form to 1e-9 relative, and a Lie–Poisson run with
/// it solves the same steps: after 500 steps of h = 0.01 the two runs agree to 1e-12 (the step
/// equations are solved to 1e-14 either way; only the Newton matrix differs).
#[test]
fn the_finite_difference_hessian_serves_like_the_closed_form() {
    for (mu, _) in so3_samples() {
        let fd = finite_difference_hessian::<So3, _>(&top(), &mu);
        let exact = top().hessian(&mu);
        assert!(
            (fd - exact).norm_max() < 1e-9 * exact.norm_max(),
            "{fd} vs {exact}"
        );
    }
    let g0 = Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)));
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let mut a = LiePoisson::<So3, Cayley, _>::new(top(), 0.5, pi0, g0).unwrap();
    let mut b = LiePoisson::<So3, Cayley, _>::new(NoHessian(top()), 0.5, pi0, g0).unwrap();
    for _ in 0..500 {
        a.step(0.01).unwrap();
        b.step(0.01).unwrap();
    }
    let d = (a.momentum() - b.momentum()).amax();
    assert!(d < 1e-12, "{d:e}");
    assert!(check_derivatives(&NoHessian(top()), &so3_samples()).passes(1e-7));
}
