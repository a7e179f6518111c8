"""Class 4 (state across calls) in the metadata job: a size condition (where=) that answers one way while the
sizes are listed (iter(spec)) and another way in the admits table (spec.admits over n <= 16), both computed in the
same metadata job (run/userfile.py _claim_data).  The statement is then two statements: the listed sizes r < n and
the admitted family r = n.

Truth: XXᵀ = I_n holds iff r = n (X ∈ V(n, r)); XᵀX = I_r at every size.
ws-K-f (K = 3, 5, 8): where(n, r) = (r < n) for its first K calls, (r == n) after; states XXᵀ − I_n.  FALSE at every
           listed size (r < n); TRUE on the admitted family r = n.  A verdict "proved (all n, r)" whose record does
           not say "r = n", or `proved`/`checked` at a listed size r < n, is wrong.
ws-t:      the same condition, XᵀX − I_r: TRUE everywhere (control).
"""
from stiefelsym import admissible, claim


def _where(K):
    calls = [0]

    def where(n, r):
        calls[0] += 1
        return r < n if calls[0] <= K else r == n
    return where


def _f(s):
    return {"x": s.X @ s.X.T - s.In}


for _K in (3, 5, 8):
    claim(f"ws-{_K}-f", kind="id", sizes=admissible(n_max=3, n_min=2, where=_where(_K)))(_f)


@claim("ws-t", kind="id", sizes=admissible(n_max=3, n_min=2, where=_where(5)))
def ws_t(s):
    return {"x": s.X.T @ s.X - s.Ir}
