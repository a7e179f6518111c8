"""Round 10: reads of R^r that the right-reduced Cayley chart's pass (ir/passes.right_action_breaks) did not see.

The exact method takes S11 = 0 (the top r x r block X1 of X symmetric) for a graph that reads nothing of R^r.
Each false claim below reads X1 - X1^T (or its pairing with a skew matrix) without an entry or a matrix of
given entries on an R^r-sided matrix: it was proved exactly at (3, 2) and (4, 2) and fails under every other
method.  The true controls read the same shapes (a column of X has norm 1)."""
from stiefelsym import Size, SizeSpec, block, claim

N3 = SizeSpec((Size(3, 2),))
N34 = SizeSpec((Size(3, 2), Size(4, 2)))


def _columns(s):
    """e_1, e_2 of R^2 as block matrices of 1 x 1 pieces of I and 0 (no entry, no matrix of given entries)."""
    one, nil = s.identity(1), s.zeros(1, 1)
    return block([[one], [nil]]), block([[nil], [one]])


@claim("adv-s39-block-columns", paper="adv", kind="id", sizes=N34)
def block_columns(s):
    """False: X21 = X12, the columns of R^2 built as blocks and applied to X (a splitting of R^r)."""
    e1, e2 = _columns(s)
    return {"X21 - X12": (s.X @ e1)[1, 0] - (s.X @ e2)[0, 0]}


@claim("adv-s39-block-columns-true", paper="adv", kind="id", sizes=N34)
def block_columns_true(s):
    """True: the first column of X has norm 1 (read through the same blocks)."""
    e1, _ = _columns(s)
    x = s.X @ e1
    return {"|X e1|^2 - 1": s.tr(x.T @ x) - 1}


@claim("adv-s39-rows-of-In", paper="adv", kind="id", sizes=N34)
def rows_of_in(s):
    """False: X1 = X1^T with X1 = (rows 0..r-1 of I_n) X: a block of a matrix on R^n alone, used on R^r."""
    X1 = s.In[0:s.r, :] @ s.X
    return {"X1 - X1^T": X1 - X1.T}


@claim("adv-s39-rows-of-In-eta", paper="adv", kind="id", sizes=N34)
def rows_of_in_eta(s):
    """False: tr(X1 eta) = 0 for eta generic in so(r) (X1 as above)."""
    X1 = s.In[0:s.r, :] @ s.X
    return {"tr(X1 eta)": s.tr(X1 @ s.eta)}


@claim("adv-s39-rows-of-In-true", paper="adv", kind="id", sizes=N34)
def rows_of_in_true(s):
    """True: tr(X1^T X1) + tr(X2^T X2) = r, X1, X2 the top and bottom rows of X through slices of I_n."""
    X1 = s.In[0:s.r, :] @ s.X
    X2 = s.In[s.r:s.n, :] @ s.X
    return {"tr X1^T X1 + tr X2^T X2 - tr I_r": s.tr(X1.T @ X1) + s.tr(X2.T @ X2) - s.tr(s.Ir)}


@claim("adv-s39-trace-given-columns", paper="adv", kind="id", sizes=N3)
def trace_given_columns(s):
    """False: tr(X^T B) = X12 - X21 = 0, B a 3 x 2 matrix of given entries met by X^T only: the trace did not join
    B's columns to R^r."""
    q0, q1 = s.q(0), s.q(1)
    B = s.mat([[q0, q1], [-q1, q0], [q0, q0]])
    return {"tr(X^T B)": s.tr(s.X.T @ B)}


@claim("adv-s39-killing-given-columns", paper="adv", kind="id", sizes=N3)
def killing_given_columns(s):
    """False: <X^T, B> = 0 (the Killing pairing -1/2 tr(X^T B)), B as above."""
    q0, q1 = s.q(0), s.q(1)
    B = s.mat([[q0, q1], [-q1, q0], [q0, q0]])
    return {"<X^T, B>": s.killing(s.X.T, B)}


@claim("adv-s39-trace-method-slice", paper="adv", kind="id", sizes=N34)
def trace_method_slice(s):
    """False: (X^T E J).trace() = 0, E = the first two columns of I_n, J = [[0, 1], [-1, 0]] untyped."""
    q0, q1 = s.q(0), s.q(1)
    E = s.In[:, 0:2]
    J = s.mat([[q0, q1], [-q1, q0]])
    return {"tr(X^T E J)": (s.X.T @ E @ J).trace()}


def _top_rows(s, M):
    """The top r x r block of an n x r matrix M as [M; 0]ᵀ[I_r; 0] taken at R^n + R^r = R^r + R^n (typed blocks
    with symbolic sizes, no block with a side on R^n alone, no entry, no matrix of given entries)."""
    return (block([[M], [s.zeros(s.r, s.r)]]).T @ block([[s.Ir], [s.zeros(s.n, s.r)]])).T


@claim("adv-s39-two-splittings-identity", paper="adv", kind="id", sizes=N34)
def two_splittings_identity(s):
    """False: X1 = I_r (true at the equivariant chart's point X = X0 only)."""
    return {"X1 - I_r": _top_rows(s, s.X) - s.Ir}


@claim("adv-s39-two-splittings-symmetric", paper="adv", kind="id", sizes=N34)
def two_splittings_symmetric(s):
    """False: X1 = X1ᵀ."""
    X1 = _top_rows(s, s.X)
    return {"X1 - X1^T": X1 - X1.T}


@claim("adv-s39-two-splittings-p-skew", paper="adv", kind="id", sizes=N34)
def two_splittings_p_skew(s):
    """False: P1 + P1ᵀ = 0, P1 the top r x r block of P (P = (W; Z), W skew, on the equivariant chart)."""
    P1 = _top_rows(s, s.P)
    return {"P1 + P1^T": P1 + P1.T}


@claim("adv-s39-two-splittings-first-columns", paper="adv", kind="id", sizes=N34)
def two_splittings_first_columns(s):
    """False: X1 = X1ᵀ with X1 = Eᵀ X, E = [I_n; 0]ᵀ[I_r; 0] the first r columns of I_n."""
    E = block([[s.In], [s.zeros(s.r, s.n)]]).T @ block([[s.Ir], [s.zeros(s.n, s.r)]])
    X1 = E.T @ s.X
    return {"X1 - X1^T": X1 - X1.T}


@claim("adv-s39-two-splittings-true", paper="adv", kind="id", sizes=N34)
def two_splittings_true(s):
    """True: the two readings of the top r x r block agree, [X; 0]ᵀ[I_r; 0] transposed and (rows 0..r-1 of I_n) X."""
    return {"X1 - X1'": _top_rows(s, s.X) - s.In[0:s.r, :] @ s.X}
