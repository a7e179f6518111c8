"""False claims with the column letters of claims stated at one r (E1, E2 at r = 2, E1 at r = 1), and with
the free scene at another point of T*V: true only at n = 2, E1 and E2 taken for each other, a dropped
column, a range of r that includes r != 2, E2 at r = 1, X X^T = I_n through E1 E1^T = I_r, points off
T*V, points moved by a rotation of R^2 and a reflection that reverses the magnetic form.  Every one
fails at (3,2) (or at (3,1) for the claims at r = 1) under the fixed-size methods."""
from stiefelsym import admissible, claim
from stiefelsym import twisted

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
R1 = admissible(n_max=4, r_min=1, r_max=1, condition="r = 1")
R12 = admissible(n_max=4, r_min=1, r_max=2, condition="r <= 2")
R23 = admissible(n_max=4, r_min=2, r_max=3, condition="2 <= r <= 3")
ALL = admissible(n_max=4, n_min=2)


def E(s, i):
    return twisted.basis_vector(s, i)


def H0(u):
    return u.tr(u.P.T @ u.P) + u.tr(u.X.T @ u.A @ u.X)


@claim("adv-cols-complete-in-n", kind="id", sizes=R2, statement="e1 e1^T + e2 e2^T = I_n")
def complete_in_n(s):
    """True at n = 2 only."""
    e1, e2 = s.X @ E(s, 0), s.X @ E(s, 1)
    return {"r": e1 @ e1.T + e2 @ e2.T - s.In}


@claim("adv-cols-swapped", kind="id", sizes=R2, statement="E1^T E2 = 1")
def swapped(s):
    """False: E1 and E2 are orthogonal."""
    return {"r": s.tr(E(s, 0).T @ E(s, 1)) - 1}


@claim("adv-cols-range-r", kind="id", sizes=R12, statement="E1 E1^T + E2 E2^T = I_r for r <= 2")
def range_r(s):
    """True at r = 2 only (and E2 does not exist at r = 1)."""
    return {"r": E(s, 0) @ E(s, 0).T + E(s, 1) @ E(s, 1).T - s.Ir}


@claim("adv-cols-r23", kind="id", sizes=R23, statement="E1 E1^T + E2 E2^T = I_r for r = 2, 3")
def r23(s):
    """True at r = 2, false at r = 3."""
    return {"r": E(s, 0) @ E(s, 0).T + E(s, 1) @ E(s, 1).T - s.Ir}


@claim("adv-cols-r2-trace", kind="id", sizes=R2, statement="tr(X^T A X) = e1^T A e1")
def r2_trace(s):
    """Drops e2^T A e2."""
    e1 = s.X @ E(s, 0)
    return {"r": s.tr(s.X.T @ s.A @ s.X) - s.tr(e1.T @ s.A @ e1)}


@claim("adv-cols-r2-phi", kind="id", sizes=R2, statement="Phi = p1 e1^T - e1 p1^T")
def r2_phi(s):
    """Drops the second column."""
    e1, p1 = s.X @ E(s, 0), s.P @ E(s, 0)
    return {"r": s.Phi - (p1 @ e1.T - e1 @ p1.T)}


@claim("adv-cols-r2-phi-sign", kind="id", sizes=R2, statement="Phi = e1 p1^T - p1 e1^T + e2 p2^T - p2 e2^T")
def r2_phi_sign(s):
    """The sign of Phi = P X^T - X P^T reversed."""
    e1, p1, e2, p2 = s.X @ E(s, 0), s.P @ E(s, 0), s.X @ E(s, 1), s.P @ E(s, 1)
    return {"r": s.Phi - (e1 @ p1.T - p1 @ e1.T + e2 @ p2.T - p2 @ e2.T)}


@claim("adv-point-minusP-flow", kind="id", sizes=ALL, statement="the Neumann flow at (X, -P) has Xdot = Xdot(X, P)")
def minus_p(s):
    """False: Xdot is odd in P."""
    t = twisted.at_point(s, s.X, -s.P)
    return {"r": t.dirac_flow(H0).Xdot - s.dirac_flow(H0).Xdot}


