"""Review h4, batch m: twisted.magnetic_matrix, now typed as an r x r matrix (stop 82, item 4).

F = E1 E2^T - E2 E1^T (free: the column letters; fixed sizes: [[0, 1], [-1, 0]] at r = 2 only, ValueError at r != 2).
By hand (E1, E2 orthonormal columns of I_r, r >= 2): F^T = -F; F^2 = -(E1E1^T + E2E2^T), which is -I_r iff r = 2;
tr(F F^T) = 2 at every r >= 2; at r = 1 F is not defined (no E2).

  m-ff-all        F@F + I_r = 0, stated at every r <= n <= 4     TRUE at r = 2 only (FALSE at r >= 3 under the free
                                                                   meaning; no meaning at r = 1, 3, 4 at fixed size)
  m-ff-r2         same, stated at r = 2                          TRUE
  m-ff-r2-false   F@F - I_r = 0 at r = 2                         FALSE (F^2 = -I)
  m-skew-all      F + F^T = 0 at every r                          TRUE where F exists (r >= 2)
  m-trff-all      tr(F F^T) - 2 = 0 at every r                    TRUE where F exists (r >= 2)
  m-trff-all-f    tr(F F^T) - tr(I_r) = 0 at every r              TRUE at r = 2 only
  m-d-r2          d/dt tr(X F P^T) along V = (U, W) minus tr(U F P^T) + tr(X F W^T), r = 2     TRUE (F constant)
  m-d-r2-false    the same without the second term                 FALSE
  m-xfx-r2        (X F X^T)^T + X F X^T = 0 at r = 2                 TRUE
  m-flowF-r2      twisted.flow(s, H, F) with F = magnetic_matrix passed explicitly minus twisted.flow(s, H)   TRUE
  m-flowF2-r2     twisted.flow(s, H, 2F) - twisted.flow(s, H)       FALSE (eps F enters P')
"""
from stiefelsym import admissible, claim, twisted

ALL = admissible(n_max=4)
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def F(t):
    return twisted.magnetic_matrix(t)


@claim("m-ff-all", kind="id", sizes=ALL)
def ff_all(s):
    return {"F^2 + I": F(s) @ F(s) + s.Ir}


@claim("m-ff-r2", kind="id", sizes=R2)
def ff_r2(s):
    return {"F^2 + I": F(s) @ F(s) + s.Ir}


@claim("m-ff-r2-false", kind="id", sizes=R2)
def ff_r2_false(s):
    return {"F^2 - I": F(s) @ F(s) - s.Ir}


@claim("m-skew-all", kind="id", sizes=ALL)
def skew_all(s):
    return {"F + F^T": F(s) + F(s).T}


@claim("m-trff-all", kind="id", sizes=ALL)
def trff_all(s):
    return {"tr FF^T - 2": s.tr(F(s) @ F(s).T) - 2}


@claim("m-trff-all-f", kind="id", sizes=ALL)
def trff_all_f(s):
    return {"tr FF^T - r": s.tr(F(s) @ F(s).T) - s.tr(s.Ir)}


def _dd(s, full):
    U, W = s.generic("U", "n", "r"), s.generic("W", "n", "r")
    lhs = s.d(lambda t: t.tr(t.X @ F(t) @ t.P.T), {"X": U, "P": W})
    rhs = s.tr(U @ F(s) @ s.P.T) + (s.tr(s.X @ F(s) @ W.T) if full else 0)
    return {"d": lhs - rhs}


@claim("m-d-r2", kind="id", sizes=R2)
def d_r2(s):
    return _dd(s, True)


@claim("m-d-r2-false", kind="id", sizes=R2)
def d_r2_false(s):
    return _dd(s, False)


@claim("m-xfx-r2", kind="id", sizes=R2)
def xfx_r2(s):
    M = s.X @ F(s) @ s.X.T
    return {"skew": M + M.T}


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("m-flowF-r2", kind="id", sizes=R2)
def flowF_r2(s):
    a, b = twisted.flow(s, H, F(s)), twisted.flow(s, H)
    return {"X": a.Xdot - b.Xdot, "P": a.Pdot - b.Pdot}


@claim("m-flowF2-r2", kind="id", sizes=R2)
def flowF2_r2(s):
    a, b = twisted.flow(s, H, 2 * F(s)), twisted.flow(s, H)
    return {"X": a.Xdot - b.Xdot, "P": a.Pdot - b.Pdot}
