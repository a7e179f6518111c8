"""Inverse statements whose op and inv reach the generic elements other than through their arguments.

op = const y and inv = const x would make op(inv(y)) = y and inv(op(x)) = x for the constant map 0 ↦ ...:
the elements' names are refused to claim code, and a function that keeps its argument from one call and
returns it at another (op(x) = 0, inv(0) = the x that op saw) is refused where the statement is made.
Each claim is false (the map is not invertible) and must not pass under any method."""
from stiefelsym import Inverse, admissible, claim

SIZES = admissible(n_max=3)


@claim("adv-inverse-named-element", kind="id", sizes=SIZES)
def inverse_reads_the_element_by_name(s):
    """op = 0, inv = the element x itself, by its name."""
    return {"inv": Inverse(lambda t, a: a - a, lambda t, b: t.generic("InverseX1", "r", "r"), on="R^{r×r}")}


def _kept():
    """op is the identity on its first call and 0 after, keeping its argument; inv is the identity until op
    has kept an argument, and that argument after."""
    seen = []

    def op(t, a):
        seen.append(a)
        return a if len(seen) == 1 else a - a

    def inv(t, b):
        return seen[-1] if len(seen) > 1 else b
    return op, inv


@claim("adv-inverse-kept-argument", kind="id", sizes=SIZES)
def inverse_keeps_an_argument(s):
    """op(inv(y)) = y on the first calls, then op(x) = 0 and inv(0) = the x that op kept."""
    op, inv = _kept()
    return {"inv": Inverse(op, inv, on="R^{r×r}")}
