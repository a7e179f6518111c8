"""Round 17: the exact method's rank decisions (the two-sided function-field rank, the constant minor, the rank at
an exact point), the components of O(n), poles on one component, R^r taken for R^n in a rank, and the route from
the dimension-free proof at families of sizes r = 3 and r = n.  The truth of each claim is in its docstring; a
false claim may never pass.

* r = n: a 1 x 1 rank of det X + 1 (det X − 1), written with the entries of X: 0 on one component of O(n) (the
  Cayley chart's D = diag(−1, 1, ..)), 2 on the other;
* r = n: 1/(det X + 1) and (det X + 1)/(det X + 1) inside a rank (generic and at every point) and in a residual:
  a division by a function that is identically 0 on the component det X = −1;
* r = n = 3: X·I₃ (I₃ an untyped identity of the int size 3, so XE joins R^n and R^r) minus its transpose,
  whose rank is 2 generically and 0 at X = I (the chart that reduces by O(n) on the right);
* the families r = 3 (a Count of r through its door, e₂ and e₃ of Ψ from power traces, a trace) and r = n (Ψ ≠ 0,
  tr(XXᵀA) = tr A) with exact_max_n=1, so that exact and auto go through the dimension-free route."""
from stiefelsym import Count, Rank, Size, SizeSpec, claim, elementary

SQ = SizeSpec((Size(2, 2), Size(3, 3)), n_min=2, n_max=3, r_min=2, r_max=3, r_is_n=True)
SQ3 = SizeSpec((Size(3, 3),), n_min=3, n_max=3, r_min=3, r_max=3, r_is_n=True)
R3 = SizeSpec((Size(5, 3), Size(6, 3), Size(7, 3)), n_min=3, n_max=7, r_min=3, r_max=3)
RN = SizeSpec((Size(4, 4), Size(5, 5), Size(6, 6)), n_min=2, n_max=7, r_min=2, r_max=7, r_is_n=True)


def _det(M, m):
    if m == 2:
        return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]
    return (M[0, 0] * (M[1, 1] * M[2, 2] - M[1, 2] * M[2, 1]) - M[0, 1] * (M[1, 0] * M[2, 2] - M[1, 2] * M[2, 0])
            + M[0, 2] * (M[1, 0] * M[2, 1] - M[1, 1] * M[2, 0]))


def _det_x(s):
    return _det(s.X, 2 if s.n == 2 else 3)


@claim("adv-s42b-det-plus-one", paper="adv", kind="dim", sizes=SQ)
def det_plus_one(s):
    """False: det X + 1 (1 x 1) is 0 on the component det X = −1 of O(n)."""
    return {"rank": Rank(s.mat([[_det_x(s) + 1]]), 1, generic=True)}


@claim("adv-s42b-det-minus-one", paper="adv", kind="dim", sizes=SQ)
def det_minus_one(s):
    """False: det X − 1 (1 x 1) is 0 on the component det X = 1 of O(n)."""
    return {"rank": Rank(s.mat([[_det_x(s) - 1]]), 1, generic=True)}


@claim("adv-s42b-det-plus-one-every-point", paper="adv", kind="dim", sizes=SQ)
def det_plus_one_every_point(s):
    """False: det X + 1 is a nonzero constant (2) on one component only."""
    return {"rank": Rank(s.mat([[_det_x(s) + 1]]), 1, generic=False)}


@claim("adv-s42b-inverse-on-one-component", paper="adv", kind="dim", sizes=SQ)
def inverse_on_one_component(s):
    """Undefined on the component det X = −1: 1/(det X + 1) (a pole along a whole component)."""
    return {"rank": Rank(s.mat([[1 / (_det_x(s) + 1)]]), 1, generic=True)}


@claim("adv-s42b-ratio-on-one-component", paper="adv", kind="dim", sizes=SQ)
def ratio_on_one_component(s):
    """Undefined on the component det X = −1: (det X + 1)/(det X + 1) is 1 on the other only."""
    return {"rank": Rank(s.mat([[(_det_x(s) + 1) / (_det_x(s) + 1)]]), 1, generic=False)}


@claim("adv-s42b-ratio-residual", paper="adv", kind="dim", sizes=SQ)
def ratio_residual(s):
    """Undefined on the component det X = −1: (det X + 1)/(det X + 1) − 1."""
    return {"res": (_det_x(s) + 1) / (_det_x(s) + 1) - 1}


def _xe(s):
    E = s.identity(3)
    M = s.X @ E
    return M - M.T


@claim("adv-s42b-untyped-join-rank-zero", paper="adv", kind="dim", sizes=SQ3)
def untyped_join_rank_zero(s):
    """False: X − Xᵀ (through an untyped I₃) is 0 at X = I only; rank 2 at a generic X of O(3)."""
    return {"rank": Rank(_xe(s), 0, generic=False)}


@claim("adv-s42b-untyped-join-generic-zero", paper="adv", kind="dim", sizes=SQ3)
def untyped_join_generic_zero(s):
    """False: the generic rank of X − Xᵀ on O(3) is 2, not 0."""
    return {"rank": Rank(_xe(s), 0, generic=True)}


@claim("adv-s42b-untyped-join-generic-two", paper="adv", kind="dim", sizes=SQ3)
def untyped_join_generic_two(s):
    """True: X − Xᵀ (3 x 3 skew) has generic rank 2 on each component of O(3)."""
    return {"rank": Rank(_xe(s), 2, generic=True)}


@claim("adv-s42b-r3-count", paper="adv", kind="dim", sizes=R3, exact_max_n=1)
def r3_count(s):
    """True: XᵀX = I_r, and r = 3 (a count through the size's door)."""
    return {"res": s.X.T @ s.X - s.Ir, "count": Count(int(s.r), 3)}


@claim("adv-s42b-r3-trace", paper="adv", kind="dim", sizes=R3, exact_max_n=1)
def r3_trace(s):
    """False at r = 3 < n: tr(XᵀAX) = tr A."""
    return {"res": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A)}


@claim("adv-s42b-r3-e2", paper="adv", kind="dim", sizes=R3, exact_max_n=1)
def r3_e2(s):
    """False: e₃(Ψ) = 0 (a 3 x 3 skew matrix) beside e₂(Ψ) = 0 (the sum of the squares of Ψ's entries above the
    diagonal)."""
    e = elementary(s, s.Psi, 3)
    return {"e3": e[3], "e2": e[2]}


@claim("adv-s42b-r3-e3", paper="adv", kind="dim", sizes=R3, exact_max_n=1)
def r3_e3(s):
    """True: e₃(Ψ) = det Ψ = 0 for a skew 3 x 3 matrix (and for every r from power traces: tr Ψ = tr Ψ³ = 0)."""
    return {"e3": elementary(s, s.Psi, 3)[3]}


@claim("adv-s42b-square-trace", paper="adv", kind="dim", sizes=RN, exact_max_n=1)
def square_trace(s):
    """True at r = n: tr(XXᵀA) = tr A."""
    return {"res": s.tr(s.X @ s.X.T @ s.A) - s.tr(s.A)}


@claim("adv-s42b-square-psi", paper="adv", kind="dim", sizes=RN, exact_max_n=1)
def square_psi(s):
    """False: Ψ = 2XᵀP is not 0 at r = n."""
    return {"res": s.Psi}
