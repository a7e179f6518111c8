# ruff: noqa
from stiefelsym import admissible, claim
from stiefelsym.proofs.sec8_dual_lax_pair import even_coefficients


@claim("own-family4-false", kind="pb", sizes=admissible(n_max=5, n_min=4, where=lambda n, r: r == 4),
       exact_max_n=2, free_max_r=4)
def a(s):
    """FALSE: the coefficients e_2l(L*(λ)) do not move when P moves along AX (P ↦ P + εAX)."""
    return {f"d e_{2 * l}": v for l, v in enumerate(s.d(even_coefficients, {"P": s.A @ s.X}), 1)}
