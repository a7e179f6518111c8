"""s77 levels2: the new refusal of the evaluator (a value of t read in a function whose scene is not a lift of
t's: a derivative on the claim's scene s taken inside t's function).  G = d_U[t -> s.d(w -> tr(X_tᵀX_w), {X: V})]
= tr(UᵀV).  -true: TRUE; -false: FALSE (G = 0).  Both must get no wrong verdict (error = refusal is right)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _g(s, U, V):
    return s.d(lambda t: s.d(lambda w: w.tr(t.X.T @ w.X), {"X": V}), {"X": U})


@claim("s77m-refuse-claimscene-true", kind="id", sizes=SZ)
def refuse_claimscene_true(s):
    """G = tr(UᵀV): TRUE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _g(s, U, V) - s.tr(U.T @ V)}


@claim("s77m-refuse-claimscene-false", kind="id", sizes=SZ)
def refuse_claimscene_false(s):
    """G = 0: FALSE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _g(s, U, V)}


@claim("s77m-refuse-claimscene-confused", kind="id", sizes=SZ)
def refuse_claimscene_confused(s):
    """G = tr(UᵀU) (V confused with U): FALSE."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    return {"w": _g(s, U, V) - s.tr(U.T @ U)}
