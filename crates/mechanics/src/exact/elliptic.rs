//! Elliptic integrals and Jacobi elliptic functions in double precision, for the exact free
//! rigid body flow.
//!
//! - Carlson's symmetric integrals R_F, R_J (and R_C) by the duplication theorem: B. C. Carlson,
//!   "Numerical computation of real or complex elliptic integrals", Numer. Algorithms 10 (1995)
//!   13–26; DLMF §19.36(i). The iteration stops when the arguments agree to 2·10⁻³ relative, where
//!   the truncated series (through degree 5) leaves an error below 10⁻¹⁶.
//! - Legendre's F(φ, k) and Π(n; φ, k) from them (DLMF 19.25.5, 19.25.14), K(k) by the AGM.
//! - sn, cn, dn by the descending Landen / AGM transformation and Bulirsch's ascending
//!   recurrence (DLMF 22.20(ii); Bulirsch 1965).
//!
//! - [`Modulus`]: sn, cn, dn and Legendre's third integral at a phase kept as u = nK + w,
//!   |w| ≤ K/2 ([`QuarterPhase`]), shifted by quarter periods (DLMF 22.4.3) so that the values near
//!   the zeros of cn and dn keep their relative accuracy, and for k' < 2⁻⁶⁰ their k = 1 limits
//!   (DLMF 22.10.8–10, 19.12.1) from ln k', so that k'² below the double range and k' = 0 (K = ∞)
//!   cost no range.
//!
//! The modulus is passed as the complementary k'² = 1 − k² (or its logarithm), so that callers
//! near k = 1 (the separatrix of the rigid body) keep k'² to full relative accuracy. Checked
//! against mpmath at 40 digits in `tests/models/exact_flow.rs` (the [`Modulus`] functions relative to
//! themselves near every zero, to 4 + 2|w| ulps: their conditioning in w).

use core::f64::consts::FRAC_PI_2;

/// Stop the duplication when the arguments agree to this relative spread: the neglected terms of
/// the degree-5 series are O(spread⁶) ≈ 6·10⁻¹⁷.
const SPREAD: f64 = 2e-3;

/// Carlson's R_F(x, y, z) = ½∫₀^∞ dt/√((t+x)(t+y)(t+z)), x, y, z ≥ 0, at most one zero.
pub fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    let (mut x, mut y, mut z) = (x, y, z);
    for _ in 0..64 {
        let a = (x + y + z) / 3.0;
        let spread = (a - x).abs().max((a - y).abs()).max((a - z).abs());
        if spread <= SPREAD * a.abs() {
            let (dx, dy) = (1.0 - x / a, 1.0 - y / a);
            let dz = -dx - dy;
            let e2 = dx * dy - dz * dz;
            let e3 = dx * dy * dz;
            return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0)
                / a.sqrt();
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lam = sx * sy + sx * sz + sy * sz;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
    }
    f64::NAN
}

/// R_C(1, 1 + e) = R_F(1, 1+e, 1+e) for e > −1: atan(√e)/√e, atanh(√−e)/√−e, or its series.
fn carlson_rc_one(e: f64) -> f64 {
    if e.abs() < 1e-3 {
        // 1 − e/3 + e²/5 − e³/7 + e⁴/9: the next term is below 1e-16 for |e| < 1e-3.
        1.0 + e * (-1.0 / 3.0 + e * (1.0 / 5.0 + e * (-1.0 / 7.0 + e / 9.0)))
    } else if e > 0.0 {
        let s = e.sqrt();
        s.atan() / s
    } else {
        let s = (-e).sqrt();
        s.atanh() / s
    }
}

