//! `EulerArnold::vector_field` (eq. 9, `ξ̇ = 𝕀⁻¹ ad*_ξ 𝕀ξ`) against independent forms: Euler's
//! equations on SO(3) written out, the matrix (Manakov) form on SO(4), and central differences
//! along the exact free-body flow.

use faer::{Col, Mat};
use integrators::EulerArnold;
use lie_groups::{LieGroup, So3, SoN};
use mechanics::exact::FreeBodyFlow;
use mechanics::systems::{GeneralizedRigidBody, RigidBody};
use nalgebra::{Matrix3, Vector3};

/// SO(3): 𝕀Ω̇ = 𝕀Ω × Ω (Euler), for a full inertia tensor.
#[test]
fn euler_arnold_field_is_euler_equations_on_so3() {
    let inertia = Matrix3::new(2.0, 0.1, 0.3, 0.1, 3.0, -0.2, 0.3, -0.2, 4.0);
    let ea = EulerArnold::<So3>::new(inertia).unwrap();
    for omega in [Vector3::new(0.3, -1.0, 0.7), Vector3::new(1e3, 2e2, -5e2)] {
        let want = inertia.try_inverse().unwrap() * (inertia * omega).cross(&omega);
        let got = ea.vector_field(&omega);
        assert!(
            (got - want).amax() <= 1e-14 * want.amax(),
            "{got:?} {want:?}"
        );
    }
}

/// The free body's Ω(t) = 𝕀⁻¹Π(t) from the exact flow: (Ω(t+δ) − Ω(t−δ))/2δ matches the field to
/// O(δ²) (δ = 1e-4: ~1e-8 relative; a sign error would miss by 200 %).
#[test]
fn euler_arnold_field_is_the_derivative_along_the_exact_flow() {
    let moments = Vector3::new(1.0, 2.0, 3.0);
    let body = RigidBody::principal([moments.x, moments.y, moments.z]).unwrap();
    let ea = EulerArnold::<So3>::new(Matrix3::from_diagonal(&moments)).unwrap();
    let flow = FreeBodyFlow::new(&body);
    let pi0 = Vector3::new(0.4, 1.0, 0.3);
    let omega = |t: f64| {
        flow.advance(t, &pi0, None)
            .unwrap()
            .0
            .component_div(&moments)
    };
    for t in [0.0, 0.7, 3.1] {
        let d = 1e-4;
        let fd = (omega(t + d) - omega(t - d)) / (2.0 * d);
        let got = ea.vector_field(&omega(t));
        assert!(
            (got - fd).amax() < 1e-7 * got.amax(),
            "t = {t}: {got:?} {fd:?}"
        );
    }
}

/// SO(4), 𝕀Ω = JΩ̂ + Ω̂J: the field solves J Ω̇ + Ω̇ J = [M̂, Ω̂] with M̂ = JΩ̂ + Ω̂J (Manakov's
/// equations in matrix form, entry by entry since J is diagonal).
#[test]
fn euler_arnold_field_is_the_manakov_matrix_equation_on_so4() {
    let j = [1.0, 1.7, 2.2, 3.1];
    let body = GeneralizedRigidBody::<4>::new(&j).unwrap();
    let ea = EulerArnold::<SoN<4>>::new(body.inertia_operator()).unwrap();
    let xi = Col::from_fn(6, |p| [0.3, -1.1, 0.4, 0.8, -0.2, 0.5][p]);
    let w = SoN::<4>::hat(&xi);
    let jm = Mat::from_fn(4, 4, |a, b| if a == b { j[a] } else { 0.0 });
    let m = &jm * &w + &w * &jm;
    let mdot = &m * &w - &w * &m;
    let wdot = Mat::from_fn(4, 4, |a, b| mdot[(a, b)] / (j[a] + j[b]));
    let want = SoN::<4>::vee(&wdot);
    let got = ea.vector_field(&xi);
    for p in 0..6 {
        assert!(
            (got[p] - want[p]).abs() < 1e-14,
            "{p}: {} {}",
            got[p],
            want[p]
        );
    }
}
