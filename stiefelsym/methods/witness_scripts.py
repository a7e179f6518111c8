"""Witness scripts: for every erratum with a template, a self-contained Python script that a reader
runs without stiefelsym.

A template (``proofs/witnesses/<claim-id>.py``, shipped with the catalog) writes the printed
formula and its correction out with sympy, from the paper, independently of the claim's code:

* ``CHECK``: the name of the claim's check the script evaluates (the small witness is searched
  for a point where this check is nonzero, so the report and the script speak of the same entry);
* ``residuals(W)``: ``{"printed": ..., "corrected": ...}``, the value of that check for the
  printed formula and for the correction, at the point ``W`` (letters by ASCII name: ``X``,
  ``P``, ``Y``, ``Q``, ``A``, ``lam``, ``kappa``, ``eps``, ``ReZ``, ``ImZ``, ``ReV``, ``ImV``, the
  double system's ``X``, ``Y``, ``Xdot``, ``Ydot``, and the claim's own scalars (``nu``);
  matrices as ``sympy.Matrix``, scalars as ``sympy.Rational``).

The generated script embeds the witness point, checks that it lies on T*V, evaluates both
residuals, and prints them; its output is committed beside it (``.out``) and the tests compare a
fresh run with it and with the value the report states.

An erratum about a number (a dimension, a rank, a count of invariants, the range of a sum) has a
*count template* instead: ``KIND = "count"``, ``CHECK`` (the claim's Count or Rank check),
``SIZE = (n, r)`` and ``counts()`` returning ``{"computed": k, "printed": m, "corrected": m2,
"meaning": "..."}``: the number computed from the paper's definitions (exactly, with sympy) and the
numbers the printed formula and the correction give.  The script confirms the report when k is
the value the engine computed, k ≠ m and k = m2.  A correction that changes what is counted (an
equation of a system) adds ``"corrected_computed": k2``, the number computed for the corrected
statement, and then k2 = m2 is required instead.
"""
from __future__ import annotations

import ast
import contextlib
import io
import re
from functools import cache
from importlib import resources
from typing import Any

TEMPLATE_DIR = "witnesses"

#: the letters' names in the scripts (ASCII)
ASCII = {"λ": "lam", "κ": "kappa", "ε": "eps", "ξ": "xi", "ζ": "zeta", "η": "eta", "θ": "theta",
         "Ẋ": "Xdot", "Ẏ": "Ydot",
         "Re Z": "ReZ", "Im Z": "ImZ", "Re V": "ReV", "Im V": "ImV"}


@cache
def _templates() -> dict[str, str]:
    try:
        root = resources.files("stiefelsym.proofs").joinpath(TEMPLATE_DIR)
        return {p.name[:-3]: p.read_text(encoding="utf-8") for p in root.iterdir() if p.name.endswith(".py")}
    except (FileNotFoundError, ModuleNotFoundError, NotADirectoryError):
        return {}


def template(cid: str) -> str | None:
    return _templates().get(cid)


def template_counts(cid: str) -> tuple[int, int] | None:
    """(computed, printed) of a count template, recomputed by its own code (sympy, no stiefelsym: the
    catalog's reviewed scripts), at the template's size; None without a count template."""
    text = template(cid)
    if text is None or template_kind(cid) != "count":
        return None
    ns: dict[str, Any] = {"__name__": "template"}
    exec(compile(text, f"<template {cid}>", "exec"), ns)   # noqa: S102 - a reviewed script of the catalog
    c = ns["counts"]()
    return int(c["computed"]), int(c["printed"])


def template_constant(cid: str, name: str, default: Any = None) -> Any:
    """The literal a claim's template assigns to ``name`` at its top level (CHECK, KIND, SIZE, KERNEL), read
    without running it; ``default`` without a template or without that name."""
    text = template(cid)
    for node in ast.parse(text).body if text else []:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == name for t in node.targets):
            return ast.literal_eval(node.value)
    return default


def template_check(cid: str) -> str | None:
    """The check a claim's template evaluates (its ``CHECK``), None without a template."""
    return template_constant(cid, "CHECK")


def template_kind(cid: str) -> str:
    """"point" (a residual at a witness point) or "count" (a number against the printed one)."""
    return template_constant(cid, "KIND", "point")


def template_size(cid: str) -> tuple[int, int] | None:
    size = template_constant(cid, "SIZE")
    return None if size is None else tuple(size)


