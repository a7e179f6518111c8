"""Stop 82's replays: the three helpers' findings (s82/classes, s82/free, s82/hidden), each kept as a test.

- classes W1: a true generic rank whose minors' degree bound is near the primes (a factor identically 0 on
  V(n, r) inflates it) was `fails` under exact and auto: the random points of prime fields could not reach the
  false-pass target, and that was recorded as a mismatch.  Not decided is `inconclusive` now.
- classes I2: a correction was traced in the process that had just traced the printed claim, so it saw module
  state the printed claim left.  Every job (the metadata, one function at one key) has a process of its own now.
- free H1: the dimension-free Euler-Lagrange solver divided by a coefficient in the sizes (n - r, n - 2r, r - 1),
  which is 0 at some stated sizes, and left no trace in the certificate: "proved for all n, r".  A division goes
  through the free algebra's one door for divisors now (refused when it may vanish at a size).
- free H2: resolvent identities divided by nu - mu = n - r (and A^-1 rules by mu); the same door; the
  independent checker rejects a certificate with a denominator that may vanish at a size.
- hidden: the magnetic form's F = E1^E2 was refused as a field strength (it was not typed as a matrix).
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import symengine as se

from stiefelsym.certificate_check import may_vanish_at_a_size

from adversary_replay import records_by_variant

S82 = Path(__file__).parent / "s82"


def test_an_undecided_rank_is_not_refuted():
    """Rank(M + z M, 6) with z = (tr XᵀX − r)^(2^64) = 0 on V(n, r): true.  Its minors' degree bound (~1e20) keeps
    the points of prime fields from reaching the false-pass target: exact said `fails` with no witness."""
    recs = records_by_variant(S82 / "classes" / "c5_rank_degree.py", "c5-deg-true", "c5-deg-small-true",
                              "c5-deg-small-false", "--method", "exact", "--size", "2,1")
    got = {cid: rec["verdict"] for (cid, _v, _n, _r), rec in recs.items()}
    assert got == {"c5-deg-true": "inconclusive", "c5-deg-small-true": "proved", "c5-deg-small-false": "fails"}, got
    msg = recs[("c5-deg-true", None, 2, 1)]["message"]
    assert "is not a verdict" in msg and "false-pass bound" in msg, msg


def test_a_correction_does_not_see_what_the_printed_claim_left():
    """corr-state's printed claim sets a module flag that its correction reads (XᵀX = I_r with the flag, XXᵀ = I_n
    without).  Traced in a process of its own, the correction is the function its file defines: XXᵀ = I_n, false at
    r < n, as the same function registered alone (corr-state-alone)."""
    recs = records_by_variant(S82 / "classes" / "c4_corrections.py", "corr-state", "corr-state-alone",
                              "--method", "exact", "--size", "3,1")
    verdicts = {(cid, v): rec["verdict"] for (cid, v, _n, _r), rec in recs.items()}
    assert verdicts == {("corr-state", None): "fails", ("corr-state-alone", None): "fails",
                        ("corr-state", "XᵀX = I_r in place of XXᵀ = I_n"): "fails"}, verdicts


#: the Euler-Lagrange claims with a Lagrangian scaled by a number of the sizes: which ones are proved for all n, r
EL_SCALED = {"b3-el-c1": True, "b3-el-n": True, "b3-el-n-minus-r": False, "b3-el-r-minus-1": False,
             "b3-el-n-minus-2r": False, "b3-el-n-minus-r-false": False}


def test_no_division_by_a_size_that_may_vanish_in_a_free_proof():
    recs = records_by_variant(S82 / "free" / "b3_el_scaled.py", "--method", "free")
    for (cid, _v, _n, _r), rec in recs.items():
        proved = rec["verdict"] == "proved"
        assert proved == EL_SCALED[cid], (cid, rec["verdict"], rec["message"][:300])
        if not EL_SCALED[cid] and cid != "b3-el-r-minus-1":      # (r - 1: the division probe's size (3,1))
            assert rec["verdict"] == "undecided", (cid, rec["verdict"])


@pytest.mark.parametrize("name", ["b1_sizes.py", "b2_poles.py"])
def test_no_resolvent_identity_across_sizes(name):
    """R(λ) and R(λ + n − r): the resolvent identity divides by n − r, 0 at r = n."""
    recs = records_by_variant(S82 / "free" / name, "--method", "free")
    for (cid, _v, _n, _r), rec in recs.items():
        if "res-nr" in cid or "commute" in cid or "ntrace" in cid or "product" in cid:
            assert rec["verdict"] != "proved", (cid, rec["message"][:300])


def test_the_checker_rejects_a_denominator_that_may_vanish_at_a_size():
    n, r, lam = se.symbols("n r lambda_")
    for den in (n - r, r - 1, (n - r) ** 2, lam * (n - 2 * r), n ** 2 - n):
        assert may_vanish_at_a_size(den), den
    for den in (n, n + r, 1 + 2 * n * r, lam + n, lam * n, lam - 1, se.Integer(3), 1 + (n - r) * lam):
        assert not may_vanish_at_a_size(den), den


def test_the_magnetic_form_is_a_field_strength():
    """F = E1∧E2 (twisted.magnetic_matrix) given to a twisted flow, alone and in sums and multiples."""
    recs = records_by_variant(S82 / "hidden" / "probes_f.py", "p82f-J-plain", "p82f-two-J", "p82f-skew-part",
                              "p82f-matrix-times-scalar", "--method", "exact", "--size", "3,2")
    for key, rec in recs.items():
        assert rec["verdict"] == "proved", (key, rec["message"][:300])
    recs = records_by_variant(S82 / "hidden" / "probes_f.py", "p82f-J-plain", "p82f-two-J", "--method", "free")
    for key, rec in recs.items():
        assert rec["verdict"] == "proved", (key, rec["message"][:300])


def test_a_forged_claim_id_is_rejected_alone():
    """A record whose claim id carries a zero-width space (s81's sweep, forged/claimzw): `check` rejected the 144
    catalog claims as missing runs of the file's command (which ran the claims file's claims only); now the forged
    record and the file's claim left without a record."""
    root = Path(__file__).parents[2]
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "check",
                          "tests/adversary/s81/classes/forged/claimzw/results.json"],
                         capture_output=True, text=True, timeout=600, cwd=root)
    assert out.returncode == 1, out.stderr[-1000:]
    rejected = [line for line in out.stdout.splitlines() if line.startswith("REJECTED")]
    assert 1 <= len(rejected) <= 3, rejected
    assert any("no such claim" in line for line in rejected), rejected
    assert not any("stiefel-corank-one" in line for line in rejected), rejected


