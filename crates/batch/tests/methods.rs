//! Every batched method against its scalar version in `integrators`, on random bodies in every
//! regime of the scalar tests, on every level this CPU runs.

mod common;

use batch::{Batch, BodyModel, ExactFlow, Level, QuaternionRk4, Rkmk4, Strang};
use common::{bodies, entries, near_separatrix, state, tops, ulps_of};
use integrators::splitting::Splitting;
use integrators::{Composition, CompositionScheme, Integrator};
use lie_groups::So3;
use nalgebra::Vector3;

/// 37 bodies (four full groups and a partial one) of one model.
const N: usize = 37;

/// The batched RK4 is the scalar `QuaternionRk4` bit for bit: momentum and attitude after 300
/// steps, for free bodies and heavy tops, |Π| from 1e-100 to 5 (h|Ω| up to 0.25), on every level.
#[test]
fn rk4_lanes_are_the_scalar_quaternion_rk4() {
    let h = 0.005;
    for level in Level::available() {
        for (k, (body, top)) in bodies().iter().zip(tops()).enumerate() {
            for radius in [1e-100, 1e-3, 1.0, 5.0] {
                let states: Vec<_> = (0..N as u64).map(|i| state(radius, k as u64, i)).collect();
                let pis: Vec<_> = states.iter().map(|s| s.0).collect();
                let rs: Vec<_> = states.iter().map(|s| s.1).collect();
                for field in [false, true] {
                    let model = if field {
                        BodyModel::heavy_top(&top).unwrap()
                    } else {
                        BodyModel::free(body).unwrap()
                    };
                    let mut b = Batch::new(QuaternionRk4::new(model), &pis, &rs, level).unwrap();
                    b.run(h, 300).unwrap();
                    for i in 0..N {
                        let (pi, r) = if field {
                            let mut s =
                                integrators::QuaternionRk4::new(top.clone(), pis[i], Some(rs[i]))
                                    .unwrap();
                            integrators::integrate(&mut s, h, 300, |_| {}).unwrap();
                            (s.momentum(), *s.configuration().unwrap())
                        } else {
                            let mut s =
                                integrators::QuaternionRk4::new(body.clone(), pis[i], Some(rs[i]))
                                    .unwrap();
                            integrators::integrate(&mut s, h, 300, |_| {}).unwrap();
                            (s.momentum(), *s.configuration().unwrap())
                        };
                        let (bpi, br) = b.state(i).unwrap();
                        assert_eq!(
                            bpi.map(f64::to_bits),
                            pi.map(f64::to_bits),
                            "{level} body {k} |Π| {radius:e} field {field} lane {i}"
                        );
                        assert_eq!(
                            br.as_matrix().map(f64::to_bits),
                            r.as_matrix().map(f64::to_bits)
                        );
                    }
                }
            }
        }
    }
}

