//! Dense output: the state between two steps by a cubic Hermite interpolant on G × 𝔤*, and a
//! driver that reports the state at requested times and locates events ([`crate::events`]).
//!
//! Over a step from (t₀, g₀, μ₀) to (t₁, g₁, μ₁), h = t₁ − t₀, s = (t − t₀)/h ∈ [0, 1]:
//!
//! - `μ(s)` is the cubic Hermite polynomial through μ₀, μ₁ with the slopes `h μ̇₀`, `h μ̇₁` of the
//!   equations of motion, `μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ)`, ξ = ∂h/∂μ;
//! - `g(s) = g₀ exp(Z(s))` with Z the cubic Hermite curve in 𝔤 through Z(0) = 0 and
//!   Z(1) = log(g₀⁻¹g₁), with the slopes that make `g⁻¹ dg/ds = h ξ` at both ends:
//!   Z'(0) = h ξ₀ and Z'(1) = (d^L exp_{Z(1)})⁻¹ h ξ₁ (`d/ds exp Z = exp Z · d^L exp_Z Z'`).
//!
//! Both interpolate values and derivatives, so the interpolant is O(h⁴) accurate against the
//! trajectory through the two end states: for methods of order ≤ 3 (Lie–Poisson, Euler–Poincaré,
//! the splittings) and RK4 the error between steps is of the method's order and size
//! (`tests/dense_output.rs`: within 2× the error at the step points), for higher-order
//! compositions the interpolant's O(h⁴) dominates between steps. g(s) stays on G (an exponential),
//! and g(0), g(1) are g₀, g₁ to round-off.
//!
//! ```
//! use integrators::dense_output::integrate_dense;
//! use integrators::events::{Direction, Event};
//! use mechanics::RigidBody;
//! use integrators::LiePoisson;
//! use lie_groups::{Cayley, LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! // A symmetric top: Π₁ = cos(t/2) falls through 0 at t = π.
//! let top = RigidBody::principal([1.0, 1.0, 2.0]).unwrap();
//! let mut lp = LiePoisson::<So3, Cayley, _>::new(top.clone(), 0.5, Vector3::new(1.0, 0.0, 1.0),
//!     Some(So3::identity())).unwrap();
//! let mut samples = Vec::new();
//! let stop = Event::new(|_t, mu: &Vector3<f64>, _g| mu.x).direction(Direction::Falling).terminal();
//! let run = integrate_dense(&mut lp, 0.02, 1000, &[0.125, 1.0, 2.5], |t, mu, _g| {
//!     samples.push((t, mu.x));
//! }, &[stop]).unwrap();
//! assert_eq!(samples.len(), 3); // output at times between the steps
//! assert!(run.stopped && (run.hits[0].t - std::f64::consts::PI).abs() < 1e-3);
//! ```

use crate::events::{locate, Event, EventHit};
use crate::system::force;
use crate::{Integrator, IntegratorError, System};
use discretization::Side;
use lie_groups::{LieGroup, Operator, Vector};

/// The cubic Hermite interpolant of one step (see the module page).
#[derive(Debug, Clone)]
pub struct HermiteStep<G: LieGroup> {
    t0: f64,
    h: f64,
    mu0: G::Algebra,
    mu1: G::Algebra,
    /// h μ̇ at both ends.
    dmu0: G::Algebra,
    dmu1: G::Algebra,
    /// g₀ (k₀ = g₀⁻¹ for the right trivialization) and Z where g is reconstructed.
    g: Option<(G, ConfigurationCurve<G>)>,
    side: Side,
}

/// Z(1), Z'(0), Z'(1) of the configuration curve `g₀ exp Z(s)`.
type ConfigurationCurve<G> = [<G as LieGroup>::Algebra; 3];

/// `μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ)`, ξ = ∂h/∂μ, of `system` at (t, μ, g).
pub fn momentum_rate<G: LieGroup, S: System<G>>(
    system: &S,
    t: f64,
    mu: &G::Algebra,
    g: Option<&G>,
) -> G::Algebra {
    momentum_rate_on(Side::Left, system, t, mu, g)
}

/// [`momentum_rate`] in the trivialization `side`: `μ̇ = ±ad*_ξ μ + F + F_ext` (− for the right
/// trivialization of a right-invariant system).
pub fn momentum_rate_on<G: LieGroup, S: System<G>>(
    side: Side,
    system: &S,
    t: f64,
    mu: &G::Algebra,
    g: Option<&G>,
) -> G::Algebra {
    let xi = system.velocity(mu);
    let mut rate = G::ad_dual_apply(&xi, mu).scale(side.ad_dual_sign());
    if let Some(f) = force(system, g) {
        rate = rate.add(&f);
    }
    if system.is_forced() {
        rate = rate.add(&system.external_force(t, g, &xi));
    }
    rate
}

