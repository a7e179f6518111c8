"""The truth behind discover_scaled_flow.py:flow_none: along (10¹² + 39)·(N0_XP2), 𝓛(λ) = λΦ + XXᵀ − λ²A of (LA2)
satisfies d𝓛/dt = [(10¹² + 39)(Φ − λA), 𝓛]: TRUE, so a Lax partner of the searched shape exists."""
from stiefelsym import admissible, claim, comm

C = 10**12 + 39


def flow(s):
    X, P, A = s.X, s.P, s.A
    return {"X": (P - X @ P.T @ X) * C,
            "P": (-(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X) * C}


def L(t):
    return t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A


@claim("s75-discover-partner-exists", kind="lax", sizes=admissible(n_max=4))
def partner_exists(s):
    """d𝓛/dt = [c(Φ − λA), 𝓛] along c·(N0_XP2), c = 10¹² + 39: TRUE."""
    return {"lax": s.d(L, flow(s)) - comm((s.Phi - s.lam * s.A) * C, L(s))}


@claim("s75-correction-exists", kind="id", sizes=admissible(n_max=4))
def correction_exists(s):
    """Ẋ = P, Ṗ = −cAX + cXXᵀAX − XPᵀP keeps XᵀX = I and XᵀP + PᵀX = 0 (c = 10¹² + 39): TRUE, so the correction
    search of correction_big_coefficient.py.in has a solution."""
    X, P, A = s.X, s.P, s.A
    tangent = {"X": P, "P": -(A @ X) * C + X @ X.T @ A @ X * C - X @ P.T @ P}
    return {"d(XᵀX)/dt": s.d(lambda t: t.X.T @ t.X, tangent),
            "d(XᵀP + PᵀX)/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, tangent)}



CB = 2**40 + 1


def flow_still(s):
    return {"X": s.X * 0, "P": s.X @ s.Psi}


def L_big(t):
    return t.X @ t.X.T + t.A * CB


@claim("s75-printed-homogeneous", kind="lax", sizes=admissible(n_max=4))
def printed_homogeneous(s):
    """dL/dt = [A + (2097152/2097153)XXᵀ, L] for L = XXᵀ + (2⁴⁰ + 1)A along Ẋ = 0, Ṗ = XΨ (what discover printed as a
    partner, "A(λ) = 0 + any multiple of A + 2097152/2097153·XXᵀ"): FALSE ((1 − kc)[A, XXᵀ] ≠ 0)."""
    W = s.A + s.X @ s.X.T * s.q(2097152, 2097153)
    return {"lax": s.d(L_big, flow_still(s)) - comm(W, L_big(s))}


@claim("s75-true-homogeneous", kind="lax", sizes=admissible(n_max=4))
def true_homogeneous(s):
    """The same with A + XXᵀ/(2⁴⁰ + 1): TRUE (it is L/c)."""
    W = s.A + s.X @ s.X.T * s.q(1, CB)
    return {"lax": s.d(L_big, flow_still(s)) - comm(W, L_big(s))}
