//! N rigid bodies coupled by springs (`systems::CoupledBodies` on SE(3)ᴺ): derivatives against
//! finite differences; without springs each body moves as alone (the SE(3) body's own run);
//! two spheres on a spring along a line follow the 1D oscillator's closed form at order 2; three
//! bodies on off-centre springs keep the total spatial momentum to round-off, have a bounded
//! energy error over 20 000 steps and converge at order 2 to an independent RK4.

use crate::common::*;
use integrators::baselines::Rkmk4;
use integrators::derivative_check::check_derivatives;
use integrators::splitting::Splitting;
use integrators::{Integrator, LiePoisson};
use lie_groups::{Cayley, ExpMap, LieGroup, Power, PowerAlgebra, Se3, So3, Tau};
use mechanics::systems::{CoupledBodies, RigidBodySe3, Spring};
use nalgebra::{DVector, Matrix3, Vector3, Vector6};

type G3 = Power<Se3, 3>;
type M3 = PowerAlgebra<Se3, 3>;

fn bodies3() -> [RigidBodySe3; 3] {
    [
        RigidBodySe3::free(
            1.0,
            Matrix3::new(0.1, 0.01, 0.0, 0.01, 0.15, 0.0, 0.0, 0.0, 0.2),
        )
        .unwrap(),
        RigidBodySe3::free(2.0, Matrix3::from_diagonal(&Vector3::new(0.3, 0.25, 0.2))).unwrap(),
        RigidBodySe3::free(
            1.5,
            Matrix3::new(0.2, 0.0, 0.02, 0.0, 0.1, 0.0, 0.02, 0.0, 0.15),
        )
        .unwrap(),
    ]
}

/// A triangle of springs between off-centre points, with rest lengths.
fn springs3() -> Vec<Spring> {
    vec![
        Spring::new(
            [0, 1],
            [Vector3::new(0.2, 0.0, 0.0), Vector3::new(-0.1, 0.1, 0.0)],
            8.0,
            1.0,
        )
        .unwrap(),
        Spring::new(
            [1, 2],
            [Vector3::new(0.0, 0.2, 0.1), Vector3::new(0.0, -0.2, 0.0)],
            5.0,
            0.8,
        )
        .unwrap(),
        Spring::new(
            [2, 0],
            [Vector3::new(0.1, 0.0, -0.1), Vector3::new(0.0, 0.0, 0.2)],
            6.0,
            1.2,
        )
        .unwrap(),
    ]
}

fn three() -> CoupledBodies<RigidBodySe3, 3> {
    CoupledBodies::new(bodies3(), springs3()).unwrap()
}

fn start3() -> (G3, M3) {
    (
        Power::new([
            Se3::from_parts(
                So3::from_matrix(&r0()).unwrap(),
                Vector3::new(0.0, 0.0, 0.0),
            ),
            Se3::from_parts(
                So3::exp(&Vector3::new(0.1, 0.5, -0.2)),
                Vector3::new(1.3, 0.2, 0.1),
            ),
            Se3::from_parts(
                So3::exp(&Vector3::new(-0.4, 0.0, 0.3)),
                Vector3::new(0.5, 1.1, -0.2),
            ),
        ]),
        PowerAlgebra::new([
            Vector6::new(0.05, -0.02, 0.1, 0.3, -0.2, 0.1),
            Vector6::new(-0.1, 0.04, 0.0, -0.4, 0.5, 0.0),
            Vector6::new(0.02, 0.06, -0.05, 0.1, -0.3, 0.2),
        ]),
    )
}

#[test]
fn coupled_differential_matches_finite_differences() {
    let (g, mu) = start3();
    let other = Power::new([
        Se3::from_parts(
            So3::exp(&Vector3::new(2.0, 0.0, 1.0)),
            Vector3::new(-1.0, 0.5, 0.0),
        ),
        Se3::from_parts(
            So3::exp(&Vector3::new(0.0, -1.5, 0.2)),
            Vector3::new(0.3, -0.2, 2.0),
        ),
        Se3::from_parts(
            So3::exp(&Vector3::new(0.7, 0.7, 0.7)),
            Vector3::new(1.5, 1.5, 0.5),
        ),
    ]);
    let report = check_derivatives::<G3, _>(&three(), &[(mu, Some(g)), (mu, Some(other))]);
    assert!(report.passes(1e-8), "{report:?}");
}

