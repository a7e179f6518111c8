# ruff: noqa
"""A documented erratum whose registered correction is false: the headline and the list of errata call it verified."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("hle-erratum", paper="r65", kind="id", sizes=SZ, statement=r"X^T X = 2 I_r",
       fails_at=lambda n, r: True, erratum="the factor 2 is wrong")
def erratum_with_false_correction(s):
    """XᵀX = 2I_r, a known misprint; the registered correction XᵀX = 3I_r is false too."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}


@erratum_with_false_correction.claim.correction("XᵀX = 3I_r")
def _corr(s):
    return {"r": s.X.T @ s.X - 3 * s.Ir}
