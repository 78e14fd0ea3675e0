//! The underwater vehicle (`systems::UnderwaterVehicle`: Kirchhoff's equations with a full 6×6
//! mass matrix and the hydrostatic restoring force) with drag (`forces::LinearDamping`,
//! `forces::QuadraticDrag`): derivatives against finite differences; the closed forms of a
//! neutrally buoyant vehicle translating along a principal axis (free, linear drag, quadratic
//! drag); the conserved components of the momentum map to round-off; the energy balance with
//! drag; orders against an independent RK4 on (R, x, Π, P); the splitting of a decoupled mass
//! matrix and the refusal of a coupled one.

use crate::common::*;
use integrators::baselines::Rkmk4;
use integrators::derivative_check::{check_derivatives, finite_difference_force_derivative};
use integrators::forces::{ExternalForce, Forced, LinearDamping, QuadraticDrag};
use integrators::splitting::Splitting;
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, Se3, So3, Tau};
use mechanics::systems::underwater_vehicle::angular_first;
use mechanics::UnderwaterVehicle;
use nalgebra::{DVector, Matrix3, Matrix6, Vector3, Vector6};

/// The rigid-body mass matrix (`UnderwaterVehicle::rigid_body_mass_matrix`, pinned against
/// Fossen's eq. 3.44 in `fossen_ordering_is_reordered_to_angular_first`).
fn rigid_body_mass(m: f64, ig: Matrix3<f64>, rg: Vector3<f64>) -> Matrix6<f64> {
    UnderwaterVehicle::rigid_body_mass_matrix(m, &ig, &rg)
}

const RG: Vector3<f64> = Vector3::new(0.02, -0.01, -0.05);
const RB: Vector3<f64> = Vector3::new(0.0, 0.01, 0.04);

/// A slender vehicle: M = M_RB + M_A with a full added-mass matrix (rotation–translation
/// coupling), slightly heavy (W = 98.1 > B = 95), centre of gravity below the centre of buoyancy.
fn vehicle() -> UnderwaterVehicle {
    let m_rb = rigid_body_mass(
        10.0,
        Matrix3::new(0.5, 0.01, 0.0, 0.01, 2.0, 0.02, 0.0, 0.02, 2.2),
        RG,
    );
    let mut m_a = Matrix6::from_diagonal(&Vector6::new(0.1, 1.5, 1.6, 1.0, 9.0, 9.5));
    for (i, j, x) in [(1, 5, 0.3), (2, 4, -0.25), (0, 3, 0.05), (4, 5, 0.1)] {
        m_a[(i, j)] = x;
        m_a[(j, i)] = x;
    }
    UnderwaterVehicle::new(m_rb + m_a)
        .unwrap()
        .with_restoring(98.1, RG, 95.0, RB)
        .unwrap()
}

/// The same vehicle neutrally buoyant (W = B = 95): the restoring moment alone, a bounded motion.
fn neutral() -> UnderwaterVehicle {
    UnderwaterVehicle::new(*vehicle().mass_matrix())
        .unwrap()
        .with_restoring(95.0, RG, 95.0, RB)
        .unwrap()
}

fn start() -> (Se3, Vector6<f64>) {
    (
        Se3::from_parts(
            So3::from_matrix(&r0()).unwrap(),
            Vector3::new(1.0, -2.0, -5.0),
        ),
        Vector6::new(0.4, -0.3, 0.5, 12.0, 1.5, -2.0),
    )
}

#[test]
fn restoring_differential_matches_finite_differences() {
    let v = vehicle();
    let (g, mu) = start();
    let g2 = Se3::from_parts(
        So3::exp(&Vector3::new(2.0, -1.0, 0.5)),
        Vector3::new(-3.0, 0.5, 2.0),
    );
    let mu2 = Vector6::new(-1.0, 0.2, 0.3, -4.0, 6.0, 1.0);
    let report = check_derivatives(&v, &[(mu, Some(g)), (mu2, Some(g2))]);
    assert!(report.passes(1e-8), "{report:?}");
    // The closed-form force derivative K = [[−ĉΓ̂, 0], [−(W − B)Γ̂, 0]] against central differences.
    for g in [g, g2] {
        let k = v.force_derivative(&g);
        let fd = finite_difference_force_derivative(&v, &g);
        assert!((k - fd).amax() < 1e-8 * k.amax(), "{k} vs {fd}");
    }
    // The restoring force is W's and B's moments about the origin and the net weight, body frame.
    let up = g.rotation().as_matrix().transpose() * Vector3::z();
    let f = -v.potential_differential(&g);
    let moment = RG.cross(&(-up * 98.1)) + RB.cross(&(up * 95.0));
    assert!((f.fixed_rows::<3>(0) - moment).amax() < 1e-13);
    assert!((f.fixed_rows::<3>(3) + up * 3.1).amax() < 1e-13);
}

