"""A false claim proved with the graph of another claim: the per-process graph cache is a dict keyed
by (claim function, n, r, realization), and a claim's "function" may be any callable, so an object
whose __hash__ and __eq__ match an earlier claim's function is handed that claim's cached graph
(also by `stiefelsym check`, which re-traces through the same cache)."""
from stiefelsym import admissible, claim


@claim("adv-cache-true", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def gram_is_identity(s):
    """XᵀX = I (true)."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}


class _Claim:
    """X = 0 on the Stiefel variety (false)."""

    def __call__(self, s):
        return {"X": s.X}

    def __hash__(self):
        return hash(gram_is_identity)

    def __eq__(self, other):
        return other is gram_is_identity or other is self


claim("adv-cache-false", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))(_Claim())
