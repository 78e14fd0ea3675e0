//! Generic properties of R̃_d, T R̃_d, the tangent lift and the cotangent lift, checked on every
//! group and τ map: the discretization axioms, round trips of every map with its inverse, the
//! tangent map against central differences, the cotangent map as its transpose, the commuting
//! diagrams, and the symplecticity of T*R̃_d⁻¹ followed by Φ̃.

use crate::common::{fd_body_velocity, fd_vector, omega};
use discretization::{phi, DiscretizationMap};
use lie_groups::testing::assert_small;
use lie_groups::{LieGroup, Tau, Vector};
use trivial_bundles::prelude::*;

fn rd<G: LieGroup, T: Tau<G>>(theta: f64) -> DiscretizationMap<T> {
    DiscretizationMap::<T>::new(theta).expect("θ ∈ [0, 1]")
}

fn tb_dist<G: LieGroup>(a: &TangentBundle<G>, b: &TangentBundle<G>) -> f64 {
    a.base()
        .matrix_distance(b.base())
        .max(a.fiber().sub(b.fiber()).norm_max())
}

fn cb_dist<G: LieGroup>(a: &CotangentBundle<G>, b: &CotangentBundle<G>) -> f64 {
    a.base()
        .matrix_distance(b.base())
        .max(a.fiber().sub(b.fiber()).norm_max())
}

fn four_dist<G: LieGroup>(g: (&G, &G), v: [(&G::Algebra, &G::Algebra); 3]) -> f64 {
    v.iter().fold(g.0.matrix_distance(g.1), |m, (a, b)| {
        m.max(a.sub(b).norm_max())
    })
}

/// (i) R̃_d(g, 0) = (g, g) and (ii) d/dt R̃²(g, tξ) − d/dt R̃¹(g, tξ) = ξ (body velocities, t = 0).
pub fn check_axioms<G: LieGroup, T: Tau<G>>(a: &G::Algebra, xi: &G::Algebra, theta: f64) {
    let map = rd::<G, T>(theta);
    let g = G::exp(a);
    let (g1, g2) = map.apply(&g, &G::Algebra::zeros(G::dim()));
    assert_small("R̃_d(g, 0)¹ = g", g1.matrix_distance(&g), 1e-15);
    assert_small("R̃_d(g, 0)² = g", g2.matrix_distance(&g), 1e-15);
    // body velocities relative to g, so that they are comparable: g⁻¹ d/dt R̃ⁱ(g, tξ)
    let v1 = fd_body_velocity::<G>(|t| g.inverse().compose(&map.apply(&g, &xi.scale(t)).0));
    let v2 = fd_body_velocity::<G>(|t| g.inverse().compose(&map.apply(&g, &xi.scale(t)).1));
    // FD error O(h²)·|ξ|³ + ε/h ≲ 1e-9 for |ξ| ≤ 2√n
    assert_small(
        "d/dt R̃² − d/dt R̃¹ = ξ",
        v2.sub(&v1).sub(xi).norm_max(),
        1e-8 * (1.0 + xi.norm()),
    );
}

/// R̃_d⁻¹ ∘ R̃_d = id near ξ = 0 and R̃_d ∘ R̃_d⁻¹ = id on pairs (g_k, g_k τ(Δ)).
pub fn check_inverse<G: LieGroup, T: Tau<G>>(a: &G::Algebra, xi: &G::Algebra, theta: f64) {
    let map = rd::<G, T>(theta);
    let g = G::exp(a);
    let (gk, gk1) = map.apply(&g, xi);
    let (g_back, xi_back) = map.inverse(&gk, &gk1).expect("inside the domain");
    let s = 1.0 + xi.norm() + a.norm();
    assert_small("R̃_d⁻¹ ∘ R̃_d: g", g_back.matrix_distance(&g), 1e-12 * s);
    assert_small("R̃_d⁻¹ ∘ R̃_d: ξ", xi_back.sub(xi).norm_max(), 1e-12 * s);
    let gk1 = gk.compose(&T::tau(xi));
    let (g, x) = map.inverse(&gk, &gk1).expect("inside the domain");
    let (hk, hk1) = map.apply(&g, &x);
    assert_small("R̃_d ∘ R̃_d⁻¹: g_k", hk.matrix_distance(&gk), 1e-12 * s);
    assert_small("R̃_d ∘ R̃_d⁻¹: g_{k+1}", hk1.matrix_distance(&gk1), 1e-12 * s);
}