#[test]
fn coupled_bodies_refuse_bad_springs() {
    let a = [Vector3::zeros(), Vector3::zeros()];
    assert!(Spring::new([1, 1], a, 1.0, 0.0)
        .unwrap_err()
        .to_string()
        .contains("different"));
    assert!(Spring::new([0, 1], a, -1.0, 0.0)
        .unwrap_err()
        .to_string()
        .contains("stiffness"));
    assert!(Spring::new([0, 1], a, 1.0, f64::NAN)
        .unwrap_err()
        .to_string()
        .contains("rest length"));
    let bad = [Vector3::new(f64::INFINITY, 0.0, 0.0), Vector3::zeros()];
    assert!(Spring::new([0, 1], bad, 1.0, 0.0).is_err());
    let far = Spring::new([0, 3], a, 1.0, 0.0).unwrap();
    let err = CoupledBodies::new(bodies3(), vec![far])
        .unwrap_err()
        .to_string();
    assert!(err.contains("spring 0") && err.contains("3"), "{err}");
}

/// Without springs the bodies do not interact: the Lie–Poisson run on SE(3)³ equals each body's
/// own run on SE(3) at every step (≤ 1e-13, the solver's tolerance; τ = exp and Cayley).
#[test]
fn without_springs_each_body_moves_as_alone() {
    fn run<T: Tau<G3> + Tau<Se3>>() -> f64 {
        let (g0, mu0) = start3();
        let mut all = LiePoisson::<G3, T, _>::new(
            CoupledBodies::new(bodies3(), vec![]).unwrap(),
            0.5,
            mu0,
            Some(g0),
        )
        .unwrap();
        let mut alone: Vec<_> = (0..3)
            .map(|k| {
                LiePoisson::<Se3, T, _>::new(
                    bodies3()[k].clone(),
                    0.5,
                    mu0.parts[k],
                    Some(g0.parts[k]),
                )
                .unwrap()
            })
            .collect();
        let mut worst = 0.0f64;
        for _ in 0..500 {
            all.step(0.02).unwrap();
            for (k, b) in alone.iter_mut().enumerate() {
                b.step(0.02).unwrap();
                worst = worst
                    .max((all.momentum().parts[k] - b.momentum()).amax())
                    .max(
                        all.configuration().unwrap().parts[k]
                            .matrix_distance(b.configuration().unwrap()),
                    );
            }
        }
        worst
    }
    // Not bitwise: the coupled step solves one 18×18 Newton system whose iterations stop on the
    // whole residual, each body's on its own, so the two differ within the solver's tolerance
    // (1e-14 relative); measured 5e-15 over 500 steps.
    let (e, c) = (run::<ExpMap>(), run::<Cayley>());
    println!("no springs: coupled vs alone, exp {e:.1e}, cayley {c:.1e}");
    assert!(e <= 1e-13 && c <= 1e-13, "{e:e} {c:e}");
}

// ---- Two spheres on a spring along a line: the 1D oscillator ----

const M1: f64 = 1.0;
const M2: f64 = 3.0;
const KAPPA: f64 = 12.0;
const L: f64 = 1.0;

/// Isotropic bodies joined centre to centre (no torque), on the line through R₀e₁ (any attitude,
/// the same R₀ for both so that the separation is along the body axes e₁ of both): start
/// stretched to 1.3 and at rest, centre of mass drifting at 0.2 along the line.
fn two() -> (
    CoupledBodies<RigidBodySe3, 2>,
    Power<Se3, 2>,
    PowerAlgebra<Se3, 2>,
) {
    let sphere = |m: f64| RigidBodySe3::free(m, Matrix3::identity() * (0.4 * m * 0.01)).unwrap();
    let spring = Spring::new([0, 1], [Vector3::zeros(), Vector3::zeros()], KAPPA, L).unwrap();
    let r = So3::from_matrix(&r0()).unwrap();
    let e1 = r0() * Vector3::x();
    let g0 = Power::new([
        Se3::from_parts(r, Vector3::new(1.0, 2.0, 3.0)),
        Se3::from_parts(r, Vector3::new(1.0, 2.0, 3.0) + e1 * 1.3),
    ]);
    let v = 0.2;
    let mu0 = PowerAlgebra::new([
        Vector6::new(0.0, 0.0, 0.0, M1 * v, 0.0, 0.0),
        Vector6::new(0.0, 0.0, 0.0, M2 * v, 0.0, 0.0),
    ]);
    (
        CoupledBodies::new([sphere(M1), sphere(M2)], vec![spring]).unwrap(),
        g0,
        mu0,
    )
}