/// After `steps` Strang steps from N states of body k: the largest difference between the batch
/// and the scalar `Splitting` (optionally composed), in ulps of |Π| (momentum) and of 1
/// (attitude), and the largest difference between the scalar run and the scalar run from Π₀
/// perturbed by one ulp (how much the problem itself amplifies round-off), in the same units.
#[allow(clippy::too_many_arguments)]
fn strang_gap(
    level: Level,
    field: bool,
    pis: &[Vector3<f64>],
    rs: &[So3],
    h: f64,
    steps: u64,
    composition: Option<CompositionScheme>,
    k: usize,
) -> [f64; 4] {
    let (body, top) = (&bodies()[k], &tops()[k]);
    let model = if field {
        BodyModel::heavy_top(top).unwrap()
    } else {
        BodyModel::free(body).unwrap()
    };
    let mut b = Batch::new(Strang::new(model), pis, rs, level).unwrap();
    if let Some(c) = &composition {
        b = b.with_composition(c.clone()).unwrap();
    }
    b.run(h, steps).unwrap();
    let scalar = |pi0: Vector3<f64>, r0: So3| {
        let run = |s: &mut dyn Integrator<Group = So3>| {
            for _ in 0..steps {
                s.step(h).unwrap();
            }
            (s.momentum(), *s.configuration().unwrap())
        };
        match (field, &composition) {
            (false, None) => run(&mut Splitting::new(body.clone(), pi0, Some(r0)).unwrap()),
            (true, None) => run(&mut Splitting::new(top.clone(), pi0, Some(r0)).unwrap()),
            (false, Some(c)) => run(&mut Composition::new(
                Splitting::new(body.clone(), pi0, Some(r0)).unwrap(),
                c.clone(),
            )
            .unwrap()),
            (true, Some(c)) => run(&mut Composition::new(
                Splitting::new(top.clone(), pi0, Some(r0)).unwrap(),
                c.clone(),
            )
            .unwrap()),
        }
    };
    let mut worst = [0.0f64; 4];
    for i in 0..pis.len() {
        let (pi, r) = scalar(pis[i], rs[i]);
        let (ppi, pr) = scalar(pis[i] * (1.0 + f64::EPSILON), rs[i]);
        let (bpi, br) = b.state(i).unwrap();
        let gaps = [
            ulps_of(bpi.as_slice(), pi.as_slice(), pi.norm()),
            ulps_of(&entries(&br), &entries(&r), 1.0),
            ulps_of(ppi.as_slice(), pi.as_slice(), pi.norm()),
            ulps_of(&entries(&pr), &entries(&r), 1.0),
        ];
        for (w, g) in worst.iter_mut().zip(gaps) {
            *w = w.max(g);
        }
    }
    worst
}

/// One Strang step of the batch is the scalar step to a few ulps times the step's largest
/// rotation angle θ (the lanes' own sin/cos and fused multiply-adds round differently, and a
/// rotation by θ turns an ulp of Π into θ ulps of the result): within `4 (1 + θ)` ulps (measured 2.9), for free
/// bodies and heavy tops in every regime of `common::MOMENTS`, |Π| from 1e-150 to 1e3 (angles
/// up to 100 rad: the lanes' reduction and the general Rodrigues branch), and near the
/// separatrix.
#[test]
fn strang_step_matches_the_scalar_splitting() {
    let level = Level::detect();
    let mut worst = 0.0f64;
    let mut worst_small = 0.0f64;
    for (k, body) in bodies().iter().enumerate() {
        let inv_max = body
            .principal_frame()
            .1
            .iter()
            .map(|m| 1.0 / m)
            .fold(0.0, f64::max);
        let mut check = |g: [f64; 4], theta: f64| {
            let u = g[0].max(g[1]);
            worst = worst.max(u / (1.0 + theta));
            if theta <= 1.0 {
                worst_small = worst_small.max(u);
            }
        };
        for (radius, h) in [
            (1e-150, 0.1),
            (1e-3, 0.1),
            (1.0, 0.01),
            (1.0, 0.3),
            (1e3, 0.01),
        ] {
            let states: Vec<_> = (0..N as u64)
                .map(|i| state(radius, 7 + k as u64, i))
                .collect();
            let pis: Vec<_> = states.iter().map(|s| s.0).collect();
            let rs: Vec<_> = states.iter().map(|s| s.1).collect();
            for field in [false, true] {
                check(
                    strang_gap(level, field, &pis, &rs, h, 1, None, k),
                    h * radius * inv_max,
                );
            }
        }
        // near the separatrix (free body; a symmetric body has none)
        let sep: Vec<_> = (0..N as u64)
            .map(|i| near_separatrix(body, 1e-10, k as u64, i))
            .collect();
        let rs: Vec<_> = (0..N as u64).map(|i| state(1.0, 3, i).1).collect();
        let theta = 0.05 * sep.iter().map(|p| p.norm()).fold(0.0, f64::max) * inv_max;
        check(strang_gap(level, false, &sep, &rs, 0.05, 1, None, k), theta);
    }
    println!(
        "one Strang step: worst ulps / (1 + θ) = {worst:.2}; worst ulps where θ ≤ 1: {worst_small:.2}"
    );
    assert!(worst <= 4.0, "{worst}");
}

