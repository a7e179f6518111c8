# ruff: noqa: F841, E702, F401, E731, E741
"""Review s63, batch 1: engine constants against the equivariant / right-reduced charts, nonzero claims
that hold on one component only, r = n facts at r < n.  Truth of each in the docstring (numpy in numpy_truth.py)."""
from stiefelsym import admissible, claim, det, elementary
from stiefelsym import twisted

S32 = admissible(n_max=3, n_min=3, r_min=2, r_max=2)
SQ = admissible(n_max=3, n_min=2, r_in=("n",))


@claim("b1-dn-x", paper="t", kind="id", section="2", sizes=S32)
def dn_x(s):
    """FALSE: D X = X with D = diag(I_2, 0) (true at X = (e1, e2) only)."""
    D = twisted.eigenspace_projector(s)
    return {"r": D @ s.X - s.X}


@claim("b1-refl-trace", paper="t", kind="id", section="2", sizes=S32)
def refl_trace(s):
    """FALSE: tr(X^T S X) = r - 2 with S = diag(-1, 1, 1) (true at X = (e1, e2) only)."""
    S = twisted.reflection(s)
    return {"r": s.tr(s.X.T @ S @ s.X) - s.tr(s.Ir) + 2}


@claim("b1-refl-right", paper="t", kind="id", section="2", sizes=S32)
def refl_right(s):
    """FALSE: X^T S X commutes with X^T A X (S = diag(-1,1,1))."""
    S = twisted.reflection(s)
    M, N = s.X.T @ S @ s.X, s.X.T @ s.A @ s.X
    return {"r": M @ N - N @ M}


@claim("b1-nz-xxt-sq", paper="t", kind="not", expect="nonzero", section="2", sizes=SQ)
def nz_xxt(s):
    """FALSE (a 'not' claim that fails): X X^T - I_n vanishes at r = n."""
    return {"r": s.X @ s.X.T - s.In}


@claim("b1-nz-det-xty", paper="t", kind="not", expect="nonzero", section="2", sizes=SQ)
def nz_det_xty(s):
    """TRUE 'not': det(X^T Y) - 1 is not 0 on T*V x T*V at r = n (-1 on mixed components)."""
    return {"r": det(s, s.X.T @ s.Y) - 1}


@claim("b1-nz-det-xty-sq", paper="t", kind="not", expect="nonzero", section="2", sizes=SQ)
def nz_det_xty_sq(s):
    """FALSE 'not': det(X^T Y)^2 - 1 = 0 at r = n."""
    d = det(s, s.X.T @ s.Y)
    return {"r": d * d - 1}


@claim("b1-nz-lastcol", paper="t", kind="not", expect="nonzero", section="2",
       sizes=admissible(n_max=3, n_min=2))
def nz_lastcol(s):
    """TRUE 'not' (at every size: at r < n the column X E_r is not e_n...):  X E_r E_r^T X^T - (I_n - X E< E<^T X^T)
    vanishes iff X X^T = I_n, i.e. at r = n only; stated for all r it is nonzero at r < n and ZERO at r = n:
    so at (2,2), (3,3) the 'not' claim is FALSE (fails), at (2,1), (3,1), (3,2) TRUE."""
    Er = twisted.last_basis_vector(s)
    L = twisted.leading_basis_vectors(s)
    return {"r": s.X @ Er @ Er.T @ s.X.T - (s.In - s.X @ L @ L.T @ s.X.T)}


@claim("b1-lead-sum", paper="t", kind="id", section="2", sizes=admissible(n_max=3))
def lead_sum(s):
    """TRUE: E< E<^T + E_r E_r^T = I_r (at r = 1: E< is r x 0)."""
    Er = twisted.last_basis_vector(s)
    L = twisted.leading_basis_vectors(s)
    return {"r": L @ L.T + Er @ Er.T - s.Ir}


@claim("b1-lead-square", paper="t", kind="id", section="2", sizes=admissible(n_max=3))
def lead_square(s):
    """FALSE at r < n: X E< E<^T X^T + X E_r E_r^T X^T = I_n (true at r = n only); stated for every r."""
    Er = twisted.last_basis_vector(s)
    L = twisted.leading_basis_vectors(s)
    return {"r": s.X @ L @ L.T @ s.X.T + s.X @ Er @ Er.T @ s.X.T - s.In}


@claim("b1-kernel-sq", paper="t", kind="id", section="2", sizes=admissible(n_max=3))
def kernel_sq(s):
    """FALSE at r < n (true at r = n only, where K = 0): K X = 0 for the kernel annihilator K of a generic W."""
    K = twisted.kernel_annihilator(s)
    return {"r": K @ s.X}


@claim("b1-kernel-rank", paper="t", kind="id", section="2", sizes=admissible(n_max=3, n_min=2))
def kernel_trace(s):
    """FALSE at r = n (K = 0 there): K^2 = tr(K)/(n-r) K ... stated as K^3 tr K = K^2 tr K^2 (true for a multiple
    of a projector, at every size: K = c * projector).  TRUE at every size at fixed sizes."""
    K = twisted.kernel_annihilator(s)
    return {"r": K @ K @ K * s.tr(K) - K @ K * s.tr(K @ K)}