@claim("adv-point-off-TV", kind="id", sizes=ALL, statement="grad_P H0 at (X, X) = grad_P H0 at (X, P)")
def off_tv(s):
    """(X, X) is not on T*V; false."""
    t = twisted.at_point(s, s.X, s.X)
    return {"r": t.gradient(H0)[1] - s.gradient(H0)[1]}


@claim("adv-point-scaled", kind="id", sizes=ALL, statement="grad_X H0 at (2X, P) = grad_X H0 at (X, P)")
def scaled(s):
    """(2X, P) is not on T*V; false (grad_X H0 = 2AX is linear in X)."""
    t = twisted.at_point(s, 2 * s.X, s.P)
    return {"r": t.gradient(H0)[0] - s.gradient(H0)[0]}


@claim("adv-point-rotated-r2", kind="id", sizes=R2, statement="the flow at (XJ, PJ) has Xdot = Xdot(X, P)")
def rotated(s):
    """False: Xdot(XJ, PJ) = Xdot(X, P) J (J the rotation of R^2)."""
    J = E(s, 0) @ E(s, 1).T - E(s, 1) @ E(s, 0).T
    t = twisted.at_point(s, s.X @ J, s.P @ J)
    return {"r": t.dirac_flow(H0).Xdot - s.dirac_flow(H0).Xdot}


@claim("adv-point-magnetic-reflected", kind="id", sizes=R2, statement="the magnetic flow at (XD, PD) is the reflected one")
def magnetic_reflected(s):
    """False: the reflection D = diag(1, -1) reverses e1 ^ e2 (the Lorentz force changes sign)."""
    D = E(s, 0) @ E(s, 0).T - E(s, 1) @ E(s, 1).T
    t = twisted.at_point(s, s.X @ D, s.P @ D)
    return {"r": twisted.flow(t, H0).Pdot - twisted.flow(s, H0).Pdot @ D}


@claim("adv-point-reflected-control", kind="id", sizes=R2, statement="the Neumann flow at (XD, PD) is the reflected one")
def reflected_control(s):
    """True (O(2)-equivariance of the canonical flow): a control that the free method proves."""
    D = E(s, 0) @ E(s, 0).T - E(s, 1) @ E(s, 1).T
    t = twisted.at_point(s, s.X @ D, s.P @ D)
    return {"r": t.dirac_flow(H0).Xdot - s.dirac_flow(H0).Xdot @ D}


@claim("adv-cols-r1-e2", kind="id", sizes=R1, statement="E2^T E2 = 1 at r = 1")
def r1_e2(s):
    """E2 does not exist at r = 1."""
    return {"r": s.tr(E(s, 1).T @ E(s, 1)) - 1}


@claim("adv-cols-r1-xxt", kind="id", sizes=R1, statement="X E1 E1^T X^T = I_n at r = 1")
def r1_xxt(s):
    """False for n > 1 (E1 E1^T = I_r, but X X^T is a projector of rank 1)."""
    return {"r": s.X @ E(s, 0) @ E(s, 0).T @ s.X.T - s.In}


@claim("adv-cols-r1-pt", kind="id", sizes=R1, statement="X^T P = 0 at r = 1, and P E1 E1^T = X")
def r1_pt(s):
    """X^T P = 0 holds at r = 1 (a skew 1x1 matrix); P = X does not."""
    return {"skew": s.X.T @ s.P, "r": s.P @ E(s, 0) @ E(s, 0).T - s.X}


def H_operator(u):
    AA = u.sym_operator("AA")
    return u.tr(AA(u.Phi) @ u.Phi)


@claim("adv-op-point-flow", kind="id", sizes=ALL, statement="the flow of tr(AA(Phi) Phi) at (X, -P) has Xdot = Xdot(X, P)")
def op_point_flow(s):
    """False: Xdot is odd in P (the operator's argument Phi must be substituted at the point too)."""
    t = twisted.at_point(s, s.X, -s.P)
    return {"r": t.dirac_flow(H_operator).Xdot - s.dirac_flow(H_operator).Xdot}


