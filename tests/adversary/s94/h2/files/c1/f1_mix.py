"""Mixed true/false claims for --jobs 1 vs --jobs 2 under auto --max-n 6."""
from stiefelsym import admissible, claim


def xtp(s):
    return {"r": s.X.T @ s.P}


def xtp_sym(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("h2-a-true", kind="id", sizes=admissible(n_max=6), statement="X^T P + P^T X = 0")
def a_true(s):
    """true"""
    return xtp_sym(s)


@claim("h2-b-proj", kind="id", sizes=admissible(n_max=6), statement="(XX^T)^2 = XX^T")
def b_proj(s):
    """true"""
    Q = s.X @ s.X.T
    return {"r": Q @ Q - Q, "s": s.X.T @ s.X @ s.X.T @ s.P - s.X.T @ s.P}


@claim("h2-c-xtp-all", kind="id", sizes=admissible(n_max=6), statement="X^T P = 0")
def c_false(s):
    """false at r >= 2, true at r = 1"""
    return xtp(s)


@claim("h2-d-xtp-r1", kind="id", sizes=admissible(n_max=6, r_in=(1,)), statement="X^T P = 0 at r = 1")
def d_r1(s):
    """true at r = 1"""
    return xtp(s)


@claim("h2-e-xxt-square", kind="id", sizes=admissible(n_max=6, r_is_n=True), statement="XX^T = I at r = n")
def e_sq(s):
    """true at r = n"""
    return {"r": s.X @ s.X.T - s.In}


@claim("h2-f-xxt-all", kind="id", sizes=admissible(n_max=6), statement="XX^T = I")
def f_all(s):
    """false at r < n"""
    return {"r": s.X @ s.X.T - s.In}


@claim("h2-g-expect-fails", kind="id", sizes=admissible(n_max=6), statement="X^T X = I", expect="fails",
       erratum="said to fail")
def g_fails(s):
    """true, stated to fail"""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("h2-h-nonzero", kind="not", sizes=admissible(n_max=6), statement="X^T X != 0", expect="nonzero")
def h_nonzero(s):
    """X^T X = I_r does not vanish"""
    return {"r": s.X.T @ s.X}


@claim("h2-i-corr", kind="id", sizes=admissible(n_max=6), statement="X^T P = P^T X")
def i_corr(s):
    """false (sign), corrected"""
    return {"r": s.X.T @ s.P - s.P.T @ s.X}


@i_corr.claim.correction("the sign of P^T X is +")
def i_corr_fixed(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@i_corr.claim.correction("a wrong correction: X^T P = 0")
def i_corr_wrong(s):
    return {"r": s.X.T @ s.P}