/// Carlson's R_J(x, y, z, p) = (3/2)∫₀^∞ dt/((t+p)√((t+x)(t+y)(t+z))), x, y, z ≥ 0 (at most one
/// zero), p > 0 (DLMF 19.36.9 and the algorithm of Carlson 1995 §2).
pub fn carlson_rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    let (mut x, mut y, mut z, mut p) = (x, y, z, p);
    let delta = (p - x) * (p - y) * (p - z);
    let mut sum = 0.0;
    let mut fac = 1.0; // 4⁻ᵐ
    for _ in 0..64 {
        let a = (x + y + z + 2.0 * p) / 5.0;
        let spread = (a - x)
            .abs()
            .max((a - y).abs())
            .max((a - z).abs())
            .max((a - p).abs());
        if spread <= SPREAD * a.abs() {
            let (dx, dy, dz) = (1.0 - x / a, 1.0 - y / a, 1.0 - z / a);
            let dp = -0.5 * (dx + dy + dz);
            let e2 = dx * dy + dx * dz + dy * dz - 3.0 * dp * dp;
            let e3 = dx * dy * dz + 2.0 * e2 * dp + 4.0 * dp * dp * dp;
            let e4 = (2.0 * dx * dy * dz + e2 * dp + 3.0 * dp * dp * dp) * dp;
            let e5 = dx * dy * dz * dp * dp;
            let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
                - 3.0 * e4 / 22.0
                - 9.0 * e2 * e3 / 52.0
                + 3.0 * e5 / 26.0;
            return fac * series / (a * a.sqrt()) + 6.0 * sum;
        }
        let (sx, sy, sz, sp) = (x.sqrt(), y.sqrt(), z.sqrt(), p.sqrt());
        let lam = sx * sy + sx * sz + sy * sz;
        let d = (sp + sx) * (sp + sy) * (sp + sz);
        let e = fac * fac * fac * delta / (d * d);
        sum += fac * carlson_rc_one(e) / d;
        fac *= 0.25;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        p = 0.25 * (p + lam);
    }
    f64::NAN
}

/// The complete integral K(k) = π/(2 AGM(1, k')), from k'² (∞ for k' = 0).
pub fn complete_k(kc2: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, kc2.sqrt());
    if b == 0.0 {
        return f64::INFINITY;
    }
    for _ in 0..64 {
        if (a - b).abs() <= 2.0 * f64::EPSILON * a {
            break;
        }
        let an = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = an;
    }
    FRAC_PI_2 / a
}

/// Jacobi's (sn u, cn u, dn u) for modulus k, from k'² ∈ [0, 1] (so that k near 1 keeps its full
/// relative accuracy), by the descending Landen/AGM transformation and Bulirsch's ascending
/// recurrence (R. Bulirsch, "Numerical calculation of elliptic integrals and elliptic functions",
/// Numer. Math. 7 (1965) 78–90; the `sncndn` of Numerical Recipes §6.12): one `sin_cos` and a
/// few divisions, no inverse trigonometric function. k' = 0 (k = 1): (tanh u, sech u, sech u).
pub fn sn_cn_dn(u: f64, kc2: f64) -> (f64, f64, f64) {
    if kc2 == 0.0 {
        let sech = 1.0 / u.cosh();
        return (u.tanh(), sech, sech);
    }
    // AGM(1, k') with the means kept for the ascent; it stops when a and b agree to 1e-8, where
    // the next mean is exact to O(1e-16) (quadratic convergence).
    let mut em = [0.0f64; 16];
    let mut en = [0.0f64; 16];
    let (mut a, mut emc) = (1.0f64, kc2);
    let mut c = 1.0;
    let mut l = 0;
    for i in 0..16 {
        l = i;
        em[i] = a;
        emc = emc.sqrt();
        en[i] = emc;
        c = 0.5 * (a + emc);
        if (a - emc).abs() <= 1e-8 * a {
            break;
        }
        emc *= a;
        a = c;
    }
    let (mut sn, mut cn) = (u * c).sin_cos();
    let mut dn = 1.0;
    if sn != 0.0 {
        let mut a = cn / sn;
        c *= a;
        for ii in (0..=l).rev() {
            let b = em[ii];
            a *= c;
            c *= dn;
            dn = (en[ii] + a) / (b + a);
            a = c / b;
        }
        let r = 1.0 / (c * c + 1.0).sqrt();
        sn = if sn >= 0.0 { r } else { -r };
        cn = c * sn;
    }
    (sn, cn, dn)
}

/// Legendre's F(φ, k) = ∫₀^φ dθ/√(1 − k² sin²θ) for |φ| ≤ π/2 (DLMF 19.25.5), from s = sin φ,
/// c = cos φ ≥ 0 and Δ² = 1 − k² sin²φ: near k = 1 and φ = π/2, F moves by ∂F/∂Δ² ~ Δ⁻², so Δ²
/// must come from k'² (Δ² = c² + k'² s²), never from a rounded k².
pub fn incomplete_f(s: f64, c: f64, delta2: f64) -> f64 {
    s * carlson_rf(c * c, delta2, 1.0)
}

