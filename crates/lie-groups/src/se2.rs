//! SE(2), the rigid motions of the plane, on nalgebra stack types.
//!
//! - Element `g = (R, t)`, acting as `p ↦ R p + t`, with matrix `[[R, t], [0, 1]]` (3×3
//!   homogeneous). R is an [`So2`] (stored as `(cos θ, sin θ)`).
//! - Algebra 𝔰𝔢(2) ≅ ℝ³ ordered **`ξ = (ω, vx, vy)`** (rotation first):
//!   `ξ̂ = [[0, −ω, vx], [ω, 0, vy], [0, 0, 0]]`.
//! - With `J = [[0, −1], [1, 0]]`: `ad_ξ η = (0, ω J u − ω_η J v)` for `η = (ω_η, u)`, and
//!   `Ad_g ξ = (ω, R v − ω J t)`.
//!
//! Closed forms use the functions of ω below, each with a Taylor branch where its direct form
//! cancels (|ω| < 0.1; the dropped terms are below 10⁻¹⁷ there):
//! - `A = sin ω/ω`, `B = (1 − cos ω)/ω` (exp: `t = [[A, −B], [B, A]] v`);
//! - `C = (1 − cos ω)/ω²`, `D = (ω − sin ω)/ω²` (d^L exp);
//! - `α = (ω/2) cot(ω/2)`, `γ = (1 − α)/ω` (log and (d^L exp)⁻¹).

use crate::so2::check_rotation2;
use crate::trig::{quartic, COSC_SERIES, SINC3_SERIES, SINC_SERIES};
use crate::{Action, CayleyGroup, LieError, LieGroup, So2};
use nalgebra::{Isometry2, Matrix2, Matrix3, Translation2, UnitComplex, Vector2, Vector3};

/// A rigid motion of the plane `p ↦ R p + t` (see the module page for the conventions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Se2 {
    rot: So2,
    t: Vector2<f64>,
}

/// Below this |ω| the Taylor branches are used.
const SMALL: f64 = 0.1;

/// `A = sin ω/ω = 1 − ω²/6 + ω⁴/120 − ω⁶/5040 + ω⁸/362880 − …`.
fn fa(w: f64) -> f64 {
    if w.abs() < SMALL {
        let w2 = w * w;
        quartic(w2, SINC_SERIES)
    } else {
        w.sin() / w
    }
}

/// `C = (1 − cos ω)/ω² = 1/2 − ω²/24 + ω⁴/720 − ω⁶/40320 + ω⁸/3628800 − …`
/// (direct form `2 sin²(ω/2)/ω²`, which has no cancellation).
fn fc(w: f64) -> f64 {
    if w.abs() < SMALL {
        let w2 = w * w;
        quartic(w2, COSC_SERIES)
    } else {
        let h = (0.5 * w).sin();
        2.0 * h * h / (w * w)
    }
}

/// `D = (ω − sin ω)/ω² = ω/6 − ω³/120 + ω⁵/5040 − ω⁷/362880 + …` (the direct form loses
/// about ε/ω absolutely, so the series runs below |ω| = 0.1).
fn fd(w: f64) -> f64 {
    if w.abs() < SMALL {
        let w2 = w * w;
        w * quartic(w2, SINC3_SERIES)
    } else {
        (w - w.sin()) / (w * w)
    }
}

/// `(α, γ)` with `α = (ω/2) cot(ω/2) = 1 − ω²/12 − ω⁴/720 − ω⁶/30240 − ω⁸/1209600 − …` and
/// `γ = (1 − α)/ω = ω/12 + ω³/720 + ω⁵/30240 + ω⁷/1209600 + …`. At ω = π, α = 0 exactly up to
/// round-off (no 0/0: `cot` is evaluated as `cos(ω/2)/sin(ω/2)`).
fn alpha_gamma(w: f64) -> (f64, f64) {
    if w.abs() < SMALL {
        let w2 = w * w;
        let g = w * (1.0 / 12.0 + w2 * (1.0 / 720.0 + w2 * (1.0 / 30240.0 + w2 / 1209600.0)));
        (1.0 - w * g, g)
    } else {
        let (s, c) = (0.5 * w).sin_cos();
        let a = 0.5 * w * c / s;
        (a, (1.0 - a) / w)
    }
}

