"""NOT A WRONG VERDICT (see FINDINGS.md, attempt 8): the "contradiction" below is explained by one function,
φ(t; y, p, q) = tr(s.Xᵀ K s.X)<p, q> (it keeps the claim's scene), which satisfies both statements; a call on the
claim's scene cannot tell keeping s from reading its scene, and one call on another scene is never compared as it
is with anything.  Kept as the record of the attempt.

check_calls: a reference on the claim's own scene (the only call with the most distinct arguments) and ONE call
on a derivative's scene that passes fewer distinct arguments.  `serves(others)` has a single call (nothing to
compare "as they are"); in `serves(everyone)` that call is compared with the own-scene reference, the claim's
scene standing for the derivative's scene, so a form that reads the claim's s.X (a constant of the derivative's
scene) at that call passes for one that reads t.X.

form(t; y, p, q) = c(X)·<p, q>, c(X) = tr(XᵀKX), X = t.X (mode "t") or s.X kept (mode "s", after the flip).
Truth (by hand): for ONE function φ(scene; y, p, q), the first statement φ(s; x, a, b) = c(s.X)<a, b> is an
identity in the scene (generic X on V(n, r)) and in a, b, so at b = a and along a curve of V(n, r) with tangent V
(V = (I − XXᵀ)Z + X(W − Wᵀ), tangent to V(n, r)): d/dε φ(t; x, a, a) = ċ<a, a>, ċ = tr(Vᵀ(K + Kᵀ)X) — not 0 for
r < n (the X(W − Wᵀ) part gives 0: Xᵀ(K + Kᵀ)X is symmetric; at (3, 3) ċ = 0 and "D = 0" is true).
  h4-ownref-contradiction: mode flipped before the derivative: {φ(s; x, a, b) = c<a, b>, D = 0}   FALSE at (3,1), (3,2)
  h4-ownref-true:          no flip: {φ(s; x, a, b) = c<a, b>, D = ċ<a, a>}                         TRUE
  h4-ownref-false:         no flip: {φ(s; x, a, b) = c<a, b>, D = 0}                               FALSE at (3,1), (3,2)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, PoissonTensor

SZ = admissible(n_min=3, n_max=3)


def _run(s, flip):
    x, a, b = (GL_N.generic(s, nm) for nm in ("x", "a", "b"))
    K = s.generic("K", "n", "n")
    Z, W = s.generic("Z", "n", "r"), s.generic("W", "r", "r")
    V = (s.In - s.X @ s.X.T) @ Z + s.X @ (W - W.T)
    mode = ["t"]

    def form(t, y, p, q):
        X = t.X if mode[0] == "t" else s.X
        return t.tr(X.T @ K @ X) * t.killing(p, q)
    T = PoissonTensor(GL_N, form, 1, "Λ")
    c = s.tr(s.X.T @ K @ s.X)
    cdot = s.tr(V.T @ (K + K.T) @ s.X)
    ref = T(s, x, a, b) - c * s.killing(a, b)
    if flip:
        mode[0] = "s"
    D = s.d(lambda t: T(t, x, a, a), {"X": V})
    return ref, D, cdot * s.killing(a, a)


@claim("h4-ownref-contradiction", kind="id", sizes=SZ)
def contra(s):
    ref, D, w = _run(s, True)
    return {"Λ(x; a, b) = c<a, b>": ref, "D = 0": D}


@claim("h4-ownref-true", kind="id", sizes=SZ)
def true_(s):
    ref, D, w = _run(s, False)
    return {"Λ(x; a, b) = c<a, b>": ref, "D = ċ<a, a>": D - w}


@claim("h4-ownref-false", kind="id", sizes=SZ)
def false_(s):
    ref, D, w = _run(s, False)
    return {"Λ(x; a, b) = c<a, b>": ref, "D = 0": D}


@claim("h4-ownref-distinct-contradiction", kind="id", sizes=SZ)
def contra_distinct(s):
    """The same, the derivative's call at the same distinct arguments as the own call: D = d/dε φ(t; x, a, b)
    must be ċ<a, b> for one function; the claim says 0.                                  FALSE at (3,1), (3,2)"""
    x, a, b = (GL_N.generic(s, nm) for nm in ("x", "a", "b"))
    K = s.generic("K", "n", "n")
    Z, W = s.generic("Z", "n", "r"), s.generic("W", "r", "r")
    V = (s.In - s.X @ s.X.T) @ Z + s.X @ (W - W.T)
    mode = ["t"]

    def form(t, y, p, q):
        X = t.X if mode[0] == "t" else s.X
        return t.tr(X.T @ K @ X) * t.killing(p, q)
    T = PoissonTensor(GL_N, form, 1, "Λ")
    ref = T(s, x, a, b) - s.tr(s.X.T @ K @ s.X) * s.killing(a, b)
    mode[0] = "s"
    return {"Λ(x; a, b) = c<a, b>": ref, "D = 0": s.d(lambda t: T(t, x, a, b), {"X": V})}
