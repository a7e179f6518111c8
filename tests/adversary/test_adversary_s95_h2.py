"""Stop 95, h2 (an adversary of the eight routes of issue 20 and beyond): what `check --no-rerun` says of the
verdicts it did not run again, a claims path that names a device or a pipe, and a graph with symbolic sizes that the
replay refuses."""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

import stiefelsym
from stiefelsym.claims import CatalogError

FILES = Path(__file__).with_name("s95") / "h2"

def _run_cli(args):
    from click.testing import CliRunner

    from stiefelsym.cli import main
    return CliRunner().invoke(main, args, catch_exceptions=False)


def test_check_without_a_run_again_says_which_verdicts_rest_on_the_file(tmp_path):
    """A fixed-size record's verdict forged from 'fails' to 'proved' (with the evidence of a true claim's record)
    passes `check --no-rerun`, which compares digests and certificates only: its count says that the verdicts
    were not run again (it said "1 records checked, 0 rejected"); `check` without the option runs them again."""
    out = tmp_path / "rep"
    r = _run_cli(["verify", "prep", "--size", "3,2", "--method", "modular", "--report-dir", str(out)])
    assert r.exit_code == 0, r.output
    payload = json.loads((out / "results.json").read_text())
    assert [x["verdict"] for x in payload["results"]] == ["checked"]
    r = _run_cli(["check", str(out / "results.json"), "--no-rerun"])
    assert r.exit_code == 0
    assert "1 records checked, 0 rejected (digests and certificates only: the verdict of 1 fixed-size record " \
           "not run again)" in r.output, r.output


@pytest.mark.parametrize("path", ["/dev/null", "fifo"])
def test_a_claims_path_that_is_not_a_regular_file_is_named_so(tmp_path, path):
    """`verify --claims /dev/zero` (or a pipe, /dev/stdin) said "claims file not found" of a path that exists."""
    if path == "fifo":
        path = str(tmp_path / "claims.py")
        os.mkfifo(path)
    r = _run_cli(["verify", "--claims", path, "--no-report"])
    assert r.exit_code == 2 and f"claims file {path} is not a regular file" in r.output, r.output
    with pytest.raises(CatalogError, match="is not a regular file"):
        stiefelsym.load(files=path)
    missing = str(tmp_path / "missing.py")
    r = _run_cli(["verify", "--claims", missing, "--no-report"])
    assert r.exit_code == 2 and f"claims file not found: {missing}" in r.output, r.output


def test_a_symbolic_graph_refused_by_the_replay_is_named_at_every_size():
    """A thread of a claim (s95/h2/p1_python.py, h2p-thread) appended an operation to the graph traced with symbolic
    sizes after the child's own replay had passed it, racing the child's output: each sized run was an `error`
    saying that the file was traced "at the sizes the run needed only (none)"; it names the replay's refusal of
    the graph that serves every size (a finalizer that does it as the claim returns, p2_thread_graph.py, is caught
    in the child)."""
    from stiefelsym.ir import compile_claim
    from stiefelsym.run.userfile import NoGraph, TracedFunction, _graph_state
    from stiefelsym.scene import REALIZATIONS
    standard = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)

    def true(s):
        return {"r": s.X.T @ s.P + s.P.T @ s.X}
    data = json.loads(json.dumps(_graph_state(compile_claim(true, None, None, standard))))
    data["ops"].append("add")
    f = TracedFunction("true", "standard", [[None, data]], "x.py", 1)
    with pytest.raises(NoGraph, match=r"traced it with symbolic sizes \(a graph that serves every size\), and that "
                       r"graph was refused here: ReplayError: refused: a graph whose ops and arguments differ"):
        compile_claim(f, 2, 1, standard)
    res = stiefelsym.verify(files=str(FILES / "p2_thread_graph.py"), sizes=[(2, 1)], methods=["modular"], jobs=1)
    assert [r.verdict for r in res] == ["error"] and "refused when the tracer replays it" in res[0].message


