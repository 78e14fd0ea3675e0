//! The integrators are assembled from the discretization layer (`discretization::LiftedMap`); this
//! file keeps the hand-derived schemes of eqs. (18)–(19) — written here with the matrices of τ,
//! plain Ad*, d^{L*}τ, and a fixed-point iteration, no code shared with the library's step — and
//! checks that one assembled step equals one hand-derived step to round-off, on every group, τ and
//! θ, with and without a potential.

use integrators::{EulerPoincare, Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, Operator, Se2, Se3, So3, SoN, Tau, Vector};
use mechanics::systems::{GeneralizedRigidBody, HeavyTop, PlanarBody, RigidBody, RigidBodySe3};
use nalgebra::{Matrix3, Vector2, Vector3};

const THETAS: [f64; 4] = [0.0, 0.3, 0.5, 1.0];

fn force<G: LieGroup, S: System<G>>(system: &S, g: &G) -> G::Algebra {
    if system.has_potential() {
        system.potential_differential(g).neg()
    } else {
        G::Algebra::zeros(G::dim())
    }
}

/// Fixed-point iteration x ← f(x) to the floating-point floor (contracting for the small steps
/// used here).
fn fixed_point<V: Vector>(mut x: V, f: impl Fn(&V) -> V) -> V {
    for _ in 0..200 {
        let next = f(&x);
        let done = next.sub(&x).norm_max() <= 1e-17 * (1.0 + x.norm_max());
        x = next;
        if done {
            break;
        }
    }
    x
}

/// The hand-derived Lie–Poisson step (eq. 19 with the corrected twist, see lie_poisson.rs):
/// `ḡ = g_k τ(θξ)`, `ν = Ad*_{τ(θξ)} μ_k + h F(ḡ)`, `μ_{k+1} = Ad*_{τ((1−θ)ξ)} ν`,
/// `μ̄ = θ d^{L*}τ_{−θξ} μ_k + (1−θ) d^{L*}τ_{(1−θ)ξ} μ_{k+1}`, `ξ = h ∂h/∂μ(μ̄)`,
/// `g_{k+1} = ḡ τ((1−θ)ξ)`.
fn hand_lie_poisson<G: LieGroup, T: Tau<G>, S: System<G>>(
    system: &S,
    theta: f64,
    h: f64,
    mu: &G::Algebra,
    g: &G,
) -> (G::Algebra, G) {
    let b = 1.0 - theta;
    let parts = |xi: &G::Algebra| {
        let gbar = g.compose(&T::tau(&xi.scale(theta)));
        let nu = T::tau(&xi.scale(theta))
            .coadjoint_apply(mu)
            .add(&force(system, &gbar).scale(h));
        let mu1 = T::tau(&xi.scale(b)).coadjoint_apply(&nu);
        (gbar, mu1)
    };
    let xi = fixed_point(system.velocity(mu).scale(h), |xi| {
        let (_, mu1) = parts(xi);
        let bar = T::dtau_left_dual_apply(&xi.scale(-theta), mu)
            .scale(theta)
            .add(&T::dtau_left_dual_apply(&xi.scale(b), &mu1).scale(b));
        system.velocity(&bar).scale(h)
    });
    let (gbar, mu1) = parts(&xi);
    (mu1, gbar.compose(&T::tau(&xi.scale(b))))
}

/// The hand-derived Euler–Poincaré step (eq. 18): with `a = θh`, `ḡ = g_k τ(aξ)`, f the
/// Euler–Poincaré field, ξ solves `ξ_k = Ad_{τ(aξ)} ξ − a d^Lτ_{−aξ} f(ḡ, ξ)`;
/// `ξ_{k+1} = Ad_{τ(−(1−θ)hξ)} ξ + (1−θ)h d^Lτ_{(1−θ)hξ} f(ḡ, ξ)`, `g_{k+1} = ḡ τ((1−θ)hξ)`.
fn hand_euler_poincare<G: LieGroup, T: Tau<G>, S: System<G>>(
    system: &S,
    theta: f64,
    h: f64,
    xi_k: &G::Algebra,
    g: &G,
) -> (G::Algebra, G) {
    let (a, b) = (theta * h, (1.0 - theta) * h);
    let field = |gb: &G, xi: &G::Algebra| {
        let mu = system.momentum(xi);
        system
            .hessian(&mu)
            .apply(&G::ad_dual_apply(xi, &mu).add(&force(system, gb)))
    };
    let gbar = |xi: &G::Algebra| g.compose(&T::tau(&xi.scale(a)));
    let xi = fixed_point(xi_k.clone(), |xi| {
        let f = field(&gbar(xi), xi);
        let rhs = xi_k.add(&T::dtau_left(&xi.scale(-a)).apply(&f).scale(a));
        T::tau(&xi.scale(-a)).adjoint_apply(&rhs)
    });
    let gb = gbar(&xi);
    let f = field(&gb, &xi);
    let tb = T::tau(&xi.scale(b));
    let xi1 = tb
        .inverse()
        .adjoint_apply(&xi)
        .add(&T::dtau_left(&xi.scale(b)).apply(&f).scale(b));
    (xi1, gb.compose(&tb))
}