def test_a_divisor_of_one_sign_in_the_sizes_is_accepted():
    """The review of the door (s82/review, F2): n + r and −2n are nonzero at every size; the door refused them (the
    constant term 0 that symengine lists, and a sign), so true claims the engine proved before were undecided."""
    recs = records_by_variant(S82 / "review" / "r_resolvents.py", "--method", "free")
    for (cid, _v, _n, _r), rec in recs.items():
        assert (rec["verdict"] == "proved") == (not cid.endswith("-false")), (cid, rec["verdict"], rec["message"][:300])
    n, r = se.symbols("n r")
    for den in (-(n + r), -2 * n, n * r + n, 2 * n + r):
        assert not may_vanish_at_a_size(den), den


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
def test_the_typed_magnetic_form_keeps_its_negative_control(method):
    """The stop's own attempt (s82/own/magnetic_false.py): with F typed, the flows of F = J and F = 2J must still
    differ (fails at fixed sizes, never proved by free), and F = J is the default F."""
    size = [] if method == "free" else ["--size", "3,2"]
    recs = records_by_variant(S82 / "own" / "magnetic_false.py", "--method", method, *size)
    got = {cid: rec["verdict"] for (cid, _v, _n, _r), rec in recs.items()}
    assert got["s82own-twice-J-false"] == ("undecided" if method == "free" else "fails"), got
    assert got["s82own-default-J-true"] in ("proved", "checked", "numeric"), got
