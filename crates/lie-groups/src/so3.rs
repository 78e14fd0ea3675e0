//! SO(3), the rotation group of ℝ³, on a stack `Matrix3<f64>`.
//!
//! - Algebra 𝔰𝔬(3) ≅ ℝ³ by `hat(ω) = ω̂`, the cross-product matrix (`ω̂ x = ω × x`).
//! - `Ad_R = R`, `ad_ω = ω̂`, `[ω, η] = ω × η`, `Ad*_R μ = Rᵀ μ`, `ad*_ω μ = ω̂ᵀ μ = μ × ω`.
//! - Every closed form below is written with θ = |ω| and carries a Taylor branch for small θ
//!   (below [`SMALL_ANGLE`]), so that |ω| = 1e-8 and ω = 0 give full double precision and no 0/0.

use crate::trig::{quartic, COSC_SERIES, SINC3_SERIES, SINC_SERIES};
use crate::{trig, Action, CayleyGroup, DomainReason, LieError, LieGroup};
use nalgebra::{Matrix3, Vector3};

/// Default tolerance of the checked constructors: `‖RᵀR − I‖_max ≤ 1e-9` and `|det R − 1| ≤ 1e-9`.
///
/// Loose enough to accept rotations that went through a few thousand products or a text round trip,
/// tight enough that the group laws hold to ~1e-9 afterwards. Use
/// [`So3::from_matrix_with_tolerance`] for another value, [`So3::project`] to repair a matrix.
pub const ORTHOGONALITY_TOLERANCE: f64 = 1e-9;

/// Angle below which the Taylor branches are used (θ < 0.1). The series are truncated after the
/// θ⁶ or θ⁸ term, so the first dropped term is below 1e-16 relative to the leading one at θ = 0.1;
/// above it the closed forms lose at most ~1e-15 absolutely to cancellation.
pub const SMALL_ANGLE: f64 = 0.1;
const SMALL_ANGLE_SQ: f64 = SMALL_ANGLE * SMALL_ANGLE;

/// An element R of SO(3): a 3×3 rotation matrix (RᵀR = I, det R = +1), stored on the stack.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct So3 {
    r: Matrix3<f64>,
}

/// The cross-product matrix ω̂ = `[[0, −ω₃, ω₂], [ω₃, 0, −ω₁], [−ω₂, ω₁, 0]]`.
#[inline]
pub(crate) fn skew(w: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

/// The outer product `a bᵀ`, entry by entry (nalgebra's generic 3×1 · 1×3 product goes through
/// its gemm loop).
#[inline]
fn outer(a: &Vector3<f64>, b: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(
        a.x * b.x,
        a.x * b.y,
        a.x * b.z,
        a.y * b.x,
        a.y * b.y,
        a.y * b.z,
        a.z * b.x,
        a.z * b.y,
        a.z * b.z,
    )
}

/// `sin θ / θ = 1 − θ²/6 + θ⁴/120 − θ⁶/5040 + θ⁸/362880 − …`.
#[inline]
pub(crate) fn sinc(t2: f64) -> f64 {
    if t2 < SMALL_ANGLE_SQ {
        quartic(t2, SINC_SERIES)
    } else {
        let t = t2.sqrt();
        t.sin() / t
    }
}

/// `(1 − cos θ)/θ² = 1/2 − θ²/24 + θ⁴/720 − θ⁶/40320 + θ⁸/3628800 − …`.
///
/// Evaluated as `½ (sin(θ/2)/(θ/2))²` away from 0, which has no cancellation.
#[inline]
pub(crate) fn cosc(t2: f64) -> f64 {
    if t2 < SMALL_ANGLE_SQ {
        quartic(t2, COSC_SERIES)
    } else {
        let h = 0.5 * t2.sqrt();
        let s = h.sin() / h;
        0.5 * s * s
    }
}

/// `(θ − sin θ)/θ³ = 1/6 − θ²/120 + θ⁴/5040 − θ⁶/362880 + θ⁸/39916800 − …`.
#[inline]
pub(crate) fn sinc3(t2: f64) -> f64 {
    if t2 < SMALL_ANGLE_SQ {
        quartic(t2, SINC3_SERIES)
    } else {
        let t = t2.sqrt();
        (t - t.sin()) / (t * t2)
    }
}

/// The three Rodrigues coefficients `(sin θ/θ, (1 − cos θ)/θ², (θ − sin θ)/θ³)`: below
/// [`SMALL_ANGLE`] the same Taylor series as [`sinc`], [`cosc`], [`sinc3`]; above it
/// `sin θ/θ = 2 (sin h/θ) cos h` and `(1 − cos θ)/θ² = 2 (sin h/θ)²` with h = θ/2, from the
/// half-angle kernels of `exp_coeffs` (no cancellation, no libm call for θ ≤ π), and
/// `(θ − sin θ)/θ³ = (1 − sin θ/θ)/θ²`. The unused entries are dropped by the optimiser when
/// inlined.
#[inline]
pub(crate) fn rodrigues_coeffs(t2: f64) -> (f64, f64, f64) {
    if t2 < SMALL_ANGLE_SQ {
        (sinc(t2), cosc(t2), sinc3(t2))
    } else {
        // sin θ/θ and (1 − cos θ)/θ² from the half-angle kernels (`exp_coeffs`: no libm call for
        // θ ≤ π), and (θ − sin θ)/θ³ = (1 − sin θ/θ)/θ²: its cancellation, ~18ε/θ² relative at
        // worst (4e-13 at θ = 0.1, the series' edge), enters d^L exp multiplied by θ².
        let (a, b) = exp_coeffs(t2);
        (a, b, (1.0 - a) / t2)
    }
}

/// `I + c₁ n̂ + c₂ n̂²` for `ω = θ n` too long for θ² to be a double: n and θ from ω scaled by its
/// largest entry, `(c₁, c₂) = coeffs(θ)`.
#[cold]
fn huge_rotation(w: &Vector3<f64>, coeffs: impl Fn(f64) -> (f64, f64)) -> So3 {
    let m = w.amax();
    let u = w / m;
    // |ω| itself overflows when it exceeds f64::MAX (every component near it): θ is then taken
    // as f64::MAX, whose ulp (2⁹⁷¹) is already far beyond 2π, so no angle is more exact.
    let t = (m * u.norm()).min(f64::MAX);
    let n = u / u.norm();
    let (c1, c2) = coeffs(t);
    So3 {
        r: rodrigues_matrix(&n, c1, c2),
    }
}

/// `(Rᵀ − I)μ` for `R = I + a ω̂ + b ω̂²`: `a (μ × ω) + b ω × (ω × μ)` (ω̂ᵀ = −ω̂, (ω̂²)ᵀ = ω̂²), of
/// size O(|ω||μ|) and with its own relative accuracy.
#[inline]
fn coadjoint_increment(w: &Vector3<f64>, mu: &Vector3<f64>, a: f64, b: f64) -> Vector3<f64> {
    let wm = w.cross(mu);
    w.cross(&wm) * b - wm * a
}

/// `(R − I)v` for `R = I + a ω̂ + b ω̂²`: `a ω × v + b ω × (ω × v)` (Ad_R = R), of size
/// O(|ω||v|) and with its own relative accuracy; [`coadjoint_increment`] is the transpose.
#[inline]
pub(crate) fn adjoint_increment(
    w: &Vector3<f64>,
    v: &Vector3<f64>,
    a: f64,
    b: f64,
) -> Vector3<f64> {
    let wv = w.cross(v);
    wv * a + w.cross(&wv) * b
}

/// `(A, B)` with `cay(ω/den) − I = A ω̂ + B ω̂²`, den = 1 − θ(1−θ)|ω|²/4 (the one element
/// cay(θω)cay((1−θ)ω)), while den ≥ ½; `None` beyond. With ω' = ω/den the Cayley coefficients
/// `a = 4/(4 + |ω'|²)`, b = a/2 scale to `A = a/den = 4 den q`, `B = b/den² = 2q`,
/// `q = 1/(4 den² + |ω|²)`: one division and no division of ω (at θ ∈ {0, 1}, den = 1 and these are
/// cay's own 4/(4 + |ω|²), 2/(4 + |ω|²)).
#[inline(always)]
fn cay_split_coeffs(theta: f64, w: &Vector3<f64>) -> Option<(f64, f64)> {
    let t2 = w.norm_squared();
    let den = 1.0 - theta * (1.0 - theta) * t2 * 0.25;
    if den >= 0.5 {
        let q = 1.0 / (4.0 * den * den + t2);
        Some((4.0 * den * q, 2.0 * q))
    } else {
        None
    }
}

/// The 3×3 product, unrolled and always inlined (nalgebra's generic product can be left out of
/// line on the integrators' step, and a call there costs about as much as the product itself).
#[inline(always)]
fn mul3(a: &Matrix3<f64>, b: &Matrix3<f64>) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| a[(i, 0)] * b[(0, j)] + a[(i, 1)] * b[(1, j)] + a[(i, 2)] * b[(2, j)])
}

