//! Events: zero crossings of a user function `e(t, μ, g)` along a run, located on the dense-output
//! interpolant ([`crate::dense_output`]) to a tolerance in t.
//!
//! After each step the driver compares the signs of e at the step's ends; where they differ (in
//! the [`Direction`] asked for), the crossing is bracketed in the step and located by the Illinois
//! variant of regula falsi on `s ↦ e(t(s), μ(s), g(s))` of the [`HermiteStep`] interpolant,
//! bisecting whenever it stalls, until the bracket is within the event's tolerance. A crossing
//! is found only when e changes sign between step ends: two crossings within one step cancel (as in
//! every step-end event detector, e.g. scipy's `solve_ivp`); take smaller steps if the event
//! function oscillates faster than the step.
//!
//! The located time is the root of the *interpolant's* e to the tolerance; its distance from the
//! true crossing is the tolerance plus the method's error (`tests/dense_output.rs`).

use crate::dense_output::HermiteStep;
use lie_groups::LieGroup;

/// Which sign changes count.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Direction {
    /// From negative to positive.
    Rising,
    /// From positive to negative.
    Falling,
    /// Either way.
    #[default]
    Either,
}

impl Direction {
    /// Whether e going from `v0` to `v1` over a step is a crossing counted in this direction:
    /// `Some(rising)` if so. A value of exactly 0 at the step's end counts (so a zero at a step
    /// point is found once, by the step that ends there); non-finite values never count.
    pub fn crossing(self, v0: f64, v1: f64) -> Option<bool> {
        if !v0.is_finite() || !v1.is_finite() {
            return None;
        }
        let rising = v0 < 0.0 && v1 >= 0.0;
        let falling = v0 > 0.0 && v1 <= 0.0;
        let counts = match self {
            Self::Rising => rising,
            Self::Falling => falling,
            Self::Either => rising || falling,
        };
        counts.then_some(rising)
    }
}

/// An event function `e(t, μ, g)`.
type EventFunction<'a, G> = Box<dyn Fn(f64, &<G as LieGroup>::Algebra, Option<&G>) -> f64 + 'a>;

/// An event function with its options.
pub struct Event<'a, G: LieGroup> {
    function: EventFunction<'a, G>,
    /// Which crossings count.
    pub direction: Direction,
    /// Whether the run stops at the first crossing.
    pub terminal: bool,
    /// The width in t to which a crossing is located.
    pub tolerance: f64,
}

impl<'a, G: LieGroup> Event<'a, G> {
    /// An event on the zeros of `function(t, μ, g)` (g is `None` when the run does not
    /// reconstruct it), counting crossings in either direction, not terminal, located to 1e-10 in t.
    pub fn new(function: impl Fn(f64, &G::Algebra, Option<&G>) -> f64 + 'a) -> Self {
        Self {
            function: Box::new(function),
            direction: Direction::Either,
            terminal: false,
            tolerance: 1e-10,
        }
    }
    /// The same event counting only crossings in `direction`.
    pub fn direction(self, direction: Direction) -> Self {
        Self { direction, ..self }
    }
    /// The same event stopping the run at its first crossing.
    pub fn terminal(self) -> Self {
        Self {
            terminal: true,
            ..self
        }
    }
    /// The same event located to `tolerance` in t (clamped to at least 4 ulps of t by the
    /// bisection).
    pub fn tolerance(self, tolerance: f64) -> Self {
        Self { tolerance, ..self }
    }
    /// e(t, μ, g).
    pub fn value(&self, t: f64, mu: &G::Algebra, g: Option<&G>) -> f64 {
        (self.function)(t, mu, g)
    }
}

/// A located crossing.
#[derive(Debug, Clone)]
pub struct EventHit<G: LieGroup> {
    /// Which event (its index in the list given to the driver).
    pub event: usize,
    /// The crossing time.
    pub t: f64,
    /// μ at the crossing (interpolated).
    pub mu: G::Algebra,
    /// g at the crossing (interpolated), where reconstructed.
    pub g: Option<G>,
    /// Whether e was rising there.
    pub rising: bool,
}

/// The crossing of `event` in the step of `interpolant` where e goes from `v0` to `v1`, if its
/// sign changes in the event's direction. An end value of exactly 0 counts at the step's end (so a
/// zero at a step point is found once, by the step that ends there).
pub(crate) fn locate<G: LieGroup>(
    event: &Event<'_, G>,
    index: usize,
    interpolant: &HermiteStep<G>,
    v0: f64,
    v1: f64,
) -> Option<EventHit<G>> {
    let rising = event.direction.crossing(v0, v1)?;
    let (ta, tb) = interpolant.span();
    let e = |t: f64| {
        let (mu, g) = interpolant.at(t);
        event.value(t, &mu, g.as_ref())
    };
    let t = find_crossing(e, (ta, v0), (tb, v1), event.tolerance);
    let (mu, g) = interpolant.at(t);
    Some(EventHit {
        event: index,
        t,
        mu,
        g,
        rising,
    })
}

/// The zero of `f` in the bracket `(ta, f(ta))`, `(tb, f(tb))` (opposite signs, or `f(tb) = 0`),
/// located to `tolerance` in t (at least 4 ulps of t) by the Illinois variant of regula falsi,
/// bisecting when an iterate leaves the bracket; stops early at an exact zero or a non-finite
/// value. `ta > tb` is allowed (integration backwards in time).
pub fn find_crossing(
    f: impl Fn(f64) -> f64,
    (ta, fa): (f64, f64),
    (tb, fb): (f64, f64),
    tolerance: f64,
) -> f64 {
    let (mut a, mut fa, mut b, mut fb) = (ta, fa, tb, fb);
    // which end was kept by the last update: -1 a, 1 b
    let mut kept = 0i8;
    for _ in 0..200 {
        if (b - a).abs() <= tolerance.max(4.0 * f64::EPSILON * b.abs()) || fb == 0.0 {
            break;
        }
        let mut c = b - fb * (b - a) / (fb - fa);
        if !c.is_finite() || (c - a) * (c - b) >= 0.0 {
            c = 0.5 * (a + b);
        }
        let fc = f(c);
        if !fc.is_finite() {
            break;
        }
        if fc == 0.0 {
            (a, b, fb) = (c, c, 0.0);
            break;
        }
        if (fc < 0.0) == (fb < 0.0) {
            b = c;
            fb = fc;
            if kept == -1 {
                fa *= 0.5;
            }
            kept = -1;
        } else {
            a = c;
            fa = fc;
            if kept == 1 {
                fb *= 0.5;
            }
            kept = 1;
        }
    }
    if fb == 0.0 {
        b
    } else {
        0.5 * (a + b)
    }
}
