//! The exact flow of the free rigid body, Π(t) and R(t), with Jacobi elliptic functions.

use super::elliptic::{Jacobi, Modulus, QuarterPhase};
use crate::exact::AxisymmetricFlow;
use crate::systems::RigidBody;
use core::f64::consts::{FRAC_PI_2, LN_2};
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
/// when `D₂ = |Π|² − 2hI₂ > 0`, the smallest when D₂ < 0) and Π₃ ≥ 0:
///
/// ```text
/// Π₁ = A₁ cn u,  Π₂ = σ A₂ sn u,  Π₃ = A₃ dn u,  u = u₀ + λt,  σ = sign(I₃ − I₂),
/// A₁² = D₃I₁/(I₃−I₁), A₂² = D₃I₂/(I₃−I₂), A₃² = D₁I₃/(I₃−I₁), λ² = (I₃−I₂)D₁/(I₁I₂I₃),
/// k² = (I₂−I₁)D₃/((I₃−I₂)D₁),  k'² = (I₃−I₁)D₂/((I₃−I₂)D₁),
/// ```
///
/// with `Dᵢ = ±(|Π|² − 2hIᵢ)`; D₁ and D₃ are sums of same-sign terms (no cancellation).
///
/// **The separatrix** (D₂ = 0, k = 1) is decided in exact arithmetic: `I₁I₃D₂ =
/// Π₃²I₁(I₃−I₂) − Π₁²I₃(I₂−I₁)` is evaluated in double-double arithmetic (Dekker's exact
/// products), and where that leaves its sign in doubt (|D₂| < 2⁻⁴⁸ of its terms), exactly, as a
/// nonoverlapping expansion of its 32 exact partial products (Shewchuk 1997). Π is first scaled by
/// a power of two, which is exact, so the decision and the value of D₂ (to relative 2⁻⁵²) are
/// those of the input itself: a state is on the separatrix only if it is on it in exact
/// arithmetic, and a state within an ulp of it gets its own k'² and its own period. (For a
/// non-diagonal 𝕀 this holds for Π in the principal frame, after its rounded rotation.)
///
/// **The phase** is kept as u = nK + w with |w| ≤ K/2 ([`QuarterPhase`]), sn, cn, dn are taken at
/// w and shifted by the quarter period ([`Modulus`]), so a component near its zero keeps its
/// relative accuracy. For k' < 2⁻⁶⁰ (within ~10⁻³⁶ of the separatrix) the functions of w are
/// their k = 1 limits tanh, sech to below rounding and K = ln(4/k'); on the separatrix K = ∞ and
/// u never wraps: Π approaches the middle axis for every t without underflow (no NaN, no error).
///
/// **R(t)** (after Celledoni, Fassò, Säfström, Zanna, "The exact computation of the free rigid
/// body motion and its use in splitting methods", SIAM J. Sci. Comput. 30 (2008), and van Zon &
/// Schofield, J. Comput. Phys. 225 (2007)). The spatial momentum m = RΠ is constant. With B(n) the
/// minimal rotation taking e₃ to n = Π/|Π| (well conditioned: n₃ ≥ 0),
/// `R(t) = R(0) P B(n₀) exp(Δψ ê₃) B(n(t))ᵀ Pᵀ` (P the relabelling) for the angle
///
/// ```text
/// ψ̇ = |Π|/I₃ + (2h − |Π|²/I₃)/(|Π| + Π₃),
/// Δψ = |Π|t/I₃ + (I₃−I₁)/(I₁I₃λ) · [|Π| ΔΛ − A₃ ΔG],
/// Λ(u) = Π(−β; am u, k),  β = I₃(I₂−I₁)/(I₁(I₃−I₂)),  G(φ) = atan2(√(1+β) sin φ, cos φ)/√(1+β),
/// ```
///
/// Λ the incomplete elliptic integral of the third kind, continued in u as c·u + n·L plus a
/// bounded part of w ([`Modulus::third_kind_part`]), G likewise with G(φ + π) = G(φ) + π/√(1+β),
/// so the cost is independent of t; near and on the separatrix both have closed forms. Time is
/// scaled by the power of two of |Π| (the flow is homogeneous), so |Π| from 10⁻¹⁵⁰ to 10¹⁵⁰
/// costs no range. Bodies with two equal moments use the closed form of [`AxisymmetricFlow`]; Π
/// along a principal axis is a steady rotation.
///
/// **Accuracy** (`tests/models/exact_flow.rs`, against mpmath references made by the scripts in
/// `tests/data/`; "the spread" is that of the true solutions of the inputs within ±2 ulps of Π₀,
/// the problem's own conditioning; measured figures, then the tests' bounds):
/// - generic states (300 random bodies and momenta, a fifth with a component 10⁻² to 10⁻⁶ of
///   |Π|; t = 1, 10): each component of Π within 5.4 ulps of its own size where the spread is
///   below 8 ulps of it (bound 16); elsewhere within 2.9× the spread (bound 16 ulps + 2×): a
///   component near its zero moves by ε·λt|Π| when Π₀ moves by an ulp, up to 418 ulps of it;
/// - near the separatrix (issue #29's family: 1000 states within ulps of it, on either side or on
///   it; t = 1, 10, 1000): Π within 0.28× the spread, or of 4ε(1 + λt)|Π| where the spread is
///   below that (bound 1.5×); with R, states an ulp off it, family states whose discriminant
///   rounds to 0 in doubles, and states 10⁻¹⁰ to 2·10⁻¹⁹ from the middle axis (the last past
///   k' = 2⁻⁶⁰, where the k = 1 limits take over): 0.49× the same (bound 2×);
/// - on and within 2 ulps of the separatrix of the nearly symmetric body 𝕀 = (2, 2(1 + 10⁻¹²), 3),
///   where λ ≈ 3·10⁻⁷ and the precession Δψ multiplies the change of Λ by |Π|(I₃ − I₁)/(I₁I₃λ)
///   (t = 1, 10, 1000): Π and R within 0.23× the same (bound 2×), where a difference of two values
///   of Λ(w) of size K left R 4e-12 to 4e-10 off (Λ's slope form for β < 1 and the DLMF 19.7.9
///   form for β ≥ 1, [`Modulus::third_kind_part`]);
/// - on the separatrix (in exact arithmetic): Π and R within 0.5 ε(1 + |Π|t/I_min) (bound 2) to
///   t = 10⁶ (the phase's own rounding; the neighbours, off the separatrix, spread by O(1)), and
///   no error or NaN for the family to t = ±10⁶;
/// - every regime of `free_body_reference.txt` (symmetric bodies, principal axes, a full 𝕀,
///   t < 0, …): within 1.8e-15 of a 40-digit integration.
///
/// ```
/// use mechanics::{exact::FreeBodyFlow, systems::RigidBody};
/// use lie_groups::{LieGroup, So3};
/// use nalgebra::Vector3;
///
/// let flow = FreeBodyFlow::new(&RigidBody::principal([1.0, 2.0, 3.0])?);
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
    /// The principal frame is not the body frame (𝕀 is not diagonal).
    turned: bool,
    moments: Vector3<f64>,
    axisymmetric: Option<AxisymmetricFlow>,
    separatrix: SeparatrixTest,
    /// The constants of the two regimes: circulation about the largest moment (D₂ ≥ 0) and
    /// about the smallest (D₂ < 0).
    regimes: [Regime; 2],
}

