//! The solver's warm start across steps ([`WarmStart`]): the quintic extrapolation of past
//! solutions, the reuse of the last Newton matrix and the contraction prior carried with it change
//! where the iteration starts and when it may stop, not what it converges to, and they remove the
//! Jacobian and most second residuals from steady runs at a fixed step.

use integrators::{
    warm_start::{CHORD_REUSE_CONTRACTION, PRIOR_INFLATION},
    EulerPoincare, Integrator, LiePoisson, SolverConfig, SolverKind, WarmStart,
};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

fn g0() -> Option<So3> {
    Some(So3::exp(&Vector3::new(0.3, -0.5, 0.8)))
}

const PI0: Vector3<f64> = Vector3::new(0.5, 1.0, 0.2);

/// Six records of one step size are needed; the extrapolation reproduces quintics exactly (to
/// round-off) and is O(δ⁶) for smooth sequences; another step size has its own slot and leaves
/// the first one's extrapolation as it was; samples unequally spaced in time start afresh.
#[test]
fn extrapolation_is_exact_for_quintics_and_needs_six_steps_of_one_size() {
    let quintic = |k: f64| {
        Vector3::new(1.0, -2.0, 0.5) + Vector3::new(0.3, 0.1, -0.2) * k
            - Vector3::new(0.02, 0.05, 0.01) * (k * k)
            + Vector3::new(0.004, -0.001, 0.002) * (k * k * k)
            + Vector3::new(-3e-4, 2e-4, 1e-4) * (k * k * k * k)
            + Vector3::new(2e-5, -1e-5, 3e-5) * (k * k * k * k * k)
    };
    let mut w = WarmStart::<So3>::default();
    for k in 0..6 {
        assert!(w.predict(0.1).is_none(), "after {k} records");
        w.record(0.1, 0.1 * k as f64, &quintic(k as f64), None, 0);
    }
    let p = w.predict(0.1).expect("six records of h = 0.1");
    assert!((p - quintic(6.0)).amax() < 1e-12, "{p} vs {}", quintic(6.0));
    // the ring keeps going: one more record, the next value
    w.record(0.1, 0.6, &quintic(6.0), None, 0);
    let p = w.predict(0.1).unwrap();
    assert!((p - quintic(7.0)).amax() < 1e-12, "{p} vs {}", quintic(7.0));
    assert!(w.predict(0.2).is_none(), "another step size");
    assert!(w.predict(-0.1).is_none(), "the reversed step");
    // a step of another size (a composition's next stage) goes to its own slot
    w.record(0.2, 0.75, &quintic(8.0), None, 0);
    assert!(w.predict(0.2).is_none());
    assert_eq!(w.predict(0.1), Some(p), "h = 0.1 kept its extrapolation");
    // a sample of h = 0.1 off the spacing of the earlier ones (0.1): the extrapolation restarts
    // from the last two
    w.record(0.1, 0.75, &quintic(7.0), None, 0);
    assert!(w.predict(0.1).is_none(), "unequally spaced samples");
    for k in 8..12 {
        w.record(
            0.1,
            0.75 + 0.15 * (k - 7) as f64,
            &quintic(k as f64),
            None,
            0,
        );
    }
    assert!(w.predict(0.1).is_some(), "six samples spaced by 0.15");
    // more step sizes than slots: the least recently used gives way
    for i in 0..integrators::warm_start::SLOTS {
        *w.chord(1.0 + i as f64) = Some(Matrix3::identity());
        w.record(1.0 + i as f64, 2.0, &Vector3::zeros(), None, 1);
    }
    assert!(
        w.predict(0.1).is_none(),
        "h = 0.1 was the least recently used"
    );
    assert_eq!(*w.chord(1.0), Some(Matrix3::identity()), "the others kept");
    // a smooth non-polynomial sequence: error O(δ⁶) in the sample spacing δ
    let err = |d: f64| {
        let mut w = WarmStart::<So3>::default();
        // (no component with a vanishing sixth derivative at 0, which would hide the δ⁶ term)
        let f = |t: f64| Vector3::new((t + 0.4).sin(), (t + 0.3).cos(), (0.5 * t).exp());
        for k in 0..6 {
            w.record(d, k as f64 * d, &f(k as f64 * d), None, 0);
        }
        (w.predict(d).unwrap() - f(6.0 * d)).amax()
    };
    let order = (err(0.04) / err(0.02)).log2();
    assert!((5.8..6.2).contains(&order), "extrapolation order {order}");
}

