"""polynomial_gradient nested in polynomial_gradient: the exact method's engine symbols are shared per (tag, shape)
on a scene (Scene._engine_params, commit 5c8bda65), so the INNER step's degree check runs along the same generic
direction w as the OUTER step's degree check, at points y = x + s·w of the outer check that hold w.

Space gl(n), <a, b> = -½tr(ab).  x, K, M generic n x n.  Write u11 = u[0,0].

  B(u, v) = <[u, v], K> · u11² · <v, M>²        (cubic in u, cubic in v, zero when u ∥ v or v = 0)
  inner form at a point y:   φ_y(c) = <c, c> + B(c − y, y − x)
  T(y) = polynomial_gradient(φ_y, at y)                                   TRUE VALUE: 2y
         (B is cubic in c − y: its derivative at c = y is 0; ∇<c,c> = 2c)
  R(y) = -2 <y, M>² <[E11, y], K>   with <[E11, y], K> = -½((yK)11 − (Ky)11)       (cubic in y)
  F_nested(y) = T(y)[0,0] + 2R(y)        F_direct(y) = 2·y11 + 2R(y)
  Since T(y) = 2y for every y, F_nested ≡ F_direct: their gradients at x are equal.

  s79-nested-grad-true:  polynomial_gradient(F_nested, x) − polynomial_gradient(F_direct, x) = 0     (TRUE)
  s79-nested-grad-false: the same difference has (2,1) entry 2 M21² K21 (0-indexed [1, 0])          (FALSE)

Prediction of the engine's error (hand): along w from y = x + s·w the inner check sees B(iw, sw) = 0, takes φ_y of
degree 2, and interpolates at degree 2: the cubic t³ term of φ_y(y + t e_l) gives −2 × its coefficient, so
T_eng(x + s w)[0,0] = 2(x + s w)11 − 2 s³ R(w); then F_nested along w is of degree 2 in s (the s³ of 2R cancels),
the outer step takes degree 2 where F has degree 3, and its degree-2 interpolation along each basis vector E_ij
adds −2·2R(E_ij) × dual: the difference is Σ_{j≠1} (2 M_j1² K_j1 E_j1 − 2 M_1j² K_1j E_1j).
Without shared symbols (fresh w per check) the inner check would see the cubic and the outer would be exact.
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, polynomial_gradient

SZ = admissible(n_min=3, n_max=3)


def _parts(s):
    x = GL_N.generic(s, "x")
    K = s.generic("K", "n", "n")
    M = s.generic("M", "n", "n")

    def B(t, u, v):
        return t.killing(comm(u, v), K) * u[0, 0] * u[0, 0] * t.killing(v, M) * t.killing(v, M)

    def R(t, y):
        br = ((y @ K)[0, 0] - (K @ y)[0, 0]) * t.q(-1, 2)
        return t.killing(y, M) * t.killing(y, M) * br * (-2)

    def T(t, y):
        return polynomial_gradient(t, lambda t2, c: t2.killing(c, c) + B(t2, c - y, y - x), y, "gl", "n")

    def F_nested(t, y):
        return T(t, y)[0, 0] + R(t, y) * 2

    def F_direct(t, y):
        return y[0, 0] * 2 + R(t, y) * 2

    G1 = polynomial_gradient(s, F_nested, x, "gl", "n")
    G2 = polynomial_gradient(s, F_direct, x, "gl", "n")
    return x, K, M, G1, G2


@claim("s79-nested-grad-true", kind="id", sizes=SZ)
def nested_true(s):
    x, K, M, G1, G2 = _parts(s)
    return {"∇F_nested − ∇F_direct = 0": G1 - G2}


@claim("s79-nested-grad-false", kind="id", sizes=SZ)
def nested_false(s):
    x, K, M, G1, G2 = _parts(s)
    return {"(∇F_nested − ∇F_direct)[1,0] = 2 M10² K10": (G1 - G2)[1, 0] - M[1, 0] * M[1, 0] * K[1, 0] * 2}


@claim("s79-inner-value-true", kind="id", sizes=SZ)
def inner_value(s):
    """control: T at the claim's own point is 2x (no shared symbols in the argument)."""
    x = GL_N.generic(s, "x")
    K = s.generic("K", "n", "n")
    M = s.generic("M", "n", "n")
    z = GL_N.generic(s, "z")

    def B(t, u, v):
        return t.killing(comm(u, v), K) * u[0, 0] * u[0, 0] * t.killing(v, M) * t.killing(v, M)
    T = polynomial_gradient(s, lambda t2, c: t2.killing(c, c) + B(t2, c - z, z - x), z, "gl", "n")
    return {"T(z) = 2z": T - z * 2}
