"""h^2 term of the modified Hamiltonian of the theta = 1/2 Lie-Poisson scheme (tau = cay | exp) on
the free rigid body, state (Pi, R), by series expansion in h (sympy). Usage: python3 modified_lp_h2.py cay|exp

Scheme (crates/integrators/src/lie_poisson.rs, no potential), theta = 1/2:
  xi = h grad H(mubar), mubar = 1/2 dtau*_{-xi/2} mu + 1/2 dtau*_{xi/2} mu1,
  mu1 = (tau(xi/2)^2)^T mu, R1 = R tau(xi/2)^2.
A symmetric Poisson method has the modified Hamiltonian H + h^2 H_2 + O(h^4), with H_2 a left-invariant
function of Pi: the local error is h^3 (Pi x grad H_2, R grad H_2^) + O(h^4). H_2 = Q(y) + lam |Pi|^4,
y_i = Pi_i^2, Q fitted from the Pi error (Q's p1^4 coefficient set to 0), lam from the R error.
"""
import sys, itertools
import sympy as sp

tau = sys.argv[1]
h = sp.Symbol('h')
p = sp.Matrix(sp.symbols('p1 p2 p3'))
u = sp.symbols('u1 u2 u3')
N = 3

def trunc(e):
    e = sp.expand(e)
    return sum(e.coeff(h, k) * h**k for k in range(N + 1))
tv = lambda v: v.applyfunc(trunc)
def skew(w):
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
def ser(coeffs, s):
    out, sk = 0, 1
    for c in coeffs:
        out += c * sk; sk = trunc(sk * s)
    return trunc(out)
K = 2
def tau_mat(w):
    s = trunc(w.dot(w)); W = skew(w)
    if tau == 'cay':
        A = ser([(-sp.Rational(1, 4))**k for k in range(K)], s); B = A / 2
    else:
        A = ser([(-1)**k / sp.factorial(2*k+1) for k in range(K)], s)
        B = ser([(-1)**k / sp.factorial(2*k+2) for k in range(K)], s)
    return tv(sp.eye(3) + A * W + B * tv(W * W))
def dtau_dual(w, m):
    s = trunc(w.dot(w)); wm = tv(w.cross(m))
    if tau == 'cay':
        f = ser([(-sp.Rational(1, 4))**k for k in range(K)], s)
        return tv((2 * m + wm) * f / 2)
    b = ser([(-1)**k / sp.factorial(2*k+2) for k in range(K)], s)
    c = ser([(-1)**k / sp.factorial(2*k+3) for k in range(K)], s)
    return tv(m + wm * b + tv(w.cross(wm)) * c)
U = sp.diag(*u)
grad = lambda q: U * q
xi = h * grad(p)
for _ in range(N):
    t = tau_mat(xi / 2); E = tv(t * t)
    mu1 = tv(E.T * p)
    bar = tv(dtau_dual(-xi / 2, p) / 2 + dtau_dual(xi / 2, mu1) / 2)
    xi = tv(h * grad(bar))
t = tau_mat(xi / 2); E = tv(t * t); mu1 = tv(E.T * p)
# exact flow of (E, Pi) from (I, p): E' = E Om^, Pi' = Pi x Om; Taylor via symbolic time derivatives
Es, Ps = sp.eye(3), p
Ecoef, Pcoef = [Es], [Ps]
Ecur, Pcur = Es, Ps
# derivatives as functions of (E, Pi) with generic symbols
Em = sp.Matrix(3, 3, sp.symbols('e0:9')); Pm = sp.Matrix(sp.symbols('q1 q2 q3'))
def field(Ex, Px):
    om = U * Px
    return Ex * skew(om), Px.cross(om)
def D(FE, FP):  # Lie derivative of (FE, FP) along the field
    fE, fP = field(Em, Pm)
    vars_ = list(Em) + list(Pm); vel = list(fE) + list(fP)
    dE = sp.Matrix(3, 3, lambda i, j: sp.expand(sum(sp.diff(FE[i, j], v) * w for v, w in zip(vars_, vel))))
    dP = sp.Matrix(3, 1, lambda i, j: sp.expand(sum(sp.diff(FP[i], v) * w for v, w in zip(vars_, vel))))
    return dE, dP
FE, FP = Em, Pm
exE, exP = sp.zeros(3, 3), sp.zeros(3, 1)
for k in range(N + 1):
    sub = {**{Em[i]: sp.eye(3)[i] for i in range(9)}, **{Pm[i]: p[i] for i in range(3)}}
    exE += h**k / sp.factorial(k) * FE.subs(sub); exP += h**k / sp.factorial(k) * FP.subs(sub)
    if k < N:
        FE, FP = D(FE, FP)
errP = (mu1 - exP).applyfunc(sp.expand); errE = (E - exE).applyfunc(sp.expand)
for j in range(3):
    assert all(sp.expand(x.coeff(h, j)) == 0 for x in list(errP) + list(errE)), j
dP = errP.applyfunc(lambda x: x.coeff(h, 3)); dE = errE.applyfunc(lambda x: x.coeff(h, 3))
y = [p[i]**2 for i in range(3)]
mons = [y[i] * y[j] for i in range(3) for j in range(i, 3)]
cs = sp.symbols('c0:6'); lam = sp.Symbol('lam')
H2 = sum(c * m for c, m in zip(cs, mons)) + lam * (y[0] + y[1] + y[2])**2
g2 = sp.Matrix([sp.diff(H2, p[i]) for i in range(3)])
eqs = []
for comp in list(p.cross(g2) - dP) + list(skew(g2) - dE):
    eqs += sp.Poly(sp.expand(comp), *p).coeffs()
sol = sp.solve(eqs + [cs[0]], list(cs) + [lam], dict=True)
assert sol, "no left-invariant H_2 fits the local error"
sol = sol[0]
print(tau, "H_2 coefficients :")
for c, m in zip(cs, mons):
    print("  ", m, ":", sp.factor(sol[c]))
print("   |Pi|^4 (lam):", sp.factor(sol[lam]))
