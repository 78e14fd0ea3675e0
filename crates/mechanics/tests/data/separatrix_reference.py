"""References for tests/models/exact_flow.rs: states on and near the separatrix, Π(t) and R(t).

On the separatrix (|Π|² = 2hI_mid exactly, in rational arithmetic): Π approaches the middle axis
for ever; times up to 10⁶. Near it: an ulp either side, the issue-#29 family states whose
discriminant rounds to 0 in floating point (found here by evaluating the flow's former formula in
doubles), and states 10⁻¹⁰ to 2·10⁻¹⁹ from the middle axis (k'² from 10⁻²⁰ to 10⁻³⁷, past the
flow's switch to the k = 1 limits at k' = 2⁻⁶⁰). On the nearly symmetric body
𝕀 = (2, 2(1 + 10⁻¹²), 3): states on and within 2 ulps of its separatrix, where the orbit's phase
moves by λt ≈ 3·10⁻⁷ t while the body precesses at O(1). Closer states (k'² below the double range) would
need some 700 digits here, hours per line: the crate's functions there are checked against
elliptic_reference.py down to k' = e⁻⁴⁰⁰ instead.

Each line: from free_body_mp (mpmath, independent of the crate: Landau's cn, sn, dn and his
Euler angles with the precession by quadrature; checked against mpmath's Taylor-series ODE solver
by free_body_mp.check(), run here first), Π(t) and R(t) for R(0) = R0 below, and the spreads of the
true Π(t), R(t) over the inputs within ±2 ulps of Π₀ (Π: each component moved by ±1, ±2 ulps and
the eight corners of ±2; R: each component by ±2 ulps) as max-norms; "nan" where not computed
(R on the separatrix, whose neighbours are off it: the test bounds those by ε·(1 + λt); R's
spread, and R beyond t = 1000, where mpmath needs more than 100 digits: k'² ≲ 10⁻³⁰).

Lines:  name I1 I2 I3 P1 P2 P3 t Π1 Π2 Π3 R11 … R33 spreadΠ spreadR
(inputs with repr: the test reads exactly the doubles mpmath saw; R0 is the same doubles there).

Regenerate (about an hour with -j 2; `--only NAME` for one case's lines):
    python3 crates/mechanics/tests/data/separatrix_reference.py -j 2 > crates/mechanics/tests/data/separatrix_reference.txt
"""
import math
import random
import sys
from multiprocessing import Pool

import mpmath as mp

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import free_body_mp as fb  # noqa: E402

R0 = [[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]]
NEAR = (1.0, 10.0, 1000.0)
ON = (1.0, 10.0, -10.0, 1000.0, 1e4, 1e6)


def former_float_d2(I, p):
    """The discriminant as the flow evaluated it before issue #29, in doubles."""
    m = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
    q = [x / m for x in p]
    lo, mid, hi = sorted(range(3), key=lambda i: I[i])
    return q[lo] * q[lo] * (I[lo] - I[mid]) / I[lo] + q[hi] * q[hi] * (I[hi] - I[mid]) / I[hi]


def issue_states(count):
    """Family states (random ordered moments, Π₁ random, Π₂ = 1, Π₃ from the separatrix
    condition) off the separatrix whose former discriminant rounded to exactly 0."""
    rng = random.Random(1729)
    out = []
    while len(out) < count:
        i1, i2, i3 = sorted(rng.uniform(0.5, 8.0) for _ in range(3))
        p1 = rng.uniform(-2.0, 2.0)
        p3 = math.copysign(p1 * math.sqrt((i2 - i1) * i3 / (i1 * (i3 - i2))), rng.choice((-1.0, 1.0)))
        I, p = (i1, i2, i3), (p1, 1.0, p3)
        if former_float_d2(I, p) == 0.0 and fb.on_separatrix(I, p) != 0:
            out.append((f"issue-{len(out)}", I, p, NEAR))
    return out


def nearly_symmetric_states():
    """On and within 2 ulps of the separatrix of the nearly symmetric body 𝕀 = (2, 2(1 + 10⁻¹²), 3)
    (I₂ − I₁ at 10⁻¹² of 𝕀: the motion along the orbit is slow, λ ≈ 3·10⁻⁷, and the precession
    is the flow's whole motion), the lie-sim extremes harness's states: Π₁ = 0.7, Π₂ = 1, Π₃ from
    the separatrix condition in doubles, then moved by ±1, ±2 ulps."""
    I = (2.0, 2.0 * (1.0 + 1e-12), 3.0)
    p1 = 0.7
    p3 = math.sqrt(p1 * p1 * (I[1] / I[0] - 1.0) / (1.0 - I[1] / I[2]))
    return [
        (f"nearly-symmetric{k:+d}", I, (p1, 1.0, fb.ulps(p3, k)), NEAR) for k in (0, 1, -1, 2, -2)
    ]


