//! External forces in the splittings: the Strang splitting of the pieces and the exact-kinetic–kick
//! schemes on a forced free rigid body (𝕀 = diag(1, 2, 3)), against an independent RK4 on
//! (R, Π) written here: `Π̇ = Π × Ω + u(t) − DΩ`, `Ṙ = RΩ̂`.

use crate::common::{fitted_order, r0};
use integrators::forces::{BodyTorque, ExternalForce, Forced, LinearDamping};
use integrators::splitting::{KineticKick, SplitSystem, Splitting, SplittingScheme};
use integrators::{Integrator, IntegratorError, System};
use lie_groups::{LieGroup, So3};
use mechanics::exact::FreeBodyFlow;
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{Matrix3, Vector3};

const PI0: Vector3<f64> = Vector3::new(0.5, 1.0, -0.7);

/// A smooth torque of time, u(t) = (0.3 sin t, 0.2 cos 2t, 0.1): it reads neither g nor ξ.
#[derive(Debug, Clone)]
struct SmoothTorque;

impl SmoothTorque {
    fn at(t: f64) -> Vector3<f64> {
        Vector3::new(0.3 * t.sin(), 0.2 * (2.0 * t).cos(), 0.1)
    }
}

impl ExternalForce<So3> for SmoothTorque {
    fn force(&self, t: f64, _g: Option<&So3>, _xi: &Vector3<f64>) -> Vector3<f64> {
        Self::at(t)
    }
    fn reads_velocity(&self) -> bool {
        false
    }
}

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

fn damping() -> Matrix3<f64> {
    Matrix3::new(0.2, 0.05, 0.0, 0.05, 0.1, 0.0, 0.0, 0.0, 0.15)
}

/// RK4 on (R, Π) for the forced body, 𝕀 = diag(1, 2, 3), n steps over [0, t_end].
fn reference(d: Matrix3<f64>, t_end: f64, n: usize) -> (Matrix3<f64>, Vector3<f64>) {
    let iinv = Matrix3::from_diagonal(&Vector3::new(1.0, 0.5, 1.0 / 3.0));
    let f = |t: f64, r: &Matrix3<f64>, p: &Vector3<f64>| {
        let om = iinv * p;
        (
            r * om.cross_matrix(),
            p.cross(&om) + SmoothTorque::at(t) - d * om,
        )
    };
    let h = t_end / n as f64;
    let (mut r, mut p) = (r0(), PI0);
    for k in 0..n {
        let t = k as f64 * h;
        let (a1, b1) = f(t, &r, &p);
        let (a2, b2) = f(t + h / 2.0, &(r + a1 * (h / 2.0)), &(p + b1 * (h / 2.0)));
        let (a3, b3) = f(t + h / 2.0, &(r + a2 * (h / 2.0)), &(p + b2 * (h / 2.0)));
        let (a4, b4) = f(t + h, &(r + a3 * h), &(p + b3 * h));
        r += (a1 + a2 * 2.0 + a3 * 2.0 + a4) * (h / 6.0);
        p += (b1 + b2 * 2.0 + b3 * 2.0 + b4) * (h / 6.0);
    }
    (r, p)
}

type Force = (SmoothTorque, Option<LinearDamping<So3>>);

fn forced(d: Option<Matrix3<f64>>) -> Forced<RigidBody, Force> {
    let damping = d.map(|d| LinearDamping::new(d).unwrap());
    Forced::new(body(), (SmoothTorque, damping))
}

fn strang(d: Option<Matrix3<f64>>) -> Splitting<So3, Forced<RigidBody, Force>> {
    Splitting::new(forced(d), PI0, Some(So3::from_matrix(&r0()).unwrap())).unwrap()
}

fn kinetic_kick(
    d: Option<Matrix3<f64>>,
    scheme: SplittingScheme,
) -> KineticKick<So3, Forced<RigidBody, Force>, FreeBodyFlow> {
    let flow = FreeBodyFlow::new(&body());
    let g0 = So3::from_matrix(&r0()).unwrap();
    KineticKick::new(forced(d), flow, scheme, PI0, Some(g0)).unwrap()
}

fn error<I: Integrator<Group = So3>>(
    mut i: I,
    h: f64,
    t_end: f64,
    want: &(Matrix3<f64>, Vector3<f64>),
) -> f64 {
    let n = (t_end / h).round() as usize;
    for _ in 0..n {
        i.step(h).unwrap();
    }
    let r = i.configuration().unwrap().as_matrix();
    (r - want.0).amax().max((i.momentum() - want.1).amax())
}

