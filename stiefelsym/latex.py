"""LaTeX from plain text and from math statements.

Text (docstrings, certificates, witnesses) is escaped for text mode, with the
Unicode a mathematician types (Φ, Xᵀ, ≤, ℝ, 𝔄, accented names) mapped to LaTeX
so that pdflatex with Debian's texlive-latex-base compiles it.  Statements are
LaTeX math already: they are checked for balance and placed in a display.
"""
from __future__ import annotations

import functools
import re
import unicodedata
from collections import Counter
from typing import Any

_TEX_SPECIAL = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "#": r"\#", "$": r"\$", "%": r"\%",
    "&": r"\&", "_": r"\_", "~": r"\~{}", "^": r"\^{}",
    "<": r"\ensuremath{<}", ">": r"\ensuremath{>}", "|": r"\ensuremath{|}",
}
_SUP = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱᵀᵗʳᵏʲ", "0123456789+-=()niTtrkj"))
_SUP["ˣ"] = r"\times "        # the size of a matrix space written in superscripts: ℝⁿˣⁿ
_SUB = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₒₓₕₖₗₘₙₚₛₜᵢⱼᵣ", "0123456789+-=()aeoxhklmnpstijr"))
#: text-mode replacements; \S and \P in text mode would need a bitmap TS1 font
_TEXT_ONLY = {"–": "--", "—": "---", "‘": "`", "’": "'", "“": "``", "”": "''",
              "\u00a0": "~", "…": r"\ldots{}", "•": r"\ensuremath{\bullet}", "§": r"\ensuremath{\S}",
              "¶": r"\ensuremath{\P}"}
_ACCENTS = {"\u0301": "'", "\u0300": "`", "\u030c": "v", "\u0308": '"', "\u0302": "^", "\u0307": ".",
            "\u0303": "~", "\u0327": "c", "\u0306": "u", "\u0304": "="}
_MATH_SYMBOLS = {
    "−": "-", "×": r"\times", "·": r"\cdot", "∘": r"\circ", "≤": r"\le", "≥": r"\ge",
    "≠": r"\neq", "∈": r"\in", "∉": r"\notin", "∧": r"\wedge", "∨": r"\vee", "⊂": r"\subset",
    "⊆": r"\subseteq", "⊕": r"\oplus", "⊗": r"\otimes", "→": r"\to", "↦": r"\mapsto",
    "⇒": r"\Rightarrow", "⇔": r"\Leftrightarrow", "∂": r"\partial", "∇": r"\nabla",
    "∑": r"\sum", "∏": r"\prod", "∫": r"\int", "∞": r"\infty", "≅": r"\cong",
    "≈": r"\approx", "≡": r"\equiv", "⟨": r"\langle", "⟩": r"\rangle", "½": r"\tfrac12",
    "⊥": r"\perp", "⟂": r"\perp", "⌈": r"\lceil", "⌉": r"\rceil", "⌊": r"\lfloor", "⌋": r"\rfloor", "∀": r"\forall", "∃": r"\exists", "±": r"\pm", "√": r"\surd",
    "∅": r"\emptyset", "∩": r"\cap", "∪": r"\cup", "∖": r"\setminus", "′": "'",
    "ℓ": r"\ell", "ħ": r"\hbar", "≔": ":=", "…": r"\dots", "⋯": r"\cdots",
}
_GREEK_LOWER = {"epsilon": "varepsilon", "phi": "varphi", "lamda": "lambda", "omicron": "o",
                "final sigma": "varsigma"}
_GREEK_UPPER = {"gamma", "delta", "theta", "lamda", "xi", "pi", "sigma", "upsilon", "phi",
                "psi", "omega"}
_ALPHABETS = {"DOUBLE-STRUCK": "mathbb", "FRAKTUR": "mathfrak", "BLACK-LETTER": "mathfrak",
              "SCRIPT": "mathcal", "BOLD SCRIPT": "mathcal", "BOLD": "mathbf", "ITALIC": "mathit"}


def _unicode_math(ch: str) -> str | None:
    """Math-mode LaTeX for one character, or None."""
    if ch in _MATH_SYMBOLS:
        return _MATH_SYMBOLS[ch]
    name = unicodedata.name(ch, "")
    m = re.fullmatch(r"GREEK (SMALL|CAPITAL) LETTER (.+?)( SYMBOL)?", name)
    if m:
        letter = m.group(2).lower()
        if m.group(3):  # ϕ, ϵ, ϑ: the symbol forms
            return {"phi": r"\phi", "theta": r"\vartheta", "epsilon": r"\epsilon",
                    "rho": r"\varrho", "pi": r"\varpi", "kappa": r"\varkappa"}.get(letter)
        if m.group(1) == "SMALL":
            cmd = _GREEK_LOWER.get(letter, letter)
            return cmd if len(cmd) == 1 else "\\" + cmd
        if letter in _GREEK_UPPER:
            cmd = "lambda" if letter == "lamda" else letter
            return "\\" + cmd.capitalize()
        greek_to_latin = {"alpha": "A", "beta": "B", "epsilon": "E", "zeta": "Z", "eta": "H",
                          "iota": "I", "kappa": "K", "mu": "M", "nu": "N", "omicron": "O",
                          "rho": "P", "tau": "T", "chi": "X"}
        return greek_to_latin.get(letter)
    m = re.fullmatch(r"(?:MATHEMATICAL )?(.+?) (CAPITAL|SMALL) ([A-Z])", name)
    if m and m.group(1) in _ALPHABETS:
        letter = m.group(3) if m.group(2) == "CAPITAL" else m.group(3).lower()
        return f"\\{_ALPHABETS[m.group(1)]}{{{letter}}}"
    return None


def _script_runs(text: str) -> list[tuple[str, str]]:
    """Split into ("sup", run), ("sub", run) and ("", other character) pieces."""
    out: list[tuple[str, str]] = []
    for ch in text:
        kind = "sup" if ch in _SUP else "sub" if ch in _SUB else ""
        if kind and out and out[-1][0] == kind:
            out[-1] = (kind, out[-1][1] + ch)
        else:
            out.append((kind, ch))
    return out


def _cmd(tex: str) -> str:
    """A command followed by a letter needs a separator."""
    return tex + " " if re.search(r"\\[A-Za-z]+$", tex) else tex


def one_line(text: Any, limit: int) -> bool:
    """Whether ``text`` is a string of 1 to ``limit`` characters with no line break or other control character:
    the words that head a line of the reports (a claim's section, labels and check names, a run's title), which
    a line break would turn into a table, a heading or an HTML block of the report's own.  Nor any invisible
    character that changes how a line reads: a format character (the bidirectional overrides and isolates, which
    display the rest of a line reversed, zero-width spaces and joiners), a line or paragraph separator, a C1
    control, a private-use, surrogate or unassigned code point (stop 86: a check name ending with U+202E displayed
    ": Ψ − XᵀP + PᵀX" as "XᵀP + PᵀX − Ψ :")."""
    return type(text) is str and 0 < len(text) <= limit and not re.search(r"[\x00-\x1f\x7f-\x9f]", text) \
        and not any(unicodedata.category(c) in _INVISIBLE for c in text if ord(c) > 0x7e)


