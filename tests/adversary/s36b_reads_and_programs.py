"""Round 6b: the gradients of coordinate reads, the symmetric operator and the Jacobians as graph transforms,
and the exact method's straight-line programs, each against a truth written out by hand (a true claim and a
false one that differs from it where a wrong rule would: off the diagonal, by a transpose, by a sign, by a
permutation of the directions).  Also: graphs of the compiled algebra that cancel (x − x, 0·x), large
integers, entries equal up to sign, and one graph evaluated several times in one process (the same claim
twice, and a correction with the claim's own graph)."""
from stiefelsym import admissible, block, claim

SIZES = admissible(n_min=3, n_max=3, r_min=2, r_max=2)


def _E(s, i, j, c, tags=("n", "r")):
    """c at (i, j) of an n x r matrix, 0 elsewhere."""
    return s.mat([[c if (a, b) == (i, j) else s.q(0) for b in range(s.r)] for a in range(s.n)], tags)


def _off(t):
    return t.X[0, 1] * t.P[1, 0]


@claim("adv-s36b-gradient-off-diagonal", kind="id", sizes=SIZES)
def gradient_off_diagonal(s):
    """True: the gradient of H = X₀₁P₁₀ is (P₁₀E₀₁, X₀₁E₁₀)."""
    HX, HP = s.gradient(_off)
    return {"X": HX - _E(s, 0, 1, s.P[1, 0]), "P": HP - _E(s, 1, 0, s.X[0, 1])}


@claim("adv-s36b-gradient-off-diagonal-transposed", kind="id", sizes=SIZES)
def gradient_off_diagonal_transposed(s):
    """False: the gradient of H = X₀₁P₁₀ is (P₁₀E₁₀, X₀₁E₀₁) (the adjoints scattered to the transposed cells)."""
    HX, HP = s.gradient(_off)
    return {"X": HX - _E(s, 1, 0, s.P[1, 0]), "P": HP - _E(s, 0, 1, s.X[0, 1])}


def _slices(t):
    return t.tr(t.X[0:3:2, :].T @ t.P[::-1, :][0:2, :])


@claim("adv-s36b-gradient-slices", kind="id", sizes=SIZES)
def gradient_slices(s):
    """True: H = tr(X[0:3:2]ᵀ (P reversed)[0:2]) = Σ_j X₀ⱼP₂ⱼ + X₂ⱼP₁ⱼ: ∂H/∂X has rows (P₂, 0, P₁), ∂H/∂P rows
    (0, X₂, X₀)."""
    HX, HP = s.gradient(_slices)
    z = s.zeros(1, s.r, ("?", "r"))
    wantX = block([[s.P[2:3, :]], [z], [s.P[1:2, :]]])
    wantP = block([[z], [s.X[2:3, :]], [s.X[0:1, :]]])
    return {"X": HX - wantX, "P": HP - wantP}


@claim("adv-s36b-gradient-slices-unreversed", kind="id", sizes=SIZES)
def gradient_slices_unreversed(s):
    """False: the same with the reversal of P ignored (∂H/∂P rows (X₀, 0, X₂))."""
    HX, HP = s.gradient(_slices)
    z = s.zeros(1, s.r, ("?", "r"))
    wantX = block([[s.P[0:1, :]], [z], [s.P[2:3, :]]])
    wantP = block([[s.X[0:1, :]], [z], [s.X[2:3, :]]])
    return {"X": HX - wantX, "P": HP - wantP}


def _op(t):
    return t.tr(t.sym_operator()(t.X @ t.P.T) @ t.X @ t.X.T @ t.A)


@claim("adv-s36b-gradient-operator", kind="id", sizes=SIZES)
def gradient_operator(s):
    """True: for H = tr(𝔸(XPᵀ) XXᵀA), 𝔸 symmetric on so(n) (extended by the skew part), W = 𝔸(XPᵀ) and
    C = 𝔸((XXᵀA)ᵀ): ∂H/∂X = CP − WAX + AWX, ∂H/∂P = −CX (tr(𝔸(U)B) = tr(Uᵀ𝔸(Bᵀ)), 𝔸(·) skew)."""
    HX, HP = s.gradient(_op)
    Aop = s.sym_operator()
    X, P, A = s.X, s.P, s.A
    C = Aop((X @ X.T @ A).T)
    W = Aop(X @ P.T)
    return {"X": HX - (C @ P - W @ A @ X + A @ W @ X), "P": HP + C @ X}


@claim("adv-s36b-gradient-operator-transposed", kind="id", sizes=SIZES)
def gradient_operator_transposed(s):
    """False: the same with the operator's adjoint transposed (𝔸(B) in place of 𝔸(Bᵀ): −C for C)."""
    HX, HP = s.gradient(_op)
    Aop = s.sym_operator()
    X, P, A = s.X, s.P, s.A
    C = Aop(X @ X.T @ A)
    W = Aop(X @ P.T)
    return {"X": HX - (C @ P - W @ A @ X + A @ W @ X), "P": HP + C @ X}


