"""s59 review, batch 6: the graph's sizes (not in its digest) set by claim code on the engine's first trace
while the second trace runs (found in the main thread's frames): ir._replayed copies g.sizes onto the
graph a method evaluates, and the Jacobian derivative makes 2nr columns from it."""
import sys
import threading
from stiefelsym import Rank, admissible, claim

SIZES = admissible(n_max=3)
_CALLS = {}


def _lie(tag, sizes):
    _CALLS[tag] = _CALLS.get(tag, 0) + 1
    if _CALLS[tag] % 2 == 0:             # the second trace: the first one's graph is a local of _compile
        f = sys._current_frames().get(threading.main_thread().ident)
        while f is not None:
            if f.f_code.co_name == "_compile" and "first" in f.f_locals:
                f.f_locals["first"].sizes = sizes
                break
            f = f.f_back


def _F(t):
    return [t.X.T @ t.X - t.Ir]


@claim("s59r-sizes-lie-jacobian", kind="dim", sizes=SIZES)
def sizes_lie_jacobian(s):
    """The Jacobian of X^T X - I (r(r+1)/2 rows, 2nr columns) has rank 1 at (3,2): FALSE (rank 3)."""
    int(s.n)                        # the door: traced at the numbers
    _lie("j", (1, 1))
    return {"rank": Rank(s.mat(s.jacobian(_F)), 1, generic=True)}


@claim("s59r-sizes-true-jacobian", kind="dim", sizes=SIZES)
def sizes_true_jacobian(s):
    """Control: rank 3 at (3,2) (r(r+1)/2 independent rows): TRUE."""
    int(s.n)
    return {"rank": Rank(s.mat(s.jacobian(_F)), 3, generic=True)}


@claim("s59r-sizes-nolie-jacobian", kind="dim", sizes=SIZES)
def sizes_nolie_jacobian(s):
    """Control: rank 1 at (3,2): FALSE, no lie."""
    int(s.n)
    return {"rank": Rank(s.mat(s.jacobian(_F)), 1, generic=True)}


def _G(t):
    return [t.P.T @ t.P]


@claim("s59r-sizes-lie-jacobian-p", kind="dim", sizes=SIZES)
def sizes_lie_jacobian_p(s):
    """The Jacobian of P^T P (3 rows, 12 columns at (3,2)) has rank 0: FALSE (rank 3).  The lie (3,1): 6
    columns, the derivatives along X alone."""
    int(s.n)
    _lie("p", (3, 1))
    return {"rank": Rank(s.mat(s.jacobian(_G)), 0, generic=True)}


@claim("s59r-sizes-nolie-jacobian-p", kind="dim", sizes=SIZES)
def sizes_nolie_jacobian_p(s):
    """Control: the same, no lie: FALSE."""
    int(s.n)
    return {"rank": Rank(s.mat(s.jacobian(_G)), 0, generic=True)}
