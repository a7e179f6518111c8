"""Adversary (generic kinds): the exact method's reduced charts (diagonal chart: A = diag(a) when no point is read;
equivariant chart with A11 diagonal by O(r) on the right; Cayley chart with X = I at r = n) with symmetric and skew
generic matrices, which must move with the reduction and stay generic: false statements that hold only when S
commutes with A, with A11, or when S_r coincides with S_n at r = n."""
from stiefelsym import claim, admissible, Size, SizeSpec

S = admissible(n_max=4)
SQ = SizeSpec((Size(2, 2), Size(3, 3), Size(4, 4)))


@claim("adv-gk-chart-diag-false", paper="adv", kind="id", sizes=S)
def diag_false(s):
    """False: tr(ASAS) = tr(A²S²) (no point read: the diagonal chart)."""
    Sm = s.generic("S", "n", "n", "sym")
    return {"x": (s.A @ Sm @ s.A @ Sm).trace() - (s.A @ s.A @ Sm @ Sm).trace()}


@claim("adv-gk-chart-diag-true", paper="adv", kind="id", sizes=S)
def diag_true(s):
    """True: AS + SA is symmetric, tr(AK) = 0, AK + KA is skew."""
    Sm, K = s.generic("S", "n", "n", "sym"), s.generic("K", "n", "n", "skew")
    M = s.A @ Sm + Sm @ s.A
    N = s.A @ K + K @ s.A
    return {"sym": M - M.T, "tr(AK)": (s.A @ K).trace(), "skew": N + N.T}


@claim("adv-gk-chart-right-false", paper="adv", kind="id", sizes=S)
def right_false(s):
    """False: (XᵀAX) S_r = S_r (XᵀAX) (A11 and S_r do not commute)."""
    Sr = s.generic("S", "r", "r", "sym")
    F = s.X.T @ s.A @ s.X
    return {"x": F @ Sr - Sr @ F}


@claim("adv-gk-square-false", paper="adv", kind="id", sizes=SQ)
def square_false(s):
    """False at r = n: X S_r Xᵀ = S_n (two generic symmetric matrices, the same name, at r = n)."""
    return {"x": s.X @ s.generic("S", "r", "r", "sym") @ s.X.T - s.generic("S", "n", "n", "sym")}


@claim("adv-gk-square-skew-false", paper="adv", kind="id", sizes=SQ)
def square_skew_false(s):
    """False at r = n: tr(K_r Ψ) = tr(K_n Φ) (Ψ = XᵀΦX at r = n, but K_r ≠ XᵀK_nX)."""
    return {"x": (s.generic("K", "r", "r", "skew") @ s.Psi).trace() - (s.generic("K", "n", "n", "skew") @ s.Phi).trace()}


@claim("adv-gk-square-true", paper="adv", kind="id", sizes=SQ)
def square_true(s):
    """True at r = n: tr((X K_r Xᵀ) Φ) = tr(K_r Ψ), X S_r Xᵀ symmetric."""
    Kr, Sr = s.generic("K", "r", "r", "skew"), s.generic("S", "r", "r", "sym")
    M = s.X @ Sr @ s.X.T
    return {"x": (s.X @ Kr @ s.X.T @ s.Phi).trace() - (Kr @ s.Psi).trace(), "sym": M - M.T}
