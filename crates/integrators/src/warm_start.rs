//! [`WarmStart`]: what the solve of one step leaves for the next step of the same size.
//!
//! Along a run at a fixed step h the solutions of the step equations (Lie–Poisson's η_k = hξ_k,
//! Euler–Poincaré's increments δ_k = ξ̄_k − ξ_k) are samples of a smooth curve (h v(t_k) + O(h²)
//! with v smooth), so the quintic extrapolation
//! `x⁰ = 6x_{k−1} − 15x_{k−2} + 20x_{k−3} − 15x_{k−4} + 6x_{k−5} − x_{k−6}` is within O(h⁷) of
//! x_k — relative O(h⁶), against O(h²) for the integrators' one-step predictors. On the free rigid
//! body at h = 0.01 its first update is 2.7e-14 of η (Lie–Poisson) and 2.3e-13 of δ
//! (Euler–Poincaré), medians over 2000 steps, where the quartic extrapolation of the last five
//! left 3.0e-12 and 1.6e-11: with the quartic one, Euler–Poincaré, whose tolerance is relative to
//! δ ~ 1e-3 |ξ|, could rarely accept its guess on the contraction prior alone (1.75 residuals per
//! step against 1.23 with the quintic; Lie–Poisson 1.33 against 1.16). The coefficients sum to 63 in
//! magnitude (the quartic's 31), so the past solutions' own errors enter the guess at most
//! 63-fold: at tiny steps, where those errors dominate, one step in 25 (Lie–Poisson, h = 1e-3)
//! to one in 7 (Euler–Poincaré) takes a second residual it did not take with the quartic one. And the simplified-Newton matrix J(ξ_{k−1})⁻¹
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
//! Everything is kept per step size: [`SLOTS`] step sizes (bitwise) at a time, the least recently
//! used one giving way to a new size, so the stages of a composition — each a step of its own size
//! γᵢh, repeated once per composed step — keep their matrices and extrapolations from one composed
//! step to the next (a plain run uses one slot). The extrapolation of a slot also needs its samples
//! equally spaced in time (to 10⁻³ relative): the two stages of a palindromic scheme that share a
//! size (γ₁ = γₛ) alternate their spacings, and their slot keeps only its matrix. Where the
//! Newton matrix is dense (a product group such as the gyrostat's SO(3) × ℝ³, a heap matrix),
//! re-assembling it at every stage would cost several plain steps per stage. The slot of the
//! current size is kept apart from the parked ones, so a plain run pays nothing for the others. A reset or a
//! new solver configuration starts afresh. The warm start changes only where the iteration starts:
//! the step is still solved to the solver's tolerance, so results agree with a cold start to that
//! tolerance (not bitwise).

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
const DEPTH: usize = 6;

/// Step sizes kept at a time: the distinct stage sizes of the crate's largest composition
/// (Kahan–Li 8: 17 stages, 9 sizes).
pub const SLOTS: usize = 9;

/// Past solutions ξ, the last simplified-Newton matrix and its contraction, for steps of one
/// size h.
#[derive(Debug, Clone)]
struct Slot<G: LieGroup> {
    /// The step size the contents belong to (NaN: free).
    h: f64,
    /// ξ of the last steps of size h in a ring, kept twice: the newest at `newest` and at
    /// `newest + DEPTH`, then older ones at `newest − 1, …` (mod [`DEPTH`]), the `count` newest of
    /// them valid. A ring, so recording one writes one entry (twice; in place: `clone_from` keeps
    /// a heap vector's buffer) instead of shifting them all; twice, so the last [`DEPTH`] are
    /// always the window `newest + 1 ..= newest + DEPTH`, read without wrapping indices.
    past: [G::Algebra; 2 * DEPTH],
    newest: usize,
    count: usize,
    /// The time the newest solution was recorded at, and the spacing of the valid ones.
    time: f64,
    spacing: f64,
    /// The inverse simplified-Newton matrix of the last step of size h.
    chord: Option<G::Operator>,
    /// The contraction prior of the next step's first iteration (see the module page); NaN when
    /// there is none.
    rate: f64,
    /// When the slot was last used (for the least-recently-used replacement).
    used: u64,
}

