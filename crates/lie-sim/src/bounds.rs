//! Work bounded by what was asked: every command estimates, before it starts, the steps it will
//! take and the bytes it will write, and refuses an estimate beyond [`MAX_STEPS`] or [`MAX_BYTES`]
//! with the figures and the way to go ahead anyway (`--allow-large`). The estimates are exact
//! counts of steps and rows; bytes are rows × columns × [`BYTES_PER_CELL`], an upper figure for
//! the CSV's shortest round-trip numbers.

use crate::error::SimError;

/// Steps a command takes without `--allow-large`: 10⁹ (minutes at the cost of a typical step).
pub const MAX_STEPS: u128 = 1_000_000_000;

/// Bytes a command writes without `--allow-large`: 1 GiB.
pub const MAX_BYTES: u128 = 1 << 30;

/// Characters per CSV cell, separator included: a shortest round-trip double is at most 24.
pub const BYTES_PER_CELL: u128 = 25;

/// What a command is about to do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Estimate {
    /// Integrator steps (composite steps count once per base step they take).
    pub steps: u128,
    /// Bytes written.
    pub bytes: u128,
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
        let over = if self.steps > MAX_STEPS {
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
        };
        assert!(ok.check("run", false).is_ok());
        let steps = Estimate {
            steps: MAX_STEPS + 1,
            bytes: 0,
        };
        let e = steps.check("run", false).unwrap_err().to_string();
        assert!(
            e.contains("1.000e9 integrator steps") && e.contains("--allow-large"),
            "{e}"
        );
        let bytes = Estimate {
            steps: 1,
            bytes: 3 * MAX_BYTES,
        };
        let e = bytes.check("run", false).unwrap_err().to_string();
        assert!(e.contains("3.0 GiB") && e.contains("--stride"), "{e}");
        assert!(steps.check("run", true).is_ok() && bytes.check("run", true).is_ok());
        assert_eq!(Estimate::csv(u128::MAX, 3), u128::MAX);
    }
}
