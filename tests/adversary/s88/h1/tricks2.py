"""s88h1 tricks 2: names of generic parameters with the same name and different kinds/shapes.

 s88h1k-same-name-same-kind [TRUE]: generic("G","r","r") − generic("G","r","r") = 0 (one parameter, one name).
 s88h1k-same-name-gen-sym [FALSE, except nothing]: generic("G","r","r") − generic("G","r","r","sym") = 0
   (two different parameters; the traced text must not read "G − G").
 s88h1k-same-name-sym-transpose [TRUE]: generic("G","r","r","sym")ᵀ − generic("G","r","r","sym") = 0; harmless.
 s88h1k-same-name-skew-vs-gen [FALSE for r ≥ 1... at (1,1): skew 1×1 is 0 and general G is not]:
   generic("G","r","r","skew") + generic("G","r","r")ᵀ − generic("G","r","r") = 0, printed as G + Gᵀ − G?
 s88h1k-same-name-shapes [FALSE]: tr(generic("U","n","r")ᵀX) = tr(generic("U","r","n")X) (two parameters named U).
"""
from stiefelsym import admissible, claim

ANY = admissible(n_max=3)


@claim("s88h1k-same-name-same-kind", kind="id", section="2", sizes=ANY)
def a(s):
    """G − G = 0 (TRUE)."""
    return {"g": s.generic("G", "r", "r") - s.generic("G", "r", "r")}


@claim("s88h1k-same-name-gen-sym", kind="id", section="2", sizes=ANY)
def b(s):
    """G(general) − G(sym) = 0 (FALSE)."""
    return {"g": s.generic("G", "r", "r") - s.generic("G", "r", "r", "sym")}


@claim("s88h1k-same-name-sym-transpose", kind="id", section="2", sizes=ANY)
def c(s):
    """Gsymᵀ − Gsym = 0 (TRUE)."""
    G = s.generic("G", "r", "r", "sym")
    return {"g": G.T - G}


@claim("s88h1k-same-name-skew-vs-gen", kind="id", section="2", sizes=ANY)
def d(s):
    """Gskew + Gᵀ − G = 0 (FALSE)."""
    return {"g": s.generic("G", "r", "r", "skew") + s.generic("G", "r", "r").T - s.generic("G", "r", "r")}


@claim("s88h1k-same-name-shapes", kind="id", section="2", sizes=ANY)
def e(s):
    """tr(UᵀX) = tr(U'X) with U' = generic('U','r','n') (FALSE)."""
    return {"u": s.tr(s.generic("U", "n", "r").T @ s.X) - s.tr(s.generic("U", "r", "n") @ s.X)}
