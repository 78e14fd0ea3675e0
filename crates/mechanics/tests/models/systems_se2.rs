//! The planar body on SE(2) (`systems::PlanarBody`): differential against finite differences,
//! free uniform motion, total angular momentum about the spring anchor to round-off, spatial
//! momentum under gravity exact, energy without drift, orders against RK4.

use crate::common::*;
use integrators::{integrate, Integrator, LiePoisson, System};
use lie_groups::{Cayley, ExpMap, LieGroup, Se2, So2, Tau};
use mechanics::systems::{planar_body_se2::cross2, PlanarBody};
use nalgebra::{DVector, Vector2, Vector3};

fn spring() -> PlanarBody {
    PlanarBody::free(1.5, 0.2)
        .unwrap()
        .with_spring(4.0, Vector2::new(0.3, -0.1))
        .unwrap()
}

fn gravity() -> PlanarBody {
    PlanarBody::free(1.5, 0.2)
        .unwrap()
        .with_gravity(Vector2::new(0.0, -9.81))
        .unwrap()
}

fn initial() -> (Se2, Vector3<f64>) {
    (
        Se2::new(So2::from_angle(0.4), Vector2::new(1.0, 0.5)),
        Vector3::new(0.3, 0.5, 1.2),
    )
}

#[test]
fn planar_differential_matches_finite_differences() {
    // Central differences with δ = 1e-5: error ~δ²|V'''| ≈ 1e-9; bound 1e-7.
    let both = PlanarBody::free(1.5, 0.2)
        .unwrap()
        .with_spring(4.0, Vector2::new(0.3, -0.1))
        .unwrap()
        .with_gravity(Vector2::new(1.0, -9.81))
        .unwrap();
    for sys in [spring(), gravity(), both] {
        for (a, x) in [
            (0.4, Vector2::new(1.0, 0.5)),
            (-2.5, Vector2::new(-0.3, 2.0)),
        ] {
            let g = Se2::new(So2::from_angle(a), x);
            let fd = fd_left_differential(|g: &Se2| sys.potential(g), &g);
            let dv = sys.potential_differential(&g);
            for i in 0..3 {
                assert!(
                    (fd[i] - dv[i]).abs() < 1e-7,
                    "{i}: fd {} vs {}",
                    fd[i],
                    dv[i]
                );
            }
        }
    }
}

#[test]
fn planar_body_refuses_bad_parameters() {
    assert!(PlanarBody::free(0.0, 1.0).is_err());
    assert!(PlanarBody::free(1.0, f64::NAN).is_err());
    let b = PlanarBody::free(1.0, 1.0).unwrap();
    assert!(b.clone().with_spring(-1.0, Vector2::zeros()).is_err());
    assert!(b
        .clone()
        .with_spring(1.0, Vector2::new(f64::NAN, 0.0))
        .is_err());
    assert!(b.with_gravity(Vector2::new(0.0, f64::INFINITY)).is_err());
}

#[test]
fn free_planar_body_moves_uniformly() {
    // Free: L is constant to round-off (the first component of ad*_ξ μ vanishes for v ∥ P; v is
    // parallel to P up to the rounding of the solver's warm-start extrapolation, so L follows a
    // walk of roundings: measured 2.6e-15 over 400 steps, bounded by 1e-14); the
    // spatial momentum R P is constant to
    // round-off (bound 1e-12 over 400 steps); the centre of mass deviates from x₀ + t v₀ by O(h²) (the translation of τ(ξ)
    // is turned by ~hω/2 relative to h v): measured and bounded by 5e-2 at hω = 0.075 over t = 20.
    let sys = PlanarBody::free(1.5, 0.2).unwrap();
    let (g0, mu0) = initial();
    let (_, p0) = PlanarBody::spatial_momentum(&g0, &mu0);
    for theta in [0.0, 0.5] {
        let mut lp = LiePoisson::<Se2, Cayley, _>::new(sys.clone(), theta, mu0, Some(g0)).unwrap();
        let (mut dp, mut dx) = (0.0f64, 0.0f64);
        integrate(&mut lp, 0.05, 400, |i| {
            let g = i.configuration().unwrap();
            let (_, p) = PlanarBody::spatial_momentum(g, &i.momentum());
            dp = dp.max((p - p0).amax());
            dx = dx.max((g.translation() - (g0.translation() + p0 * (i.time() / 1.5))).amax());
        })
        .unwrap();
        let dl = (lp.momentum().x - mu0.x).abs();
        println!("free planar θ={theta}: |Δ(RP)| {dp:.2e}, |x − (x₀ + t v₀)| {dx:.2e}");
        assert!(dp < 1e-12, "θ={theta}: {dp:e}");
        assert!(dx < 5e-2, "θ={theta}: {dx:e}");
        assert!(dl < 1e-14, "θ={theta}: ΔL {dl:e}");
    }
}

fn spring_angular_momentum_drift<T: Tau<Se2>>(theta: f64) -> f64 {
    let (g0, mu0) = initial();
    let (l0, _) = PlanarBody::spatial_momentum(&g0, &mu0);
    let mut lp = LiePoisson::<Se2, T, _>::new(spring(), theta, mu0, Some(g0)).unwrap();
    let mut worst = 0.0f64;
    integrate(&mut lp, 0.02, 2000, |i| {
        let (l, _) = PlanarBody::spatial_momentum(i.configuration().unwrap(), &i.momentum());
        worst = worst.max((l - l0).abs());
    })
    .unwrap();
    worst / l0.abs()
}

