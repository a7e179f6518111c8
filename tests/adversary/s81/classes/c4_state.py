"""Class 4 (state across calls), new tricks.

c4-swap-false: a MatrixFunction (frozen dataclass) whose value is swapped with object.__setattr__ after its gradient
was taken (and checked against the first value).  The claim's statement: for h(y) = ¼<y, y> (the value the claim
computes with), <∇h(x), x> = 4h(x).  Euler: h is homogeneous of degree 2, ∇h = ½x, <∇h(x), x> = ½<x, x> = 2h(x),
so 4h(x) = <x, x> ≠ 2h(x) = ½<x,x> wherever <x, x> ≠ 0 (x = XXᵀ: <x, x> = −½tr(XXᵀXXᵀ) = −r/2): FALSE.
c4-swap-true: the same without the swap: h = ½<y, y>, <∇h(x), x> = 2h(x): TRUE.

c4-order-a / c4-order-b: claim a sets a module global, claim b reads it: b's graph depends on which claims ran
before it in the tracing process (b is XXᵀ − I_n, FALSE at r < n, after a; XᵀX − I_r, TRUE, alone).

c4-twograd-false: a stateful gradient callable, right at its first call, wrong (0) at its second; the claim uses
the second.  FALSE: ∇(½<y, y>) = 0 stated as h.grad(s, x)·1 at its second call − 0.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_max=3, n_min=2)


def _x(s):
    return s.X @ s.X.T


@claim("c4-swap-false", kind="id", sizes=SZ)
def c4_swap_false(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    x = _x(s)
    G = h.grad(s, x)
    object.__setattr__(h, "value", lambda t, y: t.killing(y, y) / 4)
    return {"r": s.killing(G, x) - h(s, x) * 4}


@claim("c4-swap-true", kind="id", sizes=SZ)
def c4_swap_true(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    x = _x(s)
    G = h.grad(s, x)
    return {"r": s.killing(G, x) - h(s, x) * 2}


@claim("c4-swapsum-false", kind="id", sizes=SZ)
def c4_swapsum_false(s):
    """FALSE (same statement as c4-swap-false) with the swap on a part of a sum h = f + g (g = 0 function)."""
    f = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    g = MatrixFunction(lambda t, y: t.killing(y, y) * 0, lambda t, y: y * 0)
    h = f + g
    x = _x(s)
    G = h.grad(s, x)
    object.__setattr__(f, "value", lambda t, y: t.killing(y, y) / 4)
    return {"r": s.killing(G, x) - h(s, x) * 4}


_FLAG = []


@claim("c4-order-a", kind="id", sizes=SZ)
def c4_order_a(s):
    """TRUE: XᵀX = I_r; sets a module global."""
    _FLAG.append(1)
    return {"r": s.X.T @ s.X - s.Ir}


@claim("c4-order-b", kind="id", sizes=SZ)
def c4_order_b(s):
    """Depends on the run order: FALSE residual when c4-order-a was traced before in the same process."""
    if _FLAG:
        return {"r": s.X @ s.X.T - s.In}
    return {"r": s.X.T @ s.X - s.Ir}


class _TwoGrad:
    def __init__(self):
        self.k = 0

    def __call__(self, t, y):
        self.k += 1
        return y if self.k % 2 else y * 0


@claim("c4-twograd-false", kind="id", sizes=SZ)
def c4_twograd_false(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, _TwoGrad())
    x = _x(s)
    h.grad(s, x)
    return {"r": h.grad(s, x)}


@claim("c4-cell-false", kind="id", sizes=SZ)
def c4_cell_false(s):
    """FALSE (as c4-swap-false): h = quadratic(op), op(u) = u; after ∇h is taken (checked: op symmetric, ∇h = x),
    the closure cell of quadratic's op is rebound to u ↦ u/2, so h(x) = ½<x, x/2> = ¼<x, x>.  Stated:
    <∇h(x), x> = 4h(x) for that h (its true gradient is x/2: <x/2, x> = 2h(x) ≠ 4h(x))."""
    from stiefelsym.brackets import quadratic
    h = quadratic(lambda t, u: u)
    x = _x(s)
    G = h.grad(s, x)
    for f in (h.value, h.gradient):
        for i, name in enumerate(f.__code__.co_freevars):
            if name == "op_":
                f.__closure__[i].cell_contents = (lambda t, u: u / 2)
    return {"r": s.killing(G, x) - h(s, x) * 4}


@claim("c4-cell-true", kind="id", sizes=SZ)
def c4_cell_true(s):
    """TRUE: h = quadratic(u ↦ u/2): <∇h(x), x> = 2h(x)."""
    from stiefelsym.brackets import quadratic
    h = quadratic(lambda t, u: u / 2)
    x = _x(s)
    return {"r": s.killing(h.grad(s, x), x) - h(s, x) * 2}


@claim("c4-swapbr-false", kind="id", sizes=SZ)
def c4_swapbr_false(s):
    """FALSE (stop 80's "zero function with a nonzero bracket", reopened by the swap): h is the zero function (its
    value, as the claim evaluates it: r1 = h(Y) = 0 at a generic Y), g(y) = <y, B>, and the claim states
    {h, g}_Λ2(Y) = −<A, [Y, B]> with Λ2(a, b)|_x = <x − A, [a, b]> (lambda2).  For the zero function ∇h = 0 and
    {h, g} = 0, while <A, [Y, B]> ≠ 0 for generic A (symmetric), Y, B: FALSE.  The bracket is taken while h's value
    is ½<y, y> (∇h = Y, checked), then the value is swapped to 0 with object.__setattr__ (the dataclass is frozen)."""
    from stiefelsym.brackets import lambda2, linear
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    g = linear(lambda t: t.generic("B", "n", "n"))
    Y = s.generic("Y", "n", "n")
    br = lambda2().bracket(s, h, g, Y)
    object.__setattr__(h, "value", lambda t, y: t.killing(y, y) * 0)
    B = s.generic("B", "n", "n")
    return {"r1": h(s, Y), "r2": br + s.killing(s.A, Y @ B - B @ Y)}


@claim("c4-swapbr-true", kind="id", sizes=SZ)
def c4_swapbr_true(s):
    """TRUE: the same bracket for h = ½<y, y> (no swap): {h, g}_Λ2(Y) = <Y − A, [Y, B]> = −<A, [Y, B]>."""
    from stiefelsym.brackets import lambda2, linear
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    g = linear(lambda t: t.generic("B", "n", "n"))
    Y = s.generic("Y", "n", "n")
    B = s.generic("B", "n", "n")
    return {"r": lambda2().bracket(s, h, g, Y) + s.killing(s.A, Y @ B - B @ Y)}


class _Shifty(MatrixFunction):
    """A MatrixFunction subclass whose field ``value`` is read through __getattribute__: ½<y, y> at the first read
    and second reads (the gradient's check step and its hold), ¼<y, y> at every later read (the claim's own calls).  No setattr, no patch."""
    def __getattribute__(self, name):
        if name == "value":
            k = object.__getattribute__(self, "_reads")
            k.append(1)
            if len(k) > 2:
                return _quarter
        return object.__getattribute__(self, name)


def _half(t, y):
    return t.killing(y, y) / 2


def _quarter(t, y):
    return t.killing(y, y) / 4


@claim("c4-prop-false", kind="id", sizes=SZ)
def c4_prop_false(s):
    """FALSE (as c4-swap-false): h(y) = ¼<y, y> as the claim evaluates it, <∇h(x), x> = 4h(x) (true: 2h(x))."""
    h = _Shifty(_half, lambda t, y: y)
    object.__setattr__(h, "_reads", [])
    x = _x(s)
    return {"r": s.killing(h.grad(s, x), x) - h(s, x) * 4}


@claim("c4-prop-true", kind="id", sizes=SZ)
def c4_prop_true(s):
    """TRUE: the same with a plain MatrixFunction of ¼<y, y> and its gradient y/2: <∇h(x), x> = 2h(x)."""
    h = MatrixFunction(_quarter, lambda t, y: y / 2)
    x = _x(s)
    return {"r": s.killing(h.grad(s, x), x) - h(s, x) * 2}
