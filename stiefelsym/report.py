"""Renderers: terminal summary, JUnit XML, Markdown and LaTeX reports.

Every renderer reads :class:`~stiefelsym.results.Result` records (and a ``meta``
dict describing the run) and nothing else, so a report can be re-rendered from
``results.json`` at any time.  ``meta`` keys are all optional: ``title``,
``command``, ``seed``, ``date``, ``seconds``, ``versions`` (name -> version),
``platform``, ``commit``, ``sections`` (section number -> section title).
"""
from __future__ import annotations

import re
import unicodedata
import xml.etree.ElementTree as ET
from collections import Counter
from typing import Any, Iterable, Sequence

from .results import PASSING, VERDICTS, Result

DEFAULT_TITLE = ("Verification of Fedorov & Jovanović, "
                 "“Geodesic Flows and Neumann Systems on Stiefel Varieties”")

#: what each verdict means, for a mathematician reading the report
VERDICT_MEANING = {
    "proved": ("The statement holds identically.  At a size (n, r): exact symbolic "
               "computation reduced every residual to zero on the constraint set.  "
               "At size “all n, r”: a dimension-free computation with the letters "
               "X, Xᵀ, P, Pᵀ, A, … of a free noncommutative algebra proves it for "
               "every n and r at once."),
    "checked": ("Randomized exact check: every residual vanished exactly (no rounding) "
                "at independent random points over ℚ or a prime field.  A false "
                "statement passes with probability at most the stated bound p "
                "(Schwartz–Zippel, see below)."),
    "numeric": ("Floating-point evidence at random real points, with precision "
                "escalation; strong evidence, not a proof."),
    "fails": ("The statement as printed is false at this size: an exact witness (a "
              "point and a nonzero residual entry) is given and is reproducible from "
              "the seed."),
    "inconclusive": ("The method ran but could not tell zero from nonzero (for "
                     "instance only degenerate random points, or a floating-point "
                     "residual of ambiguous size)."),
    "undecided": ("The method does not apply to this claim or size, or exceeded its "
                  "budget; another method may decide."),
    "error": ("The check itself raised an error (a bug in the claim or in the "
              "engine); the message is given."),
}

BOUND_EXPLANATION = (
    "Schwartz–Zippel lemma: a nonzero polynomial of total degree d, evaluated at a "
    "point whose coordinates are drawn independently and uniformly from a finite set "
    "S of field elements, vanishes with probability at most d/|S|.  The residuals of "
    "a claim are polynomials (after clearing denominators) in the free parameters of "
    "a chart of T*V; a randomized check evaluates them exactly at several independent "
    "points.  The bound p is the probability that a false statement would have passed "
    "this run.  It concerns the random choices of the run only, which the seed fixes.")

EXPECTED_EXPLANATION = (
    "Each verdict is compared with what the catalog expects: a statement of the paper "
    "is expected to hold; a printed formula already known to be wrong is expected to "
    "fail as printed.  A verdict the catalog does not expect is marked UNEXPECTED; the "
    "command exits with status 1 if there is any.")

#: the paper's operator names, expanded for Markdown viewers that do not know them
OPERATORS = {"tr": "tr", "diag": "diag", "ad": "ad", "Ad": "Ad", "rank": "rank",
             "ddim": "ddim", "pr": "pr", "Span": "span"}


# --------------------------------------------------------------------------- grouping

class ClaimResults:
    """All results of one claim: as printed, and per candidate correction."""

    def __init__(self, first: Result) -> None:
        self.id = first.claim
        self.paper = list(first.paper)
        self.section = first.section
        self.kind = first.kind
        self.title = first.title
        self.statement = first.statement
        self.printed: list[Result] = []
        self.variants: dict[str, list[Result]] = {}

    def add(self, r: Result) -> None:
        if r.variant is None:
            self.printed.append(r)
            # the as-printed record describes the claim best
            self.title, self.statement = r.title or self.title, r.statement or self.statement
        else:
            self.variants.setdefault(r.variant, []).append(r)

    @property
    def failures(self) -> list[Result]:
        return [r for r in self.printed if r.verdict == "fails"]

    @property
    def unexpected(self) -> list[Result]:
        return [r for r in self.printed + [v for vs in self.variants.values() for v in vs]
                if not r.expected]


def group_by_claim(results: Iterable[Result]) -> list[ClaimResults]:
    """Claims in order of first appearance, each with its results."""
    out: dict[str, ClaimResults] = {}
    for r in results:
        if r.claim not in out:
            out[r.claim] = ClaimResults(r)
        out[r.claim].add(r)
    return list(out.values())


