//! Integrators of maps outside the θ-family, defined in this file by nothing but their factors
//! `R̃_d(g, ξ) = (g a(ξ), g b(ξ))`: every lift component comes from the default (composed) path of
//! `discretization::LiftedMap`, the tangents of a and b from differences, the descriptors from
//! measuring the map. Checked on the free rigid body and the heavy top (SO(3)):
//! - the fitted order of Lie–Poisson and Euler–Poincaré is the one `info()` reports (within 0.2),
//!   and the descriptors are the hand-derived ones (see each map);
//! - Lie–Poisson keeps the Casimir |Π|² at round-off;
//! - a step of h then −h returns to the start to round-off exactly when `info()` says symmetric;
//! - the step of the adjoint map at −h undoes the map's at h (the rule of `Adjoint`);
//! - and the θ-maps' integrators through the default path (`Composed`) follow the fused ones to
//!   round-off, every τ, θ and side.

use crate::common::{fitted_order, r0, rk4_heavy_top, rk4_reference, TestHeavyTop};
use discretization::{
    Adjoint, Composed, Discretization, DiscretizationMap, LiftedMap, RightDiscretizationMap,
};
use integrators::{CotangentLiftIntegrator, Integrator, System, TangentLiftIntegrator};
use lie_groups::{Cayley, CayleyGroup, ExpMap, LieGroup, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};

/// `a(ξ) = exp(−ξ/3)`, `b(ξ) = cay(2ξ/3)`: two different τ, θ = ⅓. Not symmetric (b(−ξ) ≠ a(ξ)),
/// order 1 (θ ≠ ½). Its increment `c(ξ) = exp(ξ/3) cay(2ξ/3)` is a product of rotations about
/// the same axis, reversible: Lie–Poisson without a potential is symmetric, of order 2.
#[derive(Debug, Clone, Copy)]
struct ExpCayley;

impl Discretization<So3> for ExpCayley {
    fn first_factor(&self, xi: &Vector3<f64>) -> So3 {
        So3::exp(&(xi / -3.0))
    }
    fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
        So3::cay(&(xi * (2.0 / 3.0)))
    }
}
impl LiftedMap<So3> for ExpCayley {}

/// `a(ξ) = exp(−ξ/2)`, `b(ξ) = exp(ξ/2 + ξ × Kξ)`, K symmetric: θ = ½, but the quadratic parts
/// of log a and log b differ (0 against ξ × Kξ), so the map is of order 1 although θ = ½ (the
/// θ-family's rule "order 2 iff θ = ½" would be wrong here), and its increment
/// `c(ξ) = exp(ξ + ξ × Kξ + O(ξ³))` is not reversible: every integrator is of order 1, none
/// symmetric.
#[derive(Debug, Clone, Copy)]
struct Skewed;

impl Skewed {
    fn k() -> Matrix3<f64> {
        Matrix3::new(0.3, 0.1, -0.2, 0.1, -0.4, 0.25, -0.2, 0.25, 0.5)
    }
}

impl Discretization<So3> for Skewed {
    fn first_factor(&self, xi: &Vector3<f64>) -> So3 {
        So3::exp(&(xi * -0.5))
    }
    fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
        So3::exp(&(xi * 0.5 + xi.cross(&(Self::k() * xi))))
    }
}
impl LiftedMap<So3> for Skewed {}

/// `a(ξ) = exp(−ξ/4) cay(−ξ/4)`, `b(ξ) = exp(ξ/4) cay(ξ/4) = a(−ξ)`: symmetric and of order 2,
/// outside the θ-family (neither exp nor Cayley of a multiple of ξ).
#[derive(Debug, Clone, Copy)]
struct MixedMidpoint;

impl Discretization<So3> for MixedMidpoint {
    fn first_factor(&self, xi: &Vector3<f64>) -> So3 {
        So3::exp(&(xi * -0.25)).compose(&So3::cay(&(xi * -0.25)))
    }
    fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
        So3::exp(&(xi * 0.25)).compose(&So3::cay(&(xi * 0.25)))
    }
}
impl LiftedMap<So3> for MixedMidpoint {}

fn body() -> RigidBody {
    RigidBody::new(Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 3.0)).unwrap()
}
fn top() -> TestHeavyTop {
    TestHeavyTop {
        body: body(),
        mgchi: Vector3::new(0.3, -0.2, 1.0),
    }
}
const PI0: Vector3<f64> = Vector3::new(0.5, 1.0, -0.7);
fn g0() -> So3 {
    So3::from_matrix(&r0()).unwrap()
}

