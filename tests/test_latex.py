"""LaTeX from plain text and from math statements (stiefelsym.latex)."""
from __future__ import annotations

import re

import pytest

from stiefelsym.latex import display_pieces, math_ok, tex_balanced, tex_display, tex_escape, tex_math, tex_text

NASTY = r"50% of #cases & ~x^2 {b} \foo <a|b> under_score, Božidar Jovanović, dΦ/dt = [XXᵀ, A] ≤ ½"

STATEMENTS = {
    "prep": r"\frac{d}{dt}\Phi=[XX^T,A],\qquad \frac{d}{dt}(XX^T)=[\Phi,XX^T]",
    "orbit": r"2l=\begin{cases}\tfrac{n(n-1)}2-\left[\tfrac n2\right],&n\le2r+1\\ 2r(n-r-1),&n>2r+1\end{cases}",
    "aligned": r"H &= \tfrac12\tr(P^TP) \\ &= \tfrac12\langle\Phi,\Phi\rangle",
    "lines": r"\dot X = P \\ \dot P = -XP^TP",
    "unbalanced": r"\frac{1}{2",
}


@pytest.mark.parametrize("raw, tex", [
    ("a_b", r"a\_b"), ("#1", r"\#1"), ("50%", r"50\%"), ("A&B", r"A\&B"), ("~", r"\~{}"),
    ("x^2", r"x\^{}2"), ("{b}", r"\ensuremath{\{b\}}"), ("\\foo", r"\textbackslash{}foo"), ("$5", r"\$5"),
    ("a<b", r"\ensuremath{a<b}"), ("Φ", r"\ensuremath{\Phi}"), ("XXᵀ", r"\ensuremath{XX^{T}}"),
    ("≤ ½", r"\ensuremath{\le} \ensuremath{\tfrac12}"), ("Jovanović", r"Jovanovi\'{c}"),
    ("Božidar", r"Bo\v{z}idar"), ("𝔄", r"\ensuremath{\mathfrak{A}}"), ("ℝ", r"\ensuremath{\mathbb{R}}"),
    ("x₁₂", r"\ensuremath{x_{12}}"), ("§5", r"\ensuremath{\S}5"), ("ε", r"\ensuremath{\varepsilon}"),
])
def test_tex_escape(raw, tex):
    assert tex_escape(raw) == tex


def test_tex_escape_leaves_no_special_unescaped():
    out = tex_escape(NASTY)
    stripped = out
    while r"\ensuremath{" in stripped:       # a math group (of any depth of braces) is math mode: no text specials
        at = stripped.index(r"\ensuremath{")
        depth, end = 0, at + len(r"\ensuremath")
        for end in range(end, len(stripped)):
            depth += {"{": 1, "}": -1}.get(stripped[end], 0) if stripped[end - 1] != "\\" else 0
            if depth == 0:
                break
        stripped = stripped[:at] + stripped[end + 1:]
    stripped = re.sub(r"\\[A-Za-z]+|\\[^A-Za-z]|\{|\}", "", stripped)
    assert not re.search(r"[#%&~^_$]", stripped)
    assert out.count("{") - out.count(r"\{") == out.count("}") - out.count(r"\}")
    assert all(ord(ch) < 128 for ch in out)


def test_tex_text_keeps_inline_math():
    assert tex_text(r"the sign of $\lambda A$ and 5% off") == r"the sign of $\lambda A$ and 5\% off"
    assert tex_text("costs $5") == r"costs \$5"


def test_tex_math_maps_unicode():
    assert tex_math("Φ + XXᵀ ≤ λ·𝔄") == r"\Phi  + XX^{T} \le  \lambda \cdot \mathfrak{A}"


