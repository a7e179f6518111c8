"""Stop 60: public data of the engine's modules written by a claims file loaded in-process (tests/adversary/s60:
the stop's own attacks; s60/review: the review's).  See tests/adversary/README.md."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent / "s60"
REVIEW = HERE / "review"
ROOT = HERE.parents[2]
METHODS = ("free", "exact", "rational", "modular", "float", "auto")

#: loads a claims file in-process, runs one claim of it under every method, prints the verdicts as JSON (a fresh
#: interpreter per case: a write into the engine stays for the process's life)
_RUN = """
import json, sys
from stiefelsym.claims import CatalogError, Size, load_claims_file
from stiefelsym.run.runner import run_one
try:
    reg = load_claims_file(sys.argv[1])
except CatalogError as exc:
    print(json.dumps({"load": str(exc)}))
    raise SystemExit(0)
out = {}
for cid in sys.argv[2:]:
    for m in %r:
        res = run_one(reg.get(cid), None if m == "free" else Size(3, 2), m, 0)
        out[f"{cid} {m}"] = [res.verdict, res.message or ""]
print(json.dumps(out))
""" % (METHODS,)


def _in_process(path: Path, *ids: str) -> dict:
    out = subprocess.run([sys.executable, "-c", _RUN, str(path), *ids], capture_output=True, text=True,
                         cwd=str(ROOT), timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("name", ["seal_public_data", "seal_public_containers"])
def test_a_file_that_writes_public_engine_data_at_import_is_refused_in_process(name):
    """At import, the review's files wrote an entry of a public dict of the engine: the free algebra's value of
    tr I_n (then tr I_n = tr I_r was proved for all n, r) or the method table (then X = 0 was checked by the
    "modular" method).  The seal now reads every public attribute of the engine's modules with its contents, and
    the file's loading fails."""
    got = _in_process(REVIEW / f"{name}.py")
    assert "the engine was changed by claim code" in got.get("load", ""), got


@pytest.mark.parametrize("cid", ["s60-pub-dimensions", "s60-pub-runners", "s60-pub-class-flag",
                                 "s60-pub-frozenset", "s60-pub-object", "s60-pub-module-flag"])
def test_claim_code_that_writes_public_engine_data_while_traced_gets_error(cid):
    """The class of the review's files, with the write made by the claim's code while it is traced: an entry of
    a public dict, a class's public flag, a public frozenset rebound, an engine object's attribute, a module's
    flag.  Before the change each write went unseen (the false claim got its verdict from the changed
    engine); now every method gives `error`."""
    got = _in_process(HERE / "public_writes.py", cid)
    for key, (verdict, message) in got.items():
        assert verdict == "error" and "the engine was changed by claim code" in message, (key, verdict, message)


@pytest.mark.parametrize("name", ["package_api", "swap_module", "swap_module_code", "profile_hook_results",
                                  "profile_toggle"])
def test_a_file_that_changes_what_the_engine_reads_without_writing_its_modules_is_refused_in_process(name):
    """The second review's files, each a wrong verdict in-process before: `stiefelsym.claim` replaced in the package
    (then a false catalog claim loaded after the file was proved), a stand-in for an engine module in sys.modules
    (the seal read the stand-in, the engine its own module), a profile hook that rewrote the residuals while a
    method evaluated them, or toggled the free algebra's dimensions around the seal's own checks.  The package is
    sealed, the modules are read as they were when sealed, and the interpreter's hooks are in the fingerprint:
    each file's loading fails."""
    got = _in_process(HERE / "review2" / f"{name}.py")
    assert "the engine was changed by claim code" in got.get("load", ""), got


@pytest.mark.parametrize("cid", ["s60-int-package-export", "s60-int-stand-in-module", "s60-int-builtin",
                                 "s60-int-numpy-function", "s60-int-profile-hook", "s60-int-gc-callback"])
def test_claim_code_that_changes_what_the_engine_reads_while_traced_gets_error(cid):
    """The class of the second review's files, the change made by the claim's code while it is traced: a package
    export, a stand-in module, a builtin, a numpy function, a profile hook, a garbage-collector callback."""
    got = _in_process(HERE / "interpreter_writes.py", cid)
    for key, (verdict, message) in got.items():
        assert verdict == "error" and "the engine was changed by claim code" in message, (key, verdict, message)


def test_an_honest_file_is_not_taken_for_a_change_of_the_engine():
    """False alarms the second review found: numpy.random imported on the engine's first use of it after sealing
    (a block of 64 parameters or more, at (12, 1)), and a file that imports a numpy submodule itself."""
    got = _in_process(HERE / "review2" / "honest_numpy_random.py", "s60r2-honest-npr")
    assert all(v[0] in ("proved", "checked", "numeric") for v in got.values()), got
    out = subprocess.run([sys.executable, str(HERE / "review2" / "run_honest_large.py")], capture_output=True,
                         text=True, cwd=str(ROOT), timeout=300)
    assert out.returncode == 0 and "error" not in out.stdout and "numeric" in out.stdout, out.stdout + out.stderr


def test_a_profiler_started_after_loading_is_named_in_the_refusal():
    """A trace or profile function installed after a claims file was loaded in-process (by the file, a debugger or
    a profiler) makes the next run `error`, and the message says which kind of change it was and what to do."""
    script = (
        "import sys\n"
        "from stiefelsym.claims import load_claims_file\n"
        "from stiefelsym.run.runner import run_one\n"
        "c = list(load_claims_file(sys.argv[1]))[0]\n"
        "size = list(c.sizes)[0]\n"
        "print(run_one(c, size, 'modular', 0).verdict)\n"
        "sys.setprofile(lambda *a: None)\n"
        "res = run_one(c, size, 'modular', 0)\n"
        "sys.setprofile(None)\n"
        "print(res.verdict, res.message)\n")
    out = subprocess.run([sys.executable, "-c", script, str(ROOT / "examples" / "my_claims.py")], capture_output=True,
                         text=True, cwd=str(ROOT), timeout=300)
    first, second = out.stdout.strip().splitlines()[-2:]
    assert first == "checked" and second.startswith("error ") and "profile" in second and \
        "start it before loading the file" in second, out.stdout + out.stderr


def test_underscore_names_spell_no_other_letter():
    """Own attempt on the free scene's underscore names (stop 60): false claims that would pass if a name with an
    underscore met another letter (eta_n and etan, S_1 and the skew S, G_T and Gᵀ, eta_n sym and skew) are
    undecided under the free method and fail under the fixed-size ones."""
    from stiefelsym.claims import Size, load_claims_file
    from stiefelsym.run.runner import run_one
    reg = load_claims_file(str(HERE / "underscore_names.py"))
    for c in reg:
        if c.id == "fool-underscore-kinds":
            # eta_n sym and eta_n skew: two parameters of one name, refused when traced since stop 88 (h1 I1)
            for m, size in (("free", None), ("exact", Size(3, 2)), ("modular", Size(3, 2)), ("float", Size(3, 2))):
                res = run_one(c, size, m, 0)
                assert res.verdict == "error" and "needs a name of its own" in res.message, (c.id, m, res.message)
            continue
        assert run_one(c, None, "free", 0).verdict == "undecided", c.id
        for m in ("exact", "modular", "float"):
            assert run_one(c, Size(3, 2), m, 0).verdict == "fails", (c.id, m)