#: the Unicode categories :func:`one_line` refuses: format, line and paragraph separators, controls, surrogates,
#: private use, unassigned
_INVISIBLE = frozenset({"Cf", "Zl", "Zp", "Cc", "Cs", "Co", "Cn"})


#: a short relation of running text, "r = 2", "n ≤ 2r + 1", "(n − r = 1": terms of a few characters joined by spaced
#: operators, one of them a relation; TeX would break the line at its spaces
_TERM = r"[^\s,;:.]{1,12}"
_RELATION_CHAIN = re.compile(rf"(?<![^\s(\[]){_TERM}(?: [=≤≥<>≠+−×∈] {_TERM}){{1,4}}(?=[\s,;:.]|$)")
_RELATIONS = "=≤≥<>≠∈"
#: the longest relation kept on one line whole; in a longer one only the relation signs are bound to their sides
SHORT_RELATION = 20
NBSP = "\u00a0"


def _bound(m: re.Match) -> str:
    text = m.group(0)
    if not any(f" {op} " in text for op in _RELATIONS):
        return text
    if len(text) <= SHORT_RELATION:
        return text.replace(" ", NBSP)
    return re.sub(rf" ([{_RELATIONS}]) ", NBSP + r"\1" + NBSP, text)


def bind_relations(text: str) -> str:
    """Short relations of running text with no-break spaces (a tie in LaTeX), so that a line never breaks inside
    "r = 2" or "n ≤ 2r + 1"; in a longer chain only around its relation signs."""
    return _RELATION_CHAIN.sub(_bound, text)


#: a code span of Markdown in plain words, `like this` (no backtick, newline or dollar inside)
_CODE_SPAN = re.compile(r"`([^`\n$]+)`")


def tt_escape(text: Any) -> str:
    """Plain text for ``\\texttt``: as :func:`tex_escape`, with the backslash and the braces taken from the typewriter
    font itself (``\\char92``, ``\\char123``, ``\\char125``): ``\\textbackslash`` and ``\\{`` are symbols of the
    OMS encoding, which has no typewriter shape (the font warning OMS/cmtt, and a glyph from another font); the tilde
    and the caret as characters (``\\char126``, ``\\char94``), not as accents."""
    return (_tex_escape_chars(bind_relations(str(text))).replace(r"\textbackslash{}", r"\char92{}")
            .replace(r"\{", r"\char123{}").replace(r"\}", r"\char125{}")
            .replace(r"\~{}", r"\char126{}").replace(r"\^{}", r"\char94{}"))


def tex_escape(text: Any) -> str:
    """Plain text to LaTeX text mode: specials escaped, Unicode mapped to LaTeX; a short relation kept on one line
    (:func:`bind_relations`); a code span `like this` set in typewriter type (TeX would print its backticks as
    opening quotes)."""
    text = str(text)
    if "`" in text and _CODE_SPAN.search(text):
        parts = _CODE_SPAN.split(text)           # text, code, text, code, ..., text
        return "".join(r"\texttt{" + tt_escape(p) + "}" if i % 2 else _tex_escape(p) for i, p in enumerate(parts))
    return _tex_escape(text)


@functools.lru_cache(maxsize=1 << 14)
def _tex_escape(text: str) -> str:
    """:func:`tex_escape` of a text without code spans (a pure function of the text: a report escapes the same
    words, a statement, a reduction, a message, for many records): the mathematics of the words
    (:func:`math_runs`) in math mode, the rest in text mode."""
    return _escape_with_math(bind_relations(text), {})


def _escape_with_math(text: str, scripts: dict[str, str]) -> str:
    """Text whose relations are bound already, its math runs in math mode; ``scripts`` maps a private-use
    character of the text to the LaTeX math of a script it stands for (:func:`_ascii_scripts`)."""
    out = []
    for is_math, piece in math_runs(text, scripts):
        if is_math:
            math = _tex_math_run(piece, scripts)
            out.append(r"\mbox{\ensuremath{" + math + "}}" if NBSP in piece and " " not in piece
                       else r"\ensuremath{" + math + "}")
        else:
            out.append(_tex_escape_chars(piece, scripts))
    return "".join(out)


#: the operators of the paper's words, upright in math, and its groups and Lie algebras, in math italic as the paper
#: sets them ($SO(n)$, $so(r)$): (name, how it is set)
_UPRIGHT_NAMES = {**{n: r"\mathop{\mathrm{%s}}\nolimits " % n for n in
                     "det tr rank dim diag ad Ad span ddim Pf exp ker sgn pr adj axial Sym".split()},
                  **{n: n for n in "SO GL Sp SU so gl sp su".split()}}
#: ASCII characters a math run may contain besides letters and digits (no TeX special: _ ^ { } # % & $ \ ~; no quote,
#: which math mode reads as a prime: "'G_I(V)^2'" would be a double superscript)
_MATH_ASCII = frozenset("()[]+-*/=<>|,")
#: a binary operator or a relation standing alone between two math runs: "A + λIₙ", "XᵀP + PᵀX"
_OPERATOR_TOKEN = frozenset("+−-=≤≥<>≠∈×·∧→↦⊂⊆⊥≅≈≡∘⊕⊗")
_PUNCTUATION = ",;:.!?"
#: quotation marks around words, text before and after the mathematics they quote (“V_{n,n} is SO(n)”)
_OPENING_QUOTES = "“‘"
_CLOSING_QUOTES = "”’"
#: a word of mathematics and a word of text joined by a hyphen (SO(n)×SO(r)-invariant, 2r-plane, SO(n − r)-orbit):
#: the words after it that the catalog's prose uses (not a name such as 2r-integrals, which stays text whole)
_WORD_AFTER = re.compile(r"(.+?)(-(?:invariant|invariance|equivariant|orbits?|planes?|actions?|dimensional|symmetry)"
                         r"(?:-[a-z]+)?)")


def _math_char(ch: str, scripts: dict[str, str]) -> bool:
    """Whether ``ch`` is a character of mathematics that text never has: a Greek letter, a script, a math symbol or
    a letter of a math alphabet (ℝ, 𝔤, 𝒜), a script of ASCII notation, or the mark of a time derivative or a
    conjugate on a letter (Ẋ, ë₃, Z̄, Φ̇: a word of more letters with such a mark, Möbius, stays text by
    :func:`_math_token`'s rule on runs of letters)."""
    return ch in scripts or ch in _SUP or ch in _SUB or ch in _COMBINING or _marked_letter(ch) is not None or (
        ord(ch) > 127 and ch not in _TEXT_ONLY and ch != NBSP and _unicode_math(ch) is not None)


