//! The discrete flows defined by the cotangent lift (eq. 19 of the paper for a Hamiltonian vector
//! field) on T*G: they are symplectic for the canonical form of T*G — a check of the whole chain
//! α̃, T*R̃_d⁻¹, Φ̃ including the sign of Φ̃ — and the θ = 0 Lie–Poisson scheme of §4 is consistent
//! (it runs forward, NOTES.md slip 2). Also: the error paths of the inverse.

use crate::common::{fd_body_velocity, fd_vector, grad_potential, inertia_inv, omega};
use discretization::{DiscretizationError, DiscretizationMap, InverseMethod, NewtonOptions};
use lie_groups::testing::assert_small;
use lie_groups::{Cayley, DenseMatrix, ExpMap, LieGroup, Se3, So3, SoN, Tau, Vector};
use nalgebra::{DMatrix, DVector, Vector3};
use trivial_bundles::prelude::*;

/// One step of the integrator `t X̃(pr₁₂(y)) = y`, `y = (R̃_d^{T*})⁻¹((g_k, μ_k), (g_{k+1}, μ_{k+1}))`, for
/// H(g, μ) = ½⟨μ, 𝕀⁻¹μ⟩ + V(g), whose trivialized field is X̃(g, μ) = (g, μ, 𝕀⁻¹μ, −∇V(g)).
/// Unknowns z = (ξ, μ_{k+1}) with g_{k+1} = g_k τ(θξ) τ((1−θ)ξ); Newton with a central-difference
/// Jacobian, to round-off.
fn step<G: LieGroup, T: Tau<G>>(theta: f64, t: f64, gk: &G, muk: &G::Algebra) -> (G, G::Algebra) {
    let rd = DiscretizationMap::<T>::new(theta).unwrap();
    let n = G::dim();
    let unpack = |z: &DVector<f64>| {
        let xi = G::Algebra::from_fn(n, |i| z[i]);
        let mu1 = G::Algebra::from_fn(n, |i| z[n + i]);
        let gk1 = gk
            .compose(&T::tau(&xi.scale(theta)))
            .compose(&T::tau(&xi.scale(1.0 - theta)));
        (gk1, mu1)
    };
    let residual = |z: &DVector<f64>| {
        let (gk1, mu1) = unpack(z);
        let k = CotangentBundle::from_parts(gk.clone(), muk.clone());
        let y = rd
            .cotangent_lift_inverse(&k, &CotangentBundle::from_parts(gk1, mu1))
            .unwrap();
        let r1 = y.xi().sub(&inertia_inv::<G>(y.mu()).scale(t));
        let r2 = y
            .nu()
            .add(&grad_potential::<G>(&y.g().matrix().to_mat()).scale(t));
        DVector::from_fn(2 * n, |i, _| if i < n { r1.get(i) } else { r2.get(i - n) })
    };
    let mut z = DVector::from_fn(2 * n, |i, _| {
        if i < n {
            inertia_inv::<G>(muk).get(i) * t
        } else {
            muk.get(i - n)
        }
    });
    for _ in 0..20 {
        let r = residual(&z);
        if r.amax() < 1e-15 {
            break;
        }
        let h = 1e-7;
        let jac = DMatrix::from_fn(2 * n, 2 * n, |_, _| 0.0);
        let mut jac = jac;
        for j in 0..2 * n {
            let mut zp = z.clone();
            zp[j] += h;
            let mut zm = z.clone();
            zm[j] -= h;
            jac.set_column(j, &((residual(&zp) - residual(&zm)) / (2.0 * h)));
        }
        z -= jac.lu().solve(&r).expect("regular Jacobian");
    }
    unpack(&z)
}