/// `a ω̂ + b ω̂²` (the rotation `I + a ω̂ + b ω̂²` less the identity), entry by entry as in
/// [`rodrigues_matrix`].
#[inline]
fn rodrigues_increment(w: &Vector3<f64>, a: f64, b: f64) -> Matrix3<f64> {
    let (x, y, z) = (w.x, w.y, w.z);
    let (xy, xz, yz) = (b * (x * y), b * (x * z), b * (y * z));
    let (ax, ay, az) = (a * x, a * y, a * z);
    Matrix3::new(
        -b * (y * y + z * z),
        xy - az,
        xz + ay,
        xy + az,
        -b * (x * x + z * z),
        yz - ax,
        xz - ay,
        yz + ax,
        -b * (x * x + y * y),
    )
}

/// `I + a ω̂ + b ω̂²`, written entry by entry with `ω̂² = ωωᵀ − θ² I` whose diagonal is taken as
/// `−(ω_j² + ω_k²)` (no cancellation): the same roundings as the matrix expression, without the
/// 27-multiplication product ω̂ ω̂ and the temporaries.
#[inline]
pub(crate) fn rodrigues_matrix(w: &Vector3<f64>, a: f64, b: f64) -> Matrix3<f64> {
    let (x, y, z) = (w.x, w.y, w.z);
    let (xy, xz, yz) = (b * (x * y), b * (x * z), b * (y * z));
    let (ax, ay, az) = (a * x, a * y, a * z);
    Matrix3::new(
        1.0 - b * (y * y + z * z),
        xy - az,
        xz + ay,
        xy + az,
        1.0 - b * (x * x + z * z),
        yz - ax,
        xz - ay,
        yz + ax,
        1.0 - b * (x * x + y * y),
    )
}

/// `v + a ω × v + b ω × (ω × v)` = `(I + a ω̂ + b ω̂²) v` without forming the matrix.
#[inline]
pub(crate) fn rodrigues_apply(w: &Vector3<f64>, a: f64, b: f64, v: &Vector3<f64>) -> Vector3<f64> {
    let wv = w.cross(v);
    v + wv * a + w.cross(&wv) * b
}

/// Bit patterns of +∞ and ½: for c ≥ +0, `c.to_bits() < INFINITY_BITS` ⇔ c finite, and
/// `c.to_bits() <= HALF_BITS` ⇔ c ≤ ½; negative c and NaN fail both.
const INFINITY_BITS: u64 = f64::INFINITY.to_bits();
const HALF_BITS: u64 = 0.5f64.to_bits();

/// (π/2)²: below it `exp_coeffs` evaluates the half-angle kernels on θ²/4 directly.
const HALF_PI_SQ: f64 = core::f64::consts::FRAC_PI_2 * core::f64::consts::FRAC_PI_2;

/// The two coefficients of `exp`, `(sin θ/θ, (1 − cos θ)/θ²)`, from ONE sine–cosine pair of θ/2
/// and no division after it (the fastest form, used only by `So3::exp`).
///
/// With h = θ/2 (halving is exact): `sin θ/θ = 2 (sin h/θ) cos h` and `(1 − cos θ)/θ² =
/// 2 (sin h/θ)²`: products only, so no cancellation anywhere (also near θ = π and beyond), and
/// each coefficient is within a few ulp relative. `1/θ` is taken before the sine and cosine and
/// overlaps with them. For θ ≤ π (h ≤ π/2, every principal rotation vector) sin h and cos h
/// come from inlined polynomial kernels (`trig::sin_cos_quadrant`, within 1 ulp, no libm call);
/// beyond π from libm. For θ ≤ π/2 even the square root and 1/θ go: `sin h/θ` and `cos h` are
/// even functions of h, evaluated from h² = θ²/4 (`trig::half_sinc_cos`). Below
/// [`SMALL_ANGLE`] the Taylor series of [`sinc`] and [`cosc`] in Estrin's form (`quartic`) with
/// reciprocal coefficients (one rounding more per term than dividing, i.e. ≤ 1e-17 absolute
/// there), which also avoids 1/θ at θ = 0; that branch is always inlined.
#[inline(always)]
fn exp_coeffs(t2: f64) -> (f64, f64) {
    if t2 < SMALL_ANGLE_SQ {
        (quartic(t2, SINC_SERIES), quartic(t2, COSC_SERIES))
    } else {
        exp_coeffs_trig(t2)
    }
}

