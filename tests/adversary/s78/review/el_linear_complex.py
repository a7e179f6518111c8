"""The complex Neumann system's Euler–Lagrange solve (systems.euler_lagrange with complex coordinates) with
a null Lagrangian Re tr(GᵀŻ) (G = realify(G₁, G₂), constant) added to T: the acceleration must be that of
(W-eq), Z̈ = −AZ + ZΛ, Λ = Z̄ᵀAZ − Ż̄ᵀŻ.  The free scene's solve has the same shortcut as the double
system's (d/dt ∂T/∂q̇ taken as ∂T/∂q̇ at q̇ ↦ q̈): a nonzero normal form here shows its acceleration is
not the Euler–Lagrange one."""
from stiefelsym import admissible, claim
from stiefelsym.systems import complex_coordinates, complex_point, ctranspose, euler_lagrange, hermitian_entries
from stiefelsym.systems import re_trace, realify_real

SIZES = admissible(n_max=2)


def U_complex(t, q):
    Z = q["Z"]
    return t.q(1, 2) * re_trace(t, ctranspose(t, Z) @ realify_real(t, t.A) @ t.conj(Z))


def W0(t, q):
    Z = q["Z"]
    return hermitian_entries(ctranspose(t, t.conj(Z)) @ Z - realify_real(t, t.Ir))


@claim("s78-el-complex-linear-true", paper="prep", kind="id", sizes=SIZES)
def el_complex_true(s):
    """With T = ½Re tr(ŻᵀŻ̄) + Re tr(GᵀŻ) (a null Lagrangian added), Z̈ = −AZ + ZΛ."""
    G = s.realify(s.generic("G1", "n", "r"), s.generic("G2", "n", "r"))
    z = complex_point(s)

    def T(t, v):
        Zd = v["Z"]
        return t.q(1, 2) * re_trace(t, ctranspose(t, Zd) @ t.conj(Zd)) + re_trace(t, ctranspose(t, G) @ Zd)

    acc, _ = euler_lagrange(s, T, U_complex, W0, {"Z": z["Z"]}, {"Z": z["Zdot"]}, complex_coordinates(s, ["Z"]))
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(s, s.A)
    Lam = ctranspose(s, s.conj(Z)) @ A @ Z - ctranspose(s, s.conj(Zd)) @ Zd
    return {"Zdd": acc["Z"] - (-(A @ Z) + Z @ Lam)}