/// The discrete flow Ψ: (g_k, μ_k) ↦ (g_{k+1}, μ_{k+1}) preserves ω of T*G:
/// ω(DΨ v₁, DΨ v₂) = ω(v₁, v₂) with DΨ by central differences.
fn check_flow_symplectic<G: LieGroup, T: Tau<G>>(theta: f64) {
    let n = G::dim();
    let t = 0.1;
    let gk = G::exp(&G::Algebra::from_fn(n, |i| 0.3 - 0.17 * i as f64));
    let muk = G::Algebra::from_fn(n, |i| 0.8 - 0.3 * i as f64);
    let v1 = (
        G::Algebra::from_fn(n, |i| 0.5 + 0.1 * i as f64),
        G::Algebra::from_fn(n, |i| -0.4 + 0.2 * i as f64),
    );
    let v2 = (
        G::Algebra::from_fn(n, |i| (i as f64).cos()),
        G::Algebra::from_fn(n, |i| 0.3 * (i as f64 + 1.0).sin()),
    );
    let flow = |v: &(G::Algebra, G::Algebra), s: f64| {
        step::<G, T>(
            theta,
            t,
            &gk.compose(&G::exp(&v.0.scale(s))),
            &muk.axpy(s, &v.1),
        )
    };
    let push = |v: &(G::Algebra, G::Algebra)| {
        (
            fd_body_velocity::<G>(|s| flow(v, s).0),
            fd_vector(|s| flow(v, s).1),
        )
    };
    let (w1, w2) = (push(&v1), push(&v2));
    let mu1 = flow(&v1, 0.0).1;
    let after = omega::<G>(&mu1, (&w1.0, &w1.1), (&w2.0, &w2.1));
    let before = omega::<G>(&muk, (&v1.0, &v1.1), (&v2.0, &v2.1));
    // FD truncation ~1e-10 and Newton residual 1e-15/h ~ 1e-10 per derivative
    assert_small("ω(DΨ v₁, DΨ v₂) = ω(v₁, v₂)", (after - before).abs(), 1e-7);
    // and it is not the identity: the step moves the state
    assert!(flow(&v1, 0.0).0.matrix_distance(&gk) > 1e-3);
}

macro_rules! flow_suite {
    ($name:ident, $G:ty, $T:ty) => {
        mod $name {
            use super::*;
            #[test]
            fn discrete_flow_is_symplectic_theta_0() {
                check_flow_symplectic::<$G, $T>(0.0);
            }
            #[test]
            fn discrete_flow_is_symplectic_theta_half() {
                check_flow_symplectic::<$G, $T>(0.5);
            }
            #[test]
            fn discrete_flow_is_symplectic_theta_1() {
                check_flow_symplectic::<$G, $T>(1.0);
            }
            #[test]
            fn discrete_flow_is_symplectic_theta_0_3() {
                check_flow_symplectic::<$G, $T>(0.3);
            }
        }
    };
}

flow_suite!(so3_exp, So3, ExpMap);
flow_suite!(so3_cayley, So3, Cayley);
flow_suite!(se3_exp, Se3, ExpMap);
flow_suite!(se3_cayley, Se3, Cayley);
flow_suite!(so_n3_cayley, SoN<3>, Cayley);

/// Free rigid body, θ = 0 (the scheme of §4 with Φ̃ corrected): over a fixed time the error against
/// a fine-step reference falls at least two-fold when h halves, i.e. the scheme converges forward.
/// With the paper's Φ̃ the reconstruction runs backwards and the error stays O(1).
#[test]
fn lie_poisson_theta_0_scheme_converges_forward() {
    fn run<T: Tau<So3>>(h: f64, steps: usize) -> (So3, Vector3<f64>) {
        let rd = DiscretizationMap::<T>::new(0.0).unwrap();
        let ii = Vector3::new(1.0, 0.5, 0.25);
        let (mut g, mut mu) = (So3::identity(), Vector3::new(0.3, 1.0, -0.5));
        for _ in 0..steps {
            let mut xi = (h * mu).component_mul(&ii);
            for _ in 0..100 {
                let next = (h * T::dtau_left_dual_apply(&xi, &T::tau(&xi).coadjoint_apply(&mu)))
                    .component_mul(&ii);
                let done = (next - xi).amax() < 1e-16;
                xi = next;
                if done {
                    break;
                }
            }
            let tau = T::tau(&xi);
            let (g1, mu1) = (g.compose(&tau), tau.coadjoint_apply(&mu));
            // the step satisfies the integrator equation with the library's inverse lift
            let y = rd
                .cotangent_lift_inverse(
                    &CotangentBundle::from_parts(g, mu),
                    &CotangentBundle::from_parts(g1, mu1),
                )
                .unwrap();
            assert_small(
                "ξ = t 𝕀⁻¹ μ",
                (y.xi() - (h * y.mu()).component_mul(&ii)).amax(),
                1e-15,
            );
            assert_small("ν = 0", y.nu().amax(), 1e-14);
            (g, mu) = (g1, mu1);
        }
        (g, mu)
    }
    fn check<T: Tau<So3>>() {
        let (g_ref, mu_ref) = run::<T>(1e-4, 10_000);
        let err = |h: f64, n: usize| {
            let (g, mu) = run::<T>(h, n);
            g.matrix_distance(&g_ref).max((mu - mu_ref).amax())
        };
        let (e1, e2) = (err(0.02, 50), err(0.01, 100));
        assert!(
            e1 < 0.05 && e2 < e1 / 2.0,
            "errors {e1:.3e}, {e2:.3e}: the scheme does not converge"
        );
    }
    check::<ExpMap>();
    check::<Cayley>();
}

