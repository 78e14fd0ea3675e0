//! What a batch promises whatever the arithmetic: a body's bits do not depend on its lane, the
//! batch size, the level or the threads; a bad body fails alone; bad input is a clear error;
//! the splitting keeps its invariants at round-off over long runs.

mod common;

use batch::{
    Batch, BatchError, BodyModel, ExactFlow, Kernel, LaneStatus, Level, QuaternionRk4, Rkmk4,
    Strang,
};
use common::{bodies, near_separatrix, state, tops};
use integrators::ensemble::{Execution, Status};
use integrators::CompositionScheme;
use lie_groups::{LieGroup, So3};
use nalgebra::Vector3;

const STEPS: u64 = 40;
const H: f64 = 0.02;

/// The bits of every body's (Π, R) after `STEPS` steps of `kernel` from the given states.
fn run<K: Kernel>(
    kernel: &K,
    pis: &[Vector3<f64>],
    rs: &[So3],
    level: Level,
    execution: Execution,
) -> Vec<[u64; 12]> {
    let mut b = Batch::new(kernel.clone(), pis, rs, level)
        .unwrap()
        .parallel(execution);
    b.run(H, STEPS).unwrap();
    (0..pis.len())
        .map(|i| {
            let (pi, r) = b.state(i).unwrap();
            let m = r.as_matrix();
            core::array::from_fn(|k| {
                if k < 3 {
                    pi[k].to_bits()
                } else {
                    m[((k - 3) / 3, (k - 3) % 3)].to_bits()
                }
            })
        })
        .collect()
}

/// `v` rotated left by three places.
fn rot<T: Clone>(v: &[T]) -> Vec<T> {
    [&v[3..], &v[..3]].concat()
}

fn same_bits_everywhere<K: Kernel>(kernel: K, what: &str) {
    let n = 1000;
    let states: Vec<_> = (0..n as u64).map(|i| state(1.5, 5, i)).collect();
    same_bits_for(kernel, what, states);
}

fn same_bits_for<K: Kernel>(kernel: K, what: &str, states: Vec<(Vector3<f64>, So3)>) {
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let reference = run(&kernel, &pis, &rs, Level::Scalar, Execution::Sequential);
    for level in Level::available() {
        // the whole batch, sequential and on the rayon pool
        for execution in [Execution::Sequential, Execution::Parallel] {
            let got = run(&kernel, &pis, &rs, level, execution);
            assert!(
                got == reference,
                "{what} {level} {execution:?}: 1000 bodies"
            );
        }
        // sizes 1, 3 and 8 from several starts: each body in other lanes and other groups
        for size in [1usize, 3, 8] {
            for start in [0usize, 1, 5, 13, 990] {
                let got = run(
                    &kernel,
                    &pis[start..start + size],
                    &rs[start..start + size],
                    level,
                    Execution::Sequential,
                );
                assert!(
                    got[..] == reference[start..start + size],
                    "{what} {level}: {size} bodies from {start}"
                );
            }
        }
        // the 1000 bodies rotated by three places: every body in another lane
        let got = run(&kernel, &rot(&pis), &rot(&rs), level, Execution::Sequential);
        assert!(got == rot(&reference), "{what} {level}: rotated lanes");
    }
}

/// A body's bits are the same whatever its lane, the batch size (1, 3, 8, 1000), the level and
/// sequential or threaded stepping: Strang, RK4 and RKMK4, free and in a field.
#[test]
fn a_body_has_the_same_bits_in_every_lane_size_level_and_thread_count() {
    let free = BodyModel::free(&bodies()[0]).unwrap();
    let field = BodyModel::heavy_top(&tops()[1]).unwrap();
    same_bits_everywhere(Strang::new(free.clone()), "Strang free");
    same_bits_everywhere(Strang::new(field.clone()), "Strang field");
    same_bits_everywhere(QuaternionRk4::new(free.clone()), "RK4 free");
    same_bits_everywhere(QuaternionRk4::new(field.clone()), "RK4 field");
    same_bits_everywhere(Rkmk4::new(free.clone()), "RKMK4 free");
    same_bits_everywhere(Rkmk4::new(field), "RKMK4 field");
    same_bits_everywhere(ExactFlow::new(free).unwrap(), "exact");
}

