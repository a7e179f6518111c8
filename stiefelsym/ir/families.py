"""Families of sizes: the sizes (n, r) of a claim stated at one r, for every n.

A claim stated at r = 1, at r = 2 or at r = n (or at a union of these) is traced
once per family, with its sizes symbolic.  A question about the sizes (a number
of a size, a comparison of two) is answered in such a trace when its answer is
the same at every size of the family, and refused otherwise: r is the number 1
in the family r = 1; r == n is true in the family r = n and false in the family
r = 1, n >= 2; n == 3 is refused in both.  So the graph traced with a family is
the graph traced at each of its sizes (every answer the trace gave is the one a
trace at that size gives), and a proof about it is a proof at each of them.
"""
from __future__ import annotations

import operator
from dataclasses import dataclass
from typing import Any

from stiefelsym.ir.graph import Size

#: the comparisons of sizes a family may decide, by the name of their method
COMPARISONS = {"__eq__": operator.eq, "__ne__": operator.ne, "__lt__": operator.lt, "__le__": operator.le,
               "__gt__": operator.gt, "__ge__": operator.ge}
#: their symbols, for messages
SYMBOLS = {"__eq__": "==", "__ne__": "!=", "__lt__": "<", "__le__": "<=", "__gt__": ">", "__ge__": ">="}


@dataclass(frozen=True)
class SizeFamily:
    """The sizes (n, r) with r = ``r`` (r = n when ``r`` is None) and n >= ``n_min``, for every such n."""

    r: int | None
    n_min: int
    #: one r of a claim stated at every r (``free_max_r``: a proof on it is used at a size whose graph is the
    #: family's, :mod:`stiefelsym.methods.specialise`), not a family the claim's statement declares
    one_of_every_r: bool = False

    def __post_init__(self) -> None:
        if self.r is not None and (type(self.r) is not int or self.r < 1):
            raise ValueError(f"a family of sizes has r = n or r = k >= 1, not r = {self.r!r}")
        if type(self.n_min) is not int or self.n_min < max(1, self.r or 1):
            raise ValueError(f"the family r = {self.r or 'n'} starts at n >= {max(1, self.r or 1)}, "
                             f"not n >= {self.n_min!r}")

    def __str__(self) -> str:
        return f"r = {'n' if self.r is None else self.r} (n >= {self.n_min})"

    @property
    def r_text(self) -> str:
        """"r = 1", "r = n"."""
        return f"r = {'n' if self.r is None else self.r}"

    def holds(self, n: int, r: int) -> bool:
        """Whether (n, r) is a size of the family."""
        return n >= self.n_min and r == (n if self.r is None else self.r)

    def number(self, size: Size) -> int | None:
        """The number of the size k·d when it is the same at every size of the family (k·r at r = k), else None."""
        if size.d == "r" and self.r is not None:
            return size.k * self.r
        return None

    def _affine(self, x: Any) -> tuple[int, int]:
        """x (an int or a size k·d) as a·n + b on the family."""
        if type(x) is int:
            return 0, x
        if x.d == "r" and self.r is not None:
            return 0, x.k * self.r
        return x.k, 0       # k·n, or k·r = k·n in the family r = n

    def decide(self, a: Any, name: str, b: Any) -> bool | None:
        """The comparison ``a name b`` of two sizes (or a size and an int) when it has the same truth value at
        every size of the family, else None.  On the family a − b is an affine function s·n + c of n >= n_min:
        constant when s = 0, otherwise monotone and unbounded, so its truth value changes at most once."""
        (p, q), (u, v) = self._affine(a), self._affine(b)
        s, c = p - u, q - v
        cmp = COMPARISONS[name]
        if s == 0:
            return cmp(c, 0)
        if name in ("__eq__", "__ne__"):
            root = -c // s if (-c) % s == 0 else None      # the one n at which s·n + c = 0, if an integer
            if root is not None and root >= self.n_min:
                return None
            return name == "__ne__"
        first, eventually = cmp(s * self.n_min + c, 0), cmp(s, 0)
        return first if first == eventually else None
