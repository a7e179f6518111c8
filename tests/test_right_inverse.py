"""RightInverse statements: "this map of R^{n×r} × R^{n×r} (...) onto Sym(r) × Sym(r) (...) has this right
inverse at every point of T*V", decided as the identity op(inv(y)) = y in a generic element y of the target
(with inv(y) in the source and op(x) in the target).  A linear op (a differential) then has full rank at
every point: the constraints (cond_XP) are independent, proved for every n, r by rewriting with a
certificate.  A wrong right inverse, a map that is not onto and a map that leaves the target are rejected
by every method."""
import pytest

from stiefelsym import RightInverse
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.ir import TraceRefused, trace
from stiefelsym.ir.replay import GraphClaim
from stiefelsym.methods.fixed_size import REALIZATIONS, run_ball, run_exact, run_float, run_points

CATALOG = load_catalog()
CLAIM = CATALOG.get("constraints-independent")
STANDARD = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
TANGENT = ("R^{n×r}", "R^{n×r}")
SYM2 = ("Sym(r)", "Sym(r)")


def cond(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def dF(s, dX, dP):
    return tuple(s.d(cond, {"X": dX, "P": dP}))


def dF_right(s, a, b):
    K = s.X.T @ s.P
    return s.X @ a / 2, s.X @ (b / 2 - (a @ K - K @ a) / 4)


def right_wrong_sign(s, a, b):
    K = s.X.T @ s.P
    return s.X @ a / 2, s.X @ (b / 2 + (a @ K - K @ a) / 4)


def right_wrong_factor(s, a, b):
    K = s.X.T @ s.P
    return s.X @ a, s.X @ (b / 2 - (a @ K - K @ a) / 4)


def dF_twice_the_first(s, dX, dP):
    """Not onto: both parts are the derivative of XᵀX (the second constraint's differential is lost)."""
    first = dF(s, dX, dP)[0]
    return first, first


def X_t_dX(s, dX):
    """δX ↦ XᵀδX: inverted on the right by a ↦ Xa, but it leaves Sym(r)."""
    return s.X.T @ dX


def statement(op, inv, on=TANGENT, to=SYM2):
    def claim_func(s):
        return {"onto": RightInverse(op, inv, on=on, to=to, meaning="test")}
    return claim_func


GOOD = statement(dF, dF_right)
WRONG = {
    "sign": statement(dF, right_wrong_sign),
    "factor": statement(dF, right_wrong_factor),
    "not onto": statement(dF_twice_the_first, dF_right),
    "leaves Sym(r)": statement(X_t_dX, lambda s, a: s.X @ a, on="R^{n×r}", to="Sym(r)"),
}


def test_the_constraints_are_independent_for_every_n_r_with_a_certificate():
    res = run_free(CLAIM)
    assert res.verdict == "proved", res.message
    assert check_certificate(res.certificate_data).accepted
    details = {c.name: c.detail for c in res.checks}
    assert "onto Sym(r) × Sym(r)" in details["rank d(F, G)"]
    assert "onto Sym(r)" in details["dim V"]


@pytest.mark.parametrize("size", [(3, 1), (4, 2), (4, 4)])
def test_the_constraints_are_independent_at_fixed_sizes(size):
    assert run_exact(CLAIM, *size, seed=0).verdict == "proved"
    assert run_points(CLAIM, *size, "modular", 0).verdict == "checked"


def test_the_statement_replays_to_the_same_graph():
    g = trace(CLAIM.func, None, None, STANDARD)
    assert "right_inverse" in g.ops
    assert trace(GraphClaim(g), None, None, STANDARD).digest() == g.digest()
    assert trace(GraphClaim(g), 4, 2, STANDARD).digest() == trace(CLAIM.func, 4, 2, STANDARD).digest()


def test_a_true_right_inverse_is_proved_by_every_method():
    assert run_free(CLAIM, GOOD).verdict == "proved"
    assert run_exact(CLAIM, 4, 2, 0, func=GOOD).verdict == "proved"
    assert run_points(CLAIM, 4, 2, "modular", 0, func=GOOD).verdict == "checked"
    assert run_float(CLAIM, 4, 2, 0, func=GOOD).verdict == "numeric"


@pytest.mark.parametrize("what", list(WRONG))
def test_a_wrong_right_inverse_is_rejected_by_every_method(what):
    func = WRONG[what]
    res = run_free(CLAIM, func)
    assert res.verdict == "undecided" and "nonzero normal form" in res.message, res.message
    assert run_exact(CLAIM, 3, 2, 0, func=func).verdict == "fails"
    assert run_points(CLAIM, 3, 2, "modular", 0, func=func).verdict == "fails"
    assert run_float(CLAIM, 3, 2, 0, func=func).verdict == "fails"
    assert run_ball(CLAIM, 3, 2, 0, func=func).verdict == "fails"


def test_a_wrong_sign_that_is_right_at_r_1_is_proved_only_there():
    """At r = 1, aK − Ka = 0: the right inverse with the other sign is right there, and only there."""
    func = WRONG["sign"]
    assert run_exact(CLAIM, 3, 1, 0, func=func).verdict == "proved"
    assert run_exact(CLAIM, 3, 2, 0, func=func).verdict == "fails"


def test_inv_op_x_is_not_asked():
    """dF is not injective (its kernel is the tangent space of T*V): a two-sided Inverse of it does not even
    type, and the right inverse says nothing of inv(op(x))."""
    g = trace(GOOD, None, None, STANDARD)
    i = g.ops.index("right_inverse")
    assert len(g.args[i][5]) == 2 + 0 + 2     # op(inv(y)) − y, inv(y) in R^{n×r} (none), op(x) in Sym(r)
    with pytest.raises(TraceRefused):
        from stiefelsym import Inverse
        trace(lambda s: {"x": Inverse(dF, dF_right, on=TANGENT)}, None, None, STANDARD)


# -- what the tracer refuses ---------------------------------------------------------------------------

def test_a_right_inverse_that_reads_an_element_is_refused():
    func = statement(lambda s, dX, dP: (s.generic("InverseY1", "r", "r"), s.generic("InverseY2", "r", "r")),
                     dF_right)
    with pytest.raises(TraceRefused, match="generic elements of an Inverse"):
        trace(func, None, None, STANDARD)


def test_a_right_inverse_that_divides_by_a_function_is_refused():
    def inv(s, a, b):
        dX, dP = dF_right(s, a, b)
        return dX / s.tr(s.P.T @ s.P) * s.tr(s.P.T @ s.P), dP
    with pytest.raises(TraceRefused, match="only constant divisors"):
        trace(statement(dF, inv), None, None, STANDARD)


def test_a_right_inverse_of_the_wrong_shape_is_refused():
    with pytest.raises(TraceRefused, match="where Sym"):
        trace(statement(lambda s, dX, dP: (dX, dP), dF_right), None, None, STANDARD)
    with pytest.raises(TraceRefused, match="one matrix per space"):
        trace(statement(lambda s, dX, dP: dF(s, dX, dP)[0], dF_right), None, None, STANDARD)


def test_a_right_inverse_on_an_unknown_space_is_a_type_error():
    with pytest.raises(TypeError, match="to is a space"):
        RightInverse(dF, dF_right, on=TANGENT, to="Sym(k)")
    with pytest.raises(TypeError, match="functions"):
        RightInverse(dF, 1, on=TANGENT, to=SYM2)


def test_a_crafted_right_inverse_node_gets_the_verdict_of_its_parts():
    """A graph whose statement names other residuals (the vanishing membership residuals in place of
    op(inv(y)) − y) is replayed: the tracer makes the statement again from its parts."""
    from stiefelsym.ir.graph import Graph

    g = trace(WRONG["sign"], None, None, STANDARD)
    i = g.ops.index("right_inverse")
    a = g.args[i]
    zero = a[5][-1]
    forged = Graph()
    forged.ops, forged.args = list(g.ops), list(g.args)
    forged.args[i] = a[:5] + (tuple(zero for _ in a[5]),) + a[6:]
    forged.output = g.output
    assert run_exact(CLAIM, 3, 2, 0, func=GraphClaim(forged)).verdict == "fails"


def test_a_crafted_right_inverse_whose_op_reads_y_itself_is_refused():
    """op(inv(y)) taken as y itself (op = const y): refused when the graph is replayed."""
    from stiefelsym.ir.graph import Graph

    g = trace(WRONG["not onto"], None, None, STANDARD)
    i = g.ops.index("right_inverse")
    a = g.args[i]
    forged = Graph()
    forged.ops, forged.args = list(g.ops), list(g.args)
    forged.args[i] = a[:2] + (a[0],) + a[3:]
    forged.output = g.output
    with pytest.raises(TraceRefused, match="other than through its argument"):
        trace(GraphClaim(forged), None, None, STANDARD)