/// The sign and value of I_lo·I_hi·D₂ = Π_hi²·I_lo(I_hi − I_mid) − Π_lo²·I_hi(I_mid − I_lo),
/// exactly: the moments scaled by a power of two, the two coefficients as exact expansions.
#[derive(Debug, Clone)]
struct SeparatrixTest {
    lo: usize,
    mid: usize,
    hi: usize,
    /// I_hi(I_mid − I_lo) and I_lo(I_hi − I_mid) (scaled moments), exactly: four terms each.
    coefficients: [[f64; 4]; 2],
    /// Their double-double roundings.
    dd: [(f64, f64); 2],
}

/// The constants of one labelling (c₁, c₂, c₃) of the principal axes. The amplitudes are
/// computed from the moments on every call (as products and quotients of the state's own terms):
/// a precomputed factor would carry one rounding into every restart of the flow, the same one,
/// and bias |Π|² and h step after step.
#[derive(Debug, Clone)]
struct Regime {
    axes: [usize; 3],
    /// The permutation matrix with rows e_{c₁}, e_{c₂}, e_{c₃}, and its determinant.
    perm: Matrix3<f64>,
    parity: f64,
    /// (I₁, I₂, I₃) of the labelling.
    moments: [f64; 3],
    sigma: f64,
    /// √|I₁/(I₃ − I₁)|, √|I₂/(I₃ − I₂)|: (sin φ₀, cos φ₀) ∝ (σΠ₂ρ₁, Π₁ρ₂).
    rho: [f64; 2],
    /// I_lo, I_hi of the separatrix test (scaled).
    scaled: [f64; 2],
    beta: f64,
    /// (I₃ − I₁)/(I₁I₃).
    psi_factor: f64,
}

