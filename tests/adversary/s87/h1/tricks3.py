"""s87h1 tricks, third file.

 s87h1k-not-mixed (as a user would read it, "XᵀX − I ≠ 0 and Ψ ≠ 0": FALSE, XᵀX = I on V): kind="not" with two
   residuals, one identically zero on T*V and one not.  The guide's semantics: proved when *a* residual is
   nonzero.  Probe of how the verdict/report words it.
 s87h1k-count-scalar-true (TRUE if accepted: tr XᵀX = r on V): Count of a scene scalar.
 s87h1k-count-scalar-false (FALSE: tr PᵀP is not 0): Count of a scene scalar.
"""
from stiefelsym import Count, admissible, claim

ANY = admissible(n_max=3)


@claim("s87h1k-not-mixed", kind="not", expect="nonzero", section="1", sizes=admissible(n_max=3, r_min=2))
def not_mixed(s):
    """XᵀX − I ≠ 0 and Ψ ≠ 0 (FALSE as a conjunction: XᵀX = I)."""
    return {"XtX - I": s.X.T @ s.X - s.Ir, "Psi": s.Psi}


@claim("s87h1k-count-scalar-true", kind="dim", section="1", sizes=ANY)
def count_scalar_true(s):
    """tr XᵀX = r as a Count."""
    return {"trXtX": Count(s.tr(s.X.T @ s.X), int(s.r))}


@claim("s87h1k-count-scalar-false", kind="dim", section="1", sizes=ANY)
def count_scalar_false(s):
    """tr PᵀP = 0 as a Count (FALSE)."""
    return {"trPtP": Count(s.tr(s.P.T @ s.P), 0)}
