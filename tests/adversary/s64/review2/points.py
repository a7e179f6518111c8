# ruff: noqa
"""The second point (Y, Q) and the complex point (Z, Ż) (q64): true statements and false twins that would
pass if a chart drew Y, Q, Z or Ż less generic than T*V (vertical tangent vectors only, Y tied to X, Z real)."""
from stiefelsym import admissible, claim

ANY = admissible(n_max=4)
BELOW = admissible(n_max=4, n_min=2, where=lambda n, r: r < n, condition="r < n")



# ---- the second point
@claim("q64-q-tangent-true", kind="id", sizes=ANY)
def q_tangent_true(s):
    """YᵀQ + QᵀY = 0 (true)."""
    return {"YtQ": s.Y.T @ s.Q + s.Q.T @ s.Y}


@claim("q64-q-horizontal-false", kind="id", sizes=BELOW)
def q_horizontal_false(s):
    """(I − YYᵀ)Q = 0 at r < n (false: Q has a normal component)."""
    return {"normal Q": s.Q - s.Y @ (s.Y.T @ s.Q)}


@claim("q64-q-vertical-false", kind="id", sizes=ANY)
def q_vertical_false(s):
    """YᵀQ = 0 (false: YᵀQ is a generic skew matrix, 0 at r = 1 only)."""
    return {"YtQ": s.Y.T @ s.Q}


@claim("q64-xy-false", kind="id", sizes=ANY)
def xy_false(s):
    """tr(XᵀY)² = tr((XᵀY)²)... at r = 1 true; XᵀY symmetric (false for r >= 2, and at r = 1 true)."""
    M = s.X.T @ s.Y
    return {"XtY sym": M - M.T}


@claim("q64-xy-qp-false", kind="id", sizes=ANY)
def xy_qp_false(s):
    """tr(XᵀQ) + tr(YᵀP) = 0 (false)."""
    return {"tr": s.tr(s.X.T @ s.Q) + s.tr(s.Y.T @ s.P)}


# ---- the complex point
@claim("q64-z-unitary-true", kind="id", sizes=ANY)
def z_unitary_true(s):
    """ZᵀZ = I_{2r} for the realified Z (true: Z̄ᵀZ = I_r)."""
    Z = s.Zc
    return {"ZtZ": Z.T @ Z - s.realify(s.Ir, 0 * s.Ir)}


@claim("q64-z-tangent-true", kind="id", sizes=ANY)
def z_tangent_true(s):
    """ZᵀŻ + ŻᵀZ = 0, realified (true)."""
    Z, Zd = s.Zc, s.Zc_dot
    return {"tangent": Z.T @ Zd + Zd.T @ Z}


@claim("q64-z-horizontal-false", kind="id", sizes=BELOW)
def z_horizontal_false(s):
    """(I − ZZ̄ᵀ)Ż = 0 at r < n (false)."""
    Z, Zd = s.Zc, s.Zc_dot
    return {"normal Zdot": Zd - Z @ (Z.T @ Zd)}


@claim("q64-z-complex-linear-true", kind="id", sizes=ANY)
def z_complex_linear_true(s):
    """The realified Z̄ᵀŻ commutes with the realified i I_r (true: every realified complex matrix does)."""
    Z, Zd = s.Zc, s.Zc_dot
    M = Z.T @ Zd                    # realified Z̄ᵀŻ: [[Re, −Im], [Im, Re]]
    Jr = s.realify(0 * s.Ir, s.Ir)  # i I_r
    return {"Im": M @ Jr - Jr @ M + 0 * (M - M)}


@claim("q64-z-imtrace-false", kind="id", sizes=ANY)
def z_imtrace_false(s):
    """Im tr(Z̄ᵀŻ) = 0 (false: tr of a skew-Hermitian matrix is imaginary, not 0)."""
    Z, Zd = s.Zc, s.Zc_dot
    Jr = s.realify(0 * s.Ir, s.Ir)
    return {"Im tr": s.tr(Jr.T @ Z.T @ Zd)}


@claim("q64-z-square-false", kind="id", sizes=BELOW)
def z_square_false(s):
    """ZZ̄ᵀ = I_n at r < n (false; true at r = n)."""
    Z = s.Zc
    return {"ZZt": Z @ Z.T - s.realify(s.In, 0 * s.In)}


@claim("q64-z-square-true", kind="id", sizes=admissible(n_max=3, r_is_n=True))
def z_square_true(s):
    """ZZ̄ᵀ = I_n at r = n (true)."""
    Z = s.Zc
    return {"ZZt": Z @ Z.T - s.realify(s.In, 0 * s.In)}


@claim("q64-z-real-false", kind="id", sizes=ANY)
def z_real_false(s):
    """Z̄ᵀŻ is real: M = conj(M) (false: Z̄ᵀŻ is a generic skew-Hermitian matrix, whose imaginary part is a
    generic symmetric matrix)."""
    Z, Zd = s.Zc, s.Zc_dot
    M = Z.T @ Zd
    return {"Im": M - s.conj(M)}
