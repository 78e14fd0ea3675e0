"""Cheapest run per target in a `lie-sim trade` table: the plain baselines (rk4, rkmk4) against
the structure-preserving methods, and their cost ratio.

    python3 docs/trade_summary.py docs/trade-free-rigid-body.csv error 1e-4 1e-6 1e-8 1e-10
    python3 docs/trade_summary.py docs/trade-free-rigid-body-energy.csv max_energy_error 1e-3 1e-5 1e-7 1e-9
    EXCLUDE=exact python3 docs/trade_summary.py …   # the geometric methods other than the exact flow

Cost is the stepping time of the whole run (`seconds`). A target no run of the ladder reaches is
reported as such. For the error at T, as `lie-sim trade` and `choose` do, a run meets a target
when its error bound is within it: its error plus the reference's estimated error
`reference_error`, or twice `reference_error` when the error is below it (`error_status` =
unresolved: the run is at least as accurate as the reference can tell) (tables written before
these columns existed are read as they are).
"""
import csv
import os
import sys


def label(r):
    parts = [r["method"]]
    if r["composition"] != "-":
        parts.append(r["composition"])
    if r["tau"] != "-":
        parts.append("τ = " + r["tau"])
    if r["theta"] != "-":
        parts.append("θ = " + r["theta"])
    return " ".join(parts) + f", h = {float(r['h']):g}"


def main():
    path, metric, *targets = sys.argv[1:]
    excluded = set(filter(None, os.environ.get("EXCLUDE", "").split(",")))
    rows = [
        r
        for r in csv.DictReader(open(path))
        if not r["failure"] and r["method"] not in excluded
    ]
    baseline = lambda r: r["method"] in ("rk4", "rkmk4")
    print(f"| {metric} ≤ | cheapest baseline | cheapest geometric | geometric / baseline |")
    print("|---|---|---|---|")
    def meets(r, t):
        if metric == "error" and "error_status" in r:
            floor = float(r["reference_error"])
            if r["error_status"] == "unresolved":
                return 2 * floor <= t
            return r["error_status"] == "measured" and float(r["error"]) + floor <= t
        return r[metric] != "" and float(r[metric]) <= t

    for t in map(float, targets):
        ok = [r for r in rows if meets(r, t)]
        best = lambda xs: min(xs, key=lambda r: float(r["seconds"]), default=None)
        b, g = best([r for r in ok if baseline(r)]), best([r for r in ok if not baseline(r)])
        show = lambda r: f"{label(r)}: {float(r['seconds']) * 1e6:.1f} µs" if r else "none in the ladder"
        ratio = f"{float(g['seconds']) / float(b['seconds']):.3g}" if b and g else "—"
        print(f"| {t:.0e} | {show(b)} | {show(g)} | {ratio} |")


main()
