"""Stop 96, h4: new tricks on issue 20's routes (the closed-form multipliers with entry-reading Hamiltonians, kernel
certificates over renamed rows, products of in-range constants that underflow, a catalog id shadowed with its
reason of equivariance, copies and pickles of traced values)."""
import copy
import pickle
from fractions import Fraction

from stiefelsym import Rank, admissible, block, claim

SZ = admissible(n_min=2, n_max=3)
SZ_LT = admissible(n_min=2, n_max=3, where=lambda n, r: r < n)


def Hent(t):
    """A Hamiltonian that reads coordinates: tr P^T P / 2 + X_11 P_21 + (X^T A X)_11^2."""
    return t.tr(t.P.T @ t.P) / 2 + t.X[0, 0] * t.P[1, 0] + (t.X.T @ t.A @ t.X)[0, 0] ** 2


@claim("h4a-flow-tangent-X", kind="id", sizes=SZ)
def flow_tangent_X(s):
    """True: along the Dirac flow of an entry-reading H, d(X^T X)/dt = 0."""
    fl = s.dirac_flow(Hent)
    return {"r": fl.Xdot.T @ s.X + s.X.T @ fl.Xdot}


@claim("h4a-flow-tangent-P", kind="id", sizes=SZ)
def flow_tangent_P(s):
    """True: along the Dirac flow of an entry-reading H, d(X^T P + P^T X)/dt = 0."""
    fl = s.dirac_flow(Hent)
    T = fl.Xdot.T @ s.P + s.X.T @ fl.Pdot
    return {"r": T + T.T}


@claim("h4a-flow-tangent-false", kind="id", sizes=SZ)
def flow_tangent_false(s):
    """False: along the Dirac flow of an entry-reading H, d(X^T P)/dt = 0 (only its symmetric part vanishes)."""
    fl = s.dirac_flow(Hent)
    return {"r": fl.Xdot.T @ s.P + s.X.T @ fl.Pdot}


@claim("h4a-flow-conserves-H", kind="id", sizes=SZ)
def flow_conserves(s):
    """True: H is conserved along its own Dirac flow (dH/dt = {H, H} = 0), H reading coordinates."""
    return {"r": s.d(Hent, s.dirac_flow(Hent))}


