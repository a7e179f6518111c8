"""s88h1 tricks 3: the traced text of same-named parameters of different kinds.

 s88h1k-names-text-nonzero-proved [TRUE at every size]: generic("G","r","r") + generic("G","r","r","skew")
   + generic("G","r","r","skew")ᵀ − generic("G","r","r") = 0: identically 0 (skew + its transpose); the text must
   not read as a nonzero residual.
 s88h1k-names-sym-skew [TRUE r = 1 only (both 1×1: skew = 0 ... sym G ≠ 0) → FALSE everywhere]:
   generic("H","r","r","sym") − generic("H","r","r","skew") = 0.
 s88h1k-names-scalar-vs-generic [FALSE]: s.scalar("G") ·X − X·generic("G","r","r") = 0.
"""
from stiefelsym import admissible, claim

ANY = admissible(n_max=3)


@claim("s88h1k-names-text-nonzero-proved", kind="id", section="2", sizes=ANY)
def a(s):
    """G + K + Kᵀ − G with K = skew generic named G (TRUE)."""
    G = s.generic("G", "r", "r")
    K = s.generic("G", "r", "r", "skew")
    return {"g": G + K + K.T - G}


@claim("s88h1k-names-sym-skew", kind="id", section="2", sizes=ANY)
def b(s):
    """Hsym − Hskew = 0 (FALSE)."""
    return {"h": s.generic("H", "r", "r", "sym") - s.generic("H", "r", "r", "skew")}


@claim("s88h1k-names-scalar-vs-generic", kind="id", section="2", sizes=ANY)
def c(s):
    """G·X − X·G (scalar G vs generic G) (FALSE)."""
    return {"c": s.X * s.scalar("G") - s.X @ s.generic("G", "r", "r")}
