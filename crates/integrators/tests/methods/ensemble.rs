//! Ensembles (`integrators::ensemble`): the parallel run is bit-identical to the sequential one,
//! merged shards are exactly the full run, seeded initial conditions are reproducible and lie on
//! the sphere / energy level, and bad members are reported per trajectory.

use integrators::ensemble::{
    merge_shards, momenta_on_energy_level, momenta_on_sphere, sphere_point, Ensemble, Execution,
    Shard, ShardLayout, Status, Summary,
};
use integrators::{Composition, CompositionScheme, IntegratorError, LiePoisson, System};
use lie_groups::{Cayley, LieGroup, So3};
use mechanics::RigidBody;
use nalgebra::Vector3;

fn body() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

fn sweep(n: usize, steps: usize) -> Ensemble<Vector3<f64>> {
    Ensemble::new(
        momenta_on_sphere(3, 1.0, n, 7).unwrap(),
        0.05 * steps as f64,
        steps,
    )
    .unwrap()
}

type Lp = LiePoisson<So3, Cayley, RigidBody>;

fn build(_: usize, mu: &Vector3<f64>) -> Result<Lp, IntegratorError> {
    LiePoisson::new(body(), 0.5, *mu, Some(So3::identity()))
}

/// Bit-level equality of two runs (f64 `==` would also accept −0 = +0; compare the bits).
fn assert_bit_identical(a: &[Summary<Vector3<f64>>], b: &[Summary<Vector3<f64>>]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert_eq!(x.index, y.index);
        assert_eq!(x.status, y.status);
        let (mx, my) = (x.momentum.unwrap(), y.momentum.unwrap());
        for i in 0..3 {
            assert_eq!(mx[i].to_bits(), my[i].to_bits(), "member {}", x.index);
        }
        assert_eq!(x.time.to_bits(), y.time.to_bits());
        assert_eq!(x.max_energy_error.to_bits(), y.max_energy_error.to_bits());
        assert_eq!(
            x.max_casimir_error.map(f64::to_bits),
            y.max_casimir_error.map(f64::to_bits)
        );
    }
}

#[test]
fn parallel_run_is_bit_identical_to_the_sequential_run_on_1_2_and_3_threads() {
    let sweep = sweep(24, 60);
    let seq = sweep.run_sequential(&build);
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let par = pool.install(|| sweep.run_parallel(&build));
        assert_bit_identical(&seq, &par);
    }
    assert!(seq.iter().all(|s| s.status.is_completed() && s.steps == 60));
    assert!(seq.iter().enumerate().all(|(i, s)| s.index == i));
}

#[test]
fn parallel_run_of_a_composition_is_bit_identical_to_the_sequential_run() {
    let sweep = sweep(8, 10);
    let build = |i: usize, mu: &Vector3<f64>| {
        Composition::new(build(i, mu)?, CompositionScheme::kahan_li_6())
    };
    assert_bit_identical(&sweep.run_sequential(&build), &sweep.run_parallel(&build));
}

/// Processed and modified members: the same bit-identity (the processed output is computed from
/// the kernel state on each read, never shared), every member completed, and the processed
/// members' final momenta equal those of single runs of the same method (the ensemble reads
/// them like any observer).
#[test]
fn parallel_runs_of_processed_and_modified_methods_are_bit_identical_to_the_sequential_runs() {
    use integrators::processing::{Processed, ProcessingScheme};
    use integrators::splitting::Splitting;
    use integrators::Integrator;
    use mechanics::modified::{ModifiedLiePoisson, ModifiedScheme};
    let sweep = sweep(8, 10);
    let processed = |_: usize, mu: &Vector3<f64>| {
        Processed::composition(
            Splitting::new(body(), *mu, Some(So3::identity()))?,
            ProcessingScheme::blanes_casas_murua_6_11(),
        )
    };
    let seq = sweep.run_sequential(&processed);
    assert_bit_identical(&seq, &sweep.run_parallel(&processed));
    assert!(seq.iter().all(|s| s.status.is_completed()));
    let mu3 = momenta_on_sphere(3, 1.0, 8, 7).unwrap()[3];
    let mut single = processed(3, &mu3).unwrap();
    for _ in 0..9 {
        single.step(0.05).unwrap();
    }
    // The ensemble's last step lands on T = 0.5.
    single.step(0.5 - single.time()).unwrap();
    assert_eq!(seq[3].momentum.unwrap(), single.momentum());
    assert_eq!(seq[3].time, 0.5);
    let modified = |_: usize, mu: &Vector3<f64>| {
        ModifiedLiePoisson::<Cayley>::with_scheme(
            body(),
            ModifiedScheme::new(0.0, 6)?,
            *mu,
            Some(So3::identity()),
        )
    };
    let seq = sweep.run_sequential(&modified);
    assert_bit_identical(&seq, &sweep.run_parallel(&modified));
    assert!(seq.iter().all(|s| s.status.is_completed()));
}

