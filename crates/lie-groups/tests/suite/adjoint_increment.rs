//! `Tau::tau_adjoint_increment(ζ, v) = (Ad_{τ(ζ)} − I) v`, the velocity increment of the
//! Euler–Poincaré step, on every group with closed forms (SO(3), SE(3), SE(2), the composite
//! groups, ℝⁿ) and both τ maps:
//!
//! - at moderate ζ it is `Ad_{τ(ζ)} v − v` with Ad by matrix conjugation
//!   (`matrix_path::adjoint`, independent of the closed forms);
//! - at |ζ| = 1e-8 it keeps its accuracy relative to its own size O(|ζ||v|): against the series
//!   `ad_ζ v + ½ ad_ζ² v` (both τ are exp up to O(ζ³), which leaves 1e-16 relative there) within
//!   1e-13 |ζ||v|, where the matrix form `Ad_{τ(ζ)} v − v` is off by ε|v| ≈ 1e-8 |ζ||v|;
//! - on SO(3) (Ad orthogonal) it is `tau_coadjoint_increment(−ζ, v)`.

use lie_groups::testing::{algebra, assert_small};
use lie_groups::{
    matrix_path, Cayley, ExpMap, LieGroup, Operator, Power, Product, Rn, Se2, Se3, So3, Tau, Vector,
};
use proptest::prelude::*;

/// ζ rescaled to ‖ζ‖_max = size (ζ = 0 stays 0).
fn sized<G: LieGroup>(z: &G::Algebra, size: f64) -> G::Algebra {
    let n = z.norm_max();
    if n == 0.0 {
        z.clone()
    } else {
        z.scale(size / n)
    }
}

/// The second-order series `ad_ζ v + ½ ad_ζ(ad_ζ v)` of `(Ad_{τ(ζ)} − I) v`.
fn series<G: LieGroup>(z: &G::Algebra, v: &G::Algebra) -> G::Algebra {
    let first = G::bracket(z, v);
    first.axpy(0.5, &G::bracket(z, &first))
}

fn check<G: LieGroup, T: Tau<G>>(z: &G::Algebra, v: &G::Algebra) {
    // moderate ζ: against Ad by matrix conjugation
    let inc = T::tau_adjoint_increment(z, v);
    let plain = matrix_path::adjoint(&T::tau(z)).apply(v).sub(v);
    let s = (1.0 + z.norm_max()).powi(2) * (1.0 + v.norm_max());
    assert_small(
        "(Ad_{τ(ζ)} − I) v = Ad_{τ(ζ)} v − v (matrix conjugation)",
        inc.sub(&plain).norm_max(),
        1e-14 * s,
    );
    // tiny ζ: relative to |ζ||v|, against the series
    let tiny = sized::<G>(z, 1e-8);
    let size = tiny.norm_max() * v.norm_max();
    assert_small(
        "(Ad_{τ(ζ)} − I) v at |ζ| = 1e-8, relative to |ζ||v|",
        T::tau_adjoint_increment(&tiny, v)
            .sub(&series::<G>(&tiny, v))
            .norm_max(),
        1e-13 * size,
    );
}

macro_rules! suite {
    ($name:ident, $G:ty) => {
        mod $name {
            use super::*;
            type G = $G;
            proptest! {
                #![proptest_config(ProptestConfig::with_cases(64))]
                #[test]
                fn exp_increment_is_the_adjoint_less_identity_to_its_own_precision(
                    z in algebra::<G>(1.5), v in algebra::<G>(2.0)
                ) {
                    check::<G, ExpMap>(&z, &v);
                }
                #[test]
                fn cayley_increment_is_the_adjoint_less_identity_to_its_own_precision(
                    z in algebra::<G>(1.5), v in algebra::<G>(2.0)
                ) {
                    check::<G, Cayley>(&z, &v);
                }
            }
        }
    };
}

suite!(so3, So3);
suite!(se3, Se3);
suite!(se2, Se2);
suite!(so3_r3, Product<So3, Rn<3>>);
suite!(se2_so3, Product<Se2, So3>);
suite!(so3_cubed, Power<So3, 3>);
suite!(r3, Rn<3>);

/// On SO(3) Ad_R = R is orthogonal, so `Ad_{τ(ζ)} = Ad*_{τ(ζ)}⁻¹ = Ad*_{τ(−ζ)}`: the adjoint
/// increment is the coadjoint one at −ζ, for both τ (to the rounding of the two forms).
#[test]
fn so3_adjoint_increment_is_the_coadjoint_increment_at_minus_zeta() {
    use nalgebra::Vector3;
    let v = Vector3::new(0.7, -1.2, 0.4);
    for size in [0.0, 1e-9, 1e-3, 0.3, 1.0, 2.5] {
        let z = Vector3::new(0.3, -0.5, 0.8).normalize() * size;
        for (name, a, b) in [
            (
                "exp",
                <ExpMap as Tau<So3>>::tau_adjoint_increment(&z, &v),
                <ExpMap as Tau<So3>>::tau_coadjoint_increment(&-z, &v),
            ),
            (
                "cayley",
                <Cayley as Tau<So3>>::tau_adjoint_increment(&z, &v),
                <Cayley as Tau<So3>>::tau_coadjoint_increment(&-z, &v),
            ),
        ] {
            assert_small(
                &format!("{name}, |ζ| = {size}"),
                (a - b).amax(),
                8.0 * f64::EPSILON * size * v.amax(),
            );
        }
    }
}

/// Why the closed forms: the matrix form `Ad_{τ(ζ)} v − v` rounds at ε|v| whatever ζ, so at
/// |ζ| = 1e-8 it misses the series by about 1e-8 |ζ||v| — far outside the 1e-13 the closed forms
/// meet (`check`). On SO(3) and SE(3), over a fixed set of directions.
#[test]
fn the_matrix_form_loses_the_relative_accuracy_at_small_steps() {
    fn worst<G: LieGroup, T: Tau<G>>(dirs: &[G::Algebra], v: &G::Algebra) -> f64 {
        dirs.iter()
            .map(|d| {
                let z = sized::<G>(d, 1e-8);
                let plain = T::tau(&z).adjoint_apply(v).sub(v);
                plain.sub(&series::<G>(&z, v)).norm_max() / (z.norm_max() * v.norm_max())
            })
            .fold(0.0, f64::max)
    }
    use nalgebra::{Vector3, Vector6};
    let so3: Vec<Vector3<f64>> = (0..8)
        .map(|k| Vector3::new(1.0 + k as f64, -0.3 * k as f64, 0.7))
        .collect();
    let se3: Vec<Vector6<f64>> = (0..8)
        .map(|k| Vector6::new(1.0, -0.3 * k as f64, 0.7, 0.2, k as f64, -0.5))
        .collect();
    let v3 = Vector3::new(0.7, -1.2, 0.4);
    let v6 = Vector6::new(0.7, -1.2, 0.4, 1.1, 0.3, -0.9);
    for (name, w) in [
        ("SO(3) exp", worst::<So3, ExpMap>(&so3, &v3)),
        ("SO(3) cayley", worst::<So3, Cayley>(&so3, &v3)),
        ("SE(3) exp", worst::<Se3, ExpMap>(&se3, &v6)),
        ("SE(3) cayley", worst::<Se3, Cayley>(&se3, &v6)),
    ] {
        assert!(w > 1e-10, "{name}: the matrix form at {w:e} relative");
    }
}
