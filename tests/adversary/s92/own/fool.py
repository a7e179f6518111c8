# ruff: noqa
from stiefelsym import admissible, claim
from stiefelsym.ir.trace import TraceRefused

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


@claim("own-spoofed-refusal-false", kind="id", sizes=SZ)
def a(s):
    """FALSE (X Xᵀ = I_n at r < n), after a traced function raised the engine's own refusal, caught."""
    def bad(t):
        raise TraceRefused("refused: nothing")
    try:
        s.d(bad, {"P": s.P})
    except TraceRefused:
        pass
    return {"r": s.X @ s.X.T - s.In}


@claim("own-refusal-then-number", kind="id", sizes=SZ)
def b(s):
    """FALSE: tr(PᵀP) read as 0 when a str operand raised and was caught."""
    try:
        z = s.tr(s.P.T @ s.P) * "0"
    except Exception:
        z = s.q(0)
    return {"r": s.tr(s.P.T @ s.P) + z}
