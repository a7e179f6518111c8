"""Round 15: the point methods' proof of a generic rank equal to its matrix's full size (a nonzero maximal
minor at one point of each component; `_point_rank` status "full", `_full_ranks`).  Each claim states a rank
of full size; the false ones are not of full rank on T*V (or on one component of it), or the matrix is not
what a reader of the claim would take it for, and none may be proved.  exact_max_n=1: auto takes the modular
method at every size.

* a rank of full size on one component of O(n) only (r = n = 2: det X + 1, det X + det Y with the second point);
* a residual that vanishes on T*V hidden in a matrix of full size (XᵀX − I plus a rank-one term; the metric
  realization's constraint; dH/dt along H's own Dirac flow);
* constants of the matrix that a prime field could read otherwise (1/2, 2²⁰⁰ + 1): a rank-one 2 x 2 matrix;
* one more than the full size; a wrong Count beside a rank of full size; a Jacobian read by upper
  triangles of a wide matrix (refused when traced);
* true controls: XᵀAX (r x r), XᵀAY (r = n: four pairs of components), det DX + 1 at the double point,
  A − λI (which a hard case near the pole must leave undecided);
* for the mutation analysis (lent points): XᵀX of rank r at every point, whose mutant PᵀX (X → P) is a rank of
  full size of parameters that the lent points took for a constant matrix."""
from stiefelsym import Count, Rank, Size, SizeSpec, block, claim

ALL = SizeSpec((Size(2, 2), Size(3, 2), Size(3, 3), Size(4, 2)), n_min=2, n_max=4, r_min=2, r_max=3)
SQUARE2 = SizeSpec((Size(2, 2),), n_min=2, n_max=2, r_min=2, r_max=2, r_is_n=True)
LOW = SizeSpec((Size(3, 2), Size(4, 2)), n_min=3, n_max=4, r_min=2, r_max=2)


def _det2(M):
    return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]


def _H(t):
    return (t.tr(t.P.T @ t.P) + t.tr(t.X.T @ t.A @ t.X)) * t.q(1, 2)


@claim("adv-s41b-full-true", paper="adv", kind="dim", sizes=ALL, exact_max_n=1)
def full_true(s):
    """True: XᵀAX (r x r) has generic rank r."""
    return {"rank": Rank(s.X.T @ s.A @ s.X, s.r, generic=True)}


@claim("adv-s41b-second-point-true", paper="adv", kind="dim", sizes=ALL, exact_max_n=1)
def second_point_true(s):
    """True: XᵀAY (r x r) has generic rank r on each pair of components of (X, Y)."""
    return {"rank": Rank(s.X.T @ s.A @ s.Y, s.r, generic=True)}


@claim("adv-s41b-double-point-true", paper="adv", kind="dim", sizes=SQUARE2, exact_max_n=1)
def double_point_true(s):
    """True: det DX + 1 is not identically 0 at the double point (DX = X0 D U, any sign of det)."""
    return {"rank": Rank(s.mat([[_det2(s.DX) + 1]]), 1, generic=True)}