def _jac(t):
    return [t.X[0, 1] * t.P[2, 0], t.X[1, 1]]


@claim("adv-s36b-jacobian-directions", kind="id", sizes=SIZES)
def jacobian_directions(s):
    """True: the Jacobian of (X₀₁P₂₀, X₁₁) in the coordinates X₀₀ X₀₁ X₁₀ X₁₁ X₂₀ X₂₁ P₀₀ .. P₂₁."""
    J = s.mat(s.jacobian(_jac), ("?", "?"))
    z = s.q(0)
    row0 = [z, s.P[2, 0], z, z, z, z, z, z, z, z, s.X[0, 1], z]
    row1 = [z, z, z, s.q(1), z, z, z, z, z, z, z, z]
    return {"J": J - s.mat([row0, row1], ("?", "?"))}


@claim("adv-s36b-jacobian-directions-permuted", kind="id", sizes=SIZES)
def jacobian_directions_permuted(s):
    """False: the same with the coordinates of X taken by columns (X₀₀ X₁₀ X₂₀ X₀₁ ..)."""
    J = s.mat(s.jacobian(_jac), ("?", "?"))
    z = s.q(0)
    row0 = [z, z, z, s.P[2, 0], z, z, z, z, z, z, s.X[0, 1], z]
    row1 = [z, z, z, z, s.q(1), z, z, z, z, z, z, z]
    return {"J": J - s.mat([row0, row1], ("?", "?"))}


BIG = 2 ** 200 + 1


@claim("adv-s36b-program-cancellations", kind="id", sizes=SIZES)
def program_cancellations(s):
    """True: x − x, 0·x, a large integer times XᵀP minus itself, Φ + Φᵀ (entries equal up to sign), −(−X) − X,
    3Φ² − Φ(3Φ), (BX)ᵀ(BP) − B²XᵀP and (2X − 3P) + (3P − 2X) (integer literals: the compiled algebra)."""
    X, P, Phi = s.X, s.P, s.Phi
    M = X.T @ P
    return {"xx": M - M, "0x": 0 * M, "big": (BIG * M - (BIG - 1) * M) - M, "skew": Phi + Phi.T,
            "neg": -(-X) - X, "mix": 3 * (Phi @ Phi) - Phi @ (3 * Phi),
            "bigprod": (BIG * X).T @ (BIG * P) - (BIG * BIG) * M, "cross": (2 * X - 3 * P) + (3 * P - 2 * X)}


@claim("adv-s36b-program-big-off-by-one", kind="id", sizes=SIZES)
def program_big_off_by_one(s):
    """False: (B·XᵀP − (B − 2)·XᵀP) − XᵀP = 0 for B = 2²⁰⁰ + 1 (it is XᵀP ≠ 0)."""
    M = s.X.T @ s.P
    return {"bigdiff": (BIG * M - (BIG - 2) * M) - M}


@claim("adv-s36b-program-big-square-off-by-one", kind="id", sizes=SIZES)
def program_big_square_off_by_one(s):
    """False: (BX)ᵀ(BP) = (B² − 1)XᵀP."""
    return {"bigprod": (BIG * s.X).T @ (BIG * s.P) - (BIG * BIG - 1) * (s.X.T @ s.P)}


@claim("adv-s36b-program-sign-pattern", kind="id", sizes=SIZES)
def program_sign_pattern(s):
    """False: Φ − Φᵀ = 0 (Φ is skew, so Φ − Φᵀ = 2Φ ≠ 0; its entries are equal up to sign)."""
    return {"skew": s.Phi - s.Phi.T}


@claim("adv-s36b-program-order", kind="id", sizes=SIZES)
def program_order(s):
    """False: XᵀP = PᵀX (the commutative normalisation must not make a product of matrices commute)."""
    return {"f": s.X.T @ s.P - s.P.T @ s.X}


@claim("adv-s36b-program-coefficients", kind="id", sizes=SIZES)
def program_coefficients(s):
    """False: (6X + 4P) − 2(3X + 3P) = 0 (it is −2P; the coefficients carried along must not cancel it)."""
    return {"f": (6 * s.X + 4 * s.P) - 2 * (3 * s.X + 3 * s.P)}


def _flow_claim(s):
    X, P, A = s.X, s.P, s.A
    flow = {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - (X @ X.T @ A - A @ X @ X.T)}


@claim("adv-s36b-program-twice-a", kind="id", sizes=SIZES)
def program_twice_a(s):
    """True (the README's example, [XXᵀ, A] written out): dΦ/dt = XXᵀA − AXXᵀ along the normal Neumann flow."""
    return _flow_claim(s)


@claim("adv-s36b-program-twice-b", kind="id", sizes=SIZES)
def program_twice_b(s):
    """True: the same graph as adv-s36b-program-twice-a (compiled on its second evaluation in the process)."""
    return _flow_claim(s)


