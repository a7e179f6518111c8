"""Class 3: exceptions as a side channel, new shapes.  Each e3-* is FALSE (XXᵀ = I_n at r < n) if it gets a graph
at all; e3-control is TRUE.  Looking for: a pass, or an internal crash (a traceback instead of a refusal).

e3-str-raises: an exception whose __str__ raises (the message of the refusal cannot be formatted)
e3-huge-msg: an exception with a 5 MB message
e3-kbint: KeyboardInterrupt raised by the claim while traced
e3-genexit: GeneratorExit raised by the claim
e3-catch-refusal-inner: a refusal inside a function given to s.d caught by the claim, then a true residual
e3-exc-group: an ExceptionGroup holding a TraceRefused
e3-refused-subclass: an exception class of the file named TraceRefused derived from TypeError
e3-recursion-caught: the claim catches its own RecursionError and then returns a false residual
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


class BadStr(Exception):
    def __str__(self):
        raise ValueError("no message")


@claim("e3-str-raises", kind="id", sizes=SZ)
def e3_str_raises(s):
    """FALSE residual behind an exception whose text cannot be made."""
    raise BadStr()


@claim("e3-huge-msg", kind="id", sizes=SZ)
def e3_huge_msg(s):
    """FALSE residual behind a 5 MB exception message."""
    raise ValueError("x" * 5_000_000)


@claim("e3-kbint", kind="id", sizes=SZ)
def e3_kbint(s):
    """KeyboardInterrupt while traced."""
    raise KeyboardInterrupt


@claim("e3-genexit", kind="id", sizes=SZ)
def e3_genexit(s):
    """GeneratorExit while traced."""
    raise GeneratorExit


@claim("e3-catch-refusal-inner", kind="id", sizes=SZ)
def e3_catch_refusal_inner(s):
    """FALSE: d/dt of a function that reads float(tr X) is refused; caught, and XXᵀ − I_n ·0 returned."""
    try:
        s.d(lambda t: t.tr(t.X.T @ t.X) * float(t.tr(t.X.T @ t.X)), {"X": s.P})
    except Exception:
        pass
    return {"r": (s.X @ s.X.T - s.In) * 0}


@claim("e3-exc-group", kind="id", sizes=SZ)
def e3_exc_group(s):
    """FALSE: a refusal caught and re-raised inside an ExceptionGroup."""
    try:
        float(s.tr(s.X.T @ s.X))
    except Exception as e:
        raise ExceptionGroup("group", [e])  # noqa: F821
    return {"r": s.X @ s.X.T - s.In}


class TraceRefused(TypeError):
    pass


@claim("e3-refused-subclass", kind="id", sizes=SZ)
def e3_refused_subclass(s):
    """An exception of the file's own named TraceRefused."""
    raise TraceRefused("refused: a size (n) used as a number: the claim needs fixed sizes")


def _deep(k):
    return _deep(k + 1)


@claim("e3-recursion-caught", kind="id", sizes=SZ)
def e3_recursion_caught(s):
    """FALSE: RecursionError of its own caught, then XXᵀ − I_n."""
    try:
        _deep(0)
    except RecursionError:
        pass
    return {"r": s.X @ s.X.T - s.In}


@claim("e3-control", kind="id", sizes=SZ)
def e3_control(s):
    """TRUE: XᵀX = I_r."""
    return {"r": s.X.T @ s.X - s.Ir}
