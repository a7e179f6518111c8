"""Round s55 (no wrong verdict found): dimension claims through constants of R^n / R^r that the engine builds
(twisted.reflection, eigenspace_projector, basis_vector), ambient Jacobians of the Dirac flow off T*V against the
closed form that holds on V only, a Jacobian of symmetric components of a non-square matrix, symbolic expected
ranks and counts, basis vectors of R^r in the metric realization.  The truth of each claim is in its docstring;
exact, modular (and rational, float, auto where run) gave the right verdict at (3,1), (3,2), (4,2)."""
from stiefelsym import Count, Rank, admissible, block, claim, twisted

# ---- t1.py

S_T1 = admissible(n_min=3, n_max=4, r_max=2)

@claim("adv-s55-t1-refl-res", paper="adv", kind="id", sizes=S_T1)
def refl_res(s):
    """False: tr(S1 X X^T) = r - 2 only where the first row of X is a unit vector."""
    S1 = twisted.reflection(s)
    return {"res": s.tr(S1 @ s.X @ s.X.T) - s.tr(s.Ir) + 2}

@claim("adv-s55-t1-refl-rank-every", paper="adv", kind="dim", sizes=S_T1)
def refl_rank_every(s):
    """False: X^T S1 X - I = -2 x1 x1^T has rank 0 where the first row x1 of X is 0."""
    S1 = twisted.reflection(s)
    return {"rank": Rank(s.X.T @ S1 @ s.X - s.Ir, 1, generic=False)}

@claim("adv-s55-t1-proj-rank-every", paper="adv", kind="dim", sizes=S_T1)
def proj_rank_every(s):
    """False: X^T D X (D = diag(I2,0)) has rank min(r,2) generically but drops."""
    D = twisted.eigenspace_projector(s)
    return {"rank": Rank(s.X.T @ D @ s.X, s.r, generic=False)}

@claim("adv-s55-t1-basis-rank", paper="adv", kind="dim", sizes=S_T1)
def basis_rank(s):
    """True at r = 1 (the vector is a - a = 0), false at r = 2: M E1 - (E1^T M E1) E1, M = X^T A X, is the off-diagonal
    column of M, of generic rank 1, printed 0 (E1 a constant basis vector of R^r built by the engine)."""
    E1 = twisted.basis_vector(s, 0)
    return {"rank": Rank(s.X.T @ s.A @ s.X @ E1 - (E1.T @ s.X.T @ s.A @ s.X @ E1)[0,0] * E1, 0)}

# ---- t2.py

S_T2 = admissible(n_min=3, n_max=4, r_max=2)

def F(t):
    return block([[t.X.T @ t.X, t.X.T @ t.P]])

@claim("adv-s55-t2-jac-nonsquare-sym", paper="adv", kind="dim", sizes=S_T2)
def jac_nonsquare(s):
    """False: the Jacobian of the r x 2r matrix [X^T X, X^T P] has generic rank r(r+1)/2 + r^2 (the entries of
    X^T X symmetric, those of X^T P independent of them), not r(r+1)/2."""
    r = int(s.r)
    return {"rank": Rank(s.mat(s.jacobian(F, symmetric=True)), r * (r + 1) // 2)}

@claim("adv-s55-t2-jac-nonsquare-full", paper="adv", kind="dim", sizes=S_T2)
def jac_nonsquare_full(s):
    """Control: the full Jacobian rows."""
    r = int(s.r)
    return {"rank": Rank(s.mat(s.jacobian(F)), r * (r + 1) // 2 + r * r)}

# ---- t4.py

S_T4 = admissible(n_min=3, n_max=3, r_max=2)

def H(t):
    return t.tr(t.P.T @ t.A @ t.P) / 2

def flowX(t):
    return t.dirac_flow(H)["X"]

def closedX(t):
    K = t.X.T @ t.A @ t.P
    return t.A @ t.P - t.X @ (K + K.T) / 2

@claim("adv-s55-t4-jac-dirac-vs-closed", paper="adv", kind="id", sizes=S_T4)
def jac_dirac(s):
    """False: off T*V the Dirac flow's multiplier solves a Lyapunov equation in X^T X, so the ambient Jacobian of
    its X-component differs from that of the closed form AP - X sym(X^T A P) in the directions normal to T*V."""
    J1 = s.mat(s.jacobian(flowX))
    J2 = s.mat(s.jacobian(closedX))
    return {"res": J1 - J2}

@claim("adv-s55-t4-jac-diff-rank", paper="adv", kind="dim", sizes=S_T4)
def jac_diff_rank(s):
    """False: that difference has generic rank >= 1 (rank 1 at r = 1), not 0."""
    J1 = s.mat(s.jacobian(flowX))
    J2 = s.mat(s.jacobian(closedX))
    return {"rank": Rank(J1 - J2, 0)}

# ---- t5.py

S_T5 = admissible(n_min=3, n_max=4, r_min=2, r_max=2)

@claim("adv-s55-t5-std-basis", paper="adv", kind="id", sizes=S_T5)
def std_basis(s):
    """False: (X^T A X)_12 = 0 (true only where A11 is diagonal)."""
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"res": E1.T @ s.X.T @ s.A @ s.X @ E2}

@claim("adv-s55-t5-met-basis", paper="adv", kind="id", sizes=S_T5, realization="metric")
def met_basis(s):
    """False: (X^T A^-1 X)_12 = 0."""
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"res": E1.T @ s.X.T @ s.Ainv @ s.X @ E2}

@claim("adv-s55-t5-met-mat", paper="adv", kind="id", sizes=S_T5, realization="metric")
def met_mat(s):
    """False: (X^T A^-1 X)_12 = 0 via s.mat basis vectors on R^r."""
    E1 = s.mat([[1], [0]], ("r", "?"))
    E2 = s.mat([[0], [1]], ("r", "?"))
    return {"res": E1.T @ s.X.T @ s.Ainv @ s.X @ E2}

@claim("adv-s55-t5-met-rank", paper="adv", kind="dim", sizes=S_T5, realization="metric")
def met_rank(s):
    """False: the rank of [X^T A^-1 X, diag-part] ... rank of (B11 - B11 diag) via E E^T projections: rank of
    M = X^T B X - E1 E1^T X^T B X E1 E1^T - E2 E2^T X^T B X E2 E2^T is 2 generically (off-diagonal b, b), printed 0."""
    E1 = s.mat([[1], [0]], ("r", "?"))
    E2 = s.mat([[0], [1]], ("r", "?"))
    M = s.X.T @ s.Ainv @ s.X
    return {"rank": Rank(M - E1 @ E1.T @ M @ E1 @ E1.T - E2 @ E2.T @ M @ E2 @ E2.T, 0)}

# ---- t6.py

S_T6 = admissible(n_min=3, n_max=4, r_max=2)

@claim("adv-s55-t6-rank-n", paper="adv", kind="dim", sizes=S_T6)
def rank_n(s):
    """False for r < n: X has rank r, not n."""
    return {"rank": Rank(s.X, s.n)}

@claim("adv-s55-t6-rank-expr", paper="adv", kind="dim", sizes=S_T6)
def rank_expr(s):
    """False: Phi has generic rank min(2r, n - n%2...) ; printed 2n - 2r."""
    return {"rank": Rank(s.Phi, 2 * s.n - 2 * s.r)}

@claim("adv-s55-t6-count-expr", paper="adv", kind="dim", sizes=S_T6)
def count_expr(s):
    """False at (4,2)... n*r - r*(r+1)/2 vs n r - r r."""
    return {"count": Count(s.n * s.r - s.r * s.r, s.n * s.r - s.r * (s.r + 1) // 2)}
