"""The review's own trick on the chart skip of stop 94 (a graph that reads coordinates of ℝⁿ, with no reviewed
reason of equivariance, goes straight to the unconstrained or Cayley chart): statements that hold on the
equivariant chart's reduced points (X = (I; 0) at generic P) but not on T*V, beside true twins."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4, n_min=2)


@claim("s94-first-rows-unit", kind="id", sizes=SZ, expect="holds")
def first_rows_unit(s):
    """Σ_{i<r} X_{i1}² = 1 (false: the first column has its weight on every row; true at X = (I; 0))."""
    r = int(s.r)
    tot = s.q(0)
    for i in range(r):
        tot = tot + s.X[i, 0] * s.X[i, 0]
    return {"r": tot - s.q(1)}


@claim("s94-column-unit", kind="id", sizes=SZ, expect="holds")
def column_unit(s):
    """Σ_i X_{i1}² = 1 (true: XᵀX = I_r)."""
    n = int(s.n)
    tot = s.q(0)
    for i in range(n):
        tot = tot + s.X[i, 0] * s.X[i, 0]
    return {"r": tot - s.q(1)}


@claim("s94-last-row-zero", kind="id", sizes=SZ, expect="holds")
def last_row_zero(s):
    """X_{n1} P_{n1} = 0 (false; 0 at X = (I; 0) when r < n)."""
    n = int(s.n)
    return {"r": s.X[n - 1, 0] * s.P[n - 1, 0]}


@claim("s94-xtp-diag", kind="id", sizes=SZ, expect="holds")
def xtp_diag(s):
    """(XᵀP)_{11} = 0, read through entries of X and P (true: XᵀP is skew)."""
    n = int(s.n)
    tot = s.q(0)
    for i in range(n):
        tot = tot + s.X[i, 0] * s.P[i, 0]
    return {"r": tot}
