"""Stop 63: the user trial's statements (tests/adversary/s63/user) and the review's files (s63/review).  See
tests/adversary/README.md, Stop 63."""
import json

import pytest

from adversary_cli import cli, HERE

USER = HERE / "s63" / "user"
REVIEW = HERE / "s63" / "review"


def _results(*args):
    run = cli("verify", *args, "--no-report", "--format", "json", "--timeout", "60", "--jobs", "2")
    assert run.returncode in (0, 1), run.stderr[-2000:]
    return json.loads(run.stdout)["results"]


@pytest.mark.parametrize("method", ["modular", pytest.param("exact", marks=pytest.mark.slow)])
def test_the_user_trials_statements_hold_and_their_twins_fail(method):
    """Eleven statements of §3, §4, §6 and §8 the catalog states otherwise or not at all (Φ acting on X and P, the
    Euclidean acceleration, the κ-family, the Manakov flow and Lax pair for B = A³, PᵀP along two flows, H∘Θ and
    (CPB), the rank of ξ ↦ [ξ, XXᵀ], the Neumann flow at r = n, SO(r)-invariant traces, a count), written by a user:
    each holds at (3,1), (4,2), (3,3), and each false twin fails where it is stated (numpy: s63/user/indep.py).  The
    twin that says the rank of ξ ↦ [ξ, XXᵀ] is r(n − r) + 1 is the one left open (a rank said too high is refuted
    only by a function-field rank, within the exact method's 5 s for it: inconclusive, never a pass)."""
    sizes = ("--size", "3,1", "--size", "4,2", "--size", "3,3", "--method", method)
    held = _results("--claims", str(USER / "claims.py"), *sizes)
    assert held and all(r["verdict"] in ("proved", "checked") for r in held), \
        [(r["claim"], r["n"], r["r"], r["verdict"]) for r in held if r["verdict"] not in ("proved", "checked")]
    twins = _results("--claims", str(USER / "negatives.py"), *sizes)
    for r in twins:
        if r["claim"] == "n63-l1-rank":
            assert r["verdict"] in ("fails", "inconclusive"), r
        elif r["claim"] in ("n63-gram-not-conserved", "n63-dual-matrix-not-invariant"):  # true "does not hold"
            assert r["verdict"] in ("proved", "checked"), r
        else:
            assert r["verdict"] == "fails", (r["claim"], r["n"], r["r"], r["verdict"], r["message"])


def test_an_integer_constant_of_any_size_is_exact(tmp_path):
    """c X − c X = 0 with c = 2¹⁵⁰⁰⁰ (4516 digits) was `error` under every method: the engine writes an integer in
    decimal (the graph's digest, the records, JSON between its processes), and Python refuses the decimal text of an
    integer above 4300 digits unless told otherwise.  The engine now lifts that limit for itself: the true claims are
    proved, and a false twin (c X − (c + 1) X = 0) fails under exact and modular."""
    held = _results("--claims", str(REVIEW / "big_constant.py"), "--method", "exact")
    assert held and all(r["verdict"] == "proved" for r in held), [(r["claim"], r["verdict"], r["message"]) for r in held]
    free = _results("--claims", str(REVIEW / "big_constant.py"), "--method", "free")
    assert all(r["verdict"] == "proved" for r in free), [(r["claim"], r["verdict"], r["message"]) for r in free]
    twin = tmp_path / "big_twin.py"
    twin.write_text("from stiefelsym import admissible, claim\nC = 2 ** 15000\n\n\n"
                    "@claim('bc-false', paper='t', kind='id', section='2', sizes=admissible(n_max=3))\n"
                    "def false(s):\n    return {'r': s.X * C - s.X * (C + 1)}\n")
    for method in ("exact", "modular"):
        rec = _results("--claims", str(twin), "--method", method, "--size", "3,2")
        assert [r["verdict"] for r in rec] == ["fails"], rec


def test_free_names_the_declaration_a_condition_r_equals_n_does_not_make():
    """A statement at r = n written with where=lambda n, r: r == n only: the dimension-free scene cannot read the
    condition, so X Xᵀ = I_n is no hypothesis and the Neumann flow's statement is undecided; the message now says
    to declare admissible(..., r_is_n=True), with which it is proved for every n."""
    rec = _results("--claims", str(USER / "claims.py"), "u63-r-equals-n", "--method", "free")
    assert rec[0]["verdict"] == "undecided" and "r_is_n=True" in rec[0]["message"], rec
    declared = _results("--claims", str(USER / "extra.py"), "u63-r-is-n", "--method", "free")
    assert declared[0]["verdict"] == "proved", declared


def test_a_negative_n_is_named_as_such():
    """--size -3,1 said "r = 1 > n = -3"; it now says that n must be at least 1 (exit 2)."""
    run = cli("verify", "la1", "--size", "-3,1", "--method", "modular")
    assert run.returncode == 2 and "n = -3, but the Stiefel variety V(n,r) needs n >= 1" in run.stderr, run.stderr


def test_the_python_apis_rerun_keeps_the_runs_budgets():
    """api.verify(..., timeout=60) gave results whose rerun command dropped the time limit (the command line's own
    lines keep it): both now add the budgets that differ from the command line's defaults, through one function."""
    from stiefelsym import verify
    res = verify(["neumann-flow"], sizes=["2,1"], methods=["modular"], timeout=60, memory=2)
    assert res[0].rerun.endswith("--timeout 60 --memory 2"), res[0].rerun
    plain = verify(["neumann-flow"], sizes=["2,1"], methods=["modular"])
    assert "--timeout" not in plain[0].rerun and "--memory" not in plain[0].rerun, plain[0].rerun


