//! The explicit splittings (`integrators::splitting`): the coefficient tables' orders, the pieces
//! of every system, fitted orders against independent references, invariants over long runs,
//! reversibility, fast spins, and bad input.

use crate::common::*;
use integrators::splitting::{KineticKick, SplitSystem, Splitting, SplittingScheme};
use integrators::{
    Composition, CompositionScheme, Integrator, IntegratorError, QuaternionRk4, StateSnapshot,
};
use lie_groups::{LieGroup, Se2, Se3, So3, Vector};
use mechanics::exact::{AxisymmetricFlow, FreeBodyFlow};
use mechanics::systems::{HeavyTop, PlanarBody, RigidBody, RigidBodySe3};
use nalgebra::{Matrix3, Matrix4, Vector3, Vector6};

/// ‖Ψ_h − e^{h(A+B)}‖ for the scheme's product of matrix exponentials.
fn local_error(scheme: &SplittingScheme, a: &Matrix4<f64>, b: &Matrix4<f64>, h: f64) -> f64 {
    let mut psi = Matrix4::identity();
    for (i, &ai) in scheme.a().iter().enumerate() {
        psi = (a * (ai * h)).exp() * psi;
        if let Some(&bi) = scheme.b().get(i) {
            psi = (b * (bi * h)).exp() * psi;
        }
    }
    (psi - (a + b).scale(h).exp()).amax()
}

/// Every table: Σa = Σb = 1, palindromic, and the local error of e^{h(A+B)} for random
/// non-commuting 4×4 matrices falls as h^{p+1} (fitted within 0.2).
/// A wrong digit in the fifth place already drops the order (checked by editing a coefficient).
#[test]
fn splitting_schemes_have_their_order_on_non_commuting_matrices() {
    let a = Matrix4::from_fn(|i, j| ((3 * i + 7 * j) % 5) as f64 * 0.15 - 0.25);
    let b = Matrix4::from_fn(|i, j| ((5 * i + 2 * j) % 7) as f64 * 0.1 - 0.3);
    assert!((a * b - b * a).amax() > 0.02);
    for scheme in SplittingScheme::builtin() {
        let (sa, sb): (f64, f64) = (scheme.a().iter().sum(), scheme.b().iter().sum());
        assert!(
            (sa - 1.0).abs() < 1e-15 && (sb - 1.0).abs() < 1e-15,
            "{}",
            scheme.name()
        );
        assert!(
            scheme.a().iter().eq(scheme.a().iter().rev()),
            "{}",
            scheme.name()
        );
        assert!(
            scheme.b().iter().eq(scheme.b().iter().rev()),
            "{}",
            scheme.name()
        );
        // Steps in each scheme's asymptotic range, above the round-off floor of its error.
        let hs: &[f64] = match scheme.order() {
            2 => &[0.05, 0.035, 0.025, 0.0175, 0.0125],
            4 => &[0.1, 0.07, 0.05, 0.035, 0.025],
            _ => &[0.4, 0.28, 0.2, 0.14],
        };
        let errs: Vec<f64> = hs
            .iter()
            .map(|&h| local_error(&scheme, &a, &b, h))
            .collect();
        let p = fitted_order(hs, &errs);
        println!("{}: local order {p:.2}, errors {errs:?}", scheme.name());
        let want = f64::from(scheme.order() + 1);
        assert!((p - want).abs() < 0.2, "{}: local order {p}", scheme.name());
    }
}