def test_tex_display_environments():
    # every display is shrunk to the line's width when wider (no overfull line)
    assert all(tex_display(STATEMENTS[k]).startswith("\\begin{center}\\resizebox")
               for k in ("orbit", "aligned", "lines"))
    # one of several formulas is first fitted on one, two or one formula a line, then shrunk
    prep = tex_display(STATEMENTS["prep"])
    assert prep.startswith("\\begin{center}\\sbox0{") and prep.count("\\ifdim\\wd0>1.15\\linewidth") == 2
    assert prep.rstrip().endswith("\\resizebox{\\ifdim\\wd0>\\linewidth\\linewidth\\else\\wd0\\fi}{!}{\\usebox0}\\end{center}")
    assert "aligned" not in tex_display(STATEMENTS["prep"])
    assert "aligned" not in tex_display(STATEMENTS["orbit"])  # & only inside cases
    assert "\\begin{aligned}" in tex_display(STATEMENTS["aligned"])
    assert "\\begin{gathered}" in tex_display(STATEMENTS["lines"])
    assert "verbatim" in tex_display(STATEMENTS["unbalanced"])


def test_math_ok():
    assert math_ok(r"\{a\} + \frac{1}{2}")
    assert not math_ok(r"\frac{1}{2")
    assert not math_ok("a $ b")
    assert not math_ok(r"\begin{cases} a")


def test_tex_balanced():
    assert tex_balanced("\\paragraph{a}\n\\[x^{2}\\]\n\\begin{itemize}\\item b\\end{itemize}")
    assert not tex_balanced("\\[x^{2}")
    assert not tex_balanced("\\begin{itemize}")
    assert not tex_balanced("\\end{document}")


def test_check_names_read_as_mathematics():
    from stiefelsym.latex import unicode_name
    assert unicode_name("Phi X = P - X P^T X[1,1]") == "Φ X = P - X Pᵀ X, entry (1,1)"
    assert unicode_name("dPsi/dt") == "dΨ/dt" and unicode_name("H_kappa") == "H_κ"
    assert unicode_name("derivative along the printed flow") == "derivative along the printed flow"
    assert tex_text("Ẋ") == r"\ensuremath{\dot{X}}"     # a time derivative, in math as the paper sets it


def test_the_mathematics_of_words_is_set_in_math_mode():
    """What a word of mathematics looks like in the words of the reports, set in math mode by the one converter
    (:func:`stiefelsym.latex.math_runs`), not letter by letter in the text font: a differential (de₁, de₃/dt, dF,
    ds²), a matrix times a vector (Aeₙ), a time derivative (XᵀẎ, ė₃, Φ̇), the names of the paper's operators
    (Sym(r), pr, adj) and the named subscripts (ω_mag, TW_{n,r}); words stay text (and/or, Möbius, de Vries)."""
    from stiefelsym.latex import tex_escape, tex_words, unicode_words
    assert tex_escape("ω = de₁ ∧ de₂ here") == r"\ensuremath{\omega  = de_{1} \wedge  de_{2}} here"
    assert tex_escape("de₃/dt = Ωe₃") == r"\mbox{\ensuremath{de_{3}/dt = \Omega e_{3}}}"
    assert tex_escape("dF onto Sym(r)") == r"\ensuremath{dF} onto \ensuremath{\mathop{\mathrm{Sym}}\nolimits (r)}"
    assert tex_escape("XᵀẎ − YᵀẊ, (Aeₙ, eₙ), d(XᵀX)/dt") == (
        r"\ensuremath{X^{T}\dot{Y} - Y^{T}\dot{X}}, \ensuremath{(Ae_{n}, e_{n})}, \ensuremath{d(X^{T}X)/dt}")
    assert tex_escape("ė₃ and Φ̇") == r"\ensuremath{\dot{e}_{3}} and \ensuremath{\dot{\Phi}}"
    assert tex_escape("DẊᵀDY") == r"\ensuremath{D\dot{X}^{T}DY}"     # the mark on the last of two letters
    assert tex_escape("|L − wI| = 0") == r"\mbox{\ensuremath{|L - wI| = 0}}"
    assert tex_escape("under (gXhᵀ, gPhᵀ, gAgᵀ), g in") == (
        r"under \ensuremath{(gXh^{T}, gPh^{T}, gAg^{T})}, \ensuremath{g} in")
    assert tex_words("H_CPB and H_CP, not LaTeX") == r"\ensuremath{H_{CPB}} and \ensuremath{H_{CP}}, not LaTeX"
    assert tex_words("ω_mag on TW_{n,r}, pr_{e_n}(Ω), ds²_κ") == (
        r"\ensuremath{\omega _{mag}} on \ensuremath{TW_{n,r}}, \ensuremath{\mathop{\mathrm{pr}}\nolimits _{e_{n}}(\Omega )}, "
        r"\ensuremath{ds^{2}_{\kappa }}")
    assert tex_escape("and/or Möbius de Vries") == r"and/or M\"{o}bius de Vries"
    # a quotation of mathematics, a word after a hyphen, a script after a one-letter subscript
    assert tex_words("reads “V_{n,n} is SO(n)” as") == (
        r"reads ``\ensuremath{V_{n,n}} is \ensuremath{SO(n)}'' as")
    assert tex_escape("SO(n)×SO(r)-invariant, a 2r-plane; 2r-integrals") == (
        r"\ensuremath{SO(n)\times SO(r)}-invariant, a \ensuremath{2r}-plane; 2r-integrals")
    assert tex_words("Σ a_i²e_i², N0_XP2") == r"\ensuremath{\Sigma  a_{i}^{2}e_{i}^{2}}, N0\_XP2"
    assert unicode_words("Σ a_i²e_i²") == "Σ aᵢ²eᵢ²"
    # braces that are brackets or sets, and an ellipsis inside a formula
    assert tex_words("span{e, Aė} and {F_i, F_j}_ε") == (
        r"\ensuremath{\mathop{\mathrm{span}}\nolimits \{e, A\dot{e}\}} and \ensuremath{\{F_{i}, F_{j}\}_{\varepsilon }}")
    assert tex_escape("e₁∧…∧eᵣ at a₁..aₙ, e.g. here") == (
        r"\ensuremath{e_{1}\wedge \dots \wedge e_{r}} at \ensuremath{a_{1}..a_{n}}, e.g. here")


