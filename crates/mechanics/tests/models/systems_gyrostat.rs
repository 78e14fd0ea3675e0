//! The gyrostat (`systems::Gyrostat`, a spacecraft with reaction wheels on SO(3) × ℝᴷ):
//! derivatives against finite differences; the symmetric gyrostat's closed form (free, and spun
//! up by a constant wheel torque) reached at order 2 by Lie–Poisson θ = ½ and the Strang
//! splitting; the total angular momentum R Π and |Π|² kept to round-off under a wheel-torque
//! schedule; orders against an independent RK4 on (R, φ, Π, p) for three skewed wheels.

use crate::common::*;
use integrators::derivative_check::check_derivatives;
use integrators::forces::{Forced, Schedule};
use integrators::splitting::Splitting;
use integrators::{Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, Product, ProductAlgebra, Rn, So3, Tau};
use mechanics::systems::{Gyrostat, GyrostatAlgebra, GyrostatGroup};
use nalgebra::{DVector, Matrix3, SVector, Vector1, Vector3};

type G3 = GyrostatGroup<3>;
/// A boxed integrator of a one-wheel gyrostat, and a maker of fresh ones.
type Boxed1 = Box<dyn Integrator<Group = GyrostatGroup<1>>>;
type Maker1 = Box<dyn Fn() -> Boxed1>;
/// A maker of fresh integrators of the three-wheel gyrostat.
type Maker3<'a> = &'a dyn Fn() -> Box<dyn Integrator<Group = G3>>;
type M3 = GyrostatAlgebra<3>;

/// Three wheels on skewed axes in a body with a full inertia tensor.
fn three_wheels() -> Gyrostat<3> {
    let inertia = Matrix3::new(12.0, 0.4, -0.3, 0.4, 15.0, 0.5, -0.3, 0.5, 9.0);
    let axes = [
        Vector3::new(1.0, 0.1, 0.0),
        Vector3::new(0.0, 1.0, 0.2),
        Vector3::new(0.3, -0.2, 1.0),
    ];
    Gyrostat::new(inertia, axes, [0.05, 0.04, 0.06]).unwrap()
}

fn three_wheel_state() -> (M3, G3) {
    (
        ProductAlgebra::new(
            Vector3::new(3.0, -2.0, 4.0),
            SVector::<f64, 3>::new(0.5, -0.8, 1.2),
        ),
        Product::new(
            So3::from_matrix(&r0()).unwrap(),
            Rn::new(SVector::<f64, 3>::new(0.1, 0.2, -0.3)),
        ),
    )
}

/// A piecewise-linear wheel-torque schedule with knots at whole seconds (step boundaries of every
/// step used below, so that RK4 keeps its order across the kinks).
fn wheel_schedule() -> Schedule {
    Schedule::new(
        vec![0.0, 1.0, 2.0, 3.0],
        vec![
            vec![0.2, 0.0, -0.1],
            vec![0.0, 0.3, 0.1],
            vec![-0.2, 0.1, 0.0],
            vec![0.0, 0.0, 0.0],
        ],
    )
    .unwrap()
}

/// The same schedule, evaluated independently of `Schedule` (linear between whole seconds).
fn wheel_torque_at(t: f64) -> Vector3<f64> {
    let v = [
        Vector3::new(0.2, 0.0, -0.1),
        Vector3::new(0.0, 0.3, 0.1),
        Vector3::new(-0.2, 0.1, 0.0),
        Vector3::zeros(),
    ];
    if t >= 3.0 {
        return v[3];
    }
    let i = t.floor().max(0.0) as usize;
    let s = t - i as f64;
    v[i] * (1.0 - s) + v[i + 1] * s
}

#[test]
fn gyrostat_derivatives_match_finite_differences() {
    let gyro = three_wheels();
    let (mu, g) = three_wheel_state();
    let other = ProductAlgebra::new(
        Vector3::new(-1.0, 0.5, 2.0),
        SVector::<f64, 3>::new(-2.0, 0.3, 0.1),
    );
    let report = check_derivatives::<G3, _>(&gyro, &[(mu, Some(g)), (other, None)]);
    assert!(report.passes(1e-8), "{report:?}");
    // The Legendre map inverts the velocity, and the kinetic energy is ½⟨μ, ξ⟩.
    let xi = gyro.velocity(&mu);
    assert!((gyro.hamiltonian(&mu) - 0.5 * mu.dot_product(&xi)).abs() < 1e-13);
}

/// `⟨μ, ξ⟩` for the product coordinates (the pairing of 𝔤* with 𝔤).
trait Pairing {
    fn dot_product(&self, other: &Self) -> f64;
}
impl Pairing for M3 {
    fn dot_product(&self, other: &Self) -> f64 {
        self.a.dot(&other.a) + self.b.dot(&other.b)
    }
}