/// [`exp_coeffs`] from θ = [`SMALL_ANGLE`] on, a function of its own: the three branches
/// together were too large for the compiler to inline, so every exp on a step's path — the
/// stages of `Rkmk4`, the residuals of the exp θ-methods — called them, small angles included.
#[inline]
fn exp_coeffs_trig(t2: f64) -> (f64, f64) {
    if t2 <= HALF_PI_SQ {
        // θ ≤ π/2: sin h/θ and cos h are even in h, so both come from h² = θ²/4 (exact).
        let (q, ch) = trig::half_sinc_cos(0.25 * t2);
        (2.0 * q * ch, 2.0 * q * q)
    } else {
        let t = t2.sqrt();
        let inv_t = 1.0 / t;
        let (sh, ch) = trig::sin_cos_quadrant(0.5 * t);
        let q = sh * inv_t;
        (2.0 * q * ch, 2.0 * q * q)
    }
}

/// `(1 − (θ/2) cot(θ/2))/θ² = 1/θ² − (1 + cos θ)/(2θ sin θ)
///  = 1/12 + θ²/720 + θ⁴/30240 + θ⁶/1209600 + θ⁸/47900160 + …` (from x cot x = 1 − x²/3 − x⁴/45
/// − 2x⁶/945 − x⁸/4725 − 2x¹⁰/93555 − …, x = θ/2). Below [`SMALL_ANGLE`] the series to θ⁸: the
/// first omitted term is below 1e-18 relative there (stopped at θ⁶, the omitted θ⁸ term would
/// reach 2.5e-15 relative at the branch's edge).
///
/// Finite on [0, 2π); infinite at θ = 2π, where d^L exp is singular.
#[inline]
pub(crate) fn dexp_inv_coeff(t2: f64) -> f64 {
    if t2 < SMALL_ANGLE_SQ {
        quartic(
            t2,
            [
                1.0 / 12.0,
                1.0 / 720.0,
                1.0 / 30240.0,
                1.0 / 1209600.0,
                1.0 / 47900160.0,
            ],
        )
    } else if t2 <= HALF_PI_SQ {
        // h cos h/sin h = cos h/(2 sin h/θ) with h = θ/2: the half-angle kernels on θ²/4, no
        // square root, no libm call.
        let (q, ch) = trig::half_sinc_cos(0.25 * t2);
        (1.0 - 0.5 * ch / q) / t2
    } else {
        let h = 0.5 * t2.sqrt();
        let (sh, ch) = trig::sin_cos_quadrant(h);
        (1.0 - h * ch / sh) / t2
    }
}

/// θ² below which [`dexp_dual_coeff_derivs`] uses its series (θ < 1). Higher than
/// [`SMALL_ANGLE`] because the closed forms of a′, b′ cancel badly for small θ (b′ = (a − 3b)/(2θ²)
/// loses ~60/θ² times the relative error of b, itself ~6/θ² ulps): at θ = 1 they lose only ~2 digits
/// of a term that enters multiplied by θ²|μ|, while nine series terms reach full precision there.
const DUAL_DERIV_SERIES_SQ: f64 = 1.0;

/// The derivatives in t = θ² of the coefficients a(t) = (1 − cos θ)/θ² = Σ_k (−t)^k/(2k+2)! and
/// b(t) = (θ − sin θ)/θ³ = Σ_k (−t)^k/(2k+3)! of `d^{L*}exp` (used by
/// [`LieGroup::dexp_left_dual_derivative`]):
///
/// `a′ = (sin θ/θ − 2a)/(2θ²) = Σ_{k≥1} (−1)^k k t^{k−1}/(2k+2)! = −1/24 + t/360 − t²/13440 + …`,
/// `b′ = (a − 3b)/(2θ²)       = Σ_{k≥1} (−1)^k k t^{k−1}/(2k+3)! = −1/120 + t/2520 − t²/120960 + …`.
///
/// Below θ² = [`DUAL_DERIV_SERIES_SQ`] = 1 the series to k = 9 (first dropped term < 1e-18
/// relative at t = 1); above it the closed forms.
#[inline]
fn dexp_dual_coeff_derivs(t2: f64) -> (f64, f64) {
    // (−1)^k k/(2k+2)! and (−1)^k k/(2k+3)! for k = 1..9 (folded at compile time).
    const DA: [f64; 9] = [
        -1.0 / 24.0,
        1.0 / 360.0,
        -1.0 / 13440.0,
        1.0 / 907200.0,
        -1.0 / 95800320.0,
        1.0 / 14529715200.0,
        -1.0 / 2988969984000.0,
        1.0 / 800296713216000.0,
        -1.0 / 270322445352960000.0,
    ];
    const DB: [f64; 9] = [
        -1.0 / 120.0,
        1.0 / 2520.0,
        -1.0 / 120960.0,
        1.0 / 9979200.0,
        -1.0 / 1245404160.0,
        1.0 / 217945728000.0,
        -1.0 / 50812489728000.0,
        1.0 / 15205637551104000.0,
        -1.0 / 5676771352412160000.0,
    ];
    if t2 < DUAL_DERIV_SERIES_SQ {
        // Horner from the highest term.
        let (mut da, mut db) = (0.0, 0.0);
        for (ca, cb) in DA.iter().zip(&DB).rev() {
            da = ca + t2 * da;
            db = cb + t2 * db;
        }
        (da, db)
    } else {
        let (s, a, b) = rodrigues_coeffs(t2);
        ((s - 2.0 * a) / (2.0 * t2), (a - 3.0 * b) / (2.0 * t2))
    }
}

impl So3 {
    /// The rotation matrix R.
    #[inline]
    pub fn as_matrix(&self) -> &Matrix3<f64> {
        &self.r
    }

    /// `R exp(ω̂)`, bit for bit `self.compose(&So3::exp(w))`, inlined whole into the caller (the
    /// Rodrigues matrix of [`LieGroup::exp`] is never stored): the splittings' rotation of R
    /// about Π. Huge or non-finite ω take the out-of-line [`LieGroup::exp`].
    #[inline(always)]
    pub fn compose_exp(&self, w: &Vector3<f64>) -> Self {
        let t2 = w.norm_squared();
        if !t2.is_finite() {
            return self.compose(&Self::exp(w));
        }
        let (a, b) = exp_coeffs(t2);
        Self {
            r: self.r * rodrigues_matrix(w, a, b),
        }
    }

    /// `R ← R exp(α êᵢ)` in place, from `(sin α, cos α)`: the rotation about the body axis eᵢ
    /// turns columns j = i+1 and k = i+2 (mod 3) of R, `(rⱼ, rₖ) ← (c rⱼ + s rₖ, c rₖ − s rⱼ)` —
    /// 12 flops, R rounded once; the splittings' principal-axis flows. The axis index is taken
    /// mod 3.
    #[inline]
    pub fn rotate_about_body_axis(&mut self, i: usize, sin: f64, cos: f64) {
        let (j, k) = match i % 3 {
            0 => (1, 2),
            1 => (2, 0),
            _ => (0, 1),
        };
        for row in 0..3 {
            let (rj, rk) = (self.r[(row, j)], self.r[(row, k)]);
            self.r[(row, j)] = cos * rj + sin * rk;
            self.r[(row, k)] = cos * rk - sin * rj;
        }
    }

