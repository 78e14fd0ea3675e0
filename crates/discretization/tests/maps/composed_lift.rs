//! The fused θ-formulas of `DiscretizationMap` and `RightDiscretizationMap` against the default
//! path — every `LiftedMap` component composed from the paper's lifts (κ̃, α̃, Φ̃, the products of
//! TG and T*G) of the map's factors — on every group, τ ∈ {exp, Cayley}, θ ∈ {0, ¼, ½, 1} and
//! side, written once (a new group is one line).
//!
//! Two default paths are compared with the fused one:
//! - [`Composed`] of the θ-map: the composition with the closed-form tangents of τ; the values
//!   agree to round-off (≤ 1e-14 relative; measured ≤ 2e-16), the Newton derivatives to the
//!   accuracy of their differences (≤ 1e-7; measured ≤ 1.1e-13 where the fused derivative is
//!   exact);
//! - [`FactorsOnly`]: nothing but `a(ξ) = τ(−θξ)`, `b(ξ) = τ((1−θ)ξ)` and the side — what a user
//!   writes — so the tangents come from differences too (values ≤ 1e-12 relative; measured
//!   ≤ 9e-14), and every descriptor is measured: it must be the θ-family's exact one.

use discretization::{
    Composed, Discretization, DiscretizationMap, LiftedMap, RightDiscretizationMap, Side,
    ThetaFamily,
};
use lie_groups::{Cayley, ExpMap, LieGroup, Operator, Product, Se2, Se3, So3, SoN, Tau, Vector};

const THETAS: [f64; 4] = [0.0, 0.25, 0.5, 1.0];
const SAMPLES: usize = 6;

/// A map given by its factors and side alone: every other method is the provided one.
#[derive(Debug, Clone, Copy)]
struct FactorsOnly<M>(M);

impl<G: LieGroup, M: Discretization<G>> Discretization<G> for FactorsOnly<M> {
    fn first_factor(&self, xi: &G::Algebra) -> G {
        self.0.first_factor(xi)
    }
    fn second_factor(&self, xi: &G::Algebra) -> G {
        self.0.second_factor(xi)
    }
    fn side(&self) -> Side {
        self.0.side()
    }
}
impl<G: LieGroup, M: Discretization<G>> LiftedMap<G> for FactorsOnly<M> {}

/// A deterministic stream of algebra elements with entries in [−s, s] (a linear congruential
/// generator: the failing sample is reproducible).
struct Samples(u64);

impl Samples {
    fn next<G: LieGroup>(&mut self, s: f64) -> G::Algebra {
        G::Algebra::from_fn(G::dim(), |_| {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            s * (2.0 * (self.0 >> 11) as f64 / (1u64 << 53) as f64 - 1.0)
        })
    }
}

fn op_distance<G: LieGroup>(a: &G::Operator, b: &G::Operator) -> f64 {
    a.add(&b.scale(-1.0)).norm_max()
}

/// Where the fused Newton derivatives are exact: ∂μ̄/∂η needs τ's `∂/∂ζ (d^{L*}τ_ζ μ)` in closed
/// form, ∂ξ_k/∂ξ its transpose-side twin `∂/∂ζ (d^Lτ_ζ v)`; elsewhere they are exact up to O(|η|²)
/// (the leading term), compared at a small η, and at ζ = 0 (no second derivative of τ involved).
#[derive(Clone, Copy)]
struct Exact {
    dual_derivative: bool,
    tangent_derivative: bool,
}

