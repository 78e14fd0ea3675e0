//! The seam between the scene runner and the `integrators` crate.
//!
//! Everything above this module (running, writing CSV, plotting, the work-precision trade) sees a
//! scene only through [`Simulation`]: a state (t, μ, g) advanced by one step at a time. [`build`]
//! is the one place that knows the integrators crate: it dispatches the scene's
//! (system, method, τ) to a concrete, monomorphized integrator, boxed behind the trait, and builds
//! only that one.

use crate::error::SimError;
use crate::scene::{
    inapplicable, Forces, GeodesicSoN, Method, MethodSpec, SolverChoice, SolverOptions, System,
    TauKind,
};
use crate::vehicles::{BODY_COUNTS, WHEEL_COUNTS};
use faer::{Col, Mat};
use integrators::dense_output::{DenseState, HermiteStep};
use integrators::forces::{
    BodyInputMap, BodyTorque, ControlInput, Forced, LinearDamping, QuadraticDrag,
};
use integrators::processing::Processed;
use integrators::splitting::{KineticFlow, KineticKick, SplitSystem, Splitting, SplittingScheme};
use integrators::{
    Composition, EulerArnold, EulerPoincare, Integrator, IntegratorError, LiePoisson,
    QuaternionRk4, Rkmk4, SolverConfig, SolverKind, StateSnapshot, SymmetricMethod,
};
use lie_groups::{
    Cayley, CayleyGroup, DenseMatrix, ExpMap, LieError, LieGroup, Operator, Power, PowerAlgebra,
    Product, ProductAlgebra, Rn, Se2, Se3, So2, So3, SoN, Vector,
};
use mechanics::exact::{ExactFreeBody, FreeBodyFlow, FreeBodySe3Flow};
use mechanics::modified::{ModifiedLiePoisson, ModifiedScheme};
use mechanics::systems::{
    CoupledBodies as CoupledBodiesSystem, GeneralizedRigidBody, Gyrostat as GyrostatSystem,
    HeavyTop as HeavyTopSystem, PlanarBody as PlanarBodySystem, Quadrotor as QuadrotorSystem,
    RigidBody, RigidBodySe3 as RigidBodySe3System, Spring, UnderwaterVehicle as VehicleSystem,
};
use nalgebra::{Matrix3, SVector, Vector3, Vector6};

/// One running simulation: the integrator, its system and its state.
///
/// The momentum μ ∈ 𝔤* is given in the basis of the group's `vee` (Π for SO(3)); the group element
/// g (when reconstructed) as its matrix, row-major.
pub trait Simulation {
    /// Advances the state by one step of size `h`; on error the state is left unchanged and the
    /// integrator's message is returned.
    fn step(&mut self, h: f64) -> Result<(), String>;
    /// Current time t.
    fn time(&self) -> f64;
    /// Current body momentum μ.
    fn momentum(&self) -> Vec<f64>;
    /// Side m of the group element's m×m matrix, or `None` when g is not reconstructed.
    fn group_side(&self) -> Option<usize>;
    /// The group element's matrix entries row-major, or `None` when g is not reconstructed.
    fn group_matrix(&self) -> Option<Vec<f64>>;
    /// Total energy E = h(μ) + V(g).
    fn energy(&self) -> f64;
    /// The Casimir the system monitors (|Π|² for the free rigid body), if it has one.
    fn casimir(&self) -> Option<f64>;
    /// Current body velocity ξ = ∂h/∂μ (Ω = 𝕀⁻¹Π for the rigid body), in the basis of μ.
    fn velocity(&self) -> Vec<f64>;
    /// The spatial momentum map `J = Ad*_{g⁻¹} μ` (R Π on SO(3), (R Π + x × R P, R P) on SE(3)),
    /// in the basis of μ, or `None` when g is not reconstructed. Conserved by the flow of a
    /// left-invariant system; which part of it a system with a potential keeps is
    /// [`crate::invariants::conserved_momentum_map`].
    fn spatial_momentum(&self) -> Option<Vec<f64>>;
    /// What the method is and keeps, as it describes itself (`integrators::MethodInfo`).
    fn info(&self) -> integrators::MethodInfo;
    /// Why the state cannot be read, when its reads computed NaN (a processed method whose
    /// processor failed: `integrators::Integrator::read_error`); `None` otherwise.
    fn read_error(&self) -> Option<String> {
        None
    }

    /// The current state as a trajectory row: t, μ, g's entries (when reconstructed), energy,
    /// Casimir (when the system has one) — the columns of `run::header`.
    fn row(&self) -> Vec<f64> {
        let mut r = vec![self.time()];
        r.extend(self.momentum());
        r.extend(self.group_matrix().unwrap_or_default());
        r.push(self.energy());
        r.extend(self.casimir());
        r
    }
    /// Remembers the current state as the start of the step about to be taken, for
    /// [`Self::row_at`].
    fn mark(&mut self) {}
    /// The row at time t between the marked state and the current one, by the cubic Hermite
    /// interpolant of `integrators::dense_output` (energy and Casimir evaluated at the
    /// interpolated state).
    fn row_at(&self, _t: f64) -> Result<Vec<f64>, String> {
        Err("this simulation has no dense output".into())
    }
}