#[test]
fn fossen_ordering_is_reordered_to_angular_first() {
    // Fossen (2011) eq. 3.44 in (v, ω) ordering: [[m I, −m S(r_g)], [m S(r_g), I_o]],
    // I_o = I_g − m S(r_g)².
    let (m, ig) = (10.0, Matrix3::from_diagonal(&Vector3::new(0.5, 2.0, 2.2)));
    let s = RG.cross_matrix();
    let mut fossen = Matrix6::zeros();
    fossen
        .fixed_view_mut::<3, 3>(0, 0)
        .copy_from(&(Matrix3::identity() * m));
    fossen.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-s * m));
    fossen.fixed_view_mut::<3, 3>(3, 0).copy_from(&(s * m));
    fossen
        .fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(ig - s * s * m));
    assert_eq!(angular_first(&fossen), rigid_body_mass(m, ig, RG));
    assert_eq!(angular_first(&angular_first(&fossen)), fossen);
}

#[test]
fn underwater_vehicle_refuses_bad_parameters() {
    let msg =
        |r: Result<UnderwaterVehicle, integrators::IntegratorError>| r.unwrap_err().to_string();
    let good = *vehicle().mass_matrix();
    let mut asym = good;
    asym[(0, 4)] += 0.1;
    assert!(msg(UnderwaterVehicle::new(asym)).contains("mass matrix"));
    assert!(msg(UnderwaterVehicle::new(-good)).contains("positive definite"));
    let mut nan = good;
    nan[(2, 2)] = f64::NAN;
    assert!(UnderwaterVehicle::new(nan).is_err());
    let v = || UnderwaterVehicle::new(good).unwrap();
    assert!(msg(v().with_restoring(-1.0, RG, 1.0, RB)).contains("weight W"));
    assert!(msg(v().with_restoring(1.0, RG, f64::INFINITY, RB)).contains("buoyancy B"));
    assert!(
        msg(v().with_restoring(1.0, Vector3::new(f64::NAN, 0.0, 0.0), 1.0, RB))
            .contains("centre of gravity")
    );
    assert!(QuadraticDrag::<Se3>::new(Vector6::new(1.0, -1.0, 0.0, 0.0, 0.0, 0.0)).is_err());
    assert!(QuadraticDrag::<Se3>::new(Vector6::new(f64::NAN, 1.0, 0.0, 0.0, 0.0, 0.0)).is_err());
}

// ---- Closed forms: translation along a principal axis ----

const M1: f64 = 3.0;
const V0: f64 = 0.8;

/// Diagonal M, neutrally buoyant with r_G = r_B (V ≡ 0: the potential is there but exerts no
/// force), moving along its first axis at v₀ (forwards, or backwards with `sign` = −1).
fn translating(sign: f64) -> (UnderwaterVehicle, Se3, Vector6<f64>) {
    let m = Matrix6::from_diagonal(&Vector6::new(1.0, 1.2, 1.5, M1, 4.0, 5.0));
    let c = Vector3::new(0.0, 0.0, 0.1);
    let v = UnderwaterVehicle::new(m)
        .unwrap()
        .with_restoring(50.0, c, 50.0, c)
        .unwrap();
    let g0 = Se3::from_parts(
        So3::from_matrix(&r0()).unwrap(),
        Vector3::new(1.0, 2.0, 3.0),
    );
    (v, g0, Vector6::new(0.0, 0.0, 0.0, sign * M1 * V0, 0.0, 0.0))
}

/// The distance travelled along the first body axis at t: free `v₀t`, linear drag
/// `(m v₀/d)(1 − e^{−dt/m})`, quadratic drag `(m/d) ln(1 + d v₀ t/m)`.
#[derive(Clone, Copy)]
enum Drag {
    None,
    Linear(f64),
    Quadratic(f64),
}

fn travelled(drag: Drag, t: f64) -> (f64, f64) {
    match drag {
        Drag::None => (V0 * t, V0),
        Drag::Linear(d) => (
            M1 * V0 / d * (1.0 - (-d * t / M1).exp()),
            V0 * (-d * t / M1).exp(),
        ),
        Drag::Quadratic(d) => (
            M1 / d * (1.0 + d * V0 * t / M1).ln(),
            V0 / (1.0 + d * V0 * t / M1),
        ),
    }
}

