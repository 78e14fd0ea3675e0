//! Invariants of the free rigid body: Casimir |Π| to round-off (Lie–Poisson), bounded energy error
//! without drift, time reversibility of the symmetric (θ = ½) methods, and the sign convention of
//! the rigid body's Lie–Poisson vector field.

use crate::common::*;
use integrators::{integrate, EulerPoincare, Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}
const PI0: Vector3<f64> = Vector3::new(0.8, 0.5, 0.6);

#[test]
fn rigid_body_vector_field_is_euler_equations() {
    // μ̇ = ad*_{∂h/∂μ} μ must equal Π × Ω with the crate's ad* convention.
    let b = RigidBody::new(Matrix3::new(2.0, 0.3, 0.0, 0.3, 1.0, 0.1, 0.0, 0.1, 3.0)).unwrap();
    let lp = So3::ad_dual_apply(&b.velocity(&PI0), &PI0);
    assert!((lp - b.euler_rhs(&PI0)).amax() < 1e-15);
}

fn casimir_drift<T: Tau<So3>>(theta: f64, steps: usize) -> f64 {
    let mut lp = LiePoisson::<So3, T, _>::new(body(), theta, PI0, None).unwrap();
    let c0 = PI0.norm();
    let mut worst = 0.0f64;
    integrate(&mut lp, 0.05, steps, |i| {
        worst = worst.max((i.momentum().norm() - c0).abs() / c0);
    })
    .unwrap();
    worst
}

#[test]
fn lie_poisson_casimir_conserved_to_round_off_over_1e4_steps() {
    // Each step applies one or two orthogonal matrices to Π; |Π| changes by a few ulps per step,
    // a random walk of ~√N·1e-16 ≈ 1e-14 after 10⁴ steps. Bound: 1e-13 relative.
    // Two of the six methods (the full set runs in the ignored 10⁵-step test).
    let e = casimir_drift::<ExpMap>(0.0, 10_000);
    let c = casimir_drift::<Cayley>(0.5, 10_000);
    assert!(e < 1e-13 && c < 1e-13, "exp θ=0 {e:e}, cayley θ=½ {c:e}");
}

#[test]
fn lie_poisson_casimir_conserved_to_round_off_over_1e5_steps() {
    for theta in [0.0, 0.5, 1.0] {
        let e = casimir_drift::<ExpMap>(theta, 100_000);
        let c = casimir_drift::<Cayley>(theta, 100_000);
        println!("|Π| relative drift over 1e5 steps θ={theta}: exp {e:.2e}, cayley {c:.2e}");
        assert!(e < 1e-13 && c < 1e-13, "θ={theta}: exp {e:e}, cayley {c:e}");
    }
}

/// Max |E − E₀| over the first and the last tenth of `steps` steps.
fn energy_errors<I: Integrator>(mut integ: I, h: f64, steps: usize) -> (f64, f64) {
    let e0 = integ.energy();
    let (mut first, mut last) = (0.0f64, 0.0f64);
    for k in 0..steps {
        integ.step(h).unwrap();
        let e = (integ.energy() - e0).abs();
        if k < steps / 10 {
            first = first.max(e);
        } else if k >= steps - steps / 10 {
            last = last.max(e);
        }
    }
    (first, last)
}

fn check_no_drift(steps: usize) {
    let h = 0.05;
    for theta in [0.0, 0.5, 1.0] {
        let (f, l) = energy_errors(
            LiePoisson::<So3, Cayley, _>::new(body(), theta, PI0, None).unwrap(),
            h,
            steps,
        );
        println!(
            "{steps} steps, LP cayley θ={theta}: energy error first tenth {f:.2e}, last {l:.2e}"
        );
        // No drift: the error over the last tenth stays within 2× (+ round-off) of the first tenth,
        // which already covers several periods (T ≈ 5 time units ≈ 100 steps).
        assert!(
            l <= 2.0 * f + 1e-14,
            "LP cayley θ={theta}: first {f:e}, last {l:e}"
        );
        let (f, l) = energy_errors(
            LiePoisson::<So3, ExpMap, _>::new(body(), theta, PI0, None).unwrap(),
            h,
            steps,
        );
        println!("{steps} steps, LP exp θ={theta}: energy error first tenth {f:.2e}, last {l:.2e}");
        assert!(
            l <= 2.0 * f + 1e-14,
            "LP exp θ={theta}: first {f:e}, last {l:e}"
        );
    }
    let (f, l) = energy_errors(
        EulerPoincare::<So3, Cayley, _>::from_momentum(body(), 0.5, PI0, None).unwrap(),
        h,
        steps,
    );
    println!("{steps} steps, EP cayley θ=0.5: energy error first tenth {f:.2e}, last {l:.2e}");
    assert!(
        l <= 2.0 * f + 1e-14,
        "EP cayley θ=½: first {f:e}, last {l:e}"
    );
}

