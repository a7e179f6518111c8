"""Proposition 4.6: a quadratic form on T*_{X0}V invariant under (SO(n-r)-action) and
P1 -> Q^{-1} P1 Q, P2 -> P2 Q (Q in SO(r)), P0 = (P1; P2) as in (P-neutral), is a combination of
tr(P^T P) and tr((X^T P)^2).  At (n, r) = (4, 2) (n - r = r = 2) det P2 is a third invariant form.
The correction counts also det P2 (and the Pfaffian of P1 for r = 4, <axial(P1), P2> for n - r = 1, r = 3)."""
import itertools
import sympy as sp

KIND = "count"
CHECK = "invariant forms"
SIZE = (4, 2)
#: the proposition counts the kernel of the invariance conditions: the quantity, the number of unknowns, the system
KERNEL = ("the number of independent invariant quadratic forms on the fibre", 15,
          "the invariance conditions on the 15 coefficients of a quadratic form on the 5-dimensional fibre")


def counts():
    n, r = SIZE
    p = sp.Symbol("p")
    P1 = sp.Matrix([[0, p], [-p, 0]])                                 # P1^T = -P1 (cond_XP at X0)
    P2 = sp.Matrix(n - r, r, lambda i, j: sp.Symbol(f"q{i}{j}"))
    P0 = P1.col_join(P2)                                              # (P-neutral)
    X0 = sp.eye(n)[:, :r]                                             # X0 = (E_1, ..., E_r)
    c = [p] + list(P2)                                                # the 5 fibre coordinates
    pairs = list(itertools.combinations_with_replacement(range(len(c)), 2))
    G = sp.symbols(f"g0:{len(pairs)}")                                # the 15 coefficients
    assert len(G) == KERNEL[1]
    q = sum(g * c[i] * c[j] for g, (i, j) in zip(G, pairs))           # a quadratic form on the fibre
    unit = lambda m, i, j: sp.Matrix(m, m, lambda a, b: int((a, b) == (i, j)))
    so = lambda m: [unit(m, i, j) - unit(m, j, i) for i in range(m) for j in range(i + 1, m)]
    flows = [(P1 * e - e * P1, P2 * e) for e in so(r)]                # P1 -> Q^{-1}P1Q, P2 -> P2Q
    flows += [(sp.zeros(r, r), b * P2) for b in so(n - r)]            # (SO(n-r)-action): P2 -> BP2
    eqs = []
    for d1, d2 in flows:                                              # d/dt q along each one-parameter subgroup
        dq = sp.expand(sp.diff(q, p) * d1[0, 1] + sum(sp.diff(q, x) * dx for x, dx in zip(list(P2), list(d2))))
        eqs += sp.Poly(dq, *c).coeffs()
    M, _ = sp.linear_eq_to_matrix(eqs, G)
    rank = M.rank()                                                   # kernel = the invariant quadratic forms

    def coeffs(f):                                                    # a quadratic form as a vector in the G basis
        f = sp.Poly(sp.expand(f), *c)
        return [f.coeff_monomial(c[i] * c[j]) for i, j in pairs]
    printed_forms = [(P0.T * P0).trace(), ((X0.T * P0) ** 2).trace()]  # tr(P^T P), tr((X^T P)^2)
    extra = [P2.det()]                                                 # n - r = r = 2: det P2
    for f in extra:                                                    # det P2 is invariant: M g = 0
        assert M * sp.Matrix(coeffs(f)) == sp.zeros(M.rows, 1)
    span = sp.Matrix([coeffs(f) for f in printed_forms]).rank()
    span_corr = sp.Matrix([coeffs(f) for f in printed_forms + extra]).rank()
    return {"computed": rank, "printed": len(G) - span, "corrected": len(G) - span_corr,
            "meaning": "the rank of the invariance conditions on the 15 coefficients of a quadratic form on "
                       "the 5-dimensional fibre (15 - rank = the number of independent invariant forms)"}
