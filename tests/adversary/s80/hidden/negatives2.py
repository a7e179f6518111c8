# ruff: noqa
"""s80 hidden round (h2): false twins of claims2.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, block, claim, det
from _h80_a2 import a2_checks


@claim("n80-a2-psi-zero-rad-n-plus-1", paper=("NEUMANN2", "A2"), kind="dim", sizes=admissible(n_max=4),
       fails_at=lambda n, r: True, erratum="twin: kernel dimension n + 1 in place of n",
       statement=r"\rank\Lambda_{1,-1}|_{\ker\Lambda_1}=r^2+(n-r)^2-(n+1)")
def n_a2_rad_r(s):
    """Twin of h80-a2-psi-zero: n + 1 in place of n."""
    return a2_checks(s, int(s.n) + 1)


@claim("n80-vv-pluecker-p", paper=("VV", "forms"), kind="geo", sizes=admissible(n_max=5),
       fails_at=lambda n, r: True, erratum="twin: the minor of P in place of X",
       statement=r"\det\mathcal V_{\{1..r\}\cup\{n+1..n+r\}}=\det P_{\{1..r\}}")
def n_vv_pluecker_p(s):
    """Twin of h80-vv-pluecker-span-e: det P_I in place of det X_I."""
    r = int(s.r)
    Xi, Pi = s.X[0:r, 0:r], s.P[0:r, 0:r]
    Z = s.zeros(r, r, ("r", "r"))
    V = block([[Xi, Pi], [Z, s.Ir]])
    return {"minor of V - minor of P": det(s, V) - det(s, Pi)}
