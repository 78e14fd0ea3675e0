//! The generalized rigid body on SO(n) (`systems::GeneralizedRigidBody`): n = 3 agrees with the
//! free rigid body on SO(3); n = 4 conserves tr(M²), tr(M⁴) to round-off, has no energy drift and
//! converges at the measured order against RK4; n = 10, 20, 50 construct and step.

use crate::common::*;
use faer::{Col, Mat};
use integrators::{
    integrate, EulerArnold, Integrator, LiePoisson, SolverConfig, SolverKind, System,
};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, SoN, Tau};
use mechanics::systems::{GeneralizedRigidBody, RigidBody};
use nalgebra::{DMatrix, DVector, Vector3};

#[test]
fn so3_coordinates_map_the_free_rigid_body_exactly() {
    // Principal moments (I₁, I₂, I₃) ↦ j = ((I₂+I₃−I₁)/2, (I₁+I₃−I₂)/2, (I₁+I₂−I₃)/2); So3's Π ↦
    // SoN<3>'s (Π_z, −Π_y, Π_x) with identical rotation matrices. The two Lie–Poisson runs do the
    // same arithmetic in a different basis: agreement to 1e-12 after 200 steps.
    let moments = [1.0, 2.0, 2.5];
    let body = RigidBody::principal([moments[0], moments[1], moments[2]]).unwrap();
    let gen = GeneralizedRigidBody::<3>::from_principal_moments(moments).unwrap();
    let pi0 = Vector3::new(0.8, 0.5, 0.6);
    let to_son = |p: &Vector3<f64>| Col::from_fn(3, |i| [p.z, -p.y, p.x][i]);
    let r0m = r0();
    let g0 = So3::from_matrix(&r0m).unwrap();
    let s0 = SoN::<3>::from_matrix(&Mat::from_fn(3, 3, |i, j| r0m[(i, j)])).unwrap();
    assert!((gen.hamiltonian(&to_son(&pi0)) - body.hamiltonian(&pi0)).abs() < 1e-15);
    for theta in [0.0, 0.5] {
        let mut a = LiePoisson::<So3, Cayley, _>::new(body.clone(), theta, pi0, Some(g0)).unwrap();
        let mut b = LiePoisson::<SoN<3>, Cayley, _>::new(
            gen.clone(),
            theta,
            to_son(&pi0),
            Some(s0.clone()),
        )
        .unwrap();
        integrate(&mut a, 0.05, 200, |_| {}).unwrap();
        integrate(&mut b, 0.05, 200, |_| {}).unwrap();
        let dmu = (b.momentum() - to_son(&a.momentum())).norm_max();
        let ra = a.configuration().unwrap().as_matrix();
        let rb = b.configuration().unwrap().matrix();
        let dr = (0..3)
            .flat_map(|i| (0..3).map(move |j| (i, j)))
            .fold(0.0f64, |m, (i, j)| m.max((ra[(i, j)] - rb[(i, j)]).abs()));
        println!("SO(3) vs SoN<3> θ={theta}: Δμ {dmu:.2e}, ΔR {dr:.2e}");
        assert!(
            dmu < 1e-12 && dr < 1e-12,
            "θ={theta}: Δμ {dmu:e}, ΔR {dr:e}"
        );
    }
}

