"""Combinations: a derivative along a user flow of functions with a moving resolvent, blocks, slices,
determinants and inverses; the Jacobian against the derivative; mixed second derivatives."""
from stiefelsym import block, claim, det, elementary

SZ = [(3, 2), (4, 2)]


def H_weird(t):
    """A Hamiltonian with a moving resolvent, a block, a slice, an entry, a determinant and an inverse."""
    mu = t.tr(t.X.T @ t.A @ t.X) + 7          # moving spectral parameter (away from the a_i generically)
    R = t.resolvent(mu)
    K = t.X.T @ t.P
    top = t.P[0:1, :]                          # a slice of P (row 0)
    B = block([[t.X.T @ t.X, K], [K.T, t.P.T @ t.P]])
    M = t.Ir + t.P.T @ t.A @ t.P
    return (t.tr(t.P.T @ R @ t.P) + top[0, 0] * t.X[1, 0] + t.tr(B @ B) / 3
            + det(t, M) + t.tr(M.inv() @ K @ K.T) + elementary(t, t.Phi @ t.Phi, 2)[2])


@claim("s76-dirac-tangent", kind="id", sizes=SZ)
def dirac_tangent(s):
    """The Dirac flow of H_weird keeps XᵀX and XᵀP + PᵀX (true for every H)."""
    f = s.dirac_flow(H_weird)
    return {"XtX": s.d(lambda t: t.X.T @ t.X, f),
            "sym": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, f)}


@claim("s76-canonical-tangent", kind="id", sizes=SZ)
def canonical_tangent(s):
    """FALSE: the ambient (canonical) flow of H_weird keeps XᵀP + PᵀX."""
    f = s.canonical_flow(H_weird)
    return {"sym": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, f)}


@claim("s76-dirac-energy", kind="id", sizes=SZ)
def dirac_energy(s):
    """H_weird is conserved along its own Dirac flow (true)."""
    return {"dH": s.d(H_weird, s.dirac_flow(H_weird))}


@claim("s76-jacobian-vs-d", kind="id", sizes=SZ)
def jacobian_vs_d(s):
    """The Jacobian row of H_weird applied to (V, W) is dH(V, W) (true, ambient)."""
    n, r = int(s.n), int(s.r)
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    J = s.jacobian(H_weird)
    vec = [V[i, j] for i in range(n) for j in range(r)] + [W[i, j] for i in range(n) for j in range(r)]
    lhs = sum((J[0][k] * vec[k] for k in range(1, len(vec))), J[0][0] * vec[0])
    return {"J.v - dH": lhs - s.d(H_weird, {"X": V, "P": W})}


@claim("s76-jacobian-vs-d-twin", kind="id", sizes=SZ)
def jacobian_vs_d_twin(s):
    """FALSE: the Jacobian row applied to (W, V) (X and P swapped) is dH(V, W)."""
    n, r = int(s.n), int(s.r)
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    J = s.jacobian(H_weird)
    vec = [W[i, j] for i in range(n) for j in range(r)] + [V[i, j] for i in range(n) for j in range(r)]
    lhs = sum((J[0][k] * vec[k] for k in range(1, len(vec))), J[0][0] * vec[0])
    return {"J.v - dH": lhs - s.d(H_weird, {"X": V, "P": W})}


@claim("s76-mixed-second", kind="id", sizes=SZ)
def mixed_second(s):
    """Mixed second derivatives of H_weird commute (true)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    a = s.d(lambda t: t.d(H_weird, {"X": U}), {"P": V})
    b = s.d(lambda t: t.d(H_weird, {"P": V}), {"X": U})
    return {"mixed": a - b}


@claim("s76-mixed-second-twin", kind="id", sizes=SZ)
def mixed_second_twin(s):
    """FALSE: the inner direction is the moving X: d_U(D_P H[X]) - D_P D_X H[U, X] = D_P H[U] != 0."""
    U = s.fresh("n", "r")
    a = s.d(lambda t: t.d(H_weird, {"P": t.X}), {"X": U})
    b = s.d(lambda t: t.d(H_weird, {"X": U}), {"P": s.X})
    return {"mixed": a - b}


@claim("s76-mixed-moving", kind="id", sizes=SZ)
def mixed_moving(s):
    """d_U(D_P H[X]) - D_P D_X H[U, X] - D_P H[U] = 0 (true)."""
    U = s.fresh("n", "r")
    a = s.d(lambda t: t.d(H_weird, {"P": t.X}), {"X": U})
    b = s.d(lambda t: t.d(H_weird, {"X": U}), {"P": s.X})
    return {"mixed": a - b - s.d(H_weird, {"P": U})}


@claim("s76-mutant92", kind="id", sizes=SZ)
def mutant92(s):
    """FALSE (H_weird is not O(r)-invariant): the mutant #92 of s76-dirac-tangent, d(XᵀX + PᵀX)/dt = 0."""
    f = s.dirac_flow(H_weird)
    return {"sym": s.d(lambda t: t.X.T @ t.X + t.P.T @ t.X, f)}


@claim("s76-psi-dot", kind="id", sizes=SZ)
def psi_dot(s):
    """FALSE (H_weird is not O(r)-invariant): dΨ/dt = 0 along its Dirac flow."""
    f = s.dirac_flow(H_weird)
    return {"dPsi": s.d(lambda t: t.Psi, f)}
