# ruff: noqa
"""An error of a claims file's claim named at a catalog file: (a) the raising function's code object given the
catalog file's path (co_filename), (b) a helper module of the file kept in a folder named proofs/ with a catalog
file's name, (c) the message itself carrying "(at proofs/...)".  The run's verdict must be error, never
a pass; the question is what the message says."""
import os, sys
from stiefelsym import admissible, claim

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
CATALOG = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "proofs",
                                        "sec3_geodesic_flows.py"))


def _raiser(s):
    raise ValueError("a division by zero in the printed formula")


_raiser.__code__ = _raiser.__code__.replace(co_filename=CATALOG, co_firstlineno=40)


@claim("sp-forged-file", kind="id", sizes=admissible(n_max=3))
def forged_file(s):
    """Raises from a function whose code names the catalog's file."""
    return {"x": _raiser(s)}


@claim("sp-helper-in-proofs", kind="id", sizes=admissible(n_max=3))
def helper(s):
    """Raises from a helper module at ./proofs/sec3_geodesic_flows.py (relative to the working directory)."""
    from proofs.sec3_geodesic_flows import boom
    return {"x": boom(s)}


@claim("sp-message", kind="id", sizes=admissible(n_max=3))
def message(s):
    """Raises with a message that names a catalog line."""
    raise ValueError("refused: a scene has no 'q' (at proofs/sec3_geodesic_flows.py:120)")
