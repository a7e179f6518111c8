"""Round 18 (tests/adversary/README.md, the "Round 18" table): the kernel certificate of a generic rank,
``Rank(M, k, kernel=K)``, and the exact method's point values evaluated in flint (``PolyBackend.values_at``).

The certificate is as strong as the chart it is checked on and no stronger: M K = 0 in the chart's field and rank K
= d at an exact point bound the generic rank of M on that chart, and every chart the exact method takes for a rank
already had to give M's generic rank on T*V.  So kernels that vanish against M on one component of O(n), at the
chart X = I only, or at another point of T*V prove nothing false; a kernel with a pole along a component is an
error; a kernel of too few vectors, or a stale one (a mutant of M), is not used.  Two routes were found and closed:

* a kernel that is not a matrix with as many rows as M has columns but that the trace cannot see as such (a flow,
  a value of unknown kind; Xᵀ of r rows traced with symbolic sizes) crashed the exact method or was dropped by it,
  and the point methods ignored it: now an error under every method (``ir.evaluate._rank``);
* ``values_at`` read a scalar of another field's ring (``_RF``) with this ring's variable indices and denominator
  atoms (the flint contexts are shared by size): such an entry now goes through its own expression.  No claim
  was found to reach it; the test is at the backend's level.

Every run is the CLI in a fresh process (claims file ``s43_kernel_probes.py``)."""
import copy
import json

import numpy as np
import pytest

from adversary_cli import HERE, PASSING, cli

PROBES = str(HERE / "s43_kernel_probes.py")
FALSE = ("adv-s43-component-kernel", "adv-s43-component-kernel-scaled", "adv-s43-component-kernel-upper",
         "adv-s43-rotation-kernel", "adv-s43-untyped-join-kernel", "adv-s43-own-columns-false",
         "adv-s43-rank-too-high", "adv-s43-other-point-kernel-false")
TRUE = ("adv-s43-untyped-join-kernel-true", "adv-s43-own-columns", "adv-s43-special-row",
        "adv-s43-other-point-kernel", "adv-s43-cross-kernel")
MALFORMED = ("adv-s43-kernel-flow", "adv-s43-kernel-rows-r", "adv-s43-every-point-by-setattr")


def _records(*args):
    """The records of one `stiefelsym verify --format json` run of the probes."""
    run = cli("verify", "--claims", PROBES, *args, "--format", "json", "--jobs", "1")
    try:
        return json.loads(run.stdout)["results"], run
    except ValueError:
        raise AssertionError((run.stdout[-2000:], run.stderr[-2000:])) from None


def _detail(rec):
    return " | ".join(c.get("detail") or "" for c in rec.get("checks") or [])


def test_kernels_of_one_component_one_chart_point_or_too_few_vectors_never_pass():
    """r = n: [[det X − 1]] with the kernel 1 (a kernel on det X = 1 only), diag(det X + 1, 1), the kernel e₂ of a
    rank printed 1 where det X = 1 makes it 0, XᵀY + YᵀX − tr(XᵀY) I with the kernel I (0 where XᵀY is a
    rotation); X − Xᵀ through an untyped I₃ with the kernel I₃ (0 at X = I); a matrix N with N N != 0 as its own
    kernel; a printed rank above the kernel's bound; two kernel vectors that are one.  Every method refutes or
    leaves undecided; the exact method refutes each (on the other component, at a point, or by the kernel's own
    bound, "certain")."""
    recs, run = _records(*FALSE, "--method", "exact", "--method", "modular", "--method", "auto")
    # 3 claims at (2,2), (3,3) and 5 at one size each, under 3 methods (auto records the method it chose)
    assert len([r for r in recs if r["method"] != "free"]) == 3 * (3 * 2 + 5), (run.stdout[-2000:], run.stderr[-2000:])
    for rec in recs:
        assert rec["verdict"] not in PASSING, (rec["claim"], rec["n"], rec["r"], rec["method"], _detail(rec))
        if rec["method"] == "exact":
            assert rec["verdict"] == "fails", (rec["claim"], rec["n"], rec["r"], rec["message"], _detail(rec))
    too_high = [r for r in recs if r["claim"] == "adv-s43-rank-too-high" and r["method"] == "exact"]
    assert too_high and all("so rank <= 3 − 1 = 2" in _detail(r) and "certain" in _detail(r) for r in too_high)