def _section_key(section: str) -> tuple:
    parts = re.split(r"(\d+)", section or "")
    return (section == "",) + tuple(int(p) if p.isdigit() else p for p in parts)


def group_by_section(claims: list[ClaimResults]) -> list[tuple[str, list[ClaimResults]]]:
    secs: dict[str, list[ClaimResults]] = {}
    for c in claims:
        secs.setdefault(c.section or "", []).append(c)
    return sorted(secs.items(), key=lambda kv: _section_key(kv[0]))


def _section_heading(section: str, meta: dict[str, Any]) -> str:
    if not section:
        return "Claims outside the paper's sections"
    name = (meta.get("sections") or {}).get(section, "")
    return f"§{section} {name}".strip()


# --------------------------------------------------------------------------- formatting

def format_seconds(s: float | None) -> str:
    if s is None:
        return "–"
    if s < 60:
        return f"{s:.2f} s"
    m, sec = divmod(int(round(s)), 60)
    return f"{m} min {sec} s" if m < 60 else f"{m // 60} h {m % 60} min"


def format_bound(p: float | None) -> str:
    if p is None:
        return "–"
    return "0" if p == 0 else f"{p:.1e}"


def short(text: str | None, width: int = 60) -> str:
    """First line of ``text``, cut to ``width`` characters."""
    if not text:
        return ""
    line = " ".join(str(text).split())
    return line if len(line) <= width else line[: width - 1] + "…"


def format_value(v: Any, width: int = 400) -> str:
    """A witness value on one line: dicts as ``k = v; ...``, lists as ``[a, b]``."""
    if isinstance(v, dict):
        text = "; ".join(f"{k} = {format_value(x, width)}" for k, x in v.items())
    elif isinstance(v, (list, tuple)):
        text = "[" + ", ".join(format_value(x, width) for x in v) + "]"
    else:
        text = str(v)
    return short(text, width) if len(text) > width else text


def case_name(r: Result) -> str:
    """A name that reads like the claim: ``prep[n=4,r=2]-modular``."""
    var = f"[{r.variant}]" if r.variant else ""
    size = "[all n,r]" if r.n is None else f"[n={r.n},r={r.r}]"
    return f"{r.claim}{var}{size}-{r.method}"


def labels(paper: Sequence[str]) -> str:
    return ", ".join(f"({p})" for p in paper) if paper else ""


# --------------------------------------------------------------------------- terminal

def render_summary(results: Sequence[Result]) -> str:
    """The summary table printed after a run: verdict counts by method."""
    if not results:
        return "summary: no runs\n"
    claims = {r.claim for r in results}
    unexpected = [r for r in results if not r.expected]
    head = (f"summary: {len(claims)} claim{'s' * (len(claims) != 1)}, {len(results)} "
            f"run{'s' * (len(results) != 1)}: {len(results) - len(unexpected)} as expected, "
            f"{len(unexpected)} unexpected")
    methods = list(dict.fromkeys(r.method for r in results))
    counts = Counter((r.method, r.verdict) for r in results)
    w0 = max(len("method"), *(len(m) for m in methods), len("total"))
    cols = list(VERDICTS) + ["total"]
    widths = [max(len(c), 5) for c in cols]

    def row(name: str, cells: list[str]) -> str:
        return "  " + name.ljust(w0) + "".join(c.rjust(w + 2) for c, w in zip(cells, widths))

    lines = [head, row("method", cols)]
    for m in methods:
        cells = [str(counts[(m, v)] or "-") for v in VERDICTS]
        cells.append(str(sum(counts[(m, v)] for v in VERDICTS)))
        lines.append(row(m, cells))
    if len(methods) > 1:
        tot = Counter(r.verdict for r in results)
        lines.append(row("total", [str(tot[v] or "-") for v in VERDICTS] + [str(len(results))]))
    if unexpected:
        lines.append("unexpected verdicts:")
        for r in unexpected:
            lines.append("  " + r.line())
            if r.rerun:
                lines.append(f"    rerun: {r.rerun}")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- JUnit

_XML_BAD = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def _xml(text: Any) -> str:
    return _XML_BAD.sub("?", str(text))