/// `r(t) = L + 0.3 cos ωt`, ω² = κ(1/m₁ + 1/m₂); the centre of mass moves at 0.2.
fn two_exact(t: f64) -> (Vector3<f64>, Vector3<f64>) {
    let (_, g0, _) = two();
    let e1 = r0() * Vector3::x();
    let w = (KAPPA * (1.0 / M1 + 1.0 / M2)).sqrt();
    let r = L + 0.3 * (w * t).cos();
    let com0 = (g0.parts[0].translation() * M1 + g0.parts[1].translation() * M2) / (M1 + M2);
    let com = com0 + e1 * (0.2 * t);
    (
        com - e1 * (r * M2 / (M1 + M2)),
        com + e1 * (r * M1 / (M1 + M2)),
    )
}

/// Lie–Poisson θ = ½ (exp, Cayley) and Strang reach the oscillator's closed form at order 2.
#[test]
fn two_bodies_on_a_spring_oscillate_as_the_closed_form() {
    let t_end = 3.0;
    let (x1, x2) = two_exact(t_end);
    let error = |integ: &mut dyn Integrator<Group = Power<Se3, 2>>, h: f64| {
        for _ in 0..(t_end / h).round() as usize {
            integ.step(h).unwrap();
        }
        let g = integ.configuration().unwrap();
        (g.parts[0].translation() - x1)
            .amax()
            .max((g.parts[1].translation() - x2).amax())
    };
    let hs = [0.02, 0.01, 0.005];
    let (sys, g0, mu0) = two();
    let lp_exp = hs.map(|h| {
        error(
            &mut LiePoisson::<_, ExpMap, _>::new(sys.clone(), 0.5, mu0, Some(g0)).unwrap(),
            h,
        )
    });
    let lp_cay = hs.map(|h| {
        error(
            &mut LiePoisson::<_, Cayley, _>::new(sys.clone(), 0.5, mu0, Some(g0)).unwrap(),
            h,
        )
    });
    let strang = hs.map(|h| error(&mut Splitting::new(sys.clone(), mu0, Some(g0)).unwrap(), h));
    for (name, errs) in [
        ("LP exp θ = ½", lp_exp),
        ("LP cayley θ = ½", lp_cay),
        ("Strang", strang),
    ] {
        let order = fitted_order(&hs, &errs);
        println!("two-body oscillator, {name}: errors {errs:?}, order {order:.3}");
        assert!((1.9..=2.1).contains(&order), "{name}: order {order}");
    }
}

// ---- Three bodies ----

/// The springs are invariant under moving all bodies together: Lie–Poisson (every θ, both τ)
/// and Strang keep the total spatial momentum Σ Ad*_{g_k⁻¹}μ_k to round-off (≤ 1e-13 of the
/// size of its terms over 2000 steps).
#[test]
fn three_bodies_keep_the_total_momentum_to_round_off() {
    let (g0, mu0) = start3();
    let (l0, p0) = CoupledBodies::<RigidBodySe3, 3>::total_momentum(&g0, &mu0);
    let mut runs: Vec<(String, Box<dyn Integrator<Group = G3>>)> = Vec::new();
    for theta in [0.0, 0.5, 1.0] {
        runs.push((
            format!("LP exp θ = {theta}"),
            Box::new(LiePoisson::<G3, ExpMap, _>::new(three(), theta, mu0, Some(g0)).unwrap()),
        ));
        runs.push((
            format!("LP cayley θ = {theta}"),
            Box::new(LiePoisson::<G3, Cayley, _>::new(three(), theta, mu0, Some(g0)).unwrap()),
        ));
    }
    runs.push((
        "Strang".into(),
        Box::new(Splitting::new(three(), mu0, Some(g0)).unwrap()),
    ));
    for (name, mut integ) in runs {
        let mut drift = 0.0f64;
        for _ in 0..2000 {
            integ.step(0.01).unwrap();
            let (g, mu) = (integ.configuration().unwrap(), integ.momentum());
            let (l, p) = CoupledBodies::<RigidBodySe3, 3>::total_momentum(g, &mu);
            let size = g
                .parts
                .iter()
                .map(|gk| 1.0 + gk.translation().norm())
                .fold(0.0, f64::max)
                * mu.parts.iter().map(|m| m.amax()).fold(0.0, f64::max);
            drift = drift.max((l - l0).amax().max((p - p0).amax()) / size);
        }
        println!("three bodies, {name}: momentum drift {drift:.1e}");
        assert!(drift < 1e-13, "{name}: {drift:e}");
    }
}