    /// Checked constructor with an explicit tolerance: refuses non-finite entries
    /// ([`LieError::NonFinite`]), `‖RᵀR − I‖_max > tolerance` ([`LieError::NotOrthogonal`]) and
    /// `|det R − 1| > tolerance` ([`LieError::WrongDeterminant`], e.g. a reflection).
    pub fn from_matrix_with_tolerance(m: &Matrix3<f64>, tolerance: f64) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "rotation matrix",
            });
        }
        let error = (m.transpose() * m - Matrix3::identity()).amax();
        if error > tolerance {
            return Err(LieError::NotOrthogonal { error, tolerance });
        }
        let det = m.determinant();
        if (det - 1.0).abs() > tolerance {
            return Err(LieError::WrongDeterminant { det, tolerance });
        }
        Ok(Self { r: *m })
    }

    /// The nearest rotation to `m` in the Frobenius norm (orthogonal polar factor with the
    /// determinant fixed to +1): with `m = U Σ Vᵀ`, `R = U diag(1, 1, sign det(UVᵀ)) Vᵀ`.
    ///
    /// Errors: [`LieError::NonFinite`] on NaN/inf, [`LieError::Singular`] when `m` has rank < 2
    /// (σ₂ ≤ 1e-14 σ₁, including the zero matrix), where the nearest rotation is not unique.
    pub fn project(m: &Matrix3<f64>) -> Result<Self, LieError> {
        if !m.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite {
                what: "matrix to project",
            });
        }
        let svd = m.svd(true, true);
        // nalgebra sorts singular values in decreasing order.
        let s = svd.singular_values;
        let rcond = if s[0] > 0.0 { s[1] / s[0] } else { 0.0 };
        if rcond <= 1e-14 {
            return Err(LieError::Singular { rcond });
        }
        let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
            return Err(LieError::Singular { rcond });
        };
        let mut d = Matrix3::identity();
        if (u * v_t).determinant() < 0.0 {
            d[(2, 2)] = -1.0;
        }
        Ok(Self { r: u * d * v_t })
    }

    /// The nearest rotation to this (possibly drifted) element, see [`So3::project`]; returns the
    /// element unchanged if it cannot be projected (non-finite or rank < 2 entries).
    pub fn renormalize(&self) -> Self {
        Self::project(&self.r).unwrap_or(*self)
    }

    /// Rotation by `angle` about `axis` (normalised here): `exp(angle · axis/|axis|)`.
    /// Errors: non-finite input, or a zero axis ([`LieError::OutOfDomain`]).
    pub fn from_axis_angle(axis: &Vector3<f64>, angle: f64) -> Result<Self, LieError> {
        if !axis.iter().all(|x| x.is_finite()) || !angle.is_finite() {
            return Err(LieError::NonFinite {
                what: "axis or angle",
            });
        }
        let n = axis.norm();
        if n == 0.0 {
            return Err(LieError::OutOfDomain(DomainReason::ZeroAxis));
        }
        Ok(<Self as LieGroup>::exp(&(axis * (angle / n))))
    }

    /// `exp(ω)` for a rotation vector ω (axis ω/|ω|, angle |ω|, any magnitude).
    #[inline]
    pub fn from_rotation_vector(omega: &Vector3<f64>) -> Self {
        <Self as LieGroup>::exp(omega)
    }

    /// The rotation angle θ ∈ [0, π] (robust near 0 and π: `atan2(|vee(R − Rᵀ)|/2, (tr R − 1)/2)`).
    pub fn angle(&self) -> f64 {
        let (s, c) = self.sin_cos_parts();
        s.norm().atan2(c)
    }

    /// The rare cases of `log`, out of line: non-finite entries ([`LieError::NonFinite`]),
    /// entries so large that |s|² + c overflows (not a rotation; the formulas below are applied
    /// as they are), and c < 0 (θ ∈ (π/2, π], see [`So3::log_obtuse`]); c ≥ 0 repeats the fast
    /// path's formulas on |s|.
    #[cold]
    #[inline(never)]
    fn log_rare(&self) -> Result<Vector3<f64>, LieError> {
        let (s, c) = self.sin_cos_parts();
        if !self.is_finite() {
            return Err(LieError::NonFinite {
                what: "rotation matrix",
            });
        }
        let sn = s.norm();
        if c >= 0.0 {
            if sn == 0.0 {
                return Ok(s);
            }
            let theta = if sn <= c {
                sn.min(1.0).asin()
            } else {
                c.min(1.0).acos()
            };
            return Ok(s * (theta / sn));
        }
        Ok(self.log_obtuse(&s, sn, c))
    }

    /// The c < 0 branch of `log` (θ ∈ (π/2, π]), see the `log` docs: θ = atan2(|s|, c), axis from
    /// the largest column of the symmetric part, sign from s.
    fn log_obtuse(&self, s: &Vector3<f64>, sn: f64, c: f64) -> Vector3<f64> {
        let theta = sn.atan2(c);
        // θ > π/2: B = (1 − c) n nᵀ from the symmetric part; its largest diagonal entry is ≥ (1 − c)/3.
        let b = 0.5 * (self.r + self.r.transpose()) - Matrix3::identity() * c;
        let i = if b[(0, 0)] >= b[(1, 1)] && b[(0, 0)] >= b[(2, 2)] {
            0
        } else if b[(1, 1)] >= b[(2, 2)] {
            1
        } else {
            2
        };
        let col = b.column(i).into_owned();
        let n = col / col.norm();
        let sign = match n.dot(s) {
            d if d > 0.0 => 1.0,
            d if d < 0.0 => -1.0,
            // θ = π exactly: ±π n are both logarithms; pick the one with positive n_i.
            _ => 1.0,
        };
        n * (sign * theta)
    }

    /// `(vee(R − Rᵀ)/2, (tr R − 1)/2)` = `(sin θ · n, cos θ)`.
    #[inline]
    fn sin_cos_parts(&self) -> (Vector3<f64>, f64) {
        let r = &self.r;
        let s = 0.5
            * Vector3::new(
                r[(2, 1)] - r[(1, 2)],
                r[(0, 2)] - r[(2, 0)],
                r[(1, 0)] - r[(0, 1)],
            );
        let c = 0.5 * ((r[(0, 0)] + r[(1, 1)] + r[(2, 2)]) - 1.0);
        (s, c)
    }
}

