//! What every system module implements ([`SceneSystem`]) and the little its scene types share.

use crate::error::SimError;
use crate::fields::FieldError;
use crate::forces::{ForceSlots, Forces};
use crate::model::Job;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Deserializer};
use std::fmt;

/// A system a scene may name: its `[system]` and `[initial]` keys as its own serde types, their
/// checks, the `[forces]` it takes, and the model it builds for the methods.
pub trait SceneSystem: Sized + Clone + fmt::Debug + PartialEq {
    /// The name in scene files (`kind = "…"`).
    const KIND: &'static str;
    /// Other names it is read under.
    const ALIASES: &'static [&'static str] = &[];
    /// What it is, in one line with its source.
    const SUMMARY: &'static str;
    /// Its example scene (in `examples/scenes/`): the representative the methods' listing probes.
    const EXAMPLE: &'static str;
    /// The `[forces]` keys it takes, in the order of the error messages (none: it takes no
    /// `[forces]`).
    const FORCE_KEYS: &'static [&'static str] = &[];
    /// The `[system]` table (its tag `kind` included: [`Tag`]).
    type Params: DeserializeOwned;
    /// The `[initial]` table.
    type Initial: DeserializeOwned;
    /// Checks the values of both tables.
    fn check(params: &Self::Params, initial: &Self::Initial) -> Result<Self, FieldError>;
    /// The sizes of its `[forces]`: the algebra's dimension n (damping, drag) and the number of
    /// wheels (wheel torques).
    fn force_sizes(&self) -> (usize, usize) {
        (0, 0)
    }
    /// Its checked `[forces]`, if any.
    fn forces(&self) -> Option<&Forces> {
        None
    }
    /// Attaches checked `[forces]` (only called when [`Self::FORCE_KEYS`] is not empty).
    fn set_forces(&mut self, _forces: Forces) {}
    /// Builds its model and initial state (g₀ only when `reconstruct`) and runs `job` on them.
    fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError>;

    /// What its `[forces]` may hold, or `None` when it takes none.
    fn force_slots(&self) -> Option<ForceSlots> {
        if Self::FORCE_KEYS.is_empty() {
            return None;
        }
        let (dim, wheels) = self.force_sizes();
        Some(ForceSlots {
            keys: Self::FORCE_KEYS,
            dim,
            wheels,
        })
    }
}

/// The `kind` key of a `[system]` table, already read to choose the table's type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tag;

impl<'de> Deserialize<'de> for Tag {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        String::deserialize(d).map(|_| Tag)
    }
}

/// A failure to build a model: the kind and the library's message.
pub fn build_error(kind: &str, e: impl fmt::Display) -> SimError {
    SimError::Build {
        what: kind.to_string(),
        message: e.to_string(),
    }
}

/// A model whose only capability is a splitting (or none, with the model's reason): the systems
/// without a rigid body's exact flow (the planar body, the SO(n) geodesic, the gyrostat, the
/// underwater vehicle, the coupled bodies).
pub struct Splits<G, S> {
    kind: &'static str,
    system: S,
    /// `Err(why)` when the system does not split.
    split: Result<(), String>,
    _group: core::marker::PhantomData<fn() -> G>,
}

impl<G, S> Splits<G, S> {
    /// `system`, which splits when `split` is `Ok` (and says why not otherwise).
    pub fn new(kind: &'static str, system: S, split: Result<(), String>) -> Self {
        Self {
            kind,
            system,
            split,
            _group: core::marker::PhantomData,
        }
    }
}

impl<G, S> crate::model::Model for Splits<G, S>
where
    G: lie_groups::CayleyGroup + crate::sim::SimGroup + Sync + 'static,
    S: integrators::splitting::SplitSystem<G> + Clone + Sync + 'static,
{
    type G = G;
    type S = S;
    fn kind(&self) -> &'static str {
        self.kind
    }
    fn system(&self) -> &S {
        &self.system
    }
    fn split<V: crate::model::SplitVisitor<G>>(
        &self,
        v: V,
        mu0: crate::model::Alg<G>,
        g0: Option<G>,
    ) -> crate::model::Has<V::Out> {
        match &self.split {
            Ok(()) => Ok(v.visit(&self.system, mu0, g0)),
            Err(why) => Err(crate::model::Missing::because(why.clone())),
        }
    }
}