#[test]
fn generalized_body_matches_euler_arnold_with_dense_inertia() {
    // The diagonal closed forms equal the generic EulerArnold system with 𝕀 = JΩ + ΩJ as a dense
    // operator (built from the matrix definition, not from the pair weights).
    let j = [0.5, 1.0, 1.7, 2.2];
    let gen = GeneralizedRigidBody::<4>::new(&j).unwrap();
    let d = SoN::<4>::DIM;
    let jm = Mat::from_fn(4, 4, |a, b| if a == b { j[a] } else { 0.0 });
    let inertia = Mat::from_fn(d, d, |_, _| 0.0);
    let mut inertia = inertia;
    for q in 0..d {
        let e = Col::from_fn(d, |i| if i == q { 1.0 } else { 0.0 });
        let w = SoN::<4>::hat(&e);
        let m = &jm * &w + &w * &jm;
        let col = SoN::<4>::vee(&m);
        for p in 0..d {
            inertia[(p, q)] = col[p];
        }
    }
    let ea = EulerArnold::<SoN<4>>::new(inertia).unwrap();
    let mu = Col::from_fn(d, |i| 0.3 * i as f64 - 0.4);
    assert!((gen.hamiltonian(&mu) - ea.hamiltonian(&mu)).abs() < 1e-15);
    assert!((gen.velocity(&mu) - ea.velocity(&mu)).norm_max() < 1e-15);
    assert!((gen.momentum(&mu) - ea.momentum(&mu)).norm_max() < 1e-15);
}

#[test]
fn generalized_body_refuses_bad_mass_matrix() {
    assert!(GeneralizedRigidBody::<4>::new(&[1.0, 1.0, 1.0]).is_err());
    assert!(GeneralizedRigidBody::<4>::new(&[1.0, 0.0, 1.0, 1.0]).is_err());
    assert!(GeneralizedRigidBody::<4>::new(&[1.0, f64::NAN, 1.0, 1.0]).is_err());
    // Moments violating the triangle inequality have no mass matrix.
    assert!(GeneralizedRigidBody::<3>::from_principal_moments([1.0, 1.0, 3.0]).is_err());
}

fn body4() -> GeneralizedRigidBody<4> {
    GeneralizedRigidBody::<4>::new(&[0.5, 1.0, 1.7, 2.2]).unwrap()
}

fn mu4() -> Col<f64> {
    Col::from_fn(6, |i| [0.7, -0.3, 0.5, 0.9, -0.6, 0.2][i])
}

#[test]
fn so4_casimirs_conserved_to_round_off() {
    // M_{k+1} = τ(ξ)ᵀ M_k τ(ξ) is a similarity by an orthogonal matrix: tr(M²), tr(M⁴) change by
    // round-off only. Bound 5e-12 relative over 300 steps, every θ and τ (tr(M⁴) is quartic in M:
    // its relative round-off is ~4× that of M; measured up to 1.4e-12 over 1000 steps).
    let c0 = GeneralizedRigidBody::<4>::casimirs(&mu4());
    for theta in [0.0, 0.5, 1.0] {
        for tau in ["exp", "cayley"] {
            let mut worst = 0.0f64;
            let mut obs = |i: &dyn Integrator<Group = SoN<4>>| {
                let c = GeneralizedRigidBody::<4>::casimirs(&i.momentum());
                for k in 0..2 {
                    worst = worst.max(((c[k] - c0[k]) / c0[k]).abs());
                }
            };
            if tau == "exp" {
                let mut lp =
                    LiePoisson::<SoN<4>, ExpMap, _>::new(body4(), theta, mu4(), None).unwrap();
                integrate(&mut lp, 0.05, 300, |i| obs(i)).unwrap();
            } else {
                let mut lp =
                    LiePoisson::<SoN<4>, Cayley, _>::new(body4(), theta, mu4(), None).unwrap();
                integrate(&mut lp, 0.05, 300, |i| obs(i)).unwrap();
            }
            println!(
                "SO(4) Casimirs tr(M²), tr(M⁴) {tau} θ={theta}: max relative drift {worst:.2e}"
            );
            assert!(worst < 5e-12, "{tau} θ={theta}: {worst:e}");
        }
    }
}

#[test]
fn so4_energy_error_bounded_without_drift() {
    for theta in [0.0, 0.5] {
        let (f, l) = energy_error_tenths(
            LiePoisson::<SoN<4>, Cayley, _>::new(body4(), theta, mu4(), None).unwrap(),
            0.05,
            1000,
        );
        println!("SO(4) energy error cayley θ={theta}: first tenth {f:.2e}, last {l:.2e}");
        assert!(l <= 2.0 * f + 1e-14, "θ={theta}: first {f:e}, last {l:e}");
    }
}

