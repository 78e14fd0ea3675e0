//! Work bounded by what was asked: every command estimates, before it starts, the steps it will
//! take and the bytes it will write, and refuses an estimate beyond [`MAX_STEPS`] or [`MAX_BYTES`]
//! with the figures and the way to go ahead anyway (`--allow-large`). The estimates are exact
//! counts of steps and rows; bytes are rows × columns × [`BYTES_PER_CELL`], an upper figure for
//! the CSV's shortest round-trip numbers. Where the group is known (`run`, `trade`, `sweep`), a
//! step counts for its cost on the group relative to a step on SO(3) ([`stage_cost`], measured
//! on SO(n) up to SO(50)): 10⁶ steps on SO(50), 10⁷ on SO(4), are refused, not started.

use crate::error::SimError;

/// Steps a command takes without `--allow-large`: 10⁹ (minutes at the cost of a typical step).
pub const MAX_STEPS: u128 = 1_000_000_000;

/// Bytes a command writes without `--allow-large`: 1 GiB.
pub const MAX_BYTES: u128 = 1 << 30;

/// Characters per CSV cell, separator included: a shortest round-trip double is at most 24.
pub const BYTES_PER_CELL: u128 = 25;

/// Floating-point operations that cost about what a stage on SO(3) costs in all (its constant
/// work — calls, checks, the monitor — dominates its few hundred flops there): the scale of
/// [`stage_cost`] on the stack-allocated groups (SO(3), SE(2), SE(3), …) and of the Jacobian
/// factorizations of a Newton iteration that refactors at every iteration.
pub const FLOPS_PER_UNIT: u128 = 1000;

/// Iterations a simplified-Newton stage is counted for in [`stage_cost`] (a typical count at
/// the steps the trade ladders take; an order of magnitude).
pub const CHORD_ITERATIONS: u128 = 3;

/// How a stage solves for its step, as far as its cost goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Solve {
    /// Explicit: no equation solved.
    Explicit,
    /// An implicit stage iterated on its residual alone: fixed point.
    Iterated,
    /// An implicit stage iterated with a factored Jacobian kept across iterations and steps
    /// (simplified Newton, the default): each iteration applies the stored d×d inverse.
    Chord,
    /// An implicit stage that builds and factors a d×d Jacobian at every iteration (`newton`,
    /// `newton-finite-difference`).
    Newton,
}

impl Solve {
    /// The solve of a method (`explicit` from its `MethodInfo`) with the solver `kind`.
    pub fn of(explicit: bool, kind: integrators::SolverKind) -> Self {
        use integrators::SolverKind;
        match (explicit, kind) {
            (true, _) => Self::Explicit,
            (false, SolverKind::FixedPoint) => Self::Iterated,
            (false, SolverKind::SimplifiedNewton) => Self::Chord,
            (false, _) => Self::Newton,
        }
    }
}

/// The fixed cost of a step on a group stored in dynamically sized matrices (`geodesic-so-n`:
/// faer's), in steps on SO(3), (explicit, implicit): allocation and dispatch of each matrix
/// operation, whatever n. With the per-dimension costs [`DYNAMIC_PER_DIMENSION`], from
/// instruction counts (below).
pub const DYNAMIC_FLOOR: (u128, u128) = (70, 175);

/// The cost per dimension d of the algebra (per ½m² of the m×m matrices) of a step on a
/// dynamically sized group, in steps on SO(3), (explicit, implicit), in thousandths: the
/// products, exponentials and Cayley maps on m×m matrices (faer's blocked, vectorized kernels
/// keep their instruction count near m² from SO(4) to SO(50), not m³).
pub const DYNAMIC_PER_DIMENSION: (u128, u128) = (2600, 6400);

/// Whether a system's group is stored in dynamically sized matrices (SO(n) of `geodesic-so-n`,
/// whatever n, SO(3) included), whose per-step cost [`stage_cost`] counts with
/// [`DYNAMIC_FLOOR`] and [`DYNAMIC_PER_DIMENSION`].
pub fn dynamic_group(kind: crate::systems::SystemKind) -> bool {
    matches!(kind, crate::systems::SystemKind::GeodesicSoN)
}

