//! The Gragg–Bulirsch–Stoer reference method (`integrators::GraggBulirschStoer`) against closed
//! forms: its order 2k fitted over several steps for k = 2, 3, 4 on the symmetric top (SO(3)), the
//! free symmetric body on SE(3) (Π, P and the straight-line centre of mass) and a torqued, damped
//! rotation about a principal axis (a time-dependent external force); the default k = 6 at 1e-13;
//! the heavy top (a potential read at the stages' g) against classical RK4; refusals leave the
//! state untouched.

use crate::common::*;
use integrators::forces::{BodyTorque, Forced, LinearDamping, Schedule};
use integrators::{GraggBulirschStoer, Integrator, IntegratorError, System};
use lie_groups::{LieGroup, Se3, So3};
use mechanics::systems::{HeavyTop, RigidBody, RigidBodySe3};
use nalgebra::{Matrix3, Vector3, Vector6};

/// `n` steps of size T/n; the final (R, Π) (or the SE(3) parts) through `read`.
fn run_to<G: LieGroup, S: System<G>, R>(
    mut m: GraggBulirschStoer<G, S>,
    t: f64,
    n: usize,
    read: impl Fn(&GraggBulirschStoer<G, S>) -> R,
) -> R {
    for _ in 0..n {
        m.step(t / n as f64).unwrap();
    }
    assert!((m.time() - t).abs() < 1e-12 * t);
    read(&m)
}

fn so3_state<S: System<So3>>(m: &GraggBulirschStoer<So3, S>) -> (Matrix3<f64>, Vector3<f64>) {
    (*m.configuration().unwrap().as_matrix(), m.momentum())
}

/// max(|ΔR|∞, |ΔΠ|∞).
fn distance(a: &(Matrix3<f64>, Vector3<f64>), b: &(Matrix3<f64>, Vector3<f64>)) -> f64 {
    (a.0 - b.0).amax().max((a.1 - b.1).amax())
}

/// The fitted order over the step counts `ns` and the errors, printed.
fn order_of(label: &str, t: f64, ns: &[usize], errs: &[f64]) -> f64 {
    let hs: Vec<f64> = ns.iter().map(|&n| t / n as f64).collect();
    let p = fitted_order(&hs, errs);
    println!("{label}: h {hs:?}, errors {errs:?}, order {p:.3}");
    p
}

/// The step counts per k over T = 8 for the order fits: the errors stay between ~1e-3 and ~1e-12
/// (above round-off, inside the asymptotic range).
fn ladder(k: usize) -> &'static [usize] {
    match k {
        2 => &[16, 32, 64, 128],
        3 => &[8, 16, 32, 64],
        _ => &[4, 8, 16, 32],
    }
}

/// The step counts of the forced rotation, whose error constants are smaller (its Π keeps its
/// direction): for k = 4, 32 steps reach round-off (1.2e-15) and 2 steps are pre-asymptotic (local
/// slope 8.5), so 3 … 24 steps (6.7e-8 … 4.2e-15).
fn forced_ladder(k: usize) -> &'static [usize] {
    match k {
        4 => &[3, 6, 12, 24],
        _ => ladder(k),
    }
}

/// The symmetric top 𝕀 = diag(2, 2, 3.5) from R₀ ≠ I against its closed form: order 2k for k = 2,
/// 3, 4; the default k = 6 within 1e-13 at hω ≈ 0.25.
#[test]
fn order_2k_on_the_symmetric_top() {
    let (i, i3) = (2.0, 3.5);
    let body = RigidBody::principal([i, i, i3]).unwrap();
    let pi0 = Vector3::new(0.9, -0.6, 1.4);
    let r0 = r0();
    let t = 8.0;
    let exact = axisymmetric_exact(i, i3, &r0, &pi0, t);
    let g0 = So3::from_matrix(&r0).unwrap();
    for k in [2usize, 3, 4] {
        let ns = ladder(k);
        let errs: Vec<f64> = ns
            .iter()
            .map(|&n| {
                let m = GraggBulirschStoer::with_columns(body.clone(), pi0, Some(g0), k).unwrap();
                distance(&run_to(m, t, n, so3_state), &exact)
            })
            .collect();
        let p = order_of(&format!("symmetric top k = {k}"), t, ns, &errs);
        assert!((p - 2.0 * k as f64).abs() < 0.15, "k = {k}: order {p:.3}");
    }
    // |Ω| = 0.69: 64 steps of h = 0.125.
    let m = GraggBulirschStoer::new(body, pi0, Some(g0)).unwrap();
    assert_eq!(m.info().order, 12);
    let e = distance(&run_to(m, t, 64, so3_state), &exact);
    println!("symmetric top k = 6, h = 0.125: {e:.3e}");
    assert!(e <= 1e-13, "{e:e}");
}

