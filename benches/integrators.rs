//! ns per step of every integrator of the `integrators` crate, with the baselines (explicit RK4 on
//! quaternion + momentum, RKMK4 on the group) measured in the same run.
//!
//! Groups:
//! - `rigid_body/step`: free rigid body 𝕀 = diag(1, 2, 3), Π₀ = (0.5, 1, 0.2), h = 0.01;
//!   Lie–Poisson (eq. 19) and Euler–Poincaré (eq. 18) × τ ∈ {exp, Cayley} × θ ∈ {0, ½, 1}, with
//!   (`+g`) and without (`-g`) reconstruction; RK4 and RKMK4 likewise.
//! - `rigid_body/solver`: Lie–Poisson Cayley θ = ½ with reconstruction, for each
//!   [`SolverKind`] and tolerance.
//! - `heavy_top/step`: the heavy top (reconstruction is required).
//! - `so_n/step`: the generalized rigid body (Euler–Arnold geodesic) on SO(n), n = 10, 20, 50.
//!
//! The free body and the heavy top also step the hand-written nalgebra RK4 on (q, Π) of
//! `benches/common/hand_rk4.rs` (`rk4-hand-written+g`), the plain competitor, in the same run.
//!
//! Each benchmark steps one integrator along its trajectory (`step(h)` per iteration); the motion
//! is bounded, so the cost per step is stationary. Run:
//! `cargo bench -p lie-integrators --bench integrators -- --warm-up-time 1 --measurement-time 2`.

use criterion::{
    criterion_group, criterion_main, measurement::WallTime, BenchmarkGroup, Criterion,
};
use integrators::baselines::{QuaternionRk4, Rkmk4};
use integrators::{EulerPoincare, Integrator, LiePoisson, SolverConfig, SolverKind, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, SoN, Tau, Vector};
use mechanics::systems::{GeneralizedRigidBody, HeavyTop, RigidBody};
use nalgebra::Vector3;
use std::hint::black_box;

#[path = "common/hand_rk4.rs"]
mod hand_rk4;
use hand_rk4::HandRk4;

const H: f64 = 0.01;
const THETAS: [f64; 3] = [0.0, 0.5, 1.0];

/// R₀ of the SO(3) benchmarks (the hand-written RK4 starts from its quaternion).
fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.5, 0.8))
}

fn bench_step<I: Integrator>(group: &mut BenchmarkGroup<'_, WallTime>, id: &str, mut integ: I) {
    group.bench_function(id, |b| b.iter(|| integ.step(black_box(H)).unwrap()));
}

fn so3_methods<S: System<So3> + Clone, T: Tau<So3>>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    system: &S,
    pi0: Vector3<f64>,
    reconstruct: bool,
) {
    let g0 = reconstruct.then(g0);
    let suffix = if reconstruct { "+g" } else { "-g" };
    for theta in THETAS {
        let lp = LiePoisson::<So3, T, _>::new(system.clone(), theta, pi0, g0).unwrap();
        bench_step(group, &format!("lp/{}/{theta}{suffix}", T::NAME), lp);
    }
    for theta in THETAS {
        let ep = EulerPoincare::<So3, T, _>::from_momentum(system.clone(), theta, pi0, g0).unwrap();
        bench_step(group, &format!("ep/{}/{theta}{suffix}", T::NAME), ep);
    }
}

fn baselines<S: System<So3> + Clone>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    system: &S,
    pi0: Vector3<f64>,
    reconstruct: bool,
) {
    let g0 = reconstruct.then(g0);
    let suffix = if reconstruct { "+g" } else { "-g" };
    let rk4 = QuaternionRk4::new(system.clone(), pi0, g0).unwrap();
    bench_step(group, &format!("rk4-quaternion{suffix}"), rk4);
    let rkmk = Rkmk4::new(system.clone(), pi0, g0).unwrap();
    bench_step(group, &format!("rkmk4{suffix}"), rkmk);
}