/// Builds the simulation a scene names: its system with its initial state, advanced by `method`.
///
/// Only the named combination is constructed. A (system, method, τ) that the integrators crate does
/// not provide is [`SimError::NotYetAvailable`], a method that does not apply to the system
/// (Euler–Arnold with a potential) [`SimError::Inapplicable`]; never a panic.
///
/// Systems: `mechanics::systems::{RigidBody, HeavyTop, RigidBodySe3, PlanarBody,
/// GeneralizedRigidBody<N>}` (the last for N in [`SO_N_SIZES`]). Methods: `LiePoisson` and
/// `EulerPoincare` with τ = exp or cayley and any θ; `euler-arnold`, the `EulerPoincare`
/// integrator of the `EulerArnold` system built from the system's inertia (see
/// [`EulerArnoldOf`]); any of these at θ = ½ inside a `Composition`; `Rkmk4` (τ = exp) on every
/// group; `QuaternionRk4` on the SO(3) systems.
pub fn build(
    system: &System,
    method: &MethodSpec,
    reconstruct: bool,
    solver: &SolverOptions,
) -> Result<Box<dyn Simulation>, SimError> {
    dispatch(system, method, reconstruct, solver, SingleRun)
}

/// A computation generic over the group G and the system S of a scene, run by [`dispatch`] once
/// it has built S, μ₀ and g₀. `make` turns (S, μ, g) into the scene's integrator.
pub trait Job {
    /// What the job produces.
    type Out;
    /// Runs the job on the scene's system.
    fn run<G, S, F>(
        self,
        system: S,
        mu0: G::Algebra,
        g0: Option<G>,
        make: F,
    ) -> Result<Self::Out, IntegratorError>
    where
        G: CayleyGroup + Sync + 'static,
        G::Algebra: Send + Sync,
        S: integrators::System<G> + Clone + Sync + 'static,
        F: Fn(S, G::Algebra, Option<G>) -> Result<Boxed<G>, IntegratorError> + Sync;
}

/// The [`Job`] of [`build`]: one integrator from the scene's initial state, as a [`Simulation`].
struct SingleRun;

impl Job for SingleRun {
    type Out = Box<dyn Simulation>;
    fn run<G, S, F>(
        self,
        system: S,
        mu0: G::Algebra,
        g0: Option<G>,
        make: F,
    ) -> Result<Self::Out, IntegratorError>
    where
        G: CayleyGroup + Sync + 'static,
        G::Algebra: Send + Sync,
        S: integrators::System<G> + Clone + Sync + 'static,
        F: Fn(S, G::Algebra, Option<G>) -> Result<Boxed<G>, IntegratorError> + Sync,
    {
        let integrator = make(system.clone(), mu0, g0)?;
        Ok(Box::new(Adapter::new(integrator, system)))
    }
}