/// The largest relative deviations of `other`'s components from `fused`'s: (values, Newton
/// derivatives).
fn deviations<G: LieGroup, F: LiftedMap<G>, O: LiftedMap<G>>(
    fused: &F,
    other: &O,
    exact: Exact,
    seed: u64,
) -> (f64, f64) {
    let mut rng = Samples(seed);
    let (mut values, mut derivatives) = (0.0f64, 0.0f64);
    let mut value = |what: &str, d: f64, s: f64| {
        assert!(d.is_finite(), "{what}: not finite");
        values = values.max(d / s);
    };
    for _ in 0..SAMPLES {
        let gk = G::exp(&rng.next::<G>(1.0));
        let eta = rng.next::<G>(0.5);
        let (mu, nu) = (rng.next::<G>(1.0), rng.next::<G>(0.3));
        let (xi, zeta) = (rng.next::<G>(1.0), rng.next::<G>(0.3));
        let h = 0.3;
        let s = 1.0 + eta.norm_max() + mu.norm_max() + nu.norm_max() + xi.norm_max();

        let (gbar_f, gbar_o) = (fused.base_point(&gk, &eta), other.base_point(&gk, &eta));
        value("base_point", gbar_f.matrix_distance(&gbar_o), s);
        value(
            "second_point",
            fused
                .second_point(&gbar_f, &eta)
                .matrix_distance(&other.second_point(&gbar_f, &eta)),
            s,
        );
        value(
            "next_point",
            fused
                .next_point(&gk, &eta)
                .matrix_distance(&other.next_point(&gk, &eta)),
            s,
        );
        for impulse in [Some(&nu), None] {
            let (uf, uo) = (
                fused.momentum_update(&eta, &mu, impulse),
                other.momentum_update(&eta, &mu, impulse),
            );
            value(
                "transported",
                uf.transported.sub(&uo.transported).norm_max(),
                s,
            );
            value("μ_{k+1}", uf.next.sub(&uo.next).norm_max(), s);
            value("increment", uf.increment.sub(&uo.increment).norm_max(), s);
            value(
                "momentum_increment",
                fused
                    .momentum_increment(&eta, &mu, impulse)
                    .sub(&other.momentum_increment(&eta, &mu, impulse))
                    .norm_max(),
                s,
            );
            value(
                "base_momentum",
                fused
                    .base_momentum(&eta, &mu, &uf.next)
                    .sub(&other.base_momentum(&eta, &mu, &uf.next))
                    .norm_max(),
                s,
            );
            value(
                "base_momentum_from_impulse",
                fused
                    .base_momentum_from_impulse(&eta, &mu, impulse)
                    .sub(&other.base_momentum_from_impulse(&eta, &mu, impulse))
                    .norm_max(),
                s,
            );
        }
        match (
            fused.base_momentum_impulse_derivative(&eta),
            other.base_momentum_impulse_derivative(&eta),
        ) {
            (Some(a), Some(b)) => value("∂μ̄/∂ν", op_distance::<G>(&a, &b), s),
            (a, b) => panic!(
                "∂μ̄/∂ν given by one path only: {} {}",
                a.is_some(),
                b.is_some()
            ),
        }
        match (
            fused.base_point_derivative(&eta),
            other.base_point_derivative(&eta),
        ) {
            (Some(a), Some(b)) => value("ḡ⁻¹∂ḡ/∂η", op_distance::<G>(&a, &b), s),
            (None, None) => {}
            (a, b) => panic!(
                "ḡ⁻¹∂ḡ/∂η given by one path only: {} {}",
                a.is_some(),
                b.is_some()
            ),
        }
        value(
            "first_velocity",
            fused
                .first_velocity(&eta, &xi, &zeta)
                .sub(&other.first_velocity(&eta, &xi, &zeta))
                .norm_max(),
            s,
        );
        value(
            "second_velocity",
            fused
                .second_velocity(&eta, &xi, &zeta)
                .sub(&other.second_velocity(&eta, &xi, &zeta))
                .norm_max(),
            s,
        );
        value(
            "first_velocity_increment",
            fused
                .first_velocity_increment(h, &xi, &zeta)
                .sub(&other.first_velocity_increment(h, &xi, &zeta))
                .norm_max(),
            s,
        );
        value(
            "second_velocity_increment",
            fused
                .second_velocity_increment(h, &xi, &zeta)
                .sub(&other.second_velocity_increment(h, &xi, &zeta))
                .norm_max(),
            s,
        );
        let zeta_d = if exact.tangent_derivative {
            zeta.clone()
        } else {
            G::Algebra::zeros(G::dim())
        };
        let ((af, bf), (ao, bo)) = (
            fused.first_velocity_derivative(h, &xi, &zeta_d),
            other.first_velocity_derivative(h, &xi, &zeta_d),
        );
        value("∂ξ_k/∂ζ", op_distance::<G>(&bf, &bo), s);
        derivatives = derivatives.max(op_distance::<G>(&af, &ao) / s);

        // ∂μ̄/∂η: where the fused form is exact only up to O(|η|²), at a small η and against
        // the bound of tests/maps/lifted_map.rs.
        let eta_d = if exact.dual_derivative {
            eta.clone()
        } else {
            eta.scale(0.1)
        };
        let update = fused.momentum_update(&eta_d, &mu, Some(&nu));
        let gap = op_distance::<G>(
            &fused.base_momentum_derivative(&eta_d, &mu, &update),
            &other.base_momentum_derivative(&eta_d, &mu, &update),
        ) / s;
        let allowed = if exact.dual_derivative {
            1.0
        } else {
            1e-7 / (1e-7 + 0.5 * eta_d.norm())
        };
        derivatives = derivatives.max(gap * allowed);
    }
    (values, derivatives)
}

