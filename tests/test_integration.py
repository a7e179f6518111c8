"""Installs and runs like a library: the public verify() API, Jupyter displays, the sympy residual,
the pytest plugin, the catalog's package name, thread-safe loading and the friction of the command
line (each a one-line error with exit status 2, or working)."""
import os
import subprocess
import sys
import threading

import pytest

import stiefelsym
from stiefelsym import claims as C
from stiefelsym.results import ResultList

pytest_plugins = ["pytester"]

WRONG = '''from stiefelsym import claim

@claim("prep", paper="prep", kind="id", sizes=[(3, 1), (4, 2)])
def wrong_sign(s):
    """A deliberately wrong sign: X + X vanishes."""
    return {"x": s.X + s.X}


@claim("right", paper="prep", kind="id", sizes=[(3, 2)])
def right(s):
    """X - X vanishes."""
    return {"x": s.X - s.X}
'''


@pytest.fixture
def wrong_file(tmp_path):
    f = tmp_path / "my_claims.py"
    f.write_text(WRONG)
    return f


def _env():
    return {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}


# --------------------------------------------------------------------------- verify() and displays

def test_verify_returns_result_records(wrong_file):
    res = stiefelsym.verify(files=wrong_file, methods=["modular", "exact"])
    assert isinstance(res, ResultList) and not res.ok
    assert [(r.claim, r.n, r.r, r.method, r.verdict) for r in res] == [
        ("prep", 3, 1, "modular", "fails"), ("prep", 4, 2, "modular", "fails"),
        ("prep", 3, 1, "exact", "fails"), ("prep", 4, 2, "exact", "fails"),
        ("right", 3, 2, "modular", "checked"), ("right", 3, 2, "exact", "proved")]
    assert [r.claim for r in res.unexpected] == ["prep"] * 4
    assert "summary: 2 claims, 6 runs" in res.summary()


def test_verify_names_catalog_claims_and_refuses_bad_input():
    res = stiefelsym.verify("euclidean-flow", sizes=[(3, 1)], methods="modular")
    assert res.ok and [r.verdict for r in res] == ["checked"]
    with pytest.raises(KeyError, match="unknown claim"):
        stiefelsym.verify("no-such-claim", sizes=[(3, 1)])
    with pytest.raises(ValueError, match="needs r <= n"):
        stiefelsym.verify("euclidean-flow", sizes=[(1, 2)])
    with pytest.raises(ValueError, match="memory budget"):
        stiefelsym.verify("euclidean-flow", sizes=[(100000, 2)], methods="modular")


def test_displays_reuse_the_report_renderers(wrong_file):
    res = stiefelsym.verify(files=wrong_file, methods=["exact"])
    md = res._repr_markdown_()
    assert "summary: 2 claims" in md and "| size (n,r) | method | verdict |" in md
    assert "**fails** (UNEXPECTED)" in md and "Rerun:" in md
    assert res._repr_latex_().startswith("$$\\begin{array}") and "fails" in res._repr_latex_()
    assert "prep[n=3,r=1]-exact" in res[0]._repr_markdown_()
    c = stiefelsym.load_claims_file(wrong_file).get("prep")
    assert c._repr_markdown_().startswith("**prep** (6) §5 [prep]") and "only (3,1), (4,2)" in c._repr_markdown_()
    cat = stiefelsym.load_catalog().get("euclidean-flow")
    assert "\\dot X=P" in cat._repr_markdown_() and cat._repr_latex_().startswith("$$")


def test_residual_sympy(wrong_file):
    import sympy
    res = stiefelsym.verify("prep", files=wrong_file, sizes=[(3, 1)], methods=["exact", "modular"])
    exact, modular = res
    e = exact.residual_sympy()
    assert isinstance(e, sympy.Expr) and e != 0
    from stiefelsym.reports.notebook import _sympy_text
    W13, W23, W14, W24 = (sympy.Symbol(x) for x in ("W_1,3", "W_2,3", "W_1,4", "W_2,4"))
    assert _sympy_text("-4*W_1,3*W_2,3 - 4*W_1,4*W_2,4") == -4 * W13 * W23 - 4 * W14 * W24
    assert _sympy_text("(A_1,1*lambda - 1)/(A_1,1)") == (sympy.Symbol("A_1,1") * sympy.Symbol("lambda") - 1) \
        / sympy.Symbol("A_1,1")
    m = modular.residual_sympy()
    assert isinstance(m, sympy.Integer) and 0 < m < modular.witness["prime"]
    ok = stiefelsym.verify("right", files=wrong_file, methods=["modular"])[0]
    with pytest.raises(ValueError, match="no residual witness"):
        ok.residual_sympy()


# --------------------------------------------------------------------------- claims and loading

def test_sizes_as_a_list_of_pairs(tmp_path, run):
    f = tmp_path / "sz.py"
    f.write_text("from stiefelsym import claim\n@claim('sz', paper='x', kind='id', sizes=[(3, 2)])\n"
                 "def f(s):\n    \"\"\"Zero.\"\"\"\n    return {'z': s.X - s.X}\n")
    for args in (("list",), ("show", "sz"), ("verify", "--no-report")):
        out = run(*args, "--claims", str(f))
        assert out.exit_code == 0, out.output
    out = run("verify", "sz", "--size", "4,2", "--claims", str(f), "--no-report")
    assert out.exit_code == 2 and "only (3,2)" in out.output
    f.write_text(f.read_text().replace("[(3, 2)]", "[(2, 3)]"))
    out = run("list", "--claims", str(f))
    assert out.exit_code == 2 and "1 <= r <= n" in out.output and "Traceback" not in out.output