/// A state with what the interpolant needs at a step's end: t, μ, g, ξ = ∂h/∂μ and μ̇.
#[derive(Debug, Clone)]
pub struct DenseState<G: LieGroup> {
    /// Time.
    pub t: f64,
    /// Body momentum μ.
    pub mu: G::Algebra,
    /// Configuration g, where reconstructed.
    pub g: Option<G>,
    /// Body velocity ξ = ∂h/∂μ.
    pub xi: G::Algebra,
    /// μ̇ of the equations of motion.
    pub rate: G::Algebra,
    /// The trivialization of ξ and μ ([`Integrator::side`]).
    pub side: Side,
}

impl<G: LieGroup> DenseState<G> {
    /// The integrator's current state ([`Integrator::momentum_rate`] gives μ̇).
    pub fn of<I: Integrator<Group = G>>(integrator: &I) -> Self {
        Self {
            t: integrator.time(),
            mu: integrator.momentum(),
            g: integrator.configuration().cloned(),
            xi: integrator.velocity(),
            rate: integrator.momentum_rate(),
            side: integrator.side(),
        }
    }
    /// The state (t, μ, g) of `system`.
    pub fn from_system<S: System<G>>(system: &S, t: f64, mu: &G::Algebra, g: Option<&G>) -> Self {
        Self {
            t,
            mu: mu.clone(),
            g: g.cloned(),
            xi: system.velocity(mu),
            rate: momentum_rate(system, t, mu, g),
            side: Side::Left,
        }
    }
}

impl<G: LieGroup> HermiteStep<G> {
    /// The interpolant between the states `(t0, μ0, g0)` and `(t1, μ1, g1)` of `system` (g given
    /// at both ends or at neither); see [`Self::between`].
    pub fn new<S: System<G>>(
        system: &S,
        (t0, mu0, g0): (f64, &G::Algebra, Option<&G>),
        (t1, mu1, g1): (f64, &G::Algebra, Option<&G>),
    ) -> Result<Self, IntegratorError> {
        Self::between(
            &DenseState::from_system(system, t0, mu0, g0),
            &DenseState::from_system(system, t1, mu1, g1),
        )
    }

    /// The interpolant between two states. Errors: t1 = t0 or non-finite, non-finite slopes, g at
    /// one end only, or `g0⁻¹g1` outside the domain of log (a step of a half turn or more).
    pub fn between(a: &DenseState<G>, b: &DenseState<G>) -> Result<Self, IntegratorError> {
        let (t0, t1) = (a.t, b.t);
        let h = t1 - t0;
        if h == 0.0 || !h.is_finite() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("a dense-output step needs t1 ≠ t0, finite (got {t0} and {t1})"),
            });
        }
        let dmu0 = a.rate.scale(h);
        let dmu1 = b.rate.scale(h);
        if !dmu0.is_finite() || !dmu1.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "momentum rate for dense output",
            });
        }
        if a.side != b.side {
            return Err(IntegratorError::InvalidParameter {
                reason: "dense output between states of different trivializations".into(),
            });
        }
        // Right-trivialized states go through the inversion k = g⁻¹ (left velocity −ξ):
        // g(s) = (k₀ exp Z(s))⁻¹ = exp(−Z(s)) g₀.
        let (sign, g0, g1) = match a.side {
            Side::Left => (1.0, a.g.clone(), b.g.clone()),
            Side::Right => (
                -1.0,
                a.g.as_ref().map(G::inverse),
                b.g.as_ref().map(G::inverse),
            ),
        };
        let g = match (&g0, &g1) {
            (Some(g0), Some(g1)) => {
                let z1 =
                    g0.inverse()
                        .compose(g1)
                        .log()
                        .map_err(|e| IntegratorError::StepTooLarge {
                            step: h,
                            reason: format!("no dense output across this step: {e}"),
                        })?;
                let dz0 = a.xi.scale(sign * h);
                let dz1 = G::dexp_left_inv(&z1).apply(&b.xi.scale(sign * h));
                if !dz1.is_finite() {
                    return Err(IntegratorError::NonFinite {
                        what: "configuration slope for dense output",
                    });
                }
                Some((g0.clone(), [z1, dz0, dz1]))
            }
            (None, None) => None,
            _ => {
                return Err(IntegratorError::InvalidParameter {
                    reason: "dense output needs g at both ends of the step or at neither".into(),
                })
            }
        };
        Ok(Self {
            side: a.side,
            t0,
            h,
            mu0: a.mu.clone(),
            mu1: b.mu.clone(),
            dmu0,
            dmu1,
            g,
        })
    }

    /// The step's start and end times.
    pub fn span(&self) -> (f64, f64) {
        (self.t0, self.t0 + self.h)
    }

    /// (μ(t), g(t)) for t in the step (extrapolates outside it).
    pub fn at(&self, t: f64) -> (G::Algebra, Option<G>) {
        let s = (t - self.t0) / self.h;
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        let mu = self
            .mu0
            .scale(h00)
            .add(&self.dmu0.scale(h10))
            .add(&self.mu1.scale(h01))
            .add(&self.dmu1.scale(h11));
        let g = self.g.as_ref().map(|(g0, [z1, dz0, dz1])| {
            let z = dz0.scale(h10).add(&z1.scale(h01)).add(&dz1.scale(h11));
            match self.side {
                Side::Left => G::exp_compose(g0, &z),
                Side::Right => G::exp_compose(g0, &z).inverse(),
            }
        });
        (mu, g)
    }
}

