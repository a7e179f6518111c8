"""Round 4b: Inverse statements whose op does not map the stated space into itself.

The statement is "op is a bijection of the stated product onto itself"; an op that returns a matrix of
another shape (n×r ↦ r×n, r×r ↦ n×n) is not a map of that space, even when op(inv(y)) = y and
inv(op(x)) = x hold.  None may pass under any method."""
from stiefelsym import Inverse, admissible, claim

SIZES = admissible(n_max=3)


@claim("adv-s34b-inv-transposed", kind="id", sizes=SIZES)
def transposes_nr(s):
    """x ↦ xᵀ claimed a bijection of R^{n×r} onto itself (it maps to R^{r×n})."""
    return {"inv": Inverse(lambda t, x: x.T, lambda t, y: y.T, on="R^{n×r}")}


@claim("adv-s34b-inv-swapped-pair", kind="id", sizes=SIZES)
def swaps_a_pair(s):
    """(a, b) ↦ (bᵀ, aᵀ) claimed a bijection of R^{n×r} × R^{n×r} (it maps to R^{r×n} × R^{r×n})."""
    return {"inv": Inverse(lambda t, a, b: (b.T, a.T), lambda t, c, d: (d.T, c.T), on=("R^{n×r}", "R^{n×r}"))}


@claim("adv-s34b-inv-lifted", kind="id", sizes=SIZES)
def lifts_to_n(s):
    """x ↦ X x Xᵀ + (I − XXᵀ)… claimed on Sym(r): op returns an n×n matrix, inv an r×r one."""
    def op(t, x):
        return t.X @ x @ t.X.T

    def inv(t, y):
        return t.X.T @ y @ t.X
    return {"inv": Inverse(op, inv, on="Sym(r)")}
