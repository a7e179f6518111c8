"""Certificates as data: residual entries and their cofactor representations in JSON.

The form read by :mod:`stiefelsym.certificate_check` (format
``stiefelsym-cofactor-1``)::

    {"format": ..., "symbols": {name: what it stands for},
     "letters": {name: {"kind": "resolvent", "parameter": "lambda_"} |
                       {"kind": "generic", "row": "n", "col": "r", "transpose": name} |
                       {"kind": "generic", "row": "n", "col": "n", "transpose": name, "sign": 1 or -1} |
                       {"kind": "operator", "operator": "AA", "argument": ["X", "Pt"]}},
     "entries": [{"position": "dL[1,1]", "type": ["n", "n"],
                  "residual": [{"coef": "2*kappa", "traces": [["Xt", "P"]], "word": ["X", "Pt"]}, ...],
                  "terms": [{"coef": "-1", "traces": [], "left": ["Xt"], "hyp": "XtP+PtX",
                             "right": ["X"], "in_trace": false, "word": []}, ...]}]}

Letters are written by name (X, Xt, P, Pt, A, Ainv, xi, …; R[μ] and gen:… are
declared), coefficients as strings that symengine and sympy parse, with one
name per symbol (a claim's own scalar that prints like a chart symbol gets
another name; n and r are the dimensions, tr I_n = n).
"""
from __future__ import annotations

import keyword
import re
from typing import Any, Iterable, Mapping

import symengine as se

from stiefelsym.free.algebra import DIMENSIONS, Letter, NCPoly, OperatorLetter, memo_put
from stiefelsym.free.rewriting import Certificate

FORMAT = "stiefelsym-cofactor-1"


#: coefficient -> (its free symbols, its text): both functions of the coefficient alone
_COEF_TEXT: dict = {}


def _coef_text(c: Any) -> tuple[tuple, str]:
    try:
        return _COEF_TEXT[c]
    except (KeyError, TypeError):
        pass
    return memo_put(_COEF_TEXT, c, (tuple(c.free_symbols), str(c)), 100_000)


#: words of letters that need no declaration (X, Pt, A, ...) -> their names (the same for every writer)
_PLAIN_WORDS: dict = {}
#: symbol -> the identifier it is written as, before disambiguation (a function of the symbol)
_BASE_NAMES: dict = {}


def _base_name(s: Any) -> str:
    try:
        return _BASE_NAMES[s]
    except (KeyError, TypeError):
        pass
    base = re.sub(r"\W", "_", str(s)) or "s"
    if not base[0].isalpha():
        base = "s" + base
    if keyword.iskeyword(base):
        base += "_"
    return memo_put(_BASE_NAMES, s, base, 100_000)


