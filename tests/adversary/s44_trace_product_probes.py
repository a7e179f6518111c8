"""Round 19: the exact method's fused trace of a product, tr(x @ y) computed as sum_ik x_ik y_ki when the product is
read by the trace alone (``ir.evaluate._trace_products``, ``Mat._trace_product``, ``PolyBackend.trace_matmul``).
The truth of each claim is in its docstring.

* non-square factors (r x n times n x r and n x r times r x n), transposes, blocks, scalars times matrices, the
  resolvent and an inverse (denominators), products read twice or returned, products inside functions
  differentiated along a vector field and inside brackets;
* false statements whose only nonzero part is an off-diagonal entry of a fused product's factor;
* untyped constant matrices that meet R^n at the product or at the trace only (a recorded look at coordinates:
  a fused trace that lost it would let the equivariant chart, where X = [I; 0], prove a coordinate statement);
* the value against the sum of the diagonal entries of the same product computed whole (as another node);
* sizes that do not fit (an error under every method, fused or not)."""
from stiefelsym import admissible, block, claim

R2 = admissible(n_min=3, n_max=4, r_min=2, r_max=2)
N3 = admissible(n_min=3, n_max=3, r_min=1, r_max=2)
ANY = admissible(n_min=2, n_max=4, r_max=3)
SQ = admissible(n_min=3, n_max=3, r_min=3, r_max=3)


def _xax(s):
    return s.X.T @ s.A @ s.X


def _diag_sum(M):
    """The sum of the diagonal entries of a square matrix of k rows, read one by one."""
    def go(s, k):
        acc = s.q(0)
        for i in range(k):
            acc = acc + M[i, i]
        return acc
    return go


# -- true -------------------------------------------------------------------------------------------------------

@claim("adv-s44-xtx-xxt", paper="adv", kind="id", sizes=ANY)
def xtx_xxt(s):
    """True: tr(XᵀX) = tr(XXᵀ) (an r x r and an n x n fused trace of the same factors)."""
    return {"v": s.tr(s.X.T @ s.X) - s.tr(s.X @ s.X.T)}


@claim("adv-s44-xtx-r", paper="adv", kind="id", sizes=ANY)
def xtx_r(s):
    """True on T*V: tr(XᵀX) = tr(I_r)."""
    return {"v": s.tr(s.X.T @ s.X) - s.tr(s.Ir)}


@claim("adv-s44-diag-sum", paper="adv", kind="id", sizes=ANY)
def diag_sum(s):
    """True: tr(M N) for M = XᵀA (r x n), N = AX (n x r), fused, against the diagonal of (NᵀMᵀ)ᵀ = MN read
    entry by entry (another node: NᵀMᵀ, whose diagonal is MN's)."""
    M, N = s.X.T @ s.A, s.A @ s.X
    return {"v": s.tr(M @ N) - _diag_sum(N.T @ M.T)(s, s.r)}


@claim("adv-s44-diag-sum-n", paper="adv", kind="id", sizes=ANY)
def diag_sum_n(s):
    """True: tr(N M) (n x n, fused) against the diagonal of (MᵀNᵀ) read entry by entry."""
    M, N = s.X.T @ s.A, s.A @ s.X
    return {"v": s.tr(N @ M) - _diag_sum(M.T @ N.T)(s, s.n)}


@claim("adv-s44-skew-pairing", paper="adv", kind="id", sizes=R2)
def skew_pairing(s):
    """True: tr(XᵀAX J) = (XᵀAX)₁₀ − (XᵀAX)₀₁ = 0 for J = [[0, 1], [−1, 0]] (a symmetric matrix against a skew
    one: only off-diagonal entries of the factor enter)."""
    J = s.mat([[s.q(0), s.q(1)], [s.q(-1), s.q(0)]], ("r", "r"))
    return {"v": s.tr(_xax(s) @ J)}