def render_junit(results: Sequence[Result], meta: dict[str, Any] | None = None) -> str:
    """JUnit XML: one testsuite per paper section, one testcase per result.

    An unexpected verdict is a ``<failure>`` whose text holds the line, the
    message, the witness and the rerun command."""
    meta = meta or {}
    root = ET.Element("testsuites", name="stiefelsym", tests=str(len(results)),
                      failures=str(sum(not r.expected for r in results)),
                      time=f"{sum(r.seconds for r in results):.3f}")
    by_section: dict[str, list[Result]] = {}
    for r in results:
        by_section.setdefault(r.section or "", []).append(r)
    for sec, rs in sorted(by_section.items(), key=lambda kv: _section_key(kv[0])):
        suite = ET.SubElement(root, "testsuite", name=_xml(f"section {sec}" if sec else "other"),
                              tests=str(len(rs)), failures=str(sum(not r.expected for r in rs)),
                              errors="0", skipped="0",
                              time=f"{sum(r.seconds for r in rs):.3f}")
        for r in rs:
            case = ET.SubElement(suite, "testcase", name=_xml(case_name(r)),
                                 classname=_xml(f"stiefelsym.s{sec or 'x'}.{r.claim}"),
                                 time=f"{r.seconds:.3f}")
            detail = [r.line()]
            if r.message:
                detail.append(r.message)
            if r.witness:
                detail.append("witness: " + format_value(r.witness, 2000))
            if r.rerun:
                detail.append("rerun: " + r.rerun)
            if not r.expected:
                fail = ET.SubElement(case, "failure", type=r.verdict,
                                     message=_xml(f"verdict {r.verdict} is not the one the catalog expects"))
                fail.text = _xml("\n".join(detail))
            else:
                ET.SubElement(case, "system-out").text = _xml("\n".join(detail))
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


# --------------------------------------------------------------------------- Markdown

def _md_escape(text: str) -> str:
    """Escape Markdown emphasis and HTML in running text, keeping ``$...$`` math."""
    parts = _split_math(text)
    out = []
    for is_math, seg in parts:
        if is_math:
            out.append(_md_math(seg))
        else:
            out.append(re.sub(r"([\\*_`<>])", r"\\\1", seg))
    return "".join(out)


def _md_cell(text: str) -> str:
    return _md_escape(" ".join(str(text).split())).replace("|", r"\|")


def _md_math(tex: str) -> str:
    """Expand the paper's macros, which Markdown math viewers do not know."""
    tex = re.sub(r"\\(" + "|".join(OPERATORS) + r")(?![A-Za-z])",
                 lambda m: r"\operatorname{" + OPERATORS[m.group(1)] + "}", tex)
    tex = re.sub(r"\\R(?![A-Za-z])", r"\\mathbb{R}", tex)
    return re.sub(r"\\g(?![A-Za-z])", r"\\mathfrak{g}", tex)


def _md_statement(statement: str) -> str:
    s = statement.strip()
    if not s:
        return ""
    if "$" in s or not _math_ok(s):
        return _md_escape(s)
    s = _md_math(s)
    if "\n" in s or len(s) > 70 or "\\\\" in s or "\\begin" in s:
        return f"$$\n{s}\n$$"
    return f"${s}$"


def _md_table(header: list[str], rows: list[list[str]], align: str | None = None) -> list[str]:
    align = align or "l" * len(header)
    sep = ["---:" if a == "r" else "---" for a in align]
    out = ["| " + " | ".join(header) + " |", "| " + " | ".join(sep) + " |"]
    out += ["| " + " | ".join(row) + " |" for row in rows]
    return out


def _verdict_md(r: Result) -> str:
    v = f"**{r.verdict}**" if r.verdict in ("fails", "error") else r.verdict
    return v if r.expected else f"{v} (UNEXPECTED)"


def _results_rows_md(rs: list[Result]) -> list[list[str]]:
    return [[_md_cell(r.size), _md_cell(r.method), _verdict_md(r), format_seconds(r.seconds),
             _md_cell(short(r.certificate) or "–"), str(r.seed if r.seed is not None else "–"),
             format_bound(r.false_pass_bound)] for r in rs]


_RESULT_HEADER = ["size (n,r)", "method", "verdict", "time", "certificate", "seed", "p (false pass)"]


