"""Rich displays for Jupyter: results, lists of results and claims as Markdown and LaTeX (the
``_repr_markdown_`` and ``_repr_latex_`` of :class:`~stiefelsym.results.Result`,
:class:`~stiefelsym.results.ResultList` and :class:`~stiefelsym.claims.Claim`), built from the
report's own renderers (:mod:`stiefelsym.reports.report`), and the witness residual as a sympy object."""
from __future__ import annotations

import re
from typing import Any, Sequence

from stiefelsym.results import Result


class _Report:
    """The report's module, imported at the first display (so that importing stiefelsym stays quick)."""

    def __getattr__(self, name: str) -> Any:
        from stiefelsym.reports import report
        return getattr(report, name)


R = _Report()


#: the characters that are not plain text inside ``\\text{}`` for MathJax, KaTeX or LaTeX, written in math mode
#: between the runs of text instead (MathJax takes a ``\\text{}`` literally: a text-mode command such as
#: ``\\ensuremath`` or ``\\textbackslash`` would be shown as it is written)
_MATH_CHARS = {"\\": r"\backslash", "{": r"\{", "}": r"\}", "#": r"\#", "$": r"\$", "%": r"\%", "&": r"\&",
               "_": r"\_", "~": r"\sim", "^": r"\hat{}", "<": "<", ">": ">", "|": r"\vert"}


def _tex_text(text: Any) -> str:
    """Text inside math mode, as MathJax, KaTeX and LaTeX all read it: runs of ``\\text{...}`` holding the
    characters as they are (Unicode included), with the characters of :data:`_MATH_CHARS` between them in
    math mode."""
    out: list[str] = []
    run: list[str] = []
    for ch in " ".join(str(text).split()):
        if ch in _MATH_CHARS:
            if run:
                out.append(r"\text{" + "".join(run) + "}")
                run = []
            out.append("{" + _MATH_CHARS[ch] + "}")
        else:
            run.append(ch)
    if run or not out:
        out.append(r"\text{" + "".join(run) + "}")
    return "".join(out)


# --------------------------------------------------------------------------- results

def _md_witness(r: Result) -> list[str]:
    lines = []
    reason = r.reason(None)
    if reason:
        lines += ["", f"{'Witness' if r.verdict == 'fails' else 'Reason'}: {R._md_cell(reason)}"]
    if r.verdict == "fails":
        lines += [f"- {R._md_cell(k)}: {R._md_code(v)}" for k, v in R.witness_lines(r.witness, where="the result's witness")
                  if k not in ("entry", "value")]
    if r.rerun and (r.verdict in ("fails", "error", "inconclusive") or not r.expected):
        lines += ["", f"Rerun: {R._md_code(r.rerun)}"]
    return lines


def result_markdown(r: Result) -> str:
    r = R.readable_results([r])[0]
    head = f"**{R._md_cell(R.case_name(r))}** {R._md_cell(R.labels(r.paper))}: {R._md_cell(r.title)}"
    traced = (["As traced (what the method evaluated):", ""]
              + [f"- {R._md_escape(name) + ': ' if name else ''}{R._md_escape(text)}" for name, text, _ in r.traced]
              + [""]) if r.traced else []
    return "\n".join([head, ""] + R._md_results([r]) + traced + _md_witness(r)).rstrip() + "\n"


def results_markdown(results: Sequence[Result]) -> str:
    if not results:
        return "*no results*\n"
    out = ["```", R.render_summary(results).rstrip(), "```", ""]
    for c in R.group_by_claim(R.readable_results(results)):
        rs = list(c.printed) + [r for v in c.variants.values() for r in v]
        first = rs[0]
        out += [f"**{R._md_cell(first.claim)}** {R._md_cell(R.labels(first.paper))}: {R._md_cell(first.title)}",
                ""] + R._md_results(rs)
        for r in rs:
            if r.verdict == "fails" or not r.expected:
                out += [f"*{R._md_cell(R.case_name(r))}*"] + _md_witness(r) + [""]
    return "\n".join(out).rstrip() + "\n"


def _tex_rows(results: Sequence[Result]) -> list[str]:
    rows = []
    for r in results:
        cells = [_tex_text(r.claim), _tex_text(r.size), _tex_text(r.method), _tex_text(r.verdict)
                 + ("" if r.expected else r"\ \textbf{unexpected}"), _tex_text(R.format_seconds(r.seconds)),
                 _tex_text(r.reason(80) or R.short(r.certificate, 80) or "--")]
        rows.append(" & ".join(cells) + r" \\")
    return rows