/// Σᵢ ξᵢ(μ) = ∂h/∂μ(μ) for every system that declares a splitting, each piece's flow solves
/// `μ̇ = ad*_ξ μ` at t = 0, and ξᵢ is constant along its own flow — but for the free body's
/// axisymmetric piece (piece 1 of `RigidBody`, `HeavyTop` and `RigidBodySe3`), a closed form whose
/// velocity turns with Π, checked against the exact axisymmetric flow and against products of
/// one-parameter flows below.
#[test]
fn pieces_sum_to_the_velocity_and_are_constant_along_their_flows() {
    fn check<G: LieGroup, S: SplitSystem<G>>(s: &S, mu: G::Algebra, g: G, name: &str) {
        let closed_form =
            ["free body", "full tensor", "heavy top", "SE(3) satellite"].contains(&name);
        let mut sum = G::Algebra::zeros(G::dim());
        for i in 0..s.pieces() {
            let xi = s.piece_velocity(i, &mu);
            sum = sum.add(&xi);
            let (mut m, mut gg) = (mu.clone(), g.clone());
            s.piece_flow(i, 0.7, &mut m, Some(&mut gg));
            let after = s.piece_velocity(i, &m);
            assert!(
                (closed_form && i == 1) || after.sub(&xi).norm() < 1e-14,
                "{name}: piece {i} velocity moves"
            );
            // The flow solves μ̇ = ad*_ξ μ: compare with a central difference at t = 0.
            let d = 1e-6;
            let (mut mp, mut mm) = (mu.clone(), mu.clone());
            s.piece_flow(i, d, &mut mp, None);
            s.piece_flow(i, -d, &mut mm, None);
            let rate = mp.sub(&mm).scale(0.5 / d);
            let want = G::ad_dual_apply(&xi, &mu);
            assert!(
                rate.sub(&want).norm() < 1e-8,
                "{name}: piece {i} is not μ̇ = ad*_ξ μ"
            );
        }
        assert!(
            sum.sub(&s.velocity(&mu)).norm() < 1e-14,
            "{name}: Σξᵢ ≠ ∂h/∂μ"
        );
    }
    let g3 = So3::exp(&Vector3::new(0.3, -0.2, 0.9));
    let pi = Vector3::new(0.4, -1.1, 0.7);
    check(
        &RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
        pi,
        g3,
        "free body",
    );
    let full = Matrix3::new(2.0, 0.1, 0.3, 0.1, 3.0, -0.2, 0.3, -0.2, 4.0);
    check(&RigidBody::new(full).unwrap(), pi, g3, "full tensor");
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    check(&top, pi, g3, "heavy top");
    let sat = RigidBodySe3::satellite(
        2.0,
        Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        1.0,
    )
    .unwrap();
    let g6 = Se3::exp(&Vector6::new(0.2, 0.1, -0.3, 3.0, 0.5, -0.2));
    check(
        &sat,
        Vector6::new(0.3, -0.4, 0.5, 0.1, 0.9, -0.2),
        g6,
        "SE(3) satellite",
    );
    let planar = PlanarBody::free(2.0, 0.5).unwrap();
    check(
        &planar,
        Vector3::new(0.7, 0.2, -0.4),
        Se2::exp(&Vector3::new(0.3, 1.0, 2.0)),
        "SE(2)",
    );
}

/// Fitted order of `make()` integrated to t with each n of `steps`, against `reference`.
fn order_of<I: Integrator<Group = So3>>(
    make: impl Fn() -> I,
    t: f64,
    steps: &[usize],
    reference: &(Matrix3<f64>, Vector3<f64>),
    scale: f64,
) -> (f64, f64) {
    let mut hs = vec![];
    let mut errs = vec![];
    for &n in steps {
        let got = run(make(), t / n as f64, n).unwrap();
        hs.push(t / n as f64);
        errs.push(error_vs(reference, &got, scale));
    }
    (fitted_order(&hs, &errs), *errs.last().unwrap())
}

/// Strang is order 2 and its compositions 4 and 6 on an asymmetric free body, with a full inertia
/// tensor and a diagonal one (against RK4 at h = 1e-4); each matches the order it declares. On an
/// axisymmetric body Strang is the closed form itself, to round-off, in 1, 3 or 20 steps.
#[test]
fn strang_and_its_compositions_have_their_orders_on_the_free_body() {
    let g0 = So3::from_matrix(&r0()).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, -0.7);
    let t = 2.0;
    let full = Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 3.0);
    let cases = [
        (
            RigidBody::new(full).unwrap(),
            rk4_reference(&full, &r0(), &pi0, t, 20_000),
        ),
        (
            RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
            rk4_reference(
                &Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
                &r0(),
                &pi0,
                t,
                20_000,
            ),
        ),
        (
            RigidBody::principal([1.0, 1.0, 2.5]).unwrap(),
            axisymmetric_exact(1.0, 2.5, &r0(), &pi0, t),
        ),
    ];
    for (k, (body, reference)) in cases.iter().enumerate() {
        let strang = || Splitting::new(body.clone(), pi0, Some(g0)).unwrap();
        if k == 2 {
            // Axisymmetric: the perturbation vanishes and Strang is the exact flow, at any step.
            for n in [1, 3, 20] {
                let got = run(strang(), t / f64::from(n), n as usize).unwrap();
                let e = error_vs(reference, &got, pi0.norm());
                assert!(e < 1e-14, "axisymmetric body, {n} steps: error {e:.2e}");
            }
            continue;
        }
        let (p, e) = order_of(strang, t, &[20, 40, 80, 160], reference, pi0.norm());
        println!("strang: order {p:.3}, finest error {e:.2e}");
        assert!(
            (p - f64::from(strang().info().order)).abs() < 0.2,
            "strang order {p}"
        );
        for scheme in [
            CompositionScheme::triple_jump(4).unwrap(),
            CompositionScheme::kahan_li_6(),
        ] {
            let make = || Composition::new(strang(), scheme.clone()).unwrap();
            let (p, e) = order_of(make, t, &[10, 14, 20, 28], reference, pi0.norm());
            println!("{}: order {p:.3}, finest error {e:.2e}", scheme.name());
            assert!(
                (p - f64::from(make().info().order)).abs() < 0.2,
                "{} order {p}",
                scheme.name()
            );
        }
    }
}

