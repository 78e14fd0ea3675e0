//! The seam between the scene runner and the `integrators` crate.
//!
//! Everything above this module (running, writing CSV, plotting, the work-precision trade) sees a
//! scene only through [`Simulation`]: a state (t, μ, g) advanced by one step at a time. [`build`]
//! is the one place that knows the integrators crate: it dispatches the scene's
//! (system, method, τ) to a concrete, monomorphized integrator, boxed behind the trait, and builds
//! only that one.

use crate::error::SimError;
use crate::scene::{GeodesicSoN, Method, MethodSpec, SolverOptions, System, TauKind};
use faer::{Col, Mat};
use integrators::systems::{
    GeneralizedRigidBody, HeavyTop as HeavyTopSystem, PlanarBody as PlanarBodySystem, RigidBody,
    RigidBodySe3 as RigidBodySe3System,
};
use integrators::{
    EulerPoincare, Integrator, IntegratorError, LiePoisson, QuaternionRk4, Rkmk4, SolverConfig,
};
use lie_groups::{
    Cayley, CayleyGroup, DenseMatrix, ExpMap, LieError, LieGroup, Se2, Se3, So2, So3, SoN, Vector,
};
use nalgebra::{Matrix3, Vector3, Vector6};

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
}

/// Builds the simulation a scene names: its system with its initial state, advanced by `method`.
///
/// Only the named combination is constructed. A (system, method, τ) that the integrators crate does
/// not provide is [`SimError::NotYetAvailable`], never a panic.
///
/// Systems: `integrators::systems::{RigidBody, HeavyTop, RigidBodySe3, PlanarBody,
/// GeneralizedRigidBody<N>}` (the last for N in [`SO_N_SIZES`]). Methods: `LiePoisson` and
/// `EulerPoincare` with τ = exp or cayley and any θ, `Rkmk4` (τ = exp) on every group,
/// `QuaternionRk4` on the SO(3) systems.
pub fn build(
    system: &System,
    method: &MethodSpec,
    reconstruct: bool,
    solver: &SolverOptions,
) -> Result<Box<dyn Simulation>, SimError> {
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
    match method.method {
        Method::EulerArnold => {
            return Err(unavailable(
                "the integrators crate offers Euler–Arnold as a system (EulerArnold<G>) \
                 integrated by lie-poisson or euler-poincare, not as a method of its own",
            ))
        }
        Method::Rk4 if !matches!(system, System::FreeRigidBody(_) | System::HeavyTop(_)) => {
            return Err(unavailable(
                "rk4 integrates quaternions, so only the SO(3) systems (free-rigid-body, \
                 heavy-top); use rkmk4 on other groups",
            ))
        }
        _ => {}
    }
    let mut config = SolverConfig::default();
    if let Some(t) = solver.tolerance {
        config.tolerance = t;
    }
    if let Some(m) = solver.max_iterations {
        config.max_iterations = m;
    }
    let b = Builder {
        method: *method,
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
            b.build_so3(body, p.momentum, so3(&p.attitude)?)
                .map_err(built)
        }
        System::HeavyTop(p) => {
            let top = HeavyTopSystem::new(p.inertia, p.mass, p.gravity, p.center_of_mass)
                .map_err(built)?;
            b.build_so3(top, p.momentum, so3(&p.attitude)?)
                .map_err(built)
        }
        System::RigidBodySe3(p) => {
            let g0 = so3(&p.attitude)?.map(|r| Se3::from_parts(r, p.position));
            if p.gravitational_parameter > 0.0 {
                let sat =
                    RigidBodySe3System::satellite(p.mass, p.inertia, p.gravitational_parameter)
                        .map_err(built)?;
                b.build(sat, p.momentum, g0).map_err(built)
            } else {
                let free = WithCasimir::<Se3, _> {
                    inner: RigidBodySe3System::free(p.mass, p.inertia).map_err(built)?,
                    casimir: |mu: &Vector6<f64>| mu.fixed_rows::<3>(3).norm_squared(),
                };
                b.build(free, p.momentum, g0).map_err(built)
            }
        }
        System::PlanarBodySe2(p) => {
            let body = PlanarBodySystem::free(p.mass, p.inertia)
                .and_then(|s| s.with_spring(p.stiffness, p.attachment))
                .and_then(|s| s.with_gravity(p.gravity))
                .map_err(built)?;
            let g0 = reconstruct.then(|| Se2::new(So2::from_angle(p.angle), p.position));
            if system.has_potential() {
                b.build(body, p.momentum, g0).map_err(built)
            } else {
                let free = WithCasimir::<Se2, _> {
                    inner: body,
                    casimir: |mu: &Vector3<f64>| mu[1] * mu[1] + mu[2] * mu[2],
                };
                b.build(free, p.momentum, g0).map_err(built)
            }
        }
        System::GeodesicSoN(p) => so_n(&b, p, reconstruct).map_err(|e| match e {
            SoNError::Size => unavailable(&format!(
                "SO({}) is not compiled into lie-sim (sizes: {SO_N_SIZES:?})",
                p.n
            )),
            SoNError::Integrator(e) => built(e),
            SoNError::Lie(e) => lie(e),
        }),
    }
}