def count_values(detail: str) -> tuple[int, int] | None:
    """(computed, printed) from the detail of a Count or Rank check: "...: 1 (paper: 0)", or
    "... rank 12 over the function field ...; paper: 13", "... exact rank 12 over Q, ...; paper: 13"."""
    # the claim's own words (its count's meaning, its rank's name) come first and may quote numbers of their
    # own; the engine's numbers follow them: the last match is the engine's
    pairs = re.findall(r"(\d+) \((?:paper|claimed): (\d+)\)", detail)
    if pairs:
        return int(pairs[-1][0]), int(pairs[-1][1])
    ks = re.findall(r"rank (\d+) (?:over the function field|over Q\b|at an exact)", detail)
    ps = re.findall(r"(?:paper|claimed): (\d+)", detail)
    return (int(ks[-1]), int(ps[-1])) if ks and ps else None


def count_meaning(detail: str) -> str:
    """What a Count check counts, from its detail "the generic orbit is regular (1) or singular (0):
    1 (paper: 0)"; "" for a rank's detail."""
    m = re.match(r"(.*): \d+ \((?:paper|claimed): \d+\)$", detail.strip())
    return m.group(1) if m and len(m.group(1)) < 160 else ""


def _entry(entry: str) -> tuple[int, int] | None:
    m = re.search(r"\[(\d+),(\d+)\]$", entry)
    return (int(m.group(1)), int(m.group(2))) if m else None


HEAD = '''#!/usr/bin/env python3
"""A witness to an erratum of Fedorov & Jovanovic, "Geodesic Flows and Neumann Systems on Stiefel
Varieties": {cid} {labels}.

Generated by stiefelsym from reports/results.json; do not edit.  Plain Python with sympy, no import
of stiefelsym.  It rebuilds the point below (exact rationals), checks that it lies on T*V, and
evaluates the printed formula and the correction.  Run: python3 {cid}.py
"""
import sympy as sp

SIZE = ({n}, {r})
POINT = {point}
#: the entry of the residual the report states (1-based; None: a scalar), and its value there
ENTRY = {entry}
STATED = sp.Rational("{value}")

'''

TAIL = '''

def _letters():
    def value(v):
        return sp.Matrix([[sp.Rational(q) for q in row] for row in v]) if isinstance(v, list) else sp.Rational(v)
    return {k: value(v) for k, v in POINT.items()}


def _on_tstar_v(W):
    out = []
    if "Xdot" in W:
        X, Y, Xd, Yd = W["X"], W["Y"], W["Xdot"], W["Ydot"]
        out.append(("X^T Y = I", X.T * Y == sp.eye(X.shape[1])))
        out.append(("Xdot^T Y + X^T Ydot = 0", (Xd.T * Y + X.T * Yd).is_zero_matrix))
        return out
    for x, p in (("X", "P"), ("Y", "Q")):
        if x in W and p in W:
            X, P = W[x], W[p]
            out.append((f"{x}^T {x} = I", X.T * X == sp.eye(X.shape[1])))
            out.append((f"{x}^T {p} + {p}^T {x} = 0", (X.T * P + P.T * X).is_zero_matrix))
    if "ReZ" in W:
        Z = sp.Matrix(sp.BlockMatrix([[W["ReZ"], -W["ImZ"]], [W["ImZ"], W["ReZ"]]]))
        V = sp.Matrix(sp.BlockMatrix([[W["ReV"], -W["ImV"]], [W["ImV"], W["ReV"]]]))
        # realified: conj(Z)^T Z = I_r and conj(Z)^T V + conj(V)^T Z = 0 (V = Zdot) hold iff they hold realified
        out.append(("conj(Z)^T Z = I_r", Z.T * Z == sp.eye(Z.shape[1])))
        out.append(("conj(Z)^T V + conj(V)^T Z = 0, V = Zdot", (Z.T * V + V.T * Z).is_zero_matrix))
    return out


def _show(x):
    x = sp.simplify(x)
    return str(x.tolist()) if isinstance(x, sp.MatrixBase) else str(x)


def _at(x):
    return sp.simplify(x[ENTRY[0] - 1, ENTRY[1] - 1] if ENTRY else x)


def main():
    W = _letters()
    print(f"size (n, r) = {SIZE}")
    # a point of the complex Stiefel variety's tangent bundle TW_{n,r} (realified), else of T*V
    on, check = (("TW_{n,r}", f"{CHECK} (realified)") if "ReZ" in W else
                 ("the phase space of the double system", CHECK) if "Xdot" in W else
                 ("T*V × T*V", CHECK) if "Y" in W else ("T*V", CHECK))
    for name, ok in _on_tstar_v(W):
        print(f"on {on}: {name}: {ok}")
    R = residuals(W)
    print(f"printed formula: {check} = {_show(R['printed'])}")
    print(f"printed formula: entry {ENTRY or ''} = {_at(R['printed'])} (the report states {STATED})")
    zero = all(sp.simplify(x) == 0 for x in (R["corrected"] if isinstance(R["corrected"], sp.MatrixBase)
                                              else [R["corrected"]]))
    print(f"correction: the residual of the corrected formula = {_show(R['corrected'])}"
          + (" (zero)" if zero else " (NOT zero)"))
    ok = all(ok for _, ok in _on_tstar_v(W)) and _at(R["printed"]) == STATED and STATED != 0 and zero
    print("the printed formula fails at this point, and the correction holds there" if ok
          else "MISMATCH: this script does not confirm the report")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
'''


