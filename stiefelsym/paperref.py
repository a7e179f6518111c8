"""The paper's own numbers for its ``\\label`` keys: "(12) in §5", "Theorem 5.3".

The catalog names the statements it checks by the paper's label keys (``cond_XP``, ``NEUMANN2``).
A reader looks for the printed numbers instead.  They are read from the ``.aux`` file of the
paper, compiled once with pdflatex and hyperref (which records each label's counter), and from
the paper's source (which environment a label sits in: equation, Theorem, Proposition, ...).
The table is committed as ``proofs/paper_labels.json`` and shipped with the catalog, so the
reports need neither the paper nor LaTeX; ``make paper-labels`` regenerates it.
"""
from __future__ import annotations

import json
import re
import shutil
import subprocess
import tempfile
from functools import cache
from importlib import resources
from pathlib import Path
from typing import NotRequired, TypedDict


class PaperRef(TypedDict):
    kind: str       # "equation", "Theorem", "Proposition", "Lemma", "Corollary", "Remark", "section",
                    # or "display" (an unnumbered display: no number of its own)
    number: str     # as printed: "12" for an equation, "5.3" for a theorem
    section: str    # the section's number as printed (the appendices are §9 and §10)
    page: str       # the page in the compiled paper
    within: NotRequired[str]    # the statement it stands in when that has no label of its own: "Theorem 4.2"


#: theorem-like environments of the paper and their printed names
THEOREM_NAMES = {"thm": "Theorem", "prop": "Proposition", "lem": "Lemma", "cor": "Corollary",
                 "remark": "Remark"}
LABEL_FILE = "paper_labels.json"


def _groups(text: str, start: int, count: int) -> list[str]:
    """The ``count`` brace groups of ``text`` from ``start`` on (nested braces respected)."""
    out, i = [], start
    while len(out) < count:
        i = text.index("{", i)
        depth, j = 0, i
        while True:
            if text[j] == "{":
                depth += 1
            elif text[j] == "}":
                depth -= 1
                if depth == 0:
                    break
            j += 1
        out.append(text[i + 1:j])
        i = j + 1
    return out


def _aux_labels(aux: str) -> dict[str, tuple[str, str, str]]:
    """label -> (number, page, hyperref anchor) from an .aux written with hyperref."""
    out = {}
    for m in re.finditer(r"^\\newlabel\{", aux, flags=re.M):
        key, body = _groups(aux, m.start(), 2)
        if key.endswith("@cref"):
            continue
        fields = _groups("{" + body + "}", 1, 4) if body.count("{") >= 4 else None
        if fields is None:
            continue
        number, page, _title, anchor = fields
        out[key] = (number, page, anchor)
    return out


def _environments(tex: str) -> dict[str, str]:
    """label -> the innermost theorem-like environment around it in the source ("display" for an
    unnumbered display, whose reference prints the number of the last numbered item)."""
    out: dict[str, str] = {}
    stack: list[str] = []
    for m in re.finditer(r"\\(begin|end)\{([^}]*)\}|\\label\{([^}]*)\}|\\(section)\*?\{", tex):
        if m.group(1) == "begin":
            stack.append(m.group(2))
        elif m.group(1) == "end":
            if m.group(2) in stack:
                while stack and stack.pop() != m.group(2):
                    pass
        elif m.group(3) is not None:
            env = next((e for e in reversed(stack) if e in THEOREM_NAMES or e.endswith("*")), None)
            out.setdefault(m.group(3), "display" if env and env.endswith("*")
                           else THEOREM_NAMES[env] if env else "")
    return out


#: theorem-like environments numbered by the theorem counter (shared, per section); a remark has its own
SHARED_COUNTER = ("thm", "prop", "lem", "cor")


def _nested_removed(body: str) -> str:
    """``body`` without its nested environments (their labels are theirs, not the enclosing statement's)."""
    prev = None
    while prev != body:
        prev, body = body, re.sub(r"\\begin\{([^}]*)\}(?:(?!\\begin\{).)*?\\end\{\1\}", "", body, flags=re.S)
    return body


def unlabelled_statements(tex: str) -> dict[str, list[str]]:
    """The paper's theorem-like statements that have no ``\\label`` of their own, by the names the paper prints
    ("Theorem 4.3", "Proposition 2.2"), each with the labels that stand inside it (the equations it states), in the
    order of the paper.  A reader finds such a statement by its number only: a claim that checks one of its
    equations names it too (:func:`printed`).  Numbered as the paper's ``\\newtheorem``s number them: Theorem,
    Proposition, Lemma and Corollary share one counter per section, a Remark has its own."""
    out: dict[str, list[str]] = {}
    section, counts = 0, {"thm": 0, "remark": 0}
    for m in re.finditer(r"\\section(\*?)\{|\\begin\{(" + "|".join(THEOREM_NAMES) + r")\}", tex):
        if m.group(2) is None:
            if not m.group(1):
                section, counts = section + 1, {"thm": 0, "remark": 0}
            continue
        env = m.group(2)
        counter = "thm" if env in SHARED_COUNTER else "remark"
        counts[counter] += 1
        end = tex.find("\\end{" + env + "}", m.end())
        body = tex[m.end():end if end >= 0 else len(tex)]
        if not re.search(r"\\label\{", _nested_removed(body)):
            out[f"{THEOREM_NAMES[env]} {section}.{counts[counter]}"] = re.findall(r"\\label\{([^}]*)\}", body)
    return out