/// |x − x_exact| + |v − v_exact| at T = 5, with Π and the transverse P checked to stay 0;
/// moving forwards (`sign` = 1) or backwards (−1: the drag must still oppose the motion).
fn translation_error(
    drag: Drag,
    sign: f64,
    h: f64,
    make: impl Fn(
        Forced<UnderwaterVehicle, (LinearDamping<Se3>, QuadraticDrag<Se3>)>,
        Vector6<f64>,
        Se3,
    ) -> Box<dyn Integrator<Group = Se3>>,
) -> f64 {
    let (v, g0, mu0) = translating(sign);
    let (lin, quad) = match drag {
        Drag::None => (0.0, 0.0),
        Drag::Linear(d) => (d, 0.0),
        Drag::Quadratic(d) => (0.0, d),
    };
    let force = (
        LinearDamping::<Se3>::new(Matrix6::from_diagonal(&Vector6::new(
            0.0, 0.0, 0.0, lin, 0.0, 0.0,
        )))
        .unwrap(),
        QuadraticDrag::<Se3>::new(Vector6::new(0.0, 0.0, 0.0, quad, 0.0, 0.0)).unwrap(),
    );
    let mut integ = make(Forced::new(v, force), mu0, g0);
    let t_end = 5.0;
    for _ in 0..(t_end / h).round() as usize {
        integ.step(h).unwrap();
    }
    let (s, vel) = travelled(drag, t_end);
    let mu = integ.momentum();
    let x = integ.configuration().unwrap().translation();
    let transverse = mu
        .fixed_rows::<3>(0)
        .amax()
        .max(mu[4].abs())
        .max(mu[5].abs());
    assert_eq!(transverse, 0.0, "the motion left the line: μ = {mu}");
    (x - (g0.translation() + r0() * Vector3::x() * (sign * s))).amax()
        + (mu[3] / M1 - sign * vel).abs()
}

fn lp<T: Tau<Se3> + 'static, S: System<Se3> + 'static>(
    theta: f64,
) -> impl Fn(S, Vector6<f64>, Se3) -> Box<dyn Integrator<Group = Se3>> {
    move |s, mu, g| Box::new(LiePoisson::<Se3, T, _>::new(s, theta, mu, Some(g)).unwrap())
}

fn strang<S: integrators::splitting::SplitSystem<Se3> + 'static>(
    s: S,
    mu: Vector6<f64>,
    g: Se3,
) -> Box<dyn Integrator<Group = Se3>> {
    Box::new(Splitting::new(s, mu, Some(g)).unwrap())
}

/// Without drag the vehicle glides along the line exactly (Π = 0, P ∥ e₁ stay so in the
/// discrete flow, and each step translates by exactly h v₀): error ≤ 1e-12 (round-off) after 500
/// steps.
#[test]
fn neutrally_buoyant_vehicle_glides_along_a_principal_axis_exactly() {
    // Only the rounding of x_{k+1} = x_k + R_k(h v₀ e₁) accumulates: 500 steps at |x| ≈ 5 give
    // up to 500·ε·5 ≈ 6e-13 (measured 4e-14 … 1.2e-13); bound 1e-12.
    for (name, err) in [
        (
            "LP exp",
            translation_error(Drag::None, 1.0, 0.01, lp::<ExpMap, _>(0.5)),
        ),
        (
            "LP cayley",
            translation_error(Drag::None, 1.0, 0.01, lp::<Cayley, _>(0.5)),
        ),
        ("Strang", translation_error(Drag::None, 1.0, 0.01, strang)),
    ] {
        println!("glide, {name}: error {err:.2e}");
        assert!(err < 1e-12, "{name}: {err:e}");
    }
}