/// The Newton matrix is handed to the next step only if its iteration contracted well, and only
/// for the same step size; the contraction prior comes with it: the bound measured on a matrix
/// carried from an earlier step, at least [`CHORD_REUSE_CONTRACTION`], inflated by
/// [`PRIOR_INFLATION`] at every step that measures none, and the floor alone after a step that
/// evaluated its own matrix (Newton's quadratic contraction at its own guess says nothing of the
/// next step's).
#[test]
fn the_newton_matrix_and_its_prior_are_kept_only_when_they_mean_something() {
    let j = Matrix3::identity() * 2.0;
    let mut w = WarmStart::<So3>::default();
    // the solver leaves its matrix in the slot of the step's size; record keeps it
    *w.chord(0.1) = Some(j);
    w.record(0.1, 0.1, &Vector3::zeros(), Some((1e-4, 2e-4)), 0);
    assert_eq!(
        w.prior_contraction(0.1),
        Some(CHORD_REUSE_CONTRACTION),
        "never below what a kept matrix may contract by"
    );
    w.record(0.1, 0.2, &Vector3::zeros(), Some((1e-4, 2e-3)), 0);
    assert_eq!(w.prior_contraction(0.1), Some(2e-3), "the measured bound");
    assert!(w.prior_contraction(0.2).is_none(), "another step size");
    assert!(w.chord(0.2).is_none(), "another step size");
    *w.chord(0.1) = Some(j);
    w.record(
        0.1,
        0.3,
        &Vector3::zeros(),
        Some((CHORD_REUSE_CONTRACTION, 1e-3)),
        0,
    );
    assert_eq!(*w.chord(0.1), Some(j));
    assert_eq!(
        *w.chord(0.1),
        Some(j),
        "still there: the solver updates it in place"
    );
    // a step that stopped after one iteration: the prior grows, the matrix stays
    w.record(0.1, 0.4, &Vector3::zeros(), None, 0);
    assert_eq!(w.prior_contraction(0.1), Some(PRIOR_INFLATION * 1e-3));
    w.record(0.1, 0.5, &Vector3::zeros(), None, 0);
    let inflated = PRIOR_INFLATION * PRIOR_INFLATION * 1e-3;
    assert_eq!(w.prior_contraction(0.1), Some(inflated));
    assert_eq!(*w.chord(0.1), Some(j));
    // a step that evaluated its own matrix: its Newton contraction says nothing of the next
    // step's; the floor
    w.record(0.1, 0.6, &Vector3::zeros(), Some((1e-9, 1e-9)), 1);
    assert_eq!(w.prior_contraction(0.1), Some(CHORD_REUSE_CONTRACTION));
    assert_eq!(*w.chord(0.1), Some(j));
    w.record(
        0.1,
        0.7,
        &Vector3::zeros(),
        Some((2.0 * CHORD_REUSE_CONTRACTION, 2e-3)),
        0,
    );
    assert!(w.chord(0.1).is_none(), "contracted too slowly");
    assert!(w.prior_contraction(0.1).is_none(), "no matrix, no prior");
    // a step of a new size records the matrix the solver made for it
    *w.chord(0.3) = Some(j);
    w.record(0.3, 1.0, &Vector3::zeros(), None, 1);
    assert_eq!(*w.chord(0.3), Some(j), "the new size's own matrix");
    assert!(w.predict(0.3).is_none(), "one record of h = 0.3 only");
    w.clear();
    assert!(w.chord(0.3).is_none() && w.prior_contraction(0.3).is_none());
}

/// A warm run converges to what Newton solved to the floor converges to, step by step: over 2000
/// steps the two trajectories agree within the solver's tolerance summed over the steps, while the
/// warm run evaluates no Jacobian after its first steps and needs at most 1.7 residuals per step
/// (h = 0.01, where the cold simplified Newton needs one Jacobian and two residuals: the prior
/// accepts most steps after their first update). Large steps (h = 0.2) keep
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
                residuals <= 17 * 1995 / 10,
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
        // Euler–Poincaré's unknown is the increment δ = ξ̄ − ξ_k, O(h) as Lie–Poisson's hξ, and
        // its Newton matrix is exact here (quadratic h, exact second derivatives of τ): the same
        // bound, at both steps (measured 2.2e-16 … 1.0e-15 at h = 0.01, 2.1e-14 … 4.0e-13 at
        // h = 0.2; when it solved for ξ itself to 1e-14‖ξ‖, only N · 1e-14 · 1.3 could be
        // promised, and only at the small step).
        assert!(
            worst_ep < bound,
            "{} θ={theta} h={h}: EP off Newton by {worst_ep:e}",
            T::NAME
        );
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

