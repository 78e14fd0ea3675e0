//! tr_TG (§1.1) is a group isomorphism for matrix groups: the canonical TG product
//! `u_g v_h = (u h + g v)_{gh}` and inverse `(−g⁻¹ u g⁻¹)_{g⁻¹}` go over to the semidirect product
//! of [`TangentBundle`], and tr_TG⁻¹ inverts it.

use lie_groups::testing::algebra;
use lie_groups::{LieGroup, Se3, So3};
use proptest::prelude::*;
use trivial_bundles::trivialization::{tr_tg, tr_tg_inv, MatrixTangent};
use trivial_bundles::TangentBundle;

/// Round-off bound: products of three m×m matrices with entries ≤ a few units (observed ~1e-15).
const TOL: f64 = 1e-12;

fn tangent<G: LieGroup>() -> impl Strategy<Value = MatrixTangent> {
    algebra::<TangentBundle<G>>(1.0).prop_map(|a| tr_tg_inv(&TangentBundle::<G>::exp(&a)))
}

fn check_isomorphism<G: LieGroup>(u: &MatrixTangent, v: &MatrixTangent) {
    let (tu, tv) = (tr_tg::<G>(u).unwrap(), tr_tg::<G>(v).unwrap());
    let product = tr_tg::<G>(&u.compose(v)).expect("u_g v_h ∈ T_{gh} G");
    assert!(
        product.matrix_distance(&tu.compose(&tv)) < TOL,
        "tr(u v) ≠ tr(u) tr(v)"
    );
    let inverse = tr_tg::<G>(&u.inverse().unwrap()).expect("(u_g)⁻¹ ∈ T_{g⁻¹} G");
    assert!(
        inverse.matrix_distance(&tu.inverse()) < TOL,
        "tr(u⁻¹) ≠ tr(u)⁻¹"
    );
    let back = tr_tg_inv(&tu);
    let d = (&back.g - &u.g).norm_max().max((&back.u - &u.u).norm_max());
    assert!(d < TOL, "tr⁻¹(tr u) ≠ u");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn tr_tg_is_a_group_isomorphism_so3(u in tangent::<So3>(), v in tangent::<So3>()) {
        check_isomorphism::<So3>(&u, &v);
    }
    #[test]
    fn tr_tg_is_a_group_isomorphism_se3(u in tangent::<Se3>(), v in tangent::<Se3>()) {
        check_isomorphism::<Se3>(&u, &v);
    }
}

#[test]
fn tr_tg_rejects_vectors_outside_the_tangent_space() {
    let u = tr_tg_inv(&TangentBundle::<So3>::exp(&trivial_bundles::Pair::new(
        nalgebra::Vector3::new(0.1, 0.2, 0.3),
        nalgebra::Vector3::new(1.0, 0.0, -1.0),
    )));
    let mut bad = u.clone();
    bad.u = &bad.g * 1.0; // g⁻¹ u = I is not skew
    assert!(tr_tg::<So3>(&bad).is_err());
    let mut bad = u.clone();
    bad.g[(0, 0)] = 2.0; // not a rotation
    assert!(tr_tg::<So3>(&bad).is_err());
    assert!(tr_tg::<So3>(&u).is_ok());
}

// ---------------------------------------------------------------------------------------------
// T*G
// ---------------------------------------------------------------------------------------------

use lie_groups::{DenseMatrix, Se2, SoN};
use trivial_bundles::trivialization::{tr_tstar_g, tr_tstar_g_inv, MatrixCotangent};
use trivial_bundles::CotangentBundle;

/// A covector with a component in the annihilator of T_g G added (a random matrix minus the
/// representative of its pairings with T_g G), which the trivialization must not see.
fn cotangent<G: LieGroup>() -> impl Strategy<Value = MatrixCotangent> {
    (
        algebra::<CotangentBundle<G>>(1.0),
        proptest::collection::vec(-1.0..1.0f64, 64),
    )
        .prop_map(|(a, noise)| {
            let mut c = tr_tstar_g_inv(&CotangentBundle::<G>::exp(&a));
            let m = c.g.nrows();
            let n = G::dim();
            // the component of a random matrix orthogonal to 𝔤 (Frobenius), moved to T*_g
            let r = faer::Mat::from_fn(m, m, |i, j| noise[(i * m + j) % 64]);
            let probe = MatrixCotangent {
                g: c.g.clone(),
                p: r.clone(),
            };
            let mu_r = lie_groups::Vector::from_fn(n, |i| {
                probe.pair(
                    &(&c.g * G::hat(&<G::Algebra as lie_groups::Vector>::basis(n, i)).to_mat()),
                )
            });
            let along = tr_tstar_g_inv(&CotangentBundle::<G>::from_parts(
                tr_tstar_g::<G>(&c).unwrap().base().clone(),
                mu_r,
            ));
            c.p = &c.p + (&r - &along.p);
            c
        })
}

