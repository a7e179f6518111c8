# ruff: noqa
"""Tricks through the claim API: numbers in disguise, constants at float's edges, the complex structure,
λ and the second point.  Truth (numpy): see ../truth_tricks.py."""
from decimal import Decimal
from fractions import Fraction

import numpy as np

from stiefelsym import Rank, admissible, block, claim

SZ = admissible(n_max=3)


def J(s, m, space):
    I = s.identity(m, space.split("+")[0])
    Z = s.zeros(m, m, (space.split("+")[0], space.split("+")[0]))
    return block([[Z, -I], [I, Z]])


@claim("k-cplx-j", kind="id", sizes=SZ)
def cplx_j(s):
    """A realified Z commutes with the complex structure: Z J_r = J_n Z."""
    return {"r": s.Zc @ J(s, s.r, "r+r") - J(s, s.n, "n+n") @ s.Zc}


@claim("k-cplx-j-false", kind="id", sizes=SZ)
def cplx_j_false(s):
    """Z J_r = −J_n Z (false)."""
    return {"r": s.Zc @ J(s, s.r, "r+r") + J(s, s.n, "n+n") @ s.Zc}


@claim("k-cplx-jt", kind="id", sizes=SZ)
def cplx_jt(s):
    """V J_r = J_n V for the tangent vector too, and ZᵀJ_n Z is skew."""
    V = s.Zc_dot
    M = s.Zc.T @ J(s, s.n, "n+n") @ s.Zc
    return {"v": V @ J(s, s.r, "r+r") - J(s, s.n, "n+n") @ V, "skew": M + M.T}


@claim("k-cplx-jt-false", kind="id", sizes=SZ)
def cplx_jt_false(s):
    """ZᵀJ_n Z is symmetric (false)."""
    M = s.Zc.T @ J(s, s.n, "n+n") @ s.Zc
    return {"sym": M - M.T}


@claim("k-tiny", kind="id", sizes=SZ)
def tiny(s):
    """(1 + 10⁻⁴⁰⁰)X = X (false)."""
    c = Fraction(10**400 + 1, 10**400)
    return {"r": c * s.X - s.X}


@claim("k-tiny-lam", kind="id", sizes=SZ)
def tiny_lam(s):
    """R(λ + 10⁻⁴⁰⁰) = R(λ) (false)."""
    return {"r": s.resolvent(s.lam + Fraction(1, 10**400)) - s.resolvent(s.lam)}


@claim("k-huge-cancel", kind="id", sizes=SZ)
def huge_cancel(s):
    """(10⁴⁰⁰ + 1)X − 10⁴⁰⁰X = X (true)."""
    return {"r": (10**400 + 1) * s.X - 10**400 * s.X - s.X}


@claim("k-huge-cancel-false", kind="id", sizes=SZ)
def huge_cancel_false(s):
    """(10⁴⁰⁰ + 1)(X + P) − 10⁴⁰⁰(X + P) = X (false: P is left)."""
    return {"r": (10**400 + 1) * (s.X + s.P) - 10**400 * (s.X + s.P) - s.X}


@claim("k-pow", kind="id", sizes=SZ)
def pow_tiny(s):
    """tr(XᵀX)·(1/2)^2000 = r·(1/2)^2000 (true) and (the false one) with the exponent 2001."""
    c = s.q(1, 2)
    t = s.q(1)
    for _ in range(2000):
        t = t * c
    return {"r": s.tr(s.X.T @ s.X) * t - s.tr(s.Ir) * t}


@claim("k-pow-false", kind="id", sizes=SZ)
def pow_tiny_false(s):
    """tr(XᵀX)·(1/2)^2000 = (r + 1)·(1/2)^2000 (false)."""
    c = s.q(1, 2)
    t = s.q(1)
    for _ in range(2000):
        t = t * c
    return {"r": s.tr(s.X.T @ s.X) * t - (s.tr(s.Ir) + 1) * t}


