"""Reference solutions of the free rigid body for tests/models/exact_flow.rs, at 30 significant digits.

Integrates  Π' = Π × Ω,  R' = R Ω̂,  Ω = 𝕀⁻¹Π  with mpmath's Taylor-series ODE solver (odefun) at
40 working digits (independent of the crate: no elliptic functions), and prints one line per case:
name, inertia (9), Π₀ (3), R₀ (9, row-major), t, Π(t) (3), R(t) (9).

Regenerate:  python3 crates/mechanics/tests/data/free_body_reference.py > crates/mechanics/tests/data/free_body_reference.txt
"""
import mpmath as mp

mp.mp.dps = 40


def rodrigues(w):
    w = [mp.mpf(x) for x in w]
    th = mp.sqrt(sum(x * x for x in w))
    k = mp.matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    return mp.eye(3) + (mp.sin(th) / th) * k + ((1 - mp.cos(th)) / th**2) * (k * k)


R0 = rodrigues(["0.3", "-0.5", "0.8"])


def solve(name, inertia, pi0, t):
    # The exact values of the doubles the test parses, so that the reference starts where the
    # crate does (near the separatrix a change of 1 ulp in Π₀ shows at 1e-15).
    inertia = [[mp.mpf(float(x)) for x in row] for row in inertia]
    pi0 = [mp.mpf(float(x)) for x in pi0]
    I = mp.matrix(inertia)
    Iinv = I ** -1
    y0 = list(pi0) + [R0[i, j] for i in range(3) for j in range(3)]

    def f(_t, y):
        p = mp.matrix(y[:3])
        om = Iinv * p
        R = mp.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                R[i, j] = y[3 + 3 * i + j]
        dp = [p[1] * om[2] - p[2] * om[1], p[2] * om[0] - p[0] * om[2], p[0] * om[1] - p[1] * om[0]]
        W = mp.matrix([[0, -om[2], om[1]], [om[2], 0, -om[0]], [-om[1], om[0], 0]])
        dR = R * W
        return [sign * x for x in dp + [dR[i, j] for i in range(3) for j in range(3)]]

    # odefun integrates forwards only: t < 0 runs the reversed field to |t|.
    sign = -1 if mp.mpf(t) < 0 else 1
    sol = mp.odefun(f, 0, y0)
    y = sol(abs(mp.mpf(t)))
    vals = [name] + [mp.nstr(mp.mpf(x), 30) for row in inertia for x in row]
    vals += [mp.nstr(mp.mpf(x), 30) for x in pi0]
    vals += [mp.nstr(R0[i, j], 30) for i in range(3) for j in range(3)]
    vals += [mp.nstr(mp.mpf(t), 30)] + [mp.nstr(x, 30) for x in y]
    print(" ".join(vals), flush=True)


diag = lambda a, b, c: [[a, 0, 0], [0, b, 0], [0, 0, c]]
full = [["2.0", "0.1", "0.3"], ["0.1", "3.0", "-0.2"], ["0.3", "-0.2", "4.0"]]
cases = [
    ("generic-major", diag(1, 2, 3), ["0.2", "0.3", "1.0"], "5"),
    ("generic-minor", diag(1, 2, 3), ["1.0", "0.3", "0.2"], "5"),
    ("generic-mixed-signs", diag(1, 2, 3), ["-0.4", "1.0", "-0.3"], "5"),
    ("full-tensor", full, ["0.5", "1.0", "-0.7"], "4"),
    ("near-separatrix", diag(1, "1.5", 3), ["0.3", "1.0", "0.300000000000001"], "5"),
    ("on-separatrix", diag(1, "1.5", 3), ["0.25", "1.0", "0.25"], "5"),
    ("symmetric-prolate", diag(1, 1, "2.5"), ["0.6", "-0.4", "1.3"], "5"),
    ("symmetric-oblate", diag(1, "2.5", "2.5"), ["0.6", "-0.4", "1.3"], "5"),
    ("principal-axis-1", diag(1, 2, 3), ["1.3", "0", "0"], "5"),
    ("principal-axis-2", diag(1, 2, 3), ["0", "1.3", "0"], "5"),
    ("principal-axis-3", diag(1, 2, 3), ["0", "0", "-1.3"], "5"),
    ("near-axis", diag(1, 2, 3), ["1e-7", "2e-7", "1.0"], "5"),
    ("backwards", diag(1, 2, 3), ["0.4", "1.0", "0.3"], "-5"),
    ("long", diag(1, 2, 3), ["0.4", "1.0", "0.3"], "40"),
    ("near-saddle", diag(1, 2, 3), ["0.001", "2.0", "0.001"], "3"),
]
for c in cases:
    solve(*c)