def test_the_registered_words_of_a_correction_set_their_scripts():
    """(A + λI_n)^{-1} in the words of a correction is a subscript and a superscript in the PDF, not the
    characters ^{-1}; a spaced ^ is the wedge; an underscore inside a name stays one."""
    from stiefelsym.latex import tex_words
    tex = tex_words("(A + λI_n)^{-1} and (e_1 ^ p_1)_{I_2}^2, N0_XP2")
    assert r"\ensuremath{(A + \lambda I_{n})^{-1}}" in tex
    assert r"\ensuremath{(e_{1} \wedge  p_{1})_{I_{2}}^{2}}" in tex
    assert r"N0\_XP2" in tex and "\\^{}" not in tex


def test_a_power_in_parentheses_and_the_powers_in_a_check_name_are_scripts():
    """(μI_n − A)^(-1) in a certificate and tr(μ + λA)^3 in the title of a free derivation are set as
    superscripts in the PDF (⁻¹ and ³ in Markdown), not with a literal caret; a caret before a group of
    several letters in parentheses stays as written."""
    from stiefelsym.latex import tex_words, unicode_words
    from stiefelsym.methods.dimension_free import entry_title
    tex = tex_words("(μ I_n - A)^(-1) X, A^(k)")
    assert tex.startswith(r"\ensuremath{(\mu  I_{n} - A)^{-1}}") and r"\ensuremath{A^{(k)}}" in tex
    assert "\\^{}" not in tex
    assert unicode_words("(μ I_n - A)^(-1)") == "(μ Iₙ - A)⁻¹"
    title = entry_title("{1/2<mu, AA mu>, tr(mu + lambda A)^3} (+)")
    assert r"(\mu  + \lambda  A)^{3}}" in title and "\\^{}" not in title
    assert "\\^{}" in tex_words("g^(ab)")
    assert unicode_words("d^2X/dt^2, d^2(X^T P)") == "d²X/dt², d²(Xᵀ P)"     # Leibniz's second derivative
    assert "\\^{}" not in entry_title("d^2X/dt^2 - F")
    # the order of a derivative keeps its parentheses; Leibniz with two digits; an accented letter is no script
    assert unicode_words("f^(k), d^10X/dt^10") == "f⁽ᵏ⁾, d¹⁰X/dt¹⁰"
    assert r"\ensuremath{" not in tex_words("u^(é), y_é")
    assert tex_words("M_{n×r}(ℝ)") == r"\ensuremath{M_{n\times r}(\mathbb{R})}"
    assert tex_words("ξ_(m)^{2k}").startswith(r"\ensuremath{\xi}\_(m)")     # an index in parentheses stays one


