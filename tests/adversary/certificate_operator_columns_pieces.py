"""Route S again, at the base point: the argument of the operator letter AA passes through the columns of
R^r (r = 2), so a 1x1 piece (E2^T X^T P E1, E2^T E2 ...) sits inside it.  AA is linear and a 1x1 matrix is
its own trace, so the piece is a scalar factor; the free algebra takes it out of the argument when the
letter is made (the rules act outside operator letters only).  The true claims are proved with a
certificate the checker accepts; the false one (a sign of the piece flipped) is not."""
from stiefelsym import admissible, claim
from stiefelsym import twisted

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2)


def E(s, i):
    return twisted.basis_vector(s, i)


@claim("adv-opcols-linear", kind="id", sizes=R2)
def opcols_linear(s):
    """AA(a (E2^T X^T P E1) b) = (E2^T X^T P E1) AA(a b): a 1x1 piece of an argument is a scalar (true)."""
    AA = s.sym_operator("AA")
    c = s.tr(E(s, 1).T @ s.X.T @ s.P @ E(s, 0))
    return {"r": AA(s.X @ E(s, 0) @ E(s, 1).T @ s.X.T @ s.P @ E(s, 0) @ E(s, 1).T @ s.X.T)
            - c * AA(s.X @ E(s, 0) @ E(s, 1).T @ s.X.T)}


@claim("adv-opcols-unit-piece", kind="id", sizes=R2)
def opcols_unit_piece(s):
    """AA(P E1 E2^T E2 E1^T X^T) = AA(P E1 E1^T X^T) (E2^T E2 = 1 inside the argument), and the trace
    symmetry with pieces on either side (true)."""
    AA = s.sym_operator("AA")
    u = s.P @ E(s, 1) @ E(s, 1).T @ s.X.T
    v = s.X @ E(s, 0) @ E(s, 1).T @ s.X.T @ s.P @ E(s, 1) @ E(s, 0).T @ s.X.T
    return {"unit": AA(s.P @ E(s, 0) @ E(s, 1).T @ E(s, 1) @ E(s, 0).T @ s.X.T) - AA(s.P @ E(s, 0) @ E(s, 0).T @ s.X.T),
            "symmetry": s.tr(AA(u) @ v) - s.tr(AA(v) @ u)}


@claim("adv-opcols-linear-sign", kind="id", sizes=R2)
def opcols_linear_sign(s):
    """The piece with the wrong sign (false: E2^T X^T P E1 is not 0)."""
    AA = s.sym_operator("AA")
    c = s.tr(E(s, 1).T @ s.X.T @ s.P @ E(s, 0))
    return {"r": AA(s.X @ E(s, 0) @ E(s, 1).T @ s.X.T @ s.P @ E(s, 0) @ E(s, 1).T @ s.X.T)
            + c * AA(s.X @ E(s, 0) @ E(s, 1).T @ s.X.T)}
