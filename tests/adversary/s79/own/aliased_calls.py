"""Stop 79's own attempt on its change: calls of one function are compared as graphs of their arguments, and a
call that passes one node as two arguments (Λ(g, g)) is compared with the first call whose arguments are
distinct, merged the same way.  A tensor that tests whether its two covectors are one object (p is q) is one
tensor at distinct covectors and another at equal ones; one with state is another at its second aliased call.

gl(n), <a, b> = -½tr(ab), Λ the Lie-Poisson tensor Λ(a, b)|_x = <x, [a, b]>: Λ(g, g) = 0 for every g.
  s79o-alias-lp-true:        Λ(g, g)|_x = 0 and Λ(a, b)|_x + Λ(b, a)|_x = 0 (TRUE, a pure form: proved)
  s79o-alias-test-false:     a form that is <x, K> when p is q, else LP: "Λ(g, g)|_x = <x, K>" next to a checked
                             evaluation at distinct covectors (FALSE for the tensor the engine checks: refused)
  s79o-alias-state-false:    a form whose second call at equal covectors is <x, K>: "Λ(g,g) = 0" and
                             "Λ(h,h) = <x, K>" with no call at distinct covectors (FALSE: no tensor does both)
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, PoissonTensor, checked_tensor

SZ = admissible(n_min=3, n_max=3)


def _lp(t, x, p, q):
    return t.killing(x, comm(p, q))


@claim("s79o-alias-lp-true", kind="id", sizes=SZ)
def lp_true(s):
    x, g, a, b = (GL_N.generic(s, nm) for nm in ("x", "g", "a", "b"))
    T = PoissonTensor(GL_N, _lp, 1, "Λ")
    return {"Λ(g, g)": T(s, x, g, g), "Λ(a, b) + Λ(b, a)": T(s, x, a, b) + checked_tensor(T)(s, x, b, a)}


@claim("s79o-alias-test-false", kind="id", sizes=SZ)
def alias_test(s):
    x, g, a, b, K = (GL_N.generic(s, nm) for nm in ("x", "g", "a", "b", "K"))

    def form(t, y, p, q):
        return t.killing(y, K) if p is q else _lp(t, y, p, q)
    T = PoissonTensor(GL_N, form, 1, "Λ")
    return {"Λ(g, g) − <x, K>": T(s, x, g, g) - s.killing(x, K),
            "Λ(a, b) + Λ(b, a)": checked_tensor(T)(s, x, a, b) + checked_tensor(T)(s, x, b, a)}


@claim("s79o-alias-state-false", kind="id", sizes=SZ)
def alias_state(s):
    x, g, h, K = (GL_N.generic(s, nm) for nm in ("x", "g", "h", "K"))
    calls = []

    def form(t, y, p, q):
        calls.append(1)
        return t.killing(y, K) if len(calls) > 1 else _lp(t, y, p, q)
    T = PoissonTensor(GL_N, form, 1, "Λ")
    return {"Λ(g, g)": T(s, x, g, g), "Λ(h, h) − <x, K>": T(s, x, h, h) - s.killing(x, K)}


@claim("s79o-scene-test-false", kind="id", sizes=SZ)
def scene_test(s):
    """An op that tests its scene: B·u on the claim's own scene (where the value is taken), u on any other (the
    scene of the check's function): 'h(y) = ½<y, By>' next to the gradient's check (FALSE for the op the engine
    checks: refused)."""
    from stiefelsym.brackets import linear, lie_poisson, quadratic
    B = s.generic("B", "n", "n")
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    h = quadratic(lambda t, u: B @ u if t is s else u)
    return {"h(y) − ½<y, By>": h(s, y) - s.killing(y, B @ y) / 2,
            "{h, <.,b>}(x)": lie_poisson(GL_N).bracket(s, h, linear(lambda t: b), x)}