/// The heavy top: Strang order 2 (against RK4 at h = 1e-4).
#[test]
fn strang_is_second_order_on_the_heavy_top() {
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0));
    let chi = Vector3::new(0.1, 0.2, 0.5);
    let top = HeavyTop::new(inertia, 1.0, 9.81, chi).unwrap();
    let pi0 = Vector3::new(0.3, 1.0, 2.0);
    let t = 1.0;
    let reference = rk4_heavy_top(&inertia, &(chi * 9.81), &r0(), &pi0, t, 10_000);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let make = || Splitting::new(top.clone(), pi0, Some(g0)).unwrap();
    let (p, e) = order_of(make, t, &[40, 80, 160, 320], &reference, pi0.norm());
    println!("heavy top strang: order {p:.3}, finest {e:.2e}");
    assert!((p - 2.0).abs() < 0.2, "order {p}");
}

/// Exact kinetic flow + kicks on the Lagrange top (axisymmetric, χ on the axis): Strang,
/// Blanes–Moan 4 and 6 have orders 2, 4, 6 against RK4 at h = 5e-5, also with a fast spin
/// (Π₃ = 20) that the kinetic flow takes exactly.
#[test]
fn kinetic_kick_schemes_have_their_orders_on_the_lagrange_top() {
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.4));
    let chi = Vector3::new(0.0, 0.0, 0.3);
    let top = HeavyTop::new(inertia, 1.0, 9.81, chi).unwrap();
    let flow = AxisymmetricFlow::new(top.body()).unwrap();
    let g0 = So3::from_matrix(&r0()).unwrap();
    for pi0 in [Vector3::new(0.3, -0.5, 1.0), Vector3::new(0.3, -0.5, 20.0)] {
        let t = 1.0;
        let reference = rk4_heavy_top(&inertia, &(chi * 9.81), &r0(), &pi0, t, 40_000);
        for scheme in SplittingScheme::builtin() {
            let make = || {
                KineticKick::new(top.clone(), flow.clone(), scheme.clone(), pi0, Some(g0)).unwrap()
            };
            let steps: &[usize] = if scheme.order() == 6 {
                &[11, 16, 22, 32]
            } else {
                &[10, 20, 40, 80]
            };
            let (p, e) = order_of(make, t, steps, &reference, pi0.norm());
            println!(
                "|Π| = {:.1}, {}: order {p:.3}, finest {e:.2e}",
                pi0.norm(),
                scheme.name()
            );
            assert!(
                (p - f64::from(make().info().order)).abs() < 0.2,
                "{}: order {p}",
                scheme.name()
            );
        }
    }
}

/// Exact asymmetric free-body flow (`FreeBodyFlow`, Jacobi elliptic functions) + kicks on an
/// asymmetric heavy top with a full inertia tensor and a fast spin: Strang, Blanes–Moan 4 and 6
/// have orders 2, 4, 6 against RK4 at h = 2.5e-5.
#[test]
fn exact_kinetic_flow_kicks_have_their_orders_on_an_asymmetric_heavy_top() {
    let inertia = Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 3.0);
    let chi = Vector3::new(0.1, 0.2, 0.5);
    let top = HeavyTop::new(inertia, 1.0, 9.81, chi).unwrap();
    let flow = FreeBodyFlow::new(top.body());
    let g0 = So3::from_matrix(&r0()).unwrap();
    let pi0 = Vector3::new(1.0, -2.0, 12.0);
    let t = 1.0;
    let reference = rk4_heavy_top(&inertia, &(chi * 9.81), &r0(), &pi0, t, 40_000);
    for scheme in SplittingScheme::builtin() {
        let make =
            || KineticKick::new(top.clone(), flow.clone(), scheme.clone(), pi0, Some(g0)).unwrap();
        let steps: &[usize] = if scheme.order() == 6 {
            &[11, 16, 22, 32]
        } else {
            &[10, 20, 40, 80]
        };
        let (p, e) = order_of(make, t, steps, &reference, pi0.norm());
        println!("{}: order {p:.3}, finest {e:.2e}", scheme.name());
        assert!(
            (p - f64::from(make().info().order)).abs() < 0.2,
            "{}: order {p}",
            scheme.name()
        );
    }
}

