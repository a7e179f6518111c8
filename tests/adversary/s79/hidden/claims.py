# ruff: noqa
"""s79 hidden round: 10 statements of Fedorov & Jovanović (Appendix 1, §5, §7, Introduction) that neither the
catalog nor the earlier rounds state (true; numpy check in indep.py.in).  Run with
    stiefelsym verify --claims tests/adversary/s79/hidden/claims.py --method M --jobs 1 --timeout 120
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym import twisted
from stiefelsym.systems import derivative

from _h79_helpers import (L_reduced, monopole, quartic_potential, F_Omega, H_neum, H_neum_k, col, cross, dim_V, dot, euler_ss_point, euler_ss_tangent,
                          flow_No, jacobian_along, pcol, perelomov_functions, tangent_spanning_set, yang_mills_field)

SPHERE = admissible(n_max=5, n_min=2, r_max=1,
                    condition="r = 1: the scene's X is the unit vector e of S^{n-1}; (Omega, e) a generic point of so(n) x S^{n-1}")
ALL = admissible(n_max=5)
R2 = admissible(n_max=5, n_min=2, r_min=2, r_max=2, condition="r = 2")
N3R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, stated_n_max=3, condition="n = 3, r = 2")
DIM = admissible(n_max=5)


# 1 ------------------------------------------------------------------------------------------------------------
@claim("h79-ym-field-isospectral", paper=("YM", "Euler**", "mag6", "OD"), kind="id", sizes=SPHERE,
       statement=r"\dot\Omega=[A,e\otimes e],\ \dot e=\Omega e:\quad \tfrac{d}{dt}F_\Omega=[\Omega,F_\Omega],\ "
                 r"F_\Omega=\Omega-\pr_e(\Omega)")
def ym_field_isospectral(s):
    """Appendix 1, after Proposition YM: on Ψ⁻¹(𝒪_η)/SO(n−1) the Yang–Mills field F_Ω ranges over the orbit 𝒪_η.
    In the reduced variables (Ω, e) ∈ so(n) × S^{n−1} (mag0), along (Euler**) Ω̇ = [A, e⊗e], ė = Ωe, the field
    F_Ω = pr_{e⊥}(Ω) moves by conjugation, Ḟ_Ω = [Ω, F_Ω] (by hand: pr_{e⊥}[A, e⊗e] = 0, and
    −ΩṄ − ṄΩ = NΩ² − Ω²N = [Ω, F_Ω] for N = e⊗e, NΩN = 0).  Checked at a generic point (Ω, e) of my own."""
    z = euler_ss_point(s)
    v = euler_ss_tangent(s, z)
    dF = derivative(s, lambda t, w: F_Omega(w["Om"], w["e"]), z, v)
    N = s.X @ s.X.T
    return {"dF/dt - [Omega, F]": dF - comm(z["Om"], F_Omega(z["Om"], z["e"])),
            "pr_perp([A, e e^T])": F_Omega(comm(s.A, N), s.X)}


# 2 ------------------------------------------------------------------------------------------------------------
@claim("h79-ym-mag6-reduced", paper=("YM", "mag6", "Euler**", "mag3"), kind="id", sizes=SPHERE,
       statement=r"\dot\Omega=[A,e\otimes e],\ \dot e=\Omega e:\quad \ddot e=Ae-\big((e,Ae)+(\dot e,\dot e)\big)e+F_\Omega\dot e")
def ym_mag6_reduced(s):
    """Proposition YM (ii) from (Euler**) alone, at a generic point (Ω, e) of so(n) × S^{n−1} (not only along
    the rigid body flow): d/dt(Ωe) = Ae − ((e, Ae) + (ė, ė))e + F_Ωė with F_Ω = Ω − pr_e(Ω) (by hand:
    Ω̇e + Ωė = Ae − (e, Ae)e + Ω²e and F_Ωė = Ω²e + |Ωe|²e since eᵀΩe = 0)."""
    z = euler_ss_point(s)
    v = euler_ss_tangent(s, z)
    Om, e = z["Om"], z["e"]
    edot = Om @ e
    edd = derivative(s, lambda t, w: w["Om"] @ w["e"], z, v)
    rhs = s.A @ e - (dot(s, e, s.A @ e) + dot(s, edot, edot)) * e + F_Omega(Om, e) @ edot
    return {"(mag6)": edd - rhs}


# 3 ------------------------------------------------------------------------------------------------------------
@claim("h79-ym-field-conjugation-kappa", paper=("YM", "mag6", "No", "momentum_right_map"), kind="id", sizes=ALL,
       statement=r"F=XX^T\Phi+\Phi XX^T-\Phi\ (=X\Psi X^T):\quad \tfrac{d}{dt}F=[\Phi,F]\ \text{along (No), every }\kappa")
def ym_field_conjugation_kappa(s):
    """Appendix 1 with §5: at r = n − 1 the Yang–Mills field F_Ω = Ω − pr_{e_n}(Ω) (Ω = Φ, e_n⊗e_n = I − XXᵀ) is
    πΦ + Φπ − Φ, π = XXᵀ; along the Neumann flow (No) of H_neum,κ for every κ (derived by the engine as the Dirac
    flow) it moves by conjugation with Φ: Ḟ = [Φ, F] (by hand: F = XΨXᵀ, Ψ̇ = 0, Ẋ = ΦX − 2κXPᵀX and
    X(PᵀXΨ + ΨXᵀP)Xᵀ = 0 since XᵀP = Ψ/2).  Stated for every n, r."""
    flow = s.dirac_flow(H_neum_k)
    F = yang_mills_field(s)
    return {"dF/dt - [Phi, F]": s.d(yang_mills_field, flow) - comm(s.Phi, F),
            "F - X Psi X^T": F - s.X @ s.Psi @ s.X.T}


# 4 ------------------------------------------------------------------------------------------------------------
@claim("h79-mag-force-every-kappa", paper=("mag-euk", "mag-nor", "twisted", "No"), kind="id", sizes=R2,
       statement=r"X^{\omega_\epsilon}_{H_{neum,\kappa}}-X^{\omega}_{H_{neum,\kappa}}=\big(0,-\epsilon(\mathbf I-XX^T)PJ\big),\ J=E_1\wedge E_2")
def mag_force_every_kappa(s):
    """Appendix 1, (mag-euk) and (mag-nor): the ε-terms of both printed magnetic flows are the same matrix
    −ε(I − XXᵀ)PJ, J = E₁∧E₂ (columns εp₂ − ε(e₁,p₂)e₁, −εp₁ + ε(e₂,p₁)e₂; for (mag-nor) use
    (I − XXᵀ)Φ₀X = (I − XXᵀ)P), and so for every κ: the twisted flow of H_neum,κ is (No) plus (0, −ε(I − XXᵀ)PJ).
    At n = 2 (I − XXᵀ = 0) the magnetic field exerts no force at all."""
    flow = twisted.flow(s, H_neum_k)
    plain = flow_No(s, s.kappa)
    J = twisted.magnetic_matrix(s)
    force = -s.eps * ((s.In - s.X @ s.X.T) @ s.P @ J)
    return {"dX/dt": flow.Xdot - plain["X"], "dP/dt": flow.Pdot - (plain["P"] + force)}


# 5 ------------------------------------------------------------------------------------------------------------






@claim("h79-mag-grass-monopole-n3", paper=("neum-gras-mag", "mag-euk", "iden2", "YM"), kind="id", sizes=N3R2,
       equivariance="e_3 = e_1 x e_2 is read from coordinates; (g a) x (g b) = det(g) g (a x b) for g in O(3)",
       statement=r"n=3:\ e_3=e_1\times e_2,\ \ddot e_3=Ae_3-\big((e_3,Ae_3)+(\dot e_3,\dot e_3)\big)e_3-\epsilon\,e_3\times\dot e_3\ "
                 r"\text{along (mag-euk) on }\Psi^{-1}(0)")
def mag_grass_monopole_n3(s):
    """Appendix 1: Ψ⁻¹((η_so(2), 0))/SO(2) × SO(n−2) is the magnetic T*G_{n,2}; at n = 3, under (iden2)
    e₁∧e₂ ↦ e₃ = e₁ × e₂, the magnetic Neumann system (neum-gras-mag) (the reduction of (mag-euk) on Ψ⁻¹(0)) is the
    motion of a charge on S² in the monopole field, with charge −ε for the twisted form ω + ε de₁∧de₂ (numpy, with
    the printed (mag-euk) flow: residual 3e-15 with −ε, 2.1 with +ε)."""
    return monopole(s, -1)




# 8 ------------------------------------------------------------------------------------------------------------
@claim("h79-perelomov-cayley-hamilton", paper=("perelomov", "spectral-curve"), kind="id", sizes=ALL,
       statement=r"e_{n+1}\big(\mathcal L_{neum}(\lambda)\big)=0:\ \tr\mathcal L^{n+1}\ \text{is a polynomial in}\ \tr\mathcal L^k,\ k\le n")
def perelomov_cayley_hamilton(s):
    """§5, (perelomov): 'k = 1, …, n' suffices: by Newton's identities the power sums tr 𝓛(λ)^k, k ≤ n + 1, of the
    n × n matrix 𝓛_neum(λ) = λΦ + XXᵀ − λ²A give e_{n+1} = 0 (Cayley–Hamilton), so tr 𝓛^{n+1} adds nothing."""
    n = int(s.n)
    L = s.lam * s.Phi + s.X @ s.X.T - s.lam * s.lam * s.A
    return {"e_{n+1}(L)": elementary(s, L, n + 1)[n + 1]}


# 9 ------------------------------------------------------------------------------------------------------------


@claim("h79-ym-reduced-integrals", paper=("YM", "Euler**", "perelomov", "mag0"), kind="pb", sizes=SPHERE,
       statement=r"\tfrac{d}{dt}\tr(\lambda\Omega+\mathbf I-e\otimes e-\lambda^2A)^k=0\ \text{along (Euler**)},\ k=2,3")
def ym_reduced_integrals(s):
    """Appendix 1, Theorem (the Neumann system perturbed by the Yang–Mills field is integrable): the integrals
    (perelomov) in the reduced variables of (mag0), tr(λΩ + I − e⊗e − λ²A)^k, are conserved by (Euler**) at a
    generic point (Ω, e) of so(n) × S^{n−1} (Lax form: d/dt 𝓛 = [Ω − λA, 𝓛])."""
    z = euler_ss_point(s)
    v = euler_ss_tangent(s, z)
    out = {}
    for k in (2, 3):
        def f(t, w, k=k):
            L = L_reduced(t, w)
            M = L
            for _ in range(k - 1):
                M = M @ L
            return t.tr(M)
        out[f"d/dt tr L^{k}"] = derivative(s, f, z, v)
    return out


# 10 -----------------------------------------------------------------------------------------------------------


@claim("h79-quartic-potential-duality", paper=("quartic", "iden2", "grassmannian"), kind="id", sizes=ALL,
       statement=r"\tr(X^TA^2X)-\tr(X^TAXX^TAX)=\tr(NA^2)-\tr(NANA),\ N=\mathbf I-XX^T;\ r=n-1:\ =(e_n,A^2e_n)-(e_n,Ae_n)^2")
def quartic_potential_duality(s):
    """§7, (quartic) with (iden2): the quartic potential tr(XᵀA²X) − tr(XᵀAXXᵀAX) is unchanged by the duality
    π = XXᵀ ↦ I − π of G_{n,r} and G_{n,n−r}; at r = n − 1 (e_n⊗e_n = I − XXᵀ) it is the sphere's potential
    Σaᵢ²eᵢ² − (Σaᵢeᵢ²)² of the printed r = 1 case, in e_n (by hand: expand tr((I−π)A(I−π)A))."""
    pi = s.X @ s.X.T
    N = s.In - pi
    return {"V(pi) - V(I - pi)": quartic_potential(s, pi) - quartic_potential(s, N)}
