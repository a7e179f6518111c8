"""Stop 83's replays: the stop's own changes and its helpers' findings, each kept as a test.

- own: a field strength F = c·J whose number c is an entry (η[0, 1]·J) was refused by the twisted step's skew
  test (s82's false refusal); an entry of a scene matrix or of a skew matrix by construction is a number now,
  and the false twins (η[1, 0]·J = −η, X[0, 0]·J against J) are refuted by every fixed-size method.
- hidden2 F1: a solved multiplier that is 0 (Π of the twisted Neumann flow) was `inconclusive` under float and
  ball at every precision: each solved entry had its own size as its term scale.  It has its column's largest
  entry's now; the false twins (Π = 0 for another kinetic term, and 10⁻⁹ times it) still fail.
- hidden2 F2: s.theta (a generic element of so(r), like s.eta) was refused as a field strength.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

S83 = Path(__file__).parent / "s83"


def _records(path: Path, *args: str) -> dict:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), "--jobs", "1",
                          "--format", "json", *args], capture_output=True, text=True, timeout=600)
    assert out.stdout.strip(), out.stderr[-2000:]
    return {(r["claim"], r.get("variant"), r.get("n"), r.get("r")): r for r in json.loads(out.stdout)["results"]}


@pytest.mark.parametrize("method", ["exact", "modular", "float"])
def test_an_entry_times_j_is_a_field_strength(method):
    recs = _records(S83 / "own" / "entry_field_strength.py", "--method", method, "--size", "3,2")
    verdicts = {key[0]: rec["verdict"] for key, rec in recs.items()}
    assert verdicts["s83-entry-times-J"] == {"exact": "proved", "modular": "checked", "float": "numeric"}[method]
    assert verdicts["s83-entry-times-J-false"] == "fails"
    assert verdicts["s83-x-entry-times-J-false"] == "fails"


@pytest.mark.parametrize("method", ["float", "ball"])
def test_a_solved_multiplier_that_is_zero_is_resolved(method):
    recs = _records(S83 / "own" / "solved_zero.py", "--method", method)
    for (cid, _v, n, r), rec in recs.items():
        want = "numeric" if cid == "s83-pi-zero-twisted" else "fails"
        assert rec["verdict"] == want, (cid, n, r, rec["message"][:300])