/// Negative control for NOTES.md slip 2: the scheme of §4 with eq. (20)'s printed sign,
/// `ξ + t 𝕀⁻¹ d^{L*}τ_ξ(μ_{k+1}) = 0`, `μ_{k+1} = Ad*_{τ(ξ)} μ_k`, `g_{k+1} = g_k τ(ξ)`, integrates
/// the time-reversed flow: n steps of h converge (order 2) to the exact state at −nh, computed
/// independently by a hand-written RK4 on (Π, R) with steps −1e-4, and stay O(1) away from the
/// state at +nh.
#[test]
fn the_printed_sign_of_eq_20_integrates_the_time_reversed_flow() {
    let ii = Vector3::new(1.0, 0.5, 0.25);
    let pi0 = Vector3::new(0.3, 1.0, -0.5);
    fn printed<T: Tau<So3>>(
        ii: Vector3<f64>,
        pi0: Vector3<f64>,
        h: f64,
        n: usize,
    ) -> (So3, Vector3<f64>) {
        let (mut g, mut mu) = (So3::identity(), pi0);
        for _ in 0..n {
            let mut xi = -(h * mu).component_mul(&ii);
            for _ in 0..100 {
                let next = -(h * T::dtau_left_dual_apply(&xi, &T::tau(&xi).coadjoint_apply(&mu)))
                    .component_mul(&ii);
                let done = (next - xi).amax() < 1e-16;
                xi = next;
                if done {
                    break;
                }
            }
            let tau = T::tau(&xi);
            (g, mu) = (g.compose(&tau), tau.coadjoint_apply(&mu));
        }
        (g, mu)
    }
    // Π' = Π × Ω, R' = R Ω̂ by RK4 at step `dt` (negative: backwards in time).
    let rk4 = |dt: f64, n: usize| {
        let skew = |w: Vector3<f64>| {
            nalgebra::Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
        };
        let f = |p: &Vector3<f64>, r: &nalgebra::Matrix3<f64>| {
            let w = p.component_mul(&ii);
            (p.cross(&w), r * skew(w))
        };
        let (mut p, mut r) = (pi0, nalgebra::Matrix3::identity());
        for _ in 0..n {
            let (k1, l1) = f(&p, &r);
            let (k2, l2) = f(&(p + k1 * (dt / 2.0)), &(r + l1 * (dt / 2.0)));
            let (k3, l3) = f(&(p + k2 * (dt / 2.0)), &(r + l2 * (dt / 2.0)));
            let (k4, l4) = f(&(p + k3 * dt), &(r + l3 * dt));
            p += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (dt / 6.0);
            r += (l1 + l2 * 2.0 + l3 * 2.0 + l4) * (dt / 6.0);
        }
        (p, r)
    };
    let (back, forward) = (rk4(-1e-4, 10_000), rk4(1e-4, 10_000));
    let dist = |(g, mu): &(So3, Vector3<f64>), (p, r): &(Vector3<f64>, nalgebra::Matrix3<f64>)| {
        (g.as_matrix() - r).amax().max((mu - p).amax())
    };
    // (distance to the state at −T, distance to the state at +T)
    let both = |s: &(So3, Vector3<f64>)| (dist(s, &back), dist(s, &forward));
    let check = |run: &dyn Fn(f64, usize) -> (So3, Vector3<f64>)| {
        let (b1, f1) = both(&run(0.02, 50));
        let (b2, _) = both(&run(0.01, 100));
        let order = (b1 / b2).log2();
        assert!(
            (order - 2.0).abs() < 0.2 && b2 < 1e-3,
            "to the state at −T: errors {b1:.3e}, {b2:.3e} (order {order:.2})"
        );
        assert!(f1 > 0.1, "to the state at +T: {f1:.3e}");
    };
    check(&|h, n| printed::<ExpMap>(ii, pi0, h, n));
    check(&|h, n| printed::<Cayley>(ii, pi0, h, n));
}

