"""The realified complex point Z = U + iV of W(n, r), read through slices of its 2n x 2r form
[[U, -V], [V, U]].  The reduced unitary Cayley chart puts Z = I at r = n (U = I, V = 0) and S11 = 0 below.
Docstrings state the truth."""
from stiefelsym import admissible, claim

ALL = admissible(n_max=3)
SQ = admissible(n_max=3, where=lambda n, r: r == n, condition="r = n")


def UV(s):
    n, r = int(s.n), int(s.r)
    Z = s.Zc
    return Z[0:n, 0:r], Z[n:2 * n, 0:r]


@claim("s75-cx-unitary-true", kind="id", sizes=ALL)
def cx_unitary_true(s):
    """UᵀU + VᵀV = I_r and UᵀV = VᵀU: TRUE (Z*Z = I_r)."""
    U, V = UV(s)
    return {"re": U.T @ U + V.T @ V - s.Ir, "im": U.T @ V - V.T @ U}


@claim("s75-cx-v-zero-square", kind="id", sizes=SQ)
def cx_v_zero_square(s):
    """V = 0 at r = n: FALSE (U(n) is not O(n)); 0 on the reduced chart Z = I."""
    U, V = UV(s)
    return {"w": V}


@claim("s75-cx-v-zero-square-trace", kind="id", sizes=SQ)
def cx_v_zero_square_trace(s):
    """tr(VᵀV) = 0 at r = n: FALSE; 0 at Z = I."""
    U, V = UV(s)
    return {"w": s.tr(V.T @ V)}


@claim("s75-cx-u-sym", kind="id", sizes=admissible(n_max=3, r_min=2))
def cx_u_sym(s):
    """The top r x r block of U symmetric: FALSE."""
    U, V = UV(s)
    r = int(s.r)
    U1 = U[0:r, 0:r]
    return {"w": U1 - U1.T}


@claim("s75-cx-zzt", kind="id", sizes=SQ)
def cx_zzt(s):
    """Z Zᵀ (realified, no conjugation: [[U, -V],[V, U]] times its transpose) = I at r = n: TRUE (Z Z* = I;
    the realified transpose is the realified conjugate transpose)."""
    Z = s.Zc
    n = int(s.n)
    return {"w": Z @ Z.T - s.identity(2 * n, "n+n")}
