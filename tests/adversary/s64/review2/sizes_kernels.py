# ruff: noqa
"""Size declarations and kernel certificates (q64).

* r_in with an r the dimension-free method has no letters for (r = 3), and unions (2, "n"), (1, 2):
  E1E1ᵀ + E2E2ᵀ = I_r is true at r = 2 only; at r = 3 false.
* a kernel made of constant basis vectors that is a kernel at the chart's X₀ only."""
from stiefelsym import Rank, admissible, claim, twisted
from stiefelsym.bases import matrix_of, matrix_units, so_basis


def two_columns(s):
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"E1E1t+E2E2t": E1 @ E1.T + E2 @ E2.T - s.Ir}


@claim("q64-rin-3-false", kind="id", sizes=admissible(n_max=4, r_in=(3,)))
def rin3(s):
    """E₁E₁ᵀ + E₂E₂ᵀ = I_r at r = 3 (false)."""
    return two_columns(s)


@claim("q64-rin-2n-false", kind="id", sizes=admissible(n_max=4, r_in=(2, "n")))
def rin2n(s):
    """E₁E₁ᵀ + E₂E₂ᵀ = I_r at r = 2 or r = n (false at r = n >= 3)."""
    return two_columns(s)


@claim("q64-rin-12-false", kind="id", sizes=admissible(n_max=4, r_in=(1, 2)))
def rin12(s):
    """XE₁E₁ᵀXᵀ = XXᵀ at r = 1 or 2 (false at r = 2)."""
    E1 = twisted.basis_vector(s, 0)
    return {"proj": s.X @ E1 @ E1.T @ s.X.T - s.X @ s.X.T}


@claim("q64-rin-2-true", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def rin2(s):
    """E₁E₁ᵀ + E₂E₂ᵀ = I_r at r = 2 (true)."""
    return two_columns(s)


@claim("q64-kernel-x0-false", kind="dim", sizes=admissible(n_max=4, n_min=3, where=lambda n, r: r <= n - 2,
                                                            condition="r <= n - 2"))
def kernel_x0(s):
    """ξ ↦ ξX on so(n) has rank (n−r)(n−r−1)/2 ... printed with the constant kernel of the basis elements
    E_i∧E_j, i, j > r (the kernel at X₀ = (E₁ … E_r) only).  The true rank is nr − r(r+1)/2; printed rank
    n(n−1)/2 − #kernel = nr − r(r+1)/2 is TRUE; so also a false variant below."""
    n, r = int(s.n), int(s.r)
    basis = so_basis(s, "n")
    M = matrix_of(s, lambda xi: xi @ s.X, basis)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    cols = [[1 if (a, b) == p else 0 for p in pairs] for (a, b) in pairs if a >= r and b >= r]
    K = s.mat([[c[k] for c in cols] for k in range(len(pairs))])
    return {"rank": Rank(M, n * r - r * (r + 1) // 2, kernel=K)}


@claim("q64-kernel-x0-low-false", kind="dim", sizes=admissible(n_max=4, n_min=3, where=lambda n, r: r <= n - 2,
                                                                condition="r <= n - 2"))
def kernel_x0_low(s):
    """The same map restricted to the span of E_i∧E_j, i < j, j > r ... printed rank 0 with the kernel of all
    the basis elements E_i∧E_j, i, j > r (false: ξ ↦ ξX is nonzero on them at a generic X)."""
    n, r = int(s.n), int(s.r)
    pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    basis = so_basis(s, "n")
    sub = [b for b, (i, j) in zip(basis, pairs) if i >= r and j >= r]
    M = matrix_of(s, lambda xi: xi @ s.X, sub)
    K = s.mat([[1 if a == b else 0 for b in range(len(sub))] for a in range(len(sub))])
    return {"rank": Rank(M, 0, kernel=K)}
