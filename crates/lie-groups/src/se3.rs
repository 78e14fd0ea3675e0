//! SE(3), rigid motions of ℝ³: g = (R, t) acting by p ↦ R p + t, as the 4×4 matrix
//! `[[R, t], [0, 1]]`.
//!
//! **Algebra ordering: ξ = (ω, v) ∈ ℝ⁶, rotation first.** `ξ̂ = [[ω̂, v], [0, 0]]`; ω is the
//! angular velocity and v the linear velocity, both in the body frame (for a left-trivialized
//! velocity ġ = g ξ̂). With this ordering every operator is block lower-triangular:
//! `Ad_g = [[R, 0], [t̂ R, R]]`, `ad_ξ = [[ω̂, 0], [v̂, ω̂]]`.
//! (Barfoot and manif order (v, ω); their blocks appear here transposed across the diagonal.)

use crate::so3::{
    adjoint_increment, dexp_inv_coeff, rodrigues_apply, rodrigues_coeffs, rodrigues_matrix, sinc3,
    skew,
};
use crate::{Action, CayleyGroup, LieError, LieGroup, So3};
use nalgebra::{Matrix3, Matrix4, Matrix6, Vector3, Vector6};

pub use crate::so3::ORTHOGONALITY_TOLERANCE;

/// θ² below which the coupling block Q uses its series (θ < 0.5).
const Q_SERIES_ANGLE_SQ: f64 = 0.25;

/// An element (R, t) of SE(3), stored as an [`So3`] and a translation `Vector3` (on the stack).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Se3 {
    rot: So3,
    t: Vector3<f64>,
}

#[inline]
fn head(xi: &Vector6<f64>) -> Vector3<f64> {
    xi.fixed_rows::<3>(0).into_owned()
}

#[inline]
fn tail(xi: &Vector6<f64>) -> Vector3<f64> {
    xi.fixed_rows::<3>(3).into_owned()
}

#[inline]
fn join(w: &Vector3<f64>, v: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(w.x, w.y, w.z, v.x, v.y, v.z)
}

/// `(Ad_{(R, t)} − I)(ω, v) = ((R − I)ω, (R − I)v + t × (ω + (R − I)ω))` for `R − I = a φ̂ + b φ̂²`
/// (from `Ad_g (ω, v) = (R ω, R v + t × R ω)`): every term O(|φ| + |t|) times |ξ|, computed
/// without forming R.
#[inline]
fn adjoint_increment_of(
    phi: &Vector3<f64>,
    a: f64,
    b: f64,
    t: &Vector3<f64>,
    xi: &Vector6<f64>,
) -> Vector6<f64> {
    let w = head(xi);
    let dw = adjoint_increment(phi, &w, a, b);
    let dv = adjoint_increment(phi, &tail(xi), a, b);
    join(&dw, &(dv + t.cross(&(w + dw))))
}

/// The 6×6 matrix `[[a, b], [c, d]]` of 3×3 blocks.
#[inline]
fn blocks(a: &Matrix3<f64>, b: &Matrix3<f64>, c: &Matrix3<f64>, d: &Matrix3<f64>) -> Matrix6<f64> {
    let mut m = Matrix6::zeros();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(a);
    m.fixed_view_mut::<3, 3>(0, 3).copy_from(b);
    m.fixed_view_mut::<3, 3>(3, 0).copy_from(c);
    m.fixed_view_mut::<3, 3>(3, 3).copy_from(d);
    m
}