/// Over 1000 steps (with the merged closing and opening flows and three renormalizations) and
/// under a composition (Kahan–Li order 6), the batch follows the scalar trajectory as closely as
/// the scalar trajectory follows itself from Π₀ moved by one ulp: the gap stays below 16 times
/// that amplification of round-off plus 64 ulps.
#[test]
fn strang_trajectories_and_compositions_follow_the_scalar_ones() {
    let level = Level::detect();
    let states: Vec<_> = (0..N as u64).map(|i| state(1.0, 11, i)).collect();
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    for k in [0, 1, 2, 6] {
        for field in [false, true] {
            for (h, steps, c) in [
                (0.01, 1000, None),
                (0.05, 100, Some(CompositionScheme::kahan_li_6())),
            ] {
                let g = strang_gap(level, field, &pis, &rs, h, steps, c, k);
                println!("body {k} field {field} steps {steps}: {g:?}");
                assert!(
                    g[0] <= 16.0 * g[2] + 64.0 && g[1] <= 16.0 * g[3] + 64.0,
                    "body {k} field {field} steps {steps}: {g:?} ulps"
                );
            }
        }
    }
}

/// A body's momentum Π and attitude R.
type BodyState = (Vector3<f64>, So3);

/// (Π, R) of the scalar `integrators::Rkmk4` after `steps` steps of h from (Π₀, R₀), for body k
/// of `common::MOMENTS`, free or in a field.
fn scalar_rkmk4(
    field: bool,
    k: usize,
    pi0: Vector3<f64>,
    r0: So3,
    h: f64,
    steps: u64,
) -> (Vector3<f64>, So3) {
    let run = |s: &mut dyn Integrator<Group = So3>| {
        for _ in 0..steps {
            s.step(h).unwrap();
        }
        (s.momentum(), *s.configuration().unwrap())
    };
    if field {
        run(&mut integrators::Rkmk4::new(tops()[k].clone(), pi0, Some(r0)).unwrap())
    } else {
        run(&mut integrators::Rkmk4::new(bodies()[k].clone(), pi0, Some(r0)).unwrap())
    }
}

fn rkmk4_model(field: bool, k: usize) -> BodyModel {
    if field {
        BodyModel::heavy_top(&tops()[k]).unwrap()
    } else {
        BodyModel::free(&bodies()[k]).unwrap()
    }
}

/// The batched RKMK4 is the scalar `Rkmk4` bit for bit wherever a step's rotations stay within
/// π/2: momentum and attitude after 1100 steps (one renormalization, at step 1024), for free
/// bodies and heavy tops over every body of `common::MOMENTS` (symmetric ones included), |Π|
/// from 1e-100 to 5 (h|Ω| up to 0.25: `exp`'s Taylor branch and its half-angle branch), and
/// free bodies within 1e-10 of the separatrix, on every level.
#[test]
fn rkmk4_lanes_are_the_scalar_rkmk4() {
    let (h, steps) = (0.005, 1100);
    for level in Level::available() {
        for k in 0..bodies().len() {
            // (in a field, the bodies' states)
            let mut cases: Vec<(bool, Vec<BodyState>)> = Vec::new();
            for radius in [1e-100, 1e-3, 1.0, 5.0] {
                let states: Vec<_> = (0..N as u64).map(|i| state(radius, k as u64, i)).collect();
                cases.push((false, states.clone()));
                cases.push((true, states));
            }
            let sep = (0..N as u64)
                .map(|i| {
                    (
                        near_separatrix(&bodies()[k], 1e-10, k as u64, i),
                        state(1.0, 3, i).1,
                    )
                })
                .collect();
            cases.push((false, sep));
            for (field, states) in cases {
                let pis: Vec<_> = states.iter().map(|s| s.0).collect();
                let rs: Vec<_> = states.iter().map(|s| s.1).collect();
                let mut b =
                    Batch::new(Rkmk4::new(rkmk4_model(field, k)), &pis, &rs, level).unwrap();
                b.run(h, steps).unwrap();
                for i in 0..N {
                    let (pi, r) = scalar_rkmk4(field, k, pis[i], rs[i], h, steps);
                    let (bpi, br) = b.state(i).unwrap();
                    let what = format!(
                        "{level} body {k} |Π| {:e} field {field} lane {i}",
                        pis[i].norm()
                    );
                    assert_eq!(bpi.map(f64::to_bits), pi.map(f64::to_bits), "{what}");
                    assert_eq!(
                        br.as_matrix().map(f64::to_bits),
                        r.as_matrix().map(f64::to_bits),
                        "{what}"
                    );
                }
            }
        }
    }
}