/// The energy error of the symmetric methods stays bounded over a long run of the (chaotic)
/// three-body system: over T = 200 (20 000 steps of 0.01) its maximum over the last tenth is
/// within 2× its maximum over the first tenth (measured 1.2–1.3 for Lie–Poisson, 0.5 for Strang);
/// RKMK4, which drifts, exceeds 2× — the negative control, run alongside.
#[test]
fn three_bodies_energy_error_is_bounded() {
    let (g0, mu0) = start3();
    let runs: Vec<(&str, Box<dyn Integrator<Group = G3>>)> = vec![
        (
            "LP exp θ = ½",
            Box::new(LiePoisson::<G3, ExpMap, _>::new(three(), 0.5, mu0, Some(g0)).unwrap()),
        ),
        (
            "LP cayley θ = ½",
            Box::new(LiePoisson::<G3, Cayley, _>::new(three(), 0.5, mu0, Some(g0)).unwrap()),
        ),
        (
            "Strang",
            Box::new(Splitting::new(three(), mu0, Some(g0)).unwrap()),
        ),
    ];
    for (name, mut integ) in runs {
        let (e0, steps) = (integ.energy(), 20_000);
        let (mut first, mut last) = (0.0f64, 0.0f64);
        for k in 0..steps {
            integ.step(0.01).unwrap();
            let de = (integ.energy() - e0).abs();
            if k < steps / 10 {
                first = first.max(de);
            } else if k >= steps - steps / 10 {
                last = last.max(de);
            }
        }
        println!(
            "three bodies, {name}: energy error first tenth {first:.2e}, last tenth {last:.2e}"
        );
        assert!(last <= 2.0 * first, "{name}: {first:e} {last:e}");
    }
    let (first, last) =
        energy_error_tenths(Rkmk4::new(three(), mu0, Some(g0)).unwrap(), 0.01, 20_000);
    println!("three bodies, RKMK4: energy error first tenth {first:.2e}, last tenth {last:.2e}");
    assert!(last > 2.0 * first, "RKMK4 should drift: {first:e} {last:e}");
}

