//! The heavy top (`systems::HeavyTop`): the left-trivialized differential against finite
//! differences, energy without drift, the vertical angular momentum ⟨RΠ, e₃⟩ to round-off (discrete
//! Noether), the Lagrange top's Π₃, and the orders of Lie–Poisson θ = ½ and θ = 0 against RK4.

use crate::common::*;
use integrators::{integrate, Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::HeavyTop;
use nalgebra::{Matrix3, Vector3};

const PI0: Vector3<f64> = Vector3::new(0.4, 0.8, 1.1);

fn top() -> HeavyTop {
    HeavyTop::principal([1.0, 1.5, 2.5], 2.0, 9.81, Vector3::new(0.03, -0.02, 0.1)).unwrap()
}

fn lagrange() -> HeavyTop {
    HeavyTop::lagrange(1.0, 0.6, 1.5, 9.81, 0.08).unwrap()
}

fn g0() -> So3 {
    So3::from_matrix(&r0()).unwrap()
}

#[test]
fn heavy_top_differential_matches_finite_differences() {
    // ⟨T*_e L_R dV, eᵢ⟩ = d/ds V(R exp(s eᵢ)): central differences with δ = 1e-5 are accurate to
    // ~δ² |V| ≈ 1e-10 · 2; bound 1e-8.
    let tops = [
        top(),
        lagrange(),
        HeavyTop::new(
            Matrix3::new(2.0, 0.3, 0.1, 0.3, 1.0, 0.0, 0.1, 0.0, 3.0),
            0.7,
            3.0,
            Vector3::new(-0.5, 0.4, 0.2),
        )
        .unwrap(),
    ];
    for (k, sys) in tops.iter().enumerate() {
        for w in [
            Vector3::new(0.3, -0.5, 0.8),
            Vector3::new(2.0, 1.0, -0.4),
            Vector3::new(0.0, 3.0, 0.1),
        ] {
            let g = So3::exp(&w);
            let fd = fd_left_differential(|r: &So3| sys.potential(r), &g);
            let dv = sys.potential_differential(&g);
            for i in 0..3 {
                assert!(
                    (fd[i] - dv[i]).abs() < 1e-8,
                    "top {k}, ω {w:?}, component {i}: fd {} vs {}",
                    fd[i],
                    dv[i]
                );
            }
        }
    }
}

#[test]
fn heavy_top_vector_field_is_lie_poisson_with_force() {
    // μ̇ = ad*_{∂h/∂μ} μ − T*_e L_R dV must equal Π × Ω + mg Γ × χ.
    let sys = top();
    let g = g0();
    let lp = So3::ad_dual_apply(&sys.velocity(&PI0), &PI0) - sys.potential_differential(&g);
    assert!((lp - sys.vector_field(&g, &PI0)).amax() < 1e-14);
}

#[test]
fn heavy_top_refuses_bad_parameters() {
    let chi = Vector3::z();
    assert!(HeavyTop::principal([1.0, 1.0, 1.0], 0.0, 9.81, chi).is_err());
    assert!(HeavyTop::principal([1.0, 1.0, 1.0], 1.0, -1.0, chi).is_err());
    assert!(HeavyTop::principal([1.0, 1.0, 1.0], f64::NAN, 1.0, chi).is_err());
    assert!(HeavyTop::principal([1.0, -1.0, 1.0], 1.0, 1.0, chi).is_err());
    assert!(HeavyTop::principal(
        [1.0, 1.0, 1.0],
        1.0,
        1.0,
        Vector3::new(f64::INFINITY, 0., 0.)
    )
    .is_err());
}

fn vertical_momentum_drift<T: Tau<So3>>(sys: HeavyTop, theta: f64, h: f64, steps: usize) -> f64 {
    let mut lp = LiePoisson::<So3, T, _>::new(sys, theta, PI0, Some(g0())).unwrap();
    let c0 = HeavyTop::vertical_angular_momentum(&g0(), &PI0);
    let mut worst = 0.0f64;
    integrate(&mut lp, h, steps, |i| {
        let c = HeavyTop::vertical_angular_momentum(i.configuration().unwrap(), &i.momentum());
        worst = worst.max((c - c0).abs());
    })
    .unwrap();
    worst / c0.abs()
}

#[test]
fn heavy_top_vertical_momentum_conserved_to_round_off() {
    // Discrete Noether (module page of heavy_top): the spatial momentum changes by
    // h Ad*_{ḡ⁻¹} F(ḡ), whose e₃ component vanishes exactly. What remains is round-off of a few
    // ulps per step (≈ √N · 1e-16 · |Π| after N steps): bound 1e-12 relative over 2000 steps.
    // For contrast the step h = 0.02 is coarse: the energy error is ~1e-4 (see below).
    for theta in [0.0, 0.5, 1.0] {
        let e = vertical_momentum_drift::<ExpMap>(top(), theta, 0.02, 2_000);
        let c = vertical_momentum_drift::<Cayley>(top(), theta, 0.02, 2_000);
        println!("⟨RΠ, e₃⟩ relative drift θ={theta}: exp {e:.2e}, cayley {c:.2e}");
        assert!(e < 1e-12 && c < 1e-12, "θ={theta}: exp {e:e}, cayley {c:e}");
    }
}

#[test]
fn heavy_top_energy_error_bounded_without_drift() {
    // 4000 steps of h = 0.02 (t = 80, many nutation periods): the max energy error over the last
    // tenth stays within 2× (+ round-off) of that over the first tenth.
    for theta in [0.0, 0.5, 1.0] {
        let (f, l) = energy_error_tenths(
            LiePoisson::<So3, Cayley, _>::new(top(), theta, PI0, Some(g0())).unwrap(),
            0.02,
            4_000,
        );
        println!("heavy top energy error θ={theta} cayley: first tenth {f:.2e}, last {l:.2e}");
        assert!(
            l <= 2.0 * f + 1e-13,
            "cayley θ={theta}: first {f:e}, last {l:e}"
        );
    }
    let (f, l) = energy_error_tenths(
        LiePoisson::<So3, ExpMap, _>::new(top(), 0.5, PI0, Some(g0())).unwrap(),
        0.02,
        4_000,
    );
    println!("heavy top energy error θ=0.5 exp: first tenth {f:.2e}, last {l:.2e}");
    assert!(l <= 2.0 * f + 1e-13, "exp θ=½: first {f:e}, last {l:e}");
}

/// Max |Π₃(t) − Π₃(0)| of the Lagrange top over `steps` steps.
fn lagrange_pi3_error<T: Tau<So3>>(theta: f64, h: f64, steps: usize) -> f64 {
    let mut lp = LiePoisson::<So3, T, _>::new(lagrange(), theta, PI0, Some(g0())).unwrap();
    let mut worst = 0.0f64;
    integrate(&mut lp, h, steps, |i| {
        worst = worst.max((i.momentum().z - PI0.z).abs())
    })
    .unwrap();
    worst
}

#[test]
fn lagrange_top_body_axis_momentum_conserved_to_round_off() {
    // Π₃ comes from the body symmetry R ↦ R exp(s e₃). Measured: every Lie–Poisson method keeps it
    // to round-off (a few 1e-15), because each ingredient of the step (τ, 𝕀 = diag(i, i, i₃), the
    // force mg Γ × ℓe₃) is equivariant under conjugation by rotations about e₃, so the (ξ, μ)
    // step commutes with that symmetry. Bound 1e-12 relative over 1000 and 2000 steps.
    let c = PI0.z;
    for theta in [0.0, 0.5, 1.0] {
        for (tau, e1, e2) in [
            (
                "exp",
                lagrange_pi3_error::<ExpMap>(theta, 0.02, 1_000),
                lagrange_pi3_error::<ExpMap>(theta, 0.01, 2_000),
            ),
            (
                "cayley",
                lagrange_pi3_error::<Cayley>(theta, 0.02, 1_000),
                lagrange_pi3_error::<Cayley>(theta, 0.01, 2_000),
            ),
        ] {
            println!("Lagrange top Π₃ error {tau} θ={theta}: h=0.02 {e1:.2e}, h=0.01 {e2:.2e}");
            assert!(
                e1 < 1e-12 * c && e2 < 1e-12 * c,
                "{tau} θ={theta}: {e1:e}, {e2:e}"
            );
        }
    }
}

#[test]
fn asymmetric_top_body_axis_momentum_is_not_conserved() {
    // The Π₃ check above can fail: for the asymmetric top of the other tests Π₃ varies by O(1).
    let mut lp = LiePoisson::<So3, Cayley, _>::new(top(), 0.5, PI0, Some(g0())).unwrap();
    let mut worst = 0.0f64;
    integrate(&mut lp, 0.02, 500, |i| {
        worst = worst.max((i.momentum().z - PI0.z).abs())
    })
    .unwrap();
    assert!(worst > 0.1, "{worst:e}");
}

#[test]
fn lagrange_top_integrals_exact_for_rk4_reference() {
    // Sanity check of the reference and the fixture: RK4 at h = 1e-3 keeps Π₃ and ⟨RΠ, e₃⟩ to
    // 1e-10 (its local error is O(h⁵)).
    let sys = lagrange();
    let mgchi = sys.centre_of_mass() * (sys.mass() * sys.gravity());
    let (r, p) = rk4_heavy_top(sys.inertia(), &mgchi, &r0(), &PI0, 2.0, 2_000);
    assert!((p.z - PI0.z).abs() < 1e-10);
    let c0 = PI0.dot(&(r0().transpose() * Vector3::z()));
    assert!((p.dot(&(r.transpose() * Vector3::z())) - c0).abs() < 1e-10);
}

fn order<T: Tau<So3>>(theta: f64) -> f64 {
    let sys = top();
    let mgchi = sys.centre_of_mass() * (sys.mass() * sys.gravity());
    let t = 1.0;
    let (rr, pr) = rk4_heavy_top(sys.inertia(), &mgchi, &r0(), &PI0, t, 10_000);
    let mut hs = vec![];
    let mut errs = vec![];
    for n in [20usize, 40, 80, 160] {
        let h = t / n as f64;
        let (r, p) = run(
            LiePoisson::<So3, T, _>::new(sys.clone(), theta, PI0, Some(g0())).unwrap(),
            h,
            n,
        )
        .unwrap();
        hs.push(h);
        errs.push((r - rr).amax().max((p - pr).amax()));
    }
    let p = fitted_order(&hs, &errs);
    println!(
        "heavy top LP {} θ={theta}: errors {errs:?}, order {p:.3}",
        T::NAME
    );
    p
}

#[test]
fn heavy_top_lie_poisson_orders_against_rk4() {
    // θ = ½: order 2; θ = 0: order 1 (the force enters at the base point ḡ = g_k only).
    // Tolerance 0.1 on the least-squares slope over h = 1/20 … 1/160.
    for (theta, expected) in [(0.5, 2.0), (0.0, 1.0)] {
        let e = order::<ExpMap>(theta);
        let c = order::<Cayley>(theta);
        assert!(
            (e - expected).abs() < 0.1 && (c - expected).abs() < 0.1,
            "θ={theta}: exp {e:.3}, cayley {c:.3}"
        );
    }
}

#[test]
fn heavy_top_vertical_momentum_conserved_over_1e5_steps() {
    for theta in [0.0, 0.5, 1.0] {
        let e = vertical_momentum_drift::<ExpMap>(top(), theta, 0.02, 100_000);
        let c = vertical_momentum_drift::<Cayley>(top(), theta, 0.02, 100_000);
        println!("⟨RΠ, e₃⟩ drift over 1e5 steps θ={theta}: exp {e:.2e}, cayley {c:.2e}");
        assert!(e < 1e-11 && c < 1e-11, "θ={theta}: exp {e:e}, cayley {c:e}");
    }
}
