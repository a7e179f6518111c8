"""The metric realization of T*V in the free algebra: XᵀX = I_r, XᵀA⁻¹P + PᵀA⁻¹X = 0 (cond_XP2), A
symmetric positive definite, and the multipliers of its Dirac flows.

The rules are XᵀX → I_r, PᵀA⁻¹X → −XᵀA⁻¹P, AA⁻¹ → I_n, A⁻¹A → I_n (deg-lex with X < P < A < Xᵀ < Pᵀ <
A⁻¹: every rule decreases); their critical pairs resolve (the tests), so the system is confluent.

The Dirac flow of H is Ẋ = H_P − A⁻¹XΠ, Ṗ = −H_X + XΛ + A⁻¹PΠ (the flow of H + ½⟨Λ, XᵀX⟩ −
½⟨Π, XᵀA⁻¹P + PᵀA⁻¹X⟩ for the canonical bracket, symmetric Λ, Π).  Its multipliers solve Sylvester
equations with the matrix M = XᵀA⁻¹X, positive definite (A⁻¹ is, and X has rank r):

- keeping XᵀX = I_r:  ΠM + MΠ = H_PᵀX + XᵀH_P.  When the right-hand side reduces to 0, Π = 0: the map
  Π ↦ ΠM + MΠ is invertible (its eigenvalues are the sums m_i + m_j > 0 of eigenvalues of M).  When it
  does not, the free algebra has no closed form for Π and the flow is refused.
- keeping XᵀA⁻¹P + PᵀA⁻¹X = 0 (with Π = 0):  ρ = ΛM + MΛ − C = 0, C free of Λ, symmetric.  Λ is not a
  closed form: it stays a symmetric letter, the unique solution of ρ = 0 (symmetric since ρᵀ = ρ), and ρ
  joins the ideal as a generator ("rho:Λ").

ρ is used by one step on words, ΛM → −MΛ + C (one certificate term u·ρ·v each), never inside a trace
(where ΛM and MΛ are one cyclic word and the step would not end).  It moves a Λ to the right past M, or
removes it: with C free of Λ, the word's Λ count, then the lengths of its pieces after each Λ read from
the right, decrease, so the steps end; :meth:`FreeScene.reduce` alternates them with the rules.  The
normal forms are not unique then (a nonzero one proves nothing, as always).
"""
from __future__ import annotations

from dataclasses import dataclass

import symengine as se

from stiefelsym.free.algebra import SCALAR, Letter, NCPoly, derivation, mark_moving, symmetric_letter
from stiefelsym.free.rewriting import Certificate, CertTerm, Cofactor, Hypothesis, Order, RewritingSystem, Rule, cofactor_sum, simplify_coef
from stiefelsym.free.letters import AINV, A, FreeSolveError, P, Pt, X, Xt, _by, _holds_letter, hypothesis

#: the name of the hypothesis XᵀA⁻¹P + PᵀA⁻¹X (the second constraint of the metric realization)
METRIC_HYP = "XtAinvP+PtAinvX"
COND_XAP = "X^T A^(-1) P + P^T A^(-1) X = 0 (cond_XP2)"
COND_XX = "X^T X = I_r (cond_XP2)"
#: what every proof in the metric realization uses besides the rules (for reports)
SYLVESTER_TEXT = ("A symmetric positive definite (A^(-1) is, so M = X^T A^(-1) X is, X having rank r): a "
                  "Sylvester equation Y M + M Y = C has one solution, symmetric when C is")


def _w(*letters: Letter) -> NCPoly:
    return NCPoly.word(letters)


_METRIC_RULES: tuple | None = None


def metric_rules() -> tuple:
    """The rules of (cond_XP2) and of A⁻¹, built once (their types, order and cofactors checked)."""
    global _METRIC_RULES
    if _METRIC_RULES is None:
        system = RewritingSystem(Order([X, P, A, Xt, Pt, AINV]))
        system.add_rule((Xt, X), NCPoly.identity("r"), COND_XX, name="XtX", cofactors=[_by(hypothesis("XtX"))])
        system.add_rule((Pt, AINV, X), -_w(Xt, AINV, P), COND_XAP, name="PtAinvX",
                        cofactors=[_by(hypothesis(METRIC_HYP))])
        system.add_rule((A, AINV), NCPoly.identity("n"), "A A^(-1) = I_n", name="AAinv",
                        cofactors=[_by(hypothesis("AAinv"))])
        system.add_rule((AINV, A), NCPoly.identity("n"), "A^(-1) A = I_n", name="AinvA",
                        cofactors=[_by(hypothesis("AinvA"))])
        _METRIC_RULES = tuple(system.rules)
    return _METRIC_RULES


