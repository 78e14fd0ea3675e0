//! The exact free rigid body flow (`mechanics::exact`): the elliptic functions against mpmath,
//! the flow against an independent 40-digit Taylor-series integration (mpmath's `odefun`, no
//! elliptic functions) in every regime, the group property, the invariants, extremes of |Π| and
//! t, the integrator's self-description, and bad input.

use crate::common::*;
use integrators::{Integrator, IntegratorError, StateSnapshot};
use lie_groups::{LieGroup, So3};
use mechanics::exact::{elliptic, ExactFreeBody, FreeBodyFlow};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};

fn lines(file: &str) -> Vec<Vec<String>> {
    let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path)
        .expect("reference data")
        .lines()
        .map(|l| l.split_whitespace().map(str::to_owned).collect())
        .collect()
}

fn num(s: &str) -> f64 {
    s.parse().expect("a number")
}

/// sn, cn, dn (from the amplitude), K, R_F, R_J and Π(n; φ, k) against mpmath at 40 digits, for
/// k' from 1 down to 10⁻⁸ (k'² = 10⁻¹⁶) and |u| ≤ K: within 1e-14 + 2ε·|u| + ε·cosh(u)/8, the
/// conditioning: am u has the absolute error ε·u of its argument, and near k = 1, where
/// cn ≈ sech u, ∂cn/∂k² ≈ sinh(u)·tanh(u)/4, so the rounding of k² = 1 − k'² to a double (ε/2)
/// moves cn by up to ε·cosh(u)/8 (measured 8.1e-14 at k'² = 10⁻¹⁶, u = 9.9; bound 2.7e-13).
#[test]
fn elliptic_functions_match_mpmath() {
    let mut worst = [0.0f64; 5];
    for l in lines("elliptic_reference.txt") {
        match l[0].as_str() {
            "sn-cn-dn" => {
                let (u, kc2) = (num(&l[1]), num(&l[2]));
                let (sn, cn, dn) = elliptic::sn_cn_dn(u, kc2);
                let tol = 1e-14 + 2.0 * f64::EPSILON * u.abs() + f64::EPSILON * u.cosh() / 8.0;
                for (got, want) in [(sn, num(&l[3])), (cn, num(&l[4])), (dn, num(&l[5]))] {
                    let e = (got - want).abs();
                    worst[0] = worst[0].max(e);
                    assert!(e <= tol, "{l:?}: {got} ({e:.1e})");
                }
            }
            "k" => {
                let (got, want) = (elliptic::complete_k(num(&l[1])), num(&l[2]));
                worst[1] = worst[1].max((got / want - 1.0).abs());
                assert!((got / want - 1.0).abs() < 4e-16, "{l:?}: {got}");
            }
            "pi" | "pi-complete" => {
                let n = num(&l[1]);
                let (got, want) = if l[0] == "pi" {
                    let (phi, kc2) = (num(&l[2]), num(&l[3]));
                    let (s, c) = phi.sin_cos();
                    let delta2 = c * c + kc2 * s * s;
                    (elliptic::incomplete_pi(n, s, c, delta2), num(&l[4]))
                } else {
                    (elliptic::complete_pi(n, num(&l[2])), num(&l[3]))
                };
                let e = (got / want - 1.0).abs();
                worst[2] = worst[2].max(e);
                assert!(e < 1e-14, "{l:?}: {got} ({e:.1e})");
            }
            "rf" => {
                let got = elliptic::carlson_rf(num(&l[1]), num(&l[2]), num(&l[3]));
                let e = (got / num(&l[4]) - 1.0).abs();
                worst[3] = worst[3].max(e);
                assert!(e < 4e-16, "{l:?}: {got}");
            }
            "rj" => {
                let got = elliptic::carlson_rj(num(&l[1]), num(&l[2]), num(&l[3]), num(&l[4]));
                let e = (got / num(&l[5]) - 1.0).abs();
                worst[4] = worst[4].max(e);
                assert!(e < 1e-15, "{l:?}: {got}");
            }
            "jacobi" | "third-kind" => {} // the quarter-period tests below
            other => panic!("unknown line {other}"),
        }
    }
    println!(
        "worst: sn/cn/dn {:.1e}, K {:.1e}, Π {:.1e}, R_F {:.1e}, R_J {:.1e}",
        worst[0], worst[1], worst[2], worst[3], worst[4]
    );
}