/// Barfoot's coupling block `Q(ρ, φ)` of the SE(3) left Jacobian (State Estimation for Robotics,
/// eq. 7.86), with θ = |φ|:
///
/// `Q = ½ρ̂ + c₁ (φ̂ρ̂ + ρ̂φ̂ + φ̂ρ̂φ̂) + c₂ (φ̂²ρ̂ + ρ̂φ̂² − 3φ̂ρ̂φ̂) + c₃ (φ̂ρ̂φ̂² + φ̂²ρ̂φ̂)`,
/// `c₁ = (θ − sin θ)/θ³`, `c₂ = (θ² + 2 cos θ − 2)/(2θ⁴)`, `c₃ = (2θ − 3 sin θ + θ cos θ)/(2θ⁵)`.
///
/// It is the off-diagonal block of `Σ_k ad_ξ^k/(k+1)!`; in the (ω, v) ordering it sits bottom-left.
fn barfoot_q(rho: &Vector3<f64>, phi: &Vector3<f64>) -> Matrix3<f64> {
    let t2 = phi.norm_squared();
    let (c2, c3) = if t2 < Q_SERIES_ANGLE_SQ {
        // c₂ = Σ_j (−1)^j θ^{2j}/(2j + 4)! = 1/24 − θ²/720 + θ⁴/40320 − …
        // c₃ = 1/120 − θ²/2520 + θ⁴/120960 − θ⁶/9979200 + θ⁸/1245404160 − …
        // The closed forms lose ~eps/θ absolutely to cancellation, so the series is used up to
        // θ = 0.5, through θ¹²: the first dropped term is < 1e-17 relative to the leading one.
        const C2: [f64; 7] = [
            1.0 / 24.0,
            -1.0 / 720.0,
            1.0 / 40320.0,
            -1.0 / 3628800.0,
            1.0 / 479001600.0,
            -1.0 / 87178291200.0,
            1.0 / 20922789888000.0,
        ];
        const C3: [f64; 7] = [
            1.0 / 120.0,
            -1.0 / 2520.0,
            1.0 / 120960.0,
            -1.0 / 9979200.0,
            1.0 / 1245404160.0,
            -1.0 / 217945728000.0,
            1.0 / 50812489728000.0,
        ];
        let horner = |c: &[f64; 7]| c.iter().rev().fold(0.0, |acc, &k| acc * t2 + k);
        (horner(&C2), horner(&C3))
    } else {
        let t = t2.sqrt();
        let (s, c) = t.sin_cos();
        // 2 cos θ − 2 = −4 sin²(θ/2) without the cancellation of 2 cos θ against 2 (which would
        // cost eps/θ² absolutely in the c₂ term).
        let sh = (0.5 * t).sin();
        (
            (t2 - 4.0 * sh * sh) / (2.0 * t2 * t2),
            (2.0 * t - 3.0 * s + t * c) / (2.0 * t2 * t2 * t),
        )
    };
    let c1 = sinc3(t2);
    let p = skew(phi);
    let r = skew(rho);
    let pr = p * r;
    let rp = r * p;
    let prp = pr * p;
    let pp = p * p;
    r * 0.5 + (pr + rp + prp) * c1 + (pp * r + rp * p - prp * 3.0) * c2 + (prp * p + pp * rp) * c3
}

impl Se3 {
    /// `(R, t)` from its parts.
    #[inline]
    pub fn from_parts(rotation: So3, translation: Vector3<f64>) -> Self {
        Self {
            rot: rotation,
            t: translation,
        }
    }
    /// A pure translation `(I, t)`.
    #[inline]
    pub fn from_translation(translation: Vector3<f64>) -> Self {
        Self::from_parts(So3::identity(), translation)
    }
    /// A pure rotation `(R, 0)`.
    #[inline]
    pub fn from_rotation(rotation: So3) -> Self {
        Self::from_parts(rotation, Vector3::zeros())
    }
    /// The rotation part R.
    #[inline]
    pub fn rotation(&self) -> &So3 {
        &self.rot
    }
    /// The translation part t.
    #[inline]
    pub fn translation(&self) -> &Vector3<f64> {
        &self.t
    }

    /// Checked constructor with an explicit tolerance: refuses non-finite entries, a bottom row
    /// that differs from `[0 0 0 1]` by more than `tolerance` ([`LieError::NotHomogeneous`]) and a
    /// top-left block that [`So3::from_matrix_with_tolerance`] refuses.
    pub fn from_matrix_with_tolerance(m: &Matrix4<f64>, tolerance: f64) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "homogeneous matrix",
            });
        }
        Self::check_bottom_row(m, tolerance)?;
        let rot =
            So3::from_matrix_with_tolerance(&m.fixed_view::<3, 3>(0, 0).into_owned(), tolerance)?;
        Ok(Self::from_parts(
            rot,
            m.fixed_view::<3, 1>(0, 3).into_owned(),
        ))
    }

    /// Projects a drifted homogeneous matrix onto SE(3): the rotation block is replaced by its
    /// nearest rotation ([`So3::project`]), the translation column is kept. The bottom row must
    /// still be `[0 0 0 1]` within [`ORTHOGONALITY_TOLERANCE`] (a projective matrix is refused
    /// rather than silently reinterpreted).
    pub fn project(m: &Matrix4<f64>) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "matrix to project",
            });
        }
        Self::check_bottom_row(m, ORTHOGONALITY_TOLERANCE)?;
        let rot = So3::project(&m.fixed_view::<3, 3>(0, 0).into_owned())?;
        Ok(Self::from_parts(
            rot,
            m.fixed_view::<3, 1>(0, 3).into_owned(),
        ))
    }

    /// The same element with its rotation re-projected onto SO(3) ([`So3::renormalize`]).
    pub fn renormalize(&self) -> Self {
        Self::from_parts(self.rot.renormalize(), self.t)
    }

    fn check_bottom_row(m: &Matrix4<f64>, tolerance: f64) -> Result<(), LieError> {
        let error = m[(3, 0)]
            .abs()
            .max(m[(3, 1)].abs())
            .max(m[(3, 2)].abs())
            .max((m[(3, 3)] - 1.0).abs());
        if error > tolerance {
            return Err(LieError::NotHomogeneous { error });
        }
        Ok(())
    }
}

