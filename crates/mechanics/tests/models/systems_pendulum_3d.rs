//! The 3D pendulum (`systems::Pendulum3d`, the heavy top of Lee, Leok and McClamroch): the
//! equilibria; the small-oscillation modes (`K v = ω² J v`) and the linearized motion they give,
//! reached at order 2; the large planar swing's closed form `sin(θ/2) = k sn(K − ω₀t; k)` and its
//! period `4K(k)/ω₀` (K by the arithmetic–geometric mean, written here); a general body (full J,
//! ρ off every axis) against an independent RK4, with the vertical angular momentum to round-off.

use crate::common::*;
use integrators::derivative_check::check_derivatives;
use integrators::splitting::Splitting;
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3};
use mechanics::exact::elliptic::{complete_k, sn_cn_dn};
use mechanics::Pendulum3d;
use nalgebra::{Matrix3, Vector3};

const M: f64 = 1.2;
const G: f64 = 9.81;

/// An elliptic cylinder-like body with a full inertia about the pivot and ρ off every axis.
fn general() -> Pendulum3d {
    Pendulum3d::new(
        Matrix3::new(0.13, 0.01, -0.02, 0.01, 0.28, 0.015, -0.02, 0.015, 0.17),
        M,
        G,
        Vector3::new(0.05, -0.08, 0.3),
    )
    .unwrap()
}

#[test]
fn pendulum_derivatives_match_finite_differences() {
    let p = general();
    let samples = [
        (
            Vector3::new(0.1, -0.2, 0.05),
            Some(So3::from_matrix(&r0()).unwrap()),
        ),
        (
            Vector3::new(-0.3, 0.0, 0.4),
            Some(So3::exp(&Vector3::new(2.0, 1.0, -0.5))),
        ),
    ];
    let report = check_derivatives(&p, &samples);
    assert!(report.passes(1e-8), "{report:?}");
}

/// Hanging (Rρ = −|ρ|e₃) and inverted (Rρ = +|ρ|e₃) attitudes are equilibria: zero torque, and a
/// Lie–Poisson run from rest there stays to round-off — 10 s hanging; 1 s inverted, where the
/// rounding grows as e^{ωt} (ω ≈ 3.6: unstable). A pivot at the centre of mass has none.
#[test]
fn hanging_and_inverted_attitudes_are_equilibria() {
    let p = general();
    let rho = *p.centre_of_mass();
    for (name, r, steps, bound) in [
        ("hanging", p.hanging_attitude().unwrap(), 1000, 1e-14),
        ("inverted", p.inverted_attitude().unwrap(), 100, 1e-13),
    ] {
        let sign = if name == "hanging" { -1.0 } else { 1.0 };
        let down = r.as_matrix() * rho - Vector3::z() * (sign * rho.norm());
        assert!(down.amax() < 1e-15, "{name}: Rρ off the vertical by {down}");
        assert!(
            p.potential_differential(&r).amax() < 1e-15,
            "{name}: torque"
        );
        let mut lp =
            LiePoisson::<So3, Cayley, _>::new(p.clone(), 0.5, Vector3::zeros(), Some(r)).unwrap();
        for _ in 0..steps {
            lp.step(0.01).unwrap();
        }
        let moved = lp.configuration().unwrap().matrix_distance(&r);
        println!(
            "{name}: moved {moved:.1e}, |Π| {:.1e}",
            lp.momentum().amax()
        );
        assert!(
            moved < bound && lp.momentum().amax() < bound,
            "{name}: {moved:e}"
        );
    }
    let centred = Pendulum3d::new(Matrix3::identity(), M, G, Vector3::zeros()).unwrap();
    assert!(centred.hanging_attitude().is_err());
    assert!(centred.small_oscillations().is_err());
}

