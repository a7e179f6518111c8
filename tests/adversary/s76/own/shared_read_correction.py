"""Stop 76's own attempt, on the class of the review's D1 (a change described at one of the places it is made):
a registered correction that changes a product read twice, once as it is and once transposed.

As printed, K + Kᵀ = 2Iᵣ with K = XᵀP (false: XᵀP + PᵀX = 0 on T*V).  The correction reads K = XᵀX, so that
K + Kᵀ = XᵀX + XᵀX = 2Iᵣ (true).  Described as "XᵀP → XᵀX", the correction would read XᵀX + PᵀX = 2Iᵣ, which is
false; the report must show the change at both places."""
from stiefelsym import claim


def residual(s, K):
    return K + K.T - s.Ir * 2


@claim("own-shared-read", kind="id", sizes=[(3, 2), (4, 2)], fails_at=lambda n, r: True,
       erratum="K = XᵀP in place of K = XᵀX.")
def shared_read(s):
    """K + Kᵀ = 2Iᵣ for K = XᵀP (as printed: false)."""
    return {"K + K^T - 2I": residual(s, s.X.T @ s.P)}


@shared_read.claim.correction("K = XᵀX in place of XᵀP")
def shared_read_corrected(s):
    return {"K + K^T - 2I": residual(s, s.X.T @ s.X)}