/// B(n): the rotation about e₃ × n taking e₃ to the unit vector n (n₃ > −1).
fn minimal_rotation(n: &Vector3<f64>) -> Matrix3<f64> {
    let v = Vector3::new(-n.y, n.x, 0.0);
    let vh = v.cross_matrix();
    Matrix3::identity() + vh + vh * vh / (1.0 + n.z)
}

/// ⌊log₂|x|⌋ for finite x ≠ 0 (subnormals included).
fn binade(x: f64) -> i32 {
    let bits = x.abs().to_bits();
    let e = (bits >> 52) as i32;
    if e == 0 {
        // Subnormal: 2⁻¹⁰⁷⁴ times its integer mantissa.
        63 - bits.leading_zeros() as i32 - 1074
    } else {
        e - 1023
    }
}

/// 2ᵏ for −2098 ≤ k ≤ 2046, as a product of two doubles when one would overflow or underflow:
/// `scale(x, k)` = x·2ᵏ exactly unless the result is subnormal.
fn scale(x: f64, k: i32) -> f64 {
    let half = k / 2;
    x * pow2(half) * pow2(k - half)
}

fn pow2(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// a·b = p + e exactly (Dekker's product: no fused multiply–add needed), for |a|, |b| < 2⁹⁹⁶
/// and products away from underflow.
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let split = |x: f64| {
        let t = 134_217_729.0 * x; // 2²⁷ + 1
        let hi = t - (t - x);
        (hi, x - hi)
    };
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// a + b = s + e exactly (Knuth).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Adds b to the nonoverlapping expansion e[..len] (increasing magnitude), dropping zeros
/// (Shewchuk's GROW-EXPANSION with zero elimination).
fn grow_expansion(e: &mut [f64; 40], len: &mut usize, b: f64) {
    if b == 0.0 {
        return;
    }
    let mut q = b;
    let mut k = 0;
    for i in 0..*len {
        let (s, err) = two_sum(q, e[i]);
        q = s;
        if err != 0.0 {
            e[k] = err;
            k += 1;
        }
    }
    if q != 0.0 {
        e[k] = q;
        k += 1;
    }
    *len = k;
}

impl SeparatrixTest {
    fn new(moments: &Vector3<f64>) -> Self {
        let (mut lo, mut mid, mut hi) = (0usize, 1usize, 2usize);
        if moments[lo] > moments[mid] {
            (lo, mid) = (mid, lo);
        }
        if moments[mid] > moments[hi] {
            (mid, hi) = (hi, mid);
        }
        if moments[lo] > moments[mid] {
            (lo, mid) = (mid, lo);
        }
        let s = -binade(moments[hi]);
        let i = moments.map(|x| scale(x, s));
        // c·(a − b) as four exact terms: a − b = d + d' (two_sum), c·d and c·d' two products each.
        let exact = |c: f64, a: f64, b: f64| {
            let (d, dl) = two_sum(a, -b);
            let (p, pl) = two_prod(c, d);
            let (q, ql) = two_prod(c, dl);
            [p, pl, q, ql]
        };
        let coefficients = [exact(i[hi], i[mid], i[lo]), exact(i[lo], i[hi], i[mid])];
        let dd = coefficients.map(|t| two_sum(t[0], t[1] + t[2] + t[3]));
        Self {
            lo,
            mid,
            hi,
            coefficients,
            dd,
        }
    }

    /// I_lo I_hi D₂ for (Π_lo, Π_hi) = (x_lo, x_hi) (scaled moments), with its exact sign and
    /// to relative 2⁻⁵²; 0 exactly on the separatrix.
    fn eval(&self, x_lo: f64, x_hi: f64) -> f64 {
        let [(ah, al), (bh, bl)] = self.dd;
        let (yh, yl) = {
            let (xh, xl) = two_prod(x_hi, x_hi);
            let (p, e) = two_prod(xh, bh);
            (p, e + (xh * bl + xl * bh))
        };
        let (zh, zl) = {
            let (xh, xl) = two_prod(x_lo, x_lo);
            let (p, e) = two_prod(xh, ah);
            (p, e + (xh * al + xl * ah))
        };
        let (s, e) = two_sum(yh, -zh);
        let d = s + (e + (yl - zl));
        // The double-double error is below 2⁻¹⁰⁰(|y| + |z|): beyond 2⁻⁴⁸ of it, d has its sign
        // and 52 bits.
        if d.abs() > (yh.abs() + zh.abs()) * 3.552_713_678_800_501e-15 {
            return d;
        }
        let mut e = [0.0f64; 40];
        let mut len = 0;
        for (x, coefficient, sign) in [
            (x_hi, &self.coefficients[1], 1.0),
            (x_lo, &self.coefficients[0], -1.0),
        ] {
            let (xh, xl) = two_prod(x, x);
            for &c in coefficient {
                for xp in [xh, xl] {
                    let (p, pe) = two_prod(xp, c);
                    grow_expansion(&mut e, &mut len, sign * p);
                    grow_expansion(&mut e, &mut len, sign * pe);
                }
            }
        }
        // Nonoverlapping and increasing: the sum from the smallest is the value to rounding.
        e[..len].iter().sum()
    }
}

impl Regime {
    fn new(moments: &Vector3<f64>, axes: [usize; 3], test: &SeparatrixTest) -> Self {
        let [c1, c2, c3] = axes;
        let (i1, i2, i3) = (moments[c1], moments[c2], moments[c3]);
        let s = -binade(moments[test.hi]);
        let mut perm = Matrix3::zeros();
        for (row, &c) in axes.iter().enumerate() {
            perm[(row, c)] = 1.0;
        }
        Self {
            axes,
            perm,
            parity: perm.determinant(),
            moments: [i1, i2, i3],
            sigma: (i3 - i2).signum(),
            rho: [(i1 / (i3 - i1)).abs().sqrt(), (i2 / (i3 - i2)).abs().sqrt()],
            scaled: [scale(moments[test.lo], s), scale(moments[test.hi], s)],
            beta: i3 * (i2 - i1) / (i1 * (i3 - i2)),
            psi_factor: (i3 - i1) / (i1 * i3),
        }
    }
}

/// One orbit of the flow, its constants computed once from (Π₀, R₀): evaluating it at t costs
/// only the t-dependent part (sn, cn, dn, one third-kind integral, the rotation), and every value
/// comes from the same constants (so the same invariants |Π|², h, RΠ), so that a sequence of
/// evaluations does not accumulate rounding in them.
#[derive(Debug, Clone)]
pub(crate) struct Orbit {
    pi0: Vector3<f64>,
    r0: Option<So3>,
    /// |Π|/I_min: the fastest angular rate, for the phase limit.
    rate: f64,
    kind: OrbitKind,
}

// Built on every `advance`: boxing the elliptic variant would allocate on the hot path.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
enum OrbitKind {
    /// Π = 0.
    Rest,
    /// Π along a principal axis: R(t) = R₀ exp(tΩ).
    Steady(Vector3<f64>),
    Axisymmetric,
    Elliptic(Elliptic),
}

#[derive(Debug, Clone)]
struct Elliptic {
    /// 2ᵉ: Π = 2ᵉ P q, with q the scaled canonical momentum (max |qᵢ| in [1, 2)).
    scale: f64,
    /// P: canonical → body.
    pmat: Matrix3<f64>,
    /// (A₁, σA₂, A₃) of q.
    amplitudes: Vector3<f64>,
    lambda: f64,
    modulus: Modulus,
    phase0: QuarterPhase,
    attitude: Option<Attitude>,
}

impl Elliptic {
    /// The scaled canonical momentum q = (A₁ cn, σA₂ sn, A₃ dn) at the functions' values.
    #[inline]
    fn canonical(&self, jac: &Jacobi) -> Vector3<f64> {
        let a = &self.amplitudes;
        Vector3::new(a.x * jac.cn, a.y * jac.sn, a.z * jac.dn)
    }

    /// Π = 2ᵉ P q at the phase u, as [`FreeBodyFlow::evaluate`] forms it.
    fn momentum(&self, phase: QuarterPhase) -> Vector3<f64> {
        self.pmat * self.canonical(&self.modulus.jacobi(phase)) * self.scale
    }
}

/// The constants of a generic elliptic orbit of the free rigid body with its attitude
/// ([`FreeBodyFlow::elliptic_orbit`]), in the notation of [`FreeBodyFlow`]: at time t, with
/// τ = 2ᵉt and u = u₀ + λτ = nK + w,
///
/// ```text
/// Π(t) = 2ᵉ P (A₁ cn u, σA₂ sn u, A₃ dn u),
/// R(t) = R₀ P B(n₀) exp(Δψ ê₃) B(q(t)/|q|)ᵀ Pᵀ,
/// Δψ = |q|τ/I₃ + (I₃ − I₁)/(I₁I₃λ) · [|q| ΔΛ − A₃ ΔG],
/// ```
///
/// ΔΛ = c·λτ + Δn·L + B(n, w) − B(n₀, w₀) (c = 1 for β < 1, 0 for β ≥ 1;
/// [`Modulus::third_kind_part`]) and ΔG = (Δn·π/2 + atan_G(u) − atan_G(u₀))/√(1 + β), each
/// continued by its quarter periods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticOrbit {
    /// |Π|/I_min: the phase limit holds while |t|·rate < 2⁵².
    pub rate: f64,
    /// 2ᵉ: Π = 2ᵉ P q, q the scaled canonical momentum.
    pub scale: f64,
    /// P: canonical → body frame (a signed permutation, times the principal axes).
    pub pmat: Matrix3<f64>,
    /// (A₁, σA₂, A₃) of q.
    pub amplitudes: [f64; 3],
    /// λ: u = u₀ + λτ.
    pub lambda: f64,
    /// k'² of the modulus (≥ 2⁻¹²⁰).
    pub kc2: f64,
    /// k' = √k'².
    pub kc: f64,
    /// The quarter period K.
    pub quarter: f64,
    /// u₀ = n₀K + w₀.
    pub phase0: QuarterPhase,
    /// R₀ P B(n₀).
    pub start: Matrix3<f64>,
    /// |q| and 1/|q|.
    pub norm: f64,
    /// See [`EllipticOrbit::norm`].
    pub inv_norm: f64,
    /// I₃ of the labelling.
    pub i3: f64,
    /// (I₃ − I₁)/(I₁I₃λ).
    pub factor: f64,
    /// β = I₃(I₂ − I₁)/(I₁(I₃ − I₂)).
    pub beta: f64,
    /// √(1 + β).
    pub sb: f64,
    /// L = [`Modulus::third_kind_quarter`]`(β)`.
    pub lambda_quarter: f64,
    /// B(n₀, w₀) = [`Modulus::third_kind_part`] at the start.
    pub part0: f64,
    /// atan_G(u₀): atan(√(1+β) S/C) for even n₀, atan(k'S/(√(1+β) C)) for odd.
    pub atan0: f64,
}

