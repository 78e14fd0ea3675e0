//! [`WarmStart`]: what the solve of one step leaves for the next step of the same size.
//!
//! Along a run at a fixed step h the solutions ξ_k of the step equations are samples of a smooth
//! curve (ξ_k = h v(t_k) + O(h²) with v smooth), so the quartic extrapolation
//! `ξ⁰ = 5ξ_{k−1} − 10ξ_{k−2} + 10ξ_{k−3} − 5ξ_{k−4} + ξ_{k−5}` is within O(h⁶) of ξ_k —
//! relative O(h⁵), against O(h²) for the integrators' one-step predictors (on the free rigid body
//! at h = 0.01: 1.4e-12 relative with exactly solved past steps, 2e-12 with the solver's, where
//! the cubic extrapolation is at 2e-10; at hω ≈ 1 still 2–3× closer than the cubic). A quintic
//! one would be within 2e-14 at h = 0.01, at the solver's tolerance, where no contraction can be
//! measured any more: one more residual buys nothing then. The coefficients sum to 31 in
//! magnitude, so the past solutions' own errors enter the guess at most 31-fold. And the simplified-Newton matrix J(ξ_{k−1})⁻¹
//! differs from J(ξ_k)⁻¹ by O(h²) (J − I = O(h), and its arguments move by O(h) per step), so it
//! still contracts the iteration by O(h²): from such a guess the default tolerance is met with no
//! Jacobian evaluated at all (`SolverKind::SimplifiedNewton`; the solver re-evaluates J if the
//! observed contraction exceeds 0.1).
//!
//! The contraction ρ the iteration measured is carried to the next step as a prior (as Hairer &
//! Wanner, *Solving ODEs II*, §IV.8, carry η = max(ρ_{k−1}, ε)^0.8 across steps): here
//! η = max(ρ, [`CHORD_REUSE_CONTRACTION`]), ρ measured on a matrix carried from an earlier step.
//! The error left after the first update Δ is then estimated by `η/(1 − η) ‖Δ‖`, so a step whose
//! guess is already within the tolerance of the solution up to that factor takes one residual
//! evaluation, and η is a floor for the later updates of the step (the ratio of two updates
//! measures the contraction along the current error only: at h = 0.1 on the free body it was seen
//! at 1.5e-4 where the next updates contracted by 3e-3). A step that stops after one iteration
//! measures no ρ, and η doubles ([`PRIOR_INFLATION`]) at every such step, which forces a second
//! iteration — a new measurement — within a few steps.
//!
//! Everything is used only when the step size repeats bitwise; a new h (compositions alternate step
//! sizes, a reversed run negates h), a reset or a new solver configuration starts afresh. The
//! warm start changes only where the iteration starts: the step is still solved to the solver's
//! tolerance, so results agree with a cold start to that tolerance (not bitwise).

use lie_groups::{LieGroup, Vector};

/// The largest contraction factor of a step's iteration for which its Newton matrix is kept for
/// the next step. Above it (large steps, where J moves by more than 10⁻³ per step) one fresh J
/// costs less than the extra iterations a stale one needs.
pub const CHORD_REUSE_CONTRACTION: f64 = 1e-3;

/// How much the contraction prior grows at every step that measures none (Hairer–Wanner's
/// `max(ρ, ε)^0.8` is ×6 at ρ = 1e-4; a product instead of a `powf` per step): the exponential
/// growth outruns the ageing of the kept matrix (whose contraction grows by O(h²) per step: from
/// 1.2e-5 by ~1e-5 a step at h = 0.01 on the free body, against a prior of at least 1e-3), and a
/// second iteration, which measures ρ again, follows within a few steps.
pub const PRIOR_INFLATION: f64 = 2.0;

/// Past solutions taken by the extrapolation.
const DEPTH: usize = 5;

/// Past solutions ξ, the last simplified-Newton matrix and its contraction, for steps of one
/// size h.
#[derive(Debug, Clone)]
pub struct WarmStart<G: LieGroup> {
    /// The step size the contents belong to.
    h: f64,
    /// ξ of the last steps of size h in a ring: the newest at `newest`, then older ones at
    /// `newest − 1, …` (mod [`DEPTH`]), the `count` newest of them valid. A ring, so recording one
    /// writes one slot (in place: `clone_from` keeps a heap vector's buffer) instead of shifting
    /// them all.
    past: [G::Algebra; DEPTH],
    newest: usize,
    count: usize,
    /// The inverse simplified-Newton matrix of the last step of size h.
    chord: Option<G::Operator>,
    /// The contraction prior of the next step's first iteration (see the module page); NaN when
    /// there is none.
    rate: f64,
}

