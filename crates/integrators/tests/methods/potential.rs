//! The potential force term of both integrators, checked on a heavy top (a test fixture with
//! V(R) = mg χ·Rᵀe₃) against classical RK4: orders fitted from four step sizes, and the missing-g
//! refusal.

use crate::common::*;
use integrators::{EulerPoincare, IntegratorError, LiePoisson};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use nalgebra::{Matrix3, Vector3};

fn top() -> (TestHeavyTop, Matrix3<f64>) {
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.5, 2.5));
    let body = mechanics::systems::RigidBody::new(inertia).unwrap();
    (
        TestHeavyTop {
            body,
            mgchi: Vector3::new(0.3, -0.2, 1.0),
        },
        inertia,
    )
}

fn fit<T: Tau<So3>>(lie_poisson: bool, theta: f64) -> f64 {
    let (sys, inertia) = top();
    let pi0 = Vector3::new(0.4, 0.8, 1.1);
    let t = 1.5;
    let (rr, pr) = rk4_heavy_top(&inertia, &sys.mgchi, &r0(), &pi0, t, 10_000);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let mut hs = vec![];
    let mut errs = vec![];
    for n in [20usize, 40, 80, 160] {
        let h = t / n as f64;
        let (r, p) = if lie_poisson {
            run(
                LiePoisson::<So3, T, _>::new(sys.clone(), theta, pi0, Some(g0)).unwrap(),
                h,
                n,
            )
        } else {
            run(
                EulerPoincare::<So3, T, _>::from_momentum(sys.clone(), theta, pi0, Some(g0))
                    .unwrap(),
                h,
                n,
            )
        }
        .unwrap();
        hs.push(h);
        errs.push((r - rr).amax().max((p - pr).amax()));
    }
    fitted_order(&hs, &errs)
}

#[test]
fn potential_force_orders_match_rk4_heavy_top() {
    let mut failures = vec![];
    for lp in [true, false] {
        for theta in [0.0, 0.5, 1.0] {
            let expected = if theta == 0.5 { 2.0 } else { 1.0 };
            for (tau, p) in [
                ("exp", fit::<ExpMap>(lp, theta)),
                ("cayley", fit::<Cayley>(lp, theta)),
            ] {
                let name = if lp { "lie-poisson" } else { "euler-poincare" };
                println!("heavy top: {name} tau={tau} theta={theta}: order {p:.3}");
                // Tolerance 0.1: see tests/order.rs.
                if (p - expected).abs() > 0.1 {
                    failures.push(format!("{name} {tau} θ={theta}: {p:.3}"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "orders off: {failures:?}");
}

#[test]
fn system_with_potential_refuses_missing_configuration() {
    let (sys, _) = top();
    let e = LiePoisson::<So3, Cayley, _>::new(sys.clone(), 0.5, Vector3::x(), None).unwrap_err();
    assert_eq!(e, IntegratorError::MissingConfiguration);
    let e = EulerPoincare::<So3, Cayley, _>::new(sys, 0.5, Vector3::x(), None).unwrap_err();
    assert_eq!(e, IntegratorError::MissingConfiguration);
}
