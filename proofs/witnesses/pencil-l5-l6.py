"""The proof of Lemma 6.3 (condition (A2)) says that the solutions (xi1, eta1) in so(r,C)_{h1} + Sym(r)
of (16) §6 [A1, xi1] - [h1, eta1] = 0 and (17) §6 [A1, eta1] in so(r,C)^perp form an r-dimensional space.
so(r)^perp = Sym(r) and [A1, eta1] is skew, so the printed (17) §6 says [A1, eta1] = 0, and for r >= 3 the
solutions form a 2-dimensional space: the system has rank (unknowns - 2), not (unknowns - r).  The
correction: (17) §6 [A1, eta1] perp so(r,C)_{h1} (what pairing with the Cartan subalgebra gives); with it
the solutions are r-dimensional, as the proof says."""
import sympy as sp

KIND = "count"
CHECK = "rank of (16), (17) §6"
SIZE = (3, 3)
#: the proof states the dimension of the kernel of the system: the quantity, the number of unknowns, the system
KERNEL = ("the dimension of the solutions (ξ₁, η₁) ∈ so(r)_{h₁} ⊕ Sym(r) of (16), (17) §6", 7,
          "(16), (17) §6 as printed, a linear system in the 7 coordinates of (ξ₁, η₁)")


def counts():
    n, r = SIZE
    unit = lambda i, j: sp.Matrix(r, r, lambda a, b: int((a, b) == (i, j)))
    br = lambda a, b: a * b - b * a
    A1 = sp.diag(1, 2, 4)                                   # A1 = diag(a_1, ..., a_r), distinct a_i
    h1 = sp.Matrix([[0, 1, 2], [-1, 0, 3], [-2, -3, 0]])    # a generic element of so(r)
    cartan = [h1]                                           # so(r)_{h1} = span{h1} for r = 3 (odd powers of h1)
    assert all(br(c, h1) == sp.zeros(r, r) for c in cartan)
    zero = sp.zeros(r, r)
    unknowns = [(c, zero) for c in cartan] + \
               [(zero, unit(a, b) + unit(b, a) if a != b else unit(a, a)) for a in range(r) for b in range(a, r)]

    def system(printed):
        cols = []
        for xi1, eta1 in unknowns:
            eq16 = br(A1, xi1) - br(h1, eta1)                     # (16) §6
            C = br(A1, eta1)
            eq17 = list(C) if printed else [(C * c).trace() for c in cartan]   # (17) §6: C = 0, or C perp so(r)_{h1}
            cols.append(list(eq16) + eq17)
        return sp.Matrix(cols).T
    N = len(unknowns)                                       # dim so(r)_{h1} + dim Sym(r) = 1 + 6
    assert N == KERNEL[1]
    return {"computed": system(True).rank(),                # (16), (17) §6 as printed
            "printed": N - r,                               # the proof: r-dimensional solutions
            "corrected": N - r,                             # the same count, for the corrected (17) §6
            "corrected_computed": system(False).rank(),     # (16) §6 with the corrected (17) §6
            "meaning": "the rank of (16) §6 with the printed (17) §6 on so(r)_{h₁} ⊕ Sym(r) (7 unknowns); "
                       "7 − rank = the dimension of its solutions"}