/// Without a potential, the kinetic–kick integrator is the exact flow (one step of any size
/// lands on the closed form).
#[test]
fn kinetic_kick_without_potential_is_the_exact_flow() {
    let body = RigidBody::principal([1.0, 1.0, 2.5]).unwrap();
    let flow = AxisymmetricFlow::new(&body).unwrap();
    let pi0 = Vector3::new(0.6, -0.4, 1.3);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let mut k =
        KineticKick::new(body, flow, SplittingScheme::blanes_moan_4(), pi0, Some(g0)).unwrap();
    k.step(7.3).unwrap();
    let (r, p) = axisymmetric_exact(1.0, 2.5, &r0(), &pi0, 7.3);
    assert!(
        (k.momentum() - p).amax() < 1e-14
            && (k.configuration().unwrap().as_matrix() - r).amax() < 1e-14
    );
    assert!(AxisymmetricFlow::new(&RigidBody::principal([1.0, 2.0, 3.0]).unwrap()).is_err());
}

/// Casimir |Π|² and the spatial momentum RΠ at round-off over 10⁶ Strang steps of the free body:
/// no worse than the random walk of the plane rotations carried from step to step (two a step:
/// the merged outer one and the inner one), each rounding c² + s² = 1 by ≲ 1 ulp, whose standard
/// deviation is 2ε√(2·10⁶) ≈ 3e-13: the maximum over the run is checked at 1e-12 (measured
/// 1.8e-13 and 6.6e-14; 5.1e-13 and 2.0e-13 with the principal-axis splitting's five rotations
/// a step; a biased rounding, 1 ulp per rotation, would reach 1e-9), R on SO(3).
#[test]
fn strang_keeps_casimir_and_momentum_map_over_a_million_steps() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let m0 = r0() * pi0;
    let mut s = Splitting::new(body, pi0, Some(g0)).unwrap();
    let (mut dc, mut dm) = (0.0f64, 0.0f64);
    for k in 0..1_000_000 {
        s.step(0.01).unwrap();
        if k % 1000 == 999 {
            let p = s.momentum();
            dc = dc.max((p.norm_squared() - pi0.norm_squared()).abs() / pi0.norm_squared());
            dm = dm.max((s.configuration().unwrap().as_matrix() * p - m0).amax() / m0.norm());
        }
    }
    let r = s.configuration().unwrap().as_matrix();
    println!(
        "Casimir {dc:.2e}, momentum map {dm:.2e}, ‖RᵀR − I‖ {:.2e}",
        (r.transpose() * r - Matrix3::identity()).amax()
    );
    assert!(
        dc < 1e-12 && dm < 1e-12,
        "Casimir {dc:e}, momentum map {dm:e}"
    );
    assert!((r.transpose() * r - Matrix3::identity()).amax() < 1e-14);
}

/// Energy bounded with no drift over 10⁷ steps (first against last tenth) for the free body and
/// the heavy top (Strang), and over 10⁶ steps for the exact-flow kicks on an asymmetric top.
#[test]
fn splitting_energy_does_not_drift() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let g0 = So3::from_matrix(&r0()).unwrap();
    let s = Splitting::new(body, Vector3::new(0.4, 1.0, 0.3), Some(g0)).unwrap();
    let (first, last) = energy_error_tenths(s, 0.05, 10_000_000);
    println!("free body: first tenth {first:.2e}, last tenth {last:.2e}");
    assert!(last < 1.5 * first, "drift: {first:e} → {last:e}");
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    let s = Splitting::new(top.clone(), Vector3::new(0.3, 1.0, 2.0), Some(g0)).unwrap();
    let (first, last) = energy_error_tenths(s, 0.01, 10_000_000);
    println!("heavy top: first tenth {first:.2e}, last tenth {last:.2e}");
    assert!(last < 1.5 * first, "drift: {first:e} → {last:e}");
    let flow = FreeBodyFlow::new(top.body());
    let k = KineticKick::new(
        top,
        flow,
        SplittingScheme::strang(),
        Vector3::new(0.3, 1.0, 2.0),
        Some(g0),
    )
    .unwrap();
    let (first, last) = energy_error_tenths(k, 0.01, 1_000_000);
    println!("heavy top, exact-flow kicks: first tenth {first:.2e}, last tenth {last:.2e}");
    assert!(last < 1.5 * first, "drift: {first:e} → {last:e}");
}

