//! The exact flow of the free rigid body, Π(t) and R(t), with Jacobi elliptic functions.

use super::elliptic::{
    complete_k, complete_pi, incomplete_f, incomplete_f_and_pi, incomplete_pi, sn_cn_dn,
};
use crate::exact::AxisymmetricFlow;
use crate::systems::RigidBody;
use core::f64::consts::PI;
use integrators::splitting::KineticFlow;
use integrators::IntegratorError;
use lie_groups::{LieGroup, So3};
use nalgebra::{Matrix3, Vector3};

/// 2⁵²: the largest angle whose rounding is below one radian.
const PHASE_LIMIT: f64 = 4_503_599_627_370_496.0;

/// The exact flow of the free rigid body `Π̇ = Π × Ω`, `Ṙ = R Ω̂`, `Ω = 𝕀⁻¹Π`, for any t, at a
/// cost that does not grow with t.
///
/// **Π(t)** (Jacobi, 1849; Landau–Lifshitz, *Mechanics*, §37). In the principal frame, relabelled
/// by a proper signed permutation so that axis 3 is the one Π circulates about (the largest moment
/// when `D₂ = |Π|² − 2hI₂ ≥ 0`, the smallest otherwise) and Π₃ > 0:
///
/// ```text
/// Π₁ = A₁ cn u,  Π₂ = σ A₂ sn u,  Π₃ = A₃ dn u,  u = u₀ + λt,  σ = sign(I₃ − I₂),
/// A₁² = D₃I₁/(I₃−I₁), A₂² = D₃I₂/(I₃−I₂), A₃² = D₁I₃/(I₃−I₁), λ² = (I₃−I₂)D₁/(I₁I₂I₃),
/// k² = (I₂−I₁)D₃/((I₃−I₂)D₁),  k'² = (I₃−I₁)D₂/((I₃−I₂)D₁),
/// ```
///
/// with `Dᵢ = ±(|Π|² − 2hIᵢ)` each evaluated as a sum of same-sign terms (no cancellation; only
/// D₂, whose sign is the side of the separatrix, is as ill-conditioned as the problem).
///
/// **R(t)** (after Celledoni, Fassò, Säfström, Zanna, "The exact computation of the free rigid
/// body motion and its use in splitting methods", SIAM J. Sci. Comput. 30 (2008), and van Zon &
/// Schofield, J. Comput. Phys. 225 (2007)). The spatial momentum m = RΠ is constant. With B(n) the
/// minimal rotation taking e₃ to n = Π/|Π| (well conditioned: n₃ ≥ 0),
/// `R(t) = R(0) P B(n₀) exp(Δψ ê₃) B(n(t))ᵀ Pᵀ` (P the relabelling) for the angle
///
/// ```text
/// ψ̇ = |Π|/I₃ + (2h − |Π|²/I₃)/(|Π| + Π₃),
/// Δψ = |Π|t/I₃ + (I₃−I₁)/(I₁I₃λ) · [|Π| ΔΠ(−β; am u, k) − A₃ ΔG(am u)],
/// β = I₃(I₂−I₁)/(I₁(I₃−I₂)),  G(φ) = atan2(√(1+β) sin φ, cos φ)/√(1+β),
/// ```
///
/// Π(n; φ, k) the incomplete elliptic integral of the third kind (Carlson's R_J). The amplitude is
/// reduced by the period, `am(u + 2Kj) = am u + jπ`, and Π and G by their values over π, so the
/// cost is independent of t. Time is scaled by |Π| first (the flow is homogeneous), so |Π| from
/// 10⁻¹⁵⁰ to 10¹⁵⁰ costs no range. Bodies with two equal moments use the closed form of
/// [`AxisymmetricFlow`]; Π along a principal axis is a steady rotation; on the separatrix
/// (k = 1) am u = gd u.
///
/// ```
/// use mechanics::{exact::FreeBodyFlow, systems::RigidBody};
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let flow = FreeBodyFlow::new(&RigidBody::principal(1.0, 2.0, 3.0)?);
/// let pi0 = Vector3::new(0.4, 1.0, 0.3);
/// let (pi, r) = flow.advance(1e4, &pi0, Some(&So3::identity()))?;
/// let r = r.unwrap();
/// assert!((pi.norm() - pi0.norm()).abs() < 1e-13);            // the Casimir
/// assert!((r.as_matrix() * pi - pi0).amax() < 1e-9);          // the spatial momentum RΠ
/// # Ok::<(), integrators::IntegratorError>(())
/// ```
#[derive(Debug, Clone)]
pub struct FreeBodyFlow {
    axes: Matrix3<f64>,
    moments: Vector3<f64>,
    axisymmetric: Option<AxisymmetricFlow>,
}