impl<G: LieGroup> Default for Slot<G> {
    fn default() -> Self {
        Self {
            h: f64::NAN,
            past: core::array::from_fn(|_| G::Algebra::zeros(G::dim())),
            newest: 0,
            count: 0,
            time: f64::NAN,
            spacing: f64::NAN,
            chord: None,
            rate: f64::NAN,
            used: 0,
        }
    }
}

impl<G: LieGroup> Slot<G> {
    /// Whether the slot belongs to steps of size h (bitwise).
    #[inline(always)]
    fn holds(&self, h: f64) -> bool {
        self.h.to_bits() == h.to_bits()
    }

    /// Empties the slot and gives it to steps of size h.
    fn take_for(&mut self, h: f64) {
        self.h = h;
        self.count = 0;
        self.chord = None;
        self.rate = f64::NAN;
    }

    /// The last [`DEPTH`] solutions, oldest first (the newest last).
    #[inline(always)]
    fn window(&self) -> &[G::Algebra] {
        &self.past[self.newest + 1..=self.newest + DEPTH]
    }

    /// The contraction prior of the kept matrix (see [`WarmStart::prior_contraction`]).
    #[inline]
    fn prior(&self) -> Option<f64> {
        self.chord.is_some().then(|| {
            if self.rate.is_finite() {
                self.rate.max(CHORD_REUSE_CONTRACTION)
            } else {
                CHORD_REUSE_CONTRACTION
            }
        })
    }
}

/// Past solutions, Newton matrices and contractions of the last [`SLOTS`] step sizes (see the
/// module page).
#[derive(Debug, Clone)]
pub struct WarmStart<G: LieGroup> {
    /// The slot of the last step's size: a plain run touches only it.
    current: Slot<G>,
    /// The other sizes' slots (at most [`SLOTS`] − 1), parked until a step of their size swaps
    /// them in; made when a second size first appears, so a plain run holds one slot only (its
    /// past solutions are heap vectors on SO(n), 1225 entries each at n = 50).
    parked: Vec<Slot<G>>,
    /// The use counter ([`Slot::used`]).
    clock: u64,
}

impl<G: LieGroup> Default for WarmStart<G> {
    fn default() -> Self {
        Self {
            current: Slot::default(),
            parked: Vec::new(),
            clock: 0,
        }
    }
}

impl<G: LieGroup> WarmStart<G> {
    /// Forgets everything (after a reset of the state or of the solver).
    pub fn clear(&mut self) {
        self.current.take_for(f64::NAN);
        for slot in &mut self.parked {
            slot.take_for(f64::NAN);
        }
    }

    /// The slot of steps of size h (bitwise), if there is one.
    #[inline(always)]
    fn find(&self, h: f64) -> Option<&Slot<G>> {
        if self.current.holds(h) {
            Some(&self.current)
        } else {
            self.find_parked(h)
        }
    }

    /// The parked slot of steps of size h, if there is one (out of line: a plain run never
    /// looks).
    #[inline(never)]
    fn find_parked(&self, h: f64) -> Option<&Slot<G>> {
        self.parked.iter().find(|s| s.holds(h))
    }

    /// Makes the slot of h the current one: swaps in the parked slot of h, or parks the current
    /// slot in place of the least recently used one and empties it for h.
    #[inline(always)]
    fn select(&mut self, h: f64) {
        if !self.current.holds(h) {
            self.swap_in(h);
        }
    }

    #[inline(never)]
    fn swap_in(&mut self, h: f64) {
        self.clock += 1;
        self.current.used = self.clock;
        let i = match self.parked.iter().position(|s| s.holds(h)) {
            Some(i) => i,
            None if self.parked.len() < SLOTS - 1 => {
                let mut fresh = Slot::default();
                fresh.take_for(h);
                self.parked
                    .push(core::mem::replace(&mut self.current, fresh));
                return;
            }
            None => {
                let i = (0..self.parked.len())
                    .min_by_key(|&i| self.parked[i].used)
                    .unwrap_or(0);
                self.parked[i].take_for(h);
                i
            }
        };
        core::mem::swap(&mut self.current, &mut self.parked[i]);
    }

