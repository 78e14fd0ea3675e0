//! Extremes and failures: fast spin near the edge of τ's domain, the separatrix of the
//! intermediate axis, inertia ratio 1e6, |Π| = 1e-8, a step too large (error, state untouched),
//! NaN refused, θ outside [0, 1] refused.

use crate::common::*;
use integrators::{
    integrate, EulerPoincare, Integrator, IntegratorError, LiePoisson, SolverConfig, SolverKind,
};
use lie_groups::{Cayley, ExpMap, LieGroup, So3};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

#[test]
fn principal_axis_rotation_is_reproduced_to_round_off() {
    // Π = (0, 0, p) is a relative equilibrium: every method must keep Π fixed and rotate R about e₃.
    let pi0 = Vector3::new(0.0, 0.0, 1.5);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let h = 0.1;
    let mut lp = LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, pi0, Some(g0)).unwrap();
    integrate(&mut lp, h, 50, |_| {}).unwrap();
    let (re, pe) = axisymmetric_exact(2.0, 3.0, &r0(), &pi0, 5.0); // Π₁ = Π₂ = 0: i is irrelevant
    assert!((lp.momentum() - pe).amax() < 1e-14);
    // τ = exp with ξ = hΩ exactly: R matches the exact rotation to round-off.
    assert!((lp.configuration().unwrap().as_matrix() - re).amax() < 1e-12);
}

#[test]
fn fast_spin_near_edge_of_exp_domain_converges_with_fd_newton() {
    // |Ω| h = 2.8 < π: still inside exp's domain, a hard nonlinear solve.
    let pi0 = Vector3::new(0.3, 0.2, 3.0 * 28.0);
    let h = 0.1 * 0.999;
    let cfg = SolverConfig {
        kind: SolverKind::NewtonFiniteDifference,
        ..Default::default()
    };
    let mut lp = LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, pi0, None)
        .unwrap()
        .with_solver(cfg);
    integrate(&mut lp, h, 20, |_| {}).unwrap();
    assert!(((lp.momentum().norm() - pi0.norm()) / pi0.norm()).abs() < 1e-13);
}

#[test]
fn step_leaving_exp_domain_is_refused_and_state_untouched() {
    // |Ω| h ≈ 4 > π: the rotation per step is not in exp's principal domain.
    let pi0 = Vector3::new(0.0, 0.1, 3.0 * 40.0);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let mut lp = LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, pi0, Some(g0)).unwrap();
    let before = (lp.time(), lp.momentum(), *lp.configuration().unwrap());
    let err = lp.step(0.1).unwrap_err();
    assert!(
        matches!(
            err,
            IntegratorError::StepTooLarge { .. } | IntegratorError::NoConvergence { .. }
        ),
        "{err:?}"
    );
    assert_eq!(
        (lp.time(), lp.momentum(), *lp.configuration().unwrap()),
        before
    );
}

#[test]
fn non_converging_step_returns_no_convergence_and_state_untouched() {
    // Fixed-point iteration with h |Ω| ~ 10 diverges: the step must fail cleanly.
    let pi0 = Vector3::new(50.0, 1.0, 1.0);
    let cfg = SolverConfig {
        kind: SolverKind::FixedPoint,
        max_iterations: 30,
        ..Default::default()
    };
    let mut ep = EulerPoincare::<So3, Cayley, _>::from_momentum(body(), 1.0, pi0, None)
        .unwrap()
        .with_solver(cfg);
    let before = (ep.time(), ep.velocity());
    let err = ep.step(0.2).unwrap_err();
    assert!(
        matches!(
            err,
            IntegratorError::NoConvergence { .. } | IntegratorError::NonFinite { .. }
        ),
        "{err:?}"
    );
    assert_eq!((ep.time(), ep.velocity()), before);
}

#[test]
fn near_separatrix_of_intermediate_axis_stays_on_energy_and_casimir() {
    // Π close to the unstable intermediate axis e₂: the solution follows the separatrix.
    let pi0 = Vector3::new(1e-6, 1.0, 1e-6);
    let mut lp = LiePoisson::<So3, Cayley, _>::new(body(), 0.5, pi0, None).unwrap();
    let e0 = lp.energy();
    let mut worst = 0.0f64;
    integrate(&mut lp, 0.05, 2000, |i| {
        worst = worst.max((i.energy() - e0).abs() / e0)
    })
    .unwrap();
    assert!((lp.momentum().norm() - pi0.norm()).abs() < 1e-13);
    // Second-order energy error with h|Ω| = 0.025: ~1e-4 at most.
    assert!(worst < 1e-3, "{worst:e}");
}

#[test]
fn inertia_ratio_1e6_is_integrated() {
    let b = RigidBody::principal([1e-3, 1.0, 1e3]).unwrap();
    let pi0 = Vector3::new(1e-4, 0.5, 0.5);
    for theta in [0.0, 0.5, 1.0] {
        let mut lp =
            LiePoisson::<So3, Cayley, _>::new(b.clone(), theta, pi0, Some(So3::identity()))
                .unwrap();
        integrate(&mut lp, 0.01, 200, |_| {}).unwrap();
        assert!(((lp.momentum().norm() - pi0.norm()) / pi0.norm()).abs() < 1e-13);
        let r = lp.configuration().unwrap().as_matrix();
        assert!((r.transpose() * r - Matrix3::identity()).amax() < 1e-13);
    }
}

