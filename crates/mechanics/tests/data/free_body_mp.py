"""The free rigid body's true solution for double inputs, in mpmath (imported by the
*_reference.py scripts of this directory; not a transcription of the crate's formulas).

A body with a diagonal inertia 𝕀 = diag(I) of distinct moments and a momentum Π₀, both doubles
taken exactly. Π(t) from Landau–Lifshitz §37 (the angular velocities in Jacobi's cn, sn, dn),
with every branch decided in rational arithmetic (fractions.Fraction: the sign of |Π|² − 2hI_mid,
k'² = 1 − k² exactly) and every sign and the direction of time read off Euler's equations
themselves; sn, cn, dn, F from mpmath (theta functions, at a working precision raised by the
digits k'² takes away). The orientation by Landau's Euler angles about the constant spatial
momentum m = RΠ: body axes (a, b, c) with c the axis Π circulates about,

    Π_a = |Π| sin θ sin ψ,  Π_b = |Π| sin θ cos ψ,  Π_c = |Π| cos θ,
    φ̇ = |Π| (Π_a²/I_a + Π_b²/I_b) / (Π_a² + Π_b²),
    R(t) = R₀ E(0)ᵀ Rz(φ(t) − φ(0)) E(t),  E = Rx(θ) Rz(ψ) P  (P: body → (a, ±b, c)),

and φ(t) − φ(0) by Gauss–Legendre/tanh–sinh quadrature of φ̇ (mpmath.quad) over the whole
half-periods of Π_a², Π_b² and the rest; on the separatrix φ̇ − |Π|/I_b decays exponentially and
its integral to t is the integral to ∞ less a tail below 10⁻⁴⁰. `check()` compares all of it with
mpmath's Taylor-series ODE solver (odefun) on Euler's equations and Ṙ = RΩ̂.
"""
import math
from fractions import Fraction as Fr

import mpmath as mp


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def euler_field(I, p):
    """Π × Ω, Ω = 𝕀⁻¹Π."""
    return cross(p, [p[i] / I[i] for i in range(3)])


def mat(rows):
    return mp.matrix([[mp.mpf(x) for x in row] for row in rows])


