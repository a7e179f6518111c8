"""First job: honest claims around one MatrixFunction used at several points / scenes / combinators, run on the new
commit and its parent.  Each "-true" is true by hand (below), each "-false" changes one constant.

h-multi: q = ½<y,y>: <∇q(x), x> = 2q(x) at x1 = XXᵀ and x2 = XᵀX (gl(r)); q(x1) = <XXᵀ,XXᵀ>/2 = −r/4.
h-momentum: ({h1, h2}^+ = <μ,[𝔸μ, 4μ³]>·c = 0 since μ⁴ commutes with μ; twin: 2·h1(Φ) = h1∘Φ) for h1 = ½<μ, 𝔸μ>, h2 = tr μ⁴ (one instance each), Φ Poisson: {h1∘Φ, h2∘Φ} = {h1, h2}^+(Φ) (paper,
  Proposition Phi), plus the claim's own h1(Φ) − h1.pullback(Φ) = 0 and tr μ⁴ a Casimir of (+) on so(n).
h-flow: d/dt (h∘Φ) along the Dirac flow of h∘Φ is {h∘Φ, h∘Φ} = 0 (h = tr μ², one instance also evaluated inline).
h-combo: sums, products, scaled: (f + g)(x) = f(x) + g(x), ∇(f·g) = ∇f g + f ∇g, ∇(c f) = c ∇f, f used inline.
h-twin: two instances from ONE value function, honest, at two points and in a bracket.
h-global: a module-global instance used in two claims.
h-pencil: casimir of the pencil: for Λ1 (semi-direct) the trace tr(x) ... here: the residual Λ(∇f, b) of
  f = <x, I> with Λ2: Λ2(I, b)|_x = <x − A, [I, b]> = 0 (TRUE); f also evaluated inline.
h-nr: one trace_power(2) instance used at an n×n and an r×r point: tr(Φ²) and tr(Ψ²) with Ψ the right moment:
  h(Φ) = tr Φ², h(Ψ) = tr Ψ² (trace_power(2) at x is tr x²: M = skew(x) + sym(x) = x).  TRUE; twin: 2·tr Φ².
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import (GL_N, SO_N, MatrixFunction, casimir_residual, lambda2, lie_poisson, linear,
                                 pencil, quadratic, trace_power)

SZ = admissible(n_max=3, n_min=2)


def _k(m):
    return (lambda s: m)


@claim("h-multi-true", kind="id", sizes=SZ)
def multi_true(s):
    return _multi(s, 2)


def _unused(s, c=2):
    q = quadratic()
    x1, x2 = s.X @ s.X.T, s.X.T @ s.X
    return {"1": s.killing(q.grad(s, x1), x1) - q(s, x1) * c, "2": s.killing(q.grad(s, x2), x2) - q(s, x2) * 2,
            "v": q(s, x1) + s.q(s.r) / 4}


@claim("h-multi-false", kind="id", sizes=SZ)
def multi_false(s):
    return _multi(s, 3)


def _multi(s, c):
    q = quadratic()
    x1, x2 = s.X @ s.X.T, s.X.T @ s.X
    return {"1": s.killing(q.grad(s, x1), x1) - q(s, x1) * c, "2": s.killing(q.grad(s, x2), x2) - q(s, x2) * 2,
            "v": q(s, x1) + s.q(s.r) / 4}


def _momentum(s, c):
    plus = lie_poisson(SO_N, 1)
    h1 = quadratic(lambda t, mu: t.sym_operator("AA")(mu))
    h2 = trace_power(4)
    Phi = lambda t: t.Phi       # noqa: E731
    b = SO_N.generic(s, "b")
    return {"pb": s.bracket(h1.pullback(Phi), h2.pullback(Phi)) - plus.bracket(s, h1, h2, s.Phi),
            "inline": h1(s, s.Phi) * c - h1.pullback(Phi)(s),
            "cas": casimir_residual(s, plus, h2, s.Phi, b) + h2(s, s.Phi) - h2.pullback(Phi)(s)}


@claim("h-momentum-true", kind="pb", sizes=SZ)
def momentum_true(s):
    return _momentum(s, 1)


@claim("h-momentum-false", kind="pb", sizes=SZ)
def momentum_false(s):
    return _momentum(s, 2)


def _flow(s, c):
    h = trace_power(2)
    H = h.pullback(lambda t: t.Phi)
    return {"d": s.d(H, s.dirac_flow(H)) + (h(s, s.Phi) - H(s)) * c,
            "c": h(s, s.Phi) + h(s, s.Phi) * 0 - s.d(lambda t: h(t, t.Phi), s.dirac_flow(H)) * 0 - H(s) * c}


@claim("h-flow-true", kind="pb", sizes=SZ)
def flow_true(s):
    return _flow(s, 1)


@claim("h-flow-false", kind="pb", sizes=SZ)
def flow_false(s):
    out = _flow(s, 1)
    out["d"] = out["d"] + s.q(1)
    return out


def _combo(s, c):
    f = quadratic()
    g = linear(lambda t: t.generic("a", "n", "n"))
    x = s.X @ s.X.T + s.generic("y", "n", "n")
    a = s.generic("a", "n", "n")
    lam = lambda t: t.q(3)      # noqa: E731
    return {"sum": (f + g)(s, x) - f(s, x) - g(s, x),
            "prod": (f * g).grad(s, x) - (x * g(s, x) + a * f(s, x)) * c,
            "scaled": f.scaled(lam).grad(s, x) - f.grad(s, x) * 3, "scaledv": f.scaled(lam)(s, x) - f(s, x) * 3}


@claim("h-combo-true", kind="id", sizes=SZ)
def combo_true(s):
    return _combo(s, 1)


@claim("h-combo-false", kind="id", sizes=SZ)
def combo_false(s):
    return _combo(s, 2)


def _v(t, y):
    return t.killing(y, y) / 2


def _twin(s, c):
    f1, f2 = MatrixFunction(_v, lambda t, y: y, "f1"), MatrixFunction(_v, lambda t, y: y, "f2")
    x1, x2 = s.X @ s.X.T, SO_N.generic(s, "z")
    L = lie_poisson(GL_N, 1)
    return {"a": f1(s, x1) - f2(s, x1), "b": s.killing(f1.grad(s, x2), x2) - f2(s, x2) * 2 * c,
            "br": L.bracket(s, f1, f2, x2)}


@claim("h-twin-true", kind="id", sizes=SZ)
def twin_true(s):
    return _twin(s, 1)


@claim("h-twin-false", kind="id", sizes=SZ)
def twin_false(s):
    return _twin(s, 2)


G_F = trace_power(2)


@claim("h-global-true", kind="id", sizes=SZ)
def global_true(s):
    x = SO_N.generic(s, "z")
    return {"e": s.killing(G_F.grad(s, x), x) - G_F(s, x) * 2}


@claim("h-global2-true", kind="pb", sizes=SZ)
def global2_true(s):
    b = SO_N.generic(s, "b")
    return {"c": casimir_residual(s, lie_poisson(SO_N), G_F, s.Phi, b), "v": G_F(s, s.Phi) - G_F.pullback(lambda t: t.Phi)(s)}


@claim("h-global-false", kind="id", sizes=SZ)
def global_false(s):
    x = SO_N.generic(s, "z")
    return {"e": s.killing(G_F.grad(s, x), x) - G_F(s, x) * 3}


def _pencil(s, c):
    f = linear(lambda t: t.In)
    T = pencil(lambda t: t.q(2), lambda t: t.q(5))
    x = s.generic("x", "n", "n")
    b = s.generic("b", "n", "n")
    return {"cas2": casimir_residual(s, lambda2(), f, x, b), "p": casimir_residual(s, T, f, x, b) * c,
            "v": f(s, x) + f(s, x * 2) - f(s, x * 3)}


@claim("h-pencil-true", kind="id", sizes=SZ)
def pencil_true(s):
    return _pencil(s, 1)


@claim("h-pencil-false", kind="id", sizes=SZ)
def pencil_false(s):
    f = linear(lambda t: t.generic("c", "n", "n"))
    x = s.generic("x", "n", "n")
    b = s.generic("b", "n", "n")
    return {"cas2": casimir_residual(s, lambda2(), f, x, b), "v": f(s, x)}


def _nr(s, c):
    h = trace_power(2)
    return {"n": h(s, s.Phi) - (s.Phi @ s.Phi).trace() * c, "r": h(s, s.Psi) - (s.Psi @ s.Psi).trace()}


@claim("h-nr-true", kind="pb", sizes=SZ)
def nr_true(s):
    return _nr(s, 1)


@claim("h-nr-false", kind="pb", sizes=SZ)
def nr_false(s):
    return _nr(s, 2)


@claim("h-nr2-true", kind="pb", sizes=SZ)
def nr2_true(s):
    """Two instances: the same statement tr Φ² = tr Ψ² (control of h-nr)."""
    return {"n": trace_power(2)(s, s.Phi) - (s.Phi @ s.Phi).trace(), "r": trace_power(2)(s, s.Psi) - (s.Psi @ s.Psi).trace()}
