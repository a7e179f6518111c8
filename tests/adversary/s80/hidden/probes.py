# ruff: noqa
"""s80 (h2) probes: not statements of the paper.  Rank twins below the truth (refutable), and coordinate reads
of X through the Plücker minor (a false 'minor = 1' that holds at X0 = (E_1..E_r), the exact method's chart)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, block, claim, det
from stiefelsym.bases import matrix_of, matrix_units

from _h80_helpers import lam1_vec, lam2_vec
from claims import semidirect_tensor


@claim("p80-theta1-rank-minus-2", kind="dim", sizes=admissible(n_max=5), fails_at=lambda n, r: True,
       erratum="probe: rank 2 below the truth")
def p_theta1_minus_2(s):
    """Probe: the rank of the semi-direct tensor at Θ₁(X, P) claimed 2 below dim T*V (false everywhere)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(semidirect_tensor(s, s.Phi, s.X), 2 * n * r - r * (r + 1) - 2)}


@claim("p80-a1-rank-minus-2", kind="dim", sizes=admissible(n_max=4, n_min=2), fails_at=lambda n, r: True,
       erratum="probe: rank 2 below the truth")
def p_a1_minus_2(s):
    """Probe: rank Λ_{1,1} at Θ(Ψ⁻¹(0)) claimed n² − n − 2 (false)."""
    n = int(s.n)
    Pt = s.P - s.X @ (s.X.T @ s.P)
    x = (Pt @ s.X.T - s.X @ Pt.T) + s.X @ s.X.T
    M = matrix_of(s, lambda y: lam1_vec(x, y) + lam2_vec(x, s.A, y), matrix_units(s, "n", "n"))
    return {"rank": Rank(M, n * n - n - 2)}


@claim("p80-minor-x-is-one", kind="geo", sizes=admissible(n_max=4), fails_at=lambda n, r: r < n,
       erratum="probe: det X_{1..r} = 1 holds only at X0 (and at r = n up to the sign of det X)")
def p_minor_one(s):
    """Probe: the Plücker minor of 𝒱 on rows {1..r} ∪ {n+1..n+r} equals 1 — false for r < n (it is det X_{1..r});
    true at X0 = (E_1..E_r), the exact method's chart point.  At r = n det X = ±1 (both components: false too)."""
    r = int(s.r)
    Xi, Pi = s.X[0:r, 0:r], s.P[0:r, 0:r]
    V = block([[Xi, Pi], [s.zeros(r, r, ("r", "r")), s.Ir]])
    return {"minor - 1": det(s, V) - 1}


@claim("p80-minor-x-squared-r-n", kind="geo", sizes=admissible(n_max=4, r_is_n=True))
def p_minor_sq(s):
    """Probe (true): at r = n, (det X)² = 1 (X ∈ O(n)), read through the minor of 𝒱."""
    r = int(s.r)
    V = block([[s.X, s.P], [s.zeros(r, r, ("r", "r")), s.Ir]])
    d = det(s, V)
    return {"minor^2 - 1": d * d - 1}