/// Legendre's Π(n; φ, k) = ∫₀^φ dθ/((1 − n sin²θ)√(1 − k² sin²θ)) for |φ| ≤ π/2 and
/// 1 − n sin²φ > 0 (DLMF 19.25.14), from s, c, Δ² as for [`incomplete_f`].
pub fn incomplete_pi(n: f64, s: f64, c: f64, delta2: f64) -> f64 {
    incomplete_f_and_pi(n, s, c, delta2).1
}

/// (F(φ, k), Π(n; φ, k)) together, sharing R_F (Π = F + (n/3) s³ R_J).
pub fn incomplete_f_and_pi(n: f64, s: f64, c: f64, delta2: f64) -> (f64, f64) {
    let f = s * carlson_rf(c * c, delta2, 1.0);
    let p = f + n / 3.0 * s * s * s * carlson_rj(c * c, delta2, 1.0, 1.0 - n * s * s);
    (f, p)
}

/// The complete Π(n, k) = Π(n; π/2, k), from k'².
pub fn complete_pi(n: f64, kc2: f64) -> f64 {
    carlson_rf(0.0, kc2, 1.0) + n / 3.0 * carlson_rj(0.0, kc2, 1.0, 1.0 - n)
}

/// Below this k' the Jacobi functions of a quarter-period-reduced argument |w| ≤ K/2 are their
/// k = 1 limits to a relative O(k') (DLMF 22.10.8–10: the corrections are
/// (k'²/4)(sinh w cosh w ± w)·…, at most k'/4 relative where e^{2|w|} ≤ e^K = 4/k'), and
/// K = ln(4/k') to O(k'² ln k') (DLMF 19.12.1): 2⁻⁶⁰ leaves both below 2⁻⁶².
const ASYMPTOTIC_KC: f64 = 8.673_617_379_884_035e-19; // 2⁻⁶⁰

/// Below this k' its products with sinh w, cosh w (w ≤ K/2) are taken through logarithms: k'
/// itself may have underflowed (a state 10⁻¹⁶⁰ from the middle axis has k' ≈ 10⁻³²⁰).
const TINY_KC: f64 = 1e-290;

/// A phase u = nK + w of the Jacobi functions, reduced to the nearest multiple n of the quarter
/// period K (|w| ≤ K/2 up to rounding; n = 0 and w = u when K = ∞).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuarterPhase {
    /// The number of quarter periods (an integer, exact below 2⁵³).
    pub n: f64,
    /// The remainder.
    pub w: f64,
}

impl QuarterPhase {
    /// n mod 4 (n is an integer below 2⁵³ in magnitude: the cast is exact).
    #[inline]
    pub fn quadrant(&self) -> u8 {
        ((self.n as i64) & 3) as u8
    }

    /// Whether n is odd (u nearer a zero of cn than of sn).
    #[inline]
    pub fn is_odd(&self) -> bool {
        self.quadrant() & 1 == 1
    }
}

/// The Jacobi functions at a [`QuarterPhase`]: (sn, cn, dn) of u = nK + w, and the pieces of the
/// reduced argument that the integrals need: S = sn w, C = cn w, D = dn w, and k'S/C.
#[derive(Debug, Clone, Copy)]
pub struct Jacobi {
    /// sn u.
    pub sn: f64,
    /// cn u.
    pub cn: f64,
    /// dn u.
    pub dn: f64,
    /// sn w.
    pub s: f64,
    /// cn w ≥ 0 (0 only where it underflows, asymptotically).
    pub c: f64,
    /// dn w.
    pub d: f64,
    /// k' sn w / cn w (= k' sinh w as k' → 0).
    pub ksc: f64,
}

