//! The modified-Hamiltonian θ = ½ Lie–Poisson methods (`integrators::modified`): H̃'s derivatives
//! against finite differences, fitted orders against the exact free-body flow, invariants,
//! reversibility, bad input.

mod common;

use common::{fitted_order, r0};
use integrators::exact::FreeBodyFlow;
use integrators::modified::{ModifiedLiePoisson, ModifiedRigidBody, ModifiedTau};
use integrators::systems::RigidBody;
use integrators::{Integrator, IntegratorError, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3};
use nalgebra::{Matrix3, Vector3};

fn bodies() -> Vec<RigidBody> {
    let full = Matrix3::new(2.0, 0.3, -0.2, 0.3, 1.5, 0.1, -0.2, 0.1, 3.0);
    vec![
        RigidBody::principal(1.0, 2.0, 3.0).unwrap(),
        RigidBody::new(full).unwrap(),
    ]
}

fn pi0() -> Vector3<f64> {
    Vector3::new(0.9, 0.5, -0.7)
}

/// ∂H̃/∂Π and ∂²H̃/∂Π² against central differences of H̃ and of ∂H̃/∂Π.
fn derivatives_match_finite_differences<T: ModifiedTau>() {
    for body in bodies() {
        let m = ModifiedRigidBody::<T>::new(body, 0.3).unwrap();
        let p = pi0();
        let d = 1e-5;
        let (v, hess) = (m.velocity(&p), m.hessian(&p));
        for i in 0..3 {
            let e = Vector3::ith(i, d);
            let fd = (m.hamiltonian(&(p + e)) - m.hamiltonian(&(p - e))) / (2.0 * d);
            assert!((fd - v[i]).abs() < 1e-9, "gradient {i}: {fd} vs {}", v[i]);
            let fdv = (m.velocity(&(p + e)) - m.velocity(&(p - e))) / (2.0 * d);
            assert!((fdv - hess.column(i)).norm() < 1e-8, "Hessian column {i}");
        }
        // The Legendre map inverts the velocity.
        assert!((m.velocity(&m.momentum(&v)) - v).norm() < 1e-13);
    }
}

#[test]
fn modified_hamiltonian_derivatives_cayley() {
    derivatives_match_finite_differences::<Cayley>();
}

#[test]
fn modified_hamiltonian_derivatives_exp() {
    derivatives_match_finite_differences::<ExpMap>();
}

/// max(|ΔΠ|, ‖ΔR‖) at T against the exact flow.
fn error_at<I: Integrator<Group = So3>>(mut m: I, body: &RigidBody, h: f64, n: usize) -> f64 {
    let flow = FreeBodyFlow::new(body);
    let r = So3::from_matrix(&r0()).unwrap();
    let (pe, re) = flow.advance(h * n as f64, &pi0(), Some(&r)).unwrap();
    for _ in 0..n {
        m.step(h).unwrap();
    }
    let dp = (m.momentum() - pe).norm();
    let dr = (m.configuration().unwrap().as_matrix() - re.unwrap().as_matrix()).norm();
    dp.max(dr)
}

fn fit<T: ModifiedTau>(body: &RigidBody, modified: bool) -> f64 {
    let hs = [0.2, 0.1, 0.05, 0.025];
    let r = So3::from_matrix(&r0()).unwrap();
    let errs: Vec<f64> = hs
        .iter()
        .map(|&h| {
            let n = (2.0_f64 / h).round() as usize;
            if modified {
                let m = ModifiedLiePoisson::<T>::new(body.clone(), pi0(), Some(r)).unwrap();
                error_at(m, body, h, n)
            } else {
                let m = LiePoisson::<So3, T, _>::new(body.clone(), 0.5, pi0(), Some(r)).unwrap();
                error_at(m, body, h, n)
            }
        })
        .collect();
    let p = fitted_order(&hs, &errs);
    eprintln!(
        "{} modified={modified}: errors {errs:?}, order {p:.3}",
        <T as lie_groups::Tau<So3>>::NAME
    );
    p
}

#[test]
fn order_four_against_exact_flow() {
    for body in bodies() {
        for (p, name) in [
            (fit::<Cayley>(&body, true), "cayley"),
            (fit::<ExpMap>(&body, true), "exp"),
        ] {
            assert!((p - 4.0).abs() < 0.2, "{name}: fitted order {p}");
        }
        // The unmodified kernel is order 2: the modification is what raises it.
        let p2 = fit::<Cayley>(&body, false);
        assert!((p2 - 2.0).abs() < 0.2, "kernel order {p2}");
    }
}

