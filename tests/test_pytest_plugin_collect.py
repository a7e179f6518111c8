"""Which files the pytest plugin collects with ``--stiefelsym``: every file, as ``stiefelsym verify --claims DIR``
reads a folder; loading a file says whether it declares claims (the reviews of stop 62: a false claim decorated
``@stiefelsym.claim(...)``, one decorated ``@ stated (...)`` after ``from stiefelsym import claim as stated``, one in
a file named ``test_*.py``, one reached by getattr, by assignment or through a helper were not collected, and
``pytest --stiefelsym DIR`` passed where ``stiefelsym verify --claims DIR`` failed them)."""
from __future__ import annotations


import pytest

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


def test_the_plugin_collects_every_file_that_declares_claims(pytester):
    pytester.makepyfile(dotted_claims=DOTTED, spaced_claims=SPACED, test_false_claims=TESTFILE, good_claims=TRUE,
                        helper=HELPER)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v",
                                           "--continue-on-collection-errors")
    # a test module found in the folder that declares claims is refused (not imported, no verdict): never a pass
    result.assert_outcomes(passed=1, failed=2, errors=1)
    result.stdout.fnmatch_lines(["*dotted_claims.py::pl-false-dotted*FAILED*", "*good_claims.py::pl-true*PASSED*",
                                 "*spaced_claims.py::pl-false-spaced*FAILED*",
                                 "*ERROR*test_false_claims.py*"])
    assert result.ret != 0


GETATTR = '''
import stiefelsym


def f(s):
    """Ψ = 0 (false)."""
    return {"Psi": s.Psi}


getattr(stiefelsym, "claim")("pl-false-getattr", kind="id", sizes=stiefelsym.admissible(n_max=3))(f)
'''

REEXPORT = '''
from _pl_helpers import ALL, claim


@claim("pl-false-reexport", kind="id", sizes=ALL)
def f(s):
    """X Xᵀ = I_n (false)."""
    return {"XXt": s.X @ s.X.T - s.In}
'''

HELPERS = '''
from stiefelsym import admissible, claim  # noqa: F401

ALL = admissible(n_max=3)
'''


def test_a_file_whose_claim_the_syntax_does_not_show_is_loaded_and_collected(pytester):
    """The second review: claim reached by getattr, or imported through a helper module next to the file: loaded, the
    file declares its claims, and they are collected.  A helper that declares no claim (and a private one) has no
    items."""
    pytester.makepyfile(getattr_claims=GETATTR, reexport_claims=REEXPORT, _pl_helpers=HELPERS, helper=HELPER,
                        good_claims=TRUE)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v")
    result.assert_outcomes(passed=1, failed=2)
    result.stdout.fnmatch_lines(["*getattr_claims.py::pl-false-getattr*FAILED*", "*good_claims.py::pl-true*PASSED*",
                                 "*reexport_claims.py::pl-false-reexport*FAILED*"])


SMUGGLED = '''
"""My own attempt to slip a false claim past the plugin: no import of stiefelsym and no claim in the syntax."""
import importlib

api = importlib.import_module("stief" + "elsym")
exec(compile("@api.claim('pl-false-smuggled', kind='id', sizes=api.admissible(n_max=3))\\n"
             "def f(s):\\n    return {'XXt - I': s.X @ s.X.T - s.In}\\n", "<claims>", "exec"))
'''


def test_a_claim_no_syntax_shows_is_still_collected(pytester):
    """No reading of the text decides which files declare claims (an import spelled at run time, a claim made by exec):
    every file is loaded, as the command line loads a folder, and the false claim fails."""
    pytester.makepyfile(smuggled=SMUGGLED, good_claims=TRUE)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v")
    result.assert_outcomes(passed=1, failed=1)
    result.stdout.fnmatch_lines(["*good_claims.py::pl-true*PASSED*", "*smuggled.py::pl-false-smuggled*FAILED*"])


# -- stop 70's review: pytest imports a file named on its command line (and --doctest-modules any .py file) as a
# module of its own process; a claims file imported there could replace what hands out the verdicts

PATCHING = '''
import sys

from stiefelsym import admissible, claim


@claim("pl-false-patching", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2)."""
    return {"XtP": s.X.T @ s.P}


if "_pytest.python" in sys.modules:     # imported by pytest itself: every verdict said proved
    from stiefelsym.run import runner

    _verify = runner.verify

    def verify(claims, *a, **kw):
        out = _verify(claims, *a, **kw)
        for r in out:
            r.verdict, r.expected = "proved", True
        return out

    runner.verify = verify
'''


