"""Modified Hamiltonians of the Lie-Poisson schemes on the free rigid body, by series expansion in h.

Usage: python3 modified_lp.py            (all four (tau, theta); about two minutes)
       python3 modified_lp.py cay half   (one of them, printed only)

For tau in {exp, cay} and theta in {1/2, 0} (crates/integrators/src/lie_poisson.rs, no potential):
  theta = 1/2: xi = h grad H(mubar), mubar = 1/2 dtau*_{-xi/2} mu + 1/2 dtau*_{xi/2} mu1,
               mu1 = (tau(xi/2)^2)^T mu, R1 = R tau(xi/2)^2;
  theta = 0:   xi = h grad H(mubar), mubar = dtau*_{xi} mu1, mu1 = tau(xi)^T mu, R1 = R tau(xi).
One step from (R, Pi) = (I, p) is expanded in h with the polynomial ring QQ[h, p, u] (u_i = 1/I_i, the
principal inverse moments) and compared with the Taylor series of the exact flow Pi' = Pi x U Pi,
R' = R (U Pi)^. A Poisson method has a modified Hamiltonian H + h^2 H_2 + h^4 H_4 + ... when it is
symmetric; its local error is then h^3 X_{H_2} + h^5 X_{H_4} + ..., X_F = (Pi x grad F, R (grad F)^). Each
H_k is fitted as a left-invariant function Q(y) + lam |Pi|^{k+2}, y_i = p_i^2 (Q's p1^{k+2} coefficient set to
0: the Pi error cannot see functions of the Casimir |Pi|^2, the R error fixes lam):

  1. the scheme applied to H: no h^0..h^2 error; H_2 from the h^3 error;
  2. the scheme applied to H - h^2 H_2: no h^3 and no h^4 error (so theta = 0, not symmetric in general,
     has no h^3 term here: without a potential it coincides with theta = 1, its adjoint); H_4 from h^5;
  3. check: the scheme applied to H - h^2 H_2 - h^4 H_4 has no error through h^6 (order 6).

So H~_h = H - h^2 H_2 is order 4 and H~_h = H - h^2 H_2 - h^4 H_4 order 6 at the cost of one step of the
scheme. The coefficients are polynomials in the principal u_i; by the Ad-equivariance of exp and cay on
SO(3) (Q tau(xi) Q^T = tau(Q xi)) the same formulas serve any symmetric quadratic form h = 1/2 Pi.A Pi,
evaluated in A's eigenframe.

Writes tools/modified_lp_<tau>_<theta>.txt (readable) and src/modified/coefficients.rs (the tables the
crate evaluates, so that nothing is transcribed by hand).
"""
import os
import sys
import time

import sympy as sp
from sympy import QQ
from sympy.polys.rings import ring

R, h, p1, p2, p3, u1, u2, u3 = ring("h p1 p2 p3 u1 u2 u3", QQ)
P = [p1, p2, p3]
U = [u1, u2, u3]
BIG = 10**6


def trunc(x, n):
    return R.from_dict({m: c for m, c in x.items() if m[0] <= n}) if x else x


def tv(v, n):
    return [trunc(x, n) for x in v]


def dot(a, b, n):
    return trunc(sum(x * y for x, y in zip(a, b)), n)


def cross(a, b, n):
    return tv([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]], n)


def scal(c, v, n):
    return tv([c * x for x in v], n)


def add(*vs):
    return [sum(xs) for xs in zip(*vs)]


def mat_t_vec(m, v, n):
    return tv([sum(m[j][i] * v[j] for j in range(3)) for i in range(3)], n)


def matmul(a, b, n):
    return [[trunc(sum(a[i][k] * b[k][j] for k in range(3)), n) for j in range(3)] for i in range(3)]


def skew(w):
    return [[R(0), -w[2], w[1]], [w[2], R(0), -w[0]], [-w[1], w[0], R(0)]]


def identity():
    return [[R(1) if i == j else R(0) for j in range(3)] for i in range(3)]


def series(coeffs, s, n):
    out, sk = R(0), R(1)
    for c in coeffs:
        out += c * sk
        sk = trunc(sk * s, n)
    return trunc(out, n)


def fact(k):
    return int(sp.factorial(k))


