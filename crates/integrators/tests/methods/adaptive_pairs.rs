//! The adaptive runs' behaviour: the error estimate against the true local error, rejected steps
//! leaving the state as it was, the last step landing on T, output times and events inside
//! variable steps, bad input refused with an error naming it, and no allocation in a run.

use crate::common::fitted_order;
use integrators::adaptive::{Adaptive, EmbeddedPair, RkmkDop853, RkmkDopri5, Tolerance};
use integrators::baselines::{QuaternionDop853, QuaternionDopri5};
use integrators::events::{Direction, Event};
use integrators::{Integrator, IntegratorError};
use lie_groups::testing::allocations;
use lie_groups::{LieGroup, So3, Vector};
use mechanics::exact::FreeBodyFlow;
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::Vector3;
use std::f64::consts::PI;

fn top() -> HeavyTop {
    HeavyTop::principal([1.0, 1.5, 2.0], 1.0, 1.0, Vector3::new(0.1, -0.2, 0.6)).unwrap()
}
const PI0: Vector3<f64> = Vector3::new(0.3, 0.8, 1.1);
fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

/// A tolerance under which the scaled error is the RMS of the raw estimate (atol = 1 dominates
/// the scale `atol + rtol|y|` of these O(1) states to 1e-13).
fn raw() -> Tolerance {
    Tolerance::new(Tolerance::MIN_RTOL, 1.0).unwrap()
}

/// The scaled estimate of one step of h from `m`'s state, leaving `m` as it was.
fn estimate<M: EmbeddedPair>(m: &M, h: f64) -> f64 {
    let mut c = m.clone();
    c.try_step_to(m.time() + h, &raw()).unwrap()
}

/// The RMS over the components of (log(g⁻¹g_ref), μ − μ_ref): the true local error in the norm
/// the estimate of the RKMK pairs is measured in (under [`raw`]).
fn true_error<M: Integrator<Group = So3>>(m: &M, reference: &M) -> f64 {
    let dg = m
        .configuration()
        .unwrap()
        .inverse()
        .compose(reference.configuration().unwrap())
        .log()
        .unwrap();
    let dmu = m.momentum().sub(&reference.momentum());
    ((dg.norm_squared() + dmu.norm_squared()) / 6.0).sqrt()
}

/// One step of h of the advanced solution, of the embedded one, and 64 steps of h/64 (the
/// reference: an error ~64⁻⁵ of the step's).
fn one_step<M: EmbeddedPair<Group = So3>>(
    m: &M,
    h: f64,
    embedded: impl Fn(&mut M, f64),
) -> (f64, f64, f64) {
    let mut reference = m.clone();
    for _ in 0..64 {
        reference.step(h / 64.0).unwrap();
    }
    let mut advanced = m.clone();
    advanced.step(h).unwrap();
    let mut low = m.clone();
    embedded(&mut low, h);
    (
        estimate(m, h),
        true_error(&advanced, &reference),
        true_error(&low, &reference),
    )
}

/// Dormand–Prince in the algebra: the estimate `h Σ eᵢKᵢ` (the BCH leading term of
/// log(ĝ⁻¹g)) tracks the true local error of the embedded solution — their ratio within 6 % of
/// 1 at h = 0.2 and closer as h falls (the gap is the advanced solution's own error, O(h)
/// relative) — and bounds that of the advanced one; it falls like h⁵.
#[test]
fn dopri5_estimate_tracks_the_local_error_of_its_embedded_solution() {
    let m = RkmkDopri5::new(top(), PI0, Some(g0())).unwrap();
    let hs = [0.2, 0.1, 0.05, 0.025];
    let mut estimates = vec![];
    let mut last_gap = f64::INFINITY;
    for h in hs {
        let (est, advanced, embedded) = one_step(&m, h, |m, h| m.step_embedded(h, false).unwrap());
        let gap = (est / embedded - 1.0).abs();
        println!("h = {h}: estimate {est:.3e}, embedded {embedded:.3e} (gap {gap:.1e}), advanced {advanced:.3e}");
        assert!(
            gap < 0.06 && gap < last_gap,
            "h = {h}: {est:e} vs {embedded:e}"
        );
        last_gap = gap;
        assert!(est > 3.0 * advanced);
        estimates.push(est);
    }
    let p = fitted_order(&hs, &estimates);
    println!("estimate ∝ h^{p:.2}");
    assert!((p - 5.0).abs() < 0.2);
}

