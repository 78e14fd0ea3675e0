"""Reference values of the elliptic functions for tests/exact_flow.rs, from mpmath at 40 digits.

Lines:  sn-cn-dn u kc2 sn cn dn   |   rf x y z value   |   rj x y z p value   |
        pi n phi kc2 value (Legendre's third kind, k² = 1 − kc2)   |   k kc2 value
Inputs are doubles (printed with repr), so the test feeds exactly what mpmath saw.

Regenerate:  python3 crates/integrators/tests/data/elliptic_reference.py > crates/integrators/tests/data/elliptic_reference.txt
"""
import mpmath as mp

mp.mp.dps = 40
f = lambda x: mp.nstr(x, 25)

for kc2 in [1.0, 0.9, 0.5, 0.1, 1e-3, 1e-8, 1e-12, 1e-16]:
    m = 1 - mp.mpf(kc2)
    K = mp.ellipk(m)
    for frac in [-1.0, -0.7, -0.2, 1e-9, 0.05, 0.3, 0.5, 0.77, 0.99, 1.0]:
        u = float(frac * K)
        sn, cn, dn = (mp.ellipfun(w, mp.mpf(u), m=m) for w in ("sn", "cn", "dn"))
        print("sn-cn-dn", repr(u), repr(kc2), f(sn), f(cn), f(dn))
    print("k", repr(kc2), f(K))
    for n in [-3.0, -0.5, 0.3]:
        print("pi-complete", repr(n), repr(kc2), f(mp.ellippi(n, m)))
        for phi in [-1.2, 0.1, 0.9, 1.5707963267948966]:
            print("pi", repr(n), repr(phi), repr(kc2), f(mp.ellippi(n, mp.mpf(phi), m)))
for x, y, z in [(1.0, 2.0, 0.0), (0.5, 1e-12, 3.0), (2.0, 2.0, 2.0), (1e-3, 7.0, 0.25)]:
    print("rf", repr(x), repr(y), repr(z), f(mp.elliprf(x, y, z)))
    for p in [0.1, 1.0, 5.0]:
        print("rj", repr(x), repr(y), repr(z), repr(p), f(mp.elliprj(x, y, z, p)))
