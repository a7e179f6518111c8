# ruff: noqa: E702
"""Compare every record of logs/*.json with the truth table TRUTH (claim -> function (n, r) -> True/False/None)."""
import glob
import json
import sys
PASS = {"proved", "checked", "numeric"}
def F(n, r): return False
def T(n, r): return True
def false_n2(n, r): return n == 1          # tr PᵀP = 0 only at n = 1 (P = 0 at (1,1))
def false_rlt(n, r): return r == n
TRUTH = {
 "c1-idcol": lambda n, r: n == 1, "c1-top": false_rlt, "c1-eig-a": lambda n, r: n == 1, "c1-eig-a-true": T,
 "c1-diag-a-true": T, "c1-fresh-entry": lambda n, r: n == 1, "c1-gp-entry": lambda n, r: n == 1,
 "c1-zero-block-read": false_rlt, "c1-resolvent-entry": lambda n, r: n == 1,
 "c2-pow-underflow": false_n2, "c2-pow-overflow-true": T, "c2-pow-neg": false_n2, "c2-big-cancel": false_n2,
 "c2-frac-from-float": T, "c2-tiny-sum": false_n2, "c2-frac-int": T, "c2-frac-int-false": false_n2,
 "c7e-false": false_rlt, "c7e-true": T,
 "c8-true": T, "c8-false": false_rlt, "c8-true2": T, "c8-false2": lambda n, r: r == 1,
 "c2-frac-zero": T, "c2-frac-third": T, "c2-frac-int-matrix": T, "c2-frac-int-sum": T,
 "c1r-xax01": F, "c1r-ptp01": lambda n, r: n == 2, "c1r-xtp-diag": T, "c1r-psi12": T, "c1r-psi12-false": F,
 "c1r-a01": T, "c1r-a00": T, "c1r-ainv00": T, "c1r-a00-false": F, "c1r-phi-entry": F,
 "c3-sysexit": false_rlt, "c3-exit-first": false_rlt, "c3-kbint": false_rlt, "c3-baseexc-caught": false_rlt,
 "c4-thread": false_rlt, "c4-dict-subclass": false_rlt, "c4-gc-callback": false_rlt, "c6-copyreg": false_rlt,
 "c7-engine-filename": false_rlt, "c7-reload": false_rlt, "c7-patch-restore-dims": F, "c4-random-seeded": T,
 "c4-env": F, "c7p-own": T, "c7g-false": false_rlt, "c7g-true": T, "c7g-nonzero": T,
 "nz-underflow-true": T, "nz-overflow-true": T, "nz-tiny-true": T, "nz-absorb-false": F, "nz-constraint-false": F,
 "nz-constraint2-false": F, "nz-big-const-false": F,
 "rk-generic": F, "rk-A": F, "rk-lam": F, "rk-fresh": F, "rk-generic-gen": T, "rk-X": T,
 "d-outer-true": T, "d-outer-false": lambda n, r: n == 1,
 "fm-resolvent-int": T, "fm-resolvent-half": T, "fm-scalar-matrix": T, "fm-mat": T, "fm-div": T, "fm-rsub": T,
 "fm-lam": T, "fm-neg-int": T,
 "r1-ppt-false": F, "r1-ppt-true": T, "r1-phi-false": F, "r1-swap-false": F, "r1-scalar-true": T, "r1-scalar-false": F,
 "r2-comm-false": lambda n, r: n == 2,
 "sb-square": lambda n, r: r < n, "sb-lt": lambda n, r: r == n, "sb-r2": lambda n, r: r == 1,
 "sb-n3": lambda n, r: not (n == 3 and r < 3), "sb-ne": lambda n, r: r == n, "r2-psi-sq-true": T, "r2-ch-true": T, "r2-ch-false": F, "r2-sym-false": F,
}
wrong, total, unknown = [], 0, set()
for f in sorted(x for x in glob.glob(sys.argv[1] if len(sys.argv) > 1 else "logs/*.json") if "/c7p_" not in x):
    try:
        d = json.load(open(f))
    except Exception:
        continue
    if not isinstance(d, dict) or "results" not in d:
        continue
    for r in d["results"]:
        total += 1
        c, n, rr, v = r["claim"], r["n"], r["r"], r["verdict"]
        t = TRUTH.get(c)
        if t is None:
            unknown.add(c); continue
        if n is None:      # free: for every size stated
            truth = None if c.startswith("c7e-false") or c in ("c8-false", "c1-top", "c1-zero-block-read") else all(t(a, b) for a, b in [(2, 1), (3, 1), (3, 2), (3, 3), (4, 2)])
            if c in ("c7e-false", "c8-false", "c1-top", "c1-zero-block-read", "c8-false2", "c1r-ptp01") or c.startswith("sb-") or c in ("r1-ppt-false", "r1-phi-false", "r1-swap-false", "r1-scalar-false", "r2-comm-false", "r2-ch-false", "r2-sym-false", "c7g-false", "d-outer-false", "nz-absorb-false", "nz-constraint-false", "nz-constraint2-false", "nz-big-const-false", "rk-generic", "rk-A", "rk-lam", "rk-fresh") or c.startswith(("c3-", "c4-thread", "c4-dict", "c4-gc", "c6-", "c7-", "c4-env")):
                truth = False
        else:
            truth = t(n, rr)
        bad = (truth is False and v in PASS) or (truth is True and v == "fails")
        if bad:
            wrong.append((f.split('/')[-1], c, n, rr, r["method"], v, truth))
print(f"{total} records; wrong verdicts: {len(wrong)}; claims without a truth entry: {sorted(unknown)}")
for w in wrong:
    print("  WRONG", *w)