/// The modulus of the Jacobi functions, given by k'² to full relative accuracy (so that k near 1,
/// the separatrix of the rigid body, keeps its digits), with the quarter period K, evaluating
/// sn, cn, dn and the integrals with relative accuracy in every quarter of the period.
///
/// The phase is kept as u = nK + w with |w| ≤ K/2 ([`QuarterPhase`]), and the functions of u come
/// from those of w by the quarter-period shift (DLMF 22.4.3, Table 22.4.3):
///
/// ```text
/// n even:  (sn, cn, dn)(u) = (±S, ±C, D),       n odd:  (sn, cn, dn)(u) = (±C/D, ∓k'S/D, k'/D),
/// ```
///
/// S, C, D = sn, cn, dn of w: on |w| ≤ K/2, C and D stay above √(k'/(1+k')) and S is small only
/// with w itself, so the small values near the zeros of sn, cn and dn (S, k'S/D, k'/D) keep
/// their relative accuracy, where evaluating at u itself leaves them the absolute error of u.
///
/// For k' ≥ 2⁻⁶⁰, S, C, D by Bulirsch's method ([`sn_cn_dn`]) and K by the AGM; below, the k = 1
/// limits (S, C, D) = (tanh w, sech w, sech w), K = ln 4 − ln k', with ln k' carried so that
/// k'² below the double range (states within 10⁻¹⁵⁰ of the middle axis) still has its period.
/// k' = 0 (the separatrix) is K = ∞: u never wraps.
#[derive(Debug, Clone, Copy)]
pub struct Modulus {
    kc2: f64,
    kc: f64,
    ln_kc: f64,
    sqrt_kc: f64,
    quarter: f64,
    asymptotic: bool,
}

impl Modulus {
    /// The modulus with k'² = `kc2` ∈ [0, 1] (clamped).
    pub fn new(kc2: f64) -> Self {
        let kc2 = kc2.clamp(0.0, 1.0);
        if kc2 < ASYMPTOTIC_KC * ASYMPTOTIC_KC {
            return Self::from_ln_kc(0.5 * kc2.ln());
        }
        let kc = kc2.sqrt();
        Self {
            kc2,
            kc,
            // Read only asymptotically.
            ln_kc: f64::NAN,
            sqrt_kc: kc.sqrt(),
            quarter: complete_k(kc2),
            asymptotic: false,
        }
    }

    /// The modulus with ln k' = `ln_kc` (−∞ for k' = 0, the separatrix), for k' that k'² could
    /// not hold; above 2⁻⁶⁰ the same as [`Modulus::new`].
    pub fn from_ln_kc(ln_kc: f64) -> Self {
        let kc = ln_kc.exp();
        if kc >= ASYMPTOTIC_KC {
            return Self::new(kc * kc);
        }
        Self {
            kc2: kc * kc,
            kc,
            ln_kc,
            sqrt_kc: (0.5 * ln_kc).exp(),
            quarter: core::f64::consts::LN_2 * 2.0 - ln_kc,
            asymptotic: true,
        }
    }

    /// k'² (0 when it underflows).
    pub fn kc2(&self) -> f64 {
        self.kc2
    }

    /// k² = 1 − k'².
    pub fn k2(&self) -> f64 {
        1.0 - self.kc2
    }

    /// The quarter period K(k) (∞ for k = 1).
    pub fn quarter_period(&self) -> f64 {
        self.quarter
    }

    /// Whether the functions are the k = 1 limits (k' < 2⁻⁶⁰; see the type's page).
    pub fn is_asymptotic(&self) -> bool {
        self.asymptotic
    }

    /// u + du, reduced again to the nearest quarter period.
    pub fn advance(&self, phase: QuarterPhase, du: f64) -> QuarterPhase {
        let x = phase.w + du;
        let m = (x / self.quarter).round();
        if m == 0.0 || m.is_nan() {
            return QuarterPhase { n: phase.n, w: x };
        }
        QuarterPhase {
            n: phase.n + m,
            w: x - m * self.quarter,
        }
    }

    /// k'·sinh|w| and k'·cosh w without overflow or the underflow of k'.
    fn kc_sinh_cosh(&self, w: f64) -> (f64, f64) {
        let a = w.abs();
        if self.kc >= TINY_KC {
            (self.kc * a.sinh(), self.kc * a.cosh())
        } else {
            // ln sinh a = a − ln 2 + ln(1 − e^{−2a}), ln cosh a = a − ln 2 + ln(1 + e^{−2a}).
            let e = (-2.0 * a).exp();
            let base = self.ln_kc + a - core::f64::consts::LN_2;
            (
                (base + (-(-2.0 * a).exp_m1()).ln()).exp(),
                (base + e.ln_1p()).exp(),
            )
        }
    }

