"""Twins of claims_b.py (one change each)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim
from stiefelsym.brackets import lambda1, linear, quadratic, skew

from _h81_helpers import H_neum, Psi, Theta, gl_functions, so_r_functions, B_r


@claim("n81-theta-commutes-with-psi-functions", kind="pb", sizes=admissible(n_max=4, r_min=2, condition="r >= 2"))
def theta_commutes_twin(s):
    """Twin: Φ + XBXᵀ (B generic symmetric r×r, not right-invariant) in place of Θ = Φ + XXᵀ."""
    out = {}
    for nF, F in gl_functions():
        for nf, f in so_r_functions():
            out[f"{{{nF} o Theta, {nf} o Psi}}"] = s.bracket(
                F.pullback(lambda t: t.Phi + t.X @ B_r(t) @ t.X.T), f.pullback(Psi))
    return out


H_CPB_TWIN = quadratic(lambda s, x: skew(x), "1/2<h,h>") + linear(lambda s: s.A, "+<A,v>")


@claim("n81-theta-cpb-every-kappa", kind="pb", sizes=admissible(n_max=4, n_min=2, where=lambda n, r: r < n, condition="r < n"))
def theta_cpb_twin(s):
    """Twin: H = ½<h,h> + <A,v> in place of ½<h,h> − <A,v> (Λ2 in place of Λ1 is no twin: numpy finds it true,
    H_CPB being bi-Hamiltonian for the pair, see FINDINGS)."""
    flow = s.dirac_flow(H_neum)
    T = lambda1()
    out = {}
    for nF, F in gl_functions():
        out[f"d {nF}(Theta) - {{F, H}}_1"] = s.d(F.pullback(Theta), flow) - T.bracket(s, F, H_CPB_TWIN, Theta(s))
    return out
