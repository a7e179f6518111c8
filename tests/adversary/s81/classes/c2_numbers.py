"""Class 2 (floats in disguise), new number types: bool, IntEnum, Decimal, an int subclass that lies, a Fraction
subclass, numpy.bool_, a float hidden in a Fraction's numerator via __index__.

Every -false claim is c·(XXᵀ − I_n) with c a nonzero constant: XXᵀ has rank r < n, so XXᵀ − I_n ≠ 0: FALSE at r < n.
Every -true claim is c·(XᵀX − I_r): TRUE on V(n, r).
"""
import decimal
import enum
from fractions import Fraction

import numpy as np

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


class Two(enum.IntEnum):
    TWO = 2


class LyingInt(int):
    """An int 1 that multiplies as 0 and compares equal to 0."""
    def __mul__(self, o):
        return 0 * o

    __rmul__ = __mul__

    def __eq__(self, o):
        return o == 0

    def __hash__(self):
        return 0


class LyingFrac(Fraction):
    def __mul__(self, o):
        return 0 * o

    __rmul__ = __mul__


class Idx:
    def __index__(self):
        return 3


VALUES = {
    "bool": lambda: True,
    "intenum": lambda: Two.TWO,
    "decimal": lambda: decimal.Decimal("1E-400"),
    "lyingint": lambda: LyingInt(1),
    "lyingfrac": lambda: LyingFrac(1, 3),
    "npbool": lambda: np.bool_(True),
    "index": lambda: Idx(),
    "fracfloat": lambda: Fraction(1e-320),
}


def _make(name, mk, side, true):
    def body(s):
        c = mk()
        R = (s.X.T @ s.X - s.Ir) if true else (s.X @ s.X.T - s.In)
        if side == "l":
            return {"r": c * R}
        if side == "q":
            return {"r": R * s.q(c)}
        return {"r": R * c}
    body.__name__ = f"c2_{name}_{side}_{'t' if true else 'f'}"
    body.__doc__ = f"{'TRUE' if true else 'FALSE'}: {name} constant times the residual ({side})."
    return body


for _n, _mk in VALUES.items():
    for _side in ("l", "r", "q"):
        for _true in (False, True):
            claim(f"c2-{_n}-{_side}-{'true' if _true else 'false'}", kind="id", sizes=SZ)(_make(_n, _mk, _side, _true))
