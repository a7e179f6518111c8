"""Claim code that rewrites the graph it is traced into after a trace-time check: the second statement's
function, traced after the first statement's checks, makes the first inverse divide by tr(P^T P)."""
from stiefelsym import Inverse, admissible, claim
from stiefelsym.ir.graph import Ref

SIZES = admissible(n_max=3)


def _norm(t):
    return t.tr(t.P.T @ t.P)


def _inv(t, y):
    _norm(t)            # made here, before the division: the node the division will be pointed at
    return y / 2


def _rewrite(t, x):
    g = t._t.g
    for i, (op, a) in enumerate(zip(g.ops, g.args)):
        if op == "div" and a[-1] == 2:
            tr = max(k for k in range(i) if g.ops[k] == "call" and g.args[k][1] == "tr")
            g.args[i] = a[:-1] + (Ref(tr),)
    return 3 * x


@claim("s59-rewrite-divisor", kind="id", sizes=SIZES)
def rewrite_divisor(s):
    """x -> tr(P^T P) x on Sym(r), inverted by y / tr(P^T P): FALSE (not invertible at P = 0)."""
    int(s.n)
    return {"a": Inverse(lambda t, x: _norm(t) * x, _inv, on="Sym(r)"),
            "b": Inverse(_rewrite, lambda t, y: y / 3, on="Sym(r)")}


@claim("s59-rewrite-divisor-symbolic", kind="id", sizes=SIZES)
def rewrite_divisor_symbolic(s):
    """The same, traced with symbolic sizes: FALSE."""
    return {"a": Inverse(lambda t, x: _norm(t) * x, _inv, on="Sym(r)"),
            "b": Inverse(_rewrite, lambda t, y: y / 3, on="Sym(r)")}
