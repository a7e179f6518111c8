"""h81 probes, fourth set: the class of the new refusal (a checked gradient inside a function whose gradient the
scene takes).  Each statement is true because the two functions compared are equal on all of T*R^{n×r}:
<Φ, ∇h_𝔸(Φ)> = <Φ, 𝔸Φ> = 2h_𝔸(Φ) (Euler's relation for a quadratic form)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim
from stiefelsym.brackets import quadratic

from _h81_helpers import Phi


def hA():
    return quadratic(lambda t, x: t.sym_operator("AA")(x))


def H_grad(t):
    return t.killing(t.Phi, hA().grad(t, t.Phi)) / 2


@claim("p81-bracket-of-gradient-function", paper=("submersion_metric", "momentum_map"), kind="pb",
       sizes=admissible(n_max=4))
def bracket_of_gradient_function(s):
    """{½<Φ, ∇h_𝔸(Φ)>, <Φ, ξ>} = {h_𝔸∘Φ, <Φ, ξ>} (the same function)."""
    h = hA()
    xi = s.xi
    return {"bracket": s.bracket(H_grad, lambda t: t.killing(t.Phi, xi))
            - s.bracket(h.pullback(Phi), lambda t: t.killing(t.Phi, xi))}


@claim("p81-gradient-of-gradient-function", paper=("submersion_metric",), kind="id", sizes=admissible(n_max=4))
def gradient_of_gradient_function(s):
    """s.gradient of ½<Φ, ∇h_𝔸(Φ)> equals that of h_𝔸∘Φ (the same function)."""
    a = s.gradient(H_grad)
    b = s.gradient(hA().pullback(Phi))
    return {"HX": a["X"] - b["X"], "HP": a["P"] - b["P"]}


@claim("p81-derivative-of-gradient-function", paper=("submersion_metric", "No"), kind="id", sizes=admissible(n_max=4))
def derivative_of_gradient_function(s):
    """The derivative along (dot_XP2) of ½<Φ, ∇h_𝔸(Φ)> is 0 (energy conservation, through the gradient)."""
    h = hA()
    return {"dH": s.d(H_grad, s.dirac_flow(h.pullback(Phi)))}
