//! The baselines (`QuaternionRk4`, `Rkmk4`): their measured order, what they preserve (R on SO(3))
//! and what they do not (energy, Casimir), and their input checks.

use crate::common::*;
use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::{EulerArnold, Integrator, IntegratorError, LiePoisson, System};
use lie_groups::{Cayley, LieGroup, Se3, So3};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use proptest::prelude::*;

const STEPS: [usize; 4] = [20, 40, 80, 160];

fn g0() -> So3 {
    So3::from_matrix(&r0()).expect("a rotation")
}

/// Fitted order and finest error of a method against a reference (R, Π) at time t; the error is
/// `max(‖R − R_ref‖_max, ‖Π − Π_ref‖_max / |Π₀|)`.
fn order<I: Integrator<Group = So3>>(
    make: impl Fn() -> I,
    t: f64,
    reference: &(Matrix3<f64>, Vector3<f64>),
    pi_scale: f64,
) -> (f64, f64) {
    let (mut hs, mut errs) = (vec![], vec![]);
    for n in STEPS {
        let h = t / n as f64;
        let (r, p) = run(make(), h, n).unwrap();
        let err = (r - reference.0)
            .amax()
            .max((p - reference.1).amax() / pi_scale);
        hs.push(h);
        errs.push(err);
    }
    (fitted_order(&hs, &errs), errs[errs.len() - 1])
}

/// Order 4 within 0.15: the four steps h = T/20 … T/160 are in the asymptotic regime (the
/// successive error ratios are 16 ± 10 %), and the finest error stays 1e4× above the reference's.
fn assert_order_4(label: &str, (p, e): (f64, f64)) {
    println!("{label}: order {p:.3} (finest error {e:.2e})");
    assert!((p - 4.0).abs() < 0.15, "{label}: order {p:.3}");
}

#[test]
fn rk4_and_rkmk4_are_order_4_against_axisymmetric_closed_form() {
    let (i, i3) = (1.0, 2.5);
    let body = RigidBody::principal([i, i, i3]).unwrap();
    let pi0 = Vector3::new(0.6, -0.4, 1.3);
    let t = 4.0;
    let reference = axisymmetric_exact(i, i3, &r0(), &pi0, t);
    let mk_rk4 = || QuaternionRk4::new(body.clone(), pi0, Some(g0())).unwrap();
    let mk_rkmk = || Rkmk4::new(body.clone(), pi0, Some(g0())).unwrap();
    assert_order_4("rk4 axisymmetric", order(mk_rk4, t, &reference, pi0.norm()));
    assert_order_4(
        "rkmk4 axisymmetric",
        order(mk_rkmk, t, &reference, pi0.norm()),
    );
}

#[test]
fn rk4_and_rkmk4_are_order_4_against_tiny_step_reference_for_asymmetric_body() {
    let inertia = Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 3.0);
    let body = RigidBody::new(inertia).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, -0.7);
    let t = 4.0;
    // Matrix RK4 (tests/common, independent of the crate) with h = 2e-4: error ~1e-15.
    let reference = rk4_reference(&inertia, &r0(), &pi0, t, 20_000);
    let mk_rk4 = || QuaternionRk4::new(body.clone(), pi0, Some(g0())).unwrap();
    let mk_rkmk = || Rkmk4::new(body.clone(), pi0, Some(g0())).unwrap();
    assert_order_4("rk4 asymmetric", order(mk_rk4, t, &reference, pi0.norm()));
    assert_order_4(
        "rkmk4 asymmetric",
        order(mk_rkmk, t, &reference, pi0.norm()),
    );
}

#[test]
fn rk4_and_rkmk4_are_order_4_on_heavy_top() {
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.5, 2.0));
    let top = TestHeavyTop {
        body: RigidBody::new(inertia).unwrap(),
        mgchi: Vector3::new(0.1, -0.2, 1.0),
    };
    let pi0 = Vector3::new(0.3, 0.8, 1.1);
    let t = 4.0;
    let reference = rk4_heavy_top(&inertia, &top.mgchi, &r0(), &pi0, t, 20_000);
    let mk_rk4 = || QuaternionRk4::new(top.clone(), pi0, Some(g0())).unwrap();
    let mk_rkmk = || Rkmk4::new(top.clone(), pi0, Some(g0())).unwrap();
    assert_order_4("rk4 heavy top", order(mk_rk4, t, &reference, pi0.norm()));
    assert_order_4("rkmk4 heavy top", order(mk_rkmk, t, &reference, pi0.norm()));
}

