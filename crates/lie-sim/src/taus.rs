//! The τ maps a scene may name (`tau = "…"`): one row each in `taus!`, and one dispatch
//! ([`with_tau`]) from the name to the type, so that a method is written once, generic over
//! `T: Tau<G>`, and never once per τ.

use lie_groups::{Cayley, CayleyGroup, ExpMap, Tau};
use serde::Deserialize;
use std::fmt;

/// A computation generic over the τ map, run by [`with_tau`] for the τ a scene names.
pub trait TauVisitor<G: CayleyGroup> {
    /// What it produces.
    type Out;
    /// Runs with τ = `T`.
    fn visit<T: Tau<G>>(self) -> Self::Out;
}

/// The rows: the variant, the name in scene files, the type implementing `lie_groups::Tau`, and
/// what it is. Adding a τ is one row.
macro_rules! taus {
    ($($(#[doc = $doc:literal])* $variant:ident => $name:literal, $ty:ty;)*) => {
        /// The τ map of the retraction g τ(ξ).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
        #[serde(rename_all = "kebab-case")]
        pub enum TauKind {
            $($(#[doc = $doc])* #[serde(rename = $name)] $variant,)*
        }

        impl TauKind {
            /// Every τ, in the order of the rows.
            pub const ALL: &'static [TauKind] = &[$(TauKind::$variant),*];

            /// The name used in scene files.
            pub fn name(self) -> &'static str {
                match self {
                    $(TauKind::$variant => $name,)*
                }
            }
        }

        /// Runs `visitor` with the τ map `kind` names: the one place where a τ becomes a type.
        pub fn with_tau<G: CayleyGroup, V: TauVisitor<G>>(kind: TauKind, visitor: V) -> V::Out {
            match kind {
                $(TauKind::$variant => visitor.visit::<$ty>(),)*
            }
        }
    };
}

taus! {
    /// τ = exp (`lie_groups::ExpMap`).
    Exp => "exp", ExpMap;
    /// τ = cay (`lie_groups::Cayley`).
    Cayley => "cayley", Cayley;
}

impl fmt::Display for TauKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
