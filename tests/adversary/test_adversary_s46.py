"""Adversarial review of 5d3dc53: dimension-free proofs on the family r = k (``free_max_r``), specialised at a size.

Each test states the CORRECT behaviour: a false statement is never ``proved`` (at a size, or for every n), and a
record whose certificate does not prove it is refused.  A failing test marks a hole.

The truth of each statement is known independently: the modular method at the size (a nonzero residual at an
exact point is a refutation), or elementary linear algebra stated in the docstring.
"""
from __future__ import annotations

import copy
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from stiefelsym import admissible, elementary
from stiefelsym.claims import Claim, Size
from stiefelsym.run.runner import run_one

ROOT = Path(__file__).resolve().parents[2]
SPECIALISED = "the dimension-free proof, specialised"


def _claim(func, free_max_r=3, exact_max_n=2, sizes=None, **kw):
    return Claim(id=func.__name__.replace("_", "-"), paper=("prep",), kind="id", section="t", func=func,
                 sizes=sizes if sizes is not None else admissible(7), exact_max_n=exact_max_n,
                 free_max_r=free_max_r, **kw)


def _on_family(s):
    """Whether the claim is being traced on a family of sizes (introspection: the trace that owns the size)."""
    return getattr(object.__getattribute__(s.n, "_owner"), "_family", None) is not None


def _specialised(res):
    return any(x.startswith(SPECIALISED) for x in res.reductions or [])


def _cli(*args, cwd=ROOT):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "stiefelsym", *args], capture_output=True, text=True, env=env,
                          cwd=str(cwd), timeout=240)


@pytest.fixture(autouse=True)
def _fresh(fresh_specialise):
    _SAVED.clear()
    _CALLS.clear()


# --------------------------------------------------------------------------- claims


def e2_is_one(s):
    """e_2(XᵀX) = 1: true at r = 2 only (e_2(I_r) = r(r-1)/2).  It reads r as a number without using it, so its
    graph (no symbolic one: int(s.r) is refused there) is the SAME at every r: one digest at r = 1, 2, 3."""
    _ = int(s.r)
    return {"e2(X^T X) - 1": elementary(s, s.X.T @ s.X, 2)[2] - s.q(1)}


def cayley_hamilton_2(s):
    """Cayley-Hamilton of a 2 x 2 matrix applied to M = PᵀP (r x r): true at r <= 2, false at r = 3."""
    _ = int(s.r)
    M = s.P.T @ s.P
    e = elementary(s, M, 2)
    return {"CH2": M @ M - e[1] * M + e[2] * s.Ir}


def xtp_vanishes(s):
    """XᵀP = 0: true at r = 1 only (XᵀP is skew)."""
    _ = int(s.r)
    return {"X^T P": s.X.T @ s.P}


def family_detector(s):
    """On the family: XᵀX = I_r (true); at a size: XᵀX + PᵀP = I_r (false)."""
    _ = int(s.r)
    res = s.X.T @ s.X - s.Ir
    if not _on_family(s):
        res = res + s.P.T @ s.P
    return {"x": res}


_SAVED: list = []


def n_from_an_earlier_trace(s):
    """XᵀX = I_r, plus PᵀP unless n == 5 (so true at n = 5 only); on the family it reads n from the size
    object of an earlier trace at a size (not refused), so its family graph is the one of n = 5."""
    _ = int(s.r)
    if _on_family(s):
        n = int(_SAVED[-1]) if _SAVED else 5
    else:
        _SAVED.append(s.n)
        n = int(s.n)
    res = s.X.T @ s.X - s.Ir
    if n != 5:
        res = res + s.P.T @ s.P
    return {"x": res}


_CALLS: list = []


def stateful(s):
    """False for its first two traces that get past int(s.r) (the traces at the size), true afterwards (the
    traces on the family): the claim's graph at the size is XᵀX + PᵀP - I_r, false."""
    _ = int(s.r)
    _CALLS.append(1)
    res = s.X.T @ s.X - s.Ir
    if len(_CALLS) <= 2:
        res = res + s.P.T @ s.P
    return {"x": res}


def zero_over_zero(s):
    """d/d - 1 with d = tr(XᵀX) - 3 = r - 3: undefined at r = 3 (0/0), the free algebra's r - 3 over r - 3."""
    _ = int(s.r)
    d = s.tr(s.X.T @ s.X) - s.q(3)
    return {"x": s.tr(s.P.T @ s.P) * d / d - s.tr(s.P.T @ s.P)}


def gram_with_momenta(s):
    """det(XᵀX + PᵀP) = 1, as e_r: false at every r."""
    return {"det - 1": elementary(s, s.X.T @ s.X + s.P.T @ s.P, s.r)[s.r] - s.q(1)}


