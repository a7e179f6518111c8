"""Free method: a check made on the claim's scene s (f.grad(s, x) inside the function of s.d) of a MatrixFunction
built inside that function, whose declared gradient reads the derivative's scene t.  FreeScene.
declared_gradient_holds strips the Dual parts of x and G (`point`, free/scene.py:1315-1319): on the claim's scene the
check compares G's point part only, and the derivative of G is taken as declared.

f(y) = <y, A> (value read from the scene it is given: u.killing(y, u.A)), so ∇f = A at every y, on every scene, and
d/dε ∇f(x) = 0 along every flow.   Declared gradient: A + K(t), K(t) = t.X (t.Xᵀ t.X M − M t.Xᵀ t.X) t.Xᵀ with M a
generic r×r matrix: K = X(M − M)Xᵀ = 0 at the claim's point (XᵀX = I), so the declared gradient is right there.
Along X + εV: dK = X (W M − M W) Xᵀ, W = VᵀX + XᵀV (r×r, symmetric).  At r = 1, W and M are numbers: dK = 0, the
declared gradient is right to first order too; at r >= 2, dK ≠ 0 for generic V, M.
  r81-fs-true:   d/dε ∇f(x) = 0                    TRUE  (every n, r)
  r81-fs-false:  d/dε ∇f(x) = X(WM − MW)Xᵀ         FALSE for r >= 2 (TRUE at r = 1, where it is 0)
The division probe of the free method runs the claim at (3, 1), where the check passes (dK = 0 there).
Variant x = s.A read inside the function: r81-fs2-true / r81-fs2-false.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _K(t, M):
    XtX = t.X.T @ t.X
    return t.X @ (XtX @ M - M @ XtX) @ t.X.T


def _dK(s, V, M):
    W = V.T @ s.X + s.X.T @ V
    return s.X @ (W @ M - M @ W) @ s.X.T


def _d(s, inside):
    M = s.generic("M", "r", "r")
    V = s.fresh("n", "r")
    x = GL_N.generic(s, "x")

    def body(t):
        f = MatrixFunction(lambda u, y: u.killing(y, u.A), lambda u, y: u.A + _K(t, M), "<y, A>")
        return f.grad(s, s.A if inside else x)
    return V, M, s.d(body, {"X": V})


@claim("r81-fs-true", kind="id", sizes=SZ)
def fs_true(s):
    V, M, d = _d(s, False)
    return {"d∇f(x) = 0": d}


@claim("r81-fs-false", kind="id", sizes=SZ)
def fs_false(s):
    V, M, d = _d(s, False)
    return {"d∇f(x) = X(WM − MW)Xᵀ": d - _dK(s, V, M)}


@claim("r81-fs2-true", kind="id", sizes=SZ)
def fs2_true(s):
    V, M, d = _d(s, True)
    return {"d∇f(A) = 0": d}


@claim("r81-fs2-false", kind="id", sizes=SZ)
def fs2_false(s):
    V, M, d = _d(s, True)
    return {"d∇f(A) = X(WM − MW)Xᵀ": d - _dK(s, V, M)}