def test_the_registered_words_set_a_spaced_inequality_as_one():
    """n <= 2r + 2 in the words of a correction or of what is wrong is n ≤ 2r + 2 in the PDF; a bracket
    <a, b> (no = after <) and <= inside a word stay as they are."""
    from stiefelsym.latex import tex_words
    tex = tex_words("regular iff n <= 2r + 2; rank >= 5; <axial(P1), P2>; a<=b")
    assert r"\ensuremath{n \le  2r + 2}" in tex and r"rank \ensuremath{\ge} 5" in tex
    assert r"\ensuremath{<}axial" in tex and r"a\ensuremath{<}=b" in tex


def test_a_wide_display_breaks_only_between_its_formulas():
    """A display of several formulas breaks after a comma, semicolon or colon followed by a space
    command at its top level; never inside braces, a matrix, \\left…\\right, parentheses or a set."""
    body = (r"H=T:\ \dot L(\nu)=[L(\nu),\ A(\nu)],\ L=\begin{pmatrix}0&a,\ b\\c&0\end{pmatrix}\nu,\quad "
            r"\left(c,\ d\right)=\{x,\ y\},\ f(a,\ b);\qquad \text{along (x,\ y)},\ z\leftarrow w")
    pieces = display_pieces(body)
    assert pieces == [r"H=T:", r"\dot L(\nu)=[L(\nu),\ A(\nu)],", r"L=\begin{pmatrix}0&a,\ b\\c&0\end{pmatrix}\nu,",
                      r"\left(c,\ d\right)=\{x,\ y\},", r"f(a,\ b);", r"\text{along (x,\ y)},", r"z\leftarrow w"]
    assert display_pieces(r"a=b,c=d") == [r"a=b,c=d"]
    # every piece is in each of the three forms, in its order; nothing of the formula is lost
    tex = tex_display(body)
    one, two, each = tex.split("\\ifdim\\wd0>1.15\\linewidth")
    for form in (one, two, each):
        at = [form.index(p) for p in pieces]
        assert at == sorted(at)
    # the line breaks of the gathered forms (the matrix's own \\\\ is followed by no newline)
    assert "\\\\\n" not in one and two.count("\\\\\n") == 1 and each.count("\\\\\n") == len(pieces) - 1


def test_an_exterior_product_with_an_ellipsis_is_set_with_wedges():
    """(e_1^...^e_r^p_i)^2 in the words of what is wrong: every ^ before a letter of that word is a
    wedge, the square stays a power; a word with no ^...^ keeps its scripts (X^T, A^{-1})."""
    from stiefelsym.latex import tex_words
    tex = tex_words("sums (e_1^...^e_r^p_i^p_j)^2 over i < j; X^T P and A^{-1}")
    assert tex.startswith(r"sums \ensuremath{(e_{1}\wedge \dots \wedge e_{r}\wedge p_{i}\wedge p_{j})^{2}}")
    assert r"\ensuremath{X^{T}} \ensuremath{P}" in tex and r"\ensuremath{A^{-1}}" in tex
    assert r"\^{}" not in tex
    # without an ellipsis: a ^ between two subscripted letters is the wedge, a power or transpose is not
    tex = tex_words("the mixed terms (e_j^p_i)^2 and (e_j^p_j)(e_k^p_k); Phi_{I_2}^2, X_{ij}^T, d^2e_3/dt^2")
    assert r"\ensuremath{(e_{j}\wedge p_{i})^{2}}" in tex
    assert r"(e_{k}\wedge p_{k})" in tex
    assert tex.count("wedge") == 3 and r"X_{ij}^{T}" in tex