/// A Strang body keeps its bits next to bodies whose steps turn them by any angle: |Π| from 10⁻³
/// to 200 side by side (turns and Rodrigues half angles within the short kernels' range, within
/// π/4, and beyond it: the reduction and the general Rodrigues path), free and in a field.
#[test]
fn a_strang_body_has_the_same_bits_next_to_bodies_turning_by_any_angle() {
    let radii = [1.5, 20.0, 200.0, 1e-3, 5.0];
    let states: Vec<_> = (0..1000u64)
        .map(|i| state(radii[i as usize % radii.len()], 5, i))
        .collect();
    let free = BodyModel::free(&bodies()[0]).unwrap();
    let field = BodyModel::heavy_top(&tops()[1]).unwrap();
    same_bits_for(Strang::new(free), "Strang free, any angle", states.clone());
    same_bits_for(Strang::new(field), "Strang field, any angle", states);
}

/// The batched exact flow's bodies of every kind side by side — generic orbits (the lanes),
/// bodies at rest, steady rotations about an axis, states on the separatrix in exact arithmetic
/// (k' = 0: the scalar path), an ulp off it and near it — keep their bits whatever their lane,
/// the batch size, the level and the threads; and so do the bodies of an axisymmetric body (all
/// on the scalar path).
#[test]
fn exact_bodies_of_every_kind_have_the_same_bits_everywhere() {
    // 𝕀 = (1, 3, 6): I₃(I₂ − I₁) = 4 I₁(I₃ − I₂), so Π = (a, b, 2a) is on the separatrix exactly.
    let body = mechanics::RigidBody::principal([1.0, 3.0, 6.0]).unwrap();
    let states: Vec<_> = (0..1000u64)
        .map(|i| {
            let (pi, r) = state(1.5, 5, i);
            let pi = match i % 9 {
                1 => Vector3::zeros(),
                2 => Vector3::new(0.0, -1.2, 0.0),
                3 => Vector3::new(0.7, 0.0, 0.0),
                4 => Vector3::new(pi.x, pi.y, 2.0 * pi.x),
                5 => Vector3::new(pi.x, pi.y, 2.0 * pi.x * (1.0 + f64::EPSILON)),
                6 => near_separatrix(&body, 1e-9, 13, i),
                _ => pi,
            };
            (pi, r)
        })
        .collect();
    let exact = |b: &mechanics::RigidBody| ExactFlow::new(BodyModel::free(b).unwrap()).unwrap();
    same_bits_for(exact(&body), "exact, every kind", states.clone());
    same_bits_for(exact(&bodies()[2]), "exact, axisymmetric", states.clone());
    // the bodies at rest, the steady rotations and the states on the separatrix are the scalar
    // `ExactFreeBody`'s bits (the scalar path, or (Π₀, R₀) kept)
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let mut b = Batch::new(exact(&body), &pis, &rs, Level::detect()).unwrap();
    b.run(H, STEPS).unwrap();
    for i in (0..1000).filter(|i| (1..=4).contains(&(i % 9))) {
        let mut s =
            mechanics::exact::ExactFreeBody::new(body.clone(), pis[i], Some(rs[i])).unwrap();
        for _ in 0..STEPS {
            integrators::Integrator::step(&mut s, H).unwrap();
        }
        let (pi, r) = b.state(i).unwrap();
        assert_eq!(pi, integrators::Integrator::momentum(&s), "body {i}");
        assert_eq!(
            r.as_matrix(),
            integrators::Integrator::configuration(&s)
                .unwrap()
                .as_matrix(),
            "body {i}"
        );
    }
}