def results_latex(results: Sequence[Result]) -> str:
    head = " & ".join(_tex_text(h) for h in ("claim", "size (n,r)", "method", "verdict", "time", "witness / certificate"))
    return ("$$\\begin{array}{llllrl}\n" + head + r" \\ \hline" + "\n" + "\n".join(_tex_rows(results))
            + "\n\\end{array}$$")


# --------------------------------------------------------------------------- claims

def claim_markdown(c: Any) -> str:
    out = [f"**{R._md_cell(c.id)}** {R._md_cell(R.labels(c.paper))} · {c.kind} · §{R._md_cell(c.section or '-')}",
           "", R._md_cell(c.title)]
    statement = R._md_statement(c.statement)
    if statement:
        out += ["", statement]
    out += ["", f"Sizes: {R._md_cell(c.sizes.describe())}; expected: {c.expect}"]
    if c.erratum:
        out += ["", f"Erratum: {R._md_cell(c.erratum)}"]
    return "\n".join(out) + "\n"


def claim_latex(c: Any) -> str:
    head = _tex_text(f"{c.id} {R.labels(c.paper)}: {c.title}")
    statement = c.statement.strip()
    if statement and R.math_ok(statement) and "\\begin" not in statement:
        return f"$$\\begin{{gathered}}{head} \\\\ {R._md_math(statement)}\\end{{gathered}}$$"
    return f"$${head}$$"


# --------------------------------------------------------------------------- sympy

_MOD = re.compile(r"^\s*(-?\d+)\s*\(mod\s+(\d+)\)\s*$")
_BALL = re.compile(r"^\s*\[\s*([-+0-9.eE]+)\s*\+/-\s*([-+0-9.eE]+)\s*\]\s*$")
#: the largest exponent a residual's text may hold (an engine's residual has small ones; a record edited by
#: hand could hold 9**9**9**9, which would be evaluated for ever)
MOST_EXPONENT = 10_000
#: the most bits a power of a number in a residual's text may have ((9**9999)**9999 has 10^8)
MOST_POWER_BITS = 1 << 20
#: the longest residual text read (an engine's residual entry is far shorter)
MOST_CHARS = 1_000_000
#: the tokens of a residual's text: a number, a chart coordinate (Z_2,1), a name (lambda, a_1), an operator
_TOKEN = re.compile(r"\s*(?:(?P<num>\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)|(?P<coord>[A-Za-z][A-Za-z0-9]*_\d+,\d+)"
                    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<op>\*\*|[-+*/()]))", re.ASCII)


