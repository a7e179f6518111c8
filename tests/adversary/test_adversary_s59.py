"""Stop 59: claim code that changes a compiled graph, or the engine's state, after the tracer checked it
(tests/adversary/s59: the stop's own attacks; s59/review: the review's).  See tests/adversary/README.md."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from stiefelsym.claims import Size, load_catalog, load_claims_file
from stiefelsym.run.runner import run_one

HERE = Path(__file__).resolve().parent / "s59"
REVIEW = HERE / "review"
PASSING = ("proved", "checked", "numeric")


def _cli(path: Path, ids: list[str], method: str) -> dict[str, str]:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), *ids, "--size", "3,2",
                          "--method", method, "--jobs", "1", "--no-report", "--format", "json"],
                         capture_output=True, text=True, cwd=str(path.parent), timeout=300)
    return {r["claim"]: r["verdict"] for r in json.loads(out.stdout)["results"]}


@pytest.mark.parametrize("method", ["exact", "float"])
def test_a_file_that_puts_a_true_graph_under_its_claims_cache_keys_is_verified_on_its_own_graph(method):
    """The file, at import (and the claim, while it is traced), puts the graph of X − X under the false claim's
    keys in the graph cache of the interpreter that traces it; the child sent that graph as the claim's, and
    X = 0 was proved through the CLI (review of stop 59).  The tracing interpreter now takes no graph from a
    cache."""
    got = _cli(REVIEW / "batch1.py", ["s59r-graphs-poison-import", "s59r-graphs-poison-trace", "s59r-graphs-control"],
               method)
    assert got == dict.fromkeys(("s59r-graphs-poison-import", "s59r-graphs-poison-trace", "s59r-graphs-control"),
                                "fails"), got


def test_a_file_that_changes_the_tracers_memos_gets_error_for_its_claims():
    """The file changes, at import, a size expression the tracer hands out (2r as r): every claim traced in that
    interpreter is `error`, the true control included (the interpreter's engine is not the engine)."""
    got = _cli(HERE / "memo_poison.py", ["s59-memo-size", "s59-memo-size-control"], "exact")
    assert got == {"s59-memo-size": "error", "s59-memo-size-control": "error"}, got


def test_a_later_claim_cannot_rewrite_an_earlier_claims_graph_through_the_public_api():
    """In-process, a later claim's code took the victim's compiled graph from the public compile_claim (the
    engine's own object) and pointed its residual at X − X: X = 0 was proved, checked and numeric (review of
    stop 59).  compile_claim now hands out a copy."""
    reg = load_claims_file(str(REVIEW / "batch2.py"))
    for order in (("s59r-mutator", "s59r-victim"), ("s59r-victim", "s59r-mutator", "s59r-victim")):
        for cid in order:
            for m in ("exact", "rational", "float", "auto"):
                got = run_one(reg.get(cid), Size(3, 2), m, 0).verdict
                assert got == ("fails" if cid == "s59r-victim" else got) and (cid == "s59r-victim" or got in PASSING), \
                    (order, cid, m, got)


def test_a_users_claim_cannot_rewrite_the_catalogs_graphs_through_the_public_api():
    """The catalog and a user's file in one process: the file's claim rewrote two catalog claims' graphs, and
    both (true) failed under every method (review of stop 59)."""
    cat = load_catalog()
    reg = load_claims_file(str(REVIEW / "batch3.py"))
    run_one(reg.get("s59r-catalog-mutator"), Size(3, 2), "exact", 0)
    for cid in ("invariants-so-n", "gram-not-in-involution-with-psi"):
        for m in ("exact", "rational", "float"):
            assert run_one(cat.get(cid), Size(3, 2), m, 0).verdict in PASSING, (cid, m)


def test_sizes_set_on_the_first_graph_during_the_second_trace_do_not_reach_the_evaluated_graph():
    """The sizes of a graph are not in its digest: they are the replay's, not the first trace's, which claim
    code reached through the frames during the second trace (review of stop 59)."""
    reg = load_claims_file(str(REVIEW / "batch6.py"))
    for m in ("exact", "rational", "modular"):
        assert run_one(reg.get("s59r-sizes-lie-jacobian-p"), Size(3, 2), m, 0).verdict == "fails", m


@pytest.mark.parametrize("name", ["batch1.py", "batch4.py"])
def test_files_that_write_the_engines_private_caches_are_verified_correctly_when_loaded_isolated(name):
    """Loaded into the calling process, code that writes the engine's private graph cache (batch1 at import,
    batch4 from a thread) changes what is evaluated: that is outside what in-process loading promises (docs/
    architecture.md, "Where a claims file is trusted").  Loaded as the library's `stiefelsym.load` loads a file
    (fresh interpreters), every false claim of them fails."""
    import stiefelsym
    reg = stiefelsym.load(REVIEW / name, sizes=[(3, 2)])
    for c in reg:
        if c.id in ("s59r-graphs-poison-import", "s59r-graphs-poison-trace", "s59r-graphs-control",
                    "s59r-thread-rewrite", "s59r-thread-control"):
            for m in ("exact", "float"):
                assert run_one(c, Size(3, 2), m, 0).verdict == "fails", (name, c.id, m)


def test_a_graph_claim_with_an_edit_of_the_files_own_gets_no_passing_verdict():
    """The claim function is the engine's GraphClaim with an edit written in the file, run during the replay
    after the first inverse statement's checks, which points its division by 2 at tr(PᵀP).  The engine
    re-checks every inverse statement of the claim's dict once the dict is made: `error`, not a verdict on the
    rewritten graph (stop 59, own attempt)."""
    reg = load_claims_file(str(HERE / "graph_claim_edits.py"))
    for m in ("exact", "rational", "modular", "float"):
        res = run_one(reg.get("s59-graph-claim-edits"), Size(3, 2), m, 0)
        assert res.verdict == "error" and "divides by a number that is not a constant" in res.message, (m, res)
