//! Fitted orders of both members of each embedded pair on fixed steps: the RKMK pairs on SO(3)
//! (free body against the exact flow, heavy top) and SE(3), the (q, Π) baselines on SO(3). Each
//! within 0.2 of its design order (5 and 4 for Dormand–Prince; 8, 5 and 3 for DOP853 and its
//! two estimators).
//!
//! The truncation of (d^L exp)⁻¹ in the RKMK stages (powers of ad up to p − 2) is what keeps
//! order 5 and 8, and every kept term counts (negative controls, run by hand on all three
//! problems): without the ad² term the Dormand–Prince RKMK fits order 3.0, without the ad⁴
//! term DOP853 fits 5.0, without the ad⁶ term 7.0.

use crate::common::*;
use integrators::adaptive::{ButcherPair, RkmkPair};
use integrators::baselines::QuaternionPair;
use integrators::{EulerArnold, Integrator, System};
use lie_groups::{LieGroup, Se3, So3};
use mechanics::exact::FreeBodyFlow;
use mechanics::systems::{HeavyTop, RigidBody};
use nalgebra::{Matrix6, Vector3, Vector6};

const T: f64 = 4.0;

/// The member of a pair that a fixed step advances.
#[derive(Clone, Copy, Debug)]
enum Member {
    /// The solution the pair advances (weights b).
    Advanced,
    /// The embedded solution b − e.
    Embedded,
    /// DOP853's second estimator's solution b − e_low.
    Low,
}

/// A pair that can take a fixed step of each member.
trait Members: Integrator + Sized {
    fn member_step(&mut self, member: Member, h: f64);
}
impl<G: LieGroup, S: System<G>, P: ButcherPair<N>, const N: usize> Members
    for RkmkPair<G, S, P, N>
{
    fn member_step(&mut self, member: Member, h: f64) {
        match member {
            Member::Advanced => self.step(h).unwrap(),
            Member::Embedded => self.step_embedded(h, false).unwrap(),
            Member::Low => self.step_embedded(h, true).unwrap(),
        }
    }
}
impl<S: System<So3>, P: ButcherPair<N>, const N: usize> Members for QuaternionPair<S, P, N> {
    fn member_step(&mut self, member: Member, h: f64) {
        match member {
            Member::Advanced => self.step(h).unwrap(),
            Member::Embedded => self.step_embedded(h, false).unwrap(),
            Member::Low => self.step_embedded(h, true).unwrap(),
        }
    }
}

/// `max(‖g − g_ref‖_max, ‖μ − μ_ref‖_max / ‖μ_ref‖_max)`.
fn error<G: LieGroup>(g: &G, mu: &G::Algebra, reference: &(G, G::Algebra)) -> f64 {
    use lie_groups::Vector;
    g.matrix_distance(&reference.0)
        .max(mu.sub(&reference.1).norm_max() / reference.1.norm_max())
}

/// The fitted order of `member` over n steps of T/n for each n, against `reference`.
fn fitted<M: Members>(
    make: impl Fn() -> M,
    member: Member,
    ns: &[usize],
    reference: &(M::Group, <M::Group as LieGroup>::Algebra),
) -> (f64, f64) {
    let (mut hs, mut errs) = (vec![], vec![]);
    for &n in ns {
        let mut m = make();
        let h = T / n as f64;
        for _ in 0..n {
            m.member_step(member, h);
        }
        hs.push(h);
        errs.push(error(m.configuration().unwrap(), &m.momentum(), reference));
    }
    println!(
        "  errors {:?}",
        errs.iter().map(|e| format!("{e:.2e}")).collect::<Vec<_>>()
    );
    (fitted_order(&hs, &errs), errs[errs.len() - 1])
}

fn assert_near(label: &str, design: f64, (p, e): (f64, f64)) {
    println!("{label}: order {p:.3} (finest error {e:.2e})");
    assert!(
        (p - design).abs() < 0.2,
        "{label}: order {p:.3}, design {design}"
    );
}

