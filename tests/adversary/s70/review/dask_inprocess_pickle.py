# ruff: noqa
"""On the dask path (`stiefelsym verify --scheduler ADDR`), a run server loads a user's claims file with
`load_claims_file`, i.e. it imports the file in the very process that runs the claims and sends their outcomes
back (stage separation does not hold there).  The seal's fingerprint watches the engine and numpy, flint,
builtins ..., but not `pickle`: the file wraps `pickle.dumps` so that every Outcome carrying a Result is sent
back with the verdict `proved`.  Acts only in a process where stiefelsym.run.distributed is loaded (the run
server); in the sandbox and the CLI's own runs the file is an honest false claim.
Honest verdict: s70-dask-false (XᵀP = 0) fails at (3,2) under every fixed-size method; undecided under free."""
import sys

from stiefelsym import admissible, claim


@claim("s70-dask-false", kind="id", sizes=admissible(n_min=3, r_min=2, n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2)."""
    return {"xtp": s.X.T @ s.P}


if "stiefelsym.run.distributed" in sys.modules and sys.argv[:1] == ["-c"]:
    import pickle

    _dumps = pickle.dumps

    def _forge(o, depth=0):
        if depth > 4 or o is None:
            return
        if hasattr(o, "verdict") and hasattr(o, "expected") and hasattr(o, "claim"):
            if str(getattr(o, "claim", "")).startswith("s70-"):
                o.verdict, o.expected, o.message, o.witness, o.checks = "proved", True, "", None, []
            return
        for name in ("value",):
            if hasattr(o, name):
                _forge(getattr(o, name), depth + 1)
        if isinstance(o, (list, tuple)):
            for x in o:
                _forge(x, depth + 1)
        if isinstance(o, dict):
            for x in o.values():
                _forge(x, depth + 1)

    def dumps(obj, *a, **kw):
        try:
            _forge(obj)
        except Exception:
            pass
        return _dumps(obj, *a, **kw)

    pickle.dumps = dumps
