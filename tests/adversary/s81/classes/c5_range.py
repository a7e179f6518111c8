"""Class 5 (float underflow/overflow), new tricks: constants inside float64's range whose PRODUCTS (formed in the
graph, not as one constant) fall outside it; and a tiny constant through a MatrixFunction gradient.

c = 2⁻⁶⁰⁰: c·c·tr(XXᵀ − I_n)... we use the matrix residual c·c·(XXᵀ − I_n) (FALSE at r < n: nonzero, exact)
and its TRUE twin c·c·(XᵀX − I_r).  C = 2⁶⁰⁰: (C·C·X + X) − C·C·X = X (FALSE), twin (C·C·X + X) − C·C·X − X (TRUE).
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_max=3, n_min=2)


@claim("c5-under-false", kind="id", sizes=SZ)
def c5_under_false(s):
    c = s.q(1, 2 ** 600)
    return {"r": (s.X @ s.X.T - s.In) * c * c}


@claim("c5-under-true", kind="id", sizes=SZ)
def c5_under_true(s):
    c = s.q(1, 2 ** 600)
    return {"r": (s.X.T @ s.X - s.Ir) * c * c}


@claim("c5-under4-false", kind="id", sizes=SZ)
def c5_under4_false(s):
    """FALSE: (2⁻³⁰⁰)⁴·tr(XᵀX) = r·2⁻¹²⁰⁰ ≠ 0."""
    c = s.q(1, 2 ** 300)
    return {"r": s.tr(s.X.T @ s.X) * c * c * c * c}


@claim("c5-over-false", kind="id", sizes=SZ)
def c5_over_false(s):
    C = s.q(2 ** 600)
    return {"r": (s.X * C * C + s.X) - s.X * C * C}


@claim("c5-over-true", kind="id", sizes=SZ)
def c5_over_true(s):
    C = s.q(2 ** 600)
    return {"r": (s.X * C * C + s.X) - s.X * C * C - s.X}


@claim("c5-grad-false", kind="id", sizes=SZ)
def c5_grad_false(s):
    """FALSE: h(y) = c²·½<y, y> (c = 2⁻⁶⁰⁰), declared gradient 0 (true: c²·y, tiny but nonzero)."""
    h = MatrixFunction(lambda t, y: t.killing(y, y) * t.q(1, 2 ** 600) * t.q(1, 2 ** 600) / 2, lambda t, y: y * 0)
    return {"r": h.grad(s, s.X @ s.X.T)}


@claim("c5-grad-true", kind="id", sizes=SZ)
def c5_grad_true(s):
    """TRUE: same h, declared gradient c²·y; residual ∇h − c²·y."""
    c2 = s.q(1, 2 ** 600) * s.q(1, 2 ** 600)
    h = MatrixFunction(lambda t, y: t.killing(y, y) * t.q(1, 2 ** 600) * t.q(1, 2 ** 600) / 2,
                       lambda t, y: y * t.q(1, 2 ** 600) * t.q(1, 2 ** 600))
    return {"r": h.grad(s, s.X @ s.X.T) - s.X @ s.X.T * c2}
