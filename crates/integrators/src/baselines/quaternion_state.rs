//! The attitude a quaternion baseline carries from step to step: t on a compensated [`Clock`], the
//! unit quaternion q of R where it is reconstructed (renormalized after every step, the one
//! projection these baselines make), and R(q) built only when asked for — with the tail each step
//! ends with and the formulas both baselines step with.

use crate::clock::Clock;
use crate::system::force;
use crate::{IntegratorError, System};
use core::cell::OnceCell;
use lie_groups::{LieGroup, So3, Vector};
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

/// t, q and the cached R(q) of a quaternion baseline (see the module page).
#[derive(Debug, Clone)]
pub(crate) struct QuaternionState {
    /// tₖ.
    pub(crate) t: Clock,
    /// The unit quaternion of the attitude, where it is reconstructed.
    pub(crate) q: Option<Quaternion<f64>>,
    /// R(q), computed when [`Self::configuration`] asks for it (a cell, so that it can return a
    /// reference); emptied by every step.
    rotation: OnceCell<So3>,
}

impl QuaternionState {
    /// At t = 0 with R₀, kept exactly as given (not re-derived from q₀) until the first step.
    pub(crate) fn new(r0: Option<So3>) -> Self {
        Self {
            t: Clock::at(0.0),
            q: r0.map(|r| UnitQuaternion::from(r).into_inner()),
            rotation: r0.map_or_else(OnceCell::new, OnceCell::from),
        }
    }

    /// tₖ.
    #[inline(always)]
    pub(crate) fn now(&self) -> f64 {
        self.t.now()
    }

    /// Rₖ = R(qₖ), where reconstructed.
    pub(crate) fn configuration(&self) -> Option<&So3> {
        self.q
            .as_ref()
            .map(|q| self.rotation.get_or_init(|| rotation(q)))
    }

    /// qₖ as a unit quaternion, where reconstructed.
    pub(crate) fn quaternion(&self) -> Option<UnitQuaternion<f64>> {
        self.q.map(UnitQuaternion::new_unchecked)
    }

    /// |q₁| of a step's new (q₁, Π₁), refused where Π₁ or |q₁| is not finite or q₁ = 0 (1
    /// without the attitude). The state is not touched.
    #[inline(always)]
    pub(crate) fn check(
        q1: Option<&Quaternion<f64>>,
        pi1: &Vector3<f64>,
    ) -> Result<f64, IntegratorError> {
        let norm = q1.map_or(1.0, |q| q.norm());
        if Vector::is_finite(pi1) && norm.is_finite() && norm > 0.0 {
            Ok(norm)
        } else {
            Err(IntegratorError::NonFinite {
                what: "Runge–Kutta state (q, Π)_{k+1}",
            })
        }
    }

    /// The tail of an accepted step: q₁/|q₁| stored (`norm` from [`Self::check`]), R forgotten,
    /// t advanced by h on the clock, or set to exactly `t1` (an adaptive step's chosen end).
    #[inline(always)]
    pub(crate) fn commit(
        &mut self,
        q1: Option<Quaternion<f64>>,
        norm: f64,
        h: f64,
        t1: Option<f64>,
    ) {
        self.q = q1.map(|q| q / norm);
        self.rotation = OnceCell::new();
        match t1 {
            Some(t1) => self.t.set(t1),
            None => self.t.advance(h),
        }
    }
}

/// `½ q ⊗ (0, Ω)`: the quaternion velocity of `Ṙ = R Ω̂`.
#[inline]
pub(crate) fn quaternion_rate(q: &Quaternion<f64>, omega: &Vector3<f64>) -> Quaternion<f64> {
    (q * Quaternion::from_imag(*omega)) * 0.5
}

/// The rotation R(q/|q|) of a nonzero quaternion, from the homogeneous form
/// `R = (1/|q|²)·[(w² − |v|²)I + 2vvᵀ + 2w v̂]`, q = (w, v): no square root, one division.
///
/// The products of q's entries are formed before they are scaled by s = 2/|q|², so the division
/// runs beside them instead of ahead of them: in a stage of a system with a potential, R is on
/// the step's critical path (the force at the next stage waits for it).
#[inline]
pub(crate) fn rotation(q: &Quaternion<f64>) -> So3 {
    let (w, x, y, z) = (q.w, q.i, q.j, q.k);
    let s = 2.0 / (w * w + x * x + y * y + z * z);
    let (wx, wy, wz) = (w * x, w * y, w * z);
    let (xx, xy, xz) = (x * x, x * y, x * z);
    let (yy, yz, zz) = (y * y, y * z, z * z);
    So3::from_matrix_unchecked(&Matrix3::new(
        1.0 - (yy + zz) * s,
        (xy - wz) * s,
        (xz + wy) * s,
        (xy + wz) * s,
        1.0 - (xx + zz) * s,
        (yz - wx) * s,
        (xz - wy) * s,
        (yz + wx) * s,
        1.0 - (xx + yy) * s,
    ))
}

/// `Π̇ = ad*_Ω Π + F(R) + F_ext(t, R, Ω)` at a stage (q, Π) with Ω = ∂h/∂Π(Π) given; R = R(q)
/// is formed only where the system reads it.
#[inline(always)]
pub(crate) fn momentum_rate<S: System<So3>>(
    system: &S,
    t: f64,
    q: Option<&Quaternion<f64>>,
    pi: &Vector3<f64>,
    omega: &Vector3<f64>,
) -> Vector3<f64> {
    let mut dpi = So3::ad_dual_apply(omega, pi);
    if system.has_potential() || system.is_forced() {
        let r = q.filter(|_| system.needs_configuration()).map(rotation);
        if let Some(f) = force(system, r.as_ref()) {
            dpi += f;
        }
        if system.is_forced() {
            dpi += system.external_force(t, r.as_ref(), omega);
        }
    }
    dpi
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The homogeneous formula against nalgebra's normalise-then-convert, for unit and scaled q.
    #[test]
    fn rotation_of_a_scaled_quaternion_is_that_of_the_unit_one() {
        for (q, scale) in [
            (Quaternion::new(0.3, -0.5, 0.8, 0.1), 1.0),
            (Quaternion::new(-0.9, 0.1, 0.2, -0.4), 3.7),
            (Quaternion::new(1e-3, 1.0, -2.0, 0.5), 1e-5),
        ] {
            let want = So3::from(UnitQuaternion::from_quaternion(q));
            let got = rotation(&(q * scale));
            assert!((got.as_matrix() - want.as_matrix()).amax() < 4e-16);
        }
    }
}
