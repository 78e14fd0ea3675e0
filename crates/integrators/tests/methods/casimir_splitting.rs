//! The Casimir splitting (`integrators::splitting::CasimirSplitting`) on the free rigid body: the
//! body's split, fitted orders against the exact flow, the folded composition of Strang,
//! symmetry, invariants over long runs, agreement with `Splitting`, and bad input.

use crate::common::*;
use integrators::splitting::{CasimirSplit, CasimirSplitting, Splitting, SplittingScheme};
use integrators::{Composition, CompositionScheme, Integrator, IntegratorError, System};
use lie_groups::{LieGroup, So3};
use mechanics::exact::ExactFreeBody;
use mechanics::systems::RigidBody;
use nalgebra::{Matrix3, Vector3};

fn full_tensor() -> Matrix3<f64> {
    Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0)
}

/// The bodies: diag(2, 3, 4) (the free-body scene's) and a full tensor.
fn bodies() -> [(RigidBody, &'static str); 2] {
    [
        (
            RigidBody::principal([2.0, 3.0, 4.0]).unwrap(),
            "diag(2,3,4)",
        ),
        (RigidBody::new(full_tensor()).unwrap(), "full tensor"),
    ]
}

fn casimir(
    body: &RigidBody,
    scheme: SplittingScheme,
    pi0: Vector3<f64>,
) -> CasimirSplitting<So3, RigidBody> {
    let g0 = So3::from_matrix(&r0()).unwrap();
    CasimirSplitting::new(body.clone(), scheme, pi0, Some(g0)).unwrap()
}

/// The split of the body: `∂C/∂μ + ξ_A + ξ_B = Ω`, C is a Casimir (`Π × ∂C/∂Π = 0`), the pieces'
/// velocities are constant along their own flows, and every closed-form flow equals the provided
/// one-parameter-subgroup form (through `exp`) to round-off.
#[test]
fn free_body_split_sums_to_the_velocity_and_its_flows_are_one_parameter_subgroups() {
    struct Generic<'a>(&'a RigidBody);
    impl System<So3> for Generic<'_> {
        fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
            self.0.hamiltonian(mu)
        }
        fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
            self.0.velocity(mu)
        }
        fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
            self.0.hessian(mu)
        }
        fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
            System::momentum(self.0, xi)
        }
    }
    impl CasimirSplit<So3> for Generic<'_> {
        fn casimir_velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
            self.0.casimir_velocity(mu)
        }
        fn perturbation_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
            self.0.perturbation_velocity(i, mu)
        }
    }
    let pi = Vector3::new(0.7, -1.1, 0.4);
    let g = So3::from_matrix(&r0()).unwrap();
    for (body, name) in bodies() {
        let sum = body.casimir_velocity(&pi)
            + body.perturbation_velocity(0, &pi)
            + body.perturbation_velocity(1, &pi);
        let e = (sum - body.velocity(&pi)).amax();
        assert!(e < 1e-15, "{name}: Σ velocities − Ω = {e:e}");
        let e = pi.cross(&body.casimir_velocity(&pi)).amax();
        assert!(e < 1e-15, "{name}: Π × ∂C/∂Π = {e:e}");
        let generic = Generic(&body);
        for t in [0.3, -1.7] {
            for i in 0..2 {
                let (mut m1, mut g1) = (pi, g);
                body.perturbation_flow(i, t, &mut m1, Some(&mut g1));
                let (mut m2, mut g2) = (pi, g);
                generic.perturbation_flow(i, t, &mut m2, Some(&mut g2));
                let e = (m1 - m2)
                    .amax()
                    .max((g1.as_matrix() - g2.as_matrix()).amax());
                assert!(e < 1e-14, "{name}: piece {i}, t = {t}: {e:e}");
                let v = (body.perturbation_velocity(i, &m1) - body.perturbation_velocity(i, &pi))
                    .amax();
                assert!(v < 1e-15, "{name}: ξ_{i} moved by {v:e} along its flow");
            }
            let (mut g1, mut g2) = (g, g);
            body.casimir_flow(t, &pi, &mut g1);
            generic.casimir_flow(t, &pi, &mut g2);
            let e = (g1.as_matrix() - g2.as_matrix()).amax();
            assert!(e < 1e-14, "{name}: φᶜ, t = {t}: {e:e}");
        }
    }
}

