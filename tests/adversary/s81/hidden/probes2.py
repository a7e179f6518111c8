"""h81 probes, second set: second derivatives along the submersion flow, through a sharp map and a checked
gradient (the stop's change: checks made at the point, carried along a derivative by dual numbers)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm
from stiefelsym.brackets import SO_N, lie_poisson, quadratic

from _h81_helpers import Phi


def hA():
    return quadratic(lambda t, x: t.sym_operator("AA")(x))


@claim("p81-phi-second-derivative", paper=("dot_XP2", "Euler-so(n)"), kind="id", sizes=admissible(n_max=4))
def phi_second_derivative(s):
    """Along (dot_XP2) Φ̇ = [𝔸Φ, Φ], so Φ̈ = [𝔸Φ̇, Φ] + [𝔸Φ, Φ̇]; the derivative of the (+) Lie–Poisson field
    (its sharp at Φ of ∇h_𝔸(Φ)) along the flow is the same."""
    h = hA()
    AA = s.sym_operator("AA")
    T = lie_poisson(SO_N, 1)
    flow = s.dirac_flow(h.pullback(Phi))
    Pd = comm(AA(s.Phi), s.Phi)
    rhs = comm(AA(Pd), s.Phi) + comm(AA(s.Phi), Pd)
    return {"Phi'' - rhs": s.d(lambda t: t.d(Phi, t.dirac_flow(h.pullback(Phi))), flow) - rhs,
            "d sharp - rhs": s.d(lambda t: T.sharp(t, t.Phi, h.grad(t, t.Phi)), flow) - rhs}


@claim("q81-phi-second-derivative", kind="id", sizes=admissible(n_max=4, n_min=3))
def phi_second_derivative_twin(s):
    """Twin: [Φ, 𝔸Φ] in place of [𝔸Φ, Φ] in Φ̇ (both residuals then false for n >= 3)."""
    h = hA()
    AA = s.sym_operator("AA")
    T = lie_poisson(SO_N, 1)
    flow = s.dirac_flow(h.pullback(Phi))
    Pd = comm(s.Phi, AA(s.Phi))
    rhs = comm(AA(Pd), s.Phi) + comm(AA(s.Phi), Pd)
    return {"Phi'' - rhs": s.d(lambda t: t.d(Phi, t.dirac_flow(h.pullback(Phi))), flow) - rhs,
            "d sharp - rhs": s.d(lambda t: T.sharp(t, t.Phi, h.grad(t, t.Phi)), flow) - rhs}
