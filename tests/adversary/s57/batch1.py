"""Batch 1: grouping attacks.  Each claim mixes a check that reads an entry of R^n (so the claim is
grouped) with checks that read nothing statically."""
from stiefelsym import admissible, claim, Rank
from stiefelsym import block

SZ = admissible(n_max=4)


def _sq(s):
    acc = s.q(0)
    for i in range(s.n):
        for j in range(s.r):
            acc = acc + s.X[i, j] * s.X[i, j]
    return acc


def READ(s):
    return _sq(s) - s.q(s.r)      # true on V


# 1. a derivative along a flow whose body reads an entry (false identity): d/dV of X[0,0] along X-> X+eps*E
@claim("b1-dflow-entry", kind="id", sizes=SZ)
def b1_dflow_entry(s):
    """d/de tr(X^T X) along a flow written from an entry: false claim d(X[0,0]) along V=X is 0."""
    return {"read": READ(s), "d entry": s.d(lambda t: t.X[0, 0], {"X": s.X})}


# 2. jacobian inside an unread-looking check: false rank
@claim("b2-jacobian-rank", kind="id", sizes=SZ)
def b2_jac(s):
    """rank of Jacobian of tr(X^T X) stated 0 (false: rank 1)."""
    return {"read": READ(s), "rank": Rank(s.mat(s.jacobian(lambda t: t.tr(t.X.T @ t.X))), 0)}


# 3. a bracket whose function reads an entry: {X[0,0], tr(P^T X)} claimed 0 (false)
@claim("b3-bracket-entry", kind="id", sizes=SZ)
def b3_bracket(s):
    """{X00, tr P^T X} = 0 (false)."""
    return {"read": READ(s), "br": s.bracket(lambda t: t.X[0, 0], lambda t: t.tr(t.P.T @ t.X))}


# 4. gradient whose body reads an entry
@claim("b4-gradient-entry", kind="id", sizes=SZ)
def b4_grad(s):
    """gradient of X00 wrt X claimed 0 (false)."""
    g = s.gradient(lambda t: t.X[0, 0] * t.P[0, 0])
    return {"read": READ(s), "grad": g["X"]}


# 5. a dirac flow of a Hamiltonian reading entries, derivative of a covariant function
@claim("b5-flow-H-entry", kind="id", sizes=SZ)
def b5_flow(s):
    """tr(P^T P) conserved along the flow of H = X00 (false)."""
    fl = s.dirac_flow(lambda t: t.X[0, 0])
    return {"read": READ(s), "dH": s.d(lambda t: t.tr(t.P.T @ t.P), fl)}


# 6. eigenvalues s.a inside a check
@claim("b6-eigs", kind="id", sizes=SZ)
def b6_eigs(s):
    """a_1 = tr A / n (false)."""
    return {"read": READ(s), "a": s.a[0] - s.tr(s.A) / s.n}


# 7. constant untyped matrix, combined only through a sum with an n-matrix in another check
@claim("b7-untyped", kind="id", sizes=SZ)
def b7_untyped(s):
    """X^T E X = X^T X / n, E = e1 e1^T untyped (false)."""
    n = s.n
    E = s.mat([[1 if (i == 0 and j == 0) else 0 for j in range(n)] for i in range(n)], ("?", "?"))
    return {"read": READ(s), "E": s.X.T @ E @ s.X - s.X.T @ s.X / n}


# 8. untyped E only: its slice has E and a product with X (covariance broken)
@claim("b8-untyped-sum", kind="id", sizes=SZ)
def b8_untyped(s):
    """tr(E XX^T) - r/n = 0 (false)."""
    n = s.n
    E = s.mat([[1 if (i == 0 and j == 0) else 0 for j in range(n)] for i in range(n)], ("?", "?"))
    return {"read": READ(s), "E": s.tr(E @ s.X @ s.X.T) - s.q(s.r, n)}


# 9. the false check hidden in the 'unread' group, true read group: sanity
@claim("b9-false-unread", kind="id", sizes=SZ)
def b9(s):
    """X^T A X = A_rr block? false: X^T A X - tr(A)/n I."""
    return {"read": READ(s), "f": s.X.T @ s.A @ s.X - s.tr(s.A) / s.n * s.Ir}


# 10. block matrix of X and P: [X P]
@claim("b10-block", kind="id", sizes=SZ)
def b10(s):
    """[X P]^T [X P] top-left = I (true) and bottom-right = I (false)."""
    B = block([[s.X, s.P]])
    M = B.T @ B
    return {"read": READ(s), "blk": M - block([[s.Ir, s.zeros(s.r, s.r, ("r", "r"))],
                                              [s.zeros(s.r, s.r, ("r", "r")), s.Ir]])}
