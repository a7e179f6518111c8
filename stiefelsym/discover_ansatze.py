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
from .systems import derivative

ONE = Fraction(1)


def _outer(text: str, latex: str, key: str, transpose: bool = False) -> Factor:
    if transpose:
        return Factor(text, latex, lambda s, w: w[key].T)
    return Factor(text, latex, lambda s, w: w[key])


def _middles(s_inverse: tuple[str, str, Callable[[Any], Any]] | None = None,
             wrap: Callable[[Any, Any], Any] = lambda s, M: M) -> list[Factor]:
    """The middle factors M of UᵀMV: I_n, A, λI_n, λA, the printed resolvent (if any) and (λI_n − A)⁻¹
    (each passed through ``wrap``, e.g. to realify it)."""
    out = [Factor("", "", lambda s: wrap(s, s.In)),
           Factor("A", "A", lambda s: wrap(s, s.A)),
           Factor("", "", lambda s: wrap(s, s.In * s.lam), "λ·", r"\lambda "),
           Factor("A", "A", lambda s: wrap(s, s.A * s.lam), "λ·", r"\lambda ")]
    if s_inverse is not None:
        f = s_inverse[2]
        out.append(Factor(s_inverse[0], s_inverse[1], lambda s: wrap(s, f(s))))
    out.append(Factor("(λI_n − A)⁻¹", r"(\lambda\mathbf I_n-A)^{-1}", lambda s: wrap(s, s.resolvent(s.lam))))
    return out


def _resolvent_last(pos, U, M, V) -> int:
    return 1 if "⁻¹" in M.text else 0


def _zero_r(s):
    return s.zeros(s.r, s.r, ("r", "r"))


def _at(block: tuple[int, int], word: str) -> str:
    return f"{word} in block ({block[0] + 1},{block[1] + 1})"


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
        size=Size(3, 2), blocks=(2, 2), free=True)


# -- (LA3*D) and (LA3*): the dual Lax pairs of the double and the complex Neumann systems ----------

FLIPPED = ("(I_n − λA)⁻¹", r"(\mathbf I_n-\lambda A)^{-1}")


def _flipped_value(s):
    return s.resolvent(s.q(1) / s.lam) / s.lam


def _off_diagonal_lax(claim: str, label: str, left, right, identity: tuple[str, str], wrap, zero, point,
                      diagonal, A_of, flow_of, realization: str = "standard") -> CorrectionAnsatz:
    """The off-diagonal blocks of 𝓛(λ) = [[−UᵀRV̇, B₁₂], [B₂₁, U̇ᵀRV]] searched, its diagonal blocks as printed."""
    from .ir import block
    middles = _middles((*FLIPPED, _flipped_value), wrap)
    pattern = {(0, 1): (left[0].text, right[0].text), (1, 0): (left[1].text, right[1].text)}

    def preferred(pos, U, M, V):
        return 2 * ("⁻¹" in M.text) + (pattern[pos] != (U.text, V.text))
    word = left[0].text + right[0].text
    terms = sandwich_terms(left, right, middles, list(pattern), (2, 2), zero, preferred,
                           identities={word: identity})

    def residual(s, slot):
        z = point(s)

        def L(t, w):
            D11, D22 = diagonal(t, w)
            return block([[D11, zero(t)], [zero(t), D22]]) + slot(t, w)
        return derivative(s, L, z, flow_of(s, z)) - comm(L(s, z), A_of(s, z))

    def coeffs(mid: str) -> dict[str, Fraction]:
        (u1, v1), (u2, v2) = pattern[(0, 1)], pattern[(1, 0)]
        return {_at((0, 1), u1 + mid + v1): -ONE, _at((1, 0), identity[0]): ONE, _at((1, 0), u2 + mid + v2): ONE}
    return CorrectionAnsatz(
        claim=claim, label=label, slot="the off-diagonal blocks of 𝓛(λ)",
        slot_latex=r"\text{the off-diagonal blocks of }\mathcal L(\lambda)", terms=terms, residual=residual,
        point=point,
        description=f"of the blocks (1,2), (2,1), each Σ c·UᵀMV, U ∈ {{{left[0].text}, {left[1].text}}}, "
                    f"V ∈ {{{right[0].text}, {right[1].text}}}, M ∈ {{I_n, A, λI_n, λA, {FLIPPED[0]}, (λI_n − A)⁻¹}}",
        description_latex=rf"blocks (1,2), (2,1), each $\sum c\,U^TMV$, $U\in\{{{left[0].latex},{left[1].latex}\}}$, "
                          rf"$V\in\{{{right[0].latex},{right[1].latex}\}}$, $M\in\{{\mathbf I_n,A,\lambda\mathbf I_n,"
                          rf"\lambda A,{FLIPPED[1]},(\lambda\mathbf I_n-A)^{{-1}}\}}$",
        printed=coeffs(FLIPPED[0]), registered=coeffs("(λI_n − A)⁻¹"), size=Size(3, 2), blocks=(2, 2),
        realization=realization)