/// T R̃_d against central differences of R̃_d along the curve s ↦ (g, ξ)·exp_{G⋉𝔤}(s(ξ̄, ξ̃)) (the
/// definition of the left-trivialized tangent vector (g, ξ, ξ̄, ξ̃), with the group structure of
/// `trivial-bundles`), and pr₁₂ ∘ T R̃_d = R̃_d ∘ pr₁₂.
pub fn check_tangent_map<G: LieGroup, T: Tau<G>>(x: &Ttg<G>, theta: f64) {
    let map = rd::<G, T>(theta);
    let base = x.base().clone();
    let dir = x.fiber().clone();
    let curve = |s: f64| base.compose(&TangentBundle::<G>::exp(&dir.scale(s)));
    let (k, k1) = map.tangent_map(x);
    let fd1 = fd_body_velocity::<G>(|s| {
        let c = curve(s);
        map.apply(c.base(), c.fiber()).0
    });
    let fd2 = fd_body_velocity::<G>(|s| {
        let c = curve(s);
        map.apply(c.base(), c.fiber()).1
    });
    let s = 1.0 + dir.norm() * (1.0 + x.xi().norm()).powi(2);
    assert_small(
        "T R̃_d = FD, first factor",
        k.fiber().sub(&fd1).norm_max(),
        1e-7 * s,
    );
    assert_small(
        "T R̃_d = FD, second factor",
        k1.fiber().sub(&fd2).norm_max(),
        1e-7 * s,
    );
    let (g1, g2) = map.apply(x.g(), x.xi());
    assert_small(
        "pr₁₂ ∘ T R̃_d = R̃_d ∘ pr₁₂",
        k.base()
            .matrix_distance(&g1)
            .max(k1.base().matrix_distance(&g2)),
        1e-14,
    );
}

/// (T R̃_d)⁻¹ ∘ T R̃_d = id, R̃_d^T⁻¹ ∘ R̃_d^T = id and the other way round; R̃_d^T = T R̃_d ∘ κ̃ covers
/// R̃_d ∘ pr₁₃.
pub fn check_tangent_lift<G: LieGroup, T: Tau<G>>(x: &Ttg<G>, theta: f64) {
    let map = rd::<G, T>(theta);
    let s = 1.0 + x.fiber().norm() + x.xi().norm();
    let (k, k1) = map.tangent_map(x);
    let y = map.tangent_map_inverse(&k, &k1).expect("inside the domain");
    let err = four_dist::<G>(
        (y.g(), x.g()),
        [
            (y.xi(), x.xi()),
            (y.xi_bar(), x.xi_bar()),
            (y.xi_tilde(), x.xi_tilde()),
        ],
    );
    assert_small("(T R̃_d)⁻¹ ∘ T R̃_d = id", err, 1e-11 * s * s);
    let (k, k1) = map.tangent_lift(x);
    let y = map
        .tangent_lift_inverse(&k, &k1)
        .expect("inside the domain");
    let err = four_dist::<G>(
        (y.g(), x.g()),
        [
            (y.xi(), x.xi()),
            (y.xi_bar(), x.xi_bar()),
            (y.xi_tilde(), x.xi_tilde()),
        ],
    );
    assert_small("(R̃_d^T)⁻¹ ∘ R̃_d^T = id", err, 1e-11 * s * s);
    let (m, m1) = map.tangent_lift(&y);
    assert_small(
        "R̃_d^T ∘ (R̃_d^T)⁻¹ = id",
        tb_dist(&m, &k).max(tb_dist(&m1, &k1)),
        1e-11 * s * s,
    );
    // the diagram of eq. 16: pr₁₂ ∘ R̃_d^T = R̃_d ∘ pr₁₃
    let p = x.pr_13();
    let (g1, g2) = map.apply(p.base(), p.fiber());
    assert_small(
        "pr₁₂ ∘ R̃_d^T = R̃_d ∘ pr₁₃",
        k.base()
            .matrix_distance(&g1)
            .max(k1.base().matrix_distance(&g2)),
        1e-14,
    );
    // and R̃_d^T is T R̃_d after κ̃
    let (n, n1) = map.tangent_map(&kappa(x));
    assert_small(
        "R̃_d^T = T R̃_d ∘ κ̃",
        tb_dist(&n, &k).max(tb_dist(&n1, &k1)),
        0.0,
    );
}

