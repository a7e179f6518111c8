"""Adversarial review of stop 53: generic symmetric and skew matrices, s.generic(name, m, m, "sym" | "skew").

The review found that the dimension-free scene named a generic letter by the claim's name alone
(gen:NAME, gen:NAME:sym): the matrices of one name on R^n and on R^r, n x r and r x n, were one letter, and
false identities between them were proved for every n, r (the fixed-size methods refuted them at every size).
This held for the general kind before the stop as well.  The letters now carry their spaces
(gen:S[nxn]:sym, gen:G[nxr] with gen:G[nxr]^T).  It also found that the certificate checker did not check the
name of a general letter's transpose (a general letter declared with a symmetric one for transpose); it now
must be the letter's name with ^T."""
from __future__ import annotations

import json

from adversary_cli import PASSING, verdicts_each

POINT = ("exact", "rational", "modular", "float")


def test_one_name_in_two_spaces_is_two_matrices_under_every_method():
    for file in ("generic_kinds_spaces_free.py", "generic_kinds_spaces_free_general.py"):
        got = verdicts_each(file, ("free",) + POINT, size="3,2")
        for method, v in got.items():
            assert v and all(x not in PASSING for x in v.values()), (file, method, v)
        got = verdicts_each(file, ("exact", "modular"), size="3,3")        # r = n: the spaces have one size
        for method, v in got.items():
            assert v and all(x == "fails" for x in v.values()), (file, method, v)


def test_the_true_claims_of_the_review_still_pass():
    got = verdicts_each("generic_kinds_true_mutate.py", ("free", "exact", "modular"), size="3,2")
    assert got["free"]["adv-gk-true-traces"] == "proved", got
    for method in ("exact", "modular"):
        assert all(x in PASSING for x in got[method].values()), (method, got)


def test_false_claims_through_charts_derivatives_and_blocks_fail():
    for file, size in (("generic_kinds_charts.py", "3,2"), ("generic_kinds_derivatives.py", "3,2"),
                       ("generic_kinds_big_blocks.py", "12,1")):
        got = verdicts_each(file, ("exact", "modular", "float") if size == "3,2" else ("modular", "rational"), size=size)
        for method, v in got.items():
            for cid, x in v.items():
                assert (x in PASSING) == ("true" in cid), (file, method, cid, x)


def test_a_general_letter_cannot_be_declared_with_a_symmetric_transpose():
    from stiefelsym.certificate_check import check_certificate
    data = {"format": "stiefelsym-cofactor-1", "symbols": {},
            "letters": {"gen:G[nxn]": {"kind": "generic", "row": "n", "col": "n", "transpose": "gen:G[nxn]:sym"}},
            "entries": [{"position": "x", "type": ["1", "1"], "terms": [],
                         "residual": [{"coef": "1", "traces": [["Xt", "gen:G[nxn]:sym", "X"]], "word": []},
                                      {"coef": "-1", "traces": [["Xt", "gen:G[nxn]", "X"]], "word": []}]}]}
    assert not check_certificate(json.loads(json.dumps(data))).accepted
