"""s72 review: user scalars named like the sizes n, r (attempts S1-S4).  Each is FALSE: a scalar parameter is a free
generic number, not the size."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=3)


@claim("s72-scalar-n", paper="No", kind="id", section="t", sizes=SIZES)
def scalar_n(s):
    """tr(I_n) = c with c = s.scalar("n") (false)."""
    return {"x": s.tr(s.In) - s.scalar("n")}


@claim("s72-scalar-r", paper="No", kind="id", section="t", sizes=SIZES)
def scalar_r(s):
    """tr(XᵀX) = c with c = s.scalar("r") (false)."""
    return {"x": s.tr(s.X.T @ s.X) - s.scalar("r")}


@claim("s72-scalar-n-div", paper="No", kind="id", section="t", sizes=SIZES)
def scalar_n_div(s):
    """tr(I_n)/c = 1 with c = s.scalar("n") (false)."""
    return {"x": s.tr(s.In) / s.scalar("n") - 1}


@claim("s72-scalar-n-matrix", paper="No", kind="id", section="t", sizes=SIZES)
def scalar_n_matrix(s):
    """c·X = tr(I_n)·X with c = s.scalar("n") (false)."""
    return {"x": s.scalar("n") * s.X - s.tr(s.In) * s.X}
