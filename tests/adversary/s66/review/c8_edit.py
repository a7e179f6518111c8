# ruff: noqa
"""Class 8 (report ingestion): hand-edited copies of a results.json, each given to `stiefelsym check` and
`stiefelsym report`.  Usage: c8_edit.py BASE_DIR OUT_ROOT [variant ...]"""
import copy, json, math, os, subprocess, sys

SB = "/work/main/.venv/bin/stiefelsym"
base_dir, out_root = sys.argv[1], sys.argv[2]
only = sys.argv[3:]
base = json.load(open(os.path.join(base_dir, "results.json")))


def rec(d, claim, method):
    for r in d["results"]:
        if r["claim"] == claim and r["method"] == method:
            return r
    raise KeyError((claim, method))


def forge_checked(r):
    r.update(verdict="checked", expected=True, witness=None, residual=None, message="")
    for c in r["checks"]:
        c["status"] = "zero"


V = {}


def v(f):
    V[f.__name__] = f
    return f


@v
def method_unknown(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["method"] = "hand"


@v
def method_case(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["method"] = "Modular"


@v
def seed_bool(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["seed"] = True


@v
def seed_none(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["seed"] = None


@v
def n_float(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["n"] = 3.0


@v
def n_bool(d):
    r = rec(d, "c8-false", "modular"); r["n"] = True; r["r"] = True


@v
def nan_bound(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["false_pass_bound"] = float("nan")


@v
def free_proved_copied_cert(d):
    t = rec(d, "c8-true", "free"); f = rec(d, "c8-false", "free")
    f.update(verdict="proved", expected=True, certificate=t["certificate"],
             certificate_data=copy.deepcopy(t["certificate_data"]), message="")


@v
def free_proved_no_cert(d):
    f = rec(d, "c8-false", "free")
    f.update(verdict="proved", expected=True, certificate="beyond the symbolic budget", certificate_data=None, message="")


@v
def free_proved_cert_edited(d):
    """the true claim's certificate with its residual replaced by X^T P's words"""
    t = rec(d, "c8-true", "free"); f = rec(d, "c8-false", "free")
    cd = copy.deepcopy(t["certificate_data"])
    for e in cd["entries"]:
        e["residual"] = [{"coef": "1", "traces": [], "word": ["Xt", "P"]}]
    f.update(verdict="proved", expected=True, certificate=t["certificate"], certificate_data=cd, message="")


@v
def claim_swapped(d):
    """the two claims' modular records swapped by id (each record keeps its digest)"""
    t = rec(d, "c8-true", "modular"); f = rec(d, "c8-false", "modular")
    t["claim"], f["claim"] = "c8-false", "c8-true"
    t["title"], f["title"] = f["title"], t["title"]
    t["rerun"], f["rerun"] = f["rerun"], t["rerun"]


@v
def duplicate_record(d):
    """an extra, forged, checked record of the false claim beside the real one"""
    f = rec(d, "c8-false", "modular"); g = copy.deepcopy(f); forge_checked(g); g["seed"] = 1
    d["results"].append(g)


@v
def drop_false_and_command(d):
    d["results"] = [r for r in d["results"] if r["claim"] != "c8-false"]
    d["meta"]["command"] = d["meta"]["command"].replace("verify --claims", "verify c8-true --claims")


@v
def meta_methods_only_free(d):
    """the modular records removed and the command says free only"""
    d["results"] = [r for r in d["results"] if r["method"] != "modular"]
    d["meta"]["command"] = d["meta"]["command"].replace("--method modular ", "")
    d["meta"]["methods"] = ["free"]


@v
def expected_flipped(d):
    """the false claim's failure declared expected, an erratum text added"""
    f = rec(d, "c8-false", "modular"); f["expected"] = False; f["erratum"] = "a misprint of the paper: XᵀP is skew"


@v
def unicode_verdict(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["verdict"] = "chеcked"   # Cyrillic e


@v
def extra_key(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["verdict"] = "checked"; r["__proto__"] = 1


@v
def results_dict(d):
    """results as a dict keyed by index"""
    d["results"] = {str(i): r for i, r in enumerate(d["results"])}


@v
def checks_empty(d):
    r = rec(d, "c8-false", "modular"); forge_checked(r); r["checks"] = []


for name, f in V.items():
    if only and name not in only:
        continue
    d = copy.deepcopy(base)
    f(d)
    out = os.path.join(out_root, name)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "results.json"), "w") as fh:
        json.dump(d, fh, indent=1, ensure_ascii=False)
    c = subprocess.run([SB, "check", os.path.join(out, "results.json")], capture_output=True, text=True, cwd="/work/main")
    rp = subprocess.run([SB, "report", "--results", os.path.join(out, "results.json")], capture_output=True, text=True, cwd="/work/main")
    tail = lambda s: " | ".join(s.strip().splitlines()[-2:])[:300]
    tb = "TRACEBACK" if "Traceback" in c.stderr + rp.stderr else ""
    print(f"{name}: check rc={c.returncode} [{tail(c.stdout + c.stderr)}] ; report rc={rp.returncode} [{tail(rp.stdout + rp.stderr)}] {tb}", flush=True)


# second batch (run with names): the failure presented as a documented erratum
def expected_true_erratum(d):
    f = rec(d, "c8-false", "modular"); f["expected"] = True; f["erratum"] = "XᵀP is skew, not 0 (a misprint)"
    g = rec(d, "c8-false", "free"); g["expected"] = True; g["erratum"] = "XᵀP is skew, not 0 (a misprint)"


def erratum_on_true(d):
    t = rec(d, "c8-true", "modular"); t["erratum"] = "the paper's XᵀX = I is wrong at r = 2"
    t2 = rec(d, "c8-true", "free"); t2["erratum"] = "the paper's XᵀX = I is wrong at r = 2"


def variant_forged(d):
    """a correction record ("variant") attached to the false claim, verdict checked"""
    f = rec(d, "c8-false", "modular"); g = copy.deepcopy(rec(d, "c8-true", "modular"))
    g["claim"] = "c8-false"; g["variant"] = "XᵀP → XᵀP − PᵀX... corrected"; g["rerun"] = f["rerun"]; g["title"] = f["title"]
    d["results"].append(g)


for name in only:
    if name in V:
        continue
    f = globals()[name]
    d = copy.deepcopy(base)
    f(d)
    out = os.path.join(out_root, name)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "results.json"), "w") as fh:
        json.dump(d, fh, indent=1, ensure_ascii=False)
    c = subprocess.run([SB, "check", "--no-rerun", os.path.join(out, "results.json")], capture_output=True, text=True, cwd="/work/main")
    rp = subprocess.run([SB, "report", "--results", os.path.join(out, "results.json")], capture_output=True, text=True, cwd="/work/main")
    tail = lambda s: " | ".join(s.strip().splitlines()[-2:])[:400]
    print(f"{name}: check --no-rerun rc={c.returncode} [{tail(c.stdout + c.stderr)}] ; report rc={rp.returncode} [{tail(rp.stdout + rp.stderr)}]", flush=True)
