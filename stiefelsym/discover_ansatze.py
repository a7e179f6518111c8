"""The search spaces of the paper's corrections: for each printed formula that fails, the formulas of
its shape (every term of the same type and degree, in the scene's letters and the resolvents the
printed formula uses), searched by :func:`stiefelsym.discover.correction_space`.

Each ansatz is built on first use from the catalog's own functions; nothing here is a claim."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable

from .claims import Size
from .discover import CorrectionAnsatz, Factor, _catalog_module, sandwich_terms
from .matrix import comm

ONE = Fraction(1)


def _outer(text: str, latex: str, key: str, transpose: bool = False) -> Factor:
    if transpose:
        return Factor(text, latex, lambda s, w: w[key].T)
    return Factor(text, latex, lambda s, w: w[key])


def _middles(s_inverse: tuple[str, str, Callable[[Any], Any]] | None = None) -> list[Factor]:
    """The middle factors M of UᵀMV: I_n, A, λI_n, λA, the printed resolvent (if any) and (λI_n − A)⁻¹."""
    out = [Factor("", "", lambda s: s.In),
           Factor("A", "A", lambda s: s.A),
           Factor("", "", lambda s: s.In * s.lam, "λ·", r"\lambda "),
           Factor("A", "A", lambda s: s.A * s.lam, "λ·", r"\lambda ")]
    if s_inverse is not None:
        out.append(Factor(s_inverse[0], s_inverse[1], s_inverse[2]))
    out.append(Factor("(λI_n − A)⁻¹", r"(\lambda\mathbf I_n-A)^{-1}", lambda s: s.resolvent(s.lam)))
    return out


def _resolvent_last(pos, U, M, V) -> int:
    return 1 if "⁻¹" in M.text else 0


def _zero_r(s):
    return s.zeros(s.r, s.r, ("r", "r"))


def _signed(pairs: dict[str, int], middle: Factor, prefix: str = "") -> dict[str, Fraction]:
    return {f"{prefix}{k.split('|')[0]}{middle}{k.split('|')[1]} in block {b}": Fraction(c)
            for k, (b, c) in pairs.items()}


# -- (MAN-LA): the dual Lax pair of the Manakov flows ------------------------------------------------

def manakov_dual_lax() -> CorrectionAnsatz:
    """𝓐*_man(λ) of (LA-MAN3), every block a combination of UᵀMV (U, V ∈ {X, P})."""
    sec4 = _catalog_module("sec4_integrability")
    X, P = _outer("X", "X", "X"), _outer("P", "P", "P")
    Xt, Pt = _outer("Xᵀ", "X^T", "X", True), _outer("Pᵀ", "P^T", "P", True)
    inverse = ("(A + λI_n)⁻¹", r"(A+\lambda\mathbf I_n)^{-1}", lambda s: sec4.inverse_of_A_plus_lambda(s))
    pattern = {(0, 0): ("Xᵀ", "P"), (0, 1): ("Xᵀ", "X"), (1, 0): ("Pᵀ", "P"), (1, 1): ("Pᵀ", "X")}

    def preferred(pos, U, M, V):
        return 2 * ("⁻¹" in M.text) + (pattern[pos] != (U.text, V.text))
    terms = sandwich_terms([Xt, Pt], [P, X], _middles(inverse), list(pattern), (2, 2), _zero_r, preferred,
                           identities={"XᵀX": ("I_r", r"\mathbf I_r")})

    def residual(s, slot):
        flow = s.dirac_flow(sec4.H_manakov_square)
        return s.d(sec4.L_man_dual, flow) - comm(sec4.L_man_dual(s), slot(s, {"X": s.X, "P": s.P}))
    sign = {(0, 0): 1, (0, 1): 1, (1, 0): -1, (1, 1): -1}

    def coeffs(middles: list[tuple[str, str]]) -> dict[str, Fraction]:
        word = {"XᵀX": "I_r"}
        return {f"{pre}{word.get(pattern[b][0] + mid + pattern[b][1], pattern[b][0] + mid + pattern[b][1])} "
                f"in block ({b[0] + 1},{b[1] + 1})": Fraction(sign[b])
                for b in pattern for pre, mid in middles}
    return CorrectionAnsatz(
        claim="manakov-dual-lax", label="(MAN-LA)", slot="𝓐*_man(λ)", slot_latex=r"\mathcal A^*_{man}(\lambda)",
        terms=terms, residual=residual, point=lambda s: {"X": s.X, "P": s.P},
        description="of 2r×2r block matrices, each block Σ c·UᵀMV, U, V ∈ {X, P}, "
                    "M ∈ {I_n, A, λI_n, λA, (A + λI_n)⁻¹, (λI_n − A)⁻¹}",
        description_latex=r"each block $\sum c\,U^TMV$, $U,V\in\{X,P\}$, $M\in\{\mathbf I_n,A,\lambda\mathbf I_n,"
                          r"\lambda A,(A+\lambda\mathbf I_n)^{-1},(\lambda\mathbf I_n-A)^{-1}\}$",
        printed=coeffs([("", "(A + λI_n)⁻¹")]), registered=coeffs([("", "A"), ("λ·", "")]),
        size=Size(3, 2), blocks=(2, 2))


#: the paper's corrections searched as solution spaces: claim id -> the ansatz builder
CORRECTIONS: dict[str, Callable[[], CorrectionAnsatz]] = {
    "manakov-dual-lax": manakov_dual_lax,
}