@claim("adv-s36b-program-twice-false", kind="id", sizes=SIZES, expect="fails",
       erratum="the commutator's sign")
def program_twice_false(s):
    """False as printed (the commutator's sign flipped), with a correction whose graph is the true claim's."""
    X, P, A = s.X, s.P, s.A
    flow = {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) + (X @ X.T @ A - A @ X @ X.T)}


program_twice_false.claim.correction("the commutator's sign restored")(_flow_claim)


def _neumann(s):
    X, P, A = s.X, s.P, s.A
    return {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}


@claim("adv-s36b-derivative-operator", kind="id", sizes=SIZES)
def derivative_operator(s):
    """True: d𝔸(ΦA)/dt = 𝔸(dΦ/dt A) along the normal Neumann flow (𝔸 linear with constant coefficients)."""
    flow = _neumann(s)
    dPhi = s.d(lambda t: t.Phi, flow)
    return {"d": s.d(lambda t: t.sym_operator()(t.Phi @ t.A), flow) - s.sym_operator()(dPhi @ s.A)}


@claim("adv-s36b-derivative-operator-other", kind="id", sizes=SIZES)
def derivative_operator_other(s):
    """False: d𝔸(ΦA)/dt = 𝔹(dΦ/dt A) with 𝔹 another symmetric operator."""
    flow = _neumann(s)
    dPhi = s.d(lambda t: t.Phi, flow)
    return {"d": s.d(lambda t: t.sym_operator()(t.Phi @ t.A), flow) - s.sym_operator("BB")(dPhi @ s.A)}


def _cells(t):
    return t.mat([[t.X[0, 1], t.P[2, 0] * t.X[1, 1]], [t.P[0, 0], t.X[2, 0]]], ("r", "r"))


@claim("adv-s36b-derivative-cells", kind="id", sizes=SIZES)
def derivative_cells(s):
    """True: the derivative of a matrix of given entries along a flow is the matrix of their derivatives."""
    flow = _neumann(s)
    dX, dP = flow["X"], flow["P"]
    want = s.mat([[dX[0, 1], dP[2, 0] * s.X[1, 1] + s.P[2, 0] * dX[1, 1]], [dP[0, 0], dX[2, 0]]], ("r", "r"))
    return {"d": s.d(_cells, flow) - want}


@claim("adv-s36b-derivative-cells-transposed", kind="id", sizes=SIZES)
def derivative_cells_transposed(s):
    """False: the same with the derivative's off-diagonal cells exchanged."""
    flow = _neumann(s)
    dX, dP = flow["X"], flow["P"]
    want = s.mat([[dX[0, 1], dP[0, 0]], [dP[2, 0] * s.X[1, 1] + s.P[2, 0] * dX[1, 1], dX[2, 0]]], ("r", "r"))
    return {"d": s.d(_cells, flow) - want}


def _sym(t):
    return t.X.T @ t.A @ t.X


@claim("adv-s36b-jacobian-upper-triangle", kind="id", sizes=SIZES)
def jacobian_upper_triangle(s):
    """True: the Jacobian of the symmetric XᵀAX read by its upper triangle has the rows of its entries
    (0,0), (0,1), (1,1), in that order."""
    J = s.mat(s.jacobian(_sym, True), ("?", "?"))
    K = s.mat(s.jacobian(lambda t: [_sym(t)[0, 0], _sym(t)[0, 1], _sym(t)[1, 1]]), ("?", "?"))
    return {"J": J - K}


@claim("adv-s36b-jacobian-upper-triangle-order", kind="id", sizes=SIZES)
def jacobian_upper_triangle_order(s):
    """False: the same rows in the order (0,0), (1,1), (0,1)."""
    J = s.mat(s.jacobian(_sym, True), ("?", "?"))
    K = s.mat(s.jacobian(lambda t: [_sym(t)[0, 0], _sym(t)[1, 1], _sym(t)[0, 1]]), ("?", "?"))
    return {"J": J - K}


def _H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("adv-s36b-bracket-captured-half", kind="id", sizes=SIZES)
def bracket_captured_half(s):
    """True (Φ₀ = the claim's Φ, a constant inside F): {tr(Φ₀ΦA), H} = ½{tr(ΦΦA), H}."""
    return {"b": s.bracket(lambda t: t.tr(s.Phi @ t.Phi @ t.A), _H) - s.bracket(lambda t: t.tr(t.Phi @ t.Phi @ t.A), _H) / 2}


@claim("adv-s36b-bracket-captured-whole", kind="id", sizes=SIZES)
def bracket_captured_whole(s):
    """False: {tr(Φ₀ΦA), H} = {tr(ΦΦA), H} (as if the captured Φ₀ moved with the point)."""
    return {"b": s.bracket(lambda t: t.tr(s.Phi @ t.Phi @ t.A), _H) - s.bracket(lambda t: t.tr(t.Phi @ t.Phi @ t.A), _H)}
