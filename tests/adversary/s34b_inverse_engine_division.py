"""Round 4b: an Inverse whose op divides inside an engine step: the multipliers of a constrained
Hamiltonian flow (`systems.hamiltonian_flow`) solve C μ = b with the claim's own constraints, whose
bracket matrix C may be singular at some point of T*V.  The claim is false: op is not defined at P = 0."""
from stiefelsym import Inverse, admissible, claim
from stiefelsym.systems import hamiltonian_flow

R2 = admissible(n_max=3, r_min=2, r_max=2)


def _mu2(t):
    """μ₂ = r/tr(PᵀP) = 2/tr(PᵀP) at r = 2: the flow of H = tr(XᵀX)/2 with the constraints
    F₁ = tr(XᵀP), F₂ = tr(PᵀP)/2, whose bracket {F₁, F₂} = tr(PᵀP) vanishes at P = 0."""
    def H(u, z):
        return u.tr(z["X"].T @ z["X"]) / 2

    def constraints(u, z):
        return [u.tr(z["X"].T @ z["P"]), u.tr(z["P"].T @ z["P"]) / 2]
    _flow, mu = hamiltonian_flow(t, H, constraints, {"X": t.X, "P": t.P}, [("X", "P")])
    return mu[1]


@claim("adv-s34b-inv-engine-division", kind="id", sizes=R2)
def multiplier_times(s):
    """x ↦ μ₂ x on Sym(r), inverted by tr(PᵀP) y / 2 (a polynomial): op is not defined at P = 0."""
    return {"inv": Inverse(lambda t, x: _mu2(t) * x, lambda t, y: t.tr(t.P.T @ t.P) * y / 2, on="Sym(r)")}


def _mu2_unscaled(t):
    """μ₂ = r/(2 tr PᵀP) = 1/tr(PᵀP) at r = 2, the constraints F₁ = tr(XᵀP), F₂ = tr(PᵀP)."""
    def H(u, z):
        return u.tr(z["X"].T @ z["X"]) / 2

    def constraints(u, z):
        return [u.tr(z["X"].T @ z["P"]), u.tr(z["P"].T @ z["P"])]
    _flow, mu = hamiltonian_flow(t, H, constraints, {"X": t.X, "P": t.P}, [("X", "P")])
    return mu[1]


@claim("adv-s34b-inv-engine-division-so", kind="id", sizes=R2)
def multiplier_times_on_so(s):
    """ξ ↦ μ₂ ξ on so(n), inverted by tr(PᵀP) η: op is not defined at P = 0."""
    return {"inv": Inverse(lambda t, x: _mu2_unscaled(t) * x, lambda t, y: t.tr(t.P.T @ t.P) * y, on="so(n)")}
