"""Which files the pytest plugin collects with ``--stiefelsym``: every file that declares claims, however it spells
the decorator and whatever its name (the review of stop 62: a false claim decorated ``@stiefelsym.claim(...)``, one
decorated ``@ stated (...)`` after ``from stiefelsym import claim as stated``, and one in a file named
``test_*.py`` were not collected, and ``pytest --stiefelsym DIR`` passed where ``stiefelsym verify --claims DIR``
failed all three)."""
from __future__ import annotations

import pytest

from stiefelsym.pytest_plugin import defines_claims

pytest_plugins = ["pytester"]

DOTTED = '''
import stiefelsym


@stiefelsym.claim("pl-false-dotted", kind="id", sizes=stiefelsym.admissible(n_max=3))
def false_one(s):
    """XᵀP = 0 (false)."""
    return {"XtP": s.X.T @ s.P}
'''

SPACED = '''
from stiefelsym import admissible, claim as stated


@ stated ("pl-false-spaced", kind="id", sizes=admissible(n_max=3))
def false_two(s):
    """tr PᵀP = 0 (false)."""
    return {"trPtP": s.tr(s.P.T @ s.P)}
'''

TESTFILE = '''
from stiefelsym import admissible, claim


@claim("pl-false-testfile", kind="id", sizes=admissible(n_max=3))
def false_three(s):
    """PᵀP = 0 (false)."""
    return {"PtP": s.P.T @ s.P}
'''

TRUE = '''
from stiefelsym import admissible, claim


@claim("pl-true", kind="id", sizes=admissible(n_max=3))
def true_one(s):
    """XᵀX = I (true)."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}
'''

HELPER = '''
"""A helper module: it imports stiefelsym and mentions @claim( in a docstring, and declares no claim."""
from stiefelsym import comm


def psi(s):
    return comm(s.X.T, s.P)
'''


@pytest.mark.parametrize("text,expected", [
    (DOTTED, True), (SPACED, True), (TESTFILE, True), (TRUE, True), (HELPER, False),
    ("import stiefelsym.claims as C\n\n@C.claim('x', kind='id')\ndef f(s):\n    return {}\n", True),
    ("from stiefelsym.claims import claim\nf = claim('x', kind='id')(lambda s: {})\n", True),
    ("from stiefelsym import *\n\n@claim('x', kind='id')\ndef f(s):\n    return {}\n", True),
    ("def claim(*a, **k):\n    return lambda f: f\n\n@claim('x')\ndef f(s):\n    return {}\n", False),
    ("from stiefelsym import claim\n@claim(\n", True),      # does not parse: loading it reports the error
])
def test_defines_claims_reads_the_syntax_not_the_spelling(text, expected):
    assert defines_claims(text) is expected


def test_the_plugin_collects_every_file_that_declares_claims(pytester):
    pytester.makepyfile(dotted_claims=DOTTED, spaced_claims=SPACED, test_false_claims=TESTFILE, good_claims=TRUE,
                        helper=HELPER)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v")
    result.assert_outcomes(passed=1, failed=3)
    result.stdout.fnmatch_lines(["*dotted_claims.py::pl-false-dotted*FAILED*", "*good_claims.py::pl-true*PASSED*",
                                 "*spaced_claims.py::pl-false-spaced*FAILED*",
                                 "*test_false_claims.py::pl-false-testfile*FAILED*"])
