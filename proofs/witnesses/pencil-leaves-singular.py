"""(dimension) says 2l < n^2 - n: the generic leaf in Theta(T*V) is a singular symplectic leaf of
(gl(n), Lambda_1).  At (n, r) = (2, 1) the rank of Lambda_1 at Theta(X, P) = Phi + XX^T equals the rank
n^2 - n at a generic point of gl(n) (2 = 2).  The correction: 2l <= n^2 - n, equality at (1,1), (2,1)."""
import sympy as sp

KIND = "count"
CHECK = "2l < n² − n"
SIZE = (2, 1)


def counts():
    n, r = SIZE
    ip = lambda a, b: -sp.Rational(1, 2) * (a * b).trace()      # <.,.>: positive on so(n), negative on Sym(n)
    br = lambda a, b: a * b - b * a

    def E(i, j):
        return sp.Matrix(n, n, lambda a, b: 1 if (a, b) == (i, j) else 0)
    so = [E(i, j) - E(j, i) for i in range(n) for j in range(i + 1, n)]
    sym = [E(i, j) + E(j, i) for i in range(n) for j in range(i, n)]

    def rank_lambda1(x):
        # (LAMBDA12): Lambda_1(xi + eta, zeta + theta)|_x = <x, [xi, zeta] + [xi, theta] + [eta, zeta]>,
        # the Sym x Sym part vanishes; a basis so(n) + Sym(n) of gl(n)
        basis = [(u, 0 * u) for u in so] + [(0 * u, u) for u in sym]
        M = sp.Matrix(len(basis), len(basis), lambda a, b: ip(x, br(basis[a][0], basis[b][0])
                      + br(basis[a][0], basis[b][1]) + br(basis[a][1], basis[b][0])))
        return M.rank()
    X = sp.Matrix([[1], [0]])                     # X^T X = I_r
    P = sp.Matrix([[0], [1]])                     # X^T P + P^T X = 0
    assert X.T * X == sp.eye(r) and X.T * P + P.T * X == sp.zeros(r, r)
    theta = P * X.T - X * P.T + X * X.T           # Theta(X, P) = Phi + XX^T, Phi = PX^T - XP^T
    two_l = rank_lambda1(theta)                   # the dimension of the leaf through Theta(X, P)
    y = sp.Matrix([[1, 2], [3, 5]])               # a generic point of gl(2)
    generic = rank_lambda1(y)                     # n^2 - n
    assert (two_l, generic) == (2 * r * (n - r) + r * (r - 1) // 2 - r // 2, n * n - n) == (2, 2)
    return {"computed": int(two_l < generic),     # 1: singular leaf, 0: a leaf of maximal rank
            "printed": 1,                         # (dimension): 2l < n^2 - n, singular at every size
            "corrected": int((n, r) not in [(1, 1), (2, 1)]),   # 2l <= n^2 - n, equality at (1,1), (2,1)
            "meaning": "the leaf through Theta(X, P) is a singular leaf of (gl(n), Lambda_1): yes (1), no (0)"}