/// Builds the scene's system, μ₀ and g₀ (g₀ only when `reconstruct`), checks that the method
/// applies, and runs `job` on them with the integrator maker of `method`.
pub fn dispatch<J: Job>(
    system: &System,
    method: &MethodSpec,
    reconstruct: bool,
    solver: &SolverOptions,
    job: J,
) -> Result<J::Out, SimError> {
    let what = || format!("{} with {}", system.kind(), method);
    let unavailable = |why: &str| SimError::NotYetAvailable {
        what: what(),
        why: why.to_string(),
    };
    let built = |e: IntegratorError| SimError::Build {
        what: what(),
        message: e.to_string(),
    };
    let lie = |e: LieError| SimError::Build {
        what: what(),
        message: e.to_string(),
    };
    if let Some(why) = inapplicable(method, system) {
        return Err(SimError::Inapplicable { what: what(), why });
    }
    if method.method == Method::Rk4
        && !matches!(system, System::FreeRigidBody(_) | System::HeavyTop(_))
    {
        return Err(unavailable(
            "rk4 integrates quaternions, so only the SO(3) systems (free-rigid-body, \
             heavy-top); use rkmk4 on other groups",
        ));
    }
    let mut config = SolverConfig::default();
    if let Some(kind) = solver.kind {
        config.kind = match kind {
            SolverChoice::SimplifiedNewton => SolverKind::SimplifiedNewton,
            SolverChoice::Newton => SolverKind::Newton,
            SolverChoice::NewtonFd => SolverKind::NewtonFiniteDifference,
            SolverChoice::FixedPoint => SolverKind::FixedPoint,
        };
    }
    if let Some(t) = solver.tolerance {
        config.tolerance = t;
    }
    if let Some(m) = solver.max_iterations {
        config.max_iterations = m;
    }
    let b = Builder {
        method: method.clone(),
        config,
    };
    let so3 = |r: &Matrix3<f64>| -> Result<Option<So3>, SimError> {
        if reconstruct {
            So3::from_matrix(r).map(Some).map_err(lie)
        } else {
            Ok(None)
        }
    };
    match system {
        System::FreeRigidBody(p) => {
            let body = RigidBody::new(p.inertia).map_err(built)?;
            if let Some(f) = &p.forces {
                let forced = Forced::new(body, scene_force(f).map_err(built)?);
                return job
                    .run(forced, p.momentum, so3(&p.attitude)?, |s, mu, g| {
                        let flow = FreeBodyFlow::new(s.system());
                        b.make_forced(s, flow, mu, g)
                    })
                    .map_err(built);
            }
            job.run(body, p.momentum, so3(&p.attitude)?, |s, mu, g| {
                b.make_rigid_body(s, mu, g)
            })
            .map_err(built)
        }
        System::HeavyTop(p) => {
            let top = HeavyTopSystem::new(p.inertia, p.mass, p.gravity, p.center_of_mass)
                .map_err(built)?;
            if let Some(f) = &p.forces {
                let forced = Forced::new(top, scene_force(f).map_err(built)?);
                return job
                    .run(forced, p.momentum, so3(&p.attitude)?, |s, mu, g| {
                        let flow = FreeBodyFlow::new(s.system().body());
                        b.make_forced(s, flow, mu, g)
                    })
                    .map_err(built);
            }
            job.run(top, p.momentum, so3(&p.attitude)?, |s, mu, g| {
                b.make_heavy_top(s, mu, g)
            })
            .map_err(built)
        }
        System::RigidBodySe3(p) => {
            let g0 = so3(&p.attitude)?.map(|r| Se3::from_parts(r, p.position));
            if p.gravitational_parameter > 0.0 {
                let sat =
                    RigidBodySe3System::satellite(p.mass, p.inertia, p.gravitational_parameter)
                        .map_err(built)?;
                job.run(sat, p.momentum, g0, |s, mu, g| b.make_se3(s, mu, g))
                    .map_err(built)
            } else {
                let free = WithCasimir::<Se3, _> {
                    inner: RigidBodySe3System::free(p.mass, p.inertia).map_err(built)?,
                    casimir: |mu: &Vector6<f64>| mu.fixed_rows::<3>(3).norm_squared(),
                };
                job.run(free, p.momentum, g0, |s, mu, g| {
                    let flow = FreeBodySe3Flow::new(&s.inner);
                    b.make_kinetic_or_split(s, flow, mu, g)
                })
                .map_err(built)
            }
        }
        System::PlanarBodySe2(p) => {
            let body = PlanarBodySystem::free(p.mass, p.inertia)
                .and_then(|s| s.with_spring(p.stiffness, p.attachment))
                .and_then(|s| s.with_gravity(p.gravity))
                .map_err(built)?;
            let g0 = reconstruct.then(|| Se2::new(So2::from_angle(p.angle), p.position));
            if system.has_potential() {
                job.run(body, p.momentum, g0, |s, mu, g| b.make_split(s, mu, g))
                    .map_err(built)
            } else {
                let free = WithCasimir::<Se2, _> {
                    inner: body,
                    casimir: |mu: &Vector3<f64>| mu[1] * mu[1] + mu[2] * mu[2],
                };
                job.run(free, p.momentum, g0, |s, mu, g| b.make_split(s, mu, g))
                    .map_err(built)
            }
        }
        System::GeodesicSoN(p) => so_n(&b, p, reconstruct, job).map_err(|e| match e {
            SizedError::Size => unavailable(&format!(
                "SO({}) is not compiled into lie-sim (sizes: {SO_N_SIZES:?})",
                p.n
            )),
            SizedError::Integrator(e) => built(e),
            SizedError::Lie(e) => lie(e),
        }),
        System::Gyrostat(p) => gyrostat(&b, p, reconstruct, job).map_err(|e| match e {
            SizedError::Size => unavailable(&format!(
                "{} wheels are not compiled into lie-sim (counts: {WHEEL_COUNTS:?})",
                p.axes.len()
            )),
            SizedError::Integrator(e) => built(e),
            SizedError::Lie(e) => lie(e),
        }),
        System::UnderwaterVehicle(p) => {
            let vehicle = VehicleSystem::new(p.mass_matrix())
                .and_then(|v| {
                    v.with_restoring(
                        p.weight(),
                        p.center_of_gravity,
                        p.buoyancy,
                        p.center_of_buoyancy,
                    )
                })
                .map_err(built)?;
            let g0 = so3(&p.attitude)?.map(|r| Se3::from_parts(r, p.position));
            match &p.forces {
                None => job.run(vehicle, p.momentum, g0, |s, mu, g| b.make_split(s, mu, g)),
                Some(f) => {
                    let forced = Forced::new(vehicle, se3_force(f).map_err(built)?);
                    job.run(forced, p.momentum, g0, |s, mu, g| b.make_split(s, mu, g))
                }
            }
            .map_err(built)
        }
        System::Quadrotor(p) => {
            let quad = QuadrotorSystem::new(p.mass, p.inertia, p.gravity).map_err(built)?;
            let g0 = so3(&p.attitude)?.map(|r| Se3::from_parts(r, p.position));
            match &p.forces {
                None => job.run(quad, p.momentum, g0, |s, mu, g| {
                    let flow = FreeBodySe3Flow::new(s.body());
                    b.make_kinetic_or_split(s, flow, mu, g)
                }),
                Some(f) => {
                    let forced = Forced::new(quad, se3_force(f).map_err(built)?);
                    job.run(forced, p.momentum, g0, |s, mu, g| {
                        let flow = FreeBodySe3Flow::new(s.system().body());
                        b.make_kinetic_or_split(s, flow, mu, g)
                    })
                }
            }
            .map_err(built)
        }
        System::CoupledBodies(p) => coupled(&b, p, reconstruct, job).map_err(|e| match e {
            SizedError::Size => unavailable(&format!(
                "{} bodies are not compiled into lie-sim (counts: {BODY_COUNTS:?})",
                p.bodies.len()
            )),
            SizedError::Integrator(e) => built(e),
            SizedError::Lie(e) => lie(e),
        }),
    }
}

/// The n of SO(n) compiled into the binary (one monomorphized integrator per n, method and τ).
pub const SO_N_SIZES: [usize; 8] = [3, 4, 5, 6, 8, 10, 20, 50];

/// Any integrator of the integrators crate on the group G, boxed: the type the scene's
/// (method, τ, composition) is erased to, so that one generic code path runs them all.
pub struct Boxed<G: LieGroup>(Box<dyn Integrator<Group = G>>);

impl<G: LieGroup> Boxed<G> {
    fn new<I: Integrator<Group = G> + 'static>(i: I) -> Self {
        Self(Box::new(i))
    }
}

