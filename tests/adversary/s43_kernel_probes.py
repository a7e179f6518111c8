"""Round 18: the kernel certificate of a generic rank, Rank(M, k, kernel=K) (the exact method proves M K = 0
identically in its chart and finds rank K = d at an exact point, so rank M <= cols − d).  The truth of each claim
is in its docstring; a false claim may never pass, a kernel that is not one is never used, and a kernel that is
not a matrix with as many rows as M has columns is an error under every method.

* r = n: kernels that are kernels on one component of O(n) only (det X − 1 with the kernel 1 or det X + 1), a
  kernel with a pole along a whole component, and X^T Y + Y^T X − tr(X^T Y) I (0 where X^T Y is a rotation) with
  the kernel I;
* r = n = 3: X − Xᵀ through an untyped I₃ (0 at X = I only) with the kernel I₃, and its true generic rank 2 with
  its axial vector;
* a nilpotent matrix with itself as its kernel, a matrix whose second row is x − x, a printed rank above what
  the kernel allows, a kernel built at another point of T*V, a kernel whose product with M vanishes at the
  chart's point only through a 2x2 rotation;
* malformed kernels only the evaluation can see: a flow (a value of unknown kind) and Xᵀ (r rows) traced with
  symbolic sizes; a kernel kept on a rank switched to every point after construction."""
from stiefelsym import Rank, Size, SizeSpec, admissible, claim, twisted

SQ = SizeSpec((Size(2, 2), Size(3, 3)), n_min=2, n_max=3, r_min=2, r_max=3, r_is_n=True)
SQ2 = SizeSpec((Size(2, 2),), n_min=2, n_max=2, r_min=2, r_max=2, r_is_n=True)
SQ3 = SizeSpec((Size(3, 3),), n_min=3, n_max=3, r_min=3, r_max=3, r_is_n=True)
ONE = admissible(n_min=3, n_max=3, r_max=1)


def _det(M, m):
    if m == 2:
        return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]
    return (M[0, 0] * (M[1, 1] * M[2, 2] - M[1, 2] * M[2, 1]) - M[0, 1] * (M[1, 0] * M[2, 2] - M[1, 2] * M[2, 0])
            + M[0, 2] * (M[1, 0] * M[2, 1] - M[1, 1] * M[2, 0]))


def _detx(s):
    return _det(s.X, 2 if s.n == 2 else 3)


def _skew(s):
    return s.P @ s.X.T - s.X @ s.P.T


def _axial(s, W):
    return s.mat([[W[2, 1]], [W[0, 2]], [W[1, 0]]])


@claim("adv-s43-component-kernel", paper="adv", kind="dim", sizes=SQ)
def component_kernel(s):
    """False: [[det X − 1]] has rank 1 on the component det X = −1; the kernel [[1]] is one on det X = 1 only."""
    return {"rank": Rank(s.mat([[_detx(s) - 1]]), 0, kernel=s.mat([[s.q(1)]]))}


@claim("adv-s43-component-kernel-scaled", paper="adv", kind="dim", sizes=SQ)
def component_kernel_scaled(s):
    """False: [det X − 1, 0] has rank 1 on det X = −1; the kernel diag(det X + 1, 1) has rank 2 on det X = 1 only."""
    d = _detx(s)
    return {"rank": Rank(s.mat([[d - 1, s.q(0)]]), 0, kernel=s.mat([[d + 1, s.q(0)], [s.q(0), s.q(1)]]))}


@claim("adv-s43-component-kernel-upper", paper="adv", kind="dim", sizes=SQ)
def component_kernel_upper(s):
    """False: [det X − 1, 0] has rank 0 on det X = 1 (generic rank 1 is printed); the kernel e₂ allows rank 1."""
    d = _detx(s)
    return {"rank": Rank(s.mat([[d - 1, s.q(0)]]), 1, kernel=s.mat([[s.q(0)], [s.q(1)]]))}


@claim("adv-s43-component-pole", paper="adv", kind="dim", sizes=SQ)
def component_pole(s):
    """Undefined on det X = −1: the kernel 1/(det X + 1)."""
    d = _detx(s)
    return {"rank": Rank(s.mat([[d - 1]]), 0, kernel=s.mat([[1 / (d + 1)]]))}


@claim("adv-s43-rotation-kernel", paper="adv", kind="dim", sizes=SQ2)
def rotation_kernel(s):
    """False: M = XᵀY + (XᵀY)ᵀ − tr(XᵀY) I is 0 where XᵀY is a rotation, of rank 2 where it is a reflection."""
    M = s.X.T @ s.Y
    return {"rank": Rank(M + M.T - s.tr(M) * s.Ir, 0, kernel=s.Ir)}


def _xe(s):
    E = s.identity(3)
    M = s.X @ E
    return M - M.T


@claim("adv-s43-untyped-join-kernel", paper="adv", kind="dim", sizes=SQ3)
def untyped_join_kernel(s):
    """False: X − Xᵀ through an untyped I₃ is 0 at X = I only (generic rank 2); the kernel I₃."""
    return {"rank": Rank(_xe(s), 0, kernel=s.identity(3))}


