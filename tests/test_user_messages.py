"""What a user meets when writing claims: the gradient read by its components' names, clear refusals of
abs(), a matrix power written with ** and a number as a block, a long exact witness shown by its magnitude,
and a note for the claims a --size skips (found by a new user writing statements of the paper)."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import pytest

from stiefelsym import admissible, block
from stiefelsym.claims import Claim, Size
from stiefelsym.results import Result, short_value
from stiefelsym.run.runner import run_one

PASS = {"proved", "checked", "numeric"}


def _H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def _gradient_by_names(s):
    g = s.gradient(_H)
    HX, HP = g
    return {"X": g["X"] - s.A @ s.X, "P": g["P"] - s.P, "pair": [g[0] - HX, g[1] - HP]}


def _gradient_by_names_false(s):
    g = s.gradient(_H)
    return {"P": g["P"] - s.X}


def _claim(func, cid):
    return Claim(id=cid, paper=("Euclidean",), kind="id", section="3", func=func, sizes=admissible(4))


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
def test_a_gradient_is_read_by_the_names_of_its_components(method):
    size = None if method == "free" else Size(3, 2)
    good = run_one(_claim(_gradient_by_names, "grad-names"), size, method, seed=1)
    bad = run_one(_claim(_gradient_by_names_false, "grad-names-false"), size, method, seed=1)
    assert good.verdict in PASS, good.line()
    assert bad.verdict == ("undecided" if method == "free" else "fails"), bad.line()


def _gradient_unknown_name(s):
    return {"Q": s.gradient(_H)["Q"]}


def _abs(s):
    return {"a": abs(s.tr(s.P.T @ s.P)) - s.tr(s.P.T @ s.P)}


def _matrix_power(s):
    return {"a": s.Phi ** 2 - s.Phi @ s.Phi}


def _number_block(s):
    return {"a": block([[s.Phi, 0], [0, s.Phi]])}


def _bare_matrix(s):
    return s.X.T @ s.P + s.P.T @ s.X


def _rank_of_a_float(s):
    from stiefelsym import Rank
    return {"r": Rank(s.X, 1.0)}


@pytest.mark.parametrize("func, words, refused", [
    (_gradient_unknown_name, "components 'X' and 'P'", False),      # a KeyError of the claim's own code
    (_bare_matrix, "a matrix or number of the trace: put it in a dict", True),
    (_rank_of_a_float, "the expected rank is an int", True),
    (_abs, "abs() of a traced value", True),
    (_matrix_power, "a matrix power is a product", True),
    (_number_block, "a zero block is s.zeros(", True),
])
@pytest.mark.parametrize("method", ["exact", "modular", "free"])
def test_a_refusal_says_what_to_write_instead(func, words, refused, method):
    """A refusal of the tracer at every size (with symbolic sizes and at a fixed size) is an error under every
    method, free included (it was undecided there, always as expected: a run of free alone passed an ill-formed
    claims file); an exception of the claim's own code is an error under every method."""
    res = run_one(_claim(func, "refused"), None if method == "free" else Size(3, 2), method, seed=1)
    assert res.verdict == "error", res.line()
    assert words in res.message, res.message


def test_a_long_exact_witness_is_shown_by_its_magnitude():
    value = "-" + "28874702567616940019" * 8 + "/" + "7" * 140
    res = Result(claim="c", paper=[], section="3", kind="id", title="", statement="", n=3, r=2, method="exact",
                 verdict="fails", expected=True, seconds=0.1, seed=0, witness={"entry": "LA1[1,2]", "value": value})
    line = res.line()
    assert "-3.7125e19 (a rational of 160/140 digits; exact with --format json)" in line, line
    assert short_value("12/7") == "12/7"
    assert short_value("x" * 80).endswith("...")


#: a claims file: one claim at every r, one at r = 1 only, one dimension claim
CLAIMS_FILE = textwrap.dedent('''
    from stiefelsym import Rank, admissible, claim

    @claim("every-r", paper="cond_XP", kind="id", section="2", sizes=admissible(4))
    def every_r(s):
        """XᵀX = I_r."""
        return {"XtX": s.X.T @ s.X - s.Ir}

    @claim("r-one", paper="cond_XP", kind="id", section="2", sizes=admissible(4, r_max=1))
    def r_one(s):
        """XᵀX = 1 at r = 1."""
        return {"XtX": s.X.T @ s.X - s.Ir}

    @claim("rank-x", paper="cond_XP", kind="dim", section="2", sizes=admissible(4))
    def rank_x(s):
        """X has rank r."""
        return {"rank": Rank(s.X, s.r, generic=True)}
''')


def _verify(tmp_path, *args):
    path = tmp_path / "claims.py"
    path.write_text(CLAIMS_FILE)
    return subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), "--size", "3,2",
                           "--no-report", *args], capture_output=True, text=True, timeout=300)


def test_a_size_given_without_claims_names_the_claims_it_skips(tmp_path):
    out = _verify(tmp_path, "--method", "modular")
    assert out.returncode == 0, out.stderr
    assert "note: (3,2): 1 of 3 claims are not stated at this size and skip it: r-one" in out.stderr, out.stderr


def test_float_and_ball_say_they_skip_dimension_claims(tmp_path):
    out = _verify(tmp_path, "--method", "float")
    assert out.returncode == 0, out.stderr
    assert "note: --method float skips 1 dimension claim (rank-x)" in out.stderr, out.stderr
    out = _verify(tmp_path, "rank-x", "--method", "float", "--method", "ball")
    assert out.returncode == 2 and "Traceback" not in out.stderr, out.stderr
    assert "rank-x: a dimension claim (kind 'dim') is an integer, which the float and ball methods do not compute" \
        in out.stderr, out.stderr



def _derivative_along_a_gradient(s):
    return {"d": s.d(lambda t: t.tr(t.X.T @ t.P), s.gradient(_H))}


def _scaled_gradient(s):
    g = s.gradient(_H)
    return {"d": (2 * g)[0] - 2 * g["X"]}


@pytest.mark.parametrize("func, words", [
    (_derivative_along_a_gradient, "a derivative along a gradient"),
    (_scaled_gradient, "arithmetic on a gradient"),
])
@pytest.mark.parametrize("method", ["exact", "modular", "free"])
def test_a_gradient_is_not_a_flow_nor_a_tuple_to_repeat(func, words, method):
    res = run_one(_claim(func, "gradient-misused"), None if method == "free" else Size(3, 2), method, seed=1)
    assert res.verdict == "error", res.line()
    assert words in res.message, res.message


def test_a_mistyped_claim_id_gets_the_nearest_ids():
    from stiefelsym.claims import load_catalog
    with pytest.raises(KeyError, match="did you mean manakov-lax"):
        load_catalog().get("manakov-lex")


def test_an_error_raised_in_a_statement_s_constructor_is_located_at_the_claim_s_line():
    """Rank's __init__ is generated code (a dataclass's, file "<string>"): the location is the claim's line."""
    import inspect
    res = run_one(_claim(_rank_of_a_float, "rank-float"), Size(3, 2), "modular", seed=1)
    line = inspect.getsourcelines(_rank_of_a_float)[1] + 2
    assert res.verdict == "error" and f"(at {os.path.relpath(__file__)}:{line})" in res.message, res.message
