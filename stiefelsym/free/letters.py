"""The letters of the dimension-free scenes and the hypotheses of their ideals.

The point (X, P) of T*V and the second point (Y, Q), A and A⁻¹, the generic points of the double and the
complex systems, the multipliers; :func:`hypothesis` rebuilds each generator of the ideal of relations
from its name (every rule's lhs − rhs is a combination of them, and a certificate names them).  Shared by
the scene (:mod:`.scene`) and the metric realization (:mod:`.metric`), neither of which the other imports
at module level through this one.
"""
from __future__ import annotations

from typing import Any

from stiefelsym.free.algebra import Letter, NCPoly, OperatorLetter, as_coef, letter_pair, skew_letter, symmetric_letter
from stiefelsym.free.columns import SREF, column_hypotheses
from stiefelsym.free.rewriting import Cofactor, Hypothesis

X, Xt = letter_pair("X", "Xt", "n", "r", "X", "X^{T}")
P, Pt = letter_pair("P", "Pt", "n", "r", "P", "P^{T}")
A = symmetric_letter("A", "n", "A")
Y, Yt = letter_pair("Y", "Yt", "n", "r", "Y", "Y^{T}")
Q, Qt = letter_pair("Q", "Qt", "n", "r", "Q", "Q^{T}")
AINV = symmetric_letter("Ainv", "n", "A^{-1}")
#: a generic point (X, Y, Ẋ, Ẏ) of the double Neumann system: XᵀY = I_r, ẊᵀY + XᵀẎ = 0
DX, DXt = letter_pair("DX", "DXt", "n", "r", "X", "X^{T}")
DY, DYt = letter_pair("DY", "DYt", "n", "r", "Y", "Y^{T}")
DXd, DXdt = letter_pair("DXd", "DXdt", "n", "r", r"\dot X", r"\dot X^{T}")
DYd, DYdt = letter_pair("DYd", "DYdt", "n", "r", r"\dot Y", r"\dot Y^{T}")
DOUBLE = {"X": DX, "Y": DY, "Xdot": DXd, "Ydot": DYd}
#: a generic point (Z, Ż) of the tangent bundle of the complex Stiefel variety W(n, r), realified:
#: Z = U + iV, Ż = U̇ + iV̇ with U, V, U̇, V̇ real n×r letters, Z̄ᵀZ = I_r and Z̄ᵀŻ + Ż̄ᵀZ = 0, i.e.
#: UᵀU + VᵀV = I_r, UᵀV − VᵀU = 0 and their derivatives (real and imaginary parts)
CU, CUt = letter_pair("U", "Ut", "n", "r", "U", "U^{T}")
CV, CVt = letter_pair("V", "Vt", "n", "r", "V", "V^{T}")
CUd, CUdt = letter_pair("Ud", "Udt", "n", "r", r"\dot U", r"\dot U^{T}")
CVd, CVdt = letter_pair("Vd", "Vdt", "n", "r", r"\dot V", r"\dot V^{T}")
#: the keys of a complex point and the letters (real part, imaginary part) of each
COMPLEX = {"Z": (CU, CV), "Zdot": (CUd, CVd)}
#: the hypotheses of the complex point: Re and Im of Z̄ᵀZ − I_r and of its derivative
COMPLEX_HYPOTHESES = ("UtU+VtV", "UtV-VtU", "UdtU+UtUd+VdtV+VtVd", "UdtV+UtVd-VdtU-VtUd")
#: the multipliers of Z̄ᵀZ = I_r in the Euler–Lagrange equations on W(n, r): a Hermitian r×r matrix, its
#: real (symmetric) part and its imaginary (skew) part
W0_RE = symmetric_letter("SigmaW", "r", r"\Sigma")
W0_IM = skew_letter("KappaW", "r", r"K")
PI = symmetric_letter("Pi", "r", r"\Pi")
LAMBDA = symmetric_letter("Lambda", "r", r"\Lambda")


class FreeSolveError(ArithmeticError):
    """Lagrange multipliers that are not of the form c·Π + (terms free of Π) = 0."""


def _i(t: str) -> NCPoly:
    return NCPoly.identity(t)


def _w(*letters: Letter) -> NCPoly:
    return NCPoly.word(letters)


# ---------------------------------------------------------------------------
# the hypotheses: every rule's lhs − rhs is a combination of these (its cofactors), and a
# certificate names them; the independent checker rebuilds each from its name
def hypothesis(name: str, R: Letter | None = None, mu: Any = None) -> Hypothesis:
    """The generator of the ideal of relations called ``name`` (``res_left``/``res_right``
    take the resolvent letter R = (mu I_n − A)^{-1})."""
    if name in ("res_left", "res_right"):
        mu = as_coef(mu)
        shifted = _i("n") * mu - _w(A)
        poly = (shifted * _w(R) if name == "res_left" else _w(R) * shifted) - _i("n")
        return Hypothesis(f"{name}:{R}", poly)
    polys = {
        "XtX": lambda: _w(Xt, X) - _i("r"),
        "XtP+PtX": lambda: _w(Xt, P) + _w(Pt, X),
        "XtAinvP+PtAinvX": lambda: _w(Xt, AINV, P) + _w(Pt, AINV, X),
        "YtY": lambda: _w(Yt, Y) - _i("r"),
        "YtQ+QtY": lambda: _w(Yt, Q) + _w(Qt, Y),
        "AAinv": lambda: _w(A, AINV) - _i("n"),
        "AinvA": lambda: _w(AINV, A) - _i("n"),
        "XXt": lambda: _w(X, Xt) - _i("n"),
        "SrefA": lambda: _w(SREF, A) - _w(A, SREF),
        "DXtDY": lambda: _w(DXt, DY) - _i("r"),
        "DYtDX": lambda: _w(DYt, DX) - _i("r"),
        "DXdtDY+DXtDYd": lambda: _w(DXdt, DY) + _w(DXt, DYd),
        "DYtDXd+DYdtDX": lambda: _w(DYt, DXd) + _w(DYdt, DX),
        "UtU+VtV": lambda: _w(CUt, CU) + _w(CVt, CV) - _i("r"),
        "UtV-VtU": lambda: _w(CUt, CV) - _w(CVt, CU),
        "UdtU+UtUd+VdtV+VtVd": lambda: _w(CUdt, CU) + _w(CUt, CUd) + _w(CVdt, CV) + _w(CVt, CVd),
        "UdtV+UtVd-VdtU-VtUd": lambda: _w(CUdt, CV) + _w(CUt, CVd) - _w(CVdt, CU) - _w(CVt, CUd),
    }
    if name not in polys:
        return column_hypotheses()[name]
    return Hypothesis(name, polys[name]())


def _by(h: Hypothesis, coef: Any = 1, left: tuple = (), right: tuple = ()) -> Cofactor:
    return Cofactor(as_coef(coef), tuple(left), h, tuple(right))



def _holds_letter(p: NCPoly, L: Letter) -> bool:
    """L or its transpose occurs in p (in a word, a trace, or an operator letter's argument)."""
    def hit(letters) -> bool:
        return any(x == L or x == L.adjoint or (isinstance(x, OperatorLetter) and hit(x.argument)) for x in letters)
    return any(hit(w) or any(hit(c) for c in tm) for tm, w in p.terms)