/// `strang_composed` is the formula of its docs, and the integrator with it is the same map as
/// `Composition` of the Strang step (which applies φᶜ at every stage): to round-off after 100
/// steps, for Kahan–Li 8 and the triple jump.
#[test]
fn strang_composed_scheme_is_the_composition_of_strang() {
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    for c in [
        CompositionScheme::kahan_li_8(),
        CompositionScheme::triple_jump(4).unwrap(),
    ] {
        let s = SplittingScheme::strang_composed(&c).unwrap();
        assert_eq!(s.order(), c.order());
        assert_eq!(s.b(), c.gammas());
        assert_eq!(s.a().len(), c.stages() + 1);
        let (sa, sb): (f64, f64) = (s.a().iter().sum(), s.b().iter().sum());
        assert!((sa - 1.0).abs() < 1e-15 && (sb - 1.0).abs() < 1e-15);
        for (body, name) in bodies() {
            let folded = run(casimir(&body, s.clone(), pi0), 0.2, 100).unwrap();
            let composed =
                Composition::new(casimir(&body, SplittingScheme::strang(), pi0), c.clone())
                    .unwrap();
            let composed = run(composed, 0.2, 100).unwrap();
            let e = error_vs(&composed, &folded, pi0.norm());
            println!("{} on {name}: folded − composed {e:.2e}", c.name());
            assert!(e < 1e-13, "{} on {name}: {e:e}", c.name());
        }
    }
    let lopsided = CompositionScheme::custom("lopsided", vec![0.25, 0.75], 2).unwrap();
    assert!(matches!(
        SplittingScheme::strang_composed(&lopsided),
        Err(IntegratorError::InvalidParameter { .. })
    ));
}

/// Builds an integrator afresh.
type Make<'a> = Box<dyn Fn() -> Box<dyn Integrator<Group = So3>> + 'a>;

/// Every scheme has its order (fitted within 0.2) against the exact flow (`mechanics::exact`) on
/// both bodies, Π₀ = (1, 0.5, −0.3), T = 10: Strang 2, Blanes–Moan 4 and 6, Kahan–Li 8 folded
/// (`strang_composed`) and composed (`Composition`) 8. Steps in each scheme's asymptotic range,
/// above round-off.
#[test]
fn casimir_splitting_schemes_have_their_orders_against_the_exact_flow() {
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    let g0 = So3::from_matrix(&r0()).unwrap();
    let t = 10.0;
    let kl8 = CompositionScheme::kahan_li_8();
    for (body, name) in bodies() {
        let mut exact = ExactFreeBody::new(body.clone(), pi0, Some(g0)).unwrap();
        exact.step(t).unwrap();
        let reference = (
            *exact.configuration().unwrap().as_matrix(),
            exact.momentum(),
        );
        let order = |make: &dyn Fn() -> Box<dyn Integrator<Group = So3>>, ns: &[usize]| {
            let mut hs = vec![];
            let mut errs = vec![];
            for &n in ns {
                let mut it = make();
                for _ in 0..n {
                    it.step(t / n as f64).unwrap();
                }
                let got = (*it.configuration().unwrap().as_matrix(), it.momentum());
                hs.push(t / n as f64);
                errs.push(error_vs(&reference, &got, pi0.norm()));
            }
            (fitted_order(&hs, &errs), errs)
        };
        let cases: Vec<(&str, u32, Make, &[usize])> = vec![
            (
                "strang",
                2,
                Box::new(|| Box::new(casimir(&body, SplittingScheme::strang(), pi0))),
                &[100, 140, 200, 280, 400],
            ),
            (
                "blanes-moan-4",
                4,
                Box::new(|| Box::new(casimir(&body, SplittingScheme::blanes_moan_4(), pi0))),
                &[25, 35, 50, 70, 100],
            ),
            (
                "blanes-moan-6",
                6,
                Box::new(|| Box::new(casimir(&body, SplittingScheme::blanes_moan_6(), pi0))),
                &[8, 10, 14, 20, 28],
            ),
            (
                "kahan-li-8∘strang",
                8,
                Box::new(|| {
                    let s = SplittingScheme::strang_composed(&CompositionScheme::kahan_li_8());
                    Box::new(casimir(&body, s.unwrap(), pi0))
                }),
                &[5, 6, 7, 8, 10],
            ),
            (
                "composition(kahan-li-8)",
                8,
                Box::new(|| {
                    let base = casimir(&body, SplittingScheme::strang(), pi0);
                    Box::new(Composition::new(base, kl8.clone()).unwrap())
                }),
                &[5, 6, 7, 8, 10],
            ),
        ];
        for (label, want, make, ns) in &cases {
            assert_eq!(make().info().order, *want, "{label}");
            let (p, errs) = order(make.as_ref(), ns);
            println!("{name}, {label}: order {p:.3}, errors {errs:?}");
            assert!(
                (p - f64::from(*want)).abs() < 0.2,
                "{name}, {label}: order {p}"
            );
        }
    }
}

/// With the Strang scheme it is the same map as `Splitting` of the body (whose inner piece is
/// φᶜ with B): to round-off after 1000 steps of h = 0.05 on both bodies.
#[test]
fn strang_equals_the_splitting_of_the_body() {
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    let g0 = So3::from_matrix(&r0()).unwrap();
    for (body, name) in bodies() {
        let ours = run(casimir(&body, SplittingScheme::strang(), pi0), 0.05, 1000).unwrap();
        let theirs = run(
            Splitting::new(body.clone(), pi0, Some(g0)).unwrap(),
            0.05,
            1000,
        )
        .unwrap();
        let e = error_vs(&theirs, &ours, pi0.norm());
        println!("{name}: casimir-splitting(strang) − splitting {e:.2e}");
        assert!(e < 1e-12, "{name}: {e:e}");
    }
}