def rot(axis, a):
    c, s = mp.cos(a), mp.sin(a)
    if axis == "x":
        return mat([[1, 0, 0], [0, c, -s], [0, s, c]])
    return mat([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def on_separatrix(I, p):
    """The sign of |Π|² − 2hI_mid, exactly."""
    mid = sorted(range(3), key=lambda i: I[i])[1]
    d = sum(Fr(p[i]) ** 2 * (Fr(I[i]) - Fr(I[mid])) / Fr(I[i]) for i in range(3))
    return (d > 0) - (d < 0)


class Orbit:
    def __init__(self, I, p, digits=30):
        assert len(set(I)) == 3, "distinct moments"
        If = [Fr(x) for x in I]
        pf = [Fr(x) for x in p]
        lo, b, hi = sorted(range(3), key=lambda i: I[i])
        m2 = sum(x * x for x in pf)
        e2 = sum(pf[i] ** 2 / If[i] for i in range(3))  # 2h
        d = m2 - e2 * If[b]
        a, c = (lo, hi) if d >= 0 else (hi, lo)
        self.axes = (a, b, c)
        Ia, Ib, Ic = If[a], If[b], If[c]
        # Landau–Lifshitz (37.8)–(37.10) for Π = 𝕀Ω, axes 1, 2, 3 = a, b, c; with d < 0 the
        # same with 1 and 3 exchanged: every factor then changes sign in pairs.
        da, dc = e2 * Ic - m2, m2 - e2 * Ia
        amp2 = [Ia * da / (Ic - Ia), Ib * da / (Ic - Ib), Ic * dc / (Ic - Ia)]
        lam2 = (Ic - Ib) * dc / (Ia * Ib * Ic)
        k2 = (Ib - Ia) * da / ((Ic - Ib) * dc)
        kc2 = 1 - k2  # exact: 0 on the separatrix, tiny near it
        assert all(x >= 0 for x in amp2) and lam2 > 0 and 0 <= k2 <= 1
        self.steady = amp2[0] == 0 and amp2[1] == 0
        lost = 0 if kc2 == 0 else max(0, -math.floor(math.log10(kc2)))
        # A component far below |Π| (near an axis) must survive in the amplitude φ₀ too.
        small = max(0, -math.floor(math.log10(min(abs(x) for x in p if x != 0) / max(abs(x) for x in p))))
        self.dps = digits + lost + 2 * small + 20
        with mp.workdps(self.dps):
            q = lambda x: mp.mpf(x.numerator) / x.denominator
            self.I = [mp.mpf(x) for x in I]
            self.p0 = [mp.mpf(x) for x in p]
            self.M = mp.sqrt(q(m2))
            self.amp = [mp.sqrt(q(x)) for x in amp2]
            self.lam = mp.sqrt(q(lam2))
            self.kc2 = q(kc2)
            self.m = 1 - self.kc2
            self.sc = 1 if p[c] > 0 else -1
            # On the separatrix cn = sech u > 0: Π_a keeps its sign (two heteroclinic orbits).
            self.sa = -1 if kc2 == 0 and p[a] < 0 else 1
            # Directions from Euler's equations: Π̇_b = κ Π_a Π_c must be s_b B λ cn dn with
            # Π_a = s_a A cn, Π_c = s_c C dn; then Π̇_a = −s_a A λ sn dn checks the other one.
            e = [mp.mpf(0)] * 3
            e[a] = e[c] = mp.mpf(1)
            kappa = euler_field(self.I, e)[b]
            self.sb = 1 if kappa * self.sa * self.sc > 0 else -1
            A, B, C = self.amp
            assert abs(B * self.lam - abs(kappa) * A * C) <= mp.mpf(10) ** (10 - self.dps) * B * self.lam
            e = [mp.mpf(0)] * 3
            e[b] = e[c] = mp.mpf(1)
            assert euler_field(self.I, e)[a] * self.sa * self.sb * self.sc < 0 or self.steady
            if not self.steady:
                phi0 = mp.atan2(self.sb * self.p0[b] / B, self.sa * self.p0[a] / A)
                self.u0 = mp.ellipf(phi0, self.m)
                # Half-period of Π_a², Π_b² in t (∞ on the separatrix).
                self.half = mp.inf if self.kc2 == 0 else 2 * mp.ellipk(self.m) / self.lam

    def pi(self, t):
        """Π(t)."""
        if self.steady:
            return list(self.p0)
        with mp.workdps(self.dps):
            a, b, c = self.axes
            u = self.u0 + self.lam * mp.mpf(t)
            sn, cn, dn = (mp.ellipfun(w, u, m=self.m) for w in ("sn", "cn", "dn"))
            out = [None] * 3
            out[a] = self.sa * self.amp[0] * cn
            out[b] = self.sb * self.amp[1] * sn
            out[c] = self.sc * self.amp[2] * dn
            return out

    def frame(self):
        """P: body coordinates → the right-handed labelled frame (a, ±b, c)."""
        a, b, c = self.axes
        P = mp.matrix(3, 3)
        P[0, a] = 1
        P[1, b] = 1
        P[2, c] = 1
        if mp.det(P) < 0:
            P[1, b] = -1
        return P

    def euler(self, p):
        """E = Rx(θ) Rz(ψ) P for the body momentum p: Eᵀ e_z = p/|p|."""
        P = self.frame()
        x = P * mp.matrix(p)
        theta = mp.acos(x[2] / self.M)
        psi = mp.atan2(x[0], x[1])
        return rot("x", theta) * rot("z", psi) * P

    def phidot(self, t):
        P = self.frame()
        x = P * mp.matrix(self.pi(t))
        a, b, c = self.axes
        s = x[0] ** 2 + x[1] ** 2
        return self.M * (x[0] ** 2 / self.I[a] + x[1] ** 2 / self.I[b]) / s

    def phi(self, t):
        """φ(t) − φ(0) = ∫₀ᵗ φ̇."""
        t = mp.mpf(t)
        with mp.workdps(self.dps):
            sign = 1 if t >= 0 else -1
            t = abs(t)
            f = lambda s: self.phidot(sign * s)
            if self.half == mp.inf:
                rate = self.M / self.I[self.axes[1]]
                g = lambda s: f(s) - rate
                # The excess decays like e^{−2λs}: beyond 120/λ it is below 10⁻⁹⁰ of |Π|/I.
                end = min(t, 120 / self.lam)
                pts = [end * k / 16 for k in range(17)]
                return sign * (rate * t + mp.quad(g, pts))
            n = mp.floor(t / self.half)

            def pieces(x0, x1):
                # Near the separatrix φ̇ has a bump of width ~1/λ once per half-period: a piece
                # per 2/λ at least.
                k = max(16, int(mp.ceil(self.lam * (x1 - x0) / 2)))
                return [x0 + (x1 - x0) * j / k for j in range(k + 1)]

            if n > 0 and getattr(self, "whole", None) is None:
                self.whole = mp.quad(self.phidot, pieces(0, self.half))  # the same both ways
            whole = self.whole if n > 0 else 0
            rest = mp.quad(f, pieces(n * self.half, t)) if t > n * self.half else 0
            return sign * (n * whole + rest)

    def attitude(self, r0, t):
        """R(t) for R(0) = r0 (a 3×3 list of doubles, taken exactly)."""
        with mp.workdps(self.dps):
            R0 = mat(r0)
            if self.steady:
                om = [self.p0[i] / self.I[i] for i in range(3)]
                w = mp.sqrt(sum(x * x for x in om))
                if w == 0:
                    return R0
                k = mp.matrix([[0, -om[2], om[1]], [om[2], 0, -om[0]], [-om[1], om[0], 0]]) / w
                th = w * mp.mpf(t)
                return R0 * (mp.eye(3) + mp.sin(th) * k + (1 - mp.cos(th)) * k * k)
            E0 = self.euler(self.p0)
            Et = self.euler(self.pi(t))
            return R0 * E0.T * rot("z", self.phi(t)) * Et


def ulps(x, k):
    """x moved by k ulps."""
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


def perturbed(p, steps=(-2, -1, 1, 2)):
    """Π₀ moved by up to ±2 ulps: each component alone, and the eight corners of ±2."""
    out = []
    for i in range(3):
        for k in steps:
            q = list(p)
            q[i] = ulps(q[i], k)
            out.append(q)
    for sx in (-2, 2):
        for sy in (-2, 2):
            for sz in (-2, 2):
                out.append([ulps(p[0], sx), ulps(p[1], sy), ulps(p[2], sz)])
    return out


def check():
    """The whole construction against mpmath's Taylor-series integration of Π̇ = Π × Ω, Ṙ = RΩ̂."""
    r0 = [[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]]
    cases = [
        ((1.0, 2.0, 3.0), (0.4, 1.0, 0.3), 3),
        ((1.0, 2.0, 3.0), (1.0, 0.3, -0.2), 3),
        ((3.0, 1.0, 2.0), (-0.4, 0.7, 0.9), 2.5),
        ((2.0, 3.0, 6.0), (1.0, 0.5, 1.0), 4),  # on the separatrix
        ((2.0, 3.0, 6.0), (-1.0, -0.5, 1.0), 3),  # on the separatrix, other branch
        ((2.0, 3.0, 6.0), (1.0, 0.5, ulps(1.0, 1)), 3),  # an ulp outside
        ((6.0, 2.0, 3.0), (1.0, 0.3, -0.7), 3),
    ]
    worst = 0
    for I, p, t in cases:
        orbit = Orbit(I, p)
        In = [mp.mpf(x) for x in I]

        def f(_t, y):
            om = [y[i] / In[i] for i in range(3)]
            R = [y[3 + 3 * i: 6 + 3 * i] for i in range(3)]
            W = [[0, -om[2], om[1]], [om[2], 0, -om[0]], [-om[1], om[0], 0]]
            dR = [[sum(R[i][k] * W[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
            return cross(y[:3], om) + [x for row in dR for x in row]

        y0 = [mp.mpf(x) for x in p] + [mp.mpf(x) for row in r0 for x in row]
        y = mp.odefun(f, 0, y0)(t)
        pi, R = orbit.pi(t), orbit.attitude(r0, t)
        e = max([abs(pi[i] - y[i]) for i in range(3)] + [abs(R[i, j] - y[3 + 3 * i + j]) for i in range(3) for j in range(3)])
        worst = max(worst, e)
        assert e < mp.mpf(10) ** -30, (I, p, t, e)
    return worst