fn order_of<I: Integrator<Group = So3>>(
    make: impl Fn() -> I,
    hs: &[f64],
    t_end: f64,
    want: &(Matrix3<f64>, Vector3<f64>),
) -> (f64, f64) {
    let errs: Vec<f64> = hs.iter().map(|&h| error(make(), h, t_end, want)).collect();
    (fitted_order(hs, &errs), errs[errs.len() - 1])
}

/// With a torque of time and linear damping (a force that reads ξ, kicked by the implicit
/// midpoint rule): the Strang splitting and the kinetic–kick schemes are of order 2 (fitted
/// within 0.2) and say so.
#[test]
fn splittings_with_a_torque_and_damping_are_of_order_2() {
    let t_end = 2.0;
    let want = reference(damping(), t_end, 20_000);
    let hs = [0.04, 0.02, 0.01];
    let d = Some(damping());
    let (p, e) = order_of(|| strang(d), &hs, t_end, &want);
    println!("strang: order {p:.3}, error {e:.2e}");
    assert!((p - 2.0).abs() < 0.2, "strang: {p}");
    assert_eq!(strang(d).info().order, 2);
    for scheme in [SplittingScheme::strang(), SplittingScheme::blanes_moan_4()] {
        let (p, e) = order_of(|| kinetic_kick(d, scheme.clone()), &hs, t_end, &want);
        println!(
            "kinetic-kick {}: order {p:.3}, error {e:.2e}",
            scheme.name()
        );
        assert!((p - 2.0).abs() < 0.2, "{}: {p}", scheme.name());
        assert_eq!(kinetic_kick(d, scheme).info().order, 2);
    }
}

/// A torque of time alone is kicked exactly, the kicks at the times the kinetic flows have
/// reached: Blanes–Moan 4 stays of order 4 and Strang of order 2, as `info` says.
#[test]
fn kinetic_kick_keeps_its_order_with_a_torque_of_time() {
    let t_end = 2.0;
    let want = reference(Matrix3::zeros(), t_end, 20_000);
    for (scheme, hs, design) in [
        (SplittingScheme::strang(), [0.04, 0.02, 0.01], 2.0),
        (SplittingScheme::blanes_moan_4(), [0.2, 0.1, 0.05], 4.0),
    ] {
        let (p, e) = order_of(|| kinetic_kick(None, scheme.clone()), &hs, t_end, &want);
        println!(
            "kinetic-kick {}: order {p:.3}, error {e:.2e}",
            scheme.name()
        );
        assert!((p - design).abs() < 0.2, "{}: {p}", scheme.name());
        assert_eq!(kinetic_kick(None, scheme).info().order as f64, design);
    }
}

/// A pure body torque changes the spatial momentum map J = RΠ by exactly the applied spatial
/// impulse: for Strang, `J_{k+1} − J_k = (h/2)(R_k u(t_k) + R_{k+1} u(t_k + h))` at every step to
/// round-off (≤ 32 ulps of |J|: three plane rotations and one Rodrigues rotation, J formed from R and
/// Π at both ends), and over 2000 steps to a
/// walk of roundings.
#[test]
fn a_body_torque_changes_the_momentum_map_by_the_applied_impulse() {
    let mut s = strang(None);
    let h = 0.01;
    let spatial = |s: &Splitting<So3, _>| s.configuration().unwrap().as_matrix() * s.momentum();
    let j0 = spatial(&s);
    let (mut impulse, mut worst_step) = (Vector3::zeros(), 0.0_f64);
    for k in 0..2000 {
        let t = k as f64 * h;
        let (r_k, j_k) = (*s.configuration().unwrap().as_matrix(), spatial(&s));
        s.step(h).unwrap();
        let r_k1 = *s.configuration().unwrap().as_matrix();
        let step = (r_k * SmoothTorque::at(t) + r_k1 * SmoothTorque::at(t + h)) * (h / 2.0);
        worst_step = worst_step.max((spatial(&s) - j_k - step).amax());
        impulse += step;
    }
    let off = (spatial(&s) - j0 - impulse).amax();
    println!(
        "per step ≤ {worst_step:.2e}; J(T) − J(0) − impulse: {off:.2e} (|J| {:.2}, impulse {:.3})",
        j0.amax(),
        impulse.amax()
    );
    assert!(
        worst_step < 32.0 * f64::EPSILON * j0.amax(),
        "{worst_step:e}"
    );
    assert!(off < 2000.0 * 2.0 * f64::EPSILON * j0.amax(), "{off:e}");
    assert!(impulse.amax() > 0.1);
}