/// The θ-maps' descriptors are exact; the measured ones of the same factors must agree.
fn check_descriptors<G: LieGroup, M: Discretization<G>>(exact: &M, label: &str) {
    let measured = FactorsOnly(exact.clone());
    assert!(
        (measured.theta() - exact.theta()).abs() < 1e-10,
        "{label}: θ read off d^L a_0 = {} against {}",
        measured.theta(),
        exact.theta()
    );
    assert_eq!(
        measured.symmetric(),
        exact.symmetric(),
        "{label}: symmetric"
    );
    assert_eq!(measured.order(), exact.order(), "{label}: order");
    assert_eq!(
        measured.reversible_increment(),
        exact.reversible_increment(),
        "{label}: reversible increment"
    );
    assert_eq!(
        measured.increment_order(),
        exact.increment_order(),
        "{label}: increment order"
    );
    assert_eq!(
        measured.base_is_first_point(),
        exact.base_is_first_point(),
        "{label}: base is the first point"
    );
}

/// Every τ, θ and side on the group G; prints the worst deviations.
fn check_group<G: LieGroup>(name: &str, exact_exp: Exact, exact_cayley: Exact)
where
    ExpMap: Tau<G>,
    Cayley: Tau<G>,
{
    fn one<G: LieGroup, M: LiftedMap<G> + ThetaFamily>(
        name: &str,
        tau: &str,
        exact: Exact,
    ) -> [f64; 3] {
        let mut worst = [0.0f64; 3];
        for (i, theta) in THETAS.into_iter().enumerate() {
            let fused = M::with_theta(theta).unwrap();
            let side = format!("{:?}", fused.side());
            let label = format!("{name}, τ = {tau}, θ = {theta}, {side}");
            let (v, d) = deviations(&fused, &Composed(fused.clone()), exact, 11 + i as u64);
            let (vf, _) = deviations(&fused, &FactorsOnly(fused.clone()), exact, 23 + i as u64);
            assert!(v <= 1e-14, "{label}: composed values off by {v:.1e}");
            assert!(d <= 1e-7, "{label}: composed derivatives off by {d:.1e}");
            assert!(vf <= 1e-12, "{label}: factors-only values off by {vf:.1e}");
            check_descriptors::<G, M>(&fused, &label);
            worst = [worst[0].max(v), worst[1].max(d), worst[2].max(vf)];
        }
        worst
    }
    let rows = [
        (
            "exp, left",
            one::<G, DiscretizationMap<ExpMap>>(name, "exp", exact_exp),
        ),
        (
            "exp, right",
            one::<G, RightDiscretizationMap<ExpMap>>(name, "exp", exact_exp),
        ),
        (
            "cayley, left",
            one::<G, DiscretizationMap<Cayley>>(name, "cayley", exact_cayley),
        ),
        (
            "cayley, right",
            one::<G, RightDiscretizationMap<Cayley>>(name, "cayley", exact_cayley),
        ),
    ];
    for (what, [v, d, vf]) in rows {
        println!(
            "{name} {what}: fused − composed values {v:.1e}, derivatives {d:.1e}; fused − factors-only values {vf:.1e}"
        );
    }
}