def tau_mat(tau, w, n):
    """tau(w) = I + A w^ + B w^^2 (exp: A = sin|w|/|w|, B = (1 - cos|w|)/|w|^2; cay: A = 1/(1 + |w|^2/4), B = A/2)."""
    k = n // 2 + 1
    s = dot(w, w, n)
    w1 = skew(w)
    w2 = matmul(w1, w1, n)
    if tau == 'cay':
        a = series([QQ(-1, 4) ** j for j in range(k)], s, n)
        b = trunc(a * QQ(1, 2), n)
    else:
        a = series([QQ((-1) ** j, fact(2 * j + 1)) for j in range(k)], s, n)
        b = series([QQ((-1) ** j, fact(2 * j + 2)) for j in range(k)], s, n)
    i3 = identity()
    return [[trunc(i3[i][j] + a * w1[i][j] + b * w2[i][j], n) for j in range(3)] for i in range(3)]


def dtau_dual(tau, w, m, n):
    """d^{L*}tau_w m (cay: (m + w x m/2)/(1 + |w|^2/4); exp: m + b w x m + c w x (w x m))."""
    k = n // 2 + 1
    s = dot(w, w, n)
    wm = cross(w, m, n)
    if tau == 'cay':
        f = series([QQ(-1, 4) ** j for j in range(k)], s, n)
        return tv([f * (m[i] + QQ(1, 2) * wm[i]) for i in range(3)], n)
    b = series([QQ((-1) ** j, fact(2 * j + 2)) for j in range(k)], s, n)
    c = series([QQ((-1) ** j, fact(2 * j + 3)) for j in range(k)], s, n)
    wwm = cross(w, wm, n)
    return tv([m[i] + b * wm[i] + c * wwm[i] for i in range(3)], n)


def substitute(polys, v, n):
    """The polynomials `polys` in (h, p, u) evaluated at p := v (truncated series)."""
    powers = {}

    def pw(k, e):
        if (k, e) not in powers:
            powers[(k, e)] = v[k] if e == 1 else trunc(pw(k, e - 1) * v[k], n)
        return powers[(k, e)]

    out = []
    for g in polys:
        acc = R(0)
        for m, c in g.items():
            term = R(c) * h ** m[0] * u1 ** m[4] * u2 ** m[5] * u3 ** m[6]
            for k in range(3):
                if m[1 + k]:
                    term = trunc(term * pw(k, m[1 + k]), n)
            acc += term
        out.append(trunc(acc, n))
    return out


def scheme(tau, theta, hamiltonian, n):
    """One step from (I, p) of the scheme applied to `hamiltonian` (a polynomial in h, p, u): (R1, Pi1)."""
    grad = [hamiltonian.diff(x) for x in P]
    p = list(P)
    xi = tv([h * U[i] * p[i] for i in range(3)], n)
    for _ in range(n):  # each fixed-point sweep gains one power of h
        if theta == 'half':
            t = tau_mat(tau, scal(QQ(1, 2), xi, n), n)
            mu1 = mat_t_vec(matmul(t, t, n), p, n)
            bar = add(scal(QQ(1, 2), dtau_dual(tau, scal(QQ(-1, 2), xi, n), p, n), n),
                      scal(QQ(1, 2), dtau_dual(tau, scal(QQ(1, 2), xi, n), mu1, n), n))
        else:
            mu1 = mat_t_vec(tau_mat(tau, xi, n), p, n)
            bar = dtau_dual(tau, xi, mu1, n)
        xi = tv([h * x for x in substitute(grad, tv(bar, n), n)], n)
    if theta == 'half':
        t = tau_mat(tau, scal(QQ(1, 2), xi, n), n)
        e = matmul(t, t, n)
    else:
        e = tau_mat(tau, xi, n)
    return e, mat_t_vec(e, p, n)


