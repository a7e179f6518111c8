"""s89h1: constants (no parameter enters) at small sizes.

 s89h1-y00 (FALSE at (1,1)): Y[0,0] = 1 (Y = -1 is a point of V(1,1)).
 s89h1-x00 (FALSE at (1,1)): X[0,0] = 1 (X = -1 is a point).
 s89h1-x00sq (TRUE at (1,1)): X[0,0]² = 1.
 s89h1-xy00 (FALSE at (1,1)): X[0,0]·Y[0,0] = 1.
 s89h1-p-zero (TRUE at (1,1)): P = 0  (XᵀP + PᵀX = 2xp = 0, x = ±1).
 s89h1-psi-zero-nonzero (FALSE: expect nonzero, but Ψ = 0 at r = 1): expect="nonzero" for Ψ at (1,1),(2,1).
 s89h1-rank-psi (TRUE at (1,1), (2,1)): Rank(Ψ, 0).
 s89h1-count-const (FALSE): Count(3, 4).
 s89h1-zc-norm (TRUE): Z*Z = I realified at (1,1).
"""
from stiefelsym import claim, Rank, Count


@claim("s89h1-y00", kind="id", sizes=[(1, 1)])
def y00(s):
    """Y[0,0] = 1 (false)."""
    return {"r": s.Y[0, 0] - 1}


@claim("s89h1-x00", kind="id", sizes=[(1, 1)])
def x00(s):
    """X[0,0] = 1 (false)."""
    return {"r": s.X[0, 0] - 1}


@claim("s89h1-x00sq", kind="id", sizes=[(1, 1)])
def x00sq(s):
    """X[0,0]² = 1 (true)."""
    return {"r": s.X[0, 0] * s.X[0, 0] - 1}


@claim("s89h1-xy00", kind="id", sizes=[(1, 1)])
def xy00(s):
    """X[0,0] Y[0,0] = 1 (false)."""
    return {"r": s.X[0, 0] * s.Y[0, 0] - 1}


@claim("s89h1-p-zero", kind="id", sizes=[(1, 1)])
def p_zero(s):
    """P = 0 at (1,1) (true)."""
    return {"r": s.P}


@claim("s89h1-psi-nonzero", kind="not", expect="nonzero", sizes=[(1, 1), (2, 1)])
def psi_nonzero(s):
    """Ψ does not vanish (false at r = 1)."""
    return {"r": s.Psi}


@claim("s89h1-rank-psi", kind="dim", sizes=[(1, 1), (2, 1)])
def rank_psi(s):
    """rank Ψ = 0 at r = 1 (true)."""
    return {"r": Rank(s.Psi, 0)}


@claim("s89h1-count-const", kind="dim", sizes=[(1, 1), (2, 1)])
def count_const(s):
    """3 = 4 (false)."""
    return {"r": Count(3, 4)}


@claim("s89h1-q00", kind="id", sizes=[(1, 1)])
def q00(s):
    """Q = 0 at (1,1) (true: Q is a covector at Y on V(1,1))."""
    return {"r": s.Q}
