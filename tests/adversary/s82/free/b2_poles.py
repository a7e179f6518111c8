"""Batch 2: resolvents at two parameters that coincide on the claim's own family of sizes.

  b2-sq-commute   at r = n (declared): R(l) R(l + n - r) = R(l + n - r) R(l)          TRUE (the two are one matrix there)
  b2-sq-product   at r = n: R(l) R(l + n - r) = R(l)^2                                 TRUE at r = n (one matrix)
  b2-r2-commute   at r = 2 (declared): R(l) R(l + r - 2) = R(l + r - 2) R(l)           TRUE
  b2-r1-commute   at r = 1 (declared): R(l) R(l + r - 1) = R(l + r - 1) R(l)           TRUE
  b2-sq-ntrace    at r = n: tr(R(l) R(l+n-r)) (n - r) = tr R(l) - tr R(l+n-r)           TRUE (0 = 0)
"""
from stiefelsym import admissible, claim


def _pair(s, shift):
    return s.resolvent(s.lam), s.resolvent(s.lam + shift)


@claim("b2-sq-commute", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def sq_commute(s):
    R1, R2 = _pair(s, s.tr(s.In) - s.tr(s.Ir))
    return {"[R1, R2]": R1 @ R2 - R2 @ R1}


@claim("b2-sq-product", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def sq_product(s):
    R1, R2 = _pair(s, s.tr(s.In) - s.tr(s.Ir))
    return {"R1R2 - R1^2": R1 @ R2 - R1 @ R1}


@claim("b2-r2-commute", kind="id", sizes=admissible(n_max=5, r_min=2, r_max=2))
def r2_commute(s):
    R1, R2 = _pair(s, s.tr(s.Ir) - 2)
    return {"[R1, R2]": R1 @ R2 - R2 @ R1}


@claim("b2-r1-commute", kind="id", sizes=admissible(n_max=5, r_min=1, r_max=1))
def r1_commute(s):
    R1, R2 = _pair(s, s.tr(s.Ir) - 1)
    return {"[R1, R2]": R1 @ R2 - R2 @ R1}


@claim("b2-sq-ntrace", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def sq_ntrace(s):
    R1, R2 = _pair(s, s.tr(s.In) - s.tr(s.Ir))
    return {"tr": s.tr(R1 @ R2) * (s.tr(s.In) - s.tr(s.Ir)) - s.tr(R1) + s.tr(R2)}
