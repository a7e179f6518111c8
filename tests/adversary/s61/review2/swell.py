"""Determinant identities at larger sizes: true ones must not be refuted by the rational pre-check."""
from stiefelsym import admissible, claim, det, elementary

S = admissible(n_max=5, n_min=3)


@claim("sw-true", kind="id", sizes=S)
def sw_true(s):
    """TRUE: det(I + Psi) = det(I - Psi) (Psi skew)."""
    return {"r": det(s, s.Ir + s.Psi) - det(s, s.Ir - s.Psi)}


@claim("sw-false", kind="id", sizes=S)
def sw_false(s):
    """FALSE: det(I + Psi) = -det(I - Psi)."""
    return {"r": det(s, s.Ir + s.Psi) + det(s, s.Ir - s.Psi)}


@claim("sw-true-res", kind="id", sizes=S)
def sw_true_res(s):
    """TRUE: tr (lam I - A)^{-1} ... det(lam I - A) tr R(lam) = e'(lam): the derivative of det(lam I-A) in lam,
    written as sum over j of (n-j)(-1)^j e_j(A) lam^{n-j-1}."""
    n = int(s.n)
    e = elementary(s, s.A, n)
    lam = s.lam
    d = det(s, s.In * lam - s.A)
    deriv = None
    for j in range(n):
        term = e[j] * (lam ** (n - j - 1)) * ((-1) ** j * (n - j))
        deriv = term if deriv is None else deriv + term
    return {"r": d * s.tr(s.resolvent(lam)) - deriv}


@claim("sw-true-x-psi", kind="id", sizes=S)
def sw_true_x_psi(s):
    """TRUE: det(I + X^T A X + Psi^T Psi) = det(I + X^T A X + Psi Psi^T)^T... (Psi^T Psi = Psi Psi^T for skew)."""
    M = s.X.T @ s.A @ s.X
    return {"r": det(s, s.Ir + M + s.Psi.T @ s.Psi) - det(s, s.Ir + M + s.Psi @ s.Psi.T)}


@claim("sw-false-x-psi", kind="id", sizes=S)
def sw_false_x_psi(s):
    """FALSE: det(I + X^T A X + Psi) = det(I + X^T A X - Psi) + 1."""
    M = s.X.T @ s.A @ s.X
    return {"r": det(s, s.Ir + M + s.Psi) - det(s, s.Ir + M - s.Psi) - s.q(1)}
