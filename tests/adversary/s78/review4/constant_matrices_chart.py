"""Constant matrices of twisted (reflection S1, eigenspace projector D, kernel frame W) are not O(n)-covariant:
the equivariant chart (A -> gAg^T general symmetric) must not be taken with them.  A = diag(a) commutes with S1 and
with D (TRUE); A S1 − S1 A + (anything nonzero) is FALSE.  Under the equivariant chart the true twin would fail."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import reflection, eigenspace_projector, kernel_frame, kernel_annihilator

SZ = admissible(n_max=3, n_min=2)


@claim("r4-refl-commutes-true", kind="id", sizes=SZ)
def refl_true(s):
    S = reflection(s)
    return {"S1 A - A S1": S @ s.A - s.A @ S, "X^T S1 A S1 X - X^T A X": s.X.T @ S @ s.A @ S @ s.X - s.X.T @ s.A @ s.X}


@claim("r4-proj-commutes-true", kind="id", sizes=SZ)
def proj_true(s):
    D = eigenspace_projector(s)
    return {"tr(X^T (D A - A D) P)": s.tr(s.X.T @ (D @ s.A - s.A @ D) @ s.P)}


@claim("r4-proj-commutes-false", kind="id", sizes=SZ)
def proj_false(s):
    D = eigenspace_projector(s)
    return {"tr(X^T (D A - A D) P) - tr(X^T D P)": s.tr(s.X.T @ (D @ s.A - s.A @ D) @ s.P) - s.tr(s.X.T @ D @ s.P)}


@claim("r4-annihilator-true", kind="id", sizes=SZ)
def ann_true(s):
    W, K = kernel_frame(s), kernel_annihilator(s)
    return {"K W": K @ W, "tr(X^T K W P^T X)": s.tr(s.X.T @ K @ W @ s.P.T @ s.X)}