/// DOP853's combined estimate `|e₅|² / √(|e₅|² + 0.01|e₃|²)` falls like h⁸ (the exponent its
/// controller uses) and stays above the true local error of the order-8 solution (h⁹): it is
/// conservative, increasingly so as h falls.
#[test]
fn dop853_estimate_scales_as_h8_and_bounds_the_local_error() {
    let m = RkmkDop853::new(top(), PI0, Some(g0())).unwrap();
    let q = QuaternionDop853::new(top(), PI0, Some(g0())).unwrap();
    let hs = [0.4, 0.3, 0.2, 0.15];
    let (mut estimates, mut estimates_q) = (vec![], vec![]);
    for h in hs {
        let (est, advanced, _) = one_step(&m, h, |m, h| m.step_embedded(h, false).unwrap());
        println!("h = {h}: estimate {est:.3e}, advanced {advanced:.3e}");
        assert!(est > advanced, "h = {h}: {est:e} < {advanced:e}");
        estimates.push(est);
        estimates_q.push(estimate(&q, h));
    }
    let (p, pq) = (
        fitted_order(&hs, &estimates),
        fitted_order(&hs, &estimates_q),
    );
    println!("estimate ∝ h^{p:.2} (RKMK), h^{pq:.2} (q, Π)");
    assert!((p - 8.0).abs() < 0.3 && (pq - 8.0).abs() < 0.3);
}

/// On (q, Π) the estimate is that of scipy on the 7 components; it tracks the error of the
/// embedded Dormand–Prince solution there too (the renormalization of q removes only the radial
/// part of it, a higher-order quantity).
#[test]
fn quaternion_dopri5_estimate_tracks_its_embedded_error() {
    let m = QuaternionDopri5::new(top(), PI0, Some(g0())).unwrap();
    for h in [0.1, 0.05, 0.025] {
        let mut reference = m.clone();
        for _ in 0..64 {
            reference.step(h / 64.0).unwrap();
        }
        let mut low = m.clone();
        low.step_embedded(h, false).unwrap();
        let (q, qr) = (low.quaternion().unwrap(), reference.quaternion().unwrap());
        // q and −q are the same rotation; the runs stay in one sheet.
        let dq = q.coords - qr.coords;
        let dpi = low.momentum() - reference.momentum();
        let true_err = ((dq.norm_squared() + dpi.norm_squared()) / 7.0).sqrt();
        let est = estimate(&m, h);
        println!("h = {h}: estimate {est:.3e}, embedded {true_err:.3e}");
        assert!(
            (est / true_err - 1.0).abs() < 0.1,
            "h = {h}: {est:e} vs {true_err:e}"
        );
    }
}

/// The estimate on the group is log(ĝ⁻¹g) to leading order: against the log of the two
/// solutions formed and compared, within 2 % at h = 0.1 and closer as h falls (the BCH terms
/// left out are O(h) relative).
#[test]
fn group_estimate_is_the_log_distance_between_the_two_solutions() {
    // A free body (no μ error from a potential): drop μ by comparing g alone.
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let m = RkmkDopri5::new(body, Vector3::new(0.5, 1.0, -0.7), Some(g0())).unwrap();
    let mut last = f64::INFINITY;
    for h in [0.2, 0.1, 0.05] {
        let (mut y, mut yhat) = (m.clone(), m.clone());
        y.step(h).unwrap();
        yhat.step_embedded(h, false).unwrap();
        let log = yhat
            .configuration()
            .unwrap()
            .inverse()
            .compose(y.configuration().unwrap())
            .log()
            .unwrap();
        let dmu = y.momentum() - yhat.momentum();
        let formed = ((log.norm_squared() + dmu.norm_squared()) / 6.0).sqrt();
        let est = estimate(&m, h);
        let gap = (est / formed - 1.0).abs();
        println!("h = {h}: estimate {est:.4e}, formed {formed:.4e}, gap {gap:.1e}");
        assert!(gap < 0.02 && gap < last);
        last = gap;
    }
}