#[test]
fn gyrostat_refuses_bad_parameters() {
    let i = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 1.0));
    let axis = [Vector3::z()];
    let msg = |r: Result<Gyrostat<1>, integrators::IntegratorError>| r.unwrap_err().to_string();
    assert!(msg(Gyrostat::new(i, [Vector3::zeros()], [0.1])).contains("a[0]"));
    assert!(msg(Gyrostat::new(i, axis, [0.0])).contains("J[0]"));
    assert!(msg(Gyrostat::new(i, axis, [f64::NAN])).contains("J[0]"));
    // The wheel's axial inertia exceeds the body's about e₃.
    assert!(msg(Gyrostat::new(i, axis, [1.5])).contains("platform inertia"));
    let mut nan = i;
    nan[(0, 1)] = f64::NAN;
    assert!(Gyrostat::new(nan, axis, [0.1]).is_err());
    assert!(Gyrostat::<0>::new(i, [], []).is_err());
    // A wheel torque schedule must have one value per wheel.
    assert!(Gyrostat::<3>::wheel_torques(Schedule::constant(vec![1.0, 2.0]).unwrap()).is_err());
}

// ---- The symmetric gyrostat's closed form (module page of systems::gyrostat) ----

const I: f64 = 2.0;
const I3: f64 = 1.0;
const J: f64 = 0.5;
const P0: f64 = 0.8;

/// 𝕀_s = diag(I, I, I₃), one wheel on e₃: 𝕀 = 𝕀_s + J e₃e₃ᵀ.
fn symmetric() -> Gyrostat<1> {
    Gyrostat::new(
        Matrix3::from_diagonal(&Vector3::new(I, I, I3 + J)),
        [Vector3::z()],
        [J],
    )
    .unwrap()
}

fn symmetric_start() -> (GyrostatAlgebra<1>, GyrostatGroup<1>) {
    (
        ProductAlgebra::new(Vector3::new(0.6, -0.3, 1.2), Vector1::new(P0)),
        Product::new(So3::from_matrix(&r0()).unwrap(), Rn::new(Vector1::new(0.0))),
    )
}

/// The exact (R, φ, Π, p) at t under the wheel torque u (constant): p = p₀ + ut,
/// B(t) = ∫β = t(Π₃/I₃ − Π₃/I) − (p₀t + ut²/2)/I₃, Π = R_z(−B)Π₀, R = R₀ exp(tΠ̂₀/I) R_z(B),
/// φ = (p₀t + ut²/2)(1/J + 1/I₃) − Π₃t/I₃.
fn symmetric_exact(u: f64, t: f64) -> (Matrix3<f64>, f64, Vector3<f64>, f64) {
    let pi0 = symmetric_start().0.a;
    let impulse = P0 * t + 0.5 * u * t * t;
    let b = t * (pi0.z / I3 - pi0.z / I) - impulse / I3;
    let rz = |a: f64| rodrigues(&Vector3::new(0.0, 0.0, a));
    let pi = rz(-b) * pi0;
    let r = r0() * rodrigues(&(pi0 * (t / I))) * rz(b);
    let phi = impulse * (1.0 / J + 1.0 / I3) - pi0.z * t / I3;
    (r, phi, pi, P0 + u * t)
}

/// max(|ΔR|, |ΔΠ|/|Π|, |Δφ|, |Δp|) at T = 4 against the closed form, for an integrator `make`s.
fn symmetric_error(
    u: f64,
    h: f64,
    make: &dyn Fn() -> Box<dyn Integrator<Group = GyrostatGroup<1>>>,
) -> f64 {
    let t_end = 4.0;
    let mut integ = make();
    let n = (t_end / h).round() as usize;
    for _ in 0..n {
        integ.step(h).unwrap();
    }
    let (r, phi, pi, p) = symmetric_exact(u, t_end);
    let g = integ.configuration().unwrap();
    let mu = integ.momentum();
    (g.g.as_matrix() - r)
        .amax()
        .max((mu.a - pi).amax() / pi.norm())
        .max((g.h.vector()[0] - phi).abs())
        .max((mu.b[0] - p).abs())
}

