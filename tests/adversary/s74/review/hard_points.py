"""Claims whose residual vanishes exactly at a hard point (--hard near-pole: λ = a₁ + 10⁻¹²; manakov-0/0: the
claim's own scalars b_i moved next to b_1; near-equal-a: a_i = a_1 + 1e-9 i (1 + t²)); the truth of each claim is
in its docstring."""
from stiefelsym import admissible, claim


@claim("s74-hard-pole-nonzero", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def pole_nonzero(s):
    """(λ − a₁)·10¹² − 1 is not identically 0: TRUE (it vanishes only at the hard point λ = a₁ + 10⁻¹²)."""
    return {"w": (s.lam - s.A[0, 0]) * 10**12 - 1}


@claim("s74-hard-pole-false", kind="id", sizes=admissible(n_max=3))
def pole_false(s):
    """(λ − a₁)·10¹² − 1 = 0: FALSE (it holds at the hard point only)."""
    return {"w": (s.lam - s.A[0, 0]) * 10**12 - 1}


@claim("s74-hard-b-nonzero", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def b_nonzero(s):
    """b₂ − b₁ − 2·10⁻⁹(2 + t²)... written as a scalar of the claim: (b_2 − b_1) is not identically 0: TRUE."""
    b1, b2 = s.scalar("b_1"), s.scalar("b_2")
    return {"w": b2 - b1}


@claim("s74-hard-a-gap-nonzero", kind="not", expect="nonzero", sizes=admissible(n_min=2, n_max=3))
def a_gap_nonzero(s):
    """(a₂ − a₁)·10⁹ − 2(1 + t²) for a free scalar t is not identically 0: TRUE (vanishes at near-equal-a's point
    only if t is the drawn value; here t is the claim's own scalar, so it does not)."""
    t = s.scalar("t")
    return {"w": (s.A[1, 1] - s.A[0, 0]) * 10**9 - 2 * (1 + t * t)}


@claim("s74-hard-momenta-nonzero", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def momenta_nonzero(s):
    """tr(PᵀP) − 10¹² tr(PᵀP) is not identically 0: TRUE."""
    return {"w": s.tr(s.P.T @ s.P) - s.tr(s.P.T @ s.P) * 10**12}