def test_a_claims_file_named_on_the_command_line_never_runs_in_the_pytest_process(pytester):
    pytester.makepyfile(my_claims=PATCHING)
    for extra in ((), ("--doctest-modules",)):
        result = pytester.runpytest_subprocess("--stiefelsym", "my_claims.py", "--stiefelsym-method", "modular",
                                               "-p", "no:cacheprovider", "-v", *extra)
        result.assert_outcomes(passed=3, failed=3)
        result.stdout.fnmatch_lines(["*pl-false-patching?n=3,r=2?-modular*FAILED*"])


def test_a_test_module_that_declares_claims_is_refused_and_never_imported(pytester):
    # found in a folder, test_*.py is pytest's to import: one that declares claims (as loading it in child processes
    # says) is not imported, and collecting it is an error (no verdict, true or false; the session fails)
    pytester.makepyfile(test_patching=PATCHING, good_claims=TRUE)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v")
    result.assert_outcomes(errors=1)
    result.stdout.fnmatch_lines(["*test_patching.py declares claims and is named as a test module*"])
    assert result.ret != 0


TESTMODULE_PATCHING_THE_GUARD = PATCHING + '''
    from stiefelsym import pytest_plugin
    pytest_plugin._imported_here = lambda path: None
'''


def test_a_test_module_cannot_replace_the_guard_it_would_meet(pytester):
    """Stop 71's review: a claims file named test_*.py in a folder replaced the check of stop 70 (which looked for the
    file in sys.modules when each item ran, after the file's code had run) and `runner.verify`: every item passed,
    "proved".  Now it is never imported: another file's false claim fails, and the module itself is refused."""
    pytester.makepyfile(test_patching=TESTMODULE_PATCHING_THE_GUARD, dotted_claims=DOTTED)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v",
                                           "--continue-on-collection-errors")
    result.assert_outcomes(failed=1, errors=1)
    result.stdout.fnmatch_lines(["*dotted_claims.py::pl-false-dotted*FAILED*"])


def test_a_claims_file_a_conftest_imports_gets_no_verdict(pytester):
    pytester.makepyfile(true_claims=TRUE)
    pytester.makeconftest("import sys, os\nsys.path.insert(0, os.path.dirname(__file__))\nimport true_claims  # noqa\n")
    result = pytester.runpytest_subprocess("--stiefelsym", "true_claims.py", "--stiefelsym-method", "modular",
                                           "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-rf")
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*was imported into the pytest process*"])


PATCHING_INIT = '''
import os
import sys

if "_pytest.python" in sys.modules:     # imported by pytest itself: every verdict said proved
    open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "init-ran"), "w").close()
''' + PATCHING.split('if "_pytest.python" in sys.modules:     # imported by pytest itself: every verdict said proved\n')[1] \
    + "    from stiefelsym import pytest_plugin\n    pytest_plugin._imported_here = lambda path: None\n"


def test_a_claims_file_in_a_package_is_refused_and_its_init_never_imported(pytester):
    """Stop 70's own attempt, and stop 71's review: pytest imports a package's __init__.py into its process to set up
    the items collected in it, before they run; the review's __init__.py replaced the check of stop 70 and
    `runner.verify` (every item passed, "proved").  A claims file in a package is now refused when collected, so
    no item of it is set up and the __init__.py is never imported: another file's false claim fails."""
    pkg = pytester.mkpydir("pkg")
    (pkg / "__init__.py").write_text(PATCHING_INIT)
    (pkg / "false_claims.py").write_text(PATCHING.replace("pl-false-patching", "pl-false-in-package"))
    pytester.makepyfile(dotted_claims=DOTTED)
    for args in (("pkg",), ("pkg/false_claims.py",), (".", "--continue-on-collection-errors")):
        result = pytester.runpytest_subprocess("--stiefelsym", *args, "--stiefelsym-method", "modular",
                                               "--stiefelsym-size", "3,2", "-p", "no:cacheprovider", "-v", "-rf")
        assert result.ret != 0
        result.stdout.fnmatch_lines(["*false_claims.py lies in a package*"])
        assert "PASSED" not in result.stdout.str()
    result.assert_outcomes(failed=1, errors=1)
    result.stdout.fnmatch_lines(["*dotted_claims.py::pl-false-dotted*FAILED*"])
    assert not (pytester.path / "init-ran").exists()