def _source_sections(tex: str) -> dict[str, str]:
    """label -> the number of the section it stands in, counted in the source (the paper's sections,
    appendices included, are numbered in order): an unnumbered display's reference prints the last
    numbered item's number, not its section's."""
    out: dict[str, str] = {}
    count = 0
    for m in re.finditer(r"\\section(\*?)\{|\\label\{([^}]*)\}", tex):
        if m.group(2) is not None:
            out.setdefault(m.group(2), str(count) if count else "")
        elif not m.group(1):        # \section*: no number
            count += 1
    return out


#: multi-line displays whose rows are numbered one by one (a row with \notag or \nonumber has no number)
ROW_DISPLAYS = ("gather", "align", "eqnarray", "multline", "flalign", "alignat")
_UNNUMBERED_ROW = re.compile(r"\\(notag|nonumber)\b")


def _rows(body: str) -> list[str]:
    """The rows of a display's body: split at each ``\\\\`` outside braces and nested environments (a matrix's
    rows stay in its row)."""
    rows, cur, depth, nest, i = [], [], 0, 0, 0
    while i < len(body):
        if body.startswith("\\begin{", i):
            nest += 1
        elif body.startswith("\\end{", i):
            nest -= 1
        if body.startswith("\\\\", i) and depth == 0 and nest == 0:
            rows.append("".join(cur))
            cur, i = [], i + 2
            continue
        depth += {"{": 1, "}": -1}.get(body[i], 0)
        cur.append(body[i])
        i += 1
    return rows + ["".join(cur)]


def _labels_on_numbered_rows(tex: str) -> str:
    """The source with every label that stands in an unnumbered row of a multi-line display moved to the nearest
    numbered row of that display (the first after it, else the last before it).  A display carries the number of
    its numbered row, which is what a reader sees beside it; amsmath gives such a label another number (the
    next equation's, elsewhere: the paper's (so(n,n)) resolves to the number of (LA3*C)), which the reports must
    not print as the display's."""
    out, pos = [], 0
    for m in re.finditer(r"\\begin\{(" + "|".join(ROW_DISPLAYS) + r")\}", tex):
        end = tex.find("\\end{" + m.group(1) + "}", m.end())
        if end < 0 or m.start() < pos:
            continue
        rows = _rows(tex[m.end():end])
        numbered = [k for k, row in enumerate(rows) if not _UNNUMBERED_ROW.search(row)]
        moved = list(rows)
        for k, row in enumerate(rows):
            labels = re.findall(r"\\label\{[^}]*\}", row)
            if not labels or k in numbered or not numbered:
                continue
            to = next((j for j in numbered if j > k), numbered[-1])
            for label in labels:
                moved[k] = moved[k].replace(label, "", 1)
                moved[to] = moved[to] + label
        out += [tex[pos:m.end()], "\\\\".join(moved)]
        pos = end
    return "".join(out) + tex[pos:]


def build(tex_path: Path) -> dict[str, PaperRef]:
    """Compile a copy of the paper with hyperref (two pdflatex passes, errors tolerated) and read
    every label's printed number, environment and section."""
    tex = Path(tex_path).read_text(encoding="utf-8", errors="replace")
    if shutil.which("pdflatex") is None:
        raise RuntimeError("pdflatex is needed to number the paper's labels (Debian: texlive-latex-base)")
    with tempfile.TemporaryDirectory() as tmp:
        src = re.sub(r"(\\documentclass[^\n]*\n)", lambda m: m.group(1) + "\\usepackage{hyperref}\n",
                     _labels_on_numbered_rows(tex), count=1)
        (Path(tmp) / "paper.tex").write_text(src, encoding="utf-8")
        for _ in range(2):
            subprocess.run(["pdflatex", "-interaction=nonstopmode", "paper.tex"], cwd=tmp, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300, check=False)
        aux = (Path(tmp) / "paper.aux").read_text(encoding="utf-8", errors="replace")
    envs, sections = _environments(tex), _source_sections(tex)
    out: dict[str, PaperRef] = {}
    for key, (number, page, anchor) in sorted(_aux_labels(aux).items()):
        counter, _, where = anchor.partition(".")
        section = where.split(".")[0]
        kind = counter if counter in ("section", "equation") else (envs.get(key) or "Theorem")
        if kind == "display":
            section = sections.get(key, section)
        out[key] = PaperRef(kind=kind, number=number, section=section, page=page)
    for name, keys in unlabelled_statements(tex).items():
        for key in keys:
            if key in out:
                out[key]["within"] = name
    return out


def write(tex_path: Path, dest: Path) -> dict[str, PaperRef]:
    table = build(tex_path)
    dest.write_text(json.dumps(table, indent=1, sort_keys=True, ensure_ascii=False) + "\n", encoding="utf-8")
    return table


