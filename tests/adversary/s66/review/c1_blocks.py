# ruff: noqa
"""Class 1 (entries read through a block / constant R^n matrices): engine constant steps that are
coordinate matrices of R^n (twisted.reflection, eigenspace_projector), read through blocks and traces.
Every statement here is FALSE on T*V (it holds at X0 = (E1..Er) only)."""
from stiefelsym import admissible, claim, twisted, block

S = admissible(n_min=3, n_max=4, r_in=(2,))


@claim("c1-refl-trace", kind="id", sizes=S)
def refl_trace(s):
    """tr(X^T S1 X) = r - 2: true at X0 only."""
    R = twisted.reflection(s)
    return {"x": s.tr(s.X.T @ R @ s.X) - (s.r - 2)}


@claim("c1-eig-trace", kind="id", sizes=S)
def eig_trace(s):
    """tr(X^T D X) = 2 (D = diag(I2, 0)): true at X0 only (r = 2)."""
    D = twisted.eigenspace_projector(s)
    return {"x": s.tr(s.X.T @ D @ s.X) - 2}


@claim("c1-eig-fixes-X", kind="id", sizes=S)
def eig_fix(s):
    """D X = X: true at X0 only."""
    D = twisted.eigenspace_projector(s)
    return {"x": D @ s.X - s.X}


@claim("c1-refl-block", kind="id", sizes=S)
def refl_block(s):
    """the block [[S1 X, X]] times [[I],[I]] read through a block: S1 X + X = 2 X - 2 e1 e1^T X."""
    R = twisted.reflection(s)
    B = block([[R @ s.X, s.X]])
    J = block([[s.Ir], [s.Ir]])
    C = B @ J                   # S1 X + X, an n x r matrix: at X0 its first column is 0
    return {"x": C @ twisted.basis_vector(s, 0)}


@claim("c1-refl-commutes-XXt", kind="id", sizes=S)
def refl_comm(s):
    """S1 X X^T = X X^T S1: true at X0 only."""
    R = twisted.reflection(s)
    return {"x": R @ s.X @ s.X.T - s.X @ s.X.T @ R}


@claim("c1-refl-Phi", kind="id", sizes=S)
def refl_phi(s):
    """tr(S1 Phi S1 Phi) = tr(Phi Phi): false in general."""
    R = twisted.reflection(s)
    return {"x": s.tr(R @ s.Phi @ R @ s.Phi) - s.tr(s.Phi @ s.Phi)}