def _marked_letter(ch: str) -> str | None:
    """The math of a Latin letter written with the marks of :data:`_COMBINING` in one character (Ẋ, ė, ë, Ȳ):
    ``\\dot{X}``; None for any other character."""
    base, *marks = unicodedata.normalize("NFD", ch)
    if not marks or not base.isascii() or not base.isalpha() or any(m not in _COMBINING for m in marks):
        return None
    for m in marks:
        base = _COMBINING[m] + "{" + base + "}"
    return base


def _math_token(core: str, scripts: dict[str, str]) -> bool:
    """Whether a word (its outer punctuation taken off) is mathematics: made of letters, digits, math characters
    and ``()[]+-*/=<>|',`` only, every run of Latin letters one letter or an operator or group name (det, tr, SO),
    and one Latin letter alone or a math character in it ("r", "2r", "Λ₁", "TₓO", "so(r", "X = ±1")."""
    if not core or not all(c.isascii() and (c.isalnum() or c in _MATH_ASCII or c in ".{}") or c in (NBSP, "…", "⋯")
                           or _math_char(c, scripts) for c in core):
        return False
    if core in _OPERATOR_TOKEN or core[0] in "<>" or core[-1] in "<>" or "<=" in core or ">=" in core:    # a lone operator, an angle bracket
        return False
    if re.search(r"(?<!\d)\.|\.(?!\d)", core.replace("...", "…").replace("..", "…")):   # a point only in a decimal
        # number or an ellipsis (a₁..aₙ): not e.g
        return False
    runs = re.findall(r"[A-Za-z]+", core)
    scripted = any(_math_char(c, scripts) for c in core)
    # a product of matrices written together (PXᵀ, XXᵀ, gXhᵀ), a matrix times a vector or a scalar times a matrix
    # (Aeₙ, wIₙ, fE₁) or a differential (de₁, ds²): two letters, or up to 4 with no two small letters together
    # (every word but a, I has two): mathematics where a math character
    # says so (UNEXPECTED, LA1, of are words and names); a small letter and a capital (a differential dF, a scalar
    # times a matrix wI: no word is written so) are mathematics anywhere, and a differential of a small letter in a
    # quotient of differentials (de₃/dt, d(XᵀX)/dt)
    quotient = "/" in core

    def letters(w: str) -> bool:
        return (len(w) == 1 or w in _UPRIGHT_NAMES or bool(re.fullmatch(r"[a-z][A-Z]", w))
                or scripted and (len(w) == 2 or len(w) <= 4 and not re.search(r"[a-z]{2}", w))
                or quotient and bool(re.fullmatch(r"d[a-z]", w)))
    if not all(letters(w) for w in runs):
        return False
    if re.fullmatch(r"\d+(?:\.\d+)?e[-+]?\d+", core):     # a number in E notation
        return False
    return any(len(w) == 1 or re.fullmatch(r"d[A-Za-z]|[a-z][A-Z]", w) for w in runs) or scripted


def _depth(text: str) -> int:
    return sum(text.count(c) for c in "([{") - sum(text.count(c) for c in ")]}")


def math_runs(text: str, scripts: dict[str, str] | None = None) -> list[tuple[bool, str]]:
    """Plain words cut into (is_math, piece): the mathematics of running text ("r", "2l ≤ n² − n", "Λ₁", "TₓO",
    "A + λIₙ", "det X", "(X₀, P₀)") as math pieces, everything else as text.  A word is mathematics as
    :func:`_math_token` says, except "a", "A" opening a sentence, and "s" after a number ("0.2 s"); math words
    joined by a lone operator ("A + λIₙ", "e₁ ∧ p₁ + … + eᵣ ∧ pᵣ") are one piece, and so are an operator name
    before a math word ("det X") and math words after a comma inside brackets ("(X₀, P₀)"); a bracket without its
    partner in the piece is left in the text."""
    scripts = scripts or {}
    tokens = re.split(r"([ \u00a0]+)", text)     # a no-break space (a bound relation) separates words too
    if tokens[0][:1] in tuple(_OPENING_QUOTES):
        tokens[:1] = ["", "", tokens[0]]
    for i in range(2, len(tokens), 2):          # an opening quotation mark is text before the word it opens
        lead = tokens[i][:len(tokens[i]) - len(tokens[i].lstrip(_OPENING_QUOTES))]
        tokens[i - 1], tokens[i] = tokens[i - 1] + lead, tokens[i][len(lead):]
    words: list[list[Any]] = []              # [core, tail, math] of each word (tokens[2 i])
    for i in range(0, len(tokens), 2):
        token = tokens[i]
        core = token.rstrip(_PUNCTUATION + _CLOSING_QUOTES) if token not in ("...", "…", "⋯") else token
        tail = token[len(core):]
        math = _math_token(core, scripts)
        suffix = _WORD_AFTER.fullmatch(core) if not math else None
        if suffix and _math_token(suffix.group(1), scripts):    # SO(n)×SO(r)-invariant, 2r-plane: a word after
            core, tail, math = suffix.group(1), suffix.group(2) + tail, True
        word = core.strip("()[]")
        if math and word in ("a", "A", "s"):    # an article, a sentence's first word, a unit of seconds
            before = "".join(tokens[:i]).rstrip() + core[:len(core) - len(core.lstrip("(["))]
            math = not (word == "a" or (word == "A" and (not before or before[-1] in ".!?"))
                        or (word == "s" and re.search(r"\d$", before)))
        words.append([core, tail, math])
    def joining(w: list[Any]) -> bool:
        return not w[1] and (w[0] in _OPERATOR_TOKEN or w[0] in ("...", "…", "⋯"))
    for k, (core, tail, math) in enumerate(words):     # names before math words
        if not math and not tail and core in _UPRIGHT_NAMES and k + 1 < len(words) and words[k + 1][2]:
            words[k][2] = True
    for k in range(len(words)):                         # lone operators (and ellipses) after a math word
        prev, nxt = words[k - 1] if k else None, words[k + 1] if k + 1 < len(words) else None
        if not words[k][2] and joining(words[k]) and prev and prev[2] and not prev[1] and nxt \
                and (nxt[2] or joining(nxt) or re.fullmatch(r"\d+", nxt[0])):
            words[k][2] = True
            if re.fullmatch(r"\d+", nxt[0]):          # a number after an operator: "2r + 2"
                nxt[2] = True
    while words and words[-1][2] and joining(words[-1]):    # ... but not a chain that ends in an operator
        words[-1][2] = False
    for k in range(len(words) - 2, -1, -1):
        if words[k][2] and joining(words[k]) and not words[k + 1][2]:
            words[k][2] = False
    out: list[tuple[bool, str]] = []

    def put(is_math: bool, piece: str) -> None:
        if piece:
            out.append((is_math, out.pop()[1] + piece) if out and out[-1][0] == is_math else (is_math, piece))
    depth = 0
    for k, (core, tail, math) in enumerate(words):
        if k:
            prev, space = words[k - 1], tokens[2 * k - 1]
            joined = prev[2] and math and not space.strip(" \u00a0") and (
                not prev[1] and (prev[0] in _OPERATOR_TOKEN or core in _OPERATOR_TOKEN or prev[0] in _UPRIGHT_NAMES
                                 or prev[0] in ("Σ", "∑")
                                 or prev[0] in ("...", "…", "⋯") or core in ("...", "…", "⋯"))
                or prev[1] in ("", ",") and depth > 0)
            if joined:
                put(True, (prev[1] if prev[1] else "") + space)
            else:
                put(False, prev[1] + space) if prev[2] else put(False, space)
                depth = 0
        if math:
            put(True, core)
            depth += _depth(core)
        else:
            put(False, core + tail)
    if words and words[-1][2]:
        put(False, words[-1][1])
    return [piece for run in out for piece in (_bracketed(run[1]) if run[0] else [(False, run[1])]) if piece[1]]