    /// The quintic extrapolation `6ξ₁ − 15ξ₂ + 20ξ₃ − 15ξ₄ + 6ξ₅ − ξ₆` of the last six
    /// solutions, when the last six steps of size h were equally spaced in time.
    #[inline(always)]
    pub fn predict(&self, h: f64) -> Option<G::Algebra> {
        let slot = self.find(h)?;
        if slot.count < DEPTH {
            return None;
        }
        // The window always holds DEPTH entries: the `else` arm is never taken.
        let [x6, x5, x4, x3, x2, x1] = slot.window() else {
            return None;
        };
        // The newest, stored by the last step, entry by entry (crate::carried_state).
        let x1 = &crate::carried_state::read(x1);
        // 6(ξ₁ + ξ₅) − 15(ξ₂ + ξ₄) + 20ξ₃ − ξ₆
        Some(
            x1.add(x5)
                .scale(6.0)
                .sub(&x2.add(x4).scale(15.0))
                .add(&x3.scale(20.0))
                .sub(x6),
        )
    }

    /// The simplified-Newton matrix of the last step of size h (`None` when there is none; a
    /// slot is made for h, replacing the least recently used one), for
    /// [`crate::solver::solve`] to use and update in place.
    #[inline]
    pub fn chord(&mut self, h: f64) -> &mut Option<G::Operator> {
        self.select(h);
        &mut self.current.chord
    }

    /// The contraction prior of the kept matrix for a step of size h: the last measured bound (or
    /// its inflation, see [`Self::record`]), at least [`CHORD_REUSE_CONTRACTION`] — the most a
    /// kept matrix was seen to contract by, and the prior of a matrix not yet measured on a later
    /// step than its own; `None` without a kept matrix of that size.
    #[inline]
    pub fn prior_contraction(&self, h: f64) -> Option<f64> {
        self.find(h)?.prior()
    }

    /// Records the solution ξ of a successful step of size h ending at time t, the contraction
    /// its iteration measured and its rounding-proof bound (`None` when it stopped after one
    /// iteration, on its prior; see [`crate::solver::Solution`]) and how many Jacobians it
    /// evaluated. The Newton matrix the solver left in [`Self::chord`] is kept only if it
    /// contracted by at most [`CHORD_REUSE_CONTRACTION`] (otherwise the next step evaluates J
    /// afresh at its guess). A contraction measured with a matrix carried from an earlier step
    /// becomes the next prior; one measured with a matrix evaluated in this step is Newton's
    /// (quadratic, at the step's own guess) and says nothing of the next step's older matrix, so
    /// the next step has no prior; without a measurement the prior inflates
    /// ([`Self::prior_contraction`]). A solution not equally spaced in time from the slot's
    /// earlier ones starts its extrapolation afresh.
    pub fn record(
        &mut self,
        h: f64,
        t: f64,
        xi: &G::Algebra,
        contraction: Option<(f64, f64)>,
        jacobians: usize,
    ) {
        self.select(h);
        let slot = &mut self.current;
        let spacing = t - slot.time;
        // 10⁻³ relative: the times themselves round (by ε t, which at t = 10⁶ and h = 10⁻⁵ is
        // 2·10⁻⁵ of h); the spacings this tells apart differ by O(1).
        let even = (spacing - slot.spacing).abs() <= 1e-3 * spacing.abs();
        slot.count = match slot.count {
            0 => 1,
            1 => {
                slot.spacing = spacing;
                2
            }
            n if even => (n + 1).min(DEPTH),
            _ => {
                slot.spacing = spacing;
                2
            }
        };
        slot.time = t;
        slot.newest = if slot.newest + 1 == DEPTH {
            0
        } else {
            slot.newest + 1
        };
        slot.past[slot.newest].clone_from(xi);
        slot.past[slot.newest + DEPTH].clone_from(xi);
        match contraction {
            Some((rho, bound)) => {
                slot.rate = if jacobians == 0 { bound } else { f64::NAN };
                if rho > CHORD_REUSE_CONTRACTION {
                    slot.chord = None;
                }
            }
            None if jacobians == 0 => {
                if let Some(prior) = slot.prior() {
                    slot.rate = PRIOR_INFLATION * prior;
                }
            }
            None => slot.rate = f64::NAN,
        }
    }
}