CASES = [
    ("on-236", (2.0, 3.0, 6.0), (1.0, 0.5, 1.0), ON),
    ("on-236-other-branch", (2.0, 3.0, 6.0), (-1.0, -0.5, 1.0), ON),
    ("on-236-at-equator", (2.0, 3.0, 6.0), (1.0, 0.0, -1.0), ON),
    ("on-236-near-axis", (2.0, 3.0, 6.0), (1e-100, 1.0, 1e-100), ON),
    ("on-permuted-axes", (6.0, 2.0, 3.0), (1.0, 1.0, 0.5), ON),
    ("on-1-1.5-3", (1.0, 1.5, 3.0), (0.25, 1.0, 0.25), ON),
    # Π₃ = 3Π₁ is the separatrix of (1, 5, 9); Π/|Π| rounded leaves it by an ulp.
    ("on-1-5-9", (1.0, 5.0, 9.0), (1.0, 0.7, 3.0), ON),
    ("ulp-outside", (2.0, 3.0, 6.0), (1.0, 0.5, fb.ulps(1.0, 1)), NEAR),
    ("ulp-inside", (2.0, 3.0, 6.0), (1.0, 0.5, fb.ulps(1.0, -1)), NEAR),
    ("ulp-outside-1-1.5-3", (1.0, 1.5, 3.0), (0.25, 1.0, fb.ulps(0.25, 1)), NEAR),
    ("axis-1e-10", (1.0, 2.0, 3.0), (1e-10, 1.0, 1e-10), NEAR),
    ("axis-1e-18", (1.0, 2.0, 3.0), (1e-18, 1.0, 1e-18), NEAR),
    ("axis-2e-19", (1.0, 2.0, 3.0), (2e-19, 1.0, 2e-19), NEAR),
] + issue_states(4) + nearly_symmetric_states()


def row(args):
    name, I, p, t, with_spread = args
    mp.mp.dps = 40
    orbit = fb.Orbit(I, p)
    # Beyond 100 working digits (k'² ≲ 10⁻³⁰ and the small components that come with it) the
    # quadrature of φ̇ is slow: R only while no whole period is integrated at them, and without
    # its spread (on the separatrix there is no period).
    on = fb.on_separatrix(I, p) == 0
    deep = orbit.dps > 100 and not on
    pi = orbit.pi(t)
    R = mp.matrix(3, 3) * mp.nan if deep and t > 1000 else orbit.attitude(R0, t)
    sp = 0
    # The neighbours only need the spread's leading digits: 20 digits suffice.
    for q in fb.perturbed(p):
        x = fb.Orbit(I, q, digits=20).pi(t)
        sp = max([sp] + [abs(x[i] - pi[i]) for i in range(3)])
    sr = mp.nan
    if with_spread and not on and not deep:
        sr = 0
        for i in range(3):
            for k in (-2, 2):
                q = list(p)
                q[i] = fb.ulps(q[i], k)
                x = fb.Orbit(I, q, digits=20).attitude(R0, t)
                sr = max([sr] + [abs(x[a, b] - R[a, b]) for a in range(3) for b in range(3)])
    vals = [name] + [repr(x) for x in I] + [repr(x) for x in p] + [repr(t)]
    vals += [mp.nstr(x, 20) for x in pi] + [mp.nstr(R[i, j], 20) for i in range(3) for j in range(3)]
    vals += [mp.nstr(sp, 3), mp.nstr(sr, 3)]
    return " ".join(vals)


def main():
    jobs = int(sys.argv[sys.argv.index("-j") + 1]) if "-j" in sys.argv else 1
    # `--only NAME`: that case's lines alone (to regenerate one case into the file).
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else None
    mp.mp.dps = 40
    if only is None:
        print("# free_body_mp.check(): max deviation from odefun", mp.nstr(fb.check(), 3), file=sys.stderr)
    work = [(name, I, p, t, True) for name, I, p, times in CASES for t in times if only in (None, name)]
    with Pool(jobs) as pool:
        for text in pool.imap(row, work):
            print(text, flush=True)


if __name__ == "__main__":
    main()
