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
//! The modulus is passed as k² and the complementary k'² = 1 − k² separately, so that callers
//! near k = 1 (the separatrix of the rigid body) keep k'² to full relative accuracy. Checked
//! against mpmath at 30 digits in `tests/exact_flow.rs`.

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