def _reproduce_md(meta: dict[str, Any]) -> list[str]:
    cmd = meta.get("command") or "stiefelsym verify"
    out = ["## How to reproduce", "", "```sh", cmd, "```", ""]
    seed = meta.get("seed")
    facts = []
    if seed is not None:
        facts.append(f"Seed {seed}: every random choice (points, primes) is drawn from it, so "
                     "the command reproduces every verdict, witness and bound below.")
    run = []
    if meta.get("date"):
        run.append(f"run on {meta['date']}")
    if meta.get("seconds") is not None:
        run.append(f"in {format_seconds(meta['seconds'])}")
    if meta.get("commit"):
        run.append(f"at commit `{meta['commit']}`")
    if meta.get("platform"):
        run.append(f"on {meta['platform']}")
    if run:
        facts.append(_md_escape(" ".join(run).capitalize() + "."))
    versions = meta.get("versions") or {}
    if versions:
        facts.append("Versions: " + ", ".join(f"{k} {v}" for k, v in versions.items()) + ".")
    return out + facts + [""] if facts else out


def _vocabulary_md() -> list[str]:
    out = ["## What the verdicts mean", ""]
    out += [f"- **{v}**: {_md_escape(VERDICT_MEANING[v])}" for v in VERDICTS]
    out += ["", f"**The bound p.** {_md_escape(BOUND_EXPLANATION)}", "",
            f"**Expected verdicts.** {_md_escape(EXPECTED_EXPLANATION)}", ""]
    return out


def _summary_counts(claims: list[ClaimResults]) -> tuple[list[str], list[list[str]]]:
    present = [v for v in VERDICTS if any(r.verdict == v for c in claims for r in c.printed)]
    rows = []
    for c in claims:
        cnt = Counter(r.verdict for r in c.printed)
        bad = len(c.unexpected)
        rows.append([c.id, labels(c.paper), c.section or "–", c.kind]
                    + [str(cnt[v] or "") for v in present]
                    + ["as expected" if not bad else f"{bad} unexpected"])
    return present, rows


def _witness_lines(w: dict[str, Any] | None) -> list[tuple[str, str]]:
    return [(str(k), format_value(v)) for k, v in (w or {}).items()]


def render_markdown(results: Sequence[Result], meta: dict[str, Any] | None = None) -> str:
    """The Markdown report: reproduce, vocabulary, summary, per section, errata."""
    meta = meta or {}
    claims = group_by_claim(results)
    runs = len(results)
    unexpected = sum(not r.expected for r in results)
    out = [f"# {_md_escape(meta.get('title') or DEFAULT_TITLE)}", "",
           "Generated by `stiefelsym` from `results.json`; do not edit by hand. "
           f"{len(claims)} claims, {runs} runs, "
           + ("every verdict as expected." if not unexpected else
              f"**{unexpected} verdicts not as expected.**"), ""]
    out += _reproduce_md(meta)
    out += _vocabulary_md()

    out += ["## Summary", "",
            "Number of runs (sizes × methods) of each claim, as printed, by verdict.", ""]
    present, rows = _summary_counts(claims)
    out += _md_table(["claim", "paper", "§", "kind"] + present + ["status"],
                     [[_md_cell(x) for x in row] for row in rows],
                     "llll" + "r" * len(present) + "l")
    out.append("")

    errata = [c for c in claims if c.failures]
    for sec, cs in group_by_section(claims):
        out += [f"## {_md_escape(_section_heading(sec, meta))}", ""]
        for c in cs:
            out += [f"### `{c.id}` {_md_escape(labels(c.paper))}".rstrip(), ""]
            if c.title:
                out += [_md_escape(c.title), ""]
            st = _md_statement(c.statement)
            if st:
                out += [st, ""]
            out += [f"Kind: {c.kind}.", ""]
            if c.printed:
                out += _md_table(_RESULT_HEADER, _results_rows_md(c.printed), "lllrlrr")
                out.append("")
            reductions = sorted({x for r in c.printed for x in r.reductions})
            if reductions:
                out += ["Reductions: " + _md_escape("; ".join(reductions)) + ".", ""]
            notes = [r for r in c.printed if r.message and (r.verdict not in PASSING or not r.expected)]
            for r in notes:
                out.append(f"- {_md_cell(r.size)} {_md_cell(r.method)}: {_md_cell(r.message)}")
            if notes:
                out.append("")
            if c.failures:
                out += ["Fails as printed: see the Errata section below.", ""]
            elif c.variants:
                out += [f"{len(c.variants)} candidate correction(s) also checked: see below.", ""]

    out += ["## Errata", ""]
    if not errata:
        out += ["No statement failed as printed.", ""]
    else:
        out += ["Statements that fail as printed.  Each comes with a witness: an exact point "
                "where a residual entry is nonzero, reproducible from the seed with the rerun "
                "command.  Then the candidate corrections that were checked.", ""]
    for c in errata:
        out += _errata_md(c)
    for c in claims:
        if c.variants and not c.failures:
            out += _errata_md(c, failed=False)
    return "\n".join(out).rstrip() + "\n"


