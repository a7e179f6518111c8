"""A step's parameter that the step's function does not read is skipped by the substitution of _holds (x < 0 or
y < 0: continue), so the reference's ARGUMENT stays in place as if it were a constant of the function.

op(t, u) = u² − u at the claim's y and at M = XXᵀ (u is y, u is M), and the constant M² − M elsewhere (at the
check's parameter).  M² − M = X(XᵀX − I)Xᵀ = 0 on V(n, r): the check's op is the zero operator (linear and
symmetric), the op the claim's value computes with is u ↦ u² − u (not linear).  Calls of op:
  the check's function (scene k, parameter u): M² − M, reads neither → entries (−1, −1001);
  h(t, M) on a derivative's scene t: M² − M, where M is the argument → the reference (another scene);
  h(s, y) on the claim's scene: y² − y.
The reference's graph as a function of its argument is u ↦ u² − u (so y's call holds by shape); the check's
call holds by "substitution" with nothing substituted (both entries skipped): M² − M is M² − M.
Truth (by hand): whatever h is, if h(y) = ½<y, y² − y> at a generic y (an identity in y), then its derivative at
M along E is ½<E, M² − M> + ½<M, EM + ME − E> = ½<M, EM + ME − E> = ½ c·tr(M(EM + ME − E)) = ½ c·tr(ME)
(M symmetric, M² = M; <a, b> = c·tr(ab) or c·tr(aᵀb)), which is not 0 at E = M (tr M = r): ∇h(M) = ½M ≠ 0.
  s80r-quad-unread-contradiction: {h(y) = ½<y, y² − y>, ∇h(M) = 0}                                  FALSE
  s80r-quad-unread-honest-false:  pure op u ↦ u² − u: {h(y) = ½<y, y² − y>, ∇h(M) = 0}  (refused: not linear)
  s80r-quad-unread-control-true:  the zero op: {h(y) = 0, ∇h(M) = 0}                                    TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _run(s, op_of):
    y = GL_N.generic(s, "y")
    M = s.X @ s.X.T
    V = s.fresh("n", "r")
    h = quadratic(op_of(y, M))
    return y, M, {"h(y)": h(s, y), "∇h(M)": h.grad(s, M), "d h(M) (M kept)": s.d(lambda t: h(t, M), {"X": V})}


@claim("s80r-quad-unread-contradiction", kind="id", sizes=SZ)
def contra(s):
    def op_of(y, M):
        return lambda t, u: u @ u - u if (u is y or u is M) else M @ M - M
    y, M, c = _run(s, op_of)
    return {"h(y) − ½<y, y² − y>": c["h(y)"] - s.killing(y, y @ y - y) / 2, "∇h(M)": c["∇h(M)"],
            "d h(M)": c["d h(M) (M kept)"]}


@claim("s80r-quad-unread-honest-false", kind="id", sizes=SZ)
def honest(s):
    y, M, c = _run(s, lambda y, M: (lambda t, u: u @ u - u))
    return {"h(y) − ½<y, y² − y>": c["h(y)"] - s.killing(y, y @ y - y) / 2, "∇h(M)": c["∇h(M)"],
            "d h(M)": c["d h(M) (M kept)"]}


@claim("s80r-quad-unread-control-true", kind="id", sizes=SZ)
def control(s):
    y, M, c = _run(s, lambda y, M: (lambda t, u: M @ M - M))
    return {"h(y)": c["h(y)"], "∇h(M)": c["∇h(M)"], "d h(M)": c["d h(M) (M kept)"]}


@claim("s80r-quad-unread-reads-param", kind="id", sizes=SZ)
def reads_param(s):
    """Diagnosis control: the same op, its check's function READING its parameter (M² − M + (u − u)): the
    parameter is then substituted, and the claim is refused (expected: error)."""
    def op_of(y, M):
        return lambda t, u: u @ u - u if (u is y or u is M) else M @ M - M + (u - u)
    y, M, c = _run(s, op_of)
    return {"h(y) − ½<y, y² − y>": c["h(y)"] - s.killing(y, y @ y - y) / 2, "∇h(M)": c["∇h(M)"],
            "d h(M)": c["d h(M) (M kept)"]}
