"""False claims that use the free algebra's operator letter on so(n) the way a careless or clever
user would: two different operators, the self-pairing, additivity with a term dropped, the
symmetry without a trace, and Φ against XXᵀΦ."""
from stiefelsym import claim, admissible

@claim("two-operators-equal", kind="id", sizes=admissible(n_max=3), statement="tr(AA(xi) zeta) = tr(BB(xi) zeta)")
def two_ops(s):
    """False: two different generic operators."""
    A, B = s.sym_operator("AA"), s.sym_operator("BB")
    return {"r": s.tr(A(s.xi) @ s.zeta) - s.tr(B(s.xi) @ s.zeta)}

@claim("operator-self-pairing-zero", kind="id", sizes=admissible(n_max=3), statement="tr(AA(xi) xi) = 0")
def self_pair(s):
    """False: <AA xi, xi> = 0."""
    A = s.sym_operator("AA")
    return {"r": s.tr(A(s.xi) @ s.xi)}

@claim("operator-additive-wrong", kind="id", sizes=admissible(n_max=3), statement="AA(xi + zeta) = AA(xi)")
def additive(s):
    """False: drops AA(zeta)."""
    A = s.sym_operator("AA")
    return {"r": A(s.xi + s.zeta) - A(s.xi)}

@claim("operator-symmetric-no-trace", kind="id", sizes=admissible(n_max=3), statement="AA(xi) zeta = xi AA(zeta)")
def notrace(s):
    """False: symmetry holds only under the trace."""
    A = s.sym_operator("AA")
    return {"r": A(s.xi) @ s.zeta - s.xi @ A(s.zeta)}

@claim("operator-on-phi-vs-psi-size", kind="id", sizes=admissible(n_max=3), statement="tr(AA(Phi) Phi) = tr(AA(Phi) X X^T Phi)")
def pp(s):
    """False in general."""
    A = s.sym_operator("AA")
    return {"r": s.tr(A(s.Phi) @ s.Phi) - s.tr(A(s.Phi) @ s.X @ s.X.T @ s.Phi)}
