//! Micro-benchmarks of the trivialized bundles (§1 of the paper): compose and inverse of TG and
//! TTG over SO(3) and SE(3), with the base group's compose and `adjoint_apply` (Ad_g ξ) measured in
//! the same run as the yardstick. TG compose `(g, ξ)(h, η) = (gh, Ad_{h⁻¹}ξ + η)` is exactly one
//! base compose, one `adjoint_inverse_apply` and one vector add: the row "G parts of TG" does those
//! three on the same operands and returns the same data (a base element and an algebra vector), so
//! TG compose against it is the cost of the bundle wrapper itself. TTG compose is roughly three of
//! each (the nested product calls TG's Ad, which is two base Ad and one bracket).
//!
//! Run: `cargo bench -p lie-integrators --bench bundles` (add `-- --quick` for a smoke run).

use criterion::{criterion_group, criterion_main, Criterion};
use lie_groups::{LieGroup, Se3, So3, Vector};
use nalgebra::{Vector3, Vector6};
use std::hint::black_box;
use trivial_bundles::prelude::*;

fn bench_group<G: LieGroup + Copy>(c: &mut Criterion, label: &str, a: [G::Algebra; 4])
where
    G::Algebra: Copy,
{
    let (g, h) = (G::exp(&a[0]), G::exp(&a[1]));
    let (x, y) = (
        TangentBundle::from_parts(g, a[2]),
        TangentBundle::from_parts(h, a[3]),
    );
    let (xx, yy) = (
        Ttg::<G>::new(g, a[2], a[3], a[1]),
        Ttg::<G>::new(h, a[3], a[2], a[0]),
    );

    let mut grp = c.benchmark_group(format!("{label}/compose"));
    grp.bench_function("G", |b| b.iter(|| black_box(&g).compose(black_box(&h))));
    grp.bench_function("G adjoint_apply", |b| {
        b.iter(|| black_box(&g).adjoint_apply(black_box(&a[2])))
    });
    grp.bench_function("G parts of TG", |b| {
        b.iter(|| {
            let (g, h) = (black_box(&g), black_box(&h));
            let (xi, eta) = (black_box(&a[2]), black_box(&a[3]));
            (g.compose(h), h.adjoint_inverse_apply(xi).add(eta))
        })
    });
    grp.bench_function("TG", |b| b.iter(|| black_box(&x).compose(black_box(&y))));
    grp.bench_function("TTG", |b| b.iter(|| black_box(&xx).compose(black_box(&yy))));
    grp.finish();

    let mut grp = c.benchmark_group(format!("{label}/inverse"));
    grp.bench_function("G", |b| b.iter(|| black_box(&g).inverse()));
    grp.bench_function("TG", |b| b.iter(|| black_box(&x).inverse()));
    grp.bench_function("TTG", |b| b.iter(|| black_box(&xx).inverse()));
    grp.finish();
}

fn so3(c: &mut Criterion) {
    let v = Vector3::new;
    bench_group::<So3>(
        c,
        "so3_bundles",
        [
            v(0.3, -0.7, 1.1),
            v(-0.5, 0.2, 0.4),
            v(1.0, 2.0, -0.5),
            v(-0.3, 0.1, 0.9),
        ],
    );
}

fn se3(c: &mut Criterion) {
    let v = Vector6::new;
    bench_group::<Se3>(
        c,
        "se3_bundles",
        [
            v(0.3, -0.7, 1.1, 1.0, 0.5, -2.0),
            v(-0.5, 0.2, 0.4, 0.3, -0.1, 0.8),
            v(1.0, 2.0, -0.5, 0.2, 0.2, 0.1),
            v(-0.3, 0.1, 0.9, -1.0, 0.4, 0.6),
        ],
    );
}

criterion_group!(benches, so3, se3);
criterion_main!(benches);
