//! What every one-step method on a group carries from step to step besides its momentum: the
//! time on a compensated [`Clock`], the configuration g ∈ G when it is reconstructed, and how
//! long ago g was last projected back onto G — and the tail each step ends with.
//!
//! A step forms g_{k+1} as a product of g_k with group elements. Each product rounds, so g leaves
//! G by a random walk of roundings, ‖gᵀg − I‖ ≈ ε√n after n rounded products; projecting g back
//! ([`LieGroup::normalize`]) at every step would round it once more per step, with a bias the
//! spatial momentum map Ad*_{g⁻¹}μ accumulates (9e-13 after 10⁷ Lie–Poisson steps of
//! h = 1e-5, against 1.2e-13 when renormalized rarely: `tests/methods/casimir_drift.rs`). So g is
//! renormalized once about [`RENORMALIZE_AFTER`] rounded products have accumulated: every that
//! many steps for a method with one product per step (Lie–Poisson, Euler–Poincaré, RKMK),
//! fewer for one with several (a splitting's flows).
//!
//! The momentum stays in the method (μ, or ξ for Euler–Poincaré, some with a compensation
//! word); [`state_accessors!`] writes the [`crate::Integrator`] accessors from the momentum's
//! field and the state.

use crate::clock::Clock;
use crate::IntegratorError;
use lie_groups::LieGroup;

/// The number of rounded group products after which g is projected back onto G (see the module
/// page): the defect is then ε√[`RENORMALIZE_AFTER`] ≈ 32ε ≲ 1e-14 at most.
pub const RENORMALIZE_AFTER: u32 = 1024;

/// The steps between renormalizations of a method whose step forms g_{k+1} in `products` rounded
/// products: [`RENORMALIZE_AFTER`] / `products`, at least 1.
pub const fn renormalize_every(products: u32) -> u32 {
    let p = if products == 0 { 1 } else { products };
    let every = RENORMALIZE_AFTER / p;
    if every == 0 {
        1
    } else {
        every
    }
}

/// The time, the configuration and the renormalization count of a one-step method (see the
/// module page).
#[derive(Debug, Clone)]
pub(crate) struct StepState<G: LieGroup> {
    /// tₖ.
    pub(crate) t: Clock,
    /// gₖ, where reconstructed.
    pub(crate) g: Option<G>,
    /// Steps since g was last renormalized.
    unnormalized: u32,
    /// Steps between renormalizations: [`RENORMALIZE_AFTER`] over the rounded products a step
    /// makes.
    every: u32,
}

impl<G: LieGroup> StepState<G> {
    /// At t = 0 with g₀, for a method whose step forms g_{k+1} in `products` rounded products.
    pub(crate) fn new(g: Option<G>, products: u32) -> Self {
        Self {
            t: Clock::at(0.0),
            g,
            unnormalized: 0,
            every: renormalize_every(products),
        }
    }

    /// Back to (t, g), renormalization count cleared.
    pub(crate) fn reset(&mut self, t: f64, g: Option<G>) {
        self.t.set(t);
        self.g = g;
        self.unnormalized = 0;
    }

    /// tₖ.
    #[inline(always)]
    pub(crate) fn now(&self) -> f64 {
        self.t.now()
    }

    /// gₖ, where reconstructed.
    #[inline(always)]
    pub(crate) fn configuration(&self) -> Option<&G> {
        self.g.as_ref()
    }

    /// Whether the step being taken is the one that renormalizes g_{k+1}.
    #[inline(always)]
    pub(crate) fn renormalizes(&self) -> bool {
        self.unnormalized + 1 >= self.every
    }

    /// g_{k+1} = `next(g_k)`, projected onto G when [`Self::renormalizes`], refused when not
    /// finite; `None` when g is not reconstructed. The state is not touched.
    #[inline(always)]
    pub(crate) fn next_configuration(
        &self,
        next: impl FnOnce(&G) -> G,
    ) -> Result<Option<G>, IntegratorError> {
        let mut g1 = self.g.as_ref().map(next);
        self.finish_configuration(&mut g1)?;
        Ok(g1)
    }

