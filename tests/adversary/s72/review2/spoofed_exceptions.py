"""s72 review2 (attempts E1-E6, class 3): a claim raises, at one size only, an exception of its own whose class name is
one the verifying process maps back to an engine class (`userfile._Recorded.exception`: TraceRefused, NotDeterministic,
ClaimTimeout, NoGraph, ReplayError) or a builtin's (MemoryError, RecursionError, TimeoutError, KeyboardInterrupt).
Expected: no verdict at that size (error or inconclusive), never a pass; nothing skipped silently."""
from stiefelsym import admissible, claim

SIZES = admissible(n_min=3, n_max=4, r_max=1)


def _make(name, base=Exception):
    return type(name, (base,), {})


def _def(cid, exc_name, base=Exception):
    exc = _make(exc_name, base)

    @claim(cid, kind="id", paper="No", section="t", sizes=SIZES)
    def f(s):
        """X X^T = I_n at n = 3 (false), and at n = 4 an exception named like an engine's."""
        if int(s.n) == 4:
            raise exc("exceeded its time budget")
        return {"id": s.X @ s.X.T - s.identity(s.n)}
    return f


for _cid, _name, _base in [("rw2-exc-timeout", "ClaimTimeout", Exception), ("rw2-exc-refused", "TraceRefused", Exception),
                           ("rw2-exc-nograph", "NoGraph", Exception), ("rw2-exc-notdet", "NotDeterministic", Exception),
                           ("rw2-exc-memory", "MemoryError", Exception), ("rw2-exc-recursion", "RecursionError", Exception),
                           ("rw2-exc-kbd", "KeyboardInterrupt", BaseException), ("rw2-exc-exit", "SystemExit", BaseException),
                           ("rw2-exc-unavail", "GraphUnavailable", Exception), ("rw2-exc-expired", "Expired", Exception)]:
    _def(_cid, _name, _base)
