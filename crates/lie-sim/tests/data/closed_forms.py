"""Closed-form final states for tests/reference.rs, at 30 significant digits (mpmath, 40 working).

Each case is a scene whose exact solution is known in closed form; the test writes the scene from
the parameters below (every number a double, printed exactly with repr), runs `lie-sim trade
--write-reference`, and checks that the reference's reported error bounds its distance from the
state printed here. The initial attitude is given as a matrix (the doubles of a rotation, used by
lie-sim as they are), so that the closed form starts from exactly the scene's initial state.

- top:     free symmetric top 𝕀 = diag(i, i, i3) on SO(3):  Π(t) = Rz(−βt) Π₀,
           R(t) = R₀ exp(t Π̂₀ / i) Rz(βt),  β = Π₃ (1/i3 − 1/i).
- se3:     the free symmetric body on SE(3), μ = (Π, P):  Π, R as the top's;  the spatial momentum
           p = R₀P₀ is constant, P(t) = R(t)ᵀ p,  x(t) = x₀ + t p / m; also with fast spins
           (Ω₃ = 10 … 50 rad/s, T up to 30), where rounding amplified over T dominates.
- torque:  a rotation about e₃ (Π₀ = (0, 0, Π₃₀), I₃) under the body torque u(t) e₃, u piecewise
           linear through the knots (held after the last), and damping F = −DΩ (d₃ = D₃₃): on a
           piece u = α + βτ (τ = t − tₛ), with a = d₃/I₃, B = β/a, A = (α − B)/a,
           Π₃ = A + Bτ + (Π₃ₛ − A) e^{−aτ}, and the angle φ grows by
           (Aτ + Bτ²/2 + (Π₃ₛ − A)(1 − e^{−aτ})/a) / I₃;  R = R₀ Rz(φ).

One line per case:  kind name T | parameters … | R₀ (9, row-major) | μ(T) | g(T) (row-major).

Regenerate:  python3 crates/lie-sim/tests/data/closed_forms.py > crates/lie-sim/tests/data/closed_forms.txt
"""
import mpmath as mp
import random

mp.mp.dps = 40


def hat(w):
    return mp.matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def rod(w):
    w = [mp.mpf(x) for x in w]
    th = mp.sqrt(sum(x * x for x in w))
    k = hat(w)
    if th == 0:
        return mp.eye(3)
    return mp.eye(3) + (mp.sin(th) / th) * k + ((1 - mp.cos(th)) / th**2) * (k * k)


def rz(a):
    return rod([0, 0, a])


def dbl(x):
    """The double nearest x, as an mpf (what the scene file carries)."""
    return mp.mpf(float(x))


def r0_of(w):
    r = rod(w)
    return mp.matrix([[dbl(r[i, j]) for j in range(3)] for i in range(3)])


def top(i, i3, r0, pi0, t):
    beta = pi0[2] * (1 / i3 - 1 / i)
    pi = rz(-beta * t) * mp.matrix(pi0)
    r = r0 * rod([x * t / i for x in pi0]) * rz(beta * t)
    return r, pi


def fmt(xs):
    return " ".join(mp.nstr(x, 30, min_fixed=1, max_fixed=0) for x in xs)


def flat(m):
    return [m[i, j] for i in range(m.rows) for j in range(m.cols)]


def rep(xs):
    return " ".join(repr(float(x)) for x in xs)


rnd = random.Random(15)


def u(a, b):
    return rnd.uniform(a, b)


def se3_line(name, t, i, i3, r0, pi0, T, r, pi):
    """The se3 case over the top's (r, pi): mass, x₀, P₀ drawn next; P(T) = RᵀR₀P₀, x(T) = x₀ + T R₀P₀/m."""
    mass = dbl(u(0.5, 3))
    x0 = [dbl(u(-1, 1)) for _ in range(3)]
    p0 = [dbl(u(-1, 1)) for _ in range(3)]
    p_s = r0 * mp.matrix(p0)
    p = r.T * p_s
    x = [x0[k] + T * p_s[k] / mass for k in range(3)]
    g = mp.eye(4)
    for a in range(3):
        for b in range(3):
            g[a, b] = r[a, b]
        g[a, 3] = x[a]
    return (
        f"se3 {name} {t!r} | {rep([i, i3, mass] + pi0 + p0 + x0)} | {rep(flat(r0))} | "
        f"{fmt(list(pi) + list(p))} | {fmt(flat(g))}"
    )


lines = []
for n, t in enumerate([1.0, 10.0, 30.0, 10.0, 5.0]):
    i, i3 = dbl(u(1, 3)), dbl(u(1, 4))
    w0 = [u(-1, 1) for _ in range(3)]
    r0 = r0_of(w0)
    pi0 = [dbl(u(-2, 2)) for _ in range(3)]
    T = mp.mpf(t)
    r, pi = top(i, i3, r0, pi0, T)
    lines.append(f"top top{n} {t!r} | {rep([i, i3] + pi0)} | {rep(flat(r0))} | {fmt(list(pi))} | {fmt(flat(r))}")
    lines.append(se3_line("se3-" + str(n), t, i, i3, r0, pi0, T, r, pi))

# Fast spins (Ω₃ = 10 … 50 rad/s) in SE(3), where rounding, amplified over T, dominates the
# reference's error and two runs can agree far better than either is accurate.
for n, t in enumerate([10.0, 30.0, 30.0, 10.0, 30.0, 30.0]):
    i, i3 = dbl(u(1, 3)), dbl(u(0.3, 1))
    w0 = [u(-1, 1) for _ in range(3)]
    r0 = r0_of(w0)
    pi0 = [dbl(u(-2, 2)), dbl(u(-2, 2)), dbl(u(8, 15))]
    T = mp.mpf(t)
    r, pi = top(i, i3, r0, pi0, T)
    lines.append(se3_line("fast-" + str(n), t, i, i3, r0, pi0, T, r, pi))

# torque: knots (times, values of u) and damping; T = 10.
for n, (times, values, d3, i3, pi30) in enumerate(
    [
        ([0.0, 2.0, 2.5], [1.0, 1.0, -0.5], 0.6, 3.0, 2.0),
        ([0.0, 1.0, 4.0, 4.25], [0.0, 2.0, 2.0, 0.0], 0.3, 1.5, -1.0),
    ]
):
    T = mp.mpf(10)
    w0 = [u(-1, 1) for _ in range(3)]
    r0 = r0_of(w0)
    a = mp.mpf(d3) / i3
    p3, phi = mp.mpf(pi30), mp.mpf(0)
    # pieces: [t_k, t_{k+1}] linear, then held after the last knot
    pieces = []
    for k in range(len(times) - 1):
        tau = mp.mpf(times[k + 1]) - times[k]
        pieces.append((tau, mp.mpf(values[k]), (mp.mpf(values[k + 1]) - values[k]) / tau))
    pieces.append((T - times[-1], mp.mpf(values[-1]), mp.mpf(0)))
    for tau, alpha, beta in pieces:
        b = beta / a
        aa = (alpha - b) / a
        decay = mp.e ** (-a * tau)
        phi += (aa * tau + b * tau**2 / 2 + (p3 - aa) * (1 - decay) / a) / i3
        p3 = aa + b * tau + (p3 - aa) * decay
    r = r0 * rz(phi)
    lines.append(
        f"torque torque{n} 10.0 | {rep([i3, d3, pi30] + times + values)} | {rep(flat(r0))} | "
        f"{fmt([0, 0, p3])} | {fmt(flat(r))}"
    )

print("\n".join(lines))
