"""Class 4 (state across calls) and errata: corrections and erratum metadata of a user's file.

Truths (V(n, r), r < n at the sizes run, (3,2)): XᵀX = I_r TRUE; XXᵀ = I_n FALSE (rank r < n);
tr(XᵀX) = r TRUE; tr(XXᵀ) = n FALSE (it is r).

corr-state: the printed claim states XXᵀ = I_n (FALSE, declared an erratum: expect="fails") and sets a module flag;
  its correction computes XᵀX − I_r (TRUE) when the flag is set, XXᵀ − I_n (FALSE) when it is not.  Standalone
  (corr-state-alone, the same correction function as its own claim) the flag is never set: FALSE.  A correction
  "verified" through the flag would be the correction's graph as traced after the printed claim.
corr-same: a correction whose function is the printed one (XXᵀ = I_n, FALSE): must fail, never "verified".
corr-nonzero: printed "XᵀX − I_r does not vanish" (expect nonzero, FALSE: it vanishes), correction expect="holds"
  with the same function: TRUE (XᵀX − I_r = 0) -> proved is right; the printed one must fail.
corr-fails-true: a claim declared an erratum (fails_at everywhere) that is TRUE (XᵀX = I_r): must be proved
  (unexpected), never fails.
corr-failsat-state: fails_at that answers True at its first call and False after (erratum metadata with state),
  on a FALSE statement (tr XXᵀ = n): the verdict must be fails whatever fails_at says.
corr-default-arg: a correction taking the printed claim's residual through a default argument bound at import
  (a Python object made before any scene): FALSE corrected statement tr(XXᵀ) − n; must fail.
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)
_FLAG = [False]


@claim("corr-state", kind="id", sizes=SZ, expect="fails", erratum="XXᵀ = I_n is printed; XᵀX = I_r is meant")
def corr_state(s):
    _FLAG[0] = True
    return {"XXt": s.X @ s.X.T - s.In}


@corr_state.claim.correction("XᵀX = I_r in place of XXᵀ = I_n")
def corr_state_fixed(s):
    if _FLAG[0]:
        return {"XXt": s.X.T @ s.X - s.Ir}
    return {"XXt": s.X @ s.X.T - s.In}


@claim("corr-state-alone", kind="id", sizes=SZ)
def corr_state_alone(s):
    return corr_state_fixed(s)


@claim("corr-same", kind="id", sizes=SZ, expect="fails", erratum="printed XXᵀ = I_n")
def corr_same(s):
    return {"XXt": s.X @ s.X.T - s.In}


corr_same.claim.correction("the same statement")(corr_same)


@claim("corr-nonzero", kind="not", sizes=SZ, expect="nonzero")
def corr_nonzero(s):
    return {"XtX - I": s.X.T @ s.X - s.Ir}


@corr_nonzero.claim.correction("it vanishes", expect="holds")
def corr_nonzero_fixed(s):
    return {"XtX - I": s.X.T @ s.X - s.Ir}


@claim("corr-fails-true", kind="id", sizes=SZ, fails_at=lambda n, r: True, erratum="(a wrong erratum)")
def corr_fails_true(s):
    return {"XtX": s.X.T @ s.X - s.Ir}


_CALLS = [0]


def _first_only(n, r):
    _CALLS[0] += 1
    return _CALLS[0] == 1


@claim("corr-failsat-state", kind="id", sizes=SZ, fails_at=_first_only, erratum="(stateful erratum sizes)")
def corr_failsat_state(s):
    return {"trXXt": s.tr(s.X @ s.X.T) - s.tr(s.In)}


@claim("corr-default-arg", kind="id", sizes=SZ, expect="fails", erratum="tr XXᵀ = n printed")
def corr_default_arg(s):
    return {"trXXt": s.tr(s.X @ s.X.T) - s.tr(s.In)}


@corr_default_arg.claim.correction("tr XXᵀ = r")
def corr_default_arg_fixed(s, _printed=corr_default_arg):
    return _printed(s)
