"""h2 (stop 85), second file: other normalisations of §2 and §5 (truth: indep_b.py, indep_b_output.txt).

h2-phi-bracket-trace (TRUE): with tr instead of ⟨,⟩ = −½tr, the (+) Lie–Poisson property of Φ reads
  {tr Φξ, tr Φζ} = −2 tr(Φ[ξ, ζ])  (4{Φ_ξ, Φ_ζ} = 4⟨Φ, [ξ, ζ]⟩).
h2-phi-bracket-trace-twin (FALSE for n ≥ 3; true at n ≤ 2 where so(n) is abelian): +2 tr(Φ[ξ, ζ]).
h2-psi-bracket-trace (TRUE): the (−) property of Ψ: {tr Ψη, tr Ψθ} = +2 tr(Ψ[η, θ]).
h2-psi-bracket-trace-twin (FALSE for r ≥ 3; true at r ≤ 2): −2 tr(Ψ[η, θ]).
h2-lax-over-lambda (TRUE): (LA1) divided by λ: 𝓛/λ = Φ + λ⁻¹XXᵀ − λA, d(𝓛/λ)/dt = [Φ − λA, 𝓛/λ] along (No).
h2-lax-over-lambda-twin (FALSE for n ≥ 2): Φ + λ⁻¹XXᵀ + λA with the same 𝓐.
"""
from stiefelsym import admissible, claim, comm


@claim("h2-phi-bracket-trace", kind="pb", section="2", sizes=admissible(n_max=5))
def phi_bracket_trace(s):
    """{tr Φξ, tr Φζ} = −2 tr(Φ[ξ, ζ])."""
    return {"b": s.bracket(lambda t: t.tr(t.Phi @ t.xi), lambda t: t.tr(t.Phi @ t.zeta)) + 2 * s.tr(s.Phi @ comm(s.xi, s.zeta))}


@claim("h2-phi-bracket-trace-twin", kind="pb", section="2", sizes=admissible(n_max=5))
def phi_bracket_trace_twin(s):
    """FALSE for n >= 3: +2 tr(Φ[ξ, ζ])."""
    return {"b": s.bracket(lambda t: t.tr(t.Phi @ t.xi), lambda t: t.tr(t.Phi @ t.zeta)) - 2 * s.tr(s.Phi @ comm(s.xi, s.zeta))}


@claim("h2-psi-bracket-trace", kind="pb", section="2", sizes=admissible(n_max=5))
def psi_bracket_trace(s):
    """{tr Ψη, tr Ψθ} = +2 tr(Ψ[η, θ])."""
    return {"b": s.bracket(lambda t: t.tr(t.Psi @ t.eta), lambda t: t.tr(t.Psi @ t.theta)) - 2 * s.tr(s.Psi @ comm(s.eta, s.theta))}


@claim("h2-psi-bracket-trace-twin", kind="pb", section="2", sizes=admissible(n_max=5))
def psi_bracket_trace_twin(s):
    """FALSE for r >= 3: −2 tr(Ψ[η, θ])."""
    return {"b": s.bracket(lambda t: t.tr(t.Psi @ t.eta), lambda t: t.tr(t.Psi @ t.theta)) + 2 * s.tr(s.Psi @ comm(s.eta, s.theta))}


def H_neum(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def lax_over_lambda(s, sign):
    L = lambda t: t.Phi + (t.X @ t.X.T) / t.lam - sign * t.lam * t.A
    Aa = s.Phi - s.lam * s.A
    return {"lax": s.d(L, s.dirac_flow(H_neum)) - comm(Aa, L(s))}


@claim("h2-lax-over-lambda", kind="lax", section="5", sizes=admissible(n_max=5))
def lax_over_lambda_true(s):
    """d(𝓛/λ)/dt = [Φ − λA, 𝓛/λ], 𝓛/λ = Φ + λ⁻¹XXᵀ − λA, along (No)."""
    return lax_over_lambda(s, 1)


@claim("h2-lax-over-lambda-twin", kind="lax", section="5", sizes=admissible(n_max=5))
def lax_over_lambda_twin(s):
    """FALSE for n >= 2: Φ + λ⁻¹XXᵀ + λA."""
    return lax_over_lambda(s, -1)
