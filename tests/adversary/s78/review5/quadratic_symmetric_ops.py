"""brackets.quadratic(op) after stop 78's fix (the operator checked linear and symmetric for <,> at engine
elements): operators that ARE symmetric, through paths the check has to decide on every scene.

(a) op = 𝔸 = s.sym_operator() (a generic symmetric operator on so(n), acting on the skew part): h = ½<x, 𝔸x>,
    ∇h = 𝔸x.  Lie–Poisson on so(n), g = <., b>: {h, g}(x) = <x, [𝔸x, b]> (TRUE); the false twin states
    {h, g}(x) = 0 (h is not a Casimir: <x, [𝔸x, b]> ≠ 0 for generic 𝔸, n >= 3).
(b) op(x) = xᵀ on gl(n): <y, zᵀ> = -½tr(y zᵀ) = <z, yᵀ> (symmetric, linear), h = ½<x, xᵀ> = -¼tr(x xᵀ),
    dh(δ) = -½tr(xᵀδ) = <xᵀ, δ>, so ∇h = xᵀ.
    Lie–Poisson on gl(n): {h, g}(x) = <x, [xᵀ, b]> (TRUE); false twin: = <x, [x, b]> = 0 (FALSE: xxᵀ ≠ xᵀx).
(c) op(x) = Π x Π with Π = X Xᵀ (symmetric, reads the scene's point: a constant of the function on gl(n)):
    {h, g}(x) = <x, [ΠxΠ, b]> (TRUE); false twin: <x, [Πx, b]> (FALSE).
Hand derivations; numpy: quadratic_symmetric_ops_check.py.in."""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import SO_N, GL_N, lie_poisson, quadratic, linear

SZ = admissible(n_max=3, n_min=3)


def _bracket(s, space, op):
    h = quadratic(op, "h")
    x, b = space.generic(s, "x"), space.generic(s, "b")
    return x, b, lie_poisson(space).bracket(s, h, linear(lambda t: b), x)


@claim("r5-quad-symop-true", kind="pb", sizes=SZ)
def symop_true(s):
    AA = s.sym_operator()
    x, b, br = _bracket(s, SO_N, lambda t, y: AA(y))
    return {"{½<x,𝔸x>, <.,b>} = <x,[𝔸x,b]>": br - s.killing(x, comm(AA(x), b))}


@claim("r5-quad-symop-false", kind="pb", sizes=SZ)
def symop_false(s):
    AA = s.sym_operator()
    x, b, br = _bracket(s, SO_N, lambda t, y: AA(y))
    return {"{½<x,𝔸x>, <.,b>} = 0": br}


@claim("r5-quad-transpose-true", kind="pb", sizes=SZ)
def transpose_true(s):
    x, b, br = _bracket(s, GL_N, lambda t, y: y.T)
    return {"{½<x,xᵀ>, <.,b>} = <x,[xᵀ,b]>": br - s.killing(x, comm(x.T, b))}


@claim("r5-quad-transpose-false", kind="pb", sizes=SZ)
def transpose_false(s):
    x, b, br = _bracket(s, GL_N, lambda t, y: y.T)
    return {"{½<x,xᵀ>, <.,b>} = <x,[x,b]>": br - s.killing(x, comm(x, b))}


@claim("r5-quad-proj-true", kind="pb", sizes=SZ)
def proj_true(s):
    Pi = s.X @ s.X.T
    x, b, br = _bracket(s, GL_N, lambda t, y: Pi @ y @ Pi)
    return {"{½<x,ΠxΠ>, <.,b>} = <x,[ΠxΠ,b]>": br - s.killing(x, comm(Pi @ x @ Pi, b))}


@claim("r5-quad-proj-false", kind="pb", sizes=SZ)
def proj_false(s):
    Pi = s.X @ s.X.T
    x, b, br = _bracket(s, GL_N, lambda t, y: Pi @ y @ Pi)
    return {"{½<x,ΠxΠ>, <.,b>} = <x,[Πx,b]>": br - s.killing(x, comm(Pi @ x, b))}
