//! Work bounded by what was asked: every command estimates, before it starts, the steps it will
//! take and the bytes it will write, and refuses an estimate beyond [`MAX_STEPS`] or [`MAX_BYTES`]
//! with the figures and the way to go ahead anyway (`--allow-large`). The estimates are exact
//! counts of steps and rows; bytes are rows × columns × [`BYTES_PER_CELL`], an upper figure for
//! the CSV's shortest round-trip numbers. Where the group is known (`run`), a step counts for
//! its cost on the group relative to a step on SO(3) ([`stage_cost`]): 10⁸ steps on SO(50) are
//! refused, not started.

use crate::error::SimError;

/// Steps a command takes without `--allow-large`: 10⁹ (minutes at the cost of a typical step).
pub const MAX_STEPS: u128 = 1_000_000_000;

/// Bytes a command writes without `--allow-large`: 1 GiB.
pub const MAX_BYTES: u128 = 1 << 30;

/// Characters per CSV cell, separator included: a shortest round-trip double is at most 24.
pub const BYTES_PER_CELL: u128 = 25;

/// Floating-point operations that cost about what a stage on SO(3) costs in all (its constant
/// work — calls, checks, the monitor — dominates its few hundred flops there).
///
/// An order-of-magnitude scale, not a calibration: timing Lie–Poisson (τ = Cayley, Newton) on
/// the geodesic SO(n) against the free rigid body puts a step on SO(10) and SO(50) at some 16
/// times what [`stage_cost`] says (it counts one Newton factorization, not the iterations nor
/// the Jacobian's assembly), on SO(20) at 0.7 times, and on SO(4) to SO(8), whose fixed cost
/// per step (dynamically sized matrices) [`stage_cost`] leaves out, at some 250 to 370 steps
/// on SO(3) where it counts 1. The limit stops runs of years, not of minutes.
pub const FLOPS_PER_UNIT: u128 = 1000;

/// The cost of one stage of a method relative to a stage on SO(3), at least 1: the group's
/// products and exponentials on m×m matrices take ~m³ operations, an operator on the algebra
/// ~d² to apply (d the algebra's dimension), and an implicit stage whose solver uses a Jacobian
/// (`newton`) factors a d×d Newton matrix, ~d³/3; per [`FLOPS_PER_UNIT`]. On SO(50) with Newton
/// (d = 1225): ~6·10⁵.
pub fn stage_cost(algebra_dim: usize, matrix_side: Option<usize>, newton: bool) -> u128 {
    let d = algebra_dim as u128;
    let m = matrix_side.unwrap_or(0) as u128;
    let newton_flops = if newton { d.pow(3) / 3 } else { 0 };
    let flops = m.pow(3).max(d.pow(2)) + newton_flops;
    (flops / FLOPS_PER_UNIT).max(1)
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
        assert_eq!(stage_cost(3, Some(3), true), 1);
        assert!(stage_cost(1225, Some(50), true) > 500_000);
    }
}