/// Symmetric methods are time-reversible: n steps forward then n back return to the start, to the
/// round-off accumulated over 200 steps of 23 sub-flows (≲ 1e-12; a non-symmetric method of order p
/// would miss by ~n hᵖ⁺¹, 1e-5 for Strang and 1e-7 for Blanes–Moan 6 here).
#[test]
fn splittings_are_reversible() {
    let top = HeavyTop::principal([1.0, 1.0, 0.4], 1.0, 9.81, Vector3::new(0.0, 0.0, 0.3)).unwrap();
    let flow = AxisymmetricFlow::new(top.body()).unwrap();
    let pi0 = Vector3::new(0.3, 1.0, 2.0);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let mut a = Splitting::new(top.clone(), pi0, Some(g0)).unwrap();
    let mut b =
        KineticKick::new(top, flow, SplittingScheme::blanes_moan_6(), pi0, Some(g0)).unwrap();
    for _ in 0..200 {
        a.step(0.1).unwrap();
        b.step(0.1).unwrap();
    }
    for _ in 0..200 {
        a.step(-0.1).unwrap();
        b.step(-0.1).unwrap();
    }
    for (name, p, g) in [
        ("strang", a.momentum(), *a.configuration().unwrap()),
        ("kinetic-kick", b.momentum(), *b.configuration().unwrap()),
    ] {
        let e = (p - pi0).amax().max((g.as_matrix() - r0()).amax());
        println!("{name}: back by {e:.2e}");
        assert!(e < 1e-11, "{name}: back by {e:e}");
    }
}

/// A fast-spinning body, |Π| ≈ 100 with h|Ω| from 0.1 to 5: Strang keeps the Casimir at
/// round-off and the energy bounded (relative error < 1 over 10⁴ steps); from h|Ω| = 1 on, RK4
/// at the same step drifts by more or diverges.
#[test]
fn fast_spin_keeps_invariants_where_rk4_fails() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(60.0, 50.0, -40.0);
    let omega = body.angular_velocity(&pi0).norm();
    let g0 = So3::from_matrix(&r0()).unwrap();
    for hw in [0.1, 1.0, 5.0] {
        let h = hw / omega;
        let mut s = Splitting::new(body.clone(), pi0, Some(g0)).unwrap();
        let mut rk = QuaternionRk4::new(body.clone(), pi0, Some(g0)).unwrap();
        let e0 = s.energy();
        let (mut de, mut dc, mut de_rk) = (0.0f64, 0.0f64, 0.0f64);
        for _ in 0..10_000 {
            s.step(h).unwrap();
            de = de.max((s.energy() - e0).abs() / e0);
            dc = dc.max((s.casimir().unwrap() - pi0.norm_squared()).abs() / pi0.norm_squared());
            if rk.step(h).is_ok() {
                de_rk = de_rk.max(((rk.energy() - e0) / e0).abs());
            } else {
                de_rk = f64::INFINITY;
            }
        }
        println!("h|Ω| = {hw}: strang ΔE {de:.2e} ΔC {dc:.2e}; rk4 ΔE {de_rk:.2e}");
        assert!(dc < 1e-13, "Casimir {dc:e}");
        assert!(de < 1.0, "energy {de:e}");
        if hw >= 1.0 {
            assert!(de < de_rk, "energy {de:e} against RK4 {de_rk:e}");
        }
    }
}

/// NaN and infinite steps are refused with the state untouched; a system with a potential needs g.
#[test]
fn bad_input_is_refused_and_leaves_the_state() {
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    let pi0 = Vector3::new(0.3, 1.0, 2.0);
    assert_eq!(
        Splitting::new(top.clone(), pi0, None).unwrap_err(),
        IntegratorError::MissingConfiguration
    );
    let mut s = Splitting::new(top.clone(), pi0, Some(So3::identity())).unwrap();
    s.step(0.1).unwrap();
    let before = s.snapshot();
    for h in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(s.step(h).is_err());
        assert_eq!(s.snapshot(), before);
    }
    assert!(Splitting::new(top, Vector3::new(f64::NAN, 0.0, 0.0), Some(So3::identity())).is_err());
    assert!(SplittingScheme::by_name("verlet-9").is_err());
}

