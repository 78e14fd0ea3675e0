//! The reversible step-density controller (`adaptive::ReversibleSteps`) on the heavy top with
//! the system's provided density (|Ω| + the potential's frequency, G by central differences):
//! the inverse steps come back to round-off, output times do not move the grid, and bad input —
//! a non-symmetric method, ε = 0, a monitor returning NaN, ε too large for the density — is a
//! clear error with the state as it was. (The satellite on an eccentric orbit, with its own
//! density: `mechanics/tests/models/satellite_orbit.rs`.)

use integrators::adaptive::ReversibleSteps;
use integrators::splitting::Splitting;
use integrators::{
    Composition, CompositionScheme, Integrator, IntegratorError, LiePoisson, StateSnapshot, System,
};
use lie_groups::{Cayley, LieGroup, So3};
use mechanics::{HeavyTop, RigidBody};
use nalgebra::Vector3;

fn top() -> HeavyTop {
    HeavyTop::principal([1.0, 2.0, 3.0], 1.0, 9.81, Vector3::new(0.0, 0.1, 0.5)).unwrap()
}

fn start() -> (Vector3<f64>, So3) {
    (
        Vector3::new(0.5, 1.0, 0.2),
        So3::exp(&Vector3::new(0.3, -0.5, 0.8)),
    )
}

fn composed() -> Composition<Splitting<So3, HeavyTop>> {
    let (mu0, g0) = start();
    let strang = Splitting::new(top(), mu0, Some(g0)).unwrap();
    Composition::new(strang, CompositionScheme::triple_jump(4).unwrap()).unwrap()
}

/// The free asymmetric body: the provided density |Ω| is smooth, so its G by central
/// differences is smooth to ~1e-11 and the run comes back to round-off. (With the heavy top's
/// provided density, whose force derivative K is itself a central difference, G carries the
/// rounding of K magnified by 1/s ~ 10⁵ and the way back misses by ~1e-5: a model that wants
/// round-off reversibility gives ρ and G in closed form, as the satellite does.)
fn free_composed() -> Composition<Splitting<So3, RigidBody>> {
    let (mu0, g0) = start();
    let strang = Splitting::new(free(), mu0, Some(g0)).unwrap();
    Composition::new(strang, CompositionScheme::triple_jump(4).unwrap()).unwrap()
}

fn free() -> RigidBody {
    RigidBody::principal([1.0, 2.0, 3.0]).unwrap()
}

#[test]
fn inverse_steps_come_back_to_round_off() {
    let mut run = ReversibleSteps::new(free_composed(), free(), 0.05).unwrap();
    let (t0, mu0, g0) = run.method().snapshot();
    let rho0 = run.density();
    for _ in 0..500 {
        run.step().unwrap();
    }
    let stats = *run.stats();
    // The density follows |Ω|.
    assert!(stats.max_step > 1.05 * stats.min_step, "{stats:?}");
    let duration = run.method().time() - t0;
    let (m, rho) = run.into_parts();
    let mut back = ReversibleSteps::resume(m, free(), -0.05, rho).unwrap();
    for _ in 0..500 {
        back.step().unwrap();
    }
    let (t, mu, g) = back.method().snapshot();
    let g = g.unwrap();
    let dg = (g.as_matrix() - g0.unwrap().as_matrix()).norm();
    // t sums 2 × 500 steps, each rounded to an ulp of t.
    assert!(
        (t - t0).abs() < 1e-12 * duration,
        "t back to {t} (from {t0}, duration {duration})"
    );
    assert!(
        (mu - mu0).norm() < 1e-12,
        "μ back within {:e}",
        (mu - mu0).norm()
    );
    // Each h comes back to the rounding of ρ_{n+½}, so g (turning at |Ω| ≈ 1) comes back to
    // the time's round-off, |Ω| · 1000 ulps of t.
    assert!(dg < 1e-11, "g back within {dg:e}");
    // ρ sums G(y) by central differences of |Ω|, whose rounding (~1e-11 relative, the
    // difference's ε/s) differs between the way out and the way back by as much.
    let drho = (back.density() - rho0).abs() / rho0;
    assert!(drho < 1e-10, "ρ back within {drho:e}");
}