fn rigid_body(c: &mut Criterion) {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let mut group = c.benchmark_group("rigid_body/step");
    // The plain competitor in the same run (benches/common/hand_rk4.rs).
    let mut hand = HandRk4::<false>::new([1.0, 2.0, 3.0], Vector3::zeros(), pi0, g0().as_matrix());
    group.bench_function("rk4-hand-written+g", |b| b.iter(|| hand.step(black_box(H))));
    for reconstruct in [true, false] {
        baselines(&mut group, &body, pi0, reconstruct);
        so3_methods::<_, Cayley>(&mut group, &body, pi0, reconstruct);
        so3_methods::<_, ExpMap>(&mut group, &body, pi0, reconstruct);
    }
    group.finish();

    let mut group = c.benchmark_group("rigid_body/solver");
    let g0 = Some(g0());
    for (name, kind) in [
        ("simplified-newton", SolverKind::SimplifiedNewton),
        ("newton", SolverKind::Newton),
        ("newton-fd", SolverKind::NewtonFiniteDifference),
        ("fixed-point", SolverKind::FixedPoint),
    ] {
        for tolerance in [1e-14, 1e-10] {
            for theta in [0.0, 0.5] {
                let config = SolverConfig {
                    kind,
                    tolerance,
                    ..SolverConfig::default()
                };
                let lp = LiePoisson::<So3, Cayley, _>::new(body.clone(), theta, pi0, g0)
                    .unwrap()
                    .with_solver(config);
                bench_step(
                    &mut group,
                    &format!("lp/cayley/{theta}+g/{name}/{tolerance:e}"),
                    lp,
                );
            }
        }
    }
    let unchecked = SolverConfig {
        check_domain: false,
        ..SolverConfig::default()
    };
    for theta in [0.0, 0.5] {
        let lp = LiePoisson::<So3, Cayley, _>::new(body.clone(), theta, pi0, g0)
            .unwrap()
            .with_solver(unchecked);
        bench_step(
            &mut group,
            &format!("lp/cayley/{theta}+g/simplified-newton/no-domain-check"),
            lp,
        );
    }
    group.finish();
}

fn heavy_top(c: &mut Criterion) {
    let top = HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 1.0, Vector3::new(0.0, 0.1, 0.5)).unwrap();
    let pi0 = Vector3::new(0.5, 1.0, 0.2);
    let mut group = c.benchmark_group("heavy_top/step");
    let mgchi = Vector3::new(0.0, 0.1, 0.5);
    let mut hand = HandRk4::<true>::new([1.0, 2.0, 3.0], mgchi, pi0, g0().as_matrix());
    group.bench_function("rk4-hand-written+g", |b| b.iter(|| hand.step(black_box(H))));
    baselines(&mut group, &top, pi0, true);
    so3_methods::<_, Cayley>(&mut group, &top, pi0, true);
    so3_methods::<_, ExpMap>(&mut group, &top, pi0, true);
    group.finish();
}

/// The generalized rigid body on SO(N). Newton's dense Jacobian has (N(N−1)/2)² entries, each
/// column an ad* evaluation, and is composed by dense products: O(N⁶) per iteration, so at N = 50
/// (dimension 1225) only the Jacobian-free methods are benchmarked (`newton = false`): the
/// Lie–Poisson step with the fixed-point solver, explicit Euler–Poincaré θ = 0 and RKMK4.
fn so_n_case<const N: usize>(group: &mut BenchmarkGroup<'_, WallTime>, newton: bool) {
    let j: Vec<f64> = (0..N).map(|i| 1.0 + i as f64 / N as f64).collect();
    let body = GeneralizedRigidBody::<N>::new(&j).unwrap();
    let d = SoN::<N>::DIM;
    // A generic momentum of size |M| ~ 1 (deterministic).
    let mu0 = <<SoN<N> as LieGroup>::Algebra as Vector>::from_fn(d, |p| {
        ((p as f64 * 0.7548776662).fract() - 0.5) * 2.0 / (d as f64).sqrt()
    });
    let g0 = Some(SoN::<N>::identity());
    let fixed_point = SolverConfig {
        kind: SolverKind::FixedPoint,
        ..SolverConfig::default()
    };
    for theta in [0.0, 0.5] {
        if newton {
            let lp =
                LiePoisson::<SoN<N>, Cayley, _>::new(body.clone(), theta, mu0.clone(), g0.clone())
                    .unwrap();
            bench_step(
                group,
                &format!("lp/cayley/{theta}+g/simplified-newton/n={N}"),
                lp,
            );
        }
        let lp = LiePoisson::<SoN<N>, Cayley, _>::new(body.clone(), theta, mu0.clone(), g0.clone())
            .unwrap()
            .with_solver(fixed_point);
        bench_step(group, &format!("lp/cayley/{theta}+g/fixed-point/n={N}"), lp);
    }
    let ep = EulerPoincare::<SoN<N>, Cayley, _>::from_momentum(
        body.clone(),
        0.0,
        mu0.clone(),
        g0.clone(),
    )
    .unwrap();
    bench_step(group, &format!("ep/cayley/0+g/n={N}"), ep);
    let rkmk = Rkmk4::new(body, mu0, g0).unwrap();
    bench_step(group, &format!("rkmk4+g/n={N}"), rkmk);
}

fn so_n(c: &mut Criterion) {
    let mut group = c.benchmark_group("so_n/step");
    group.sample_size(10);
    so_n_case::<10>(&mut group, true);
    so_n_case::<20>(&mut group, true);
    so_n_case::<50>(&mut group, false);
    group.finish();
}

criterion_group!(benches, rigid_body, heavy_top, so_n);
criterion_main!(benches);
