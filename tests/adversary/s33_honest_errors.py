"""Claims whose honest runs end in `error` although their graphs trace: a division by an identically zero
expression (exact), and a size statement that raises where the dimension-free method asks it (free).  Their
records carry no graph digest (runner._guarded builds the error result without one), and `stiefelsym check`
compares the record's digest with the claim's: the honest results file does not hold up (exit 1)."""
from stiefelsym import Size, SizeSpec, admissible, claim, twisted


@claim("adv-s33-honest-divzero", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="1 / (tr X^T X - r) = 0")
def honest_divzero(s):
    """Undefined (a division by tr XᵀX − r = 0): exact answers error."""
    return {"r": s.q(1) / (s.tr(s.X.T @ s.X) - s.tr(s.Ir))}


class _RaisesAtFiveThree(SizeSpec):
    def admits(self, n, r):
        if (n, r) == (5, 3):
            raise ValueError("this statement has no answer at (5,3)")
        return r == 2 and 2 <= n <= 3


@claim("adv-s33-honest-statement", kind="id", sizes=_RaisesAtFiveThree((Size(2, 2), Size(3, 2)), r_min=2, r_max=2),
       statement="E1 E1^T + E2 E2^T = I_r")
def honest_statement(s):
    """True at r = 2; its statement raises at (5,3): free answers error."""
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    return {"r": E1 @ E1.T + E2 @ E2.T - s.Ir}