def double_neumann_dual_lax() -> CorrectionAnsatz:
    """(LA3*D): the off-diagonal blocks of 𝓛(λ) for the double Neumann system (D-eq)."""
    from .systems import double_point
    app2 = _catalog_module("app2_double_coupled_complex")
    left = [_outer("Xᵀ", "X^T", "X", True), _outer("Ẋᵀ", r"\dot X^T", "Xdot", True)]
    right = [_outer("Y", "Y", "Y"), _outer("Ẏ", r"\dot Y", "Ydot")]

    def diagonal(t, w):
        R = t.resolvent(t.lam)
        return -(w["X"].T @ R @ w["Ydot"]), w["Xdot"].T @ R @ w["Y"]
    return _off_diagonal_lax("double-neumann-dual-lax", "(LA3*D)", left, right, ("I_r", r"\mathbf I_r"),
                             lambda s, M: M, _zero_r, double_point, diagonal, app2.A_dual_double, app2.flow_double)


def complex_neumann_dual_lax() -> CorrectionAnsatz:
    """(LA3*): the off-diagonal blocks of 𝓛(λ) for the Neumann system (W-eq) on W(n, r)."""
    from .systems import complex_point, ctranspose, realify_real
    app2 = _catalog_module("app2_double_coupled_complex")
    left = [Factor("Zᵀ", "Z^T", lambda s, w: ctranspose(s, w["Z"])),
            Factor("Żᵀ", r"\dot Z^T", lambda s, w: ctranspose(s, w["Zdot"]))]
    right = [Factor("Z̄", r"\bar Z", lambda s, w: s.conj(w["Z"])),
             Factor("Ż̄", r"\dot{\bar Z}", lambda s, w: s.conj(w["Zdot"]))]

    def diagonal(t, w):
        R = realify_real(t, t.resolvent(t.lam))
        Z, Zd = w["Z"], w["Zdot"]
        return -(ctranspose(t, Z) @ R @ t.conj(Zd)), ctranspose(t, Zd) @ R @ t.conj(Z)
    return _off_diagonal_lax("complex-neumann-dual-lax", "(LA3*)", left, right, ("I_r", r"\mathbf I_r"),
                             realify_real, lambda s: realify_real(s, _zero_r(s)), complex_point, diagonal,
                             app2.A_dual_complex, app2.flow_complex)


# -- (C-eq): the r-coupled Neumann system -----------------------------------------------------------

def coupled_neumann_flow() -> CorrectionAnsatz:
    """(C-eq): the last term of the equation for Q̇, among U·M, U ∈ {X, P, Y, Q}, M ∈ {Λ, Π}, and
    U·S, U ∈ {X, P, Y, Q}, S ∈ {XᵀAY, YᵀAX, PᵀP, QᵀQ, XᵀP, YᵀQ} (Λ, Π of (C-L))."""
    from .systems import coupled_point
    app2 = _catalog_module("app2_double_coupled_complex")
    letters = [("X", "X"), ("Y", "Y"), ("P", "P"), ("Q", "Q")]
    multipliers = [("Π", r"\Pi", lambda t, w: app2.Lambda_Pi_coupled(t, w)[1]),
                   ("Λ", r"\Lambda", lambda t, w: app2.Lambda_Pi_coupled(t, w)[0])]
    parts = [("XᵀAY", "X^TAY", lambda t, w: w["X"].T @ t.A @ w["Y"]),
             ("YᵀAX", "Y^TAX", lambda t, w: w["Y"].T @ t.A @ w["X"]),
             ("PᵀP", "P^TP", lambda t, w: w["P"].T @ w["P"]), ("QᵀQ", "Q^TQ", lambda t, w: w["Q"].T @ w["Q"]),
             ("XᵀP", "X^TP", lambda t, w: w["X"].T @ w["P"]), ("YᵀQ", "Y^TQ", lambda t, w: w["Y"].T @ w["Q"])]
    from .discover import Term
    terms = [Term(u + m, ul + ml, lambda t, w, u=u, f=f: w[u] @ f(t, w))
             for m, ml, f in multipliers + parts for u, ul in letters]

    def residual(s, slot):
        z = coupled_point(s)
        derived = app2.coupled_flow(s, app2.H_coupled(app2.FREE_KAPPA))
        printed = dict(app2.flow_C_eq(s, z, s.kappa, Q_Pi=True))
        _, Pi = app2.Lambda_Pi_coupled(s, z)
        printed["Q"] = printed["Q"] - z["Q"] @ Pi + slot(s, z)
        kept = derivative(s, lambda t, w: [w["X"].T @ w["X"], w["X"].T @ w["P"] + w["P"].T @ w["X"],
                                           w["Y"].T @ w["Y"], w["Y"].T @ w["Q"] + w["Q"].T @ w["Y"]], z, printed)
        out = {f"d{k}/dt (C-neumann) - (C-eq)": derived[k] - printed[k] for k in ("X", "P", "Y", "Q")}
        out.update({f"constraint {i + 1} kept": v for i, v in enumerate(kept)})
        return out
    return CorrectionAnsatz(
        claim="coupled-neumann-flow", label="(C-eq)", slot="the last term of Q̇",
        slot_latex=r"\text{the last term of }\dot Q", terms=terms, residual=residual, point=coupled_point,
        description="Σ c·UM, U ∈ {X, Y, P, Q}, M ∈ {Π, Λ, XᵀAY, YᵀAX, PᵀP, QᵀQ, XᵀP, YᵀQ}",
        description_latex=r"$\sum c\,UM$, $U\in\{X,Y,P,Q\}$, $M\in\{\Pi,\Lambda,X^TAY,Y^TAX,P^TP,Q^TQ,"
                          r"X^TP,Y^TQ\}$",
        printed={"QΠ": ONE}, registered={"YΠ": ONE}, size=Size(3, 2))