fn fails_alone<K: Kernel>(kernel: K, what: &str) {
    let n = 16;
    let states: Vec<_> = (0..n as u64).map(|i| state(1.0, 9, i)).collect();
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let clean = run(&kernel, &pis, &rs, Level::detect(), Execution::Sequential);
    // body 5 starts with a NaN; body 10 overflows in its first step (RK4, RKMK4: Π × Ω), or turns by
    // more than 2²⁸ rad (Strang), or beyond the exact flow's phase limit of 2⁵² rad
    let mut bad = pis.clone();
    bad[5][1] = f64::NAN;
    bad[10] = Vector3::new(3e200, -1e200, 2e200);
    let mut b = Batch::new(kernel.clone(), &bad, &rs, Level::detect()).unwrap();
    b.run(H, STEPS).unwrap();
    assert_eq!(b.status(5).unwrap(), LaneStatus::Invalid, "{what}");
    assert_eq!(
        b.status(10).unwrap(),
        LaneStatus::Failed { step: 0 },
        "{what}"
    );
    // the failed body keeps its last finite state
    assert_eq!(b.momentum(10).unwrap(), bad[10], "{what}");
    let got = run(&kernel, &bad, &rs, Level::detect(), Execution::Sequential);
    for i in (0..n).filter(|&i| i != 5 && i != 10) {
        assert_eq!(b.status(i).unwrap(), LaneStatus::Running, "{what} body {i}");
        assert_eq!(got[i], clean[i], "{what}: body {i} next to the bad ones");
    }
    let sums = b.summaries(|i| i);
    assert!(matches!(sums[5].status, Status::BuildFailed(_)), "{what}");
    assert!(
        matches!(sums[10].status, Status::StepFailed { .. }),
        "{what}"
    );
    assert_eq!((sums[10].steps, sums[10].time), (0, 0.0), "{what}");
    assert_eq!(sums[3].status, Status::Completed, "{what}");
    assert_eq!(sums[3].steps, STEPS as usize, "{what}");
}

/// A NaN in one body's state, or a step that leaves one body non-finite, fails that body only
/// (its status says which and when); its neighbours' bits are those of a batch without it.
#[test]
fn a_bad_body_fails_alone() {
    let free = BodyModel::free(&bodies()[0]).unwrap();
    let field = BodyModel::heavy_top(&tops()[0]).unwrap();
    fails_alone(Strang::new(free.clone()), "Strang free");
    fails_alone(Strang::new(field.clone()), "Strang field");
    fails_alone(QuaternionRk4::new(free.clone()), "RK4 free");
    fails_alone(QuaternionRk4::new(field.clone()), "RK4 field");
    fails_alone(Rkmk4::new(free.clone()), "RKMK4 free");
    fails_alone(Rkmk4::new(field), "RKMK4 field");
    fails_alone(ExactFlow::new(free).unwrap(), "exact");
}

/// A body that fails in the middle of a call (the step loop checks the lanes once per call
/// when it can, and then runs the call again checked after every step) fails at its own step:
/// its status, last finite state, steps, time and monitored maxima are those of a batch of it
/// alone stopped before that step, and its neighbours' bits and maxima those of a batch without
/// it. The body turns steadily about the perturbed axis p (Π = X a_p), by (h/2) r_p X in the
/// first step's opening turn and by h r_p X in every later one (the merged half steps,
/// r_p = 1/I_p − 1/I_r): X puts the second turn beyond the lanes' 2²⁸ rad and the first
/// within it. Monitored every third step: the unchecked pass monitored the body's non-finite
/// states, the checked one never reaches a monitored step of it.
#[test]
fn a_body_that_fails_in_the_middle_of_a_call_fails_at_its_step() {
    let body = &bodies()[0];
    let model = BodyModel::free(body).unwrap();
    let [r, p, _] = body.split_axes();
    let moments = body.principal_frame().1;
    let rate = (1.0 / moments[p] - 1.0 / moments[r]).abs();
    let limit = batch::trig::REDUCTION_LIMIT;
    let x = 1.5 * limit / (H * rate);
    // the first step (its Rodrigues angle h X / I_r on the general path, halved there) stays
    // within the range
    assert!(H * x / moments[r] / 2.0 < limit && 0.5 * H * rate * x < limit);
    let n = 16;
    let states: Vec<_> = (0..n as u64).map(|i| state(1.0, 9, i)).collect();
    let mut pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let kernel = Strang::new(model);
    let batch_of = |pis: &[Vector3<f64>], rs: &[So3], steps: u64| {
        let mut b = Batch::new(kernel.clone(), pis, rs, Level::detect())
            .unwrap()
            .monitor_every(3);
        b.run(H, steps).unwrap();
        b
    };
    let bits = |b: &mut Batch<Strang>, i: usize| {
        let (pi, r) = b.state(i).unwrap();
        let s = &b.summaries(|i| i)[i];
        let mut v: Vec<u64> = pi
            .iter()
            .chain(r.as_matrix().iter())
            .map(|x| x.to_bits())
            .collect();
        v.extend([
            s.max_energy_error.to_bits(),
            s.max_casimir_error.unwrap().to_bits(),
        ]);
        (v, s.status.clone(), s.steps, s.time)
    };
    let mut clean = batch_of(&pis, &rs, STEPS);
    pis[10] = Vector3::zeros();
    pis[10][p] = x;
    let mut bad = batch_of(&pis, &rs, STEPS);
    let mut alone = batch_of(&pis[10..11], &rs[10..11], 1);
    assert_eq!(bad.status(10).unwrap(), LaneStatus::Failed { step: 1 });
    let (got, status, steps, time) = bits(&mut bad, 10);
    assert!(matches!(status, Status::StepFailed { .. }), "{status:?}");
    assert_eq!((steps, time), (1, H));
    assert_eq!(
        got,
        bits(&mut alone, 0).0,
        "the failed body's state and maxima"
    );
    for i in (0..n).filter(|&i| i != 10) {
        assert_eq!(bad.status(i).unwrap(), LaneStatus::Running, "body {i}");
        assert_eq!(bits(&mut bad, i), bits(&mut clean, i), "body {i}");
    }
}