/// Linear drag `m v̇ = −d v` and quadratic drag `m v̇ = −d |v| v` (forwards and backwards):
/// Lie–Poisson θ = ½ and Strang (implicit-midpoint drag kicks) reach the closed forms at order 2.0.
#[test]
fn drag_slows_the_vehicle_as_the_closed_forms_at_order_2() {
    let hs = [0.2, 0.1, 0.05];
    for (drag, sign) in [
        (Drag::Linear(1.5), 1.0),
        (Drag::Quadratic(2.0), 1.0),
        (Drag::Quadratic(2.0), -1.0),
    ] {
        let label = match drag {
            Drag::Linear(_) => "linear drag",
            Drag::Quadratic(_) => "quadratic drag",
            Drag::None => unreachable!(),
        };
        for (name, errs) in [
            (
                "LP exp θ = ½",
                hs.map(|h| translation_error(drag, sign, h, lp::<ExpMap, _>(0.5))),
            ),
            (
                "LP cayley θ = ½",
                hs.map(|h| translation_error(drag, sign, h, lp::<Cayley, _>(0.5))),
            ),
            (
                "Strang",
                hs.map(|h| translation_error(drag, sign, h, strang)),
            ),
        ] {
            let order = fitted_order(&hs, &errs);
            println!("{label}, direction {sign}, {name}: errors {errs:?}, order {order:.3}");
            assert!(
                (1.9..=2.1).contains(&order),
                "{label} {sign}, {name}: {order}"
            );
        }
    }
}

// ---- Invariants ----

/// Max drift of (L₃, p₁, p₂, p₃) over `steps` steps, relative to |μ|(1 + |x|).
fn momentum_drift<T: Tau<Se3>>(v: UnderwaterVehicle, theta: f64, h: f64, steps: usize) -> [f64; 4] {
    let (g0, mu0) = start();
    let parts = |g: &Se3, mu: &Vector6<f64>| {
        let (l, p) = UnderwaterVehicle::spatial_momentum(g, mu);
        [l.z, p.x, p.y, p.z]
    };
    let j0 = parts(&g0, &mu0);
    let mut lp = LiePoisson::<Se3, T, _>::new(v, theta, mu0, Some(g0)).unwrap();
    let mut worst = [0.0f64; 4];
    for _ in 0..steps {
        lp.step(h).unwrap();
        let (g, mu) = (lp.configuration().unwrap(), lp.momentum());
        let j = parts(g, &mu);
        // Relative to the size of the terms of L = RΠ + x × RP (x grows as the vehicle moves).
        let scale = mu.amax() * (1.0 + g.translation().norm());
        for i in 0..4 {
            worst[i] = worst[i].max((j[i] - j0[i]).abs() / scale);
        }
    }
    worst
}

/// V is invariant under rotations about the vertical and horizontal translations: Lie–Poisson
/// keeps L₃, p₁, p₂ to round-off (≤ 1e-13 of |μ|(1 + |x|) over 2000 steps) for every θ and τ, and
/// p₃ too when the vehicle is neutrally buoyant (W = B); heavy, p₃ falls.
#[test]
fn restoring_force_keeps_vertical_angular_and_horizontal_linear_momentum() {
    for theta in [0.0, 0.5, 1.0] {
        for (name, d) in [
            (
                "exp",
                momentum_drift::<ExpMap>(vehicle(), theta, 0.01, 2000),
            ),
            (
                "cayley",
                momentum_drift::<Cayley>(vehicle(), theta, 0.01, 2000),
            ),
        ] {
            println!("heavy vehicle {name} θ = {theta}: drift of (L₃, p₁, p₂, p₃) {d:?}");
            assert!(d[..3].iter().all(|&x| x < 1e-13), "{name} θ={theta}: {d:?}");
            assert!(d[3] > 1e-3, "the net weight must change p₃: {d:?}");
        }
        let d = momentum_drift::<Cayley>(neutral(), theta, 0.01, 2000);
        println!("neutral vehicle cayley θ = {theta}: drift of (L₃, p₁, p₂, p₃) {d:?}");
        assert!(d.iter().all(|&x| x < 1e-13), "neutral θ={theta}: {d:?}");
    }
}

/// Without drag the energy error of the neutrally buoyant vehicle (a bounded motion: the heavy
/// one sinks faster and faster) is bounded: 3000 steps of h = 0.02, last-tenth maximum within 2×
/// the first tenth's. RKMK4 in the same run is the negative control: its error drifts, to more
/// than 2× its first tenth's.
#[test]
fn vehicle_energy_error_is_bounded_without_drift() {
    let (g0, mu0) = start();
    for theta in [0.0, 0.5, 1.0] {
        let (f, l) = energy_error_tenths(
            LiePoisson::<Se3, Cayley, _>::new(neutral(), theta, mu0, Some(g0)).unwrap(),
            0.02,
            3000,
        );
        println!("vehicle energy error θ = {theta}: first tenth {f:.2e}, last {l:.2e}");
        assert!(l <= 2.0 * f + 1e-12, "θ = {theta}: first {f:e}, last {l:e}");
    }
    let (f, l) = energy_error_tenths(Rkmk4::new(neutral(), mu0, Some(g0)).unwrap(), 0.02, 3000);
    println!("vehicle energy error RKMK4: first tenth {f:.2e}, last {l:.2e}");
    assert!(l > 2.0 * f, "RKMK4 should drift: first {f:e}, last {l:e}");
}

