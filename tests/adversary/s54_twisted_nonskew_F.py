"""twisted.bracket vs. the derivative along twisted.flow for a field strength F that is not skew.

twisted.flow / twisted.bracket accept any r x r matrix of the scene as the field strength F (the docs say
F is in so(r); nothing refuses a symmetric or general F).  On the coordinate scenes the bracket is the Dirac
formula {f,g}_eps + sum_ij {F_i,f}_eps C^ij {F_j,g}_eps, which equals d f along the twisted flow of g only
when the ambient tensor W^-1 is antisymmetric (F skew).  On the dimension-free scene twisted.bracket is
*defined* as s.d(f, _free_flow(s, g, F)), so the identity below is a tautology there.
"""
from stiefelsym import admissible, claim, twisted

S = admissible(n_max=4)


def f(t):
    return t.tr(t.P.T @ t.A @ t.P) + t.tr(t.X.T @ t.A @ t.X)


def g(t):
    return t.tr(t.X.T @ t.A @ t.A @ t.P) + t.tr(t.P.T @ t.A @ t.X @ t.X.T @ t.P)


@claim("nsf-control-skew", kind="id", sizes=S)
def control_skew(s):
    """Control (F skew, in the documented domain): {f, g}_F = d f along the twisted flow of g."""
    F = s.generic("F", "r", "r", "skew")
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("nsf-sym", kind="id", sizes=S)
def sym_F(s):
    """Same identity with a symmetric F: free 'proved (all n, r)', exact/modular 'fails' with a witness."""
    F = s.generic("F", "r", "r", "sym")
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("nsf-general", kind="id", sizes=S)
def general_F(s):
    """Same identity with a general r x r F."""
    F = s.generic("F", "r", "r")
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("nsf-product-of-skew", kind="id", sizes=S)
def product_of_skew_F(s):
    """Same identity with F = K1 K2, a product of two skew matrices (not skew): refused like the others."""
    F = s.generic("K1", "r", "r", "skew") @ s.generic("K2", "r", "r", "skew")
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("nsf-explicit-not-opposite", kind="id", sizes=S)
def explicit_F(s):
    """An explicit F whose entries across the diagonal are equal, not opposite (at r = 2: symmetric)."""
    c = s.tr(s.X.T @ s.P)
    F = s.mat([[0 if i == j else c for j in range(s.r)] for i in range(s.r)], ("r", "r"))
    return {"x": twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))}


@claim("nsf-control-constructions", kind="id", sizes=S)
def control_constructions(s):
    """Control: skew field strengths built in the recognised ways (M − Mᵀ, an explicit skew matrix, multiples
    of s.eta by a function of the point, a sum): the identity holds (true)."""
    M = s.generic("G", "r", "r")
    c = s.tr(s.X.T @ s.A @ s.X)
    E = s.mat([[0 if i == j else (c if i < j else -c) for j in range(s.r)] for i in range(s.r)], ("r", "r"))
    checks = {}
    for name, F in (("M - M^T", M - M.T), ("explicit", E), ("c eta + K", s.eta * c + s.generic("K", "r", "r", "skew"))):
        checks[name] = twisted.bracket(s, f, g, F) - s.d(f, twisted.flow(s, g, F))
    return checks