@claim("adv-s44-resolvent", paper="adv", kind="id", sizes=ANY)
def resolvent(s):
    """True: tr(R(λ)(λI − A)) = tr(I_n), tr(R A) = tr(A R), and tr(R R) against the diagonal of RᵀRᵀ."""
    R = s.resolvent(s.lam)
    return {"inverse": s.tr(R @ (s.lam * s.In - s.A)) - s.tr(s.In),
            "commute": s.tr(R @ s.A) - s.tr(s.A @ R),
            "square": s.tr(R @ R) - _diag_sum(R.T @ R.T)(s, s.n)}


@claim("adv-s44-inverse", paper="adv", kind="id", sizes=ANY)
def inverse(s):
    """True: tr(M⁻¹ M) = tr(I_r) for M = I_r + XᵀAX, and tr(M⁻¹ XᵀX) = tr(M⁻¹) on T*V."""
    M = s.Ir + _xax(s)
    Mi = M.inv()
    return {"v": s.tr(Mi @ M) - s.tr(s.Ir), "w": s.tr(Mi @ (s.X.T @ s.X)) - s.tr(Mi)}


@claim("adv-s44-scalar", paper="adv", kind="id", sizes=ANY)
def scalar(s):
    """True: tr((λXᵀ) X) = λ tr(I_r), tr(Xᵀ (2P)) = 2 tr(PᵀX)."""
    return {"v": s.tr((s.lam * s.X.T) @ s.X) - s.lam * s.tr(s.Ir),
            "w": s.tr(s.X.T @ (2 * s.P)) - 2 * s.tr(s.P.T @ s.X)}


@claim("adv-s44-block", paper="adv", kind="id", sizes=ANY)
def block_trace(s):
    """True: Z = [X; P] (2n x r): tr(ZᵀZ) = tr(XᵀX) + tr(PᵀP) = tr(Z Zᵀ)."""
    Z = block([[s.X], [s.P]])
    return {"v": s.tr(Z.T @ Z) - s.tr(s.X.T @ s.X) - s.tr(s.P.T @ s.P),
            "w": s.tr(Z @ Z.T) - s.tr(Z.T @ Z)}


@claim("adv-s44-read-twice", paper="adv", kind="id", sizes=ANY)
def read_twice(s):
    """True: S = XᵀAX: tr(S S) (fused) against Σ S_ij S_ji, S − Sᵀ = 0, and a product returned and traced:
    (S XᵀX) − S and tr(S XᵀX) − tr(S)."""
    S = _xax(s)
    k = s.r
    acc = s.q(0)
    for i in range(k):
        for j in range(k):
            acc = acc + S[i, j] * S[j, i]
    T = S @ (s.X.T @ s.X)
    return {"ss": s.tr(S @ S) - acc, "sym": S - S.T, "m": T - S, "t": s.tr(T) - s.tr(S)}


@claim("adv-s44-derivative", paper="adv", kind="id", sizes=ANY)
def derivative(s):
    """True: along X' = AX, P' = 0, d tr(XᵀAX) = 2 tr(XᵀAAX); a product made outside the function and read
    inside it (Q = XᵀAX, a constant there): along X' = X, d tr(Q XᵀX) = 2 tr(Q XᵀX)."""
    Q = _xax(s)
    flow = {"X": s.A @ s.X, "P": 0 * s.P}
    grow = {"X": s.X, "P": 0 * s.P}
    return {"d": s.d(lambda u: u.tr(u.X.T @ u.A @ u.X), flow) - 2 * s.tr(s.X.T @ s.A @ s.A @ s.X),
            "q": s.d(lambda u: u.tr(Q @ (u.X.T @ u.X)), grow) - 2 * s.tr(Q @ (s.X.T @ s.X)),
            "qq": s.tr(Q @ Q) - s.tr(_xax(s) @ _xax(s))}


