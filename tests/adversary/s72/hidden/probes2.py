# ruff: noqa
"""s72 probes, second set: graphs that read no point of T*V but depend on r (the r_dependence pass), a division
by a function that vanishes on T*V, and trace identities for the dimension-free rewriting."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, block, claim, comm

R_GE_2 = lambda n, r: r >= 2


@claim("p72-no-point-trace-ir", kind="id", sizes=admissible(n_max=3), fails_at=R_GE_2,
       erratum="probe: tr I_r = 1 holds at r = 1 only")
def no_point_trace_ir(s):
    """No point of T*V is read: tr(I_r) − 1 = 0 (false for r ≥ 2)."""
    return {"tr I_r - 1": s.tr(s.Ir) - 1}


@claim("p72-no-point-eta", kind="id", sizes=admissible(n_max=3), fails_at=R_GE_2,
       erratum="probe: <η, η> = 0 holds at r = 1 only")
def no_point_eta(s):
    """No point of T*V is read: <η, η> = 0 for the generic η ∈ so(r) (false for r ≥ 2)."""
    return {"<eta, eta>": s.killing(s.eta, s.eta)}


@claim("p72-no-point-a-and-r", kind="id", sizes=admissible(n_max=3), fails_at=R_GE_2,
       erratum="probe: tr A · (tr I_r − 1) = 0 holds at r = 1 only")
def no_point_a_and_r(s):
    """Reads A and I_r only: tr(A)·(tr(I_r) − 1) = 0 (false for r ≥ 2)."""
    return {"trA (tr I_r - 1)": s.tr(s.A) * (s.tr(s.Ir) - 1)}


@claim("p72-no-point-block-r", kind="id", sizes=admissible(n_max=3), fails_at=R_GE_2,
       erratum="probe: tr diag(I_r, I_r) = 2 at r = 1 only")
def no_point_block_r(s):
    """Reads a block of I_r only: tr diag(I_r, I_r) − 2 = 0 (false for r ≥ 2)."""
    Z = s.zeros(s.r, s.r, ("r", "r"))
    return {"tr diag(I, I) - 2": block([[s.Ir, Z], [Z, s.Ir]]).trace() - 2}


@claim("p72-divide-by-constraint", kind="id", sizes=admissible(n_max=3, r_max=2))
def divide_by_constraint(s):
    """0/0 on T*V: (c·tr PᵀP)/c − tr PᵀP with c = tr(XᵀP + PᵀX) + tr(XᵀX) − r, which vanishes on T*V; identically
    zero ambiently, undefined on T*V: must not be proved."""
    c = s.tr(s.X.T @ s.P + s.P.T @ s.X) + s.tr(s.X.T @ s.X) - s.tr(s.Ir)
    F = s.tr(s.P.T @ s.P)
    return {"(cF)/c - F": (c * F) / c - F}


def _man3_expanded(s, sign):
    X, P, A, lam = s.X, s.P, s.A, s.lam
    K = X.T @ P
    inner = s.tr(K @ X.T @ A @ P) * (2 * sign) - s.tr(P.T @ A @ P) - s.tr(P.T @ P @ X.T @ A @ X)
    M = s.Phi + A * lam
    return s.tr(M @ M @ M) - (inner * 3 * lam + s.tr(A @ A @ A) * (lam * lam * lam))


@claim("p72-man3-expanded", kind="id", sizes=admissible(n_max=4))
def man3_expanded(s):
    """(man) at k = 3 in coordinates: tr(Φ + λA)³ = 3λ[2tr(XᵀP·XᵀAP) − tr(PᵀAP) − tr(PᵀP·XᵀAX)] + λ³tr A³."""
    return {"tr(Phi + lam A)^3 - expanded": _man3_expanded(s, 1)}


@claim("p72-man3-expanded-sign", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: n >= 2 and r >= 2,
       erratum="probe: −2tr(XᵀP·XᵀAP)")
def man3_expanded_sign(s):
    """Twin: −2tr(XᵀP·XᵀAP) in place of +2."""
    return {"tr(Phi + lam A)^3 - twin": _man3_expanded(s, -1)}


@claim("p72-trace-skew-sym", kind="id", sizes=admissible(n_max=4))
def trace_skew_sym(s):
    """tr(XᵀP·PᵀP) = tr(XᵀP·PᵀAP) = tr(XᵀP·XᵀAX) = tr((XᵀP)³) = 0 (skew times symmetric; odd power of a skew)."""
    K = s.X.T @ s.P
    return {"a": s.tr(K @ s.P.T @ s.P), "b": s.tr(K @ s.P.T @ s.A @ s.P), "c": s.tr(K @ s.X.T @ s.A @ s.X),
            "d": s.tr(K @ K @ K)}


@claim("p72-trace-xap", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r < n,
       erratum="probe: tr XᵀAP = 0 holds at r = n only")
def trace_xap(s):
    """tr(XᵀAP) = 0: false for r < n, true at r = n (XᵀAP = XᵀAX·XᵀP, symmetric times skew)."""
    return {"tr X^TAP": s.tr(s.X.T @ s.A @ s.P)}
