"""Class 1 (entries read through a block / chart choice), new tricks: coordinate reads made only inside the
function argument of a check step (MatrixFunction's value, read by gradient_check), never in the claim's own graph.

h(y) = y₀₀ + … + y_{r−1,r−1} (entries of an n×n matrix y).  dh(δ) = Σ_{i<r} δ_ii = <G, δ> with <a, b> = −½tr(ab)
gives ∇h = −2·E_r, E_r = diag(I_r, 0) (a constant).  On the equivariant chart X = (I_r; 0) one has XXᵀ = E_r, so a
declared gradient −2XXᵀ passes a check made at that point only.  At a generic point XXᵀ ≠ E_r (r < n): FALSE.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_max=4, n_min=2)


def _er(t):
    n, r = int(t.n), int(t.r)
    return t.mat([[t.q(1) if (i == j and i < r) else t.q(0) for j in range(n)] for i in range(n)], ("n", "n"))


def _value(t, y):
    acc = y[0, 0]
    for i in range(1, int(t.r)):
        acc = acc + y[i, i]
    return acc


@claim("c1-entryval-false", kind="id", sizes=SZ)
def c1_entryval_false(s):
    """FALSE (r < n): ∇h = −2XXᵀ for h(y) = Σ_{i<r} y_ii (true gradient −2E_r)."""
    h = MatrixFunction(_value, lambda t, y: t.X @ t.X.T * (-2))
    return {"r": h.grad(s, s.generic("Y", "n", "n")) + s.X @ s.X.T * 2}


@claim("c1-entryval-true", kind="id", sizes=SZ)
def c1_entryval_true(s):
    """TRUE: ∇h = −2E_r."""
    h = MatrixFunction(_value, lambda t, y: _er(t) * (-2))
    return {"r": h.grad(s, s.generic("Y", "n", "n")) + _er(s) * 2}


def _value_b(t, y):
    # the entry read through a block: the top-left r×r block of y, its trace
    return t.tr(y[0:int(t.r), 0:int(t.r)])


@claim("c1-blockval-false", kind="id", sizes=SZ)
def c1_blockval_false(s):
    """FALSE (r < n): same h as a trace of y's top r×r block, declared gradient −2XXᵀ."""
    h = MatrixFunction(_value_b, lambda t, y: t.X @ t.X.T * (-2))
    return {"r": h.grad(s, s.generic("Y", "n", "n")) + s.X @ s.X.T * 2}


@claim("c1-blockval-true", kind="id", sizes=SZ)
def c1_blockval_true(s):
    """TRUE: gradient −2E_r."""
    h = MatrixFunction(_value_b, lambda t, y: _er(t) * (-2))
    return {"r": h.grad(s, s.generic("Y", "n", "n")) + _er(s) * 2}


@claim("c1-bracket-false", kind="id", sizes=SZ)
def c1_bracket_false(s):
    """FALSE (r < n): a consequence read through a Lie–Poisson bracket: {h, g}(x) = <x, [∇h, ∇g]> with g = <y, A>,
    with the declared ∇h = −2XXᵀ, stated as <x, [−2XXᵀ, A]>... through the engine.  The residual
    {h, g}(x) − <x, [−2E_r, A]> is −2<x, [XXᵀ − E_r, A]> ≠ 0 at generic x, A, X when the wrong gradient is used;
    with the TRUE gradient it is 0.  So proved = right answer only if the check refuses; we state it as the true
    formula with E_r written in the residual (visible), which the engine must then refute or error."""
    from stiefelsym.brackets import GL_N, lie_poisson, linear
    h = MatrixFunction(_value, lambda t, y: t.X @ t.X.T * (-2))
    g = linear(lambda t: t.A)
    x = s.generic("Y", "n", "n")
    T = lie_poisson(GL_N)
    return {"r": T.bracket(s, h, g, x) - s.killing(x, (s.X @ s.X.T * (-2)) @ s.A - s.A @ (s.X @ s.X.T * (-2)))}