    /// A g_{k+1} the step formed itself, projected onto G in place when
    /// [`Self::renormalizes`], refused when not finite (in place: a group element is moved once,
    /// into the state, on a path as short as a free body's step).
    #[inline(always)]
    pub(crate) fn finish_configuration(&self, g1: &mut Option<G>) -> Result<(), IntegratorError> {
        if let Some(g1) = g1 {
            if self.renormalizes() {
                *g1 = g1.normalize();
            }
            if !g1.is_finite() {
                return Err(IntegratorError::NonFinite {
                    what: "configuration g_{k+1}",
                });
            }
        }
        Ok(())
    }

    /// The tail of an accepted step of size h: g_{k+1} stored, t advanced by h (compensated),
    /// the renormalization counted.
    #[inline(always)]
    pub(crate) fn commit(&mut self, h: f64, g: Option<G>) {
        self.count();
        self.g = g;
        self.t.advance(h);
    }

    /// The tail of an accepted step that ends at exactly t1 (a step to an end time chosen by an
    /// adaptive driver): g_{k+1} stored, t = t1, the renormalization counted.
    #[inline(always)]
    pub(crate) fn commit_to(&mut self, t1: f64, g: Option<G>) {
        self.count();
        self.g = g;
        self.t.set(t1);
    }

    #[inline(always)]
    fn count(&mut self) {
        self.unnormalized = if self.renormalizes() {
            0
        } else {
            self.unnormalized + 1
        };
    }
}

/// The [`crate::Integrator`] accessors of a method that carries its momentum in the field named
/// by the argument (μ, or Π on SO(3)), its system in `self.system` and its time and
/// configuration in `self.state` (a [`StepState`], or any state with `now()` and
/// `configuration()`): t, μ, ξ = ∂h/∂μ, μ̇ in the method's trivialization, g, the energy and
/// the Casimir, each read from the state in place.
macro_rules! state_accessors {
    ($mu:ident) => {
        fn time(&self) -> f64 {
            self.state.now()
        }
        fn momentum(&self) -> <Self::Group as lie_groups::LieGroup>::Algebra {
            self.$mu.clone()
        }
        fn velocity(&self) -> <Self::Group as lie_groups::LieGroup>::Algebra {
            self.system.velocity(&self.$mu)
        }
        fn momentum_rate(&self) -> <Self::Group as lie_groups::LieGroup>::Algebra {
            crate::dense_output::momentum_rate_on(
                crate::Integrator::side(self),
                &self.system,
                self.state.now(),
                &self.$mu,
                self.state.configuration(),
            )
        }
        fn configuration(&self) -> Option<&Self::Group> {
            self.state.configuration()
        }
        fn energy(&self) -> f64 {
            self.system.energy(&self.$mu, self.state.configuration())
        }
        fn casimir(&self) -> Option<f64> {
            self.system.casimir(&self.$mu)
        }
    };
}
pub(crate) use state_accessors;

#[cfg(test)]
mod tests {
    use super::*;
    use lie_groups::So3;
    use nalgebra::Vector3;

    #[test]
    fn renormalizes_once_per_period_of_products() {
        for (products, period) in [(1, RENORMALIZE_AFTER), (4, RENORMALIZE_AFTER / 4)] {
            let mut s = StepState::new(Some(So3::identity()), products);
            let mut due = Vec::new();
            for k in 0..3 * period {
                if s.renormalizes() {
                    due.push(k);
                }
                s.commit(0.1, s.g);
            }
            let expected: Vec<u32> = (1..=3).map(|i| i * period - 1).collect();
            assert_eq!(due, expected, "{products} products a step");
            assert_eq!(renormalize_every(products), period);
        }
    }

    #[test]
    fn a_non_finite_configuration_is_refused_and_nothing_moves() {
        let s = StepState::new(Some(So3::identity()), 1);
        let bad = So3::exp(&Vector3::new(f64::NAN, 0.0, 0.0));
        assert!(s.finish_configuration(&mut Some(bad)).is_err());
        assert!(s.finish_configuration(&mut None).is_ok());
        assert!(s.next_configuration(|_| bad).is_err());
        assert_eq!(s.now(), 0.0);
        assert!(s.g.as_ref().unwrap().is_finite());
        assert!(StepState::<So3>::new(None, 1)
            .next_configuration(|_| bad)
            .unwrap()
            .is_none());
    }
}