# --------------------------------------------------------------------------- the engine at a size


def test_a_graph_the_same_at_every_r_true_at_r2_only():
    """Attempt: the one digest at r = 1, 2, 3 (size values are left out of the digest), proved on the family
    r = 2.  Right: proved at (5, 2), (6, 2); fails at (5, 3) and (4, 1)."""
    c = _claim(e2_is_one)
    digests = set()
    for n, r in ((5, 2), (6, 2)):
        res = run_one(c, Size(n, r), "auto", 0)
        assert res.verdict == "proved" and _specialised(res), (n, r, res.verdict, res.message)
        digests.add(res.digest)
    for n, r in ((5, 3), (4, 1)):
        res = run_one(c, Size(n, r), "auto", 0)
        assert res.verdict == "fails", (n, r, res.verdict, res.message)
        digests.add(res.digest)
    assert len(digests) == 1        # the premise of the record forgery below


def test_cayley_hamilton_of_a_2x2_matrix_is_not_proved_at_r3():
    c = _claim(cayley_hamilton_2)
    for n, r in ((5, 1), (5, 2)):
        res = run_one(c, Size(n, r), "auto", 0)
        assert res.verdict in ("proved", "checked"), (n, r, res.verdict, res.message)
    res = run_one(c, Size(5, 3), "auto", 0)
    assert res.verdict == "fails", res.verdict


def test_xtp_vanishes_at_r1_only():
    c = _claim(xtp_vanishes)
    assert run_one(c, Size(5, 1), "auto", 0).verdict in ("proved", "checked")
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "fails", res.verdict


def test_a_claim_that_detects_the_family_gets_no_proof_of_its_false_graph():
    """Attempt: a true graph on the family, a false one at the size (introspection of the trace).  Right:
    fails (the digests differ)."""
    for n, r in ((5, 2), (5, 3)):
        res = run_one(_claim(family_detector), Size(n, r), "auto", 0)
        assert res.verdict == "fails", (n, r, res.verdict)


def test_n_read_from_an_earlier_trace_on_the_family():
    """Attempt: on the family, n read (unrefused) from the size object of an earlier trace.  Right: the
    statement is false at n = 6, 9 and never proved there; at n = 5 it is true."""
    c = _claim(n_from_an_earlier_trace)
    assert run_one(c, Size(5, 2), "auto", 0).verdict in ("proved", "checked")
    for n in (6, 9):
        res = run_one(c, Size(n, 2), "auto", 0)
        assert res.verdict == "fails", (n, res.verdict)


def test_a_claim_with_state_across_its_traces():
    res = run_one(_claim(stateful), Size(5, 2), "auto", 0)
    assert res.verdict != "proved", (res.verdict, res.reductions[:1])


def test_a_division_by_a_trace_that_vanishes_at_r3_is_not_proved_there():
    res = run_one(_claim(zero_over_zero), Size(5, 3), "auto", 0)
    assert res.verdict != "proved", (res.verdict, res.reductions[:1])


@pytest.mark.parametrize("value", [True, 10 ** 9, math.nan, math.inf])
def test_free_max_r_set_after_construction_proves_no_false_statement(value):
    """free_max_r is validated at construction only: set afterwards (the claim is a frozen dataclass, but
    object.__setattr__ writes it) to anything.  Right: a false statement is still never proved."""
    c = _claim(gram_with_momenta)
    object.__setattr__(c, "free_max_r", value)
    for n, r in ((4, 1), (5, 2), (5, 3)):
        res = run_one(c, Size(n, r), "auto", 0)
        assert res.verdict == "fails", (value, n, r, res.verdict)


def test_a_correction_true_at_r2_only():
    """The printed claim (false) and its correction (e_2(XᵀX) = 1, true at r = 2 only): the correction is proved
    at (5, 2) on the family, fails at (5, 3); the printed claim fails at both."""
    c = _claim(gram_with_momenta)
    c.correction("e_2 in place of det of the momenta")(e2_is_one)
    fixed, func = c.corrected(0), c.corrections[0].func
    res = run_one(fixed, Size(5, 2), "auto", 0, func, variant=c.corrections[0].description)
    assert res.verdict == "proved" and _specialised(res), res.verdict
    res = run_one(fixed, Size(5, 3), "auto", 0, func, variant=c.corrections[0].description)
    assert res.verdict == "fails", res.verdict
    for n, r in ((5, 2), (5, 3)):
        assert run_one(c, Size(n, r), "auto", 0).verdict == "fails"


# --------------------------------------------------------------------------- records


def _moved(rec: dict, r: int) -> dict:
    out = copy.deepcopy(rec)
    out["r"] = r
    out["rerun"] = str(out.get("rerun") or "").replace(f"--size {rec['n']},{rec['r']}", f"--size {rec['n']},{r}")
    return out