/// The flow against the 40-digit integration, every regime: generic on both sides of the
/// separatrix and with mixed signs, a full inertia tensor, 10⁻¹⁵ from the separatrix, on it, both
/// kinds of symmetric body, steady rotation about each principal axis, 10⁻⁷ from an axis, t < 0,
/// t = 40. Π relative to |Π| and R absolutely, within 1e-14 (the reference's R₀ is the 40-digit
/// rotation, the crate's its double rounding: 1e-16).
#[test]
fn exact_flow_matches_a_forty_digit_integration_in_every_regime() {
    let data = lines("free_body_reference.txt");
    assert_eq!(data.len(), 15);
    for l in data {
        let v: Vec<f64> = l[1..].iter().map(|s| num(s)).collect();
        let inertia = Matrix3::from_row_slice(&v[0..9]);
        let pi0 = Vector3::from_row_slice(&v[9..12]);
        let r0 = So3::from_matrix(&Matrix3::from_row_slice(&v[12..21])).unwrap();
        let t = v[21];
        let pi_ref = Vector3::from_row_slice(&v[22..25]);
        let r_ref = Matrix3::from_row_slice(&v[25..34]);
        let flow = FreeBodyFlow::new(&RigidBody::new(inertia).unwrap());
        let (pi, r) = flow.advance(t, &pi0, Some(&r0)).unwrap();
        let (ep, er) = (
            (pi - pi_ref).amax() / pi0.norm(),
            (r.unwrap().as_matrix() - r_ref).amax(),
        );
        println!("{:>20}: Π {ep:.1e}, R {er:.1e}", l[0]);
        assert!(ep < 1e-14 && er < 1e-14, "{}: Π {ep:e}, R {er:e}", l[0]);
    }
}

/// φ_{t₁} ∘ φ_{t₂} = φ_{t₁+t₂} and φ_{−t} ∘ φ_t = id to round-off, over many periods and for both
/// sides of the separatrix.
#[test]
fn exact_flow_is_a_one_parameter_group() {
    let flow = FreeBodyFlow::new(&RigidBody::principal(1.0, 2.0, 3.0).unwrap());
    let g0 = So3::from_matrix(&r0()).unwrap();
    for pi0 in [Vector3::new(0.4, 1.0, 0.3), Vector3::new(1.0, 0.3, -0.2)] {
        for (t1, t2) in [(0.3, 0.45), (17.0, -4.0), (123.4, 56.7)] {
            let (p1, r1) = flow.advance(t1, &pi0, Some(&g0)).unwrap();
            let (p12, r12) = flow.advance(t2, &p1, r1.as_ref()).unwrap();
            let (p, r) = flow.advance(t1 + t2, &pi0, Some(&g0)).unwrap();
            let e = (p12 - p)
                .amax()
                .max((r12.unwrap().as_matrix() - r.unwrap().as_matrix()).amax());
            // Conditioning: the phase error of a time t is ε·λt radians.
            assert!(e < 1e-15 * (1.0 + t1 + t2), "{pi0:?} {t1}+{t2}: {e:e}");
            let (pb, rb) = flow.advance(-t1, &p1, r1.as_ref()).unwrap();
            let e = (pb - pi0)
                .amax()
                .max((rb.unwrap().as_matrix() - g0.as_matrix()).amax());
            assert!(e < 1e-15 * (1.0 + t1), "back from {t1}: {e:e}");
        }
    }
}

/// At t = 10⁶ (about 10⁵ periods, in one call): energy, Casimir and the spatial momentum RΠ at
/// round-off (the phase itself is only as accurate as ε·t).
#[test]
fn exact_flow_keeps_the_invariants_at_huge_times() {
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let flow = FreeBodyFlow::new(&body);
    use integrators::System;
    let g0 = So3::from_matrix(&r0()).unwrap();
    for pi0 in [Vector3::new(0.4, 1.0, 0.3), Vector3::new(1.0, 0.3, -0.2)] {
        let (p, r) = flow.advance(1e6, &pi0, Some(&g0)).unwrap();
        let r = r.unwrap();
        let de = (body.hamiltonian(&p) / body.hamiltonian(&pi0) - 1.0).abs();
        let dc = (p.norm_squared() / pi0.norm_squared() - 1.0).abs();
        let dm = (r.as_matrix() * p - g0.as_matrix() * pi0).amax() / pi0.norm();
        let orth = (r.as_matrix().transpose() * r.as_matrix() - Matrix3::identity()).amax();
        println!("t = 1e6: ΔE {de:.1e}, ΔC {dc:.1e}, Δm {dm:.1e}, ‖RᵀR − I‖ {orth:.1e}");
        assert!(de < 1e-14 && dc < 1e-14 && dm < 1e-14 && orth < 1e-15);
    }
}