/// A rejected step leaves the state exactly as it was (time, μ, g bit for bit) and is counted.
#[test]
fn a_rejected_step_leaves_the_state_untouched_and_is_counted() {
    let m = RkmkDopri5::new(top(), PI0, Some(g0())).unwrap();
    let mut c = m.clone();
    let tol = Tolerance::new(1e-12, 1e-12).unwrap();
    let err = c.try_step_to(1.0, &tol).unwrap();
    assert!(err > 1.0);
    assert_eq!(c.time(), m.time());
    assert_eq!(c.momentum(), m.momentum());
    assert_eq!(c.configuration(), m.configuration());
    // A step that overflows is a rejection too (infinite error), the state kept.
    let mut c = QuaternionDop853::new(top(), PI0 * 1e150, Some(g0())).unwrap();
    assert_eq!(c.try_step_to(1e10, &tol).unwrap(), f64::INFINITY);
    assert_eq!(c.time(), 0.0);
    // In a run, the first step from a deliberately large initial step is rejected and counted.
    let mut run = Adaptive::new(m, tol).with_initial_step(1.0).unwrap();
    run.step_towards(10.0).unwrap();
    let s = run.stats();
    assert!(s.rejected >= 1 && s.accepted == 1, "{s:?}");
    assert!(s.max_step < 1.0);
}

/// The last step lands exactly on T, forwards and backwards, and the steps vary.
#[test]
fn runs_land_exactly_on_the_end_time() {
    let tol = Tolerance::new(1e-9, 1e-9).unwrap();
    let mut run = Adaptive::new(RkmkDop853::new(top(), PI0, Some(g0())).unwrap(), tol);
    run.advance_to(10.0).unwrap();
    assert_eq!(run.method().time(), 10.0);
    let s = *run.stats();
    assert!(s.min_step < 0.5 * s.max_step, "{s:?}");
    run.advance_to(10.0 + 1e-3).unwrap();
    assert_eq!(run.method().time(), 10.001);
    run.advance_to(0.0).unwrap();
    assert_eq!(run.method().time(), 0.0);
    let back = run.method();
    let dmu = (back.momentum() - PI0).amax();
    let dg = back.configuration().unwrap().matrix_distance(&g0());
    println!("forward to 10 and back: |Δμ| {dmu:.1e}, |Δg| {dg:.1e}");
    assert!(dmu < 1e-7 && dg < 1e-7);
}

/// Output at requested times comes exactly at those times, from partial steps inside the
/// accepted ones: the state at T is bit for bit that of a run without output, and each output
/// is as accurate as the accepted steps around it (against the exact free-body flow).
#[test]
fn output_times_are_exact_and_do_not_change_the_steps() {
    let body = RigidBody::principal([2.0, 3.0, 4.0]).unwrap();
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    let flow = FreeBodyFlow::new(&body);
    let tol = Tolerance::new(1e-10, 1e-10).unwrap();
    let make = || Adaptive::new(RkmkDop853::new(body.clone(), pi0, Some(g0())).unwrap(), tol);
    // The run without output, step by step: the largest error at the accepted steps' ends.
    let mut plain = make();
    let mut at_steps = 0.0f64;
    while plain.method().time() != 10.0 {
        plain.step_towards(10.0).unwrap();
        let m = plain.method();
        let (pe, re) = flow.advance(m.time(), &pi0, Some(&g0())).unwrap();
        let e = (m.momentum() - pe)
            .amax()
            .max(m.configuration().unwrap().matrix_distance(&re.unwrap()));
        at_steps = at_steps.max(e);
    }
    let times: Vec<f64> = (0..=100).map(|k| 0.1 * k as f64).collect();
    let mut dense = make();
    let mut seen = vec![];
    let mut worst = 0.0f64;
    dense
        .solve(
            10.0,
            &times,
            |t, pi, r| {
                seen.push(t);
                let (pe, re) = flow.advance(t, &pi0, Some(&g0())).unwrap();
                let e = (pi - pe)
                    .amax()
                    .max(r.unwrap().matrix_distance(&re.unwrap()));
                worst = worst.max(e);
            },
            &[],
        )
        .unwrap();
    assert_eq!(seen, times);
    assert_eq!(dense.stats(), plain.stats());
    assert_eq!(dense.method().momentum(), plain.method().momentum());
    assert_eq!(
        dense.method().configuration(),
        plain.method().configuration()
    );
    println!(
        "{} steps, worst output error {worst:.1e}, at the steps {at_steps:.1e}",
        plain.stats().accepted
    );
    assert!(worst < 1.5 * at_steps);
}

