"""Inverse and RightInverse statements whose maps are multiples by a size (or a scalar) that vanish at some size."""
from stiefelsym import Inverse, RightInverse, admissible, claim


def op_r1(s, x):
    return ((s.r - 1) * x,)


def inv_r1(s, y):
    return (y / (s.r - 1),)


@claim("h2i-r-minus-1", kind="id", sizes=admissible(n_max=3))
def r_minus_1(s):
    """False at r = 1: x -> (r - 1) x is invertible on Sym(r) (it is 0 at r = 1)."""
    return {"inv": Inverse(op_r1, inv_r1, on=("Sym(r)",))}


def op_nr(s, x):
    return ((s.n - s.r) * x,)


def inv_nr(s, y):
    return (y / (s.n - s.r),)


@claim("h2i-n-minus-r", kind="id", sizes=admissible(n_max=3))
def n_minus_r(s):
    """False at r = n: x -> (n - r) x is invertible on R^{n x r}."""
    return {"inv": Inverse(op_nr, inv_nr, on=("R^{n×r}",))}


@claim("h2i-n-minus-r-right", kind="id", sizes=admissible(n_max=3))
def n_minus_r_right(s):
    """False at r = n: x -> (n - r) x is onto R^{n x r}."""
    return {"onto": RightInverse(op_nr, inv_nr, on=("R^{n×r}",), to=("R^{n×r}",))}


def op_k(s, x):
    return (s.kappa * x,)


def inv_k(s, y):
    return (y / s.kappa,)


@claim("h2i-kappa", kind="id", sizes=admissible(n_max=3))
def kappa(s):
    """False at kappa = 0: x -> kappa x is invertible on so(r)."""
    return {"inv": Inverse(op_k, inv_k, on=("so(r)",))}


def op_l(s, x):
    return (s.lam * x,)


def inv_l(s, y):
    return (y / s.lam,)


@claim("h2i-lam", kind="id", sizes=admissible(n_max=3))
def lam(s):
    """False at lambda = 0: x -> lambda x is invertible on Sym(n)."""
    return {"inv": Inverse(op_l, inv_l, on=("Sym(n)",))}


def op_r2(s, x):
    return ((s.r * s.r - 3 * s.r + 2) * x,)


def inv_r2(s, y):
    return (y / (s.r * s.r - 3 * s.r + 2),)


@claim("h2i-r-quadratic", kind="id", sizes=admissible(n_max=3))
def r_quadratic(s):
    """False at r = 1, 2: x -> (r - 1)(r - 2) x is invertible on Sym(r)."""
    return {"inv": Inverse(op_r2, inv_r2, on=("Sym(r)",))}