/// The flow is homogeneous: Π ↦ sΠ, t ↦ t/s gives sΠ(t) and the same R, for s = 10⁻¹⁵⁰ and 10¹⁵⁰;
/// Π = 0 is rest.
#[test]
fn exact_flow_scales_to_tiny_and_huge_momenta() {
    let flow = FreeBodyFlow::new(&RigidBody::principal(1.0, 2.0, 3.0).unwrap());
    let g0 = So3::from_matrix(&r0()).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let (p, r) = flow.advance(3.0, &pi0, Some(&g0)).unwrap();
    for s in [1e-150, 1e150] {
        let (ps, rs) = flow.advance(3.0 / s, &(pi0 * s), Some(&g0)).unwrap();
        let e = (ps / s - p)
            .amax()
            .max((rs.unwrap().as_matrix() - r.unwrap().as_matrix()).amax());
        assert!(e < 1e-14, "s = {s:e}: {e:e}");
    }
    let (p, r) = flow.advance(5.0, &Vector3::zeros(), Some(&g0)).unwrap();
    assert_eq!((p, r), (Vector3::zeros(), Some(g0)));
}

/// Against the crate-independent RK4 reference (h = 2e-5) on an asymmetric full tensor, and the
/// closed form of the axisymmetric body.
#[test]
fn exact_flow_matches_rk4_and_the_axisymmetric_closed_form() {
    let full = Matrix3::new(2.0, 0.1, 0.3, 0.1, 3.0, -0.2, 0.3, -0.2, 4.0);
    let pi0 = Vector3::new(0.5, 1.0, -0.7);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let (p, r) = FreeBodyFlow::new(&RigidBody::new(full).unwrap())
        .advance(3.0, &pi0, Some(&g0))
        .unwrap();
    let (rr, pr) = rk4_reference(&full, &r0(), &pi0, 3.0, 150_000);
    assert!((p - pr).amax() < 1e-13 && (r.unwrap().as_matrix() - rr).amax() < 1e-13);
    let (p, r) = FreeBodyFlow::new(&RigidBody::principal(1.0, 1.0, 2.5).unwrap())
        .advance(7.0, &pi0, Some(&g0))
        .unwrap();
    let (rr, pr) = axisymmetric_exact(1.0, 2.5, &r0(), &pi0, 7.0);
    assert!((p - pr).amax() < 1e-14 && (r.unwrap().as_matrix() - rr).amax() < 1e-14);
}

/// The integrator's declared properties, checked: exact (one step of 10 equals 1000 steps of
/// 0.01 up to the random walk of 1000 roundings: ≤ 5e-13, measured 1.3e-13), symmetric (h then −h returns), energy, Casimir and RΠ kept over 10⁵ steps to a random
/// walk of roundings with a slight bias (≤ 5e-13; measured 2.6e-13, 2.6e-18 per step); bad input refused
/// with the state untouched.
#[test]
fn exact_integrator_is_what_it_declares() {
    let body = RigidBody::principal(1.0, 2.0, 3.0).unwrap();
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let info = ExactFreeBody::new(body.clone(), pi0, Some(g0))
        .unwrap()
        .info();
    assert!(info.symmetric && info.explicit && info.energy && info.casimirs && info.momentum_map);
    let mut one = ExactFreeBody::new(body.clone(), pi0, Some(g0)).unwrap();
    let mut many = ExactFreeBody::new(body.clone(), pi0, Some(g0)).unwrap();
    one.step(10.0).unwrap();
    for _ in 0..1000 {
        many.step(0.01).unwrap();
    }
    let e = (one.momentum() - many.momentum()).amax().max(
        (one.configuration().unwrap().as_matrix() - many.configuration().unwrap().as_matrix())
            .amax(),
    );
    assert!(e < 5e-13, "one step against 1000: {e:e}");
    let (e0, c0, m0) = (many.energy(), many.casimir().unwrap(), g0.as_matrix() * pi0);
    for _ in 0..100_000 {
        many.step(0.37).unwrap();
    }
    let m = many.configuration().unwrap().as_matrix() * many.momentum();
    println!(
        "10⁵ steps: ΔE {:.1e}, ΔC {:.1e}, Δm {:.1e}",
        (many.energy() / e0 - 1.0).abs(),
        (many.casimir().unwrap() / c0 - 1.0).abs(),
        (m - m0).amax()
    );
    assert!(
        (many.energy() / e0 - 1.0).abs() < 5e-13
            && (many.casimir().unwrap() / c0 - 1.0).abs() < 5e-13
    );
    assert!(
        (m - m0).amax() < 3e-13,
        "momentum map {:e}",
        (m - m0).amax()
    );
    one.step(-10.0).unwrap();
    assert!((one.momentum() - pi0).amax() < 1e-14);
    let before = one.snapshot();
    for h in [f64::NAN, f64::INFINITY] {
        assert!(matches!(
            one.step(h),
            Err(IntegratorError::NonFinite { .. })
        ));
        assert_eq!(one.snapshot(), before);
    }
    assert!(one.step(1e308).is_err()); // |Π|t overflows: an error, not a NaN state
    assert_eq!(one.snapshot(), before);
    assert!(ExactFreeBody::new(body, Vector3::new(f64::NAN, 0.0, 0.0), None).is_err());
}