COUNT_HEAD = '''#!/usr/bin/env python3
"""A witness to an erratum of Fedorov & Jovanovic, "Geodesic Flows and Neumann Systems on Stiefel
Varieties": {cid} {labels}.

Generated by stiefelsym from reports/results.json; do not edit.  Plain Python with sympy, no import
of stiefelsym.  It computes the number the printed statement is about, from the paper's
definitions, and compares it with the printed formula and the correction.  Run: python3 {cid}.py
"""
import sympy as sp

#: the number the engine computed (the report states it), and the printed formula's
STATED = {value}
STATED_PRINTED = {paper}

'''

COUNT_TAIL = '''

def main():
    c = counts()
    print(f"size (n, r) = {SIZE}")
    print(f"{CHECK}: {c['meaning']}")
    print(f"computed: {c['computed']} (the report states {STATED})")
    print(f"printed formula: {c['printed']}")
    # a correction that changes what is counted gives the number computed for the corrected statement
    after = c.get("corrected_computed", c["computed"])
    print(f"correction: {c['corrected']}" + (f" (computed for the corrected statement: {after})"
                                              if "corrected_computed" in c else ""))
    ok = (c["computed"] == STATED and c["printed"] == STATED_PRINTED and c["computed"] != c["printed"]
          and after == c["corrected"])
    print("the printed statement fails at this size, and the correction holds there" if ok
          else "MISMATCH: this script does not confirm the report")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
'''


def script_text(cid: str, labels: str, n: int, r: int, witness: dict[str, Any]) -> str | None:
    """The witness script of claim ``cid`` for a small witness (JSON form), None without a template."""
    body = template(cid)
    if body is None:
        return None
    if witness.get("kind") == "count":
        return (COUNT_HEAD.format(cid=cid, labels=labels, value=witness["value"], paper=witness["paper"])
                + _strip_docstring_imports(body).strip() + "\n" + COUNT_TAIL)
    point = {ASCII.get(k, k): v for k, v in witness["letters"].items()}
    return (HEAD.format(cid=cid, labels=labels, n=n, r=r, point=repr(point), entry=repr(_entry(witness["entry"])),
                        value=witness["value"])
            + _strip_docstring_imports(body).strip() + "\n" + TAIL)


def _strip_docstring_imports(body: str) -> str:
    """The template's code without ``import sympy as sp`` (the head imports it once)."""
    return "\n".join(line for line in body.splitlines() if line.strip() != "import sympy as sp")


def run_script(text: str) -> tuple[int, str]:
    """Run a generated script in a fresh namespace; (exit status, what it printed)."""
    out = io.StringIO()
    ns: dict[str, Any] = {"__name__": "witness"}
    with contextlib.redirect_stdout(out):
        exec(compile(text, "<witness>", "exec"), ns)   # noqa: S102 - our own generated script
        status = ns["main"]()
    return status, out.getvalue()


def scripts(results: list[Any], labels_of: Any, catalog: Any = None) -> dict[str, str]:
    """{file name: text} of every witness script and its output, for the results' small witnesses of the
    claims in ``catalog`` (ids; None: every claim): a template recomputes the paper's formula of the
    catalog's claim of that id, not a claim of a user's file that reuses the id."""
    files: dict[str, str] = {}
    for r in results:
        w = r.witness.get("small") if isinstance(r.witness, dict) else None
        if not isinstance(w, dict) or r.variant or (catalog is not None and r.claim not in catalog):
            continue
        text = script_text(r.claim, labels_of(r), r.n, r.r, w)
        if text is None or f"{r.claim}.py" in files:
            continue
        files[f"{r.claim}.py"] = text
        status, printed = run_script(text)
        files[f"{r.claim}.out"] = printed
    return files