/// Events are located across variable steps to the event tolerance on the method's solution:
/// the symmetric top 𝕀 = diag(1, 1, 2), Π₀ = (1, 0, 1) has Π₁ = cos(t/2), zero at π, 3π, 5π.
#[test]
fn events_are_located_across_variable_steps_to_their_tolerance() {
    let top = RigidBody::principal([1.0, 1.0, 2.0]).unwrap();
    let pi0 = Vector3::new(1.0, 0.0, 1.0);
    for tol in [1e-6, 1e-10] {
        let tolerance = Tolerance::new(tol, tol).unwrap();
        let mut run = Adaptive::new(
            RkmkDopri5::new(top.clone(), pi0, Some(g0())).unwrap(),
            tolerance,
        );
        let crossing = Event::new(|_t, mu: &Vector3<f64>, _g: Option<&So3>| mu.x).tolerance(1e-12);
        let result = run.solve(20.0, &[], |_, _, _| {}, &[crossing]).unwrap();
        let want = [PI, 3.0 * PI, 5.0 * PI];
        assert_eq!(result.hits.len(), 3);
        let s = run.stats();
        for (hit, t) in result.hits.iter().zip(want) {
            // The located root is that of the computed Π₁ to 1e-12; it is off the exact one by
            // the method's error in Π₁ over the slope |dΠ₁/dt| = ½.
            let miss = (hit.t - t).abs();
            println!(
                "tol {tol:.0e}: hit at {:.15} (off {miss:.1e}), steps {} in [{:.3}, {:.3}]",
                hit.t, s.accepted, s.min_step, s.max_step
            );
            assert!(miss < 20.0 * tol, "tol {tol}: {miss:e}");
            assert!(hit.mu.x.abs() < 1e-11);
        }
        assert!(s.min_step < 0.5 * s.max_step, "steps did not vary: {s:?}");
        assert!(!result.hits[0].rising && result.hits[1].rising);
    }
}

/// A terminal event stops the run at its crossing, in the state of the partial step there.
#[test]
fn a_terminal_event_stops_the_run_at_the_crossing() {
    let top = RigidBody::principal([1.0, 1.0, 2.0]).unwrap();
    let pi0 = Vector3::new(1.0, 0.0, 1.0);
    let tol = Tolerance::new(1e-10, 1e-10).unwrap();
    let mut run = Adaptive::new(QuaternionDopri5::new(top, pi0, Some(g0())).unwrap(), tol);
    let stop = Event::new(|_t, mu: &Vector3<f64>, _g: Option<&So3>| mu.x)
        .direction(Direction::Rising)
        .terminal()
        .tolerance(1e-12);
    let mut outputs = vec![];
    let result = run
        .solve(
            20.0,
            &[1.0, 9.0, 9.5, 10.0],
            |t, _, _| outputs.push(t),
            &[stop],
        )
        .unwrap();
    assert!(result.stopped);
    let hit = result.hits.last().unwrap();
    assert!((hit.t - 3.0 * PI).abs() < 1e-8, "{}", hit.t);
    assert_eq!(run.method().time(), hit.t);
    assert_eq!(run.method().momentum(), hit.mu);
    // Outputs up to the crossing only.
    assert_eq!(outputs, [1.0, 9.0]);
}

