"""s82 hidden (h2), statements 14-16 with their twins.  numpy: indep3.py.in.

14 (App.2, the perturbed coupled Hamiltonian H_κ = T_κ + tr XᵀAY − 2κ tr(XᵀP YᵀQ)) every term is invariant under
   the diagonal right SO(r) action (X, P, Y, Q) ↦ (XR, PR, YR, QR) (tr(RᵀXᵀPR RᵀYᵀQR) = tr(XᵀPYᵀQ)), so the
   diagonal momentum XᵀP − PᵀX + YᵀQ − QᵀY is conserved by its Dirac flow for every κ.
   Twin: XᵀP − PᵀX − (YᵀQ − QᵀY) (false r ≥ 2: the anti-diagonal action is no symmetry of tr XᵀAY).
15 (App.1, after Prop. YM: "(F_Ω, e_n, ė_n) ranges over O_η ×_s TS^{n−1}") F_Ω = Ω − ė∧e = πΩπ, π = I − eeᵀ; the
   spectral invariants of F_Ω are Casimirs of the reduced space so(n) × S^{n−1} (catalog ym-charge: XᵀF_ΩX = Ψ),
   hence tr F_Ω², tr F_Ω⁴ are conserved along (Euler**) at every point.  Twin: Ω + ė∧e.
16 (§7 (iden2), (neum-gras**) at G_{3,2} ≅ S²) at (X, P̃) ∈ Ψ⁻¹(0), e₃ = e₁ × e₂ (entries), along (NE_XP):
   ë₃ = Ae₃ − ((e₃, Ae₃) + (ė₃, ė₃))e₃.  Twin: − (ė₃, ė₃) inside the bracket.
"""
from stiefelsym import admissible, claim, comm
from stiefelsym.systems import derivative, stiefel_pairs_flow


# 14 --------------------------------------------------------------------------------------------
def H_pert(t, z):
    XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    c = t.q(1, 2) + t.kappa
    return (t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(XP @ XP) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(YQ @ YQ)
            + t.tr(z["X"].T @ t.A @ z["Y"]) - 2 * t.kappa * t.tr(XP @ YQ))


def _pert(s, sign):
    z = {"X": s.X, "P": s.P, "Y": s.Y, "Q": s.Q}
    f = stiefel_pairs_flow(s, H_pert, z, [("X", "P"), ("Y", "Q")])
    mom = lambda t: t.X.T @ t.P - t.P.T @ t.X + sign * (t.Y.T @ t.Q - t.Q.T @ t.Y)
    return {"d/dt momentum": s.d(mom, f)}


@claim("h82-coupled-perturbed-diagonal-momentum", paper=("C-neumann", "so(n,n)", "C-eq"), kind="pb",
       sizes=admissible(n_max=3))
def coupled_perturbed_diagonal_momentum(s):
    """The diagonal momentum is conserved by the flow of T_κ + tr XᵀAY − 2κ tr(XᵀPYᵀQ)."""
    return _pert(s, 1)


@claim("n82-coupled-perturbed-diagonal-momentum", paper=("C-neumann", "C-eq"), kind="pb",
       sizes=admissible(n_max=3), fails_at=lambda n, r: r >= 2, erratum="twin: anti-diagonal momentum")
def coupled_perturbed_diagonal_momentum_twin(s):
    """Twin: XᵀP − PᵀX − (YᵀQ − QᵀY)."""
    return _pert(s, -1)


# 15 --------------------------------------------------------------------------------------------
R1 = admissible(n_max=5, r_in=(1,), condition="r = 1 (e a unit vector)")


def _euler_ss(t, z):
    e = z["e"]
    return {"Om": comm(t.A, e @ e.T), "e": z["Om"] @ e}


def _charge(s, sign):
    z = {"Om": s.xi, "e": s.X}
    f = _euler_ss(s, z)

    def invariants(t, w):
        e, Om = w["e"], w["Om"]
        ed = Om @ e
        F = Om + sign * (ed @ e.T - e @ ed.T)
        F2 = F @ F
        return [t.tr(F2), t.tr(F2 @ F2)]
    d2, d4 = derivative(s, invariants, z, f)
    return {"d tr F^2/dt": d2, "d tr F^4/dt": d4}


@claim("h82-ym-charge-orbit", paper=("YM", "mag6", "Euler**"), kind="pb", sizes=R1)
def ym_charge_orbit(s):
    """tr F_Ω², tr F_Ω⁴ (F_Ω = Ω − ė∧e, ė = Ωe) are conserved along (Euler**)."""
    return _charge(s, -1)


@claim("n82-ym-charge-orbit", paper=("YM", "mag6", "Euler**"), kind="pb", sizes=R1,
       fails_at=lambda n, r: n >= 2, erratum="twin: Omega + e' wedge e")
def ym_charge_orbit_twin(s):
    """Twin: F = Ω + ė∧e."""
    return _charge(s, 1)


# 16 --------------------------------------------------------------------------------------------
def _cross(t, X):
    a = [X[i, 0] for i in range(3)]
    b = [X[i, 1] for i in range(3)]
    return t.mat([[a[1] * b[2] - a[2] * b[1]], [a[2] * b[0] - a[0] * b[2]], [a[0] * b[1] - a[1] * b[0]]], ("n", "?"))


def _ne_flow(t, w):
    X, P = w["X"], w["P"]
    return {"X": P, "P": -(t.A @ X) + X @ (X.T @ t.A @ X - P.T @ P)}


def _g32(s, sign):
    X = s.X
    z = {"X": X, "P": (s.In - X @ X.T) @ s.P}
    e3 = _cross(s, X)
    e3d = derivative(s, lambda t, w: _cross(t, w["X"]), z, _ne_flow(s, z))
    e3dd = derivative(s, lambda t, w: derivative(t, lambda u, y: _cross(u, y["X"]), w, _ne_flow(t, w)), z,
                      _ne_flow(s, z))
    A = s.A
    return {"e3'' - (neum-gras**)": e3dd - (A @ e3 - e3 @ (e3.T @ A @ e3 + sign * (e3d.T @ e3d)))}


@claim("h82-grassmann-g32-sphere", paper=("iden2", "neum-gras**", "neum-gras", "NE_XP"), kind="id",
       sizes=[(3, 2)])
def grassmann_g32_sphere(s):
    """G_{3,2} ≅ S²: along (NE_XP) at a point of Ψ⁻¹(0), e₃ = e₁ × e₂ moves by the Neumann system on S²."""
    return _g32(s, 1)


@claim("n82-grassmann-g32-sphere", paper=("iden2", "neum-gras**"), kind="id", sizes=[(3, 2)],
       fails_at=lambda n, r: True, erratum="twin: -(e3', e3')")
def grassmann_g32_sphere_twin(s):
    """Twin: ë₃ = Ae₃ − ((e₃, Ae₃) − (ė₃, ė₃))e₃."""
    return _g32(s, -1)