def metric_system() -> RewritingSystem:
    """(cond_XP2) and A A⁻¹ = A⁻¹ A = I_n as rules, a fresh system on the shared, checked rules."""
    return RewritingSystem(Order([X, P, A, Xt, Pt, AINV]), metric_rules())


def constraint_polys() -> list[tuple[NCPoly, str]]:
    """The constraints of the metric realization (polynomials that vanish on T*V) with their text."""
    return [(_w(Xt, X), COND_XX), (_w(Xt, AINV, P) + _w(Pt, AINV, X), COND_XAP)]


@dataclass(frozen=True)
class SylvesterMultiplier:
    """The multiplier Λ of a Dirac flow of the metric realization: the unique solution of ρ = 0."""

    letter: Letter
    Xdot: NCPoly
    Pdot: NCPoly
    #: ρ = ΛM + MΛ − C = d/dt (XᵀA⁻¹P + PᵀA⁻¹X) along the flow (reduced)
    relation: NCPoly
    hypothesis: Hypothesis
    #: ΛM → −MΛ + C (words only), its cofactor ρ
    rule: Rule
    #: d/dt XᵀX along the flow (Π = 0), as derived, through the hypotheses (its normal form is 0)
    keeps_certificate: Certificate
    #: the constraint whose preservation gives ρ (the name of its hypothesis)
    hypothesis_of_constraint: str = METRIC_HYP
    #: d/dt (XᵀA⁻¹P + PᵀA⁻¹X) along the flow, as derived, minus ρ (its normal form), through the hypotheses of
    #: the constraints (normal form 0): ρ is the derivative on T*V, reduced by the rules
    relation_certificate: Certificate | None = None


_LAMBDAS = [0]


def sylvester_letter() -> Letter:
    """A fresh symmetric r×r letter Λ for the multiplier of one flow."""
    _LAMBDAS[0] += 1
    k = _LAMBDAS[0]
    # a function of the point no derivation of the free scene knows: every derivative of a polynomial
    # that holds it is refused
    return mark_moving(symmetric_letter(f"Lambda:{k}", "r", rf"\Lambda_{{{k}}}"))


