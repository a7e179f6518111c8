"""A FALSE gradient PROVED by the exact method: polynomial_gradient nested in polynomial_gradient, where the outer
form has degree 7 (beyond MAX_FORM_DEGREE = 6) along every generic direction, but degree 6 along the engine's own
direction w as the symbolic scene evaluates it, because the inner step's degree check shares w (one set of engine
symbols per (tag, shape) on a symbolic scene, Scene._engine_params, commit 5c8bda65).

gl(n) with <a, b> = -½tr(ab); x, K, M generic n x n; E11 the unit matrix; u11 = u[0,0].

  B(u, v)  = <[u, v], K> · u11² · <v, M>⁶      (degree 3 in u; zero when u ∥ v or v = 0)
  φ_y(c)   = <c, c> + B(c − y, y − x)
  T(y)     = polynomial_gradient(φ_y at y)              TRUE VALUE 2y (B is cubic in c − y)
  R(y)     = −2 <y, M>⁶ <[E11, y], K>                  (<[E11, y], K> = <y, [K, E11]>)
  F(y)     = T(y)[0,0] + 2R(y)          = 2 y11 + 2R(y)  (true), a polynomial of degree 7 in y
  ∇F(x)    = −4 E11 − 4 (6 <x,M>⁵ <x,[K,E11]> M + <x,M>⁶ [K, E11])          (y11 = <y, −2E11>)

  s79-nested7-true:  polynomial_gradient(F at x) = ∇F(x)                                     (TRUE; the honest
                     verdict is an error: F has degree 7 > 6, which the step refuses)
  s79-nested7-false: polynomial_gradient(F at x) = ∇F(x) + 45 Σ_{j≠1}(M_j1⁶ K_j1 E_j1 − M_1j⁶ K_1j E_1j)   (FALSE)

The engine (hand, see nested_gradient_shared_w.py for the degree-3 version): along w from y = x + s·w the inner
check sees B(iw, sw) = 0 and interpolates φ_y at degree 2: T[0,0] gains −2 s⁷ R(w); F along w then has degree 6
(the s⁷ of 2R cancels), so the outer step interpolates the degree-7 F at degree 6 along each E_ij, adding
D₆(t⁷)·2R(E_ij)·dual = −1440 R(E_ij)·(−2E_ji).  The exact method's rational point (fresh engine numbers) meets
the degree-7 refusal and so refutes nothing, and the division probe passes over the same exception.
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, polynomial_gradient

SZ = admissible(n_min=3, n_max=3)


def _e11(s):
    n = int(s.n)
    return s.mat([[s.q(1) if (i, j) == (0, 0) else s.q(0) for j in range(n)] for i in range(n)], ("n", "n"))


def _parts(s):
    x = GL_N.generic(s, "x")
    K = s.generic("K", "n", "n")
    M = s.generic("M", "n", "n")
    E = _e11(s)
    KE = comm(K, E)

    def p6(v):
        a = s.killing(v, M)
        a2 = a * a
        return a2 * a2 * a2

    def B(t, u, v):
        a = t.killing(v, M)
        a2 = a * a
        return t.killing(comm(u, v), K) * u[0, 0] * u[0, 0] * a2 * a2 * a2

    def R(t, y):
        a = t.killing(y, M)
        a2 = a * a
        return a2 * a2 * a2 * t.killing(y, KE) * (-2)

    def T(t, y):
        return polynomial_gradient(t, lambda t2, c: t2.killing(c, c) + B(t2, c - y, y - x), y, "gl", "n")

    def F(t, y):
        return T(t, y)[0, 0] + R(t, y) * 2

    G = polynomial_gradient(s, F, x, "gl", "n")
    a = s.killing(x, M)
    a5 = a * a * a * a * a
    grad = E * (-4) - (M * (a5 * s.killing(x, KE) * 6) + KE * (a5 * a)) * 4
    return x, K, M, G, grad


@claim("s79-nested7-true", kind="id", sizes=SZ)
def nested7_true(s):
    x, K, M, G, grad = _parts(s)
    return {"polynomial_gradient(F) = ∇F": G - grad}


@claim("s79-nested7-false", kind="id", sizes=SZ)
def nested7_false(s):
    x, K, M, G, grad = _parts(s)
    n = int(s.n)
    err = s.zeros(n, n, ("n", "n"))
    rows = [[s.q(0) for _ in range(n)] for _ in range(n)]
    for j in range(1, n):
        rows[j][0] = M[j, 0] ** 6 * K[j, 0] * 45
        rows[0][j] = M[0, j] ** 6 * K[0, j] * (-45)
    err = s.mat(rows, ("n", "n"))
    return {"polynomial_gradient(F) = ∇F + 45 Σ (M_j1⁶K_j1E_j1 − M_1j⁶K_1jE_1j)": G - grad - err}
