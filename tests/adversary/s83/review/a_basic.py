"""Stop 83 review (h2): the exact method's reassociated traces tr(x @ y), y a sum of signed products (new in 96621a3a).
Claims -t- are true, -f- false (one change each); the docstring says why.  The independent numpy check is
a_basic.py.in (it builds the same matrices at random real points on V_{n,r} and prints each residual)."""
from stiefelsym import admissible, claim, comm

S = admissible(n_min=3, n_max=4, r_min=1, r_max=3)


def _m(s):
    F = s.X @ s.P.T - s.P @ s.X.T          # so(n)
    G = s.A @ F - F @ s.A                  # [A, F]
    M = s.generic("M", "n", "n")
    return F, G, M


@claim("adv-s83r-t-mixed-signs", paper="adv", kind="id", sizes=S)
def t_mixed(s):
    """True: tr(M (FG − GF + ΦF − ΦF + GG − GG − FG + GF + AΦ)) = tr(M A Φ): everything but AΦ cancels
    (FG − GF and −FG + GF cancel pairwise as products, ΦF − ΦF and GG − GG cancel), compared with tr((MA)Φ)
    read otherwise."""
    F, G, M = _m(s)
    Phi, A = s.Phi, s.A
    y = F @ G - G @ F + Phi @ F - Phi @ F + G @ G - G @ G - F @ G + G @ F + A @ Phi
    return {"c": s.tr(M @ y) - s.tr((M @ A) @ Phi)}


@claim("adv-s83r-f-mixed-signs", paper="adv", kind="id", sizes=S)
def f_mixed(s):
    """False: the same with the last −FG written +FG (then y = 2FG − GF + ... no longer cancels: tr(M (FG+GF)) ≠ 0
    for generic M)."""
    F, G, M = _m(s)
    Phi, A = s.Phi, s.A
    y = F @ G - G @ F + Phi @ F - Phi @ F + G @ G - G @ G + F @ G + G @ F + A @ Phi
    return {"c": s.tr(M @ y) - s.tr((M @ A) @ Phi)}


@claim("adv-s83r-t-dup-commutator", paper="adv", kind="id", sizes=S)
def t_dup(s):
    """True: tr(M (FG − GF − GF)) = tr(MFG) − 2 tr(MGF) (a commutator plus a leftover −GF: _parts pairs FG with one
    −GF and keeps the other as a product)."""
    F, G, M = _m(s)
    return {"c": s.tr(M @ (F @ G - G @ F - G @ F)) - s.tr((M @ F) @ G) + 2 * s.tr((M @ G) @ F)}


@claim("adv-s83r-f-dup-commutator", paper="adv", kind="id", sizes=S)
def f_dup(s):
    """False: the same with −tr(MGF) once instead of twice."""
    F, G, M = _m(s)
    return {"c": s.tr(M @ (F @ G - G @ F - G @ F)) - s.tr((M @ F) @ G) + s.tr((M @ G) @ F)}


@claim("adv-s83r-t-y-first", paper="adv", kind="id", sizes=S)
def t_yfirst(s):
    """True: tr((FG − GF + ΦA) M) = tr(M(FG − GF + ΦA)) (the sum on the left of the product; cyclic trace)."""
    F, G, M = _m(s)
    return {"c": s.tr((F @ G - G @ F + s.Phi @ s.A) @ M) - s.tr((M @ F) @ G) + s.tr((M @ G) @ F)
            - s.tr((M @ s.Phi) @ s.A)}


@claim("adv-s83r-f-y-first", paper="adv", kind="id", sizes=S)
def f_yfirst(s):
    """False: tr((FG − GF + ΦA) M) = tr(M(FG − GF + AΦ)) (AΦ for ΦA)."""
    F, G, M = _m(s)
    return {"c": s.tr((F @ G - G @ F + s.Phi @ s.A) @ M) - s.tr((M @ F) @ G) + s.tr((M @ G) @ F)
            - s.tr((M @ s.A) @ s.Phi)}


@claim("adv-s83r-t-rect", paper="adv", kind="id", sizes=S)
def t_rect(s):
    """True: rectangular factors. tr(M (X Pᵀ − P Xᵀ)) = 2 tr(M X Pᵀ) − tr(M (X Pᵀ + P Xᵀ))... written as
    tr(M(XPᵀ − PXᵀ)) − tr(PᵀMX) + tr(XᵀMP) = 0 and on ℝʳ: tr(Ψ (XᵀP − PᵀX)) = tr(Ψ Ψ)."""
    F, G, M = _m(s)
    X, P = s.X, s.P
    return {"n": s.tr(M @ (X @ P.T - P @ X.T)) - s.tr(P.T @ (M @ X)) + s.tr(X.T @ (M @ P)),
            "r": s.tr(s.Psi @ (X.T @ P - P.T @ X)) - s.tr(s.Psi @ s.Psi)}