def metric_multipliers(system: RewritingSystem, HX: NCPoly, HP: NCPoly,
                       known: dict[Letter, SylvesterMultiplier]) -> SylvesterMultiplier:
    """The Dirac flow of the gradient (H_X, H_P) on (cond_XP2): Π = 0 when its Sylvester equation has the
    right-hand side 0 (else FreeSolveError), Λ a fresh letter with its relation ρ (FreeSolveError when ρ is
    not ΛM + MΛ − C with C free of Λ, symmetric and without traces)."""
    nf = system.normal_form
    x, ainv = _w(X), _w(AINV)
    M = _w(Xt, AINV, X)
    # keeping X^T X = I_r along Xdot = H_P - A^{-1} X Pi:  H_P^T X + X^T H_P - (Pi M + M Pi)
    Pi = symmetric_letter("Pi:metric", "r", r"\Pi")
    Xd_pi = HP - ainv * x * _w(Pi)
    keeps = nf(Xd_pi.star() * x + x.star() * Xd_pi)
    rhs = nf(keeps + _w(Pi) * M + M * _w(Pi))
    if _holds_letter(rhs, Pi):
        raise FreeSolveError(f"the equation of the multiplier Pi of X^T X = I_r is not Pi M + M Pi = (free of Pi): "
                             f"{keeps}")
    if rhs.terms:
        raise FreeSolveError("the multiplier Pi of X^T X = I_r solves Pi M + M Pi = S with M = X^T A^(-1) X and "
                             f"S = {rhs} not 0 in the free algebra: no closed form")
    for L in known:
        if _holds_letter(HX, L) or _holds_letter(HP, L):
            raise FreeSolveError(f"a Hamiltonian that holds the multiplier {L} of another flow")
    Lam = sylvester_letter()
    Xd = nf(HP)
    Pd = nf(-HX + x * _w(Lam))
    images = {X: Xd, P: Pd}
    keeps = system.certify(derivation(_w(Xt, X), images))
    if keeps.normal_form.terms:   # (the same as S = 0 above: a self-check)
        raise FreeSolveError("the flow with Pi = 0 does not keep X^T X = I_r")
    derived = derivation(_w(Xt, AINV, P) + _w(Pt, AINV, X), images)
    rho = nf(derived)
    linked = system.certify(derived, rho)
    relation_certificate = Certificate(derived - rho, NCPoly.zero("r", "r"), linked.terms)
    C = nf(_w(Lam) * M + M * _w(Lam) - rho)
    if _holds_letter(C, Lam):
        raise FreeSolveError(f"the equation of the multiplier Lambda of (cond_XP2) is not Lambda M + M Lambda = C "
                             f"with C free of Lambda: {rho}")
    if any(tm for tm, _w2 in C.terms):
        raise FreeSolveError("the Sylvester equation of the multiplier Lambda has traces in its right-hand side "
                             "(not supported by the certificates)")
    if nf(rho.star() - rho).terms:
        raise FreeSolveError(f"the right-hand side of the Sylvester equation of Lambda is not symmetric: {C}")
    hyp = Hypothesis(f"rho:{Lam}", rho)
    lhs = (Lam, Xt, AINV, X)
    rule_rhs = C - M * _w(Lam)
    cofactors = (Cofactor(se.Integer(1), (), hyp, ()),)
    gap = _w(*lhs) - rule_rhs - cofactor_sum(cofactors, "r", "r")
    if any(simplify_coef(c) != 0 for c in gap.expand().terms.values()):
        raise FreeSolveError(f"the step of Lambda does not match its relation (misses {gap})")
    reason = (f"{Lam} is the solution of {Lam} M + M {Lam} = C, M = X^T A^(-1) X (unique and symmetric: "
              "M positive definite, C symmetric); C from the flow keeping (cond_XP2)")
    rule = Rule(f"rho:{Lam}", lhs, rule_rhs, reason, cofactors)
    return SylvesterMultiplier(Lam, Xd, Pd, rho, hyp, rule, keeps, relation_certificate=relation_certificate)


def _find(w: tuple, lhs: tuple) -> int | None:
    k = len(lhs)
    for i in range(len(w) - k + 1):
        if w[i:i + k] == lhs:
            return i
    return None


def sylvester_step(p: NCPoly, multipliers: dict[Letter, SylvesterMultiplier]) -> tuple[NCPoly, list[CertTerm],
                                                                                        list[Rule]]:
    """(q, terms, rules): every word of p (outside traces) with one occurrence of ΛM replaced by −MΛ + C, the
    leftmost, and p − q = Σ terms (each c·T·u·ρ·v); ``rules`` the steps used."""
    if not multipliers:
        return p, [], []
    rules = [m.rule for m in multipliers.values()]
    out = NCPoly.zero(p.row, p.col)
    cert: list[CertTerm] = []
    used: list[Rule] = []
    for (tm, w), c in p.terms.items():
        hit = None
        for rule in rules:
            i = _find(w, rule.lhs)
            if i is not None and (hit is None or i < hit[0]):
                hit = (i, rule)
        if hit is None:
            out = out + NCPoly({(tm, w): c}, p.row, p.col)
            continue
        i, rule = hit
        if rule not in used:
            used.append(rule)
        left, right = w[:i], w[i + len(rule.lhs):]
        factor = NCPoly({(tm, ()): c}, SCALAR, SCALAR)
        out = out + factor * (NCPoly.word(left, p.row) * rule.rhs * NCPoly.word(right, rule.lhs[-1].col))
        cert.append(CertTerm(c, left, rule.cofactors[0].hyp, right, False, tm, ()))
    return out, cert, used
