"""s89h1: the exact backend's common-factor step (products of rational matrices sharing factors).

K = XᵀP (skew), Φ = PXᵀ − XPᵀ, M = I_n − Φ² = I + ΦΦᵀ (positive definite: invertible everywhere).
 s89h1-minv-phi-commute (TRUE): M⁻¹Φ = ΦM⁻¹ (Φ commutes with M).
 s89h1-minv-xxt-commute (FALSE for r < n): M⁻¹XXᵀ = XXᵀM⁻¹.
 s89h1-resolvent-square (TRUE): R(μ)(μI − A)R(μ) = R(μ), R = (μI − A)⁻¹.
 s89h1-resolvent-square-twin (FALSE): R(μ)(μI − A)R(μ) = R(μ)², n ≥ 1.
 s89h1-resolvent-difference (TRUE, resolvent identity): R(μ) − R(ν) = (ν − μ)R(μ)R(ν).
 s89h1-resolvent-difference-twin (FALSE): R(μ) − R(ν) = (μ − ν)R(μ)R(ν).
 s89h1-mixed-denominators (TRUE): N = (I + KKᵀ)⁻¹; N(I + KKᵀ)XᵀX − I_r·1 ... :  N (I + KKᵀ) = I_r  and
    (XᵀX + KKᵀ) N = I_r  (XᵀX = I_r on T*V).
 s89h1-mixed-denominators-twin: N XᵀAX = XᵀAX N.  FALSE for r ≥ 3; TRUE for r ≤ 2 (at r = 2, K = kJ and
    KKᵀ = k²I_2, so N = I/(1 + k²) is a scalar matrix; at r = 1, K = 0).  (N K = K N is TRUE: K commutes with KKᵀ = −K².)
 s89h1-shared-factor-entries (TRUE): B = R(μ) X (XᵀR(μ)X)⁻¹: XᵀB = I_r (every entry of B shares the factor
    det(XᵀR X) only partly with the others).
 s89h1-shared-factor-entries-twin (FALSE): B Xᵀ = I_n (true only at r = n).
"""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


def M_of(s):
    return s.In - s.Phi @ s.Phi


@claim("s89h1-minv-phi-commute", kind="id", sizes=S)
def minv_phi(s):
    """M⁻¹Φ = ΦM⁻¹ (true)."""
    Mi = M_of(s).inv()
    return {"r": Mi @ s.Phi - s.Phi @ Mi}


@claim("s89h1-minv-xxt-commute", kind="id", sizes=S)
def minv_xxt(s):
    """M⁻¹XXᵀ = XXᵀM⁻¹ (false for r < n)."""
    Mi = M_of(s).inv()
    G = s.X @ s.X.T
    return {"r": Mi @ G - G @ Mi}


@claim("s89h1-resolvent-square", kind="id", sizes=S)
def res_sq(s):
    """R(μI − A)R = R (true)."""
    mu = s.scalar("mu")
    R = s.resolvent(mu)
    return {"r": R @ (mu * s.In - s.A) @ R - R}


@claim("s89h1-resolvent-square-twin", kind="id", sizes=S)
def res_sq_twin(s):
    """R(μI − A)R = R² (false)."""
    mu = s.scalar("mu")
    R = s.resolvent(mu)
    return {"r": R @ (mu * s.In - s.A) @ R - R @ R}


@claim("s89h1-resolvent-difference", kind="id", sizes=S)
def res_diff(s):
    """R(μ) − R(ν) = (ν − μ)R(μ)R(ν) (true)."""
    mu, nu = s.scalar("mu"), s.scalar("nu")
    return {"r": s.resolvent(mu) - s.resolvent(nu) - (nu - mu) * (s.resolvent(mu) @ s.resolvent(nu))}


@claim("s89h1-resolvent-difference-twin", kind="id", sizes=S)
def res_diff_twin(s):
    """R(μ) − R(ν) = (μ − ν)R(μ)R(ν) (false)."""
    mu, nu = s.scalar("mu"), s.scalar("nu")
    return {"r": s.resolvent(mu) - s.resolvent(nu) - (mu - nu) * (s.resolvent(mu) @ s.resolvent(nu))}


@claim("s89h1-mixed-denominators", kind="id", sizes=S)
def mixed(s):
    """N = (I + KKᵀ)⁻¹: N K = K N and (XᵀX + KKᵀ)N = I_r (true)."""
    K = s.X.T @ s.P
    N = (s.Ir + K @ K.T).inv()
    return {"comm": N @ K - K @ N, "inv": (s.X.T @ s.X + K @ K.T) @ N - s.Ir}


@claim("s89h1-mixed-denominators-twin", kind="id", sizes=S)
def mixed_twin(s):
    """N XᵀAX = XᵀAX N (false for r ≥ 2)."""
    K = s.X.T @ s.P
    N = (s.Ir + K @ K.T).inv()
    V = s.X.T @ s.A @ s.X
    return {"comm": N @ V - V @ N}


@claim("s89h1-shared-factor-entries", kind="id", sizes=S)
def shared(s):
    """B = R X (XᵀRX)⁻¹: XᵀB = I_r (true)."""
    R = s.resolvent(s.scalar("mu"))
    B = R @ s.X @ (s.X.T @ R @ s.X).inv()
    return {"r": s.X.T @ B - s.Ir}


@claim("s89h1-shared-factor-entries-twin", kind="id", sizes=S)
def shared_twin(s):
    """B Xᵀ = I_n (false for r < n; at r = n: B = R X X⁻¹R⁻¹X⁻ᵀ = X⁻ᵀ = X, BXᵀ = XXᵀ = I: true)."""
    R = s.resolvent(s.scalar("mu"))
    B = R @ s.X @ (s.X.T @ R @ s.X).inv()
    return {"r": B @ s.X.T - s.In}