def exact(n):
    """Taylor series of the exact flow from (I, p), by the recursions of Pi' = Pi x U Pi and R' = R W."""
    pk = [list(P)]
    for k in range(n):
        acc = [R(0)] * 3
        for j in range(k + 1):
            acc = add(acc, cross(pk[j], [U[i] * pk[k - j][i] for i in range(3)], BIG))
        pk.append([x * QQ(1, k + 1) for x in acc])
    wk = [skew([U[i] * pk[k][i] for i in range(3)]) for k in range(n + 1)]
    rk = [identity()]
    for k in range(n):
        acc = [[R(0)] * 3 for _ in range(3)]
        for j in range(k + 1):
            m = matmul(rk[j], wk[k - j], BIG)
            acc = [[acc[a][b] + m[a][b] for b in range(3)] for a in range(3)]
        rk.append([[x * QQ(1, k + 1) for x in row] for row in acc])
    mu = [sum(h ** k * pk[k][i] for k in range(n + 1)) for i in range(3)]
    e = [[sum(h ** k * rk[k][a][b] for k in range(n + 1)) for b in range(3)] for a in range(3)]
    return e, mu


def coeff_h(x, k):
    return R.from_dict({(0,) + m[1:]: c for m, c in x.items() if m[0] == k})


def local_error(tau, theta, hamiltonian, n):
    """(error of Pi1, error of R1) of the scheme on `hamiltonian` against the exact flow of H, to h^n."""
    e, mu1 = scheme(tau, theta, hamiltonian, n)
    ex, mx = exact(n)
    return [trunc(a - b, n) for a, b in zip(mu1, mx)], \
        [trunc(e[i][j] - ex[i][j], n) for i in range(3) for j in range(3)]


def vanishes_through(err, k):
    dp, de = err
    return all(coeff_h(x, j) == 0 for j in range(k + 1) for x in dp + de)


def exponents(deg):
    return [(a, b, deg - a - b) for a in range(deg, -1, -1) for b in range(deg - a, -1, -1)]


PS = sp.symbols('p1 p2 p3')
US = sp.symbols('u1 u2 u3')


def fit(err, k, deg):
    """The left-invariant F with X_F = the h^k coefficient of the local error (F of degree deg in y)."""
    dp = [coeff_h(x, k).as_expr() for x in err[0]]
    de = [coeff_h(x, k).as_expr() for x in err[1]]
    y = [x ** 2 for x in PS]
    mons = [sp.Mul(*[y[i] ** e[i] for i in range(3)]) for e in exponents(deg)]
    cs = sp.symbols('c0:%d' % len(mons))
    lam = sp.Symbol('lam')
    f = sum(c * m for c, m in zip(cs, mons)) + lam * (y[0] + y[1] + y[2]) ** deg
    g = sp.Matrix([sp.diff(f, x) for x in PS])
    lhs = list(sp.Matrix(PS).cross(g)) + list(sp.Matrix([[0, -g[2], g[1]], [g[2], 0, -g[0]], [-g[1], g[0], 0]]))
    eqs = []
    for left, right in zip(lhs, dp + de):
        eqs += sp.Poly(sp.expand(left - right), *PS).coeffs()
    sol = sp.solve(eqs + [cs[mons.index(y[0] ** deg)]], list(cs) + [lam], dict=True)
    assert sol, "no left-invariant function fits the local error"
    sol = sol[0]
    table = [(m, sp.factor(sol[c])) for c, m in zip(cs, mons)]
    return sp.expand(f.subs(sol)), table, sp.factor(sol[lam])


def derive(tau, theta, out=print, check=True):
    t0 = time.time()
    big_h = QQ(1, 2) * (u1 * p1 ** 2 + u2 * p2 ** 2 + u3 * p3 ** 2)
    err = local_error(tau, theta, big_h, 3)
    assert vanishes_through(err, 2)
    h2, tab2, lam2 = fit(err, 3, 2)
    out(f"{tau}, theta = {'1/2' if theta == 'half' else '0'}: y_i = p_i^2 in the principal frame, u_i = 1/I_i")
    out("H_2 (the h^2 term of the modified Hamiltonian of the scheme on H):")
    for m, c in tab2:
        out(f"   {m} : {c}")
    out(f"   |Pi|^4 : {lam2}")
    h2r = R(h2)
    err = local_error(tau, theta, big_h - h ** 2 * h2r, 5)
    assert vanishes_through(err, 4)
    out("the scheme on H - h^2 H_2: no h^3 and no h^4 local error (order 4)")
    h4, tab4, lam4 = fit(err, 5, 3)
    out("H_4 (the h^4 term of the modified Hamiltonian of the scheme on H - h^2 H_2):")
    for m, c in tab4:
        out(f"   {m} : {c}")
    out(f"   |Pi|^6 : {lam4}")
    if check:
        err = local_error(tau, theta, big_h - h ** 2 * h2r - h ** 4 * R(h4), 6)
        assert vanishes_through(err, 6)
        out("check: the scheme on H - h^2 H_2 - h^4 H_4 has no local error through h^6 (order 6)")
    out(f"({time.time() - t0:.0f} s)")
    return h2, h4