def _errata_md(c: ClaimResults, failed: bool = True) -> list[str]:
    out = [f"### `{c.id}` {_md_escape(labels(c.paper))}".rstrip(), ""]
    st = _md_statement(c.statement)
    if failed:
        if st:
            out += ["As printed:", "", st, ""]
        sizes = ", ".join(f"{r.size} {r.method}" for r in c.failures)
        out += [f"Fails at: {_md_escape(sizes)}.", ""]
        w = c.failures[0]
        out += [f"Witness ({_md_escape(w.size)}, method {w.method}, seed {w.seed}):", ""]
        wl = _witness_lines(w.witness)
        out += [f"- {_md_escape(k)}: `{v}`" for k, v in wl] or ["- (no witness recorded)"]
        if w.residual:
            out.append(f"- residual: `{short(w.residual, 400)}`")
        if w.rerun:
            out.append(f"- rerun: `{w.rerun}`")
        out.append("")
    else:
        out += ["Holds as printed; candidate corrections were checked as well.", ""]
    if c.variants:
        out += ["Candidate corrections:", ""]
        rows = []
        for var, rs in c.variants.items():
            ok = all(r.verdict in PASSING for r in rs)
            status = "**verified**" if ok else ("rejected" if any(r.verdict == "fails" for r in rs)
                                                else "undecided")
            runs = ", ".join(f"{r.size} {r.method}: {r.verdict}"
                             + (f" (p ≤ {format_bound(r.false_pass_bound)})"
                                if r.false_pass_bound is not None else "") for r in rs)
            rows.append([_md_cell(var), status, _md_cell(runs)])
        out += _md_table(["correction", "status", "runs"], rows)
        out.append("")
    elif failed:
        out += ["No candidate correction was checked.", ""]
    return out


# --------------------------------------------------------------------------- LaTeX

_TEX_SPECIAL = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "#": r"\#", "$": r"\$", "%": r"\%",
    "&": r"\&", "_": r"\_", "~": r"\~{}", "^": r"\^{}",
    "<": r"\ensuremath{<}", ">": r"\ensuremath{>}", "|": r"\ensuremath{|}",
}
_SUP = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱᵀᵗʳᵏʲ", "0123456789+-=()niTtrkj"))
_SUB = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₒₓₕₖₗₘₙₚₛₜᵢⱼᵣ", "0123456789+-=()aeoxhklmnpstijr"))
_TEXT_ONLY = {"–": "--", "—": "---", "‘": "`", "’": "'", "“": "``", "”": "''",
              "\u00a0": "~", "…": r"\ldots{}", "•": r"\ensuremath{\bullet}", "§": r"\S{}",
              "¶": r"\P{}"}
_ACCENTS = {"\u0301": "'", "\u0300": "`", "\u030c": "v", "\u0308": '"', "\u0302": "^",
            "\u0303": "~", "\u0327": "c", "\u0306": "u", "\u0304": "="}
_MATH_SYMBOLS = {
    "−": "-", "×": r"\times", "·": r"\cdot", "∘": r"\circ", "≤": r"\le", "≥": r"\ge",
    "≠": r"\neq", "∈": r"\in", "∉": r"\notin", "∧": r"\wedge", "∨": r"\vee", "⊂": r"\subset",
    "⊆": r"\subseteq", "⊕": r"\oplus", "⊗": r"\otimes", "→": r"\to", "↦": r"\mapsto",
    "⇒": r"\Rightarrow", "⇔": r"\Leftrightarrow", "∂": r"\partial", "∇": r"\nabla",
    "∑": r"\sum", "∏": r"\prod", "∫": r"\int", "∞": r"\infty", "≅": r"\cong",
    "≈": r"\approx", "≡": r"\equiv", "⟨": r"\langle", "⟩": r"\rangle", "½": r"\tfrac12",
    "⊥": r"\perp", "∀": r"\forall", "∃": r"\exists", "±": r"\pm", "√": r"\surd",
    "∅": r"\emptyset", "∩": r"\cap", "∪": r"\cup", "∖": r"\setminus", "′": "'",
    "ℓ": r"\ell", "ħ": r"\hbar", "≔": ":=", "…": r"\dots", "⋯": r"\cdots",
}
_GREEK_LOWER = {"epsilon": "varepsilon", "phi": "varphi", "lamda": "lambda", "omicron": "o",
                "final sigma": "varsigma"}