@claim("adv-s83r-f-rect", paper="adv", kind="id", sizes=S)
def f_rect(s):
    """False: tr(Ψ (XᵀP + PᵀX)) = tr(Ψ Ψ) (false where Ψ ≠ 0, i.e. r >= 2; at r = 1 Ψ = 0 and XᵀP = 0 on V so it
    holds: the twin fails at r >= 2 only)."""
    X, P = s.X, s.P
    return {"r": s.tr(s.Psi @ (X.T @ P + P.T @ X)) - s.tr(s.Psi @ s.Psi)}


@claim("adv-s83r-t-shared-cluster", paper="adv", kind="id", sizes=S)
def t_cluster(s):
    """True: three traces share the commutator C = [F, G] (two tr, one killing): tr(M C) + tr(A C) + <M, C>
    = tr((M + A − M/2) C), the right side read as tr of products made otherwise."""
    F, G, M = _m(s)
    C = comm(F, G)
    lhs = s.tr(M @ C) + s.tr(s.A @ C) + s.killing(M, C)
    W = M + s.A - M / 2
    rhs = s.tr((W @ F) @ G) - s.tr((W @ G) @ F)
    return {"c": lhs - rhs}


@claim("adv-s83r-f-shared-cluster", paper="adv", kind="id", sizes=S)
def f_cluster(s):
    """False: the killing term counted as +M/2 instead of −M/2 (tr(M [F, G]) ≠ 0 for generic M)."""
    F, G, M = _m(s)
    C = comm(F, G)
    lhs = s.tr(M @ C) + s.tr(s.A @ C) + s.killing(M, C)
    W = M + s.A + M / 2
    rhs = s.tr((W @ F) @ G) - s.tr((W @ G) @ F)
    return {"c": lhs - rhs}


@claim("adv-s83r-t-x-in-y", paper="adv", kind="id", sizes=S)
def t_x_in_y(s):
    """True: x is a factor of its own y: tr(M (M F − F M)) = 0 (tr(MMF) = tr(MFM)), and tr(M (MF + FM)) = 2tr(MMF)."""
    F, G, M = _m(s)
    return {"a": s.tr(M @ (M @ F - F @ M)), "b": s.tr(M @ (M @ F + F @ M)) - 2 * s.tr((M @ M) @ F)}


@claim("adv-s83r-f-x-in-y", paper="adv", kind="id", sizes=S)
def f_x_in_y(s):
    """False: tr(M (M F + F M)) = 0 (generic M: 2 tr(M² F) ≠ 0 since F is skew, M² is not symmetric)."""
    F, G, M = _m(s)
    return {"b": s.tr(M @ (M @ F + F @ M))}


@claim("adv-s83r-t-nested-y", paper="adv", kind="id", sizes=S)
def t_nested(s):
    """True: y's product factor is itself a trace's y elsewhere: C = FG read as factor of C Φ and as y of tr(M C):
    tr(M C) + tr(A (C Φ − Φ C)) = tr(MFG) + tr([A, C] Φ)."""
    F, G, M = _m(s)
    C = F @ G
    lhs = s.tr(M @ C) + s.tr(s.A @ (C @ s.Phi - s.Phi @ C))
    rhs = s.tr((M @ F) @ G) + s.tr(((s.A @ F) @ G) @ s.Phi) - s.tr((F @ (G @ s.A)) @ s.Phi)
    return {"c": lhs - rhs}


@claim("adv-s83r-f-nested-y", paper="adv", kind="id", sizes=S)
def f_nested(s):
    """False: with M for Φ (generic: tr([A, FG] M) ≠ 0), the commutator's sign reversed on the right."""
    F, G, M = _m(s)
    C = F @ G
    lhs = s.tr(M @ C) + s.tr(s.A @ (C @ M - M @ C))
    rhs = s.tr((M @ F) @ G) - s.tr(((s.A @ F) @ G) @ M) + s.tr((F @ (G @ s.A)) @ M)
    return {"c": lhs - rhs}