fn drag() -> (LinearDamping<Se3>, QuadraticDrag<Se3>) {
    (
        LinearDamping::<Se3>::new(Matrix6::from_diagonal(&Vector6::new(
            0.3, 0.8, 0.8, 1.0, 6.0, 6.0,
        )))
        .unwrap(),
        QuadraticDrag::<Se3>::new(Vector6::new(0.1, 0.5, 0.5, 0.8, 8.0, 8.0)).unwrap(),
    )
}

/// The drag's energy balance `E(T) = E(0) − ∫₀ᵀ ⟨ξ, Dξ⟩ + Σ dᵢ|ξᵢ|³ dt`: the dissipated work
/// accumulated along the Lie–Poisson run (trapezoidal rule) closes the balance at order 2.0, and
/// the energy falls at every step.
#[test]
fn drag_dissipates_the_energy_it_should() {
    let (g0, mu0) = start();
    let hs = [0.04, 0.02, 0.01];
    let t_end = 2.0;
    let residual = |h: f64| {
        let system = Forced::new(vehicle(), drag());
        let power = |s: &Forced<UnderwaterVehicle, (LinearDamping<Se3>, QuadraticDrag<Se3>)>,
                     mu: &Vector6<f64>| {
            let xi = s.velocity(mu);
            -s.force().force(0.0, None, &xi).dot(&xi)
        };
        let mut lp = LiePoisson::<Se3, Cayley, _>::new(system.clone(), 0.5, mu0, Some(g0)).unwrap();
        let e0 = lp.energy();
        let (mut work, mut last_power, mut last_e) = (0.0, power(&system, &mu0), e0);
        for _ in 0..(t_end / h).round() as usize {
            lp.step(h).unwrap();
            let p = power(&system, &lp.momentum());
            work += 0.5 * h * (p + last_power);
            last_power = p;
            assert!(lp.energy() < last_e, "the energy rose at t = {}", lp.time());
            last_e = lp.energy();
        }
        (lp.energy() - e0 + work).abs()
    };
    let errs = hs.map(residual);
    let order = fitted_order(&hs, &errs);
    println!("drag energy balance residuals {errs:?}, order {order:.3}");
    assert!((1.9..=2.1).contains(&order), "order {order}");
}

// ---- Against an independent RK4 ----

/// RK4 on y = (R column-major, x, Π, P): `Ṙ = RΩ̂`, `ẋ = Rv`, `Π̇ = Π × Ω + P × v + Γ × c + τ_d`,
/// `Ṗ = P × Ω − (W − B)Γ + f_d`, (Ω, v) = M⁻¹(Π, P), Γ = Rᵀe₃, c = W r_G − B r_B, the drag
/// (τ_d, f_d) = −Dξ − (dᵢ|ξᵢ|ξᵢ) written here from the module page.
fn reference(m: &Matrix6<f64>, with_drag: bool, t_end: f64) -> DVector<f64> {
    let m_inv = m.try_inverse().unwrap();
    let c = RG * 98.1 - RB * 95.0;
    let (dl, dq) = if with_drag {
        (
            Vector6::new(0.3, 0.8, 0.8, 1.0, 6.0, 6.0),
            Vector6::new(0.1, 0.5, 0.5, 0.8, 8.0, 8.0),
        )
    } else {
        (Vector6::zeros(), Vector6::zeros())
    };
    let (g0, mu0) = start();
    let y0 = DVector::from_vec(pack_se3(&g0, &mu0));
    let f = |_t: f64, y: &DVector<f64>| {
        let (r, _, mu) = unpack_se3(y.as_slice());
        let xi = m_inv * mu;
        let drag = -xi.component_mul(&dl) - dq.component_mul(&xi.map(|x| x.abs() * x));
        let (om, v) = (xi.fixed_rows::<3>(0), xi.fixed_rows::<3>(3));
        let (pi, p) = (mu.fixed_rows::<3>(0), mu.fixed_rows::<3>(3));
        let up = r.transpose() * Vector3::z();
        let mut dy = DVector::zeros(18);
        dy.rows_mut(0, 9)
            .copy_from_slice((r * om.cross_matrix()).as_slice());
        dy.rows_mut(9, 3).copy_from(&(r * v));
        dy.rows_mut(12, 3)
            .copy_from(&(pi.cross(&om) + p.cross(&v) + up.cross(&c) + drag.fixed_rows::<3>(0)));
        dy.rows_mut(15, 3)
            .copy_from(&(p.cross(&om) - up * (98.1 - 95.0) + drag.fixed_rows::<3>(3)));
        dy
    };
    rk4_richardson(f, &y0, t_end, 8000)
}