def test_true_ranks_are_proved_two_sided_by_their_kernels():
    """The axial vector of a skew matrix (through an untyped I₃ at r = n = 3, or x × p from the entries of X and P),
    a nilpotent matrix as its own kernel, a row x − x, the axial vector at the point (X, 2P): proved by exact with
    the kernel's bound in the detail, checked by modular (which does not use kernels)."""
    recs, run = _records(*TRUE, "--method", "exact", "--method", "modular")
    assert len(recs) == 2 * len(TRUE), (run.stdout[-2000:], run.stderr[-2000:])
    for rec in recs:
        want = "proved" if rec["method"] == "exact" else "checked"
        assert rec["verdict"] == want, (rec["claim"], rec["method"], rec["message"], _detail(rec))
        if rec["method"] == "exact":
            assert "of the claim, M K = 0 identically in the chart" in _detail(rec), _detail(rec)
            assert "two-sided" in _detail(rec)


def test_a_kernel_with_a_pole_along_a_component_is_never_passed():
    """1/(det X + 1) at r = n is undefined on the whole component det X = −1: an error of the exact method, the
    point methods inconclusive."""
    recs, run = _records("adv-s43-component-pole", "--method", "exact", "--method", "modular")
    assert len(recs) == 4, (run.stdout[-2000:], run.stderr[-2000:])
    for rec in recs:
        assert rec["verdict"] not in PASSING, (rec["n"], rec["method"], rec["verdict"])
        if rec["method"] == "exact":
            assert rec["verdict"] == "error", (rec["n"], rec["message"])


def test_a_kernel_that_is_not_a_matrix_of_the_right_rows_is_an_error_under_every_method():
    """A flow as the kernel (a value of unknown kind, accepted by the trace), Xᵀ (r rows for n columns, traced with
    symbolic sizes, where the trace cannot compare them), and a kernel kept on a rank switched to every point after
    it was made.  Before: the exact method crashed on the flow (AttributeError), dropped Xᵀ ("not used") and
    proved the rank, and the point methods ignored both; now each is an error wherever it is evaluated.  The rank
    switched to every point is refused by the trace itself (it was an exception of the replay at the size)."""
    recs, run = _records(*MALFORMED, "--method", "exact", "--method", "modular", "--method", "rational",
                         "--method", "auto")
    fixed = [r for r in recs if r["method"] != "free"]
    assert len(fixed) == 4 * len(MALFORMED), (run.stdout[-2000:], run.stderr[-2000:])
    for rec in recs:
        assert rec["verdict"] not in PASSING, (rec["claim"], rec["method"], rec["verdict"])
    for rec in fixed:
        assert rec["verdict"] == "error", (rec["claim"], rec["method"], rec["verdict"], rec["message"])
    words = {r["claim"]: r["message"] for r in fixed if r["method"] == "exact"}
    assert "the kernel must be a matrix of the scene" in words["adv-s43-kernel-flow"], words
    assert "the kernel has 1 rows and the matrix 3 columns" in words["adv-s43-kernel-rows-r"], words
    # refused by the trace (before: an exception of the replay at the size, reported as "NoGraph")
    assert "refused: Rank: a kernel certifies a generic rank" in words["adv-s43-every-point-by-setattr"], words


def test_check_rejects_a_kernel_record_grafted_or_edited(tmp_path):
    """A record proved by the kernel is re-derived by `check`: its certificate grafted onto a record whose kernel
    was not used, or its rank of K edited, is rejected; the file as written is accepted."""
    out = tmp_path / "rep"
    run = cli("verify", "adv-s43-cross-kernel", "adv-s43-component-kernel-upper", "--claims", PROBES,
              "--method", "exact", "--report-dir", str(out), "--jobs", "1")
    assert (out / "results.json").exists(), (run.stdout[-2000:], run.stderr[-2000:])
    ok = cli("check", str(out / "results.json"))
    assert "0 rejected" in ok.stdout + ok.stderr, (ok.stdout[-2000:], ok.stderr[-2000:])
    data = json.loads((out / "results.json").read_text())
    proved = next(r for r in data["results"] if r["claim"] == "adv-s43-cross-kernel")
    assert proved["verdict"] == "proved" and "of the claim, M K = 0 identically" in proved["certificate"]
    for edit in ("graft", "rank"):
        e = copy.deepcopy(data)
        if edit == "graft":
            other = next(r for r in e["results"] if r["claim"] == "adv-s43-component-kernel-upper")
            other["verdict"], other["certificate"] = "proved", proved["certificate"]
            other["checks"] = copy.deepcopy(proved["checks"])
        else:
            rec = next(r for r in e["results"] if r["claim"] == "adv-s43-cross-kernel")
            rec["certificate"] = rec["certificate"].replace("rank K = 1", "rank K = 2")
            rec["checks"][0]["detail"] = rec["checks"][0]["detail"].replace("rank K = 1", "rank K = 2")
        path = out / f"edited-{edit}.json"
        path.write_text(json.dumps(e))
        res = cli("check", str(path))
        assert "REJECTED" in res.stdout + res.stderr, (edit, res.stdout[-2000:], res.stderr[-2000:])