/// T*R̃_d is the transpose of T R̃_d: ⟨(μ₁, μ₂), T R̃_d v⟩ = ⟨T*R̃_d(μ₁, μ₂), v⟩; T*R̃_d⁻¹ inverts it.
pub fn check_cotangent_map<G: LieGroup, T: Tau<G>>(
    x: &Ttg<G>,
    mu1: &G::Algebra,
    mu2: &G::Algebra,
    theta: f64,
) {
    let map = rd::<G, T>(theta);
    let (k, k1) = map.tangent_map(x);
    let y = map.cotangent_map(x.base(), mu1, mu2);
    let lhs = mu1.dot(k.fiber()) + mu2.dot(k1.fiber());
    let rhs = y.mu().dot(x.xi_bar()) + y.nu().dot(x.xi_tilde());
    let s =
        (1.0 + mu1.norm() + mu2.norm()) * (1.0 + x.fiber().norm()) * (1.0 + x.xi().norm()).powi(2);
    assert_small("⟨μ, T R̃_d v⟩ = ⟨T*R̃_d μ, v⟩", (lhs - rhs).abs(), 1e-13 * s);
    assert_small(
        "T*R̃_d keeps the base point",
        y.g()
            .matrix_distance(x.g())
            .max(y.xi().sub(x.xi()).norm_max()),
        0.0,
    );
    let (c, c1) = map.cotangent_map_inverse(&y).expect("inside the domain");
    assert_small(
        "T*R̃_d⁻¹ ∘ T*R̃_d = id",
        c.fiber()
            .sub(mu1)
            .norm_max()
            .max(c1.fiber().sub(mu2).norm_max()),
        1e-12 * s,
    );
    assert_small(
        "T*R̃_d⁻¹ covers R̃_d",
        c.base()
            .matrix_distance(k.base())
            .max(c1.base().matrix_distance(k1.base())),
        1e-14,
    );
}