/// RKMK4 is generic over the group: on SE(3) (Euler–Arnold, a free body in space) it is order 4
/// against itself at h/64, and that reference agrees with the Lie–Poisson Cayley θ = ½ integrator
/// (an independent discretization of the same equations, order 2) to its error.
#[test]
fn rkmk4_is_order_4_on_se3_and_agrees_with_lie_poisson() {
    let inertia = Matrix6::from_diagonal(&Vector6::new(1.0, 2.0, 3.0, 2.0, 2.0, 2.0));
    let system = EulerArnold::<Se3>::new(inertia).unwrap();
    let mu0 = Vector6::new(0.4, -0.6, 0.9, 0.5, 0.2, -0.3);
    let t = 4.0;
    let run_se3 = |n: usize| {
        let mut m = Rkmk4::new(system.clone(), mu0, Some(Se3::identity())).unwrap();
        integrators::integrate(&mut m, t / n as f64, n, |_| {}).unwrap();
        (*m.configuration().unwrap(), m.momentum())
    };
    let (g_ref, mu_ref) = run_se3(160 * 64);
    let (mut hs, mut errs) = (vec![], vec![]);
    for n in STEPS {
        let (g, mu) = run_se3(n);
        hs.push(t / n as f64);
        errs.push(g.matrix_distance(&g_ref).max((mu - mu_ref).amax()));
    }
    assert_order_4("rkmk4 SE(3)", (fitted_order(&hs, &errs), errs[3]));

    let n = 4000;
    let mut lp =
        LiePoisson::<Se3, Cayley, _>::new(system.clone(), 0.5, mu0, Some(Se3::identity())).unwrap();
    integrators::integrate(&mut lp, t / n as f64, n, |_| {}).unwrap();
    let diff = lp
        .configuration()
        .unwrap()
        .matrix_distance(&g_ref)
        .max((lp.momentum() - mu_ref).amax());
    // LP θ = ½ is order 2 with an error constant ~1: at h = 1e-3 its error is ~1e-6.
    println!("LP Cayley θ=½ (h = 1e-3) vs RKMK4 reference on SE(3): {diff:.2e}");
    assert!(diff < 1e-5, "LP and RKMK4 disagree on SE(3): {diff:e}");
}

fn orthogonality(r: &So3) -> f64 {
    (r.as_matrix().transpose() * r.as_matrix() - Matrix3::identity()).amax()
}

#[test]
fn rkmk4_and_rk4_keep_rotation_orthogonal_to_round_off_over_1e5_steps() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let mut rkmk = Rkmk4::new(body.clone(), pi0, Some(g0())).unwrap();
    let mut rk4 = QuaternionRk4::new(body, pi0, Some(g0())).unwrap();
    integrators::integrate(&mut rkmk, 0.05, 100_000, |_| {}).unwrap();
    integrators::integrate(&mut rk4, 0.05, 100_000, |_| {}).unwrap();
    let (e_mk, e_q) = (
        orthogonality(rkmk.configuration().unwrap()),
        orthogonality(rk4.configuration().unwrap()),
    );
    println!("‖RᵀR − I‖ after 1e5 steps: rkmk4 {e_mk:.2e}, rk4 {e_q:.2e}");
    // RKMK4 multiplies by exp(Θ), orthogonal to ~1e-16 each: a random walk of 1e5 such errors
    // is ~1e-14 (a linear drift would reach 1e-11). The quaternion is renormalised every step, so
    // R(q) is orthogonal to a few ulps whatever the history.
    assert!(e_mk < 1e-13, "rkmk4 orthogonality {e_mk:e}");
    assert!(e_q < 1e-14, "rk4 orthogonality {e_q:e}");
}

/// Maximum relative energy error over each of `chunks` equal pieces of `steps` steps.
fn energy_error_by_chunk<I: Integrator>(
    mut integ: I,
    h: f64,
    steps: usize,
    chunks: usize,
) -> Vec<f64> {
    let e0 = integ.energy();
    let mut out = vec![0.0f64; chunks];
    for k in 0..steps {
        integ.step(h).unwrap();
        let c = k * chunks / steps;
        out[c] = out[c].max(((integ.energy() - e0) / e0).abs());
    }
    out
}

/// The honest trade: at a moderate step h = 0.1 RK4's energy error grows secularly (linearly in
/// t), while the Lie–Poisson θ = ½ Cayley integrator's stays bounded. RK4's error is much smaller
/// over this horizon (order 4 against 2): measured 6.8e-7 per 5000 time units against a constant
/// 1.0e-4, so at h = 0.1 RK4 only loses after T ≈ 7e5 (see docs/work-precision.md).
#[test]
fn rk4_energy_drifts_secularly_where_lie_poisson_stays_bounded() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let (h, steps) = (0.1, 200_000);
    let rk4 = energy_error_by_chunk(
        QuaternionRk4::new(body.clone(), pi0, None).unwrap(),
        h,
        steps,
        4,
    );
    let lp = energy_error_by_chunk(
        LiePoisson::<So3, Cayley, _>::new(body, 0.5, pi0, None).unwrap(),
        h,
        steps,
        4,
    );
    println!("max relative energy error per quarter of T = 2e4, h = 0.1: rk4 {rk4:?}, lp {lp:?}");
    // RK4: the maximum over the k-th quarter is ≈ k × the first (linear drift); a bounded
    // oscillation would give a ratio ≈ 1, a quadratic drift ≈ 16.
    let ratio = rk4[3] / rk4[0];
    assert!((3.5..4.5).contains(&ratio), "rk4 drift not linear: {rk4:?}");
    assert!(
        rk4.windows(2).all(|w| w[1] > w[0] * 1.2),
        "rk4 not drifting: {rk4:?}"
    );
    // LP: bounded, the last quarter's maximum within 1 % of the first's.
    assert!((lp[3] / lp[0] - 1.0).abs() < 0.01, "lp drifting: {lp:?}");
}