#[test]
fn spring_total_angular_momentum_conserved_to_round_off() {
    // V = ½k|x + Rc|² is invariant under rotations about the origin: by discrete Noether
    // L + x × RP is conserved to round-off by every Lie–Poisson method (bound 1e-12 relative,
    // 2000 steps).
    for theta in [0.0, 0.5, 1.0] {
        let e = spring_angular_momentum_drift::<ExpMap>(theta);
        let c = spring_angular_momentum_drift::<Cayley>(theta);
        println!("planar spring: L_total drift θ={theta}: exp {e:.2e}, cayley {c:.2e}");
        assert!(e < 1e-12 && c < 1e-12, "θ={theta}: exp {e:e}, cayley {c:e}");
    }
}

#[test]
fn gravity_spatial_momentum_exact() {
    // k = 0: the spatial force is m γ at every ḡ, so R P grows by exactly h m γ per step; the
    // horizontal part is conserved. Bound 1e-12 (|RP| ≈ 60 after t = 4).
    let (g0, mu0) = initial();
    let (_, p0) = PlanarBody::spatial_momentum(&g0, &mu0);
    for theta in [0.0, 0.5, 1.0] {
        let mut lp = LiePoisson::<Se2, Cayley, _>::new(gravity(), theta, mu0, Some(g0)).unwrap();
        let mut worst = 0.0f64;
        integrate(&mut lp, 0.02, 200, |i| {
            let (_, p) = PlanarBody::spatial_momentum(i.configuration().unwrap(), &i.momentum());
            let expect = p0 + Vector2::new(0.0, -9.81) * (1.5 * i.time());
            worst = worst.max((p - expect).amax());
        })
        .unwrap();
        println!("planar gravity θ={theta}: |RP − (R₀P₀ + mγt)| {worst:.2e}");
        assert!(worst < 1e-12, "θ={theta}: {worst:e}");
    }
}

#[test]
fn spring_energy_error_bounded_without_drift() {
    // 10⁴ steps of h = 0.02: the first tenth (t = 20) covers several periods of the coupled
    // spring–rotation motion; the last tenth's max error stays within 2× of it (+ round-off).
    let (g0, mu0) = initial();
    for theta in [0.0, 0.5, 1.0] {
        let (f, l) = energy_error_tenths(
            LiePoisson::<Se2, Cayley, _>::new(spring(), theta, mu0, Some(g0)).unwrap(),
            0.02,
            10_000,
        );
        println!("planar spring energy error θ={theta}: first tenth {f:.2e}, last {l:.2e}");
        assert!(l <= 2.0 * f + 1e-13, "θ={theta}: first {f:e}, last {l:e}");
    }
}

/// RK4 on (φ, x, L, P_body) with the equations of the module page written out by hand.
fn rk4_spring(sys: &PlanarBody, g0: &Se2, mu0: &Vector3<f64>, t: f64, n: usize) -> DVector<f64> {
    let (m, j, k, c) = (
        sys.mass(),
        sys.inertia(),
        sys.stiffness(),
        *sys.attachment(),
    );
    let y0 = DVector::from_vec(vec![
        g0.rotation().angle(),
        g0.translation().x,
        g0.translation().y,
        mu0.x,
        mu0.y,
        mu0.z,
    ]);
    let f = |y: &DVector<f64>| {
        let r = So2::from_angle(y[0]);
        let x = Vector2::new(y[1], y[2]);
        let p = Vector2::new(y[4], y[5]);
        let omega = y[3] / j;
        // Body-frame spring vector s = Rᵀx + c; body torque −k c × s, body force −k s.
        let s = r.inverse().rotate(&x) + c;
        let xdot = r.rotate(&(p / m));
        DVector::from_vec(vec![
            omega,
            xdot.x,
            xdot.y,
            -k * cross2(&c, &s),
            omega * p.y - k * s.x,
            -omega * p.x - k * s.y,
        ])
    };
    rk4_dvec(f, &y0, t, n)
}

fn order<T: Tau<Se2>>(theta: f64) -> f64 {
    let sys = spring();
    let (g0, mu0) = initial();
    let t = 1.0;
    let yr = rk4_spring(&sys, &g0, &mu0, t, 8_000);
    let (mut hs, mut errs) = (vec![], vec![]);
    for n in [40usize, 80, 160, 320] {
        let h = t / n as f64;
        let mut lp = LiePoisson::<Se2, T, _>::new(sys.clone(), theta, mu0, Some(g0)).unwrap();
        integrate(&mut lp, h, n, |_| {}).unwrap();
        let g = lp.configuration().unwrap();
        let mu = lp.momentum();
        let dphi = g.rotation().compose(&So2::from_angle(-yr[0])).angle();
        let err = [
            dphi,
            g.translation().x - yr[1],
            g.translation().y - yr[2],
            mu.x - yr[3],
            mu.y - yr[4],
            mu.z - yr[5],
        ]
        .iter()
        .fold(0.0f64, |a, e| a.max(e.abs()));
        hs.push(h);
        errs.push(err);
    }
    let p = fitted_order(&hs, &errs);
    println!(
        "planar spring LP {} θ={theta}: errors {errs:?}, order {p:.3}",
        T::NAME
    );
    p
}

#[test]
fn planar_spring_lie_poisson_orders_against_rk4() {
    // θ = ½: order 2; θ = 0: order 1. Tolerance 0.1 on the slope over h = 1/40 … 1/320.
    for (theta, expected) in [(0.5, 2.0), (0.0, 1.0)] {
        let e = order::<ExpMap>(theta);
        let c = order::<Cayley>(theta);
        assert!(
            (e - expected).abs() < 0.1 && (c - expected).abs() < 0.1,
            "θ={theta}: exp {e:.3}, cayley {c:.3}"
        );
    }
}
