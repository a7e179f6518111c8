"""Round 11, the right-reduced Cayley chart (X = I, P = W at r = n; S11 = 0 below it): reads of ℝʳ that the pass
`ir/passes.right_action_breaks` let through, written with the public API.

* JA: at r = n an untyped identity of an int size (``s.identity(3)``) is a piece the tracer cannot tell apart from
  ℝⁿ or ℝʳ (3 is neither s.n nor s.r); used on ℝʳ on one side and on ℝⁿ on the other, it makes X a matrix on ℝⁿ:
  X symmetric, tr X = 3 and P skew hold at X = I only.
* JB: a number that an engine call made (``s.d`` of a scalar function) had an engine value's sides in the pass, and
  a product c·M took the number's sides instead of the matrix's: every join of M (c·I₃ above; c·I_r, c·0 in the
  blocks of round 10's RD, ℝⁿ ⊕ ℝʳ taken for ℝʳ ⊕ ℝⁿ) went unseen, at r = n and below it.
The true controls are proved."""
from stiefelsym import Size, SizeSpec, block, claim

SQ3 = SizeSpec((Size(3, 3),), n_min=3, n_max=3, r_is_n=True)        # stated at (3,3) only
R32 = SizeSpec((Size(3, 2), Size(4, 2)), n_min=3, n_max=4, r_min=2, r_max=2)


def _c(s):
    """A number made by s.d: d/dt tr(XᵀAX) along X' = AX, P' = 0, that is 2 tr(XᵀA²X) (nonzero)."""
    return s.d(lambda t: s.tr(t.X.T @ s.A @ t.X), {"X": s.A @ s.X, "P": s.zeros(s.n, s.r, ("n", "r"))})


@claim("adv-s40-sq-int-identity-sym", paper="adv", kind="id", sizes=SQ3)
def x_sym_int_identity(s):
    """False: X symmetric at r = n = 3, X made square by an int-sized untyped identity (JA)."""
    Xu = s.X @ s.identity(3)
    return {"Xu - Xu^T": Xu - Xu.T}


@claim("adv-s40-sq-int-identity-trace", paper="adv", kind="id", sizes=SQ3)
def x_trace_int_identity(s):
    """False: tr X = 3 at r = n = 3 (JA)."""
    return {"tr XE - 3": (s.X @ s.identity(3)).trace() - 3}


@claim("adv-s40-sq-int-identity-p-skew", paper="adv", kind="id", sizes=SQ3)
def p_skew_int_identity(s):
    """False: P skew at r = n = 3 (JA)."""
    Pu = s.P @ s.identity(3)
    return {"Pu + Pu^T": Pu + Pu.T}


@claim("adv-s40-sq-int-generic-commutes", paper="adv", kind="id", sizes=SQ3)
def generic_commutes(s):
    """False: XG = GX at r = n = 3 for one untyped generic 3 x 3 matrix G, on ℝʳ right of X and on ℝⁿ left of it (JA)."""
    G = s.general_params("G", 3, 3, ("?", "?"))
    return {"XG - GX": s.X @ G - G @ s.X}


@claim("adv-s40-sq-int-identity-true", paper="adv", kind="id", sizes=SQ3)
def int_identity_true(s):
    """True: (XE)(XE)ᵀ = I at r = n = 3 with E the int-sized untyped identity."""
    Xu = s.X @ s.identity(3)
    return {"XE(XE)^T - I": Xu @ Xu.T - s.identity(3)}


@claim("adv-s40-sq-d-scalar-sym", paper="adv", kind="id", sizes=SQ3)
def x_sym_d_scalar(s):
    """False: c(X − Xᵀ) = 0 at r = n = 3, through c·I₃ with c = s.d(...) (JB)."""
    Xu = s.X @ (_c(s) * s.identity(3))
    return {"Xu - Xu^T": Xu - Xu.T}


def _top(s, M):
    """c M1ᵀ for the top r x r block M1 of the n x r matrix M: [M; 0]ᵀ[c I_r; c 0] (ℝⁿ ⊕ ℝʳ taken for ℝʳ ⊕ ℝⁿ)."""
    c = _c(s)
    return block([[M], [s.zeros(s.r, s.r)]]).T @ block([[c * s.Ir], [c * s.zeros(s.n, s.r)]])


@claim("adv-s40-d-scalar-two-splittings-sym", paper="adv", kind="id", sizes=R32)
def two_splittings_sym(s):
    """False: the top r x r block of X symmetric, read through blocks of c·I_r and c·0 (JB)."""
    M = _top(s, s.X)
    return {"M - M^T": M - M.T}


@claim("adv-s40-d-scalar-two-splittings-p", paper="adv", kind="id", sizes=R32)
def two_splittings_p(s):
    """False: the top r x r block of P skew, read the same way (JB; true at the equivariant chart's point)."""
    M = _top(s, s.P)
    return {"M + M^T": M + M.T}


@claim("adv-s40-eigenvalue-two-splittings-sym", paper="adv", kind="id", sizes=R32)
def eigenvalue_two_splittings(s):
    """False: a₁ X1ᵀ symmetric through blocks a₁·I_r, a₁·0 (an eigenvalue of A is a number of an engine value's
    sides as well; JB)."""
    c = s.a[0]
    M = block([[s.X], [s.zeros(s.r, s.r)]]).T @ block([[c * s.Ir], [c * s.zeros(s.n, s.r)]])
    return {"M - M^T": M - M.T}


@claim("adv-s40-d-scalar-true", paper="adv", kind="id", sizes=R32)
def d_scalar_true(s):
    """True: c(XᵀX − I_r) = 0 with c = s.d(...), a covariant graph (the chart reduced by O(r) is kept)."""
    c = _c(s)
    return {"c(X^T X - I)": c * (s.X.T @ s.X) - c * s.Ir}


@claim("adv-s40-d-scalar-two-splittings-true", paper="adv", kind="id", sizes=R32)
def two_splittings_true(s):
    """True: the blocks read c X1ᵀ, the same as c times the transposed rows 0..r-1 of I_n times X."""
    return {"cX1^T - cX1^T": _top(s, s.X) - _c(s) * (s.In[0:s.r, :] @ s.X).T}