/// The default path keeps the increment forms: at a step |η| = 1e-8 (ζ and ν of the same size)
/// the velocity increments of [`Composed`] are the fused map's to 1e-12 of their own size
/// (|η||ξ| + |ζ|, not |ξ|), and so is its momentum increment with an impulse. Without one, both
/// momentum increments are compared with the series `ad*_η μ + ½ ad*_η² μ` (η ↦ −η on the right;
/// τ = exp(x + O(x³)) for exp and Cayley, so the product of the two factors agrees with it to
/// O(|η|³)), relative to |η||μ|: within 1e-12 where the group has a closed-form coadjoint
/// increment (`relative`: SO(3)); SE(3) and SE(2) have none yet (`LieGroup::exp_coadjoint_increment`
/// is their matrix form there), so both paths round at ε|μ| there, ≈ 2e-8 of the size, and the
/// figures are only printed. Checked where the group has closed-form adjoint increments (SO(3),
/// SE(3), SE(2) and their products; SO(n)'s matrix forms round at ε|ξ| on either path). A default
/// path that formed Ad from the factors' matrices misses the velocity bound by eight orders of
/// magnitude, and on SO(3) the momentum one.
fn check_small_steps<G: LieGroup, M: LiftedMap<G> + ThetaFamily>(name: &str, relative: bool) {
    let mut rng = Samples(97);
    let (mut worst, mut worst_series) = (0.0f64, (0.0f64, 0.0f64));
    for theta in THETAS {
        let fused = M::with_theta(theta).unwrap();
        let composed = Composed(fused.clone());
        for _ in 0..SAMPLES {
            let (xi, mu) = (rng.next::<G>(1.0), rng.next::<G>(1.0));
            let (zeta, nu) = (rng.next::<G>(1e-8), rng.next::<G>(1e-8));
            let h = 1e-8 / xi.norm_max();
            let eta = xi.scale(h);
            let size = eta.norm_max() * xi.norm_max() + zeta.norm_max();
            let first = fused
                .first_velocity_increment(h, &xi, &zeta)
                .sub(&composed.first_velocity_increment(h, &xi, &zeta));
            let second = fused
                .second_velocity_increment(h, &xi, &zeta)
                .sub(&composed.second_velocity_increment(h, &xi, &zeta));
            let msize = eta.norm_max() * mu.norm_max() + nu.norm_max();
            let dmu = fused
                .momentum_increment(&eta, &mu, Some(&nu))
                .sub(&composed.momentum_increment(&eta, &mu, Some(&nu)));
            let gap = (first.norm_max().max(second.norm_max()) / size).max(dmu.norm_max() / msize);
            assert!(
                gap <= 1e-12,
                "{name}, θ = {theta}: increments apart by {gap:.1e} of their size"
            );
            worst = worst.max(gap);
            let e = match fused.side() {
                Side::Left => eta.clone(),
                Side::Right => eta.neg(),
            };
            let series = G::ad_dual_apply(&e, &mu)
                .axpy(0.5, &G::ad_dual_apply(&e, &G::ad_dual_apply(&e, &mu)));
            let scale = eta.norm_max() * mu.norm_max();
            let err = |m: &dyn Fn() -> G::Algebra| m().sub(&series).norm_max() / scale;
            let (ef, ec) = (
                err(&|| fused.momentum_increment(&eta, &mu, None)),
                err(&|| composed.momentum_increment(&eta, &mu, None)),
            );
            assert!(
                !relative || ec <= 1e-12,
                "{name}, θ = {theta}: momentum increment off the series by {ec:.1e} of its size (fused {ef:.1e})"
            );
            worst_series = (worst_series.0.max(ef), worst_series.1.max(ec));
        }
    }
    println!(
        "{name}: at |η| = 1e-8, fused − composed increments {worst:.1e} of their size; \
         momentum increment off its series by {:.1e} fused, {:.1e} composed",
        worst_series.0, worst_series.1
    );
}

fn small_steps<G: LieGroup>(name: &str, relative: bool)
where
    ExpMap: Tau<G>,
    Cayley: Tau<G>,
{
    check_small_steps::<G, DiscretizationMap<ExpMap>>(&format!("{name} exp, left"), relative);
    check_small_steps::<G, RightDiscretizationMap<ExpMap>>(&format!("{name} exp, right"), relative);
    check_small_steps::<G, DiscretizationMap<Cayley>>(&format!("{name} cayley, left"), relative);
    check_small_steps::<G, RightDiscretizationMap<Cayley>>(
        &format!("{name} cayley, right"),
        relative,
    );
}

#[test]
fn composed_increments_keep_their_relative_accuracy_at_small_steps() {
    small_steps::<So3>("SO(3)", true);
    small_steps::<Se3>("SE(3)", false);
    small_steps::<Se2>("SE(2)", false);
    small_steps::<Product<So3, Se2>>("SO(3)×SE(2)", false);
}

const BOTH: Exact = Exact {
    dual_derivative: true,
    tangent_derivative: true,
};
const TANGENT: Exact = Exact {
    dual_derivative: false,
    tangent_derivative: true,
};
const NEITHER: Exact = Exact {
    dual_derivative: false,
    tangent_derivative: false,
};

// (group, exact derivatives of exp, of Cayley), as tests/maps/lifted_map.rs checks them against
// finite differences.
#[test]
fn fused_so3_components_are_the_composed_lifts() {
    check_group::<So3>("SO(3)", BOTH, BOTH);
}
#[test]
fn fused_se3_components_are_the_composed_lifts() {
    check_group::<Se3>("SE(3)", TANGENT, TANGENT);
}
#[test]
fn fused_se2_components_are_the_composed_lifts() {
    check_group::<Se2>("SE(2)", TANGENT, TANGENT);
}
#[test]
fn fused_so4_components_are_the_composed_lifts() {
    check_group::<SoN<4>>("SO(4)", TANGENT, NEITHER);
}
#[test]
fn fused_product_components_are_the_composed_lifts() {
    check_group::<Product<So3, Se2>>("SO(3)×SE(2)", TANGENT, TANGENT);
}