/// Three steps of each assembled integrator against the hand-derived ones, every θ.
fn check<G: LieGroup, T: Tau<G>, S: System<G> + Clone>(
    name: &str,
    system: S,
    mu0: G::Algebra,
    g0: G,
    h: f64,
) {
    for theta in THETAS {
        let mut lp =
            LiePoisson::<G, T, S>::new(system.clone(), theta, mu0.clone(), Some(g0.clone()))
                .unwrap();
        let xi0 = system.velocity(&mu0);
        let mut ep =
            EulerPoincare::<G, T, S>::new(system.clone(), theta, xi0.clone(), Some(g0.clone()))
                .unwrap();
        let (mut mu, mut g, mut xi, mut ge) = (mu0.clone(), g0.clone(), xi0, g0.clone());
        let scale = 1.0 + mu0.norm_max();
        for _ in 0..3 {
            lp.step(h).unwrap();
            ep.step(h).unwrap();
            (mu, g) = hand_lie_poisson::<G, T, S>(&system, theta, h, &mu, &g);
            (xi, ge) = hand_euler_poincare::<G, T, S>(&system, theta, h, &xi, &ge);
        }
        let dmu = lp.momentum().sub(&mu).norm_max() / scale;
        let dg = lp.configuration().unwrap().matrix_distance(&g);
        let dxi = ep.velocity().sub(&xi).norm_max() / (1.0 + xi.norm_max());
        let dge = ep.configuration().unwrap().matrix_distance(&ge);
        let worst = dmu.max(dg).max(dxi).max(dge);
        assert!(
            worst < 1e-13,
            "{name}, τ = {}, θ = {theta}: LP Δμ {dmu:.1e} Δg {dg:.1e}, EP Δξ {dxi:.1e} Δg {dge:.1e}",
            T::NAME
        );
    }
}

fn both_taus<G: LieGroup, S: System<G> + Clone>(
    name: &str,
    system: S,
    mu0: G::Algebra,
    g0: G,
    h: f64,
) where
    ExpMap: Tau<G>,
    Cayley: Tau<G>,
{
    check::<G, ExpMap, S>(name, system.clone(), mu0.clone(), g0.clone(), h);
    check::<G, Cayley, S>(name, system, mu0, g0, h);
}

#[test]
fn assembled_steps_equal_the_hand_derived_schemes_on_so3() {
    let g0 = So3::exp(&Vector3::new(0.3, -0.5, 0.8));
    let mu0 = Vector3::new(0.5, 1.0, 0.2);
    let body = RigidBody::new(Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0)).unwrap();
    both_taus("free body", body, mu0, g0, 0.05);
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    both_taus("heavy top", top, mu0, g0, 0.02);
}

#[test]
fn assembled_steps_equal_the_hand_derived_schemes_on_se3_and_se2() {
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0));
    let a = nalgebra::Vector6::new(0.2, -0.1, 0.3, 7.0, 0.5, -0.2);
    let g0 = Se3::exp(&a);
    let mu0 = nalgebra::Vector6::new(0.3, 0.5, -0.2, 0.1, 0.8, 0.05);
    both_taus(
        "free body on SE(3)",
        RigidBodySe3::free(2.0, inertia).unwrap(),
        mu0,
        g0,
        0.05,
    );
    both_taus(
        "satellite",
        RigidBodySe3::satellite(2.0, inertia, 400.0).unwrap(),
        mu0,
        g0,
        0.05,
    );
    let planar = PlanarBody::free(1.5, 0.7)
        .unwrap()
        .with_spring(2.0, Vector2::new(0.3, 0.1))
        .unwrap()
        .with_gravity(Vector2::new(0.0, -9.81))
        .unwrap();
    let g2 = Se2::exp(&Vector3::new(0.4, 0.2, -0.3));
    both_taus(
        "planar body",
        planar,
        Vector3::new(0.6, -0.2, 0.4),
        g2,
        0.02,
    );
}

#[test]
fn assembled_steps_equal_the_hand_derived_schemes_on_so4() {
    let body = GeneralizedRigidBody::<4>::new(&[1.0, 1.5, 2.2, 3.1]).unwrap();
    let mu0 =
        <SoN<4> as LieGroup>::Algebra::from_fn(6, |i| 0.3 + 0.2 * i as f64 - 0.05 * (i * i) as f64);
    let g0 = SoN::<4>::exp(&<SoN<4> as LieGroup>::Algebra::from_fn(6, |i| {
        0.1 * i as f64 - 0.2
    }));
    both_taus("generalized rigid body on SO(4)", body, mu0, g0, 0.05);
}