/// The free body's piece 1 is the exact flow of the axisymmetric body with moments I_r about a_r
/// and a_p and I_s about a_s ([`RigidBody::split_axes`]), compared with `FreeBodyFlow` (the
/// closed form of `AxisymmetricFlow`) for a diagonal and a full tensor, forward and backward,
/// slow and fast; piece 0 is the rotation about a_p at the rate (1/I_p − 1/I_r)(a_p·Π).
#[test]
fn free_body_pieces_are_an_axisymmetric_body_and_a_principal_rotation() {
    let full = Matrix3::new(2.0, 0.1, 0.3, 0.1, 3.0, -0.2, 0.3, -0.2, 4.0);
    let g0 = So3::exp(&Vector3::new(0.3, -0.2, 0.9));
    for inertia in [Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0)), full] {
        let body = RigidBody::new(inertia).unwrap();
        let (axes, moments) = body.principal_frame();
        let [r, p, s] = body.split_axes();
        let mut sorted = [moments[0], moments[1], moments[2]];
        sorted.sort_by(f64::total_cmp);
        assert_eq!(moments[r], sorted[1], "the reference is the middle moment");
        let dyad = |i: usize| axes.column(i) * axes.column(i).transpose();
        let axisymmetric =
            RigidBody::new((dyad(r) + dyad(p)) * moments[r] + dyad(s) * moments[s]).unwrap();
        let exact = FreeBodyFlow::new(&axisymmetric);
        for (t, pi) in [
            (0.7, Vector3::new(0.4, -1.1, 0.7)),
            (-2.3, Vector3::new(0.4, -1.1, 0.7)),
            (0.05, Vector3::new(3.0, 80.0, -40.0)),
        ] {
            let (mut m, mut g) = (pi, g0);
            body.piece_flow(1, t, &mut m, Some(&mut g));
            let (pe, ge) = exact.advance(t, &pi, Some(&g0)).unwrap();
            assert!(
                (m - pe).amax() < 1e-14 * pi.norm(),
                "Π: {:e}",
                (m - pe).amax()
            );
            assert!((g.as_matrix() - ge.unwrap().as_matrix()).amax() < 1e-14);
            let (mut m, mut g) = (pi, g0);
            body.piece_flow(0, t, &mut m, Some(&mut g));
            let a = axes.column(p).into_owned();
            let e = So3::exp(&(a * (t * (1.0 / moments[p] - 1.0 / moments[r]) * a.dot(&pi))));
            assert!((m - e.coadjoint_apply(&pi)).amax() < 1e-14 * pi.norm());
            assert!((g.as_matrix() - g0.compose(&e).as_matrix()).amax() < 1e-14);
        }
    }
}

/// The axisymmetric-plus-rotation split against the principal-axis split, Strang at h = 0.1 and
/// 0.05 to T = 5 against the exact flow, on seven bodies from near-axisymmetric to flat: never
/// worse (≤ 1.05×: the two tie on diag(1, 100, 101), where both are at 3e-8), at least 3× more
/// accurate on five, 10× on the free-body scene's diag(2, 3, 4) (measured 1.0–320×).
#[test]
fn the_axisymmetric_split_beats_the_principal_axes() {
    let g0 = So3::exp(&Vector3::new(0.3, -0.5, 0.2));
    let bodies = [
        ([2.0, 3.0, 4.0], [1.0, 0.5, -0.3], 6.0),
        ([1.0, 2.0, 3.0], [0.4, -1.1, 0.7], 3.0),
        ([1.0, 1.01, 100.0], [0.4, -1.1, 0.7], 100.0),
        ([1.0, 100.0, 101.0], [1.0, 0.3, 0.2], 0.95),
        ([3.0, 2.0, 1.0], [0.1, 1.0, 0.05], 5.0),
        ([1.0, 0.75, 0.25], [0.3, 0.6, 0.8], 5.0),
        ([1.0, 2.0, 1e3], [1.0, 1.0, 1.0], 1.2),
    ];
    for (m, pi, gain) in bodies {
        let body = RigidBody::principal([m[0], m[1], m[2]]).unwrap();
        let pi0 = Vector3::new(pi[0], pi[1], pi[2]);
        let (pe, ge) = FreeBodyFlow::new(&body)
            .advance(5.0, &pi0, Some(&g0))
            .unwrap();
        let reference = (*ge.unwrap().as_matrix(), pe);
        for n in [50, 100] {
            let h = 5.0 / f64::from(n);
            let new = run(
                Splitting::new(body.clone(), pi0, Some(g0)).unwrap(),
                h,
                n as usize,
            );
            let old = run(
                Splitting::new(PrincipalAxes(body.clone()), pi0, Some(g0)).unwrap(),
                h,
                n as usize,
            );
            let (new, old) = (
                error_vs(&reference, &new.unwrap(), pi0.norm()),
                error_vs(&reference, &old.unwrap(), pi0.norm()),
            );
            println!("{m:?}, h = {h}: principal axes {old:.2e}, axisymmetric + rotation {new:.2e}");
            assert!(new * gain <= old * 1.05, "{m:?}: {new:e} against {old:e}");
        }
    }
}