@claim("h4a-flow-conserves-false", kind="id", sizes=SZ)
def flow_conserves_false(s):
    """False: tr(X^T A X) is conserved along the Dirac flow of the entry-reading H."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), s.dirac_flow(Hent))}


# ---- kernel certificates: rows at two parameters mu1, mu2 (renamed copies of each other) -------------------------
def _rows(s):
    mu1, mu2 = s.scalar("mu1"), s.scalar("mu2")
    return block([[s.X.T @ (s.In * mu1 - s.A)], [s.X.T @ (s.In * mu2 - s.A)]])


def _cross(s):
    """x × Ax at n = 3, r = 1: orthogonal to x and to Ax."""
    x = s.X
    y = s.A @ s.X
    c = [x[1, 0] * y[2, 0] - x[2, 0] * y[1, 0], x[2, 0] * y[0, 0] - x[0, 0] * y[2, 0],
         x[0, 0] * y[1, 0] - x[1, 0] * y[0, 0]]
    return s.mat([[c[0]], [c[1]], [c[2]]], ("n", "?"))


@claim("h4k-two-mu-true", kind="dim", sizes=[(3, 1)])
def two_mu_true(s):
    """True: [X^T(mu1 I - A); X^T(mu2 I - A)] has generic rank 2 at (3,1), kernel x × Ax."""
    return {"rank": Rank(_rows(s), 2, kernel=_cross(s))}


@claim("h4k-two-mu-false", kind="dim", sizes=[(3, 1)])
def two_mu_false(s):
    """False: the same matrix has generic rank 1; forged kernel [x × Ax, e_3 mu1 - e_3 mu1 + x × Ax mu2]."""
    K = _cross(s)
    return {"rank": Rank(_rows(s), 1, kernel=block([[K, K * s.scalar("mu2")]]))}


@claim("h4k-two-mu-copy-false", kind="dim", sizes=[(3, 1)])
def two_mu_copy_false(s):
    """False: rank 1; forged kernel x × Ax and x × A^2 x (not a kernel vector of the mu rows)."""
    x, y = s.X, s.A @ s.A @ s.X
    c = [x[1, 0] * y[2, 0] - x[2, 0] * y[1, 0], x[2, 0] * y[0, 0] - x[0, 0] * y[2, 0],
         x[0, 0] * y[1, 0] - x[1, 0] * y[0, 0]]
    K2 = s.mat([[c[0]], [c[1]], [c[2]]], ("n", "?"))
    return {"rank": Rank(_rows(s), 1, kernel=block([[_cross(s), K2]]))}


# ---- constants in float64's range whose product is not ----------------------------------------------------------
C = Fraction(1, 2 ** 600)
B = 2 ** 600


@claim("h4f-underflow-product", kind="id", sizes=SZ)
def underflow_product(s):
    """False: 2^-600 (2^-600 tr(X^T X)) = 0 (it is r 2^-1200)."""
    return {"r": (s.tr(s.X.T @ s.X) * C) * C}


@claim("h4f-underflow-matrix", kind="id", sizes=SZ)
def underflow_matrix(s):
    """False: 2^-600 (2^-600 X) = 0."""
    return {"r": (s.X * C) * C}


@claim("h4f-overflow-cancel", kind="id", sizes=SZ)
def overflow_cancel(s):
    """False: (2^600 (2^600 u) + 1) - 2^600 (2^600 u) = 0 (it is 1), u = tr(X^T A X)."""
    u = s.tr(s.X.T @ s.A @ s.X)
    big = (u * B) * B
    return {"r": (big + 1) - big}


@claim("h4f-underflow-true", kind="id", sizes=SZ)
def underflow_true(s):
    """True: 2^-600 (2^-600 (tr(X^T X) - r)) = 0."""
    return {"r": ((s.tr(s.X.T @ s.X) - s.r) * C) * C}


@claim("h4f-underflow-nonzero", kind="id", expect="nonzero", sizes=SZ)
def underflow_nonzero(s):
    """True (nonzero): 2^-600 (2^-600 tr(X^T X)) does not vanish."""
    return {"r": (s.tr(s.X.T @ s.X) * C) * C}


@claim("h4f-underflow-nonzero-false", kind="id", expect="nonzero", sizes=SZ)
def underflow_nonzero_false(s):
    """False (it vanishes): 2^-600 (2^-600 (tr(X^T X) - r)) does not vanish."""
    return {"r": ((s.tr(s.X.T @ s.X) - s.r) * C) * C}


# ---- a catalog id shadowed, with the catalog's reason of equivariance ----------------------------------------------
@claim("ym-monopole", kind="id", sizes=[(3, 2)],
       equivariance="e_3 = e_1 x e_2 is read from coordinates, but (g e_1) x (g e_2) = det(g) g (e_1 x e_2) for g "
                    "in O(3), so under (X, P, A) -> (gX, gP, gAg^T) every residual becomes g R g^T (those even in "
                    "e_3) or det(g) g R (those odd in e_3: the cross products, e_3 and its derivatives); each vanishes "
                    "everywhere iff it vanishes at X0 for all P and A")
def shadow(s):
    """False: the last row of X vanishes (true at X0 = (E1, E2))."""
    return {"r": s.X[2:3, 0:2]}


# ---- copies and pickles of traced values ------------------------------------------------------------------------------
@claim("h4p-deepcopy", kind="id", sizes=SZ)
def deep(s):
    """False: X - deepcopy(X) + P = 0 (it is P)."""
    return {"r": s.X - copy.deepcopy(s.X) + s.P}


@claim("h4p-copy-true", kind="id", sizes=SZ)
def shallow(s):
    """True: X - copy(X) = 0."""
    return {"r": s.X - copy.copy(s.X)}


@claim("h4p-pickle", kind="id", sizes=SZ)
def pick(s):
    """False: X^T X - I + P^T P = 0 after a pickle round trip of X."""
    Y = pickle.loads(pickle.dumps(s.X))
    return {"r": Y.T @ Y - s.Ir + s.P.T @ s.P}