@claim("adv-s43-untyped-join-kernel-true", paper="adv", kind="dim", sizes=SQ3)
def untyped_join_kernel_true(s):
    """True: X − Xᵀ through an untyped I₃ is skew 3x3 of generic rank 2; its axial vector is its kernel."""
    M = _xe(s)
    return {"rank": Rank(M, 2, kernel=s.mat([[M[1, 2]], [-M[0, 2]], [M[0, 1]]]))}


@claim("adv-s43-own-columns", paper="adv", kind="dim", sizes=ONE)
def own_columns(s):
    """True: N = [[0, x], [0, 0]] (x = X₁₁) is nilpotent, N N = 0, rank 1; the kernel is N itself."""
    x = s.X[0, 0]
    N = s.mat([[s.q(0), x], [s.q(0), s.q(0)]])
    return {"rank": Rank(N, 1, kernel=N)}


@claim("adv-s43-own-columns-false", paper="adv", kind="dim", sizes=ONE)
def own_columns_false(s):
    """False: N = [[x, x], [0, 0]] has rank 1 (N N != 0); printed 0 with the kernel N."""
    x = s.X[0, 0]
    N = s.mat([[x, x], [s.q(0), s.q(0)]])
    return {"rank": Rank(N, 0, kernel=N)}


@claim("adv-s43-special-row", paper="adv", kind="dim", sizes=ONE)
def special_row(s):
    """True: diag(x, x − x) has generic rank 1; the kernel e₂."""
    x = s.X[0, 0]
    return {"rank": Rank(s.mat([[x, s.q(0)], [s.q(0), x - x]]), 1, kernel=s.mat([[s.q(0)], [s.q(1)]]))}


@claim("adv-s43-rank-too-high", paper="adv", kind="dim", sizes=ONE)
def rank_too_high(s):
    """False: W = PXᵀ − XPᵀ (3x3 skew) has rank 2, printed 3; its axial vector proves rank <= 2."""
    W = _skew(s)
    return {"rank": Rank(W, 3, kernel=_axial(s, W))}


@claim("adv-s43-other-point-kernel", paper="adv", kind="dim", sizes=ONE)
def other_point_kernel(s):
    """True: W(X, P) has rank 2; the kernel is the axial vector of W at the point (X, 2P) of T*V, 2W."""
    t = twisted.at_point(s, s.X, 2 * s.P)
    W2 = t.P @ t.X.T - t.X @ t.P.T
    return {"rank": Rank(_skew(s), 2, kernel=_axial(s, W2))}


@claim("adv-s43-other-point-kernel-false", paper="adv", kind="dim", sizes=ONE)
def other_point_kernel_false(s):
    """False: W(X, P) has rank 2, printed 1; the axial vectors at (X, P) and (X, 2P) are one vector (rank K = 1)."""
    t = twisted.at_point(s, s.X, 2 * s.P)
    W2 = t.P @ t.X.T - t.X @ t.P.T
    W = _skew(s)
    return {"rank": Rank(W, 1, kernel=s.mat([[W[2, 1], W2[2, 1]], [W[0, 2], W2[0, 2]], [W[1, 0], W2[1, 0]]]))}


@claim("adv-s43-cross-kernel", paper="adv", kind="dim", sizes=ONE)
def cross_kernel(s):
    """True: W = PXᵀ − XPᵀ (r = 1) has rank 2 with the kernel x × p, built from the entries of X and P (not of W)."""
    x, p = s.X, s.P
    k = s.mat([[x[1, 0] * p[2, 0] - x[2, 0] * p[1, 0]], [x[2, 0] * p[0, 0] - x[0, 0] * p[2, 0]],
               [x[0, 0] * p[1, 0] - x[1, 0] * p[0, 0]]])
    return {"rank": Rank(_skew(s), 2, kernel=k)}


@claim("adv-s43-kernel-flow", paper="adv", kind="dim", sizes=ONE)
def kernel_flow(s):
    """Malformed: a flow (not a matrix) as the kernel of a true rank."""
    fl = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P))
    return {"rank": Rank(_skew(s), 2, kernel=fl)}


@claim("adv-s43-kernel-rows-r", paper="adv", kind="dim", sizes=ONE)
def kernel_rows_r(s):
    """Malformed: the kernel Xᵀ has r rows, the matrix n columns (traced with symbolic sizes)."""
    return {"rank": Rank(_skew(s), 2, kernel=s.X.T)}


@claim("adv-s43-every-point-by-setattr", paper="adv", kind="dim", sizes=ONE)
def every_point_by_setattr(s):
    """Malformed: a kernel kept on a rank switched to 'at every point' after it was made."""
    W = _skew(s)
    R = Rank(W, 2, kernel=_axial(s, W))
    object.__setattr__(R, "generic", False)
    return {"rank": R}
