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
