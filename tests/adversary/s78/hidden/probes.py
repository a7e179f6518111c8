# ruff: noqa
"""s78 hidden round: soundness probes next to the statements (not statements of the paper).  Each is FALSE in
general but TRUE at the special points of a reduced chart (X = X0, A11 / A22 diagonal, r = 1), so a reduction that
were applied where it does not hold would pass it.  fails_at = where numpy (indep_probes.py.in) finds it false."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim
from stiefelsym.bases import so_basis, sym_basis

from _h78_helpers import killing

ERR = "soundness probe (s78 hidden round)"


@claim("p78-phi-normal-entry", kind="id", sizes=admissible(n_max=5, where=lambda n, r: n - r >= 2),
       fails_at=lambda n, r: True, erratum=ERR)
def phi_normal_entry(s):
    """<E_{r+1} ∧ E_{r+2}, Φ> = Φ_{r+1,r+2}: zero at X0 = (E_1..E_r) (the (2,2) block of h is 0), not in general."""
    r = int(s.r)
    n = int(s.n)
    basis = so_basis(s, "n")
    idx = [(i, j) for i in range(n) for j in range(i + 1, n)].index((r, r + 1))
    return {"<E_r+1 ^ E_r+2, Phi>": killing(s, basis[idx], s.Phi)}


@claim("p78-xtax-offdiagonal", kind="id", sizes=admissible(n_max=5, r_min=2),
       fails_at=lambda n, r: True, erratum=ERR)
def xtax_offdiagonal(s):
    """tr((E_12 + E_21) XᵀAX) = 2(XᵀAX)_12: zero where the chart diagonalizes A11 = XᵀAX, not in general."""
    B = sym_basis(s, "r")[int(s.r)]          # E_12 + E_21 (after the r diagonal units)
    return {"(X^T A X)_12": s.tr(B @ s.X.T @ s.A @ s.X)}


@claim("p78-trace-ir-is-one", kind="id", sizes=admissible(n_max=4, n_min=3), fails_at=lambda n, r: r >= 2,
       erratum=ERR)
def trace_ir_is_one(s):
    """tr I_r = 1 with a graph that reads no point of T*V (only A and a generic ξ): false for r >= 2; a shortcut that
    computed it once per n at r = 1 would pass it."""
    return {"tr I_r - 1 + <xi, [A, A]>": s.tr(s.Ir) - 1 + killing(s, s.xi, s.A @ s.A - s.A @ s.A)}


@claim("p78-xtax-commutes-xta2x", kind="id", sizes=admissible(n_max=4, r_min=2), fails_at=lambda n, r: r < n,
       erratum=ERR)
def xtax_commutes(s):
    """[XᵀAX, XᵀA²X] = 0: false for 2 <= r < n; true at r = n (both are A, A² conjugated)."""
    M1, M2 = s.X.T @ s.A @ s.X, s.X.T @ s.A @ s.A @ s.X
    return {"[X^TAX, X^TA^2X]": M1 @ M2 - M2 @ M1}


@claim("p78-generic-r-commutes-psi", kind="id", sizes=admissible(n_max=4, r_min=2), fails_at=lambda n, r: True,
       erratum=ERR)
def generic_r_commutes_psi(s):
    """[S, XᵀAX] = 0 for a generic symmetric r×r S: false (a chart that moved S with h ∈ O(r) but fixed it would
    still see a generic S)."""
    S = s.generic("S", "r", "r", "sym")
    M = s.X.T @ s.A @ s.X
    return {"[S, X^TAX]": S @ M - M @ S}


@claim("p78-xtp-zero-r1", kind="id", sizes=admissible(n_max=5, r_max=1, condition="r = 1"), erratum="")
def xtp_zero_r1(s):
    """TRUE at r = 1 only (XᵀP + PᵀX = 0 is 2XᵀP = 0 there): a dimension-free proof must be one 'at r = 1'."""
    return {"X^T P": s.X.T @ s.P}


@claim("p78-xxt-identity-r-n", kind="id", sizes=admissible(n_max=4, r_is_n=True, condition="r = n"), erratum="")
def xxt_identity_r_n(s):
    """TRUE at r = n only (XXᵀ = I there): a dimension-free proof must be one 'at r = n'."""
    return {"XX^T - I": s.X @ s.X.T - s.In}
