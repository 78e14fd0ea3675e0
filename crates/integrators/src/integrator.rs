//! The uniform interface every integrator of the crate offers, so that one generic function can
//! drive any (system, method, τ, θ) combination.

use crate::IntegratorError;
use lie_groups::LieGroup;

/// What a method is and what it keeps, so that tools (`lie-sim trade`, `choose`, the docs) read it
/// from the method instead of repeating it.
///
/// Each flag is a property of the method *as configured* (θ, the system's potential, the
/// composition scheme): LP θ = 0 is order 2 on a free body and order 1 with a potential, and says so.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MethodInfo {
    /// The classical order p of the global error O(hᵖ) on smooth problems (the effective order
    /// for processed methods, the exact flow's being [`MethodInfo::EXACT`]).
    pub order: u32,
    /// Symmetric (time-reversible): Φ_{−h} = Φ_h⁻¹.
    pub symmetric: bool,
    /// Explicit: no equation is solved in a step.
    pub explicit: bool,
    /// A Poisson (symplectic) map of T*G, restricted to each coadjoint orbit.
    pub poisson: bool,
    /// Casimirs of the Lie–Poisson bracket conserved to round-off (μ stays on its coadjoint orbit).
    pub casimirs: bool,
    /// The spatial momentum map `Ad*_{g⁻¹} μ` conserved to round-off when the system is
    /// invariant (no potential).
    pub momentum_map: bool,
    /// The energy conserved to round-off (not merely bounded).
    pub energy: bool,
    /// g stays on G to round-off.
    pub on_group: bool,
}

impl MethodInfo {
    /// The order reported by an exact flow (no truncation error at all).
    pub const EXACT: u32 = u32::MAX;

    /// A general explicit method of order p that keeps nothing but g on G.
    pub const fn plain(order: u32) -> Self {
        Self {
            order,
            symmetric: false,
            explicit: true,
            poisson: false,
            casimirs: false,
            momentum_map: false,
            energy: false,
            on_group: true,
        }
    }

    /// The names of the kept structures, e.g. `["poisson", "casimirs", "momentum-map"]`.
    pub fn preserved(&self) -> Vec<&'static str> {
        [
            (self.poisson, "poisson"),
            (self.casimirs, "casimirs"),
            (self.momentum_map, "momentum-map"),
            (self.energy, "energy"),
            (self.on_group, "on-group"),
        ]
        .into_iter()
        .filter_map(|(keep, name)| keep.then_some(name))
        .collect()
    }
}

/// `order 4, symmetric, explicit; keeps poisson, casimirs, on-group` (`order exact` for an exact
/// flow; `keeps nothing` when nothing is kept).
impl core::fmt::Display for MethodInfo {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.order == Self::EXACT {
            f.write_str("order exact")?;
        } else {
            write!(f, "order {}", self.order)?;
        }
        if self.symmetric {
            f.write_str(", symmetric")?;
        }
        f.write_str(if self.explicit {
            ", explicit"
        } else {
            ", implicit"
        })?;
        let kept = self.preserved();
        if kept.is_empty() {
            f.write_str("; keeps nothing")
        } else {
            write!(f, "; keeps {}", kept.join(", "))
        }
    }
}

/// A one-step method advancing the state (t, μ, optional g) of a mechanical system on G.
///
/// `step(h)` either advances the state by h or returns an error and leaves it exactly as it was.
/// `h < 0` integrates backwards in time.
pub trait Integrator {
    /// The configuration group G.
    type Group: LieGroup;

    /// Advances the state by the step h (which may be negative).
    fn step(&mut self, h: f64) -> Result<(), IntegratorError>;
    /// The current time t.
    fn time(&self) -> f64;
    /// The body momentum μ ∈ 𝔤* at the current time.
    fn momentum(&self) -> <Self::Group as LieGroup>::Algebra;
    /// The body velocity ξ = ∂h/∂μ ∈ 𝔤 at the current time.
    fn velocity(&self) -> <Self::Group as LieGroup>::Algebra;
    /// `μ̇ = ad*_ξ μ + F(g) + F_ext(t, g, ξ)` of the system at the current state: the slope the
    /// dense output interpolates with ([`crate::dense_output`]).
    fn momentum_rate(&self) -> <Self::Group as LieGroup>::Algebra;
    /// The configuration g, where it is being reconstructed.
    fn configuration(&self) -> Option<&Self::Group>;
    /// The total energy h(μ) + V(g).
    fn energy(&self) -> f64;
    /// The system's Casimir C(μ), where it has one.
    fn casimir(&self) -> Option<f64>;
    /// A short description of the method, e.g. `"lie-poisson(tau=cayley, theta=0.5)"`.
    fn method_name(&self) -> String;
    /// What the method is (order, symmetric, explicit) and what it keeps.
    fn info(&self) -> MethodInfo;
    /// Which translation trivializes its velocities and momenta: left (body frame, `ġ = g ξ`;
    /// the default) or right (spatial frame, `ġ = ξ g`, for right-invariant systems).
    fn side(&self) -> discretization::Side {
        discretization::Side::Left
    }
    /// Why the state cannot be read, for a method whose reads compute something that can fail —
    /// a processed method's processor P ([`crate::processing::Processed`]), whose reads are then
    /// NaN. `None` (the default) for every method that holds its state as it is read.
    fn read_error(&self) -> Option<IntegratorError> {
        None
    }
}

/// Takes `steps` steps of size h, calling `observe` after each one; stops at the first error.
pub fn integrate<I: Integrator>(
    integrator: &mut I,
    h: f64,
    steps: usize,
    mut observe: impl FnMut(&I),
) -> Result<(), IntegratorError> {
    for _ in 0..steps {
        integrator.step(h)?;
        observe(integrator);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::MethodInfo;

    #[test]
    fn method_info_reads_as_a_sentence() {
        assert_eq!(
            MethodInfo::plain(4).to_string(),
            "order 4, explicit; keeps on-group"
        );
        let exact = MethodInfo {
            order: MethodInfo::EXACT,
            symmetric: true,
            explicit: true,
            poisson: true,
            casimirs: true,
            momentum_map: true,
            energy: true,
            on_group: true,
        };
        assert_eq!(
            exact.to_string(),
            "order exact, symmetric, explicit; keeps poisson, casimirs, momentum-map, energy, on-group"
        );
        let none = MethodInfo {
            explicit: false,
            on_group: false,
            ..MethodInfo::plain(1)
        };
        assert_eq!(none.to_string(), "order 1, implicit; keeps nothing");
    }
}