#[test]
fn energy_error_bounded_without_drift_over_2000_steps() {
    check_no_drift(2_000);
}

#[test]
fn energy_error_bounded_without_drift_over_1e6_steps() {
    check_no_drift(1_000_000);
}

fn reversibility<I: Integrator<Group = So3>>(mut integ: I, n: usize, h: f64) -> (f64, f64) {
    let mu0 = integ.momentum();
    let g0 = *integ.configuration().unwrap();
    for _ in 0..n {
        integ.step(h).unwrap();
    }
    for _ in 0..n {
        integ.step(-h).unwrap();
    }
    (
        (integ.momentum() - mu0).amax(),
        integ.configuration().unwrap().matrix_distance(&g0),
    )
}

#[test]
fn symmetric_methods_are_time_reversible() {
    // θ = ½: N steps forward then N with −h return to the start up to solver tolerance and
    // round-off (1e-14 relative per step, 200 steps → ≤ 1e-11).
    let g0 = So3::from_matrix(&r0()).unwrap();
    let n = 100;
    let h = 0.1;
    let checks = [
        (
            "LP exp",
            reversibility(
                LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, PI0, Some(g0)).unwrap(),
                n,
                h,
            ),
        ),
        (
            "LP cay",
            reversibility(
                LiePoisson::<So3, Cayley, _>::new(body(), 0.5, PI0, Some(g0)).unwrap(),
                n,
                h,
            ),
        ),
        (
            "EP exp",
            reversibility(
                EulerPoincare::<So3, ExpMap, _>::from_momentum(body(), 0.5, PI0, Some(g0)).unwrap(),
                n,
                h,
            ),
        ),
        (
            "EP cay",
            reversibility(
                EulerPoincare::<So3, Cayley, _>::from_momentum(body(), 0.5, PI0, Some(g0)).unwrap(),
                n,
                h,
            ),
        ),
    ];
    for (name, (dm, dg)) in checks {
        assert!(dm < 1e-11 && dg < 1e-11, "{name}: Δμ {dm:e}, Δg {dg:e}");
    }
}

#[test]
fn non_symmetric_euler_poincare_is_not_reversible() {
    // The reversibility test can fail: θ = 0 (explicit) does not return to the start.
    let g0 = So3::from_matrix(&r0()).unwrap();
    let (dm, _) = reversibility(
        EulerPoincare::<So3, Cayley, _>::from_momentum(body(), 0.0, PI0, Some(g0)).unwrap(),
        100,
        0.1,
    );
    assert!(dm > 1e-4, "Δμ {dm:e}");
}

#[test]
fn reconstruction_is_optional_and_does_not_change_momentum() {
    let g0 = So3::from_matrix(&r0()).unwrap();
    let mut with = LiePoisson::<So3, Cayley, _>::new(body(), 0.5, PI0, Some(g0)).unwrap();
    let mut without = LiePoisson::<So3, Cayley, _>::new(body(), 0.5, PI0, None).unwrap();
    integrate(&mut with, 0.1, 50, |_| {}).unwrap();
    integrate(&mut without, 0.1, 50, |_| {}).unwrap();
    assert!(without.configuration().is_none());
    assert_eq!(with.momentum(), without.momentum());
}

