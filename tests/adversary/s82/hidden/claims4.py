"""s82 hidden (h2), statements 17-18 with their twins (V(3, 2), e₃ = e₁ × e₂ from entries).  numpy: indep4.py.in.

17 (App.1: the monopole form of (mag6) at n = 3, r = 2, combined with the twisted form (twisted) and (iden2)):
   along the flow of H_{neum,κ} (κ generic) for ω_ε, e₃ = e₁ × e₂ obeys
       ë₃ = Ae₃ − ((e₃, Ae₃) + (ė₃, ė₃))e₃ − (ε + Ψ₁₂) e₃ × ė₃.
   By hand: e₃ is invariant under the right SO(2) rotation, and the κ-flows differ by such a rotation (catalog:
   the κ = 0 and κ = −½ flows differ by ½(XΨ, PΨ)), so e₃'s motion is κ-independent; at ε = 0, (mag6) with
   F_Ω = XΨXᵀ (catalog ym-charge) = Ψ₁₂ e₁∧e₂ and (e₁∧e₂)w = e₁(e₂·w) − e₂(e₁·w) = −e₃ × w gives the charge −Ψ₁₂;
   the magnetic form adds ε to the level of Ψ₁₂ (numpy fits the charge as −1.000·ε − 1.000·Ψ₁₂ at 6 random points,
   residual 1e-6, seeds 0 and 7).  Twin: −(ε − Ψ₁₂).
18 (§7 (neum-gras**) at G_{3,2} ≅ S², every κ): at (X, P̃) ∈ Ψ⁻¹(0), along the Dirac flow of H_{neum,κ} computed at
   that point (and differentiated again along itself), ë₃ = Ae₃ − ((e₃, Ae₃) + (ė₃, ė₃))e₃ (17 at ε = Ψ₁₂ = 0,
   untwisted).  Twin: at (X, P) (Ψ₁₂ ≠ 0: the charge term is missing).
"""
from stiefelsym import claim, twisted
from stiefelsym.systems import derivative, stiefel_pairs_flow

from _h82_helpers import H_kappa, H_kappa_at, psi12


def cross(t, X):
    a = [X[i, 0] for i in range(3)]
    b = [X[i, 1] for i in range(3)]
    return t.mat([[a[1] * b[2] - a[2] * b[1]], [a[2] * b[0] - a[0] * b[2]], [a[0] * b[1] - a[1] * b[0]]], ("n", "?"))


def cross_vec(t, u, w):
    a = [u[i, 0] for i in range(3)]
    b = [w[i, 0] for i in range(3)]
    return t.mat([[a[1] * b[2] - a[2] * b[1]], [a[2] * b[0] - a[0] * b[2]], [a[0] * b[1] - a[1] * b[0]]], ("n", "?"))


def _monopole(s, sign):
    flow = twisted.flow(s, H_kappa)
    e3 = cross(s, s.X)
    e3d = s.d(lambda t: cross(t, t.X), flow)
    e3dd = s.d(lambda t: t.d(lambda u: cross(u, u.X), twisted.flow(t, H_kappa)), flow)
    A = s.A
    q = s.eps + sign * psi12(s)
    return {"e3'' - monopole": e3dd - (A @ e3 - e3 @ (e3.T @ A @ e3 + e3d.T @ e3d)) + q * cross_vec(s, e3, e3d)}


@claim("h82-monopole-charge", paper=("YM", "mag6", "twisted", "iden2", "mag-euk", "mag-nor"), kind="id",
       sizes=[(3, 2)])
def monopole_charge(s):
    """V(3, 2), ω_ε, H_{neum,κ}: ë₃ = Ae₃ − ((e₃,Ae₃) + (ė₃,ė₃))e₃ − (ε + Ψ₁₂) e₃ × ė₃."""
    return _monopole(s, 1)


@claim("n82-monopole-charge", paper=("YM", "mag6", "twisted", "iden2"), kind="id", sizes=[(3, 2)],
       fails_at=lambda n, r: True, erratum="twin: -(eps - Psi12)")
def monopole_charge_twin(s):
    """Twin: charge −(ε − Ψ₁₂)."""
    return _monopole(s, -1)


def _g32_kappa(s, project):
    X = s.X
    z = {"X": X, "P": (s.In - X @ X.T) @ s.P if project else s.P}
    pairs = [("X", "P")]
    fl = lambda t, w: stiefel_pairs_flow(t, H_kappa_at, w, pairs)
    e3 = cross(s, X)
    e3d = derivative(s, lambda t, w: cross(t, w["X"]), z, fl(s, z))
    e3dd = derivative(s, lambda t, w: derivative(t, lambda u, y: cross(u, y["X"]), w, fl(t, w)), z, fl(s, z))
    A = s.A
    return {"e3'' - (neum-gras**)": e3dd - (A @ e3 - e3 @ (e3.T @ A @ e3 + e3d.T @ e3d))}


@claim("h82-g32-sphere-kappa-flow", paper=("iden2", "neum-gras**", "grassmannian", "neumann"), kind="id",
       sizes=[(3, 2)])
def g32_sphere_kappa_flow(s):
    """At (X, (I − XXᵀ)P), along the κ-flow (nested), e₃ = e₁ × e₂ moves by the Neumann system on S²."""
    return _g32_kappa(s, True)


@claim("n82-g32-sphere-kappa-flow", paper=("iden2", "neum-gras**"), kind="id", sizes=[(3, 2)],
       fails_at=lambda n, r: True, erratum="twin: at (X, P)")
def g32_sphere_kappa_flow_twin(s):
    """Twin: at (X, P)."""
    return _g32_kappa(s, False)
