"""h81 probes, third set: the derivative of the (+) Lie–Poisson field along (dot_XP2) alone (no flow of a tangent
scene), for the dimension-free method; with its twin."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm
from stiefelsym.brackets import SO_N, lie_poisson, quadratic, trace_power

from _h81_helpers import Phi


def hA():
    return quadratic(lambda t, x: t.sym_operator("AA")(x))


@claim("p81-sharp-derivative", paper=("dot_XP2", "Euler-so(n)"), kind="id", sizes=admissible(n_max=4))
def sharp_derivative(s):
    """d/dt of the (+) Lie–Poisson field [𝔸Φ, Φ] along (dot_XP2) is [𝔸Φ̇, Φ] + [𝔸Φ, Φ̇], Φ̇ = [𝔸Φ, Φ]; and
    d/dt ∇g(Φ) for g = tr(x + λA)³ is −6(Φ̇M + MΦ̇), M = Φ + λA."""
    h = hA()
    AA = s.sym_operator("AA")
    T = lie_poisson(SO_N, 1)
    flow = s.dirac_flow(h.pullback(Phi))
    Pd = comm(AA(s.Phi), s.Phi)
    g = trace_power(3, shift=lambda t: t.lam * t.A)
    M = s.Phi + s.lam * s.A
    return {"d sharp - rhs": s.d(lambda t: T.sharp(t, t.Phi, h.grad(t, t.Phi)), flow)
            - (comm(AA(Pd), s.Phi) + comm(AA(s.Phi), Pd)),
            "d grad g(Phi)": s.d(lambda t: g.grad(t, t.Phi), flow) + 6 * (Pd @ M + M @ Pd)}


@claim("q81-sharp-derivative", kind="id", sizes=admissible(n_max=4, n_min=3))
def sharp_derivative_twin(s):
    """Twin: −6(Φ̇M − MΦ̇) (a sign inside)."""
    h = hA()
    AA = s.sym_operator("AA")
    T = lie_poisson(SO_N, 1)
    flow = s.dirac_flow(h.pullback(Phi))
    Pd = comm(AA(s.Phi), s.Phi)
    g = trace_power(3, shift=lambda t: t.lam * t.A)
    M = s.Phi + s.lam * s.A
    return {"d sharp - rhs": s.d(lambda t: T.sharp(t, t.Phi, h.grad(t, t.Phi)), flow)
            - (comm(AA(Pd), s.Phi) + comm(AA(s.Phi), Pd)),
            "d grad g(Phi)": s.d(lambda t: g.grad(t, t.Phi), flow) + 6 * (Pd @ M - M @ Pd)}
