"""free_strip.py's route for quadratic's operator: quadratic(op).grad(s, x) inside the function of s.d, the op
reading the derivative's scene t: op_t(v) = v + K(t) v, K(t) = t.X (t.Xᵀt.X M − M t.Xᵀt.X) t.Xᵀ (0 on V(n, r)).
At the claim's point op = identity (symmetric).  Along X + εV, op_ε = I + ε dK(·) with dK = X(WM − MW)Xᵀ,
W = VᵀX + XᵀV, which is not symmetric for <,> (dKᵀ ≠ dK for r >= 2): op_ε is not the gradient operator of
h_ε(y) = ½<y, op_ε y>; that function's gradient is ½(op_ε + op_εᵀ)y = y + ε·½(dK + dKᵀ)y... (the adjoint for <,>
of v ↦ Kv is v ↦ Kᵀv), so the true d/dε ∇h_ε(x) = ½(dK + dKᵀ)x, the declared one dK x.
  r81-fq-true:  d/dε ∇h(x) = ½(dK + dKᵀ) x     TRUE
  r81-fq-false: d/dε ∇h(x) = dK x               FALSE for r >= 2 (at r = 1, dK = 0 and both are 0)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _K(t, M):
    XtX = t.X.T @ t.X
    return t.X @ (XtX @ M - M @ XtX) @ t.X.T


def _dK(s, V, M):
    W = V.T @ s.X + s.X.T @ V
    return s.X @ (W @ M - M @ W) @ s.X.T


def _d(s):
    M = s.generic("M", "r", "r")
    V = s.fresh("n", "r")
    x = GL_N.generic(s, "x")

    def body(t):
        h = quadratic(lambda u, v: v + _K(t, M) @ v, "½<y, y + Ky>")
        return h.grad(s, x)
    return x, V, M, s.d(body, {"X": V})


@claim("r81-fq-true", kind="id", sizes=SZ)
def fq_true(s):
    x, V, M, d = _d(s)
    D = _dK(s, V, M)
    return {"d∇h = ½(dK + dKᵀ)x": d - (D + D.T) @ x / 2}


@claim("r81-fq-false", kind="id", sizes=SZ)
def fq_false(s):
    x, V, M, d = _d(s)
    return {"d∇h = dK x": d - _dK(s, V, M) @ x}
