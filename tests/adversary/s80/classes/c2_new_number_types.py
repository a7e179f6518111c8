"""Class 2: floats / foreign numbers in disguise, new types (python-flint, sympy, numpy 0-d, mpmath).

Each d2-<type> claim is FALSE: c·(XXᵀ − I_n) with c a nonzero (or tiny) constant of a foreign type; XXᵀ − I_n
is nonzero at r < n (XXᵀ has rank r).  d2-control is TRUE: (XᵀX − I_r)·2.
A foreign number that some method reads as 0 (a residue, a ball containing 0, an underflowed float) would pass.
"""
import mpmath
import numpy as np
import sympy
import flint

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)

VALUES = {
    "fmpz": lambda: flint.fmpz(3),
    "fmpq": lambda: flint.fmpq(1, 10 ** 400),
    "nmod": lambda: flint.nmod(5, 7),
    "arb0": lambda: flint.arb(0, 1),
    "fmpzmod": lambda: flint.fmpz_mod(0, flint.fmpz_mod_ctx(7)),
    "sympyrat": lambda: sympy.Rational(1, 3),
    "sympyint": lambda: sympy.Integer(2),
    "sympyzero": lambda: sympy.Float("1e-400"),
    "np0d": lambda: np.array(2),
    "npint": lambda: np.int64(2),
    "npobj": lambda: np.array(2, dtype=object),
    "mpf": lambda: mpmath.mpf("1e-400"),
}


def _make(name, mk, side):
    def body(s):
        c = mk()
        R = s.X @ s.X.T - s.In
        if side == "l":
            return {"r": c * R}
        if side == "q":
            return {"r": R * s.q(c, 1)}
        return {"r": R * c}
    body.__name__ = f"d2_{name}_{side}"
    body.__doc__ = f"FALSE: {name} constant times XXᵀ − I_n ({side})."
    return body


for _n, _mk in VALUES.items():
    for _side in ("l", "r", "q"):
        claim(f"d2-{_n}-{_side}", kind="id", sizes=SZ)(_make(_n, _mk, _side))


@claim("d2-control", kind="id", sizes=SZ)
def d2_control(s):
    """TRUE: 2·(XᵀX − I_r)."""
    return {"r": (s.X.T @ s.X - s.Ir) * 2}
