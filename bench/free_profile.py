"""Where the time of a dimension-free proof goes (issue 7, target "free LA1 <= 0.5 ms warm").

Measures, in this process, what ``make bench`` measures -- ``run_one(LA1, None, "free")``, best
of warm runs, the independent certificate check included -- and splits it into its phases: the
claim on the free scene, the reductions, the division probe (at a fixed size, over GF(p)), the
certificate and its check.  ``--catalog`` adds every catalog claim under the free method (best of
``--repeat`` runs each), ``--profile`` a cProfile of the warm runs.

    python bench/free_profile.py                     # LA1: total and phases
    python bench/free_profile.py --profile           # ... and the functions that take the time
    python bench/free_profile.py --catalog           # ... and the catalog under --method free
    python bench/free_profile.py --root /other/tree  # the same, for another checkout (side by side)
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path


def best_of(f, repeat: int) -> float:
    """The best wall time of ``repeat`` calls, in milliseconds."""
    best = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    return 1e3 * best


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=str(Path(__file__).resolve().parents[1]), help="the checkout to measure")
    ap.add_argument("--repeat", type=int, default=200, help="warm runs of LA1 (best is reported)")
    ap.add_argument("--profile", action="store_true", help="cProfile the warm runs")
    ap.add_argument("--catalog", action="store_true", help="every catalog claim under the free method")
    ap.add_argument("--json", action="store_true", help="one JSON document on stdout")
    args = ap.parse_args(argv)
    root = Path(args.root).resolve()
    sys.path[:0] = [str(root), str(root / "bench")]

    import stiefelsym
    from bench import LA1  # the claim make bench measures
    from stiefelsym.certificate_check import check_certificate
    from stiefelsym.free import FreeScene
    from stiefelsym.methods.dimension_free import certify_entries
    from stiefelsym.methods.fixed_size import _entries, call_claim, division_probe
    from stiefelsym.run.runner import run_one

    assert Path(stiefelsym.__file__).resolve().is_relative_to(root), stiefelsym.__file__
    res = run_one(LA1, None, "free", seed=0)
    if res.verdict != "proved":
        print(f"free LA1: {res.verdict} {res.message}", file=sys.stderr)
        return 1
    # what make bench measures: the best of the first 5 warm runs after the cold one (these are
    # slower than later ones while the interpreter specializes code run once per proof)
    first = best_of(lambda: run_one(LA1, None, "free", seed=0), 5)
    out: dict = {"root": str(root),
                 "LA1 warm, best of the first 5 (as make bench)": first,
                 "LA1 warm (run_one, best)": best_of(lambda: run_one(LA1, None, "free", seed=0), args.repeat)}

    def claim_on_free_scene():
        scene = FreeScene(realization=LA1.realization, lazy=True)
        return scene, call_claim(LA1.func, scene)

    out["  claim on the free scene"] = best_of(claim_on_free_scene, args.repeat)

    def reductions():
        scene, checks = claim_on_free_scene()
        entries = _entries(checks["LA1"], "LA1")
        t0 = time.perf_counter()
        reds = [(pos, scene.reduce(x), None) for pos, x in entries]
        return time.perf_counter() - t0, scene, reds

    out["  reductions (memos shared by standard systems)"] = 1e3 * min(reductions()[0] for _ in range(args.repeat))
    _, scene, reds = reductions()
    out["  derivations (LaTeX)"] = best_of(lambda: [r.latex() for _, r, _ in reds], args.repeat)
    probe = next((z for z in LA1.sizes if z.n >= 3), None) or list(LA1.sizes)[-1]
    out[f"  division probe at ({probe.n},{probe.r}) over GF(p), once per claim"] = best_of(
        lambda: division_probe(LA1, probe.n, probe.r), args.repeat)

    def certify():
        _, scene, reds = reductions()
        t0 = time.perf_counter()
        certify_entries(scene, reds)
        return time.perf_counter() - t0

    out["  certificate (memos shared by standard systems)"] = 1e3 * min(certify() for _ in range(args.repeat))
    data = certify_entries(scene, reds)
    out["  independent check"] = best_of(lambda: check_certificate(data), args.repeat)

    if args.catalog:
        from stiefelsym.claims import load_catalog
        cat = load_catalog()
        rows = {}
        for c in cat:
            r = run_one(c, None, "free", seed=0)
            t = best_of(lambda: run_one(c, None, "free", seed=0), 3)
            rows[c.id] = (r.verdict, t)
        out["catalog under free: total of best runs (ms)"] = sum(t for _, t in rows.values())
        out["catalog under free: proved"] = sum(v == "proved" for v, _ in rows.values())
        out["catalog under free: slowest (ms)"] = dict(sorted(((k, round(t, 3)) for k, (_, t) in rows.items()),
                                                          key=lambda kv: -kv[1])[:8])
    if args.profile:
        import cProfile
        import pstats
        pr = cProfile.Profile()
        pr.enable()
        for _ in range(args.repeat):
            run_one(LA1, None, "free", seed=0)
        pr.disable()
        pstats.Stats(pr, stream=sys.stderr).sort_stats("tottime").print_stats(30)
    if args.json:
        print(json.dumps(out, indent=1))
    else:
        for k, v in out.items():
            print(f"{k:50s} {v:.3f} ms" if isinstance(v, float) else f"{k:50s} {v}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
