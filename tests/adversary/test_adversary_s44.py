"""Round 19 (tests/adversary/README.md, the "Round 19" table): the exact method's fused trace of a product (tr(x @ y)
computed as sum_ik x_ik y_ki when the product is read by the trace alone: ``ir.evaluate._trace_products``,
``Mat._trace_product``, ``PolyBackend.trace_matmul``), and the seed a proof by a generic rank at a drawn point
carries (``methods.fixed_size._RandomizedRank.drew``).

No hole was found.  The fused trace does the product's and the trace's checks and joins of spaces (an untyped
matrix meeting R^n at the product or at the trace only is still a recorded look at coordinates, so the equivariant
chart does not prove a coordinate statement), reads every entry of both factors (a statement whose only nonzero
part is an off-diagonal entry of a factor fails), and keeps the factors' denominators (the resolvent, an
inverse).  The exact method on its flint backend (fused) and on symengine (``STIEFELSYM_EXACT_BACKEND=symengine``:
no ``trace_matmul``, never fused) give the same verdicts, and so does the mutation analysis (its shared node
values included).

Every run is the CLI in a fresh process (claims file ``s44_trace_product_probes.py``)."""
import copy
import json
import os

import pytest

from adversary_cli import HERE, PASSING, cli

PROBES = str(HERE / "s44_trace_product_probes.py")
TRUE = ("adv-s44-xtx-xxt", "adv-s44-xtx-r", "adv-s44-diag-sum", "adv-s44-diag-sum-n", "adv-s44-skew-pairing",
        "adv-s44-resolvent", "adv-s44-resolvent-diagonal", "adv-s44-inverse", "adv-s44-scalar", "adv-s44-block",
        "adv-s44-read-twice", "adv-s44-derivative", "adv-s44-bracket", "adv-s44-untyped-pair")
FALSE = ("adv-s44-xxt-n", "adv-s44-diag-sum-off", "adv-s44-sym-pairing", "adv-s44-unit-entry",
         "adv-s44-untyped-product", "adv-s44-untyped-trace", "adv-s44-resolvent-off", "adv-s44-inverse-off",
         "adv-s44-scalar-off", "adv-s44-derivative-off", "adv-s44-transpose-off")
#: true at r = n (tr XXᵀ = n, tr XXᵀA = tr A; (R X Xᵀ)₁₀ = 0), false for r < n
TRUE_AT_R_EQUALS_N = ("adv-s44-xxt-n", "adv-s44-transpose-off", "adv-s44-resolvent-off")


def _records(*args, env=None):
    """The records of one `stiefelsym verify --format json` run of the probes (the dimension-free ones left out)."""
    run = cli("verify", "--claims", PROBES, *args, "--format", "json", "--jobs", "1", env=env)
    try:
        recs = json.loads(run.stdout)["results"]
    except ValueError:
        raise AssertionError((run.stdout[-2000:], run.stderr[-2000:])) from None
    return [r for r in recs if r["method"] != "free"], run


def _truth(rec):
    """Whether the record's statement is true at its size (the probes' docstrings)."""
    if rec["claim"] in TRUE_AT_R_EQUALS_N:
        return rec["n"] == rec["r"]
    return rec["claim"] in TRUE


@pytest.mark.parametrize("method", ["exact", "modular", "rational", "auto"])
def test_fused_traces_give_the_truth_under_every_method(method):
    """Every true probe proved (exact, auto) or checked (modular, rational), every false one refuted, at every
    admitted size up to n = 3 (those true at r = n only proved there); the exact method's runs fuse the traces (auto takes exact at these sizes)."""
    recs, run = _records(*TRUE, *FALSE, "--method", method, "--max-n", "3")
    # every admitted size up to n = 3: (2,1), (2,2), (3,1), (3,2), (3,3) of most, (3,2) or (3,1), (3,2) of some
    assert len(recs) >= 3 * len(TRUE + FALSE), (len(recs), run.stderr[-2000:])
    for rec in recs:
        where = (rec["claim"], rec["n"], rec["r"], rec["method"], rec["message"][:300])
        if _truth(rec):
            want = ("proved",) if method in ("exact", "auto") else ("checked",)
            assert rec["verdict"] in want, where
        else:
            assert rec["verdict"] == "fails", where


