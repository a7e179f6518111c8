"""The paragraph before Lemma 2.5 says that the generic adjoint orbit in Phi(T*V) is regular iff n <= 2r + 1.
At n = 2r + 2 (here (4, 1)) the orbit of Phi = PX^T - XP^T has the regular dimension n(n-1)/2 - [n/2]
as well.  The correction: regular iff n <= 2r + 2."""
import sympy as sp

KIND = "count"
CHECK = "regular iff n ≤ 2r + 1"
SIZE = (4, 1)


def counts():
    n, r = SIZE
    def E(i, j):
        return sp.Matrix(n, n, lambda a, b: 1 if (a, b) == (i, j) else 0)
    so = [E(i, j) - E(j, i) for i in range(n) for j in range(i + 1, n)]     # a basis of so(n)
    X = sp.Matrix([[1], [0], [0], [0]])           # X = (E_1): X^T X = I_r
    P = sp.Matrix([[0], [1], [0], [0]])           # X^T P + P^T X = 0
    assert X.T * X == sp.eye(r) and X.T * P + P.T * X == sp.zeros(r, r)
    Phi = P * X.T - X * P.T                       # the momentum map Phi(X, P) = PX^T - XP^T
    # ad_Phi on so(n): the columns are the coordinates of [Phi, e_k]; its rank is dim Ad_SO(n) Phi
    coords = lambda m: [m[i, j] for i in range(n) for j in range(i + 1, n)]
    ad = sp.Matrix([coords(Phi * e - e * Phi) for e in so]).T
    dim = ad.rank()                               # 2l (Lemma 2.5: n > 2r+1 gives 2r(n-r-1) = 4)
    regular = n * (n - 1) // 2 - n // 2           # the dimension of a regular orbit of so(n)
    assert dim == 2 * r * (n - r - 1) == 4
    return {"computed": int(dim == regular),      # 1: regular orbit, 0: singular
            "printed": int(n <= 2 * r + 1),       # the remark: regular iff n <= 2r + 1
            "corrected": int(n <= 2 * r + 2),     # the correction: regular iff n <= 2r + 2
            "meaning": "the generic adjoint orbit in Phi(T*V) is regular (1) or singular (0)"}
