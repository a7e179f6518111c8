"""Determinants of square lists of scalars, without a division, and the characteristic polynomial of a matrix
from the traces of its powers (claim code shared by the sections)."""
from __future__ import annotations

from math import comb

from stiefelsym import elementary


def det(s, rows):
    """The determinant of a square list of lists of scalars, without a division: the Laplace expansion
    along the first row (memoized by minor, about m 2^(m-1) products) or, where it takes at most half
    as many products, Berkowitz's recursion (about m^4/4 products: from m = 10 on, e.g. 2r x 2r at
    r >= 5; 8k products against 115k at m = 14)."""
    m = len(rows)
    if 2 * _berkowitz_products(m) <= _laplace_products(m):
        return _det_berkowitz(s, rows)
    memo = {}

    def minor(k, cols):
        # the determinant of rows k.. and the columns cols (a tuple of m - k indices)
        if k == m:
            return s.q(1)
        key = (k, cols)
        if key not in memo:
            acc = s.q(0)
            for pos, c in enumerate(cols):
                term = rows[k][c] * minor(k + 1, cols[:pos] + cols[pos + 1:])
                acc = acc - term if pos % 2 else acc + term
            memo[key] = acc
        return memo[key]
    return minor(0, tuple(range(m)))


def _laplace_products(m):
    """The products of the memoized Laplace expansion of an m x m determinant."""
    return sum(comb(m, k) * (m - k) for k in range(m))


def _berkowitz_products(m):
    """The products of Berkowitz's recursion for an m x m determinant (vectors R M^j C, then the
    Toeplitz products)."""
    return sum((k - 1) * (k - 1) * max(k - 2, 0) + (k - 1) + k * (k + 1) // 2 for k in range(1, m + 1))


def _det_berkowitz(s, rows):
    """det A by Berkowitz's division-free recursion: with A_k the leading k x k block of A, its
    characteristic polynomial p_k(x) = det(x I - A_k) is T_k p_(k-1), T_k the lower triangular
    Toeplitz matrix with first column (1, -a, -R C, -R M C, ..., -R M^(k-2) C), where
    A_k = [[M, C], [R, a]]; det A = (-1)^m p_m(0)."""
    m = len(rows)
    p = [s.q(1)]                                   # the coefficients of p_0, leading first
    for k in range(1, m + 1):
        a = rows[k - 1][k - 1]
        R = [rows[k - 1][j] for j in range(k - 1)]
        v = [rows[i][k - 1] for i in range(k - 1)]  # C, then M C, M^2 C, ...
        t = [s.q(1), s.q(0) - a]
        for _ in range(k - 1):
            acc = s.q(0)
            for x, y in zip(R, v):
                acc = acc + x * y
            t.append(s.q(0) - acc)
            if len(t) < k + 1:
                nv = []
                for i in range(k - 1):
                    acc = s.q(0)
                    for j in range(k - 1):
                        acc = acc + rows[i][j] * v[j]
                    nv.append(acc)
                v = nv
        q = []
        for i in range(k + 1):
            acc = s.q(0)
            for j in range(max(0, i - len(t) + 1), min(i, k - 1) + 1):
                acc = acc + t[i - j] * p[j]
            q.append(acc)
        p = q
    return p[m] if m % 2 == 0 else s.q(0) - p[m]



def charpoly(s, M, lam):
    """det(λI − M) = Σ_k (−1)^k e_k(M) λ^(m−k) of an m × m matrix M that maps a space to itself, from the
    coefficients e_k of :func:`stiefelsym.elementary` (the traces of the powers of M by Newton's
    identities): no entry of M is read, so a statement about the characteristic polynomial of a matrix on
    ℝⁿ stays covariant under O(n) (the exact method's equivariant chart), where an expansion by entries
    reads coordinates of ℝⁿ."""
    m = M.shape[0]
    e = elementary(s, M, m)
    out, lam_power = s.q(0), s.q(1)
    for k in range(m, -1, -1):          # the coefficient of λ^(m−k) is (−1)^k e_k
        out = out + lam_power * e[k] if k % 2 == 0 else out - lam_power * e[k]
        lam_power = lam_power * lam
    return out