def test_at_r_equals_n_the_statements_true_there_are_proved():
    """tr XXᵀ = tr Iₙ, tr XXᵀA = tr A and (R X Xᵀ)₁₀ = 0 hold at r = n = 3 (X orthogonal): proved; the false
    ones of every r still fail."""
    ids = TRUE_AT_R_EQUALS_N + ("adv-s44-scalar-off", "adv-s44-derivative-off", "adv-s44-xtx-xxt")
    recs, run = _records(*ids, "--method", "exact", "--size", "3,3")
    got = {r["claim"]: r["verdict"] for r in recs}
    assert got == {**{c: "proved" for c in TRUE_AT_R_EQUALS_N}, "adv-s44-scalar-off": "fails",
                   "adv-s44-derivative-off": "fails", "adv-s44-xtx-xxt": "proved"}, (got, run.stderr[-2000:])


def test_an_untyped_matrix_meeting_R_n_in_a_fused_trace_keeps_the_coordinate_chart():
    """tr(E XXᵀ) − 1 = (XXᵀ)₀₀ − 1 and tr(B Xᵀ) − 1 = X₀₀ − 1 (E, B untyped constants) vanish at X = [I; 0], the
    equivariant chart's point: the untyped join (at the product, and at the trace only for B) is recorded by
    the fused trace as by the product, and the residual is in the Cayley chart's coordinates (K_i,j)."""
    recs, run = _records("adv-s44-untyped-product", "adv-s44-untyped-trace", "--method", "exact",
                         "--size", "3,1", "--size", "3,2")
    assert len(recs) == 4, (run.stdout[-2000:], run.stderr[-2000:])
    for rec in recs:
        assert rec["verdict"] == "fails", (rec["claim"], rec["n"], rec["r"], rec["message"])
        assert "K_" in (rec.get("residual") or ""), (rec["claim"], rec.get("residual"))


def test_sizes_or_spaces_that_do_not_fit_are_an_error_under_every_method():
    """The trace of the n x r product (XXᵀ)X, and XP at r = n (R^r joined with R^n): refused, never a verdict."""
    for size, cid in (("3,2", "adv-s44-nonsquare"), ("3,3", "adv-s44-spaces")):
        recs, run = _records(cid, "--method", "exact", "--method", "modular", "--method", "rational",
                             "--method", "auto", "--size", size)
        assert len(recs) == 4, (cid, run.stdout[-2000:], run.stderr[-2000:])
        for rec in recs:
            assert rec["verdict"] == "error", (cid, rec["method"], rec["verdict"], rec["message"])
            assert "Traceback" not in rec["message"], rec["message"]


def _unfused():
    """The environment of a run whose exact method computes in symengine (no trace_matmul: nothing fused)."""
    env = dict(os.environ)
    env["STIEFELSYM_EXACT_BACKEND"] = "symengine"
    return env


def test_fused_and_unfused_exact_methods_agree():
    """The exact method on flint (fused traces) and on symengine (none fused): the same verdict for every probe at
    every admitted size up to n = 3."""
    args = (*TRUE, *FALSE, "--method", "exact", "--max-n", "3")
    fused, run = _records(*args)
    plain, run2 = _records(*args, env=_unfused())
    a = {(r["claim"], r["n"], r["r"]): r["verdict"] for r in fused}
    b = {(r["claim"], r["n"], r["r"]): r["verdict"] for r in plain}
    assert a == b and len(a) > 50, ({k: (a.get(k), b.get(k)) for k in set(a) | set(b) if a.get(k) != b.get(k)},
                                    run.stderr[-1000:], run2.stderr[-1000:])


def _mutants(cid, env=None):
    run = cli("mutate", cid, "--claims", PROBES, "--method", "exact", "--size", "3,2", "--jobs", "1", env=env)
    lines = sorted(line.split(" [exact")[0].strip() for line in run.stdout.splitlines()
                   if " killed: " in line or " equivalent: " in line or " survived: " in line)
    return run, lines


