"""A correction (and its twin as a mutate target) whose change is described by a printed text that
occurs at more places of the check than the change is made at.

K = XᵀP is one node, read as K and, transposed, as Kᵀ; a third term Xᵀ(P·λ) + (P·λ)ᵀX is computed apart
from K and prints "λXᵀP…" (it contains the text XᵀP).  The correction replaces K by XᵀX and leaves the third
term alone:

    printed   K + Kᵀ − 2Iᵣ + [third] ,  K = XᵀP      FALSE  (= −2Iᵣ on T*V)
    corrected K + Kᵀ − 2Iᵣ + [third] ,  K = XᵀX      TRUE   (= 0: the third term is λ(XᵀP + PᵀX) = 0)

If the report describes the correction as "XᵀP → XᵀX" in the check, the literal reading replaces the XᵀP of
the third term too, giving XᵀX + XᵀX − 2Iᵣ + λ(XᵀX + PᵀX) = λ(Iᵣ + PᵀX) ≠ 0: FALSE
(claim s76r2-literal-reading), while the correction made is TRUE (s76r2-actual-correction)."""
from stiefelsym import claim

SZ = [(3, 2), (4, 2)]


def third(s):
    Pl = s.P * s.lam
    return s.X.T @ Pl + Pl.T @ s.X


def residual(s, K):
    return K + K.T - s.Ir * 2 + third(s)


@claim("s76r2-partial", kind="id", sizes=SZ, fails_at=lambda n, r: True,
       erratum="K = XᵀP in place of K = XᵀX (the third term is left as it is).")
def partial(s):
    """K + Kᵀ − 2Iᵣ + λ(XᵀP + PᵀX) = 0 for K = XᵀP (as printed: false)."""
    return {"res": residual(s, s.X.T @ s.P)}


@partial.claim.correction("K = XᵀX in place of K = XᵀP")
def partial_corrected(s):
    return {"res": residual(s, s.X.T @ s.X)}


@claim("s76r2-actual-correction", kind="id", sizes=SZ)
def actual(s):
    """TRUE: the correction made, XᵀX + XᵀX − 2Iᵣ + λ(XᵀP + PᵀX) = 0."""
    return {"res": residual(s, s.X.T @ s.X)}


@claim("s76r2-literal-reading", kind="id", sizes=SZ)
def literal(s):
    """FALSE: the description read literally, every XᵀP replaced: XᵀX + XᵀX − 2Iᵣ + λ(XᵀX + PᵀX)."""
    Pl = s.P * s.lam
    return {"res": s.X.T @ s.X + s.X.T @ s.X - s.Ir * 2 + s.lam * (s.X.T @ s.X) + Pl.T @ s.X}
