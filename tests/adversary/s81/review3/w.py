"""Second job: wrong verdicts through the new keying (commit 3aebb72c keys the holds of a MatrixFunction's value
by the instance, no longer by the value function object).

Truth used throughout (by hand).  Y = XXᵀ (n×n), <a, b> = −½tr(ab), <Y, Y> = −½tr(XXᵀXXᵀ) = −r/2 ≠ 0.
A function h on gl(n) whose gradient is ∇h(y) = y at EVERY y (what gradient_check certifies: it checks the value's
function at a generic point) is h(y) = ½<y, y> + c (c constant in y); with h(0) = 0, c = 0.  Then
<∇h(Y), Y> = <Y, Y> and 4h(Y) = 2<Y, Y>, so <∇h(Y), Y> − 4h(Y) = −<Y, Y> = r/2 ≠ 0: the "-false" claims below
(residual "r" stated 0, with "zero" = h(0)) are FALSE at every size; the "-true" twins state
<∇h(Y), Y> − 2h(Y) = 0 and h(0) = 0: TRUE.

The value v is ONE Python function shared by copies of one MatrixFunction (copy.copy, dataclasses.replace,
MatrixFunction(f.value, f.gradient)): it tests whether its argument is the claim's own point Y (¼<y, y> there,
½<y, y> elsewhere: stop 79's "tests its point" route).  With ONE instance this is refused (w-one-false, control);
the parent keyed every call by v itself, so copies were held together.

w-sub-false: a subclass overriding __call__ (pre-existing route, in both commits): value field ½<y,y>, gradient y,
__call__ ¼<y,y>; the engine's own f.pullback(moment) calls the override.  The claim computes h = ¼<y, y> at every
call; its declared gradient y is not h's (∇h = y/2): <∇h(Y), Y> = 4h(Y) is FALSE for h = ¼<y,y>
(<Y/2, Y> = ½<Y,Y> vs <Y,Y>), the same standard as the sweep's W1' (c4-prop-false).
"""
import copy
import dataclasses

from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction, lambda2, linear

SZ = admissible(n_max=3, n_min=2)


def _pointy(Y):
    return lambda t, y: t.killing(y, y) / 4 if y is Y else t.killing(y, y) / 2


def _honest():
    return lambda t, y: t.killing(y, y) / 2


def _grad(t, y):
    return y


def _run(s, make_value, copier, k):
    Y = s.X @ s.X.T
    f1 = MatrixFunction(make_value(Y), _grad, "h")
    f2 = copier(f1)
    f3 = copier(f1)
    G = f2.grad(s, Y)
    return {"r": s.killing(G, Y) - f1(s, Y) * k, "zero": f3(s, Y * 0)}


COPIERS = {
    "copy": copy.copy,
    "replace": lambda f: dataclasses.replace(f, name="h'"),
    "rebuild": lambda f: MatrixFunction(f.value, f.gradient, f.name),
}

for _name, _cp in COPIERS.items():
    def _mk(cp, name):
        @claim(f"w-{name}-false", kind="id", sizes=SZ)
        def false_(s):
            return _run(s, _pointy, cp, 4)

        @claim(f"w-{name}-true", kind="id", sizes=SZ)
        def true_(s):
            return _run(s, lambda Y: _honest(), cp, 2)
    _mk(_cp, _name)


@claim("w-one-false", kind="id", sizes=SZ)
def w_one_false(s):
    """Control: the same pointy value, ONE instance (f1 = f2 = f3). FALSE; expected refused."""
    return _run(s, _pointy, lambda f: f, 4)


@claim("w-one-true", kind="id", sizes=SZ)
def w_one_true(s):
    return _run(s, lambda Y: _honest(), lambda f: f, 2)


_COUNT = [0]


def _stateful(t, y):
    _COUNT[0] += 1
    return t.killing(y, y) / (2 if _COUNT[0] == 1 else 4)