#[inline]
fn j(v: &Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

/// `(Ad_{(R, t)} − I)(ω, v) = (0, (R − I) v − ω J t)` for `R − I = c I + s J` (from
/// `Ad_g (ω, v) = (ω, R v − ω J t)`), computed without forming R: c = cos φ − 1 and s = sin φ,
/// given in the forms of the τ map that keep their relative accuracy.
#[inline]
fn adjoint_increment_of(c: f64, s: f64, t: &Vector2<f64>, xi: &Vector3<f64>) -> Vector3<f64> {
    let w = xi[0];
    let v = Vector2::new(xi[1], xi[2]);
    let d = v * c + j(&v) * s - j(t) * w;
    Vector3::new(0.0, d.x, d.y)
}

impl Se2 {
    /// Default tolerance of [`LieGroup::from_matrix`] (as [`So2::TOLERANCE`]; the bottom row must be
    /// `[0, 0, 1]` within it too).
    pub const TOLERANCE: f64 = 1e-9;

    /// The motion `p ↦ R p + t`.
    #[inline]
    pub fn new(rotation: So2, translation: Vector2<f64>) -> Self {
        Self {
            rot: rotation,
            t: translation,
        }
    }

    /// The rotation R.
    #[inline]
    pub fn rotation(&self) -> So2 {
        self.rot
    }

    /// The translation t.
    #[inline]
    pub fn translation(&self) -> Vector2<f64> {
        self.t
    }

    /// Checked constructor with an explicit tolerance: refuses non-finite entries, a bottom row
    /// farther than `tol` from `[0, 0, 1]` ([`LieError::NotHomogeneous`]) and a rotation block
    /// that is not orthogonal with det +1 within `tol`.
    pub fn from_matrix_with_tolerance(m: &Matrix3<f64>, tol: f64) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite { what: "matrix" });
        }
        let bottom = m[(2, 0)]
            .abs()
            .max(m[(2, 1)].abs())
            .max((m[(2, 2)] - 1.0).abs());
        if bottom > tol {
            return Err(LieError::NotHomogeneous { error: bottom });
        }
        let r: Matrix2<f64> = m.fixed_view::<2, 2>(0, 0).into_owned();
        check_rotation2(&r, tol)?;
        Ok(Self::from_matrix_unchecked(m))
    }

    /// The nearest element: the rotation block projected with [`So2::project`], the translation
    /// column kept, the bottom row ignored. An error for non-finite input or a rotation block with
    /// no unique nearest rotation.
    pub fn project(m: &Matrix3<f64>) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite { what: "matrix" });
        }
        let rot = So2::project(&m.fixed_view::<2, 2>(0, 0).into_owned())?;
        Ok(Self::new(rot, Vector2::new(m[(0, 2)], m[(1, 2)])))
    }
}

impl LieGroup for Se2 {
    /// The principal log inverts exp for |ω| < π (any translation); 3 keeps clear of the cut at π.
    const EXP_INVERTIBLE_RADIUS: f64 = 3.0;
    /// Normalizes the rotation part; the translation cannot drift off.
    #[inline]
    fn normalize(&self) -> Self {
        Self {
            rot: self.rot.normalize(),
            t: self.t,
        }
    }
    type Algebra = Vector3<f64>;
    type Operator = Matrix3<f64>;
    type Matrix = Matrix3<f64>;

