"""s81 hidden2 (h81b): integrals in involution at small r (true claim, its twin, and a 'not' at r = 3).
numpy: indep_small_r.py.in (output indep_small_r_output.txt)."""
from __future__ import annotations

from stiefelsym import admissible, claim

R2 = admissible(n_max=5, r_min=2, r_max=2, condition="r = 2")


def G(t):
    return t.P.T @ t.P


def K(t):
    return t.X.T @ t.P


def trG(t):
    return t.tr(G(t))


def detG(t):
    g = G(t)
    return g[0, 0] * g[1, 1] - g[0, 1] * g[1, 0]


def trK2(t):
    k = K(t)
    return t.tr(k @ k)


def psi12(t):
    return t.Psi[0, 1]


@claim("h81b-r2-invariants-involution", paper=("SO(n)-inv", "com", "so(n)+so(r)", "ET"), kind="pb", section="2",
       sizes=R2)
def r2_invariants_involution(s):
    """At r = 2 the SO(n)×SO(2)-invariant functions tr PᵀP, det PᵀP, tr (XᵀP)² (= −Ψ₁₂²/2 on T*V) and the
    SO(2) momentum Ψ₁₂ pairwise commute for the Dirac bracket (the Jensen Hamiltonians H_κ of Theorem ET are in
    this algebra).  Hand for Ψ₁₂: it generates the right SO(2) action, under which G = PᵀP ↦ hᵀGh, so tr G, det G
    are invariant; numpy (indep_small_r.py.in) for the brackets among tr G, det G, tr K²."""
    return {"{tr G, det G}": s.bracket(trG, detG), "{tr G, tr K^2}": s.bracket(trG, trK2),
            "{det G, tr K^2}": s.bracket(detG, trK2), "{det G, Psi12}": s.bracket(detG, psi12),
            "{tr G, Psi12}": s.bracket(trG, psi12)}


@claim("n81b-r2-gram-entry", kind="pb", section="2", sizes=R2, fails_at=lambda n, r: n > 2,
       erratum="twin: (PᵀP)₁₁ for det PᵀP")
def r2_gram_entry(s):
    """Twin: (PᵀP)₁₁ (not SO(2)-invariant) in place of det PᵀP: {(PᵀP)₁₁, tr K²} = 0."""
    return {"{G11, tr K^2}": s.bracket(lambda t: G(t)[0, 0], trK2)}


@claim("h81b-r3-invariants-noncommutative", kind="not", expect="nonzero", section="2",
       sizes=[(5, 3)])
def r3_invariants_noncommutative(s):
    """At r = 3 (n = 5) the SO(n)×SO(3)-invariant functions do not commute: {tr GK², tr G²K²} ≠ 0 (numpy:
    −60 at (6,3), 0.22 at (5,3); ~0 at (3,3), (4,3))."""
    f1 = lambda t: t.tr(G(t) @ K(t) @ K(t))
    f2 = lambda t: t.tr(G(t) @ G(t) @ K(t) @ K(t))
    return {"{tr G K^2, tr G^2 K^2}": s.bracket(f1, f2)}


def detG_traces(t):
    """det G for a 2×2 G, written with traces: ((tr G)² − tr G²)/2 (so the dimension-free method can read it)."""
    g = G(t)
    return (t.tr(g) * t.tr(g) - t.tr(g @ g)) / 2


@claim("h81b-r2-invariants-involution-traces", paper=("SO(n)-inv", "com", "ET"), kind="pb", section="2", sizes=R2)
def r2_invariants_involution_traces(s):
    """h81b-r2-invariants-involution with det PᵀP written ((tr G)² − tr G²)/2 (valid at r = 2)."""
    return {"{tr G, det G}": s.bracket(trG, detG_traces), "{det G, tr K^2}": s.bracket(detG_traces, trK2)}


@claim("n81b-r2-trace-g2-k2", kind="pb", section="2", sizes=R2, fails_at=lambda n, r: n > 2,
       erratum="twin: tr(G K) ... (PᵀP)₁₁ replaced by a non-invariant trace tr(G C) with C generic")
def r2_trace_gc(s):
    """Twin: tr(G C), C a generic symmetric 2×2 (not SO(2)-invariant), in place of det G: {tr GC, tr K²} = 0."""
    C = s.generic("C", "r", "r", "sym")
    return {"{tr GC, tr K^2}": s.bracket(lambda t: t.tr(G(t) @ C), trK2)}