/// First same as last: the merged run equals the Strang sequence applied step by step without
/// merging (φ⁰_{h/2} φ¹_h φ⁰_{h/2}, the kicks around them for the top; g renormalized at the same
/// steps) to round-off (measured 1–2e-14), over 2000 steps of varying size (300 for the chaotic
/// top; the free body tumbles about its largest axis, away from the separatrix, where a rounding
/// grows exponentially); a fresh integrator from a restored state continues bit for bit like a
/// new one (restore starts afresh); the published state is the whole step's (it is not the
/// state before the closing half-flow, which would be off by O(h)).
#[test]
fn merged_outer_flows_equal_the_unmerged_sequence() {
    fn unmerged<S: SplitSystem<So3>>(s: &S, h: f64, mu: &mut Vector3<f64>, g: &mut So3) {
        let kick = |mu: &mut Vector3<f64>, g: &So3| {
            if s.has_potential() {
                *mu -= s.potential_differential(g) * (0.5 * h);
            }
        };
        kick(mu, g);
        let last = s.pieces() - 1;
        for i in 0..last {
            s.piece_flow(i, 0.5 * h, mu, Some(g));
        }
        s.piece_flow(last, h, mu, Some(g));
        for i in (0..last).rev() {
            s.piece_flow(i, 0.5 * h, mu, Some(g));
        }
        kick(mu, g);
    }
    fn check<S: SplitSystem<So3> + Clone>(s: S, steps: usize, name: &str) {
        let (pi0, g0) = (
            Vector3::new(1.2, -0.3, 0.4),
            So3::exp(&Vector3::new(0.3, -0.2, 0.9)),
        );
        let mut merged = Splitting::new(s.clone(), pi0, Some(g0)).unwrap();
        let (mut mu, mut g) = (pi0, g0);
        let mut worst = 0.0_f64;
        for k in 0..steps {
            let h = [0.01, 0.013, 0.007][k % 3];
            merged.step(h).unwrap();
            unmerged(&s, h, &mut mu, &mut g);
            if (k + 1) % integrators::splitting::RENORMALIZE_EVERY as usize == 0 {
                g = g.normalize();
            }
            worst = worst
                .max((merged.momentum() - mu).amax())
                .max((merged.configuration().unwrap().as_matrix() - g.as_matrix()).amax());
        }
        println!("{name}: merged against unmerged, worst {worst:.2e}");
        assert!(worst < 1e-13, "{name}: {worst:e}");
        assert!(worst > 0.0, "{name}: not merged at all?");
        let snapshot = merged.snapshot();
        let mut fresh = Splitting::new(s, snapshot.1, snapshot.2).unwrap();
        fresh.set_time(snapshot.0).unwrap();
        merged.step(0.3).unwrap(); // moves the state before the closing flow away
        merged.restore(snapshot).unwrap();
        for _ in 0..10 {
            merged.step(0.02).unwrap();
            fresh.step(0.02).unwrap();
        }
        assert_eq!(merged.momentum(), fresh.momentum(), "{name}");
        assert_eq!(merged.configuration(), fresh.configuration(), "{name}");
    }
    check(
        RigidBody::principal([1.0, 2.0, 3.0]).unwrap(),
        2000,
        "free body",
    );
    let full = Matrix3::new(2.0, 0.1, 0.3, 0.1, 3.0, -0.2, 0.3, -0.2, 4.0);
    check(RigidBody::new(full).unwrap(), 2000, "full tensor");
    // The top is chaotic here: a rounding grows ×50 per 1000 steps, so 300 steps.
    check(
        HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap(),
        300,
        "heavy top",
    );
}