/// R̃_d^{T*} and its inverse round-trip, the diagram of eq. 17 commutes, and Φ̃ is an involution.
pub fn check_cotangent_lift<G: LieGroup, T: Tau<G>>(x: &Ttsg<G>, theta: f64) {
    let map = rd::<G, T>(theta);
    let s = (1.0 + x.xi().norm()).powi(2) * (1.0 + x.mu().norm() + x.nu().norm());
    let (k, k1) = map.cotangent_lift(x).expect("inside the domain");
    let y = map
        .cotangent_lift_inverse(&k, &k1)
        .expect("inside the domain");
    let err = four_dist::<G>(
        (y.g(), x.g()),
        [(y.mu(), x.mu()), (y.xi(), x.xi()), (y.nu(), x.nu())],
    );
    assert_small("(R̃_d^{T*})⁻¹ ∘ R̃_d^{T*} = id", err, 1e-11 * s);
    let (m, m1) = map.cotangent_lift(&y).expect("inside the domain");
    assert_small(
        "R̃_d^{T*} ∘ (R̃_d^{T*})⁻¹ = id",
        cb_dist(&m, &k).max(cb_dist(&m1, &k1)),
        1e-11 * s,
    );
    let p = x.pr_13();
    let (g1, g2) = map.apply(p.base(), p.fiber());
    assert_small(
        "pr₁ × pr₁ ∘ R̃_d^{T*} = R̃_d ∘ pr₁₃",
        k.base()
            .matrix_distance(&g1)
            .max(k1.base().matrix_distance(&g2)),
        1e-14,
    );
    let (a, b) = phi(&k, &k1);
    let (a, b) = phi(&a, &b);
    assert_small("Φ̃ ∘ Φ̃ = id", cb_dist(&a, &k).max(cb_dist(&b, &k1)), 0.0);
    // and it is the composition of eq. 17
    let (c, c1) = map
        .cotangent_map_inverse(&alpha(x))
        .expect("inside the domain");
    let (c, c1) = phi(&c, &c1);
    assert_small(
        "R̃_d^{T*} = Φ̃ ∘ T*R̃_d⁻¹ ∘ α̃",
        cb_dist(&c, &k).max(cb_dist(&c1, &k1)),
        0.0,
    );
}

/// A tangent vector (X, δM) of T*(G ⋉ 𝔤): body velocity X ∈ 𝔤 ⋉ 𝔤 and covector variation δM.
type TangentVector<'a, G> = (
    &'a Pair<<G as LieGroup>::Algebra, <G as LieGroup>::Algebra>,
    &'a Pair<<G as LieGroup>::Algebra, <G as LieGroup>::Algebra>,
);

/// Φ̃ ∘ T*R̃_d⁻¹ is symplectic from the canonical form of T*(G ⋉ 𝔤) to the twisted form ω₂ − ω₁ of
/// T*G × T*G: the pull-back is checked on two random tangent vectors by central differences of the
/// map along s ↦ (x exp(s X), M + s δM) in T*(G ⋉ 𝔤) = (G ⋉ 𝔤) ⋉ (𝔤* ⋉ 𝔤*).
pub fn check_symplectic<G: LieGroup, T: Tau<G>>(
    y: &Tstg<G>,
    v1: TangentVector<'_, G>,
    v2: TangentVector<'_, G>,
    theta: f64,
) {
    let map = rd::<G, T>(theta);
    let (x, m) = (y.base().clone(), y.fiber().clone());
    let image = |v: TangentVector<'_, G>, s: f64| {
        let z = CotangentBundle::from_parts(
            x.compose(&TangentBundle::<G>::exp(&v.0.scale(s))),
            m.axpy(s, v.1),
        );
        let (c, c1) = map.cotangent_map_inverse(&z).expect("inside the domain");
        phi(&c, &c1)
    };
    let push = |v| {
        let xi1 = fd_body_velocity::<G>(|s| image(v, s).0.base().clone());
        let xi2 = fd_body_velocity::<G>(|s| image(v, s).1.base().clone());
        let dmu1 = fd_vector(|s| image(v, s).0.fiber().clone());
        let dmu2 = fd_vector(|s| image(v, s).1.fiber().clone());
        (xi1, dmu1, xi2, dmu2)
    };
    let (a1, da1, a2, da2) = push(v1);
    let (b1, db1, b2, db2) = push(v2);
    let (k, k1) = image(v1, 0.0);
    let twisted = omega::<G>(k1.fiber(), (&a2, &da2), (&b2, &db2))
        - omega::<G>(k.fiber(), (&a1, &da1), (&b1, &db1));
    let canonical = omega::<TangentBundle<G>>(&m, (v1.0, v1.1), (v2.0, v2.1));
    let s = (1.0 + m.norm())
        * (1.0 + v1.0.norm() + v1.1.norm())
        * (1.0 + v2.0.norm() + v2.1.norm())
        * (1.0 + x.fiber().norm()).powi(3);
    assert_small(
        "(Φ̃ ∘ T*R̃_d⁻¹)*(ω₂ − ω₁) = ω_{T*(G⋉𝔤)}",
        (twisted - canonical).abs(),
        1e-7 * s,
    );
}