    /// The Jacobi functions at u = nK + w.
    pub fn jacobi(&self, phase: QuarterPhase) -> Jacobi {
        let w = phase.w;
        let quadrant = phase.quadrant();
        let odd = quadrant & 1 == 1;
        let sign = if quadrant < 2 { 1.0 } else { -1.0 };
        if self.asymptotic {
            let (s, c) = (w.tanh(), 1.0 / w.cosh());
            let (ks, kch) = if odd {
                self.kc_sinh_cosh(w)
            } else {
                (0.0, 0.0)
            };
            let ksc = ks.copysign(w);
            let (sn, cn, dn) = if odd {
                (sign, -sign * ksc, kch)
            } else {
                (sign * s, sign * c, c)
            };
            return Jacobi {
                sn,
                cn,
                dn,
                s,
                c,
                d: c,
                ksc,
            };
        }
        let (s, c, _) = sn_cn_dn(w.abs(), self.kc2);
        let s = s.copysign(w);
        // dn from (S, C) (Δ² = C² + k'²S², a sum of positive terms): sn² + cn² = 1 and
        // dn² = cn² + k'² sn² hold to rounding in every quarter.
        let d = (c * c + self.kc2 * s * s).sqrt();
        let ksc = self.kc * s / c;
        let (sn, cn, dn) = if odd {
            (sign * c / d, -sign * self.kc * s / d, self.kc / d)
        } else {
            (sign * s, sign * c, d)
        };
        Jacobi {
            sn,
            cn,
            dn,
            s,
            c,
            d,
            ksc,
        }
    }

    /// The phase u (one of its values mod 4K, the one with |u| ≤ 2K) of the amplitude φ = am u
    /// given by (sin φ, cos φ) (not necessarily normalized), with the Jacobi functions of its
    /// reduced argument w and R_F(C², D², 1) (NaN when asymptotic): the inverse of `jacobi`,
    /// by F(φ, k) = sin φ·R_F(cos²φ, Δ², 1) (DLMF 19.25.5) near even quarters and by the
    /// complementary amplitude near odd ones (sn(K − v) = cd v: v = F(φ*, k) with
    /// sin φ* = cos φ/Δ, cos φ* = k' sin φ/Δ), each evaluated where its sine is the smaller, so
    /// that w has the relative accuracy of the input's small component.
    pub fn phase_of(&self, sin_phi: f64, cos_phi: f64) -> (QuarterPhase, Jacobi, f64) {
        let big = sin_phi.abs().max(cos_phi.abs());
        let (s, c) = (sin_phi / big, cos_phi / big);
        let h = (s * s + c * c).sqrt();
        let (s, c) = (s / h, c / h);
        // Reduce φ to [−π/2, π/2] (cos φ ≥ 0) by am(u + 2Kj) = am u + jπ.
        let (j, s, c) = if c >= 0.0 {
            (0.0, s, c)
        } else if s >= 0.0 {
            (1.0, -s, -c)
        } else {
            (-1.0, -s, -c)
        };
        // |w| ≤ K/2 about 2jK iff tan²φ ≤ 1/k' (sn²/cn² = 1/k' at K/2).
        let even = c >= self.sqrt_kc * s.abs();
        let nan = f64::NAN;
        if even {
            let phase = |w| QuarterPhase { n: 2.0 * j, w };
            if self.asymptotic {
                // sinh w = S/C.
                let w = asinh_ratio(s, c);
                let jac = self.jacobi(phase(w));
                return (phase(w), Jacobi { s, c, d: c, ..jac }, nan);
            }
            let d2 = c * c + self.kc2 * s * s;
            let rf = carlson_rf(c * c, d2, 1.0);
            let w = s * rf;
            let jac = Jacobi {
                sn: 0.0,
                cn: 0.0,
                dn: 0.0,
                s,
                c,
                d: d2.sqrt(),
                ksc: self.kc * s / c,
            };
            return (phase(w), jac, rf);
        }
        // Near the odd quarter (2j ± 1)K: u = (2j + 1)K − v for s > 0, (2j − 1)K + v for s < 0.
        let side = if s > 0.0 { 1.0 } else { -1.0 };
        let phase = |v: f64| QuarterPhase {
            n: 2.0 * j + side,
            w: -side * v,
        };
        // k'·sn w/cn w = −side·cos φ/|sin φ|: exact from the input.
        let ksc = -side * c / s.abs();
        if self.asymptotic {
            // k' sinh v = cos φ/|sin φ|.
            let v = if self.kc >= TINY_KC {
                (c / (self.kc * s.abs())).asinh()
            } else if c == 0.0 {
                0.0
            } else {
                let y = c.ln() - s.abs().ln() - self.ln_kc;
                if y > 20.0 {
                    y + core::f64::consts::LN_2
                } else {
                    y.exp().asinh()
                }
            };
            let jac = self.jacobi(phase(v));
            return (phase(v), Jacobi { ksc, ..jac }, nan);
        }
        let d2 = c * c + self.kc2 * s * s;
        let d = d2.sqrt();
        let rf = carlson_rf(self.kc2 * s * s, self.kc2, d2);
        let v = c * rf;
        let jac = Jacobi {
            sn: 0.0,
            cn: 0.0,
            dn: 0.0,
            s: side * -c / d,
            c: self.kc * s.abs() / d,
            d: self.kc / d,
            ksc,
        };
        // R_F(C², D², 1) = R_F(k'²s²/Δ², k'²/Δ², 1) = Δ·R_F(k'²s², k'², Δ²) (homogeneity).
        (phase(v), jac, d * rf)
    }