#[test]
fn reconstruction_is_optional_and_does_not_change_the_momentum() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let mut a = QuaternionRk4::new(body.clone(), pi0, Some(g0())).unwrap();
    let mut b = QuaternionRk4::new(body.clone(), pi0, None).unwrap();
    let mut c = Rkmk4::new(body.clone(), pi0, Some(g0())).unwrap();
    let mut d = Rkmk4::new(body, pi0, None).unwrap();
    for _ in 0..100 {
        a.step(0.05).unwrap();
        b.step(0.05).unwrap();
        c.step(0.05).unwrap();
        d.step(0.05).unwrap();
    }
    // Without a potential Π does not depend on R: the same floating-point operations.
    assert_eq!(a.momentum(), b.momentum());
    assert_eq!(c.momentum(), d.momentum());
    assert!(b.configuration().is_none() && d.configuration().is_none());
}

#[test]
fn bad_input_is_refused_and_a_failed_step_leaves_the_state_untouched() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let nan = Vector3::new(f64::NAN, 0.0, 0.0);
    assert!(matches!(
        QuaternionRk4::new(body.clone(), nan, None),
        Err(IntegratorError::NonFinite { .. })
    ));
    assert!(matches!(
        Rkmk4::new(body.clone(), nan, None),
        Err(IntegratorError::NonFinite { .. })
    ));
    let top = TestHeavyTop {
        body: body.clone(),
        mgchi: Vector3::z(),
    };
    assert!(matches!(
        QuaternionRk4::new(top.clone(), Vector3::x(), None),
        Err(IntegratorError::MissingConfiguration)
    ));
    assert!(matches!(
        Rkmk4::new(top, Vector3::x(), None),
        Err(IntegratorError::MissingConfiguration)
    ));

    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let mut rk4 = QuaternionRk4::new(body.clone(), pi0, Some(g0())).unwrap();
    let mut rkmk = Rkmk4::new(body, pi0, Some(g0())).unwrap();
    for h in [f64::NAN, f64::INFINITY, 1e300] {
        assert!(rk4.step(h).is_err(), "rk4 accepted h = {h}");
        assert!(rkmk.step(h).is_err(), "rkmk4 accepted h = {h}");
        assert_eq!((rk4.time(), rk4.momentum()), (0.0, pi0));
        assert_eq!((rkmk.time(), rkmk.momentum()), (0.0, pi0));
        assert_eq!(rk4.configuration().unwrap(), &g0());
        assert_eq!(rkmk.configuration().unwrap(), &g0());
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// For random Π and R, one step of each baseline keeps R orthogonal to round-off, and its
    /// energy and Casimir errors are O(h⁵) small (not zero: neither method conserves them).
    #[test]
    fn one_step_keeps_rotation_and_changes_invariants_by_o_h5(
        p in prop::array::uniform3(-2.0f64..2.0),
        w in prop::array::uniform3(-3.0f64..3.0),
        h in 0.001f64..0.05,
    ) {
        let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
        let pi0 = Vector3::from(p);
        prop_assume!(pi0.norm() > 0.1);
        let r0 = So3::exp(&Vector3::from(w));
        let e0 = body.hamiltonian(&pi0);
        let c0 = pi0.norm_squared();
        let mut rk4 = QuaternionRk4::new(body.clone(), pi0, Some(r0)).unwrap();
        let mut rkmk = Rkmk4::new(body, pi0, Some(r0)).unwrap();
        rk4.step(h).unwrap();
        rkmk.step(h).unwrap();
        // |Ω| ≤ |Π| / min I = 2√3: the local error is ≤ C (h|Ω|)⁵ |Π| with C ~ 1e-2.
        let bound = 1e-12 + ((h * 3.5).powi(5)) * 10.0;
        for integ in [&rk4 as &dyn Integrator<Group = So3>, &rkmk] {
            prop_assert!(orthogonality(integ.configuration().unwrap()) < 1e-14);
            prop_assert!(((integ.energy() - e0) / e0).abs() < bound);
            prop_assert!(((integ.casimir().unwrap() - c0) / c0).abs() < bound);
        }
    }
}