fn error_against(yref: &DVector<f64>, integ: &dyn Integrator<Group = Se3>) -> f64 {
    let g = integ.configuration().unwrap();
    let (r, x, mu) = unpack_se3(yref.as_slice());
    (g.rotation().as_matrix() - r)
        .amax()
        .max((g.translation() - x).amax() / x.amax())
        .max((integ.momentum() - mu).amax() / mu.amax())
}

/// Lie–Poisson θ = ½ (exp, Cayley) converges at order 2.0 to the independent reference, with the
/// full coupled mass matrix and the restoring force, without and with linear + quadratic drag
/// (T = 4, h = 0.04 … 0.01; reference RK4 at 5e-4 and 1e-3, Richardson).
#[test]
fn vehicle_converges_at_order_2_to_an_independent_rk4() {
    let t_end = 4.0;
    let hs = [0.04, 0.02, 0.01];
    let (g0, mu0) = start();
    for with_drag in [false, true] {
        let yref = reference(vehicle().mass_matrix(), with_drag, t_end);
        let run = |exp: bool, h: f64| -> f64 {
            let mut integ: Box<dyn Integrator<Group = Se3>> = match (with_drag, exp) {
                (false, true) => lp::<ExpMap, _>(0.5)(vehicle(), mu0, g0),
                (false, false) => lp::<Cayley, _>(0.5)(vehicle(), mu0, g0),
                (true, true) => lp::<ExpMap, _>(0.5)(Forced::new(vehicle(), drag()), mu0, g0),
                (true, false) => lp::<Cayley, _>(0.5)(Forced::new(vehicle(), drag()), mu0, g0),
            };
            for _ in 0..(t_end / h).round() as usize {
                integ.step(h).unwrap();
            }
            error_against(&yref, integ.as_ref())
        };
        for (name, exp) in [("exp", true), ("cayley", false)] {
            let errs = hs.map(|h| run(exp, h));
            let order = fitted_order(&hs, &errs);
            println!(
                "vehicle (drag: {with_drag}), LP {name} θ = ½: errors {errs:?}, order {order:.3}"
            );
            assert!(
                (1.9..=2.1).contains(&order),
                "drag {with_drag}, {name}: {order}"
            );
        }
    }
}

/// A block-diagonal mass matrix splits (rotations about the eigenvectors of M_ωω, translation by
/// M_vv⁻¹P): the Strang splitting converges at order 2.0 to the independent reference; a coupled
/// one is refused with a message saying why.
#[test]
fn decoupled_vehicle_splits_and_a_coupled_one_is_refused() {
    let coupled = vehicle();
    let (g0, mu0) = start();
    assert!(!coupled.is_decoupled());
    let err = Splitting::new(coupled, mu0, Some(g0))
        .unwrap_err()
        .to_string();
    assert!(err.contains("no splitting"), "{err}");

    let mut m = *vehicle().mass_matrix();
    m.fixed_view_mut::<3, 3>(0, 3).fill(0.0);
    m.fixed_view_mut::<3, 3>(3, 0).fill(0.0);
    let decoupled = || {
        UnderwaterVehicle::new(m)
            .unwrap()
            .with_restoring(98.1, RG, 95.0, RB)
            .unwrap()
    };
    assert!(decoupled().is_decoupled());
    let t_end = 2.0;
    let yref = reference(&m, false, t_end);
    let hs = [0.04, 0.02, 0.01];
    let errs = hs.map(|h| {
        let mut s = Splitting::new(decoupled(), mu0, Some(g0)).unwrap();
        for _ in 0..(t_end / h).round() as usize {
            s.step(h).unwrap();
        }
        error_against(&yref, &s)
    });
    let order = fitted_order(&hs, &errs);
    println!("decoupled vehicle, Strang: errors {errs:?}, order {order:.3}");
    assert!((1.9..=2.1).contains(&order), "order {order}");
}