@cache
def table() -> dict[str, PaperRef]:
    """The committed table (empty if the catalog ships none)."""
    try:
        text = resources.files("stiefelsym.proofs").joinpath(LABEL_FILE).read_text(encoding="utf-8")
    except (FileNotFoundError, ModuleNotFoundError):
        return {}
    return json.loads(text)


def printed(label: str) -> str:
    """How the paper prints a reference to ``label``: "(12) §5", "Thm 5.3", "§7"; the label
    itself where the paper's table does not know it."""
    ref = table().get(label)
    if ref is None:
        return f"({label})"
    if ref["kind"] == "equation":
        return f"({ref['number']}) §{ref['section']}" + (f" in {ref['within']}" if ref.get("within") else "")
    if ref["kind"] == "section":
        return f"§{ref['number']}"
    if ref["kind"] == "display":      # its page depends on the paper's build: named by its section
        return f"unnumbered display in §{ref['section']}" if ref["section"] else "unnumbered display"
    return f"{ref['kind']} {ref['number']}"


#: the words a theorem-like label follows in prose ("Theorem man-dual")
_KIND_WORDS = ("Theorem", "Proposition", "Lemma", "Corollary", "Remark")
#: their plurals, followed by a list of labels ("Theorems DUAL and man-dual", "Lemmas LEMA1, LEMA2")
_PLURALS = {"Theorems": "Theorem", "Propositions": "Proposition", "Lemmas": "Lemma", "Corollaries": "Corollary",
            "Remarks": "Remark"}


@cache
def _label_patterns() -> tuple[re.Pattern, re.Pattern, re.Pattern, re.Pattern] | None:
    """(label in parentheses, kind word and label, plural kind word and a list of labels, a label alone) for the
    labels of the table, longest first; an
    underscore of a label may be written ``\\_`` (the LaTeX of a statement)."""
    labels = sorted(table(), key=len, reverse=True)
    if not labels:
        return None
    alt = "|".join(re.escape(k).replace("_", r"\\?_") for k in labels)
    one = r"(?:" + alt + r")(?![\w*()\-])"
    return (re.compile(r"\((" + alt + r")\)"),
            re.compile(r"\b(" + "|".join(_KIND_WORDS) + r")[ ~]+(" + alt + r")(?![\w*()\-])"),
            re.compile(r"\b(" + "|".join(_PLURALS) + r")[ ~]+(" + one + r"(?:(?:,[ ~]*|,?[ ~]+and[ ~]+)" + one + r")+)"),
            re.compile(alt.join((r"(?<![\w\-])(", r")(?![\w*()\-])"))))


#: names the paper prints as names, not as numbers, although a ``\label`` of the same key stands beside them: the
#: conditions (A1), (A2) in the proof of Lemma 6.3 (the label A2 is the equation (11) §6 that states the second).
#: ``readable(..., keep=CONDITION_NAMES)`` leaves "(A2)" as printed.
CONDITION_NAMES = ("A1", "A2")


def readable(text: str, statement: bool = False, keep: tuple[str, ...] = ()) -> str:
    """``text`` with the paper's label keys replaced by the numbers the paper prints: "(dot_XP3*)" becomes
    "(5) §4" ("(5) of Section 4" in a ``statement``, which is LaTeX), "Theorem man-dual" becomes
    "Theorem 4.4", "Theorems DUAL and man-dual" "Theorems 8.1 and 4.4", "(DUAL)" becomes "(Theorem 8.1)".  A label the table does not know, or of an unnumbered
    display or a section, is left as it is: the keys stay in the headings, as the catalog's names.  A key in
    ``keep`` (such as :data:`CONDITION_NAMES`, names the paper itself prints) is left as it is too."""
    pats = _label_patterns()
    if pats is None or not text:
        return text
    t = {k: v for k, v in table().items() if k not in keep}
    paren, named, plural, label = pats

    def ref(m: re.Match) -> str:
        key = m.group(1).replace("\\_", "_")
        r = t.get(key)
        if r is None:
            return m.group(0)
        if r["kind"] == "equation":
            return f"({r['number']}) of Section {r['section']}" if statement else f"({r['number']}) §{r['section']}"
        if r["kind"] in _KIND_WORDS:
            return f"({r['kind']} {r['number']})"
        return m.group(0)

    def kind(m: re.Match) -> str:
        r = t.get(m.group(2).replace("\\_", "_"))
        if r is None or r["kind"] not in _KIND_WORDS:
            return m.group(0)
        return f"{r['kind']} {r['number']}"

    def kinds(m: re.Match) -> str:
        word = _PLURALS[m.group(1)]
        refs = [t.get(k.replace("\\_", "_")) for k in label.findall(m.group(2))]
        if any(r is None or r["kind"] != word for r in refs):
            return m.group(0)
        numbers = iter(r["number"] for r in refs)
        return m.group(1) + " " + label.sub(lambda _: next(numbers), m.group(2).lstrip(" ~"))

    return paren.sub(ref, named.sub(kind, plural.sub(kinds, text)))