/// Beyond a rotation of π/2 in one step the lanes take sin and cos of θ/2 from their own
/// reduction ([`batch::trig`]) where the scalar `So3::exp` takes its quadrant kernels or libm:
/// one step whose largest rotation h|Ω|_max is 2, 3 or 6 rad, from |Π| = 1 and 1000, stays within
/// 8 ulps of the scalar step in Π (of |Π|) and R (of 1), free and (from |Π| = 1000) in a field,
/// over every body of `common::MOMENTS`. Measured, not hard-coded: the worst gap is printed.
#[test]
fn rkmk4_beyond_a_quarter_turn_is_the_scalar_step_to_a_few_ulps() {
    let level = Level::detect();
    let mut worst = [0.0f64; 2];
    let mut exact = 0usize;
    for (k, body) in bodies().iter().enumerate() {
        let inv_max = body
            .principal_frame()
            .1
            .iter()
            .map(|m| 1.0 / m)
            .fold(0.0, f64::max);
        for (radius, angle) in [(1.0, 2.0), (1.0, 3.0), (1e3, 3.0), (1e3, 6.0)] {
            let h = angle / (radius * inv_max);
            let states: Vec<_> = (0..N as u64)
                .map(|i| state(radius, 40 + k as u64, i))
                .collect();
            let pis: Vec<_> = states.iter().map(|s| s.0).collect();
            let rs: Vec<_> = states.iter().map(|s| s.1).collect();
            // In the field only where the step resolves the pendulum (h ω_p ≤ 0.02 at
            // |Π| = 1000): at |Π| = 1 these steps last seconds, several pendulum periods, and
            // the stages amplify an ulp of a stage attitude by (h ω_p)² and more.
            for field in [false, true].into_iter().filter(|&f| !f || radius > 1.0) {
                let mut b =
                    Batch::new(Rkmk4::new(rkmk4_model(field, k)), &pis, &rs, level).unwrap();
                b.step(h).unwrap();
                for i in 0..N {
                    let (pi, r) = scalar_rkmk4(field, k, pis[i], rs[i], h, 1);
                    let (bpi, br) = b.state(i).unwrap();
                    let g = [
                        ulps_of(bpi.as_slice(), pi.as_slice(), pi.norm()),
                        ulps_of(&entries(&br), &entries(&r), 1.0),
                    ];
                    exact += (g == [0.0, 0.0]) as usize;
                    worst[0] = worst[0].max(g[0]);
                    worst[1] = worst[1].max(g[1]);
                }
            }
        }
    }
    println!(
        "RKMK4 beyond π/2: worst {worst:?} ulps (Π of |Π|, R of 1); {exact} lanes bit for bit"
    );
    assert!(worst[0] <= 8.0 && worst[1] <= 8.0, "{worst:?}");
}

/// Over 10⁶ RKMK4 steps of eight free bodies (h = 0.01, |Π| = 1, random attitudes) the lanes
/// stay the scalar `Rkmk4`'s bit for bit, and R stays on SO(3) to 1e-14 (renormalized every
/// 1024 steps, as the scalar method). |Π| is not kept by the method (RK4 on Π: its error,
/// O(h⁴) per unit time, is printed with the rest), so it is not held to round-off here.
#[test]
fn rkmk4_stays_on_so3_and_with_the_scalar_method_over_a_million_steps() {
    let k = 1;
    let (h, steps) = (0.01, 1_000_000);
    let states: Vec<_> = (0..8u64).map(|i| state(1.0, 21, i)).collect();
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let mut b = Batch::new(
        Rkmk4::new(rkmk4_model(false, k)),
        &pis,
        &rs,
        Level::detect(),
    )
    .unwrap();
    b.run(h, steps).unwrap();
    let (mut d_orth, mut d_norm) = (0.0f64, 0.0f64);
    for i in 0..8 {
        let (pi, r) = scalar_rkmk4(false, k, pis[i], rs[i], h, steps);
        let (bpi, br) = b.state(i).unwrap();
        assert_eq!(bpi.map(f64::to_bits), pi.map(f64::to_bits), "lane {i}");
        assert_eq!(
            br.as_matrix().map(f64::to_bits),
            r.as_matrix().map(f64::to_bits),
            "lane {i}"
        );
        let m = br.as_matrix();
        d_orth = d_orth.max((m.transpose() * m - nalgebra::Matrix3::identity()).amax());
        d_norm = d_norm.max((bpi.norm() - pis[i].norm()).abs());
    }
    println!("10⁶ RKMK4 steps: RᵀR − I {d_orth:e}, |Π| − |Π₀| {d_norm:e}");
    assert!(d_orth < 1e-14, "{d_orth:e}");
}

