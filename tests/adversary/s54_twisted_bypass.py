"""Routes around the skew check: the undecorated function, a private step, F built by a helper."""
from stiefelsym import admissible, claim, twisted

S = admissible(n_max=4)


def f(t):
    return t.tr(t.P.T @ t.A @ t.P) + t.tr(t.X.T @ t.A @ t.X)


def g(t):
    return t.tr(t.X.T @ t.A @ t.A @ t.P) + t.tr(t.P.T @ t.A @ t.X @ t.X.T @ t.P)


@claim("byp-wrapped", kind="id", sizes=S)
def wrapped(s):
    F = s.generic("F", "r", "r", "sym")
    br = getattr(twisted.bracket, "__wrapped__", twisted.bracket)
    fl = getattr(twisted.flow, "__wrapped__", twisted.flow)
    return {"x": br(s, f, g, F) - s.d(f, fl(s, g, F))}


@claim("byp-private", kind="id", sizes=S)
def private(s):
    F = s.generic("F", "r", "r", "sym")
    return {"x": twisted.bracket(s, f, g, F=F + F.T - F.T) - s.d(f, twisted._free_flow(s, g, F))}


@claim("byp-sym-as-skew-sum", kind="id", sizes=S)
def sym_sum(s):
    """F = (M - M^T) + (N + N^T): a sum with one symmetric part."""
    M, N = s.generic("M", "r", "r"), s.generic("N", "r", "r")
    F = (M - M.T) + (N + N.T)
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("byp-T-of-other", kind="id", sizes=S)
def t_other(s):
    """F = M - N^T with N another matrix."""
    M, N = s.generic("M", "r", "r"), s.generic("N", "r", "r")
    F = M - N.T
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("byp-scalar-matrix-mul", kind="id", sizes=S)
def scal(s):
    """F = eta * c where c is a 1x1 matrix entry read (a number, fine) times eta; then plus identity times lam."""
    F = s.eta + s.Ir * s.lam
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}
