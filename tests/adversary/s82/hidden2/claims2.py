"""s82 hidden2 (h5), second file: a Casimir statement of §6 through the library's Λ1, and the count of §8.
True; twins in twins2.py."""
from __future__ import annotations

from stiefelsym import Count, admissible, claim
from stiefelsym.brackets import casimir_residual, lambda1, trace_power

from _claims2_helpers import neumann_casimir

ALL = admissible(n_max=5)


@claim("h5-lambda1-casimirs-v", paper=("LAMBDA12", "symmetric-pair", "central"), kind="pb", section="6", sizes=ALL)
def lambda1_casimirs_v(s):
    """The invariants tr(v^k) of the symmetric part v of x = h + v are Casimirs of Λ1 (the semidirect product
    so(n) ⊕_ad Sym(n)): ∇ tr(v^k) = −2k v^{k−1} ∈ Sym(n) (η = v^{k−1}, ξ = 0), so Λ1(∇f, ζ + θ)|_x ∝
    ⟨x, [v^{k−1}, ζ]⟩ = ⟨v, [v^{k−1}, ζ]⟩ (a symmetric bracket pairs with v only) = −½tr([v, v^{k−1}]ζ) = 0.
    They are the λ → 0 limits of the pencil's Casimirs tr(λh + v − λ²A)^k (central)."""
    x, b = s.fresh("n", "n"), s.fresh("n", "n")
    zero = lambda t: t.q(0)
    T = lambda1()
    return {f"Lambda1(grad tr v^{k}, b)": casimir_residual(s, T, trace_power(k, so_scale=zero), x, b) for k in (1, 2, 3)}


@claim("h5-dual-integral-count", paper=("2r-integrals",), kind="dim", section="8", sizes=ALL)
def dual_integral_count(s):
    """'N = (n − 1) + (n − 2) + … + (n − r) = r(n − r) + r(r − 1)/2, the dimension of the Stiefel variety':
    deg 𝓘_{2l} = n − l, minus the constant leading coefficient, summed over l = 1..r."""
    n, r = int(s.n), int(s.r)
    N = sum(n - l for l in range(1, r + 1))
    return {"N = r(n-r) + r(r-1)/2": Count(N, r * (n - r) + r * (r - 1) // 2),
            "N = dim V": Count(N, n * r - r * (r + 1) // 2)}


@claim("h5-neumann-integral-casimir-of-pencil", paper=("LAMBDA", "L3", "L4", "central", "perelomov", "prep"), kind="pb",
       section="6", sizes=ALL)
def neumann_integral_casimir(s):
    """The Neumann integral tr Φ² − 2tr(XᵀAX) (h5-neumann-quadratic-integral) is Θ* of f = tr h² − 2tr(Av), and f is a
    Casimir of the bracket Λ_{1,−1} = Λ1 − Λ2 left out of (central) (λ1 + λ2 = 0): ∇f = ξ + η with ξ = −4h, η = 4A,
    which solves (L3) [η, A] = 0 and (L4) [ξ, A] − [η, h] = −4[h, A] − 4[A, h] = 0.  (It is the μ⁻² term of the
    pencil Casimirs tr(μh + v − μ²A)² as μ → ∞.)"""
    from stiefelsym.brackets import pencil
    x, b = s.fresh("n", "n"), s.fresh("n", "n")
    T = pencil(lambda t: t.q(1), lambda t: t.q(-1))
    f = neumann_casimir()
    theta = lambda t: t.Phi + t.X @ t.X.T
    return {"Lambda_{1,-1}(grad f, b)": casimir_residual(s, T, f, x, b),
            "f o Theta - (tr Phi^2 - 2 tr X^T A X)": f.pullback(theta)(s)
            - (s.tr(s.Phi @ s.Phi) - 2 * s.tr(s.X.T @ s.A @ s.X))}