/// (Π, R) of the scalar `mechanics::exact::ExactFreeBody` of body k after `steps` steps of h from
/// (Π₀, R₀); `None` where a step fails.
fn scalar_exact(k: usize, pi0: Vector3<f64>, r0: So3, h: f64, steps: u64) -> Option<BodyState> {
    let mut s = mechanics::exact::ExactFreeBody::new(bodies()[k].clone(), pi0, Some(r0)).ok()?;
    for _ in 0..steps {
        s.step(h).ok()?;
    }
    Some((s.momentum(), *s.configuration().unwrap()))
}

/// The batched exact flow of body k against the scalar `ExactFreeBody` after `steps` steps of h:
/// the largest differences in ulps of |Π| (Π) and of 1 (R), the same between the scalar run and
/// the scalar run from Π₀ scaled by 1 + ε (the problem's own amplification of an ulp), and the
/// number of bodies whose bits are the scalar's.
fn exact_gap(
    level: Level,
    k: usize,
    pis: &[Vector3<f64>],
    rs: &[So3],
    h: f64,
    steps: u64,
) -> ([f64; 4], usize) {
    let model = BodyModel::free(&bodies()[k]).unwrap();
    let mut b = Batch::new(ExactFlow::new(model).unwrap(), pis, rs, level).unwrap();
    b.run(h, steps).unwrap();
    let mut worst = [0.0f64; 4];
    let mut same = 0;
    for i in 0..pis.len() {
        let (pi, r) = scalar_exact(k, pis[i], rs[i], h, steps).unwrap();
        let (ppi, pr) = scalar_exact(k, pis[i] * (1.0 + f64::EPSILON), rs[i], h, steps).unwrap();
        assert_eq!(b.status(i).unwrap(), batch::LaneStatus::Running);
        let (bpi, br) = b.state(i).unwrap();
        same += (bpi == pi && br.as_matrix() == r.as_matrix()) as usize;
        let gaps = [
            ulps_of(bpi.as_slice(), pi.as_slice(), pi.norm()),
            ulps_of(&entries(&br), &entries(&r), 1.0),
            ulps_of(ppi.as_slice(), pi.as_slice(), pi.norm()),
            ulps_of(&entries(&pr), &entries(&r), 1.0),
        ];
        for (w, g) in worst.iter_mut().zip(gaps) {
            *w = w.max(g);
        }
    }
    (worst, same)
}

