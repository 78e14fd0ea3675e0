//! The integrators' clock: the time tₖ = t₀ + Σᵢ hᵢ carried as a compensated sum, so that a run of
//! n steps of size h ends at the correctly rounded t₀ + n·fl(h), not n roundings away from it.
//!
//! With plain addition the time after n steps is off by up to n/2 ulps of t (after 2000 steps
//! of 0.05 it is 99.99999999999646, not 100): a run then misses an output requested at its end
//! time, and an event or a force schedule sees the wrong t. The clock keeps the rounding error
//! of each addition in a second word (Knuth's TwoSum, then a renormalization — a double-double
//! accumulator), which costs a few additions per step.

/// The time of an integrator: `now()` is the correctly rounded value (to within an ulp) of
/// t₀ + Σᵢ hᵢ over the steps taken since it was set.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Clock {
    /// The rounded time.
    t: f64,
    /// The part of the exact sum below t's last bit, |carry| ≤ ulp(t)/2.
    carry: f64,
}

impl Clock {
    /// The clock at t (no carried error).
    #[inline]
    pub const fn at(t: f64) -> Self {
        Self { t, carry: 0.0 }
    }

    /// The time now.
    #[inline]
    pub const fn now(&self) -> f64 {
        self.t
    }

    /// Adds h: the new time is the rounding of the exact t + carry + h.
    #[inline]
    pub fn advance(&mut self, h: f64) {
        // TwoSum (Knuth): s + e = t + h exactly.
        let s = self.t + h;
        let b = s - self.t;
        let e = (self.t - (s - b)) + (h - b);
        // Fold the carried error in and renormalize (Fast2Sum: |s| ≥ |lo| here).
        let lo = self.carry + e;
        let t = s + lo;
        self.carry = lo - (t - s);
        self.t = t;
    }

    /// This clock advanced by h.
    #[inline]
    pub fn advanced(mut self, h: f64) -> Self {
        self.advance(h);
        self
    }

    /// Sets the time to t; a no-op when t is the time now (the carried error is kept, so that a
    /// method that steps away and sets its time back, as processing does, stays exact).
    #[inline]
    pub fn set(&mut self, t: f64) {
        if t != self.t {
            *self = Self::at(t);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Clock;

    #[test]
    fn n_steps_of_h_end_at_the_rounded_product() {
        for (h, n, end) in [
            (0.05, 2000usize, 100.0),
            (0.01, 1000, 10.0),
            (0.1, 1_000_000, 100_000.0),
            (-0.1, 30, -3.0),
        ] {
            let mut c = Clock::at(0.0);
            let mut naive = 0.0;
            for _ in 0..n {
                c.advance(h);
                naive += h;
            }
            assert_eq!(c.now(), end, "h = {h}, n = {n}");
            // the negative control: plain addition misses (except where it happens to land)
            if n >= 1000 {
                assert_ne!(naive, end, "h = {h}, n = {n}");
            }
        }
    }

    #[test]
    fn setting_the_time_now_keeps_the_carry_and_another_time_clears_it() {
        let mut c = Clock::at(0.0);
        for _ in 0..3 {
            c.advance(0.1);
        }
        let kept = c;
        c.set(c.now());
        assert_eq!(c, kept);
        c.set(1.0);
        assert_eq!(c, Clock::at(1.0));
    }
}