/// How a dense run ended.
#[derive(Debug, Clone)]
pub struct DenseRun<G: LieGroup> {
    /// Every event crossing found, in time order.
    pub hits: Vec<EventHit<G>>,
    /// Whether a terminal event stopped the run (the integrator is then at the end of the step
    /// that contains the event; the event's state is in the last hit).
    pub stopped: bool,
    /// Steps taken.
    pub steps: usize,
}

/// Takes `steps` steps of size h, calling `observe(t, μ, g)` at each of the `times` (sorted in
/// the direction of integration, within the run) from the step's [`HermiteStep`] interpolant, and
/// locating the zero crossings of each event ([`crate::events`]) to its tolerance. A terminal event
/// stops the run after the step in which it occurs. The slopes come from
/// [`Integrator::momentum_rate`] and [`Integrator::velocity`].
///
/// Errors: unsorted or non-finite `times`, a failed step (the run stops there, the integrator
/// left at the last good state), or an interpolant that cannot be formed.
pub fn integrate_dense<I>(
    integrator: &mut I,
    h: f64,
    steps: usize,
    times: &[f64],
    mut observe: impl FnMut(f64, &<I::Group as LieGroup>::Algebra, Option<&I::Group>),
    events: &[Event<'_, I::Group>],
) -> Result<DenseRun<I::Group>, IntegratorError>
where
    I: Integrator,
{
    let forward = h > 0.0;
    if times.iter().any(|t| !t.is_finite())
        || times
            .windows(2)
            .any(|w| if forward { w[1] < w[0] } else { w[1] > w[0] })
    {
        return Err(IntegratorError::InvalidParameter {
            reason: "output times must be finite and sorted in the direction of integration".into(),
        });
    }
    // times before the start are skipped
    let start = integrator.time();
    let mut next_time = times
        .iter()
        .position(|&t| if forward { t >= start } else { t <= start })
        .unwrap_or(times.len());
    let mut run = DenseRun {
        hits: Vec::new(),
        stopped: false,
        steps: 0,
    };
    let mut values: Vec<f64> = events
        .iter()
        .map(|e| e.value(start, &integrator.momentum(), integrator.configuration()))
        .collect();
    let mut before = DenseState::of(integrator);
    for _ in 0..steps {
        integrator.step(h)?;
        run.steps += 1;
        let after = DenseState::of(integrator);
        let interpolant = HermiteStep::between(&before, &after)?;
        let (t1, mu1) = (after.t, after.mu.clone());
        // events first: a terminal one ends the output at its time
        let mut step_hits = Vec::new();
        for (k, e) in events.iter().enumerate() {
            let v1 = e.value(t1, &mu1, integrator.configuration());
            if let Some(hit) = locate(e, k, &interpolant, values[k], v1) {
                step_hits.push(hit);
            }
            values[k] = v1;
        }
        step_hits.sort_by(|a, b| {
            let (x, y) = if forward { (a.t, b.t) } else { (b.t, a.t) };
            x.total_cmp(&y)
        });
        if let Some(i) = step_hits.iter().position(|hit| events[hit.event].terminal) {
            step_hits.truncate(i + 1);
            run.stopped = true;
        }
        let t_end = if run.stopped {
            step_hits.last().map_or(t1, |hit| hit.t)
        } else {
            t1
        };
        let before_end = |t: f64| if forward { t <= t_end } else { t >= t_end };
        while next_time < times.len() && before_end(times[next_time]) {
            let t = times[next_time];
            let (mu, g) = if t == t1 {
                (mu1.clone(), integrator.configuration().cloned())
            } else {
                interpolant.at(t)
            };
            observe(t, &mu, g.as_ref());
            next_time += 1;
        }
        run.hits.extend(step_hits);
        if run.stopped {
            return Ok(run);
        }
        before = after;
    }
    Ok(run)
}