/// RK4 on each body's (R, x, Π, P) with the springs' forces written here from the module page:
/// on body i `(a × R_iᵀ(−f)… )`, i.e. `Π̇_i = Π_i × Ω_i + a × R_iᵀf_i`, `Ṗ_i = P_i × Ω_i + R_iᵀf_i`
/// with f_i the spatial spring force on body i (`−κ(|d| − L) d/|d|` at its point, d from j to i).
fn reference(t_end: f64) -> DVector<f64> {
    let bodies = bodies3();
    let springs = springs3();
    let (g0, mu0) = start3();
    let y0 = DVector::from_vec(
        (0..3)
            .flat_map(|k| pack_se3(&g0.parts[k], &mu0.parts[k]))
            .collect(),
    );
    let iinv: Vec<Matrix3<f64>> = bodies
        .iter()
        .map(|b| b.inertia().try_inverse().unwrap())
        .collect();
    let f = |_t: f64, y: &DVector<f64>| {
        let r = |k: usize| Matrix3::from_column_slice(&y.as_slice()[18 * k..18 * k + 9]);
        let x = |k: usize| Vector3::from_column_slice(&y.as_slice()[18 * k + 9..18 * k + 12]);
        let mut wrench = [Vector6::<f64>::zeros(); 3];
        for s in &springs {
            let [i, j] = s.bodies;
            let (a, b) = (s.attachments[0], s.attachments[1]);
            let d = (x(i) + r(i) * a) - (x(j) + r(j) * b);
            let fi = -d * (s.stiffness * (d.norm() - s.rest_length) / d.norm());
            for (k, point, force) in [(i, a, fi), (j, b, -fi)] {
                let fb = r(k).transpose() * force;
                let m = point.cross(&fb);
                wrench[k] += Vector6::new(m.x, m.y, m.z, fb.x, fb.y, fb.z);
            }
        }
        let mut dy = DVector::zeros(54);
        for k in 0..3 {
            let o = 18 * k;
            let pi = Vector3::from_column_slice(&y.as_slice()[o + 12..o + 15]);
            let p = Vector3::from_column_slice(&y.as_slice()[o + 15..o + 18]);
            let om = iinv[k] * pi;
            dy.rows_mut(o, 9)
                .copy_from_slice((r(k) * om.cross_matrix()).as_slice());
            dy.rows_mut(o + 9, 3)
                .copy_from(&(r(k) * p / bodies[k].mass()));
            dy.rows_mut(o + 12, 3)
                .copy_from(&(pi.cross(&om) + wrench[k].fixed_rows::<3>(0)));
            dy.rows_mut(o + 15, 3)
                .copy_from(&(p.cross(&om) + wrench[k].fixed_rows::<3>(3)));
        }
        dy
    };
    rk4_richardson(f, &y0, t_end, 8000)
}

/// Lie–Poisson θ = ½ (exp, Cayley) and Strang converge at order 2 to the independent reference
/// (T = 3, h = 0.02 … 0.005; RK4 at 3.75e-4 and 7.5e-4, Richardson).
#[test]
fn three_bodies_converge_at_order_2_to_an_independent_rk4() {
    let t_end = 3.0;
    let yref = reference(t_end);
    let (g0, mu0) = start3();
    let error = |integ: &mut dyn Integrator<Group = G3>, h: f64| {
        for _ in 0..(t_end / h).round() as usize {
            integ.step(h).unwrap();
        }
        let (g, mu) = (integ.configuration().unwrap(), integ.momentum());
        (0..3).fold(0.0f64, |e, k| {
            let (r, x, m) = unpack_se3(&yref.as_slice()[18 * k..]);
            e.max((g.parts[k].rotation().as_matrix() - r).amax())
                .max((g.parts[k].translation() - x).amax())
                .max((mu.parts[k] - m).amax())
        })
    };
    let hs = [0.02, 0.01, 0.005];
    let lp_exp = hs.map(|h| {
        error(
            &mut LiePoisson::<G3, ExpMap, _>::new(three(), 0.5, mu0, Some(g0)).unwrap(),
            h,
        )
    });
    let lp_cay = hs.map(|h| {
        error(
            &mut LiePoisson::<G3, Cayley, _>::new(three(), 0.5, mu0, Some(g0)).unwrap(),
            h,
        )
    });
    let strang = hs.map(|h| error(&mut Splitting::new(three(), mu0, Some(g0)).unwrap(), h));
    for (name, errs) in [
        ("LP exp θ = ½", lp_exp),
        ("LP cayley θ = ½", lp_cay),
        ("Strang", strang),
    ] {
        let order = fitted_order(&hs, &errs);
        println!("three bodies, {name}: errors {errs:?}, order {order:.3}");
        assert!((1.9..=2.1).contains(&order), "{name}: order {order}");
    }
}

/// The Hessian's size without the matrix is the matrix's largest entry.
#[test]
fn coupled_bodies_hessian_norm_is_the_hessians() {
    use integrators::System;
    let chain = three();
    let mu =
        PowerAlgebra::from_parts_fn(|k| Vector6::new(0.3, -1.0 + k as f64, 0.2, 0.5, 0.1, -0.4));
    assert_eq!(chain.hessian_norm(&mu), chain.hessian(&mu).amax());
}