/// The cost of one stage of a method relative to a Lie–Poisson step (τ = Cayley, simplified
/// Newton) of the free rigid body on SO(3), at least 1.
///
/// - **Dynamically sized groups** (`dynamic`: SO(n) of `geodesic-so-n`): `F + c·d` with the
///   floor F = [`DYNAMIC_FLOOR`] and c = [`DYNAMIC_PER_DIMENSION`] (explicit, implicit), d =
///   n(n−1)/2, fitted to instruction counts of Lie–Poisson (Cayley, θ = ½; fixed point and
///   simplified Newton alike) and RKMK4 on the generalized rigid body, per step, over that of
///   Lie–Poisson on the free body:
///
///   | n | LP measured | LP model | RKMK4 measured | RKMK4 model |
///   |---|---|---|---|---|
///   | 3 | 202 | 194 | | |
///   | 4 | 229 | 213 | 90 | 85 |
///   | 5 | 275 | 239 | | |
///   | 6 | 306 | 271 | | |
///   | 8 | 367 | 354 | | |
///   | 10 | 521 | 463 | 196 | 187 |
///   | 20 | 1474 (fixed point 1511) | 1391 | 528 | 564 |
///   | 50 | fixed point 9133 | 8015 | 3834 | 3255 |
///
///   within 0.85 to 1.07 of the measurement (and so "within a factor 2"). Regenerate with
///   valgrind (`examples/step_cost.rs`, its `so-n/…` cases):
///
///   ```text
///   cargo build --release -p lie-integrators --example step_cost
///   for n in 100 200; do
///     valgrind --tool=callgrind --callgrind-out-file=/tmp/cg.$n \
///       target/release/examples/step_cost so-n/4/lp-cayley-0.5 $n
///   done   # (Ir(200) − Ir(100)) / 100 per step, over free/lp-cayley-0.5's
///   ```
///
///   A [`Solve::Chord`] stage (simplified Newton, the default) adds the application of its
///   stored d×d inverse at each iteration, 2d² flops × [`CHORD_ITERATIONS`] per
///   [`FLOPS_PER_UNIT`] (negligible up to SO(20), where the measurements above agree with fixed
///   point; on SO(50) it doubles the step, and its factorization, d³/3 flops at the first step
///   and at each refresh, is left out), and a [`Solve::Newton`] stage its d×d factorization,
///   ~d³/3 flops per [`FLOPS_PER_UNIT`]: orders of magnitude, not calibrations.
/// - **Stack-allocated groups** (SO(3), SE(2), SE(3), their products): the group's products
///   and exponentials on m×m matrices take ~m³ operations, an operator on the algebra ~d² to
///   apply, a Newton stage's factorization ~d³/3, per [`FLOPS_PER_UNIT`] — 1 on every group of
///   dimension ≤ 6, an order of magnitude, not a calibration.
pub fn stage_cost(
    algebra_dim: usize,
    matrix_side: Option<usize>,
    solve: Solve,
    dynamic: bool,
) -> u128 {
    let d = algebra_dim as u128;
    let solve_cost = match solve {
        Solve::Newton => d.pow(3) / 3 / FLOPS_PER_UNIT,
        Solve::Chord => 2 * d.pow(2) * CHORD_ITERATIONS / FLOPS_PER_UNIT,
        Solve::Explicit | Solve::Iterated => 0,
    };
    if dynamic {
        let (floor, per_dimension) = match solve {
            Solve::Explicit => (DYNAMIC_FLOOR.0, DYNAMIC_PER_DIMENSION.0),
            _ => (DYNAMIC_FLOOR.1, DYNAMIC_PER_DIMENSION.1),
        };
        return floor + per_dimension * d / 1000 + solve_cost;
    }
    let m = matrix_side.unwrap_or(0) as u128;
    let flops = m.pow(3).max(d.pow(2));
    (flops / FLOPS_PER_UNIT + solve_cost).max(1)
}

