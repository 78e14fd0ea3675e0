//! Convergence orders of every method (Lie–Poisson and Euler–Poincaré, τ ∈ {exp, Cayley},
//! θ ∈ {0, ½, 1}) on the free rigid body, fitted by least squares from four step sizes, against
//! (a) the closed-form axisymmetric solution and (b) classical RK4 at a tiny step. The fitted order
//! must be the one each method declares in its `MethodInfo`.

use crate::common::*;
use integrators::{EulerPoincare, Integrator, IntegratorError, LiePoisson};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};

#[derive(Clone, Copy, Debug)]
enum Method {
    Lp,
    Ep,
}

fn run_method<T: Tau<So3>>(
    method: Method,
    body: &RigidBody,
    theta: f64,
    pi0: Vector3<f64>,
    t: f64,
    n: usize,
) -> Result<(Matrix3<f64>, Vector3<f64>), IntegratorError> {
    let g0 = So3::from_matrix(&r0()).expect("a rotation");
    let h = t / n as f64;
    match method {
        Method::Lp => run(
            LiePoisson::<So3, T, _>::new(body.clone(), theta, pi0, Some(g0))?,
            h,
            n,
        ),
        Method::Ep => run(
            EulerPoincare::<So3, T, _>::from_momentum(body.clone(), theta, pi0, Some(g0))?,
            h,
            n,
        ),
    }
}

const STEPS: [usize; 4] = [20, 40, 80, 160];

/// Fits the order of `method` with τ = T, θ, against a reference (R, Π) at time t.
fn order<T: Tau<So3>>(
    method: Method,
    body: &RigidBody,
    theta: f64,
    pi0: Vector3<f64>,
    t: f64,
    reference: &(Matrix3<f64>, Vector3<f64>),
) -> (f64, f64) {
    let mut hs = vec![];
    let mut errs = vec![];
    for n in STEPS {
        let (r, p) = run_method::<T>(method, body, theta, pi0, t, n).unwrap();
        let err = (r - reference.0)
            .amax()
            .max((p - reference.1).amax() / pi0.norm());
        hs.push(t / n as f64);
        errs.push(err);
    }
    (fitted_order(&hs, &errs), errs[errs.len() - 1])
}

/// The order the method declares in its [`integrators::MethodInfo`], which the fit must confirm.
fn declared<T: Tau<So3>>(method: Method, body: &RigidBody, theta: f64, pi0: Vector3<f64>) -> f64 {
    let info = match method {
        Method::Lp => LiePoisson::<So3, T, _>::new(body.clone(), theta, pi0, None)
            .unwrap()
            .info(),
        Method::Ep => EulerPoincare::<So3, T, _>::from_momentum(body.clone(), theta, pi0, None)
            .unwrap()
            .info(),
    };
    f64::from(info.order)
}

/// Orders of all 12 combinations against a reference; the fit must be within 0.1 of the
/// expected integer order (four step sizes in the asymptotic regime give slopes within ~0.05).
fn check_all(
    body: &RigidBody,
    pi0: Vector3<f64>,
    t: f64,
    reference: (Matrix3<f64>, Vector3<f64>),
    label: &str,
) {
    let mut failures = vec![];
    for method in [Method::Lp, Method::Ep] {
        for theta in [0.0, 0.5, 1.0] {
            for (tau, (p, e), want) in [
                (
                    "exp",
                    order::<ExpMap>(method, body, theta, pi0, t, &reference),
                    declared::<ExpMap>(method, body, theta, pi0),
                ),
                (
                    "cayley",
                    order::<Cayley>(method, body, theta, pi0, t, &reference),
                    declared::<Cayley>(method, body, theta, pi0),
                ),
            ] {
                println!("{label}: {method:?} tau={tau} theta={theta}: order {p:.3} (finest error {e:.2e})");
                if (p - want).abs() > 0.1 {
                    failures.push(format!("{method:?} {tau} θ={theta}: {p:.3}"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "orders off: {failures:?}");
}

#[test]
fn orders_match_axisymmetric_closed_form() {
    let (i, i3) = (1.0, 2.5);
    let body = RigidBody::principal([i, i, i3]).unwrap();
    let pi0 = Vector3::new(0.6, -0.4, 1.3);
    let t = 2.0;
    let reference = axisymmetric_exact(i, i3, &r0(), &pi0, t);
    check_all(&body, pi0, t, reference, "axisymmetric");
}

#[test]
fn orders_match_rk4_reference_for_asymmetric_body() {
    let inertia = Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 3.0);
    let body = RigidBody::new(inertia).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, -0.7);
    let t = 2.0;
    // RK4 with h = 2e-4: error ~ (h ω)⁴ ~ 1e-15, far below the finest integrator error (> 1e-6).
    let reference = rk4_reference(&inertia, &r0(), &pi0, t, 10_000);
    check_all(&body, pi0, t, reference, "asymmetric");
}

#[test]
fn rk4_reference_matches_axisymmetric_closed_form() {
    let (i, i3) = (1.0, 2.5);
    let pi0 = Vector3::new(0.6, -0.4, 1.3);
    let (r, p) = rk4_reference(
        &Matrix3::from_diagonal(&Vector3::new(i, i, i3)),
        &r0(),
        &pi0,
        2.0,
        10_000,
    );
    let (re, pe) = axisymmetric_exact(i, i3, &r0(), &pi0, 2.0);
    assert!(
        (r - re).amax() < 1e-12 && (p - pe).amax() < 1e-12,
        "{} {}",
        (r - re).amax(),
        (p - pe).amax()
    );
}
