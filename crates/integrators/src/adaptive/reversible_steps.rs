//! Variable steps that keep a symmetric method symmetric: the explicit, reversible step-density
//! controller of Hairer–Söderlind.
//!
//! A standard controller picks the next step from the past (the last error), so the step
//! sequence of a run backwards is not the mirror of the forward one, and a symmetric method
//! loses what symmetry gave it: the energy of a variable-step splitting drifts as a Runge–Kutta
//! method's does. Hairer and Söderlind (E. Hairer, G. Söderlind, "Explicit, time reversible,
//! adaptive step size control", SIAM J. Sci. Comput. 26 (2005) 1838–1851; Hairer–Lubich–Wanner,
//! *Geometric Numerical Integration*, 2nd ed., §VIII.3) instead let the step follow a *step
//! density* ρ(y) = 1/σ(y) of the state — the rate at which the motion changes — through the
//! time transformation dt/dτ = 1/ρ: along the flow of `ẏ = f(y)`, ρ obeys
//!
//! ```text
//! dρ/dτ = (dρ/dt)(dt/dτ) = G(y),      G(y) = (1/ρ) dρ/dt = −σ'(y) f(y) / σ(y),
//! ```
//!
//! and the augmented system `y' = f(y)/ρ`, `ρ' = G(y)` (′ = d/dτ) is integrated with a constant
//! step ε in τ by the symmetric composition of a half step of ρ, a step of the method Φ with
//! ρ frozen, and a half step of ρ:
//!
//! ```text
//! ρ_{n+½} = ρ_n + (ε/2) G(y_n),
//! h_n     = ε / ρ_{n+½},           y_{n+1} = Φ_{h_n}(y_n),      t_{n+1} = t_n + h_n,
//! ρ_{n+1} = ρ_{n+½} + (ε/2) G(y_{n+1}),
//! ```
//!
//! which is their `ρ_{n+½} = ρ_{n−½} + ε G(y_n)`, `h_n = ε/ρ_{n+½}` with the two half steps of
//! consecutive steps merged, started at `ρ_0 = ρ(y_0)`. Explicit: one evaluation of G per step
//! (G(y_{n+1}) is kept for the next one), no equation solved.
//!
//! **Why it is symmetric and reversible.** Call the three maps Z_{ε/2} (y frozen, exact),
//! Y_ε: y ↦ Φ_{ε/ρ}(y) (ρ frozen) and Z_{ε/2}. Y_{−ε} = Φ_{−ε/ρ} = Φ_{ε/ρ}⁻¹ = Y_ε⁻¹ because Φ is
//! symmetric, and Z_{−s} = Z_s⁻¹, so the palindrome Ψ_ε = Z_{ε/2} Y_ε Z_{ε/2} satisfies
//! Ψ_{−ε} = Ψ_ε⁻¹: run n steps with ε and n with −ε, and the state (t, y, ρ) comes back to
//! round-off. If the system is reversible under R (for the Lie–Poisson systems of the crate with h
//! even in μ: R(g, μ) = (g, −μ)), Φ is R-reversible, and ρ is even (ρ(Ry) = ρ(y), so G is odd,
//! G(Ry) = −G(y)), then R̂(y, ρ) = (Ry, ρ) gives R̂ Ψ_ε R̂ = Ψ_ε⁻¹: run forward, flip μ, run
//! forward again as many steps, and the start comes back flipped. This is what keeps the long-time
//! behaviour of constant steps — energy without drift, ρ_n·σ(y_n) = 1 + O(ε²) bounded — with
//! steps that follow the motion (Hairer–Söderlind, Theorems 3.1–3.3). The Casimirs and momentum
//! maps a method keeps step by step it keeps with any step sequence.
//!
//! **The density.** [`System::step_density`] gives ρ (the provided form from the body's velocity
//! |∂h/∂μ| and the potential's frequency; a model overrides it, e.g. √(|Ω|² + GM/r³) for a
//! satellite on an orbit, and √(½‖Π̂𝕀⁻¹ − Ω̂‖² + GM/r³), the body's nutation frequency and
//! the orbit's, for a method that follows the spin about Π exactly), of the scope the method declares ([`SymmetricMethod::density_scope`],
//! [`crate::DensityScope`]) and [`System::step_density_rate`] gives G (the provided form by central
//! differences of ρ along the flow; a model gives the closed form). Any system can be the
//! monitor, so a user chooses the density by wrapping the model. ε is the accuracy knob: ε/ρ is
//! the step where ρ is the rate, and the error of an order-p method falls as ε^p.
//!
//! **Reaching T and output times.** The run's own state stays on its τ-grid: the steps never
//! depend on where the run is stopped or looked at. The state at a time T between two grid
//! points t_n ≤ T < t_{n+1} is a separate step Φ_{T − t_n} from y_n on a copy, which does not
//! feed back into ρ or y ([`ReversibleSteps::advance_to`], [`ReversibleSteps::solve`]; as
//! GeometricIntegrators.jl's target times, without interpolation error). A run continued past T
//! is then the same run as one that never stopped there, and a reversibility check runs on the
//! grid ([`ReversibleSteps::step`]).
//!
//! The method must be symmetric ([`SymmetricMethod::is_symmetric`]: the splittings and their
//! compositions, kinetic–kick, Lie–Poisson and Euler–Poincaré θ = ½); anything else is refused,
//! as its variable steps would not be reversible.
//!
//! # Example: a satellite on an eccentric orbit
//!
//! ```
//! use integrators::adaptive::ReversibleSteps;
//! use integrators::{splitting::Splitting, Integrator};
//! use lie_groups::{LieGroup, Se3, So3};
//! use mechanics::RigidBodySe3;
//! use nalgebra::{Matrix3, Vector3, Vector6};
//!
//! // GM = 1, a = 1, e = 0.8: periapsis r = 0.2 at speed 3, period 2π; a small, nearly
//! // axisymmetric body turning slowly.
//! let inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.03, 1.06)) * 1e-3;
//! let sat = RigidBodySe3::satellite(1.0, inertia, 1.0)?;
//! let g0 = Se3::from_parts(So3::identity(), Vector3::new(0.2, 0.0, 0.0));
//! let mu0 = Vector6::new(0.0, 0.0, 1e-4, 0.0, 3.0, 0.0);
//! let method = Splitting::new(sat.clone(), mu0, Some(g0))?;
//! let mut run = ReversibleSteps::new(method, sat, 0.05)?;
//! let at_t = run.advance_to(2.0 * std::f64::consts::PI)?; // one orbit
//! assert_eq!(at_t.time(), 2.0 * std::f64::consts::PI);
//! let stats = run.stats();
//! assert!(stats.max_step > 10.0 * stats.min_step); // short steps at periapsis only
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

