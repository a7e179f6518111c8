"""Batch 6: the complex Neumann Lagrangian (W-Lag) times a number c that depends on the size.

For c != 0 the Euler-Lagrange accelerations are (W-eq): Z'' = -AZ + Z Lam, Lam = conj(Z)^T A Z - conj(Z')^T Z'
(the catalog's complex-neumann-flow, c = 1).  For c = 0 the Lagrangian is 0: no acceleration is determined.

  b6-cx-c1         c = 1                       TRUE (control)
  b6-cx-n-minus-r  c = n - r                   degenerate at r = n (W(n, n) = U(n))
  b6-cx-false      c = n - r, Lam with the sign of its kinetic part flipped   FALSE at r < n
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import (complex_coordinates, complex_point, ctranspose, euler_lagrange, hermitian_entries,
                                re_trace, realify_real)

SZ = admissible(n_max=3)


def _T(c_of):
    def T(t, v):
        Zd = v["Z"]
        return t.q(1, 2) * re_trace(t, ctranspose(t, Zd) @ t.conj(Zd)) * c_of(t)
    return T


def _U(c_of):
    def U(t, q):
        Z = q["Z"]
        return t.q(1, 2) * re_trace(t, ctranspose(t, Z) @ realify_real(t, t.A) @ t.conj(Z)) * c_of(t)
    return U


def W0(t, q):
    Z = q["Z"]
    return hermitian_entries(ctranspose(t, t.conj(Z)) @ Z - realify_real(t, t.Ir))


def _run(s, c_of, sign=1):
    z = complex_point(s)
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(s, s.A)
    Lam = ctranspose(s, s.conj(Z)) @ A @ Z - ctranspose(s, s.conj(Zd)) @ Zd * sign
    acc, _ = euler_lagrange(s, _T(c_of), _U(c_of), W0, {"Z": Z}, {"Z": Zd}, complex_coordinates(s, ["Z"]))
    return {"Z''": acc["Z"] - (-(A @ Z) + Z @ Lam)}


@claim("b6-cx-c1", kind="id", sizes=SZ)
def cx_c1(s):
    return _run(s, lambda t: t.q(1))


@claim("b6-cx-n-minus-r", kind="id", sizes=SZ)
def cx_n_minus_r(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir))


@claim("b6-cx-false", kind="id", sizes=SZ)
def cx_false(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir), sign=-1)