_GREEK_UPPER = {"gamma", "delta", "theta", "lamda", "xi", "pi", "sigma", "upsilon", "phi",
                "psi", "omega"}
_ALPHABETS = {"DOUBLE-STRUCK": "mathbb", "FRAKTUR": "mathfrak", "BLACK-LETTER": "mathfrak",
              "SCRIPT": "mathcal", "BOLD": "mathbf", "ITALIC": "mathit"}


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


def tex_escape(text: Any) -> str:
    """Plain text to LaTeX text mode: specials escaped, Unicode mapped to LaTeX."""
    out = []
    for kind, piece in _script_runs(str(text)):
        if kind == "sup":
            out.append(r"\ensuremath{^{" + "".join(_SUP[c] for c in piece) + "}}")
        elif kind == "sub":
            out.append(r"\ensuremath{_{" + "".join(_SUB[c] for c in piece) + "}}")
        elif piece in _TEX_SPECIAL:
            out.append(_TEX_SPECIAL[piece])
        elif piece == "\n":
            out.append(" ")
        elif ord(piece) < 128:
            out.append(piece)
        elif piece in _TEXT_ONLY:
            out.append(_TEXT_ONLY[piece])
        else:
            out.append(_tex_nonascii(piece))
    return "".join(out)


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
        else:
            m = _unicode_math(piece)
            out.append(_cmd(m) if m is not None else r"\text{" + _tex_nonascii(piece) + "}")
    return "".join(out)


def _split_math(text: str) -> list[tuple[bool, str]]:
    """Split text at unescaped ``$``: (is_math, segment).  Unpaired ``$``: all text."""
    pieces = re.split(r"(?<!\\)\$", text)
    if len(pieces) % 2 == 0 or len(pieces) == 1:
        return [(False, text)]
    return [(i % 2 == 1, p) for i, p in enumerate(pieces) if p or i % 2 == 0]


def _math_ok(tex: str) -> bool:
    """Balanced braces and environments, no math delimiters: safe inside a display."""
    depth = 0
    for m in re.finditer(r"\\.|[{}]", tex, re.S):
        tok = m.group()
        if tok == "{":
            depth += 1
        elif tok == "}":
            depth -= 1
            if depth < 0:
                return False
    if depth:
        return False
    if re.search(r"(?<!\\)\$|\\[\[\]()]|\\(?:end\{document\}|begin\{document\}|section|par\b)", tex):
        return False
    begins = Counter(re.findall(r"\\begin\{([^}]*)\}", tex))
    ends = Counter(re.findall(r"\\end\{([^}]*)\}", tex))
    return begins == ends


def _toplevel(tex: str) -> str:
    """``tex`` with every environment block removed (for spotting top-level & and \\\\)."""
    prev = None
    while prev != tex:
        prev, tex = tex, re.sub(r"\\begin\{([^}]*)\}(?:(?!\\begin\{).)*?\\end\{\1\}", "", tex,
                                flags=re.S)
    return tex


def tex_text(text: str) -> str:
    """Running text that may contain ``$...$`` math (docstrings)."""
    out = []
    for is_math, seg in _split_math(text):
        if is_math and _math_ok(seg):
            out.append("$" + tex_math(seg) + "$")
        else:
            out.append(tex_escape(f"${seg}$" if is_math else seg))
    return "".join(out)


def tex_display(statement: str) -> str:
    """A statement in display math (``align*`` if it aligns, ``gather*`` if multi-line)."""
    s = statement.strip()
    if not s:
        return ""
    if not _math_ok(s):
        return ("\\noindent\\texttt{" + tex_escape(s) + "}\\\\\n"
                "{\\small (statement shown verbatim: it is not balanced LaTeX math)}\n")
    body = tex_math(s)
    top = _toplevel(body)
    if re.search(r"(?<!\\)&", top):
        return "\\begin{align*}\n" + body + "\n\\end{align*}\n"
    if "\\\\" in top:
        return "\\begin{gather*}\n" + body + "\n\\end{gather*}\n"
    return "\\[\n" + body + "\n\\]\n"


def _tex_bound(p: float | None) -> str:
    if p is None:
        return "--"
    if p == 0:
        return "0"
    mant, exp = f"{p:.1e}".split("e")
    return f"${mant}\\cdot 10^{{{int(exp)}}}$"


def _tex_verdict(r: Result) -> str:
    v = r.verdict if r.verdict not in ("fails", "error") else f"\\textbf{{{r.verdict}}}"
    return v if r.expected else v + " \\textsc{(unexpected)}"