@pytest.mark.parametrize("to_r", [3, 1])
def test_a_certificate_of_the_family_r2_in_a_record_at_another_r_is_refused(to_r):
    """Closed (the scope of a carried certificate is read against its record's size).  The record at (5, 2) carries the certificate of the family r = 2 (it uses E1E1ᵀ + E2E2ᵀ = I_r, true
    at r = 2 only).  Moved to a record at (5, 3) or (5, 1) (same claim, and the same digest: the graph is the
    same at every r), `certificate_problems` (what `stiefelsym report` refuses by) must refuse it: the
    certificate is no proof at that r (the statement is false there, the modular method refutes it)."""
    from stiefelsym.run.integrity import certificate_problems
    rec = run_one(_claim(e2_is_one), Size(5, 2), "auto", 0).to_json()
    assert rec["verdict"] == "proved" and certificate_problems([rec]) == []
    assert "E1E1t+E2E2t" in rec["certificate_data"]["summary"]["hypotheses"]
    assert run_one(_claim(e2_is_one), Size(5, to_r), "modular", 0).verdict == "fails"
    assert certificate_problems([_moved(rec, to_r)]) != [], "a certificate of r = 2 accepted in a record at r = %d" % to_r


E2_FILE = '''
from stiefelsym import admissible, claim, elementary

@claim("e2-is-one", kind="id", sizes=admissible(n_max=5), exact_max_n=2, free_max_r=3)
def e2_is_one(s):
    """e_2(XᵀX) = 1 (true at r = 2 only)."""
    _ = int(s.r)
    return {"e2 - 1": elementary(s, s.X.T @ s.X, 2)[2] - s.q(1)}
'''


@pytest.fixture(scope="module")
def e2_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("e2")
    f = tmp / "e2.py"
    f.write_text(E2_FILE)
    out = _cli("verify", "--claims", str(f), "--size", "5,2", "--size", "5,3", "--report-dir", str(tmp / "r"))
    assert (tmp / "r" / "results.json").is_file(), out.stdout + out.stderr
    data = json.loads((tmp / "r" / "results.json").read_text())
    recs = data["results"]
    good = next(x for x in recs if x["r"] == 2)
    bad = next(i for i, x in enumerate(recs) if x["r"] == 3)
    assert good["verdict"] == "proved" and recs[bad]["verdict"] == "fails"
    recs[bad] = _moved(good, 3)
    forged = tmp / "forged" / "results.json"
    forged.parent.mkdir()
    forged.write_text(json.dumps(data))
    return f, forged


def test_report_refuses_a_proof_moved_from_r2_to_r3(e2_run):
    """Closed: `stiefelsym report` rendered "proved at (5, 3)" from the certificate of the family r = 2 (the
    statement fails at (5, 3)); the scope of a certificate a record carries is now read against its size."""
    f, forged = e2_run
    out = _cli("report", "--results", str(forged), "--claims", str(f))
    assert out.returncode != 0, "report accepted it: " + out.stdout + out.stderr


def test_check_refuses_a_proof_moved_from_r2_to_r3(e2_run):
    f, forged = e2_run
    out = _cli("check", "--claims", str(f), str(forged))
    assert out.returncode != 0 and "does not hold at (5,3)" in out.stdout + out.stderr, out.stdout + out.stderr


# --------------------------------------------------------------------------- proofs for every n on a family


def _introspecting(beyond, name):
    """XᵀX = I_r, plus PᵀP where n > ``beyond`` (false there); on the family (introspection) it asks nothing of n."""
    def f(s):
        res = s.X.T @ s.X - s.Ir
        if not _on_family(s) and int(s.n) > beyond:
            res = res + s.P.T @ s.P
        return {"x": res}
    f.__name__ = f.__qualname__ = name
    return f


family_introspection = _introspecting(7, "family_introspection")
square_introspection = _introspecting(4, "square_introspection")


