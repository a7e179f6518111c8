"""Cost of check_calls (O(calls × candidates)): a pure tensor (Λ(p, q)|_x = <x, [p, q]>·(1 + tr((pq)^6)), one
function) called at 7 points that are products its form computes (a_i b_i: each serves as a reference only for
calls of its structure), then at a generic point, then N calls of the first kind, then one more generic call:
each of the 7 bad candidates is held against every call before it fails at the last one.
Truth: every check is the form's definition (TRUE).
  s80r-slow-true:  N = 300
  s80r-slow-good-first-true: the same, the generic call first (the first candidate serves)
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, PoissonTensor

SZ = admissible(n_min=3, n_max=3, r_max=1)
N = 300


def _form(t, x, p, q):
    m = p @ q
    k = m @ m @ m @ m @ m @ m
    return t.killing(x, comm(p, q)) * (1 + t.tr(k))


def _want(s, x, p, q):
    return _form(s, x, p, q)


def _run(s, good_first):
    T = PoissonTensor(GL_N, _form, 1, "Λ")
    out = {}  # noqa: F841
    a, b = GL_N.generic(s, "a"), GL_N.generic(s, "b")
    y, c, d = (GL_N.generic(s, nm) for nm in ("y", "c", "d"))
    acc = 0
    if good_first:
        acc = acc + T(s, y, c, d)
    for i in range(7):
        ai, bi = a * (i + 2), b
        acc = acc + T(s, ai @ bi, ai, bi)
    if not good_first:
        acc = acc + T(s, y, c, d)
    for i in range(N):
        ai, bi = a * (i + 20), b
        acc = acc + T(s, ai @ bi, ai, bi)
    acc = acc + T(s, y, d, c)
    return {"Λ is its form (sum)": acc - acc}


@claim("s80r-slow-true", kind="id", sizes=SZ)
def slow(s):
    return _run(s, False)


@claim("s80r-slow-good-first-true", kind="id", sizes=SZ)
def slow_first(s):
    return _run(s, True)
