//! On ℝⁿ the lifted maps are the familiar one-step methods: each step is solved once through the
//! lift (find the base point b with pr₁ of the lifted point at (b, t X(b)) equal to the given
//! state) and once by the textbook formula, and the two agree to round-off.

use discretization::{DiscretizationError, VectorSpaceDiscretization};
use lie_groups::testing::assert_small;
use nalgebra::Vector2;
use proptest::prelude::*;

type V = Vector2<f64>;

/// A nonlinear second-order field: ẋ = v, v̇ = −sin x − 0.3 v |x|.
fn accel(x: &V, v: &V) -> V {
    V::new(-x[0].sin(), -x[1].sin()) - v * (0.3 * x.norm())
}

/// A non-separable Hamiltonian H = ½|p|²(1 + ¼|x|²) + ¼|x|⁴ and its gradients.
fn dh_dx(x: &V, p: &V) -> V {
    x * (0.25 * p.norm_squared()) + x * x.norm_squared()
}
fn dh_dp(x: &V, p: &V) -> V {
    p * (1.0 + 0.25 * x.norm_squared())
}

/// Fixed-point iteration to round-off (contraction factor O(t) for the step sizes used).
fn fixed_point<S: Clone>(mut s: S, f: impl Fn(&S) -> S, dist: impl Fn(&S, &S) -> f64) -> S {
    for _ in 0..200 {
        let next = f(&s);
        let d = dist(&next, &s);
        s = next;
        if d < 1e-16 {
            break;
        }
    }
    s
}

fn dist4(a: &(V, V), b: &(V, V)) -> f64 {
    (a.0 - b.0).norm().max((a.1 - b.1).norm())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn tangent_lift_step_is_the_theta_method(x in prop::array::uniform2(-1.0..1.0f64), v in prop::array::uniform2(-1.0..1.0f64), th in prop_oneof![Just(0.0), Just(0.5), Just(1.0), 0.0..1.0f64]) {
        let (t, rd) = (0.05, VectorSpaceDiscretization::new(th).unwrap());
        let zk = (V::from(x), V::from(v));
        // through the lift: b = (x, v) with pr₁ R_d^T(b, t X(b)) = z_k, then z_{k+1} = pr₂
        let b = fixed_point(zk, |b| {
            let (first, _) = rd.tangent_lift(&(b.0, b.1, b.1 * t, accel(&b.0, &b.1) * t));
            (b.0 + (zk.0 - first.0), b.1 + (zk.1 - first.1))
        }, dist4);
        let (_, via_lift) = rd.tangent_lift(&(b.0, b.1, b.1 * t, accel(&b.0, &b.1) * t));
        // textbook θ-method: z_{k+1} = z_k + t X((1−θ) z_k + θ z_{k+1})
        let reference = fixed_point(zk, |z| {
            let (xm, vm) = (zk.0 * (1.0 - th) + z.0 * th, zk.1 * (1.0 - th) + z.1 * th);
            (zk.0 + vm * t, zk.1 + accel(&xm, &vm) * t)
        }, dist4);
        assert_small("R_d^T step = θ-method", dist4(&via_lift, &reference), 1e-14);
        // and the inverse lift returns exactly (b, t X(b))
        let back = rd.tangent_lift_inverse(&zk, &via_lift);
        assert_small("(R_d^T)⁻¹ gives t X(b)", (back.2 - b.1 * t).norm().max((back.3 - accel(&b.0, &b.1) * t).norm()), 1e-14);
    }

    #[test]
    fn cotangent_lift_step_is_symplectic_euler_or_midpoint(x in prop::array::uniform2(-1.0..1.0f64), p in prop::array::uniform2(-1.0..1.0f64), th in prop_oneof![Just(0.0), Just(0.5), Just(1.0)]) {
        let (t, rd) = (0.05, VectorSpaceDiscretization::new(th).unwrap());
        let zk = (V::from(x), V::from(p));
        let field = |b: &(V, V)| (b.0, b.1, dh_dp(&b.0, &b.1) * t, -dh_dx(&b.0, &b.1) * t);
        let b = fixed_point(zk, |b| {
            let (first, _) = rd.cotangent_lift(&field(b));
            (b.0 + (zk.0 - first.0), b.1 + (zk.1 - first.1))
        }, dist4);
        let (_, via_lift) = rd.cotangent_lift(&field(&b));
        let reference = if th == 0.0 {
            // symplectic Euler: p_{k+1} = p_k − t ∂H/∂x(x_k, p_{k+1}), x_{k+1} = x_k + t ∂H/∂p(x_k, p_{k+1})
            let p1 = fixed_point(zk.1, |p1| zk.1 - dh_dx(&zk.0, p1) * t, |a, b| (a - b).norm());
            (zk.0 + dh_dp(&zk.0, &p1) * t, p1)
        } else if th == 1.0 {
            // its adjoint: x_{k+1} = x_k + t ∂H/∂p(x_{k+1}, p_k), p_{k+1} = p_k − t ∂H/∂x(x_{k+1}, p_k)
            let x1 = fixed_point(zk.0, |x1| zk.0 + dh_dp(x1, &zk.1) * t, |a, b| (a - b).norm());
            (x1, zk.1 - dh_dx(&x1, &zk.1) * t)
        } else {
            // implicit midpoint rule
            fixed_point(zk, |z| {
                let (xm, pm) = ((zk.0 + z.0) * 0.5, (zk.1 + z.1) * 0.5);
                (zk.0 + dh_dp(&xm, &pm) * t, zk.1 - dh_dx(&xm, &pm) * t)
            }, dist4)
        };
        assert_small("R_d^{T*} step = symplectic Euler / midpoint", dist4(&via_lift, &reference), 1e-14);
    }

    #[test]
    fn vector_space_maps_and_inverses_round_trip(a in prop::array::uniform4(-2.0..2.0f64), b in prop::array::uniform4(-2.0..2.0f64), th in 0.0..1.0f64) {
        let rd = VectorSpaceDiscretization::new(th).unwrap();
        let (x, v, dx, dv) = (V::new(a[0], a[1]), V::new(a[2], a[3]), V::new(b[0], b[1]), V::new(b[2], b[3]));
        let (k, k1) = rd.apply(&x, &v);
        let (xb, vb) = rd.inverse(&k, &k1);
        assert_small("R_d⁻¹ ∘ R_d", (xb - x).norm().max((vb - v).norm()), 1e-15);
        let (k, k1) = rd.tangent_lift(&(x, v, dx, dv));
        let y = rd.tangent_lift_inverse(&k, &k1);
        assert_small("(R_d^T)⁻¹ ∘ R_d^T", [(y.0 - x), (y.1 - v), (y.2 - dx), (y.3 - dv)].iter().fold(0.0, |m, d| d.norm().max(m)), 1e-14);
        let (k, k1) = rd.cotangent_lift(&(x, v, dx, dv));
        let y = rd.cotangent_lift_inverse(&k, &k1);
        assert_small("(R_d^{T*})⁻¹ ∘ R_d^{T*}", [(y.0 - x), (y.1 - v), (y.2 - dx), (y.3 - dv)].iter().fold(0.0, |m, d| d.norm().max(m)), 1e-14);
    }
}

#[test]
fn theta_outside_unit_interval_is_refused() {
    for theta in [-0.1, 1.5, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            VectorSpaceDiscretization::new(theta),
            Err(DiscretizationError::InvalidTheta { .. })
        ));
        assert!(matches!(
            discretization::DiscretizationMap::<lie_groups::ExpMap>::new(theta),
            Err(DiscretizationError::InvalidTheta { .. })
        ));
    }
}