/// A body that ran a call and fails at the first step of the next one (|Π| = 10⁷, then steps
/// of h = 1000 turn it beyond 2²⁸ rad, and not its neighbours with |Π| = 1) keeps the largest
/// energy and Casimir errors of its monitored steps before, as a batch of it alone stopped
/// there: the unchecked pass, which monitored its non-finite states, leaves the maxima as they
/// were. The neighbours are those of a batch without it.
#[test]
fn a_body_that_fails_keeps_its_monitored_maxima() {
    let kernel = Strang::new(BodyModel::free(&bodies()[0]).unwrap());
    let n = 16;
    let states: Vec<_> = (0..n as u64).map(|i| state(1.0, 9, i)).collect();
    let mut pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let summaries = |pis: &[Vector3<f64>], rs: &[So3], calls: &[(f64, u64)]| {
        let mut b = Batch::new(kernel.clone(), pis, rs, Level::detect())
            .unwrap()
            .monitor_every(1);
        for &(h, steps) in calls {
            b.run(h, steps).unwrap();
        }
        b.summaries(|i| i)
    };
    let calls = [(H, 5), (1000.0, 3)];
    let clean = summaries(&pis, &rs, &calls);
    pis[10] *= 1e7;
    let bad = summaries(&pis, &rs, &calls);
    let alone = summaries(&pis[10..11], &rs[10..11], &calls[..1]);
    assert!(
        matches!(bad[10].status, Status::StepFailed { step: 5, .. }),
        "{:?}",
        bad[10].status
    );
    let maxima = |s: &integrators::ensemble::Summary<Vector3<f64>>| {
        [s.max_energy_error, s.max_casimir_error.unwrap()].map(f64::to_bits)
    };
    assert_eq!(
        maxima(&bad[10]),
        maxima(&alone[0]),
        "the failed body's maxima"
    );
    assert_eq!(bad[10].momentum, alone[0].momentum);
    for i in (0..n).filter(|&i| i != 10) {
        assert_eq!(bad[i].status, Status::Completed, "body {i}");
        assert_eq!(bad[i], clean[i], "body {i}");
    }
}

/// Zero bodies, arrays of different lengths, an unusable step or a body out of range: a clear
/// error naming what was wrong.
#[test]
fn bad_input_is_a_clear_error() {
    let k = Strang::new(BodyModel::free(&bodies()[0]).unwrap());
    let l = Level::Scalar;
    let pis = vec![Vector3::new(1.0, 0.0, 0.0); 3];
    let rs = vec![So3::identity(); 2];
    assert_eq!(
        Batch::new(k.clone(), &[], &[So3::identity()], l).unwrap_err(),
        BatchError::Empty { what: "momenta" }
    );
    assert_eq!(
        Batch::new(k.clone(), &pis, &rs, l).unwrap_err(),
        BatchError::LengthMismatch {
            what: "attitudes",
            got: 2,
            expected: 3
        }
    );
    let (one, two) = ([1.0, 2.0], [0.0]);
    let e = Batch::from_soa(
        k.clone(),
        [&one, &one, &one],
        [&one, &one, &one, &one, &one, &two, &one, &one, &one],
        l,
    )
    .unwrap_err();
    assert_eq!(
        e,
        BatchError::LengthMismatch {
            what: "R₂₃",
            got: 1,
            expected: 2
        }
    );
    assert!(e.to_string().contains("R₂₃ has 1 entries"), "{e}");
    let empty: [&[f64]; 3] = [&[], &[], &[]];
    assert!(matches!(
        Batch::from_soa(k.clone(), empty, [&one; 9], l),
        Err(BatchError::Empty { .. })
    ));
    let mut b = Batch::new(k, &pis, &[So3::identity()], l).unwrap();
    for h in [f64::NAN, f64::INFINITY, 0.0] {
        assert!(matches!(
            b.step(h),
            Err(BatchError::InvalidParameter { .. })
        ));
    }
    assert_eq!(b.steps(), 0, "a refused step takes none");
    assert!(matches!(
        b.state(3),
        Err(BatchError::InvalidParameter { .. })
    ));
}