fn symmetric_orders(u: f64) -> Vec<(&'static str, f64, f64)> {
    let hs = [0.04, 0.02, 0.01];
    let (mu0, g0) = symmetric_start();
    let torque = move || {
        Forced::new(
            symmetric(),
            Gyrostat::<1>::wheel_torques(Schedule::constant(vec![u]).unwrap()).unwrap(),
        )
    };
    fn lp<T: Tau<GyrostatGroup<1>> + 'static>(
        s: impl System<GyrostatGroup<1>> + 'static,
        mu0: GyrostatAlgebra<1>,
        g0: GyrostatGroup<1>,
    ) -> Box<dyn Integrator<Group = GyrostatGroup<1>>> {
        Box::new(LiePoisson::<_, T, _>::new(s, 0.5, mu0, Some(g0)).unwrap())
    }
    let makers: Vec<(&str, Maker1)> = vec![
        (
            "LP exp θ = ½",
            Box::new(move || lp::<ExpMap>(torque(), mu0, g0)),
        ),
        (
            "LP cayley θ = ½",
            Box::new(move || lp::<Cayley>(torque(), mu0, g0)),
        ),
        (
            "Strang",
            Box::new(move || Box::new(Splitting::new(torque(), mu0, Some(g0)).unwrap())),
        ),
    ];
    makers
        .iter()
        .map(|(name, make)| {
            let errs: Vec<f64> = hs.iter().map(|&h| symmetric_error(u, h, make)).collect();
            (*name, fitted_order(&hs, &errs), errs[2])
        })
        .collect()
}

/// The free symmetric gyrostat (constant wheel momentum): order 2.0 to the closed form.
#[test]
fn symmetric_gyrostat_converges_to_its_closed_form_at_order_2() {
    for (name, order, err) in symmetric_orders(0.0) {
        println!("free symmetric gyrostat, {name}: order {order:.3}, error at h = 0.01 {err:.2e}");
        assert!((1.9..=2.1).contains(&order), "{name}: order {order}");
    }
}

/// Spun up by a constant wheel torque u = 0.3 (p = p₀ + ut): still order 2.0.
#[test]
fn symmetric_gyrostat_under_a_wheel_torque_converges_to_its_closed_form_at_order_2() {
    for (name, order, err) in symmetric_orders(0.3) {
        println!(
            "symmetric gyrostat, wheel torque 0.3, {name}: order {order:.3}, error at h = 0.01 \
             {err:.2e}"
        );
        assert!((1.9..=2.1).contains(&order), "{name}: order {order}");
    }
}

// ---- Three skewed wheels under a torque schedule ----

/// Max over `steps` steps of |RΠ − R₀Π₀|/|Π₀| and ||Π|² − |Π₀|²|/|Π₀|², with the wheel torques of
/// `wheel_schedule`.
fn balance_drift(integ: &mut dyn Integrator<Group = G3>, h: f64, steps: usize) -> (f64, f64) {
    let l = |i: &dyn Integrator<Group = G3>| {
        Gyrostat::<3>::total_angular_momentum(i.configuration().unwrap(), &i.momentum())
    };
    let l0 = l(integ);
    let c0 = integ.momentum().a.norm_squared();
    let (mut dl, mut dc) = (0.0f64, 0.0f64);
    for _ in 0..steps {
        integ.step(h).unwrap();
        dl = dl.max((l(integ) - l0).amax() / l0.norm());
        dc = dc.max((integ.momentum().a.norm_squared() - c0).abs() / c0);
    }
    (dl, dc)
}

/// A wheel torque is internal: R Π (the total angular momentum in space) and |Π|² do not change.
/// Lie–Poisson (any θ, both τ) and the Strang splitting keep both to round-off over 2000 steps
/// while the wheels' momenta p change by O(1) (bound 1e-13 relative).
#[test]
fn wheel_torques_keep_the_total_angular_momentum_to_round_off() {
    let (mu0, g0) = three_wheel_state();
    let forced = || {
        Forced::new(
            three_wheels(),
            Gyrostat::<3>::wheel_torques(wheel_schedule()).unwrap(),
        )
    };
    let mut runs: Vec<(String, Box<dyn Integrator<Group = G3>>)> = Vec::new();
    for theta in [0.0, 0.5, 1.0] {
        runs.push((
            format!("LP exp θ = {theta}"),
            Box::new(LiePoisson::<G3, ExpMap, _>::new(forced(), theta, mu0, Some(g0)).unwrap()),
        ));
        runs.push((
            format!("LP cayley θ = {theta}"),
            Box::new(LiePoisson::<G3, Cayley, _>::new(forced(), theta, mu0, Some(g0)).unwrap()),
        ));
    }
    runs.push((
        "Strang".into(),
        Box::new(Splitting::new(forced(), mu0, Some(g0)).unwrap()),
    ));
    for (name, mut integ) in runs {
        let (dl, dc) = balance_drift(integ.as_mut(), 0.002, 2000);
        let dp = (integ.momentum().b - mu0.b).amax();
        println!("{name}: |Δ(RΠ)| {dl:.2e}, |Δ|Π|²| {dc:.2e}, wheel momenta moved by {dp:.2}");
        assert!(dl < 1e-13 && dc < 1e-13, "{name}: {dl:e} {dc:e}");
        assert!(dp > 0.1, "{name}: the wheels did not spin up ({dp})");
    }
}

