"""The search spaces of the paper's corrections: for each printed formula that fails, the formulas of
its shape (every term of the same type and degree, in the scene's letters and the resolvents the
printed formula uses), searched by :func:`stiefelsym.analyses.discover.correction_space`.

Each ansatz is built on first use from the catalog's own functions; nothing here is a claim."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable

from stiefelsym.claims import Size
from stiefelsym.analyses.discover import CorrectionAnsatz, Factor, _catalog_module, sandwich_terms
from stiefelsym.backends.matrix import comm
from stiefelsym.systems import derivative

ONE = Fraction(1)

#: the sizes, besides the search's (3, 2), at which each solution found is verified
MORE = (Size(2, 1), Size(4, 2), Size(4, 3))


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
        size=Size(3, 2), blocks=(2, 2), free=True, verify_sizes=MORE)


# -- (LA3*D) and (LA3*): the dual Lax pairs of the double and the complex Neumann systems ----------

FLIPPED = ("(I_n − λA)⁻¹", r"(\mathbf I_n-\lambda A)^{-1}")


def _flipped_value(s):
    return s.resolvent(s.q(1) / s.lam) / s.lam


def _off_diagonal_lax(claim: str, label: str, left, right, identity: tuple[str, str], wrap, zero, point,
                      diagonal, A_of, flow_of, realization: str = "standard") -> CorrectionAnsatz:
    """The off-diagonal blocks of 𝓛(λ) = [[−UᵀRV̇, B₁₂], [B₂₁, U̇ᵀRV]] searched, its diagonal blocks as printed."""
    from stiefelsym.ir import block
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
        realization=realization, verify_sizes=MORE)


def double_neumann_dual_lax() -> CorrectionAnsatz:
    """(LA3*D): the off-diagonal blocks of 𝓛(λ) for the double Neumann system (D-eq)."""
    from stiefelsym.systems import double_point
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
    from stiefelsym.systems import complex_point, ctranspose, realify_real
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
    from stiefelsym.systems import coupled_point
    app2 = _catalog_module("app2_double_coupled_complex")
    letters = [("X", "X"), ("Y", "Y"), ("P", "P"), ("Q", "Q")]
    multipliers = [("Π", r"\Pi", lambda t, w: app2.Lambda_Pi_coupled(t, w)[1]),
                   ("Λ", r"\Lambda", lambda t, w: app2.Lambda_Pi_coupled(t, w)[0])]
    parts = [("XᵀAY", "X^TAY", lambda t, w: w["X"].T @ t.A @ w["Y"]),
             ("YᵀAX", "Y^TAX", lambda t, w: w["Y"].T @ t.A @ w["X"]),
             ("PᵀP", "P^TP", lambda t, w: w["P"].T @ w["P"]), ("QᵀQ", "Q^TQ", lambda t, w: w["Q"].T @ w["Q"]),
             ("XᵀP", "X^TP", lambda t, w: w["X"].T @ w["P"]), ("YᵀQ", "Y^TQ", lambda t, w: w["Y"].T @ w["Q"])]
    from stiefelsym.analyses.discover import Term
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
        printed={"QΠ": ONE}, registered={"YΠ": ONE}, size=Size(3, 2), verify_sizes=MORE)


# -- (so(n,n)): the big Lax pair of the coupled Neumann system -----------------------------------------

def _big_lax(order: str) -> CorrectionAnsatz:
    """(so(n,n)) for κ = 0: the ν⁻¹ part of L(ν) among the 2n×2n block matrices with blocks Σ c·UVᵀ,
    U, V ∈ {X, Y, P, Q}; A(ν) = L₊(ν) as printed; the Lax equation in the printed order dL/dt = [L, A]
    (``order`` "LA") or in the order [A, L] ("AL")."""
    from stiefelsym.systems import coupled_point
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
        printed=K,
        registered={k: -ONE for k in K} if order == "AL" else None, size=Size(3, 2), blocks=(2, 2),
        verify_sizes=MORE)


def coupled_big_lax_normal() -> CorrectionAnsatz:
    return _big_lax("LA")


def coupled_big_lax_normal_reordered() -> CorrectionAnsatz:
    return _big_lax("AL")


# -- (2r-integrals): the general line I_{2l} -------------------------------------------------------

def _sorted_sign(cols: list[int]) -> tuple[int, tuple[int, ...]]:
    """The sign of the permutation sorting ``cols`` (0 if two are equal) and the sorted tuple."""
    if len(set(cols)) < len(cols):
        return 0, ()
    inv = sum(1 for i in range(len(cols)) for j in range(i + 1, len(cols)) if cols[i] > cols[j])
    return (-1 if inv % 2 else 1), tuple(sorted(cols))


class _Plucker:
    """The minors of W = (e₁ … e_r p₁ … p_r) (the columns of X, then of P) of a scene, each computed once
    by Laplace expansion along its first row."""

    def __init__(self, s: Any) -> None:
        self.s, self.memo = s, {}
        self.W = [[s.X[i, j] for j in range(s.r)] + [s.P[i, j] for j in range(s.r)] for i in range(s.n)]

    def minor(self, rows: tuple[int, ...], cols: tuple[int, ...]) -> Any:
        if not rows:
            return self.s.q(1)
        key = (rows, cols)
        if key not in self.memo:
            acc = None
            for t, c in enumerate(cols):
                v = self.W[rows[0]][c] * self.minor(rows[1:], cols[:t] + cols[t + 1:])
                v = -v if t % 2 else v
                acc = v if acc is None else acc + v
            self.memo[key] = acc
        return self.memo[key]


def _wedge_power_term(a: int, b: int, k: int) -> Callable[[Any, Any], Any]:
    """G_{a,b,k} = Σ_{|I| = a+b+2k} w_I Σ_{|J| = a, |K| = b} ((e_J ∧ p_K ∧ ω^k/k!)_I)², ω = Σ_j e_j ∧ p_j,
    w_I = a(λ)/∏_{i∈I}(λ − a_i)."""
    from itertools import combinations
    sec8 = _catalog_module("sec8_dual_lax_pair")

    def value(s, w):
        W, n, r = w["plucker"], s.n, s.r
        m = a + b + 2 * k
        acc = s.q(0)
        if m > n or a > r or b > r:
            return acc
        for I in combinations(range(n), m):
            inner = s.q(0)
            for J in combinations(range(r), a):
                for K in combinations(range(r), b):
                    coord = None
                    for L in combinations([j for j in range(r) if j not in J and j not in K], k):
                        cols = list(J) + [r + x for x in K] + [c for j in L for c in (j, r + j)]
                        sign, key = _sorted_sign(cols)
                        if sign:
                            v = W.minor(I, key)
                            v = -v if sign < 0 else v
                            coord = v if coord is None else coord + v
                    if coord is not None:
                        inner = inner + coord * coord
            acc = acc + sec8.weight(s, s.lam, I) * inner
        return acc
    return value


def _g_text(a: int, b: int, k: int, latex: bool) -> str:
    m = a + b + 2 * k
    if latex:
        parts = ([rf"e_{{J_{a}}}"] if a else []) + ([rf"p_{{K_{b}}}"] if b else []) + \
                ([r"\omega" if k == 1 else rf"\tfrac{{\omega^{k}}}{{{k}!}}"] if k else [])
        sums = ",".join(x for x, y in ((f"J_{a}", a), (f"K_{b}", b)) if y)
        return (rf"\sum_{{I_{m}}}w_I" + (rf"\sum_{{{sums}}}" if sums else "")
                + "(" + r"\wedge ".join(parts) + rf")_{{I_{m}}}^2")
    digits = "₀₁₂₃₄₅₆₇₈₉"
    sub = ["".join(digits[int(d)] for d in str(i)) for i in range(2 * m + 1)]
    parts = ([f"e_J{sub[a]}"] if a else []) + ([f"p_K{sub[b]}"] if b else []) + \
            (["ω" if k == 1 else f"ω^{k}/{k}!"] if k else [])
    sums = ",".join(x for x, y in ((f"J{sub[a]}", a), (f"K{sub[b]}", b)) if y)
    return f"Σ_I{sub[m]} w_I" + (f" Σ_{sums}" if sums else "") + " (" + "∧".join(parts) + ")²"


_POINT: dict[str, Any] = {}


def _plucker_point(s: Any) -> dict[str, Any]:
    """The point (X, P) with the minors of (X | P), one per scene (so that the terms share them)."""
    if _POINT.get("scene") is not s:
        _POINT.clear()
        _POINT.update(scene=s, point={"X": s.X, "P": s.P, "plucker": _Plucker(s)})
    return _POINT["point"]


def general_line(l: int, r_max: int = 3) -> CorrectionAnsatz:
    """(2r-integrals), the line 𝓘_{2l}(λ): every G_{a,b,k} of order l <= a + b + 2k <= 2l with a + k, b + k <= r_max
    (the printed line's terms are G_{l,b,0}: l vectors e, b vectors p)."""
    from stiefelsym.analyses.discover import Term
    sec8 = _catalog_module("sec8_dual_lax_pair")
    shapes = [(a, b, k) for m in range(l, 2 * l + 1) for k in range(m // 2 + 1) for b in range(m - 2 * k + 1)
              for a in [m - 2 * k - b] if a + k <= r_max and b + k <= r_max]
    # the fewest vectors p outside ω first (then the fewest ω), so that the solution is written with them
    shapes.sort(key=lambda t: (t[1], t[2], -t[0]))
    terms = [Term(_g_text(*t, latex=False), _g_text(*t, latex=True), _wedge_power_term(*t)) for t in shapes]

    def residual(s, slot):
        integrals, _ = sec8.spectral_integrals(s, s.lam)
        return integrals[l] - slot(s, _plucker_point(s)) if l <= s.r else s.q(0)
    g = {t: _g_text(*t, latex=False) for t in shapes}
    return CorrectionAnsatz(
        claim="2r-integrals-general-line", label=f"(2r-integrals), l = {l}", slot=f"𝓘_{2 * l}(λ)",
        slot_latex=rf"\mathcal I_{{{2 * l}}}(\lambda)", terms=terms, residual=residual, point=_plucker_point,
        description=f"Σ c·G_a,b,k, G_a,b,k = Σ_I w_I Σ_J,K ((e_J∧p_K∧ω^k/k!)_I)², |J| = a, |K| = b, |I| = a + b + 2k "
                    f"∈ [{l}, {2 * l}], w_I = a(λ)/∏_(i∈I)(λ − a_i), ω = e₁∧p₁ + ⋯ + e_r∧p_r",
        description_latex=r"$\sum c\,G_{a,b,k}$, $G_{a,b,k}=\sum_{I}w_I\sum_{J,K}(e_J\wedge p_K\wedge"
                          r"\tfrac{\omega^k}{k!})_I^2$, $|J|=a$, $|K|=b$, $|I|=a+b+2k\in[" + f"{l},{2 * l}" + r"]$, "
                          r"$w_I=a(\lambda)/\prod_{i\in I}(\lambda-a_i)$, $\omega=\sum_j e_j\wedge p_j$",
        printed={g[(l, b, 0)]: ONE for b in range(l + 1) if (l, b, 0) in g},
        registered={g[(l - k, 0, k)]: ONE for k in range(l + 1)},
        registered_name="the registered correction" if l == 1 else "the general line Σ_k G_(l−k),0,k",
        size=Size(6, 3))


def general_line_formula(l: int) -> tuple[CorrectionAnsatz, list[Fraction]]:
    """The general line 𝓘_{2l} = Σ_{k=0}^{l} G_{l−k,0,k} (its ansatz and coefficients)."""
    a = general_line(l, r_max=max(3, l))
    assert a.registered is not None
    return a, a.vector(a.registered)


def sweep_general_line(n_max: int = 6, method: str = "auto", seed: int = 0) -> list[tuple[int, int, int, str]]:
    """The verdict of the general line 𝓘_{2l} = Σ_{k=0}^{l} G_{l−k,0,k} at every 1 <= l <= r <= n <= ``n_max``
    (the catalog's claim 2r-integrals-general-line with the line in place of the printed one)."""
    from stiefelsym.claims import load_catalog
    from stiefelsym.analyses.discover import combination
    from stiefelsym.run.runner import run_one
    claim = load_catalog().get("2r-integrals-general-line")
    out = []
    for n in range(1, n_max + 1):
        for r in range(1, n + 1):
            for l in range(1, r + 1):
                a, c = general_line_formula(l)
                slot = combination(a.terms, c)
                func = (lambda s, a=a, slot=slot: {f"I_{2 * l} - general line": a.residual(s, slot)})
                out.append((n, r, l, run_one(claim, Size(n, r), method, seed, func=func).verdict))
    return out


#: the paper's corrections searched as solution spaces: a name -> the ansatz builder
CORRECTIONS: dict[str, Callable[[], CorrectionAnsatz]] = {
    "manakov-dual-lax": manakov_dual_lax,
    "double-neumann-dual-lax": double_neumann_dual_lax,
    "complex-neumann-dual-lax": complex_neumann_dual_lax,
    "coupled-neumann-flow": coupled_neumann_flow,
    "coupled-big-lax-normal": coupled_big_lax_normal,
    "coupled-big-lax-normal/[A,L]": coupled_big_lax_normal_reordered,
    "2r-integrals-general-line/l=1": lambda: general_line(1),
    "2r-integrals-general-line/l=2": lambda: general_line(2),
    "2r-integrals-general-line/l=3": lambda: general_line(3),
}


def searches_for(claim: str) -> list[str]:
    """The names of the searches of ``claim``'s corrections (a name of :data:`CORRECTIONS`, or a claim id
    with several searches)."""
    return [k for k in CORRECTIONS if k == claim or k.split("/")[0] == claim]
