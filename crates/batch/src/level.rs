//! The instruction sets a batch runs on, detected at run time, and a way to force one.

use crate::BatchError;
use core::fmt;
use core::str::FromStr;
use pulp::{Simd, WithSimd};

/// An instruction set for the lanes: how many bodies one vector operation advances.
///
/// Every level computes the same bits for a body (each lane is the same sequence of IEEE
/// operations, fused multiply-adds included: [`crate`] page, "Determinism"); the level changes
/// only the speed. [`Level::detect`] picks the widest one the CPU has; a level can be forced (to
/// measure AVX2 on an AVX-512 machine, or to check that every level gives the same bits).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Level {
    /// x86-64-v4 (AVX-512 F/BW/CD/DQ/VL): 8 lanes of f64.
    Avx512,
    /// x86-64-v3 (AVX2 + FMA): 4 lanes.
    Avx2,
    /// One lane, plain f64 arithmetic (any CPU; `f64::mul_add` for the fused multiply-adds).
    Scalar,
}

impl Level {
    /// Every level, widest first.
    pub const ALL: [Level; 3] = [Level::Avx512, Level::Avx2, Level::Scalar];

    /// The widest level this CPU runs.
    pub fn detect() -> Self {
        Self::ALL
            .into_iter()
            .find(|l| l.is_available())
            .unwrap_or(Level::Scalar)
    }
    /// Whether this CPU runs the level.
    pub fn is_available(self) -> bool {
        match self {
            #[cfg(target_arch = "x86_64")]
            Level::Avx512 => pulp::x86::V4::try_new().is_some(),
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => pulp::x86::V3::try_new().is_some(),
            #[cfg(not(target_arch = "x86_64"))]
            Level::Avx512 | Level::Avx2 => false,
            Level::Scalar => true,
        }
    }
    /// The levels this CPU runs, widest first.
    pub fn available() -> Vec<Self> {
        Self::ALL.into_iter().filter(|l| l.is_available()).collect()
    }
    /// Lanes of f64 per vector: 8, 4 or 1.
    pub fn lanes(self) -> usize {
        match self {
            Level::Avx512 => 8,
            Level::Avx2 => 4,
            Level::Scalar => 1,
        }
    }
    /// The name: `avx512`, `avx2` or `scalar` (what [`Level::from_str`] reads).
    pub fn name(self) -> &'static str {
        match self {
            Level::Avx512 => "avx512",
            Level::Avx2 => "avx2",
            Level::Scalar => "scalar",
        }
    }
    /// Runs `op` with this level's vector type; [`BatchError::LevelUnavailable`] if the CPU lacks
    /// it.
    pub(crate) fn dispatch<Op: WithSimd>(self, op: Op) -> Result<Op::Output, BatchError> {
        match self {
            #[cfg(target_arch = "x86_64")]
            Level::Avx512 => pulp::x86::V4::try_new()
                .map(|s| Simd::vectorize(s, op))
                .ok_or(BatchError::LevelUnavailable { level: self }),
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => pulp::x86::V3::try_new()
                .map(|s| Simd::vectorize(s, op))
                .ok_or(BatchError::LevelUnavailable { level: self }),
            #[cfg(not(target_arch = "x86_64"))]
            Level::Avx512 | Level::Avx2 => Err(BatchError::LevelUnavailable { level: self }),
            Level::Scalar => Ok(Simd::vectorize(pulp::Scalar, op)),
        }
    }
    /// Checks that the CPU runs the level.
    pub fn check(self) -> Result<Self, BatchError> {
        if self.is_available() {
            Ok(self)
        } else {
            Err(BatchError::LevelUnavailable { level: self })
        }
    }
}

impl Default for Level {
    /// [`Level::detect`].
    fn default() -> Self {
        Self::detect()
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Level {
    type Err = BatchError;
    /// `avx512`, `avx2` or `scalar`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|l| l.name() == s)
            .ok_or_else(|| BatchError::UnknownLevel { name: s.into() })
    }
}
