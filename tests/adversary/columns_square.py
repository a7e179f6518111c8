"""False claims at r = n (declared by admissible(r_is_n=True)): the last column and the leading columns
with a sign changed, the completion E_<r E_<r^T + E_r E_r^T = I_r stated for every r through X, and
X^T P = 0.  Every one fails at (3,3) under the fixed-size methods (adv-last-every-r at (3,2))."""
from stiefelsym import admissible, claim
from stiefelsym import twisted

SQ = admissible(n_max=4, n_min=2, r_is_n=True, condition="r = n")
ALL = admissible(n_max=4, n_min=2)


@claim("adv-last-sign", kind="id", sizes=SQ, statement="e_n e_n^T + E E^T = -I_n")
def last_sign(s):
    """The sign of I_n reversed."""
    er = s.X @ twisted.last_basis_vector(s)
    L = s.X @ twisted.leading_basis_vectors(s)
    return {"r": er @ er.T + L @ L.T + s.In}


@claim("adv-last-every-r", kind="id", sizes=ALL, statement="X E_r E_r^T X^T + X E_<r E_<r^T X^T = I_n for every r")
def last_every_r(s):
    """True at r = n only."""
    er = s.X @ twisted.last_basis_vector(s)
    L = s.X @ twisted.leading_basis_vectors(s)
    return {"r": er @ er.T + L @ L.T - s.In}


@claim("adv-square-xtp-zero", kind="id", sizes=SQ, statement="X^T P = 0 at r = n")
def xtp_zero(s):
    """False: X^T P is skew, not zero."""
    return {"r": s.X.T @ s.P}


@claim("adv-square-pxt-sym", kind="id", sizes=SQ, statement="P X^T = X P^T at r = n")
def pxt_sym(s):
    """False: the sign (P X^T = -X P^T)."""
    return {"r": s.P @ s.X.T - s.X @ s.P.T}


@claim("adv-last-lead-one", kind="id", sizes=SQ, statement="E_r^T E_<r E_<r^T E_r = 1")
def last_lead_one(s):
    """False: E_<r^T E_r = 0."""
    er, L = twisted.last_basis_vector(s), twisted.leading_basis_vectors(s)
    return {"r": s.tr(er.T @ L @ L.T @ er) - 1}
