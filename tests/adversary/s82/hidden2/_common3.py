"""Helper of claims3/twins3 (no claims)."""
from __future__ import annotations

from stiefelsym import block


def VBV(s, sign=1):
    R = s.resolvent(s.lam)
    zr = s.zeros(s.r, s.r, ("r", "r"))
    V = block([[s.X, s.P], [zr, s.Ir]])
    B = block([[R * sign, s.zeros(s.n, s.r, ("n", "r"))], [s.zeros(s.r, s.n, ("r", "n")), s.Ir]])
    return V.T @ B @ V
