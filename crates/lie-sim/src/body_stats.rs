//! The statistics of a many-body scene (`crate::many_bodies`) at one output time, folded body by
//! body so that nothing of them grows with the number of bodies N.
//!
//! A body i in a uniform field or free (`batch::BodyModel`: 𝕀 = diag(I₁, I₂, I₃), potential
//! `V(R) = ⟨m g χ, Γ⟩`, `Γ = Rᵀe₃`) is read at time t as an [`Observation`] of its (Π, R):
//!
//! - its energy `E = ½ Σ Πᵢ²/Iᵢ + ⟨m g χ, Γ⟩` and, free, its Casimir `C = |Π|²`, as the batch's
//!   monitor computes them (the same fused multiply-adds, so that at T the errors `|E − E₀|` and
//!   `|C − C₀|` are the bits of the `max_energy_error` and `max_casimir_error` the sweep writes
//!   for the same member when it monitors T only);
//! - `cos θ = ⟨R b, f⟩`, the angle of its axis against the field: in a field (χ ≠ 0) b = χ/|χ|
//!   and f = −e₃, the direction the field pulls χ towards (`V` is least at cos θ = 1: a dipole
//!   aligned with its field); free, b = e₃ (the third principal axis) and f = e₃;
//! - its kinetic energy per principal axis `Kᵢ = Πᵢ²/(2Iᵢ)`.
//!
//! A [`RowStats`] folds the running bodies' observations at one output time, in index order:
//! the mean and maximum of the energy and Casimir errors, quantiles of the energy error from a
//! log-binned histogram ([`LogHistogram`]), the orientational order parameters ⟨cos θ⟩ (the
//! polarisation) and ⟨P₂(cos θ)⟩ = ⟨(3 cos²θ − 1)/2⟩ (0 for isotropic axes, 1 for aligned
//! ones), the mean kinetic energy per axis ⟨Kᵢ⟩ and the rotational temperature
//! `T_rot = ⅔ Σᵢ ⟨Kᵢ⟩` (k_B = 1: equipartition gives each axis ½ T_rot). Why these: they are what
//! a molecular-dynamics or Monte Carlo run of rigid rotors is judged by — whether the integrator
//! keeps the energy (mean: drift; maximum and the 99th percentile: the worst members, which a mean
//! hides), whether equipartition holds between the axes, and how the ensemble orders in the field.
//!
//! **Deterministic.** The sums are plain sums in index order and the histogram counts integers,
//! so a row has the same bits whatever the chunks, the threads and the path that stepped the
//! bodies, as long as the observations have the same bits.

use integrators::ensemble::push_exp;
use nalgebra::{Matrix3, Vector3};

/// One body's (Π, R) at one output time, read by an [`Observer`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observation {
    /// E = ½ Σ Πᵢ²/Iᵢ (+ ⟨m g χ, Γ⟩ in a field).
    pub energy: f64,
    /// C = |Π|², free; `None` in a field.
    pub casimir: Option<f64>,
    /// cos θ of the body's axis against the field (module page).
    pub cos: f64,
    /// Kᵢ = Πᵢ²/(2Iᵢ).
    pub kinetic: [f64; 3],
}

/// Reads bodies of one model (module page).
#[derive(Debug, Clone, PartialEq)]
pub struct Observer {
    inv: [f64; 3],
    /// m g χ, in a field.
    field: Option<[f64; 3]>,
    /// χ/|χ|, in a field with χ ≠ 0.
    axis: Option<[f64; 3]>,
}

impl Observer {
    /// The reader of bodies of `body`.
    pub fn new(body: &batch::BodyModel) -> Self {
        let field = body.field_arm();
        let axis = field.and_then(|m| {
            let norm = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
            (norm > 0.0).then(|| m.map(|x| x / norm))
        });
        Self {
            inv: body.inverse_moments(),
            field,
            axis,
        }
    }

    /// Whether the bodies have the Casimir |Π|² (free bodies).
    pub fn has_casimir(&self) -> bool {
        self.field.is_none()
    }

    /// The observation of (Π, R).
    pub fn observe(&self, pi: &Vector3<f64>, r: &Matrix3<f64>) -> Observation {
        let (p, inv) = (pi, self.inv);
        // The batch monitor's expression (`batch::Strang`, `batch::QuaternionRk4`), FMA for FMA.
        let two_h = p[2].mul_add(
            p[2] * inv[2],
            p[1].mul_add(p[1] * inv[1], p[0] * (p[0] * inv[0])),
        );
        let kinetic = two_h * 0.5;
        // Γ = Rᵀe₃: the third row of R.
        let gamma = [r[(2, 0)], r[(2, 1)], r[(2, 2)]];
        let (energy, casimir) = match self.field {
            Some(m) => {
                let v = gamma[2].mul_add(m[2], gamma[1].mul_add(m[1], gamma[0] * m[0]));
                (kinetic + v, None)
            }
            None => {
                let c = p[2].mul_add(p[2], p[1].mul_add(p[1], p[0] * p[0]));
                (kinetic, Some(c))
            }
        };
        let cos = match self.axis {
            // ⟨R b, −e₃⟩ = −⟨b, Γ⟩.
            Some(b) => -(b[0] * gamma[0] + b[1] * gamma[1] + b[2] * gamma[2]),
            // ⟨R e₃, e₃⟩ = R₃₃.
            None => gamma[2],
        };
        Observation {
            energy,
            casimir,
            cos,
            kinetic: core::array::from_fn(|i| 0.5 * (p[i] * (p[i] * inv[i]))),
        }
    }
}

