"""Round 4b: more Inverse statements — a resolvent at a moving μ, a division hidden in a function the
engine differentiates, a map that is not linear, an inverse valid only at r = 1 — and one true statement
(a triangular map that is not linear) that must not be answered `fails`."""
from stiefelsym import Inverse, admissible, claim

SIZES = admissible(n_max=3)


def _norm(t):
    return t.tr(t.P.T @ t.P)


@claim("adv-s34b-inv-resolvent", kind="id", sizes=SIZES)
def resolvent_at_the_norm(s):
    """x ↦ (tr(PᵀP)I − A)x on R^{n×r}, inverted by the resolvent R(tr PᵀP): singular where tr PᵀP is an
    eigenvalue of A."""
    return {"inv": Inverse(lambda t, x: (_norm(t) * t.In - t.A) @ x, lambda t, y: t.resolvent(_norm(t)) @ y,
                           on="R^{n×r}")}


@claim("adv-s34b-inv-hidden-quotient", kind="id", sizes=SIZES)
def derivative_of_a_quotient(s):
    """x ↦ d(1/tr PᵀP)(0, P)·x = −2x/tr(PᵀP) on Sym(r), inverted by −tr(PᵀP)y/2 (a polynomial): op is
    not defined at P = 0 (its division is inside the function the engine differentiates)."""
    def op(t, x):
        c = t.d(lambda u: 1 / _norm(u), {"X": t.X - t.X, "P": t.P})
        return c * x

    def inv(t, y):
        return -(_norm(t) * y) / 2
    return {"inv": Inverse(op, inv, on="Sym(r)")}


@claim("adv-s34b-inv-hidden-flow", kind="id", sizes=SIZES)
def flow_of_a_quotient(s):
    """x ↦ tr(PᵀẊ_H)·x = −2x/tr(PᵀP) on Sym(r), Ẋ_H the Dirac flow of H = 1/tr(PᵀP) (the division is in
    the Hamiltonian), inverted by −tr(PᵀP)y/2: op is not defined at P = 0."""
    def op(t, x):
        flow = t.dirac_flow(lambda u: 1 / _norm(u))
        c = t.tr(t.P.T @ flow.Xdot)          # = −2/tr(PᵀP) on T*V
        return c * x

    def inv(t, y):
        return -(_norm(t) * y) / 2
    return {"inv": Inverse(op, inv, on="Sym(r)")}


@claim("adv-s34b-inv-not-linear", kind="id", sizes=SIZES)
def plus_its_square(s):
    """x ↦ x + x² on Sym(r) (not injective: 0 and −I), "inverted" by y − y²."""
    return {"inv": Inverse(lambda t, x: x + x @ x, lambda t, y: y - y @ y, on="Sym(r)")}


@claim("adv-s34b-inv-r1-only", kind="id", sizes=SIZES)
def commutator_dropped(s):
    """x ↦ x + Kx − xK on Sym(r) (K = XᵀP), inverted by the identity: true at r = 1 only (K = 0 there)."""
    def op(t, x):
        K = t.X.T @ t.P
        return x + K @ x - x @ K
    return {"inv": Inverse(op, lambda t, y: y, on="Sym(r)")}


@claim("adv-s34b-inv-triangular-true", kind="id", sizes=SIZES)
def triangular(s):
    """True: (a, b) ↦ (a, b + a²) on Sym(r) × Sym(r), inverted by (c, d) ↦ (c, d − c²): a bijection
    that is not linear."""
    return {"inv": Inverse(lambda t, a, b: (a, b + a @ a), lambda t, c, d: (c, d - c @ c), on=("Sym(r)", "Sym(r)"))}