impl LieGroup for So3 {
    /// The principal log inverts exp for rotation angles |ω| < π; 3 keeps clear of the cut at π.
    const EXP_INVERTIBLE_RADIUS: f64 = 3.0;
    /// One Newton–Schulz step of the polar decomposition, `R ← R (3I − RᵀR)/2`: for RᵀR = I + E it
    /// leaves an error of O(E²), so drift never accumulates (two 3×3 products).
    #[inline]
    fn normalize(&self) -> Self {
        // RᵀR is symmetric: its six distinct entries are the column dot products.
        let c = |j: usize| self.r.column(j).into_owned();
        let (c0, c1, c2) = (c(0), c(1), c(2));
        let (d01, d02, d12) = (-0.5 * c0.dot(&c1), -0.5 * c0.dot(&c2), -0.5 * c1.dot(&c2));
        let corr = Matrix3::new(
            1.5 - 0.5 * c0.norm_squared(),
            d01,
            d02,
            d01,
            1.5 - 0.5 * c1.norm_squared(),
            d12,
            d02,
            d12,
            1.5 - 0.5 * c2.norm_squared(),
        );
        Self { r: self.r * corr }
    }
    type Algebra = Vector3<f64>;
    type Operator = Matrix3<f64>;
    type Matrix = Matrix3<f64>;