def _bracketed(piece: str) -> list[tuple[bool, str]]:
    """A math piece with the brackets that have no partner in it taken out to the text: "(A" as "(" and "A"."""
    head, tail = "", ""
    while piece and piece[0] in "([{" and _depth(piece) > 0:
        head, piece = head + piece[0], piece[1:]
    while piece and piece[-1] in ")]}" and _depth(piece) < 0:
        tail, piece = piece[-1] + tail, piece[:-1]
    return [(False, head), (True, piece), (False, tail)] if piece.strip() else [(False, head + piece + tail)]


def _tex_math_run(piece: str, scripts: dict[str, str]) -> str:
    """The LaTeX math of a math piece of running text: names upright, scripts of ASCII notation as they are
    set, the rest as :func:`tex_math` sets it."""
    piece = re.sub(r"(?<=[^\W_]|[)\]}])\*", "\x05", piece)       # T*V, 𝒜*ₘₐₙ, λ*: a star is a superscript
    # a run of letters whose last letter bears a mark (DẊ: D, X and U+0307) is not a name: tex_math sets the mark
    parts = re.split(r"([A-Za-z]{2,}(?![A-Za-z\u0300-\u036f])|[\ue000-\uf8ff])",
                     piece.replace(NBSP, " ").replace("...", "…"))
    return "".join(scripts[part] if part in scripts else _UPRIGHT_NAMES.get(part, part) if i % 2 else _braced(part)
                   for i, part in enumerate(parts)).strip().replace("\x05", "^{*}")


def _braced(part: str) -> str:
    """:func:`tex_math` of words whose braces are braces ({F_i, F_j}, span{e, p}: a bracket or a set), not groups."""
    return tex_math(part.replace("{", "\x02").replace("}", "\x03")).replace("\x02", r"\{").replace("\x03", r"\}")


def _tex_escape_chars(text: str, scripts: dict[str, str] | None = None) -> str:
    """Text mode, character by character: specials escaped, each Unicode math character (and each script of
    ``scripts``) in its own math group."""
    out = []
    for kind, piece in _script_runs(text):
        if kind == "sup":
            out.append(r"\ensuremath{^{" + "".join(_SUP[c] for c in piece) + "}}")
        elif kind == "sub":
            out.append(r"\ensuremath{_{" + "".join(_SUB[c] for c in piece) + "}}")
        elif piece in _TEX_SPECIAL:
            out.append(_TEX_SPECIAL[piece])
        elif scripts and piece in scripts:
            out.append(r"\ensuremath{" + scripts[piece] + "}")
        elif piece in "\n\t\r":
            out.append(" ")
        elif piece == NBSP:
            out.append(r"\nobreakspace{}")
        elif ord(piece) < 32 or ord(piece) == 127:     # a control character: named, never handed to TeX
            out.append(r"\texttt{[U+%04X]}" % ord(piece))
        elif ord(piece) < 128:
            out.append(piece)
        elif piece in _COMBINING and out and _markable(out[-1]):
            out[-1] = r"\ensuremath{" + _COMBINING[piece] + "{" + _markable(out[-1]) + "}}"   # Q̇, Σ̄, 𝒳̇, Ż̄
        elif piece in _TEXT_ONLY:
            out.append(_TEXT_ONLY[piece])
        else:
            out.append(_tex_nonascii(piece))
    return "".join(out)


def _markable(prev: str) -> str:
    """What a combining mark puts its accent on, for ``prev``, the text of the character before it: a letter, the
    math of one character (\\ensuremath{\\mathcal{X}}: each character is one group), or any other text of a
    letter as a box (\\.{Z}); "" for a script (an accent on ^{2} is no LaTeX), which keeps the mark as its code."""
    if len(prev) == 1:
        return prev if prev.isalpha() else ""
    if prev.startswith("\\ensuremath{") and prev.endswith("}"):
        inner = prev[len("\\ensuremath{"):-1]
        return "" if inner.startswith(("^", "_")) else inner
    return r"\mbox{" + prev + "}" if prev.startswith("\\") else ""


#: combining marks written after a letter (U+0307 dot above, U+0308 diaeresis: time derivatives)
_COMBINING = {"\u0307": r"\dot", "\u0308": r"\ddot", "\u0304": r"\bar"}


def _tex_nonascii(ch: str) -> str:
    math = _unicode_math(ch)
    if math is not None:
        return r"\ensuremath{" + math + "}"
    base, *marks = unicodedata.normalize("NFD", ch)
    if ord(base) < 128 and marks and all(m in _ACCENTS for m in marks):
        res = base if base not in "ij" else "\\" + base  # dotless i, j under accents
        for m in marks:
            res = f"\\{_ACCENTS[m]}{{{res}}}"
        return res
    folded = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode()
    if folded and folded.isalnum():
        return folded
    return r"\texttt{[U+%04X]}" % ord(ch)


def tex_math(statement: str) -> str:
    """A LaTeX math statement, Unicode characters mapped to math commands."""
    out = []
    for kind, piece in _script_runs(statement):
        if kind == "sup":
            out.append("^{" + "".join(_SUP[c] for c in piece) + "}")
        elif kind == "sub":
            out.append("_{" + "".join(_SUB[c] for c in piece) + "}")
        elif ord(piece) < 128:
            out.append(piece)
        elif piece in _COMBINING and out and not out[-1].startswith(("^", "_")):
            out[-1] = _COMBINING[piece] + "{" + out[-1].rstrip() + "}"      # Φ̇, 𝒳̇: the mark on the letter before
        elif _marked_letter(piece) is not None:
            out.append(_marked_letter(piece) or "")
        else:
            m = _unicode_math(piece)
            out.append(_cmd(m) if m is not None else r"\text{" + _tex_nonascii(piece) + "}")
    return "".join(out)


