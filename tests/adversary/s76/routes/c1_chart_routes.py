"""Class 1: entries read through constant / untyped matrices so that an equivariant chart stays in use.

At the right-reduced equivariant chart A11 = XᵀAX is diagonal, at the diagonal chart A is diagonal.
Each claim below reads an off-diagonal entry without an `entry` node.  All FALSE at (3,2) unless said.
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


@claim("c1-mat-rr-offdiag", paper="t", kind="id", section="0", sizes=SZ)
def mat_rr(s):
    """E11 (XᵀAX) E22 = 0 with E11, E22 r×r constant matrices of s.mat tagged (r, r). FALSE."""
    r = 2  # noqa: F841
    E11 = s.mat([[1, 0], [0, 0]], ("r", "r"))
    E22 = s.mat([[0, 0], [0, 1]], ("r", "r"))
    return {"x": E11 @ s.X.T @ s.A @ s.X @ E22}


@claim("c1-mat-untyped-offdiag", paper="t", kind="id", section="0", sizes=SZ)
def mat_untyped(s):
    """Untyped ('?') constant 2×2 matrices around XᵀAX. FALSE."""
    E11 = s.mat([[1, 0], [0, 0]])
    E22 = s.mat([[0, 0], [0, 1]])
    return {"x": E11 @ (s.X.T @ s.A @ s.X) @ E22}


@claim("c1-mat-trace-asym", paper="t", kind="id", section="0", sizes=SZ)
def mat_trace(s):
    """tr(N XᵀAX) = 0 with N = [[0,1],[-1,0]]... that is 0 (XᵀAX symmetric) -- control TRUE;
    and tr(M XᵀAX) with M = [[0,1],[0,0]] (reads the (2,1) entry): FALSE."""
    N = s.mat([[0, 1], [-1, 0]], ("r", "r"))  # noqa: F841
    M = s.mat([[0, 1], [0, 0]], ("r", "r"))
    return {"x": s.tr(M @ s.X.T @ s.A @ s.X)}


@claim("c1-mat-trace-asym-control", paper="t", kind="id", section="0", sizes=SZ)
def mat_trace_control(s):
    """tr(N XᵀAX) = 0 with N skew constant: TRUE."""
    N = s.mat([[0, 1], [-1, 0]], ("r", "r"))
    return {"x": s.tr(N @ s.X.T @ s.A @ s.X)}


@claim("c1-mat-scalar-rr", paper="t", kind="id", section="0", sizes=SZ)
def mat_scalar(s):
    """D Ψ - Ψ D = 0 with D = diag(1, 2) constant on R^r: FALSE (Ψ generic skew)."""
    D = s.mat([[1, 0], [0, 2]], ("r", "r"))
    return {"x": D @ s.Psi - s.Psi @ D}


@claim("c1-diagA-mat-nn", paper="t", kind="id", section="0", sizes=SZ)
def diag_chart(s):
    """A E12 - E12 A has zero (1,2)... (reads A only: the diagonal chart): tr(E12 A) = 0 with
    E12 a constant n×n matrix given through s.identity slices avoided: s.mat tagged (n, n). FALSE."""
    E = s.mat([[0, 1, 0], [0, 0, 0], [0, 0, 0]], ("n", "n"))
    return {"x": s.tr(E @ s.A)}


@claim("c1-diagA-resolvent-mat", paper="t", kind="id", section="0", sizes=SZ)
def diag_chart_untyped(s):
    """tr(E R(λ)) = 0, E untyped constant 3×3 with one off-diagonal 1. FALSE."""
    E = s.mat([[0, 1, 0], [0, 0, 0], [0, 0, 0]])
    return {"x": s.tr(E @ s.resolvent(s.lam))}


@claim("c1-killing-const", paper="t", kind="id", section="0", sizes=SZ)
def killing_const(s):
    """<E, Ψ> = 0 with E = [[0,1],[-1,0]] on R^r: FALSE (Ψ12 ≠ 0)."""
    E = s.mat([[0, 1], [-1, 0]], ("r", "r"))
    return {"x": s.killing(E, s.Psi)}


@claim("c1-scalarmatrix-r", paper="t", kind="id", section="0", sizes=SZ)
def scalar_matrix_control(s):
    """scalar_matrix(3, r) Ψ − 3Ψ = 0: TRUE (control)."""
    return {"x": s.scalar_matrix(3, "r") @ s.Psi - 3 * s.Psi}