/// The free symmetric body on SE(3): Π and R are the symmetric top's, P = Rᵀ p with the spatial
/// momentum p constant, and the centre of mass moves on the line x₀ + t p/m. Order 2k.
#[test]
fn order_2k_on_the_free_body_in_se3() {
    let (i, i3, mass) = (2.0, 3.5, 1.5);
    let sys = RigidBodySe3::free(mass, Matrix3::from_diagonal(&Vector3::new(i, i, i3))).unwrap();
    let r0 = r0();
    let x0 = Vector3::new(1.0, -0.5, 0.25);
    let p_spatial = Vector3::new(0.3, 0.8, -0.4);
    let pi0 = Vector3::new(0.9, -0.6, 1.4);
    let p0 = r0.transpose() * p_spatial;
    let mu0 = Vector6::new(pi0.x, pi0.y, pi0.z, p0.x, p0.y, p0.z);
    let g0 = Se3::from_parts(So3::from_matrix(&r0).unwrap(), x0);
    let t = 8.0;
    let (r, pi) = axisymmetric_exact(i, i3, &r0, &pi0, t);
    let p = r.transpose() * p_spatial;
    let x = x0 + p_spatial * (t / mass);
    let read = |m: &GraggBulirschStoer<Se3, RigidBodySe3>| {
        let g = m.configuration().unwrap();
        let mu = m.momentum();
        (g.rotation().as_matrix() - r)
            .amax()
            .max((g.translation() - x).amax())
            .max((mu.fixed_rows::<3>(0) - pi).amax())
            .max((mu.fixed_rows::<3>(3) - p).amax())
    };
    for k in [2usize, 3, 4] {
        let ns = ladder(k);
        let errs: Vec<f64> = ns
            .iter()
            .map(|&n| {
                let m = GraggBulirschStoer::with_columns(sys.clone(), mu0, Some(g0), k).unwrap();
                run_to(m, t, n, read)
            })
            .collect();
        let p = order_of(&format!("SE(3) free body k = {k}"), t, ns, &errs);
        assert!((p - 2.0 * k as f64).abs() < 0.15, "k = {k}: order {p:.3}");
    }
}

/// A rotation about the principal axis e₃ (I₃ = 3) under the torque ramp u(t) = (u₀ + u₁t) e₃
/// (a two-knot schedule, linear over [0, T]) and damping F = −D Ω, D = diag(0.2, 0.3, 0.6):
/// `Π₃' = u₀ + u₁t − aΠ₃`, a = d₃/I₃, so Π₃ = A + Bt + (Π₃(0) − A)e^{−at} with B = u₁/a,
/// A = (u₀ − B)/a, and R = R₀ Rz(φ), φ = (At + Bt²/2 + (Π₃(0) − A)(1 − e^{−at})/a)/I₃.
/// Order 2k: the force is evaluated at the substeps' times.
#[test]
fn order_2k_with_a_time_dependent_torque_and_damping() {
    let i3 = 3.0;
    let body = RigidBody::principal([1.0, 2.0, i3]).unwrap();
    let t = 8.0;
    let (u0, u1, d3) = (0.5, 0.25, 0.6);
    let torque = Schedule::new(
        vec![0.0, t],
        vec![vec![0.0, 0.0, u0], vec![0.0, 0.0, u0 + u1 * t]],
    )
    .unwrap();
    let damping = Matrix3::from_diagonal(&Vector3::new(0.2, 0.3, d3));
    let sys = Forced::new(
        body,
        (
            Some(BodyTorque::new(torque).unwrap()),
            Some(LinearDamping::<So3>::new(damping).unwrap()),
        ),
    );
    let pi30 = 2.0;
    let pi0 = Vector3::new(0.0, 0.0, pi30);
    let r0 = r0();
    let a = d3 / i3;
    let b = u1 / a;
    let aa = (u0 - b) / a;
    let pi3 = aa + b * t + (pi30 - aa) * (-a * t).exp();
    let phi = (aa * t + b * t * t / 2.0 + (pi30 - aa) * (1.0 - (-a * t).exp()) / a) / i3;
    let exact = (
        r0 * rodrigues(&Vector3::new(0.0, 0.0, phi)),
        Vector3::new(0.0, 0.0, pi3),
    );
    let g0 = So3::from_matrix(&r0).unwrap();
    for k in [2usize, 3, 4] {
        let ns = forced_ladder(k);
        let errs: Vec<f64> = ns
            .iter()
            .map(|&n| {
                let m = GraggBulirschStoer::with_columns(sys.clone(), pi0, Some(g0), k).unwrap();
                distance(&run_to(m, t, n, so3_state), &exact)
            })
            .collect();
        let p = order_of(&format!("forced rotation k = {k}"), t, ns, &errs);
        assert!((p - 2.0 * k as f64).abs() < 0.15, "k = {k}: order {p:.3}");
    }
}

