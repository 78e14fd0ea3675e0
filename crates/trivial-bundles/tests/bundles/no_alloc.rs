//! compose, inverse, Ad and Ad* of the bundles allocate nothing when the base group is fixed-size
//! (SO(3), SE(3)), including the nested TTG, TT*G, T*TG, T*T*G: counted by a global allocator.

use lie_groups::testing::{allocations, CountingAllocator};
use lie_groups::{LieGroup, Se3, So3};
use nalgebra::{Vector3, Vector6};
use trivial_bundles::prelude::*;

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

fn assert_hot_paths_allocate_nothing<B: LieGroup>(x: &B, y: &B, v: &B::Algebra) {
    let n = allocations(|| {
        std::hint::black_box(x.compose(y));
        std::hint::black_box(x.inverse());
        std::hint::black_box(x.adjoint_apply(v));
        std::hint::black_box(x.coadjoint_apply(v));
        std::hint::black_box(B::bracket(v, v));
        std::hint::black_box(B::ad_dual_apply(v, v));
    });
    assert_eq!(n, 0, "{} hot paths allocated {n} times", B::name());
    // the counter does see allocations: the dense operator Ad_x is a heap-allocated faer matrix
    assert!(allocations(|| drop(std::hint::black_box(x.adjoint()))) > 0);
}

fn check<G: LieGroup + Copy>(a: [G::Algebra; 4])
where
    G::Algebra: Copy,
{
    let (g, h) = (G::exp(&a[0]), G::exp(&a[1]));
    assert_hot_paths_allocate_nothing(
        &TangentBundle::from_parts(g, a[2]),
        &TangentBundle::from_parts(h, a[3]),
        &Pair::new(a[0], a[1]),
    );
    assert_hot_paths_allocate_nothing(
        &CotangentBundle::from_parts(g, a[2]),
        &CotangentBundle::from_parts(h, a[3]),
        &Pair::new(a[0], a[1]),
    );
    let v = Pair::new(Pair::new(a[0], a[1]), Pair::new(a[2], a[3]));
    assert_hot_paths_allocate_nothing(
        &Ttg::<G>::new(g, a[2], a[3], a[1]),
        &Ttg::<G>::new(h, a[3], a[2], a[0]),
        &v,
    );
    assert_hot_paths_allocate_nothing(
        &Ttsg::<G>::new(g, a[2], a[3], a[1]),
        &Ttsg::<G>::new(h, a[3], a[2], a[0]),
        &v,
    );
    assert_hot_paths_allocate_nothing(
        &Tstg::<G>::new(g, a[2], a[3], a[1]),
        &Tstg::<G>::new(h, a[3], a[2], a[0]),
        &v,
    );
    assert_hot_paths_allocate_nothing(
        &Tstsg::<G>::new(g, a[2], a[3], a[1]),
        &Tstsg::<G>::new(h, a[3], a[2], a[0]),
        &v,
    );
}

#[test]
fn bundle_products_inverses_and_adjoints_allocate_nothing_over_fixed_size_groups() {
    let v3 = Vector3::new;
    check::<So3>([
        v3(0.3, -0.7, 1.1),
        v3(-0.5, 0.2, 0.4),
        v3(1.0, 2.0, -0.5),
        v3(-0.3, 0.1, 0.9),
    ]);
    let v6 = Vector6::new;
    check::<Se3>([
        v6(0.3, -0.7, 1.1, 1.0, 0.5, -2.0),
        v6(-0.5, 0.2, 0.4, 0.3, -0.1, 0.8),
        v6(1.0, 2.0, -0.5, 0.2, 0.2, 0.1),
        v6(-0.3, 0.1, 0.9, -1.0, 0.4, 0.6),
    ]);
}
