"""h81, two more statements (added after finding that h81-phi-minor-pluecker, h81-phi-rank and the potential part of
h81-r-equals-n are stated in examples/ or tests/user_claims/ already).  Twins in negatives_b.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim
from stiefelsym.brackets import lambda1, linear, quadratic, skew

from _h81_helpers import H_neum, Psi, Theta, gl_functions, so_r_functions


@claim("h81-theta-commutes-with-psi-functions", paper=("LAMBDA12", "REDUCED_BRACKET", "right_action"), kind="pb",
       sizes=admissible(n_max=4))
def theta_commutes_with_psi_functions(s):
    """§6: 'Θ ... is invariant with respect to the right SO(r)-action', so by Noether every F∘Θ commutes with every
    f∘Ψ, f on so(r) not ad-invariant (tr(η + μB)³, <η, θ>²), F on gl(n) (tr(x + C)³, ½<x, x + xᵀ>)."""
    out = {}
    for nF, F in gl_functions():
        for nf, f in so_r_functions():
            out[f"{{{nF} o Theta, {nf} o Psi}}"] = s.bracket(F.pullback(Theta), f.pullback(Psi))
    return out


H_CPB = quadratic(lambda s, x: skew(x), "1/2<h,h>") + linear(lambda s: -s.A, "-<A,v>")


@claim("h81-theta-cpb-every-kappa", paper=("prep", "CPB", "LAMBDA12", "No"), kind="pb", sizes=admissible(n_max=4))
def theta_cpb_every_kappa(s):
    """§5 + §6: (prep) gives the same Θ̇ = ([XXᵀ, A], [Φ, XXᵀ]) for every κ, which is the (CPB) field of
    H = ½<h,h> − <A,v> at Θ; so along (No) with a generic κ, d/dt F(Θ) = {F, H}_{Λ1}(Θ) for F on gl(n)."""
    flow = s.dirac_flow(H_neum)
    T = lambda1()
    out = {}
    for nF, F in gl_functions():
        out[f"d {nF}(Theta) - {{F, H}}_1"] = s.d(F.pullback(Theta), flow) - T.bracket(s, F, H_CPB, Theta(s))
    return out
