//! Micro-benchmarks of the SO(3) and SE(3) closed forms, with nalgebra's geometry types as the
//! comparison rows in the same groups (UnitQuaternion, Rotation3, Isometry3).
//!
//! Like with like: `So3` stores a 3×3 matrix, so its natural peer is `Rotation3` (also a 3×3
//! matrix); `UnitQuaternion` stores 4 numbers, so e.g. its inverse (a conjugate: 3 sign flips) moves
//! less than half the data of any matrix transpose. Every SO(3) operation is timed against both.
//! `Se3` (matrix + translation) is timed against `Isometry3` (quaternion + translation).
//! Every row passes its operands the same way, through `black_box(&x)` (by reference), so no row
//! pays for copying its inputs through `black_box` by value.
//!
//! Run: `cargo bench -p lie-integrators --bench lie_groups` (add `-- --quick` for a smoke run). `black_box` is
//! `std::hint::black_box` (criterion 0.8 deprecates its own re-export).

use criterion::{criterion_group, criterion_main, Criterion};
use lie_groups::Action;
use lie_groups::{CayleyGroup, LieGroup, Se3, So3};
use nalgebra::{Isometry3, Point3, Rotation3, UnitQuaternion, Vector3, Vector6};
use std::hint::black_box;

fn so3(c: &mut Criterion) {
    let w = Vector3::new(0.3, -0.7, 1.1);
    let w2 = Vector3::new(-0.5, 0.2, 0.4);
    let (r, s) = (So3::exp(&w), So3::exp(&w2));
    let (q, q2) = (
        UnitQuaternion::from_scaled_axis(w),
        UnitQuaternion::from_scaled_axis(w2),
    );
    let (m, m2) = (
        Rotation3::from_scaled_axis(w),
        Rotation3::from_scaled_axis(w2),
    );

    let mut g = c.benchmark_group("so3/compose");
    g.bench_function("So3", |b| b.iter(|| black_box(&r).compose(black_box(&s))));
    g.bench_function("UnitQuaternion", |b| {
        b.iter(|| black_box(&q) * black_box(&q2))
    });
    g.bench_function("Rotation3", |b| b.iter(|| black_box(&m) * black_box(&m2)));
    g.finish();

    let mut g = c.benchmark_group("so3/inverse");
    g.bench_function("So3", |b| b.iter(|| black_box(&r).inverse()));
    g.bench_function("UnitQuaternion", |b| b.iter(|| black_box(&q).inverse()));
    g.bench_function("Rotation3", |b| b.iter(|| black_box(&m).inverse()));
    g.finish();

    let mut g = c.benchmark_group("so3/exp");
    g.bench_function("So3", |b| b.iter(|| So3::exp(black_box(&w))));
    g.bench_function("UnitQuaternion", |b| {
        b.iter(|| UnitQuaternion::from_scaled_axis(*black_box(&w)))
    });
    g.bench_function("Rotation3", |b| {
        b.iter(|| Rotation3::from_scaled_axis(*black_box(&w)))
    });
    g.finish();

    let mut g = c.benchmark_group("so3/log");
    g.bench_function("So3", |b| b.iter(|| black_box(&r).log()));
    g.bench_function("UnitQuaternion", |b| b.iter(|| black_box(&q).scaled_axis()));
    g.bench_function("Rotation3", |b| b.iter(|| black_box(&m).scaled_axis()));
    g.finish();

    let p = Vector3::new(0.4, -1.2, 2.5);
    let mut g = c.benchmark_group("so3/act");
    g.bench_function("So3", |b| b.iter(|| black_box(&r).act(black_box(&p))));
    g.bench_function("UnitQuaternion", |b| {
        b.iter(|| black_box(&q) * black_box(&p))
    });
    g.bench_function("Rotation3", |b| b.iter(|| black_box(&m) * black_box(&p)));
    g.finish();

    let mut g = c.benchmark_group("so3/adjoint");
    g.bench_function("Ad matrix", |b| b.iter(|| black_box(&r).adjoint()));
    g.bench_function("Ad apply", |b| {
        b.iter(|| black_box(&r).adjoint_apply(black_box(&w2)))
    });
    g.finish();

    let mut g = c.benchmark_group("so3/tangent");
    g.bench_function("dexp", |b| b.iter(|| So3::dexp_left(black_box(&w))));
    g.bench_function("dexp_inv", |b| b.iter(|| So3::dexp_left_inv(black_box(&w))));
    g.bench_function("dcay", |b| b.iter(|| So3::dcay_left(black_box(&w))));
    g.bench_function("dcay_inv", |b| b.iter(|| So3::dcay_left_inv(black_box(&w))));
    g.finish();
}

fn se3(c: &mut Criterion) {
    let a = Vector6::new(0.3, -0.7, 1.1, 1.0, 2.0, -0.5);
    let a2 = Vector6::new(-0.5, 0.2, 0.4, -1.0, 0.3, 0.8);
    let (g1, g2) = (Se3::exp(&a), Se3::exp(&a2));
    let (i1, i2): (Isometry3<f64>, Isometry3<f64>) = (g1.into(), g2.into());

    let mut g = c.benchmark_group("se3/compose");
    g.bench_function("Se3", |b| b.iter(|| black_box(&g1).compose(black_box(&g2))));
    g.bench_function("Isometry3", |b| b.iter(|| black_box(&i1) * black_box(&i2)));
    g.finish();

    let mut g = c.benchmark_group("se3/inverse");
    g.bench_function("Se3", |b| b.iter(|| black_box(&g1).inverse()));
    g.bench_function("Isometry3", |b| b.iter(|| black_box(&i1).inverse()));
    g.finish();

    let (p, pt) = (Vector3::new(0.4, -1.2, 2.5), Point3::new(0.4, -1.2, 2.5));
    let mut g = c.benchmark_group("se3/act");
    g.bench_function("Se3", |b| b.iter(|| black_box(&g1).act(black_box(&p))));
    g.bench_function("Isometry3", |b| b.iter(|| black_box(&i1) * black_box(&pt)));
    g.finish();

    let mut g = c.benchmark_group("se3/exp_log");
    g.bench_function("exp", |b| b.iter(|| Se3::exp(black_box(&a))));
    g.bench_function("log", |b| b.iter(|| black_box(&g1).log()));
    g.bench_function("cay", |b| b.iter(|| Se3::cay(black_box(&a))));
    g.finish();

    let mut g = c.benchmark_group("se3/adjoint");
    g.bench_function("Ad matrix", |b| b.iter(|| black_box(&g1).adjoint()));
    g.bench_function("Ad apply", |b| {
        b.iter(|| black_box(&g1).adjoint_apply(black_box(&a2)))
    });
    g.finish();

    let mut g = c.benchmark_group("se3/tangent");
    g.bench_function("dexp", |b| b.iter(|| Se3::dexp_left(black_box(&a))));
    g.bench_function("dexp_inv", |b| b.iter(|| Se3::dexp_left_inv(black_box(&a))));
    g.bench_function("dcay", |b| b.iter(|| Se3::dcay_left(black_box(&a))));
    g.bench_function("dcay_inv", |b| b.iter(|| Se3::dcay_left_inv(black_box(&a))));
    g.finish();
}

criterion_group!(benches, so3, se3);
criterion_main!(benches);