/// RK4 on y = (R (column-major), φ, Π, p) for `Ṙ = RΩ̂`, `φ̇ = J⁻¹p − AᵀΩ`, `Π̇ = Π × Ω`,
/// `ṗ = u(t)`, Ω = 𝕀_s⁻¹(Π − Ap), written from the module page without the crate's system.
fn reference(t_end: f64) -> DVector<f64> {
    let gyro = three_wheels();
    let a = *gyro.axes();
    let j = *gyro.wheel_inertias();
    let platform_inv = (gyro.inertia() - a * Matrix3::from_diagonal(&j) * a.transpose())
        .try_inverse()
        .unwrap();
    let (mu0, g0) = three_wheel_state();
    let mut y0 = DVector::zeros(18);
    y0.rows_mut(0, 9)
        .copy_from_slice(g0.g.as_matrix().as_slice());
    y0.rows_mut(9, 3).copy_from(&g0.h.vector());
    y0.rows_mut(12, 3).copy_from(&mu0.a);
    y0.rows_mut(15, 3).copy_from(&mu0.b);
    let f = |t: f64, y: &DVector<f64>| {
        let r = Matrix3::from_column_slice(&y.as_slice()[0..9]);
        let pi = Vector3::from_column_slice(&y.as_slice()[12..15]);
        let p = Vector3::from_column_slice(&y.as_slice()[15..18]);
        let om = platform_inv * (pi - a * p);
        let rates = p.component_div(&j) - a.transpose() * om;
        let mut dy = DVector::zeros(18);
        dy.rows_mut(0, 9)
            .copy_from_slice((r * om.cross_matrix()).as_slice());
        dy.rows_mut(9, 3).copy_from(&rates);
        dy.rows_mut(12, 3).copy_from(&pi.cross(&om));
        dy.rows_mut(15, 3).copy_from(&wheel_torque_at(t));
        dy
    };
    rk4_richardson(f, &y0, t_end, 8000)
}

/// Lie–Poisson θ = ½ (exp, Cayley) and Strang converge at order 2 to the independent reference
/// under the torque schedule (T = 4, h = 0.04 … 0.01; the reference: RK4 at h = 5e-4 and 1e-3,
/// Richardson-extrapolated, error ≲ 1e-13).
#[test]
fn three_wheel_gyrostat_converges_at_order_2_to_an_independent_rk4() {
    let t_end = 4.0;
    let yref = reference(t_end);
    let r_ref = Matrix3::from_column_slice(&yref.as_slice()[0..9]);
    let phi_ref = Vector3::from_column_slice(&yref.as_slice()[9..12]);
    let pi_ref = Vector3::from_column_slice(&yref.as_slice()[12..15]);
    let p_ref = Vector3::from_column_slice(&yref.as_slice()[15..18]);
    let (mu0, g0) = three_wheel_state();
    let forced = || {
        Forced::new(
            three_wheels(),
            Gyrostat::<3>::wheel_torques(wheel_schedule()).unwrap(),
        )
    };
    let error = |mut integ: Box<dyn Integrator<Group = G3>>, h: f64| {
        for _ in 0..(t_end / h).round() as usize {
            integ.step(h).unwrap();
        }
        let g = integ.configuration().unwrap();
        let mu = integ.momentum();
        (g.g.as_matrix() - r_ref)
            .amax()
            .max((g.h.vector() - phi_ref).amax())
            .max((mu.a - pi_ref).amax() / pi_ref.norm())
            .max((mu.b - p_ref).amax())
    };
    let hs = [0.04, 0.02, 0.01];
    let methods: [(&str, Maker3); 3] = [
        ("LP exp θ = ½", &|| {
            Box::new(LiePoisson::<G3, ExpMap, _>::new(forced(), 0.5, mu0, Some(g0)).unwrap())
        }),
        ("LP cayley θ = ½", &|| {
            Box::new(LiePoisson::<G3, Cayley, _>::new(forced(), 0.5, mu0, Some(g0)).unwrap())
        }),
        ("Strang", &|| {
            Box::new(Splitting::new(forced(), mu0, Some(g0)).unwrap())
        }),
    ];
    for (name, make) in methods {
        let errs: Vec<f64> = hs.iter().map(|&h| error(make(), h)).collect();
        let order = fitted_order(&hs, &errs);
        println!("three wheels, torque schedule, {name}: errors {errs:?}, order {order:.3}");
        assert!((1.9..=2.1).contains(&order), "{name}: order {order}");
    }
}

/// The Hessian's size without the matrix is the matrix's largest entry.
#[test]
fn gyrostat_hessian_norm_is_the_hessians() {
    let gyro = three_wheels();
    let (mu, _) = three_wheel_state();
    assert_eq!(gyro.hessian_norm(&mu), gyro.hessian(&mu).amax());
}
