"""Round 6: the op (or inv) of a RightInverse / Inverse statement is Python called more than once by the
tracer (op on inv(y), then op on a generic x; inv on y, then inv on op(x)).  A map whose state or whose test
of its argument makes it another map on its second call: the identity on inv(y), so that op(inv(y)) = y, and
the projection X Xᵀ x on x (onto only at r = n)."""
from stiefelsym import Inverse, RightInverse, admissible, claim


class CountingOp:
    """The identity on its first call, x ↦ X Xᵀ x afterwards."""

    def __init__(self):
        self.calls = 0

    def __call__(self, t, x):
        self.calls += 1
        return x if self.calls == 1 else t.X @ t.X.T @ x


@claim("adv-s36-ri-stateful-projection", kind="id", sizes=admissible(n_max=3))
def stateful_projection(s):
    """False for r < n: x ↦ X Xᵀ x maps R^{n×r} onto R^{n×r} (the identity as its right inverse)."""
    return {"onto": RightInverse(CountingOp(), lambda t, y: y, on="R^{n×r}", to="R^{n×r}")}


@claim("adv-s36-ri-argument-test", kind="id", sizes=admissible(n_max=3))
def argument_test(s):
    """False for r < n: x ↦ X Xᵀ x maps R^{n×r} onto R^{n×r}; the op is the identity on the very value its
    right inverse returned (it keeps it), the projection on every other."""
    kept = []

    def inv(t, y):
        out = y + t.zeros(t.n, t.r, ("n", "r"))
        kept.append(out)
        return out

    def op(t, x):
        return x if any(x is k for k in kept) else t.X @ t.X.T @ x
    return {"onto": RightInverse(op, inv, on="R^{n×r}", to="R^{n×r}")}


class CountingInv:
    """y on its first call, y/2 afterwards."""

    def __init__(self):
        self.calls = 0

    def __call__(self, t, y):
        self.calls += 1
        return y if self.calls == 1 else y / 2


class CountingDouble:
    """The identity on its first call, x ↦ 2x afterwards."""

    def __init__(self):
        self.calls = 0

    def __call__(self, t, x):
        self.calls += 1
        return x if self.calls == 1 else 2 * x


@claim("adv-s36-inv-stateful-pair", kind="id", sizes=admissible(n_max=3))
def stateful_pair(s):
    """Ill-formed: op is the identity and then 2x, inv the identity and then y/2 (each identity holds for
    one reading of op and inv): not one map."""
    return {"inv": Inverse(CountingDouble(), CountingInv(), on="Sym(r)")}


@claim("adv-s36-ri-fresh-functions", kind="id", sizes=admissible(n_max=3))
def fresh_functions(s):
    """True: d(XᵀX) maps R^{n×r} onto Sym(r) on V, with a function made anew at each call of op (as the
    catalog's constraints-independent does)."""
    def op(t, dX):
        return t.d(lambda u: u.X.T @ u.X, {"X": dX, "P": t.zeros(t.n, t.r, ("n", "r"))})

    return {"onto": RightInverse(op, lambda t, a: t.X @ a / 2, on="R^{n×r}", to="Sym(r)")}
