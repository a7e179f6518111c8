"""FALSE REFUSALS of the one-function hold: an argument that is (as a node of the graph) a subexpression the
tensor's form computes from its other arguments.  The graph hash-conses nodes, so in the call T(s, a@b, a, b)
the product a@b the Lie–Poisson form computes inside comm(a, b) IS the node of the point argument; the call's
graph then reads its argument where the reference graph (distinct parameters) has a product.

Truth (by hand), T = Lie–Poisson on gl(n), Λ(p, q)|_x = <x, [p, q]>, a pure function (no state, no test):
  s79r2-subexpr-true:    T(a@b, a, b) − <a@b, [a, b]> = 0                               TRUE (identity)
  s79r2-subexpr-true2:   T(y, a, b) at generic y and T(a@b, a, b) − <a@b, ab − ba> = 0     TRUE
  s79r2-subexpr-false:   T(a@b, a, b) = 0 (false: <ab, ab − ba> = −½tr(abab − abba) ≠ 0 for generic a, b)
  s79r2-quadval-true:    quadratic(op: u ↦ Bu + uB, B sym) at x = B: h(B) = ½<B, 2B²> = <B, B²>   TRUE
                          (op(x) computes B@x = B@B; the argument x = B is not a subexpression; control)
  s79r2-quadsub-true:    quadratic(op: u ↦ B u + u B) at x = B@B − ... no: x = B@u0? (see file)
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, SYM_N, lie_poisson, quadratic, checked_tensor

SZ = admissible(n_min=3, n_max=3)


@claim("s79r2-subexpr-true", kind="id", sizes=SZ)
def subexpr_true(s):
    a, b = (GL_N.generic(s, nm) for nm in ("a", "b"))
    T = lie_poisson(GL_N)
    return {"T(ab; a, b) = <ab, [a, b]>": T(s, a @ b, a, b) - s.killing(a @ b, comm(a, b))}


@claim("s79r2-subexpr-true2", kind="id", sizes=SZ)
def subexpr_true2(s):
    y, a, b = (GL_N.generic(s, nm) for nm in ("y", "a", "b"))
    T = lie_poisson(GL_N)
    return {"T(y; a, b) = <y, [a, b]>": T(s, y, a, b) - s.killing(y, comm(a, b)),
            "T(ab; a, b) = <ab, [a, b]>": T(s, a @ b, a, b) - s.killing(a @ b, comm(a, b))}


@claim("s79r2-subexpr-checked-true", kind="id", sizes=SZ)
def subexpr_checked(s):
    a, b = (GL_N.generic(s, nm) for nm in ("a", "b"))
    T = lie_poisson(GL_N)
    C = checked_tensor(T)
    return {"C(ab; a, b) = T(ab; a, b)": C(s, a @ b, a, b) - T(s, a @ b, a, b)}


@claim("s79r2-subexpr-false", kind="id", sizes=SZ)
def subexpr_false(s):
    y, a, b = (GL_N.generic(s, nm) for nm in ("y", "a", "b"))
    T = lie_poisson(GL_N)
    return {"T(y; a, b) = <y, [a, b]>": T(s, y, a, b) - s.killing(y, comm(a, b)),
            "T(ab; a, b) = 0": T(s, a @ b, a, b)}


@claim("s79r2-quadsub-true", kind="id", sizes=SZ)
def quadsub_true(s):
    """op(u) = B u + u B (symmetric for <,> with B symmetric); value at x = B: op computes B@B, no argument node."""
    B = SYM_N.generic(s, "B")
    y = GL_N.generic(s, "y")
    h = quadratic(lambda t, u: B @ u + u @ B)
    return {"h(y) = ½<y, By + yB>": h(s, y) - s.killing(y, B @ y + y @ B) / 2,
            "∇h(B) = 2B²": h.grad(s, B) - B @ B * 2}
