"""More honest claims (first job), true by hand; each twin changes one constant.

h2-grad: H = h∘Φ with h = tr μ² (one instance): s.gradient(H) exists; the claim checks d/dt H along the canonical
  flow of H is 0 ({H, H}_0 = 0) and h(Φ) = H(s).
h2-inflow: f.grad inside a derivative along a flow: d/dt ∇h(Φ) = ∇h(dΦ/dt) for h = ½<μ, μ> (∇h = μ linear),
  along the Dirac flow of K = ½<Φ, Φ>... stated as s.d(t ↦ h.grad(t, t.Φ)) − s.d(t ↦ t.Φ) = 0.
h2-l1: Λ1 bracket of one linear function with itself is 0 (antisymmetry), the same instance also inline.
h2-copy: an honest copy.copy of quadratic() used beside the original: values and gradients agree.
"""
import copy

from stiefelsym import admissible, claim
from stiefelsym.brackets import lambda1, linear, quadratic, trace_power

SZ = admissible(n_max=3, n_min=2)


def _grad(s, c):
    h = trace_power(2)
    H = h.pullback(lambda t: t.Phi)
    return {"d": s.d(H, s.canonical_flow(H)) * c, "v": h(s, s.Phi) - H(s) * c}


@claim("h2-grad-true", kind="pb", sizes=SZ)
def grad_true(s):
    return _grad(s, 1)


@claim("h2-grad-false", kind="pb", sizes=SZ)
def grad_false(s):
    return _grad(s, 2)


def _inflow(s, c):
    h = quadratic()
    K = h.pullback(lambda t: t.Phi)
    fl = s.dirac_flow(K)
    return {"d": s.d(lambda t: h.grad(t, t.Phi), fl) - s.d(lambda t: t.Phi, fl) * c, "k": K(s) - h(s, s.Phi)}


@claim("h2-inflow-true", kind="pb", sizes=SZ)
def inflow_true(s):
    return _inflow(s, 1)


@claim("h2-inflow-false", kind="pb", sizes=SZ)
def inflow_false(s):
    out = _inflow(s, 1)
    out["k"] = out["k"] + s.q(1)
    return out


def _l1(s, c):
    f = linear(lambda t: t.generic("a", "n", "n"))
    x = s.generic("x", "n", "n")
    return {"b": lambda1().bracket(s, f, f, x) * c, "v": f(s, x) - s.killing(x, s.generic("a", "n", "n")) * c}


@claim("h2-l1-true", kind="id", sizes=SZ)
def l1_true(s):
    return _l1(s, 1)


@claim("h2-l1-false", kind="id", sizes=SZ)
def l1_false(s):
    return _l1(s, 2)


def _copy(s, c):
    f = quadratic()
    g = copy.copy(f)
    x = s.X @ s.X.T
    return {"v": f(s, x) - g(s, x) * c, "g": f.grad(s, x) - g.grad(s, x)}


@claim("h2-copy-true", kind="id", sizes=SZ)
def copy_true(s):
    return _copy(s, 1)


@claim("h2-copy-false", kind="id", sizes=SZ)
def copy_false(s):
    return _copy(s, 2)
