# ruff: noqa
"""Claims whose graphs name steps of stiefelsym.twisted / systems / brackets (the lazily imported modules)."""
from stiefelsym import admissible, claim, twisted

S = admissible(n_max=3, r_in=(2,))


def f(t):
    return t.tr(t.P.T @ t.A @ t.P) + t.tr(t.X.T @ t.A @ t.X)


def g(t):
    return t.tr(t.X.T @ t.A @ t.A @ t.P) + t.tr(t.P.T @ t.A @ t.X @ t.X.T @ t.P)


@claim("rv-mag-skew", kind="id", sizes=S)
def mag_skew(s):
    F = twisted.magnetic_matrix(s)
    return {"F + F^T": F + F.T}


@claim("rv-mag-sym-false", kind="id", sizes=S)
def mag_false(s):
    F = twisted.magnetic_matrix(s)
    return {"F - F^T": F - F.T}


@claim("rv-tw-antisym", kind="pb", sizes=S)
def tw_antisym(s):
    M = s.generic("M", "r", "r")
    F = M - M.T
    return {"{f,g}+{g,f}": twisted.bracket(s, f, g, F) + twisted.bracket(s, g, f, F)}


@claim("rv-tw-flow-vs-bracket", kind="pb", sizes=S)
def tw_flow(s):
    M = s.generic("M", "r", "r")
    F = M - M.T
    return {"{f,g} - df(X_g)": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("rv-tw-false", kind="pb", sizes=S)
def tw_false(s):
    M = s.generic("M", "r", "r")
    F = M - M.T
    return {"{f,g}-{g,f}": twisted.bracket(s, f, g, F) - twisted.bracket(s, g, f, F)}
