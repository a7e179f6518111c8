"""Aliased calls of one tensor in two DIFFERENT patterns, and no call at distinct arguments: check_calls holds an
aliased call only to the first call of its own pattern (and to a reference at distinct arguments, when there is
one), so Λ(x; g, g) and Λ(g; g, g) are never compared.  But Λ(x; g, g) for a GENERIC x is an identity in x: at
x = g it is Λ(g; g, g).

Truth (by hand), for ONE function φ(scene; x, a, b) (any form):
  φ(x; g, g) = <g, g> for generic x, g  ==>  φ(g; g, g) = <g, g> ≠ 0  (set x = g; <g, g> = tr(g g) here is the
  Killing form of the scene, not 0 for a generic g).
  s80r-alias-state-contradiction:  {Λ(x; g, g) = <g, g>,  Λ(g; g, g) = 0}   FALSE (no function does both);
                                   the form has state: <p, q> at its first call, 0 after.
  s80r-alias-test-contradiction:   the same, the form tests its arguments (0 when y is p), no state.  FALSE.
  s80r-alias-honest-false:         one pure form <p, q>: {Λ(x; g, g) = <g, g>, Λ(g; g, g) = 0}  FALSE (the
                                   engine should refute: Λ(g; g, g) = <g, g>).
  s80r-alias-control-true:         two objects, forms <p, q> and 0: the same two checks   TRUE.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, PoissonTensor

SZ = admissible(n_min=3, n_max=3)


def _kf(t, y, p, q):
    return t.killing(p, q)


@claim("s80r-alias-state-contradiction", kind="id", sizes=SZ)
def alias_state(s):
    x, g = (GL_N.generic(s, nm) for nm in ("x", "g"))
    calls = []

    def form(t, y, p, q):
        calls.append(1)
        return t.killing(p, q) if len(calls) == 1 else t.killing(p, q) * 0
    T = PoissonTensor(GL_N, form, 1, "Λ")
    return {"Λ(x; g, g) − <g, g>": T(s, x, g, g) - s.killing(g, g), "Λ(g; g, g)": T(s, g, g, g)}


@claim("s80r-alias-test-contradiction", kind="id", sizes=SZ)
def alias_test(s):
    x, g = (GL_N.generic(s, nm) for nm in ("x", "g"))

    def form(t, y, p, q):
        return t.killing(p, q) * 0 if y is p else t.killing(p, q)
    T = PoissonTensor(GL_N, form, 1, "Λ")
    return {"Λ(x; g, g) − <g, g>": T(s, x, g, g) - s.killing(g, g), "Λ(g; g, g)": T(s, g, g, g)}


@claim("s80r-alias-honest-false", kind="id", sizes=SZ)
def alias_honest(s):
    x, g = (GL_N.generic(s, nm) for nm in ("x", "g"))
    T = PoissonTensor(GL_N, _kf, 1, "Λ")
    return {"Λ(x; g, g) − <g, g>": T(s, x, g, g) - s.killing(g, g), "Λ(g; g, g)": T(s, g, g, g)}


@claim("s80r-alias-control-true", kind="id", sizes=SZ)
def alias_control(s):
    x, g = (GL_N.generic(s, nm) for nm in ("x", "g"))
    T1 = PoissonTensor(GL_N, _kf, 1, "Λ1")
    T2 = PoissonTensor(GL_N, lambda t, y, p, q: t.killing(p, q) * 0, 1, "Λ2")
    return {"Λ1(x; g, g) − <g, g>": T1(s, x, g, g) - s.killing(g, g), "Λ2(g; g, g)": T2(s, g, g, g)}