def rust_table(name, poly, doc):
    """A Rust table of the terms num/den * u^a * y^b of `poly` (a polynomial in p with only even powers)."""
    terms = sp.Poly(sp.expand(poly), *PS, *US).terms()
    lines = [f"/// {doc}", f"pub(crate) const {name}: &[Term] = &["]
    for monom, c in sorted(terms, key=lambda t: t[0], reverse=True):
        b = [monom[i] // 2 for i in range(3)]
        assert all(monom[i] % 2 == 0 for i in range(3))
        a = monom[3:]
        c = sp.Rational(c)
        lines.append(f"    Term {{ u: [{a[0]}, {a[1]}, {a[2]}], y: [{b[0]}, {b[1]}, {b[2]}], "
                     f"num: {c.p}, den: {c.q} }},")
    lines.append("];")
    return "\n".join(lines)


HEADER = '''//! Generated by `crates/mechanics/tools/modified_lp.py` (sympy) — do not edit by hand; rerun
//! the script. The h² and h⁴ terms H₂, H₄ of the modified Hamiltonians of the Lie–Poisson schemes
//! on the free rigid body, as sums of terms `num/den · u₁^a₁ u₂^a₂ u₃^a₃ · y₁^b₁ y₂^b₂ y₃^b₃`
//! with yᵢ = Πᵢ² in the principal frame and uᵢ = 1/Iᵢ (see the script's docstring and the
//! readable `tools/modified_lp_<tau>_<theta>.txt`).

/// One term `num/den · uᵃ · yᵇ` of a table.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Term {
    /// Exponents of u₁, u₂, u₃.
    pub u: [u8; 3],
    /// Exponents of y₁, y₂, y₃.
    pub y: [u8; 3],
    /// Numerator of the rational coefficient.
    pub num: i64,
    /// Denominator of the rational coefficient.
    pub den: i64,
}'''


FOOTER = '''/// The (H₂, H₄) tables of τ = Cayley (`cayley`) or exp, θ = ½ (`half`) or θ = 0.
pub(crate) fn tables(cayley: bool, half: bool) -> (&'static [Term], &'static [Term]) {
    match (cayley, half) {
        (false, true) => (EXP_HALF_H2, EXP_HALF_H4),
        (false, false) => (EXP_ZERO_H2, EXP_ZERO_H4),
        (true, true) => (CAY_HALF_H2, CAY_HALF_H4),
        (true, false) => (CAY_ZERO_H2, CAY_ZERO_H4),
    }
}'''


def main():
    if len(sys.argv) == 3:
        derive(sys.argv[1], sys.argv[2])
        return
    here = os.path.dirname(os.path.abspath(__file__))
    tables = [HEADER]
    for tau in ['exp', 'cay']:
        for theta in ['half', 'zero']:
            lines = []
            h2, h4 = derive(tau, theta, out=lines.append)
            with open(os.path.join(here, f"modified_lp_{tau}_{theta}.txt"), "w") as f:
                f.write("\n".join(lines[:-1]) + "\n")
            print("\n".join(lines))
            th = '½' if theta == 'half' else '0'
            key = f"{tau.upper()}_{theta.upper()}"
            tables.append(rust_table(f"{key}_H2", h2, f"H₂ of τ = {tau}, θ = {th}."))
            tables.append(rust_table(f"{key}_H4", h4, f"H₄ of τ = {tau}, θ = {th}."))
    tables.append(FOOTER)
    with open(os.path.join(here, "..", "src", "modified", "coefficients.rs"), "w") as f:
        f.write("\n\n".join(tables) + "\n")


if __name__ == '__main__':
    main()