/// Steps for each order: from where the error is asymptotic down to ~1e-11 (above round-off).
const COARSE: [usize; 4] = [20, 40, 80, 160];
const FINE: [usize; 4] = [12, 16, 24, 32];

fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

/// Every member of both pairs, RKMK and (q, Π), for one system on SO(3).
/// `ns5` and `ns8` are the steps of the order-5 and order-8 advanced solutions (the others use
/// [`COARSE`]), chosen per problem between the pre-asymptotic range and the round-off floor.
fn so3_orders<S: System<So3> + Clone>(
    label: &str,
    system: &S,
    (pi0, reference): (Vector3<f64>, &(So3, Vector3<f64>)),
    ns5: &[usize],
    ns8: &[usize],
) {
    use integrators::adaptive::{RkmkDop853, RkmkDopri5};
    use integrators::baselines::{QuaternionDop853, QuaternionDopri5};
    let g = Some(g0());
    let rk5 = || RkmkDopri5::new(system.clone(), pi0, g).unwrap();
    let rk8 = || RkmkDop853::new(system.clone(), pi0, g).unwrap();
    let q5 = || QuaternionDopri5::new(system.clone(), pi0, g).unwrap();
    let q8 = || QuaternionDop853::new(system.clone(), pi0, g).unwrap();
    assert_near(
        &format!("{label} rkmk-dopri5 b"),
        5.0,
        fitted(rk5, Member::Advanced, ns5, reference),
    );
    assert_near(
        &format!("{label} rkmk-dopri5 b̂"),
        4.0,
        fitted(rk5, Member::Embedded, &COARSE, reference),
    );
    assert_near(
        &format!("{label} rkmk-dop853 b"),
        8.0,
        fitted(rk8, Member::Advanced, ns8, reference),
    );
    assert_near(
        &format!("{label} rkmk-dop853 b − e₅"),
        5.0,
        fitted(rk8, Member::Embedded, &COARSE, reference),
    );
    assert_near(
        &format!("{label} rkmk-dop853 b − e₃"),
        3.0,
        fitted(rk8, Member::Low, &COARSE, reference),
    );
    assert_near(
        &format!("{label} dopri5(q) b"),
        5.0,
        fitted(q5, Member::Advanced, ns5, reference),
    );
    assert_near(
        &format!("{label} dopri5(q) b̂"),
        4.0,
        fitted(q5, Member::Embedded, &COARSE, reference),
    );
    assert_near(
        &format!("{label} dop853(q) b"),
        8.0,
        fitted(q8, Member::Advanced, ns8, reference),
    );
    assert_near(
        &format!("{label} dop853(q) b − e₅"),
        5.0,
        fitted(q8, Member::Embedded, &COARSE, reference),
    );
    assert_near(
        &format!("{label} dop853(q) b − e₃"),
        3.0,
        fitted(q8, Member::Low, &COARSE, reference),
    );
}

#[test]
fn pairs_fit_their_orders_on_the_free_body_against_the_exact_flow() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, -0.7);
    let (pi, r) = FreeBodyFlow::new(&body)
        .advance(T, &pi0, Some(&g0()))
        .unwrap();
    // DOP853 at T/32 is at the round-off floor here (1.6e-15): its steps stop at T/24.
    so3_orders(
        "free body",
        &body,
        (pi0, &(r.unwrap(), pi)),
        &COARSE,
        &[8, 12, 16, 24],
    );
}

