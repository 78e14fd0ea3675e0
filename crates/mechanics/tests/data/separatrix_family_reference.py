"""References for tests/models/exact_flow.rs: the separatrix family of issue #29 and generic states.

Separatrix family ("family" lines): random ordered moments I₁ < I₂ < I₃ (log-uniform in
[0.1, 10]), Π₁ random in [−2, 2], Π₂ = 1, Π₃ from
the separatrix condition |Π|² = 2hI₂ in doubles (so each state lies within ulps of the
separatrix, on either side or on it), both signs of Π₁ and Π₃. Generic states ("generic" lines):
random moments in any order, Π random on the unit sphere scaled by a random size, and states with
a component near its zero.

For each state and t: Π(t) of the double input from free_body_mp (mpmath, 30 digits, independent
of the crate), and the spread of the true solutions of the inputs within ±2 ulps (each component
of Π₀ moved by ±1, ±2 ulps, and the eight corners of ±2): max over them of |Π'ᵢ(t) − Πᵢ(t)|, per
component. The test compares the crate's error with that spread: conditioning, not the method,
should set it.

Lines:  family|generic I1 I2 I3 P1 P2 P3 n  then n times:  t R1 R2 R3 S1 S2 S3
(inputs printed with repr: the test reads exactly the doubles mpmath saw).

Regenerate (a few minutes; `-j` processes):
    python3 crates/mechanics/tests/data/separatrix_family_reference.py -j 2 > crates/mechanics/tests/data/separatrix_family_reference.txt
"""
import math
import random
import sys
from multiprocessing import Pool

import mpmath as mp

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import free_body_mp as fb  # noqa: E402

FAMILY = 1000
GENERIC = 300
TIMES_FAMILY = (1.0, 10.0, 1000.0)
TIMES_GENERIC = (1.0, 10.0)


def family(rng):
    # Moments over two decades: λ from ~0.1 to ~10, so that some states leave the middle axis
    # (after ~ln(1/k')/λ) before t = 1 or 10 and others only after 1000.
    i1, i2, i3 = sorted(10 ** rng.uniform(-1.0, 1.0) for _ in range(3))
    p1 = rng.uniform(-2.0, 2.0)
    p3 = math.copysign(p1 * math.sqrt((i2 - i1) * i3 / (i1 * (i3 - i2))), rng.choice((-1.0, 1.0)))
    return (i1, i2, i3), (p1, 1.0, p3)


def generic(rng, k):
    I = [rng.uniform(0.5, 8.0) for _ in range(3)]
    v = [rng.gauss(0, 1) for _ in range(3)]
    n = math.sqrt(sum(x * x for x in v))
    size = 10 ** rng.uniform(-1, 1)
    p = [x / n * size for x in v]
    if k % 5 == 0:
        # A component near its zero at the start.
        p[rng.randrange(3)] *= 10 ** -rng.uniform(2, 6)
    return tuple(I), tuple(p)


def line(args):
    kind, I, p, times = args
    mp.mp.dps = 40
    orbit = fb.Orbit(I, p)
    neighbours = [fb.Orbit(I, q) for q in fb.perturbed(p)]
    out = [kind] + [repr(x) for x in I] + [repr(x) for x in p] + [str(len(times))]
    for t in times:
        ref = orbit.pi(t)
        spread = [0, 0, 0]
        for nb in neighbours:
            x = nb.pi(t)
            spread = [max(spread[i], abs(x[i] - ref[i])) for i in range(3)]
        out += [repr(t)] + [mp.nstr(x, 20) for x in ref] + [mp.nstr(x, 3) for x in spread]
    return " ".join(out)


def main():
    jobs = int(sys.argv[sys.argv.index("-j") + 1]) if "-j" in sys.argv else 1
    rng = random.Random(29)
    cases = [("family",) + family(rng) + (TIMES_FAMILY,) for _ in range(FAMILY)]
    cases += [("generic",) + generic(rng, k) + (TIMES_GENERIC,) for k in range(GENERIC)]
    with Pool(jobs) as pool:
        for text in pool.imap(line, cases, chunksize=4):
            print(text, flush=True)


if __name__ == "__main__":
    main()