#[test]
fn merged_shards_equal_the_full_run_for_contiguous_and_strided_layouts() {
    let sweep = sweep(23, 20);
    let full = sweep.run_sequential(&build);
    for layout in [ShardLayout::Contiguous, ShardLayout::Strided] {
        for n in [1, 2, 3, 5, 23, 30] {
            let parts: Vec<_> = (0..n)
                .map(|i| {
                    let shard = Shard::with_layout(i, n, layout).unwrap();
                    sweep.run_shard(shard, Execution::Parallel, &build)
                })
                .collect();
            // The shards partition the indices.
            let total: usize = parts.iter().map(Vec::len).sum();
            assert_eq!(total, 23, "{layout:?} n = {n}");
            // Merging in any order gives the full run.
            let merged = merge_shards(parts.into_iter().rev(), sweep.len()).unwrap();
            assert_bit_identical(&full, &merged);
        }
    }
}

#[test]
fn merge_refuses_missing_duplicate_and_foreign_indices() {
    let sweep = sweep(6, 3);
    let a = sweep.run_shard(Shard::new(0, 2).unwrap(), Execution::Sequential, &build);
    let b = sweep.run_shard(Shard::new(1, 2).unwrap(), Execution::Sequential, &build);
    assert!(merge_shards([a.clone()], 6).is_err());
    assert!(merge_shards([a.clone(), a.clone(), b.clone()], 6).is_err());
    assert!(merge_shards([a.clone(), b.clone()], 5).is_err());
    assert!(merge_shards([a, b], 6).is_ok());
}

#[test]
fn shard_parses_i_over_n_and_rejects_out_of_range() {
    let s: Shard = "2/5".parse().unwrap();
    assert_eq!((s.index(), s.count()), (2, 5));
    assert_eq!(s.to_string(), "2/5");
    for bad in ["5/5", "1", "a/3", "1/0", "-1/3", ""] {
        assert!(bad.parse::<Shard>().is_err(), "{bad:?}");
    }
    assert_eq!(Shard::new(1, 3).unwrap().indices(10), vec![3, 4, 5]);
    assert_eq!(Shard::strided(1, 3).unwrap().indices(10), vec![1, 4, 7]);
    assert_eq!(Shard::all().indices(4), vec![0, 1, 2, 3]);
}

#[test]
fn seeded_momenta_are_reproducible_on_the_sphere_and_depend_only_on_seed_and_index() {
    let a: Vec<Vector3<f64>> = momenta_on_sphere(3, 2.0, 50, 11).unwrap();
    let b: Vec<Vector3<f64>> = momenta_on_sphere(3, 2.0, 50, 11).unwrap();
    let c: Vec<Vector3<f64>> = momenta_on_sphere(3, 2.0, 50, 12).unwrap();
    assert_eq!(a, b);
    assert_ne!(a, c);
    // Point k is the same whether drawn alone or in a batch (shards can draw their own).
    assert_eq!(sphere_point::<Vector3<f64>>(3, 2.0, 11, 37).unwrap(), a[37]);
    // On the sphere to round-off.
    assert!(a.iter().all(|m| (m.norm() - 2.0).abs() < 1e-15 * 2.0 * 4.0));
    assert!(sphere_point::<Vector3<f64>>(0, 1.0, 1, 0).is_err());
    assert!(sphere_point::<Vector3<f64>>(3, f64::NAN, 1, 0).is_err());
}