def test_a_claim_stated_at_r2_that_detects_its_family_has_no_verdict_where_its_tracings_differ():
    """Closed (it was open since before free_max_r).  The claim is stated at r = 2 for every n (admissible: no
    largest n).  Traced at the numbers of a size it reads n; on its family it sees, by introspection of a private
    attribute, that it is on the family and asks nothing of n.  Its graph on the family was compared with its
    graphs at the sizes it lists (n <= 5) only, while the fixed-size methods traced it at (9, 2) at the numbers:
    "proved for every n at r = 2" by the dimension-free method, and "fails" at (9, 2).  Now the graph on the
    family is the claim's graph at every size of it, once the graph traced at the
    size's numbers is the same: at (5, 2) it is, and every method evaluates the graph that was proved; at (9, 2)
    it is not, and no verdict is given (error: the claim tells the two tracings apart)."""
    from stiefelsym.ir import compile_at_size
    from stiefelsym.scene import REALIZATIONS
    c = _claim(family_introspection, free_max_r=0, sizes=admissible(5, r_min=2, r_max=2))
    cons = REALIZATIONS["standard"]
    at_numbers = compile_at_size(family_introspection, 9, 2, (cons.name, cons.build), twice=False)
    free = run_one(c, None, "free", 0)
    assert free.verdict == "proved", free.message
    at5 = run_one(c, Size(5, 2), "modular", 0)
    assert at5.verdict == "checked" and at5.digest != at_numbers.digest()     # the trick is there
    for method in ("modular", "exact", "auto"):
        at9 = run_one(c, Size(9, 2), method, 0)
        assert at9.verdict == "error" and "differs from its graph traced at (9,2)" in at9.message, (method, at9.message)


def test_the_family_r_equals_n_is_compared_at_its_sizes_too():
    """The same trick on the family r = n (stated at r = n, listed up to n = 4): the free proof for every n and
    the run at (3, 3) are about the one graph traced on the family; at (6, 6) the claim's code gives another graph
    at the numbers, and no verdict is given."""
    c = _claim(square_introspection, free_max_r=0, sizes=admissible(4, r_is_n=True))
    free = run_one(c, None, "free", 0)
    at6 = run_one(c, Size(6, 6), "modular", 0)
    assert (free.verdict, at6.verdict) == ("proved", "error"), (free.message, at6.message)
    assert run_one(c, Size(3, 3), "modular", 0).verdict == "checked"


FAMILY_FILE = '''
from stiefelsym import admissible, claim


def _on_family(s):
    owner = object.__getattribute__(s.n, "_owner")
    return getattr(owner, "_family", None) is not None


@claim("xtx-small-n", kind="id", sizes=admissible(n_max=5, r_min=2, r_max=2), exact_max_n=2, free_max_r=2)
def xtx_small_n(s):
    """XᵀX = I_r, with PᵀP added when n > 7 (false there)."""
    res = s.X.T @ s.X - s.Ir
    if not _on_family(s) and int(s.n) > 7:
        res = res + s.P.T @ s.P
    return {"x": res}
'''


def test_a_claims_file_family_graph_from_the_r_key_proves_no_false_statement(tmp_path):
    """Closed (it was new with 5d3dc53; the graphs on families r = k now serve a claim stated at every r only).  In a claims file, the claim's own family r = 2 now gets the graph the child traced
    on the family ("r", 2) (TracedFunction.__call__), where before it got the graph with symbolic sizes (refused
    for this claim: the free record was undecided; with free_max_r=0 it still is).  One `verify --max-n 9` then
    writes "proved for every n at r = 2" and "fails" at (8, 2), (9, 2), and `check` accepts the file."""
    f = tmp_path / "fam.py"
    f.write_text(FAMILY_FILE)
    out = _cli("verify", "--claims", str(f), "--max-n", "9", "--report-dir", str(tmp_path / "r"))
    recs = json.loads((tmp_path / "r" / "results.json").read_text())["results"]
    failing = [(x["n"], x["r"]) for x in recs if x["verdict"] == "fails"]
    free = [x for x in recs if x["n"] is None]
    assert failing, out.stdout + out.stderr
    assert not any(x["verdict"] == "proved" for x in free), \
        f"proved for every n at r = 2, and fails at {failing}: {free[0]['certificate'][:120]}"


def catch_the_refusal(s):
    """XᵀX = I_r on the family (int(s.n) refused there, the refusal caught), XᵀX + PᵀP = I_r at a size n > 5
    (false there), with a loop over r (so that only a family r = k can trace it)."""
    res = s.X.T @ s.X - s.Ir
    try:
        big = int(s.n) > 5
    except Exception:   # noqa: BLE001 - the trick: the family trace's refusal, caught
        big = False
    if big:
        res = res + s.P.T @ s.P
    for _ in range(s.r):
        res = res + s.zeros(s.r, s.r, ("r", "r"))
    return {"x": res}


def test_a_refusal_caught_on_the_family_gives_no_proof():
    """The claim catches the refusal of n's number on the family trace and gives a true graph there.  A refusal is
    recorded before it is raised, so the family trace is refused whatever the claim did with it: no proof on the
    family, and the runs beyond n = 5 fail under every method."""
    c = _claim(catch_the_refusal)
    for n, r in ((6, 2), (7, 3)):
        for method in ("auto", "exact", "modular"):
            res = run_one(c, Size(n, r), method, 0)
            assert res.verdict == "fails" and not _specialised(res), (n, r, method, res.verdict)
    assert not _specialised(run_one(c, Size(4, 2), "auto", 0))
