# ruff: noqa
"""The stop's own attempt on r_in, now sent from the claims file's child: a declaration that the statement's sizes
do not keep.  (I − XXᵀ)P = 0 holds at r = n only, XᵀP = 0 at r = 1 only."""
import dataclasses

from stiefelsym import admissible, claim
from stiefelsym.claims import SizeSpec


class Everywhere(SizeSpec):
    """Declares r = n, admits every size."""

    def admits(self, n, r):
        return 1 <= r <= n <= 4


@claim("own-rin-subclass", kind="id", sizes=Everywhere(admissible(n_max=4).sizes, r_in=("n",), condition="r = n"))
def subclass(s):
    """(I − XXᵀ)P = 0, declared at r = n by a statement that admits every size."""
    return {"r": (s.In - s.X @ s.X.T) @ s.P}


@claim("own-rin-listed", kind="id",
       sizes=dataclasses.replace(admissible(n_max=4, r_in=(1,)), sizes=(admissible(n_max=4).sizes)))
def listed(s):
    """XᵀP = 0, declared at r = 1 by a statement that lists every size up to n = 4."""
    return {"r": s.X.T @ s.P}


@claim("own-rin-false", kind="id", sizes=admissible(n_max=4, r_in=(1, "n")))
def false_at_r1(s):
    """(I − XXᵀ)P = 0 declared at r = 1 and r = n: false at r = 1 (n >= 2)."""
    return {"r": (s.In - s.X @ s.X.T) @ s.P}