#[test]
fn pairs_fit_their_orders_on_the_heavy_top() {
    let top = HeavyTop::principal([1.0, 1.5, 2.0], 1.0, 1.0, Vector3::new(0.1, -0.2, 0.6)).unwrap();
    let pi0 = Vector3::new(0.3, 0.8, 1.1);
    // Reference: DOP853 on (q, Π) at h = T/4000 (error ~1e-16); the RKMK DOP853 at the same
    // step, an independent discretization, agrees with it to round-off.
    let fine = |n: usize| {
        let mut q =
            integrators::baselines::QuaternionDop853::new(top.clone(), pi0, Some(g0())).unwrap();
        let mut r = integrators::adaptive::RkmkDop853::new(top.clone(), pi0, Some(g0())).unwrap();
        integrators::integrate(&mut q, T / n as f64, n, |_| {}).unwrap();
        integrators::integrate(&mut r, T / n as f64, n, |_| {}).unwrap();
        (
            (*q.configuration().unwrap(), q.momentum()),
            (*r.configuration().unwrap(), r.momentum()),
        )
    };
    let (reference, other) = fine(4000);
    let agree = error(&other.0, &other.1, &reference);
    println!("heavy top references (q, Π) vs RKMK DOP853: {agree:.1e}");
    assert!(agree < 1e-13);
    // Dormand–Prince on (q, Π) is pre-asymptotic at T/20 here (error ratios 47, 37, 34 from
    // T/20 to T/160): its steps start at T/40.
    so3_orders(
        "heavy top",
        &top,
        (pi0, &reference),
        &[40, 80, 160, 320],
        &FINE,
    );
}

/// The RKMK pairs are generic over the group: on SE(3) (a free body in space, Euler–Arnold)
/// against RKMK DOP853 at T/1000, which agrees with itself at T/2000 and with RKMK4 at T/10000
/// (an independent method) to the latter's error.
#[test]
fn rkmk_pairs_fit_their_orders_on_se3() {
    use integrators::adaptive::{RkmkDop853, RkmkDopri5};
    let inertia = Matrix6::from_diagonal(&Vector6::new(1.0, 2.0, 3.0, 2.0, 2.0, 2.0));
    let system = EulerArnold::<Se3>::new(inertia).unwrap();
    let mu0 = Vector6::new(0.4, -0.6, 0.9, 0.5, 0.2, -0.3);
    let g0 = Se3::exp(&Vector6::new(0.3, -0.5, 0.8, 1.0, 0.0, -0.5));
    let fine = |n: usize| {
        let mut m = RkmkDop853::new(system.clone(), mu0, Some(g0)).unwrap();
        integrators::integrate(&mut m, T / n as f64, n, |_| {}).unwrap();
        (*m.configuration().unwrap(), m.momentum())
    };
    // Few steps for the reference: each step rounds the translation once, and those roundings
    // add up (T/8000 was 7e-13 from T/4000, T/2000 6e-14).
    let reference = fine(1000);
    let refined = fine(2000);
    let own = error(&refined.0, &refined.1, &reference);
    let mut rk4 = integrators::Rkmk4::new(system.clone(), mu0, Some(g0)).unwrap();
    integrators::integrate(&mut rk4, T / 10000.0, 10000, |_| {}).unwrap();
    let agree = error(rk4.configuration().unwrap(), &rk4.momentum(), &reference);
    println!("SE(3) reference vs itself at T/2000: {own:.1e}, vs RKMK4 at T/10000: {agree:.1e}");
    assert!(own < 1e-13);
    // RKMK4's error at h = 4e-4 is ~1e-13, plus its 10⁴ roundings of the translation.
    assert!(agree < 2e-12);
    let rk5 = || RkmkDopri5::new(system.clone(), mu0, Some(g0)).unwrap();
    let rk8 = || RkmkDop853::new(system.clone(), mu0, Some(g0)).unwrap();
    assert_near(
        "SE(3) rkmk-dopri5 b",
        5.0,
        fitted(rk5, Member::Advanced, &COARSE, &reference),
    );
    assert_near(
        "SE(3) rkmk-dopri5 b̂",
        4.0,
        fitted(rk5, Member::Embedded, &COARSE, &reference),
    );
    // The reference is good to ~5e-14: DOP853's steps stop at T/16.
    assert_near(
        "SE(3) rkmk-dop853 b",
        8.0,
        fitted(rk8, Member::Advanced, &[6, 8, 12, 16], &reference),
    );
    assert_near(
        "SE(3) rkmk-dop853 b − e₅",
        5.0,
        fitted(rk8, Member::Embedded, &COARSE, &reference),
    );
    assert_near(
        "SE(3) rkmk-dop853 b − e₃",
        3.0,
        fitted(rk8, Member::Low, &COARSE, &reference),
    );
}