/// What a command is about to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Estimate {
    /// Integrator steps (composite steps count once per base step they take).
    pub steps: u128,
    /// Bytes written.
    pub bytes: u128,
    /// The cost of a step relative to one on SO(3) ([`stage_cost`]; 0 or 1: SO(3)'s).
    pub step_cost: u128,
}

impl Estimate {
    /// A CSV of `rows` rows (header included) of `columns` numbers.
    pub fn csv(rows: u128, columns: u128) -> u128 {
        rows.saturating_mul(columns).saturating_mul(BYTES_PER_CELL)
    }
    /// Refuses the estimate when it exceeds a limit and `allow_large` is not set.
    pub fn check(&self, what: &str, allow_large: bool) -> Result<(), SimError> {
        if allow_large {
            return Ok(());
        }
        let cost = self.step_cost.max(1);
        let work = self.steps.saturating_mul(cost);
        let over = if work > MAX_STEPS && cost > 1 {
            Some(format!(
                "{:.3e} integrator steps × {cost} (a step's cost on this group in steps on SO(3)) \
                 = {:.3e} SO(3)-step equivalents (limit {MAX_STEPS:.0e})",
                self.steps as f64, work as f64
            ))
        } else if work > MAX_STEPS {
            Some(format!(
                "{:.3e} integrator steps (limit {MAX_STEPS:.0e})",
                self.steps as f64
            ))
        } else if self.bytes > MAX_BYTES {
            Some(format!(
                "about {:.1} GiB of output (limit {} GiB; a larger --stride writes fewer rows)",
                self.bytes as f64 / (1u64 << 30) as f64,
                MAX_BYTES >> 30
            ))
        } else {
            None
        };
        match over {
            Some(message) => Err(SimError::TooLarge {
                what: what.into(),
                message,
            }),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_refuse_with_figures_and_allow_large_lets_through() {
        let ok = Estimate {
            steps: MAX_STEPS,
            bytes: MAX_BYTES,
            step_cost: 1,
        };
        assert!(ok.check("run", false).is_ok());
        let steps = Estimate {
            steps: MAX_STEPS + 1,
            bytes: 0,
            step_cost: 1,
        };
        let e = steps.check("run", false).unwrap_err().to_string();
        assert!(
            e.contains("1.000e9 integrator steps") && e.contains("--allow-large"),
            "{e}"
        );
        let bytes = Estimate {
            steps: 1,
            bytes: 3 * MAX_BYTES,
            step_cost: 1,
        };
        let e = bytes.check("run", false).unwrap_err().to_string();
        assert!(e.contains("3.0 GiB") && e.contains("--stride"), "{e}");
        assert!(steps.check("run", true).is_ok() && bytes.check("run", true).is_ok());
        assert_eq!(Estimate::csv(u128::MAX, 3), u128::MAX);
        let costly = Estimate {
            steps: MAX_STEPS / 10,
            bytes: 0,
            step_cost: 11,
        };
        let e = costly.check("run", false).unwrap_err().to_string();
        assert!(e.contains("× 11") && e.contains("1.100e9"), "{e}");
        assert_eq!(stage_cost(3, Some(3), Solve::Newton, false), 1);
        assert_eq!(stage_cost(3, Some(3), Solve::Iterated, false), 1);
        assert_eq!(stage_cost(3, Some(3), Solve::Chord, false), 1);
        // SO(50) (d = 1225) with simplified Newton: the floor, the per-dimension cost and the
        // stored inverse applied at each of 3 iterations; fixed point pays no matrix.
        assert_eq!(
            stage_cost(1225, None, Solve::Chord, true),
            175 + 7840 + 9003
        );
        assert_eq!(stage_cost(1225, None, Solve::Iterated, true), 175 + 7840);
    }
}