/// A histogram of non-negative numbers (errors) in bins of 1/[`LogHistogram::PER_DECADE`] of a
/// decade from 10^[`LogHistogram::LOWEST`] to 10^[`LogHistogram::HIGHEST`], with one bin below
/// (zero included) and one above (NaN included): a quantile is known to a factor
/// 10^(1/PER_DECADE), from counts that do not depend on the order of the values.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LogHistogram {
    counts: Vec<u64>,
}

impl Default for LogHistogram {
    fn default() -> Self {
        Self {
            counts: vec![0; Self::BINS + 2],
        }
    }
}

impl LogHistogram {
    /// Bins per decade.
    pub const PER_DECADE: i32 = 20;
    /// The lowest edge, 10^LOWEST.
    pub const LOWEST: i32 = -20;
    /// The highest edge, 10^HIGHEST.
    pub const HIGHEST: i32 = 2;
    /// The number of bins between the lowest and the highest edge.
    pub const BINS: usize = ((Self::HIGHEST - Self::LOWEST) * Self::PER_DECADE) as usize;

    /// Edge k = 0 … BINS: 10^(LOWEST + k/PER_DECADE) (bin k ≥ 1 holds edge k−1 < x ≤ edge k).
    pub fn edge(k: usize) -> f64 {
        10f64.powf(f64::from(Self::LOWEST) + k as f64 / f64::from(Self::PER_DECADE))
    }

    /// The bin of x: 0 for x ≤ edge 0, k for edge k−1 < x ≤ edge k, BINS + 1 above the last
    /// edge (and for NaN). The logarithm only guesses k; the edges decide it.
    fn bin(x: f64) -> usize {
        if x.is_nan() || x > Self::edge(Self::BINS) {
            return Self::BINS + 1;
        }
        if x <= Self::edge(0) {
            return 0;
        }
        let guess = (x.log10() - f64::from(Self::LOWEST)) * f64::from(Self::PER_DECADE);
        let mut k = (guess.ceil().max(1.0) as usize).min(Self::BINS);
        while k < Self::BINS && x > Self::edge(k) {
            k += 1;
        }
        while k > 1 && x <= Self::edge(k - 1) {
            k -= 1;
        }
        k
    }

    /// Counts x.
    pub fn add(&mut self, x: f64) {
        self.counts[Self::bin(x)] += 1;
    }

    /// The number of values counted.
    pub fn total(&self) -> u64 {
        self.counts.iter().sum()
    }

    /// An upper bound within a factor 10^(1/PER_DECADE) of the q-quantile (the ⌈q n⌉-th smallest
    /// of the n values, 0 < q ≤ 1): the upper edge of its bin; +∞ above the last edge; `None`
    /// when nothing was counted.
    pub fn quantile(&self, q: f64) -> Option<f64> {
        let n = self.total();
        if n == 0 {
            return None;
        }
        let rank = ((q * n as f64).ceil() as u64).clamp(1, n);
        let mut seen = 0;
        for (k, c) in self.counts.iter().enumerate() {
            seen += c;
            if seen >= rank {
                return Some(if k <= Self::BINS {
                    Self::edge(k)
                } else {
                    f64::INFINITY
                });
            }
        }
        Some(f64::INFINITY)
    }
}

/// The statistics of the running bodies at one output time (module page), folded in index order.
#[derive(Debug, Clone, PartialEq)]
pub struct RowStats {
    /// The output time t.
    pub time: f64,
    /// The steps taken to t.
    pub steps: u64,
    running: u64,
    failed: u64,
    energy_sum: f64,
    energy_max: f64,
    energy_histogram: LogHistogram,
    /// Σ and max of |C − C₀|, for free bodies.
    casimir: Option<(f64, f64)>,
    cos_sum: f64,
    p2_sum: f64,
    kinetic_sum: [f64; 3],
}

/// The quantiles of the energy error a row reports.
const QUANTILES: [(f64, &str); 2] = [(0.5, "p50"), (0.99, "p99")];

impl RowStats {
    /// No body yet, at time t after `steps` steps; `casimir`: the bodies have one.
    pub fn new(time: f64, steps: u64, casimir: bool) -> Self {
        Self {
            time,
            steps,
            running: 0,
            failed: 0,
            energy_sum: 0.0,
            energy_max: 0.0,
            energy_histogram: LogHistogram::default(),
            casimir: casimir.then_some((0.0, 0.0)),
            cos_sum: 0.0,
            p2_sum: 0.0,
            kinetic_sum: [0.0; 3],
        }
    }

