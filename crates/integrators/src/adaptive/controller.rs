//! The step-size controller of the adaptive methods: the PI controller of Gustafsson (with
//! Hairer's choice of exponents), of which the elementary controller is the case β = 0.
//!
//! After a step with scaled error `err` (accepted when `err ≤ 1`) the next step is `h·fac`,
//!
//! ```text
//! fac = safety · err^(−α) · err_prev^β,      α = 1/k − 0.75 β,
//! ```
//!
//! clamped to `[min_factor, max_factor]`, where k is the power of h the error estimate scales
//! with (5 for Dormand–Prince 5(4), 8 for DOP853) and `err_prev` the error of the last accepted
//! step (at least 1e-4). A rejected step is retried with `max(min_factor, safety · err^(−1/k))`
//! (no β, no growth), and the step after a rejection may not grow. (K. Gustafsson, "Control
//! theoretic techniques for stepsize selection in explicit Runge–Kutta methods", ACM TOMS 17
//! (1991); Hairer–Nørsett–Wanner, *Solving ODEs I*, §II.4 and §IV.2, and `dopri5.f`.)
//!
//! The controller holds the one number it remembers (ln `err_prev`) and nothing about the method,
//! so any method with an error estimate can use it. The factor is evaluated as
//! `safety · exp(β ln err_prev − α ln err)`: one logarithm and one exponential per step, where two
//! powers would cost about twice as much, which matters next to a step of a few hundred flops.

/// ln 1e-4: the floor of the remembered error, so that one nearly exact step does not let the
/// next grow by the largest factor (Hairer's `facold ≥ 1e-4`).
const LN_ERR_FLOOR: f64 = -9.210_340_371_976_184;

/// The outcome of one controlled attempt.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decision {
    /// Whether the step is accepted (`err ≤ 1`).
    pub accept: bool,
    /// The factor h_next / h.
    pub factor: f64,
}

/// A PI step-size controller (see the module page).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Controller {
    /// The safety factor (0.9 by default).
    pub safety: f64,
    /// The smallest factor a step may be changed by.
    pub min_factor: f64,
    /// The largest factor a step may be changed by.
    pub max_factor: f64,
    /// The exponent α of the current error.
    pub alpha: f64,
    /// The exponent β of the previous error (0: elementary control).
    pub beta: f64,
    /// The error exponent 1/k used on rejection.
    pub reject_exponent: f64,
    /// ln of the scaled error of the last accepted step (at least ln 1e-4).
    ln_err_prev: f64,
    /// Whether the last attempt was rejected.
    rejected: bool,
}

impl Controller {
    /// The PI controller for an error estimate O(h^k) with β (Hairer: 0.04 for order 5, 0 for
    /// DOP853; 0 gives the elementary controller), safety 0.9, factors in [0.2, 10].
    pub fn pi(k: u32, beta: f64) -> Self {
        let inv_k = 1.0 / f64::from(k.max(1));
        Self {
            safety: 0.9,
            min_factor: 0.2,
            max_factor: 10.0,
            alpha: inv_k - 0.75 * beta,
            beta,
            reject_exponent: inv_k,
            ln_err_prev: LN_ERR_FLOOR,
            rejected: false,
        }
    }
    /// The elementary controller `fac = safety · err^(−1/k)`.
    pub fn elementary(k: u32) -> Self {
        Self::pi(k, 0.0)
    }
    /// The same controller with the step changed by a factor in `[min_factor, max_factor]`.
    pub fn with_limits(self, min_factor: f64, max_factor: f64) -> Self {
        Self {
            min_factor,
            max_factor,
            ..self
        }
    }
    /// The same controller with another safety factor.
    pub fn with_safety(self, safety: f64) -> Self {
        Self { safety, ..self }
    }

    /// Decides on an attempt of scaled error `err` (a NaN or infinite error, from a step whose
    /// stages overflowed, is a rejection by the smallest factor) and remembers what it needs.
    #[inline]
    pub fn decide(&mut self, err: f64) -> Decision {
        if err.is_nan() || err > 1.0 {
            let factor = if err.is_finite() {
                (self.safety * (-self.reject_exponent * err.ln()).exp()).max(self.min_factor)
            } else {
                self.min_factor
            };
            self.rejected = true;
            return Decision {
                accept: false,
                factor: factor.min(1.0),
            };
        }
        let ln_err = err.ln();
        let mut factor = if err == 0.0 {
            self.max_factor
        } else {
            let fac = self.safety * (self.beta * self.ln_err_prev - self.alpha * ln_err).exp();
            fac.clamp(self.min_factor, self.max_factor)
        };
        if self.rejected {
            factor = factor.min(1.0);
        }
        self.ln_err_prev = ln_err.max(LN_ERR_FLOOR);
        self.rejected = false;
        Decision {
            accept: true,
            factor,
        }
    }
    /// Forgets the history (a restart, e.g. after an event that changes the system).
    pub fn reset(&mut self) {
        self.ln_err_prev = LN_ERR_FLOOR;
        self.rejected = false;
    }
}
