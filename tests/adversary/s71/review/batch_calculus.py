# ruff: noqa
"""Derivatives, gradients and brackets of functions that agree on T*V but not off it (true and false twins).
Truth: numpy_truth.py (finite differences of the ambient functions at a point of T*V).
Run: S verify --claims R/batch_calculus.py --method exact --method modular --method float --method free --size 3,2 --size 3,3 --size 2,1 --jobs 1"""
from stiefelsym import admissible, claim


def H1(t):   # = tr(I_r) tr(PᵀP)/2 on T*V, not off it
    return t.tr(t.X.T @ t.X) * t.tr(t.P.T @ t.P) / 2


def H2(t):
    return t.tr(t.Ir) * t.tr(t.P.T @ t.P) / 2


@claim("s71-c-dirac-restrict", kind="id", sizes=admissible(n_max=3))
def dirac_restrict(s):
    """The Dirac flow depends on H on T*V only (true)."""
    f1, f2 = s.dirac_flow(H1), s.dirac_flow(H2)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("s71-c-radial", kind="id", sizes=admissible(n_max=3))
def radial(s):
    """d/de tr((X + eX)ᵀ(X + eX)) = 2 tr(XᵀX) = 2r (true: the ambient derivative)."""
    return {"d": s.d(lambda t: t.tr(t.X.T @ t.X), {"X": s.X}) - 2 * s.tr(s.Ir)}


@claim("s71-c-radial-false", kind="id", sizes=admissible(n_max=3))
def radial_false(s):
    """d/de tr((X + eX)ᵀ(X + eX)) = 0 (false: that would be the derivative of the restriction)."""
    return {"d": s.d(lambda t: t.tr(t.X.T @ t.X), {"X": s.X})}


@claim("s71-c-grad", kind="id", sizes=admissible(n_max=3))
def grad(s):
    """The ambient gradient of H1: H_P = tr(XᵀX) P = r P, H_X = tr(PᵀP) X (true)."""
    HX, HP = s.gradient(H1)
    return {"HP": HP - s.P * s.tr(s.Ir), "HX": HX - s.X * s.tr(s.P.T @ s.P)}


@claim("s71-c-grad-false", kind="id", sizes=admissible(n_max=3))
def grad_false(s):
    """H_X of H1 = 0, as for H2 (false: the gradients differ off T*V)."""
    HX, HP = s.gradient(H1)
    return {"HX": HX}


@claim("s71-c-canon", kind="id", sizes=admissible(n_max=3))
def canon(s):
    """{tr XᵀX, tr XᵀP}_can² = 4 tr(XᵀX)² = 4r² (true, either sign)."""
    b = s.canonical_bracket(lambda t: t.tr(t.X.T @ t.X), lambda t: t.tr(t.X.T @ t.P))
    return {"b2": b * b - 4 * s.tr(s.Ir) * s.tr(s.Ir)}


@claim("s71-c-dirac-casimir", kind="id", sizes=admissible(n_max=3))
def dirac_casimir(s):
    """{tr XᵀX, tr PᵀAX}_Dirac = 0 (true: a function of the constraints)."""
    return {"b": s.bracket(lambda t: t.tr(t.X.T @ t.X), lambda t: t.tr(t.P.T @ t.A @ t.X))}


@claim("s71-c-dirac-casimir-false", kind="id", sizes=admissible(n_max=3))
def dirac_casimir_false(s):
    """{tr XᵀAX, tr PᵀX... } : {tr XᵀAX, tr PᵀP}_Dirac = 0 (false: the Neumann potential is not conserved by geodesics)."""
    return {"b": s.bracket(lambda t: t.tr(t.X.T @ t.A @ t.X), lambda t: t.tr(t.P.T @ t.P))}
