//! The solver's warm start across steps ([`WarmStart`]): the cubic extrapolation of past
//! solutions and the reuse of the last Newton matrix change where the iteration starts, not what
//! it converges to, and they remove the Jacobian from steady runs at a fixed step.

use integrators::systems::RigidBody;
use integrators::{
    warm_start::CHORD_REUSE_CONTRACTION, EulerPoincare, Integrator, LiePoisson, SolverConfig,
    SolverKind, WarmStart,
};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use nalgebra::{Matrix3, Vector3};

fn body() -> RigidBody {
    RigidBody::principal(1.0, 2.0, 3.0).unwrap()
}

fn g0() -> Option<So3> {
    Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)))
}

const PI0: Vector3<f64> = Vector3::new(0.5, 1.0, 0.2);

/// Four records of one step size are needed; the extrapolation reproduces cubics exactly (to
/// round-off) and is O(h⁴) for smooth sequences; a new step size starts afresh.
#[test]
fn extrapolation_is_exact_for_cubics_and_needs_four_steps_of_one_size() {
    let cubic = |k: f64| {
        Vector3::new(1.0, -2.0, 0.5) + Vector3::new(0.3, 0.1, -0.2) * k
            - Vector3::new(0.02, 0.05, 0.01) * (k * k)
            + Vector3::new(0.004, -0.001, 0.002) * (k * k * k)
    };
    let mut w = WarmStart::<So3>::default();
    for k in 0..4 {
        assert!(w.predict(0.1).is_none(), "after {k} records");
        w.record(0.1, &cubic(k as f64), None, 0.0);
    }
    let p = w.predict(0.1).expect("four records of h = 0.1");
    assert!((p - cubic(4.0)).amax() < 1e-14, "{p} vs {}", cubic(4.0));
    assert!(w.predict(0.2).is_none(), "another step size");
    assert!(w.predict(-0.1).is_none(), "the reversed step");
    w.record(0.2, &cubic(5.0), None, 0.0);
    assert!(w.predict(0.1).is_none() && w.predict(0.2).is_none());
    // a smooth non-polynomial sequence: error O(δ⁴) in the sample spacing δ
    let err = |d: f64| {
        let mut w = WarmStart::<So3>::default();
        let f = |t: f64| Vector3::new(t.sin(), (2.0 * t).cos(), (0.5 * t).exp());
        for k in 0..4 {
            w.record(d, &f(k as f64 * d), None, 0.0);
        }
        (w.predict(d).unwrap() - f(4.0 * d)).amax()
    };
    let order = (err(0.02) / err(0.01)).log2();
    assert!((3.8..4.2).contains(&order), "extrapolation order {order}");
}

/// The Newton matrix is handed to the next step only if its iteration contracted well, and only
/// for the same step size.
#[test]
fn the_newton_matrix_is_kept_only_when_it_contracted_well() {
    let j = Matrix3::identity() * 2.0;
    let mut w = WarmStart::<So3>::default();
    w.record(0.1, &Vector3::zeros(), Some(j), CHORD_REUSE_CONTRACTION);
    assert!(w.take_chord(0.2).is_none(), "another step size");
    w.record(0.1, &Vector3::zeros(), Some(j), CHORD_REUSE_CONTRACTION);
    assert_eq!(w.take_chord(0.1), Some(j));
    assert!(w.take_chord(0.1).is_none(), "taken");
    w.record(
        0.1,
        &Vector3::zeros(),
        Some(j),
        2.0 * CHORD_REUSE_CONTRACTION,
    );
    assert!(w.take_chord(0.1).is_none(), "contracted too slowly");
}