impl LieGroup for Se3 {
    /// The principal log inverts exp for |ω| < π (any translation); 3 keeps clear of the cut at π.
    const EXP_INVERTIBLE_RADIUS: f64 = 3.0;
    /// Normalizes the rotation part (see [`So3`]'s `normalize`); the translation cannot drift off.
    #[inline]
    fn normalize(&self) -> Self {
        Self {
            rot: self.rot.normalize(),
            t: self.t,
        }
    }
    /// ξ = (ω, v): rotation first.
    type Algebra = Vector6<f64>;
    type Operator = Matrix6<f64>;
    type Matrix = Matrix4<f64>;

    fn name() -> String {
        "SE(3)".into()
    }
    #[inline]
    fn dim() -> usize {
        6
    }
    #[inline]
    fn identity() -> Self {
        Self::from_parts(So3::identity(), Vector3::zeros())
    }
    /// `(R₁, t₁)(R₂, t₂) = (R₁R₂, R₁t₂ + t₁)`.
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        Self::from_parts(
            self.rot.compose(&other.rot),
            self.rot.as_matrix() * other.t + self.t,
        )
    }
    /// `(R, t)⁻¹ = (Rᵀ, −Rᵀ t)`.
    #[inline]
    fn inverse(&self) -> Self {
        Self::from_parts(self.rot.inverse(), -self.rot.as_matrix().tr_mul(&self.t))
    }
    /// `exp(ω, v) = (exp ω, V(ω) v)` with V the left Jacobian of SO(3),
    /// `V(ω) = I + ((1 − cos θ)/θ²) ω̂ + ((θ − sin θ)/θ³) ω̂²` (Taylor branches below θ = 0.1).
    ///
    /// The three coefficients share one `sin_cos(θ)`, and `V v` is applied as
    /// `v + c₁ ω × v + c₂ ω × (ω × v)` without forming V.
    #[inline]
    fn exp(xi: &Vector6<f64>) -> Self {
        let w = head(xi);
        let (a, b, c) = rodrigues_coeffs(w.norm_squared());
        Self::from_parts(
            So3::from_matrix_unchecked(&rodrigues_matrix(&w, a, b)),
            rodrigues_apply(&w, b, c, &tail(xi)),
        )
    }
    /// `(Ad_{exp(φ, ρ)} − I) ξ` with `exp(φ, ρ) = (I + a φ̂ + b φ̂², V(φ) ρ)`, a = sin θ/θ,
    /// b = (1 − cos θ)/θ², `V(φ) ρ = ρ + b φ × ρ + c φ × (φ × ρ)`, c = (θ − sin θ)/θ³ (the
    /// coefficients of [`LieGroup::exp`]), from the closed form of `Ad_g`.
    #[inline]
    fn exp_adjoint_increment(z: &Vector6<f64>, xi: &Vector6<f64>) -> Vector6<f64> {
        let phi = head(z);
        let (a, b, c) = rodrigues_coeffs(phi.norm_squared());
        adjoint_increment_of(&phi, a, b, &rodrigues_apply(&phi, b, c, &tail(z)), xi)
    }
    /// `log(R, t) = (ω, V(ω)⁻¹ t)` with ω = log R (principal, |ω| ≤ π; see [`So3`]'s `log`) and
    /// `V(ω)⁻¹ = I − ω̂/2 + (1/θ² − (1 + cos θ)/(2θ sin θ)) ω̂²`, applied with cross products.
    #[inline]
    fn log(&self) -> Result<Vector6<f64>, LieError> {
        if !self.t.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "translation",
            });
        }
        let w = self.rot.log()?;
        let coeff = dexp_inv_coeff(w.norm_squared());
        Ok(join(&w, &rodrigues_apply(&w, -0.5, coeff, &self.t)))
    }
    /// `ξ̂ = [[ω̂, v], [0, 0]]`.
    #[inline]
    fn hat(xi: &Vector6<f64>) -> Matrix4<f64> {
        let mut m = Matrix4::zeros();
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&skew(&head(xi)));
        m.fixed_view_mut::<3, 1>(0, 3).copy_from(&tail(xi));
        m
    }
    /// Reads ω from the skew part of the top-left block and v from the last column.
    #[inline]
    fn vee(m: &Matrix4<f64>) -> Vector6<f64> {
        let w = So3::vee(&m.fixed_view::<3, 3>(0, 0).into_owned());
        join(&w, &m.fixed_view::<3, 1>(0, 3).into_owned())
    }
    /// `[[R, t], [0, 1]]`.
    #[inline]
    fn matrix(&self) -> Matrix4<f64> {
        let mut m = Matrix4::identity();
        m.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(self.rot.as_matrix());
        m.fixed_view_mut::<3, 1>(0, 3).copy_from(&self.t);
        m
    }
    /// Checked with [`ORTHOGONALITY_TOLERANCE`], see [`Se3::from_matrix_with_tolerance`].
    fn from_matrix(m: &Matrix4<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, ORTHOGONALITY_TOLERANCE)
    }
    #[inline]
    fn from_matrix_unchecked(m: &Matrix4<f64>) -> Self {
        Self::from_parts(
            So3::from_matrix_unchecked(&m.fixed_view::<3, 3>(0, 0).into_owned()),
            m.fixed_view::<3, 1>(0, 3).into_owned(),
        )
    }
    /// `Ad_g = [[R, 0], [t̂ R, R]]` in the (ω, v) ordering.
    #[inline]
    fn adjoint(&self) -> Matrix6<f64> {
        let r = self.rot.as_matrix();
        blocks(r, &Matrix3::zeros(), &(skew(&self.t) * r), r)
    }
    /// `ad_ξ = [[ω̂, 0], [v̂, ω̂]]`.
    #[inline]
    fn ad(xi: &Vector6<f64>) -> Matrix6<f64> {
        let k = skew(&head(xi));
        blocks(&k, &Matrix3::zeros(), &skew(&tail(xi)), &k)
    }
    /// `Ad_g (ω, v) = (R ω, R v + t × R ω)`.
    #[inline]
    fn adjoint_apply(&self, xi: &Vector6<f64>) -> Vector6<f64> {
        let r = self.rot.as_matrix();
        let rw = r * head(xi);
        join(&rw, &(r * tail(xi) + self.t.cross(&rw)))
    }
    /// `Ad_{g⁻¹} (ω, v) = (Rᵀ ω, Rᵀ (v − t × ω))`, inverting `Ad_g (ω, v) = (R ω, t × R ω + R v)`.
    #[inline]
    fn adjoint_inverse_apply(&self, xi: &Vector6<f64>) -> Vector6<f64> {
        let r = self.rot.as_matrix();
        let w = head(xi);
        join(&r.tr_mul(&w), &r.tr_mul(&(tail(xi) - self.t.cross(&w))))
    }
    /// `Ad*_g (μ_ω, μ_v) = (Rᵀ(μ_ω + μ_v × t), Rᵀ μ_v)`.
    #[inline]
    fn coadjoint_apply(&self, mu: &Vector6<f64>) -> Vector6<f64> {
        let r = self.rot.as_matrix();
        let mv = tail(mu);
        join(&r.tr_mul(&(head(mu) + mv.cross(&self.t))), &r.tr_mul(&mv))
    }
    /// `[(ω₁, v₁), (ω₂, v₂)] = (ω₁ × ω₂, ω₁ × v₂ + v₁ × ω₂)`.
    #[inline]
    fn bracket(xi: &Vector6<f64>, eta: &Vector6<f64>) -> Vector6<f64> {
        let (w1, v1, w2, v2) = (head(xi), tail(xi), head(eta), tail(eta));
        join(&w1.cross(&w2), &(w1.cross(&v2) + v1.cross(&w2)))
    }
    /// `ad*_ξ (μ_ω, μ_v) = (μ_ω × ω + μ_v × v, μ_v × ω)`.
    #[inline]
    fn ad_dual_apply(xi: &Vector6<f64>, mu: &Vector6<f64>) -> Vector6<f64> {
        let (w, v, mw, mv) = (head(xi), tail(xi), head(mu), tail(mu));
        join(&(mw.cross(&w) + mv.cross(&v)), &mv.cross(&w))
    }
    /// `d^L exp_ξ = Σ (−ad_ξ)^k/(k+1)! = [[J_r(ω), 0], [Q_r, J_r(ω)]]` with J_r the SO(3)
    /// `dexp_left` and `Q_r = Q(−v, −ω) = −Q(v, −ω)` Barfoot's coupling block (manif's SE(3)
    /// right Jacobian, reordered to (ω, v)). Taylor branches below θ = 0.1 (θ = 0.5 for Q).
    fn dexp_left(xi: &Vector6<f64>) -> Matrix6<f64> {
        let w = head(xi);
        let j = So3::dexp_left(&w);
        let q = -barfoot_q(&tail(xi), &(-w));
        blocks(&j, &Matrix3::zeros(), &q, &j)
    }
    /// `(d^L exp_ξ)⁻¹ = [[J⁻¹, 0], [−J⁻¹ Q_r J⁻¹, J⁻¹]]` (block lower-triangular inverse).
    fn dexp_left_inv(xi: &Vector6<f64>) -> Matrix6<f64> {
        let w = head(xi);
        let ji = So3::dexp_left_inv(&w);
        let q = -barfoot_q(&tail(xi), &(-w));
        blocks(&ji, &Matrix3::zeros(), &(-(ji * q * ji)), &ji)
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.rot.is_finite() && self.t.iter().all(|x| x.is_finite())
    }
    #[inline]
    fn matrix_distance(&self, other: &Self) -> f64 {
        self.rot
            .matrix_distance(&other.rot)
            .max((self.t - other.t).amax())
    }
}