#[derive(Debug, Clone)]
struct Attitude {
    /// R₀ P B(n₀).
    start: Matrix3<f64>,
    /// |q|, 1/|q|.
    norm: f64,
    inv_norm: f64,
    i3: f64,
    /// (I₃ − I₁)/(I₁I₃λ).
    factor: f64,
    beta: f64,
    /// √(1 + β).
    sb: f64,
    /// L of Λ(u) = c·u + n·L + B(n, w) ([`Modulus::third_kind_part`]; NaN: computed when needed).
    lambda_quarter: f64,
    /// The bounded parts of Λ and of atan(√(1+β)·G) at the start.
    part0: f64,
    atan0: f64,
}

impl Attitude {
    /// atan of the reduced G: atan(√(1+β) S/C) in even quarters, atan(k'S/(√(1+β) C)) in odd.
    fn atan(&self, phase: QuarterPhase, jac: &Jacobi) -> f64 {
        if phase.is_odd() {
            (jac.ksc / self.sb).atan()
        } else {
            (self.sb * jac.s / jac.c).atan()
        }
    }
}

impl FreeBodyFlow {
    /// The flow of `body` (its principal frame is computed once, at the body's construction).
    pub fn new(body: &RigidBody) -> Self {
        let (axes, moments) = body.principal_frame();
        let separatrix = SeparatrixTest::new(moments);
        let (lo, mid, hi) = (separatrix.lo, separatrix.mid, separatrix.hi);
        let regimes = [
            Regime::new(moments, [lo, mid, hi], &separatrix),
            Regime::new(moments, [hi, mid, lo], &separatrix),
        ];
        Self {
            axes: *axes,
            turned: *axes != Matrix3::identity(),
            moments: *moments,
            axisymmetric: AxisymmetricFlow::new(body).ok(),
            separatrix,
            regimes,
        }
    }