@pytest.mark.parametrize("cid", ["h2f-pow-huge", "h2f-pow-diff"])
def test_a_degree_beyond_expansion_is_inconclusive_at_once_where_the_modular_method_refutes(cid):
    """(t/(t+1))^(2^40) = 0 and u^(2^62) − u^(2^62 + 2^61) = 0 (false): the exact and rational methods expanded them
    until flint failed to allocate (≈ 140 s, then `inconclusive` or `error`); their structural degree bound is read
    from degree markers before any value is written out, so both answer `inconclusive` at once, naming the bound,
    and the modular method still refutes them.  The catalog's degrees are far below the limit."""
    from stiefelsym.methods import fixed_size as fs
    claims = stiefelsym.load(files=[FILES / "f1_powers.py"], catalog=False)
    c = next(x for x in claims if x.id == cid)
    for res in (fs.run_exact(c, 2, 1, 0), fs.run_points(c, 2, 1, "rational", 0)):
        assert res.verdict == "inconclusive", res.message
        assert "structural degree bound" in res.message and str(fs.EXPANDABLE_DEGREE) in res.message
    assert fs.run_points(c, 2, 1, "modular", 0).verdict == "fails"
    small = next(x for x in claims if x.id == "h2f-pow-small")      # degree 4096: written out, refuted
    assert fs.run_exact(small, 2, 1, 0).verdict == "fails"


def test_the_degree_pass_runs_where_powers_multiply_past_the_gate(tmp_path):
    """The structural degree bound is computed before an exact run only where the graph's powers multiply to more
    than POWER_GATE (a product of exponents, so nested powers count): (x^20)^20 has 400 > 256 and is read, x^2 is not
    (its degree grows only through products, each written out by the method)."""
    from stiefelsym.ir.passes import power_exponents
    from stiefelsym.methods import fixed_size as fs
    from stiefelsym.scene import REALIZATIONS
    f = tmp_path / "nested.py"
    f.write_text(
        "from stiefelsym import claim, admissible\n"
        "@claim('nested-huge', kind='id', sizes=admissible(n_min=2, n_max=3))\n"
        "def nested(s):\n"
        "    '''False: ((t/(t+1))^2048)^1024 = 0.'''\n"
        "    t = s.tr(s.P.T @ s.P)\n"
        "    return {'r': ((t / (t + 1)) ** 2048) ** 1024}\n"
        "@claim('square', kind='id', sizes=admissible(n_min=2, n_max=3))\n"
        "def square(s):\n"
        "    '''True: (tr PᵀP)² − tr PᵀP · tr PᵀP = 0.'''\n"
        "    t = s.tr(s.P.T @ s.P)\n"
        "    return {'r': t ** 2 - t * t}\n")
    claims = {c.id: c for c in stiefelsym.load(files=[f], catalog=False)}
    cons = REALIZATIONS["standard"]
    graph = lambda c: fs._claim_graph(c.func, 2, 1, (cons.name, cons.build))
    assert power_exponents(graph(claims["nested-huge"])) == 2048 * 1024 > fs.POWER_GATE
    assert power_exponents(graph(claims["square"])) == 2 <= fs.POWER_GATE
    res = fs.run_exact(claims["nested-huge"], 2, 1, 0)
    assert res.verdict == "inconclusive" and "structural degree bound" in res.message
    assert fs.run_exact(claims["square"], 2, 1, 0).verdict == "proved"
    # the dimension-free method reads the same product before it rewrites anything (it rewrote such a power for its
    # 20 s of CPU, which every exact or auto run through the command line spent first) and still proves x^2 - x x
    from stiefelsym.methods.dimension_free import run_free
    res = run_free(claims["nested-huge"])
    assert res.verdict == "undecided" and "multiply to 2097152, beyond the 256" in res.message
    assert run_free(claims["square"]).verdict == "proved"