impl CayleyGroup for Se3 {
    /// cay is a diffeomorphism onto the elements whose rotation part is not a rotation by π; the
    /// round trip loses ≈ ε‖ξ‖² relative accuracy as g + I nears singularity (checked up to r).
    const CAY_INVERTIBLE_RADIUS: f64 = 1000.0;
    /// The 4×4 matrix Cayley map `(I − ξ̂/2)⁻¹(I + ξ̂/2) = (cay ω, (I − ω̂/2)⁻¹ v)`, with
    /// `(I − ω̂/2)⁻¹ = I + (2ω̂ + ω̂²)/(4 + θ²)`.
    #[inline]
    fn cay(xi: &Vector6<f64>) -> Self {
        let w = head(xi);
        let k = skew(&w);
        let m_inv = Matrix3::identity() + (k * 2.0 + k * k) / (4.0 + w.norm_squared());
        Self::from_parts(So3::cay(&w), m_inv * tail(xi))
    }
    /// `(Ad_{cay(φ, ρ)} − I) ξ` with `cay(φ, ρ) = (I + a φ̂ + (a/2) φ̂², (I − φ̂/2)⁻¹ ρ)`,
    /// a = 4/(4 + θ²), `(I − φ̂/2)⁻¹ ρ = ρ + (a/2) φ × ρ + (a/4) φ × (φ × ρ)`.
    #[inline]
    fn cay_adjoint_increment(z: &Vector6<f64>, xi: &Vector6<f64>) -> Vector6<f64> {
        let phi = head(z);
        let a = 4.0 / (4.0 + phi.norm_squared());
        let t = rodrigues_apply(&phi, 0.5 * a, 0.25 * a, &tail(z));
        adjoint_increment_of(&phi, a, 0.5 * a, &t, xi)
    }
    /// `cay⁻¹(R, t) = (ω, (I − ω̂/2) t)` with ω = cay⁻¹(R) (the blocks of `2(g − I)(g + I)⁻¹`);
    /// an error at half-turn rotations, where g + I is singular.
    fn cay_inv(&self) -> Result<Vector6<f64>, LieError> {
        if !self.t.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "translation",
            });
        }
        let w = self.rot.cay_inv()?;
        Ok(join(&w, &(self.t - w.cross(&self.t) * 0.5)))
    }
    /// `d^L cay_ξ = [[D, 0], [−½ v̂ D, (I + ω̂/2)⁻¹]]` with `D = 2/(4 + θ²)(2I − ω̂)` the SO(3) block
    /// and `(I + ω̂/2)⁻¹ = I + (ω̂² − 2ω̂)/(4 + θ²)`; the block inverse of [`Self::dcay_left_inv`].
    fn dcay_left(xi: &Vector6<f64>) -> Matrix6<f64> {
        let w = head(xi);
        let k = skew(&w);
        let d = So3::dcay_left(&w);
        let p_inv = Matrix3::identity() + (k * k - k * 2.0) / (4.0 + w.norm_squared());
        blocks(&d, &Matrix3::zeros(), &(skew(&tail(xi)) * d * -0.5), &p_inv)
    }
    /// The exact `D cay(ξ; μ) = ∂/∂ξ (d^{L*}cay_ξ μ)`. From the blocks of [`Self::dcay_left`],
    /// `d^{L*}cay_ξ (m, p) = (Dᵀ (m + ½ v × p), (I − ω̂/2)⁻¹ p)`, so with `q = m + ½ v × p` and
    /// `y = (I − ω̂/2)⁻¹ p`:
    /// `D cay = [[D cay_SO(3)(ω; q), −½ Dᵀ p̂], [−½ (I − ω̂/2)⁻¹ ŷ, 0]]`
    /// (the SO(3) block is [`So3`]'s closed form; `∂_ω (I − ω̂/2)⁻¹ p · δ = ½ (I − ω̂/2)⁻¹ (δ × y)`).
    fn dcay_left_dual_derivative(xi: &Vector6<f64>, mu: &Vector6<f64>) -> Matrix6<f64> {
        let (w, v) = (head(xi), tail(xi));
        let (m, p) = (head(mu), tail(mu));
        let q = m + v.cross(&p) * 0.5;
        let d = So3::dcay_left(&w);
        let k = skew(&w);
        let q_inv = Matrix3::identity() + (k * k + k * 2.0) / (4.0 + w.norm_squared());
        let y = q_inv * p;
        blocks(
            &So3::dcay_left_dual_derivative(&w, &q),
            &(d.transpose() * skew(&p) * -0.5),
            &(q_inv * skew(&y) * -0.5),
            &Matrix3::zeros(),
        )
    }
    /// `(d^L cay_ξ)⁻¹ = [[I + ω̂/2 + ωωᵀ/4, 0], [½ (I + ω̂/2) v̂, I + ω̂/2]]`: the blocks of
    /// `η̂ + [ξ̂, η̂]/2 − ξ̂ η̂ ξ̂/4`, whose translation part is `(I + ω̂/2)(u + ½ v̂ w)` for η = (w, u).
    fn dcay_left_inv(xi: &Vector6<f64>) -> Matrix6<f64> {
        let w = head(xi);
        let p = Matrix3::identity() + skew(&w) * 0.5;
        blocks(
            &So3::dcay_left_inv(&w),
            &Matrix3::zeros(),
            &(p * skew(&tail(xi)) * 0.5),
            &p,
        )
    }
}