def test_mutants_of_a_kernel_certified_rank_are_never_proved_by_a_stale_kernel():
    """W = PXᵀ − XPᵀ with the kernel x × p built from X and P (not from W): a mutant of W keeps the old kernel, a
    mutant of the kernel keeps W.  No survivor: a mutant whose statement is false is refuted (the kernel is no
    longer one and is not used), and one whose statement is still true (rank 2 of PXᵀ + XPᵀ, a wrong kernel) is
    proved by the function-field rank, never by the stale kernel."""
    run = cli("mutate", "adv-s43-cross-kernel", "--claims", PROBES, "--method", "exact", "--size", "3,1",
              "--jobs", "1")
    assert "0 survivors" in run.stdout, (run.stdout[-3000:], run.stderr[-2000:])
    killed = [line for line in run.stdout.splitlines() if " killed: " in line]
    assert any("the second term dropped" in line for line in killed), run.stdout[-3000:]
    assert any("changed to 3" in line for line in killed) and any("lowered to 1" in line for line in killed)


# -- the point values in flint (in process: backend objects, no claim) ------------------------------------------

def _field():
    from stiefelsym.backends.native import backend
    from stiefelsym.backends.polyfield import SymbolicField
    f = SymbolicField()
    return f, backend(f)


def test_values_at_agrees_with_symengine_across_a_growing_ring():
    """A matrix built entry by entry mixing flint scalars (``_RF``), symengine expressions with variables only in a
    denominator, zeros and fractions, whose conversion grows the ring past its first context (15 variables, then
    3 more): every value is the expression's value at the point drawn (variables in the order of their names)."""
    import symengine as se
    from fractions import Fraction
    from stiefelsym.backends.polyfield import _RF
    f, be = _field()
    R = be.ring
    syms = [f.param(f"v{i:02d}") for i in range(15)]
    for s in syms:
        R.var(s)
    x, y, z = syms[:3]
    a, b, c = f.param("w0"), f.param("w1"), f.param("w2")
    arr = np.empty((2, 3), dtype=object)
    arr[0, 0] = _RF(R, R.from_se(x / y))
    arr[0, 1] = z / (x + 1)
    arr[0, 2] = se.Integer(0)
    arr[1, 0] = se.Rational(1, 3)
    arr[1, 1] = a * b / (c + 1) + x
    arr[1, 2] = 1 / c
    drawn = {}

    def draw(k):
        drawn["v"] = [3 * i + 2 for i in range(k)]
        return drawn["v"]
    cap = R.cap
    out = be.values_at(arr, draw)
    assert R.cap > cap
    exprs = [[e.to_se() if type(e) is _RF else se.sympify(e) for e in row] for row in arr]
    names = sorted({str(s) for row in exprs for e in row for s in e.free_symbols})
    by_name = {str(s): s for row in exprs for e in row for s in e.free_symbols}
    point = {by_name[nm]: v for nm, v in zip(names, drawn["v"])}
    for i, row in enumerate(exprs):
        for j, e in enumerate(row):
            want = Fraction(str(e.subs(point)))
            assert Fraction(int(out[i][j].p), int(out[i][j].q)) == want, (i, j, e)


def test_values_at_leaves_a_scalar_of_another_ring_to_its_own_expression():
    """1/(q + 1) of another field: its variable 0 and its denominator atom 0 are that ring's.  values_at read them
    as this ring's (x and the atom of 1/y here): a wrong value, not a point of either field.  Now NotImplemented,
    and the caller evaluates the symengine expression."""
    from stiefelsym.backends.polyfield import _RF
    f, be = _field()
    R = be.ring
    x, y = f.param("x"), f.param("y")
    R.var(x)
    R.var(y)
    R.from_se(1 / y)            # an atom of this ring at index 0
    g, be2 = _field()
    q = g.param("q")
    R2 = be2.ring
    R2.var(q)
    foreign = _RF(R2, R2.from_se(1 / (q + 1)))
    arr = np.empty((1, 2), dtype=object)
    arr[0, 0], arr[0, 1] = foreign, _RF(R, R.from_se(x))
    assert be.values_at(arr, lambda k: [5] * k) is NotImplemented


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_the_other_methods_are_not_affected_by_a_kernel(method):
    """x × p as the kernel of W at (3,1): exact (and auto, which takes it) prove the rank by the kernel; a printed
    rank one too high fails by the kernel's bound."""
    recs, run = _records("adv-s43-cross-kernel", "adv-s43-rank-too-high", "--method", method, "--size", "3,1")
    got = {r["claim"]: r["verdict"] for r in recs if r["method"] != "free"}
    assert got == {"adv-s43-cross-kernel": "proved", "adv-s43-rank-too-high": "fails"}, (got, run.stderr[-2000:])