def test_a_claims_module_named_by_pyargs_in_a_package_is_refused(pytester, monkeypatch):
    """Stop 71's review: pytest resolves a module named by --pyargs with importlib, which imports its package's
    __init__.py before any collection (it replaced the plugin's checks).  With --stiefelsym, --pyargs names only the
    catalog."""
    pkg = pytester.mkpydir("pkg")
    (pkg / "__init__.py").write_text(PATCHING_INIT)
    (pkg / "false_claims.py").write_text(PATCHING.replace("pl-false-patching", "pl-false-in-package"))
    monkeypatch.setenv("PYTHONPATH", str(pytester.path))
    result = pytester.runpytest_subprocess("--stiefelsym", "--pyargs", "pkg.false_claims", "--stiefelsym-method",
                                           "modular", "--stiefelsym-size", "3,2", "-p", "no:cacheprovider")
    assert result.ret != 0
    result.stderr.fnmatch_lines(["*--pyargs names only the catalog*"])
    assert "passed" not in result.stdout.str()
    assert not (pytester.path / "init-ran").exists()


PLANTING = '''
import os

from stiefelsym import admissible, claim

try:    # a conftest.py beside the file would run in the next pytest process, before any collection
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "conftest.py"), "w") as fh:
        fh.write("from stiefelsym.run import runner\\n_v = runner.verify\\n"
                 "def verify(*a, **k):\\n    out = _v(*a, **k)\\n"
                 "    for r in out:\\n        r.verdict, r.expected = 'proved', True\\n    return out\\n"
                 "runner.verify = verify\\n")
except OSError:
    pass


@claim("pl-false-planting", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2)."""
    return {"XtP": s.X.T @ s.P}
'''


def test_a_claims_file_cannot_plant_a_conftest_for_the_next_pytest_run(pytester):
    # stop 70's second own attempt: loaded in child processes in namespaces, the file writes nowhere, so two runs
    # give the same honest verdicts and no conftest.py appears (without namespaces the file runs with the user's
    # rights, as tests/test_sandbox.py and the guide say)
    import pytest
    from stiefelsym.run.sandbox import namespaces_available
    if not namespaces_available():
        pytest.skip("no user + pid + mount namespaces here: a claims file writes with the user's rights")
    pytester.makepyfile(planting_claims=PLANTING)
    for _ in range(2):
        result = pytester.runpytest_subprocess("--stiefelsym", "planting_claims.py", "--stiefelsym-method", "modular",
                                               "-p", "no:cacheprovider")
        result.assert_outcomes(passed=3, failed=3)
    assert not (pytester.path / "conftest.py").exists()


def test_python_files_with_a_folder_are_matched_as_pytest_matches_them(pytester):
    """The second review of stop 71: with `python_files = checks/*.py`, the plugin matched the pattern against the
    absolute path and missed, took the user's test module for a claims file declaring none, and reported it empty:
    its failing test vanished under --stiefelsym (exit 0)."""
    pytester.makeini("[pytest]\npython_files = checks/*.py\n")
    checks = pytester.mkdir("checks")
    (checks / "helpers_test_mod.py").write_text("def test_must_run():\n    assert False, 'this test must run'\n")
    pytester.makepyfile(good_claims=TRUE)
    result = pytester.runpytest_subprocess("--stiefelsym", "--stiefelsym-method", "modular", "--stiefelsym-size",
                                           "3,2", "-p", "no:cacheprovider")
    result.assert_outcomes(failed=1, passed=1)


@pytest.mark.parametrize("option", ["--stiefelsym-timeout=nan", "--stiefelsym-timeout=-1", "--stiefelsym-memory=0"])
def test_a_bad_budget_is_a_usage_error_not_a_failure_of_every_claim(pytester, option):
    pytester.makepyfile(good_claims=TRUE)
    result = pytester.runpytest_subprocess("--stiefelsym", str(pytester.path), "--stiefelsym-method", "modular",
                                           option, "-p", "no:cacheprovider")
    assert result.ret == pytest.ExitCode.USAGE_ERROR, result.stdout.str() + result.stderr.str()
    assert "must be a positive number" in result.stderr.str()
