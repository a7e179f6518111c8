"""alias_patterns.py WITH a call at distinct arguments (the reference): the reference is on the claim's own scene
(no call at distinct arguments on another scene), and the aliased calls are on derivative scenes.  Each aliased
call is compared with the own-scene reference with the claim's scene standing for its scene (s.X kept and t.X
are one argument there), and with the first call of its own pattern only: two aliased calls of two patterns, one
reading t.X (moves) and one reading s.X (a constant of the derivative's scene), both pass.
form(t; y, p, q) = c·<p, q>, c = tr(XᵀKX), X = t.X (mode "t") or s.X (mode "s").
Truth (by hand): for ONE function φ(scene; y, p, q), D1 = d/dε φ(t; x, g, g) along {X: V} is an identity in the
generic x, so at x = g it is D2 = d/dε φ(t; g, g, g) (same tangent V).  The claim says D1 = ċ<g, g> ≠ 0,
ċ = tr(Vᵀ(K + Kᵀ)X), and D2 = 0.
  s80r-alias-scene-contradiction: {T(x; a, b) = c<a, b>, D1 = ċ<g, g>, D2 = 0}, mode flipped before D2    FALSE
  s80r-alias-scene-true:          the same form, mode "t" throughout: {…, D1 = ċ<g, g>, D2 = ċ<g, g>}      TRUE
  s80r-alias-scene-false:         mode "t" throughout, "D2 = 0"                                            FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, PoissonTensor

SZ = admissible(n_min=3, n_max=3)


def _run(s, flip):
    x, a, b, g = (GL_N.generic(s, nm) for nm in ("x", "a", "b", "g"))
    K = s.generic("K", "n", "n")
    V = s.fresh("n", "r")
    mode = ["t"]

    def form(t, y, p, q):
        X = t.X if mode[0] == "t" else s.X
        return t.tr(X.T @ K @ X) * t.killing(p, q)
    T = PoissonTensor(GL_N, form, 1, "Λ")
    c = s.tr(s.X.T @ K @ s.X)
    cdot = s.tr(V.T @ (K + K.T) @ s.X)
    ref = T(s, x, a, b) - c * s.killing(a, b)
    D1 = s.d(lambda t: T(t, x, g, g), {"X": V})
    if flip:
        mode[0] = "s"
    D2 = s.d(lambda t: T(t, g, g, g), {"X": V})
    return ref, D1 - cdot * s.killing(g, g), D2, cdot * s.killing(g, g)


@claim("s80r-alias-scene-contradiction", kind="id", sizes=SZ)
def contra(s):
    ref, d1, D2, _ = _run(s, True)
    return {"T(x; a, b) = c<a, b>": ref, "D1 = ċ<g, g>": d1, "D2 = 0": D2}


@claim("s80r-alias-scene-true", kind="id", sizes=SZ)
def true_(s):
    ref, d1, D2, w = _run(s, False)
    return {"T(x; a, b) = c<a, b>": ref, "D1 = ċ<g, g>": d1, "D2 = ċ<g, g>": D2 - w}


@claim("s80r-alias-scene-false", kind="id", sizes=SZ)
def false_(s):
    ref, d1, D2, _ = _run(s, False)
    return {"T(x; a, b) = c<a, b>": ref, "D1 = ċ<g, g>": d1, "D2 = 0": D2}