class CertificateWriter:
    """Serializes the entries of one scene (one naming of symbols and letters)."""

    def __init__(self, resolvents: Mapping[Letter, Any], sylvester: Mapping[Letter, Any] | None = None,
                 realization: str = "standard") -> None:
        self.resolvents = dict(resolvents)
        #: the multipliers of the metric realization's flows (letters declared with their flow and relation)
        self.sylvester = dict(sylvester or {})
        self.realization = realization
        self.symbols: dict[Any, str] = {DIMENSIONS["n"]: "n", DIMENSIONS["r"]: "r"}
        self.meaning: dict[str, str] = {"n": "the dimension n (tr I_n)", "r": "the dimension r (tr I_r)"}
        self.letters: dict[str, dict] = {}
        self.entries: list[dict] = []

    # -- names ----------------------------------------------------------------
    def _symbol_name(self, s: Any) -> str:
        name = self.symbols.get(s)
        if name is not None:
            return name
        base = _base_name(s)
        name, k = base, 1
        taken = set(self.symbols.values())
        while name in taken:
            k += 1
            name = f"{base}_{k}"
        self.symbols[s] = name
        self.meaning[name] = f"the scalar {s}" + ("" if type(s) is se.Symbol else " (a claim's own)")
        return name

    def coef(self, c: Any) -> str:
        if not isinstance(c, se.Basic):
            c = se.sympify(c)
        symbols, text = _coef_text(c)
        subs = {}
        for s in symbols:
            name = self._symbol_name(s)
            if name != str(s) or type(s) is not se.Symbol:
                subs[s] = se.Symbol(name)
        return str(c.xreplace(subs)) if subs else text

    def letter(self, L: Letter) -> str:
        name = str(L)
        if name in self.letters:
            return name
        if isinstance(L, OperatorLetter):
            argument = self.word(L.argument)   # the letters of the argument first
            self.letters[name] = {"kind": "operator", "operator": L.operator, "argument": argument}
        elif L in self.resolvents:
            self.letters[name] = {"kind": "resolvent", "parameter": self.coef(self.resolvents[L])}
        elif L in self.sylvester:
            m = self.sylvester[L]
            decl = self.letters[name] = {"kind": "sylvester", "row": L.row, "constraint": m.hypothesis_of_constraint}
            # (declared before its flow is written: the flow holds the letter itself)
            decl["flow"] = {"X": self.residual(m.Xdot), "P": self.residual(m.Pdot)}
            decl["relation"] = self.residual(m.relation)
            decl["keeps"] = {"XtX": self.entry("d(X^T X)/dt", m.keeps_certificate)}
            if getattr(m, "relation_certificate", None) is not None and m.relation_certificate.residual.expand().terms:
                # the derivative of the constraint as derived minus rho (its normal form), in the constraints
                decl["derived"] = self.entry("d(X^T A^-1 P + P^T A^-1 X)/dt - rho", m.relation_certificate)
            decl["assumes"] = [f"{name} is the solution of rho:{name} = 0, unique and symmetric (M = X^T A^-1 X "
                               "positive definite)", "Pi = 0 by uniqueness: Pi M + M Pi = 0 (keeps: X^T X = I_r)"]
        elif name.startswith("gen:") and L.adjoint != L:
            G = L if not name.endswith("^T") else L.adjoint
            if str(G) not in self.letters:
                self.letters[str(G)] = {"kind": "generic", "row": G.row, "col": G.col, "transpose": str(G.adjoint)}
        elif name.startswith("gen:") and name not in self.letters:
            # a generic symmetric or skew letter: its own transpose, with the sign of its transpose
            self.letters[name] = {"kind": "generic", "row": L.row, "col": L.col, "transpose": name,
                                  "sign": L.adjoint_sign}
        return name

    def word(self, w: Iterable[Letter]) -> list[str]:
        w = tuple(w)
        names = _PLAIN_WORDS.get(w)
        if names is not None:
            return list(names)
        out = [self.letter(L) for L in w]
        if not any(x.startswith(("R[", "gen:", "Lambda:")) or "(" in x for x in out):   # no letter to declare: any writer's names
            memo_put(_PLAIN_WORDS, w, tuple(out), 100_000)
        return out

    # -- entries --------------------------------------------------------------
    def residual(self, p: NCPoly) -> list[dict]:
        return [{"coef": self.coef(c), "traces": [self.word(t) for t in tm], "word": self.word(w)}
                for (tm, w), c in p.expand().terms.items()]

    def add(self, position: str, cert: Certificate) -> dict:
        entry = self.entry(position, cert)
        self.entries.append(entry)
        return entry

    def entry(self, position: str, cert: Certificate) -> dict:
        """The JSON form of one entry's certificate (not added to the entries)."""
        p = cert.residual
        by_name = {str(R): R for R in self.resolvents}
        for t in cert.terms:   # a hypothesis res_left:R / res_right:R needs R declared, in a word or not
            kind, _, R = t.hyp.name.partition(":")
            if kind in ("res_left", "res_right") and R in by_name:
                self.letter(by_name[R])
        entry = {"position": position, "type": [p.row, p.col], "residual": self.residual(p),
                 "terms": [{"coef": self.coef(t.coef), "traces": [self.word(x) for x in t.traces],
                            "left": self.word(t.left), "hyp": t.hyp.name, "right": self.word(t.right),
                            "in_trace": t.in_trace, "word": self.word(t.word)} for t in cert.terms],
                 "hypotheses": cert.hypotheses()}
        return entry

    def data(self) -> dict:
        terms = sum(len(e["terms"]) for e in self.entries)
        used = {h for e in self.entries for h in e["hypotheses"]}
        declared = [d for d in self.letters.values() if d.get("kind") == "sylvester"]
        used |= {h for d in declared for h in d["keeps"]["XtX"]["hypotheses"]}
        used |= {h for d in declared for h in d.get("derived", {}).get("hypotheses", [])}
        summary = {"entries": len(self.entries), "terms": terms, "hypotheses": sorted(used)}
        if self.realization != "standard":
            summary["realization"] = self.realization
            summary["assumes"] = ["A symmetric positive definite"] + [a for d in declared for a in d["assumes"]]
        return {"format": FORMAT, "realization": self.realization, "symbols": dict(self.meaning),
                "letters": dict(self.letters), "entries": self.entries, "summary": summary}
