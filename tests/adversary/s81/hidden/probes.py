"""h81 probes of the stop's change (derivatives along flows taken through a MatrixFunction's checked gradient,
and a Hamiltonian built from a gradient).  True statements; twins in probes_neg.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm
from stiefelsym.brackets import quadratic, trace_power

from _h81_helpers import H_neum, Phi


def hA():
    return quadratic(lambda t, x: t.sym_operator("AA")(x))


def hT():
    return trace_power(3, shift=lambda t: t.lam * t.A)


@claim("p81-euler-homogeneity-along-flow", paper=("submersion_metric",), kind="id", sizes=admissible(n_max=4))
def euler_homogeneity(s):
    """(submersion_metric) H_𝔸 = ½<𝔸Φ, Φ>: <x, ∇h(x)> = 2h(x) for h_𝔸 and 3h(x) for tr(x + λA)³ − … (not
    homogeneous: checked for h_𝔸 only), differentiated along the Neumann flow (No): d<Φ, ∇h_𝔸(Φ)> = 2 d h_𝔸(Φ)."""
    h = hA()
    flow = s.dirac_flow(H_neum)
    return {"d<Phi, grad h(Phi)> - 2 d h(Phi)":
            s.d(lambda t: t.killing(t.Phi, h.grad(t, t.Phi)), flow) - 2 * s.d(h.pullback(Phi), flow)}


@claim("p81-euler-eq-gradient-derivative", paper=("dot_XP2", "Manakov"), kind="id", sizes=admissible(n_max=4))
def euler_eq_gradient_derivative(s):
    """Along (dot_XP2) Φ̇ = [𝔸Φ, Φ] (Euler equations on so(n)), so d/dt 𝔸(Φ) = 𝔸([𝔸Φ, Φ]), taken through the
    gradient of h_𝔸 (∇h_𝔸 = 𝔸x); and for h = tr(x + λA)³, d/dt ∇h(Φ) = −6(Φ̇M + MΦ̇), M = Φ + λA, along (No)."""
    h = hA()
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(h.pullback(Phi))
    out = {"d grad h_AA(Phi) - AA([AA Phi, Phi])":
           s.d(lambda t: h.grad(t, t.Phi), flow) - AA(comm(AA(s.Phi), s.Phi))}
    g = hT()
    fl2 = s.dirac_flow(H_neum)
    M = s.Phi + s.lam * s.A
    Pd = comm(s.X @ s.X.T, s.A)
    out["d grad tr(Phi+lam A)^3 along (No)"] = s.d(lambda t: g.grad(t, t.Phi), fl2) + 6 * (Pd @ M + M @ Pd)
    return out


@claim("p81-hamiltonian-from-gradient", paper=("submersion_metric", "dot_XP2"), kind="id", sizes=admissible(n_max=4))
def hamiltonian_from_gradient(s):
    """(submersion_metric) written as ½<Φ, ∇h_𝔸(Φ)> (= ½<𝔸Φ, Φ>): its Dirac flow is (dot_XP2) Ẋ = 𝔸(Φ)X,
    Ṗ = 𝔸(Φ)P."""
    h = hA()
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(lambda t: t.killing(t.Phi, h.grad(t, t.Phi)) / 2)
    return {"Xdot - AA(Phi) X": flow["X"] - AA(s.Phi) @ s.X, "Pdot - AA(Phi) P": flow["P"] - AA(s.Phi) @ s.P}


@claim("p81-bracket-second-derivative", paper=("momentum_map",), kind="pb", sizes=admissible(n_max=4))
def bracket_second_derivative(s):
    """Φ is Poisson (+): d/dt h2(Φ) = {h2, h1}^+(Φ) along the flow of h1∘Φ at every point, so the derivatives of
    both sides along that flow agree (a derivative taken through the checked gradients of the bracket)."""
    from stiefelsym.brackets import SO_N, lie_poisson
    T = lie_poisson(SO_N, 1)
    h1, h2 = hA(), hT()
    flow = s.dirac_flow(h1.pullback(Phi))
    first = s.d(lambda t: T.bracket(t, h2, h1, t.Phi), flow)
    second = s.d(lambda t: t.d(h2.pullback(Phi), t.dirac_flow(h1.pullback(Phi))), flow)
    return {"d{h2,h1}(Phi) - d^2 h2(Phi)": first - second,
            "{h2,h1}(Phi) - d h2(Phi)": T.bracket(s, h2, h1, s.Phi) - s.d(h2.pullback(Phi), flow)}