fn lp<M: LiftedMap<So3>, S: System<So3>>(system: S, map: M) -> CotangentLiftIntegrator<So3, M, S> {
    CotangentLiftIntegrator::with_map(system, map, PI0, Some(g0())).unwrap()
}
fn ep<M: LiftedMap<So3>, S: System<So3>>(system: S, map: M) -> TangentLiftIntegrator<So3, M, S> {
    let xi0 = system.velocity(&PI0);
    TangentLiftIntegrator::with_map(system, map, xi0, Some(g0())).unwrap()
}

/// (R, Π) after `n` steps of `t/n`.
fn end<I: Integrator<Group = So3>>(mut i: I, t: f64, n: usize) -> (Matrix3<f64>, Vector3<f64>) {
    for _ in 0..n {
        i.step(t / n as f64).unwrap();
    }
    (*i.configuration().unwrap().as_matrix(), i.momentum())
}

const T: f64 = 2.0;
const STEPS: [usize; 4] = [40, 80, 160, 320];

/// The order fitted from four step sizes against a reference at T.
fn fitted<I: Integrator<Group = So3>>(
    make: impl Fn() -> I,
    reference: &(Matrix3<f64>, Vector3<f64>),
) -> f64 {
    let (hs, errs): (Vec<f64>, Vec<f64>) = STEPS
        .iter()
        .map(|&n| {
            let (r, p) = end(make(), T, n);
            let err = (r - reference.0)
                .amax()
                .max((p - reference.1).amax() / PI0.norm());
            (T / n as f64, err)
        })
        .unzip();
    fitted_order(&hs, &errs)
}

/// Fitted orders of both integrators of `map` on both systems against `info().order`; the
/// expected descriptors `(LP free, LP heavy top, EP)` as (order, symmetric).
fn check_orders<M: LiftedMap<So3> + Copy>(name: &str, map: M, want: [(u32, bool); 3]) {
    // RK4 with h = 1e-4: error ~1e-15, far below the finest integrator error (> 1e-7).
    let free = rk4_reference(body().inertia(), &r0(), &PI0, T, 20_000);
    let heavy = rk4_heavy_top(body().inertia(), &top().mgchi, &r0(), &PI0, T, 20_000);
    let cases = [
        (
            "LP free",
            lp(body(), map).info(),
            fitted(|| lp(body(), map), &free),
            want[0],
        ),
        (
            "LP heavy top",
            lp(top(), map).info(),
            fitted(|| lp(top(), map), &heavy),
            want[1],
        ),
        (
            "EP free",
            ep(body(), map).info(),
            fitted(|| ep(body(), map), &free),
            want[2],
        ),
        (
            "EP heavy top",
            ep(top(), map).info(),
            fitted(|| ep(top(), map), &heavy),
            want[2],
        ),
    ];
    for (what, info, order, (want_order, want_symmetric)) in cases {
        println!(
            "{name}, {what}: fitted order {order:.3}, reported {} ({})",
            info.order,
            if info.symmetric {
                "symmetric"
            } else {
                "not symmetric"
            }
        );
        assert_eq!(
            (info.order, info.symmetric),
            (want_order, want_symmetric),
            "{name}, {what}: descriptors"
        );
        assert!(
            (order - f64::from(info.order)).abs() < 0.2,
            "{name}, {what}: fitted order {order:.3}, reported {}",
            info.order
        );
    }
}

#[test]
fn exp_cayley_map_integrates_with_the_orders_it_reports() {
    let m = ExpCayley;
    assert!((m.theta() - 1.0 / 3.0).abs() < 1e-10, "θ = {}", m.theta());
    assert!(!m.symmetric() && m.order() == 1);
    assert!(m.reversible_increment() && m.increment_order() == 2);
    check_orders("exp/cayley", m, [(2, true), (1, false), (1, false)]);
}

#[test]
fn skewed_midpoint_map_integrates_with_the_orders_it_reports() {
    let m = Skewed;
    assert!((m.theta() - 0.5).abs() < 1e-10, "θ = {}", m.theta());
    assert!(!m.symmetric() && m.order() == 1);
    assert!(!m.reversible_increment() && m.increment_order() == 1);
    check_orders("skewed", m, [(1, false), (1, false), (1, false)]);
}