    /// (Π(t), R(t)) from (Π, R) at time 0; `r = None` advances Π alone (cheaper). t = 0 returns
    /// the input unchanged.
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
        let orbit = self.orbit(pi, r, false)?;
        let (mut pi_t, r_t) = self.evaluate(&orbit, t)?;
        if let (true, OrbitKind::Elliptic(ell)) = (self.turned && t != 0.0, &orbit.kind) {
            // On a turned body Π(t) = A p(t), p(t) from the orbit through p = AᵀΠ in the
            // principal frame A. Restarted at every call (as a kinetic–kick splitting calls it),
            // the orbit's own start A p(0) — off Π by A's departure from orthonormality and by
            // the roundings of the orbit's constants, the same way at every call — would enter
            // each result and drift (|Π|² by ~0.02 ulp a call). Only the increment is taken:
            // Π(t) = Π + A p(t) − A p(0). A diagonal 𝕀 (A = I) takes p(t) itself, which does
            // not drift.
            pi_t += pi - ell.momentum(ell.phase0);
        }
        Ok((pi_t, r_t))
    }

    /// The orbit through (Π, R) (`reuse`: also precompute what only repeated evaluations far
    /// from the start need).
    pub(crate) fn orbit(
        &self,
        pi: &Vector3<f64>,
        r: Option<&So3>,
        reuse: bool,
    ) -> Result<Orbit, IntegratorError> {
        if !pi.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "momentum Π"
            });
        }
        let m = pi.norm();
        let orbit = |kind| Orbit {
            pi0: *pi,
            r0: r.copied(),
            rate: m / self.moments.min(),
            kind,
        };
        if self.axisymmetric.is_some() {
            return Ok(orbit(OrbitKind::Axisymmetric));
        }
        if m == 0.0 {
            return Ok(orbit(OrbitKind::Rest));
        }
        let p = self.axes.tr_mul(pi);
        let steady = || {
            let omega = self.axes * p.component_div(&self.moments);
            Ok(orbit(OrbitKind::Steady(omega)))
        };
        let test = &self.separatrix;
        let (p_lo, p_hi) = (p[test.lo], p[test.hi]);
        if p_lo == 0.0 && p_hi == 0.0 {
            return steady();
        }
        // The side of the separatrix, exactly: I_lo I_hi D₂ of Π scaled by 2^{-e₂}.
        let e2 = binade(p_lo.abs().max(p_hi.abs()));
        let d2 = test.eval(scale(p_lo, -e2), scale(p_hi, -e2));
        let regime = &self.regimes[usize::from(d2 < 0.0)];
        let [c1, c2, c3] = regime.axes;
        // q = Q 2^{-e} p, Q the proper signed permutation with rows s₁e_{c1}, s₂e_{c2}, s₃e_{c3}.
        let e = binade(p.amax());
        let s3 = if p[c3] < 0.0 { -1.0 } else { 1.0 };
        let s2 = regime.parity * s3;
        let q = Vector3::new(p[c1], s2 * p[c2], s3 * p[c3]).map(|x| scale(x, -e));
        if q.iter().filter(|&&x| x == 0.0).count() >= 2 {
            return steady();
        }
        let signs = Vector3::new(1.0, s2, s3);
        let pmat = self.axes * (Matrix3::from_diagonal(&signs) * regime.perm).transpose();
        // Dᵢ = ±(|q|² − 2hIᵢ) as sums of same-sign terms, D₃ scaled by the larger of q₁, q₂ where
        // both are tiny (near the circulation axis).
        let [i1, i2, i3] = regime.moments;
        let (d31, d32) = (i3 - i1, i3 - i2);
        let d1 = q.y * q.y * (i2 - i1) / i2 + q.z * q.z * d31 / i3;
        let r12 = q.x.abs().max(q.y.abs());
        let (x1, x2, r12) = if r12 >= 1e-150 {
            (q.x, q.y, 1.0)
        } else {
            (q.x / r12, q.y / r12, r12)
        };
        let d3 = x1 * x1 * d31 / i1 + x2 * x2 * d32 / i2;
        let amplitudes = Vector3::new(
            r12 * (d3 * i1 / d31).sqrt(),
            regime.sigma * r12 * (d3 * i2 / d32).sqrt(),
            (d1 * i3 / d31).sqrt(),
        );
        let lambda = (d32 * d1 / (i1 * i2 * i3)).sqrt();
        // k'² = (I₃ − I₁)D₂/((I₃ − I₂)D₁), D₂ = (I_lo I_hi D₂)/(I_lo I_hi) · 4^{e₂ − e}, through
        // ln k' where it underflows.
        let modulus = if d2 == 0.0 {
            Modulus::from_ln_kc(f64::NEG_INFINITY)
        } else {
            let [ilo, ihi] = regime.scaled;
            let mantissa = (d31 * (d2 / ilo / ihi) / (d32 * d1)).abs();
            let shift = 2 * (e2 - e);
            let kc2 = if shift > -1900 {
                scale(mantissa, shift)
            } else {
                0.0
            };
            // 2⁻⁹⁶⁰: well inside the normal range, where ln k'² keeps its digits.
            if kc2 >= 1.026_134_200_324_594_1e-289 {
                Modulus::new(kc2)
            } else {
                Modulus::from_ln_kc(0.5 * (mantissa.ln() + f64::from(shift) * LN_2))
            }
        };
        // The amplitude φ₀ = am u₀: (sin φ₀, cos φ₀) ∝ (σq₂/A₂, q₁/A₁) ∝ (σq₂ρ₁, q₁ρ₂).
        let [rho1, rho2] = regime.rho;
        let (phase0, jac0, rf0) = modulus.phase_of(regime.sigma * q.y * rho1, q.x * rho2);
        let attitude = r.map(|r0| {
            let i3 = regime.moments[2];
            let norm = q.norm();
            let b0 = minimal_rotation(&(q / norm));
            let beta = regime.beta;
            let mut att = Attitude {
                start: r0.as_matrix() * pmat * b0,
                norm,
                inv_norm: 1.0 / norm,
                i3,
                factor: regime.psi_factor / lambda,
                beta,
                sb: (1.0 + beta).sqrt(),
                lambda_quarter: f64::NAN,
                part0: modulus.third_kind_part(beta, phase0, &jac0, rf0),
                atan0: 0.0,
            };
            att.atan0 = att.atan(phase0, &jac0);
            if reuse {
                att.lambda_quarter = modulus.third_kind_quarter(beta);
            }
            att
        });
        Ok(orbit(OrbitKind::Elliptic(Elliptic {
            scale: scale(1.0, e),
            pmat,
            amplitudes,
            lambda,
            modulus,
            phase0,
            attitude,
        })))
    }

    /// The constants of the orbit through (Π, R) when it is of the generic elliptic kind — not
    /// at rest, not a steady rotation, the body not axisymmetric, k' ≥ 2⁻⁶⁰ (not within ~10⁻³⁶
    /// of the separatrix, where the functions are their k = 1 limits) — as [`ExactFreeBody`]
    /// computes them once and reads them at every step; `Ok(None)` for the other kinds.
    ///
    /// For evaluating the same orbit elsewhere (the batched exact flow of the `batch` crate
    /// evaluates [`FreeBodyFlow::advance`]'s t-dependent part on SIMD lanes from these values);
    /// every field is the double the scalar evaluation reads. Errors: a non-finite Π.
    ///
    /// [`ExactFreeBody`]: crate::exact::ExactFreeBody
    pub fn elliptic_orbit(
        &self,
        pi: &Vector3<f64>,
        r: &So3,
    ) -> Result<Option<EllipticOrbit>, IntegratorError> {
        let orbit = self.orbit(pi, Some(r), true)?;
        let OrbitKind::Elliptic(ell) = &orbit.kind else {
            return Ok(None);
        };
        let Some(att) = &ell.attitude else {
            return Ok(None);
        };
        if ell.modulus.is_asymptotic() {
            return Ok(None);
        }
        let kc2 = ell.modulus.kc2();
        Ok(Some(EllipticOrbit {
            rate: orbit.rate,
            scale: ell.scale,
            pmat: ell.pmat,
            amplitudes: ell.amplitudes.into(),
            lambda: ell.lambda,
            kc2,
            // As `Modulus::new` keeps it.
            kc: kc2.sqrt(),
            quarter: ell.modulus.quarter_period(),
            phase0: ell.phase0,
            start: att.start,
            norm: att.norm,
            inv_norm: att.inv_norm,
            i3: att.i3,
            factor: att.factor,
            beta: att.beta,
            sb: att.sb,
            lambda_quarter: att.lambda_quarter,
            part0: att.part0,
            atan0: att.atan0,
        }))
    }

    /// The orbit's state at time t from its start.
    pub(crate) fn evaluate(
        &self,
        orbit: &Orbit,
        t: f64,
    ) -> Result<(Vector3<f64>, Option<So3>), IntegratorError> {
        if t == 0.0 {
            return Ok((orbit.pi0, orbit.r0));
        }
        // The fastest angle the flow turns, t|Π|/I_min, must keep its phase: beyond 2⁵² rad the
        // rounding of one period exceeds the period itself and the result would be noise.
        let phase = t.abs() * orbit.rate;
        if phase.is_nan() || phase >= PHASE_LIMIT {
            return Err(IntegratorError::NonFinite {
                what: "phase |Π|t/I of the exact flow (beyond 2⁵² rad, no digit of the phase left)",
            });
        }
        let ell = match &orbit.kind {
            OrbitKind::Rest => return Ok((orbit.pi0, orbit.r0)),
            OrbitKind::Steady(omega) => {
                let g = orbit
                    .r0
                    .map(|r| r.compose(&So3::exp(&(omega * t))).normalize());
                return Ok((orbit.pi0, g));
            }
            OrbitKind::Axisymmetric => {
                let (mut p, mut g) = (orbit.pi0, orbit.r0);
                if let Some(flow) = &self.axisymmetric {
                    flow.kinetic_flow(t, &mut p, g.as_mut())?;
                }
                return Ok((p, g));
            }
            OrbitKind::Elliptic(ell) => ell,
        };
        // u = u₀ + λ·t·2ᵉ (the scaling by 2ᵉ is exact).
        let tau = t * ell.scale;
        let du = ell.lambda * tau;
        let phase = ell.modulus.advance(ell.phase0, du);
        let jac = ell.modulus.jacobi(phase);
        let qt = ell.canonical(&jac);
        let pi_t = ell.pmat * qt * ell.scale;
        if !pi_t.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "momentum Π(t) of the exact flow",
            });
        }
        let (Some(att), Some(_)) = (&ell.attitude, orbit.r0) else {
            return Ok((pi_t, None));
        };
        // Δψ from Λ and G, each continued by its quarter periods.
        let dn = phase.n - ell.phase0.n;
        let mut d_lambda = ell.modulus.third_kind_slope(att.beta) * du
            + (ell.modulus.third_kind_part(att.beta, phase, &jac, f64::NAN) - att.part0);
        if dn != 0.0 {
            let lk = if att.lambda_quarter.is_nan() {
                ell.modulus.third_kind_quarter(att.beta)
            } else {
                att.lambda_quarter
            };
            d_lambda += dn * lk;
        }
        let d_g = (dn * FRAC_PI_2 + (att.atan(phase, &jac) - att.atan0)) / att.sb;
        let dpsi =
            att.norm * tau / att.i3 + att.factor * (att.norm * d_lambda - ell.amplitudes.z * d_g);
        let bt = ell.pmat * minimal_rotation(&(qt * att.inv_norm));
        let (sin, cos) = dpsi.sin_cos();
        let s = &att.start;
        let (col0, col1) = (s.column(0), s.column(1));
        let rotated = Matrix3::from_columns(&[
            col0 * cos + col1 * sin,
            col1 * cos - col0 * sin,
            s.column(2).into_owned(),
        ]);
        let g = So3::from_matrix_unchecked(&(rotated * bt.transpose())).normalize();
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