macro_rules! maps_suite {
    ($name:ident, $G:ty, $T:ty, $scale:expr) => {
        mod $name {
            use super::*;
            use lie_groups::testing::algebra;
            use proptest::prelude::*;
            type G = $G;
            type A = <G as LieGroup>::Algebra;

            fn theta() -> impl Strategy<Value = f64> {
                prop_oneof![Just(0.0), Just(0.5), Just(1.0), 0.0..1.0f64]
            }
            fn ttg(s: f64) -> impl Strategy<Value = Ttg<G>> {
                (algebra::<G>(1.0), algebra::<G>(s), algebra::<G>(1.0), algebra::<G>(1.0))
                    .prop_map(|(a, b, c, d): (A, A, A, A)| Ttg::new(G::exp(&a), b, c, d))
            }
            fn ttsg(s: f64) -> impl Strategy<Value = Ttsg<G>> {
                (algebra::<G>(1.0), algebra::<G>(1.0), algebra::<G>(s), algebra::<G>(1.0))
                    .prop_map(|(a, b, c, d): (A, A, A, A)| Ttsg::new(G::exp(&a), b, c, d))
            }
            fn pair() -> impl Strategy<Value = Pair<A, A>> {
                (algebra::<G>(1.0), algebra::<G>(1.0)).prop_map(|(a, b)| Pair::new(a, b))
            }

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(32))]
                #[test]
                fn discretization_axioms_hold(a in algebra::<G>(1.0), xi in algebra::<G>($scale), th in theta()) {
                    check_axioms::<G, $T>(&a, &xi, th);
                }
                #[test]
                fn discretization_map_and_inverse_round_trip(a in algebra::<G>(1.0), xi in algebra::<G>($scale), th in theta()) {
                    check_inverse::<G, $T>(&a, &xi, th);
                }
                #[test]
                fn tangent_map_matches_finite_differences(x in ttg($scale), th in theta()) {
                    check_tangent_map::<G, $T>(&x, th);
                }
                #[test]
                fn tangent_lift_and_inverse_round_trip_and_cover_rd(x in ttg($scale), th in theta()) {
                    check_tangent_lift::<G, $T>(&x, th);
                }
                #[test]
                fn cotangent_map_is_transpose_of_tangent_map(x in ttg($scale), m1 in algebra::<G>(1.0), m2 in algebra::<G>(1.0), th in theta()) {
                    check_cotangent_map::<G, $T>(&x, &m1, &m2, th);
                }
                #[test]
                fn cotangent_lift_and_inverse_round_trip_and_cover_rd(x in ttsg($scale), th in theta()) {
                    check_cotangent_lift::<G, $T>(&x, th);
                }
                #[test]
                fn twisted_cotangent_map_is_symplectic(y in ttg($scale), m in pair(), v1 in (pair(), pair()), v2 in (pair(), pair()), th in theta()) {
                    let z = Tstg::<G>::new(y.g().clone(), y.xi().clone(), m.a, m.b);
                    check_symplectic::<G, $T>(&z, (&v1.0, &v1.1), (&v2.0, &v2.1), th);
                }
            }
        }
    };
}

use lie_groups::{Cayley, ExpMap, Se2, Se3, So3, SoN};

maps_suite!(so3_exp, So3, ExpMap, 1.0);
maps_suite!(so3_cayley, So3, Cayley, 1.0);
maps_suite!(se3_exp, Se3, ExpMap, 1.0);
maps_suite!(se3_cayley, Se3, Cayley, 1.0);
maps_suite!(se2_exp, Se2, ExpMap, 1.0);
maps_suite!(se2_cayley, Se2, Cayley, 1.0);
maps_suite!(so_n3_exp, SoN<3>, ExpMap, 1.0);
maps_suite!(so_n3_cayley, SoN<3>, Cayley, 1.0);