def split_math(text: str) -> list[tuple[bool, str]]:
    """Split text at unescaped ``$``: (is_math, segment).  Unpaired ``$``: all text."""
    pieces = re.split(r"(?<!\\)\$", text)
    if len(pieces) % 2 == 0 or len(pieces) == 1:
        return [(False, text)]
    return [(i % 2 == 1, p) for i, p in enumerate(pieces) if p or i % 2 == 0]


def tex_balanced(tex: str) -> bool:
    """Balanced braces, environments and display delimiters, only the vocabulary of a derivation
    (:data:`DERIVATION_COMMANDS`): safe to include as is."""
    if not _braces_balanced(tex):
        return False
    if not _vocabulary_ok(tex, DERIVATION_COMMANDS, DERIVATION_ENVIRONMENTS, _MATH_SYMBOLS_ESCAPED | _DERIVATION_SYMBOLS):
        return False
    if len(re.findall(r"\\\[", tex)) != len(re.findall(r"\\\]", tex)):
        return False
    if re.search(r"\\(?:end|begin)\{document\}", tex):
        return False
    return _environments_balanced(tex)


def _environments_balanced(tex: str) -> bool:
    begins = Counter(re.findall(r"\\begin\s*\{([^}]*)\}", tex))
    return begins == Counter(re.findall(r"\\end\s*\{([^}]*)\}", tex))


#: the deepest nesting of braces a claim's formula may have (TeX stops at 255 groups, with no document)
MAX_BRACE_DEPTH = 32


def _braces_balanced(tex: str) -> bool:
    depth = 0
    for m in re.finditer(r"\\.|[{}]", tex, re.S):
        tok = m.group()
        if tok == "{":
            depth += 1
            if depth > MAX_BRACE_DEPTH:
                return False
        elif tok == "}":
            depth -= 1
            if depth < 0:
                return False
    return depth == 0


def _delimiters_paired(tex: str) -> bool:
    """As many \\left as \\right, and no blank line (a paragraph break, which math mode refuses)."""
    return (len(re.findall(r"\\left(?![A-Za-z])", tex)) == len(re.findall(r"\\right(?![A-Za-z])", tex))
            and not re.search(r"\n[ \t]*\n", tex))


#: the control sequences a formula of a claim (its statement, the ``$...$`` of its docstring and title) may use:
#: the vocabulary of mathematics, each defined by the report's preamble (amsmath, amssymb and its operators).  A
#: formula with any other (\\def, \\let, \\input, \\catcode, \\write, a font or package the preamble lacks, ...)
#: is set as plain text: a claims file cannot redefine what the report prints, read a file into it, or break it
MATH_COMMANDS = frozenset("""
    alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi varpi rho varrho
    sigma varsigma tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega
    cdot cdots ldots dots vdots ddots times circ otimes oplus ominus odot wedge vee cap cup setminus pm mp ast star
    bullet div le leq ge geq ne neq equiv cong sim simeq approx propto in notin ni subset subseteq supset supseteq
    perp parallel mid nmid not to mapsto gets rightarrow leftarrow Rightarrow Leftarrow leftrightarrow
    Leftrightarrow longrightarrow longleftarrow Longrightarrow Longleftarrow longmapsto iff implies hookrightarrow
    uparrow downarrow sum prod coprod int oint bigoplus bigotimes bigcup bigcap bigwedge
    left right big Big bigg Bigg bigl bigr Bigl Bigr biggl biggr langle rangle lvert rvert lVert rVert vert Vert
    lbrace rbrace lfloor rfloor lceil rceil backslash
    mathrm mathbf mathit mathcal mathbb mathfrak mathsf mathtt boldsymbol operatorname text textrm textit textbf
    textup emph
    hat bar tilde dot ddot vec widehat widetilde overline underline check breve acute grave
    frac tfrac dfrac binom tbinom dbinom sqrt overset underset stackrel
    quad qquad infty partial nabla forall exists nexists emptyset varnothing ell hbar imath jmath top bot sharp
    flat natural prime angle triangle Box
    det dim ker deg exp log ln sin cos tan sinh cosh tanh max min sup inf lim liminf limsup arg gcd Re Im Pr hom
    tr diag ad Ad rank ddim pr Span
    displaystyle textstyle scriptstyle scriptscriptstyle ensuremath begin end
""".split())
#: the environments a formula of a claim may open (amsmath's)
MATH_ENVIRONMENTS = frozenset("""matrix pmatrix bmatrix Bmatrix vmatrix Vmatrix smallmatrix cases aligned gathered
    split""".split())
#: the control symbols (a backslash and one character) a formula may use: spacing, a line break, escaped specials
_MATH_SYMBOLS_ESCAPED = frozenset(" ,;:!{}|_%#&$\\")
#: what the engine's own LaTeX of a dimension-free derivation adds to them (a record's derivation is data of a
#: results file, which ``report`` renders: the same allow-list, with the few text commands the engine writes)
DERIVATION_COMMANDS = MATH_COMMANDS | frozenset("paragraph item textbf emph texttt textbackslash ldots S P surd i j v "
                                                 "c u nobreakspace mbox".split())
DERIVATION_ENVIRONMENTS = MATH_ENVIRONMENTS | frozenset(("itemize", "enumerate"))
#: ... and the control symbols of text that :func:`tex_escape` writes (accents, ``\^{}``, ``\~{}``, display math)
_DERIVATION_SYMBOLS = frozenset("[]^~'`\".=")


def _vocabulary_ok(tex: str, commands: frozenset, environments: frozenset, symbols: frozenset) -> bool:
    """Every control sequence of ``tex`` in ``commands`` (a control symbol in ``symbols``), every environment in
    ``environments``, no control character, no ``^^`` (TeX's notation of a character by its code, which spells any
    command), no unescaped ``%`` (a comment would swallow the rest of the line) or ``#``."""
    if re.search(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]|\^\^", tex):
        return False
    for m in re.finditer(r"\\([A-Za-z]+)|\\(.)|([%#])", tex, re.S):
        word, sym, bare = m.groups()
        if bare or (word is not None and word not in commands) or (sym is not None and sym not in symbols):
            return False
    return all(env in environments for env in re.findall(r"\\(?:begin|end)\s*\{([^}]*)\}", tex))


#: the commands of :data:`MATH_COMMANDS` that take arguments, with how many (a missing one is a TeX error)
_ARGUMENTS = {**{c: 2 for c in "frac tfrac dfrac binom tbinom dbinom overset underset stackrel".split()},
              **{c: 1 for c in """sqrt mathrm mathbf mathit mathcal mathbb mathfrak mathsf mathtt boldsymbol operatorname
                 text textrm textit textbf textup emph hat bar tilde dot ddot vec widehat widetilde overline underline
                 check breve acute grave ensuremath begin end left right big Big bigg Bigg bigl bigr Bigl Bigr biggl
                 biggr""".split()}}
