# ruff: noqa
"""Batch 1: graphs that stress the evaluators rather than the tracer (the claims file's code runs only where it is
traced; what reaches the methods is its graph).  Each claim is plainly true or false; `truth` in its docstring."""
import sys
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))
DEPTH = 1500


def _chain(s, start):
    R = start
    XP = s.X.T @ s.P
    for _ in range(DEPTH):
        R = (R + XP) - XP
    return R


@claim("b1-deep-false", kind="id", sizes=S)
def deep_false(s):
    """FALSE: X^T P nested in 1500 (R + X^T P) - X^T P."""
    return {"x": _chain(s, s.X.T @ s.P)}


@claim("b1-deep-true", kind="id", sizes=S)
def deep_true(s):
    """TRUE: X^T X - I nested the same way."""
    return {"x": _chain(s, s.X.T @ s.X - s.Ir)}


@claim("b1-deep-scalar-false", kind="id", sizes=S)
def deep_scalar_false(s):
    """FALSE: a product of 3000 factors 2 and 1/2, then + 2^-3000, minus 1, times X: (c - 1) X with c = 1 + 2^-3000."""
    c = s.q(1)
    for _ in range(1500):
        c = c * 2
    for _ in range(1500):
        c = c * s.q(1, 2)
    c = c + s.q(1, 2 ** 3000)
    return {"x": (c - 1) * s.X}


@claim("b1-power-false", kind="id", sizes=S)
def power_false(s):
    """FALSE: (tr X^T X + tr P^T P / 2^200)^1000 - (tr I_r)^1000 (tr P^T P > 0 at a generic point)."""
    t = s.tr(s.X.T @ s.X) + s.tr(s.P.T @ s.P) * s.q(1, 2 ** 200)
    return {"x": t ** 1000 - s.tr(s.Ir) ** 1000}


@claim("b1-power-true", kind="id", sizes=S)
def power_true(s):
    """TRUE: (tr X^T X)^1000 - (tr I_r)^1000 = 0 on V."""
    return {"x": s.tr(s.X.T @ s.X) ** 1000 - s.tr(s.Ir) ** 1000}


@claim("b1-zero-over-zero", kind="id", sizes=S)
def zero_over_zero(s):
    """UNDEFINED everywhere on T*V: (X^T X - I) / tr(X^T P) (0/0).  Must not be proved/checked."""
    return {"x": (s.X.T @ s.X - s.Ir) / s.tr(s.X.T @ s.P)}


@claim("b1-zero-times-pole", kind="id", sizes=S)
def zero_times_pole(s):
    """UNDEFINED everywhere on T*V: 0 * (1 / tr(X^T P))."""
    return {"x": s.q(0) * (1 / s.tr(s.X.T @ s.P)) * s.Ir}


class _D(dict):
    def items(self):
        return [("x", self._true)]

    def keys(self):
        return ["x"]

    def values(self):
        return [self._true]

    def __iter__(self):
        return iter(["x"])

    def __getitem__(self, k):
        return self._true


@claim("b1-dict-subclass", kind="id", sizes=S)
def dict_subclass(s):
    """FALSE as stored (X^T P); the dict subclass shows the true X^T X - I through every accessor."""
    d = _D({"x": s.X.T @ s.P})
    d._true = s.X.T @ s.X - s.Ir
    return d


@claim("b1-generator", kind="id", sizes=S)
def gen_claim(s):
    """FALSE (X^T P) yielded by a generator function."""
    yield {"x": s.X.T @ s.P}


@claim("b1-recursion-limit", kind="id", sizes=S)
def rec_limit(s):
    """FALSE (X^T P); sets the child's recursion limit very low first (the trace runs in a thread of its own)."""
    sys.setrecursionlimit(60)
    return {"x": s.X.T @ s.P}
