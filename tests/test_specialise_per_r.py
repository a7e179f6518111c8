"""A proof at one size from a dimension-free proof on the family r = k (``free_max_r``).

A claim stated at every r whose graph needs r as a number (a loop over r: the coefficients e_1, ..., e_2r
of a 2r x 2r Lax matrix) has no graph with symbolic sizes, but it may have one on the family r = k, every
n >= k.  Beyond the claim's symbolic budget, at r <= its ``free_max_r``, the dimension-free proof on that
family is the exact method's proof at (n, k), once the graph at (n, k) is the graph the proof is about and
the modular method's points there agree; the record carries the certificate, bound to its graph.  The
proof is about its r only: a statement true at r = 2 and false at r = 3 is proved at (n, 2) and fails at
(n, 3); a false statement is never proved; a graph that needs n as a number gets no such proof."""
from __future__ import annotations

import pytest

from stiefelsym import admissible, elementary
from stiefelsym.certificate_check import bound, check_certificate
from stiefelsym.claims import Claim, Size, load_catalog
from stiefelsym.run.runner import run_one

SPECIALISED = "the dimension-free proof, specialised"


def _claim(func, free_max_r=3, exact_max_n=2):
    return Claim(id=func.__name__.replace("_", "-"), paper=("prep",), kind="id", section="t", func=func,
                 sizes=admissible(7), exact_max_n=exact_max_n, free_max_r=free_max_r)


def gram_determinant(s):
    """True at every r: det XᵀX = 1, as e_r(XᵀX) (r as a number: Newton's identities up to r)."""
    return {"det(X^T X) - 1": elementary(s, s.X.T @ s.X, s.r)[s.r] - s.q(1)}


def gram_trace_is_two(s):
    """True at r = 2 only: Σ_{i<r} tr(XᵀX)/r = 2 (it is r)."""
    acc = s.q(0)
    for _ in range(s.r):
        acc = acc + s.tr(s.X.T @ s.X) * s.q(1, s.r)
    return {"sum tr(X^T X)/r - 2": acc - s.q(2)}


def gram_with_momenta(s):
    """False at every r: det(XᵀX + PᵀP) = 1."""
    return {"det(X^T X + P^T P) - 1": elementary(s, s.X.T @ s.X + s.P.T @ s.P, s.r)[s.r] - s.q(1)}


def gram_and_n(s):
    """True, but its graph needs n as a number as well: tr(XXᵀ) = r as a sum over n."""
    acc = s.q(0)
    for _ in range(s.n):
        acc = acc + s.q(1)
    return {"det(X^T X) - 1": elementary(s, s.X.T @ s.X, s.r)[s.r] - s.q(1),
            "n - n": acc - s.q(s.n)}


#: the dimension-free results of the process forgotten before and after each test
pytestmark = pytest.mark.usefixtures("fresh_specialise")


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_beyond_the_budget_the_proof_on_the_family_r_is_specialised(method):
    c = _claim(gram_determinant)
    for n, r in ((4, 2), (6, 2), (5, 1)):
        res = run_one(c, Size(n, r), method, 0)
        assert res.verdict == "proved" and res.method == "exact", (n, r, res.verdict, res.message)
        assert res.reductions[0].startswith(SPECIALISED) and f"on the family r = {r} (n >= {r})" in res.reductions[0]
        assert f"for every n >= {r} at r = {r}" in res.certificate
        # the certificate is in the record, accepted by the checker and bound to the record's graph
        assert check_certificate(res.certificate_data).accepted
        assert bound(res.certificate_data, res.to_json()) == ""


def test_at_r_3_and_above_tr_i_r_stays_the_symbol_r():
    """The free algebra has the columns of R^r as letters at r = 1, 2 only: at r = k >= 3 it keeps tr I_r as the
    symbol r, so a residual that vanishes at r = 3 alone (det XᵀX − 1 as e_3 of XᵀX, a polynomial in the traces)
    is not 0 there, and the run goes to the methods that decide it; a proof there is one for every r."""
    res = run_one(_claim(gram_determinant), Size(5, 3), "auto", 0)
    assert res.verdict == "checked" and not any(x.startswith(SPECIALISED) for x in res.reductions), res.verdict


def test_beyond_free_max_r_the_randomized_method_decides():
    c = _claim(gram_determinant, free_max_r=1)
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "checked" and res.method == "modular", (res.verdict, res.message)
    assert not any(x.startswith(SPECIALISED) for x in res.reductions)
    res = run_one(_claim(gram_determinant, free_max_r=0), Size(4, 2), "auto", 0)
    assert res.verdict == "checked", res.verdict