    fn name() -> String {
        "SO(3)".into()
    }
    #[inline]
    fn dim() -> usize {
        3
    }
    #[inline]
    fn identity() -> Self {
        Self {
            r: Matrix3::identity(),
        }
    }
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        Self {
            r: self.r * other.r,
        }
    }
    /// `R⁻¹ = Rᵀ` (a transpose: nine moves, no arithmetic).
    #[inline]
    fn inverse(&self) -> Self {
        let r = &self.r;
        Self {
            r: Matrix3::new(
                r[(0, 0)],
                r[(1, 0)],
                r[(2, 0)],
                r[(0, 1)],
                r[(1, 1)],
                r[(2, 1)],
                r[(0, 2)],
                r[(1, 2)],
                r[(2, 2)],
            ),
        }
    }
    /// Rodrigues: `exp(ω) = I + (sin θ/θ) ω̂ + ((1 − cos θ)/θ²) ω̂²`, θ = |ω| (any θ, also > π).
    ///
    /// The coefficients are `2 (sin h/θ) cos h` and `2 (sin h/θ)²` with h = θ/2 (`exp_coeffs`):
    /// for θ ≤ π/2 from inlined polynomial kernels evaluated on h² = θ²/4 (no square root, no
    /// division, no libm call), for θ ≤ π from the same kernels on the reduced angle, beyond π
    /// from libm, and below θ = 0.1 from their Taylor series. The matrix is assembled entry by
    /// entry with ω̂² = ωωᵀ − θ²I (`rodrigues_matrix`).
    ///
    /// Beyond |ω| ≈ 1.3·10¹⁵⁴, where θ² overflows, the rotation is taken about the unit axis with
    /// `sin θ`, `1 − cos θ` of the (finite) θ (`huge_rotation`; θ = f64::MAX where |ω| itself
    /// exceeds it): a rotation, never NaN — though at such angles the ulp of θ exceeds 2π, so any
    /// angle about that axis is as good. Non-finite
    /// ω gives a non-finite matrix (the integrators refuse it with an error).
    ///
    /// Always inlined (the huge and trigonometric branches are functions of their own): out of
    /// line, the splittings' steps called it once per exact rotation.
    #[inline(always)]
    fn exp(w: &Vector3<f64>) -> Self {
        let t2 = w.norm_squared();
        if !t2.is_finite() && w.iter().all(|x| x.is_finite()) {
            return huge_rotation(w, |t| {
                let (s, c) = t.sin_cos();
                (s, 1.0 - c)
            });
        }
        let (a, b) = exp_coeffs(t2);
        Self {
            r: rodrigues_matrix(w, a, b),
        }
    }
    /// The principal logarithm, θ ∈ [0, π].
    ///
    /// θ = atan2(|s|, c) with `s = vee(R − Rᵀ)/2 = sin θ · n` and `c = (tr R − 1)/2`, accurate to
    /// round-off everywhere. For c ≥ 0 the axis is `s/|s|` (so ω = (θ/|s|) s, and ω = s at
    /// s = 0); for c < 0 the axis comes from the symmetric part
    /// `(R + Rᵀ)/2 − c I = (1 − cos θ) n nᵀ` (its largest column), with the sign of `s`, so that
    /// at θ = π − 1e-10 the result is accurate to ~1e-15 and at θ = π exactly it is one of the two
    /// valid answers ±π n (the one whose largest component is positive). Never NaN for a rotation;
    /// [`LieError::NonFinite`] for non-finite input.
    ///
    /// Speed: for c ≥ 0 (θ ≤ π/2, the common case) there is no libm call. With the fdlibm
    /// rational fit `asin x = x + x R(x²)` on |x| ≤ ½ (`trig::asin_half`, `trig::acos_half`, within
    /// 1 ulp), three bands, each where its formula has slope ≤ 2 in its input:
    /// - |s| ≤ ½ (θ ≤ π/6): `θ/|s| = asin|s|/|s| = 1 + R(|s|²)`, so ω = (1 + R(|s|²)) s — no
    ///   square root, no special case at s = 0;
    /// - c ≤ ½ (θ ≥ π/3): θ = acos c;
    /// - otherwise (θ ∈ (π/6, π/3)): θ = acos c = 2 asin √((1 − c)/2), where `1 − c` is exact
    ///   (c ∈ [½, 1]) and √((1 − c)/2) < ½;
    ///
    /// then ω = (θ/|s|) s, `1/|s|` taken alongside the fit. The band tests also reject every
    /// non-finite input (one integer compare on the bits of c); everything else (non-finite or
    /// huge entries, c < 0 including the near-π case) is in a separate cold function, so the fast
    /// path inlines and writes the result straight into the caller's slot.
    #[inline(always)]
    fn log(&self) -> Result<Vector3<f64>, LieError> {
        let (s, c) = self.sin_cos_parts();
        let sn2 = s.norm_squared();
        // Every entry of R enters s or c through + or −, so a NaN or an infinity in R makes s or c
        // non-finite. The tests below pass only for finite c ≥ +0 and finite |s|²: for c they
        // compare bit patterns, which for non-negative doubles order like the values, while a
        // negative c (sign bit set) and NaN compare above every finite positive pattern — one
        // integer compare instead of `c >= 0.0 && c <= bound`.
        let cb = c.to_bits();
        if cb < INFINITY_BITS {
            if sn2 <= 0.25 {
                return Ok(s * (1.0 + trig::asin_ratio(sn2)));
            }
            if sn2 <= f64::MAX {
                let inv_sn = 1.0 / sn2.sqrt();
                let theta = if cb <= HALF_BITS {
                    trig::acos_half(c)
                } else {
                    // c > 1 only for a matrix far from SO(3) (|s| > ½ here): clamp to stay finite.
                    2.0 * trig::asin_half(((1.0 - c.min(1.0)) * 0.5).sqrt())
                };
                return Ok(s * (theta * inv_sn));
            }
        }
        self.log_rare()
    }
    #[inline]
    fn hat(w: &Vector3<f64>) -> Matrix3<f64> {
        skew(w)
    }
    /// Reads ω from the skew part `(m − mᵀ)/2` (the symmetric part is ignored).
    #[inline]
    fn vee(m: &Matrix3<f64>) -> Vector3<f64> {
        0.5 * Vector3::new(
            m[(2, 1)] - m[(1, 2)],
            m[(0, 2)] - m[(2, 0)],
            m[(1, 0)] - m[(0, 1)],
        )
    }
    #[inline]
    fn matrix(&self) -> Matrix3<f64> {
        self.r
    }
    /// Checked with [`ORTHOGONALITY_TOLERANCE`], see [`So3::from_matrix_with_tolerance`].
    fn from_matrix(m: &Matrix3<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, ORTHOGONALITY_TOLERANCE)
    }
    #[inline]
    fn from_matrix_unchecked(m: &Matrix3<f64>) -> Self {
        Self { r: *m }
    }
    /// `Ad_R = R`.
    #[inline]
    fn adjoint(&self) -> Matrix3<f64> {
        self.r
    }
    /// `ad_ω = ω̂`.
    #[inline]
    fn ad(w: &Vector3<f64>) -> Matrix3<f64> {
        skew(w)
    }
    /// `Ad_R ξ = R ξ`.
    #[inline]
    fn adjoint_apply(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.r * xi
    }
    /// `Ad_{R⁻¹} ξ = Rᵀ ξ`.
    #[inline]
    fn adjoint_inverse_apply(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.r.tr_mul(xi)
    }
    /// `M(μ): δ ↦ ad*_δ μ = μ × δ`, i.e. μ̂.
    #[inline]
    fn ad_dual_operator(mu: &Vector3<f64>) -> Matrix3<f64> {
        skew(mu)
    }
    /// `Ad*_R μ = Rᵀ μ`.
    #[inline]
    fn coadjoint_apply(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.r.tr_mul(mu)
    }
    /// `(Ad*_{exp ω} − I) μ = a (μ × ω) + b ω × (ω × μ)` (exp ω = I + a ω̂ + b ω̂², a = sin θ/θ,
    /// b = (1 − cos θ)/θ²), computed from ω.
    #[inline]
    fn exp_coadjoint_increment(w: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        let (a, b) = exp_coeffs(w.norm_squared());
        coadjoint_increment(w, mu, a, b)
    }
    /// `(Ad_{exp ω} − I) v = a ω × v + b ω × (ω × v)` (Ad_R = R; a, b as for
    /// [`LieGroup::exp_coadjoint_increment`]), computed from ω.
    #[inline]
    fn exp_adjoint_increment(w: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
        let (a, b) = exp_coeffs(w.norm_squared());
        adjoint_increment(w, v, a, b)
    }
    /// `R exp ω = R + R (a ω̂ + b ω̂²)`: the increment formed without the identity, R rounded once.
    #[inline(always)]
    fn exp_compose(g: &Self, w: &Vector3<f64>) -> Self {
        let (a, b) = exp_coeffs(w.norm_squared());
        Self {
            r: g.r + mul3(&g.r, &rodrigues_increment(w, a, b)),
        }
    }
    /// `[ξ, η] = ξ × η`.
    #[inline]
    fn bracket(xi: &Vector3<f64>, eta: &Vector3<f64>) -> Vector3<f64> {
        xi.cross(eta)
    }
    /// `ad*_ξ μ = ξ̂ᵀ μ = μ × ξ`.
    #[inline]
    fn ad_dual_apply(xi: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        mu.cross(xi)
    }
    /// `d^L exp_ω = I − ((1 − cos θ)/θ²) ω̂ + ((θ − sin θ)/θ³) ω̂²` (the right Jacobian J_r).
    ///
    /// One `sin_cos(θ)` for both coefficients (`rodrigues_coeffs`), matrix entry by entry.
    #[inline]
    fn dexp_left(w: &Vector3<f64>) -> Matrix3<f64> {
        let (_, b, c) = rodrigues_coeffs(w.norm_squared());
        rodrigues_matrix(w, -b, c)
    }
    /// `d^{L*}exp_ω μ = μ + ((1 − cos θ)/θ²) ω×μ + ((θ − sin θ)/θ³) ω×(ω×μ)` (the transpose of
    /// [`LieGroup::dexp_left`]: ω̂ᵀ = −ω̂, (ω̂²)ᵀ = ω̂²), without the matrix.
    #[inline]
    fn dexp_left_dual_apply(w: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        let (_, b, c) = rodrigues_coeffs(w.norm_squared());
        let wm = w.cross(mu);
        mu + wm * b + w.cross(&wm) * c
    }
    /// `(d^L exp_ω)⁻¹ = I + ω̂/2 + (1/θ² − (1 + cos θ)/(2θ sin θ)) ω̂²`; infinite entries at θ = 2π.
    #[inline]
    fn dexp_left_inv(w: &Vector3<f64>) -> Matrix3<f64> {
        rodrigues_matrix(w, 0.5, dexp_inv_coeff(w.norm_squared()))
    }
    /// The exact `∂/∂ω (d^{L*}exp_ω μ)`. With `d^{L*}exp_ω μ = μ + a ω×μ + b ω×(ω×μ)`,
    /// a = (1 − cos θ)/θ², b = (θ − sin θ)/θ³ (the transpose of [`LieGroup::dexp_left`]),
    /// and a′, b′ their derivatives in θ² (`dexp_dual_coeff_derivs`):
    ///
    /// `D = 2a′ (ω×μ) ωᵀ + 2b′ (ω×(ω×μ)) ωᵀ − a μ̂ − b ((ω×μ)^ + ω̂ μ̂)`,
    ///
    /// from `∂θ²/∂ω = 2ωᵀ`, `δ×v = −v̂ δ` and `ω×(δ×μ) = −ω̂ μ̂ δ`; at ω = 0 it is `−½ μ̂`, i.e.
    /// `δ ↦ −½ ad*_δ μ`.
    fn dexp_left_dual_derivative(w: &Vector3<f64>, mu: &Vector3<f64>) -> Matrix3<f64> {
        let t2 = w.norm_squared();
        let (_, a, b) = rodrigues_coeffs(t2);
        let (da, db) = dexp_dual_coeff_derivs(t2);
        let wm = w.cross(mu);
        let wwm = w.cross(&wm);
        // With ω̂ μ̂ = μ ωᵀ − (ω·μ) I and μ̂, (ω×μ)^ linear in their vectors:
        // D = (2a′ ω×μ + 2b′ ω×(ω×μ) − b μ) ωᵀ + b (ω·μ) I − (a μ + b ω×μ)^.
        let mut d =
            outer(&(wm * (2.0 * da) + wwm * (2.0 * db) - mu * b), w) - skew(&(mu * a + wm * b));
        let diag = b * w.dot(mu);
        d[(0, 0)] += diag;
        d[(1, 1)] += diag;
        d[(2, 2)] += diag;
        d
    }
    #[inline]
    fn is_finite(&self) -> bool {
        // Branch-free: the AND of the nine entries' own tests (see the vectors' `is_finite`).
        self.r.iter().fold(true, |ok, x| ok & x.is_finite())
    }
    #[inline]
    fn matrix_distance(&self, other: &Self) -> f64 {
        (self.r - other.r).amax()
    }
}

