"""s82 hidden2 (h5): twins of claims2.py (false at their sizes)."""
from __future__ import annotations

from stiefelsym import Count, admissible, claim
from stiefelsym.brackets import casimir_residual, lambda1, trace_power

N2 = admissible(n_max=5, n_min=2, condition="n >= 2 (so(1) = 0)")
ALL = admissible(n_max=5)


@claim("h5x-lambda1-casimirs-x", kind="pb", section="6", sizes=N2)
def lambda1_casimirs_x(s):
    """Twin: tr(x²) (the whole x, v → x) a Casimir of Λ1: false, tr h² is not (⟨v, [h, θ]⟩ ≠ 0)."""
    x, b = s.fresh("n", "n"), s.fresh("n", "n")
    return {"Lambda1(grad tr x^2, b)": casimir_residual(s, lambda1(), trace_power(2), x, b)}


@claim("h5x-dual-integral-count", kind="dim", section="8",
       sizes=admissible(n_max=5, condition="every size (r(r+1)/2 != r(r-1)/2)"))
def dual_integral_count(s):
    """Twin: N = r(n − r) + r(r + 1)/2 (an index)."""
    n, r = int(s.n), int(s.r)
    return {"N": Count(sum(n - l for l in range(1, r + 1)), r * (n - r) + r * (r + 1) // 2)}


@claim("h5x-neumann-integral-casimir-of-pencil", kind="pb", section="6", sizes=N2)
def neumann_integral_casimir(s):
    """Twin: f = tr h² + 2tr(Av) (a sign) a Casimir of Λ1 − Λ2."""
    from stiefelsym.brackets import pencil
    from _claims2_helpers import neumann_casimir
    x, b = s.fresh("n", "n"), s.fresh("n", "n")
    T = pencil(lambda t: t.q(1), lambda t: t.q(-1))
    return {"Lambda_{1,-1}(grad f, b)": casimir_residual(s, T, neumann_casimir(sign=1), x, b)}
