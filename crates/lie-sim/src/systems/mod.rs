//! The systems a scene may name (`[system] kind = "…"`): one module each, listed once in
//! `systems!`. A module holds the system's `[system]` and `[initial]` keys as its own serde
//! types (so that a key of another system is an unknown field, with serde's message and line),
//! their checks, the `[forces]` it takes, and the [`crate::model::Model`] it builds — the
//! `mechanics` model with the capabilities the methods may ask for. The model's facts (Casimir,
//! conserved parts of the momentum map, time scale) are the `mechanics` model's own
//! (`integrators::System`).
//!
//! Adding a system is a module implementing [`common::SceneSystem`] and one line in
//! `systems!`.

pub mod common;

use crate::error::SimError;
use crate::forces::{ForceSlots, Forces};
use crate::model::Job;
use common::SceneSystem;
use serde::Deserialize;
use std::fmt;

/// A computation generic over a system's module, run by [`with_kind`].
pub trait KindVisitor {
    /// What it produces.
    type Out;
    /// Runs with the module's type `T`.
    fn visit<T: SceneSystem + Into<System>>(self) -> Self::Out;
}

/// The registry: one line per system, `Variant => module::Type`, the type implementing
/// [`SceneSystem`]. Generates [`SystemKind`] (the scene's `kind`), the checked [`System`] and the
/// dispatches over them.
macro_rules! systems {
    ($($variant:ident => $module:ident :: $ty:ident,)*) => {
        $(pub mod $module;)*

        /// Which system a scene simulates.
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum SystemKind {
            $(
                #[doc = concat!("See [`", stringify!($module), "`].")]
                $variant,
            )*
        }

        impl SystemKind {
            /// Every system, in registry order.
            pub const ALL: &'static [SystemKind] = &[$(SystemKind::$variant),*];

            /// The name used in scene files.
            pub fn name(self) -> &'static str {
                match self {
                    $(SystemKind::$variant => <$module::$ty as SceneSystem>::KIND,)*
                }
            }
            /// Other names it is read under.
            pub fn aliases(self) -> &'static [&'static str] {
                match self {
                    $(SystemKind::$variant => <$module::$ty as SceneSystem>::ALIASES,)*
                }
            }
            /// What it is.
            pub fn summary(self) -> &'static str {
                match self {
                    $(SystemKind::$variant => <$module::$ty as SceneSystem>::SUMMARY,)*
                }
            }
            /// Its example scene's text.
            pub fn example(self) -> &'static str {
                match self {
                    $(SystemKind::$variant => <$module::$ty as SceneSystem>::EXAMPLE,)*
                }
            }
            /// The `[forces]` keys it takes.
            pub fn force_keys(self) -> &'static [&'static str] {
                match self {
                    $(SystemKind::$variant => <$module::$ty as SceneSystem>::FORCE_KEYS,)*
                }
            }
        }

        /// The scene names, in registry order.
        const NAMES: &[&str] = &[$(<$module::$ty as SceneSystem>::KIND),*];

        /// A checked system with its initial state.
        // One per scene, dispatched once to build the model: the size of its largest variant
        // costs nothing.
        #[allow(clippy::large_enum_variant)]
        #[derive(Debug, Clone, PartialEq)]
        pub enum System {
            $(
                #[doc = concat!("See [`", stringify!($module), "`].")]
                $variant($module::$ty),
            )*
        }

        $(
            impl From<$module::$ty> for System {
                fn from(s: $module::$ty) -> Self {
                    System::$variant(s)
                }
            }
        )*

        impl System {
            /// The kind of system.
            pub fn kind(&self) -> SystemKind {
                match self {
                    $(System::$variant(_) => SystemKind::$variant,)*
                }
            }
            /// What its `[forces]` may hold, or `None` when it takes none.
            pub fn force_slots(&self) -> Option<ForceSlots> {
                match self {
                    $(System::$variant(s) => s.force_slots(),)*
                }
            }
            /// Its external forces, if any.
            pub fn forces(&self) -> Option<&Forces> {
                match self {
                    $(System::$variant(s) => s.forces(),)*
                }
            }
            /// Attaches checked forces (a system that takes `[forces]`).
            pub fn set_forces(&mut self, forces: Forces) {
                match self {
                    $(System::$variant(s) => s.set_forces(forces),)*
                }
            }
            /// Builds the model and the initial state (g₀ only when `reconstruct`) and runs `job`
            /// on them.
            pub fn dispatch<J: Job>(&self, reconstruct: bool, job: J) -> Result<J::Out, SimError> {
                match self {
                    $(System::$variant(s) => s.dispatch(reconstruct, job),)*
                }
            }
        }

        /// Runs `visitor` with the module of `kind`: the one place where a kind becomes a type.
        pub fn with_kind<V: KindVisitor>(kind: SystemKind, visitor: V) -> V::Out {
            match kind {
                $(SystemKind::$variant => visitor.visit::<$module::$ty>(),)*
            }
        }
    };
}

systems! {
    FreeRigidBody => free_rigid_body::FreeRigidBody,
    HeavyTop => heavy_top::HeavyTop,
    RigidBodySe3 => rigid_body_se3::RigidBodySe3,
    PlanarBodySe2 => planar_body_se2::PlanarBodySe2,
    GeodesicSoN => geodesic_so_n::GeodesicSoN,
    Gyrostat => gyrostat::Gyrostat,
    UnderwaterVehicle => underwater_vehicle::UnderwaterVehicle,
    Quadrotor => quadrotor::Quadrotor,
    CoupledBodies => coupled_bodies::CoupledBodies,
}

impl SystemKind {
    /// The kind named `name` (or an alias of it).
    pub fn by_name(name: &str) -> Option<Self> {
        Self::ALL
            .iter()
            .copied()
            .find(|k| k.name() == name || k.aliases().contains(&name))
    }
    /// The kinds that take `[forces]`, as a phrase: `free-rigid-body, heavy-top and gyrostat`.
    pub fn forced_kinds() -> String {
        let names: Vec<&str> = Self::ALL
            .iter()
            .filter(|k| !k.force_keys().is_empty())
            .map(|k| k.name())
            .collect();
        match names.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
            Some((last, _)) => last.to_string(),
            None => String::new(),
        }
    }
}

impl fmt::Display for SystemKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl<'de> Deserialize<'de> for SystemKind {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        Self::by_name(&name).ok_or_else(|| serde::de::Error::unknown_variant(&name, NAMES))
    }
}
