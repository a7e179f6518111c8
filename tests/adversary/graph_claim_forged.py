"""Graphs handed in as claim functions (stiefelsym/ir/replay.py, GraphClaim): closed doors.

* adv-rp-true (true): XᵀX = I as a hand-built graph, replayed through the tracer: proved like claim code.
* adv-rp-private (refused): a graph whose attribute node names the scene's private ``_t`` (the trace's
  state); the replay refuses a private name before anything runs.
* adv-rp-engine-step (refused): a graph whose prim node names the derivative pass's own engine step
  ``tangent_vector`` (registered for transformed graphs, never handed to claim code): not a registered
  engine object for a graph either.
"""
from stiefelsym import admissible, claim
from stiefelsym.ir.graph import Graph, Ref, Named
from stiefelsym.ir.replay import GraphClaim
ALL = admissible(n_max=4, n_min=2)

def g_trueXtX():
    g = Graph()
    s = g.add("scene", (0,))
    X = g.add("attr", (s, "X"))
    XT = g.add("T", (X,))
    M = g.add("matmul", (XT, X))
    I = g.add("attr", (s, "Ir"))
    d = g.add("sub", (M, I))
    g.output = g.add("dict", (("v",), (d,)))
    return g

@claim("adv-rp-true", kind="id", sizes=ALL)
def rp_true(s):
    """X^T X = I via a replayed graph (true)."""
    return GraphClaim(g_trueXtX())(s)



def forged_private():
    g = g_trueXtX()
    g.ops[1], g.args[1] = "attr", (Ref(0), "_t")
    return g

@claim("adv-rp-private", kind="id", sizes=ALL)
def rp_private(s):
    """a graph naming a private attribute (refused)."""
    return GraphClaim(forged_private())(s)

def forged_prim():
    g = g_trueXtX()
    g.ops[3], g.args[3] = "prim", (Named("stiefelsym.ir.derivative.tangent_vector"), Ref(0), Ref(0), ())
    return g

@claim("adv-rp-engine-step", kind="id", sizes=ALL)
def rp_engine_step(s):
    """a graph calling the engine's tangent_vector step directly (not handed to claim code)."""
    return GraphClaim(forged_prim())(s)