#[test]
fn mixed_midpoint_map_integrates_with_the_orders_it_reports() {
    let m = MixedMidpoint;
    assert!((m.theta() - 0.5).abs() < 1e-10, "θ = {}", m.theta());
    assert!(m.symmetric() && m.order() == 2);
    assert!(m.reversible_increment() && m.increment_order() == 2);
    check_orders("mixed midpoint", m, [(2, true), (2, true), (2, true)]);
}

/// |Π|² of Lie–Poisson over 10⁴ steps of h = 0.01 (free body) stays at round-off for each map:
/// the default path's momentum increments come from log of the factors, rounded relative to their
/// own size, and are added with compensated summation, as the fused θ-map's (measured 3.3e-16
/// against 2.2e-16 fused). With Ad* applied from the factors' matrices instead, |Π|² random-walked
/// to 1.4–3.5e-14 over the same steps, and this bound failed.
#[test]
fn user_maps_keep_the_casimir_at_round_off() {
    fn drift<M: LiftedMap<So3>>(map: M) -> f64 {
        let mut i = lp(body(), map);
        let c0 = PI0.norm_squared();
        let mut worst = 0.0f64;
        for _ in 0..10_000 {
            i.step(0.01).unwrap();
            worst = worst.max((i.momentum().norm_squared() / c0 - 1.0).abs());
        }
        worst
    }
    let midpoint = DiscretizationMap::<Cayley>::new(0.5).unwrap();
    for (name, d) in [
        ("exp/cayley", drift(ExpCayley)),
        ("skewed", drift(Skewed)),
        ("mixed midpoint", drift(MixedMidpoint)),
        ("θ = ½ cayley, composed", drift(Composed(midpoint))),
        ("θ = ½ cayley, fused", drift(midpoint)),
    ] {
        println!("{name}: max relative Casimir drift {d:.1e} over 10⁴ steps");
        assert!(d < 1e-15, "{name}: Casimir drift {d:e}");
    }
}

/// The distance from the start after a step of h and one of −h (relative in the velocity or
/// momentum, absolute in R).
fn round_trip<I: Integrator<Group = So3>, J: Integrator<Group = So3>>(
    mut i: I,
    back: impl FnOnce(&I) -> J,
    h: f64,
) -> f64 {
    let (v0, m0) = (i.velocity(), *i.configuration().unwrap());
    i.step(h).unwrap();
    let mut j = back(&i);
    j.step(-h).unwrap();
    (j.velocity() - v0)
        .amax()
        .max(j.configuration().unwrap().matrix_distance(&m0))
        / (1.0 + v0.amax())
}

/// Step h then −h with the same integrator: back to the start to round-off iff `info()` says
/// symmetric (a step that is not symmetric misses by O(h^{p+1}), 1e-6 and more at h = 0.05).
fn check_reversibility<I: Integrator<Group = So3> + Clone>(name: &str, i: I) {
    let symmetric = i.info().symmetric;
    let miss = round_trip(i, Clone::clone, 0.05);
    println!("{name}: step h, −h misses by {miss:.1e}; reported symmetric: {symmetric}");
    if symmetric {
        assert!(
            miss < 1e-13,
            "{name}: reported symmetric, misses by {miss:e}"
        );
    } else {
        assert!(
            miss > 1e-8,
            "{name}: reported not symmetric, misses by {miss:e}"
        );
    }
}

#[test]
fn user_maps_are_reversible_exactly_when_they_report_symmetry() {
    fn each<M: LiftedMap<So3> + Copy>(name: &str, map: M) {
        check_reversibility(&format!("{name} LP free"), lp(body(), map));
        check_reversibility(&format!("{name} LP heavy top"), lp(top(), map));
        check_reversibility(&format!("{name} EP free"), ep(body(), map));
        check_reversibility(&format!("{name} EP heavy top"), ep(top(), map));
    }
    each("exp/cayley", ExpCayley);
    each("skewed", Skewed);
    each("mixed midpoint", MixedMidpoint);
}