@pytest.mark.parametrize("cid", ["adv-s44-diag-sum", "adv-s44-skew-pairing", "adv-s44-untyped-pair"])
def test_mutants_of_fused_traces_are_decided_as_without_fusion(cid):
    """The mutation analysis (node values shared between the mutants' graphs, the fused program): 0 survivors,
    and the very same mutants killed and equivalent (still true: proved) as without fusion, so no false mutant
    is passed off as an equivalent one."""
    run, fused = _mutants(cid)
    assert "0 survivors" in run.stdout, (run.stdout[-3000:], run.stderr[-2000:])
    _run2, plain = _mutants(cid, env=_unfused())
    assert fused == plain and fused, (fused, plain)
    assert any(" equivalent: " in line for line in fused) and any(" killed: " in line for line in fused)
    if cid == "adv-s44-untyped-pair":
        # tr(E XXᵀ) − tr(E) = (XXᵀ)₀₀ − 1: 0 at X = [I; 0], refused in the Cayley chart the untyped join chose
        dropped = [line for line in fused if "the second term dropped" in line and "Iₙ − XXᵀ" in line]
        assert dropped and all(" killed: " in line for line in dropped), fused


# -- the seed of a proof by a generic rank at a drawn point ------------------------------------------------------

DIM = ("adjoint-orbit-dimension", "pencil-leaf-dimension")


def test_a_dimension_proof_prints_its_seed_and_another_seed_proves_it_too():
    """`verify CLAIM --method exact` on a dimension claim: proved, with the seed on the verdict line; --seed 5:
    proved, with seed 5."""
    for seed in (None, 5):
        extra = () if seed is None else ("--seed", str(seed))
        run = cli("verify", *DIM, "--method", "exact", "--size", "4,2", "--size", "3,3", *extra, "--jobs", "1")
        lines = [line for line in run.stdout.splitlines() if line.startswith(DIM)]
        assert len(lines) == 4, (run.stdout[-2000:], run.stderr[-2000:])
        for line in lines:
            assert ": proved (" in line and f"seed {seed or 0})" in line, line


def test_check_accepts_the_seeded_dimension_records_and_rejects_a_seed_edited(tmp_path):
    """A `verify --report-dir` run of two dimension claims at --max-n 4: `check` accepts it; a record whose seed is
    removed or changed is rejected (its rerun command and its evidence no longer match a run again)."""
    out = tmp_path / "rep"
    run = cli("verify", *DIM, "--method", "exact", "--max-n", "4", "--report-dir", str(out), "--jobs", "1")
    assert (out / "results.json").exists(), (run.stdout[-2000:], run.stderr[-2000:])
    ok = cli("check", str(out / "results.json"))
    assert "0 rejected" in ok.stdout + ok.stderr, (ok.stdout[-2000:], ok.stderr[-2000:])
    data = json.loads((out / "results.json").read_text())
    recs = data["results"]
    assert len(recs) == 20 and all(r["verdict"] == "proved" and r["seed"] == 0 for r in recs), \
        [(r["claim"], r["n"], r["r"], r["verdict"], r["seed"]) for r in recs]
    k = next(i for i, r in enumerate(recs) if (r["claim"], r["n"], r["r"]) == ("adjoint-orbit-dimension", 4, 2))
    for name, seed in (("none", None), ("seven", 7)):
        e = copy.deepcopy(data)
        e["results"][k]["seed"] = seed
        path = out / f"edited-{name}.json"
        path.write_text(json.dumps(e))
        res = cli("check", str(path))
        assert "REJECTED adjoint-orbit-dimension (4,2) exact" in res.stdout + res.stderr, \
            (name, res.stdout[-2000:], res.stderr[-2000:])


def test_no_passing_verdict_of_a_false_probe_under_auto_at_a_larger_size():
    """auto at (4,2): the false probes admitted there are refuted, never passed."""
    ids = [c for c in FALSE if not c.startswith("adv-s44-untyped")]      # those two are of n = 3 only
    recs, run = _records(*ids, "--method", "auto", "--size", "4,2")
    assert recs, run.stderr[-2000:]
    for rec in recs:
        assert rec["verdict"] not in PASSING, (rec["claim"], rec["method"], rec["verdict"])
        assert rec["verdict"] == "fails", (rec["claim"], rec["method"], rec["verdict"], rec["message"][:300])
