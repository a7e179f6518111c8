"""Stop 83's replays: the stop's own changes and its helpers' findings, each kept as a test.

- own: a field strength F = c·J whose number c is an entry (η[0, 1]·J) was refused by the twisted step's skew
  test (s82's false refusal); an entry of a scene matrix or of a skew matrix by construction is a number now,
  and the false twins (η[1, 0]·J = −η, X[0, 0]·J against J) are refuted by every fixed-size method.
- hidden2 F1: a solved multiplier that is 0 (Π of the twisted Neumann flow) was `inconclusive` under float and
  ball at every precision: each solved entry had its own size as its term scale.  It has its column's largest
  entry's now; the false twins (Π = 0 for another kinetic term, and 10⁻⁹ times it) still fail.
- hidden2 F2: s.theta (a generic element of so(r), like s.eta) was refused as a field strength.
- classes I1: the jobs of one claims file were forked from the process that imported it, so an at-fork hook
  (os.register_at_fork) counted them and an anonymous shared mapping or a pipe made at import carried a flag from
  one job to the next: one function proved under one id and refuted under another.  Every job imports the file
  in a child of its own now, forked from a process that never imported it.
- review R1, R2: the exact method's fused trace and pairing skipped the checks of the sums and products it does
  not compute: a cancelled ill-typed product (Φ A + Λ X − Λ X) and a sum of an ℝʳ and an ℝⁿ matrix were proved.
  They are checked on zero matrices of the same shapes and spaces now: `error`, as under the other methods.
- own: a file whose import registers other claims each time is refused (each job imports it again).
- hidden M2: a rank claimed above the matrix's size spent the exact method's whole symbolic budget before
  `inconclusive`; it is refuted at once now (certain), as the sampled methods refute it.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from adversary_replay import records_by_variant

S83 = Path(__file__).parent / "s83"


@pytest.mark.parametrize("method", ["exact", "modular", "float"])
def test_an_entry_times_j_is_a_field_strength(method):
    recs = records_by_variant(S83 / "own" / "entry_field_strength.py", "--method", method, "--size", "3,2")
    verdicts = {key[0]: rec["verdict"] for key, rec in recs.items()}
    assert verdicts["s83-entry-times-J"] == {"exact": "proved", "modular": "checked", "float": "numeric"}[method]
    assert verdicts["s83-entry-times-J-false"] == "fails"
    assert verdicts["s83-x-entry-times-J-false"] == "fails"


@pytest.mark.parametrize("method", ["float", "ball"])
def test_a_solved_multiplier_that_is_zero_is_resolved(method):
    recs = records_by_variant(S83 / "own" / "solved_zero.py", "--method", method)
    for (cid, _v, n, r), rec in recs.items():
        want = "numeric" if cid == "s83-pi-zero-twisted" else "fails"
        assert rec["verdict"] == want, (cid, n, r, rec["message"][:300])


def test_jobs_of_one_file_share_no_state():
    """fk-first and fk-count are one function (a branch on the number of forks an at-fork hook counted in the
    importing process); sh-read reads a byte sh-set wrote into a shared mapping made at import; sh-corr's
    correction reads a byte its printed claim's trace wrote.  Each is traced alone now: the false branch."""
    recs = records_by_variant(S83 / "classes" / "c4_fork_hooks.py", "--method", "exact", "--size", "3,2")
    verdicts = {key[0]: rec["verdict"] for key, rec in recs.items()}
    assert verdicts["fk-first"] == verdicts["fk-count"] == "fails", verdicts
    recs = records_by_variant(S83 / "classes" / "c4_shared_jobs.py", "--method", "exact", "--size", "3,2")
    verdicts = {(key[0], key[1]): rec["verdict"] for key, rec in recs.items()}
    assert verdicts[("sh-set", None)] == "proved"
    assert verdicts[("sh-read", None)] == verdicts[("sh-pipe-r", None)] == "fails", verdicts
    assert verdicts[("sh-count", None)] == "fails", verdicts
    assert all(v == "fails" for (cid, var), v in verdicts.items() if cid == "sh-corr"), verdicts


@pytest.mark.parametrize("method", ["exact", "modular"])
def test_sums_and_products_a_fused_trace_skips_are_still_checked(method):
    recs = records_by_variant(S83 / "review" / "c_types.py", "--method", method, "--size", "3,2", "--size", "3,3")
    for (cid, _v, n, r), rec in recs.items():
        want = "error" if "control" not in cid else ("proved" if method == "exact" else "checked")
        assert rec["verdict"] == want, (cid, n, r, rec["verdict"], rec["message"][:300])


def test_a_file_whose_import_is_not_deterministic_is_refused():
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims",
                          str(S83 / "own" / "nondeterministic_import.py"), "--jobs", "1", "--size", "3,2",
                          "--no-report"], capture_output=True, text=True, timeout=600)
    assert out.returncode == 2 and "its import is not deterministic" in out.stderr, out.stderr[-2000:]


def test_a_rank_above_the_matrix_size_is_refuted_at_once():
    recs = records_by_variant(S83 / "hidden" / "sec2c_hidden.py", "h3-constraints-rank-everywhere-twin",
                              "--method", "exact", "--size", "4,2", "--size", "4,3")
    for key, rec in recs.items():
        assert rec["verdict"] == "fails" and "no rank exceeds its full size" in rec["certificate"], (key, rec)
