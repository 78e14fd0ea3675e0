//! [`WarmStart`]: what the solve of one step leaves for the next step of the same size.
//!
//! Along a run at a fixed step h the solutions ξ_k of the step equations are samples of a smooth
//! curve (ξ_k = h v(t_k) + O(h²) with v smooth), so the cubic extrapolation
//! `ξ⁰ = 4ξ_{k−1} − 6ξ_{k−2} + 4ξ_{k−3} − ξ_{k−4}` is within O(h⁵) of ξ_k — relative O(h⁴), against
//! O(h²) for the integrators' one-step predictors. And the simplified-Newton matrix J(ξ_{k−1})⁻¹
//! differs from J(ξ_k)⁻¹ by O(h²) (J − I = O(h), and its arguments move by O(h) per step), so it
//! still contracts the iteration by O(h²): from such a guess two residual evaluations meet the
//! default tolerance with no Jacobian evaluated at all (`SolverKind::SimplifiedNewton`; the
//! solver re-evaluates J if the observed contraction exceeds 0.1).
//!
//! Both are used only when the step size repeats bitwise; a new h (compositions alternate step
//! sizes, a reversed run negates h), a reset or a new solver configuration starts afresh. The
//! warm start changes only where the iteration starts: the step is still solved to the solver's
//! tolerance, so results agree with a cold start to that tolerance (not bitwise).

use lie_groups::{LieGroup, Vector};

/// The largest contraction factor of a step's iteration for which its Newton matrix is kept for
/// the next step. Above it (large steps, where J moves by more than 10⁻³ per step) one fresh J
/// costs less than the extra iterations a stale one needs.
pub const CHORD_REUSE_CONTRACTION: f64 = 1e-3;

/// Past solutions ξ and the last simplified-Newton matrix, for steps of one size h.
#[derive(Debug, Clone)]
pub struct WarmStart<G: LieGroup> {
    /// The step size the contents belong to.
    h: f64,
    /// ξ of the last steps of size h, newest first.
    past: [Option<G::Algebra>; 4],
    /// The inverse simplified-Newton matrix of the last step of size h.
    chord: Option<G::Operator>,
}

impl<G: LieGroup> Default for WarmStart<G> {
    fn default() -> Self {
        Self {
            h: f64::NAN,
            past: [None, None, None, None],
            chord: None,
        }
    }
}

impl<G: LieGroup> WarmStart<G> {
    /// Forgets everything (after a reset of the state or of the solver).
    pub fn clear(&mut self) {
        *self = Self::default();
    }

    /// Whether the contents belong to steps of size h (bitwise).
    fn holds(&self, h: f64) -> bool {
        self.h.to_bits() == h.to_bits()
    }

    /// The cubic extrapolation `4ξ₁ − 6ξ₂ + 4ξ₃ − ξ₄` of the last four solutions, when the last
    /// four steps had size h.
    pub fn predict(&self, h: f64) -> Option<G::Algebra> {
        match (self.holds(h), &self.past) {
            (true, [Some(x1), Some(x2), Some(x3), Some(x4)]) => {
                Some(x1.add(x3).scale(4.0).sub(&x2.scale(6.0)).sub(x4))
            }
            _ => None,
        }
    }

    /// The simplified-Newton matrix of the last step, when it had size h.
    pub fn take_chord(&mut self, h: f64) -> Option<G::Operator> {
        if self.holds(h) {
            self.chord.take()
        } else {
            None
        }
    }

    /// Records the solution ξ of a successful step of size h, and its Newton matrix if the
    /// iteration contracted by at most [`CHORD_REUSE_CONTRACTION`] (otherwise the next step
    /// evaluates J afresh at its guess).
    pub fn record(
        &mut self,
        h: f64,
        xi: &G::Algebra,
        chord: Option<G::Operator>,
        contraction: f64,
    ) {
        if !self.holds(h) {
            self.clear();
            self.h = h;
        }
        let [p0, p1, p2, p3] = &mut self.past;
        core::mem::swap(p3, p2);
        core::mem::swap(p2, p1);
        core::mem::swap(p1, p0);
        *p0 = Some(xi.clone());
        self.chord = chord.filter(|_| contraction <= CHORD_REUSE_CONTRACTION);
    }
}