TEX_PREAMBLE = r"""\documentclass[10pt,a4paper]{article}
\usepackage[margin=2.2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{longtable,booktabs,array}
\DeclareMathOperator{\tr}{tr}
\DeclareMathOperator{\diag}{diag}
\DeclareMathOperator{\ad}{ad}
\DeclareMathOperator{\Ad}{Ad}
\DeclareMathOperator{\rank}{rank}
\DeclareMathOperator{\ddim}{ddim}
\DeclareMathOperator{\pr}{pr}
\DeclareMathOperator{\Span}{span}
\providecommand{\R}{\mathbb{R}}
\providecommand{\g}{\mathfrak{g}}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5ex}
\setlength{\LTpre}{0.5ex}
\setlength{\LTpost}{0.5ex}
"""


def _tex_results_table(rs: list[Result]) -> list[str]:
    out = [r"{\small",
           r"\begin{longtable}{@{}lll r >{\raggedright\arraybackslash}p{4.6cm} r l@{}}",
           r"\toprule",
           r"size $(n,r)$ & method & verdict & time & certificate & seed & $p$ (false pass)\\",
           r"\midrule", r"\endhead"]
    for r in rs:
        out.append(" & ".join([
            tex_escape(r.size), tex_escape(r.method), _tex_verdict(r),
            tex_escape(format_seconds(r.seconds)), tex_escape(short(r.certificate) or "--"),
            str(r.seed if r.seed is not None else "--"), _tex_bound(r.false_pass_bound)]) + r"\\")
    out += [r"\bottomrule", r"\end{longtable}", "}"]
    return out


def render_latex(results: Sequence[Result], meta: dict[str, Any] | None = None) -> str:
    """A complete ``article`` document (pdflatex, Debian's texlive-latex-base/recommended)."""
    meta = meta or {}
    claims = group_by_claim(results)
    unexpected = sum(not r.expected for r in results)
    out = [TEX_PREAMBLE,
           r"\title{" + tex_escape(meta.get("title") or DEFAULT_TITLE) + "}",
           r"\author{Generated by \texttt{stiefelsym}}",
           r"\date{" + tex_escape(meta.get("date") or "") + "}",
           r"\begin{document}", r"\maketitle", "",
           tex_escape(f"{len(claims)} claims, {len(results)} runs, ")
           + ("every verdict as expected." if not unexpected
              else f"\\textbf{{{unexpected} verdicts not as expected.}}"), ""]

    out += [r"\section*{How to reproduce}", r"\begin{verbatim}",
            (meta.get("command") or "stiefelsym verify").replace("\\end{verbatim}", ""),
            r"\end{verbatim}"]
    facts = []
    if meta.get("seed") is not None:
        facts.append(tex_escape(f"Seed {meta['seed']}: every random choice (points, primes) is "
                                "drawn from it, so the command reproduces every verdict, "
                                "witness and bound below."))
    run = []
    if meta.get("date"):
        run.append(f"run on {meta['date']}")
    if meta.get("seconds") is not None:
        run.append(f"in {format_seconds(meta['seconds'])}")
    if meta.get("commit"):
        run.append(f"at commit {meta['commit']}")
    if meta.get("platform"):
        run.append(f"on {meta['platform']}")
    if run:
        facts.append(tex_escape(" ".join(run).capitalize() + "."))
    versions = meta.get("versions") or {}
    if versions:
        facts.append(tex_escape("Versions: " + ", ".join(f"{k} {v}" for k, v in versions.items())
                                + "."))
    out += facts + [""]

    out += [r"\section*{What the verdicts mean}", r"\begin{description}"]
    out += [f"\\item[{v}] {tex_escape(VERDICT_MEANING[v])}" for v in VERDICTS]
    out += [r"\end{description}",
            r"\paragraph{The bound $p$.} " + tex_escape(BOUND_EXPLANATION),
            r"\paragraph{Expected verdicts.} " + tex_escape(EXPECTED_EXPLANATION), ""]

    present, rows = _summary_counts(claims)
    out += [r"\section*{Summary}",
            tex_escape("Number of runs (sizes × methods) of each claim, as printed, by verdict."),
            "", r"{\small",
            r"\begin{longtable}{@{}>{\raggedright\arraybackslash}p{3.6cm}"
            r">{\raggedright\arraybackslash}p{3.2cm}ll" + "r" * len(present) + "l@{}}",
            r"\toprule",
            " & ".join(["claim", "paper", r"\S", "kind"] + present + ["status"]) + r"\\",
            r"\midrule", r"\endhead"]
    for row in rows:
        cells = [r"\texttt{" + tex_escape(row[0]) + "}"] + [tex_escape(x) for x in row[1:]]
        out.append(" & ".join(cells) + r"\\")
    out += [r"\bottomrule", r"\end{longtable}", "}", ""]

    errata = [c for c in claims if c.failures]
    for sec, cs in group_by_section(claims):
        out += [r"\section*{" + tex_escape(_section_heading(sec, meta)) + "}"]
        for c in cs:
            out += [r"\subsection*{\texttt{" + tex_escape(c.id) + "} "
                    + tex_escape(labels(c.paper)) + "}"]
            if c.title:
                out += [tex_text(c.title), ""]
            if c.statement.strip():
                out.append(tex_display(c.statement))
            out += [f"Kind: {tex_escape(c.kind)}.", ""]
            if c.printed:
                out += _tex_results_table(c.printed)
            reductions = sorted({x for r in c.printed for x in r.reductions})
            if reductions:
                out += ["Reductions: " + tex_escape("; ".join(reductions)) + ".", ""]
            notes = [r for r in c.printed if r.message and (r.verdict not in PASSING or not r.expected)]
            if notes:
                out += [r"\begin{itemize}"]
                out += [r"\item " + tex_escape(f"{r.size} {r.method}: {short(r.message, 300)}")
                        for r in notes]
                out += [r"\end{itemize}"]
            if c.failures:
                out += ["Fails as printed: see the Errata section.", ""]
            elif c.variants:
                out += [tex_escape(f"{len(c.variants)} candidate correction(s) also checked: "
                                   "see the Errata section."), ""]

    out += [r"\section*{Errata}"]
    if not errata:
        out += ["No statement failed as printed.", ""]
    else:
        out += [tex_escape("Statements that fail as printed.  Each comes with a witness: an "
                           "exact point where a residual entry is nonzero, reproducible from "
                           "the seed with the rerun command.  Then the candidate corrections "
                           "that were checked."), ""]
    for c in errata:
        out += _errata_tex(c)
    for c in claims:
        if c.variants and not c.failures:
            out += _errata_tex(c, failed=False)
    out += [r"\end{document}", ""]
    return "\n".join(out)