def test_catalog_loading_is_thread_safe():
    ids = []

    def load():
        ids.append(C.load_catalog().ids())
    threads = [threading.Thread(target=load) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(ids) == 4 and all(x == ids[0] for x in ids) and len(ids[0]) > 50


def test_the_catalog_is_stiefelsym_proofs_and_a_stray_proofs_folder_changes_nothing(tmp_path):
    (tmp_path / "proofs").mkdir()
    (tmp_path / "proofs" / "__init__.py").write_text("MODULES = ()\n")
    code = ("import stiefelsym.claims as c, sys; reg = c.load_catalog(); "
            "print(len(reg), next(iter(reg)).source.split('.')[0], 'proofs' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=_env(), capture_output=True,
                         text=True, check=True)
    n, top, stray = out.stdout.split()
    assert int(n) > 50 and top == "stiefelsym" and stray == "False"
    listed = subprocess.run([sys.executable, "-m", "stiefelsym", "list"], cwd=tmp_path, env=_env(),
                            capture_output=True, text=True)
    assert listed.returncode == 0 and len(listed.stdout.splitlines()) == int(n) + 1


# --------------------------------------------------------------------------- friction

def test_claims_directory(tmp_path, wrong_file, run):
    out = run("list", "--claims", str(tmp_path))
    assert out.exit_code == 0 and "prep" in out.output and "right" in out.output
    empty = tmp_path / "empty"
    empty.mkdir()
    out = run("verify", "--claims", str(empty), "--no-report")
    assert out.exit_code == 2 and "holds no .py file" in out.output


def test_a_user_claim_with_a_catalog_id_is_warned_about(tmp_path, run):
    f = tmp_path / "dup.py"
    f.write_text(WRONG.replace('"right"', '"euclidean-flow"'))
    out = run("verify", "euclidean-flow", "--claims", str(f), "--method", "modular", "--no-report")
    assert "has the id of a catalog claim" in out.output


def test_report_of_another_file_is_one_line(tmp_path, run):
    f = tmp_path / "other.json"
    f.write_text('{"results": [{"claim": "x"}]}')
    out = run("report", "--results", str(f))
    assert out.exit_code == 2 and "lacks" in out.output and "Traceback" not in out.output
    f.write_text('[1, 2]')
    out = run("report", "--results", str(f))
    assert out.exit_code == 2 and "its top level is a JSON array" in out.output


def test_a_size_beyond_the_memory_budget_is_refused_up_front(run):
    out = run("verify", "euclidean-flow", "--size", "100000,2", "--budget", "1", "--no-report")
    assert out.exit_code == 2 and "memory budget" in out.output


def test_auto_falling_back_for_lack_of_memory_says_so():
    from stiefelsym.cli import downgrade_note
    from stiefelsym.results import Result
    r = Result("c", ["x"], "2", "id", "t", "", 9, 3, "modular", "checked", True, 1.0, 0,
               message="exact: the symbolic computation exceeded the memory budget")
    assert "ran out of memory (--memory 0.5 GiB)" in downgrade_note(r, 0.5)
    r.message = ""
    assert downgrade_note(r, 0.5) is None


def test_speed_without_matplotlib_stops_at_once(run, monkeypatch):
    import importlib.util
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "matplotlib" else real(name, *a))
    out = run("speed", "--quick")
    assert out.exit_code == 2 and "pip install 'stiefelsym[plots]'" in out.output


def test_a_run_of_no_claims_exits_2(tmp_path, run):
    f = tmp_path / "none.py"
    f.write_text("from stiefelsym import claim\n")
    out = run("verify", "--claims", str(f), "--no-report")
    assert out.exit_code == 2


def test_the_users_cost_model_goes_to_the_user_cache(tmp_path, monkeypatch):
    from stiefelsym.methods import costmodel
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv(costmodel.MODEL_ENV, raising=False)
    package = costmodel.MODEL_FILE.read_bytes()
    assert costmodel.model_file() == costmodel.MODEL_FILE
    saved = costmodel.save({"note": "mine"})
    assert saved == tmp_path / "stiefelsym" / "costmodel.json" == costmodel.model_file()
    assert costmodel.MODEL_FILE.read_bytes() == package


# --------------------------------------------------------------------------- the pytest plugin

def test_pytest_plugin_items_failures_k_and_junit(pytester, wrong_file):
    pytester.makepyfile(my_claims=WRONG)
    result = pytester.runpytest_subprocess("--stiefelsym", "my_claims.py", "--stiefelsym-method", "modular",
                                           "-p", "no:cacheprovider", "--junitxml=out.xml", "-v")
    result.assert_outcomes(passed=1, failed=2)
    result.stdout.fnmatch_lines(["*my_claims.py::prep[[]n=3,r=1[]]-modular FAILED*",
                                 "*my_claims.py::right[[]n=3,r=2[]]-modular PASSED*",
                                 "*witness entry: x[[]1,1[]]*",
                                 "*rerun: stiefelsym verify prep --size 3,1 --method modular --seed 0 --claims *"])
    assert (pytester.path / "out.xml").read_text().count("<testcase") == 3
    result = pytester.runpytest_subprocess("--stiefelsym", "my_claims.py", "--stiefelsym-method", "modular",
                                           "-p", "no:cacheprovider", "-k", "right")
    result.assert_outcomes(passed=1, deselected=2)


def test_pytest_plugin_with_xdist_and_the_catalog(pytester):
    pytest.importorskip("xdist")
    result = pytester.runpytest_subprocess("--stiefelsym", "--pyargs", "stiefelsym.proofs", "-p", "no:cacheprovider",
                                           "--stiefelsym-method", "modular", "--stiefelsym-size", "3,1",
                                           "-k", "euclidean-flow or normal-flow", "-n", "2")
    outcomes = result.parseoutcomes()
    assert outcomes.get("passed", 0) >= 2 and not outcomes.get("failed") and not outcomes.get("errors")
