"""An honest-looking claims file: on import it adds an audit hook (sys.addaudithook; the seal watches the trace,
profile and gc hooks, not audit hooks).  When the catalog's loading executes the code of its module sec8_dual_lax_pair (audit event 'exec'), the hook
applies @claim to a function of mine: the decorator writes to the registry on top of claims._ACTIVE, the catalog's,
so my claim is registered, and marked reviewed, by the catalog's own loading, with a stated reason of
equivariance.  Its statement, 'the last row of X vanishes', is false on T*V (true at X = X0 only)."""
import sys

from stiefelsym import admissible, claim


def bottom_row(s):
    """The last row of X vanishes."""
    return {"x": s.X[s.X.shape[0] - 1:, :]}


def _hook(event, args):
    if event == "exec" and args and getattr(args[0], "co_filename", "").endswith("sec8_dual_lax_pair.py"):
        # public API only: @claim, applied while the catalog's loading runs (once per loading: sec8 runs once)
        claim("zz-smuggled", paper=("cond_XP",), kind="id", sizes=admissible(n_max=4),
              equivariance="the checks are covariant")(bottom_row)


sys.addaudithook(_hook)


@claim("honest-tangent-audit", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
