"""s88h1 tricks 5: names that could print like the engine's letters (display of the traced text).

 s88h1k-name-kappa-text [FALSE]: κX − s.scalar("kappa")X = 0.
 s88h1k-name-greek-kappa [FALSE]: κX − s.scalar("κ")X = 0.
 s88h1k-name-phi-generic [FALSE]: Φ − generic("Phi","n","n","skew") = 0.
 s88h1k-name-psi-greek [FALSE]: Ψ − generic("Ψ","r","r","skew") = 0.
 s88h1k-name-lam-text [FALSE]: λX − s.scalar("lambda")X = 0.
"""
from stiefelsym import admissible, claim

ANY = admissible(n_max=3)


@claim("s88h1k-name-kappa-text", kind="id", section="5", sizes=ANY)
def a(s):
    """κ = scalar('kappa') (FALSE)."""
    return {"k": s.X * s.kappa - s.X * s.scalar("kappa")}


@claim("s88h1k-name-greek-kappa", kind="id", section="5", sizes=ANY)
def b(s):
    """κ = scalar('κ') (FALSE)."""
    return {"k": s.X * s.kappa - s.X * s.scalar("κ")}


@claim("s88h1k-name-phi-generic", kind="id", section="2", sizes=ANY)
def c(s):
    """Φ = generic 'Phi' (FALSE)."""
    return {"p": s.Phi - s.generic("Phi", "n", "n", "skew")}


@claim("s88h1k-name-psi-greek", kind="id", section="2", sizes=admissible(n_max=3, r_min=2))
def d(s):
    """Ψ = generic 'Ψ' (FALSE)."""
    return {"p": s.Psi - s.generic("Ψ", "r", "r", "skew")}


@claim("s88h1k-name-lam-text", kind="id", section="5", sizes=ANY)
def e(s):
    """λ = scalar('lambda') (FALSE)."""
    return {"l": s.X * s.lam - s.X * s.scalar("lambda")}
