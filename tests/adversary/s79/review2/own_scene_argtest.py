"""W2 without state: the op tests its argument (the claim's own y) — the very test stop 79 refuses — and reads
t.X (moving) there, s.X (the claim's: a constant of a derived scene) elsewhere.  The value is taken at y, the
gradient at another generic y2 (so the gradient's inline call and the check's traced op both read s.X; the
value's call reads t.X and is compared with the check's op with the claim's scene standing for every scene).
h = quadratic(op), op(t, u) = c·u, c = tr(XᵀKX).  For ONE function h(t, u) = ½c(t)<u, u>, ∇h = c(t)u:
   A = d/dε h(t, y) = ½ċ<y, y>,   B = d/dε <y2, ∇h(t, y2)> = ċ<y2, y2>.
  s79r2-own-argtest-contradiction:  A = ½ċ<y, y> (≠ 0) and B = 0   FALSE (B = 0 forces ċ = 0 as <y2,y2> ≠ 0)
  s79r2-own-argtest-control:        op reads t.X always: A = ½ċ<y,y>, B = ċ<y2,y2>  TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _AB(s, test):
    y, y2, K = GL_N.generic(s, "y"), GL_N.generic(s, "y2"), GL_N.generic(s, "K")
    V = s.fresh("n", "r")

    def op(t, u):
        X = t.X if (u is y or not test) else s.X
        return u * t.tr(X.T @ K @ X)
    h = quadratic(op)
    A = s.d(lambda t: h(t, y), {"X": V})
    B = s.d(lambda t: t.killing(y2, h.grad(t, y2)), {"X": V})
    cdot = s.tr(V.T @ K @ s.X + s.X.T @ K @ V)
    return y, y2, cdot, A, B


@claim("s79r2-own-argtest-contradiction", kind="id", sizes=SZ)
def contra(s):
    y, y2, cdot, A, B = _AB(s, True)
    return {"A = ½ ċ <y, y>": A - cdot * s.killing(y, y) / 2, "B = 0": B}


@claim("s79r2-own-argtest-control", kind="id", sizes=SZ)
def control(s):
    y, y2, cdot, A, B = _AB(s, False)
    return {"A = ½ ċ <y, y>": A - cdot * s.killing(y, y) / 2, "B = ċ <y2, y2>": B - cdot * s.killing(y2, y2)}