/// The SE(3) body's pieces against products of one-parameter flows `(g, μ) ↦ (g exp(tξ),
/// Ad*_{exp(tξ)} μ)` formed by `Se3::exp`: piece 0 is that of `(ω_p a_p, 0)`; piece 1 that of
/// `(ω_s a_s, 0)`, then `(Π'/I_r, 0)` at the turned Π', then the translation `(0, P/m)` — three
/// commuting flows. Diagonal and full tensors, forward and backward, to 1e-14.
#[test]
fn se3_body_pieces_are_products_of_one_parameter_flows() {
    let flow = |xi: Vector6<f64>, t: f64, mu: &mut Vector6<f64>, g: &mut Se3| {
        let e = Se3::exp(&(xi * t));
        *mu = e.coadjoint_apply(mu);
        *g = g.compose(&e);
    };
    let full = Matrix3::new(2.0, 0.1, 0.3, 0.1, 3.0, -0.2, 0.3, -0.2, 4.0);
    for inertia in [Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0)), full] {
        let sat = RigidBodySe3::satellite(2.5, inertia, 1.0).unwrap();
        let body = sat.body();
        let (axes, moments) = body.principal_frame();
        let [r, p, s] = body.split_axes();
        let g0 = Se3::exp(&Vector6::new(0.2, 0.1, -0.3, 3.0, 0.5, -0.2));
        for (t, mu0) in [
            (0.7, Vector6::new(0.3, -0.4, 0.5, 0.1, 0.9, -0.2)),
            (-1.9, Vector6::new(-1.3, 0.4, 2.5, 0.7, -0.3, 0.8)),
        ] {
            let pi = mu0.fixed_rows::<3>(0).into_owned();
            let rot = |a: Vector3<f64>| Vector6::new(a.x, a.y, a.z, 0.0, 0.0, 0.0);
            let (ap, as_) = (axes.column(p).into_owned(), axes.column(s).into_owned());
            // Piece 0.
            let (mut m, mut g) = (mu0, g0);
            sat.piece_flow(0, t, &mut m, Some(&mut g));
            let (mut me, mut ge) = (mu0, g0);
            flow(
                rot(ap * ((1.0 / moments[p] - 1.0 / moments[r]) * ap.dot(&pi))),
                t,
                &mut me,
                &mut ge,
            );
            assert!(
                (m - me).amax() < 1e-14 * mu0.amax(),
                "piece 0 μ: {:e}",
                (m - me).amax()
            );
            assert!((g.matrix() - ge.matrix()).amax() < 1e-14, "piece 0 g");
            // Piece 1.
            let (mut m, mut g) = (mu0, g0);
            sat.piece_flow(1, t, &mut m, Some(&mut g));
            let (mut me, mut ge) = (mu0, g0);
            flow(
                rot(as_ * ((1.0 / moments[s] - 1.0 / moments[r]) * as_.dot(&pi))),
                t,
                &mut me,
                &mut ge,
            );
            let turned = me.fixed_rows::<3>(0).into_owned();
            flow(rot(turned / moments[r]), t, &mut me, &mut ge);
            let v = me.fixed_rows::<3>(3).into_owned() / sat.mass();
            flow(
                Vector6::new(0.0, 0.0, 0.0, v.x, v.y, v.z),
                t,
                &mut me,
                &mut ge,
            );
            assert!(
                (m - me).amax() < 1e-14 * mu0.amax(),
                "piece 1 μ: {:e}",
                (m - me).amax()
            );
            assert!(
                (g.matrix() - ge.matrix()).amax() < 1e-13 * g0.matrix().amax(),
                "piece 1 g: {:e}",
                (g.matrix() - ge.matrix()).amax()
            );
        }
    }
}

/// Extremes of the body's splitting: inertia ratios of 10⁶ (either way round, so the reference
/// and the axes change), |Π| from 1e-150 to 1e150, steps h|Ω| of 0.01, 0.5 and 1e150: every state finite, the Casimir within 1e-13 relative over 1000 steps, R orthogonal to
/// 1e-13, and the state scales with Π (a body 1e150 times faster, stepped 1e150 times shorter,
/// follows the same path to round-off).
#[test]
fn extreme_bodies_and_momenta_keep_the_casimir() {
    let g0 = So3::from_matrix(&r0()).unwrap();
    let dir = Vector3::new(0.6, -0.3, 0.74);
    for moments in [[1.0, 1e3, 1e6], [1e6, 1.0, 1e3], [1.0, 1.0 + 1e-12, 1e6]] {
        let body = RigidBody::principal([moments[0], moments[1], moments[2]]).unwrap();
        for scale in [1e-150, 1.0, 1e150] {
            let pi0 = dir * scale;
            let omega = body.angular_velocity(&pi0).norm();
            // 1e150: a step of 1e150 rad too (angles past every range reduction's exactness:
            // still rotations, finite and orthogonal, the Casimir kept).
            for hw in [0.01, 0.5, 1e150] {
                let h = hw / omega;
                let mut s = Splitting::new(body.clone(), pi0, Some(g0)).unwrap();
                let mut dc = 0.0f64;
                for _ in 0..1000 {
                    s.step(h).unwrap();
                    dc = dc.max((s.momentum().norm() / pi0.norm() - 1.0).abs());
                }
                let r = s.configuration().unwrap().as_matrix();
                let orth = (r.transpose() * r - Matrix3::identity()).amax();
                assert!(
                    s.momentum().iter().all(|x| x.is_finite()) && dc < 1e-13 && orth < 1e-13,
                    "{moments:?}, |Π| = {scale:e}, h|Ω| = {hw}: Casimir {dc:e}, ‖RᵀR − I‖ {orth:e}"
                );
                if scale == 1e150 && hw < 1.0 {
                    // The same path as |Π| = 1 in scaled time.
                    let unit = dir;
                    let h1 = hw / body.angular_velocity(&unit).norm();
                    let mut s1 = Splitting::new(body.clone(), unit, Some(g0)).unwrap();
                    for _ in 0..1000 {
                        s1.step(h1).unwrap();
                    }
                    let d = (s.momentum() / scale - s1.momentum()).amax();
                    let dr = (s.configuration().unwrap().as_matrix()
                        - s1.configuration().unwrap().as_matrix())
                    .amax();
                    assert!(
                        d < 1e-10 && dr < 1e-10,
                        "{moments:?}: scaled path off by {d:e}, {dr:e}"
                    );
                }
            }
        }
    }
}