def test_the_registered_words_read_in_unicode_in_markdown():
    """For a plain-text reader the ASCII scripts of the catalog's words become Unicode scripts where
    every character has one; a script that has none keeps its ASCII form, its own scripts set."""
    from stiefelsym.latex import unicode_words
    assert unicode_words("(LA-MAN3): (A + λI_n) in place of (A + λI_n)^{-1}") == \
        "(LA-MAN3): (A + λIₙ) in place of (A + λIₙ)⁻¹"
    assert unicode_words("diag(I_n, B^{-1}) in place of diag(I_{n-r}, B^{-1}); n <= 2r + 2") == \
        "diag(Iₙ, B⁻¹) in place of diag(Iₙ₋ᵣ, B⁻¹); n ≤ 2r + 2"
    assert unicode_words("(e_1 ^ p_1 + ... + e_r ^ p_r)_{I_2}^2, so(r,C)^⊥, N0_XP2, X^T P") == \
        "(e₁ ∧ p₁ + ... + eᵣ ∧ pᵣ)_{I₂}², so(r,C)^⊥, N0_XP2, Xᵀ P"
    # LaTeX between dollars is the Markdown's mathematics: kept as written
    assert unicode_words(r"$\Phi_{ij}^2$ in the second sum, I_n") == r"$\Phi_{ij}^2$ in the second sum, Iₙ"


def test_the_ascii_idioms_of_the_catalog_s_prose_are_set_in_the_paper_s_notation():
    """The referee's plain-text leaks (stop 66): L*_neum with a literal underscore, r x r, i != j, 1<=i<=r,
    Theta, X0 are set as 𝓛*_{neum}, r × r, ≠, ≤, Θ, X₀ in both reports; a single a<=b inside a word and a
    variable x between words stay."""
    from stiefelsym.latex import tex_words, unicode_words
    text = "L*_neum(lambda) is 2r x 2r; i != j; 1<=i<=r; Theta(X0, P0); (n + r) x 2r; a<=b; the point x on x = 0"
    md = unicode_words(text)
    assert md == "𝓛*_neum(λ) is 2r × 2r; i ≠ j; 1≤i≤r; Θ(X₀, P₀); (n + r) × 2r; a<=b; the point x on x = 0"
    tex = tex_words(text)
    assert r"\ensuremath{\mathcal{L}^{*}_{neum}(\lambda )}" in tex and r"\_neum" not in tex
    assert r"\ensuremath{2r \times  2r}" in tex and r"\mbox{\ensuremath{i \neq  j}}" in tex
    assert r"\ensuremath{1\le i\le r}" in tex and r"\ensuremath{\Theta (X_{0}, P_{0})}" in tex
    assert r"the point \ensuremath{x} on \mbox{\ensuremath{x = 0}}" in tex


def test_subscripts_of_lie_algebras_and_index_pairs_and_cross_products_in_the_pdf():
    """The referee of stop 67: eta_so(r), Psi_so(n-r), Psi_ij and (P^T P)_ij kept a literal underscore in the PDF,
    and e_3 x de_3/dt an x.  The PDF sets the subscripts as one and the cross product as ×; the Markdown keeps the
    subscripts as written."""
    from stiefelsym.latex import tex_words, unicode_words
    text = "eta_so(r) = 0, Psi_so(n-r), Psi_ij, (P^T P)_ij, e_3 x de_3/dt, kernel_of x, H_neum,0"
    tex = tex_words(text)
    assert r"\_" not in tex.replace(r"kernel\_of", "")
    assert r"\eta _{so(r)}" in tex and r"\ensuremath{\Psi _{ij}}" in tex and r"\ensuremath{e_{3} \times  de_{3}/dt}" in tex
    assert r"\ensuremath{H_{neum,0}}" in tex      # the paper's named subscripts after any letter, not only 𝓛*
    assert unicode_words(text) == "η_so(r) = 0, Ψ_so(n-r), Ψ_ij, (Pᵀ P)_ij, e₃ × de₃/dt, kernel_of x, H_neum,0"