/// `ξ̂` in lie-groups' SO(n) convention (lexicographic pairs, `ξ̂_{ji} = ξ_p`), on nalgebra.
fn hat_n(n: usize, xi: &[f64]) -> DMatrix<f64> {
    let mut m = DMatrix::zeros(n, n);
    let mut p = 0;
    for i in 0..n {
        for j in i + 1..n {
            m[(j, i)] = xi[p];
            m[(i, j)] = -xi[p];
            p += 1;
        }
    }
    m
}

/// RK4 on (R, M̂) for `Ṙ = RΩ̂`, `Ṁ = [M̂, Ω̂]`, Ω_p = M_p/(jᵢ + jⱼ), written on nalgebra matrices.
fn rk4_so4(j: &[f64; 4], mu0: &[f64], t: f64, n: usize) -> DVector<f64> {
    let w: Vec<f64> = (0..4)
        .flat_map(|a| (a + 1..4).map(move |b| (a, b)))
        .map(|(a, b)| j[a] + j[b])
        .collect();
    let mut y0 = DVector::zeros(22);
    y0.rows_mut(0, 16).copy_from(&DVector::from_column_slice(
        DMatrix::<f64>::identity(4, 4).as_slice(),
    ));
    y0.rows_mut(16, 6).copy_from_slice(mu0);
    let f = |y: &DVector<f64>| {
        let r = DMatrix::from_column_slice(4, 4, &y.as_slice()[0..16]);
        let mu = &y.as_slice()[16..22];
        let om: Vec<f64> = (0..6).map(|p| mu[p] / w[p]).collect();
        let (mh, oh) = (hat_n(4, mu), hat_n(4, &om));
        let rdot = &r * &oh;
        let mdot = &mh * &oh - &oh * &mh;
        let mut dy = DVector::zeros(22);
        dy.rows_mut(0, 16).copy_from_slice(rdot.as_slice());
        let mut p = 0;
        for a in 0..4 {
            for b in a + 1..4 {
                dy[16 + p] = mdot[(b, a)];
                p += 1;
            }
        }
        dy
    };
    rk4_dvec(f, &y0, t, n)
}

fn order_so4<T: Tau<SoN<4>>>(theta: f64) -> f64 {
    let j = [0.5, 1.0, 1.7, 2.2];
    let mu0: Vec<f64> = (0..6).map(|i| mu4()[i]).collect();
    let t = 1.0;
    let yr = rk4_so4(&j, &mu0, t, 4_000);
    let (mut hs, mut errs) = (vec![], vec![]);
    for n in [20usize, 40, 80, 160] {
        let h = t / n as f64;
        let mut lp =
            LiePoisson::<SoN<4>, T, _>::new(body4(), theta, mu4(), Some(SoN::<4>::identity()))
                .unwrap();
        integrate(&mut lp, h, n, |_| {}).unwrap();
        let r = lp.configuration().unwrap().matrix();
        let mu = lp.momentum();
        let mut err = 0.0f64;
        for a in 0..4 {
            for b in 0..4 {
                err = err.max((r[(a, b)] - yr[b * 4 + a]).abs());
            }
        }
        for p in 0..6 {
            err = err.max((mu[p] - yr[16 + p]).abs());
        }
        hs.push(h);
        errs.push(err);
    }
    let p = fitted_order(&hs, &errs);
    println!(
        "SO(4) LP {} θ={theta}: errors {errs:?}, order {p:.3}",
        T::NAME
    );
    p
}

#[test]
fn so4_lie_poisson_orders_against_rk4() {
    // No potential: order 2 for θ = ½ and θ = 0 alike (as for the free rigid body on SO(3)).
    // Tolerance 0.1 on the slope over h = 1/20 … 1/160.
    for theta in [0.5, 0.0] {
        let e = order_so4::<ExpMap>(theta);
        let c = order_so4::<Cayley>(theta);
        assert!(
            (e - 2.0).abs() < 0.1 && (c - 2.0).abs() < 0.1,
            "θ={theta}: exp {e:.3}, cayley {c:.3}"
        );
    }
}

