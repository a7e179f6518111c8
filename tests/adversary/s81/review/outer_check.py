"""A check made on the claim's scene s at a point that moves with a derivative's scene t: f.grad(s, x_t) inside
s.d(lambda t: ..., flow).  The graph leaves the step to the scene (x_t moves), and the scene evaluates
gradient_check(s, value, x_t, G) with s the claim's scene (not the tangent scene): does it compare both parts?

h(y) = ½<y, y> on n×n matrices: ∇h(y) = y at every y (d½<y,y> = <y, dy>).
Declared gradient G(s, y) = y + (y² − y)·1 = y²: equal to y exactly at the projectors (y² = y).
Point x_t = t.X t.Xᵀ: a projector at ε = 0 (XᵀX = I), so G(x_0) = x_0 = ∇h(x_0): the check passes at the point.
Along the ambient flow X + εV: dx = V Xᵀ + X Vᵀ =: W.
  true:  d/dε ∇h(x_ε) = d x_ε = W
  declared: d/dε x_ε² = W P + P W   (P = XXᵀ)
  r81-oc-false:   d∇h(x_t) = W P + P W      FALSE  (W P + P W − W = X(VᵀX + XᵀV)Xᵀ... ≠ 0 in general, see below)
  r81-oc-true:    d∇h(x_t) = W              TRUE
  (W P + P W − W with P = XXᵀ, W = VXᵀ + XVᵀ: = VXᵀ + X VᵀXXᵀ + XXᵀVXᵀ + XVᵀ − VXᵀ − XVᵀ = X(VᵀX + XᵀV)Xᵀ ≠ 0
   for an ambient V.)
Closure variant: G(s, y) = 2y − x0 with x0 = s.X s.Xᵀ (right at y = x0 only): declared d = 2W, true W.
  r81-oc2-false: d∇h(x_t) = 2W   FALSE ;  r81-oc2-true: d∇h(x_t) = W   TRUE
Control: honest G = y: r81-oc-ctrl-true d = W, r81-oc-ctrl-false d = 2W.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _half():
    return lambda t, y: t.killing(y, y) / 2


def _proj():
    return MatrixFunction(_half(), lambda t, y: y @ y, "½<y, y>")


def _clos(s):
    x0 = s.X @ s.X.T
    return MatrixFunction(_half(), lambda t, y: y * 2 - x0, "½<y, y>")


def _honest():
    return MatrixFunction(_half(), lambda t, y: y, "½<y, y>")


def _d(s, f):
    V = s.fresh("n", "r")
    W = V @ s.X.T + s.X @ V.T
    return W, s.d(lambda t: f.grad(s, t.X @ t.X.T), {"X": V})


@claim("r81-oc-false", kind="id", sizes=SZ)
def oc_false(s):
    W, d = _d(s, _proj())
    P = s.X @ s.X.T
    return {"d∇h(x_t) = WP + PW": d - W @ P - P @ W}


@claim("r81-oc-true", kind="id", sizes=SZ)
def oc_true(s):
    W, d = _d(s, _proj())
    return {"d∇h(x_t) = W": d - W}


@claim("r81-oc2-false", kind="id", sizes=SZ)
def oc2_false(s):
    W, d = _d(s, _clos(s))
    return {"d∇h(x_t) = 2W": d - W * 2}


@claim("r81-oc2-true", kind="id", sizes=SZ)
def oc2_true(s):
    W, d = _d(s, _clos(s))
    return {"d∇h(x_t) = W": d - W}


@claim("r81-oc-ctrl-true", kind="id", sizes=SZ)
def ctrl_true(s):
    W, d = _d(s, _honest())
    return {"d∇h(x_t) = W": d - W}


@claim("r81-oc-ctrl-false", kind="id", sizes=SZ)
def ctrl_false(s):
    W, d = _d(s, _honest())
    return {"d∇h(x_t) = 2W": d - W * 2}


# -- the same on the derivative's own scene: f.grad(t, x_t) (the natural way to write it)
def _dt(s, f):
    V = s.fresh("n", "r")
    W = V @ s.X.T + s.X @ V.T
    return W, s.d(lambda t: f.grad(t, t.X @ t.X.T), {"X": V})


@claim("r81-ot-false", kind="id", sizes=SZ)
def ot_false(s):
    W, d = _dt(s, _proj())
    P = s.X @ s.X.T
    return {"d∇h(x_t) = WP + PW": d - W @ P - P @ W}


@claim("r81-ot-true", kind="id", sizes=SZ)
def ot_true(s):
    W, d = _dt(s, _proj())
    return {"d∇h(x_t) = W": d - W}


@claim("r81-ot2-false", kind="id", sizes=SZ)
def ot2_false(s):
    W, d = _dt(s, _clos(s))
    return {"d∇h(x_t) = 2W": d - W * 2}


@claim("r81-ot2-true", kind="id", sizes=SZ)
def ot2_true(s):
    W, d = _dt(s, _clos(s))
    return {"d∇h(x_t) = W": d - W}


@claim("r81-ot-ctrl-true", kind="id", sizes=SZ)
def otc_true(s):
    W, d = _dt(s, _honest())
    return {"d∇h(x_t) = W": d - W}


@claim("r81-ot-ctrl-false", kind="id", sizes=SZ)
def otc_false(s):
    W, d = _dt(s, _honest())
    return {"d∇h(x_t) = 2W": d - W * 2}