/// Uniformity, loosely: over 4000 points the mean of each coordinate is within 4σ of 0
/// (σ = 1/√(3·4000) ≈ 0.0091 for the unit sphere in ℝ³) and the mean of each squared coordinate
/// within 4σ of 1/3 (σ = √(4/45 /4000) ≈ 0.0047).
#[test]
fn seeded_sphere_points_have_the_moments_of_the_uniform_distribution() {
    let pts: Vec<Vector3<f64>> = momenta_on_sphere(3, 1.0, 4000, 3).unwrap();
    let n = pts.len() as f64;
    for i in 0..3 {
        let m1 = pts.iter().map(|p| p[i]).sum::<f64>() / n;
        let m2 = pts.iter().map(|p| p[i] * p[i]).sum::<f64>() / n;
        assert!(m1.abs() < 4.0 * 0.0091, "mean {m1}");
        assert!((m2 - 1.0 / 3.0).abs() < 4.0 * 0.0047, "second moment {m2}");
    }
}

#[test]
fn momenta_on_the_energy_level_have_that_energy() {
    let b = body();
    let mus = momenta_on_energy_level::<So3, _>(&b, 0.7, 100, 5).unwrap();
    for mu in &mus {
        assert!((b.hamiltonian(mu) - 0.7).abs() < 1e-15 * 4.0);
    }
    assert!(momenta_on_energy_level::<So3, _>(&b, -1.0, 3, 5).is_err());
    assert!(momenta_on_energy_level::<So3, _>(&b, f64::INFINITY, 3, 5).is_err());
}

/// A member the builder refuses and a member whose step fails are reported in their summaries;
/// the other members are unaffected.
#[test]
fn bad_members_are_reported_per_trajectory() {
    let members = vec![
        Vector3::new(0.6, -0.4, 0.9),
        Vector3::new(f64::NAN, 0.0, 0.0),
        Vector3::new(0.6, -0.4, 0.9),
    ];
    let sweep = Ensemble::new(members, 0.5, 10).unwrap();
    let out = sweep.run_parallel(&build);
    assert!(out[0].status.is_completed());
    assert!(matches!(
        out[1].status,
        Status::BuildFailed(IntegratorError::NonFinite { .. })
    ));
    assert!(out[1].momentum.is_none());
    assert_eq!(
        out[0],
        Summary {
            index: 0,
            ..out[2].clone()
        }
    );
    // A step that cannot converge: (huge h, 2 solver iterations).
    let sweep = Ensemble::new(vec![Vector3::new(5.0, -4.0, 9.0)], 12.0, 4).unwrap();
    let tight = |_: usize, mu: &Vector3<f64>| {
        build(0, mu).map(|lp| {
            lp.with_solver(integrators::SolverConfig {
                max_iterations: 2,
                ..Default::default()
            })
        })
    };
    let out = sweep.run_sequential(&tight);
    assert!(
        matches!(out[0].status, Status::StepFailed { step: 0, .. }),
        "{:?}",
        out[0].status
    );
    assert_eq!(out[0].steps, 0);
    assert!(Ensemble::new(vec![1.0], f64::NAN, 3).is_err());
    assert!(Ensemble::new(vec![1.0], f64::INFINITY, 3).is_err());
    assert!(Ensemble::new(vec![1.0], 1.0, 0).is_err());
}

