"""Trace identities that hold only for small r or small n (Cayley-Hamilton of low-rank skew matrices).
Each is stated for every n, r (admissible with a small default n_max): the dimension-free method must not
prove them for all n, r.  Docstrings state the truth."""
from stiefelsym import admissible, claim


@claim("s75-psi-quartic", kind="id", sizes=admissible(n_max=3))
def psi_quartic(s):
    """(tr Ψ²)² = 2 tr Ψ⁴: TRUE for r <= 3 (a skew r x r matrix has one pair ±ic), FALSE for r >= 4."""
    P2 = s.Psi @ s.Psi
    return {"w": s.tr(P2) * s.tr(P2) - s.tr(P2 @ P2) * 2}


@claim("s75-phi-cubic", kind="id", sizes=admissible(n_max=3))
def phi_cubic(s):
    """Φ³ = ½ tr(Φ²) Φ: TRUE when rank Φ <= 2 (r = 1, or n <= 3), FALSE at (4,2)."""
    F2 = s.Phi @ s.Phi
    return {"w": F2 @ s.Phi - s.Phi * s.tr(F2) / 2}


@claim("s75-phi-from-psi", kind="id", sizes=admissible(n_max=3, n_min=2, r_min=2))
def phi_from_psi(s):
    """Φ = X Ψ Xᵀ: TRUE at r = n only (P = XXᵀP there), FALSE for r < n."""
    return {"w": s.Phi - s.X @ s.Psi @ s.X.T}


@claim("s75-psi-quartic-r3", kind="id", sizes=admissible(n_max=5, r_min=3, r_max=3))
def psi_quartic_r3(s):
    """(tr Ψ²)² = 2 tr Ψ⁴ stated at r = 3 only: TRUE."""
    P2 = s.Psi @ s.Psi
    return {"w": s.tr(P2) * s.tr(P2) - s.tr(P2 @ P2) * 2}


@claim("s75-psi-quartic-r4", kind="id", sizes=admissible(n_max=5, r_min=4, r_max=4))
def psi_quartic_r4(s):
    """(tr Ψ²)² = 2 tr Ψ⁴ stated at r = 4 only: FALSE."""
    P2 = s.Psi @ s.Psi
    return {"w": s.tr(P2) * s.tr(P2) - s.tr(P2 @ P2) * 2}