@claim("w-state-false", kind="id", sizes=SZ)
def w_state_false(s):
    """A stateful value shared by two instances (½<y,y> at its first call, the gradient check's trace; ¼ after).
    FALSE (same statement, no h(0) needed: for the consistent h = ¼<y,y> of the claim's call ∇h = y/2; for
    h = ½<y,y>, 4h(Y) = 2<Y,Y> ≠ <Y,Y>; either way r = ±r/2... see the docstring: stated with h(0))."""
    _COUNT[0] = 0
    Y = s.X @ s.X.T
    f1 = MatrixFunction(_stateful, _grad, "h")
    f2 = MatrixFunction(_stateful, _grad, "h")
    G = f2.grad(s, Y)
    return {"r": s.killing(G, Y) - f1(s, Y) * 4, "zero": f1(s, Y * 0)}


@claim("w-state-true", kind="id", sizes=SZ)
def w_state_true(s):
    Y = s.X @ s.X.T
    f1 = MatrixFunction(_honest(), _grad, "h")
    f2 = MatrixFunction(f1.value, _grad, "h")
    G = f2.grad(s, Y)
    return {"r": s.killing(G, Y) - f1(s, Y) * 2, "zero": f1(s, Y * 0)}


class _Quarter(MatrixFunction):
    def __call__(self, s, x):
        return s.killing(x, x) / 4


@claim("w-sub-false", kind="id", sizes=SZ)
def w_sub_false(s):
    h = _Quarter(lambda t, y: t.killing(y, y) / 2, _grad, "h")
    Y = s.X @ s.X.T
    G = h.grad(s, Y)
    return {"r": s.killing(G, Y) - h.pullback(lambda t: t.X @ t.X.T)(s) * 4}


@claim("w-sub-true", kind="id", sizes=SZ)
def w_sub_true(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, _grad, "h")
    Y = s.X @ s.X.T
    G = h.grad(s, Y)
    return {"r": s.killing(G, Y) - h.pullback(lambda t: t.X @ t.X.T)(s) * 2}


class _Zero(MatrixFunction):
    def __call__(self, s, x):
        return s.killing(x, x) * 0


@claim("w-subbr-false", kind="id", sizes=SZ)
def w_subbr_false(s):
    """Stop 80's "zero function with a nonzero bracket" through an overridden __call__: h is 0 at every call the
    claim makes (h.pullback(Φ) = 0), its declared value and gradient are <y, A>'s; the claim states h∘Y = 0 and
    {h, g}_Λ2(Y) = Λ2(A, B)|_Y = <Y − A, [A, B]> with g = <y, B>.  For h = 0, {h, g} = 0, and <Y − A, [A, B]> ≠ 0
    for generic A, B (numpy: w_truth.py.in): FALSE."""
    A = lambda t: t.generic("Aa", "n", "n")     # noqa: E731
    B = lambda t: t.generic("Bb", "n", "n")     # noqa: E731
    h = _Zero(lambda t, y: t.killing(y, A(t)), lambda t, y: A(t), "h")
    g = linear(B)
    Y = s.X @ s.X.T
    L = lambda2()
    return {"val": h.pullback(lambda t: t.X @ t.X.T)(s),
            "br": L.bracket(s, h, g, Y) - s.killing(Y - s.A, A(s) @ B(s) - B(s) @ A(s))}


@claim("w-subbr-true", kind="id", sizes=SZ)
def w_subbr_true(s):
    A = lambda t: t.generic("Aa", "n", "n")     # noqa: E731
    B = lambda t: t.generic("Bb", "n", "n")     # noqa: E731
    h = MatrixFunction(lambda t, y: t.killing(y, A(t)), lambda t, y: A(t), "h")
    g = linear(B)
    Y = s.X @ s.X.T
    L = lambda2()
    return {"val": h.pullback(lambda t: t.X @ t.X.T)(s) - s.killing(Y, A(s)),
            "br": L.bracket(s, h, g, Y) - s.killing(Y - s.A, A(s) @ B(s) - B(s) @ A(s))}
