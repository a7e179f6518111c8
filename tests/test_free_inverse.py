"""Inverse statements: "this operator on Sym(r) × Sym(r) (so(n), R^{n×r}, ...) is invertible at every
point of T*V, with this inverse", decided as the identities op(inv(y)) = y and inv(op(x)) = x in generic
elements x, y (and op(x), inv(y) in the space).  The operators {F_i, F_j}_0 and the multiplier system of
(dot_XP) are proved invertible for every n, r by rewriting, with certificates; a wrong inverse (a sign, a
missing term), a map that is not invertible and a map that leaves the space are rejected by every
method, and by the independent checker when its certificate is altered."""
import copy
from fractions import Fraction

import pytest

from stiefelsym import Inverse
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.ir import TraceRefused, trace
from stiefelsym.ir.replay import GraphClaim
from stiefelsym.methods.fixed_size import REALIZATIONS, run_ball, run_exact, run_float, run_points

CATALOG = load_catalog()
CLAIM = CATALOG.get("dirac-bracket-multipliers")
STANDARD = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
SYM2 = ("Sym(r)", "Sym(r)")


def cond(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def multipliers(s, Lam, Pi):
    """(Λ, Π) ↦ d(F_1, F_2) along (−XΠ, XΛ + PΠ): (−2Π, 2Λ + 2(KΠ − ΠK)) on T*V, K = XᵀP."""
    return tuple(s.d(cond, {"X": -(s.X @ Pi), "P": s.X @ Lam + s.P @ Pi}))


def multipliers_inverse(s, a, b):
    K = s.X.T @ s.P
    return (b + K @ a - a @ K) / 2, -a / 2


def inverse_wrong_sign(s, a, b):
    K = s.X.T @ s.P
    return (b - K @ a + a @ K) / 2, -a / 2


def inverse_missing_term(s, a, b):
    return b / 2, -a / 2


def forgets_lambda(s, Lam, Pi):
    """Not invertible: Λ only through its skew part, which is 0 on Sym(r)."""
    return Lam - Lam.T + Pi, Pi


def translate(s, x):
    """x ↦ x + Ψ: inverted by y ↦ y − Ψ, but it leaves Sym(r)."""
    return x + s.X.T @ s.P - s.P.T @ s.X


def untranslate(s, y):
    return y - s.X.T @ s.P + s.P.T @ s.X


def statement(op, inv, on=SYM2):
    def claim_func(s):
        return {"invertible": Inverse(op, inv, on=on, meaning="test")}
    return claim_func


GOOD = statement(multipliers, multipliers_inverse)
WRONG = {
    "sign": statement(multipliers, inverse_wrong_sign),
    "missing term": statement(multipliers, inverse_missing_term),
    "not invertible": statement(forgets_lambda, lambda s, a, b: (a - b, b)),
    "leaves Sym(r)": statement(translate, untranslate, on="Sym(r)"),
}


# -- the catalog's claim -----------------------------------------------------------------------------

def test_the_dirac_bracket_claim_is_proved_for_every_n_r_with_a_certificate():
    res = run_free(CLAIM)
    assert res.verdict == "proved", res.message
    assert check_certificate(res.certificate_data).accepted
    details = {c.name: c.detail for c in res.checks}
    for name in ("{F_i, F_j}_0 invertible", "Lambda, Pi unique"):
        assert "op invertible on Sym(r) × Sym(r)" in details[name]


@pytest.mark.parametrize("size", [(3, 2), (4, 3)])
def test_the_dirac_bracket_claim_is_proved_at_fixed_sizes(size):
    res = run_exact(CLAIM, *size, seed=0)
    assert res.verdict == "proved", res.message
    assert all(c.status == "zero" for c in res.checks)


def test_the_statement_replays_to_the_same_graph():
    g = trace(CLAIM.func, None, None, STANDARD)
    assert trace(GraphClaim(g), None, None, STANDARD).digest() == g.digest()
    assert trace(GraphClaim(g), 4, 2, STANDARD).digest() == trace(GraphClaim(g), 4, 2, STANDARD).digest()


# -- a true statement, and wrong ones, under every method -----------------------------------------------

def test_a_true_inverse_is_proved_by_every_method():
    assert run_free(CLAIM, GOOD).verdict == "proved"
    assert run_exact(CLAIM, 4, 2, 0, func=GOOD).verdict == "proved"
    assert run_points(CLAIM, 4, 2, "modular", 0, func=GOOD).verdict == "checked"
    assert run_float(CLAIM, 4, 2, 0, func=GOOD).verdict == "numeric"


@pytest.mark.parametrize("what", list(WRONG))
def test_a_wrong_inverse_is_rejected_by_every_method(what):
    func = WRONG[what]
    res = run_free(CLAIM, func)
    assert res.verdict == "undecided" and "nonzero normal form" in res.message, res.message
    assert run_exact(CLAIM, 3, 2, 0, func=func).verdict == "fails"
    assert run_points(CLAIM, 3, 2, "modular", 0, func=func).verdict == "fails"
    assert run_float(CLAIM, 3, 2, 0, func=func).verdict == "fails"
    assert run_ball(CLAIM, 3, 2, 0, func=func).verdict == "fails"


def test_a_wrong_inverse_that_is_right_at_r_1_is_proved_only_there():
    """At r = 1, KΠ − ΠK = 0: the inverse without that term is right there, and only there."""
    func = WRONG["missing term"]
    assert run_exact(CLAIM, 3, 1, 0, func=func).verdict == "proved"
    assert run_exact(CLAIM, 3, 2, 0, func=func).verdict == "fails"


def test_the_checker_rejects_a_certificate_whose_inverse_was_altered():
    """The certificate of a proof, with one identity of the inverse replaced by that of a wrong inverse
    (the terms in XᵀP negated: the commutator's sign), is rejected."""
    data = run_free(CLAIM, GOOD).certificate_data
    assert check_certificate(data).accepted
    bad = copy.deepcopy(data)
    hit = 0
    for entry in bad["entries"]:
        if entry["position"].startswith("invertible#3"):
            for term in entry["residual"]:
                if "P" in term["word"] or "Pt" in term["word"]:
                    term["coef"] = str(-Fraction(term["coef"]))
                    hit += 1
    assert hit
    report = check_certificate(bad)
    assert not report.accepted, report.message


# -- what the tracer refuses ---------------------------------------------------------------------------

def test_an_inverse_that_reads_an_element_of_the_statement_is_refused():
    """op = const y and inv = const x would pass both identities: the elements have reserved names."""
    func = statement(lambda s, a, b: (a, b), lambda s, a, b: (s.generic("InverseX1", "r", "r"), b))
    with pytest.raises(TraceRefused, match="generic elements of an Inverse"):
        trace(func, None, None, STANDARD)


def test_an_inverse_with_the_wrong_number_of_parts_is_refused():
    with pytest.raises(TraceRefused, match="one matrix per space"):
        trace(statement(lambda s, a, b: a, multipliers_inverse), None, None, STANDARD)


def test_an_inverse_inside_a_list_is_refused():
    def func(s):
        return {"x": [Inverse(multipliers, multipliers_inverse, on=SYM2)]}
    with pytest.raises(TraceRefused):
        trace(func, None, None, STANDARD)


def test_an_inverse_on_an_unknown_space_is_a_type_error():
    with pytest.raises(TypeError, match="on is a space"):
        Inverse(multipliers, multipliers_inverse, on="Sym(k)")
    with pytest.raises(TypeError, match="functions"):
        Inverse(1, multipliers_inverse, on=SYM2)


def test_an_element_of_another_shape_is_refused_where_it_is_written():
    """op maps Sym(r) to n×r matrices: op(x) − x does not type."""
    with pytest.raises(TraceRefused):
        trace(statement(lambda s, a: s.X @ a, lambda s, y: y, on="Sym(r)"), None, None, STANDARD)


# -- the operators are the paper's matrices -------------------------------------------------------------

def _sym_units(s):
    """The basis E_ab + E_ba (a < b), E_aa of Sym(r), with the weight of each in tr(S·F) (2 or 1)."""
    r = s.r
    out = []
    for a in range(r):
        for b in range(a, r):
            E = s.mat([[s.q(1) if (i, j) in ((a, b), (b, a)) else s.q(0) for j in range(r)] for i in range(r)],
                      ("r", "r"))
            out.append((E, 1 if a == b else 2))
    return out


def _upper(M):
    m = M.shape[0]
    return [M[i, j] for i in range(m) for j in range(i, m)]


def _twisted_wrong_sign(s, S, T):
    """Negative control: Ṗ = −h_X + ε h_P F."""
    import stiefelsym.proofs.app1_magnetic_neumann as app1
    from stiefelsym import twisted

    def h(t):
        F1, F2 = app1.cond_XP(t)
        return t.tr(S @ F1) + t.tr(T @ F2)
    canonical = s.canonical_flow(h)
    F = twisted.magnetic_matrix(s)
    return tuple(s.d(app1.cond_XP, {"X": canonical.Xdot, "P": canonical.Pdot + s.eps * (canonical.Xdot @ F)}))


@pytest.mark.parametrize("which", ["standard", "twisted", "twisted, wrong sign"])
def test_the_operator_is_the_matrix_of_constraint_brackets(which):
    """At a point of T*V(3, 2): the operator applied to the coefficients of h = tr(S F_1) + tr(T F_2) is the
    engine's matrix {F_i, F_j} (untwisted, or for ω₀ + ε de₁∧de₂) times those coefficients, column by column."""
    import random

    from stiefelsym import twisted
    from stiefelsym.backends.fields import ModularField
    from stiefelsym.scene import Scene
    import stiefelsym.proofs.app1_magnetic_neumann as app1
    import stiefelsym.proofs.sec2_hamiltonian_flows as sec2

    s = Scene(3, 2, ModularField(), rng=random.Random("inverse|matrix"))
    if which == "standard":
        op, C = sec2.constraint_brackets, s.constraint_bracket_matrix()
    else:
        op = app1.twisted_constraint_brackets if which == "twisted" else _twisted_wrong_sign
        C = twisted.constraint_bracket_matrix(s)
    zero = s.zeros(2, 2, ("r", "r"))
    units = _sym_units(s)
    columns = [(E, zero, w) for E, w in units] + [(zero, E, w) for E, w in units]
    agree = True
    for i, (S, T, w) in enumerate(columns):
        a, b = op(s, S, T)
        column = _upper(a) + _upper(b)
        agree &= all(s.field.is_zero(x - C[j][i] * w) for j, x in enumerate(column))
    assert agree == ("wrong" not in which)


def test_a_crafted_inverse_node_gets_the_verdict_of_its_parts():
    """A graph whose inverse node names other residuals (here the membership residual, which vanishes, in
    place of op(inv(y)) − y, which does not) is replayed: the tracer makes the statement again from its parts,
    so the crafted residuals are not what the methods evaluate."""
    from stiefelsym.ir.graph import Graph

    g = trace(WRONG["sign"], None, None, STANDARD)
    i = g.ops.index("inverse")
    a = g.args[i]
    zero = a[6][-1]                       # inv(y)ᵀ − inv(y)... : 0 on T*V
    forged = Graph()
    forged.ops, forged.args = list(g.ops), list(g.args)
    forged.args[i] = a[:6] + (tuple(zero for _ in a[6]),) + a[7:]
    forged.output = g.output
    assert run_exact(CLAIM, 3, 2, 0, func=GraphClaim(forged)).verdict == "fails"
    assert run_exact(CLAIM, 3, 2, 0, func=GraphClaim(g)).verdict == "fails"


def test_a_crafted_inverse_whose_op_reads_y_itself_is_refused():
    """op(inv(y)) taken as y itself (op = const y): refused when the graph is replayed."""
    from stiefelsym.ir.graph import Graph

    g = trace(WRONG["not invertible"], None, None, STANDARD)
    i = g.ops.index("inverse")
    a = g.args[i]
    forged = Graph()
    forged.ops, forged.args = list(g.ops), list(g.args)
    forged.args[i] = a[:2] + (a[0],) + a[3:5] + (a[3],) + a[6:]
    forged.output = g.output
    with pytest.raises(TraceRefused, match="other than through its argument"):
        trace(GraphClaim(forged), None, None, STANDARD)


def test_a_claims_file_whose_inverse_reaches_the_elements_passes_nowhere(tmp_path):
    """tests/adversary/inverse_elements.py: the elements by name, and an argument kept by op for inv."""
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    for method in ("auto", "free"):
        p = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims",
                            str(root / "tests" / "adversary" / "inverse_elements.py"), "--size", "3,2", "--method",
                            method, "--jobs", "1", "--report-dir", str(tmp_path / method)],
                           cwd=root, capture_output=True, text=True, timeout=300)
        lines = [x for x in p.stdout.splitlines() if x.startswith("adv-inverse-")]
        assert len(lines) == 2, p.stdout + p.stderr
        assert all(": error" in x for x in lines), p.stdout     # free too: refused at every size
        assert "the names Inverse... are the generic elements" in p.stdout, p.stdout
        if method == "free":    # not "needs coordinates": refused at a fixed size too
            assert p.stdout.count("and at (3,2) too (TraceRefused; (3,2) is a size it is stated for") >= 2, p.stdout
        assert "inv(op(x)) reads a generic element of the statement other than through its argument" in p.stdout