impl<G: LieGroup> Default for WarmStart<G> {
    fn default() -> Self {
        Self {
            h: f64::NAN,
            past: core::array::from_fn(|_| G::Algebra::zeros(G::dim())),
            newest: 0,
            count: 0,
            chord: None,
            rate: f64::NAN,
        }
    }
}

impl<G: LieGroup> WarmStart<G> {
    /// Forgets everything (after a reset of the state or of the solver).
    pub fn clear(&mut self) {
        self.h = f64::NAN;
        self.count = 0;
        self.chord = None;
        self.rate = f64::NAN;
    }

    /// Whether the contents belong to steps of size h (bitwise).
    fn holds(&self, h: f64) -> bool {
        self.h.to_bits() == h.to_bits()
    }

    /// The solution recorded `age` (< [`DEPTH`]) steps ago (0: the last one).
    #[inline(always)]
    fn past(&self, age: usize) -> &G::Algebra {
        let i = if self.newest >= age {
            self.newest - age
        } else {
            self.newest + DEPTH - age
        };
        &self.past[i]
    }

    /// The quartic extrapolation `5ξ₁ − 10ξ₂ + 10ξ₃ − 5ξ₄ + ξ₅` of the last five solutions, when
    /// the last five steps had size h.
    #[inline(always)]
    pub fn predict(&self, h: f64) -> Option<G::Algebra> {
        if !self.holds(h) || self.count < DEPTH {
            return None;
        }
        let (x1, x2, x3, x4, x5) = (
            self.past(0),
            self.past(1),
            self.past(2),
            self.past(3),
            self.past(4),
        );
        Some(x1.sub(x4).scale(5.0).add(&x3.sub(x2).scale(10.0)).add(x5))
    }

    /// The simplified-Newton matrix of the last step, when it had size h (emptied otherwise), for
    /// [`crate::solver::solve`] to use and update in place.
    #[inline]
    pub fn chord(&mut self, h: f64) -> &mut Option<G::Operator> {
        if !self.holds(h) {
            self.chord = None;
        }
        &mut self.chord
    }

    /// The contraction prior of the kept matrix for a step of size h: the last measured bound (or
    /// its inflation, see [`Self::record`]), at least [`CHORD_REUSE_CONTRACTION`] — the most a
    /// kept matrix was seen to contract by, and the prior of a matrix not yet measured on a later
    /// step than its own; `None` without a kept matrix of that size.
    #[inline]
    pub fn prior_contraction(&self, h: f64) -> Option<f64> {
        (self.holds(h) && self.chord.is_some()).then(|| {
            if self.rate.is_finite() {
                self.rate.max(CHORD_REUSE_CONTRACTION)
            } else {
                CHORD_REUSE_CONTRACTION
            }
        })
    }

    /// Records the solution ξ of a successful step of size h, the contraction its iteration
    /// measured and its rounding-proof bound (`None` when it stopped after one iteration, on its
    /// prior; see [`crate::solver::Solution`]) and how many Jacobians it evaluated. The Newton matrix the solver left in [`Self::chord`] is kept only
    /// if it contracted by at most [`CHORD_REUSE_CONTRACTION`] (otherwise the next step evaluates
    /// J afresh at its guess). A contraction measured with a matrix carried from an earlier step
    /// becomes the next prior; one measured with a matrix evaluated in this step is Newton's
    /// (quadratic, at the step's own guess) and says nothing of the next step's older matrix, so
    /// the next step has no prior; without a measurement the prior inflates
    /// ([`Self::prior_contraction`]).
    pub fn record(
        &mut self,
        h: f64,
        xi: &G::Algebra,
        contraction: Option<(f64, f64)>,
        jacobians: usize,
    ) {
        if !self.holds(h) {
            let chord = self.chord.take();
            self.clear();
            self.h = h;
            self.chord = chord;
        }
        self.newest = if self.newest + 1 == DEPTH {
            0
        } else {
            self.newest + 1
        };
        self.past[self.newest].clone_from(xi);
        self.count = (self.count + 1).min(DEPTH);
        match contraction {
            Some((rho, bound)) => {
                self.rate = if jacobians == 0 { bound } else { f64::NAN };
                if rho > CHORD_REUSE_CONTRACTION {
                    self.chord = None;
                }
            }
            None if jacobians == 0 => {
                if let Some(prior) = self.prior_contraction(h) {
                    self.rate = PRIOR_INFLATION * prior;
                }
            }
            None => self.rate = f64::NAN,
        }
    }
}