use super::Stats;
use crate::compose::{StateSnapshot, SymmetricMethod};
use crate::{IntegratorError, System};
use lie_groups::LieGroup;

/// A symmetric method run with the reversible step-density controller of Hairer–Söderlind (see
/// the [module page](crate::adaptive::reversible_steps)): the state is (t_n, y_n, ρ_n) on the
/// grid of constant steps ε in the fictitious time τ, the monitor S gives ρ and G.
#[derive(Debug, Clone)]
pub struct ReversibleSteps<M, S> {
    method: M,
    monitor: S,
    epsilon: f64,
    /// The method's [`SymmetricMethod::density_scope`].
    scope: crate::DensityScope,
    /// ρ_n.
    rho: f64,
    /// G(y_n), kept for the next step.
    rate: f64,
    max_steps: usize,
    stats: Stats,
}

impl<M, S> ReversibleSteps<M, S>
where
    M: SymmetricMethod + StateSnapshot,
    S: System<M::Group>,
{
    /// The method run with steps ε in τ and the density of `monitor`, started at
    /// ρ_0 = ρ(y_0). ε < 0 runs backwards in time. A budget of 10⁷ steps.
    ///
    /// Errors: the method not symmetric ([`IntegratorError::InvalidParameter`] naming it), ε
    /// not finite or 0, ρ(y_0) not finite and > 0 or G(y_0) not finite
    /// ([`IntegratorError::InvalidStepDensity`]).
    pub fn new(method: M, monitor: S, epsilon: f64) -> Result<Self, IntegratorError> {
        let scope = method.density_scope();
        let rho = monitor.step_density(&method.momentum(), method.configuration(), scope);
        Self::resume(method, monitor, epsilon, rho)
    }

    /// The same as [`ReversibleSteps::new`] with a given density ρ_n at the method's state: a
    /// run continued from the parts of another ([`ReversibleSteps::into_parts`]), e.g. with ε
    /// negated (the inverse steps) or after flipping the momentum (the reversed motion).
    pub fn resume(method: M, monitor: S, epsilon: f64, rho: f64) -> Result<Self, IntegratorError> {
        if !method.is_symmetric() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "{} is not symmetric (Φ_−h ≠ Φ_h⁻¹): its variable steps cannot be \
                     reversible; use a splitting, a composition, or θ = ½",
                    method.method_name()
                ),
            });
        }
        if !(epsilon.is_finite() && epsilon != 0.0) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("ε = {epsilon:e} must be finite and ≠ 0"),
            });
        }
        let t = method.time();
        let rho = valid(rho, "ρ", t, true)?;
        let scope = method.density_scope();
        let rate = monitor.step_density_rate(&method.momentum(), method.configuration(), scope);
        let rate = valid(rate, "G = (1/ρ) dρ/dt", t, false)?;
        Ok(Self {
            method,
            monitor,
            epsilon,
            scope,
            rho,
            rate,
            max_steps: 10_000_000,
            stats: Stats::default(),
        })
    }

    /// The same run with a budget of `max_steps` steps ([`IntegratorError::TooManySteps`]
    /// beyond).
    pub fn with_max_steps(self, max_steps: usize) -> Self {
        Self { max_steps, ..self }
    }
    /// The method, at the last grid state (t_n, y_n).
    pub fn method(&self) -> &M {
        &self.method
    }
    /// The monitor.
    pub fn monitor(&self) -> &S {
        &self.monitor
    }
    /// ε, the step in τ.
    pub fn epsilon(&self) -> f64 {
        self.epsilon
    }
    /// ρ_n, the controller's density at the grid state (tracks the monitor's ρ(y_n) to O(ε²)).
    pub fn density(&self) -> f64 {
        self.rho
    }
    /// The method and ρ_n, given back.
    pub fn into_parts(self) -> (M, f64) {
        (self.method, self.rho)
    }
    /// Steps taken (none rejected) and the smallest and largest |h|.
    pub fn stats(&self) -> &Stats {
        &self.stats
    }
    /// The step h_n = ε/ρ_{n+½} the next [`ReversibleSteps::step`] takes (NaN or negative when
    /// ρ_{n+½} is not > 0, which that step reports).
    pub fn next_step(&self) -> f64 {
        self.epsilon / (self.rho + 0.5 * self.epsilon * self.rate)
    }

    /// One step Ψ_ε: (t_n, y_n, ρ_n) ↦ (t_{n+1}, y_{n+1}, ρ_{n+1}) (module page).
    ///
    /// Errors, with the state as it was: ρ_{n+½} or ρ_{n+1} not finite and > 0, G(y_{n+1}) not
    /// finite ([`IntegratorError::InvalidStepDensity`]), the step budget used up, an error of
    /// the method.
    pub fn step(&mut self) -> Result<(), IntegratorError> {
        let t = self.method.time();
        if self.stats.accepted >= self.max_steps {
            return Err(IntegratorError::TooManySteps {
                steps: self.stats.accepted,
                t,
            });
        }
        let half = self.rho + 0.5 * self.epsilon * self.rate;
        valid(half, "ρ_{n+½}", t, true)?;
        let h = self.epsilon / half;
        let saved = self.method.snapshot();
        self.method.step(h)?;
        let checked = valid(
            self.monitor.step_density_rate(
                &self.method.momentum(),
                self.method.configuration(),
                self.scope,
            ),
            "G = (1/ρ) dρ/dt",
            t,
            false,
        )
        .and_then(|rate| {
            valid(half + 0.5 * self.epsilon * rate, "ρ_{n+1}", t, true).map(|rho| (rho, rate))
        });
        match checked {
            Ok((rho, rate)) => {
                self.rho = rho;
                self.rate = rate;
                self.stats.accepted += 1;
                self.stats.min_step = self.stats.min_step.min(h.abs());
                self.stats.max_step = self.stats.max_step.max(h.abs());
                Ok(())
            }
            Err(e) => {
                self.method.restore(saved)?;
                Err(e)
            }
        }
    }

    /// Steps of the grid while they do not pass `t_end`, then the state at `t_end` exactly: a
    /// copy of the method stepped from the last grid point t_n ≤ t_end by `t_end − t_n`, which
    /// does not feed back into the run (module page). The run stays at t_n.
    ///
    /// Errors: `t_end` not finite or behind the run, errors of [`ReversibleSteps::step`] (the
    /// run is then at the last grid state).
    pub fn advance_to(&mut self, t_end: f64) -> Result<M, IntegratorError>
    where
        M: Clone,
    {
        self.solve(t_end, &[], |_, _, _| {})
    }

    /// [`ReversibleSteps::advance_to`], calling `observe(t, μ, g)` at each of the `times`
    /// within the run (sorted in the direction of integration; times outside are skipped), each
    /// by a separate step of the method from the grid point before it — the method's accuracy,
    /// and the grid does not depend on the output times.
    ///
    /// Errors: unsorted or non-finite `times`, and those of [`ReversibleSteps::advance_to`].
    pub fn solve(
        &mut self,
        t_end: f64,
        times: &[f64],
        mut observe: impl FnMut(f64, &<M::Group as LieGroup>::Algebra, Option<&M::Group>),
    ) -> Result<M, IntegratorError>
    where
        M: Clone,
    {
        let start = self.method.time();
        if !t_end.is_finite() {
            return Err(IntegratorError::NonFinite { what: "end time" });
        }
        let forward = self.epsilon > 0.0;
        let ahead = |a: f64, b: f64| if forward { a < b } else { a > b };
        if ahead(t_end, start) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "end time {t_end} is behind the run (t = {start}, ε = {:e})",
                    self.epsilon
                ),
            });
        }
        if times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| ahead(w[1], w[0])) {
            return Err(IntegratorError::InvalidParameter {
                reason: "output times must be finite and sorted in the direction of integration"
                    .into(),
            });
        }
        let mut next = times
            .iter()
            .position(|&t| !ahead(t, start))
            .unwrap_or(times.len());
        loop {
            let t = self.method.time();
            let h = self.next_step();
            if !(h.is_finite() && h != 0.0 && h.signum() == self.epsilon.signum()) {
                // ρ_{n+½} is not > 0: the step reports it, the state as it was.
                self.step()?;
                continue;
            }
            // Whether the next grid point would pass the end: then the end is reached from
            // this one.
            let ends_here = t == t_end || ahead(t_end, t + h);
            let until = if ends_here { t_end } else { t + h };
            while next < times.len() {
                let tk = times[next];
                if ahead(t_end, tk) {
                    next = times.len();
                } else if ahead(tk, until) || (ends_here && tk == t_end) {
                    let m = self.state_at(tk)?;
                    observe(tk, &m.momentum(), m.configuration());
                    next += 1;
                } else {
                    break;
                }
            }
            if ends_here {
                return self.state_at(t_end);
            }
            self.step()?;
        }
    }

    /// The state at `t` by a step of the method from the grid state (the grid state itself when
    /// t is its time), on a copy.
    fn state_at(&self, t: f64) -> Result<M, IntegratorError>
    where
        M: Clone,
    {
        let mut m = self.method.clone();
        let t0 = m.time();
        if t != t0 {
            m.step(t - t0)?;
            m.set_time(t)?;
        }
        Ok(m)
    }
}

/// `value` if finite (and > 0 when `positive`), else the error naming `what`.
fn valid(value: f64, what: &'static str, t: f64, positive: bool) -> Result<f64, IntegratorError> {
    if value.is_finite() && (!positive || value > 0.0) {
        Ok(value)
    } else {
        Err(IntegratorError::InvalidStepDensity {
            what,
            value,
            requirement: if positive {
                "finite and > 0 (a smaller ε follows the density's variation)"
            } else {
                "finite"
            },
            t,
        })
    }
}