#[test]
fn output_times_and_the_end_time_do_not_move_the_grid() {
    let times = [0.0, 0.31, 1.0, 2.5, 2.5, 4.0, 7.0];
    let mut with = ReversibleSteps::new(composed(), top(), 0.05).unwrap();
    let mut seen = Vec::new();
    let at_end = with
        .solve(4.0, &times, |t, mu, g| seen.push((t, *mu, g.copied())))
        .unwrap();
    assert_eq!(at_end.time(), 4.0);
    // Times within [0, 4], in order, each exactly; 7 is past the end.
    let ts: Vec<f64> = seen.iter().map(|s| s.0).collect();
    assert_eq!(ts, vec![0.0, 0.31, 1.0, 2.5, 2.5, 4.0]);
    assert_eq!(seen.last().unwrap().1, at_end.momentum());
    // The grid stays at or before the end, as without output times, and continuing past 4
    // is the run that never stopped there.
    let mut without = ReversibleSteps::new(composed(), top(), 0.05).unwrap();
    without.advance_to(4.0).unwrap();
    assert!(with.method().time() <= 4.0);
    assert_eq!(with.method().snapshot(), without.method().snapshot());
    let mut straight = ReversibleSteps::new(composed(), top(), 0.05).unwrap();
    with.advance_to(6.0).unwrap();
    straight.advance_to(6.0).unwrap();
    assert_eq!(with.method().snapshot(), straight.method().snapshot());
    assert_eq!(with.density(), straight.density());
    // An output is the state a run ending there gives, and as accurate as the grid: against
    // 4000 fixed steps of the composition.
    let mut to = ReversibleSteps::new(composed(), top(), 0.05).unwrap();
    assert_eq!(to.advance_to(2.5).unwrap().momentum(), seen[3].1);
    let mut fine = composed();
    for _ in 0..4000 {
        fine.step(2.5 / 4000.0).unwrap();
    }
    let err = (fine.momentum() - seen[3].1).norm();
    assert!(err < 1e-4, "output at 2.5 off by {err:e}");
    // Bad times.
    assert!(with.solve(8.0, &[7.0, 6.5], |_, _, _| {}).is_err());
    assert!(with.advance_to(1.0).is_err()); // behind the run
}

#[test]
fn a_non_symmetric_method_or_a_zero_epsilon_is_refused() {
    let (mu0, g0) = start();
    let theta0 = LiePoisson::<So3, Cayley, _>::new(top(), 0.0, mu0, Some(g0)).unwrap();
    match ReversibleSteps::new(theta0, top(), 0.05) {
        Err(IntegratorError::InvalidParameter { reason }) => {
            assert!(reason.contains("not symmetric"), "{reason}")
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    let half = LiePoisson::<So3, Cayley, _>::new(top(), 0.5, mu0, Some(g0)).unwrap();
    assert!(ReversibleSteps::new(half, top(), 0.05).is_ok());
    for eps in [0.0, f64::NAN, f64::INFINITY] {
        assert!(
            ReversibleSteps::new(composed(), top(), eps).is_err(),
            "ε = {eps}"
        );
    }
}

/// The heavy top whose density is NaN once Π₁ passes `limit`: a monitor that breaks mid-run.
#[derive(Debug, Clone)]
struct Breaking {
    top: HeavyTop,
    limit: f64,
}

impl System<So3> for Breaking {
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.top.hamiltonian(mu)
    }
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.top.velocity(mu)
    }
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.top.momentum(xi)
    }
    fn has_potential(&self) -> bool {
        true
    }
    fn potential(&self, g: &So3) -> f64 {
        self.top.potential(g)
    }
    fn potential_differential(&self, g: &So3) -> Vector3<f64> {
        self.top.potential_differential(g)
    }
    fn step_density(
        &self,
        mu: &Vector3<f64>,
        g: Option<&So3>,
        scope: integrators::DensityScope,
    ) -> f64 {
        if mu.x.abs() > self.limit {
            f64::NAN
        } else {
            self.top.step_density(mu, g, scope)
        }
    }
}

#[test]
fn a_monitor_returning_nan_is_an_error_with_the_state_as_it_was() {
    // At the start: refused.
    let nan_now = Breaking {
        top: top(),
        limit: 0.1,
    };
    match ReversibleSteps::new(composed(), nan_now, 0.05) {
        Err(IntegratorError::InvalidStepDensity { what, value, .. }) => {
            assert_eq!(what, "ρ");
            assert!(value.is_nan());
        }
        other => panic!("expected InvalidStepDensity, got {other:?}"),
    }
    // Mid-run: the step that would end where the monitor fails is not taken.
    let later = Breaking {
        top: top(),
        limit: 0.55,
    };
    let mut run = ReversibleSteps::new(composed(), later, 0.05).unwrap();
    let failure = loop {
        let before = (run.method().snapshot(), run.density(), *run.stats());
        match run.step() {
            Ok(()) => continue,
            Err(e) => break (e, before),
        }
    };
    let (error, (state, rho, stats)) = failure;
    assert!(
        matches!(error, IntegratorError::InvalidStepDensity { value, .. } if value.is_nan()),
        "{error:?}"
    );
    assert!(error.to_string().contains("step density"), "{error}");
    assert_eq!(run.method().snapshot(), state);
    assert_eq!(run.density(), rho);
    assert_eq!(*run.stats(), stats);
    // And it stays refused, with the state as it was.
    assert!(run.step().is_err());
    assert_eq!(run.method().snapshot(), state);
}

#[test]
fn an_epsilon_too_large_for_the_density_is_an_error_not_a_negative_step() {
    // With ε large, ρ_{n+½} = ρ_n + (ε/2) G goes ≤ 0 where the density falls.
    let mut run = ReversibleSteps::new(composed(), top(), 40.0).unwrap();
    let mut error = None;
    for _ in 0..1000 {
        let before = run.method().snapshot();
        if let Err(e) = run.step() {
            assert_eq!(run.method().snapshot(), before);
            error = Some(e);
            break;
        }
    }
    match error {
        Some(IntegratorError::InvalidStepDensity { what, value, .. }) => {
            assert!(what.starts_with("ρ_"), "{what}");
            assert!(value.is_nan() || value <= 0.0, "{value}");
        }
        other => panic!("expected InvalidStepDensity, got {other:?}"),
    }
}