/// One Lie–Poisson step (Cayley, θ = ½) on SO(N) with J = diag(1, 2, …, N) from R = I; returns
/// the relative changes of the Casimirs and of the energy.
fn one_step<const N: usize>(kind: SolverKind) -> (f64, f64) {
    let j: Vec<f64> = (1..=N).map(|i| i as f64).collect();
    let body = GeneralizedRigidBody::<N>::new(&j).unwrap();
    let d = SoN::<N>::DIM;
    let mu0 = Col::from_fn(d, |p| ((p * 7919) % 13) as f64 / 13.0 - 0.5);
    let cfg = SolverConfig {
        kind,
        ..SolverConfig::default()
    };
    let mut lp =
        LiePoisson::<SoN<N>, Cayley, _>::new(body, 0.5, mu0.clone(), Some(SoN::<N>::identity()))
            .unwrap()
            .with_solver(cfg);
    let e0 = lp.energy();
    lp.step(0.01).unwrap();
    let c0 = GeneralizedRigidBody::<N>::casimirs(&mu0);
    let c1 = GeneralizedRigidBody::<N>::casimirs(&lp.momentum());
    let dc = c0
        .iter()
        .zip(&c1)
        .fold(0.0f64, |m, (a, b)| m.max(((a - b) / a).abs()));
    (dc, ((lp.energy() - e0) / e0).abs())
}

#[test]
fn large_n_bodies_construct_and_step() {
    // n = 10 and 20 with the default Newton solver (dense LU on faer Mat of size 45 and 190);
    // n = 50 (dim 1225) with the fixed-point iteration, which forms no Jacobian: the debug-mode
    // cost of Newton's 1225² Jacobian products is tested in the ignored test below.
    // One step of h = 0.01: Casimirs to 1e-11 relative (⌊n/2⌋ of them, up to tr(M⁵⁰)), energy
    // to 1e-5 relative (the per-step energy error is O(h³)).
    for (n, (dc, de)) in [
        (10, one_step::<10>(SolverKind::Newton)),
        (20, one_step::<20>(SolverKind::Newton)),
        (50, one_step::<50>(SolverKind::FixedPoint)),
    ] {
        println!("SO({n}) one step: Casimir change {dc:.2e}, energy change {de:.2e}");
        assert!(dc < 1e-11 && de < 1e-5, "n = {n}: {dc:e}, {de:e}");
    }
}

#[test]
fn so50_newton_step() {
    let (dc, de) = one_step::<50>(SolverKind::Newton);
    println!("SO(50) Newton step: Casimir change {dc:.2e}, energy change {de:.2e}");
    assert!(dc < 1e-11 && de < 1e-5, "{dc:e}, {de:e}");
}

#[test]
fn so3_mass_matrix_reproduces_principal_moments() {
    let g = GeneralizedRigidBody::<3>::from_principal_moments([1.0, 2.0, 2.5]).unwrap();
    // pair order (0,1), (0,2), (1,2) ↦ (I₃, I₂, I₁)
    let w = g.inertia_diagonal();
    assert!((w[0] - 2.5).abs() < 1e-15 && (w[1] - 2.0).abs() < 1e-15 && (w[2] - 1.0).abs() < 1e-15);
}

/// The Hessian's size without the dense d × d matrix is the matrix's largest entry.
#[test]
fn so_n_hessian_norm_is_the_hessians() {
    let body = GeneralizedRigidBody::<4>::new(&[1.0, 2.0, 3.5, 0.7]).unwrap();
    let mu = Col::from_fn(6, |p| 0.3 * p as f64 - 0.5);
    assert_eq!(body.hessian_norm(&mu), body.hessian(&mu).norm_max());
}
