"""The complex Neumann system's Euler–Lagrange solve (complex_coordinates) with a potential that reads the
velocity (closed over): U = U_(W-Lag) + Re tr(Ż₀*Z), Ż₀ the point's velocity.  L = T − U_(W-Lag) − Re tr(Ż*Z)
and Re tr(Ż*Z) = ½ d/dt tr(Z*Z) is a null Lagrangian: the true accelerations are (W-eq)'s, Z̈ = −AZ + ZΛ.
The constant-coefficient reading gives the force −Ż₀: Z̈ = −AZ + ZΛ − Ż (the multiplier's extra ½(Z*Ż + Ż*Z) is 0
on the tangent bundle)."""
from stiefelsym import claim
from stiefelsym.systems import (complex_coordinates, complex_point, ctranspose, euler_lagrange, hermitian_entries,
                                re_trace, realify_real)

SZ = [(1, 1), (2, 1), (2, 2)]


def T_complex(t, v):
    Zd = v["Z"]
    return t.q(1, 2) * re_trace(t, ctranspose(t, Zd) @ t.conj(Zd))


def W0(t, q):
    Z = q["Z"]
    return hermitian_entries(ctranspose(t, t.conj(Z)) @ Z - realify_real(t, t.Ir))


def _acc(s):
    z = complex_point(s)
    Zd0 = z["Zdot"]

    def U(t, q):
        Z = q["Z"]
        return (t.q(1, 2) * re_trace(t, ctranspose(t, Z) @ realify_real(t, t.A) @ t.conj(Z))
                + re_trace(t, ctranspose(t, t.conj(Zd0)) @ Z))
    acc, _ = euler_lagrange(s, T_complex, U, W0, {"Z": z["Z"]}, {"Z": z["Zdot"]}, complex_coordinates(s, ["Z"]))
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(s, s.A)
    Lam = ctranspose(s, s.conj(Z)) @ A @ Z - ctranspose(s, s.conj(Zd)) @ Zd
    return acc["Z"], -(A @ Z) + Z @ Lam, Zd


@claim("r2-el-cx-Uvel-true", paper="prep", kind="id", sizes=SZ)
def cx_true(s):
    acc, printed, Zd = _acc(s)
    return {"Zdd": acc - printed}


@claim("r2-el-cx-Uvel-false", paper="prep", kind="id", sizes=SZ)
def cx_false(s):
    acc, printed, Zd = _acc(s)
    return {"Zdd": acc - (printed - Zd)}