/// The modes solve `K v = ω² J v` and are J-orthonormal; a symmetric body with ρ = ℓe₃ swings at
/// `√(mgℓ/J₁₁)` and `√(mgℓ/J₂₂)`, and turns freely (ω = 0) about the vertical.
#[test]
fn small_oscillation_modes_solve_the_linearized_problem() {
    let p = general();
    let (w, v) = p.small_oscillations().unwrap();
    let k = p.hanging_stiffness().unwrap();
    let j = *p.inertia();
    for c in 0..3 {
        let res = k * v.column(c) - j * v.column(c) * (w[c] * w[c]);
        assert!(res.amax() < 1e-12, "mode {c}: residual {res}");
    }
    assert!((v.transpose() * j * v - Matrix3::identity()).amax() < 1e-12);
    assert!(w[0] < 1e-7 && w[1] > 1.0, "{w}");
    let ell = 0.3;
    let sym = Pendulum3d::principal([0.2, 0.25, 0.1], M, G, Vector3::new(0.0, 0.0, ell)).unwrap();
    let (ws, _) = sym.small_oscillations().unwrap();
    let want = [0.0, (M * G * ell / 0.25).sqrt(), (M * G * ell / 0.2).sqrt()];
    for i in 0..3 {
        assert!((ws[i] - want[i]).abs() < 1e-12, "{ws} vs {want:?}");
    }
}

/// Small oscillations of the general body about the hanging equilibrium, ε₀ = 1e-5 along the two
/// swinging modes: `R(t) = R_h exp(ε(t)^)`, `ε(t) = Σ αₖ vₖ cos ωₖt`. Lie–Poisson θ = ½ converges
/// to it at order 2 (relative errors 1e-2 … 1e-3, far above the linearization's ε₀² = 1e-10).
#[test]
fn small_oscillations_follow_the_linearized_solution_at_order_2() {
    let p = general();
    let (w, v) = p.small_oscillations().unwrap();
    let rh = p.hanging_attitude().unwrap();
    let eps0 = (v.column(1) + v.column(2) * 0.7) * 1e-5;
    let alpha = v.try_inverse().unwrap() * eps0;
    let t_end = 5.0;
    let linear = |t: f64| -> Vector3<f64> {
        (0..3)
            .map(|k| v.column(k) * (alpha[k] * (w[k] * t).cos()))
            .sum()
    };
    let g0 = rh.compose(&So3::exp(&eps0));
    let error = |h: f64| {
        let mut lp =
            LiePoisson::<So3, ExpMap, _>::new(p.clone(), 0.5, Vector3::zeros(), Some(g0)).unwrap();
        for _ in 0..(t_end / h).round() as usize {
            lp.step(h).unwrap();
        }
        let eps = rh
            .inverse()
            .compose(lp.configuration().unwrap())
            .log()
            .unwrap();
        (eps - linear(t_end)).amax() / eps0.amax()
    };
    let hs = [0.02, 0.01, 0.005];
    let errs = hs.map(error);
    let order = fitted_order(&hs, &errs);
    println!(
        "small oscillations (ω = {:?}): relative errors {errs:?}, order {order:.3}",
        w.as_slice()
    );
    assert!((1.9..=2.1).contains(&order), "order {order}");
}

/// K(k) by the arithmetic–geometric mean, `K = π / (2 AGM(1, √(1 − k²)))` (independent of the
/// crate's Carlson forms).
fn k_agm(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    core::f64::consts::PI / (2.0 * a)
}