@claim("adv-s44-bracket", paper="adv", kind="id", sizes=ANY)
def bracket(s):
    """True: {F, G} + {G, F} = 0 for F = tr(XᵀAX), G = tr(PᵀAX) (antisymmetry; traces of products in the bodies)."""
    F = lambda t: t.tr(t.X.T @ t.A @ t.X)       # noqa: E731
    G = lambda t: t.tr(t.P.T @ t.A @ t.X)       # noqa: E731
    return {"v": s.bracket(F, G) + s.bracket(G, F)}


@claim("adv-s44-untyped-pair", paper="adv", kind="id", sizes=N3)
def untyped_pair(s):
    """True: tr(E XXᵀ) − tr(E) + tr(E (Iₙ − XXᵀ)) = 0 for the untyped E = diag(1, 0, 0) (two fused traces where E
    meets R^n).  Its mutant without the third term, (XXᵀ)₀₀ − 1, is false but 0 at X = [I; 0], the equivariant
    chart's point: a mutant that took a fused trace's shared value without its recorded look at coordinates
    would be proved there."""
    E = s.mat([[s.q(1), s.q(0), s.q(0)], [s.q(0), s.q(0), s.q(0)], [s.q(0), s.q(0), s.q(0)]])
    XX = s.X @ s.X.T
    return {"v": s.tr(E @ XX) - s.tr(E) + s.tr(E @ (s.In - XX))}


# -- false ------------------------------------------------------------------------------------------------------

@claim("adv-s44-xxt-n", paper="adv", kind="id", sizes=ANY)
def xxt_n(s):
    """False for r < n: tr(XXᵀ) = r, not tr(I_n) = n (true at r = n)."""
    return {"v": s.tr(s.X @ s.X.T) - s.tr(s.In)}


@claim("adv-s44-diag-sum-off", paper="adv", kind="id", sizes=R2)
def diag_sum_off(s):
    """False: the true diag-sum statement with the off-diagonal entry (NᵀMᵀ)₀₁ = (XᵀAAX)₁₀ added."""
    M, N = s.X.T @ s.A, s.A @ s.X
    W = N.T @ M.T
    return {"v": s.tr(M @ N) - _diag_sum(W)(s, s.r) - W[0, 1]}


@claim("adv-s44-sym-pairing", paper="adv", kind="id", sizes=R2)
def sym_pairing(s):
    """False: tr(XᵀAX J) = 2 (XᵀAX)₀₁ for J = [[0, 1], [1, 0]]: only the factor's off-diagonal entry enters."""
    J = s.mat([[s.q(0), s.q(1)], [s.q(1), s.q(0)]], ("r", "r"))
    return {"v": s.tr(_xax(s) @ J)}


@claim("adv-s44-unit-entry", paper="adv", kind="id", sizes=R2)
def unit_entry(s):
    """False: tr(E₀₁ XᵀAX) = (XᵀAX)₁₀ (E₀₁ the matrix unit, of the spaces of R^r)."""
    E = s.mat([[s.q(0), s.q(1)], [s.q(0), s.q(0)]], ("r", "r"))
    return {"v": s.tr(E @ _xax(s))}


@claim("adv-s44-untyped-product", paper="adv", kind="id", sizes=N3)
def untyped_product(s):
    """False: tr(E (XXᵀ)) = (XXᵀ)₀₀ for the untyped E = diag(1, 0, 0); it is 1 at X = [I; 0] (the equivariant
    chart's point) only.  The untyped E meets R^n in the product."""
    E = s.mat([[s.q(1), s.q(0), s.q(0)], [s.q(0), s.q(0), s.q(0)], [s.q(0), s.q(0), s.q(0)]])
    return {"v": s.tr(E @ (s.X @ s.X.T)) - 1}


