"""h10: ranks at every point (generic=False) and generic ranks of simple matrices."""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=4, r_min=2, r_max=2)


@claim("h10-psi-rank2-everywhere-FALSE", paper="momentum_right_map", kind="dim", sizes=SZ)
def psi_every(s):
    """(false) At r = 2, Ψ has rank 2 at every point of T*V (false: P = 0 is in T*V)."""
    return {"rank": Rank(s.Psi, 2, generic=False)}


@claim("h10-psi-rank2-generic", paper="momentum_right_map", kind="dim", sizes=SZ)
def psi_gen(s):
    """At r = 2, Ψ has generic rank 2."""
    return {"rank": Rank(s.Psi, 2)}


@claim("h10-x-rank-everywhere", paper="cond_X", kind="dim", sizes=admissible(n_max=4))
def x_every(s):
    """X has rank r at every point."""
    return {"rank": Rank(s.X, int(s.r), generic=False)}


@claim("h10-p-rank-everywhere-FALSE", paper="cond_XP", kind="dim", sizes=admissible(n_max=4, n_min=2))
def p_every(s):
    """(false) P has rank r at every point of T*V (false: P = 0)."""
    return {"rank": Rank(s.P, int(s.r), generic=False)}


@claim("h10-phi-generic-rank", paper="momentum_map", kind="dim", sizes=admissible(n_max=4, n_min=2))
def phi_gen(s):
    """Φ has generic rank min(2r, n) rounded down to even."""
    n, r = int(s.n), int(s.r)
    k = min(2 * r, n)
    k -= k % 2
    return {"rank": Rank(s.Phi, k)}


@claim("h10-phi-generic-rank-TWIN", paper="momentum_map", kind="dim", sizes=admissible(n_max=4, n_min=2))
def phi_gen_twin(s):
    """(false twin) Φ has generic rank min(2r, n)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(s.Phi, min(2 * r, n))}