/// The heavy top (the force −T*_e L_g dV read at each stage's g_k exp Θ) against classical RK4 on
/// (R, Π) with 20 000 steps over T = 2 (error ~1e-14): within 1e-12 at 32 steps.
#[test]
fn the_heavy_top_matches_an_independent_rk4() {
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.4, 0.8));
    let (mass, gravity, chi) = (1.0, 9.81, Vector3::new(0.0, 0.1, 0.3));
    let top = HeavyTop::new(inertia, mass, gravity, chi).unwrap();
    let pi0 = Vector3::new(0.4, 1.5, -0.7);
    let r0 = r0();
    let t = 2.0;
    let reference = rk4_heavy_top(&inertia, &(chi * mass * gravity), &r0, &pi0, t, 20_000);
    let m = GraggBulirschStoer::new(top, pi0, Some(So3::from_matrix(&r0).unwrap())).unwrap();
    let e = distance(&run_to(m, t, 32, so3_state), &reference);
    println!("heavy top k = 6, 32 steps: {e:.3e} from RK4");
    assert!(e <= 1e-12, "{e:e}");
}

/// A step whose exponential coordinates leave the series' domain (|Θ| ≈ 14 on SO(3)), a NaN step
/// and k outside 1 ..= 10 are refused; the state after a refused step is the state before it.
#[test]
fn refusals_name_the_cause_and_keep_the_state() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    // Π off the principal axes, so that Θ and ξ do not commute (about an axis the series is exact
    // in one term at any |Θ|).
    let pi0 = Vector3::new(1.0, 2.0, 3.0);
    let mut m = GraggBulirschStoer::new(body.clone(), pi0, Some(So3::identity())).unwrap();
    m.step(0.1).unwrap();
    let before = (
        m.time(),
        m.momentum(),
        *m.configuration().unwrap().as_matrix(),
    );
    let e = m.step(10.0).unwrap_err();
    assert!(
        matches!(e, IntegratorError::StepTooLarge { step, .. } if step == 10.0),
        "{e}"
    );
    assert!(e.to_string().contains("(d^L exp_Θ)⁻¹"), "{e}");
    let e = m.step(f64::NAN).unwrap_err();
    assert!(matches!(e, IntegratorError::NonFinite { .. }), "{e}");
    assert_eq!(
        (
            m.time(),
            m.momentum(),
            *m.configuration().unwrap().as_matrix()
        ),
        before
    );
    for k in [0, 11] {
        let e =
            GraggBulirschStoer::with_columns(body.clone(), Vector3::zeros(), None, k).unwrap_err();
        assert!(e.to_string().contains(&format!("got {k}")), "{e}");
    }
    let e = GraggBulirschStoer::new(body, Vector3::new(f64::NAN, 0.0, 0.0), None).unwrap_err();
    assert!(matches!(e, IntegratorError::NonFinite { .. }), "{e}");
}

/// Compensated summation of μ: a spin Π₃ = 1000 about e₃ under the constant torque u = 1e-3·√2
/// gains uh ≈ 1.4e-5 per step, far below an ulp of Π₃'s scale; over 10⁵ steps plain addition
/// would drift by up to 10⁵ · ε|Π₃|/2 ≈ 6e-9, the compensated sum stays within 1e-12 of
/// Π₃ + uT (relative 1e-15).
#[test]
fn many_small_increments_do_not_random_walk() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let u = 1e-3 * 2f64.sqrt();
    let sys = Forced::new(
        body,
        BodyTorque::new(Schedule::constant(vec![0.0, 0.0, u]).unwrap()).unwrap(),
    );
    let pi0 = Vector3::new(0.0, 0.0, 1000.0);
    let mut m = GraggBulirschStoer::with_columns(sys, pi0, None, 2).unwrap();
    let (h, n) = (0.01, 100_000);
    for _ in 0..n {
        m.step(h).unwrap();
    }
    let exact = 1000.0 + u * h * n as f64;
    let e = (m.momentum().z - exact).abs();
    println!("Π₃ after 10⁵ steps: {e:.2e} from Π₃(0) + uT");
    assert!(e <= 1e-12, "{e:e}");
}
