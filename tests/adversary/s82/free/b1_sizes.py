"""Batch 1: identities that hold only at particular sizes, and resolvents whose parameters differ by a size.

Truths by hand (numpy check in b1_sizes.py.in):
  b1-res-nr-product   (n - r) R(l) R(l + n - r) = R(l) - R(l + n - r)                 TRUE at every size (resolvent identity; 0 = 0 at r = n)
  b1-res-nr-commute   R(l) R(l + n - r) = R(l + n - r) R(l)                            TRUE at every size
  b1-res-nr-equal     R(l) = R(l + n - r)                                              FALSE for r < n (true at r = n only)
  b1-res-nr-square    R(l) R(l + n - r) = R(l)^2                                       FALSE for r < n
  b1-ch-r2            Cayley-Hamilton of M = X^T A X at r = 2 (declared)               TRUE
  b1-ch-r2-false      the same with the constant term's 1/2 dropped                    FALSE at r = 2
  b1-ch-every-r       Cayley-Hamilton (2x2 form) at every r                            FALSE at r >= 3 (and r = 1: M^2 - tr M M = 0 but
                                                                                        the constant 1/2 (trM^2 - trM^2)=0 -> true at r = 1; false at r=3)
  b1-r1-xtp           X^T P = 0 at r = 1 (declared)                                    TRUE
  b1-r1-xtp-every     X^T P = 0 at every r                                             FALSE at r >= 2
  b1-rn-xxt           X X^T = I_n at r = n (declared)                                  TRUE
  b1-rn-pxt           P X^T + X P^T = 0 at r = n                                       TRUE
  b1-rn-pxt-every     P X^T + X P^T = 0 at every r                                     FALSE for r < n
  b1-lead-trace       tr(E_<r^T E_<r) = r - 1 (every r)                                TRUE
  b1-lead-trace-false tr(E_<r E_<r^T) = r                                              FALSE
  b1-lead-square      X E_<r E_<r^T X^T + X E_r E_r^T X^T = I_n at r = n               TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym import twisted


def _two(s):
    mu = s.lam + s.tr(s.In) - s.tr(s.Ir)
    return s.resolvent(s.lam), s.resolvent(mu), s.tr(s.In) - s.tr(s.Ir)


@claim("b1-res-nr-product", kind="id", sizes=admissible(n_max=4))
def res_nr_product(s):
    R1, R2, d = _two(s)
    return {"(n-r)R1R2 - R1 + R2": (R1 @ R2) * d - R1 + R2}


@claim("b1-res-nr-commute", kind="id", sizes=admissible(n_max=4))
def res_nr_commute(s):
    R1, R2, d = _two(s)
    return {"[R1, R2]": R1 @ R2 - R2 @ R1}


@claim("b1-res-nr-equal", kind="id", sizes=admissible(n_max=4))
def res_nr_equal(s):
    R1, R2, d = _two(s)
    return {"R1 - R2": R1 - R2}


@claim("b1-res-nr-square", kind="id", sizes=admissible(n_max=4))
def res_nr_square(s):
    R1, R2, d = _two(s)
    return {"R1R2 - R1^2": R1 @ R2 - R1 @ R1}


def _ch(s, half):
    M = s.X.T @ s.A @ s.X
    t1, t2 = s.tr(M), s.tr(M @ M)
    return M @ M - M * t1 + s.Ir * ((t1 * t1 - t2) * half)


@claim("b1-ch-r2", kind="id", sizes=admissible(n_max=5, r_min=2, r_max=2))
def ch_r2(s):
    return {"CH": _ch(s, s.q(1, 2))}


@claim("b1-ch-r2-false", kind="id", sizes=admissible(n_max=5, r_min=2, r_max=2))
def ch_r2_false(s):
    return {"CH": _ch(s, s.q(1))}


@claim("b1-ch-every-r", kind="id", sizes=admissible(n_max=4))
def ch_every(s):
    return {"CH": _ch(s, s.q(1, 2))}


@claim("b1-r1-xtp", kind="id", sizes=admissible(n_max=5, r_min=1, r_max=1))
def r1_xtp(s):
    return {"XtP": s.X.T @ s.P}


@claim("b1-r1-xtp-every", kind="id", sizes=admissible(n_max=4))
def r1_xtp_every(s):
    return {"XtP": s.X.T @ s.P}


@claim("b1-rn-xxt", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def rn_xxt(s):
    return {"XXt - I": s.X @ s.X.T - s.In}


@claim("b1-rn-pxt", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def rn_pxt(s):
    return {"PXt + XPt": s.P @ s.X.T + s.X @ s.P.T}


@claim("b1-rn-pxt-every", kind="id", sizes=admissible(n_max=4))
def rn_pxt_every(s):
    return {"PXt + XPt": s.P @ s.X.T + s.X @ s.P.T}


@claim("b1-lead-trace", kind="id", sizes=admissible(n_max=4))
def lead_trace(s):
    L = twisted.leading_basis_vectors(s)
    return {"tr(LtL) - r + 1": s.tr(L.T @ L) - s.tr(s.Ir) + 1}


@claim("b1-lead-trace-false", kind="id", sizes=admissible(n_max=4))
def lead_trace_false(s):
    L = twisted.leading_basis_vectors(s)
    return {"tr(LLt) - r": s.tr(L @ L.T) - s.tr(s.Ir)}


@claim("b1-lead-square", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def lead_square(s):
    L, E = twisted.leading_basis_vectors(s), twisted.last_basis_vector(s)
    return {"split": s.X @ L @ L.T @ s.X.T + s.X @ E @ E.T @ s.X.T - s.In}