/// The planar swing of amplitude θ₀ = 2.5 rad (past the horizontal) of a body with χ = ℓe₃
/// about its principal axis e₁: `sin(θ/2) = k sn(K − ω₀t; k)`, `θ̇ = −2kω₀ cn(K − ω₀t; k)`.
/// Lie–Poisson θ = ½ and Strang converge to it at order 2; the period from the Lie–Poisson run
/// (its Π₁'s sign changes, interpolated linearly, at h = 1e-3) is 4K/ω₀ to 1e-5 relative.
#[test]
fn large_planar_swing_follows_the_elliptic_closed_form() {
    let (i1, ell) = (0.2, 0.3);
    let p = Pendulum3d::principal([i1, 0.25, 0.1], M, G, Vector3::new(0.0, 0.0, ell)).unwrap();
    let theta0: f64 = 2.5;
    let k = (theta0 / 2.0).sin();
    let w0 = (M * G * ell / i1).sqrt();
    let kk = k_agm(k);
    assert!((kk - complete_k(1.0 - k * k)).abs() < 1e-13 * kk);
    let rh = p.hanging_attitude().unwrap();
    let at = |theta: f64| rh.compose(&So3::exp(&Vector3::new(theta, 0.0, 0.0)));
    let exact = |t: f64| {
        let (sn, cn, _) = sn_cn_dn(kk - w0 * t, 1.0 - k * k);
        (2.0 * (k * sn).asin(), -2.0 * k * w0 * cn)
    };
    let t_end = 3.0;
    let (theta_t, rate_t) = exact(t_end);
    let g_exact = at(theta_t);
    let error = |integ: &mut dyn Integrator<Group = So3>, h: f64| {
        for _ in 0..(t_end / h).round() as usize {
            integ.step(h).unwrap();
        }
        integ
            .configuration()
            .unwrap()
            .matrix_distance(&g_exact)
            .max((integ.momentum() - Vector3::new(i1 * rate_t, 0.0, 0.0)).amax() / (i1 * w0))
    };
    let hs = [0.02, 0.01, 0.005];
    let lp = hs.map(|h| {
        error(
            &mut LiePoisson::<So3, Cayley, _>::new(
                p.clone(),
                0.5,
                Vector3::zeros(),
                Some(at(theta0)),
            )
            .unwrap(),
            h,
        )
    });
    let st = hs.map(|h| {
        error(
            &mut Splitting::new(p.clone(), Vector3::zeros(), Some(at(theta0))).unwrap(),
            h,
        )
    });
    for (name, errs) in [("LP cayley θ = ½", lp), ("Strang", st)] {
        let order = fitted_order(&hs, &errs);
        println!("planar swing θ₀ = 2.5, {name}: errors {errs:?}, order {order:.3}");
        assert!((1.9..=2.1).contains(&order), "{name}: order {order}");
    }
    // The period: sign changes of Π₁ (θ̇) at the half periods.
    let h = 1e-3;
    let mut lp =
        LiePoisson::<So3, Cayley, _>::new(p.clone(), 0.5, Vector3::zeros(), Some(at(theta0)))
            .unwrap();
    let mut crossings = Vec::new();
    let mut last = 0.0f64;
    lp.step(h).unwrap();
    while crossings.len() < 4 {
        last = if last == 0.0 { lp.momentum()[0] } else { last };
        lp.step(h).unwrap();
        let now = lp.momentum()[0];
        if now.signum() != last.signum() {
            crossings.push(lp.time() - h * now / (now - last));
        }
        last = now;
    }
    let period = crossings[3] - crossings[1];
    let want = 4.0 * kk / w0;
    println!("period {period:.8} vs 4K/ω₀ = {want:.8}");
    assert!((period - want).abs() < 1e-5 * want, "{period} vs {want}");
}

/// The general body (full J, ρ off the axes) from a tilted, turning start: Lie–Poisson θ = ½
/// (exp, Cayley) at order 2 against RK4 on (R, Π) at h = 2.5e-4 (`crate::common::rk4_heavy_top`),
/// keeping the vertical angular momentum Π·Γ to round-off.
#[test]
fn general_pendulum_converges_to_rk4_and_keeps_the_vertical_momentum() {
    let p = general();
    let pi0 = Vector3::new(0.3, -0.2, 0.25);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let t_end = 3.0;
    let (r_ref, pi_ref) = rk4_heavy_top(
        p.inertia(),
        &(p.centre_of_mass() * (M * G)),
        &r0(),
        &pi0,
        t_end,
        12000,
    );
    let hs = [0.02, 0.01, 0.005];
    for exp in [true, false] {
        let errs = hs.map(|h| {
            let mut integ: Box<dyn Integrator<Group = So3>> = if exp {
                Box::new(LiePoisson::<So3, ExpMap, _>::new(p.clone(), 0.5, pi0, Some(g0)).unwrap())
            } else {
                Box::new(LiePoisson::<So3, Cayley, _>::new(p.clone(), 0.5, pi0, Some(g0)).unwrap())
            };
            let j0 = Pendulum3d::vertical_angular_momentum(&g0, &pi0);
            let mut drift = 0.0f64;
            for _ in 0..(t_end / h).round() as usize {
                integ.step(h).unwrap();
                let j = Pendulum3d::vertical_angular_momentum(
                    integ.configuration().unwrap(),
                    &integ.momentum(),
                );
                drift = drift.max((j - j0).abs());
            }
            assert!(drift < 1e-14, "Π·Γ drifted by {drift:e}");
            (integ.configuration().unwrap().as_matrix() - r_ref)
                .amax()
                .max((integ.momentum() - pi_ref).amax() / pi_ref.amax())
        });
        let order = fitted_order(&hs, &errs);
        println!(
            "general 3D pendulum, LP {} θ = ½: errors {errs:?}, order {order:.3}",
            if exp { "exp" } else { "cayley" }
        );
        assert!((1.9..=2.1).contains(&order), "order {order}");
    }
}