#[test]
fn inverse_methods_are_the_closed_forms_where_they_exist() {
    let exp_half = DiscretizationMap::<ExpMap>::new(0.3).unwrap();
    assert_eq!(exp_half.inverse_method::<So3>(), InverseMethod::TauInverse);
    let cay = |th| {
        DiscretizationMap::<Cayley>::new(th)
            .unwrap()
            .inverse_method::<So3>()
    };
    assert_eq!(cay(0.0), InverseMethod::TauInverse);
    assert_eq!(cay(1.0), InverseMethod::TauInverse);
    assert_eq!(cay(0.5), InverseMethod::SquareRoot);
    assert_eq!(cay(0.3), InverseMethod::Newton);
}

#[test]
fn inverse_is_exact_for_tiny_increments() {
    // |ξ| = 1e-8: closed forms and Newton keep full relative precision (no 0/0)
    let g = So3::exp(&Vector3::new(0.2, -0.4, 0.1));
    let xi = Vector3::new(1e-8, -2e-8, 0.5e-8);
    for theta in [0.0, 0.3, 0.5, 1.0] {
        let rd = DiscretizationMap::<Cayley>::new(theta).unwrap();
        let (gk, gk1) = rd.apply(&g, &xi);
        let (_, back) = rd.inverse(&gk, &gk1).unwrap();
        // the increment is recovered from g_k⁻¹ g_{k+1}, whose entries carry absolute round-off ε
        assert_small("ξ recovered at |ξ| = 1e-8", (back - xi).amax(), 1e-15);
    }
}

#[test]
fn inverse_outside_the_domain_is_an_error() {
    let gk = So3::identity();
    // a rotation by π: cay⁻¹ is undefined and log is not unique
    let gk1 = So3::exp(&Vector3::new(std::f64::consts::PI, 0.0, 0.0));
    for theta in [0.0, 0.3, 1.0] {
        let rd = DiscretizationMap::<Cayley>::new(theta).unwrap();
        assert!(
            matches!(rd.inverse(&gk, &gk1), Err(DiscretizationError::Lie(_))),
            "θ = {theta}"
        );
    }
    // at θ = ½ the pair is still in the domain: τ(ξ/2) is a rotation by π/2, a square root of gk1
    let rd = DiscretizationMap::<Cayley>::new(0.5).unwrap();
    let (g, xi) = rd.inverse(&gk, &gk1).unwrap();
    let (hk, hk1) = rd.apply(&g, &xi);
    assert_small(
        "R̃_d ∘ R̃_d⁻¹ at a rotation by π, θ = ½",
        hk.matrix_distance(&gk).max(hk1.matrix_distance(&gk1)),
        1e-14,
    );
    // a Newton solve that is not given enough iterations reports it
    let rd = DiscretizationMap::<Cayley>::new(0.3)
        .unwrap()
        .with_newton(NewtonOptions {
            max_iterations: 1,
            tolerance: 1e-15,
        });
    let gk1 = So3::exp(&Vector3::new(1.0, 0.5, -0.7));
    assert!(matches!(
        rd.inverse(&gk, &gk1),
        Err(DiscretizationError::NoConvergence { iterations: 1, .. })
    ));
}
