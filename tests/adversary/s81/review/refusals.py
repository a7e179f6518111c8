"""False refusals of the change?  Honest claims (every gradient declared is the value's, at every point) where a
check is evaluated on a reverse tape: (1) the value of a MatrixFunction is itself a bracket (it takes the gradients
of other functions), so MatrixFunction.grad's own check evaluates it by reverse mode (brackets._value_gradient); (2)
the bracket (s.bracket) of a function of the scene that takes a MatrixFunction's gradient at a point that moves
with the scene (reverse mode over H).

Truths (T = Lie–Poisson on gl(n), {f, g}(x) = <x, [∇f, ∇g]>, <a, b> = −½ tr(ab)):
 f = <·, a>, g = <·, b>, k = <·, c> (a, b, c generic): {f, g}(y) = <y, [a, b]>, so F := {f, g} is linear with
 ∇F = [a, b], and {F, k}(x) = <x, [[a, b], c]>.
   r81-ref-bb-true:  {F, k}(x) = <x, [[a, b], c]>     TRUE
   r81-ref-bb-false: {F, k}(x) = <x, [[b, a], c]>     FALSE (= −true; ≠ 0 for generic x, a, b, c)
   r81-ref-jac-true: {{f,g},k} + {{g,k},f} + {{k,f},g} = 0 at x (Jacobi)   TRUE (each term as above; the sum is
                     <x, [[a,b],c] + [[b,c],a] + [[c,a],b]> = 0 by the Jacobi identity of the commutator)
   r81-ref-jac-false: the same sum = <x, [[a,b],c]>   FALSE
 On T*V: F(t) = {f, g}(t.X t.Xᵀ)... written T.bracket(t, f, g, t.X @ t.X.T) = <XXᵀ, [a, b]>, a function of the scene
 with the same value as G(t) = <t.X t.Xᵀ, [a, b]>, so s.bracket(F, H) = s.bracket(G, H) for every H (H = tr(PᵀP)/2)
   r81-ref-sb-true:  s.bracket(F, H) − s.bracket(G, H) = 0        TRUE
   r81-ref-sb-false: s.bracket(F, H) = 0                            FALSE for r < n ({G, H} = d/dt <XXᵀ, [a,b]> along the
                     geodesic flow, ≠ 0 for generic a, b)
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, MatrixFunction, lie_poisson, linear

SZ = admissible(n_min=3, n_max=3)
T = lie_poisson(GL_N)


def _abc(s):
    return GL_N.generic(s, "a"), GL_N.generic(s, "b"), GL_N.generic(s, "c")


def _F(f, g, a, b):
    return MatrixFunction(lambda t, y: T.bracket(t, f, g, y), lambda t, y: comm(a, b), "{f, g}")


@claim("r81-ref-bb-true", kind="pb", sizes=SZ)
def bb_true(s):
    a, b, c = _abc(s)
    f, g, k = linear(lambda t: a), linear(lambda t: b), linear(lambda t: c)
    x = GL_N.generic(s, "x")
    return {"{{f,g},k} = <x,[[a,b],c]>": T.bracket(s, _F(f, g, a, b), k, x) - s.killing(x, comm(comm(a, b), c))}


@claim("r81-ref-bb-false", kind="pb", sizes=SZ)
def bb_false(s):
    a, b, c = _abc(s)
    f, g, k = linear(lambda t: a), linear(lambda t: b), linear(lambda t: c)
    x = GL_N.generic(s, "x")
    return {"{{f,g},k} = <x,[[b,a],c]>": T.bracket(s, _F(f, g, a, b), k, x) - s.killing(x, comm(comm(b, a), c))}


def _jac(s):
    a, b, c = _abc(s)
    f, g, k = linear(lambda t: a), linear(lambda t: b), linear(lambda t: c)
    x = GL_N.generic(s, "x")
    return a, b, c, x, (T.bracket(s, _F(f, g, a, b), k, x) + T.bracket(s, _F(g, k, b, c), f, x)
                        + T.bracket(s, _F(k, f, c, a), g, x))


@claim("r81-ref-jac-true", kind="pb", sizes=SZ)
def jac_true(s):
    a, b, c, x, j = _jac(s)
    return {"Jacobi = 0": j}


@claim("r81-ref-jac-false", kind="pb", sizes=SZ)
def jac_false(s):
    a, b, c, x, j = _jac(s)
    return {"Jacobi = <x,[[a,b],c]>": j - s.killing(x, comm(comm(a, b), c))}


def _sb(s):
    a, b = GL_N.generic(s, "a"), GL_N.generic(s, "b")
    f, g = linear(lambda t: a), linear(lambda t: b)
    F = lambda t: T.bracket(t, f, g, t.X @ t.X.T)
    G = lambda t: t.killing(t.X @ t.X.T, comm(a, b))
    H = lambda t: t.tr(t.P.T @ t.P) / 2
    return s.bracket(F, H), s.bracket(G, H)


@claim("r81-ref-sb-true", kind="id", sizes=SZ)
def sb_true(s):
    bF, bG = _sb(s)
    return {"{F, H} = {G, H}": bF - bG}


@claim("r81-ref-sb-false", kind="id", sizes=SZ)
def sb_false(s):
    bF, bG = _sb(s)
    return {"{F, H} = 0": bF}