/// Every warm step — most of them accepted after one residual on the carried contraction prior —
/// is within the solver's tolerance of the step solved to the floor from the same state: over 2000
/// steps of h = 0.01 and 500 of h = 0.1, Lie–Poisson's μ_{k+1} within 1e-14 ‖η‖ |μ| (η = hξ, its
/// unknown) and Euler–Poincaré's ξ_{k+1} within 1e-14 ‖Δξ‖ (Δξ = ξ_{k+1} − ξ_k, twice its
/// unknown δ = ξ̄ − ξ_k at θ = ½), each plus the rounding of the new state. (Solving for ξ̄
/// itself, to 1e-14 ‖ξ‖, Euler–Poincaré reached 5.2 × this bound at θ = ½, h = 0.01.)
#[test]
fn every_warm_step_is_within_the_tolerance_of_the_converged_step() {
    let newton = SolverConfig {
        kind: SolverKind::Newton,
        tolerance: 1e-16,
        ..SolverConfig::default()
    };
    for theta in [0.0, 0.5] {
        for (h, n) in [(0.01, 2000), (0.1, 500)] {
            let mut lp = LiePoisson::<So3, Cayley, _>::new(body(), theta, PI0, g0()).unwrap();
            let mut lp_ref = lp.clone().with_solver(newton);
            let mut ep =
                EulerPoincare::<So3, Cayley, _>::from_momentum(body(), theta, PI0, g0()).unwrap();
            let mut ep_ref = ep.clone().with_solver(newton);
            let (mut lp_worst, mut ep_worst, mut one_residual) = (0.0f64, 0.0f64, 0);
            for _ in 0..n {
                lp_ref
                    .reset(lp.time(), lp.momentum(), lp.configuration().cloned())
                    .unwrap();
                let ep_ref_start = ep.velocity();
                ep_ref
                    .reset(ep.time(), ep_ref_start, ep.configuration().cloned())
                    .unwrap();
                lp.step(h).unwrap();
                lp_ref.step(h).unwrap();
                ep.step(h).unwrap();
                ep_ref.step(h).unwrap();
                if lp.last_iterations() == 1 {
                    one_residual += 1;
                }
                let mu = lp.momentum().amax();
                let lp_bound = 1e-14 * 1.3 * h * mu + 4.0 * f64::EPSILON * mu;
                lp_worst = lp_worst.max((lp.momentum() - lp_ref.momentum()).amax() / lp_bound);
                let xi = ep.velocity().amax();
                let step = (ep.velocity() - ep_ref_start).amax();
                let ep_bound = 1e-14 * 1.3 * step + 4.0 * f64::EPSILON * xi;
                ep_worst = ep_worst.max((ep.velocity() - ep_ref.velocity()).amax() / ep_bound);
            }
            eprintln!(
                "θ = {theta}, h = {h}: LP {lp_worst:.2} EP {ep_worst:.2} of their bounds; \
                 {one_residual} of {n} LP steps took one residual"
            );
            assert!(
                lp_worst <= 1.0,
                "θ = {theta}, h = {h}: LP at {lp_worst} × its bound"
            );
            assert!(
                ep_worst <= 1.0,
                "θ = {theta}, h = {h}: EP at {ep_worst} × its bound"
            );
            if h == 0.01 {
                assert!(
                    one_residual > n / 4,
                    "θ = {theta}: the prior accepted only {one_residual} of {n} steps at once"
                );
            }
        }
    }
}

/// The stages of a composition keep their Newton matrices from one composed step to the next:
/// Lie–Poisson θ = ½ stepped through the triple jump's stage sizes γ₁h, γ₂h, γ₁h (as
/// [`integrators::Composition`] steps it) at h = 0.01 evaluates at most 10 Jacobians over its
/// last 300 composed steps (900 stages) — 4 measured; with one slot for the last step size only
/// it evaluated 600 (one per stage but for the γ₁h stage that follows one of its own size).
#[test]
fn composition_stages_keep_their_matrices() {
    let g1 = 1.0 / (2.0 - 2f64.cbrt());
    let stages = [g1 * 0.01, (1.0 - 2.0 * g1) * 0.01, g1 * 0.01];
    for theta in [0.5, 0.0] {
        let mut lp = LiePoisson::<So3, Cayley, _>::new(body(), theta, PI0, g0()).unwrap();
        let (mut jacobians, mut residuals) = (0, 0);
        for k in 0..310 {
            for &h in &stages {
                lp.step(h).unwrap();
                if k >= 10 {
                    jacobians += lp.last_jacobians();
                    residuals += lp.last_iterations();
                }
            }
        }
        eprintln!(
            "θ = {theta}: {jacobians} Jacobians, {:.2} residuals per stage",
            residuals as f64 / 900.0
        );
        assert!(
            jacobians <= 10,
            "θ = {theta}: {jacobians} Jacobians in 900 stages"
        );
    }
}
