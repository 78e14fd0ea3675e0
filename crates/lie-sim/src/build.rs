//! Where a scene's system and its method meet: the system's module builds its model
//! ([`crate::systems`]), the registry builds the method on it ([`crate::methods::build`]), and
//! the result is a [`Simulation`] — or why the method does not apply.

use crate::driven::DrivenSim;
use crate::driver::PairDriver;
use crate::error::SimError;
use crate::methods::spec::SolverOptions;
use crate::methods::wrap::BuildError;
use crate::methods::{build as build_method, MethodSpec};
use crate::model::{Alg, Job, Model};
use crate::sim::{Adapter, Simulation};
use crate::stepping::VariableSteps;
use crate::systems::{System, SystemKind};
use integrators::{DensityScope, System as _};

/// Builds the simulation a scene names: its system with its initial state (g₀ only when
/// `reconstruct`), advanced by `method`. A method that does not apply to the system is
/// [`SimError::Inapplicable`], one the library does not provide for it yet
/// [`SimError::NotYetAvailable`]; never a panic.
pub fn build(
    system: &System,
    method: &MethodSpec,
    reconstruct: bool,
    solver: &SolverOptions,
) -> Result<Box<dyn Simulation>, SimError> {
    build_with(system, method, reconstruct, solver, None)
}

/// As [`build`], with steps chosen as the run goes when `variable` says so
/// ([`crate::driven`]): to a tolerance, the method's embedded pair driven by the library's error
/// controller; with ε, the symmetric method driven by the reversible step-density controller. A
/// method without an error estimate refuses a tolerance, one that is not symmetric refuses ε
/// ([`SimError::Build`], naming why).
pub fn build_with(
    system: &System,
    method: &MethodSpec,
    reconstruct: bool,
    solver: &SolverOptions,
    variable: Option<VariableSteps>,
) -> Result<Box<dyn Simulation>, SimError> {
    system.dispatch(
        reconstruct,
        Single {
            system: system.kind(),
            method,
            solver,
            variable,
        },
    )
}

/// What building `method` on `system` says before a run: whether the system has a potential (so
/// that g must be integrated) and, when g is, whether the method builds.
#[derive(Debug)]
pub struct Probed {
    /// The system's `integrators::System::has_potential`.
    pub has_potential: bool,
    /// The method built (and dropped), or why not. Not tried without g on a system with a
    /// potential.
    pub built: Result<(), BuildError>,
}

/// Builds `method` on `system` once (see [`Probed`]).
pub fn probe(
    system: &System,
    method: &MethodSpec,
    reconstruct: bool,
    solver: &SolverOptions,
) -> Result<Probed, SimError> {
    system.dispatch(
        reconstruct,
        ProbeJob {
            method,
            solver,
            reconstruct,
        },
    )
}

/// The scene's time scale ω at its initial state (`integrators::System::characteristic_rate`
/// of its model; 0 at rest).
pub fn characteristic_rate(system: &System, reconstruct: bool) -> Result<f64, SimError> {
    system.dispatch(reconstruct, Rate)
}

/// The step density ρ(y₀) > 0 at the scene's initial state (`integrators::System::step_density`
/// of its model) that leaves out the spin a splitting follows exactly
/// (`integrators::DensityScope::SpinFollowed`, never above the full one): the reversible
/// variable steps of a splitting start at h = ε/ρ(y₀).
pub fn step_density(system: &System, reconstruct: bool) -> Result<f64, SimError> {
    system.dispatch(reconstruct, Density)
}

/// The scale s of the ε that `trade` and `choose` run reversible steps with at the level of step
/// h of their ladder, ε = h s, with `s = max(ρ(y₀), ω)`: ρ the step density at the initial state
/// ([`step_density`]) and ω the scene's time scale ([`characteristic_rate`]) that sets the
/// ladder (its coarsest step has hω = 1). Where ρ(y₀) ≥ ω (the provided density, |∂h/∂μ| plus
/// the potential's frequency), each reversible run starts with the ladder's step h. Where a
/// model's density leaves out a rate its steps need not resolve (a satellite's spin about Π,
/// `mechanics::RigidBodySe3`), ρ(y₀) may be far below ω, and ε = hρ(y₀) would start the
/// ε-ladder where even the coarsest run is finer than the fixed ladder's finest; ε = hω keeps
/// it the same dimensionless ladder, ε = 1, ½, ¼, … from its top. A method that declares the full
/// density (`integrators::DensityScope::Full`, Lie–Poisson θ = ½), whose ρ(y₀) ≥ ω, then starts
/// at a step at most h: one ε ladder per scene serves every method.
pub fn epsilon_scale(system: &System, reconstruct: bool) -> Result<f64, SimError> {
    Ok(step_density(system, reconstruct)?.max(characteristic_rate(system, reconstruct)?))
}