#[test]
fn tiny_momentum_is_integrated_to_relative_precision() {
    // |Π| = 1e-8: the relative tolerance solves it as accurately as |Π| = 1 (the flow is the
    // |Π| = 1 flow slowed down by 1e-8, so compare with that one at time t·1e-8).
    let pi1 = Vector3::new(0.6, -0.4, 0.7);
    let pi0 = pi1 * 1e-8;
    let mut tiny = LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, pi0, None).unwrap();
    let mut unit = LiePoisson::<So3, ExpMap, _>::new(body(), 0.5, pi1, None).unwrap();
    integrate(&mut tiny, 1e6, 20, |_| {}).unwrap();
    integrate(&mut unit, 1e-2, 20, |_| {}).unwrap();
    assert!((tiny.momentum() * 1e8 - unit.momentum()).amax() < 1e-12);
}

#[test]
fn nan_in_state_is_refused() {
    let nan = Vector3::new(f64::NAN, 0.0, 1.0);
    assert!(matches!(
        LiePoisson::<So3, Cayley, _>::new(body(), 0.5, nan, None),
        Err(IntegratorError::NonFinite { .. })
    ));
    assert!(matches!(
        EulerPoincare::<So3, Cayley, _>::new(body(), 0.5, nan, None),
        Err(IntegratorError::NonFinite { .. })
    ));
    let bad_g = So3::from_matrix_unchecked(&Matrix3::from_element(f64::NAN));
    assert!(matches!(
        LiePoisson::<So3, Cayley, _>::new(body(), 0.5, Vector3::x(), Some(bad_g)),
        Err(IntegratorError::NonFinite { .. })
    ));
    let mut lp = LiePoisson::<So3, Cayley, _>::new(body(), 0.5, Vector3::x(), None).unwrap();
    assert!(lp.reset(0.0, nan, None).is_err());
    assert_eq!(lp.momentum(), Vector3::x());
    assert!(matches!(
        lp.step(f64::NAN),
        Err(IntegratorError::NonFinite { .. })
    ));
    assert_eq!(lp.time(), 0.0);
}

/// An initial attitude that is not a rotation (a scaled matrix, a reflection, a shear — built
/// with `from_matrix_unchecked`) is refused by every constructor and by `reset`, with the group's
/// reason; the state stays as it was. (Before, every method accepted it and integrated it.)
#[test]
fn a_configuration_off_the_group_is_refused() {
    use integrators::baselines::QuaternionRk4;
    use integrators::splitting::Splitting;
    use integrators::Rkmk4;
    use mechanics::exact::ExactFreeBody;
    let not_rotations = [
        Matrix3::identity() * 2.0,
        Matrix3::new(-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
        Matrix3::new(1.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
    ];
    let off = |r: Result<(), IntegratorError>, name: &str, m: &Matrix3<f64>| match r {
        Err(IntegratorError::InvalidParameter { reason }) => {
            assert!(
                reason.contains("not an element of SO(3)"),
                "{name}: {reason}"
            )
        }
        other => panic!("{name} accepted {m}: {other:?}"),
    };
    let pi = Vector3::new(0.3, 1.0, 0.2);
    for m in &not_rotations {
        let g = Some(So3::from_matrix_unchecked(m));
        off(
            LiePoisson::<So3, Cayley, _>::new(body(), 0.5, pi, g).map(|_| ()),
            "lie-poisson",
            m,
        );
        off(
            EulerPoincare::<So3, ExpMap, _>::from_momentum(body(), 0.5, pi, g).map(|_| ()),
            "euler-poincare",
            m,
        );
        off(QuaternionRk4::new(body(), pi, g).map(|_| ()), "rk4", m);
        off(Rkmk4::new(body(), pi, g).map(|_| ()), "rkmk4", m);
        off(Splitting::new(body(), pi, g).map(|_| ()), "splitting", m);
        off(ExactFreeBody::new(body(), pi, g).map(|_| ()), "exact", m);
        let mut lp = LiePoisson::<So3, Cayley, _>::new(body(), 0.5, pi, None).unwrap();
        off(lp.reset(0.0, pi, g), "lie-poisson reset", m);
        assert!(lp.momentum() == pi && lp.configuration().is_none());
    }
    // a rotation rounded to a few digits is still one (the group's tolerance)
    let r = So3::exp(&Vector3::new(0.3, -0.2, 0.9))
        .matrix()
        .map(|x| (x * 1e12).round() / 1e12);
    assert!(LiePoisson::<So3, Cayley, _>::new(
        body(),
        0.5,
        pi,
        Some(So3::from_matrix_unchecked(&r))
    )
    .is_ok());
}

#[test]
fn theta_outside_unit_interval_is_refused() {
    for theta in [-0.1, 1.5, f64::NAN] {
        assert!(matches!(
            LiePoisson::<So3, Cayley, _>::new(body(), theta, Vector3::x(), None),
            Err(IntegratorError::InvalidTheta { .. })
        ));
    }
}

/// An inertia near f64::MAX (1e308·I) is a valid inertia: accepted, with Ω = 𝕀⁻¹Π to round-off.
/// (Before, its determinant overflowed and it was refused as "singular".)
#[test]
fn huge_and_tiny_inertias_are_accepted_not_called_singular() {
    use integrators::System;
    for s in [1e308, 1e-300] {
        let b = RigidBody::principal([s, 0.5 * s, s]).unwrap();
        let pi = Vector3::new(0.1, 0.2, -0.1) * s;
        let w = b.velocity(&pi);
        let expected = Vector3::new(0.1, 0.4, -0.1);
        assert!((w - expected).amax() < 1e-15, "{s:e}: {w}");
    }
}

#[test]
fn non_spd_inertia_is_refused() {
    assert!(RigidBody::principal([1.0, -2.0, 3.0]).is_err());
    assert!(RigidBody::new(Matrix3::new(1.0, 2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)).is_err());
    assert!(RigidBody::principal([1.0, f64::NAN, 3.0]).is_err());
}
