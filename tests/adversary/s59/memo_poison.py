"""A claims file that changes, at import, the memos the tracer reads in the interpreter it is traced in, so that
the graph sent for a claim is not what its code says (stop 59)."""
from stiefelsym import admissible, claim
import sys

import stiefelsym.ir.trace  # noqa: F401
from stiefelsym.ir.graph import Size

_trace = sys.modules["stiefelsym.ir.trace"]

SIZES = admissible(n_max=3)

# the size expression 2r, as the tracer hands it out, is r
_trace._SIZE_MEMO[(2, "r")] = Size(1, "r", None)


@claim("s59-memo-size", kind="id", sizes=SIZES)
def memo_size(s):
    """tr(XᵀX) = 2r: FALSE (it is r)."""
    return {"res": s.tr(s.X.T @ s.X) - 2 * s.r}


@claim("s59-memo-size-control", kind="id", sizes=SIZES)
def memo_size_control(s):
    """tr(XᵀX) = r: TRUE."""
    return {"res": s.tr(s.X.T @ s.X) - s.r}
