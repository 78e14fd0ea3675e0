//! Micro-benchmarks of §3: R̃_d, its tangent and cotangent lifts and their inverses on SO(3) and
//! SE(3), for τ = exp and τ = Cayley and θ ∈ {0, ½}. Everything in the hot path works on the base
//! group's stack types (nalgebra vectors and matrices), so no map allocates.
//!
//! Run: `cargo bench -p lie-integrators --bench discretization` (add `-- --quick` for a smoke run).

use criterion::{criterion_group, criterion_main, Criterion};
use discretization::DiscretizationMap;
use lie_groups::{Cayley, ExpMap, LieGroup, Se3, So3, Tau};
use nalgebra::{Vector3, Vector6};
use std::hint::black_box;
use trivial_bundles::prelude::*;

fn bench_maps<G: LieGroup + Copy, T: Tau<G>>(
    c: &mut Criterion,
    label: &str,
    theta: f64,
    a: [G::Algebra; 4],
) where
    G::Algebra: Copy,
{
    let rd = DiscretizationMap::<T>::new(theta).expect("θ ∈ [0, 1]");
    let g = G::exp(&a[0]);
    let (gk, gk1) = rd.apply(&g, &a[1]);
    let x = Ttg::<G>::new(g, a[2], a[1], a[3]);
    let (tk, tk1) = rd.tangent_lift(&x);
    let y = Ttsg::<G>::new(g, a[3], a[1], a[2]);
    let (ck, ck1) = rd.cotangent_lift(&y).expect("inside the domain");

    let mut grp = c.benchmark_group(format!("{label}/{}/theta={theta}", T::NAME));
    grp.bench_function("R_d", |b| {
        b.iter(|| rd.apply(black_box(&g), black_box(&a[1])))
    });
    grp.bench_function("R_d inverse", |b| {
        b.iter(|| rd.inverse(black_box(&gk), black_box(&gk1)))
    });
    grp.bench_function("tangent lift", |b| {
        b.iter(|| rd.tangent_lift(black_box(&x)))
    });
    grp.bench_function("tangent lift inverse", |b| {
        b.iter(|| rd.tangent_lift_inverse(black_box(&tk), black_box(&tk1)))
    });
    grp.bench_function("cotangent lift", |b| {
        b.iter(|| rd.cotangent_lift(black_box(&y)))
    });
    grp.bench_function("cotangent lift inverse", |b| {
        b.iter(|| rd.cotangent_lift_inverse(black_box(&ck), black_box(&ck1)))
    });
    grp.finish();
}

fn so3(c: &mut Criterion) {
    let a = [
        Vector3::new(0.3, -0.2, 0.5),
        Vector3::new(0.1, 0.05, -0.08),
        Vector3::new(1.0, 0.5, -0.3),
        Vector3::new(0.2, -0.7, 0.4),
    ];
    for theta in [0.0, 0.5] {
        bench_maps::<So3, ExpMap>(c, "SO(3)", theta, a);
        bench_maps::<So3, Cayley>(c, "SO(3)", theta, a);
    }
}

fn se3(c: &mut Criterion) {
    let a = [
        Vector6::new(0.3, -0.2, 0.5, 1.0, 2.0, -1.0),
        Vector6::new(0.1, 0.05, -0.08, 0.02, -0.1, 0.05),
        Vector6::new(1.0, 0.5, -0.3, 0.2, 0.1, 0.0),
        Vector6::new(0.2, -0.7, 0.4, -0.3, 0.6, 0.1),
    ];
    for theta in [0.0, 0.5] {
        bench_maps::<Se3, ExpMap>(c, "SE(3)", theta, a);
        bench_maps::<Se3, Cayley>(c, "SE(3)", theta, a);
    }
}

criterion_group!(benches, so3, se3);
criterion_main!(benches);