/// Every member ends at exactly T, forwards and backwards, where n equal steps of fl(T/n) do not
/// (the negative control: 70 steps of 0.7/70 end at 0.7000000000000001, on the integrators'
/// compensated clock, as 49 of 1/49 at 0.9999999999999999), and its last step is the one that
/// lands there: a member stepped by hand with n − 1 steps of T/n and one of T − t has its bits.
#[test]
fn every_member_ends_at_exactly_t() {
    use integrators::Integrator;
    let members = momenta_on_sphere(3, 1.0, 4, 11).unwrap();
    for (end, n) in [(0.7, 70usize), (1.0, 49), (-0.7, 70), (3.0, 7), (0.7, 1)] {
        let out = Ensemble::new(members.clone(), end, n)
            .unwrap()
            .run_sequential(&build);
        for s in &out {
            assert!(s.status.is_completed());
            assert_eq!((s.time, s.steps), (end, n), "T = {end}, n = {n}");
        }
        let mut equal = build(0, &members[0]).unwrap();
        let mut by_hand = build(0, &members[0]).unwrap();
        for k in 0..n {
            equal.step(end / n as f64).unwrap();
            let h = if k + 1 < n {
                end / n as f64
            } else {
                end - by_hand.time()
            };
            by_hand.step(h).unwrap();
        }
        assert_eq!(by_hand.time(), end);
        assert_eq!(out[0].momentum.unwrap(), by_hand.momentum());
        if n >= 49 {
            assert_ne!(equal.time(), end, "T = {end}, n = {n}");
        }
    }
}

#[test]
fn csv_rows_match_the_header() {
    let sweep = sweep(3, 5);
    let out = sweep.run_sequential(&build);
    let header = Summary::<Vector3<f64>>::csv_header(3);
    let cols = header.split(',').count();
    assert_eq!(cols, 10);
    for s in &out {
        let row = s.csv_row(3);
        assert_eq!(row.split(',').count(), cols, "{row}");
        // Round trip of μ through the CSV text is exact.
        let fields: Vec<&str> = row.split(',').collect();
        let mu = s.momentum.unwrap();
        for i in 0..3 {
            assert_eq!(fields[4 + i].parse::<f64>().unwrap(), mu[i]);
        }
    }
}

/// `push_exp` (ryu's digits in the `{:e}` form) writes what `format!("{x:e}")` writes, byte for
/// byte: on 2·10⁶ random bit patterns (every exponent, subnormals included), on the integers and
/// on both neighbours of every power of ten, on ±0, the extremes, NaN and ±∞.
#[test]
fn push_exp_writes_what_format_e_writes() {
    use integrators::ensemble::push_exp;
    let check = |x: f64| {
        let mut s = String::from("prefix,");
        push_exp(&mut s, x);
        assert_eq!(s, format!("prefix,{x:e}"), "bits {:#018x}", x.to_bits());
    };
    // SplitMix64: the bit patterns, reproducibly.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..2_000_000 {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        check(f64::from_bits(z ^ (z >> 31)));
    }
    for i in -1000..=1000 {
        check(f64::from(i));
        check(f64::from(i) / 8.0);
    }
    // Exact ties between two shortest decimals (1000000000000000.25 lies halfway between …0.2
    // and …0.3, both within half an ulp), where ryu's choice is not the standard library's.
    for k in 0..1000 {
        for f in [0.25, 0.75] {
            check(1e15 + f64::from(k) + f);
        }
    }
    check(f64::from_bits(0x4312_9879_088f_f039));
    check(f64::from_bits(0x42b6_7d63_6afc_0b90));
    // Every exponent from 2⁴⁵ to 2⁵⁸, where ties are densest.
    for e in 45..58 {
        for k in 0..2000u64 {
            let fraction = k.wrapping_mul(0x0000_5a5a_5a5a_5a5b) & ((1 << 52) - 1);
            let x = f64::from_bits(((1023 + e) << 52) | fraction);
            check(x);
            check(-x);
        }
    }
    for e in -324..=308 {
        let p: f64 = format!("1e{e}").parse().unwrap();
        for x in [
            p,
            f64::from_bits(p.to_bits() + 1),
            f64::from_bits(p.to_bits().max(1) - 1),
        ] {
            check(x);
            check(-x);
        }
    }
    for x in [
        0.0,
        -0.0,
        f64::MIN_POSITIVE,
        f64::MAX,
        f64::MIN,
        f64::EPSILON,
        f64::from_bits(1),
        3.179e-6,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ] {
        check(x);
    }
}