impl CayleyGroup for So3 {
    /// cay is a diffeomorphism onto the elements whose rotation part is not a rotation by π; the
    /// round trip loses ≈ ε‖ξ‖² relative accuracy as g + I nears singularity (checked up to r).
    const CAY_INVERTIBLE_RADIUS: f64 = 1000.0;
    /// `cay(ω) = (I − ω̂/2)⁻¹(I + ω̂/2) = I + 4/(4 + θ²) (ω̂ + ω̂²/2)`.
    #[inline]
    fn cay(w: &Vector3<f64>) -> Self {
        let t2 = w.norm_squared();
        if !t2.is_finite() && w.iter().all(|x| x.is_finite()) {
            // cay(sn) = I + (4s/(4 + s²)) n̂ + (2s²/(4 + s²)) n̂² → I + 2n̂² (the half turn) as s → ∞.
            return huge_rotation(w, |s| (4.0 / s, 2.0 / (1.0 + 4.0 / (s * s))));
        }
        let a = 4.0 / (4.0 + t2);
        Self {
            r: rodrigues_matrix(w, a, 0.5 * a),
        }
    }
    /// `(Ad*_{cay ω} − I) μ = a (μ × ω) + (a/2) ω × (ω × μ)`, a = 4/(4 + |ω|²).
    #[inline]
    fn cay_coadjoint_increment(w: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        let a = 4.0 / (4.0 + w.norm_squared());
        coadjoint_increment(w, mu, a, 0.5 * a)
    }
    /// `(Ad_{cay ω} − I) v = a (ω × v) + (a/2) ω × (ω × v)`, a = 4/(4 + |ω|²).
    #[inline]
    fn cay_adjoint_increment(w: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
        let a = 4.0 / (4.0 + w.norm_squared());
        adjoint_increment(w, v, a, 0.5 * a)
    }
    /// `R cay ω = R + R (a ω̂ + (a/2) ω̂²)`, the increment form of [`LieGroup::exp_compose`].
    #[inline]
    fn cay_compose(g: &Self, w: &Vector3<f64>) -> Self {
        let a = 4.0 / (4.0 + w.norm_squared());
        Self {
            r: g.r + mul3(&g.r, &rodrigues_increment(w, a, 0.5 * a)),
        }
    }
    /// `R cay(θω) cay((1−θ)ω) = R cay(ω / (1 − θ(1−θ)|ω|²/4))`: cay(ω) is the rotation with Gibbs
    /// vector ω/2, and Gibbs vectors compose as `(a + b + a × b)/(1 − a·b)` (the cross term
    /// vanishing for parallel ones). Used while the denominator is at least ½ (a total angle up to
    /// 2·atan(…) ≈ 141°, far beyond any integrator step); beyond it, the two products. The
    /// coefficients of `cay(ω/den) − I = A ω̂ + B ω̂²` come from `cay_split_coeffs` (one
    /// division, shared with [`CayleyGroup::cay_split_coadjoint_increment`] of the same step).
    #[inline(always)]
    fn cay_split_compose(g: &Self, theta: f64, w: &Vector3<f64>) -> Self {
        match cay_split_coeffs(theta, w) {
            Some((a, b)) => Self {
                r: g.r + mul3(&g.r, &rodrigues_increment(w, a, b)),
            },
            None => Self::cay_compose(&Self::cay_compose(g, &(w * theta)), &(w * (1.0 - theta))),
        }
    }
    /// `(Ad*_{cay((1−θ)ω)} Ad*_{cay(θω)} − I) μ = (Ad*_{cay(ω/den)} − I) μ`,
    /// den = 1 − θ(1−θ)|ω|²/4, as [`CayleyGroup::cay_split_compose`] (and on the same switch, with
    /// the same coefficients).
    #[inline]
    fn cay_split_coadjoint_increment(
        theta: f64,
        w: &Vector3<f64>,
        mu: &Vector3<f64>,
    ) -> Vector3<f64> {
        match cay_split_coeffs(theta, w) {
            Some((a, b)) => coadjoint_increment(w, mu, a, b),
            None => crate::tau::split_increment_of_factors::<Self, crate::Cayley>(theta, w, mu),
        }
    }
    /// `½ d^{L*}cay_{−a}(μ + Ad*_{cay a} μ) = c (μ + δ_a μ)`, c = 4/(4 + |a|²), δ_a = Ad*_{cay a} − I:
    /// with `d^{L*}cay_{−a} = c (I − â/2)` and `μ + cay(a)ᵀμ = 2 (I + â/2)⁻¹ μ`, the product is
    /// `c (I − â/2)(I + â/2)⁻¹ μ = c cay(a)ᵀ μ`. One division (the composition takes two).
    /// Always inlined: it is the Lie–Poisson θ = ½ residual.
    #[inline(always)]
    fn cay_midpoint_base_momentum(a: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        let c = 4.0 / (4.0 + a.norm_squared());
        (mu + coadjoint_increment(a, mu, c, 0.5 * c)) * c
    }
    /// `cay⁻¹(R) = 2 vee(R − Rᵀ)/(1 + tr R)` (the closed form of `2 (R − I)(R + I)⁻¹`); an error
    /// where `1 + tr R ≤ 1e-14`, i.e. at rotations by π, where R + I is singular.
    fn cay_inv(&self) -> Result<Vector3<f64>, LieError> {
        if !self.is_finite() {
            return Err(LieError::NonFinite {
                what: "rotation matrix",
            });
        }
        let den = 1.0 + self.r.trace();
        if den <= 1e-14 {
            return Err(LieError::OutOfDomain(DomainReason::CayleyRotationByPi {
                one_plus_trace: den,
            }));
        }
        let (s, _) = self.sin_cos_parts();
        Ok(s * (4.0 / den))
    }
    /// `d^L cay_ω = 2/(4 + θ²) (2I − ω̂)`.
    #[inline]
    fn dcay_left(w: &Vector3<f64>) -> Matrix3<f64> {
        (Matrix3::identity() * 2.0 - skew(w)) * (2.0 / (4.0 + w.norm_squared()))
    }
    /// `d^{L*}cay_ω μ = 2 (2μ + ω×μ)/(4 + θ²)` (the transpose of [`CayleyGroup::dcay_left`]),
    /// without the matrix.
    #[inline]
    fn dcay_left_dual_apply(w: &Vector3<f64>, mu: &Vector3<f64>) -> Vector3<f64> {
        (mu * 2.0 + w.cross(mu)) * (2.0 / (4.0 + w.norm_squared()))
    }
    /// `(d^L cay_ω)⁻¹ = I + ω̂/2 + ω ωᵀ/4`.
    #[inline]
    fn dcay_left_inv(w: &Vector3<f64>) -> Matrix3<f64> {
        Matrix3::identity() + skew(w) * 0.5 + w * w.transpose() * 0.25
    }
    /// The exact `∂/∂ω (d^{L*}cay_ω μ)`. With `d^{L*}cay_ω μ = c (2μ + ω×μ)`, c = 2/(4 + θ²)
    /// (the transpose of [`CayleyGroup::dcay_left`]) and `∂c/∂ω = −4ωᵀ/(4 + θ²)²`:
    ///
    /// `D = −4/(4 + θ²)² (2μ + ω×μ) ωᵀ − c μ̂`  (no small-angle branch: no division by θ);
    /// at ω = 0 it is `−½ μ̂`, i.e. `δ ↦ −½ ad*_δ μ`.
    #[inline]
    fn dcay_left_dual_derivative(w: &Vector3<f64>, mu: &Vector3<f64>) -> Matrix3<f64> {
        let d = 4.0 + w.norm_squared();
        let c = 2.0 / d;
        outer(&((mu * 2.0 + w.cross(mu)) * (-2.0 * c / d)), w) - skew(&(mu * c))
    }
}