@claim("k-np-int", kind="id", sizes=SZ)
def np_int(s):
    """np.int64(2)·X − X − X = 0 (true, if numpy ints are ints)."""
    return {"r": np.int64(2) * s.X - s.X - s.X}


@claim("k-np-int-r", kind="id", sizes=SZ)
def np_int_r(s):
    """X·np.int64(2) − 2X = 0 (true)."""
    return {"r": s.X * np.int64(2) - 2 * s.X}


@claim("k-np-float", kind="id", sizes=SZ)
def np_float(s):
    """np.float64(0.5)·X·2 = X."""
    return {"r": np.float64(0.5) * s.X * 2 - s.X}


@claim("k-np-0d", kind="id", sizes=SZ)
def np_0d(s):
    """np.array(3)·X − 3X = 0."""
    return {"r": np.array(3) * s.X - 3 * s.X}


@claim("k-decimal", kind="id", sizes=SZ)
def decimal_(s):
    """Decimal('0.5')·X·2 = X."""
    return {"r": s.X * Decimal("0.5") * 2 - s.X}


@claim("k-bool", kind="id", sizes=SZ)
def bool_(s):
    """True·X = X (a bool as the number 1)."""
    return {"r": True * s.X - s.X}


@claim("k-complex1", kind="id", sizes=SZ)
def complex1(s):
    """complex(1, 0)·X = X."""
    return {"r": complex(1, 0) * s.X - s.X}


@claim("k-npint-index", kind="id", sizes=admissible(n_max=3, n_min=2))
def npint_index(s):
    """X[np.int64(1), 0] − X[1, 0] = 0 (true)."""
    return {"r": s.X[np.int64(1), np.int64(0)] - s.X[1, 0]}


@claim("k-float-index", kind="id", sizes=admissible(n_max=3, n_min=2))
def float_index(s):
    """X[1.0, 0] − X[1, 0] = 0."""
    return {"r": s.X[1.0, 0] - s.X[1, 0]}


@claim("k-rank-np", kind="dim", sizes=SZ)
def rank_np(s):
    """rank XᵀX = r, the rank given as np.int64."""
    return {"rank": Rank(s.X.T @ s.X, np.int64(int(s.r)))}


@claim("k-mat-npint", kind="id", sizes=SZ)
def mat_npint(s):
    """A 1×1 matrix of np.int64(1) minus tr(XᵀX)/r... : [[1]] − [[XᵀX]₁₁] = 0 (true)."""
    M = s.mat([[np.int64(1)]], ("?", "?"))
    G = s.X.T @ s.X
    return {"r": M - s.mat([[G[0, 0]]], ("?", "?"))}


@claim("k-lam-y", kind="id", sizes=SZ)
def lam_y(s):
    """tr(Yᵀ R(λ) (λI − A) Y) = r (true)."""
    return {"r": s.tr(s.Y.T @ s.resolvent(s.lam) @ (s.lam * s.In - s.A) @ s.Y) - s.tr(s.Ir)}


@claim("k-lam-y-false", kind="id", sizes=SZ)
def lam_y_false(s):
    """tr(Yᵀ R(λ) (λI − A) X) = r (false: X for Y)."""
    return {"r": s.tr(s.Y.T @ s.resolvent(s.lam) @ (s.lam * s.In - s.A) @ s.X) - s.tr(s.Ir)}


@claim("k-lam-sub", kind="id", sizes=SZ)
def lam_sub(s):
    """R(λ)A − AR(λ) = 0 (true: A diagonal)."""
    R = s.resolvent(s.lam)
    return {"r": R @ s.A - s.A @ R}


@claim("k-lam-sub-false", kind="id", sizes=SZ)
def lam_sub_false(s):
    """R(λ)XXᵀ − XXᵀR(λ) = 0 (false where r < n)."""
    R = s.resolvent(s.lam)
    return {"r": R @ s.X @ s.X.T - s.X @ s.X.T @ R}