impl<G: LieGroup> Integrator for Boxed<G> {
    type Group = G;
    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        self.0.step(h)
    }
    fn time(&self) -> f64 {
        self.0.time()
    }
    fn momentum(&self) -> G::Algebra {
        self.0.momentum()
    }
    fn velocity(&self) -> G::Algebra {
        self.0.velocity()
    }
    fn momentum_rate(&self) -> G::Algebra {
        self.0.momentum_rate()
    }
    fn configuration(&self) -> Option<&G> {
        self.0.configuration()
    }
    fn energy(&self) -> f64 {
        self.0.energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.0.casimir()
    }
    fn method_name(&self) -> String {
        self.0.method_name()
    }
    fn info(&self) -> integrators::MethodInfo {
        self.0.info()
    }
    fn read_error(&self) -> Option<IntegratorError> {
        self.0.read_error()
    }
}

/// `inner`, or `inner` composed with the spec's composition scheme, or processed by its
/// processing scheme (both refuse a base that is not symmetric).
fn composed<I>(inner: I, spec: &MethodSpec) -> Result<Boxed<I::Group>, IntegratorError>
where
    I: SymmetricMethod + StateSnapshot + Clone + 'static,
{
    Ok(match (&spec.composition, &spec.processing) {
        (Some(s), _) => Boxed::new(Composition::new(inner, s.clone())?),
        (None, Some(p)) => Boxed::new(Processed::composition(inner, p.clone())?),
        (None, None) => Boxed::new(inner),
    })
}

/// Builds integrators of one method spec for any group with a Cayley map.
struct Builder {
    method: MethodSpec,
    config: SolverConfig,
}

