"""s89h2 classes 1/7 through Python features (each FALSE unless marked):
 c7-reload (FALSE): importlib.reload of an engine module (stiefelsym.backends.fields) inside the claim, XXᵀ = I_n.
 c7-patch-restore-dims (FALSE): replaces stiefelsym.ir.passes.coordinate_reads by a function returning {} while
    the claim runs and restores it (documented trust boundary in docs/architecture.md: recorded only).
 c1-mat-any (FALSE): s.mat() of an engine value (a flow) with tags ('n','r'), compared with P + X (recorded).
 c4-random-seeded (TRUE): random.seed(1) then a choice between two TRUE residuals (deterministic).
 c4-env (FALSE): a residual chosen by os.environ (the sandbox's minimal environment): XXᵀ = I_n or tr PᵀP = 0.
"""
import importlib
import os
import random
import sys
from stiefelsym import admissible, claim
RLT = admissible(n_max=3, n_min=2, where=lambda n, r: r < n, condition="r < n")

def H(t):
    return t.tr(t.P.T @ t.P) / 2

@claim("c7-reload", kind="id", sizes=RLT)
def a(s):
    """FALSE: XXᵀ = I_n."""
    importlib.reload(sys.modules["stiefelsym.backends.fields"])
    return {"r": s.X @ s.X.T - s.In}

@claim("c7-patch-restore-dims", kind="id", sizes=RLT)
def b(s):
    """FALSE: X₁₁² = 1 at r = 1 read through an entry (coordinate_reads patched while the claim runs)."""
    m = sys.modules["stiefelsym.ir.passes"]
    old = m.coordinate_reads
    m.coordinate_reads = lambda g: {}
    try:
        x = s.X[0, 0]
        return {"r": x * x - 1}
    finally:
        m.coordinate_reads = old

@claim("c1-mat-any", kind="id", sizes=RLT)
def c(s):
    """Recorded: s.mat of a flow."""
    return {"r": s.mat(s.dirac_flow(H), ("n", "r")) - s.P}

@claim("c4-random-seeded", kind="id", sizes=RLT)
def d(s):
    """TRUE: XᵀX = I_r or XᵀP + PᵀX = 0, chosen by a seeded random."""
    random.seed(1)
    if random.random() < 0.5:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X.T @ s.P + s.P.T @ s.X}

@claim("c4-env", kind="id", sizes=RLT)
def e(s):
    """FALSE either way: XXᵀ = I_n (PATH set) or tr PᵀP = 0 (no PATH)."""
    if "PATH" in os.environ:
        return {"r": s.X @ s.X.T - s.In}
    return {"r": s.tr(s.P.T @ s.P)}