/// A force derived from a potential, F_ext = −T*_e L_g dV of the heavy top, applied to the free body
/// gives the heavy top's own splitting path (to round-off; the arithmetic is the same).
#[test]
fn a_force_from_a_potential_gives_the_potential_path() {
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    let t2 = top.clone();
    let force = move |_t: f64, g: Option<&So3>, _xi: &Vector3<f64>| {
        -t2.potential_differential(g.expect("g is reconstructed"))
    };
    let g0 = So3::from_matrix(&r0()).unwrap();
    let mut a = Splitting::new(top, PI0, Some(g0)).unwrap();
    let mut b = Splitting::new(Forced::new(body(), force), PI0, Some(g0)).unwrap();
    for _ in 0..500 {
        a.step(0.01).unwrap();
        b.step(0.01).unwrap();
    }
    let off = (a.momentum() - b.momentum()).amax().max(
        a.configuration()
            .unwrap()
            .matrix_distance(b.configuration().unwrap()),
    );
    println!("heavy top vs forced free body: {off:.2e}");
    assert!(off < 1e-13, "{off:e}");
}

/// Isotropic damping D = c𝕀 (F = −cΠ) makes |Π|² decay as e^{−2ct} exactly; the splittings reproduce
/// it to their order (2, fitted), though the force reads ξ.
#[test]
fn linear_damping_decays_the_casimir_at_the_exact_rate() {
    let c = 0.3;
    let t_end = 2.0;
    let body = body();
    let make = || {
        let d = LinearDamping::<So3>::new(Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)) * c)
            .unwrap();
        Splitting::new(Forced::new(body.clone(), d), PI0, None).unwrap()
    };
    let want = PI0.norm_squared() * (-2.0 * c * t_end).exp();
    let hs = [0.1, 0.05, 0.025];
    let errs: Vec<f64> = hs
        .iter()
        .map(|&h| {
            let mut s = make();
            for _ in 0..(t_end / h).round() as usize {
                s.step(h).unwrap();
            }
            (s.momentum().norm_squared() - want).abs()
        })
        .collect();
    let p = fitted_order(&hs, &errs);
    println!(
        "|Π|² decay: order {p:.3}, errors {:.2e} {:.2e} {:.2e}",
        errs[0], errs[1], errs[2]
    );
    assert!((p - 2.0).abs() < 0.2, "{p}");
}

/// The step with a velocity-dependent force is symmetric: h then −h returns to the start.
#[test]
fn forced_splittings_are_reversible() {
    let d = Some(damping());
    let check = |mut i: Box<dyn Integrator<Group = So3>>| {
        for _ in 0..5 {
            i.step(0.05).unwrap();
        }
        let (mu, g, t) = (i.momentum(), *i.configuration().unwrap(), i.time());
        i.step(0.1).unwrap();
        i.step(-0.1).unwrap();
        let off = (i.momentum() - mu)
            .amax()
            .max(i.configuration().unwrap().matrix_distance(&g));
        assert!(off < 1e-14, "{}: {off:e}", i.method_name());
        assert!((i.time() - t).abs() < 1e-15);
    };
    check(Box::new(strang(d)));
    check(Box::new(kinetic_kick(d, SplittingScheme::blanes_moan_4())));
}

/// Damping too strong for the step: the kick's fixed point does not converge — an error, and
/// the state is left as it was.
#[test]
fn a_kick_that_cannot_converge_is_an_error_and_leaves_the_state() {
    let mut s = strang(Some(Matrix3::identity() * 1e4));
    s.step(1e-6).unwrap();
    let (mu, g, t) = (s.momentum(), *s.configuration().unwrap(), s.time());
    let err = s.step(0.1).unwrap_err();
    assert!(
        matches!(err, IntegratorError::NoConvergence { .. }),
        "{err}"
    );
    assert_eq!(s.momentum(), mu);
    assert_eq!(*s.configuration().unwrap(), g);
    assert_eq!(s.time(), t);
    let mut k = kinetic_kick(Some(Matrix3::identity() * 1e4), SplittingScheme::strang());
    assert!(k.step(0.1).is_err());
    assert_eq!(k.momentum(), PI0);
}

/// Forced systems split like their unforced system: the same pieces.
#[test]
fn a_forced_system_declares_the_pieces_of_its_system() {
    let f = forced(None);
    assert_eq!(f.pieces(), body().pieces());
    let mu = Vector3::new(0.3, -0.2, 0.9);
    for i in 0..f.pieces() {
        assert_eq!(f.piece_velocity(i, &mu), body().piece_velocity(i, &mu));
    }
    assert!(!f.external_force_reads_velocity());
    assert!(forced(Some(damping())).external_force_reads_velocity());
    let torque = BodyTorque::<So3>::constant(Vector3::new(0.1, 0.0, 0.0)).unwrap();
    assert!(!ExternalForce::<So3>::reads_velocity(&torque));
}
