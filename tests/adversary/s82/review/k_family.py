"""Review h4, batch k: the family graph (key ("r", 2), which the dimension-free method proves for every n) and the
fixed-size graphs (keys (n, 2)) of ONE function made different by job order alone (stop 82, item 2).

The file counts, in the process that imports it and forks every job, the answers that process parses (json.loads,
replaced at import; json is not fingerprinted by the seal).  The function reads r as a number (int(s.r): refused
with symbolic sizes, so it is traced at the family keys ("r", 1), ("r", 2) and at every listed size), and returns
    XᵀX − I_r            (TRUE on V(n, r))        while at most K answers were parsed (the jobs up to ("r", 2)),
    XᵀX − 2 I_r          (FALSE at every size)    afterwards (the jobs (2,2), (3,2), (4,2)).
The same code in a fresh process at (3, 2) (the meaning of the claim at that size) is the second: FALSE.

  k-fam    stated at r = 2, n <= 4, free_max_r = 2, exact_max_n = 1 (beyond the symbolic budget at every size: the
           exact method uses the family's dimension-free proof there, with a modular cross-check)
"""
import json

from stiefelsym import admissible, claim

_SEEN = [0]
_loads = json.loads


def _counting_loads(*a, **kw):
    _SEEN[0] += 1
    return _loads(*a, **kw)


json.loads = _counting_loads

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
K = 3       # the answers parsed before the job ("r", 2) of the file's first claim is forked (meta, None, ("r", 1))


@claim("k-fam", kind="id", sizes=R2, free_max_r=2, exact_max_n=1)
def k_fam(s):
    int(s.r)                    # r as a number: refused with symbolic sizes
    c = 1 if _SEEN[0] <= K else 2
    return {"XtX - cI": s.X.T @ s.X - c * s.Ir, "seen": s.q(_SEEN[0]) * 0}