/// B(n): the rotation about e₃ × n taking e₃ to the unit vector n (n₃ > −1).
fn minimal_rotation(n: &Vector3<f64>) -> Matrix3<f64> {
    let v = Vector3::new(-n.y, n.x, 0.0);
    let vh = v.cross_matrix();
    Matrix3::identity() + vh + vh * vh / (1.0 + n.z)
}

impl FreeBodyFlow {
    /// The flow of `body` (its principal frame is computed once, at the body's construction).
    pub fn new(body: &RigidBody) -> Self {
        let (axes, moments) = body.principal_frame();
        Self {
            axes: *axes,
            moments: *moments,
            axisymmetric: AxisymmetricFlow::new(body).ok(),
        }
    }

    /// (Π(t), R(t)) from (Π, R) at time 0; `r = None` advances Π alone (cheaper).
    ///
    /// Errors: non-finite t or Π, or a phase t|Π|/I_min beyond 2⁵² rad (no digit of the phase
    /// would survive); never a panic.
    pub fn advance(
        &self,
        t: f64,
        pi: &Vector3<f64>,
        r: Option<&So3>,
    ) -> Result<(Vector3<f64>, Option<So3>), IntegratorError> {
        if !t.is_finite() {
            return Err(IntegratorError::NonFinite { what: "time t" });
        }
        if !pi.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "momentum Π"
            });
        }
        // The fastest angle the flow turns, t|Π|/I_min, must keep its phase: beyond 2⁵² rad the
        // rounding of one period exceeds the period itself and the result would be noise.
        let m = pi.norm();
        let phase = t.abs() * (m / self.moments.min());
        if phase.is_nan() || phase >= PHASE_LIMIT {
            return Err(IntegratorError::NonFinite {
                what: "phase |Π|t/I of the exact flow (beyond 2⁵² rad, no digit of the phase left)",
            });
        }
        if let Some(flow) = &self.axisymmetric {
            let (mut p, mut g) = (*pi, r.copied());
            flow.kinetic_flow(t, &mut p, g.as_mut())?;
            return Ok((p, g));
        }
        if m == 0.0 {
            return Ok((*pi, r.copied()));
        }
        let tau = t * m;
        let p = self.axes.tr_mul(pi) / m;
        let i = self.moments;
        // Sort the axes by moment; D₂ = |Π|² − 2hI_mid (|Π| = 1) decides the circulation axis.
        let (mut lo, mut mid, mut hi) = (0usize, 1usize, 2usize);
        if i[lo] > i[mid] {
            (lo, mid) = (mid, lo);
        }
        if i[mid] > i[hi] {
            (mid, hi) = (hi, mid);
        }
        if i[lo] > i[mid] {
            (lo, mid) = (mid, lo);
        }
        let d2 =
            p[lo] * p[lo] * (i[lo] - i[mid]) / i[lo] + p[hi] * p[hi] * (i[hi] - i[mid]) / i[hi];
        let (c1, c3) = if d2 >= 0.0 { (lo, hi) } else { (hi, lo) };
        let c2 = mid;
        // The proper signed permutation to the canonical frame: rows s₁e_{c1}, s₂e_{c2}, s₃e_{c3}.
        let s3 = if p[c3] < 0.0 { -1.0 } else { 1.0 };
        let s1 = if d2 == 0.0 && p[c1] < 0.0 { -1.0 } else { 1.0 };
        let mut perm = Matrix3::zeros();
        perm[(0, c1)] = 1.0;
        perm[(1, c2)] = 1.0;
        perm[(2, c3)] = 1.0;
        let s2 = perm.determinant() * s1 * s3;
        let q_rows = Matrix3::from_diagonal(&Vector3::new(s1, s2, s3)) * perm;
        // P: canonical → body.
        let pmat = self.axes * q_rows.transpose();
        let q = q_rows * p;
        let (i1, i2, i3) = (i[c1], i[c2], i[c3]);
        let zeros = q.iter().filter(|&&x| x == 0.0).count();
        if zeros >= 2 {
            // Π along a principal axis: a steady rotation.
            let omega = self.axes * Vector3::from_iterator((0..3).map(|j| p[j] / i[j])) * m;
            let g = r.map(|r| r.compose(&So3::exp(&(omega * t))).normalize());
            return Ok((*pi, g));
        }
        let d3 = q[0] * q[0] * (i3 - i1) / i1 + q[1] * q[1] * (i3 - i2) / i2;
        let d1 = q[1] * q[1] * (i2 - i1) / i2 + q[2] * q[2] * (i3 - i1) / i3;
        let d2 = q[0] * q[0] * (i1 - i2) / i1 + q[2] * q[2] * (i3 - i2) / i3;
        // k'² (all the elliptic functions need): from D₂ when it is the smaller of k², k'² (full
        // relative accuracy near the separatrix), else as 1 − k².
        let kc2 = ((i3 - i1) * d2 / ((i3 - i2) * d1)).max(0.0);
        let k2 = ((i2 - i1) * d3 / ((i3 - i2) * d1)).max(0.0);
        let kc2 = if kc2 < k2 { kc2 } else { 1.0 - k2 };
        let a1 = (d3 * i1 / (i3 - i1)).sqrt();
        let a2 = (d3 * i2 / (i3 - i2)).sqrt();
        let a3 = (d1 * i3 / (i3 - i1)).sqrt();
        let lambda = ((i3 - i2) * d1 / (i1 * i2 * i3)).sqrt();
        let sigma = (i3 - i2).signum();
        let kk = complete_k(kc2);
        let beta = i3 * (i2 - i1) / (i1 * (i3 - i2));
        // φ₀ = am u₀ from (sn u₀, cn u₀) = (σq₂/A₂, q₁/A₁), reduced to |φ₀| ≤ π/2 (cn ≥ 0) by
        // am(u + 2Kj) = am u + jπ, under which sn and cn change sign.
        let (sr, cr) = (sigma * q[1] / a2, q[0] / a1);
        let norm = sr.hypot(cr);
        let (mut s0, mut c0) = (sr / norm, cr / norm);
        let j0: f64 = if c0 >= 0.0 {
            0.0
        } else if s0 >= 0.0 {
            1.0
        } else {
            -1.0
        };
        if j0 != 0.0 {
            (s0, c0) = (-s0, -c0);
        }
        // Δ²(φ₀) = dn² u₀ = cos²φ₀ + k'² sin²φ₀ (from k'², see `incomplete_f`); Π(−β; φ₀) only
        // when R is advanced.
        let delta0 = c0 * c0 + kc2 * s0 * s0;
        let (f0, pi0) = if r.is_some() {
            incomplete_f_and_pi(-beta, s0, c0, delta0)
        } else {
            (incomplete_f(s0, c0, delta0), 0.0)
        };
        let u0 = if j0 == 0.0 { 0.0 } else { 2.0 * kk * j0 } + f0;
        let u = u0 + lambda * tau;
        let j = if kk.is_finite() {
            (u / (2.0 * kk)).round()
        } else {
            0.0
        };
        let ur = if j == 0.0 { u } else { u - 2.0 * kk * j };
        let parity = if j % 2.0 == 0.0 { 1.0 } else { -1.0 };
        let (sn, cn, _) = sn_cn_dn(ur, kc2);
        // dn² = cn² + k'² sn², consistent with (sn, cn): |q(t)| = 1 to rounding, unbiased.
        let dn = (cn * cn + kc2 * sn * sn).sqrt();
        let qt = Vector3::new(a1 * cn * parity, sigma * a2 * sn * parity, a3 * dn);
        let pi_t = pmat * qt * m;
        if !pi_t.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "momentum Π(t) of the exact flow",
            });
        }
        let Some(r) = r else {
            return Ok((pi_t, None));
        };
        // Δψ from the third-kind integral, each term reduced by its value over π.
        let sb = (1.0 + beta).sqrt();
        let g_of = |s: f64, c: f64| (sb * s).atan2(c) / sb;
        let dj = j - j0;
        let whole_pi = if dj == 0.0 {
            0.0
        } else {
            2.0 * dj * complete_pi(-beta, kc2)
        };
        let d_pi = whole_pi + incomplete_pi(-beta, sn, cn, cn * cn + kc2 * sn * sn) - pi0;
        let d_g = dj * PI / sb + g_of(sn, cn) - g_of(s0, c0);
        let dpsi = tau / i3 + (i3 - i1) / (i1 * i3 * lambda) * (d_pi - a3 * d_g);
        let b0 = minimal_rotation(&q);
        let bt = minimal_rotation(&qt);
        let rz = So3::exp(&Vector3::new(0.0, 0.0, dpsi));
        let rt = r.as_matrix() * pmat * b0 * rz.as_matrix() * bt.transpose() * pmat.transpose();
        let g = So3::from_matrix_unchecked(&rt).normalize();
        if !g.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "attitude R(t) of the exact flow",
            });
        }
        Ok((pi_t, Some(g)))
    }
}

impl KineticFlow<So3> for FreeBodyFlow {
    fn kinetic_flow(
        &self,
        t: f64,
        mu: &mut Vector3<f64>,
        g: Option<&mut So3>,
    ) -> Result<(), IntegratorError> {
        let (pi, r) = self.advance(t, mu, g.as_deref())?;
        *mu = pi;
        if let (Some(g), Some(r)) = (g, r) {
            *g = r;
        }
        Ok(())
    }
}