    fn name() -> String {
        "SE(2)".into()
    }
    fn dim() -> usize {
        3
    }
    #[inline]
    fn identity() -> Self {
        Self::new(So2::identity(), Vector2::zeros())
    }
    /// `(R₁, t₁)(R₂, t₂) = (R₁R₂, R₁t₂ + t₁)`.
    #[inline]
    fn compose(&self, o: &Self) -> Self {
        Self::new(self.rot.compose(&o.rot), self.rot.rotate(&o.t) + self.t)
    }
    /// `(R, t)⁻¹ = (Rᵀ, −Rᵀ t)`.
    #[inline]
    fn inverse(&self) -> Self {
        let ri = self.rot.inverse();
        Self::new(ri, -ri.rotate(&self.t))
    }
    /// `exp(ω, v) = (R(ω), V(ω) v)` with `V = [[A, −B], [B, A]]`, `A = sin ω/ω`,
    /// `B = (1 − cos ω)/ω = ω C` (Taylor branches near 0, see the module page).
    #[inline]
    fn exp(xi: &Vector3<f64>) -> Self {
        let w = xi[0];
        let (a, b) = (fa(w), w * fc(w));
        let v = Vector2::new(xi[1], xi[2]);
        Self::new(
            So2::from_angle(w),
            Vector2::new(a * v.x - b * v.y, b * v.x + a * v.y),
        )
    }
    /// `(Ad_{exp(φ, ρ)} − I) ξ` with `cos φ − 1 = −φ² C`, `sin φ = φ A` and the translation
    /// `t = A ρ + B J ρ` of [`LieGroup::exp`] (A = sin φ/φ, C = (1 − cos φ)/φ², B = φ C; Taylor
    /// branches near 0).
    #[inline]
    fn exp_adjoint_increment(z: &Vector3<f64>, xi: &Vector3<f64>) -> Vector3<f64> {
        let p = z[0];
        let (a, c) = (fa(p), fc(p));
        let rho = Vector2::new(z[1], z[2]);
        let t = rho * a + j(&rho) * (p * c);
        adjoint_increment_of(-(p * p) * c, p * a, &t, xi)
    }
    /// `log(R, t) = (θ, V(θ)⁻¹ t)` with θ ∈ (−π, π] from [`So2::angle`] and
    /// `V⁻¹ = [[α, θ/2], [−θ/2, α]]`, `α = (θ/2) cot(θ/2)`. At θ = π, α = 0: finite, no NaN, and the
    /// result is θ = +π. Never fails for a finite element.
    fn log(&self) -> Result<Vector3<f64>, LieError> {
        if !(self.rot.is_finite() && self.t.iter().all(|x| x.is_finite())) {
            return Err(LieError::NonFinite {
                what: "SE(2) element",
            });
        }
        let th = self.rot.angle();
        let (a, _) = alpha_gamma(th);
        let h = 0.5 * th;
        let t = self.t;
        Ok(Vector3::new(th, a * t.x + h * t.y, -h * t.x + a * t.y))
    }
    #[inline]
    fn hat(xi: &Vector3<f64>) -> Matrix3<f64> {
        Matrix3::new(0.0, -xi[0], xi[1], xi[0], 0.0, xi[2], 0.0, 0.0, 0.0)
    }
    /// `(ω, vx, vy)` read as `((m₁₀ − m₀₁)/2, m₀₂, m₁₂)`.
    #[inline]
    fn vee(m: &Matrix3<f64>) -> Vector3<f64> {
        Vector3::new(0.5 * (m[(1, 0)] - m[(0, 1)]), m[(0, 2)], m[(1, 2)])
    }
    fn matrix(&self) -> Matrix3<f64> {
        let (c, s) = (self.rot.cos(), self.rot.sin());
        Matrix3::new(c, -s, self.t.x, s, c, self.t.y, 0.0, 0.0, 1.0)
    }
    /// Checked with [`Se2::TOLERANCE`]; see [`Se2::from_matrix_with_tolerance`].
    fn from_matrix(m: &Matrix3<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, Self::TOLERANCE)
    }
    fn from_matrix_unchecked(m: &Matrix3<f64>) -> Self {
        let r: Matrix2<f64> = m.fixed_view::<2, 2>(0, 0).into_owned();
        Self::new(
            So2::from_matrix_unchecked(&r),
            Vector2::new(m[(0, 2)], m[(1, 2)]),
        )
    }
    /// `Ad_{(R,t)} = [[1, 0, 0], [t_y, R], [−t_x, R]]`, i.e. `Ad_g (ω, v) = (ω, R v − ω J t)`.
    fn adjoint(&self) -> Matrix3<f64> {
        let (c, s) = (self.rot.cos(), self.rot.sin());
        let t = self.t;
        Matrix3::new(1.0, 0.0, 0.0, t.y, c, -s, -t.x, s, c)
    }
    /// `ad_(ω, v) = [[0, 0, 0], [v_y, 0, −ω], [−v_x, ω, 0]]`.
    fn ad(xi: &Vector3<f64>) -> Matrix3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        Matrix3::new(0.0, 0.0, 0.0, vy, 0.0, -w, -vx, w, 0.0)
    }
    #[inline]
    fn adjoint_apply(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        let w = xi[0];
        let rv = self.rot.rotate(&Vector2::new(xi[1], xi[2]));
        let jt = j(&self.t);
        Vector3::new(w, rv.x - w * jt.x, rv.y - w * jt.y)
    }
    /// `Ad*_g (m, p) = (m + ⟨(t_y, −t_x), p⟩, Rᵀ p)`.
    #[inline]
    fn coadjoint_apply(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        let p = Vector2::new(mu[1], mu[2]);
        let rtp = self.rot.inverse().rotate(&p);
        Vector3::new(mu[0] + self.t.y * p.x - self.t.x * p.y, rtp.x, rtp.y)
    }
    /// `[(ω, v), (ω', u)] = (0, ω J u − ω' J v)`.
    #[inline]
    fn bracket(xi: &Vector3<f64>, eta: &Vector3<f64>) -> Vector3<f64> {
        let (w, v) = (xi[0], Vector2::new(xi[1], xi[2]));
        let (w2, u) = (eta[0], Vector2::new(eta[1], eta[2]));
        let r = w * j(&u) - w2 * j(&v);
        Vector3::new(0.0, r.x, r.y)
    }
    /// `ad*_(ω, v) (m, p) = (v_y p_x − v_x p_y, ω p_y, −ω p_x)`.
    #[inline]
    fn ad_dual_apply(xi: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        Vector3::new(vy * mu[1] - vx * mu[2], w * mu[2], -w * mu[1])
    }
    /// `d^L exp_ξ = Σ (−ad_ξ)^k/(k+1)! = [[1, 0, 0], [D v_x − C v_y, A, B], [C v_x + D v_y, −B, A]]`
    /// (from `φ₁(−iω) = A − iB` on the rotation block and `φ₂(−iω) (J v)` with
    /// `φ₂(−iω) = C − iD` on the coupling column).
    fn dexp_left(xi: &Vector3<f64>) -> Matrix3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        let (a, c, d) = (fa(w), fc(w), fd(w));
        let b = w * c;
        Matrix3::new(1.0, 0.0, 0.0, d * vx - c * vy, a, b, c * vx + d * vy, -b, a)
    }
    /// `(d^L exp_ξ)⁻¹ = [[1, 0, 0], [γ v_x + v_y/2, α, −ω/2], [γ v_y − v_x/2, ω/2, α]]` with
    /// `α = (ω/2) cot(ω/2)`, `γ = (1 − α)/ω` (from `φ₂/φ₁ = 1/z − 1/(eᶻ − 1)` at `z = −iω`).
    /// Singular (huge or non-finite entries) at ω = 2πk, k ≠ 0.
    fn dexp_left_inv(xi: &Vector3<f64>) -> Matrix3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        let (a, g) = alpha_gamma(w);
        let h = 0.5 * w;
        Matrix3::new(
            1.0,
            0.0,
            0.0,
            g * vx + 0.5 * vy,
            a,
            -h,
            g * vy - 0.5 * vx,
            h,
            a,
        )
    }
    fn is_finite(&self) -> bool {
        self.rot.is_finite() && self.t.iter().all(|x| x.is_finite())
    }
}

