"""The discovery report: the corrections of the paper's printed formulas as solution spaces.

Renders :class:`stiefelsym.analyses.discover.CorrectionSpace` records (nothing is recomputed here) to
``discover.md`` and a LaTeX fragment ``discover.tex``; neither holds a time or a date, so the bytes
depend on the records only."""
from __future__ import annotations

import re
from pathlib import Path
from typing import Sequence

from stiefelsym.analyses.discover import CorrectionSpace


def _dimension(sp: CorrectionSpace) -> str:
    return "empty" if sp.empty else "none given" if sp.particular is None else str(sp.dimension)


def _registered(sp: CorrectionSpace) -> str:
    if sp.contains_registered is None:
        return "—"
    word = "matches" if sp.contains_registered else "does not match"
    if sp.ansatz.registered_name != "the registered correction":
        return f"{word} the general line (registered for l = 1)"
    return word


def _verdicts(sp: CorrectionSpace) -> str:
    if sp.empty:
        return f"certified empty (rank {sp.rank} < {sp.rank_augmented})"
    if sp.particular is None:
        return "no formula given, none excluded"
    return ", ".join(f"{m} {v}" for m, v in sp.verdicts.items()) or "not verified"


#: the claims whose printed formula is a schematic line ("+ ⋯"), and the lines l (at size r) where it states no
#: term beyond those shown, so that no printed formula can be computed there (verification.md checks the line
#: where it can be read literally)
SCHEMATIC = {"2r-integrals-general-line": lambda l, r: 1 < l < r}


def _printed_words(sp: CorrectionSpace) -> str:
    """Whether the printed formula is in the space, or, on a line that the paper writes schematically, that no
    printed formula is tested there and what its literal reading gives."""
    verdict = "holds" if sp.contains_printed else "is not in the space"
    line = re.search(r"\bl = (\d+)\b", sp.ansatz.label)
    schematic = SCHEMATIC.get(sp.ansatz.claim)
    if line is None or schematic is None or not schematic(int(line.group(1)), sp.size.r):
        return f"the printed formula {verdict}"
    return (f"the printed line is schematic at 1 < l < r (it ends in “+ ⋯”, which states no further term), so no "
            f"printed formula is tested at l = {line.group(1)}; read literally as the sums of its l vectors e and "
            f"any number of p, it {'holds' if sp.contains_printed else 'is not in the space'}")


def _md_escape(text: str) -> str:
    return text.replace("|", r"\|")


Sweep = Sequence[tuple[int, int, int, str]]


def _sweep_sentence(sweep: Sweep) -> str:
    good = sum(v in ("proved", "checked") for *_, v in sweep)
    counts = {v: sum(x[3] == v for x in sweep) for v in sorted({x[3] for x in sweep})}
    n_max = max(x[0] for x in sweep)
    return (f"The general line of (2r-integrals) found above, checked at every 1 ≤ l ≤ r ≤ n ≤ {n_max}: "
            f"{good} of {len(sweep)} hold (" + ", ".join(f"{v} {c}" for v, c in counts.items()) + ").")


GENERAL_LINE = (r"\mathcal I_{2l}(\lambda)=\sum_{k=0}^{l}\sum_{I_{l+k}}\frac{a(\lambda)}{\prod_{i\in I}(\lambda-a_i)}"
                r"\sum_{J_{l-k}}\Big(e_{j_1}\wedge\cdots\wedge e_{j_{l-k}}\wedge\frac{\omega^k}{k!}\Big)_{I_{l+k}}^2,"
                r"\quad\omega=e_1\wedge p_1+\cdots+e_r\wedge p_r")


def render_markdown(spaces: Sequence[CorrectionSpace], sweep: Sweep | None = None) -> str:
    """The table of the corrections found, then each search space with its directions or certificate."""
    out = ["# Corrections as solution spaces", "",
           "For each printed formula that fails, the formulas of its shape that hold: every term of the same "
           "type and degree with an unknown rational coefficient, solved exactly at random points over "
           "GF(2⁶¹ − 1) (modulo the combinations that vanish on the phase space), reconstructed as rationals, "
           "each solution then verified by the catalog's methods. An empty space is certified by a rank.",
           "Regenerate with `stiefelsym discover --correct all --report-dir reports`.", "",
           "| claim | formula searched | (n, r) | N | dim | solution | registered correction | verdicts |",
           "|---|---|---|---|---|---|---|---|"]
    for sp in spaces:
        a = sp.ansatz
        sol = "—" if sp.particular is None else f"${sp.latex()}$"
        out.append(f"| `{a.claim}` {a.label} | ${a.slot_latex}$ | ({sp.size.n}, {sp.size.r}) | {sp.N} | "
                   f"{_dimension(sp)} | {_md_escape(sol)} | {_registered(sp)} | {_verdicts(sp)} |")
    out.append("")
    if sweep:
        out += ["The general line of (2r-integrals), as found:", "", f"$$ {GENERAL_LINE} $$", "",
                _sweep_sentence(sweep), ""]
    for sp in spaces:
        a = sp.ansatz
        out += [f"## `{a.claim}` {a.label}: ${a.slot_latex}$", "",
                f"Search space ({sp.N} terms): {a.description_latex}.", "",
                f"- {sp.certificate()[0].upper() + sp.certificate()[1:]}."]
        if sp.particular is not None:
            out.append(f"- ${a.slot_latex} = {sp.latex()}$")
            out += [f"- plus any multiple of ${sp.latex(b)}$" for b in sp.basis]
        if sp.contains_printed is not None:
            out.append(f"- {_printed_words(sp)}.")
        out.append("")
    return "\n".join(out)


