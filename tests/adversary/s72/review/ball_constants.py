"""s72 review: the ball method's enclosures of rational constants and cancellations, from n = 32 on where the
float64 midpoint-radius rung is used first (attempts B1-B6).  Truth in each docstring."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=40, r_max=1, n_min=32)


@claim("s72-ball-third", paper="No", kind="id", section="t", sizes=SIZES)
def third(s):
    """(1/3)·(3X) − X = 0 (true)."""
    return {"x": s.q(1, 3) * (3 * s.X) - s.X}


@claim("s72-ball-third-matrix", paper="No", kind="id", section="t", sizes=SIZES)
def third_matrix(s):
    """((1/3)·I)(3·XXᵀ) − XXᵀ = 0 (true; a product of matrices with an inexact constant)."""
    return {"x": (s.q(1, 3) * s.In) @ (3 * s.X @ s.X.T) - s.X @ s.X.T}


@claim("s72-ball-tiny-false", paper="No", kind="id", section="t", sizes=SIZES)
def tiny_false(s):
    """(1 + 10⁻³⁰⁰)·XXᵀ − XXᵀ = 0 (false: 10⁻³⁰⁰ XXᵀ)."""
    c = s.q(10 ** 300 + 1, 10 ** 300)
    return {"x": (c * s.In) @ (s.X @ s.X.T) - s.X @ s.X.T}


@claim("s72-ball-cancel-false", paper="No", kind="id", section="t", sizes=SIZES)
def cancel_false(s):
    """(c·XXᵀ + XXᵀ) − c·XXᵀ − XXᵀ·(1 + 10⁻²⁰) = 0 with c = 10²⁰ (false)."""
    c = s.q(10 ** 20)
    e = s.q(10 ** 20 + 1, 10 ** 20)
    M = s.X @ s.X.T
    return {"x": (c * M + M) - c * M - e * M}


@claim("s72-ball-inverse", paper="No", kind="id", section="t", sizes=SIZES)
def inverse(s):
    """(I + XXᵀ/3)⁻¹(I + XXᵀ/3) = I (true)."""
    M = s.In + s.q(1, 3) * (s.X @ s.X.T)
    return {"x": M.inv() @ M - s.In}


@claim("s72-ball-near-singular", paper="No", kind="id", section="t", sizes=SIZES)
def near_singular(s):
    """(I − (1 − 10⁻¹²)XXᵀ)⁻¹ (I − (1 − 10⁻¹²)XXᵀ) = I (true; condition number 10¹²)."""
    M = s.In - s.q(10 ** 12 - 1, 10 ** 12) * (s.X @ s.X.T)
    return {"x": M.inv() @ M - s.In}
