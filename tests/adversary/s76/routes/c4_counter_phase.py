"""Class 4: a claim that is not deterministic with symbolic sizes is still traced at a number.

The claim's first call returns XXᵀ − I_n (FALSE at r < n), every later call XᵀX − I_r (TRUE).  With symbolic
sizes its two traces differ (NotDeterministic); the refusal sends it to the second phase, whose process
imports the file again, spends the first call on its own symbolic attempt (FALSE graph) and the next two on
the trace at (3,2) (TRUE, TRUE): one digest, so a fixed-size verdict is given on the graph of the 2nd/3rd
call, although the claim's graphs differ in that very process (architecture.md: "a claim whose graphs differ
is not deterministic and its verdict is error").
"""
import itertools
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
_calls = itertools.count()


@claim("c4-counter-phase", paper="t", kind="id", section="0", sizes=SZ)
def counter(s):
    """XXᵀ = I_n on the first call (FALSE), XᵀX = I_r afterwards (TRUE)."""
    if next(_calls) == 0:
        return {"r": s.X @ s.X.T - s.In}
    return {"r": s.X.T @ s.X - s.Ir}


_calls2 = itertools.count()


@claim("c4-counter-free-family", paper="t", kind="id", section="0", sizes=SZ, free_max_r=1)
def counter_family(s):
    """The same with a family r = 1 (free_max_r=1): XXᵀ = I_n first (FALSE for n > 1), then XᵀX = I_r."""
    if next(_calls2) == 0:
        return {"r": s.X @ s.X.T - s.In}
    return {"r": s.X.T @ s.X - s.Ir}
