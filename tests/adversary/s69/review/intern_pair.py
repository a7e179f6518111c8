# ruff: noqa
"""Claims whose checks split into groups (some read coordinates of R^n, some do not), with equal slices across
claims: a slice interned for one claim is then the other's.  Verdicts must be each claim's own."""
from stiefelsym import admissible, claim

S = admissible(n_max=4)


@claim("ip-a", kind="id", sizes=S)
def a(s):
    """XᵀX = I and X₁₁ − X₁₁ = 0 (true)."""
    return {"gram": s.X.T @ s.X - s.Ir, "entry": s.X[0, 0] - s.X[0, 0] + 0 * s.P[0, 0]}


@claim("ip-b", kind="id", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def b(s):
    """XᵀX = I (true) and X₁₁ = 0 (false)."""
    return {"gram": s.X.T @ s.X - s.Ir, "entry": s.X[0, 0]}


@claim("ip-c", kind="id", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def c(s):
    """XᵀX = 2I (false) and the entry check of ip-a (true)."""
    return {"gram": s.X.T @ s.X - 2 * s.Ir, "entry": s.X[0, 0] - s.X[0, 0] + 0 * s.P[0, 0]}


@claim("ip-d", kind="id", sizes=S, fails_at=lambda n, r: True, erratum="false on purpose")
def d(s):
    """The gram check under another name, false, and ip-a's true entry check under the name 'gram'."""
    return {"entry": s.X.T @ s.X - 2 * s.Ir, "gram": s.X[0, 0] - s.X[0, 0] + 0 * s.P[0, 0]}


@claim("ip-e", kind="id", sizes=S)
def e(s):
    """ip-a's checks in the other order (true)."""
    return {"entry": s.X[0, 0] - s.X[0, 0] + 0 * s.P[0, 0], "gram": s.X.T @ s.X - s.Ir}


@claim("ip-f", kind="id", sizes=S, fails_at=lambda n, r: r < n, erratum="false on purpose")
def f(s):
    """XᵀX = I (true) and XXᵀ = I_n (false for r < n) with an entry read (true)."""
    return {"gram": s.X.T @ s.X - s.Ir, "outer": s.X @ s.X.T - s.In + 0 * s.X[0, 0] * s.In}