# -- (so(n,n)): the big Lax pair of the coupled Neumann system -----------------------------------------

def _big_lax(order: str) -> CorrectionAnsatz:
    """(so(n,n)) for κ = 0: the ν⁻¹ part of L(ν) among the 2n×2n block matrices with blocks Σ c·UVᵀ,
    U, V ∈ {X, Y, P, Q}; A(ν) = L₊(ν) as printed; the Lax equation in the printed order dL/dt = [L, A]
    (``order`` "LA") or in the order [A, L] ("AL")."""
    from .systems import coupled_point
    app2 = _catalog_module("app2_double_coupled_complex")
    outer = [_outer(x, x, x) for x in ("X", "Y", "P", "Q")]
    outer_t = [_outer(x + "ᵀ", x + "^T", x, True) for x in ("X", "Y", "P", "Q")]
    pattern = {(0, 1): ("X", "Yᵀ"), (1, 0): ("Y", "Xᵀ")}
    middle = [Factor("", "", lambda s: s.Ir, "ν⁻¹·", r"\nu^{-1}")]

    def zero(s):
        return s.zeros(s.n, s.n, ("n", "n"))

    def preferred(pos, U, M, V):
        return 0 if pattern.get(pos) == (U.text, V.text) else 1
    terms = sandwich_terms(outer, outer_t, middle, [(0, 0), (0, 1), (1, 0), (1, 1)], (2, 2), zero, preferred)

    def residual(s, slot):
        z = coupled_point(s)
        nu = s.scalar("nu")
        L = lambda t, w: app2.A_big(t, w, nu) + slot(t, w) * (t.q(1) / nu)
        flow = app2.coupled_flow(s, app2.H_coupled(app2.NORMAL))
        A = app2.A_big(s, z, nu)
        bracket = comm(L(s, z), A) if order == "LA" else comm(A, L(s, z))
        return derivative(s, L, z, flow) - bracket
    K = {_at(b, "ν⁻¹·" + u + v): ONE for b, (u, v) in pattern.items()}
    eq = "dL/dt = [L(ν), A(ν)], as printed" if order == "LA" else "dL/dt = [A(ν), L(ν)]"
    eq_latex = r"\dot L=[L(\nu),A(\nu)]" if order == "LA" else r"\dot L=[A(\nu),L(\nu)]"
    return CorrectionAnsatz(
        claim="coupled-big-lax-normal", label="(so(n,n))", slot=f"ν⁻¹·L₋(ν) (with {eq})",
        slot_latex=r"\nu^{-1}L_-(\nu)\ (\text{with }" + eq_latex + ")",
        terms=terms, residual=residual, point=coupled_point,
        description="of 2n×2n block matrices, each block Σ c·ν⁻¹UVᵀ, U, V ∈ {X, Y, P, Q}; A(ν) = L₊(ν) as printed",
        description_latex=r"each block $\sum c\,\nu^{-1}UV^T$, $U,V\in\{X,Y,P,Q\}$; $A(\nu)=L_+(\nu)$ as printed",
        printed=K if order == "LA" else None,
        registered={k: -ONE for k in K} if order == "AL" else None, size=Size(3, 2), blocks=(2, 2))


def coupled_big_lax_normal() -> CorrectionAnsatz:
    return _big_lax("LA")


def coupled_big_lax_normal_reordered() -> CorrectionAnsatz:
    return _big_lax("AL")


#: the paper's corrections searched as solution spaces: a name -> the ansatz builder
CORRECTIONS: dict[str, Callable[[], CorrectionAnsatz]] = {
    "manakov-dual-lax": manakov_dual_lax,
    "double-neumann-dual-lax": double_neumann_dual_lax,
    "complex-neumann-dual-lax": complex_neumann_dual_lax,
    "coupled-neumann-flow": coupled_neumann_flow,
    "coupled-big-lax-normal": coupled_big_lax_normal,
    "coupled-big-lax-normal/[A,L]": coupled_big_lax_normal_reordered,
}


def searches_for(claim: str) -> list[str]:
    """The names of the searches of ``claim``'s corrections (a name of :data:`CORRECTIONS`, or a claim id
    with several searches)."""
    return [k for k in CORRECTIONS if k == claim or k.split("/")[0] == claim]
