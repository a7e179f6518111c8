"""s89h1: parameters whose names print like the scene's objects in the traced text (all FALSE statements;
the question is whether the report/traced text can be misread, not the verdict).

 s89h1-print-lambda: s.scalar("lambda") - s.lam = 0 (false: two independent parameters).
 s89h1-print-kappa:  s.scalar("kappa") - s.kappa = 0 (false).
 s89h1-print-A:      generic("A", n, n, sym) - A = 0 (false).
 s89h1-print-Phi:    generic("Phi", n, n, skew) - Φ = 0 (false).
 s89h1-print-X:      generic("X", n, r) - X = 0 (false).
 s89h1-print-Ir:     generic("I_r", r, r) - I_r = 0 (false).
 s89h1-print-AA:     sym_operator("AA") vs sym_operator("A"): 𝔸(XPᵀ) for two operators named AA and A... (false).
"""
from stiefelsym import claim, admissible

S = admissible(n_max=3)


@claim("s89h1-print-lambda", kind="id", sizes=S)
def p_lambda(s):
    """λ' = λ (false)."""
    return {"r": s.scalar("lambda") - s.lam}


@claim("s89h1-print-kappa", kind="id", sizes=S)
def p_kappa(s):
    """κ' = κ (false)."""
    return {"r": s.scalar("kappa") - s.kappa}


@claim("s89h1-print-A", kind="id", sizes=S)
def p_A(s):
    """A' = A (false)."""
    return {"r": s.generic("A", "n", "n", "sym") - s.A}


@claim("s89h1-print-Phi", kind="id", sizes=S)
def p_Phi(s):
    """Φ' = Φ (false)."""
    return {"r": s.generic("Phi", "n", "n", "skew") - s.Phi}


@claim("s89h1-print-X", kind="id", sizes=S)
def p_X(s):
    """X' = X (false)."""
    return {"r": s.generic("X", "n", "r") - s.X}


@claim("s89h1-print-Ir", kind="id", sizes=S)
def p_Ir(s):
    """I' = I_r (false)."""
    return {"r": s.generic("I_r", "r", "r") - s.Ir}


@claim("s89h1-print-ops", kind="id", sizes=S)
def p_ops(s):
    """𝔸₁(XPᵀ) = 𝔸₂(XPᵀ) for two operators named AA and A (false)."""
    M = s.X @ s.P.T
    return {"r": s.sym_operator("AA")(M) - s.sym_operator("A")(M)}