@claim("adv-s41b-resolvent-true", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def resolvent_true(s):
    """True: A − λI (n x n) has generic rank n."""
    return {"rank": Rank(s.A - s.In * s.lam, s.n, generic=True)}


@claim("adv-s41b-det-plus-one", paper="adv", kind="dim", sizes=SQUARE2, exact_max_n=1)
def det_plus_one(s):
    """False: det X + 1 is 0 on the component det X = −1 of O(2) (rank 0 there, 1 on the other)."""
    return {"rank": Rank(s.mat([[_det2(s.X) + 1]]), 1, generic=True)}


@claim("adv-s41b-det-x-plus-det-y", paper="adv", kind="dim", sizes=SQUARE2, exact_max_n=1)
def det_x_plus_det_y(s):
    """False: det X + det Y is 0 on the two pairs of components of (X, Y) with det X = −det Y."""
    return {"rank": Rank(s.mat([[_det2(s.X) + _det2(s.Y)]]), 1, generic=True)}


@claim("adv-s41b-residual-inside", paper="adv", kind="dim", sizes=ALL, exact_max_n=1)
def residual_inside(s):
    """False: XᵀX − I_r + XᵀP + PᵀX (0 on T*V) plus a rank-one term has rank 1 < r."""
    u = s.X.T @ s.A @ s.X
    return {"rank": Rank(s.X.T @ s.X - s.Ir + s.X.T @ s.P + s.P.T @ s.X + u[:, 0:1] @ u[0:1, :], s.r,
                         generic=True)}


@claim("adv-s41b-metric-constraint", paper="adv", kind="dim", sizes=ALL, realization="metric", exact_max_n=1)
def metric_constraint(s):
    """False in the metric realization: XᵀA⁻¹P + PᵀA⁻¹X + XᵀX − I_r is 0 on its T*V."""
    return {"rank": Rank(s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X + s.X.T @ s.X - s.Ir, s.r, generic=True)}


@claim("adv-s41b-dirac-derivative", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def dirac_derivative(s):
    """False: dH/dt along H's own Dirac flow is 0 on T*V (a 1 x 1 matrix of rank 0)."""
    return {"rank": Rank(s.mat([[s.d(_H, s.dirac_flow(_H))]]), 1, generic=True)}


@claim("adv-s41b-constant-half", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def constant_half(s):
    """False: [[x/2, x], [x, 2x]] (x = X₁₁) has rank 1."""
    x = s.X[0, 0]
    return {"rank": Rank(s.mat([[x * s.q(1, 2), x], [x, x * 2]]), 2, generic=True)}


@claim("adv-s41b-constant-huge", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def constant_huge(s):
    """False: [[x, c x], [1, c]] (c = 2²⁰⁰ + 1, beyond every prime of the modular method) has rank 1."""
    x, c = s.X[0, 0], 2 ** 200 + 1
    return {"rank": Rank(s.mat([[x, x * c], [s.q(1), s.q(c)]]), 2, generic=True)}


@claim("adv-s41b-one-above-full", paper="adv", kind="dim", sizes=ALL, exact_max_n=1)
def one_above_full(s):
    """False: XᵀAX (r x r) of rank r + 1."""
    return {"rank": Rank(s.X.T @ s.A @ s.X, s.r + 1, generic=True)}


@claim("adv-s41b-wrong-count", paper="adv", kind="dim", sizes=ALL, exact_max_n=1)
def wrong_count(s):
    """False: a count r = r + 1 beside a rank of full size."""
    return {"rank": Rank(s.X.T @ s.A @ s.X, s.r, generic=True), "count": Count(s.r, s.r + 1)}


@claim("adv-s41b-wide-symmetric-jacobian", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def wide_symmetric_jacobian(s):
    """Not a statement: the Jacobian of [XᵀAX | XᵀP] (r x 2r) read by upper triangles would keep r(r+1)/2 of
    its rows (a rank of full size); refused when traced."""
    F = lambda t: [block([[t.X.T @ t.A @ t.X, t.X.T @ t.P]])]   # noqa: E731
    return {"rank": Rank(s.mat(s.jacobian(F, symmetric=True)), s.r * (s.r + 1) // 2, generic=True)}


@claim("adv-s41b-every-point-gram", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def every_point_gram(s):
    """True: XᵀX = I_r has rank r at every point of T*V (its mutant PᵀX, 0 at P = 0, does not)."""
    return {"rank": Rank(s.X.T @ s.X, s.r, generic=False)}


@claim("adv-s41b-reciprocal-every-point", paper="adv", kind="dim", sizes=LOW, exact_max_n=1)
def reciprocal_every_point(s):
    """True where defined (x, y real, nonzero): [[1/x, 1/y], [1/y, −1/x]] has determinant −(1/x² + 1/y²) ≠ 0; its
    mutant with +1/x (determinant (y² − x²)/(x²y²), 0 where x = ±y) has entries c/D: numerators of degree 0."""
    x, y = s.scalar("x"), s.scalar("y")
    return {"rank": Rank(s.mat([[s.q(1) / x, s.q(1) / y], [s.q(1) / y, -(s.q(1) / x)]]), 2, generic=False)}