/// Over 10⁶ Strang steps of eight free bodies (h = 0.01; |Π| = 1, random attitudes): |Π| and
/// the spatial momentum R Π, which each piece of the splitting keeps exactly, stay within
/// 1e-12 of their initial values (a random walk of round-off: √10⁶ · 2⁻⁵³ ≈ 1e-13), R stays
/// orthogonal to 1e-14 (renormalized every 256 steps), and the energy error, O(h²) without
/// drift, stays within 1.5 times its largest value over the first 10⁵ steps.
#[test]
fn the_splitting_keeps_its_invariants_over_a_million_steps() {
    let body = &bodies()[1];
    let states: Vec<_> = (0..8u64).map(|i| state(1.0, 21, i)).collect();
    let pis: Vec<_> = states.iter().map(|s| s.0).collect();
    let rs: Vec<_> = states.iter().map(|s| s.1).collect();
    let spatial = |b: &Batch<Strang>, i: usize| {
        let (pi, r) = b.state(i).unwrap();
        (pi.norm(), r.as_matrix() * pi, *r.as_matrix())
    };
    let mut b = Batch::new(
        Strang::new(BodyModel::free(body).unwrap()),
        &pis,
        &rs,
        Level::detect(),
    )
    .unwrap()
    .monitor_every(10);
    let start: Vec<_> = (0..8).map(|i| spatial(&b, i)).collect();
    b.run(0.01, 100_000).unwrap();
    let early: Vec<_> = b
        .summaries(|i| i)
        .iter()
        .map(|s| s.max_energy_error)
        .collect();
    b.run(0.01, 900_000).unwrap();
    let late = b;
    let (mut d_norm, mut d_spatial, mut d_orth) = (0.0f64, 0.0f64, 0.0f64);
    for (i, s0) in start.iter().enumerate() {
        let (n, m, r) = spatial(&late, i);
        d_norm = d_norm.max((n - s0.0).abs());
        d_spatial = d_spatial.max((m - s0.1).amax());
        d_orth = d_orth.max((r.transpose() * r - nalgebra::Matrix3::identity()).amax());
    }
    let mut late = late;
    let sums = late.summaries(|i| i);
    println!("10⁶ steps: |Π| {d_norm:e}, R Π {d_spatial:e}, RᵀR − I {d_orth:e}");
    assert!(
        d_norm < 1e-12 && d_spatial < 1e-12,
        "{d_norm:e} {d_spatial:e}"
    );
    assert!(d_orth < 1e-14, "{d_orth:e}");
    for i in 0..8 {
        assert_eq!(sums[i].steps, 1_000_000);
        assert_eq!(
            sums[i].time, 10_000.0,
            "the clock: 10⁶ steps of 0.01 end at 10⁴"
        );
        // the energy error has no drift: over 10⁶ steps within 1.5 times that of the first 10⁵
        assert!(
            sums[i].max_energy_error <= 1.5 * early[i],
            "body {i}: {} vs {}",
            sums[i].max_energy_error,
            early[i]
        );
        assert!(early[i] > 0.0 && early[i] < 1e-4, "{}", early[i]);
    }
}

/// A summary as comparable bits (status, steps, time, Π, E₀, the error maxima).
fn summary_bits(s: &integrators::ensemble::Summary<Vector3<f64>>) -> (String, usize, Vec<u64>) {
    let mut bits = vec![s.time.to_bits(), s.initial_energy.to_bits()];
    bits.push(s.max_energy_error.to_bits());
    bits.extend(s.max_casimir_error.map(f64::to_bits));
    bits.extend(
        s.momentum
            .iter()
            .flat_map(|m| m.iter().map(|x| x.to_bits())),
    );
    (format!("{:?}", s.status), s.steps, bits)
}