/// The reference itself for a full inertia tensor: the exact flow's velocity at t = 0 is Euler's
/// Π × Ω (before the principal frame was made right-handed it was −Π × Ω).
#[test]
fn exact_flow_reference_full_inertia_matches_euler_equations() {
    let body = bodies()[1].clone();
    let flow = FreeBodyFlow::new(&body);
    let d = 1e-4;
    let (pp, _) = flow.advance(d, &pi0(), None).unwrap();
    let (pm, _) = flow.advance(-d, &pi0(), None).unwrap();
    let fd = (pp - pm) / (2.0 * d);
    assert!((fd - body.euler_rhs(&pi0())).norm() < 1e-7, "{fd:?}");
    let (axes, _) = body.principal_frame();
    assert!((axes.determinant() - 1.0).abs() < 1e-12);
}

fn method<T: ModifiedTau>(body: RigidBody) -> ModifiedLiePoisson<T> {
    ModifiedLiePoisson::<T>::new(body, pi0(), Some(So3::from_matrix(&r0()).unwrap())).unwrap()
}

/// |Π|² and RΠ to round-off, and the energy bounded without drift (mean |H − H₀| over the first
/// and the last tenth of 10⁵ steps at h = 0.1, 10⁴ time units).
fn invariants<T: ModifiedTau>() {
    let body = bodies()[0].clone();
    let mut m = method::<T>(body);
    let (c0, e0) = (m.casimir().unwrap(), m.energy());
    let m0 = m.configuration().unwrap().as_matrix() * m.momentum();
    let n = 100_000;
    let (mut first, mut last, mut cmax, mut mmax) = (0.0, 0.0, 0.0f64, 0.0f64);
    for k in 0..n {
        m.step(0.1).unwrap();
        let de = (m.energy() - e0).abs();
        if k < n / 10 {
            first += de;
        } else if k >= n - n / 10 {
            last += de;
        }
        cmax = cmax.max((m.casimir().unwrap() - c0).abs());
        mmax = mmax.max((m.configuration().unwrap().as_matrix() * m.momentum() - m0).norm());
    }
    let (first, last) = (first / (n / 10) as f64, last / (n / 10) as f64);
    eprintln!(
        "casimir {cmax:.2e}, momentum map {mmax:.2e}, energy first {first:.3e} last {last:.3e}"
    );
    assert!(cmax < 1e-12, "Casimir drift {cmax}");
    assert!(mmax < 1e-11, "momentum map drift {mmax}");
    assert!(last < 1.5 * first + 1e-15, "energy drift: {first} → {last}");
    assert!(first < 1e-4, "energy error {first}");
}

#[test]
fn invariants_cayley() {
    invariants::<Cayley>();
}

#[test]
fn invariants_exp() {
    invariants::<ExpMap>();
}

/// Φ_{−h} ∘ Φ_h = id to the solver's tolerance.
#[test]
fn time_reversible() {
    let mut m = method::<Cayley>(bodies()[1].clone());
    let (t0, p0, r0) = (
        m.time(),
        m.momentum(),
        *m.configuration().unwrap().as_matrix(),
    );
    for _ in 0..10 {
        m.step(0.2).unwrap();
    }
    for _ in 0..10 {
        m.step(-0.2).unwrap();
    }
    assert!(
        (m.momentum() - p0).norm() < 1e-12,
        "{:e}",
        (m.momentum() - p0).norm()
    );
    assert!((m.configuration().unwrap().as_matrix() - r0).norm() < 1e-12);
    assert!((m.time() - t0).abs() < 1e-14);
    assert!(m.info().symmetric && m.info().order == 4 && !m.info().explicit);
}

#[test]
fn bad_input_errors_and_leaves_state_untouched() {
    let mut m = method::<Cayley>(bodies()[0].clone());
    m.step(0.1).unwrap();
    let before = (
        m.time(),
        m.momentum(),
        *m.configuration().unwrap().as_matrix(),
    );
    let same = |m: &ModifiedLiePoisson<Cayley>| {
        (
            m.time(),
            m.momentum(),
            *m.configuration().unwrap().as_matrix(),
        ) == before
    };
    for h in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(m.step(h), Err(IntegratorError::NonFinite { .. })));
        assert!(same(&m));
    }
    // A step far beyond the scheme's reach (h|Ω| ≈ 1e3): an error, never a panic.
    assert!(m.step(1e3).is_err());
    assert!(same(&m));
    // It still steps normally afterwards.
    m.step(0.1).unwrap();
    let nan = Vector3::new(f64::NAN, 0.0, 1.0);
    assert!(ModifiedLiePoisson::<ExpMap>::new(bodies()[0].clone(), nan, None).is_err());
    assert!(ModifiedRigidBody::<ExpMap>::new(bodies()[0].clone(), f64::NAN).is_err());
}