#[test]
fn solver_kinds_agree() {
    use integrators::{SolverConfig, SolverKind};
    let mut out = vec![];
    for kind in [
        SolverKind::Newton,
        SolverKind::NewtonFiniteDifference,
        SolverKind::FixedPoint,
    ] {
        let cfg = SolverConfig {
            kind,
            ..SolverConfig::default()
        };
        let mut lp = LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, PI0, None)
            .unwrap()
            .with_solver(cfg);
        let mut ep = EulerPoincare::<So3, ExpMap, _>::from_momentum(body(), 1.0, PI0, None)
            .unwrap()
            .with_solver(cfg);
        integrate(&mut lp, 0.1, 20, |_| {}).unwrap();
        integrate(&mut ep, 0.1, 20, |_| {}).unwrap();
        out.push((kind, lp.momentum(), ep.momentum(), lp.last_iterations()));
    }
    for (kind, lp, ep, it) in &out[1..] {
        // All three solve the same equations to 1e-14 relative: results agree to 1e-12.
        assert!(
            (lp - out[0].1).amax() < 1e-12 && (ep - out[0].2).amax() < 1e-12,
            "{kind:?}"
        );
        println!("{kind:?}: {it} iterations (Newton: {})", out[0].3);
    }
}

/// The reconstructed attitude stays on SO(3) to round-off over 10⁷ steps (free body, h = 0.01,
/// Lie–Poisson Cayley θ = ½): ‖RᵀR − I‖_max ≤ 1e-14 (renormalized every `RENORMALIZE_AFTER` =
/// 1024 steps, the defect in between is a random walk of at most 1024 roundings; measured
/// 1.4e-15). Without renormalization the random walk reaches ~1e-12 (docs/long-runs.md).
#[test]
fn attitude_stays_orthogonal_to_round_off_over_1e7_steps() {
    let mut lp = LiePoisson::<So3, Cayley, _>::new(
        body(),
        0.5,
        Vector3::new(0.6, 1.0, 0.8),
        Some(So3::identity()),
    )
    .unwrap()
    .with_solver(integrators::SolverConfig {
        kind: integrators::SolverKind::FixedPoint,
        ..Default::default()
    });
    for _ in 0..10_000_000 {
        lp.step(0.01).unwrap();
    }
    let r = lp.configuration().unwrap().as_matrix();
    let orth = (r.transpose() * r - Matrix3::identity()).amax();
    println!("‖RᵀR − I‖ after 10⁷ steps: {orth:.2e}");
    assert!(orth <= 1e-14, "‖RᵀR − I‖ = {orth:.2e} after 10⁷ steps");
}

/// On SO(3) the Newton Jacobian of the Lie–Poisson step is exact (closed forms of
/// ∂/∂ζ (d^{L*}τ_ζ μ) for exp and Cayley), so Newton converges quadratically even at h = 0.1: every
/// step takes at most as many iterations as Newton with a finite-difference Jacobian, and at most 3
/// (two quadratic steps from the O(h²) predictor reach 1e-14, the third confirms). An
/// O(h²)-accurate Jacobian would converge only linearly and take more.
#[test]
fn lie_poisson_so3_newton_jacobian_is_exact_for_exp_and_cayley() {
    use integrators::{SolverConfig, SolverKind};
    fn iterations<T: lie_groups::Tau<So3>>(theta: f64, kind: SolverKind) -> Vec<usize> {
        let cfg = SolverConfig {
            kind,
            ..SolverConfig::default()
        };
        let mut lp = LiePoisson::<So3, T, _>::new(body(), theta, PI0, None)
            .unwrap()
            .with_solver(cfg);
        (0..50)
            .map(|_| {
                lp.step(0.1).unwrap();
                lp.last_iterations()
            })
            .collect()
    }
    for theta in [0.0, 0.5] {
        for (name, newton, fd) in [
            (
                "exp",
                iterations::<ExpMap>(theta, SolverKind::Newton),
                iterations::<ExpMap>(theta, SolverKind::NewtonFiniteDifference),
            ),
            (
                "cayley",
                iterations::<Cayley>(theta, SolverKind::Newton),
                iterations::<Cayley>(theta, SolverKind::NewtonFiniteDifference),
            ),
        ] {
            for (k, (n, f)) in newton.iter().zip(&fd).enumerate() {
                assert!(
                    n <= f && *n <= 3,
                    "{name}, θ = {theta}, step {k}: Newton {n} iterations, FD Newton {f}"
                );
            }
        }
    }
}
