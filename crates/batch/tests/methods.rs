//! Every batched method against its scalar version in `integrators`, on random bodies in every
//! regime of the scalar tests, on every level this CPU runs.

mod common;

use batch::{Batch, BodyModel, Level, QuaternionRk4, Strang};
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
