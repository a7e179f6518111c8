"""s62 extra probes (run by name): where the free method should or should not prove; the free TypeError."""
from stiefelsym import admissible, claim, comm
from stiefelsym import twisted

from common import R_IS_1_ALL, R_IS_2, H_neum, H_neumE, stabilizer_element

R_IS_N = admissible(n_max=4, r_is_n=True, condition="r = n")
R_N_MINUS_1 = admissible(n_max=4, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")


@claim("p-left-invariant-r-n", kind="id", section="5", sizes=R_IS_N)
def left_invariant_r_n(s):
    """TRUE at r = n only: H_neum,kappa is left SO(n)-invariant on T*SO(n) (tr X^T A X = tr A)."""
    return {"dH along (xi X, xi P)": s.d(H_neum, {"X": s.xi @ s.X, "P": s.xi @ s.P})}


@claim("p-psi-xtp-r1", kind="id", section="7", sizes=R_IS_1_ALL)
def psi_xtp_r1(s):
    """TRUE at r = 1 only: Psi = X^T P (both 0)."""
    return {"Psi - X^T P": s.Psi - s.X.T @ s.P}


@claim("p-isotropy-order-r-n-minus-1", kind="id", section="2", sizes=R_N_MINUS_1)
def isotropy_order_r_n_minus_1(s):
    """TRUE at r = n - 1 only (so(1) = 0: beta = 0): dPhi = [Phi, beta]."""
    beta = stabilizer_element(s)
    return {"dPhi - [Phi, beta]": s.d(lambda t: t.Phi, {"P": beta @ s.P}) - comm(s.Phi, beta)}


@claim("p-twisted-flow-only", kind="id", section="A1", sizes=R_IS_2)
def twisted_flow_only(s):
    """(mag-euk) Xdot = P: the twisted flow alone (no derivative of it)."""
    return {"Xdot - P": twisted.flow(s, H_neumE)["X"] - s.P}


@claim("p-d-of-twisted-flow", kind="id", section="A1", sizes=R_IS_2)
def d_of_twisted_flow(s):
    """d/ds of the twisted Xdot along (X eta, P eta) = P eta (since Xdot = P)."""
    eta = s.eta
    return {"D Xdot - P eta": s.d(lambda t: twisted.flow(t, H_neumE)["X"], {"X": s.X @ eta, "P": s.P @ eta}) - s.P @ eta}


@claim("p-d-of-dirac-flow", kind="id", section="5", sizes=R_IS_2)
def d_of_dirac_flow(s):
    """The same with the untwisted Dirac flow of H_neum,-1/2: D Xdot (X eta, P eta) = P eta."""
    eta = s.eta
    return {"D Xdot - P eta": s.d(lambda t: t.dirac_flow(H_neumE)["X"], {"X": s.X @ eta, "P": s.P @ eta}) - s.P @ eta}