/// Rotation of vectors: `R · p`.
impl Action<Vector3<f64>> for So3 {
    type PointJacobian = Matrix3<f64>;
    type GroupJacobian = Matrix3<f64>;
    #[inline]
    fn act(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.r * p
    }
    /// `R`.
    #[inline]
    fn act_jacobian_point(&self, _p: &Vector3<f64>) -> Matrix3<f64> {
        self.r
    }
    /// `R exp(δ) p ≈ R (p + δ × p)`: `−R p̂`.
    #[inline]
    fn act_jacobian_left(&self, p: &Vector3<f64>) -> Matrix3<f64> {
        -(self.r * skew(p))
    }
    /// `exp(δ) R p ≈ R p + δ × (R p)`: `−(R p)^`.
    #[inline]
    fn act_jacobian_right(&self, p: &Vector3<f64>) -> Matrix3<f64> {
        -skew(&(self.r * p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The small-angle series (below θ = 0.1) against 40-digit values (mpmath: sin θ/θ,
    /// (1 − cos θ)/θ², (θ − sin θ)/θ³, (1 − (θ/2)cot(θ/2))/θ² at the listed θ²), up to the branch's
    /// edge: each within 2 ulps. (`dexp_inv_coeff` stopped at θ⁶ would be 2.4e-15 off at the
    /// edge: this test fails then.)
    #[test]
    #[allow(clippy::excessive_precision)] // mpmath's digits, kept verbatim
    fn small_angle_series_are_within_two_ulps_up_to_the_branch_edge() {
        let cases: [(f64, [f64; 4]); 4] = [
            (
                1e-6,
                [
                    0.99999983333334166667,
                    0.49999995833333472222,
                    0.16666665833333353175,
                    0.083333334722222255291,
                ],
            ),
            (
                1e-4,
                [
                    0.99998333341666646825,
                    0.49999583334722219742,
                    0.16666583333531745756,
                    0.08333347222255291088,
                ],
            ),
            (
                0.0025,
                [
                    0.9995833854135665759,
                    0.49989584201350137485,
                    0.16664583457336964108,
                    0.083336805762248368044,
                ],
            ),
            (
                0.0099,
                [
                    0.99835081655750682621,
                    0.49958763610093769159,
                    0.1665841861104215948,
                    0.083347086575207127675,
                ],
            ),
        ];
        for (t2, exact) in cases {
            assert!(t2 < SMALL_ANGLE_SQ);
            let got = [sinc(t2), cosc(t2), sinc3(t2), dexp_inv_coeff(t2)];
            for (name, (g, e)) in ["sinc", "cosc", "sinc3", "dexp_inv_coeff"]
                .iter()
                .zip(got.iter().zip(exact))
            {
                let rel = ((g - e) / e).abs();
                assert!(rel <= 2.0 * f64::EPSILON, "{name}({t2}): {rel:e} relative");
            }
            assert_eq!(exp_coeffs(t2), (sinc(t2), cosc(t2)));
            assert_eq!(rodrigues_coeffs(t2), (sinc(t2), cosc(t2), sinc3(t2)));
        }
    }

    /// The fast path of `log` decides finiteness from s and c alone: every entry, set to NaN, +∞
    /// or −∞ in turn (on a small, a medium and a large rotation, i.e. in every band), must give
    /// `NonFinite`, never `Ok`.
    #[test]
    fn log_rejects_every_non_finite_entry_in_every_band() {
        for w in [
            Vector3::new(0.01, 0.02, -0.03),
            Vector3::new(0.3, -0.4, 0.5),
            Vector3::new(0.6, -0.7, 1.1),
        ] {
            let r = *So3::exp(&w).as_matrix();
            for k in 0..9 {
                for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    let mut m = r;
                    m[k] = bad;
                    let res = So3::from_matrix_unchecked(&m).log();
                    assert!(
                        matches!(res, Err(LieError::NonFinite { .. })),
                        "entry {k} = {bad}, ω = {w:?}: {res:?}"
                    );
                }
            }
        }
    }

    /// Round-off drift can push c = (tr R − 1)/2 just above 1 near the identity, or make the
    /// matrix slightly non-orthogonal elsewhere: the result stays finite and close to the
    /// rotation's log.
    #[test]
    fn log_of_drifted_rotations_is_finite_and_close() {
        let mut m = Matrix3::identity();
        m[(0, 0)] += 4e-16;
        m[(1, 1)] += 4e-16;
        let w = So3::from_matrix_unchecked(&m).log().unwrap();
        assert!(w.iter().all(|x| x.is_finite()) && w.norm() < 1e-15);
        for w in [
            Vector3::new(0.2, 0.1, 0.0),
            Vector3::new(0.5, 0.5, 0.5),
            Vector3::new(1.0, 0.3, 0.9),
        ] {
            let m = So3::exp(&w).as_matrix() * (1.0 + 1e-12);
            let back = So3::from_matrix_unchecked(&m).log().unwrap();
            assert!((back - w).amax() < 1e-11, "{w:?} → {back:?}");
        }
    }
}