def test_a_named_subscript_with_a_second_index_is_set_as_the_paper_sets_it():
    """H_neum_0 and H_neum₀ kept a literal underscore in the PDF, and H_neum,κ set only "neum" as the subscript.  The paper
    writes H_{neum_0} and H_{neum,\\kappa}: so does the PDF; a comma before a space stays punctuation, and a name
    that only begins with neum (H_neumann) is left alone."""
    from stiefelsym.latex import tex_words, unicode_words
    assert tex_words("H_neum_0 = H o Theta").startswith(r"\mbox{\ensuremath{H_{neum_{0}} = H}}")
    assert tex_words("the flow of H_neum,kappa.") == r"the flow of \ensuremath{H_{neum,\kappa }}."
    assert tex_words("(H_neum,0)") == r"\ensuremath{(H_{neum,0})}"
    assert tex_words("H_neum,−½ and H_man, the") == r"\ensuremath{H_{neum,-\tfrac12}} and \ensuremath{H_{man}}, the"
    assert tex_words("H_neumann") == r"H\_neumann"
    # as a claim's docstring writes it (the remark after Theorem NEUMANN): the same as H_neum_0
    assert tex_words("along the flow of H_neum₀ the image") == r"along the flow of \ensuremath{H_{neum_{0}}} the image"
    for text in ("H_neum_0", "H_neum₀", "H_neum,0", "H_neum,κ"):
        assert r"\_" not in tex_words(text)
    assert unicode_words("H_neum,0 and H_neum,κ") == "H_neum,0 and H_neum,κ"     # the Markdown keeps them


def test_a_short_relation_of_running_text_is_kept_on_one_line():
    """TeX breaks a line at a space: "r = 2", "n ≤ 2r + 1" and "(n − r = 1" are bound by no-break spaces; in a longer
    chain only the relation signs are bound to their sides; a sum with no relation is left as it is."""
    from stiefelsym.latex import NBSP, bind_relations, tex_escape
    assert bind_relations("12 at r = 2, and (n − r = 1, r = 3)") == \
        f"12 at r{NBSP}={NBSP}2, and (n{NBSP}−{NBSP}r{NBSP}={NBSP}1, r{NBSP}={NBSP}3)"
    assert bind_relations("regular iff n ≤ 2r + 1.") == f"regular iff n{NBSP}≤{NBSP}2r{NBSP}+{NBSP}1."
    assert bind_relations("a chain = 3 + 4 + 5 + 6") == f"a chain{NBSP}={NBSP}3 + 4 + 5 + 6"
    assert bind_relations("2r + 1 and n + r") == "2r + 1 and n + r"
    assert tex_escape("r = 2") == r"\mbox{\ensuremath{r = 2}}"


def test_a_rerun_command_breaks_before_an_option_not_after_it():
    from stiefelsym.reports.report import _tt
    tt = _tt("stiefelsym verify x --method exact --seed 0 --size 2,2 --size 3,1")
    assert r"--size\nobreakspace{}2,2 --size\nobreakspace{}3,1" in tt and r"--method\nobreakspace{}exact" in tt


def test_tex_escape_stays_inside_the_derivation_vocabulary():
    """Whatever tex_escape writes (specials, scripts, accents, no-break spaces of bound relations, Unicode math)
    passes the allow-list a derivation of a results file is checked against: otherwise the engine's own
    derivations are printed as their LaTeX source in the reports."""
    from stiefelsym import latex as L
    chars = (list(L._TEX_SPECIAL) + list(L._SUP) + list(L._SUB) + list(L._TEXT_ONLY) + list(L._MATH_SYMBOLS)
             + [L.NBSP, "é", "ő", "Ż̄", "Q̇", "𝒳", "∑", "λ", "Σ̄", "\x07"])
    text = " ".join(chars) + " with r = 2 and n ≤ 2r + 1, X^T X = I_r"
    tex = tex_escape(text)
    assert L._vocabulary_ok(tex, L.DERIVATION_COMMANDS, L.DERIVATION_ENVIRONMENTS,
                            L._MATH_SYMBOLS_ESCAPED | L._DERIVATION_SYMBOLS), tex
    assert tex_balanced(r"\begin{itemize}\item " + tex + r"\end{itemize}")