/// A warm run converges to what Newton solved to the floor converges to, step by step: over 2000
/// steps the two trajectories agree within the solver's tolerance summed over the steps, while the warm run evaluates no
/// Jacobian after its first steps and needs at most two residuals per step (h = 0.01, where the
/// cold simplified Newton needs one Jacobian and two residuals). Large steps (h = 0.2) keep
/// converging (the matrix is then re-evaluated when it contracts too slowly).
fn warm_run_matches_newton<T: Tau<So3>>(theta: f64) {
    for (h, steady) in [(0.01, true), (0.2, false)] {
        let cold = SolverConfig {
            kind: SolverKind::Newton,
            tolerance: 1e-16,
            ..SolverConfig::default()
        };
        let mut warm = LiePoisson::<So3, T, _>::new(body(), theta, PI0, g0()).unwrap();
        let mut reference = LiePoisson::<So3, T, _>::new(body(), theta, PI0, g0())
            .unwrap()
            .with_solver(cold);
        let mut ep = EulerPoincare::<So3, T, _>::from_momentum(body(), theta, PI0, g0()).unwrap();
        let mut ep_ref = EulerPoincare::<So3, T, _>::from_momentum(body(), theta, PI0, g0())
            .unwrap()
            .with_solver(cold);
        let (mut worst, mut worst_ep) = (0.0f64, 0.0f64);
        let (mut jacobians, mut residuals, mut ep_jacobians) = (0, 0, 0);
        for k in 0..2000 {
            warm.step(h).unwrap();
            reference.step(h).unwrap();
            ep.step(h).unwrap();
            ep_ref.step(h).unwrap();
            worst = worst.max((warm.momentum() - reference.momentum()).amax());
            worst = worst.max(
                (warm.configuration().unwrap().matrix()
                    - reference.configuration().unwrap().matrix())
                .amax(),
            );
            worst_ep = worst_ep.max((ep.velocity() - ep_ref.velocity()).amax());
            if k >= 5 {
                jacobians += warm.last_jacobians();
                residuals += warm.last_iterations();
                ep_jacobians += ep.last_jacobians();
            }
        }
        eprintln!(
            "{} θ={theta} h={h}: LP {worst:.1e} EP {worst_ep:.1e}; per step: LP {} residuals, {} Jacobians; EP {} Jacobians",
            T::NAME,
            residuals as f64 / 1995.0,
            jacobians as f64 / 1995.0,
            ep_jacobians as f64 / 1995.0
        );
        if steady {
            assert!(
                jacobians <= 20,
                "{} θ={theta}: {jacobians} Jacobians",
                T::NAME
            );
            assert!(
                residuals <= 2 * 1995 + 20,
                "{} θ={theta}: {residuals} residuals",
                T::NAME
            );
            if theta != 0.0 {
                assert!(
                    ep_jacobians <= 20,
                    "EP {} θ={theta}: {ep_jacobians}",
                    T::NAME
                );
            }
        }
        // Each step is solved to the tolerance 1e-14 ‖ξ‖ (‖ξ‖ ≈ 1.1 h here, ∂μ_{k+1}/∂ξ ≈ |μ|),
        // so N steps may differ by up to N · 1e-14 · 1.1 h · 1.1.
        let bound = 2000.0 * 1e-14 * 1.3 * h;
        assert!(
            worst < bound,
            "{} θ={theta} h={h}: LP off Newton by {worst:e}",
            T::NAME
        );
        // Euler–Poincaré's Newton matrix is itself only O(h²)-accurate (see `euler_poincare`), so
        // its "Newton" reference is a reference only at the small step.
        if steady {
            assert!(
                worst_ep < bound,
                "{} θ={theta} h={h}: EP off Newton by {worst_ep:e}",
                T::NAME
            );
        }
    }
}

#[test]
fn warm_runs_converge_to_the_newton_solution_cayley() {
    for theta in [0.0, 0.5, 1.0] {
        warm_run_matches_newton::<Cayley>(theta);
    }
}

#[test]
fn warm_runs_converge_to_the_newton_solution_exp() {
    for theta in [0.0, 0.5, 1.0] {
        warm_run_matches_newton::<ExpMap>(theta);
    }
}

/// A reset, a reversed step and a new solver all start cold: the symmetric method still
/// retraces its steps (θ = ½, 50 steps forward and back to 1e-13), and a reset run repeats the
/// first run bit for bit.
#[test]
fn warm_start_never_leaks_across_a_reset_or_a_reversal() {
    let mut lp = LiePoisson::<So3, Cayley, _>::new(body(), 0.5, PI0, g0()).unwrap();
    let first: Vec<_> = (0..20)
        .map(|_| {
            lp.step(0.05).unwrap();
            lp.momentum()
        })
        .collect();
    for _ in 0..20 {
        lp.step(-0.05).unwrap();
    }
    assert!(
        (lp.momentum() - PI0).amax() < 1e-13,
        "{}",
        lp.momentum() - PI0
    );
    lp.reset(0.0, PI0, g0()).unwrap();
    for m in &first {
        lp.step(0.05).unwrap();
        assert_eq!(&lp.momentum(), m);
    }
}