def test_a_rank_at_r_equals_n_takes_the_symbolic_cayley_inverse_of_a_linear_matrix():
    """The rank of ξ ↦ [ξ, XXᵀ] at (5,5) (0: XXᵀ = I) read entries of X, so the Cayley chart X = (I − S)(I + S)⁻¹
    was taken, and its 5x5 symbolic inverse was beyond the exact method's budget (3x3 for a symbolic matrix):
    inconclusive, while (4,4) was proved.  A matrix of polynomials of degree <= 1 (I + S, a pencil λI − A) is now
    inverted up to 6x6 (Bareiss keeps minors of degree k at step k): proved at (5,5) and (6,6), and the twin that says
    rank 1 fails there; a 7x7 inverse stays beyond the budget (inconclusive, never a pass)."""
    held = _results("--claims", str(USER / "claims.py"), "u63-l1-rank", "--size", "5,5", "--size", "6,6",
                    "--method", "exact")
    assert [r["verdict"] for r in held] == ["proved", "proved"], [(r["verdict"], r["message"]) for r in held]
    twin = _results("--claims", str(USER / "negatives.py"), "n63-l1-rank", "--size", "5,5", "--size", "6,6",
                    "--method", "exact")
    assert [r["verdict"] for r in twin] == ["fails", "fails"], [(r["verdict"], r["message"]) for r in twin]
    beyond = _results("--claims", str(USER / "claims.py"), "u63-l1-rank", "--size", "7,7", "--method", "exact")
    assert beyond[0]["verdict"] == "inconclusive" and "7x7 linear solve" in beyond[0]["message"], beyond


@pytest.mark.parametrize("method", ["exact", "modular", "float", "ball"])
def test_false_statements_with_constants_outside_float64_are_never_passed(method):
    """Own attempt once integers of any size are exact: (2¹⁵⁰⁰⁰ + 1)X − 2¹⁵⁰⁰⁰X = 0, 3⁻⁹⁰⁰⁰X = 0 (0 in float64),
    a trace times 3⁻⁹⁰⁰⁰ off by its square, ((c + 1)/c)X − X = 0: float64 overflows or underflows on each.  Exact and
    modular refute them all; float and ball refute them or stay inconclusive (a float `numeric` is confirmed at
    exact points mod p), never pass."""
    rec = _results("--claims", str(HERE / "s63" / "own" / "huge_false.py"), "--method", method)
    assert len(rec) == 4
    for r in rec:
        allowed = ("fails",) if method in ("exact", "modular") else ("fails", "inconclusive")
        assert r["verdict"] in allowed, (r["claim"], r["verdict"], r["message"])


@pytest.mark.parametrize("field,value", [("false_pass_bound", 10 ** 400), ("seconds", 10 ** 4000)])
def test_an_integer_beyond_floats_range_in_a_record_is_refused_in_one_line(tmp_path, field, value):
    """The second review: a record's false_pass_bound or seconds set to an integer of 400 or 4000 digits (below the
    4300 digits a file may have) reached math.isfinite, whose OverflowError was a traceback of `check` and `report`.
    Such a number is now refused as the field's other bad values are (inf, nan, -1): one line, exit 2 for report,
    the record rejected by check."""
    run = cli("verify", "--claims", str(HERE / "s63" / "review2" / "recs.py"), "--method", "modular", "--jobs", "1",
              "--format", "json", "--no-report", "--timeout", "60")
    doc = json.loads(run.stdout)
    doc["results"][0][field] = value
    path = tmp_path / "edited.json"
    path.write_text(json.dumps(doc))
    report = cli("report", "--results", str(path), "--report-dir", str(tmp_path / "rep"))
    assert report.returncode == 2 and "Traceback" not in report.stderr, report.stderr[-1500:]
    assert f"{field} is 1000" in report.stderr, report.stderr
    check = cli("check", str(path), "--no-rerun")
    out = check.stdout + check.stderr
    assert check.returncode == 1 and "Traceback" not in out and f"malformed: {field} is 1000" in out, out[-1500:]


def test_a_constant_outside_float64_is_named_by_its_magnitude(tmp_path):
    """X·2⁻¹⁵⁰⁰⁰ = 0 (false) fails under float with an exact witness, but its reason printed the constant's 4516
    digits (a 31 kB record); it now gives its magnitude and digit count, as a witness's value does."""
    f = tmp_path / "tiny.py"
    f.write_text("from fractions import Fraction\nfrom stiefelsym import admissible, claim\n\n\n"
                 "@claim('tiny-x', paper='t', kind='id', section='2', sizes=admissible(n_max=3, n_min=3, r_min=2, "
                 "r_max=2))\ndef tiny(s):\n    return {'r': s.X * Fraction(1, 2 ** 15000)}\n")
    rec = _results("--claims", str(f), "--method", "float")[0]
    assert rec["verdict"] == "fails" and "the constant 3.5487e-4516 (a rational of 1/4516 digits" in rec["message"]
    assert len(json.dumps(rec)) < 10_000


def test_the_command_lines_budget_default_is_the_one_a_rerun_leaves_out():
    """rerun.budget_options leaves out a budget equal to the cost model's default; the command line has a default of
    its own (it does not import the cost model at start-up): the two must be one value, or a rerun would drop a
    budget the run had."""
    from stiefelsym import cli
    from stiefelsym.methods.costmodel import DEFAULT_BUDGET
    from stiefelsym.run.rerun import budget_options
    assert cli.DEFAULT_BUDGET == DEFAULT_BUDGET
    assert budget_options(300.0, DEFAULT_BUDGET, 4.0) == []
    assert budget_options(300.0, 60.0, 4.0) == ["--budget", "60"]