    /// Legendre's third integral Λ(u) = Π(−β; am u, k) = ∫₀^u dv/(1 + β sn²v) (β > 0), continued
    /// in u = nK + w as
    ///
    /// ```text
    /// Λ(u) = c·u + n·L + B(n, w),   c = third_kind_slope, L = third_kind_quarter, B = third_kind_part,
    /// ```
    ///
    /// so that a change of u needs only the changes of n and of the bounded B (and c·Δu: no
    /// difference of two large values). `rf` = R_F(C², D², 1) if known (else NaN).
    ///
    /// For k' ≥ 2⁻⁶⁰ and β ≥ 1, c = 0, L = Λ(K) and B is the integral Λₙ(w) over w: even n,
    /// Λ(w) = S·R_F(C², D², 1) − (β/3) S³ R_J(C², D², 1, 1 + βS²) (DLMF 19.25.14), two terms of
    /// size w that cancel to O(w/√β), so evaluated as
    /// `Λ(w) = atan(qS/(CD))/q + (k²/3β) S³ R_J(C², D², 1, 1 + k²S²/β)`, q² = (1 + β)(1 + k²/β)
    /// (DLMF 19.7.9: Π(φ, −β) + Π(φ, −k²/β) = F + √c R_C((c − 1)(c − k²), (c + β)(c + k²/β)),
    /// c = 1/S²), and L = π/2q + (k²/3β) R_J(0, k'², 1, 1 + k²/β); odd n,
    /// ∫₀^w dv/(1 + β cd²v) = [k²w + βk'² Π(ν; am w, k)/(1 + β)]/(k² + β) with
    /// ν = (k² + β)/(1 + β) (the integrand is (1 − k²sn²)/((1 + β)(1 − ν sn²)); a sum of
    /// positive terms).
    /// For β < 1, Λ is u less a part of relative size β: c = 1, L = Λ(K) − K =
    /// −(β/3) R_J(0, k'², 1, 1 + β) and B = Λₙ(w) − w, from the same formulas with F(am w) = w
    /// taken out analytically,
    ///
    /// ```text
    /// even n:  B = −(β/3) S³ R_J(C², D², 1, 1 + βS²),
    /// odd n:   B = −βw/(1 + β) + βk'²ν S³ R_J(C², D², 1, 1 − νS²) / (3(1 + β)(k² + β)),
    /// ```
    ///
    /// so that B and its changes carry a rounding of β|w|, not of |w|: the free body's precession
    /// multiplies ΔΛ by |Π|(I₃ − I₁)/(I₁I₃λ), which is large where λ is small (a nearly symmetric
    /// body near its separatrix, λ ∝ √(I₂ − I₁)), and a difference of two values of Λ(w) of size
    /// K would leave it an error of ε·K times that. Asymptotically
    /// (sn w = tanh w, cd w = 1): c = 1/(1 + β), L = √β atan √β/(1 + β) and
    /// B = √β atan(√β tanh w)/(1 + β) for even n, 0 for odd — on the separatrix (K = ∞, n fixed)
    /// Λ = (u + √β atan(√β tanh u))/(1 + β) for every u.
    pub fn third_kind_part(&self, beta: f64, phase: QuarterPhase, jac: &Jacobi, rf: f64) -> f64 {
        let odd = phase.is_odd();
        let w = phase.w;
        if self.asymptotic {
            let sb = beta.sqrt();
            return if odd {
                0.0
            } else {
                sb * (sb * jac.s).atan() / (1.0 + beta)
            };
        }
        let (s, c2, d2) = (jac.s, jac.c * jac.c, jac.d * jac.d);
        let rf = || {
            if rf.is_nan() {
                carlson_rf(c2, d2, 1.0)
            } else {
                rf
            }
        };
        let s3 = s * s * s;
        let slope = beta < 1.0;
        if odd {
            let k2 = self.k2();
            let nu = (k2 + beta) / (1.0 + beta);
            // 1 − νS² = C² + k'²S²/(1 + β): no cancellation as ν → 1.
            let p = c2 + self.kc2 * s * s / (1.0 + beta);
            let rj = nu / 3.0 * s3 * carlson_rj(c2, d2, 1.0, p);
            if slope {
                -beta * w / (1.0 + beta) + beta * self.kc2 * rj / ((1.0 + beta) * (k2 + beta))
            } else {
                let pi_nu = s * rf() + rj;
                (k2 * w + beta * self.kc2 * pi_nu / (1.0 + beta)) / (k2 + beta)
            }
        } else if slope {
            -beta / 3.0 * s3 * carlson_rj(c2, d2, 1.0, 1.0 + beta * s * s)
        } else {
            // DLMF 19.7.9 with α²ω² = k²: Π(φ, −β) = F − Π(φ, −k²/β) + √c R_C(…), c = csc²φ,
            // where R_C closes to atan(qS/(CD))/q, q² = (1 + β)(1 + k²/β) (its two arguments
            // differ by exactly S²q²); F − Π(φ, −k²/β) is a positive O(1/β) term.
            let k2 = self.k2();
            let q = ((1.0 + beta) * (1.0 + k2 / beta)).sqrt();
            (q * s / (jac.c * jac.d)).atan() / q
                + k2 / (3.0 * beta) * s3 * carlson_rj(c2, d2, 1.0, 1.0 + k2 * s * s / beta)
        }
    }

