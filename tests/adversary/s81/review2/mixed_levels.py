"""A check on the derivative's scene t at a point that moves with ANOTHER scene's numbers: s.gradient (of the
claim's scene s, an enclosing scene of t) taken inside the function of s.d, of H_t(u) = <f_t.grad(t, u.X u.Xᵀ), B>.
The check is on t (dual numbers of the flow X + εV), the point on s's gradient scene u (a tape, or forward passes).
  f_t: value ½<y, y> c(w), gradient y c(w), c(w) = tr(w.Xᵀ w.X)   (honest: ∇ = y c for every scene w)
  H_t(u) = <u.X u.Xᵀ, B> c(t),  ∂H_t/∂X (at s's point, which does not move with t) = −½(B + Bᵀ)X c(t),
  d/dε along V:  −½(B + Bᵀ)X · 2 tr(XᵀV) = −(B + Bᵀ)X tr(XᵀV).
  r81b-ml-true:   d/dε ∂H_t/∂X = −(B + Bᵀ)X tr(XᵀV)        TRUE
  r81b-ml-false:  d/dε ∂H_t/∂X = 0                          FALSE
Dishonest variant g_t: gradient y c(w) + (c(w) − c_s)·y², c_s = tr(s.Xᵀ s.X) (right at ε = 0 only, and only at t):
  its check on t must refuse (dual parts differ by 2tr(XᵀV)·x²); any verdict must be that of the value:
  r81b-ml2-true:  same right-hand side as ml-true (the value's)    TRUE of the functions as values
  r81b-ml2-false: d/dε ∂H/∂X = −(B+Bᵀ)X tr(XᵀV) + d/dε ∂<(c(t) − c_s) x_u², B>/∂X   FALSE (the declared one)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def c(w):
    return w.tr(w.X.T @ w.X)


def _f():
    return MatrixFunction(lambda w, y: w.killing(y, y) * c(w) / 2, lambda w, y: y * c(w), "½<y,y>c")


def _g(s):
    cs = c(s)
    return MatrixFunction(lambda w, y: w.killing(y, y) * c(w) / 2, lambda w, y: y * c(w) + y @ y * (c(w) - cs), "g")


def _run(s, f):
    B, V = GL_N.generic(s, "B"), s.fresh("n", "r")
    d = s.d(lambda t: s.gradient(lambda u: u.killing(f.grad(t, u.X @ u.X.T), B))[0], {"X": V})
    rhs = (B + B.T) @ s.X * s.tr(s.X.T @ V) * (-1)
    return d, rhs, B, V


@claim("r81b-ml-true", kind="id", sizes=SZ)
def ml_true(s):
    d, rhs, B, V = _run(s, _f())
    return {"d ∂H/∂X = −(B+Bᵀ)X tr(XᵀV)": d - rhs}


@claim("r81b-ml-false", kind="id", sizes=SZ)
def ml_false(s):
    d, rhs, B, V = _run(s, _f())
    return {"d ∂H/∂X = 0": d}


@claim("r81b-ml2-true", kind="id", sizes=SZ)
def ml2_true(s):
    d, rhs, B, V = _run(s, _g(s))
    return {"d ∂H/∂X = −(B+Bᵀ)X tr(XᵀV)": d - rhs}


@claim("r81b-ml2-false", kind="id", sizes=SZ)
def ml2_false(s):
    d, rhs, B, V = _run(s, _g(s))
    extra = s.d(lambda t: s.gradient(lambda u: u.killing(u.X @ u.X.T @ u.X @ u.X.T, B) * (c(t) - c(s)))[0], {"X": V})
    return {"d ∂H/∂X = declared": d - rhs - extra}
