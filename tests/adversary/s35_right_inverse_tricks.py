"""Round 5, tried on the one-sided inverse: a RightInverse whose op and inverse carry a factor that is a
constant at each size but 0 at r = 1 ((tr I_r − 1): not onto there), and a projection X Xᵀ declared onto
R^{n×r} with the identity as its right inverse (onto only at r = n)."""
from stiefelsym import RightInverse, admissible, claim


@claim("adv-s35-ri-vanishing-factor", kind="dim", sizes=admissible(n_max=3))
def vanishing_factor(s):
    """False at r = 1: x ↦ (tr I_r − 1)(Xᵀx + xᵀX) maps R^{n×r} onto Sym(r)."""
    def op(t, x):
        return (t.X.T @ x + x.T @ t.X) * (t.tr(t.Ir) - 1)

    def inv(t, y):
        return t.X @ y / (2 * (t.tr(t.Ir) - 1))
    return {"onto": RightInverse(op, inv, on="R^{n×r}", to="Sym(r)")}


@claim("adv-s35-ri-projection", kind="dim", sizes=admissible(n_max=3))
def projection(s):
    """False for r < n: x ↦ X Xᵀ x maps R^{n×r} onto R^{n×r}, with the identity as a right inverse."""
    return {"onto": RightInverse(lambda t, x: t.X @ t.X.T @ x, lambda t, y: y, on="R^{n×r}", to="R^{n×r}")}