impl Builder {
    /// Lie–Poisson, Euler–Poincaré, Euler–Arnold (τ = exp or cayley, optionally composed) or
    /// RKMK4 on any group. RK4 is refused here ([`dispatch`] routes it to [`Builder::make_so3`]
    /// and refuses it on other groups before).
    fn make<G, S>(
        &self,
        system: S,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Boxed<G>, IntegratorError>
    where
        G: CayleyGroup + 'static,
        S: integrators::System<G> + Clone + 'static,
    {
        let theta = self.method.theta.unwrap_or(0.0);
        let c = self.config;
        let comp = &self.method;
        match (self.method.method, self.method.tau) {
            (Method::Rkmk4, _) => Ok(Boxed::new(Rkmk4::<G, S>::new(system, mu0, g0)?)),
            (Method::EulerPoincare, Some(TauKind::Exp)) => composed(
                EulerPoincare::<G, ExpMap, S>::from_momentum(system, theta, mu0, g0)?
                    .with_solver(c),
                comp,
            ),
            (Method::EulerPoincare, _) => composed(
                EulerPoincare::<G, Cayley, S>::from_momentum(system, theta, mu0, g0)?
                    .with_solver(c),
                comp,
            ),
            (Method::LiePoisson, Some(TauKind::Exp)) => composed(
                LiePoisson::<G, ExpMap, S>::new(system, theta, mu0, g0)?.with_solver(c),
                comp,
            ),
            (Method::LiePoisson, _) => composed(
                LiePoisson::<G, Cayley, S>::new(system, theta, mu0, g0)?.with_solver(c),
                comp,
            ),
            (Method::EulerArnold, tau) => {
                let ea = EulerArnoldOf::new(system, &mu0)?;
                match tau {
                    Some(TauKind::Exp) => composed(
                        EulerPoincare::<G, ExpMap, _>::from_momentum(ea, theta, mu0, g0)?
                            .with_solver(c),
                        comp,
                    ),
                    _ => composed(
                        EulerPoincare::<G, Cayley, _>::from_momentum(ea, theta, mu0, g0)?
                            .with_solver(c),
                        comp,
                    ),
                }
            }
            (Method::Rk4 | Method::Splitting | Method::KineticKick | Method::Exact, _) => {
                Err(IntegratorError::InvalidParameter {
                    reason: format!(
                        "{} is not built for this system on {}",
                        self.method.method,
                        G::name()
                    ),
                })
            }
        }
    }

    /// As [`Builder::make`], plus the Strang splitting of a system that declares its pieces.
    fn make_split<G, S>(
        &self,
        system: S,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Boxed<G>, IntegratorError>
    where
        G: CayleyGroup + 'static,
        S: SplitSystem<G> + Clone + 'static,
    {
        match self.method.method {
            Method::Splitting => composed(Splitting::new(system, mu0, g0)?, &self.method),
            _ => self.make(system, mu0, g0),
        }
    }

    /// The satellite (or free body) on SE(3): every method, the kinetic–kick with the exact
    /// free-body flow on SE(3) included.
    fn make_se3(
        &self,
        system: RigidBodySe3System,
        mu0: Vector6<f64>,
        g0: Option<Se3>,
    ) -> Result<Boxed<Se3>, IntegratorError> {
        let flow = FreeBodySe3Flow::new(&system);
        self.make_kinetic_or_split(system, flow, mu0, g0)
    }

    /// `kinetic-kick` with the kinetic flow `flow`, or any other method of [`Builder::make_split`].
    fn make_kinetic_or_split<G, S, K>(
        &self,
        system: S,
        flow: K,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Boxed<G>, IntegratorError>
    where
        G: CayleyGroup + 'static,
        S: SplitSystem<G> + Clone + 'static,
        K: KineticFlow<G> + Clone + 'static,
    {
        match self.method.method {
            Method::KineticKick => {
                let scheme = self
                    .method
                    .splitting
                    .clone()
                    .unwrap_or_else(SplittingScheme::strang);
                composed(
                    KineticKick::new(system, flow, scheme, mu0, g0)?,
                    &self.method,
                )
            }
            _ => self.make_split(system, mu0, g0),
        }
    }

    /// The free rigid body: every method, the exact flow, the kinetic–kick and the modified
    /// Lie–Poisson step included.
    fn make_rigid_body(
        &self,
        body: RigidBody,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Result<Boxed<So3>, IntegratorError> {
        if let Some(order) = self.method.modified {
            let c = self.config;
            let scheme = ModifiedScheme::new(self.method.theta.unwrap_or(0.5), order)?;
            return Ok(match self.method.tau {
                Some(TauKind::Exp) => Boxed::new(
                    ModifiedLiePoisson::<ExpMap>::with_scheme(body, scheme, mu0, g0)?
                        .with_solver(c),
                ),
                _ => Boxed::new(
                    ModifiedLiePoisson::<Cayley>::with_scheme(body, scheme, mu0, g0)?
                        .with_solver(c),
                ),
            });
        }
        match self.method.method {
            Method::Exact => Ok(Boxed::new(ExactFreeBody::new(body, mu0, g0)?)),
            Method::KineticKick => {
                let flow = FreeBodyFlow::new(&body);
                self.make_kinetic_or_split(body, flow, mu0, g0)
            }
            _ => self.make_so3(body, mu0, g0),
        }
    }

    /// The heavy top: every method, the kinetic–kick with the exact flow of its body included.
    fn make_heavy_top(
        &self,
        top: HeavyTopSystem,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Result<Boxed<So3>, IntegratorError> {
        match self.method.method {
            Method::KineticKick => {
                let flow = FreeBodyFlow::new(top.body());
                self.make_kinetic_or_split(top, flow, mu0, g0)
            }
            _ => self.make_so3(top, mu0, g0),
        }
    }

    /// A forced system on SO(3): Lie–Poisson, Euler–Poincaré, RK4, RKMK4, the splittings and the
    /// kinetic–kick with `flow`, the exact flow of its body (the methods that take external forces;
    /// the others are refused by [`inapplicable`] before).
    fn make_forced<S>(
        &self,
        system: S,
        flow: FreeBodyFlow,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Result<Boxed<So3>, IntegratorError>
    where
        S: SplitSystem<So3> + Clone + 'static,
    {
        match self.method.method {
            Method::KineticKick => self.make_kinetic_or_split(system, flow, mu0, g0),
            _ => self.make_so3(system, mu0, g0),
        }
    }

    /// As [`Builder::make_split`], plus RK4 on (quaternion, Π) for systems on SO(3).
    fn make_so3<S>(
        &self,
        system: S,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Result<Boxed<So3>, IntegratorError>
    where
        S: SplitSystem<So3> + Clone + 'static,
    {
        match self.method.method {
            Method::Rk4 => Ok(Boxed::new(QuaternionRk4::new(system, mu0, g0)?)),
            _ => self.make_split(system, mu0, g0),
        }
    }
}

/// The `[forces]` of a scene on SO(3): body torque schedule u(t) plus damping `−D Ω`, each
/// optional.
type SceneForce = (Option<BodyTorque<So3>>, Option<LinearDamping<So3>>);

fn scene_force(f: &Forces) -> Result<SceneForce, IntegratorError> {
    Ok((
        f.torque.clone().map(BodyTorque::new).transpose()?,
        f.damping3().map(LinearDamping::new).transpose()?,
    ))
}

/// The `[forces]` of a scene on SE(3): a body torque (input map (I₃, 0)), a body force
/// ((0, I₃)) or the quadrotor's thrust ((0, e₃)), linear damping `−D ξ` and quadratic drag, each
/// optional.
type Se3Force = (
    Option<ControlInput<Se3>>,
    (
        Option<ControlInput<Se3>>,
        (Option<LinearDamping<Se3>>, Option<QuadraticDrag<Se3>>),
    ),
);

fn se3_force(f: &Forces) -> Result<Se3Force, IntegratorError> {
    let input = |first: usize, count: usize, s: &integrators::forces::Schedule| {
        ControlInput::new(BodyInputMap::<Se3>::components(first, count)?, s.clone())
    };
    let torque = f.torque.as_ref().map(|s| input(0, 3, s)).transpose()?;
    let push = match (&f.force, &f.thrust) {
        (Some(s), _) => Some(input(3, 3, s)?),
        (None, Some(s)) => Some(QuadrotorSystem::thrust(s.clone())?),
        (None, None) => None,
    };
    Ok((
        torque,
        (
            push,
            (
                f.damping6().map(LinearDamping::new).transpose()?,
                f.quadratic_drag6().map(QuadraticDrag::new).transpose()?,
            ),
        ),
    ))
}

/// A gyrostat scene on SO(3) × ℝᴷ for the K of [`WHEEL_COUNTS`]: its system, (Π, p), (R, φ), and
/// its wheel and platform torques.
fn gyrostat<J: Job>(
    b: &Builder,
    p: &crate::scene::Gyrostat,
    reconstruct: bool,
    job: J,
) -> Result<J::Out, SizedError> {
    fn go<const K: usize, J: Job>(
        b: &Builder,
        p: &crate::scene::Gyrostat,
        reconstruct: bool,
        job: J,
    ) -> Result<J::Out, SizedError> {
        let gyro = GyrostatSystem::<K>::new(
            p.inertia,
            core::array::from_fn(|i| p.axes[i]),
            core::array::from_fn(|i| p.wheel_inertia[i]),
        )
        .map_err(SizedError::Integrator)?;
        let mu0 = ProductAlgebra::<So3, Rn<K>>::new(
            Vector3::from_column_slice(&p.momentum[..3]),
            SVector::<f64, K>::from_column_slice(&p.momentum[3..]),
        );
        let g0 = if reconstruct {
            Some(Product::new(
                So3::from_matrix(&p.attitude).map_err(SizedError::Lie)?,
                Rn::new(SVector::<f64, K>::from_column_slice(&p.wheel_angles)),
            ))
        } else {
            None
        };
        match &p.forces {
            None => job.run(gyro, mu0, g0, |s, mu, g| b.make_split(s, mu, g)),
            Some(f) => {
                let force = (
                    f.torque
                        .clone()
                        .map(GyrostatSystem::<K>::body_torque)
                        .transpose()
                        .map_err(SizedError::Integrator)?,
                    f.wheel_torque
                        .clone()
                        .map(GyrostatSystem::<K>::wheel_torques)
                        .transpose()
                        .map_err(SizedError::Integrator)?,
                );
                job.run(Forced::new(gyro, force), mu0, g0, |s, mu, g| {
                    b.make_split(s, mu, g)
                })
            }
        }
        .map_err(SizedError::Integrator)
    }
    match p.axes.len() {
        1 => go::<1, J>(b, p, reconstruct, job),
        2 => go::<2, J>(b, p, reconstruct, job),
        3 => go::<3, J>(b, p, reconstruct, job),
        4 => go::<4, J>(b, p, reconstruct, job),
        _ => Err(SizedError::Size),
    }
}

/// A coupled-bodies scene on SE(3)ᴺ for the N of [`BODY_COUNTS`]: free bodies joined by springs.
fn coupled<J: Job>(
    b: &Builder,
    p: &crate::scene::CoupledBodies,
    reconstruct: bool,
    job: J,
) -> Result<J::Out, SizedError> {
    fn go<const N: usize, J: Job>(
        b: &Builder,
        p: &crate::scene::CoupledBodies,
        reconstruct: bool,
        job: J,
    ) -> Result<J::Out, SizedError> {
        let bodies: Vec<RigidBodySe3System> = p
            .bodies
            .iter()
            .map(|(m, i)| RigidBodySe3System::free(*m, *i))
            .collect::<Result<_, _>>()
            .map_err(SizedError::Integrator)?;
        let bodies: [RigidBodySe3System; N] = bodies.try_into().map_err(|_| SizedError::Size)?;
        let springs = p
            .springs
            .iter()
            .map(|s| Spring::new(s.between, s.attachments, s.stiffness, s.rest_length))
            .collect::<Result<Vec<_>, _>>()
            .map_err(SizedError::Integrator)?;
        let system = CoupledBodiesSystem::new(bodies, springs).map_err(SizedError::Integrator)?;
        let mu0 = PowerAlgebra::<Se3, N>::from_parts_fn(|k| p.initial[k].momentum);
        let g0 = if reconstruct {
            let parts: Vec<Se3> = p
                .initial
                .iter()
                .map(|st| So3::from_matrix(&st.attitude).map(|r| Se3::from_parts(r, st.position)))
                .collect::<Result<_, _>>()
                .map_err(SizedError::Lie)?;
            let parts: [Se3; N] = parts.try_into().map_err(|_| SizedError::Size)?;
            Some(Power::new(parts))
        } else {
            None
        };
        job.run(system, mu0, g0, |s, mu, g| b.make_split(s, mu, g))
            .map_err(SizedError::Integrator)
    }
    match p.bodies.len() {
        2 => go::<2, J>(b, p, reconstruct, job),
        3 => go::<3, J>(b, p, reconstruct, job),
        4 => go::<4, J>(b, p, reconstruct, job),
        _ => Err(SizedError::Size),
    }
}

/// The Euler–Arnold system of a purely kinetic system S: l(ξ) = ½⟨𝕀ξ, ξ⟩ with
/// 𝕀 = (∂²h/∂μ²)⁻¹ (constant for the quadratic h(μ) = ½⟨μ, 𝕀⁻¹μ⟩ of the free rigid body, the free
/// SE(3) and SE(2) bodies and the SO(n) geodesics), symmetrised as ½(𝕀 + 𝕀ᵀ) against the
/// rounding of the inversion. The dynamics are `integrators::EulerArnold`'s; the Casimir
/// monitored is S's (it depends on μ only), so that `euler-arnold` runs report it like the others.
#[derive(Debug, Clone)]
pub struct EulerArnoldOf<G: LieGroup, S> {
    ea: EulerArnold<G>,
    original: S,
}

/// Relative agreement required between S's h and the Euler–Arnold h at the probe momenta: a
/// quadratic h agrees to a few ulps (the only rounding is the inversion of a well-conditioned
/// inertia), a non-quadratic one (or one with a hidden potential term in h) by far more.
const EULER_ARNOLD_AGREEMENT: f64 = 1e-10;

impl<G: LieGroup, S: integrators::System<G>> EulerArnoldOf<G, S> {
    /// Builds 𝕀 from S's Hessian at μ₀ and checks that h_S(μ) = ½⟨μ, 𝕀⁻¹μ⟩ at μ₀ and at
    /// μ = (1, …, 1), to [`EULER_ARNOLD_AGREEMENT`] relative.
    pub fn new(original: S, mu0: &G::Algebra) -> Result<Self, IntegratorError> {
        if original.has_potential() {
            return Err(IntegratorError::InvalidParameter {
                reason: "Euler–Arnold needs a purely kinetic Lagrangian: the system has a \
                         potential V(g)"
                    .into(),
            });
        }
        let inv = original.hessian(mu0).try_inverse().ok_or_else(|| {
            IntegratorError::InvalidParameter {
                reason: "the Hessian ∂²h/∂μ² is singular: no inertia operator".into(),
            }
        })?;
        let inertia = inv.add(&inv.transpose()).scale(0.5);
        let ea = EulerArnold::<G>::new(inertia)?;
        let ones = G::Algebra::from_fn(G::dim(), |_| 1.0);
        for mu in [mu0, &ones] {
            let (a, b) = (
                integrators::System::<G>::hamiltonian(&ea, mu),
                original.hamiltonian(mu),
            );
            if (a - b).abs() > EULER_ARNOLD_AGREEMENT * b.abs() {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!(
                        "Euler–Arnold needs a quadratic kinetic energy: h(μ) = {b} but \
                         ½⟨μ, 𝕀⁻¹μ⟩ = {a}"
                    ),
                });
            }
        }
        Ok(Self { ea, original })
    }
}

impl<G: LieGroup, S: integrators::System<G>> integrators::System<G> for EulerArnoldOf<G, S> {
    fn hamiltonian(&self, mu: &G::Algebra) -> f64 {
        self.ea.hamiltonian(mu)
    }
    fn velocity(&self, mu: &G::Algebra) -> G::Algebra {
        self.ea.velocity(mu)
    }
    fn hessian(&self, mu: &G::Algebra) -> G::Operator {
        self.ea.hessian(mu)
    }
    fn momentum(&self, xi: &G::Algebra) -> G::Algebra {
        self.ea.momentum(xi)
    }
    fn casimir(&self, mu: &G::Algebra) -> Option<f64> {
        self.original.casimir(mu)
    }
}

/// A failure of a dispatch over the sizes compiled into lie-sim (SO(n), the gyrostat's wheels,
/// the coupled bodies).
enum SizedError {
    Size,
    Integrator(IntegratorError),
    Lie(LieError),
}

fn so_n<J: Job>(
    b: &Builder,
    p: &GeodesicSoN,
    reconstruct: bool,
    job: J,
) -> Result<J::Out, SizedError> {
    fn go<const N: usize, J: Job>(
        b: &Builder,
        p: &GeodesicSoN,
        reconstruct: bool,
        job: J,
    ) -> Result<J::Out, SizedError> {
        let body = GeneralizedRigidBody::<N>::new(&p.inertia).map_err(SizedError::Integrator)?;
        let mu0 = Col::from_fn(p.momentum.len(), |i| p.momentum[i]);
        let g0 = if reconstruct {
            let m = Mat::from_fn(N, N, |r, c| p.attitude[r * N + c]);
            Some(SoN::<N>::from_matrix(&m).map_err(SizedError::Lie)?)
        } else {
            None
        };
        job.run::<SoN<N>, _, _>(body, mu0, g0, |s, mu, g| b.make(s, mu, g))
            .map_err(SizedError::Integrator)
    }
    match p.n {
        3 => go::<3, J>(b, p, reconstruct, job),
        4 => go::<4, J>(b, p, reconstruct, job),
        5 => go::<5, J>(b, p, reconstruct, job),
        6 => go::<6, J>(b, p, reconstruct, job),
        8 => go::<8, J>(b, p, reconstruct, job),
        10 => go::<10, J>(b, p, reconstruct, job),
        20 => go::<20, J>(b, p, reconstruct, job),
        50 => go::<50, J>(b, p, reconstruct, job),
        _ => Err(SizedError::Size),
    }
}

/// A free system of the integrators crate with a Casimir C(μ) of the Lie–Poisson bracket added for
/// monitoring: |P|² (the body linear momentum) on 𝔰𝔢(2)* and 𝔰𝔢(3)* (Ṗ = P × Ω keeps |P|), which the
/// integrators crate's `PlanarBody` and `RigidBodySe3` do not report. Only for bodies without a
/// potential: a force breaks it. Everything else is delegated.
#[derive(Debug, Clone)]
struct WithCasimir<G: LieGroup, S> {
    inner: S,
    casimir: fn(&G::Algebra) -> f64,
}

impl<G: LieGroup, S: integrators::System<G>> integrators::System<G> for WithCasimir<G, S> {
    fn hamiltonian(&self, mu: &G::Algebra) -> f64 {
        self.inner.hamiltonian(mu)
    }
    fn velocity(&self, mu: &G::Algebra) -> G::Algebra {
        self.inner.velocity(mu)
    }
    fn hessian(&self, mu: &G::Algebra) -> G::Operator {
        self.inner.hessian(mu)
    }
    fn momentum(&self, xi: &G::Algebra) -> G::Algebra {
        self.inner.momentum(xi)
    }
    fn diagonal_velocity(&self) -> Option<G::Algebra> {
        self.inner.diagonal_velocity()
    }
    fn casimir(&self, mu: &G::Algebra) -> Option<f64> {
        Some((self.casimir)(mu))
    }
}

impl<G: LieGroup, S: SplitSystem<G>> SplitSystem<G> for WithCasimir<G, S> {
    fn pieces(&self) -> usize {
        self.inner.pieces()
    }
    fn piece_velocity(&self, i: usize, mu: &G::Algebra) -> G::Algebra {
        self.inner.piece_velocity(i, mu)
    }
    fn piece_flow(&self, i: usize, t: f64, mu: &mut G::Algebra, g: Option<&mut G>) {
        self.inner.piece_flow(i, t, mu, g)
    }
}

/// The entries of g's matrix, row-major (the trajectory's `g11, g12, …`).
pub fn row_major<G: LieGroup>(g: &G) -> Vec<f64> {
    let m = g.matrix().to_mat();
    (0..m.nrows())
        .flat_map(|i| (0..m.ncols()).map(move |j| (i, j)))
        .map(|(i, j)| m[(i, j)])
        .collect()
}

/// Any integrator of the integrators crate, seen as a [`Simulation`].
struct Adapter<I: Integrator> {
    integrator: I,
    /// (E, C) at a state (μ, g), from the system (for interpolated rows).
    invariants: InvariantsOf<I::Group>,
    /// The state at the start of the current step ([`Simulation::mark`]).
    marked: Option<DenseState<I::Group>>,
}

/// `(μ, g) ↦ (E(μ, g), C(μ))` of a system.
type InvariantsOf<G> = Box<dyn Fn(&<G as LieGroup>::Algebra, Option<&G>) -> (f64, Option<f64>)>;

impl<I: Integrator> Adapter<I> {
    fn new<S: integrators::System<I::Group> + 'static>(integrator: I, system: S) -> Self {
        Self {
            integrator,
            invariants: Box::new(move |mu, g| (system.energy(mu, g), system.casimir(mu))),
            marked: None,
        }
    }
}

impl<I: Integrator> Simulation for Adapter<I> {
    fn step(&mut self, h: f64) -> Result<(), String> {
        self.integrator.step(h).map_err(|e| e.to_string())
    }
    fn mark(&mut self) {
        self.marked = Some(DenseState::of(&self.integrator));
    }
    fn row_at(&self, t: f64) -> Result<Vec<f64>, String> {
        let start = self
            .marked
            .as_ref()
            .ok_or("no step marked for dense output")?;
        let step = HermiteStep::between(start, &DenseState::of(&self.integrator))
            .map_err(|e| e.to_string())?;
        let (mu, g) = step.at(t);
        let (energy, casimir) = (self.invariants)(&mu, g.as_ref());
        let mut r = vec![t];
        r.extend(mu.to_vec());
        if let Some(g) = &g {
            r.extend(row_major(g));
        }
        r.push(energy);
        r.extend(casimir);
        Ok(r)
    }
    fn time(&self) -> f64 {
        self.integrator.time()
    }
    fn momentum(&self) -> Vec<f64> {
        self.integrator.momentum().to_vec()
    }
    fn group_side(&self) -> Option<usize> {
        self.integrator
            .configuration()
            .map(|g| g.matrix().to_mat().nrows())
    }
    fn group_matrix(&self) -> Option<Vec<f64>> {
        self.integrator.configuration().map(row_major)
    }
    fn energy(&self) -> f64 {
        self.integrator.energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.integrator.casimir()
    }
    fn velocity(&self) -> Vec<f64> {
        self.integrator.velocity().to_vec()
    }
    fn spatial_momentum(&self) -> Option<Vec<f64>> {
        // Ad*_{g⁻¹} μ = (Ad_{g⁻¹})ᵀ μ: `coadjoint_apply` is the dual map of Ad, so it is applied
        // to g⁻¹ (on SO(3), Ad_{R⁻¹} = Rᵀ and J = R Π).
        self.integrator.configuration().map(|g| {
            g.inverse()
                .coadjoint_apply(&self.integrator.momentum())
                .to_vec()
        })
    }
    fn info(&self) -> integrators::MethodInfo {
        self.integrator.info()
    }
    fn read_error(&self) -> Option<String> {
        self.integrator.read_error().map(|e| e.to_string())
    }
}

#[cfg(test)]
pub(crate) mod mock {
    //! A closed-form stand-in for the integrators, to test the runner without them: the free rigid
    //! body spinning about a principal axis, Π constant and R(t) = exp(t Ω̂), Ω = Π₃/I₃ e₃.
    use super::Simulation;

    /// Uniform rotation about e₃ at rate `omega`, with optional step failure after `fail_after`.
    pub struct Spin {
        pub t: f64,
        pub omega: f64,
        pub reconstruct: bool,
        pub fail_after: Option<usize>,
        pub steps: usize,
    }

    impl Simulation for Spin {
        fn step(&mut self, h: f64) -> Result<(), String> {
            if self.fail_after == Some(self.steps) {
                return Err("no convergence".into());
            }
            self.t += h;
            self.steps += 1;
            Ok(())
        }
        fn time(&self) -> f64 {
            self.t
        }
        fn momentum(&self) -> Vec<f64> {
            vec![0.0, 0.0, 3.0 * self.omega]
        }
        fn group_side(&self) -> Option<usize> {
            self.reconstruct.then_some(3)
        }
        fn group_matrix(&self) -> Option<Vec<f64>> {
            let (s, c) = (self.omega * self.t).sin_cos();
            self.reconstruct
                .then(|| vec![c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0])
        }
        fn energy(&self) -> f64 {
            0.5 * 3.0 * self.omega * self.omega
        }
        fn casimir(&self) -> Option<f64> {
            Some(9.0 * self.omega * self.omega)
        }
        fn velocity(&self) -> Vec<f64> {
            vec![0.0, 0.0, self.omega]
        }
        /// R Π = Π: the rotation is about Π's own axis e₃.
        fn spatial_momentum(&self) -> Option<Vec<f64>> {
            self.reconstruct.then(|| self.momentum())
        }
        /// The exact uniform rotation.
        fn info(&self) -> integrators::MethodInfo {
            integrators::MethodInfo {
                order: integrators::MethodInfo::EXACT,
                symmetric: true,
                explicit: true,
                poisson: true,
                casimirs: true,
                momentum_map: true,
                energy: true,
                on_group: true,
            }
        }
    }
}
