"""s88h1 tricks 4: same-named parameters of different kinds, order and across claims.

 s88h1k-order-sym-then-gen [FALSE for r ≥ 2, TRUE at r = 1]: K = generic("G","r","r","sym") drawn first, then
   G = generic("G","r","r"); G − Gᵀ = 0 (a general matrix is not symmetric).  K is used (tr K·0 added) so that it
   is in the graph.
 s88h1k-across-a [TRUE]: generic("M","r","r","sym") is symmetric.
 s88h1k-across-b [FALSE for r ≥ 2]: generic("M","r","r") is symmetric (another claim, same name).
 s88h1k-order-skew-then-gen-text [FALSE for r ≥ 2 ... ]: K = generic("G","r","r","skew"), G = generic("G","r","r"):
   K − G + Gᵀ = 0?  K = (G − Gᵀ)?? no: K is independent: FALSE for r ≥ 2; at r = 1: K = 0, G − G = 0 → TRUE.
"""
from stiefelsym import admissible, claim

ANY = admissible(n_max=3)


@claim("s88h1k-order-sym-then-gen", kind="id", section="2", sizes=ANY)
def a(s):
    """G − Gᵀ = 0 for a general G, after a symmetric G was drawn (FALSE for r ≥ 2)."""
    K = s.generic("G", "r", "r", "sym")
    G = s.generic("G", "r", "r")
    return {"g": G - G.T + K * 0}


@claim("s88h1k-across-a", kind="id", section="2", sizes=ANY)
def b(s):
    """Msym − Msymᵀ = 0 (TRUE)."""
    M = s.generic("M", "r", "r", "sym")
    return {"m": M - M.T}


@claim("s88h1k-across-b", kind="id", section="2", sizes=ANY)
def c(s):
    """M − Mᵀ = 0 for a general M (FALSE for r ≥ 2)."""
    M = s.generic("M", "r", "r")
    return {"m": M - M.T}


@claim("s88h1k-order-skew-then-gen-text", kind="id", section="2", sizes=ANY)
def d(s):
    """K − G + Gᵀ = 0, K skew named G (FALSE for r ≥ 2)."""
    K = s.generic("G", "r", "r", "skew")
    G = s.generic("G", "r", "r")
    return {"g": K - G + G.T}