def test_a_proof_on_one_r_is_not_a_proof_at_another():
    c = _claim(gram_trace_is_two)
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "proved" and "on the family r = 2" in res.reductions[0], (res.verdict, res.message)
    for n, r in ((5, 3), (4, 1)):
        res = run_one(c, Size(n, r), "auto", 0)
        assert res.verdict == "fails", (n, r, res.verdict, res.message)
        assert res.residual


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_a_false_statement_is_never_proved_on_a_family(method):
    c = _claim(gram_with_momenta)
    for n, r in ((4, 2), (5, 3)):
        res = run_one(c, Size(n, r), method, 0)
        assert res.verdict != "proved", (n, r, res.verdict)
        if method == "auto":
            assert res.verdict == "fails" and res.residual


def test_a_graph_that_needs_n_as_a_number_gets_no_proof_on_a_family():
    res = run_one(_claim(gram_and_n), Size(5, 2), "auto", 0)
    assert res.verdict == "checked" and not any(x.startswith(SPECIALISED) for x in res.reductions), res.verdict


@pytest.mark.parametrize("bad", [-1, True, 2.0, "3"])
def test_free_max_r_is_a_non_negative_int(bad):
    with pytest.raises(ValueError, match="free_max_r"):
        _claim(gram_determinant, free_max_r=bad)


def test_the_catalog_spectral_curve_coefficients_are_proved_on_the_families_r_up_to_4():
    c = load_catalog().get("2r-integrals-conserved")
    assert c.free_max_r == 4
    res = run_one(c, Size(5, 3), "auto", 0)
    assert res.verdict == "proved" and "on the family r = 3" in res.reductions[0], (res.verdict, res.message)
    assert check_certificate(res.certificate_data).accepted
    res = run_one(c, Size(5, 5), "auto", 0)           # beyond free_max_r
    assert res.verdict == "checked", res.verdict


def test_a_claims_file_gets_the_proof_on_the_family_r(tmp_path):
    """A claim of a user's file, traced in its own child, carries free_max_r and its graphs on the families
    r = k to the verifying process: the run at (5, 2) is proved on the family r = 2, the run at (5, 3) (beyond
    free_max_r) is checked, and the records pass `stiefelsym check` (each run again, certificates bound)."""
    import json
    import os
    import subprocess
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    f = tmp_path / "loops.py"
    f.write_text('''
from stiefelsym import admissible, claim, elementary

@claim("gram-det", kind="id", sizes=admissible(n_max=5), exact_max_n=2, free_max_r=2)
def gram_det(s):
    """det XᵀX = 1, as e_r(XᵀX)."""
    return {"det(X^T X) - 1": elementary(s, s.X.T @ s.X, s.r)[s.r] - s.q(1)}
''')
    env = dict(os.environ, PYTHONPATH=str(root))
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(f), "--size", "5,2",
                          "--size", "5,3", "--report-dir", str(tmp_path / "r")], capture_output=True, text=True,
                         env=env, cwd=str(root), timeout=300)
    assert out.returncode == 0, out.stdout + out.stderr
    records = {(x["n"], x["r"]): x for x in json.loads((tmp_path / "r" / "results.json").read_text())["results"]}
    assert records[(5, 2)]["verdict"] == "proved" and "on the family r = 2" in records[(5, 2)]["reductions"][0]
    assert records[(5, 3)]["verdict"] == "checked"
    check = subprocess.run([sys.executable, "-m", "stiefelsym", "check", "--claims", str(f),
                            str(tmp_path / "r" / "results.json")], capture_output=True, text=True, env=env,
                           cwd=str(root), timeout=300)
    assert check.returncode == 0 and "0 rejected" in check.stdout + check.stderr, check.stdout + check.stderr


def test_a_records_certificate_edited_or_moved_is_refused():
    """The certificate a record at a size carries is checked like a proof for all n, r (`stiefelsym report`
    and `check` refuse the file): edited, it is rejected by the checker; moved to another graph, it is not
    bound to the record."""
    import copy

    from stiefelsym.run.integrity import certificate_problems
    rec = run_one(_claim(gram_determinant), Size(4, 2), "auto", 0).to_json()
    assert rec["verdict"] == "proved" and certificate_problems([rec]) == []
    edited = copy.deepcopy(rec)
    edited["certificate_data"]["entries"][0]["residual"][0]["coef"] = "1/3"
    assert any("rejected by the independent checker" in p for p in certificate_problems([edited]))
    moved = dict(rec, digest="0" * 64)
    assert any("the certificate is about claim" in p for p in certificate_problems([moved]))
