"""The operator letter 𝔸 of the dimension-free algebra (sym_operator) used every way its rules could be
wrong: it sees the skew part of its argument (𝔸(ξζ) = ½𝔸([ξ, ζ]), 𝔸(Gᵀ) = −𝔸(G), 𝔸(A) = 0), its values
are skew, it is symmetric for ⟨,⟩; it does not commute with ad_A, with another operator, or with
conjugation by X (so(r) against so(n)), and two names are two operators.  The true claims are proved
by free and pass the fixed-size methods; the false ones fail there, and free proves none of them.
"""
from stiefelsym import admissible, claim

ALL = admissible(n_max=4, n_min=2)
@claim("adv-opx-skewpart-true", kind="id", sizes=ALL)
def a(s):
    AA = s.sym_operator("AA")
    return {"v": AA(s.xi @ s.zeta) - AA(s.xi @ s.zeta - s.zeta @ s.xi) * s.q(1, 2)}


@claim("adv-opx-skewpart-false", kind="id", sizes=ALL)
def b(s):
    AA = s.sym_operator("AA")
    return {"v": AA(s.xi @ s.zeta) - AA(s.xi @ s.zeta - s.zeta @ s.xi)}


@claim("adv-opx-transpose-true", kind="id", sizes=ALL)
def c(s):
    AA = s.sym_operator("AA")
    G = s.generic("G", "n", "n")
    return {"v": AA(G.T) + AA(G)}


@claim("adv-opx-transpose-false", kind="id", sizes=ALL)
def d(s):
    AA = s.sym_operator("AA")
    G = s.generic("G", "n", "n")
    return {"v": AA(G.T) - AA(G)}


@claim("adv-opx-output-skew-true", kind="id", sizes=ALL)
def e(s):
    AA = s.sym_operator("AA")
    return {"v": AA(s.xi).T + AA(s.xi)}


@claim("adv-opx-output-sym-false", kind="id", sizes=ALL)
def f(s):
    AA = s.sym_operator("AA")
    return {"v": AA(s.xi).T - AA(s.xi)}


@claim("adv-opx-A-zero-true", kind="id", sizes=ALL)
def g(s):
    return {"v": s.sym_operator("AA")(s.A)}


@claim("adv-opx-symmetric-true", kind="id", sizes=ALL)
def h(s):
    AA = s.sym_operator("AA")
    return {"v": s.killing(AA(s.xi), s.zeta) - s.killing(s.xi, AA(s.zeta))}


@claim("adv-opx-commutes-false", kind="id", sizes=ALL)
def i(s):
    AA = s.sym_operator("AA")
    return {"v": AA(s.A @ s.xi - s.xi @ s.A) - (s.A @ AA(s.xi) - AA(s.xi) @ s.A)}


@claim("adv-opx-composition-false", kind="id", sizes=ALL)
def j(s):
    AA, BB = s.sym_operator("AA"), s.sym_operator("BB")
    return {"v": AA(BB(s.xi)) - BB(AA(s.xi))}


@claim("adv-opx-scaled-name-false", kind="id", sizes=ALL)
def k(s):
    """AA and AA2 equal (false)"""
    return {"v": s.sym_operator("AA")(s.xi) - s.sym_operator("AA2")(s.xi)}


@claim("adv-opx-Phi-r-false", kind="id", sizes=ALL)
def m(s):
    """AA(Psi) on so(r) = X^T AA(Phi) X (false)"""
    AA = s.sym_operator("AA")
    return {"v": AA(s.Psi) - s.X.T @ AA(s.Phi) @ s.X}


@claim("adv-opx-trace-false", kind="id", sizes=ALL)
def o(s):
    """tr AA(xi) xi >= ... : tr(AA(xi) xi) = tr(AA(zeta) zeta) (false)"""
    AA = s.sym_operator("AA")
    return {"v": s.tr(AA(s.xi) @ s.xi) - s.tr(AA(s.zeta) @ s.zeta)}
