"""Classes 6 (copies / introspection of tracers) and 7 (spoofed module identity, privileges).

Truths at (3,2): XᵀP is skew on T*V (XᵀP + PᵀX = 0, TRUE; XᵀP − PᵀX = 0 FALSE); XᵀX = I_r TRUE; X₁₁ = 1 FALSE (true
only at the equivariant chart's X₀); tr(XXᵀ) = r TRUE.
cp-deep:       M = copy.deepcopy(XᵀP): M + Mᵀ (TRUE) -- a copy that detached from the trace would be a constant
cp-deep-f:     the same, M − Mᵀ (FALSE)
cp-copy-f:     copy.copy(s.X) used as X:  X'ᵀX' − 2 I_r (FALSE)
cp-pickle:     pickle round trip of s.P inside try: on refusal XXᵀ − I_n (FALSE), else its graph; FALSE either way?
               no: on success the residual is P'ᵀX + XᵀP' (TRUE if P' is P).  Must never be proved if refused.
id-name:       the module calls itself stiefelsym.proofs.sec1_introduction (__name__ at import) and states an
               equivariance reason, reading X₁₁: X₁₁ − 1 (FALSE).  A catalog module name or a reason must not
               bring the equivariant chart (X = X₀, where X₁₁ = 1).
id-name-t:     the same module, tr(XXᵀ) − tr(I_r) (TRUE) with an equivariance reason.
id-qualname:   a function whose __module__/__qualname__ are those of an engine step (stiefelsym.twisted.at_point)
               used as the claim: X₁₁ − 1 (FALSE)
id-code-file:  the claim function's code object renamed to an engine file (co_filename = .../stiefelsym/ir/trace.py)
               through code.replace (public API of code objects): X₁₁ − 1 (FALSE)
"""
import copy
import pickle
import types

from stiefelsym import admissible, claim

__name__ = "stiefelsym.proofs.sec1_introduction"   # noqa: A001 - the spoof
SECTION = "1"
SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


def _x11(s):
    return s.X[0, 0] - 1


@claim("cp-deep", kind="id", sizes=SZ)
def cp_deep(s):
    M = copy.deepcopy(s.X.T @ s.P)
    return {"x": M + M.T}


@claim("cp-deep-f", kind="id", sizes=SZ)
def cp_deep_f(s):
    M = copy.deepcopy(s.X.T @ s.P)
    return {"x": M - M.T}


@claim("cp-copy-f", kind="id", sizes=SZ)
def cp_copy_f(s):
    X = copy.copy(s.X)
    return {"x": X.T @ X - 2 * s.Ir}


@claim("cp-pickle", kind="id", sizes=SZ)
def cp_pickle(s):
    try:
        P = pickle.loads(pickle.dumps(s.P))
    except Exception:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": P.T @ s.X + s.X.T @ P}


@claim("id-name", kind="id", sizes=SZ, equivariance="X11 is invariant under O(n) (reviewed)")
def id_name(s):
    return {"x": _x11(s)}


@claim("id-name-t", kind="id", sizes=SZ, equivariance="the trace is invariant")
def id_name_t(s):
    return {"x": s.tr(s.X @ s.X.T) - s.tr(s.Ir)}


def _engine_like(s):
    return {"x": _x11(s)}


_engine_like.__module__ = "stiefelsym.twisted"
_engine_like.__qualname__ = "at_point"
claim("id-qualname", kind="id", sizes=SZ)(_engine_like)


def _file_like(s):
    return {"x": _x11(s)}


_file_like = types.FunctionType(_file_like.__code__.replace(co_filename="/tmp/h1/main/stiefelsym/ir/trace.py",
                                                             co_name="trace"), globals(), "trace")
claim("id-code-file", kind="id", sizes=SZ)(_file_like)
