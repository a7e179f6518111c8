"""Round 8: graphs that involve no dimension r are run once per n (run/runner.py shared_size) and their record
is copied to every r.  Each claim below reads A, λ and I_n only (a value the same at every r for a fixed n) or
something r-dependent disguised as such; the verdict at every (3, r) must be the one of the statement there."""
from stiefelsym import Rank, admissible, claim, elementary

SZ3 = admissible(n_min=3, n_max=3)


@claim("adv-s38-a-false", kind="id", sizes=SZ3)
def a_false(s):
    """tr(A)² = tr(A²) (false at every r): a graph in A alone, shared across r."""
    return {"t": s.tr(s.A) * s.tr(s.A) - s.tr(s.A @ s.A)}


@claim("adv-s38-a-cayley-hamilton", kind="id", sizes=SZ3)
def a_cayley_hamilton(s):
    """A³ − e₁A² + e₂A − e₃I = 0 at n = 3 with e_k from elementary() (true, control)."""
    e = elementary(s, s.A, 3)
    A = s.A
    return {"ch": A @ A @ A - e[1] * (A @ A) + e[2] * A - e[3] * s.In}


@claim("adv-s38-resolvent-rank", kind="dim", sizes=SZ3)
def resolvent_rank(s):
    """A − λI has rank n at every point (false: λ = a_i); shared across r."""
    return {"r": Rank(s.A - s.lam * s.In, 3, generic=False)}


@claim("adv-s38-ir-named-r", kind="id", sizes=SZ3)
def ir_named_r(s):
    """tr(I_r) = 1 (true at r = 1 only): I_r is a leaf on ℝʳ, never shared."""
    return {"t": s.tr(s.Ir) - 1}


@claim("adv-s38-scalar-named-r", kind="id", sizes=SZ3)
def scalar_named_r(s):
    """c·tr(A) − c·tr(A) = 0 for a user scalar named "r" (true at every r; its name is not the dimension)."""
    c = s.scalar("r")
    return {"t": c * s.tr(s.A) - s.tr(s.A) * c}