_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\s+|.", re.S)


class _Ungrammatical(ValueError):
    pass


#: commands followed by one delimiter (any one token)
_DELIMITED = frozenset("left right big Big bigg Bigg bigl bigr Bigl Bigr biggl biggr".split())


def _grammar_ok(tex: str) -> bool:
    """What TeX refuses in math beyond the vocabulary and the balance: a command without its arguments (\\frac
    at the end of a group), a script with nothing to raise, a second superscript or subscript of one nucleus
    (a^b^c).  A formula that passes may still be odd; one that fails is set as text, never handed to TeX."""
    tokens = [t for t in _TOKEN.findall(tex) if not t.isspace()]

    def argument(i: int) -> int:
        if i >= len(tokens) or tokens[i] in ("}", "^", "_", "&", "\\\\", "$"):
            raise _Ungrammatical
        if tokens[i] == "{":
            return group(i)
        if tokens[i][1:] in _ARGUMENTS and tokens[i].startswith("\\"):
            raise _Ungrammatical      # a^\frac{1}{2}: TeX wants braces around it
        return i + 1

    def group(i: int) -> int:
        i = sequence(i + 1, True)
        return i + 1

    def sequence(i: int, closed: bool) -> int:
        scripts: set[str] = set()
        while i < len(tokens):
            t = tokens[i]
            if t == "}":
                if not closed:
                    raise _Ungrammatical
                return i
            if t in ("^", "_"):
                if t in scripts:
                    raise _Ungrammatical
                scripts.add(t)
                i = argument(i + 1)
                continue
            if t == "'":
                i += 1
                continue
            scripts = set()
            if t == "{":
                i = group(i)
                continue
            name = t[1:] if t.startswith("\\") else ""
            i += 1
            if name in _DELIMITED:
                if i >= len(tokens) or tokens[i] in ("}", "^", "_", "&", "{"):
                    raise _Ungrammatical
                i += 1
            elif name in ("begin", "end"):
                if i >= len(tokens) or tokens[i] != "{":
                    raise _Ungrammatical
                i = group(i)
            elif name in _ARGUMENTS:
                if name == "sqrt" and i < len(tokens) and tokens[i] == "[":
                    while i < len(tokens) and tokens[i] != "]":
                        i += 1
                    i += 1
                for _ in range(_ARGUMENTS[name]):
                    i = argument(i)
        if closed:
            raise _Ungrammatical
        return i

    try:
        sequence(0, False)
    except _Ungrammatical:
        return False
    return True


def math_ok(tex: str) -> bool:
    """Balanced braces and environments, no math delimiters, only the vocabulary of mathematics
    (:data:`MATH_COMMANDS`): safe inside a display."""
    if not _braces_balanced(tex):
        return False
    if re.search(r"(?<!\\)\$|\\[\[\]()]", tex):
        return False
    if not _vocabulary_ok(tex, MATH_COMMANDS, MATH_ENVIRONMENTS, _MATH_SYMBOLS_ESCAPED) or not _delimiters_paired(tex):
        return False
    return _environments_balanced(tex) and _grammar_ok(tex)


def _toplevel(tex: str) -> str:
    """``tex`` with every environment block removed (for spotting top-level & and \\\\)."""
    prev = None
    while prev != tex:
        prev, tex = tex, re.sub(r"\\begin\{([^}]*)\}(?:(?!\\begin\{).)*?\\end\{\1\}", "", tex,
                                flags=re.S)
    return tex


