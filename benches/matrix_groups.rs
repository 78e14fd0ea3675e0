//! exp/log on SO(n) for n = 3, 10, 50 (faer, Padé expm and the eigen-based log), and the SO(2)/SE(2)
//! hot paths (compose, exp, log, Ad) with nalgebra `UnitComplex`/`Isometry2` rows for comparison.
//!
//! `cargo bench -p lie-integrators --bench matrix_groups` (add `-- --quick` for a smoke run).

use criterion::{criterion_group, criterion_main, Criterion};
use lie_groups::{LieGroup, Se2, So2, SoN, Vector};
use nalgebra::{Isometry2, UnitComplex, Vector2, Vector3};
use std::hint::black_box;

/// 𝔰𝔬(n) coordinates (a faer column, built through the crate's `Vector` trait).
type Alg<const N: usize> = <SoN<N> as LieGroup>::Algebra;

fn algebra<const N: usize>(dim: usize, scale: f64) -> Alg<N> {
    // deterministic, angles well inside the injectivity radius
    <Alg<N> as Vector>::from_fn(dim, |i| scale * (((i * 7919) % 97) as f64 / 97.0 - 0.5))
}

fn son<const N: usize>(c: &mut Criterion) {
    let dim = N * (N - 1) / 2;
    let xi = algebra::<N>(dim, 2.0 / (dim as f64).sqrt());
    let g = SoN::<N>::exp(&xi);
    let mut group = c.benchmark_group(format!("SO({N})"));
    group.bench_function("exp", |b| b.iter(|| SoN::<N>::exp(black_box(&xi))));
    group.bench_function("log", |b| b.iter(|| black_box(&g).log().unwrap()));
    group.bench_function("Ad (operator)", |b| b.iter(|| black_box(&g).adjoint()));
    group.bench_function("Ad* apply", |b| {
        b.iter(|| black_box(&g).coadjoint_apply(black_box(&xi)))
    });
    group.finish();
}

fn so2_se2(c: &mut Criterion) {
    let mut group = c.benchmark_group("SO(2)");
    let (g, h) = (So2::from_angle(0.3), So2::from_angle(-1.2));
    let (zg, zh) = (UnitComplex::new(0.3), UnitComplex::new(-1.2));
    let w = nalgebra::Vector1::new(0.7);
    group.bench_function("compose", |b| {
        b.iter(|| black_box(&g).compose(black_box(&h)))
    });
    group.bench_function("compose (nalgebra UnitComplex)", |b| {
        b.iter(|| black_box(zg) * black_box(zh))
    });
    group.bench_function("exp", |b| b.iter(|| So2::exp(black_box(&w))));
    group.bench_function("exp (nalgebra UnitComplex)", |b| {
        b.iter(|| UnitComplex::new(black_box(0.7)))
    });
    group.bench_function("log", |b| b.iter(|| black_box(&g).log().unwrap()));
    group.bench_function("log (nalgebra UnitComplex)", |b| {
        b.iter(|| black_box(zg).angle())
    });
    group.finish();

    let mut group = c.benchmark_group("SE(2)");
    let xi = Vector3::new(0.4, 1.0, -2.0);
    let (g, h) = (Se2::exp(&xi), Se2::exp(&Vector3::new(-1.1, 0.3, 0.5)));
    let (ig, ih): (Isometry2<f64>, Isometry2<f64>) = (g.into(), h.into());
    group.bench_function("compose", |b| {
        b.iter(|| black_box(&g).compose(black_box(&h)))
    });
    group.bench_function("compose (nalgebra Isometry2)", |b| {
        b.iter(|| black_box(ig) * black_box(ih))
    });
    group.bench_function("exp", |b| b.iter(|| Se2::exp(black_box(&xi))));
    group.bench_function("exp (nalgebra Isometry2::new, not the group exp)", |b| {
        b.iter(|| Isometry2::new(black_box(Vector2::new(1.0, -2.0)), black_box(0.4)))
    });
    group.bench_function("log", |b| b.iter(|| black_box(&g).log().unwrap()));
    group.bench_function("Ad", |b| b.iter(|| black_box(&g).adjoint()));
    group.bench_function("Ad apply", |b| {
        b.iter(|| black_box(&g).adjoint_apply(black_box(&xi)))
    });
    group.bench_function(
        "Ad (nalgebra: isometry conjugation of a twist matrix)",
        |b| {
            let m = Se2::hat(&xi);
            b.iter(|| {
                let hg = black_box(ig).to_homogeneous();
                hg * m * black_box(ig).inverse().to_homogeneous()
            })
        },
    );
    group.finish();
}

criterion_group!(benches, son::<3>, son::<10>, son::<50>, so2_se2);
criterion_main!(benches);