/// The batched exact flow follows the scalar `ExactFreeBody` to a few ulps: Π within 3 ulps of
/// |Π|, R within 8 ulps of 1 (measured 1.62 and 6.75; the scalar run from Π₀(1 + ε) is 1.2 to
/// 10¹⁴ ulps away from the one from Π₀, the problem's own spread, printed with the gaps), and
/// about four bodies in five bit for bit, in every regime of `common::MOMENTS` (generic, nearly symmetric, symmetric
/// either side — the scalar path, bit for bit —, flat, widely spread), |Π| from 1e-150 to 1e150,
/// near the separatrix (10⁻⁴, 10⁻¹⁰ and 10⁻¹⁵ relative), and long times (steps of 10⁴ and of 10⁹
/// — precession angles beyond the lanes' 2²⁸ rad, the scalar path for those steps — to t|Π|/I
/// of 10¹⁴, near the phase limit 2⁵²).
#[test]
fn exact_lanes_follow_the_scalar_exact_flow() {
    let level = Level::detect();
    let mut worst = [0.0f64; 2];
    let (mut same, mut total) = (0, 0);
    let mut check = |what: String, (g, n): ([f64; 4], usize), count: usize| {
        println!("{what}: {g:?} (Π, R; the spread's Π, R), {n}/{count} bit for bit");
        worst[0] = worst[0].max(g[0]);
        worst[1] = worst[1].max(g[1]);
        same += n;
        total += count;
    };
    for k in 0..bodies().len() {
        for radius in [1e-150, 1e-3, 1.0, 1e3, 1e150] {
            let states: Vec<_> = (0..N as u64)
                .map(|i| state(radius, 31 + k as u64, i))
                .collect();
            let pis: Vec<_> = states.iter().map(|s| s.0).collect();
            let rs: Vec<_> = states.iter().map(|s| s.1).collect();
            let h = 0.02 / radius;
            check(
                format!("body {k} |Π| {radius:e}"),
                exact_gap(level, k, &pis, &rs, h, 100),
                N,
            );
        }
        let rs: Vec<_> = (0..N as u64).map(|i| state(1.0, 3, i).1).collect();
        if ![2, 3].contains(&k) {
            for gap in [1e-4, 1e-10, 1e-15] {
                let sep: Vec<_> = (0..N as u64)
                    .map(|i| near_separatrix(&bodies()[k], gap, k as u64, i))
                    .collect();
                check(
                    format!("body {k} separatrix {gap:e}"),
                    exact_gap(level, k, &sep, &rs, 0.05, 100),
                    N,
                );
            }
        }
        let pis: Vec<_> = (0..N as u64).map(|i| state(1.0, 41, i).0).collect();
        for (h, steps) in [(1e4, 20), (1e9, 5), (1e13, 3)] {
            check(
                format!("body {k} steps of {h:e}"),
                exact_gap(level, k, &pis, &rs, h, steps),
                N,
            );
        }
    }
    println!(
        "exact flow: worst Π {:.2} ulps of |Π|, R {:.2} ulps; {same}/{total} bit for bit",
        worst[0], worst[1]
    );
    assert!(worst[0] <= 3.0 && worst[1] <= 8.0, "{worst:?}");
}

/// Over 10⁶ steps of h = 0.01 of eight bodies (|Π| = 1, random attitudes, body 1 of
/// `common::MOMENTS`) the batched exact flow keeps |Π|², the energy (monitored at every step) and
/// the spatial momentum RΠ (checked every 10⁵ steps) at round-off — measured 8.9e-16, 1.1e-15
/// and 5.6e-16 relative, bound 1.5e-15; the scalar `ExactFreeBody` keeps them within 9e-16 —:
/// every value comes from the orbit's constants, evaluated at the compensated elapsed time, so
/// nothing accumulates; and after 10⁶ steps the lanes are the scalar integrator to an ulp
/// (measured 0.5 and 0.25; bound 4).
#[test]
fn exact_lanes_keep_the_invariants_over_a_million_steps() {
    let k = 1;
    let states: Vec<_> = (0..8u64).map(|i| state(1.0, 21, i)).collect();
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let model = BodyModel::free(&bodies()[k]).unwrap();
    let mut b = Batch::new(ExactFlow::new(model).unwrap(), &pis, &rs, Level::detect())
        .unwrap()
        .monitor_every(1);
    let spatial0: Vec<_> = (0..8).map(|i| rs[i].as_matrix() * pis[i]).collect();
    let mut d_spatial = 0.0f64;
    for _ in 0..10 {
        b.run(0.01, 100_000).unwrap();
        for i in 0..8 {
            let (pi, r) = b.state(i).unwrap();
            d_spatial = d_spatial.max((r.as_matrix() * pi - spatial0[i]).amax() / pis[i].norm());
        }
    }
    let sums = b.summaries(|i| i);
    let (mut d_energy, mut d_casimir) = (0.0f64, 0.0f64);
    for (i, s) in sums.iter().enumerate() {
        assert_eq!((s.steps, s.time), (1_000_000, 10_000.0));
        d_energy = d_energy.max(s.max_energy_error / s.initial_energy);
        d_casimir = d_casimir.max(s.max_casimir_error.unwrap() / pis[i].norm_squared());
    }
    let mut gap = [0.0f64; 2];
    for i in 0..8 {
        let (pi, r) = scalar_exact(k, pis[i], rs[i], 0.01, 1_000_000).unwrap();
        let (bpi, br) = b.state(i).unwrap();
        gap[0] = gap[0].max(ulps_of(bpi.as_slice(), pi.as_slice(), pi.norm()));
        gap[1] = gap[1].max(ulps_of(&entries(&br), &entries(&r), 1.0));
    }
    println!(
        "10⁶ exact steps: |Π|² {d_casimir:e}, energy {d_energy:e}, RΠ {d_spatial:e} relative; against the scalar: {gap:?} ulps"
    );
    assert!(d_casimir < 1.5e-15 && d_energy < 1.5e-15 && d_spatial < 1.5e-15);
    assert!(gap[0] <= 4.0 && gap[1] <= 4.0, "{gap:?}");
}

