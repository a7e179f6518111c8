"""§6 says that for lambda_2 != 0 the bracket Lambda_{lambda_1,lambda_2} = lambda_1 Lambda_1 + lambda_2 Lambda_2 is
isomorphic to the Lie-Poisson bracket of gl(n), which vanishes at 0; so Lambda_{lambda_1,lambda_2} would vanish at some
point.  At lambda_1 = -lambda_2 = -1 the rows of Lambda_{-1,1}(x) whose first argument lies in so(n) do not depend on x
(Lambda_{-1,1}(xi, .)|_x = -<A, [xi, .]> for xi in so(n)), and they have rank n(n - 1)/2 for distinct a_i: the bracket
vanishes nowhere.  The correction: lambda_1 + lambda_2 != 0 too; then Lambda_{lambda_1,lambda_2} vanishes at
x0 = lambda_2/(lambda_1 + lambda_2) A."""
import sympy as sp

KIND = "count"
CHECK = "rank of the so(n) rows of Lambda_{-1,1}(0)"
SIZE = (3, 1)


def counts():
    n, _ = SIZE
    ip = lambda a, b: -sp.Rational(1, 2) * (a * b).trace()      # <.,.> = -1/2 tr(ab)
    br = lambda a, b: a * b - b * a

    def E(i, j):
        return sp.Matrix(n, n, lambda a, b: 1 if (a, b) == (i, j) else 0)
    so = [E(i, j) - E(j, i) for i in range(n) for j in range(i + 1, n)]
    sym = [E(i, j) + E(j, i) if i != j else E(i, i) for i in range(n) for j in range(i, n)]
    basis = [(u, 0 * u) for u in so] + [(0 * u, u) for u in sym]     # gl(n) = so(n) + Sym(n)
    A = sp.diag(1, 2, 4)                                            # distinct eigenvalues

    def pencil(l1, l2, x, rows):
        # (LAMBDA12): Lambda_1(xi + eta, zeta + theta)|_x = <x, [xi, zeta] + [xi, theta] + [eta, zeta]>,
        # Lambda_2(y, z)|_x = <x - A, [y, z]>
        def form(a, b):
            (xi, eta), (zeta, theta) = a, b
            lam1 = ip(x, br(xi, zeta) + br(xi, theta) + br(eta, zeta))
            lam2 = ip(x - A, br(xi + eta, zeta + theta))
            return l1 * lam1 + l2 * lam2
        return sp.Matrix(len(rows), len(basis), lambda a, b: form(rows[a], basis[b]))
    so_rows = basis[:len(so)]
    x = sp.Matrix([[1, 2, -1], [3, 5, 7], [-2, 4, 6]])             # a generic point of gl(3)
    at_0 = pencil(-1, 1, sp.zeros(n, n), so_rows)
    assert pencil(-1, 1, x, so_rows) == at_0                       # the so(n) rows do not depend on x
    assert pencil(-1, 1, sp.zeros(n, n), basis).rank() == n * n - n  # rank n^2 - n at x = 0 (and everywhere)
    c = sp.Rational(1, 3)                                          # lambda_1 = 1 - c, lambda_2 = c: lambda_1 + lambda_2 = 1
    assert pencil(1 - c, c, c * A, basis) == sp.zeros(len(basis), len(basis))   # the whole bracket vanishes at cA
    return {"computed": at_0.rank(),                               # n(n - 1)/2 = 3
            "printed": 0,                                          # a point where the bracket vanishes
            "corrected_computed": pencil(1 - c, c, c * A, so_rows).rank(),  # Lambda_{1-c,c} vanishes at x0 = cA
            "corrected": 0,
            "meaning": "the rank of the so(n) rows of the pencil bracket at the point where it would vanish"}