impl CayleyGroup for Se2 {
    /// cay is a diffeomorphism onto the elements whose rotation part is not a rotation by π; the
    /// round trip loses ≈ ε‖ξ‖² relative accuracy as g + I nears singularity (checked up to r).
    const CAY_INVERTIBLE_RADIUS: f64 = 1000.0;
    /// `cay(ω, v) = (cay_SO(2)(ω), k [[1, −ω/2], [ω/2, 1]] v)` with `k = 1/(1 + ω²/4)`
    /// (block form of `(I − ξ̂/2)⁻¹(I + ξ̂/2)`: the translation is `(I − ωJ/2)⁻¹ v`).
    #[inline]
    fn cay(xi: &Vector3<f64>) -> Self {
        let w = xi[0];
        let k = 1.0 / (1.0 + 0.25 * w * w);
        let h = 0.5 * w;
        let (vx, vy) = (xi[1], xi[2]);
        Self::new(
            So2::cay(&nalgebra::Vector1::new(w)),
            Vector2::new(k * (vx - h * vy), k * (h * vx + vy)),
        )
    }
    /// `(Ad_{cay(φ, ρ)} − I) ξ` with `cay φ − 1 = k (−φ²/2 + φ J)` and `t = k (ρ + (φ/2) J ρ)`,
    /// `k = 1/(1 + φ²/4)` (see [`CayleyGroup::cay`]).
    #[inline]
    fn cay_adjoint_increment(z: &Vector3<f64>, xi: &Vector3<f64>) -> Vector3<f64> {
        let p = z[0];
        let k = 1.0 / (1.0 + 0.25 * p * p);
        let rho = Vector2::new(z[1], z[2]);
        let t = (rho + j(&rho) * (0.5 * p)) * k;
        adjoint_increment_of(-0.5 * k * (p * p), k * p, &t, xi)
    }
    /// `cay⁻¹(R, t) = (ω, [[1, ω/2], [−ω/2, 1]] t)` with `ω = 2 sin θ/(1 + cos θ)` (from
    /// `2(g − I)(g + I)⁻¹`, whose translation is `2(R + I)⁻¹ t`); an error at the half turn.
    fn cay_inv(&self) -> Result<Vector3<f64>, LieError> {
        if !self.t.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "SE(2) element",
            });
        }
        let w = self.rot.cay_inv()?[0];
        let h = 0.5 * w;
        let t = self.t;
        Ok(Vector3::new(w, t.x + h * t.y, -h * t.x + t.y))
    }
    /// `d^L cay_ξ = k [[1, 0, 0], [−v_y/2, 1, ω/2], [v_x/2, −ω/2, 1]]`, `k = 1/(1 + ω²/4)`
    /// (block form of `(I + ξ̂/2)⁻¹ η̂ (I − ξ̂/2)⁻¹`).
    fn dcay_left(xi: &Vector3<f64>) -> Matrix3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        let k = 1.0 / (1.0 + 0.25 * w * w);
        let h = 0.5 * w;
        Matrix3::new(1.0, 0.0, 0.0, -0.5 * vy, 1.0, h, 0.5 * vx, -h, 1.0) * k
    }
    /// The exact `D cay(ξ; μ) = ∂/∂ξ (d^{L*}cay_ξ μ)`: with `k = 1/(1 + ω²/4)` and
    /// `f = d^{L*}cay_ξ μ = k (m − v_y p_x/2 + v_x p_y/2, p_x − ω p_y/2, ω p_x/2 + p_y)` for
    /// μ = (m, p_x, p_y), the columns are `∂f/∂ω = −(ω/2) k f + k (0, −p_y/2, p_x/2)`,
    /// `∂f/∂v_x = k (p_y/2, 0, 0)`, `∂f/∂v_y = k (−p_x/2, 0, 0)`.
    fn dcay_left_dual_derivative(xi: &Vector3<f64>, mu: &Vector3<f64>) -> Matrix3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        let (m, px, py) = (mu[0], mu[1], mu[2]);
        let k = 1.0 / (1.0 + 0.25 * w * w);
        let h = 0.5 * w;
        let f = Vector3::new(m - 0.5 * vy * px + 0.5 * vx * py, px - h * py, h * px + py) * k;
        let dw = f * (-h * k) + Vector3::new(0.0, -0.5 * py, 0.5 * px) * k;
        Matrix3::new(
            dw[0],
            0.5 * k * py,
            -0.5 * k * px,
            dw[1],
            0.0,
            0.0,
            dw[2],
            0.0,
            0.0,
        )
    }
    /// `(d^L cay_ξ)⁻¹ = [[1 + ω²/4, 0, 0], [v_y/2 + ω v_x/4, 1, −ω/2], [−v_x/2 + ω v_y/4, ω/2, 1]]`
    /// (block form of `η̂ + [ξ̂, η̂]/2 − ξ̂ η̂ ξ̂/4`).
    fn dcay_left_inv(xi: &Vector3<f64>) -> Matrix3<f64> {
        let (w, vx, vy) = (xi[0], xi[1], xi[2]);
        let h = 0.5 * w;
        Matrix3::new(
            1.0 + h * h,
            0.0,
            0.0,
            0.5 * vy + 0.25 * w * vx,
            1.0,
            -h,
            -0.5 * vx + 0.25 * w * vy,
            h,
            1.0,
        )
    }
}