def _sympy_text(text: str) -> Any:
    """An engine's residual or value text as sympy: chart coordinates such as ``Z_2,1`` become
    symbols of that name, ``v (mod p)`` the residue v (an Integer), a ball ``[m +/- r]`` the Interval.

    The text is read by a parser of its own (numbers, ASCII names, + − · / ** and parentheses), which builds the
    sympy objects itself: nothing of it is evaluated as code (sympy's parser evaluates Python, and a record edited
    by hand can hold anything); an exponent beyond :data:`MOST_EXPONENT` is refused.  ValueError otherwise."""
    import sympy
    if len(text) > MOST_CHARS:
        raise ValueError(f"not an engine's residual: {len(text):,} characters")
    m = _MOD.match(text)
    if m:
        return sympy.Integer(int(m.group(1)) % int(m.group(2)))
    m = _BALL.match(text)
    if m:          # a ball of the ball method: the interval it encloses the exact value in
        mid, rad = sympy.Float(m.group(1)), sympy.Float(m.group(2))
        return sympy.Interval(mid - rad, mid + rad)
    tokens: list[tuple[str, str]] = []
    pos, stripped = 0, text.rstrip()
    while pos < len(stripped):
        t = _TOKEN.match(stripped, pos)
        if t is None or t.end() == pos:
            raise ValueError(f"not an engine's residual: {stripped[pos:pos + 20]!r} at character {pos + 1}")
        kind = t.lastgroup or ""
        tokens.append((kind, t.group(kind)))
        pos = t.end()
    symbols: dict[str, Any] = {}
    at = [0]

    def peek() -> str | None:
        return tokens[at[0]][1] if at[0] < len(tokens) and tokens[at[0]][0] == "op" else None

    def expr() -> Any:
        out = term()
        while peek() in ("+", "-"):
            op = tokens[at[0]][1]
            at[0] += 1
            out = out + term() if op == "+" else out - term()
        return out

    def term() -> Any:
        out = unary()
        while peek() in ("*", "/"):
            op = tokens[at[0]][1]
            at[0] += 1
            rhs = unary()
            if op == "/" and rhs == 0:
                raise ValueError("not an engine's residual: a division by 0")
            out = out * rhs if op == "*" else out / rhs
        return out

    def unary() -> Any:
        if peek() in ("-", "+"):
            op = tokens[at[0]][1]
            at[0] += 1
            return -unary() if op == "-" else unary()
        return power()

    def power() -> Any:
        base = atom()
        if peek() == "**":
            at[0] += 1
            e = unary()
            if not (isinstance(e, sympy.Integer) and abs(int(e)) <= MOST_EXPONENT):
                raise ValueError(f"not an engine's residual: a power with the exponent {str(e)[:40]}")
            if base == 0 and e < 0:
                raise ValueError("not an engine's residual: a division by 0")
            if isinstance(base, sympy.Rational):
                bits = max(int(base.p).bit_length(), int(base.q).bit_length()) * abs(int(e))
                if bits > MOST_POWER_BITS:
                    raise ValueError(f"not an engine's residual: a power of about {bits:,} bits")
            return base ** e
        return base

    def atom() -> Any:
        if at[0] >= len(tokens):
            raise ValueError("not an engine's residual: it ends too soon")
        kind, value = tokens[at[0]]
        at[0] += 1
        if kind == "num":
            return sympy.Integer(int(value)) if value.isdigit() else sympy.Float(value)
        if kind in ("coord", "name"):
            if value not in symbols:
                symbols[value] = sympy.Symbol(value)
            return symbols[value]
        if value == "(":
            out = expr()
            if peek() != ")":
                raise ValueError("not an engine's residual: a parenthesis is not closed")
            at[0] += 1
            return out
        raise ValueError(f"not an engine's residual: {value!r} where a number or a name belongs")

    try:
        out = expr()
    except RecursionError:
        raise ValueError("not an engine's residual: nested deeper than Python's stack") from None
    if at[0] != len(tokens):
        raise ValueError(f"not an engine's residual: {tokens[at[0]][1]!r} after the end of an expression")
    return out


def residual_sympy(r: Result) -> Any:
    """The witness residual of a failing result as a sympy expression: the residual entry as a
    function of the chart's coordinates when the result holds it in full (the exact method), else
    its value at the witness point (a Rational; for the modular method the residue modulo
    ``witness['prime']``; for floating point the Float; for the ball method the Interval its ball
    encloses the value in).  ValueError for a text no engine writes (a record edited by hand)."""
    if r.residual and not r.residual.endswith("...") and " = " in r.residual:
        text = r.residual.rpartition(" = ")[2]
        try:
            return _sympy_text(text)
        except ValueError:
            pass
    w = r.witness or {}
    if w.get("value") is not None:
        try:
            return _sympy_text(str(w["value"]))
        except ValueError as exc:
            raise ValueError(f"{R.case_name(r)}: the witness value {str(w['value'])[:60]!r}: {exc}") from None
    raise ValueError(f"{R.case_name(r)}: {r.verdict}, no residual witness to convert")


def _install() -> None:
    """The displays and conveniences of results, result lists and claims (this module renders with
    the report's code, which the results and claims modules sit below)."""
    from stiefelsym.claims import Claim
    from stiefelsym.results import ResultList

    def summary(self: ResultList) -> str:
        """The summary table ``stiefelsym verify`` prints."""
        return R.render_summary(self)

    def result_residual_sympy(self: Result) -> Any:
        """The witness residual of a failure as a sympy expression (see :func:`residual_sympy`);
        ValueError when there is none."""
        return residual_sympy(self)

    Result.residual_sympy = result_residual_sympy                  # type: ignore[attr-defined]
    Result._repr_markdown_ = result_markdown                       # type: ignore[attr-defined]
    Result._repr_latex_ = lambda self: results_latex([self])       # type: ignore[attr-defined]
    ResultList.summary = summary                                   # type: ignore[attr-defined]
    ResultList._repr_markdown_ = results_markdown                  # type: ignore[attr-defined]
    ResultList._repr_latex_ = results_latex                        # type: ignore[attr-defined]
    Claim._repr_markdown_ = claim_markdown                         # type: ignore[attr-defined]
    Claim._repr_latex_ = claim_latex                               # type: ignore[attr-defined]


_install()
