"""Reference values of the elliptic functions for tests/models/exact_flow.rs, from mpmath at 40 digits.

Lines:  sn-cn-dn u kc2 sn cn dn   |   rf x y z value   |   rj x y z p value   |
        pi n phi kc2 value (Legendre's third kind, k² = 1 − kc2)   |   k kc2 value   |
        jacobi ln_kc n w sn cn dn (at u = nK + w, K the exact quarter period, k' = e^ln_kc)   |
        third-kind ln_kc beta n w value (Π(−β; am u, k) = ∫₀ᵘ dv/(1 + β sn²v) at u = nK + w)
Inputs are doubles (printed with repr), so the test feeds exactly what mpmath saw. The jacobi
lines sit near the zeros of cn and dn (n odd, w small) and at k' down to e⁻⁴⁰⁰, where k'²
underflows: the test asks for relative accuracy there.

Regenerate:  python3 crates/mechanics/tests/data/elliptic_reference.py > crates/mechanics/tests/data/elliptic_reference.txt
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

# The quarter-period phases: u = nK + w with K exact, so that the reference is the function of the
# phase the crate is given, near every zero; the working precision grows with the digits k'² takes.
for ln_kc in [-0.3, -4.6, -9.2, -18.4, -34.5, -41.4, -46.0, -115.0, -400.0]:
    kc = mp.exp(mp.mpf(ln_kc))
    with mp.workdps(int(40 + 2 * abs(ln_kc) / 2.3)):
        m = 1 - kc**2
        K = mp.ellipk(m)
        for n in [0, 1, 2, 3, -1, 5, 1000001]:
            for frac in [0.4995, 0.25, -0.25, 1e-3, -1e-9, 1e-17, 0.0]:
                w = float(frac * K)
                u = n * K + mp.mpf(w)
                sn, cn, dn = (mp.ellipfun(x, u, m=m) for x in ("sn", "cn", "dn"))
                if w == 0:
                    # The zeros exactly (mpmath's theta quotients leave 10⁻⁴² of noise there).
                    if n % 2 == 0:
                        sn = mp.mpf(0)
                    else:
                        cn = mp.mpf(0)
                print("jacobi", repr(ln_kc), n, repr(w), f(sn), f(cn), f(dn))
        for beta in [0.5, 3.0]:
            for n in [0, 1, 2, 3, -1]:
                for frac in [0.4995, 0.25, -0.25, 1e-3, 0.0]:
                    w = float(frac * K)
                    u = n * K + mp.mpf(w)
                    # Π(−β; φ, k) at the continuous amplitude φ = am u = jπ + atan2(±sn, ±cn)
                    # (mpmath's integral is quasi-periodic in φ).
                    j = mp.nint(u / (2 * K))
                    sn, cn = (mp.ellipfun(x, u, m=m) * (-1) ** int(j) for x in ("sn", "cn"))
                    phi = j * mp.pi + mp.atan2(sn, cn)
                    value = mp.ellippi(-beta, phi, m) if u != 0 else mp.mpf(0)
                    print("third-kind", repr(ln_kc), repr(beta), n, repr(w), f(value))