/// Rigid motion of points: `(R, t) · p = R p + t`. The Jacobians with respect to g are 3×6 in the
/// algebra's order (ω, v).
impl Action<Vector3<f64>> for Se3 {
    type PointJacobian = Matrix3<f64>;
    type GroupJacobian = nalgebra::Matrix3x6<f64>;
    #[inline]
    fn act(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.rot.as_matrix() * p + self.t
    }
    /// `R`.
    #[inline]
    fn act_jacobian_point(&self, _p: &Vector3<f64>) -> Matrix3<f64> {
        *self.rot.as_matrix()
    }
    /// `g exp(δ) · p ≈ g · (p + ω × p + v)` for δ = (ω, v): `[−R p̂, R]`.
    #[inline]
    fn act_jacobian_left(&self, p: &Vector3<f64>) -> nalgebra::Matrix3x6<f64> {
        let r = self.rot.as_matrix();
        let mut j = nalgebra::Matrix3x6::zeros();
        j.fixed_view_mut::<3, 3>(0, 0).copy_from(&-(r * skew(p)));
        j.fixed_view_mut::<3, 3>(0, 3).copy_from(r);
        j
    }
    /// `exp(δ) · q ≈ q + ω × q + v` at `q = g · p`: `[−q̂, I]`.
    #[inline]
    fn act_jacobian_right(&self, p: &Vector3<f64>) -> nalgebra::Matrix3x6<f64> {
        let q = self.act(p);
        let mut j = nalgebra::Matrix3x6::zeros();
        j.fixed_view_mut::<3, 3>(0, 0).copy_from(&-skew(&q));
        j.fixed_view_mut::<3, 3>(0, 3)
            .copy_from(&Matrix3::identity());
        j
    }
}