/// sn, cn, dn at a quarter-period phase u = nK + w (K exact) against mpmath, near every zero of
/// cn and dn (n odd, w → 0), for k' from e^{-0.3} to e^{-400} (k'² below the double range): each
/// within 4 + 2|w| ulps of itself, however small — the functions' own conditioning (near k = 1,
/// |d ln cn/d ln w| = |w tanh w|: the rounding of the reduced argument; measured at most 1.6 + |w|
/// ulps, 18.5 at w = 10.7 where cn w = 4.5e-5). Evaluated at u = nK + w itself, cn and dn near
/// their zeros keep only the absolute error of u (ε·nK, up to 10¹⁶ ulps of the value here).
#[test]
fn jacobi_functions_have_relative_accuracy_in_every_quarter() {
    let mut worst = 0.0f64;
    let mut count = 0;
    for l in lines("elliptic_reference.txt") {
        if l[0] != "jacobi" {
            continue;
        }
        let (ln_kc, n, w) = (num(&l[1]), num(&l[2]), num(&l[3]));
        let modulus = elliptic::Modulus::from_ln_kc(ln_kc);
        let jac = modulus.jacobi(elliptic::QuarterPhase { n, w });
        for (got, want) in [
            (jac.sn, num(&l[4])),
            (jac.cn, num(&l[5])),
            (jac.dn, num(&l[6])),
        ] {
            let e = if want == 0.0 {
                got.abs()
            } else {
                (got / want - 1.0).abs() / f64::EPSILON
            };
            worst = worst.max(e / (4.0 + 2.0 * w.abs()));
            count += 1;
            assert!(e <= 4.0 + 2.0 * w.abs(), "{l:?}: {got:e} ({e:.1} ulps)");
        }
    }
    assert!(count > 1000);
    println!("{count} values, worst {worst:.2} of the bound");
}

/// Λ(u) = ∫₀ᵘ dv/(1 + β sn²v) = c·u + n·L + B(n, w) at u = nK + w against mpmath's
/// Π(−β; am u, k) at the continuous amplitude: relative 1e-14 for k' from e^{-0.3} to e^{-46}
/// (both regimes; measured 2.1e-15).
#[test]
fn third_kind_integral_continues_through_the_quarter_periods() {
    let mut worst = 0.0f64;
    for l in lines("elliptic_reference.txt") {
        if l[0] != "third-kind" {
            continue;
        }
        let (ln_kc, beta, n, w) = (num(&l[1]), num(&l[2]), num(&l[3]), num(&l[4]));
        let modulus = elliptic::Modulus::from_ln_kc(ln_kc);
        let phase = elliptic::QuarterPhase { n, w };
        let jac = modulus.jacobi(phase);
        let u = n * modulus.quarter_period() + w;
        let mut got = modulus.third_kind_part(beta, phase, &jac, f64::NAN)
            + modulus.third_kind_slope(beta) * u;
        if n != 0.0 {
            got += n * modulus.third_kind_quarter(beta);
        }
        let want = num(&l[5]);
        let e = if want == 0.0 {
            got.abs()
        } else {
            (got / want - 1.0).abs()
        };
        worst = worst.max(e);
        assert!(e < 1e-14, "{l:?}: {got:e} ({e:.1e})");
    }
    println!("worst {worst:.1e}");
}