/// Symmetric: 200 steps of h then 200 of −h return to the start to round-off (a scheme whose
/// φᶜ or merged flows were misplaced would miss by about n hᵖ⁺¹).
#[test]
fn casimir_splitting_is_reversible() {
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    for (body, name) in bodies() {
        for scheme in [
            SplittingScheme::strang(),
            SplittingScheme::blanes_moan_6(),
            SplittingScheme::strang_composed(&CompositionScheme::kahan_li_8()).unwrap(),
        ] {
            let label = scheme.name().to_string();
            let mut s = casimir(&body, scheme, pi0);
            for _ in 0..200 {
                s.step(0.3).unwrap();
            }
            for _ in 0..200 {
                s.step(-0.3).unwrap();
            }
            let e = (s.momentum() - pi0)
                .amax()
                .max((s.configuration().unwrap().as_matrix() - r0()).amax());
            println!("{name}, {label}: back by {e:.2e}");
            assert!(e < 1e-12, "{name}, {label}: back by {e:e}");
        }
    }
}

/// |Π|² and the spatial momentum RΠ at round-off over 10⁵ steps of Blanes–Moan 6 and of Kahan–Li
/// 8 folded (a random walk of 2–4·10⁶ roundings: ε√n ≈ 3e-13), R on the group; the energy bounded without drift over 10⁵ steps of h = 1 and 2 (first against last tenth; steps whose energy error is above the round-off walk).
#[test]
fn casimir_splitting_keeps_casimir_momentum_map_and_energy() {
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    let m0 = r0() * pi0;
    for (body, name) in bodies() {
        for (scheme, h_energy) in [
            (SplittingScheme::blanes_moan_6(), 1.0),
            (
                SplittingScheme::strang_composed(&CompositionScheme::kahan_li_8()).unwrap(),
                2.0,
            ),
        ] {
            let label = scheme.name().to_string();
            let mut s = casimir(&body, scheme.clone(), pi0);
            let (mut dc, mut dm) = (0.0f64, 0.0f64);
            for k in 0..100_000 {
                s.step(0.5).unwrap();
                if k % 100 == 99 {
                    let p = s.momentum();
                    dc = dc.max((p.norm_squared() - pi0.norm_squared()).abs() / pi0.norm_squared());
                    dm = dm
                        .max((s.configuration().unwrap().as_matrix() * p - m0).amax() / m0.norm());
                }
            }
            let r = s.configuration().unwrap().as_matrix();
            let orth = (r.transpose() * r - Matrix3::identity()).amax();
            println!(
                "{name}, {label}: Casimir {dc:.2e}, momentum map {dm:.2e}, ‖RᵀR − I‖ {orth:.2e}"
            );
            assert!(dc < 1e-12 && dm < 1e-12, "{name}, {label}: {dc:e}, {dm:e}");
            assert!(orth < 1e-14, "{name}, {label}: ‖RᵀR − I‖ {orth:e}");
            let (first, last) = energy_error_tenths(casimir(&body, scheme, pi0), h_energy, 100_000);
            println!("{name}, {label}: energy first tenth {first:.2e}, last tenth {last:.2e}");
            assert!(
                last < 1.5 * first,
                "{name}, {label}: drift {first:e} → {last:e}"
            );
        }
    }
}

/// Bad input is refused and leaves the state: a non-finite step, a step whose angles overflow,
/// a non-finite μ₀.
#[test]
fn casimir_splitting_refuses_bad_input() {
    let body = RigidBody::principal([2.0, 3.0, 4.0]).unwrap();
    let pi0 = Vector3::new(1.0, 0.5, -0.3);
    assert!(CasimirSplitting::new(
        body.clone(),
        SplittingScheme::strang(),
        Vector3::new(f64::NAN, 0.0, 0.0),
        None
    )
    .is_err());
    let mut s = casimir(&body, SplittingScheme::blanes_moan_6(), pi0);
    s.step(0.1).unwrap();
    let before = (s.time(), s.momentum(), *s.configuration().unwrap());
    assert!(s.step(f64::NAN).is_err());
    let big = Vector3::new(1e300, -1e300, 1e300);
    let mut t = casimir(&body, SplittingScheme::blanes_moan_6(), big);
    let t_before = (t.momentum(), *t.configuration().unwrap());
    assert!(t.step(1e300).is_err());
    assert_eq!((t.momentum(), *t.configuration().unwrap()), t_before);
    assert_eq!(
        (s.time(), s.momentum(), *s.configuration().unwrap()),
        before
    );
    // The step after a refusal is the step from the untouched state.
    let mut fresh = casimir(&body, SplittingScheme::blanes_moan_6(), pi0);
    fresh.step(0.1).unwrap();
    fresh.step(0.1).unwrap();
    s.step(0.1).unwrap();
    assert_eq!(s.momentum(), fresh.momentum());
}
