//! The integrators of the right-trivialized map (`RightDiscretizationMap`): Lie–Poisson and
//! Euler–Poincaré for a right-invariant system, `μ̇ = −ad*_ξ μ = Ω × μ`, `Ṙ = Ω̂ R` on SO(3) with
//! h(μ) = ½ μᵀ𝕀⁻¹μ, checked against an independent RK4 integration of those equations written
//! here: fitted orders, the Casimir |μ|² and the right momentum map `Ad*_R μ = Rᵀμ` at round-off,
//! reversibility at θ = ½, dense output, and the refusal of potentials.

use discretization::RightDiscretizationMap;
use integrators::dense_output::integrate_dense;
use integrators::{CotangentLiftIntegrator, Integrator, TangentLiftIntegrator};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{Matrix3, Vector3};

type RightLp<T> = CotangentLiftIntegrator<So3, RightDiscretizationMap<T>, RigidBody>;
type RightEp<T> = TangentLiftIntegrator<So3, RightDiscretizationMap<T>, RigidBody>;

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}
const MU0: Vector3<f64> = Vector3::new(0.5, 1.0, 0.2);
fn r0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

fn skew(w: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

/// RK4 on (μ, R) for μ̇ = Ω × μ, Ṙ = Ω̂ R, Ω = 𝕀⁻¹μ, at h = 1e-4 (error ~1e-16·T).
fn reference(t_end: f64) -> (Vector3<f64>, Matrix3<f64>) {
    let inv = Matrix3::from_diagonal(&Vector3::new(1.0, 0.5, 1.0 / 3.0));
    let f = |mu: &Vector3<f64>, r: &Matrix3<f64>| {
        let w = inv * mu;
        (w.cross(mu), skew(&w) * r)
    };
    let n = (t_end / 1e-4).round() as usize;
    let h = t_end / n as f64;
    let (mut mu, mut r) = (MU0, *r0().as_matrix());
    for _ in 0..n {
        let (k1, l1) = f(&mu, &r);
        let (k2, l2) = f(&(mu + k1 * (h / 2.0)), &(r + l1 * (h / 2.0)));
        let (k3, l3) = f(&(mu + k2 * (h / 2.0)), &(r + l2 * (h / 2.0)));
        let (k4, l4) = f(&(mu + k3 * h), &(r + l3 * h));
        mu += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
        r += (l1 + l2 * 2.0 + l3 * 2.0 + l4) * (h / 6.0);
    }
    (mu, r)
}

fn error<I: Integrator<Group = So3>>(
    mut i: I,
    h: f64,
    t_end: f64,
    want: &(Vector3<f64>, Matrix3<f64>),
) -> f64 {
    let n = (t_end / h).round() as usize;
    for _ in 0..n {
        i.step(h).unwrap();
    }
    (i.momentum() - want.0)
        .amax()
        .max((i.configuration().unwrap().as_matrix() - want.1).amax())
}

/// Fitted orders between h = 0.04 and 0.02 over T = 2: 2 for Lie–Poisson at every θ (no
/// potential) and for Euler–Poincaré at θ = ½, matching `info().order`; a sign error in the
/// right map or in the integrators' ad* would not converge at all.
fn orders<T: Tau<So3>>() {
    let want = reference(2.0);
    for theta in [0.0, 0.5, 1.0] {
        let lp = |h| {
            error(
                RightLp::<T>::new(body(), theta, MU0, Some(r0())).unwrap(),
                h,
                2.0,
                &want,
            )
        };
        let order = (lp(0.04) / lp(0.02)).log2();
        let declared = RightLp::<T>::new(body(), theta, MU0, None)
            .unwrap()
            .info()
            .order as f64;
        assert!(
            (order - declared).abs() < 0.15,
            "LP {} θ={theta}: order {order}",
            T::NAME
        );
        let ep = |h| {
            error(
                RightEp::<T>::from_momentum(body(), theta, MU0, Some(r0())).unwrap(),
                h,
                2.0,
                &want,
            )
        };
        let order = (ep(0.04) / ep(0.02)).log2();
        let declared = RightEp::<T>::new(body(), theta, MU0, None)
            .unwrap()
            .info()
            .order as f64;
        assert!(
            (order - declared).abs() < 0.15,
            "EP {} θ={theta}: order {order}",
            T::NAME
        );
    }
}

#[test]
fn right_integrators_converge_with_their_orders_cayley() {
    orders::<Cayley>();
}

#[test]
fn right_integrators_converge_with_their_orders_exp() {
    orders::<ExpMap>();
}

/// Over 10⁴ steps of h = 0.05: |μ|² and Rᵀμ (the right momentum map) at round-off for
/// Lie–Poisson; the step retraces itself at θ = ½.
#[test]
fn right_lie_poisson_keeps_its_invariants_and_is_reversible() {
    let mut lp = RightLp::<Cayley>::new(body(), 0.5, MU0, Some(r0())).unwrap();
    let j0 = r0().as_matrix().transpose() * MU0;
    let (mut dc, mut dj) = (0.0f64, 0.0f64);
    for _ in 0..10_000 {
        lp.step(0.05).unwrap();
        let mu = lp.momentum();
        dc = dc.max((mu.norm_squared() / MU0.norm_squared() - 1.0).abs());
        dj = dj.max((lp.configuration().unwrap().as_matrix().transpose() * mu - j0).amax());
    }
    assert!(dc < 1e-14, "Casimir drift {dc:e}");
    assert!(dj < 1e-13, "momentum map drift {dj:e}");
    let mut lp = RightLp::<Cayley>::new(body(), 0.5, MU0, Some(r0())).unwrap();
    for _ in 0..50 {
        lp.step(0.05).unwrap();
    }
    for _ in 0..50 {
        lp.step(-0.05).unwrap();
    }
    assert!((lp.momentum() - MU0).amax() < 1e-13);
    assert!(lp.configuration().unwrap().matrix_distance(&r0()) < 1e-13);
}

/// Dense output of a right-trivialized run (g(s) = exp(−Z(s)) g₀ through the inversion): at
/// times between the steps within 2× the run's own error at its step points, against the
/// reference.
#[test]
fn dense_output_of_a_right_run() {
    let h = 0.1;
    let mut plain = RightLp::<Cayley>::new(body(), 0.5, MU0, Some(r0())).unwrap();
    let mut at_steps = 0.0f64;
    for k in 1..=10 {
        plain.step(h).unwrap();
        let (mu_ref, r_ref) = reference(k as f64 * h);
        at_steps = at_steps
            .max((plain.momentum() - mu_ref).amax())
            .max((plain.configuration().unwrap().as_matrix() - r_ref).amax());
    }
    let mut lp = RightLp::<Cayley>::new(body(), 0.5, MU0, Some(r0())).unwrap();
    let times: Vec<f64> = (0..10).map(|k| (k as f64 + 0.5) * h).collect();
    let mut between = 0.0f64;
    integrate_dense(
        &mut lp,
        h,
        10,
        &times,
        |t, mu, g| {
            let (mu_ref, r_ref) = reference(t);
            between = between
                .max((mu - mu_ref).amax())
                .max((g.unwrap().as_matrix() - r_ref).amax());
        },
        &[],
    )
    .unwrap();
    assert!(between <= 2.0 * at_steps, "{between:e} vs {at_steps:e}");
}

#[test]
fn right_integrators_refuse_potentials() {
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.0, 0.5)).unwrap();
    assert!(
        CotangentLiftIntegrator::<So3, RightDiscretizationMap<Cayley>, _>::new(
            top.clone(),
            0.5,
            MU0,
            Some(r0())
        )
        .is_err()
    );
    assert!(
        TangentLiftIntegrator::<So3, RightDiscretizationMap<Cayley>, _>::new(
            top,
            0.5,
            MU0,
            Some(r0())
        )
        .is_err()
    );
}