#[test]
fn bad_tolerances_are_refused_naming_them() {
    let cases = [
        (0.0, 1e-6, "rtol"),
        (-1e-6, 1e-6, "rtol"),
        (f64::NAN, 1e-6, "rtol"),
        (1e-6, 0.0, "atol"),
        (1e-6, f64::INFINITY, "atol"),
        (1e-6, f64::NAN, "atol"),
        (1e-15, 1e-6, "rtol"),
    ];
    for (rtol, atol, which) in cases {
        match Tolerance::new(rtol, atol) {
            Err(IntegratorError::InvalidTolerance { name, value, .. }) => {
                assert_eq!(name, which);
                let given = if which == "rtol" { rtol } else { atol };
                assert!(value.to_bits() == given.to_bits());
            }
            other => panic!("({rtol}, {atol}): {other:?}"),
        }
    }
    let e = Tolerance::new(1e-15, 1e-6).unwrap_err().to_string();
    assert!(
        e.contains("rtol") && e.contains("1e-15") && e.contains("100 ε"),
        "{e}"
    );
    assert!(Tolerance::new(Tolerance::MIN_RTOL, 1e-300).is_ok());
}

/// A step the controller would shrink below the minimum is an error naming it; the state is the
/// last accepted one. So is an exhausted step budget.
#[test]
fn step_underflow_and_step_budget_are_errors_with_the_state_kept() {
    let tol = Tolerance::new(1e-12, 1e-12).unwrap();
    let mut run = Adaptive::new(RkmkDopri5::new(top(), PI0, Some(g0())).unwrap(), tol)
        .with_min_step(0.3)
        .unwrap();
    let before = run.method().clone();
    match run.advance_to(10.0) {
        Err(IntegratorError::StepSizeUnderflow { t, step, minimum }) => {
            assert_eq!(t, run.method().time());
            assert!(step < minimum && minimum == 0.3, "{step} {minimum}");
        }
        other => panic!("{other:?}"),
    }
    if run.method().time() == 0.0 {
        assert_eq!(run.method().momentum(), before.momentum());
    }
    let message = run.advance_to(10.0).unwrap_err().to_string();
    assert!(
        message.contains("underflow") && message.contains("3e-1"),
        "{message}"
    );

    let mut run =
        Adaptive::new(RkmkDopri5::new(top(), PI0, Some(g0())).unwrap(), tol).with_max_steps(5);
    match run.advance_to(10.0) {
        Err(IntegratorError::TooManySteps { steps, t }) => {
            assert_eq!(steps, 5);
            assert_eq!(t, run.method().time());
            assert!(t > 0.0 && t < 10.0);
        }
        other => panic!("{other:?}"),
    }
    // Non-finite end times and zero steps are refused, the state kept.
    assert!(run.advance_to(f64::NAN).is_err());
    let mut m = RkmkDopri5::new(top(), PI0, Some(g0())).unwrap();
    assert!(m.try_step_to(0.0, &tol).is_err());
    assert!(m.step_to(f64::INFINITY).is_err());
    assert_eq!(m.time(), 0.0);
}

/// A whole adaptive run on SO(3) allocates nothing, for each pair (counted after a first run
/// that warmed up every path).
#[test]
fn adaptive_runs_allocate_nothing() {
    fn check<M: EmbeddedPair>(m: M) {
        let name = m.method_name();
        let mut run = Adaptive::new(m, Tolerance::new(1e-8, 1e-8).unwrap());
        run.advance_to(1.0).unwrap();
        let n = allocations(|| run.advance_to(std::hint::black_box(10.0)).unwrap());
        assert_eq!(n, 0, "{name}: {n} allocations");
    }
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    check(RkmkDopri5::new(top(), PI0, Some(g0())).unwrap());
    check(RkmkDop853::new(top(), PI0, Some(g0())).unwrap());
    check(QuaternionDopri5::new(top(), PI0, Some(g0())).unwrap());
    check(QuaternionDop853::new(top(), PI0, Some(g0())).unwrap());
    check(RkmkDop853::new(body.clone(), PI0, Some(g0())).unwrap());
    check(RkmkDopri5::new(body, PI0, None).unwrap());
}