/// Rigid motion of plane points: `g · p = R p + t`. The Jacobians with respect to g are 2×3 in
/// the algebra's order (ω, vx, vy).
impl Action<Vector2<f64>> for Se2 {
    type PointJacobian = Matrix2<f64>;
    type GroupJacobian = nalgebra::Matrix2x3<f64>;
    #[inline]
    fn act(&self, p: &Vector2<f64>) -> Vector2<f64> {
        self.rot.rotate(p) + self.t
    }
    /// `R`.
    #[inline]
    fn act_jacobian_point(&self, _p: &Vector2<f64>) -> Matrix2<f64> {
        self.rot.matrix()
    }
    /// `g exp(δ) · p ≈ g · (p + ω J p + v)` for δ = (ω, v), J the rotation by π/2: `R [J p, I]`.
    #[inline]
    fn act_jacobian_left(&self, p: &Vector2<f64>) -> nalgebra::Matrix2x3<f64> {
        let r = self.rot.matrix();
        let jp = r * Vector2::new(-p.y, p.x);
        nalgebra::Matrix2x3::new(jp.x, r[(0, 0)], r[(0, 1)], jp.y, r[(1, 0)], r[(1, 1)])
    }
    /// `exp(δ) · q ≈ q + ω J q + v` at `q = g · p`: `[J q, I]`.
    #[inline]
    fn act_jacobian_right(&self, p: &Vector2<f64>) -> nalgebra::Matrix2x3<f64> {
        let q = self.act(p);
        nalgebra::Matrix2x3::new(-q.y, 1.0, 0.0, q.x, 0.0, 1.0)
    }
}

impl From<Isometry2<f64>> for Se2 {
    fn from(iso: Isometry2<f64>) -> Self {
        Self::new(iso.rotation.into(), iso.translation.vector)
    }
}

impl From<Se2> for Isometry2<f64> {
    fn from(g: Se2) -> Self {
        Isometry2::from_parts(Translation2::from(g.t), UnitComplex::<f64>::from(g.rot))
    }
}
