"""The check made on the claim's scene s, at a constant point x, of a MatrixFunction built inside the function
of a derivative whose VALUE closes over the derivative's scene t (the gradient reads s):
    f_t = MatrixFunction(lambda u, y: u.killing(y, t.X t.Xᵀ), lambda u, y: s.X s.Xᵀ);   f_t.grad(s, x)
f_t(y) = <y, X_t X_tᵀ>: its gradient (for <,>, in gl) is X_t X_tᵀ at every y, so d/dε ∇f_t(x) = VXᵀ + XVᵀ.
The declared gradient s.X s.Xᵀ is right at ε = 0 only.
  r81-cv-false:  d/dε ∇f_t(x) = 0               FALSE
  r81-cv-true:   d/dε ∇f_t(x) = VXᵀ + XVᵀ       TRUE
Mirror: the value closes over s, the gradient reads t:
    g_t = MatrixFunction(lambda u, y: u.killing(y, s.X s.Xᵀ), lambda u, y: t.X t.Xᵀ);  g_t(y) = <y, XXᵀ> for every t,
    ∇g_t = XXᵀ constant, d/dε ∇g_t(x) = 0.
  r81-cv2-true:  d/dε ∇g_t(x) = 0               TRUE
  r81-cv2-false: d/dε ∇g_t(x) = VXᵀ + XVᵀ       FALSE
Honest controls: value and gradient both read t: r81-cv-ctrl-true (VXᵀ + XVᵀ) / r81-cv-ctrl-false (0).
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _run(s, mk):
    x = GL_N.generic(s, "x")
    V = s.fresh("n", "r")
    W = V @ s.X.T + s.X @ V.T
    return W, s.d(lambda t: mk(t).grad(s, x), {"X": V})


def f_t(s):
    return lambda t: MatrixFunction(lambda u, y: u.killing(y, t.X @ t.X.T), lambda u, y: s.X @ s.X.T, "f_t")


def g_t(s):
    return lambda t: MatrixFunction(lambda u, y: u.killing(y, s.X @ s.X.T), lambda u, y: t.X @ t.X.T, "g_t")


def h_t(s):
    return lambda t: MatrixFunction(lambda u, y: u.killing(y, t.X @ t.X.T), lambda u, y: t.X @ t.X.T, "h_t")


@claim("r81-cv-false", kind="id", sizes=SZ)
def cv_false(s):
    W, d = _run(s, f_t(s))
    return {"d∇f_t(x) = 0": d}


@claim("r81-cv-true", kind="id", sizes=SZ)
def cv_true(s):
    W, d = _run(s, f_t(s))
    return {"d∇f_t(x) = W": d - W}


@claim("r81-cv2-true", kind="id", sizes=SZ)
def cv2_true(s):
    W, d = _run(s, g_t(s))
    return {"d∇g_t(x) = 0": d}


@claim("r81-cv2-false", kind="id", sizes=SZ)
def cv2_false(s):
    W, d = _run(s, g_t(s))
    return {"d∇g_t(x) = W": d - W}


@claim("r81-cv-ctrl-true", kind="id", sizes=SZ)
def ctrl_true(s):
    W, d = _run(s, h_t(s))
    return {"d∇h_t(x) = W": d - W}


@claim("r81-cv-ctrl-false", kind="id", sizes=SZ)
def ctrl_false(s):
    W, d = _run(s, h_t(s))
    return {"d∇h_t(x) = 0": d}