fn check_cotangent_isomorphism<G: LieGroup>(p: &MatrixCotangent, q: &MatrixCotangent) {
    let (tp, tq) = (tr_tstar_g::<G>(p).unwrap(), tr_tstar_g::<G>(q).unwrap());
    let product = tr_tstar_g::<G>(&p.compose(q).unwrap()).unwrap();
    assert!(
        product.matrix_distance(&tp.compose(&tq)) < TOL,
        "tr(p q) ≠ tr(p) tr(q)"
    );
    let inverse = tr_tstar_g::<G>(&p.inverse().unwrap()).unwrap();
    assert!(
        inverse.matrix_distance(&tp.inverse()) < TOL,
        "tr(p⁻¹) ≠ tr(p)⁻¹"
    );
    // tr⁻¹ ∘ tr keeps every pairing with T_g G (it drops the annihilator part only)
    let back = tr_tstar_g_inv(&tp);
    let n = G::dim();
    for i in 0..n {
        let u = &p.g * G::hat(&<G::Algebra as lie_groups::Vector>::basis(n, i)).to_mat();
        assert!(
            (back.pair(&u) - p.pair(&u)).abs() < TOL,
            "⟨tr⁻¹ tr p, g Ê{i}⟩"
        );
    }
    assert!((&back.g - &p.g).norm_max() < TOL);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn tr_tstar_g_is_a_group_isomorphism_so3(p in cotangent::<So3>(), q in cotangent::<So3>()) {
        check_cotangent_isomorphism::<So3>(&p, &q);
    }
    #[test]
    fn tr_tstar_g_is_a_group_isomorphism_se3(p in cotangent::<Se3>(), q in cotangent::<Se3>()) {
        check_cotangent_isomorphism::<Se3>(&p, &q);
    }
    #[test]
    fn tr_tstar_g_is_a_group_isomorphism_se2(p in cotangent::<Se2>(), q in cotangent::<Se2>()) {
        check_cotangent_isomorphism::<Se2>(&p, &q);
    }
    #[test]
    fn tr_tstar_g_is_a_group_isomorphism_so4(p in cotangent::<SoN<4>>(), q in cotangent::<SoN<4>>()) {
        check_cotangent_isomorphism::<SoN<4>>(&p, &q);
    }
}

/// The paper's printed law `(g, μ)(h, ν) = (gh, Ad*_{h⁻¹}μ + ν)` read with Ad* as the dual map
/// (the crate's convention) is not the image of the canonical product: a negative control that
/// the isomorphism test above can tell the two apart.
#[test]
fn the_dual_map_reading_of_the_printed_law_is_not_the_canonical_product() {
    let a = CotangentBundle::<So3>::from_parts(
        So3::exp(&nalgebra::Vector3::new(0.3, -0.8, 0.5)),
        nalgebra::Vector3::new(1.0, 0.2, -0.4),
    );
    let b = CotangentBundle::<So3>::from_parts(
        So3::exp(&nalgebra::Vector3::new(-0.6, 0.1, 0.9)),
        nalgebra::Vector3::new(0.3, -1.1, 0.7),
    );
    let canonical =
        tr_tstar_g::<So3>(&tr_tstar_g_inv(&a).compose(&tr_tstar_g_inv(&b)).unwrap()).unwrap();
    let printed = b.base().inverse().coadjoint_apply(a.fiber()) + b.fiber();
    let ours = b.base().coadjoint_apply(a.fiber()) + b.fiber();
    assert!((canonical.fiber() - ours).amax() < TOL);
    assert!((canonical.fiber() - printed).amax() > 0.1);
}

#[test]
fn tr_tstar_g_rejects_points_off_the_group_and_non_finite_covectors() {
    let c = tr_tstar_g_inv(&CotangentBundle::<So3>::from_parts(
        So3::exp(&nalgebra::Vector3::new(0.1, 0.2, 0.3)),
        nalgebra::Vector3::new(1.0, 0.0, -1.0),
    ));
    assert!(tr_tstar_g::<So3>(&c).is_ok());
    let mut bad = c.clone();
    bad.g[(0, 0)] = 2.0;
    assert!(tr_tstar_g::<So3>(&bad).is_err());
    let mut bad = c.clone();
    bad.p[(1, 2)] = f64::NAN;
    assert!(tr_tstar_g::<So3>(&bad).is_err());
    let mut bad = c;
    bad.p = faer::Mat::zeros(2, 2);
    assert!(tr_tstar_g::<So3>(&bad).is_err());
}