#: the Greek letters of the paper as the claims' check names spell them in ASCII
_GREEK_WORDS = {"Phi": "Φ", "Psi": "Ψ", "Lambda": "Λ", "lambda": "λ", "kappa": "κ", "Pi": "Π", "Omega": "Ω",
                "eta": "η", "xi": "ξ", "zeta": "ζ", "theta": "θ", "epsilon": "ε", "eps": "ε", "nu": "ν",
                "Sigma": "Σ", "sigma": "σ", "omega": "ω", "mu": "μ", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ"}


_GREEK_WORD = re.compile(r"(?<![A-Za-z])(d?)(" + "|".join(sorted(_GREEK_WORDS, key=len, reverse=True)) + r")(?![a-z])")


def greek_words(text: str) -> str:
    """Plain words that spell the paper's Greek letters in ASCII (Psi, lambda, L(nu), eta_so(r)) with
    the letters themselves; a word that merely contains one (beta, Pit) is left alone."""
    return _GREEK_WORD.sub(lambda m: m.group(1) + _GREEK_WORDS[m.group(2)], text)


def unicode_name(name: str) -> str:
    """A check's ASCII name as mathematics in Unicode: ``X^T`` as Xᵀ, ``Phi`` as Φ, a trailing
    entry ``[1,2]`` as ", entry (1,2)"."""
    name = re.sub(r"\^T\b", "ᵀ", name)
    name = greek_words(name)
    return re.sub(r"\[(\d+),(\d+)\]$", r", entry (\1,\2)", name)


def tex_text(text: str, plain: Any = None) -> str:
    """Running text that may contain ``$...$`` math (docstrings); the text around the math set by
    ``plain`` (default :func:`tex_escape`)."""
    plain = plain or tex_escape
    out = []
    for is_math, seg in split_math(str(text)):
        if is_math and math_ok(seg):
            out.append("$" + tex_math(seg) + "$")
        else:
            out.append(plain(f"${seg}$" if is_math else seg))
    return "".join(out)


def tex_display(statement: str) -> str:
    """A statement in display math (``align*`` if it aligns, ``gather*`` if multi-line)."""
    s = statement.strip()
    if not s:
        return ""
    if not math_ok(s):
        return ("\\noindent\\texttt{" + tex_escape(s) + "}\\\\\n"
                "{\\small (statement shown verbatim: it is not balanced LaTeX math)}\n")
    body = tex_math(s)
    top = _toplevel(body)
    if re.search(r"(?<!\\)&", top):
        body = "\\begin{aligned}\n" + body + "\n\\end{aligned}"
    elif "\\\\" in top:
        body = "\\begin{gathered}\n" + body + "\n\\end{gathered}"
    else:
        pieces = display_pieces(body)
        if len(pieces) > 1:
            return _fitted_display(body, pieces)
    # shrunk to the line's width when it is wider (never an overfull line), at its size otherwise
    return ("\\begin{center}\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!}{$\\displaystyle\n"
            + body + "\n$}\\end{center}\n")


#: where a display of several formulas may break: a comma, semicolon or colon followed by a space
#: command (a control space, a quad or a qquad), at the top level of the formula only
_BREAK = re.compile(r"([,;:])\s*(?:\\qquad|\\quad|\\ )\s*")

#: a display wider than this many line widths is set on several lines rather than shrunk
WIDE = "1.15"


def display_pieces(body: str) -> list[str]:
    r"""The formulas of a display separated at its top level (outside braces, environments,
    ``\left … \right``, parentheses, brackets and ``\{ \}``) by ``,\ ``, ``,\quad``, ``;\quad``,
    ``:\ ``, …; each piece keeps its punctuation.  One piece when there is no such break."""
    depth, cuts, i = 0, [], 0
    while i < len(body):
        m = re.match(r"\\(begin|end)\{[^}]*\}|\\(left|right)(?![A-Za-z])|\\[A-Za-z]+|\\.", body[i:])
        if m:
            token = m.group(0)
            if m.group(1) == "begin" or m.group(2) == "left" or token in ("\\{", "\\langle"):
                depth += 1
            elif m.group(1) == "end" or m.group(2) == "right" or token in ("\\}", "\\rangle"):
                depth -= 1
            i += len(token)
            continue
        if body[i] in "{([":
            depth += 1
        elif body[i] in "})]":
            depth -= 1
        elif depth == 0 and body[i] in ",;:":
            brk = _BREAK.match(body, i)
            if brk:
                cuts.append((i + 1, brk.end()))
        i += 1
    pieces, at = [], 0
    for end, nxt in cuts:
        pieces.append(body[at:end].strip())
        at = nxt
    pieces.append(body[at:].strip())
    return [p for p in pieces if p]


def _visible(tex: str) -> int:
    """A rough width of a formula in characters: a command counts as one, braces as nothing."""
    return len(re.sub(r"[{}]", "", re.sub(r"\\[A-Za-z]+", "x", tex)))


def _two_lines(pieces: list[str]) -> list[str]:
    """The pieces on two lines of about equal width, in their order."""
    widths = [_visible(p) for p in pieces]
    best = min(range(1, len(pieces)), key=lambda j: abs(2 * sum(widths[:j]) - sum(widths)))
    return ["\\quad ".join(pieces[:best]), "\\quad ".join(pieces[best:])]


def _fitted_display(body: str, pieces: list[str]) -> str:
    r"""A display of several formulas as TeX fits it: on one line if it is at most :data:`WIDE` line
    widths wide, else on two lines of about equal width if those are, else one formula a line; the
    chosen form is shrunk to the line's width when it is still wider (never an overfull line)."""
    def gathered(lines: list[str]) -> str:
        return "$\\displaystyle\\begin{gathered}\n" + "\\\\\n".join(lines) + "\n\\end{gathered}$"
    return ("\\begin{center}\\sbox0{$\\displaystyle\n" + body + "\n$}%\n"
            f"\\ifdim\\wd0>{WIDE}\\linewidth\\sbox0{{" + gathered(_two_lines(pieces)) + "}\\fi%\n"
            f"\\ifdim\\wd0>{WIDE}\\linewidth\\sbox0{{" + gathered(pieces) + "}\\fi%\n"
            "\\resizebox{\\ifdim\\wd0>\\linewidth\\linewidth\\else\\wd0\\fi}{!}{\\usebox0}\\end{center}\n")




#: a script in ASCII notation in plain words: ^{...} or _{...} (one level of nested braces), ^ and digits
#: (an optional minus), ^⊥, ^∞, or _ and one letter or digit that no letter or digit but a Unicode script follows
#: (I_n, F_Ω, a_i²; not the underscore inside a name such as N0_XP2), or ^ and an integer or one letter in parentheses (the
#: parentheses of a negative power dropped, (μI_n - A)^(-1); kept in f^(k); a subscript _(m) stays as written)
_ASCII_SCRIPT = re.compile(r"(\^|_)(\{(?:[^{}]|\{[^{}]*\})*\}|(?<=\^)\(-?(?:\d+|[^\W\d_])\)|-?\d+(?![^\W_])|⊥|∞|[^\W_]"
                           r"(?!(?![" + "".join(_SUP) + "".join(_SUB) + r"])[^\W_]))")


_UNICODE_SUB = dict(zip("0123456789+-−=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ"))
_UNICODE_SUP = dict(zip("0123456789+-−=()TabcdefghijklmnoprstuvwxyzABDEGHIJKLMNOPRUVW",
                        "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻⁼⁽⁾ᵀᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖʳˢᵗᵘᵛʷˣʸᶻᴬᴮᴰᴱᴳᴴᴵᴶᴷᴸᴹᴺᴼᴾᴿᵁⱽᵂ"))


def unicode_words(text: str) -> str:
    """Plain words that write scripts in ASCII (I_n, (A + λI_n)^{-1}, diag(I_{n-r}, B^{-1})) for a reader
    of plain text (Markdown): each script whose every character has a Unicode sub- or superscript set
    as one (Iₙ, ⁻¹, Iₙ₋ᵣ), a spaced ^ as the wedge, a spaced <= and >= as ≤ and ≥; any other script
    keeps its ASCII form with its own scripts set (_{I_2} as _{I₂}, ^⊥ as it is).  ``$...$`` (LaTeX the
    Markdown shows as mathematics) is kept as written."""
    return "".join(f"${seg}$" if is_math else _unicode_scripts(seg) for is_math, seg in split_math(text))


#: ASCII idioms of the catalog's prose for the paper's notation: (pattern, replacement), in this order
_MATH_IDIOMS = (
    (re.compile(r"(?<=\s)!=(?=\s)"), lambda m: "≠"),
    (re.compile(r"\b(\w)<=(\w)<=(\w)\b"), lambda m: f"{m.group(1)}≤{m.group(2)}≤{m.group(3)}"),
    (re.compile(r"(?<=\s)->(?=\s)"), lambda m: "→"),
    # a cross product of two vectors with indices: e_1 x e_2, e_3 x de_3/dt
    (re.compile(r"(\b[A-Za-z]_\w+) x (?=[A-Za-z])"), lambda m: m.group(1) + " × "),
    # a size: r x r, 2r x 2r, n x r, (n + r) x 2r
    (re.compile(r"(\b\d*[nrkm]\b|\b\d+\b|\)) x (?=\(|\d*[nrkm]\b|\d+\b)"), lambda m: m.group(1) + " × "),
    (re.compile(r"\b([XPYQ])0\b"), lambda m: m.group(1) + "₀"),
    # a second derivative in Leibniz's notation: d^2X/dt^2, d^2(X^T P)
    (re.compile(r"(?<![^\W\d_])d\^(\d+)(?=[^\W\d_]|\()"), lambda m: "d^{" + m.group(1) + "}"),
)


#: the dual Lax matrices of the paper, 𝓛*_neum, 𝓐*_man, ... written L*_neum, A*_man
_DUAL_LAX = re.compile(r"(?<![A-Za-z])([LA])\*_(?=neum|man)")
#: subscripts the PDF sets as one (the Markdown keeps them as written): the paper's named ones (H_neum, 𝓛*_man, ω_mag, H_CPB) with a
#: second index as the paper writes them (H_neum,κ as H_{neum,κ}; H_neum_0 and H_neum₀ as H_{neum_0}), a Lie algebra's
#: (eta_so(r)) and two indices (Psi_ij)
_TEX_SUBSCRIPTS = (re.compile(r"(?<=[^\W_]|\)|\*)_((?:neum|man|mag|CPB|CP)(?:,[^\s,;:.()]+|_[^\W_]+|[₀-₉]+)?)(?![^\W_])"),
                   re.compile(r"(?<=[^\W_]|\))_((?:so|sp|gl|u)\([^()\s]*\))"),
                   re.compile(r"(?<=[^\W_]|\))_([ijklabpq][ijklabpq])\b"))


def math_idioms(text: str, tex: bool = False) -> str:
    """The ASCII idioms of plain prose for the paper's notation: L*_neum as 𝓛*_neum, e_3 x de_3 as a cross
    product, a spaced != as ≠, a range 1<=i<=r as 1≤i≤r (a single a<=b inside a word stays), a spaced -> as →,
    a size r x r as r × r, X0 as X₀ (and the Greek words, :func:`greek_words`); with ``tex``, the subscripts of
    H_neum, eta_so(r) and Psi_ij set as one (:data:`_TEX_SUBSCRIPTS`)."""
    text = _DUAL_LAX.sub(lambda m: ("𝓛" if m.group(1) == "L" else "𝓐") + "*_", greek_words(text))
    for pattern, repl in _MATH_IDIOMS:
        text = pattern.sub(repl, text)
    if tex:
        for pattern in _TEX_SUBSCRIPTS:
            text = pattern.sub(lambda m: "_{" + m.group(1) + "}", text)
    return text


#: letters that are not set as a script (accented Latin letters, Cyrillic: LaTeX's text accents fail in math)
_NOT_SCRIPT = re.compile("[\u00c0-\u00d6\u00d8-\u00f6\u00f8-\u024f\u0400-\u04ff]")   # (not × and ÷)


def _script_body(group: str) -> str | None:
    """The body of a script as matched: braces dropped, the parentheses of a negative integer dropped
    ((μI − A)^(-1) is the power −1) and kept otherwise (f^(k), the order of a derivative); None where the body
    holds a letter that is not set as a script (é, ß, ж)."""
    if _NOT_SCRIPT.search(group):
        return None
    if group.startswith("{") or re.fullmatch(r"\(-\d+\)", group):
        return group[1:-1]
    return group


def _unicode_scripts(text: str) -> str:
    text = math_idioms(text)
    text = re.sub(r"(?<=\s)([<>])=(?=\s)", lambda m: "≤" if m.group(1) == "<" else "≥", text.replace(" ^ ", " ∧ "))
    text = re.sub(r"\S+", lambda m: _wedges(m.group(0)), text)

    def one(m: re.Match) -> str:
        if m.start() == 0 or text[m.start() - 1] == " ":
            return m.group(0)                 # a script needs a base before it
        body = _script_body(m.group(2))
        if body is None:
            return m.group(0)
        table = _UNICODE_SUP if m.group(1) == "^" else _UNICODE_SUB
        if body and all(c in table for c in body):
            return "".join(table[c] for c in body)
        return m.group(1) + "{" + _unicode_scripts(body) + "}" if m.group(2).startswith("{") else m.group(0)
    return _ASCII_SCRIPT.sub(one, text)


def tex_words(text: str) -> str:
    """Plain words that write scripts in ASCII (I_n, (A + λI_n)^{-1}, (e_1 ^ p_1)_{I_2}^2, as the
    registered words of a correction do) to LaTeX text: each script set as one, a spaced ^ as the wedge,
    a spaced <= and >= as ≤ and ≥, ``$...$`` as mathematics; everything else as :func:`tex_escape` sets it."""
    return tex_text(text, _ascii_scripts)


def _wedges(token: str) -> str:
    """A word that writes an exterior product in ASCII: with an ellipsis, ``e_1^...^e_r^p_i``, every ^
    before a letter in it is the wedge; without, a ^ between two subscripted letters, ``e_j^p_i``, is
    (a power or a transpose, ^2, ^{-1}, X^T, Phi_{I_2}^2, stays a script)."""
    if "^...^" not in token:
        return re.sub(r"(?<=_[A-Za-z0-9}])\^(?=[A-Za-z]_)", "∧", token)
    return re.sub(r"\^(?=[A-Za-z.])", "∧", token.replace("^...^", "∧...∧"))


def _ascii_scripts(text: str) -> str:
    # the relations bound before the text is cut at its scripts: "P_r = MX_r" is one relation
    text = bind_relations(math_idioms(text, tex=True))
    text = re.sub(r"(?<=\s)([<>])=(?=\s)", lambda m: "≤" if m.group(1) == "<" else "≥", text.replace(" ^ ", " ∧ "))
    text = re.sub(r"\S+", lambda m: _wedges(m.group(0)), text)
    if "`" in text and _CODE_SPAN.search(text):
        parts = _CODE_SPAN.split(text)           # text, code, text, code, ..., text
        return "".join(r"\texttt{" + tt_escape(p) + "}" if i % 2 else _ascii_scripts(p) for i, p in enumerate(parts))
    scripts: dict[str, str] = {}
    out, at = [], 0
    for m in _ASCII_SCRIPT.finditer(text):
        if m.start() == 0 or text[m.start() - 1] == " ":
            continue                      # a script needs a base before it
        body = _script_body(m.group(2))
        if body is None:
            continue                      # left as it is written (escaped with the text around it)
        body = body.replace("-", "−")     # a script is mathematics: n-r, -1 with minus signs
        mark = chr(0xE000 + len(scripts))  # a private-use character stands for the script in the words
        scripts[mark] = m.group(1) + "{" + _script_math(body) + "}"
        out.append(text[at:m.start()] + mark)
        at = m.end()
    out.append(text[at:])
    return _escape_with_math("".join(out), scripts)


def _script_math(body: str) -> str:
    """The LaTeX math of the body of a script of ASCII notation (its own scripts set, names upright)."""
    out, at = [], 0
    for m in _ASCII_SCRIPT.finditer(body):
        inner = _script_body(m.group(2))
        if m.start() == 0 or inner is None:
            continue
        out.append(_script_math_plain(body[at:m.start()]) + m.group(1) + "{" + _script_math(inner) + "}")
        at = m.end()
    out.append(_script_math_plain(body[at:]))
    return "".join(out)


def _script_math_plain(text: str) -> str:
    text = re.sub(r"[#%&$~\\{}]", lambda m: "\\" + m.group(0) if m.group(0) in "#%&$" else "", text)
    parts = re.split(r"([A-Za-z]{2,})", text)
    return "".join(_UPRIGHT_NAMES.get(p, p) if i % 2 else tex_math(p) for i, p in enumerate(parts))