/// `Batch::refill` (the sweep's chunks reuse one batch) gives the bodies the bits a new batch
/// gives them: states, statuses, times and monitored errors, with a composition, a body that
/// fails mid-run and one refused at build, after the batch had run other bodies (larger and
/// smaller, so that the storage both shrinks and grows).
#[test]
fn a_refilled_batch_is_a_new_batch() {
    let body = bodies().remove(0);
    let kernel = Strang::new(BodyModel::free(&body).unwrap());
    let mut pis: Vec<_> = (0..203u64).map(|i| state(1.5, 9, i).0).collect();
    // one body that overflows mid-run, one that cannot start
    pis[17] = Vector3::new(1e300, 3e300, -2e300);
    pis[150] = Vector3::new(f64::NAN, 0.0, 1.0);
    let rs = [So3::identity()];
    let scheme = CompositionScheme::kahan_li_6();
    let fresh = |pis: &[Vector3<f64>]| {
        let mut b = Batch::new(kernel.clone(), pis, &rs, Level::detect())
            .unwrap()
            .with_composition(scheme.clone())
            .unwrap()
            .monitor_every(3);
        b.run(H, STEPS).unwrap();
        b.summaries(|i| i)
            .iter()
            .map(summary_bits)
            .collect::<Vec<_>>()
    };
    let mut reused = Batch::new(kernel.clone(), &pis[..50], &rs, Level::detect())
        .unwrap()
        .with_composition(scheme.clone())
        .unwrap()
        .monitor_every(3);
    let mut out = Vec::new();
    for part in [&pis[..], &pis[100..140], &pis[..]] {
        reused.run(H, 7).unwrap();
        reused.refill(part, &rs).unwrap();
        assert_eq!(reused.steps(), 0);
        assert_eq!(reused.len(), part.len());
        reused.run(H, STEPS).unwrap();
        reused.summaries_into(|i| i, &mut out);
        let got: Vec<_> = out.iter().map(summary_bits).collect();
        assert!(got == fresh(part), "{} bodies refilled", part.len());
    }
    assert!(matches!(out[17].status, Status::StepFailed { .. }));
    assert!(matches!(out[150].status, Status::BuildFailed(_)));
    // bad input leaves the batch as it was
    assert!(matches!(
        reused.refill(&[], &rs),
        Err(BatchError::Empty { .. })
    ));
    assert!(matches!(
        reused.refill(&pis[..3], &[So3::identity(); 2]),
        Err(BatchError::LengthMismatch { .. })
    ));
    assert_eq!(reused.len(), pis.len());
}

/// `run_to(T, n)` ends at exactly T (the batch's time and every summary's) where n steps of
/// fl(T/n) end an ulp past it (0.7 in 70 steps: 0.7000000000000001), forwards and backwards; its
/// last step is T − t, as `integrators::ensemble::Ensemble` takes it; a T that is not finite or
/// no steps are refused, the batch untouched.
#[test]
fn run_to_lands_on_t() {
    let k = Strang::new(BodyModel::free(&bodies()[0]).unwrap());
    let (pis, rs): (Vec<_>, Vec<_>) = (0..5).map(|i| state(1.0, 3, i)).unzip();
    let new = || Batch::new(k.clone(), &pis, &rs, Level::Scalar).unwrap();
    for end in [0.7, -0.7] {
        let mut b = new();
        b.run_to(end, 70).unwrap();
        assert_eq!((b.time(), b.steps()), (end, 70));
        let mut out = Vec::new();
        b.summaries_into(|i| i, &mut out);
        assert!(out.iter().all(|s| s.time == end && s.status.is_completed()));
        let mut by_hand = new();
        by_hand.run(end / 70.0, 69).unwrap();
        by_hand.run(end - by_hand.time(), 1).unwrap();
        assert_eq!(by_hand.momenta(), b.momenta());
        // the negative control: 70 equal steps miss T
        let mut equal = new();
        equal.run(end / 70.0, 70).unwrap();
        assert_ne!(equal.time(), end);
    }
    let mut b = new();
    b.run_to(0.7, 1).unwrap();
    assert_eq!(b.time(), 0.7);
    for (end, n) in [(f64::NAN, 3), (f64::INFINITY, 3), (1.0, 0)] {
        assert!(matches!(
            b.run_to(end, n),
            Err(BatchError::InvalidParameter { .. })
        ));
    }
    assert_eq!(
        (b.time(), b.steps()),
        (0.7, 1),
        "a refused run takes no step"
    );
}
