"""The record of (n, r_min) shared with every r of n (`ir.passes.r_dependence`): graphs that read no point of
T*V and hold r only in a space NAME of an Inverse / RightInverse statement ("Sym(r)", "so(r)", "R^{r×r}"),
strings that the pass's _mentions_r does not read as r.  Each statement is TRUE at r = 1 and FALSE at r >= 2
(the truth at each size is in the docstring)."""
from stiefelsym import Inverse, RightInverse, admissible, claim

SZ = admissible(n_min=3, stated_n_max=3, n_max=3, r_max=2, condition="n = 3, r <= 2")


def double(s, x):
    return (x * 2,)


def same(s, y):
    return (y,)


def square_shift(s, x):
    """x + x² − tr(x) x: x at r = 1 (x² = tr(x) x for a 1 x 1 x), not at r = 2."""
    return (x + x @ x - x * s.tr(x),)


def with_a(s, y):
    # reads A (and so nothing of the point) beside y, multiplied by 0 through a trace difference
    return (y + y * (s.tr(s.A) - s.tr(s.A)),)


@claim("s74-rshare-so-r", kind="id", sizes=SZ)
def so_r(s):
    """y ↦ 2y on so(r) has the inverse y ↦ y: TRUE at r = 1 (so(1) = 0), FALSE at r = 2."""
    return {"inv": Inverse(double, with_a, on=("so(r)",))}


@claim("s74-rshare-sym-r", kind="id", sizes=SZ)
def sym_r(s):
    """x ↦ x + x² − tr(x)x on Sym(r) has the inverse y ↦ y: TRUE at r = 1, FALSE at r = 2."""
    return {"inv": Inverse(square_shift, with_a, on=("Sym(r)",))}


@claim("s74-rshare-gl-r", kind="id", sizes=SZ)
def gl_r(s):
    """x ↦ x + x² − tr(x)x on R^{r×r} is onto with right inverse y ↦ y: TRUE at r = 1, FALSE at r = 2."""
    return {"onto": RightInverse(square_shift, with_a, on=("R^{r×r}",), to=("R^{r×r}",))}


@claim("s74-rshare-so-r-twin", kind="id", sizes=admissible(n_min=3, stated_n_max=3, n_max=3, r_min=2, r_max=2,
                                                          condition="n = 3, r = 2"))
def so_r_twin(s):
    """The same statement as s74-rshare-so-r stated at r = 2 only: FALSE (the control)."""
    return {"inv": Inverse(double, with_a, on=("so(r)",))}
