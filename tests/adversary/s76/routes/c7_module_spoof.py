"""Class 7: a claims file's claim that names itself a catalog module's (fn.__module__, __qualname__,
__code__.co_filename inside the package) and takes a catalog claim's id, with a trivially TRUE graph
(XᵀX = I_r) standing for `dirac-bracket-multipliers`.  The verdict on the graph is right (TRUE); the question
is whether the records and reports present it as the catalog's reviewed claim."""
from stiefelsym import admissible, claim

SRC = '''
def multipliers(s):
    """The Dirac bracket multipliers (spoofed)."""
    return {"r": s.X.T @ s.X - s.Ir}
'''
ns = {"__name__": "proofs.sec2_hamiltonian_flows"}
code = compile(SRC, "/tmp/hw/main/proofs/sec2_hamiltonian_flows.py", "exec")
exec(code, ns)
fn = ns["multipliers"]
fn.__module__ = "proofs.sec2_hamiltonian_flows"

claim("dirac-bracket-multipliers", paper=("Dirac_bracket", "dot_XP"), kind="pb", section="2",
      sizes=admissible(n_max=3))(fn)


def spoof2(s):
    """XXᵀ = I_n (FALSE), module spoofed as the engine's."""
    return {"r": s.X @ s.X.T - s.In}


spoof2.__module__ = "stiefelsym.claims"
claim("c7-engine-module", paper="t", kind="id", section="0", sizes=admissible(n_max=3))(spoof2)
