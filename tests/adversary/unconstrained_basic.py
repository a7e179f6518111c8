"""Adversary of the exact method's unconstrained chart (commit f340a62): basic routes.

Every claim here reads an entry of a matrix with a side on R^r (so the right-reduced Cayley chart does
not apply and the unconstrained chart is tried first)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3)


def _d(s):
    """tr(XᵀX) − r: identically 0 on T*V, not off it."""
    return s.tr(s.X.T @ s.X) - s.tr(s.Ir)


@claim("u-zero-over-zero", kind="id", sizes=S, statement="X11 d/d = X11 for d = tr(X^T X) - r")
def zero_over_zero(s):
    """Undefined on T*V (0/0), 0 off it."""
    d = _d(s)
    return {"r": s.X[0, 0] * d / d - s.X[0, 0]}


def H_undefined(t):
    d = t.tr(t.X.T @ t.X) - t.tr(t.Ir)
    return t.tr(t.P.T @ t.P) * d / d


def H_plain(t):
    return t.tr(t.P.T @ t.P)


@claim("u-undefined-hamiltonian", kind="id", sizes=S,
       statement="the Dirac flow of (tr P^T P) d/d is that of tr P^T P, entry (1,1)")
def undefined_hamiltonian(s):
    """Undefined on T*V: H = tr(PᵀP)·d/d with d = tr(XᵀX) − r."""
    return {"r": s.dirac_flow(H_undefined).Xdot[0, 0] - s.dirac_flow(H_plain).Xdot[0, 0]}


def H_entry(t):
    return t.X[0, 0] * t.P[1, 0] + t.tr(t.P.T @ t.A @ t.P)


@claim("u-dirac-tangent", kind="id", sizes=S, statement="sym(X^T Xdot) = 0 along the Dirac flow (entry-read H)")
def dirac_tangent(s):
    """True on T*V (and on every level set of the constraints)."""
    f = s.dirac_flow(H_entry)
    M = s.X.T @ f.Xdot
    return {"r": M + M.T}


@claim("u-dirac-closed-form", kind="id", sizes=S, statement="Xdot = H_P - X sym(X^T H_P) (entry-read H)")
def dirac_closed_form(s):
    """True on T*V (XᵀX = I), false off it: the unconstrained pre-test must send it to the Cayley chart."""
    f = s.dirac_flow(H_entry)
    HX, HP = s.gradient(H_entry)
    Pi = (s.X.T @ HP + HP.T @ s.X) * s.q(1, 2)
    return {"r": f.Xdot - (HP - s.X @ Pi)}


@claim("u-dirac-closed-form-false", kind="id", sizes=S, statement="Xdot = H_P (false)")
def dirac_closed_form_false(s):
    f = s.dirac_flow(H_entry)
    HX, HP = s.gradient(H_entry)
    return {"r": f.Xdot - HP}


@claim("u-bracket-entry", kind="id", sizes=S, statement="{X11, P11} Dirac = 1 - X11^2 (false in general)")
def bracket_entry(s):
    """Dirac bracket of two coordinate functions."""
    b = s.bracket(lambda t: t.X[0, 0], lambda t: t.P[0, 0])
    return {"r": b - (s.q(1) - s.X[0, 0] * s.X[0, 0])}


@claim("u-bracket-entry-true", kind="id", sizes=S,
       statement="{X11, P11} = 1 - X11^2/2 - (X X^T)_11 / 2 ... as computed by the Dirac formula")
def bracket_entry_true(s):
    """{x_11, p_11}_Dirac on T*V: 1 - ½ Σ_k X_1k² - ½ X_11² (r >= 1)."""
    b = s.bracket(lambda t: t.X[0, 0], lambda t: t.P[0, 0])
    row = s.X[0, 0] * s.X[0, 0]
    for k in range(1, s.r):
        row = row + s.X[0, k] * s.X[0, k]
    return {"r": b - (s.q(1) - row * s.q(1, 2) - s.X[0, 0] * s.X[0, 0] * s.q(1, 2))}