@claim("adv-op-point-grad", kind="id", sizes=ALL, statement="grad_P tr(AA(Phi) Phi) at (X, P + X eta) = grad_P at (X, P)")
def op_point_grad(s):
    """False: Phi changes with P."""
    t = twisted.at_point(s, s.X, s.P + s.X @ s.eta)
    return {"r": t.gradient(H_operator)[1] - s.gradient(H_operator)[1]}


@claim("adv-op-point-flow-control", kind="id", sizes=ALL, statement="the flow at (X, -P) has Xdot = -Xdot(X, P)")
def op_point_flow_control(s):
    """True: a control that the free method proves."""
    t = twisted.at_point(s, s.X, -s.P)
    return {"r": t.dirac_flow(H_operator).Xdot + s.dirac_flow(H_operator).Xdot}


@claim("adv-cols-nonzero-vanishes", kind="id", sizes=R2, expect="nonzero", statement="E1^T E2 does not vanish")
def nonzero_vanishes(s):
    """False: a statement of nonvanishing whose value is 0 (E1 and E2 are orthogonal)."""
    return {"r": s.tr(E(s, 0).T @ E(s, 1))}


@claim("adv-cols-nonzero-at-n2", kind="id", sizes=R2, expect="nonzero", statement="e1 e1^T + e2 e2^T - I_n does not vanish")
def nonzero_at_n2(s):
    """False at n = 2 (it vanishes there), true for n >= 3."""
    e1, e2 = s.X @ E(s, 0), s.X @ E(s, 1)
    return {"r": e1 @ e1.T + e2 @ e2.T - s.In}


@claim("adv-mix-er-e2", kind="id", sizes=R2, statement="E2^T E_r = 0 at r = 2")
def mix_er_e2(s):
    """False: at r = 2 the last column E_r is E2."""
    return {"r": s.tr(E(s, 1).T @ twisted.last_basis_vector(s))}


@claim("adv-mix-lead-e2", kind="id", sizes=R2, statement="E_<r E_<r^T = E2 E2^T at r = 2")
def mix_lead_e2(s):
    """False: at r = 2, E_<r = E1."""
    L = twisted.leading_basis_vectors(s)
    return {"r": L @ L.T - E(s, 1) @ E(s, 1).T}


@claim("adv-mix-er-e1-r1", kind="id", sizes=R1, statement="E_r^T E1 = 0 at r = 1")
def mix_er_e1_r1(s):
    """False: at r = 1, E_r = E1."""
    return {"r": s.tr(twisted.last_basis_vector(s).T @ E(s, 0))}


@claim("adv-r1-pxt", kind="id", sizes=R1, statement="P X^T = X P^T at r = 1")
def r1_pxt(s):
    """False: Phi does not vanish at r = 1."""
    return {"r": s.P @ s.X.T - s.X @ s.P.T}


@claim("adv-r1-xxtp", kind="id", sizes=R1, statement="X X^T P = P at r = 1")
def r1_xxtp(s):
    """False for n >= 2 (X X^T is a projector of rank 1)."""
    return {"r": s.X @ s.X.T @ s.P - s.P}


@claim("adv-r1-commute", kind="id", sizes=R1, statement="A P P^T = P P^T A at r = 1")
def r1_commute(s):
    """False: only the r x r words are scalars at r = 1, not the n x n ones."""
    return {"r": s.A @ s.P @ s.P.T - s.P @ s.P.T @ s.A}


@claim("adv-r1-scalar-control", kind="id", sizes=R1, statement="X^T A P = P^T A X at r = 1")
def r1_scalar_control(s):
    """True at r = 1 (a 1 x 1 matrix is its transpose): a control that the free method proves."""
    return {"r": s.X.T @ s.A @ s.P - s.P.T @ s.A @ s.X}
