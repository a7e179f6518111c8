# ruff: noqa
"""s73 probes (not statements of their own): h73-twisted-psi12-any-kappa with Ψ_12 written without an entry read,
Ψ_12 = −½tr(FΨ), F = E_1∧E_2 (the dimension-free method refuses the entry read Ψ[0, 1] at r = 2)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, twisted
from _h73_helpers import H_quartic, Psi_of


def H_neum_kappa(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("p73-twisted-psi12-trace-form", paper=("twisted", "mag-euk", "mag-nor"), kind="pb",
       sizes=admissible(n_max=4, r_min=2, r_max=2, condition="r = 2"))
def twisted_psi12_trace_form(s):
    """h73-twisted-psi12-any-kappa with Ψ_12 = −½tr(FΨ) (no entry read)."""
    psi12 = lambda t: -t.tr(twisted.magnetic_matrix(t) @ Psi_of(t.X, t.P)) / 2
    fk = twisted.flow(s, H_neum_kappa)
    fq = twisted.flow(s, H_quartic)
    return {"dPsi12/dt (kappa)": s.d(psi12, fk), "dH/dt (kappa)": s.d(H_neum_kappa, fk),
            "dPsi12/dt (quartic)": s.d(psi12, fq)}
