"""A correction true at r <= 3 only, for a claim stated at every r."""
from stiefelsym import admissible, claim


@claim("s73-psi-quartic", kind="id", sizes=admissible(n_max=3))
def psi_quartic(s):
    """(tr Psi^2)^2 - 2 tr Psi^4 = 1: FALSE at every size.  Its mutant with 0 on the right is TRUE at r <= 3 only
    (Psi skew r x r: eigenvalues +-i a, +-i b, ...; at r = 4 the left side is 8 a^2 b^2)."""
    Q = s.Psi @ s.Psi
    return {"quartic": s.tr(Q) * s.tr(Q) - 2 * s.tr(Q @ Q) - 1}


@claim("s73-psi-quartic-zero", kind="id", sizes=admissible(n_max=5))
def psi_quartic_zero(s):
    """(tr Psi^2)^2 - 2 tr Psi^4 = 0: TRUE at r <= 3, FALSE at r >= 4."""
    Q = s.Psi @ s.Psi
    return {"quartic": s.tr(Q) * s.tr(Q) - 2 * s.tr(Q @ Q)}
