//! [`Schedule`]: a piecewise-linear function of time with values in ℝⁿ.

use crate::IntegratorError;

/// A piecewise-linear schedule `u(t)`: `values[i]` at `times[i]`, linear in between, constant
/// before the first and after the last time (a single entry is a constant).
///
/// Each knot is a kink, and a method of order p > 2 keeps its order across a kink only where its
/// steps end on the knot and it samples the force inside the step. Compositions with a large
/// negative stage reach outside the step (the triple jump's stages end at t + 1.35h and
/// t − 0.35h), and the splittings' kicks sample the force there: on the far side of a knot, at an
/// O(h²) cost per knot (the triple jump of the forced Strang splitting measured order 2.00 where it
/// is 4 on a smooth input; docs/work-precision.md, quadrotor). The constant extension before the
/// first time is a kink too when the first segment has a slope: to start a run on a ramp, put a
/// knot before the start continuing it.
///
/// Built only from finite, strictly increasing times and finite values of one length; otherwise
/// an [`IntegratorError::InvalidParameter`] naming the offending entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Schedule {
    times: Vec<f64>,
    values: Vec<Vec<f64>>,
}

impl Schedule {
    /// The schedule through `(times[i], values[i])`.
    pub fn new(times: Vec<f64>, values: Vec<Vec<f64>>) -> Result<Self, IntegratorError> {
        let bad = |reason: String| Err(IntegratorError::InvalidParameter { reason });
        if times.is_empty() || times.len() != values.len() {
            return bad(format!(
                "a schedule needs as many values as times, at least one (got {} times, {} values)",
                times.len(),
                values.len()
            ));
        }
        if let Some(i) = times.iter().position(|t| !t.is_finite()) {
            return bad(format!("times[{i}] = {} is not finite", times[i]));
        }
        if let Some(i) = (1..times.len()).find(|&i| times[i] <= times[i - 1]) {
            return bad(format!(
                "times must increase strictly: times[{}] = {} after times[{}] = {}",
                i,
                times[i],
                i - 1,
                times[i - 1]
            ));
        }
        let n = values[0].len();
        for (i, v) in values.iter().enumerate() {
            if v.len() != n {
                return bad(format!(
                    "values[{i}] has {} entries, values[0] has {n}",
                    v.len()
                ));
            }
            if let Some(j) = v.iter().position(|x| !x.is_finite()) {
                return bad(format!("values[{i}][{j}] = {} is not finite", v[j]));
            }
        }
        Ok(Self { times, values })
    }
    /// The constant schedule u(t) = value.
    pub fn constant(value: Vec<f64>) -> Result<Self, IntegratorError> {
        Self::new(vec![0.0], vec![value])
    }
    /// The dimension of the values.
    pub fn dim(&self) -> usize {
        self.values[0].len()
    }
    /// The knot times (strictly increasing; one for a constant).
    pub fn times(&self) -> &[f64] {
        &self.times
    }
    /// The number of knots (1 for a constant).
    pub fn knots(&self) -> usize {
        self.times.len()
    }
    /// The largest Euclidean norm |u| of the values, which bounds |u(t)| for every t (the
    /// interpolation is convex).
    pub fn max_abs(&self) -> f64 {
        self.values
            .iter()
            .map(|v| v.iter().map(|x| x * x).sum::<f64>().sqrt())
            .fold(0.0, f64::max)
    }
    /// `f(u(t))`, with u(t) evaluated into a stack buffer when [`Self::dim`] ≤
    /// [`Self::STACK_DIM`] (no allocation; a heap buffer beyond).
    #[inline]
    pub fn eval_with<R>(&self, t: f64, f: impl FnOnce(&[f64]) -> R) -> R {
        // Before the first knot, from the last on, or a constant: a stored value, as it is (what
        // `eval_into` copies there).
        let last = self.times.len() - 1;
        if t < self.times[0] {
            return f(&self.values[0]);
        }
        if t >= self.times[last] {
            return f(&self.values[last]);
        }
        let n = self.dim();
        let mut buf = [0.0; Self::STACK_DIM];
        if n <= buf.len() {
            self.eval_into(t, &mut buf[..n]);
            f(&buf[..n])
        } else {
            let mut v = vec![0.0; n];
            self.eval_into(t, &mut v);
            f(&v)
        }
    }
    /// Schedules of at most this many components evaluate without allocating
    /// ([`Self::eval_with`]).
    pub const STACK_DIM: usize = 16;
    /// `u(t)` into `out` (length [`Self::dim`]); no allocation.
    pub fn eval_into(&self, t: f64, out: &mut [f64]) {
        let n = self.times.len();
        let i = self.times.partition_point(|&ti| ti <= t);
        if i == 0 || n == 1 {
            out.copy_from_slice(&self.values[0]);
        } else if i == n {
            out.copy_from_slice(&self.values[n - 1]);
        } else {
            let (t0, t1) = (self.times[i - 1], self.times[i]);
            let s = (t - t0) / (t1 - t0);
            for (k, o) in out.iter_mut().enumerate() {
                let (a, b) = (self.values[i - 1][k], self.values[i][k]);
                *o = a + s * (b - a);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_linearly_and_holds_the_ends() {
        let s = Schedule::new(vec![1.0, 3.0], vec![vec![0.0, 2.0], vec![4.0, -2.0]]).unwrap();
        let mut out = [0.0; 2];
        for (t, want) in [
            (0.0, [0.0, 2.0]),
            (2.0, [2.0, 0.0]),
            (2.5, [3.0, -1.0]),
            (9.0, [4.0, -2.0]),
        ] {
            s.eval_into(t, &mut out);
            assert_eq!(out, want, "t = {t}");
        }
    }

    /// `eval_with` returns the stored values where it skips the buffer (before the first knot,
    /// from the last on, a constant) and equals `eval_into` bitwise everywhere, -0.0 included.
    #[test]
    fn eval_with_equals_eval_into_bitwise() {
        let ramp = Schedule::new(
            vec![-1.0, 0.5, 2.0],
            vec![vec![-0.0, 1.0], vec![3.0, -2.0], vec![0.25, 7.0]],
        )
        .unwrap();
        let constant = Schedule::constant(vec![-0.0, 4.0]).unwrap();
        for s in [&ramp, &constant] {
            for t in [-5.0, -1.0, -0.3, 0.5, 1.7, 2.0, 9.0, f64::NAN] {
                let mut want = [0.0; 2];
                s.eval_into(t, &mut want);
                let got = s.eval_with(t, |u| [u[0], u[1]]);
                assert_eq!(
                    got.map(f64::to_bits),
                    want.map(f64::to_bits),
                    "t = {t}: {got:?} against {want:?}"
                );
            }
        }
    }

    #[test]
    fn malformed_schedules_are_refused_naming_the_entry() {
        let msg = |r: Result<Schedule, IntegratorError>| r.unwrap_err().to_string();
        assert!(msg(Schedule::new(vec![0.0, 1.0], vec![vec![1.0]])).contains("as many values"));
        assert!(
            msg(Schedule::new(vec![0.0, 0.0], vec![vec![1.0], vec![2.0]])).contains("times[1]")
        );
        assert!(msg(Schedule::new(
            vec![0.0, f64::NAN],
            vec![vec![1.0], vec![2.0]]
        ))
        .contains("times[1]"));
        assert!(msg(Schedule::new(
            vec![0.0, 1.0],
            vec![vec![1.0], vec![2.0, 3.0]]
        ))
        .contains("values[1]"));
        assert!(msg(Schedule::new(vec![0.0], vec![vec![f64::INFINITY]])).contains("values[0][0]"));
        assert!(Schedule::new(vec![], vec![]).is_err());
    }

    #[test]
    fn max_abs_is_the_largest_value_norm() {
        let s = Schedule::new(vec![0.0, 1.0], vec![vec![3.0, 4.0], vec![0.0, -1.0]]).unwrap();
        assert_eq!(s.max_abs(), 5.0);
    }
}
