"""Numbers of w's level (inside t's function) multiplying t's matrices: t.X * c_w, then products, traces and
inverses of the result in t's terms.  G = d_U[t -> d_V[w -> body(t, w)]] at X_t = X_w = X."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
R1 = admissible(n_max=3, r_max=1, condition="r = 1")


def _two(s, U, V, body):
    return s.d(lambda t: t.d(lambda w: body(t, w), {"X": V}), {"X": U})


def _c(w):
    return w.tr(w.X.T @ w.X)


# body = tr((c_w X_t)ᵀ(c_w X_t)) = c_w² |X_t|² ; with X_t = X + ε1 U, X_w = X_t + ε2 V:
# f(ε1, ε2) = |X+ε1U+ε2V|⁴ |X+ε1U|²; d2 d1 at 0: let a = |X|², p = 2tr(XᵀU), q = 2tr(XᵀV), m = 2tr(UᵀV)
# |X+ε1U+ε2V|⁴ = (a + ε1 p + ε2 q + ε1ε2 m + ...)², |X+ε1U|² = a + ε1 p + ...
# d1d2 [g² h] with g = a + ε1p + ε2q + ε1ε2 m, h = a + ε1 p:
#   = d1 [2 g q h] = 2 (p q a + a m a + a q p) = 2pqa + 2a²m + 2apq  (terms: d1 g = p + ε2 m, d1 h = p)
#   careful: d2(g² h) = 2 g (q + ε1 m) h; d1 of that at 0 = 2 p q a + 2 a m a + 2 a q p = 4apq + 2a²m
def _truth(s, U, V):
    a = s.tr(s.X.T @ s.X)
    p, q, m = s.tr(s.X.T @ U) * 2, s.tr(s.X.T @ V) * 2, s.tr(U.T @ V) * 2
    return a * p * q * 4 + a * a * m * 2


@claim("o78-smul-trace-true", kind="id", sizes=SZ)
def smul_trace_true(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def body(t, w):
        M = t.X * _c(w)
        return w.tr(M.T @ M)
    return {"w": _two(s, U, V, body) - _truth(s, U, V)}


@claim("o78-smul-trace-false", kind="id", sizes=SZ, expect="fails", erratum="twin")
def smul_trace_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def body(t, w):
        M = t.X * _c(w)
        return w.tr(M.T @ M)
    return {"w": _two(s, U, V, body) - _truth(s, U, U)}


@claim("o78-smul-ttrace-true", kind="id", sizes=SZ)
def smul_ttrace_true(s):
    """the same with t.tr (t's trace of the product)"""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def body(t, w):
        M = t.X * _c(w)
        return t.tr(M.T @ M)
    return {"w": _two(s, U, V, body) - _truth(s, U, V)}


@claim("o78-smul-ttrace-false", kind="id", sizes=SZ, expect="fails", erratum="twin")
def smul_ttrace_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def body(t, w):
        M = t.X * _c(w)
        return t.tr(M.T @ M)
    return {"w": _two(s, U, V, body) - _truth(s, U, U)}


# body = tr((XᵀX c_w)⁻¹) at r = 1: 1/(|X_t|² c_w) = 1/(|X_t|² |X_w|²)
def _inv_truth(s, U, V):
    a = s.tr(s.X.T @ s.X)
    p, q, m = s.tr(s.X.T @ U) * 2, s.tr(s.X.T @ V) * 2, s.tr(U.T @ V) * 2
    # f = 1/(h g), h = a + ε1 p, g = a + ε1 p + ε2 q + ε1ε2 m
    # d2 f = -(q + ε1 m)/(h g²); d1 at 0: -(m)/(a a²) + q (p/(a² a²) + 2p/(a a³))  = -m/a³ + 3pq/a⁴
    return -(m / (a * a * a)) + p * q * 3 / (a * a * a * a)


@claim("o78-smul-inv-true", kind="id", sizes=R1)
def smul_inv_true(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def body(t, w):
        M = (t.X.T @ t.X) * _c(w)
        return w.tr(M.inv())
    return {"w": _two(s, U, V, body) - _inv_truth(s, U, V)}


@claim("o78-smul-inv-false", kind="id", sizes=R1, expect="fails", erratum="twin")
def smul_inv_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def body(t, w):
        M = (t.X.T @ t.X) * _c(w)
        return w.tr(M.inv())
    return {"w": _two(s, U, V, body) - _inv_truth(s, U, U)}