def _tex_id(claim: str) -> str:
    """A claim's name in typewriter type that may break after each hyphen (a table's narrow column)."""
    return r"\texttt{" + claim.replace("-", r"-\allowbreak{}") + "}"


def _tex_slot(slot: str) -> str:
    r"""The formula searched, followed by =, in a table cell: words that open it (``\text{the last term
    of }\dot Q``) as text, which breaks between the cell's lines."""
    m = re.fullmatch(r"\\text\{([^{}$\\]*)\}(.*)", slot, re.S)
    if m:
        return m.group(1).rstrip() + f" ${m.group(2)} ={{}}$"
    return f"${slot} ={{}}$"


def _tex_cell_math(tex: str) -> str:
    r"""Mathematics in a table cell: as it is when TeX can break it across the cell's lines; a matrix
    (or ``\left … \right``), which it cannot, shrunk to the cell's width when wider (never overfull)."""
    if "\\begin{" not in tex and "\\left" not in tex:
        return f"${tex}$"
    return r"\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{$" + tex + "$}"


#: the table's columns, as fractions of the text width
COLUMNS = (0.19, 0.07, 0.04, 0.08, 0.32, 0.13)


def render_latex(spaces: Sequence[CorrectionSpace], sweep: Sweep | None = None) -> str:
    """A LaTeX fragment (for amsmath, longtable and graphicx).  Every cell is set
    ragged right (a row ends with \\tabularnewline, which \\raggedright leaves alone)."""
    def row(cells: Sequence[str]) -> str:
        return " & ".join(r"\raggedright " + c for c in cells) + r" \tabularnewline"
    out = [r"% generated by stiefelsym discover --correct all --report-dir reports; do not edit",
           r"% needs \usepackage{amsmath,longtable,graphicx}",
           # 0.83 of the text width and ten gaps of 8pt: within the line of any usual text width
           r"{\setlength{\tabcolsep}{4pt}",
           r"\begin{longtable}{@{}" + "".join(f"p{{{w}\\textwidth}}" for w in COLUMNS) + "@{}}",
           row(["claim", "$(n,r)$", "$N$", "dim", "solution", "registered"]) + r" \hline", r"\endhead"]
    for sp in spaces:
        a = sp.ansatz
        sol = r"---" if sp.particular is None else _tex_slot(a.slot_latex) + " " + _tex_cell_math(sp.latex())
        out.append(row([f"{_tex_id(a.claim)} {a.label}", f"$({sp.size.n},{sp.size.r})$", str(sp.N),
                        _dimension(sp), sol, _registered(sp).replace("—", "---")]))
    out += [r"\end{longtable}}", ""]
    if sweep:
        out += [r"The general line of (2r-integrals), as found:", r"\[" + GENERAL_LINE + r"\]",
                _sweep_sentence(sweep).replace("≤", r"$\le$"), ""]
    # the search spaces: long sets in inline mathematics, so the paragraphs are set sloppy
    out.append(r"{\sloppy")
    for sp in spaces:
        a = sp.ansatz
        # the primes as the certificate writes them, 2^e - k, in mathematics
        cert = re.sub(r"2\^(\d+) - (\d+)", r"$2^{\1}-\2$", sp.certificate())
        cert = cert.replace("GF($2^{61}-1$)", r"$\mathrm{GF}(2^{61}-1)$").replace(" x ", r" $\times$ ")
        out.append(rf"\paragraph{{{_tex_id(a.claim)} {a.label}: ${a.slot_latex}$.}} Search space ({sp.N} terms): "
                   rf"{a.description_latex}. {cert[0].upper() + cert[1:]}.")
        out.append("")
    out += [r"\par}", ""]
    return "\n".join(out)


def write_reports(spaces: Sequence[CorrectionSpace], directory: Path, sweep: Sweep | None = None) -> list[Path]:
    """Write discover.md and discover.tex into ``directory``; returns their paths."""
    directory.mkdir(parents=True, exist_ok=True)
    md, tex = directory / "discover.md", directory / "discover.tex"
    md.write_text(render_markdown(spaces, sweep), encoding="utf-8")
    tex.write_text(render_latex(spaces, sweep), encoding="utf-8")
    return [md, tex]