    /// L of [`Modulus::third_kind_part`]: Λ(K) = Π(−β, k) = K − (β/3) R_J(0, k'², 1, 1 + β)
    /// (DLMF 19.25.2) for β ≥ 1, that less K for β < 1, asymptotically √β atan √β/(1 + β).
    pub fn third_kind_quarter(&self, beta: f64) -> f64 {
        if self.asymptotic {
            let sb = beta.sqrt();
            return sb * sb.atan() / (1.0 + beta);
        }
        if beta < 1.0 {
            -beta / 3.0 * carlson_rj(0.0, self.kc2, 1.0, 1.0 + beta)
        } else {
            // The limit φ → π/2 of the β ≥ 1 form of `third_kind_part` (R_C(0, y) = π/2√y).
            let k2 = self.k2();
            let q = ((1.0 + beta) * (1.0 + k2 / beta)).sqrt();
            core::f64::consts::FRAC_PI_2 / q
                + k2 / (3.0 * beta) * carlson_rj(0.0, self.kc2, 1.0, 1.0 + k2 / beta)
        }
    }

    /// c of [`Modulus::third_kind_part`]: 0 for β ≥ 1, 1 for β < 1, asymptotically 1/(1 + β).
    pub fn third_kind_slope(&self, beta: f64) -> f64 {
        if self.asymptotic {
            1.0 / (1.0 + beta)
        } else if beta < 1.0 {
            1.0
        } else {
            0.0
        }
    }
}

/// asinh(s/c) for c > 0, also where s/c overflows.
fn asinh_ratio(s: f64, c: f64) -> f64 {
    if c >= s.abs() * 1e-150 {
        (s / c).asinh()
    } else {
        // asinh x = ln 2x for x > 10⁸ to rounding; c = 0 (an underflowed cosine) as the
        // smallest subnormal, so that w stays finite.
        (core::f64::consts::LN_2 + s.abs().ln() - c.max(f64::from_bits(1)).ln()).copysign(s)
    }
}
