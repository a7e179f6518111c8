"""Round 5: the double Neumann system's generic point (s.DX, s.DY, s.DXdot, s.DYdot) read next to the scene's
own point (X, P).

The dimension-free scene has DX, DY, DẊ, DẎ as letters of their own with (D0) DXᵀDY = I_r only (guide:
"four letters with (D0)"); the coordinate scenes built DX = X₀DU on X₀ = s.X, the scene's own point, so
every fixed-size method saw DX in the column space of X, and a flow of (X, P) moved DX."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=4)


@claim("adv-s35-dx-in-the-span-of-x", kind="id", sizes=SIZES)
def dx_in_the_span_of_x(s):
    """False for r < n: X Xᵀ DX = DX (DX is a generic rank-r matrix, independent of X)."""
    return {"r": s.X @ s.X.T @ s.DX - s.DX}


@claim("adv-s35-dx-dy-against-x", kind="id", sizes=SIZES)
def dx_dy_against_x(s):
    """False for r < n: (XᵀDX)(DYᵀX) = I_r."""
    return {"r": (s.X.T @ s.DX) @ (s.DY.T @ s.X) - s.Ir}


@claim("adv-s35-dx-against-p", kind="id", sizes=SIZES)
def dx_against_p(s):
    """False: (I − XXᵀ)DX is orthogonal to P, tr(Pᵀ(I − XXᵀ)DX) = 0."""
    return {"r": s.tr(s.P.T @ (s.In - s.X @ s.X.T) @ s.DX)}


@claim("adv-s35-dx-not-moved-by-x", kind="id", sizes=SIZES)
def dx_not_moved_by_a_flow_of_x(s):
    """True: DX is a point of its own, a flow of (X, P) does not move it (dDX/dt = 0 along X' = P, P' = −X)."""
    return {"d": s.d(lambda t: t.DX, {"X": s.P, "P": -s.X})}


@claim("adv-s35-dx-in-the-span-of-y", kind="id", sizes=SIZES)
def dx_in_the_span_of_y(s):
    """False for r < n (control, the second point): Y Yᵀ DX = DX."""
    return {"r": s.Y @ s.Y.T @ s.DX - s.DX}


@claim("adv-s35-scalar-named-like-d", kind="id", sizes=SIZES)
def scalar_named_like_the_double_points(s):
    """False: for a free scalar ν of the claim's own, named double_d1, tr(DXᵀDX) = ν² at r = 1."""
    nu = s.scalar("double_d1")
    return {"r": s.tr(s.DX.T @ s.DX) - nu * nu}


@claim("adv-s35-params-named-like-v", kind="id", sizes=SIZES)
def params_named_like_the_double_points(s):
    """False: for a generic n×r matrix G of the claim's own, named double_V, DẊ = G."""
    return {"r": s.DXdot - s.general_params("double_V", s.n, s.r, ("n", "r"))}
