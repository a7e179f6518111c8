"""The stop's own attempt after the level fixes: one flow whose components come from two levels (X from the inner
scene u, P from the outer scene t), and a float pole with a false twin.  Docstrings state the truth."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def xp(t):
    return t.tr(t.X.T @ t.P)


def _mixed(s, U, V):
    # innermost along (X: u.X, P: t.P) at u's point; middle along X = V; outer along P = U
    return s.d(lambda t: t.d(lambda u: u.d(xp, {"X": u.X, "P": t.P}), {"X": V}), {"P": U})


@claim("s77-mixed-flow-true", kind="id", sizes=SZ)
def mixed_flow_true(s):
    """innermost 2tr(XᵤᵀPₜ); along V: 2tr(VᵀPₜ); along U (Pₜ = P + ε₁U): 2tr(VᵀU): TRUE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _mixed(s, U, V) - s.tr(V.T @ U) * 2}


@claim("s77-mixed-flow-false", kind="id", sizes=SZ)
def mixed_flow_false(s):
    """2tr(UᵀU) (U taken for V): FALSE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _mixed(s, U, V) - s.tr(U.T @ U) * 2}


@claim("s77-pole-false", kind="id", sizes=admissible(n_max=4))
def pole_false(s):
    """(c·tr PᵀP)/c = 2tr PᵀP, c = n − 100: FALSE wherever defined, undefined at n = 100."""
    c = s.tr(s.In) - 100
    K = s.tr(s.P.T @ s.P)
    return {"w": (c * K) / c - K * 2}