    /// Folds the next body: its observation at t (`None`: it failed or was never built) and at
    /// t = 0.
    pub fn fold(&mut self, now: Option<&Observation>, initial: Option<&Observation>) {
        let (Some(o), Some(o0)) = (now, initial) else {
            self.failed += 1;
            return;
        };
        self.running += 1;
        let de = (o.energy - o0.energy).abs();
        self.energy_sum += de;
        self.energy_max = self.energy_max.max(de);
        self.energy_histogram.add(de);
        if let (Some((sum, max)), Some(c), Some(c0)) =
            (self.casimir.as_mut(), o.casimir, o0.casimir)
        {
            let dc = (c - c0).abs();
            *sum += dc;
            *max = max.max(dc);
        }
        self.cos_sum += o.cos;
        self.p2_sum += (1.5 * o.cos).mul_add(o.cos, -0.5);
        for (s, k) in self.kinetic_sum.iter_mut().zip(o.kinetic) {
            *s += k;
        }
    }

    /// Bodies still running at t.
    pub fn running(&self) -> u64 {
        self.running
    }
    /// Bodies that failed (or were never built) by t.
    pub fn failed(&self) -> u64 {
        self.failed
    }
    fn mean(&self, sum: f64) -> Option<f64> {
        (self.running > 0).then(|| sum / self.running as f64)
    }
    /// ⟨|E − E₀|⟩ over the running bodies.
    pub fn energy_error_mean(&self) -> Option<f64> {
        self.mean(self.energy_sum)
    }
    /// max |E − E₀| over the running bodies (0 when none runs).
    pub fn energy_error_max(&self) -> f64 {
        self.energy_max
    }
    /// An upper bound within 10^(1/20) of the q-quantile of |E − E₀| ([`LogHistogram::quantile`]).
    pub fn energy_error_quantile(&self, q: f64) -> Option<f64> {
        self.energy_histogram.quantile(q)
    }
    /// ⟨|C − C₀|⟩ and max |C − C₀|, for free bodies.
    pub fn casimir_error(&self) -> Option<(Option<f64>, f64)> {
        self.casimir.map(|(sum, max)| (self.mean(sum), max))
    }
    /// ⟨cos θ⟩.
    pub fn cos_mean(&self) -> Option<f64> {
        self.mean(self.cos_sum)
    }
    /// ⟨P₂(cos θ)⟩.
    pub fn p2_mean(&self) -> Option<f64> {
        self.mean(self.p2_sum)
    }
    /// ⟨Kᵢ⟩ per principal axis.
    pub fn kinetic_mean(&self) -> Option<[f64; 3]> {
        (self.running > 0).then(|| self.kinetic_sum.map(|s| s / self.running as f64))
    }
    /// T_rot = ⅔ Σᵢ ⟨Kᵢ⟩ (k_B = 1).
    pub fn temperature(&self) -> Option<f64> {
        self.kinetic_mean()
            .map(|k| 2.0 / 3.0 * (k[0] + k[1] + k[2]))
    }

    /// The CSV header of [`RowStats::write_csv_row`].
    pub fn csv_header() -> String {
        let mut s = String::from("time,steps,running,failed,energy_error_mean,energy_error_max");
        for (_, name) in QUANTILES {
            s.push_str(",energy_error_");
            s.push_str(name);
        }
        s.push_str(
            ",casimir_error_mean,casimir_error_max,cos_mean,p2_mean,kinetic_1,kinetic_2,kinetic_3,temperature",
        );
        s
    }

    /// The row, floats in shortest round-trip form, an empty field where a value is undefined
    /// (no running body; no Casimir in a field).
    pub fn write_csv_row(&self, out: &mut String) {
        use std::fmt::Write as _;
        let opt = |out: &mut String, x: Option<f64>| {
            out.push(',');
            if let Some(x) = x {
                push_exp(out, x);
            }
        };
        push_exp(out, self.time);
        let _ = write!(out, ",{},{},{}", self.steps, self.running, self.failed);
        opt(out, self.energy_error_mean());
        opt(out, (self.running > 0).then_some(self.energy_max));
        for (q, _) in QUANTILES {
            opt(out, self.energy_error_quantile(q));
        }
        let (cm, cx) = match self.casimir_error() {
            Some((mean, max)) => (mean, (self.running > 0).then_some(max)),
            None => (None, None),
        };
        opt(out, cm);
        opt(out, cx);
        opt(out, self.cos_mean());
        opt(out, self.p2_mean());
        let k = self.kinetic_mean().map_or([None; 3], |k| k.map(Some));
        for k in k {
            opt(out, k);
        }
        opt(out, self.temperature());
    }
}
