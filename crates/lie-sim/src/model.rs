//! Where systems and methods meet: a scene's system hands the methods a [`Model`] — the
//! `integrators::System` S on its group G, and the optional capabilities a method may need
//! (pieces with exact flows, an exact kinetic flow, SO(3) for quaternion RK4, the free rigid body
//! itself for its exact flow and modified Hamiltonian).
//!
//! A method is generic over G and S, so a capability cannot be a trait object: each is a provided
//! method of [`Model`] taking a visitor with a generic `visit`, which the model calls with its
//! concrete types when it has the capability and refuses ([`Missing`]) when it does not. What a
//! method applies to is then what its capabilities allow — derived, never listed per method — and
//! a model that lacks a capability for a reason of its own (a vehicle whose mass matrix couples
//! rotation and translation has no splitting) says why.

use crate::error::SimError;
use crate::sim::SimGroup;
use integrators::splitting::{KineticFlow, SplitSystem};
use integrators::System;
use lie_groups::{CayleyGroup, LieGroup, So3};
use mechanics::RigidBody;
use nalgebra::Vector3;

/// The algebra of G (momenta μ, velocities ξ).
pub type Alg<G> = <G as LieGroup>::Algebra;

/// Why a model lacks a capability: `None` when the capability's own message says it all, or the
/// model's reason (it says why *this* system has none).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Missing(pub Option<String>);

impl Missing {
    /// The model's reason.
    pub fn because(why: impl Into<String>) -> Self {
        Self(Some(why.into()))
    }
}

/// A capability, or why it is missing.
pub type Has<T> = Result<T, Missing>;

/// Uses a system whose Hamiltonian splits into pieces with exact flows
/// (`integrators::splitting::SplitSystem`).
pub trait SplitVisitor<G: LieGroup> {
    /// What it produces.
    type Out;
    /// Runs on the split system with the state (μ₀, g₀).
    fn visit<S: SplitSystem<G> + Clone + Sync + 'static>(
        self,
        system: &S,
        mu0: Alg<G>,
        g0: Option<G>,
    ) -> Self::Out;
}

/// Uses the exact flow K of the system's kinetic energy (`integrators::splitting::KineticFlow`).
pub trait KineticVisitor<G: LieGroup> {
    /// What it produces.
    type Out;
    /// Runs on the system and its kinetic flow with the state (μ₀, g₀).
    fn visit<S, K>(self, system: &S, flow: K, mu0: Alg<G>, g0: Option<G>) -> Self::Out
    where
        S: System<G> + Clone + Sync + 'static,
        K: KineticFlow<G> + Clone + Sync + 'static;
}

/// Uses a system on SO(3) (quaternion RK4). Its output is indexed by the group so that a model on
/// SO(3) returns it as its own (`Out<So3>` is `Out<Self::G>` there).
pub trait So3Visitor {
    /// What it produces on the group G.
    type Out<G: LieGroup>;
    /// Runs on the SO(3) system with the state (Π₀, R₀).
    fn visit<S: System<So3> + Clone + Sync + 'static>(
        self,
        system: &S,
        mu0: Vector3<f64>,
        g0: Option<So3>,
    ) -> Self::Out<So3>;
}

/// Uses the free rigid body itself, unforced (its exact flow, its modified Hamiltonian).
pub trait FreeBodyVisitor {
    /// What it produces on the group G.
    type Out<G: LieGroup>;
    /// Runs on the body with the state (Π₀, R₀).
    fn visit(self, body: &RigidBody, mu0: Vector3<f64>, g0: Option<So3>) -> Self::Out<So3>;
}

/// A scene's system as the methods see it (see the module page). The capabilities are provided
/// as missing; a model overrides those it has.
pub trait Model: Sync + 'static {
    /// The configuration group G.
    type G: CayleyGroup + SimGroup + Sync + 'static;
    /// The system on G.
    type S: System<Self::G> + Clone + Sync + 'static;
    /// The scene kind (`free-rigid-body`, …), for messages.
    fn kind(&self) -> &'static str;
    /// The system.
    fn system(&self) -> &Self::S;
    /// Pieces with exact flows.
    fn split<V: SplitVisitor<Self::G>>(
        &self,
        _visitor: V,
        _mu0: Alg<Self::G>,
        _g0: Option<Self::G>,
    ) -> Has<V::Out> {
        Err(Missing::default())
    }
    /// The exact flow of the kinetic energy.
    fn kinetic_flow<V: KineticVisitor<Self::G>>(
        &self,
        _visitor: V,
        _mu0: Alg<Self::G>,
        _g0: Option<Self::G>,
    ) -> Has<V::Out> {
        Err(Missing::default())
    }
    /// The system on SO(3).
    fn so3<V: So3Visitor>(
        &self,
        _visitor: V,
        _mu0: Alg<Self::G>,
        _g0: Option<Self::G>,
    ) -> Has<V::Out<Self::G>> {
        Err(Missing::default())
    }
    /// The body a batch of N copies carries (`batch::BodyModel`: a rigid body in principal axes,
    /// free or in a uniform field, unforced) and the attitude g₀ as a rotation (the identity
    /// where the run does not reconstruct g: the batch carries R all the same, and the free
    /// body's Π does not read it), for the sweep's batched path.
    fn batch_body(&self, _g0: Option<&Self::G>) -> Has<(batch::BodyModel, So3)> {
        Err(Missing::default())
    }
    /// The free rigid body, unforced.
    fn free_body<V: FreeBodyVisitor>(
        &self,
        _visitor: V,
        _mu0: Alg<Self::G>,
        _g0: Option<Self::G>,
    ) -> Has<V::Out<Self::G>> {
        Err(Missing::default())
    }
}

/// A computation generic over a scene's model, run by `crate::systems::System::dispatch` once
/// it has built the model and the initial state (μ₀, and g₀ when the run reconstructs g).
pub trait Job {
    /// What it produces.
    type Out;
    /// Runs on the model.
    fn run<M: Model>(
        self,
        model: &M,
        mu0: Alg<M::G>,
        g0: Option<M::G>,
    ) -> Result<Self::Out, SimError>;
}