def test_a_code_span_is_set_in_typewriter_type():
    """`stiefelsym discover` in a claim's words printed its backticks as opening quotes in the PDF."""
    from stiefelsym.latex import tex_escape
    assert tex_escape("found by `stiefelsym discover` here") == r"found by \texttt{stiefelsym discover} here"
    assert tex_escape("the term `a_1 & b`") == r"the term \texttt{a\_1 \& b}"
    assert tex_escape("a lone ` backtick") == "a lone ` backtick"


def test_text_in_a_jupyter_display_has_no_text_mode_command():
    """MathJax takes a \\text{} literally: the characters LaTeX treats specially are written in math mode
    between runs of text, never as \\ensuremath or \\textbackslash inside it (stop 90 h2 M4)."""
    from stiefelsym.reports.notebook import _tex_text
    out = _tex_text("rank |Φ| ≤ 2 & {x}_1 \\ 50% ~^ <>")
    assert "\\ensuremath" not in out and "\\textbackslash" not in out
    texts = re.findall(r"\\text\{([^{}]*)\}", out)
    assert "".join(texts) == "rank Φ ≤ 2  x1  50  "
    assert "{\\vert}" in out and "{\\&}" in out and "{\\backslash}" in out and "{\\_}" in out
    assert tex_balanced(out) and _tex_text("") == "\\text{}"


def test_typewriter_text_takes_its_backslash_and_braces_from_the_typewriter_font():
    """\\textbackslash and \\{ are symbols of the OMS encoding, which has no typewriter shape (font warning OMS/cmtt):
    inside \\texttt the characters of the typewriter font itself are used, the tilde and caret as characters."""
    from stiefelsym.latex import tex_escape, tt_escape
    assert tt_escape("\\ref{No} a~b^2") == r"\char92{}ref\char123{}No\char125{} a\char126{}b\char94{}2"
    assert tex_escape("Printed `{\\ref{No}` here") == r"Printed \texttt{\char123{}\char92{}ref\char123{}No\char125{}} here"
    assert tex_escape("{\\ref}") == r"\{\textbackslash{}ref\}"


def test_mathematics_of_running_text_is_set_in_math_mode():
    """The referee's P4: letters, scripts and Greek letters of prose were set in the text font (Λ1, TₓO, I_{r+1}, the
    r of "r = 2").  Each formula of running text is one math group; words, numbers and code stay text, a quote is
    never read as a prime."""
    from stiefelsym.latex import math_runs, tex_escape, tex_words
    assert tex_escape("the bracket Λ₁ on TₓO") == r"the bracket \ensuremath{\Lambda _{1}} on \ensuremath{T_{x}O}"
    assert tex_words("the subscript I_{r+1} for I_{l+1}") == r"the subscript \ensuremath{I_{r+1}} for \ensuremath{I_{l+1}}"
    assert tex_words("O(n) in place of SO(n): det X = ±1, both") == \
        r"\ensuremath{O(n)} in place of \ensuremath{SO(n)}: \ensuremath{\mathop{\mathrm{det}}\nolimits  X = \pm 1}, both"
    assert tex_words("h = Φ(X_0, P_0) in place of Ψ(X₀, P₀)") == \
        r"\ensuremath{h = \Phi (X_{0}, P_{0})} in place of \ensuremath{\Psi (X_{0}, P_{0})}"
    assert [m for m, _ in math_runs("A claim in 0.2 s, e.g. 2r-integrals at 3404 runs")] == [False]
    assert tex_escape("Σ pᵢ ∧ eᵢ = PXᵀ − XPᵀ, UNEXPECTED") == \
        r"\ensuremath{\Sigma  p_{i} \wedge  e_{i} = PX^{T} - XP^{T}}, UNEXPECTED"
    assert tex_words("'G_I(V)^2', 'a'").count("'") == 4 and "^{2}'" not in tex_words("'G_I(V)^2', 'a'")