@claim("adv-s44-untyped-trace", paper="adv", kind="id", sizes=N3)
def untyped_trace(s):
    """False: tr(B Xᵀ) = X₀₀ for the untyped 3 x r matrix B = e₀e₀ᵀ; 1 at X = [I; 0] only.  B Xᵀ joins B's
    columns with R^r, and B's rows meet R^n only at the trace (the product's rows stay untyped)."""
    rows = [[s.q(1 if (i, j) == (0, 0) else 0) for j in range(s.r)] for i in range(3)]
    B = s.mat(rows)
    return {"v": s.tr(B @ s.X.T) - 1}


@claim("adv-s44-resolvent-diagonal", paper="adv", kind="id", sizes=ANY)
def resolvent_diagonal(s):
    """True: tr(R(λ)(λI − A + E)) = n + R₁₀ = n for E the matrix unit E₀₁ (of the spaces of R^n): A = diag(a),
    so R is diagonal."""
    R = s.resolvent(s.lam)
    E = s.mat([[s.q(1 if (i, j) == (0, 1) else 0) for j in range(s.n)] for i in range(s.n)], ("n", "n"))
    return {"v": s.tr(R @ (s.lam * s.In - s.A + E)) - s.tr(s.In)}


@claim("adv-s44-resolvent-off", paper="adv", kind="id", sizes=ANY)
def resolvent_off(s):
    """False: tr((R X)(Xᵀ E₀₁)) = (R X Xᵀ)₁₀ = R₁₁ (XXᵀ)₁₀ (R = R(λ) diagonal, E₀₁ the n x n matrix unit)."""
    R = s.resolvent(s.lam)
    E = s.mat([[s.q(1 if (i, j) == (0, 1) else 0) for j in range(s.n)] for i in range(s.n)], ("n", "n"))
    return {"v": s.tr((R @ s.X) @ (s.X.T @ E))}


@claim("adv-s44-inverse-off", paper="adv", kind="id", sizes=R2)
def inverse_off(s):
    """False: tr(M⁻¹ (M + E₀₁)) = r + (M⁻¹)₁₀ for M = I_r + XᵀAX."""
    M = s.Ir + _xax(s)
    E = s.mat([[s.q(0), s.q(1)], [s.q(0), s.q(0)]], ("r", "r"))
    return {"v": s.tr(M.inv() @ (M + E)) - s.tr(s.Ir)}


@claim("adv-s44-scalar-off", paper="adv", kind="id", sizes=ANY)
def scalar_off(s):
    """False: tr(Xᵀ (2X)) = 2r, not r."""
    return {"v": s.tr(s.X.T @ (2 * s.X)) - s.tr(s.Ir)}


@claim("adv-s44-derivative-off", paper="adv", kind="id", sizes=ANY)
def derivative_off(s):
    """False: along X' = AX, P' = 0, d tr(XᵀAX) = 2 tr(XᵀAAX), not 3 tr(XᵀAAX)."""
    flow = {"X": s.A @ s.X, "P": 0 * s.P}
    return {"d": s.d(lambda u: u.tr(u.X.T @ u.A @ u.X), flow) - 3 * s.tr(s.X.T @ s.A @ s.A @ s.X)}


@claim("adv-s44-transpose-off", paper="adv", kind="id", sizes=ANY)
def transpose_off(s):
    """False for r < n: tr(XXᵀA) = tr(XᵀAX), not tr(A)."""
    return {"v": s.tr((s.X @ s.X.T) @ s.A) - s.tr(s.A)}


# -- ill-formed -------------------------------------------------------------------------------------------------

@claim("adv-s44-nonsquare", paper="adv", kind="id", sizes=ANY)
def nonsquare(s):
    """Ill-formed: the trace of the n x r product (XXᵀ) X."""
    return {"v": s.tr((s.X @ s.X.T) @ s.X)}


@claim("adv-s44-spaces", paper="adv", kind="id", sizes=SQ)
def spaces(s):
    """Ill-formed at r = n: X P joins R^r (X's columns) with R^n (P's rows), though the sizes agree."""
    return {"v": s.tr(s.X @ s.P)}