def _tt(text: str) -> str:
    """Monospace text that may break at spaces and after commas."""
    return r"\texttt{" + tex_escape(text).replace(",", r",\allowbreak{}") + "}"


def _errata_tex(c: ClaimResults, failed: bool = True) -> list[str]:
    out = [r"\subsection*{\texttt{" + tex_escape(c.id) + "} " + tex_escape(labels(c.paper)) + "}"]
    if failed:
        if c.statement.strip():
            out += ["As printed:", tex_display(c.statement)]
        sizes = ", ".join(f"{r.size} {r.method}" for r in c.failures)
        w = c.failures[0]
        out += [tex_escape(f"Fails at: {sizes}."), "",
                tex_escape(f"Witness ({w.size}, method {w.method}, seed {w.seed}):"),
                r"\begin{itemize}"]
        items = [r"\item " + tex_escape(k) + ": " + _tt(v) for k, v in _witness_lines(w.witness)]
        out += items or [r"\item (no witness recorded)"]
        if w.residual:
            out.append(r"\item residual: " + _tt(short(w.residual, 400)))
        if w.rerun:
            out.append(r"\item rerun: " + _tt(w.rerun))
        out += [r"\end{itemize}"]
    else:
        out += ["Holds as printed; candidate corrections were checked as well.", ""]
    if c.variants:
        out += ["Candidate corrections:", r"\begin{itemize}"]
        for var, rs in c.variants.items():
            ok = all(r.verdict in PASSING for r in rs)
            status = (r"\textbf{verified}" if ok else
                      "rejected" if any(r.verdict == "fails" for r in rs) else "undecided")
            runs = "; ".join(f"{r.size} {r.method}: {r.verdict}" for r in rs)
            bounds = [r.false_pass_bound for r in rs if r.false_pass_bound is not None]
            bound = f" ($p\\le$ {_tex_bound(max(bounds))})" if bounds else ""
            out.append(r"\item " + tex_text(var) + f" --- {status}. " + tex_escape(runs) + bound)
        out += [r"\end{itemize}"]
    elif failed:
        out += ["No candidate correction was checked.", ""]
    return out
