# ruff: noqa: F841, E702, F401, E731, E741
"""Review2 s63: results files edited by hand, given to `stiefelsym check` and `stiefelsym report`.
Usage: .venv/bin/python tests/adversary/s63/review2/results_edits.py BASE.json OUTDIR
(BASE.json: `stiefelsym verify --claims tests/adversary/s63/review2/recs.py --method modular --method exact
--jobs 1 --timeout 120 --format json --no-report`)."""
import copy
import json
import math
import subprocess
import sys
import time
from pathlib import Path

base = json.loads(Path(sys.argv[1]).read_text())
ONLY = sys.argv[3:]
out = Path(sys.argv[2])
out.mkdir(parents=True, exist_ok=True)
EXE = str(Path(sys.executable).parent / "stiefelsym")


def find(claim, method):
    for i, r in enumerate(base["results"]):
        if r["claim"] == claim and r["method"] == method:
            return i
    raise KeyError(claim)


def edit(name, f, raw=None):
    if ONLY and name not in ONLY:
        return
    d = copy.deepcopy(base)
    f(d)
    p = out / f"{name}.json"
    text = raw(json.dumps(d)) if raw else json.dumps(d)
    p.write_text(text)
    for cmd in (["check", str(p)], ["report", "--results", str(p), "--report-dir", str(out / f"rep-{name}")]):
        t = time.time()
        try:
            cp = subprocess.run([EXE, *cmd], capture_output=True, text=True, timeout=150)
            rc, tail = cp.returncode, (cp.stdout + cp.stderr).strip().splitlines()[-2:]
        except subprocess.TimeoutExpired:
            rc, tail = "TIMEOUT", []
        print(f"{name:28} {cmd[0]:6} rc={rc} {time.time() - t:5.1f}s | " + " / ".join(x[:230] for x in tail), flush=True)


im, ie = find("rc-true", "modular"), find("rc-true", "exact")
fm = find("rc-false", "modular")


def setf(i, k, v):
    return lambda d: d["results"][i].__setitem__(k, v)


edit("bound-tiny", setf(im, "false_pass_bound", 1e-300))
edit("bound-zero", setf(im, "false_pass_bound", 0.0))
edit("bound-neg", setf(im, "false_pass_bound", -1.0))
edit("bound-nan", setf(im, "false_pass_bound", float("nan")))
edit("bound-inf", setf(im, "false_pass_bound", float("inf")))
edit("bound-hugeint", setf(im, "false_pass_bound", 10 ** 4000))
edit("seconds-inf", setf(im, "seconds", float("inf")))
edit("degree-low", lambda d: [c.__setitem__("degree", 1) for c in d["results"][im]["checks"]])
edit("degree-huge", lambda d: [c.__setitem__("degree", 10 ** 4000) for c in d["results"][im]["checks"]])
edit("degree-neg", lambda d: [c.__setitem__("degree", -5) for c in d["results"][im]["checks"]])
edit("cert-points", setf(im, "certificate", base["results"][im]["certificate"].replace("2 independent", "24 independent")))
edit("dup-record", lambda d: d["results"].insert(im + 1, copy.deepcopy(d["results"][im])))
edit("dup-conflict", lambda d: d["results"].insert(im + 1, dict(copy.deepcopy(d["results"][fm]), claim="rc-true",
                                                                 title=d["results"][im]["title"])))
edit("seed-huge", lambda d: [setf(im, "seed", 10 ** 4000)(d), d["meta"].__setitem__("seed", 10 ** 4000)])
edit("seed-bool", lambda d: [setf(im, "seed", True)(d)])
edit("n-bool", lambda d: [setf(im, "n", True)(d), setf(im, "r", True)(d)])
edit("n-huge", lambda d: [setf(im, "n", 10 ** 4000), setf(im, "n", 10 ** 4000)(d), setf(im, "r", 2)(d)])
edit("n-float", lambda d: [setf(im, "n", 3.0)(d)])
edit("int-5000digits", setf(im, "seconds", 12345.5), raw=lambda t: t.replace("12345.5", "1" + "0" * 5000))
edit("timeout-huge", lambda d: d["meta"].__setitem__("timeout", 10 ** 300))
edit("timeout-bool", lambda d: d["meta"].__setitem__("timeout", True))
edit("sizes-huge", lambda d: d["meta"].__setitem__("sizes", [[10 ** 50, 2]]))
edit("other-file", lambda d: [d["meta"].__setitem__("claims_files", ["tests/adversary/s63/review2/other_recs.py"]),
                              d["meta"].__setitem__("claims_file", "tests/adversary/s63/review2/other_recs.py")])
edit("false-fails-as-checked", lambda d: d["results"][fm].update(verdict="checked", expected=True, residual=None,
                                                                  witness=None, false_pass_bound=1e-40))
