"""Checks inside the functions of stiefelsym.systems steps (derivative at a point, hamiltonian_flow).

h(y) = ½<y, y> on n×n matrices, ∇h(y) = y.  Declared "projector" gradient y² (right at y² = y only), honest y.
Point {"x": P}, P = XXᵀ (a projector), tangent {"x": W}, W = generic n×n (leaves the projectors).
  derivative(s, F, point, tangent) with F(t, z) = ∇h(z["x"]) (f.grad(t, z["x"])):
    true value d/dε ∇h(P + εW) = W; the declared one would give WP + PW.
  r81-sys-d-true:  = W (declared y²)    TRUE         r81-sys-d-false: = WP + PW (declared y²)   FALSE
  r81-sys-dh-true: = W (honest)         TRUE         r81-sys-dh-false: = 2W (honest)            FALSE
hamiltonian_flow on T*R^{n×n} (pairs (x, p), no constraint) of H(t, z) = <∇h(z["x"]), z["p"]> with ∇h honest:
  H = <x, p> = −½tr(xp), so ẋ = ∂H/∂p = −½xᵀ, ṗ = −∂H/∂x = ½pᵀ (∂/∂x of −½tr(xp) is −½pᵀ).
  (with the convention ∂/∂x_ij of a scalar: the matrix of partial derivatives.)
  r81-sys-hf-true:  ẋ = −½ xᵀ          TRUE    r81-sys-hf-false: ẋ = −½ x    FALSE (x generic, not symmetric)
"""
from stiefelsym import admissible, claim
from stiefelsym import systems
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _half():
    return lambda t, y: t.killing(y, y) / 2


def _f(honest):
    return MatrixFunction(_half(), (lambda t, y: y) if honest else (lambda t, y: y @ y), "½<y, y>")


def _d(s, honest):
    P = s.X @ s.X.T
    W = GL_N.generic(s, "W")
    f = _f(honest)
    d = systems.derivative(s, lambda t, z: f.grad(t, z["x"]), {"x": P}, {"x": W})
    return P, W, d


@claim("r81-sys-d-true", kind="id", sizes=SZ)
def d_true(s):
    P, W, d = _d(s, False)
    return {"d∇h = W": d - W}


@claim("r81-sys-d-false", kind="id", sizes=SZ)
def d_false(s):
    P, W, d = _d(s, False)
    return {"d∇h = WP + PW": d - W @ P - P @ W}


@claim("r81-sys-dh-true", kind="id", sizes=SZ)
def dh_true(s):
    P, W, d = _d(s, True)
    return {"d∇h = W": d - W}


@claim("r81-sys-dh-false", kind="id", sizes=SZ)
def dh_false(s):
    P, W, d = _d(s, True)
    return {"d∇h = 2W": d - W * 2}


def _hf(s):
    x, p = GL_N.generic(s, "x"), GL_N.generic(s, "p")
    f = _f(True)
    H = lambda t, z: t.killing(f.grad(t, z["x"]), z["p"])
    flow, mu = systems.hamiltonian_flow(s, H, lambda t, z: [], {"x": x, "p": p}, [("x", "p")])
    return x, p, flow


@claim("r81-sys-hf-true", kind="id", sizes=SZ)
def hf_true(s):
    x, p, flow = _hf(s)
    return {"ẋ = −½xᵀ": flow["x"] + x.T / 2}


@claim("r81-sys-hf-false", kind="id", sizes=SZ)
def hf_false(s):
    x, p, flow = _hf(s)
    return {"ẋ = −½x": flow["x"] + x / 2}