/// The n of SO(n) compiled into the binary (one monomorphized integrator per n, method and τ).
pub const SO_N_SIZES: [usize; 8] = [3, 4, 5, 6, 8, 10, 20, 50];

/// Builds integrators of one method spec for any group with a Cayley map.
struct Builder {
    method: MethodSpec,
    config: SolverConfig,
}

impl Builder {
    /// Lie–Poisson, Euler–Poincaré (τ = exp or cayley) or RKMK4 on any group. RK4 is refused here
    /// ([`build`] routes it to [`Builder::build_so3`] and refuses it on other groups before).
    fn build<G, S>(
        &self,
        system: S,
        mu0: G::Algebra,
        g0: Option<G>,
    ) -> Result<Box<dyn Simulation>, IntegratorError>
    where
        G: CayleyGroup,
        S: integrators::System<G> + 'static,
    {
        let theta = self.method.theta.unwrap_or(0.0);
        let c = self.config;
        Ok(match (self.method.method, self.method.tau) {
            (Method::Rkmk4, _) => Box::new(Adapter(Rkmk4::<G, S>::new(system, mu0, g0)?)),
            (Method::EulerPoincare, Some(TauKind::Exp)) => Box::new(Adapter(
                EulerPoincare::<G, ExpMap, S>::from_momentum(system, theta, mu0, g0)?
                    .with_solver(c),
            )),
            (Method::EulerPoincare, _) => Box::new(Adapter(
                EulerPoincare::<G, Cayley, S>::from_momentum(system, theta, mu0, g0)?
                    .with_solver(c),
            )),
            (Method::LiePoisson, Some(TauKind::Exp)) => Box::new(Adapter(
                LiePoisson::<G, ExpMap, S>::new(system, theta, mu0, g0)?.with_solver(c),
            )),
            (Method::LiePoisson, _) => Box::new(Adapter(
                LiePoisson::<G, Cayley, S>::new(system, theta, mu0, g0)?.with_solver(c),
            )),
            (Method::Rk4 | Method::EulerArnold, _) => {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!("{} is not built on {}", self.method.method, G::name()),
                })
            }
        })
    }

    /// As [`Builder::build`], plus RK4 on (quaternion, Π) for systems on SO(3).
    fn build_so3<S>(
        &self,
        system: S,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Result<Box<dyn Simulation>, IntegratorError>
    where
        S: integrators::System<So3> + 'static,
    {
        match self.method.method {
            Method::Rk4 => Ok(Box::new(Adapter(QuaternionRk4::new(system, mu0, g0)?))),
            _ => self.build(system, mu0, g0),
        }
    }
}

enum SoNError {
    Size,
    Integrator(IntegratorError),
    Lie(LieError),
}

fn so_n(b: &Builder, p: &GeodesicSoN, reconstruct: bool) -> Result<Box<dyn Simulation>, SoNError> {
    fn go<const N: usize>(
        b: &Builder,
        p: &GeodesicSoN,
        reconstruct: bool,
    ) -> Result<Box<dyn Simulation>, SoNError> {
        let body = GeneralizedRigidBody::<N>::new(&p.inertia).map_err(SoNError::Integrator)?;
        let mu0 = Col::from_fn(p.momentum.len(), |i| p.momentum[i]);
        let g0 = if reconstruct {
            let m = Mat::from_fn(N, N, |r, c| p.attitude[r * N + c]);
            Some(SoN::<N>::from_matrix(&m).map_err(SoNError::Lie)?)
        } else {
            None
        };
        b.build::<SoN<N>, _>(body, mu0, g0)
            .map_err(SoNError::Integrator)
    }
    match p.n {
        3 => go::<3>(b, p, reconstruct),
        4 => go::<4>(b, p, reconstruct),
        5 => go::<5>(b, p, reconstruct),
        6 => go::<6>(b, p, reconstruct),
        8 => go::<8>(b, p, reconstruct),
        10 => go::<10>(b, p, reconstruct),
        20 => go::<20>(b, p, reconstruct),
        50 => go::<50>(b, p, reconstruct),
        _ => Err(SoNError::Size),
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
    fn casimir(&self, mu: &G::Algebra) -> Option<f64> {
        Some((self.casimir)(mu))
    }
}

/// Any integrator of the integrators crate, seen as a [`Simulation`].
struct Adapter<I>(I);

impl<I: Integrator> Simulation for Adapter<I> {
    fn step(&mut self, h: f64) -> Result<(), String> {
        self.0.step(h).map_err(|e| e.to_string())
    }
    fn time(&self) -> f64 {
        self.0.time()
    }
    fn momentum(&self) -> Vec<f64> {
        self.0.momentum().to_vec()
    }
    fn group_side(&self) -> Option<usize> {
        self.0.configuration().map(|g| g.matrix().to_mat().nrows())
    }
    fn group_matrix(&self) -> Option<Vec<f64>> {
        self.0.configuration().map(|g| {
            let m = g.matrix().to_mat();
            (0..m.nrows())
                .flat_map(|i| (0..m.ncols()).map(move |j| (i, j)))
                .map(|(i, j)| m[(i, j)])
                .collect()
        })
    }
    fn energy(&self) -> f64 {
        self.0.energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.0.casimir()
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
    }
}
