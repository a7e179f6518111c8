"""(2r-integrals): the general line for I_{2l}(lambda), read at l = 1 (where its two sums are all the terms),
has in its second sum the squares of all (e_j ^ p_i)_{I_2}, i, j = 1..r, and is not I_2(lambda) for r >= 2;
the correction puts (e_1 ^ p_1 + ... + e_r ^ p_r)_{I_2}^2 there."""
from itertools import combinations

import sympy as sp

CHECK = "𝓘₂ − the general line of (5) §8 at l = 1"


def residuals(W):
    X, P, A, lam = W["X"], W["P"], W["A"], W["lam"]
    n, r = X.shape
    a = [A[i, i] for i in range(n)]
    a_lam = sp.prod([lam - ai for ai in a])                     # a(lambda) = (lambda - a_1)...(lambda - a_n)
    R = (lam * sp.eye(n) - A).inv()
    L = sp.Matrix(sp.BlockMatrix([[-X.T * R * P, -X.T * R * X],                # (LA3): L*_neum(lambda)
                                  [sp.eye(r) + P.T * R * P, P.T * R * X]]))
    # |a L* - w I| = w^{2r} + w^{2r-2} a I_2 + ...: I_2 = a(lambda) e_2(L*), e_2 = ((tr L)^2 - tr L^2)/2
    I2 = a_lam * (L.trace() ** 2 - (L * L).trace()) / 2

    def weight(I):                                              # a(lambda)/((lambda - a_i1)...(lambda - a_ik))
        return a_lam / sp.prod([lam - a[i] for i in I])

    def form(vectors, I):                                       # (v_1 ^ ... ^ v_k)_I, the minor on the rows I
        return sp.Matrix.hstack(*vectors).extract(list(I), list(range(len(vectors)))).det()

    e = [X[:, j] for j in range(r)]
    p = [P[:, j] for j in range(r)]
    first = sum(weight((i,)) * sum(form([e[j]], (i,)) ** 2 for j in range(r)) for i in range(n))
    printed = I2 - (first + sum(weight(I) * sum(form([e[j], p[i]], I) ** 2           # the line at l = 1
                                              for j in range(r) for i in range(r))
                                for I in combinations(range(n), 2)))
    corrected = I2 - (first + sum(weight(I) * sum(form([e[j], p[j]], I) for j in range(r)) ** 2
                                  for I in combinations(range(n), 2)))          # (e_1^p_1 + ... + e_r^p_r)^2
    return {"printed": printed, "corrected": corrected}
