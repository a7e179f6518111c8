"""h81 probes, fifth set: the same class with trace_power (a gradient checked by reverse mode): <x, ∇g(x)> = 4g(x)
for g = tr x⁴ (homogeneous of degree 4), so the Dirac flows of ¼<Φ, ∇g(Φ)> and g∘Φ agree; and its twin (½)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim
from stiefelsym.brackets import trace_power

from _h81_helpers import Phi


@claim("p81-flow-of-euler-relation", paper=("momentum_map",), kind="id", sizes=admissible(n_max=4))
def flow_of_euler_relation(s):
    g = trace_power(4)
    a = s.dirac_flow(lambda t: t.killing(t.Phi, g.grad(t, t.Phi)) / 4)
    b = s.dirac_flow(g.pullback(Phi))
    return {"X": a["X"] - b["X"], "P": a["P"] - b["P"]}


@claim("q81-flow-of-euler-relation", kind="id", sizes=admissible(n_max=4, n_min=3))
def flow_of_euler_relation_twin(s):
    g = trace_power(4)
    a = s.dirac_flow(lambda t: t.killing(t.Phi, g.grad(t, t.Phi)) / 2)
    b = s.dirac_flow(g.pullback(Phi))
    return {"X": a["X"] - b["X"], "P": a["P"] - b["P"]}