/// At the phase limit: a step that takes |t|·|Π|/I_min to 2⁵² rad or beyond fails the body (its
/// last state kept), as the scalar `ExactFreeBody`'s first step fails there; just below it the
/// body runs and is the scalar's bits (a precession angle far beyond 2²⁸ rad: the scalar path).
#[test]
fn exact_lanes_fail_at_the_phase_limit_as_the_scalar_step() {
    let k = 0; // I_min = 1, |Π| = 1: the phase is t
    let (pis, rs): (Vec<_>, Vec<_>) = (0..N as u64).map(|i| state(1.0, 51, i)).unzip();
    let model = BodyModel::free(&bodies()[k]).unwrap();
    for level in Level::available() {
        let mut b = Batch::new(ExactFlow::new(model.clone()).unwrap(), &pis, &rs, level).unwrap();
        b.step(4.4e15).unwrap();
        for i in 0..N {
            assert_eq!(
                b.status(i).unwrap(),
                batch::LaneStatus::Running,
                "{level} {i}"
            );
            let (pi, r) = scalar_exact(k, pis[i], rs[i], 4.4e15, 1).unwrap();
            let (bpi, br) = b.state(i).unwrap();
            assert_eq!((bpi, *br.as_matrix()), (pi, *r.as_matrix()), "{level} {i}");
        }
        let mut b = Batch::new(ExactFlow::new(model.clone()).unwrap(), &pis, &rs, level).unwrap();
        b.step(4.6e15).unwrap();
        for i in 0..N {
            assert!(scalar_exact(k, pis[i], rs[i], 4.6e15, 1).is_none());
            assert_eq!(b.status(i).unwrap(), batch::LaneStatus::Failed { step: 0 });
            assert_eq!(b.momentum(i).unwrap(), pis[i]);
        }
        // a flat body (I_min = 10⁻⁸): the phase limit comes at t ≈ 4.5·10⁷, where the precession
        // angle is still within the lanes' sine range
        let flat = mechanics::RigidBody::principal([1e-8, 1.0, 2.0]).unwrap();
        let kernel = ExactFlow::new(BodyModel::free(&flat).unwrap()).unwrap();
        for (h, runs) in [(4.4e7, true), (4.6e7, false)] {
            let mut b = Batch::new(kernel.clone(), &pis, &rs, level).unwrap();
            b.step(h).unwrap();
            for i in 0..N {
                let mut s = mechanics::exact::ExactFreeBody::new(flat.clone(), pis[i], Some(rs[i]))
                    .unwrap();
                assert_eq!(s.step(h).is_ok(), runs, "{level} h {h:e} body {i}");
                let want = if runs {
                    batch::LaneStatus::Running
                } else {
                    batch::LaneStatus::Failed { step: 0 }
                };
                assert_eq!(b.status(i).unwrap(), want, "{level} h {h:e} body {i}");
            }
        }
    }
}
