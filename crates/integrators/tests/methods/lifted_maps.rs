//! The integrators are the paper's eqs (18) and (19): each step, read back through the
//! `discretization` crate's lifted maps, satisfies `t X̃(pr₁₂(R̃⁻¹(x_k, x_{k+1}))) = R̃⁻¹(x_k, x_{k+1})`.
//!
//! The steps of `LiePoisson` and `EulerPoincare` are solved for ξ by the solver; these tests read
//! each step back through the lifts built from κ̃, α̃, Φ̃ and the tangents of τ, for
//! τ ∈ {exp, Cayley}, θ ∈ {0, ½, 1, 0.3}, with and without a potential (one step of h = 0.05).
//! Bounds: 1e-13 on ξ, ν (Lie–Poisson) and η (Euler–Poincaré), 1e-12 on ζ (Euler–Poincaré).

use crate::common::TestHeavyTop;
use discretization::DiscretizationMap;
use integrators::{EulerPoincare, Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, So3, Tau};
use mechanics::RigidBody;
use nalgebra::{Matrix3, Vector3};
use trivial_bundles::prelude::*;

const THETAS: [f64; 4] = [0.0, 0.5, 1.0, 0.3];

fn heavy_top() -> TestHeavyTop {
    TestHeavyTop {
        body: RigidBody::new(Matrix3::from_diagonal(&Vector3::new(1.0, 1.5, 2.5))).unwrap(),
        mgchi: Vector3::new(0.3, -0.2, 1.0),
    }
}

fn g0() -> So3 {
    So3::exp(&Vector3::new(0.3, -0.7, 0.4))
}

/// One Lie–Poisson step from (g0, μ0), then the cotangent lift inverse of the pair of points:
/// it must be `(g, μ̄, h ∂h/∂μ(μ̄), −h T*_eL_g dV(g))`.
fn check_lie_poisson<T: Tau<So3>, S: System<So3> + Clone>(system: S, theta: f64) {
    let h = 0.05;
    let mu0 = Vector3::new(0.4, 0.8, -1.1);
    let mut lp = LiePoisson::<So3, T, _>::new(system.clone(), theta, mu0, Some(g0())).unwrap();
    lp.step(h).unwrap();
    let g1 = *lp.configuration().unwrap();
    let mu1 = lp.momentum();
    let map = DiscretizationMap::<T>::new(theta).unwrap();
    let x = map
        .cotangent_lift_inverse(
            &CotangentBundle::from_parts(g0(), mu0),
            &CotangentBundle::from_parts(g1, mu1),
        )
        .unwrap();
    let velocity = system.velocity(x.mu()) * h;
    let force = system.potential_differential(x.g()) * (-h);
    let err_xi = (x.xi() - velocity).amax();
    let err_nu = (x.nu() - force).amax();
    println!(
        "Lie–Poisson {} θ = {theta}: ξ off by {err_xi:.2e}, ν off by {err_nu:.2e}",
        T::NAME
    );
    assert!(
        err_xi < 1e-13 && err_nu < 1e-13,
        "Lie–Poisson {} θ = {theta}: ξ off by {err_xi:.2e}, ν off by {err_nu:.2e}",
        T::NAME
    );
}

/// One Euler–Poincaré step from (g0, ξ0), then the tangent lift inverse: it must be
/// `(g, ξ̄, h ξ̄, h ∂²h/∂μ² (ad*_ξ̄ μ̄ − T*_eL_g dV(g)))` with μ̄ = ∂l/∂ξ(ξ̄).
fn check_euler_poincare<T: Tau<So3>, S: System<So3> + Clone>(system: S, theta: f64) {
    let h = 0.05;
    let xi0 = Vector3::new(0.4, 0.5, -0.6);
    let mut ep = EulerPoincare::<So3, T, _>::new(system.clone(), theta, xi0, Some(g0())).unwrap();
    ep.step(h).unwrap();
    let g1 = *ep.configuration().unwrap();
    let xi1 = ep.velocity();
    let map = DiscretizationMap::<T>::new(theta).unwrap();
    let x = map
        .tangent_lift_inverse(
            &TangentBundle::from_parts(g0(), xi0),
            &TangentBundle::from_parts(g1, xi1),
        )
        .unwrap();
    let xi = *x.xi();
    let mu = system.momentum(&xi);
    let rhs = So3::ad_dual_apply(&xi, &mu) - system.potential_differential(x.g());
    let accel = system.hessian(&mu) * rhs * h;
    let err_eta = (x.xi_bar() - xi * h).amax();
    let err_zeta = (x.xi_tilde() - accel).amax();
    println!(
        "Euler–Poincaré {} θ = {theta}: η off by {err_eta:.2e}, ζ off by {err_zeta:.2e}",
        T::NAME
    );
    assert!(
        err_eta < 1e-13 && err_zeta < 1e-12,
        "Euler–Poincaré {} θ = {theta}: η off by {err_eta:.2e}, ζ off by {err_zeta:.2e}",
        T::NAME
    );
}

#[test]
fn lie_poisson_steps_satisfy_the_cotangent_lift_equation_free_body() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    for theta in THETAS {
        check_lie_poisson::<ExpMap, _>(body.clone(), theta);
        check_lie_poisson::<Cayley, _>(body.clone(), theta);
    }
}

#[test]
fn lie_poisson_steps_satisfy_the_cotangent_lift_equation_with_potential() {
    for theta in THETAS {
        check_lie_poisson::<ExpMap, _>(heavy_top(), theta);
        check_lie_poisson::<Cayley, _>(heavy_top(), theta);
    }
}

#[test]
fn euler_poincare_steps_satisfy_the_tangent_lift_equation_free_body() {
    let body = RigidBody::principal([1.0, 2.0, 3.0]).unwrap();
    for theta in THETAS {
        check_euler_poincare::<ExpMap, _>(body.clone(), theta);
        check_euler_poincare::<Cayley, _>(body.clone(), theta);
    }
}

#[test]
fn euler_poincare_steps_satisfy_the_tangent_lift_equation_with_potential() {
    for theta in THETAS {
        check_euler_poincare::<ExpMap, _>(heavy_top(), theta);
        check_euler_poincare::<Cayley, _>(heavy_top(), theta);
    }
}