/// The θ-maps through the same rule: Lie–Poisson without a potential is symmetric at every θ on
/// exp and Cayley (reversible increment), on both sides; with a potential and for
/// Euler–Poincaré only at θ = ½.
#[test]
fn theta_maps_are_reversible_exactly_when_they_report_symmetry() {
    fn each<T: Tau<So3>>() {
        for theta in [0.0, 0.25, 0.3, 0.5, 1.0] {
            let name = format!("τ = {}, θ = {theta}", T::NAME);
            let left = DiscretizationMap::<T>::new(theta).unwrap();
            let right = RightDiscretizationMap::<T>::new(theta).unwrap();
            check_reversibility(&format!("{name}: LP free"), lp(body(), left));
            check_reversibility(&format!("{name}: LP heavy top"), lp(top(), left));
            check_reversibility(&format!("{name}: EP free"), ep(body(), left));
            check_reversibility(&format!("{name}: EP heavy top"), ep(top(), left));
            check_reversibility(&format!("{name}: right LP"), lp(body(), right));
            check_reversibility(&format!("{name}: right EP"), ep(body(), right));
        }
    }
    each::<ExpMap>();
    each::<Cayley>();
}

/// The integrator of `Adjoint(M)` at −h undoes M's at h, to round-off, for maps that are not
/// symmetric (for a symmetric one this is the reversibility above), with a potential.
#[test]
fn the_adjoint_map_steps_back() {
    fn each<M: LiftedMap<So3> + Copy>(name: &str, map: M) {
        let cases = [
            (
                "LP",
                round_trip(
                    lp(top(), map),
                    |i| {
                        let mut j = lp(top(), Adjoint(map));
                        j.reset(0.0, i.momentum(), i.configuration().cloned())
                            .unwrap();
                        j
                    },
                    0.05,
                ),
            ),
            (
                "EP",
                round_trip(
                    ep(top(), map),
                    |i| {
                        let mut j = ep(top(), Adjoint(map));
                        j.reset(0.0, i.velocity(), i.configuration().cloned())
                            .unwrap();
                        j
                    },
                    0.05,
                ),
            ),
        ];
        for (what, miss) in cases {
            println!("{name} {what}: M at h, adjoint at −h misses by {miss:.1e}");
            assert!(miss < 1e-13, "{name} {what}: misses by {miss:e}");
        }
    }
    each("exp/cayley", ExpCayley);
    each("skewed", Skewed);
    each(
        "θ = 0.3 cayley",
        DiscretizationMap::<Cayley>::new(0.3).unwrap(),
    );
}

/// The θ-maps' integrators through the default path (`Composed`: no fused formula) follow the
/// fused ones: 200 steps of h = 0.01, every τ, θ ∈ {0, ¼, ½, 1}, LP and EP, free body and heavy
/// top, and the right maps on the free body.
#[test]
fn theta_maps_through_the_default_path_follow_the_fused_steps() {
    fn gap<I: Integrator<Group = So3>, J: Integrator<Group = So3>>(mut i: I, mut j: J) -> f64 {
        for _ in 0..200 {
            i.step(0.01).unwrap();
            j.step(0.01).unwrap();
        }
        (i.velocity() - j.velocity())
            .amax()
            .max((i.momentum() - j.momentum()).amax() / PI0.norm())
            .max(
                i.configuration()
                    .unwrap()
                    .matrix_distance(j.configuration().unwrap()),
            )
    }
    fn each<T: Tau<So3>>() -> f64 {
        let mut worst = 0.0f64;
        for theta in [0.0, 0.25, 0.5, 1.0] {
            let left = DiscretizationMap::<T>::new(theta).unwrap();
            let right = RightDiscretizationMap::<T>::new(theta).unwrap();
            let gaps = [
                gap(lp(body(), left), lp(body(), Composed(left))),
                gap(lp(top(), left), lp(top(), Composed(left))),
                gap(ep(body(), left), ep(body(), Composed(left))),
                gap(ep(top(), left), ep(top(), Composed(left))),
                gap(lp(body(), right), lp(body(), Composed(right))),
                gap(ep(body(), right), ep(body(), Composed(right))),
            ];
            for (what, g) in [
                "LP free", "LP top", "EP free", "EP top", "right LP", "right EP",
            ]
            .iter()
            .zip(gaps)
            {
                assert!(
                    g < 1e-12,
                    "τ = {}, θ = {theta}, {what}: apart by {g:e}",
                    T::NAME
                );
                worst = worst.max(g);
            }
        }
        worst
    }
    let (e, c) = (each::<ExpMap>(), each::<Cayley>());
    println!("fused against composed integrators after 200 steps: exp {e:.1e}, cayley {c:.1e}");
}
