"""s58 batch 5: check groups (exact) with checks that read entries of R^r only (not of R^n): they land in
the group 'reading no R^n', proved on the equivariant chart, whose O(r) right reduction (A11 diagonal)
would make an off-diagonal entry of XᵀAX vanish.  Indices are negative / sliced with odd steps."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def READ(s):
    return s.X[0, 0] * s.X[0, 0] - s.X[0, 0] * s.X[0, 0]      # reads an entry of R^n, identically 0


@claim("s58-g-rentry-false", kind="id", sizes=SZ)
def g_rentry_false(s):
    """(XᵀAX)[0, 1] = 0 (FALSE), beside a true check reading R^n."""
    return {"read": READ(s), "off": (s.X.T @ s.A @ s.X)[0, 1]}


@claim("s58-g-rentry-neg-false", kind="id", sizes=SZ)
def g_rentry_neg_false(s):
    """(XᵀAX)[-1, -2] = 0 (FALSE)."""
    return {"read": READ(s), "off": (s.X.T @ s.A @ s.X)[-1, -2]}


@claim("s58-g-rslice-rev-false", kind="id", sizes=SZ)
def g_rslice_rev_false(s):
    """tr((XᵀAX)[::-1, :]) = 0 (FALSE: the anti-diagonal sum 2·(XᵀAX)₁₂)."""
    return {"read": READ(s), "off": s.tr((s.X.T @ s.A @ s.X)[::-1, :])}


@claim("s58-g-rslice-step-false", kind="id", sizes=SZ)
def g_rslice_step_false(s):
    """(XᵀAX)[0:2:3, 1:] = 0 (FALSE: the 1x1 block (XᵀAX)₁₂)."""
    return {"read": READ(s), "off": (s.X.T @ s.A @ s.X)[0:2:3, 1:]}


@claim("s58-g-pp-false", kind="id", sizes=SZ)
def g_pp_false(s):
    """(PᵀP)[1, 0] = 0 (FALSE)."""
    return {"read": READ(s), "off": (s.P.T @ s.P)[1, 0]}


@claim("s58-g-psi-false", kind="id", sizes=SZ)
def g_psi_false(s):
    """Ψ[0, 1] = 0 (FALSE in general)."""
    return {"read": READ(s), "off": s.Psi[0, 1]}


@claim("s58-g-rentry-true", kind="id", sizes=SZ)
def g_rentry_true(s):
    """(XᵀP)[0, 1] + (XᵀP)[1, 0] = 0 (TRUE on T*V)."""
    M = s.X.T @ s.P
    return {"read": READ(s), "sym": M[0, 1] + M[-1, -2]}


@claim("s58-g-rentry-resolvent-false", kind="id", sizes=SZ)
def g_rentry_resolvent_false(s):
    """(Xᵀ R(λ) X)[0, 1] = 0 (FALSE)."""
    return {"read": READ(s), "off": (s.X.T @ s.resolvent(s.lam) @ s.X)[0, 1]}


@claim("s58-g-flow-false", kind="id", sizes=SZ)
def g_flow_false(s):
    """(Xᵀ Ẋ)[0, 1] = 0 along the Dirac flow of tr(PᵀAP)/2 + tr(XᵀAX)/2 (FALSE?)."""
    fl = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2)
    return {"read": READ(s), "off": (s.P.T @ fl.Pdot)[0, 1]}