/// The refusal of `method` on a system of `kind` as an error of the run.
pub fn refusal(kind: SystemKind, method: &MethodSpec, e: BuildError) -> SimError {
    let what = format!("{kind} with {method}");
    match e {
        BuildError::Missing {
            need,
            why,
            unavailable: true,
        } => SimError::NotYetAvailable {
            what,
            why: BuildError::reason(&need, &why),
        },
        BuildError::Missing { need, why, .. } => SimError::Inapplicable {
            what,
            why: BuildError::reason(&need, &why),
        },
        BuildError::NotSymmetric { message, .. } => SimError::Inapplicable { what, why: message },
        BuildError::Integrator(e) => SimError::Build {
            what,
            message: e.to_string(),
        },
    }
}

/// The [`Job`] of [`build`]: the method on the model, with its system, as a [`Simulation`].
struct Single<'a> {
    system: SystemKind,
    method: &'a MethodSpec,
    solver: &'a SolverOptions,
    variable: Option<VariableSteps>,
}

impl Job for Single<'_> {
    type Out = Box<dyn Simulation>;
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<Self::Out, SimError> {
        let integrator = build_method(self.method, &self.solver.config(), model, mu0, g0)
            .map_err(|e| refusal(self.system, self.method, e))?;
        let system = model.system().clone();
        let what = || format!("{} with {}", self.system, self.method);
        let driver = match self.variable {
            None => return Ok(Box::new(Adapter::new(integrator, system))),
            Some(VariableSteps::Tolerance(tolerance)) => match integrator.into_pair() {
                Ok(pair) => Box::new(PairDriver::new(pair, tolerance)) as _,
                Err(_) => {
                    return Err(SimError::Build {
                        what: what(),
                        message: "it has no error estimate to run to a tolerance".into(),
                    })
                }
            },
            Some(VariableSteps::Reversible(epsilon)) => match integrator.into_reversible(epsilon) {
                Ok(driver) => driver.map_err(|e| SimError::Build {
                    what: what(),
                    message: e.to_string(),
                })?,
                Err(_) => {
                    return Err(SimError::Build {
                        what: what(),
                        message: "it is not symmetric (Φ_−h ≠ Φ_h⁻¹) on this system, so its \
                                  variable steps cannot be reversible (epsilon is for the \
                                  splittings, their compositions, kinetic-kick, and θ = ½); a \
                                  processed method takes fixed steps only"
                            .into(),
                    })
                }
            },
        };
        Ok(Box::new(DrivenSim::new(driver, system)))
    }
}

/// The [`Job`] of [`probe`].
struct ProbeJob<'a> {
    method: &'a MethodSpec,
    solver: &'a SolverOptions,
    reconstruct: bool,
}

impl Job for ProbeJob<'_> {
    type Out = Probed;
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<Probed, SimError> {
        let has_potential = model.system().has_potential();
        let built = if has_potential && !self.reconstruct {
            Ok(())
        } else {
            build_method(self.method, &self.solver.config(), model, mu0, g0).map(drop)
        };
        Ok(Probed {
            has_potential,
            built,
        })
    }
}

/// The [`Job`] of [`step_density`].
struct Density;

impl Job for Density {
    type Out = f64;
    fn run<M: Model>(self, model: &M, mu0: Alg<M::G>, g0: Option<M::G>) -> Result<f64, SimError> {
        Ok(model
            .system()
            .step_density(&mu0, g0.as_ref(), DensityScope::SpinFollowed))
    }
}

/// The [`Job`] of [`characteristic_rate`].
struct Rate;

impl Job for Rate {
    type Out = f64;
    fn run<M: Model>(self, model: &M, mu0: Alg<M::G>, g0: Option<M::G>) -> Result<f64, SimError> {
        Ok(model.system().characteristic_rate(&mu0, g0.as_ref()))
    }
}

/// The cost of a step of the built simulation `sim` relative to one on SO(3) ([`crate::bounds::stage_cost`]): its
/// group's sizes, how `solver` solves it when it is implicit, and whether its group is
/// dynamically sized (`dynamic`, [`crate::bounds::dynamic_group`]).
pub fn step_cost(sim: &dyn crate::sim::Simulation, solver: &SolverOptions, dynamic: bool) -> u128 {
    let solve = crate::bounds::Solve::of(sim.info().explicit, solver.config().kind);
    crate::bounds::stage_cost(sim.momentum_dim(), sim.group_side(), solve, dynamic)
}

/// Whether the solver iterates without a Jacobian.
pub fn fixed_point(solver: &SolverOptions) -> bool {
    matches!(solver.config().kind, integrators::SolverKind::FixedPoint)
}
