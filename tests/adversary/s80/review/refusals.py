"""FALSE REFUSALS left by the substitution rule (a pure tensor, the engine's own Lie–Poisson tensor on gl(n),
Λ(p, q)|_x = <x, [p, q]>).  The reference must be one of the first 8 calls at distinct arguments; a call whose
point is a product its form also computes (ab, the first term of [a, b] = ab − ba) serves as a reference only for
calls of the same structure.
Truth (by hand): Λ(p, q)|_x = <x, pq − qp> for every x, p, q.
  s80r-ref-ab-ba-true:      Λ(a, b)|_{ab} = <ab, [a, b]> and Λ(a, b)|_{ba} = <ba, [a, b]>             TRUE
  s80r-ref-ab-ba-false:     the same, the second = 0 (<ba, ab − ba> ≠ 0 generically)                  FALSE
  s80r-ref-nine-true:       Λ(a_i, b_i)|_{a_i b_i} for i = 1..8, then Λ(c, d)|_y = <y, [c, d]>             TRUE
  s80r-ref-nine-first-true: the same with the generic call first                                           TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, lie_poisson

SZ = admissible(n_min=3, n_max=3)


@claim("s80r-ref-ab-ba-true", kind="id", sizes=SZ)
def ab_ba(s):
    a, b = (GL_N.generic(s, nm) for nm in ("a", "b"))
    T = lie_poisson(GL_N)
    return {"Λ(a, b)|ab": T(s, a @ b, a, b) - s.killing(a @ b, comm(a, b)),
            "Λ(a, b)|ba": T(s, b @ a, a, b) - s.killing(b @ a, comm(a, b))}


@claim("s80r-ref-ab-ba-false", kind="id", sizes=SZ)
def ab_ba_false(s):
    a, b = (GL_N.generic(s, nm) for nm in ("a", "b"))
    T = lie_poisson(GL_N)
    return {"Λ(a, b)|ab": T(s, a @ b, a, b) - s.killing(a @ b, comm(a, b)), "Λ(a, b)|ba": T(s, b @ a, a, b)}


def _nine(s, generic_first):
    T = lie_poisson(GL_N)
    out = {}
    y, c, d = (GL_N.generic(s, nm) for nm in ("y", "c", "d"))
    if generic_first:
        out["Λ(c, d)|y"] = T(s, y, c, d) - s.killing(y, comm(c, d))
    for i in range(8):
        a, b = GL_N.generic(s, f"a{i}"), GL_N.generic(s, f"b{i}")
        out[f"Λ(a{i}, b{i})|a{i}b{i}"] = T(s, a @ b, a, b) - s.killing(a @ b, comm(a, b))
    if not generic_first:
        out["Λ(c, d)|y"] = T(s, y, c, d) - s.killing(y, comm(c, d))
    return out


@claim("s80r-ref-nine-true", kind="id", sizes=SZ)
def nine(s):
    return _nine(s, False)


@claim("s80r-ref-nine-first-true", kind="id", sizes=SZ)
def nine_first(s):
    return _nine(s, True)
