"""The columns e₁ = XE₁, e₂ = XE₂ of a point of T*V(n, 2): E₁, E₂ ∈ ℝʳ as letters, for r = 2 only
(and E₁ alone for r = 1: every r×r matrix is then a scalar).

E₁, E₂ are r×1 letters (columns of the identity), E₁ᵀ, E₂ᵀ their transposes, with
E_iᵀE_j = δ_ij (rules of the rewriting system, true for every r ≥ 2) and
E₁E₁ᵀ + E₂E₂ᵀ = I_r, which holds exactly when r = 2: it is used only for claims
stated at r = 2 alone, and every proof that uses it says so (the hypothesis
``E1E1t+E2E2t``).

That last relation is not a rewriting rule (it would not decrease): it is a
canonical form.  :func:`canonical` *resolves* every place of a word where it
passes through ℝʳ without a column next to it (inserting I_r = E₁E₁ᵀ + E₂E₂ᵀ, one
certificate term −c·u·(E₁E₁ᵀ + E₂E₂ᵀ − I_r)·v each), then *extracts* the 1×1
pieces: a word that passes through the scalar object twice, u·E_i·(E_jᵀ w E_k)·E_lᵀ·v,
is tr(E_jᵀ w E_k)·u·E_i E_lᵀ v, and a trace that passes k times is a product
of k traces (a 1×1 matrix is its own trace: an identity, no hypothesis).  After
that every r×r quantity is written in the basis E_iE_jᵀ with scalar coefficients,
so the normal form is that of the columns e₁, e₂, p₁, p₂.  At r = 1 the same with E₁ alone and
E₁E₁ᵀ = I_r (hypothesis ``E1E1t``): every r×r word is then a scalar.
"""
from __future__ import annotations

from typing import Any

import symengine as se

from stiefelsym.free.algebra import LEADING, SCALAR, Letter, NCPoly, cycle_rep, letter_pair, merge_traces
from stiefelsym.free.rewriting import CertTerm, Hypothesis

E1, E1t = letter_pair("E1", "E1t", "r", SCALAR, "E_1", "E_1^{T}")
E2, E2t = letter_pair("E2", "E2t", "r", SCALAR, "E_2", "E_2^{T}")
COLUMNS = (E1, E2)
COVECTORS = (E1t, E2t)
#: the last column E_r of I_r (e_n = XE_n of X ∈ SO(n) when r = n): E_rᵀE_r = 1 for every r
ER, ERt = letter_pair("Er", "Ert", "r", SCALAR, "E_r", "E_r^{T}")
#: the first r − 1 columns (E_1, ..., E_{r−1}) of I_r, an r×(r−1) matrix: its columns and E_r are I_r
LEAD, LEADt = letter_pair("Elead", "Eleadt", "r", LEADING, r"E_{<r}", r"E_{<r}^{T}")

#: the orthogonal projectors D, C of ℝʳ onto the two blocks of a splitting ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂}: symmetric,
#: D² = D, C² = C, DC = CD = 0 (not D + C = I_r: a proof holds for every pair of orthogonal blocks)
DSPLIT = Letter("Dsplit", "r", "r", "D")
CSPLIT = Letter("Csplit", "r", "r", "C")
SPLIT = (DSPLIT, CSPLIT)

#: an orthogonal symmetry S of ℝⁿ that commutes with A (S = Sᵀ, S² = I_n, SA = AS): a reflection S_i of a
#: coordinate hyperplane when A is diagonal, and every element of the group they generate
SREF = Letter("Sref", "n", "n", "S")
#: an orthogonal projector of ℝⁿ (D = Dᵀ = D²): the eigenspace of an eigenvalue of A in the claims that build A
#: from it (A = αD + (I − D)B(I − D))
DN = Letter("Dn", "n", "n", "D_n")
#: a generic constant n×r matrix W and a symmetric K of ℝⁿ with KW = 0 (so WᵀK = 0): det(WᵀW) times the
#: projector onto ker Wᵀ in the claims that build A = αI + βWWᵀ from W (the eigenspace ker Wᵀ of α)
WK, WKt = letter_pair("Wk", "Wkt", "n", "r", "W", "W^{T}")
KW = Letter("Kw", "n", "n", "K_W")

#: the name of the hypothesis E₁E₁ᵀ + … + E_rE_rᵀ − I_r (true at that r only), by r
COMPLETE = {1: "E1E1t", 2: "E1E1t+E2E2t"}


def column_hypotheses() -> dict[str, Hypothesis]:
    """E_iᵀE_j − δ_ij (1×1), E₁E₁ᵀ − I_r and E₁E₁ᵀ + E₂E₂ᵀ − I_r (r×r), by name."""
    w = NCPoly.word
    out = {}
    for i, (Ei, Eit) in enumerate(zip(COLUMNS, COVECTORS), start=1):
        for j, Ej in enumerate(COLUMNS, start=1):
            poly = w((Eit, Ej)) - (NCPoly.identity(SCALAR) if i == j else NCPoly.zero(SCALAR, SCALAR))
            out[f"E{i}tE{j}"] = Hypothesis(f"E{i}tE{j}", poly)
    out["ErtEr"] = Hypothesis("ErtEr", w((ERt, ER)) - NCPoly.identity(SCALAR))
    out["EleadtElead"] = Hypothesis("EleadtElead", w((LEADt, LEAD)) - NCPoly.identity(LEADING))
    out["EleadtEr"] = Hypothesis("EleadtEr", w((LEADt, ER)))
    out["ErtElead"] = Hypothesis("ErtElead", w((ERt, LEAD)))
    out["SrefSref"] = Hypothesis("SrefSref", w((SREF, SREF)) - NCPoly.identity("n"))
    out["DnDn"] = Hypothesis("DnDn", w((DN, DN)) - w((DN,)))
    out["KwWk"] = Hypothesis("KwWk", w((KW, WK)))
    out["WktKw"] = Hypothesis("WktKw", w((WKt, KW)))
    for a in SPLIT:
        for b in SPLIT:
            out[f"{a}{b}"] = Hypothesis(f"{a}{b}", w((a, b)) - (w((a,)) if a == b else NCPoly.zero("r", "r")))
    out["EleadEleadt+ErErt"] = Hypothesis("EleadEleadt+ErErt", w((LEAD, LEADt)) + w((ER, ERt)) - NCPoly.identity("r"))
    for r, name in COMPLETE.items():
        poly = NCPoly.zero("r", "r")
        for E, Et in zip(COLUMNS[:r], COVECTORS[:r]):
            poly = poly + w((E, Et))
        out[name] = Hypothesis(name, poly - NCPoly.identity("r"))
    return out


#: E₁E₁ᵀ + … + E_rE_rᵀ − I_r by r, built once (the hypothesis every resolution of a place in ℝʳ uses)
_COMPLETE_HYPS: dict[int, Hypothesis] = {}


def _complete(r: int) -> Hypothesis:
    h = _COMPLETE_HYPS.get(r)
    if h is None:
        h = _COMPLETE_HYPS[r] = column_hypotheses()[COMPLETE[r]]
    return h


def _open_at(w: tuple, k: int, row: str) -> bool:
    """Whether place k of the word w (before w[k]) is in ℝʳ with no column next to it."""
    t = w[k].row if k < len(w) else (w[-1].col if w else row)
    if t != "r":
        return False
    return not ((k > 0 and w[k - 1] in COVECTORS) or (k < len(w) and w[k] in COLUMNS))


def _open_in_cycle(c: tuple) -> int | None:
    """A place of the cyclic word c in ℝʳ with no column next to it, or None."""
    for k in range(len(c)):
        if c[k].row == "r" and not (c[k - 1] in COVECTORS or c[k] in COLUMNS):
            return k
    return None


def _resolve(p: NCPoly, hyp: Hypothesis, cert: list[CertTerm], r: int) -> list[tuple[Any, tuple, tuple]]:
    """The terms (c, traces, word) of p with every open place resolved in the basis E_1, …, E_r;
    ``cert`` gets p − result."""
    basis = list(zip(COLUMNS[:r], COVECTORS[:r]))
    todo = [(c, tm, w) for (tm, w), c in p.terms.items()]
    done = []
    while todo:
        c, tm, w = todo.pop()
        k = next((k for k in range(len(w) + 1) if _open_at(w, k, p.row)), None)
        if k is not None:   # c·T·w = Σ_i c·T·w[:k]E_iE_iᵀw[k:] − c·T·w[:k]·h·w[k:]
            cert.append(CertTerm(-c, w[:k], hyp, w[k:], False, tm, ()))
            todo.extend((c, tm, w[:k] + (E, Et) + w[k:]) for E, Et in basis)
            continue
        j = next((j for j, cyc in enumerate(tm) if _open_in_cycle(cyc) is not None), None)
        if j is not None:   # tr(cyc) = tr(rot) = Σ_i tr(E_iE_iᵀ rot) − tr(h·rot)
            cyc = tm[j]
            k = _open_in_cycle(cyc)
            rot = cyc[k:] + cyc[:k]
            rest = tm[:j] + tm[j + 1:]
            cert.append(CertTerm(-c, (), hyp, rot, True, rest, w))
            todo.extend((c, merge_traces(rest, ((E, Et) + rot,)), w) for E, Et in basis)
            continue
        done.append((c, tm, w))
    return done


def _scalar_places(w: tuple, cyclic: bool) -> list[int]:
    places = [k for k in range(len(w)) if w[k].row == SCALAR]
    if not cyclic and w and w[-1].col == SCALAR:
        places.append(len(w))
    return places


#: the extractions of single terms, (traces, word) -> (the term, (sign, traces, word)) (letters by identity,
#: as in _TERMS): the extraction only cuts words and multiplies the coefficient by ±1 or 0
_EXTRACTS: dict = {}


def _extract(c: Any, tm: tuple, w: tuple) -> tuple[Any, tuple, tuple]:
    """c·T·w with every 1×1 piece of w and of the traces made a trace of its own (c = 0: it vanishes)."""
    hit = _EXTRACTS.get((tm, w))
    if hit is None or not all(a is b for a, b in zip(_letters_of(hit[0]), _letters_of((tm, w)))):
        if len(_EXTRACTS) >= _TERMS_MAX:
            _EXTRACTS.clear()
        hit = _EXTRACTS[(tm, w)] = ((tm, w), _extracted(tm, w))
    s, out, rest = hit[1]
    return (se.Integer(0), (), rest) if s == 0 else (c if s == 1 else -c, out, rest)


def _extracted(tm: tuple, w: tuple) -> tuple[int, tuple, tuple]:
    """(s, traces, word) of :func:`_extract` for the coefficient 1."""
    pieces: list[tuple] = []
    ks = _scalar_places(w, False)
    if len(ks) > 1:
        pieces += [w[a:b] for a, b in zip(ks, ks[1:])]
        w = w[:ks[0]] + w[ks[-1]:]
    for cyc in tm:
        ks = _scalar_places(cyc, True)
        if len(ks) > 1:
            rot = cyc[ks[0]:] + cyc[:ks[0]]
            ks = [k - ks[0] for k in ks] + [len(cyc)]
            pieces += [rot[a:b] for a, b in zip(ks, ks[1:])]
        else:
            pieces.append(cyc)
    out: tuple = ()
    sign = 1
    for piece in pieces:
        s, rep = cycle_rep(piece)
        if s == 0:
            return 0, (), w
        sign *= s
        out = merge_traces(out, (rep,))
    return sign, out, w


#: canonical forms of single terms, (row, col, r, traces, word) -> (the term, [(sign, key), ...]): a term's
#: form is a sum of ±1 times terms, the same whatever its coefficient (resolving and extracting only
#: expand and multiply by ±1); letters compare by name, so a hit counts only for the very same letters
_TERMS: dict = {}
_TERMS_MAX = 50_000


def _letters_of(key: tuple) -> list:
    tm, w = key
    return [L for c in tm for L in c] + list(w)


def _term_form(row: str, col: str, r: int, tm: tuple, w: tuple) -> list[tuple[int, tuple]]:
    memo_key = (row, col, r, tm, w)
    hit = _TERMS.get(memo_key)
    if hit is not None and all(a is b for a, b in zip(_letters_of(hit[0]), _letters_of((tm, w)))):
        return hit[1]
    one = se.Integer(1)
    terms = _resolve(NCPoly({(tm, w): one}, row, col), _complete(r), [], r) if r else \
        [(one, tm, w)]
    form: list[tuple[int, tuple]] = []
    for c, tm2, w2 in terms:
        c, tm2, w2 = _extract(c, tm2, w2)
        if c != 0:
            form.append((int(c), (tm2, w2)))
    if len(_TERMS) >= _TERMS_MAX:
        _TERMS.clear()
    _TERMS[memo_key] = ((tm, w), form)
    return form


def canonical_form(p: NCPoly, r: int) -> NCPoly:
    """The canonical form of :func:`canonical` without its certificate, term by term (remembered)."""
    out: dict = {}
    items = list(p.terms.items())
    # the order of canonical()'s terms: its resolution is a stack (the last term first, each term's
    # expansion in full before the next), and its extraction keeps that order
    for (tm, w), c in (reversed(items) if r else items):
        for s, key in _term_form(p.row, p.col, r, tm, w):
            out[key] = out[key] + c * s if key in out else c * s
    return NCPoly(out, p.row, p.col)


def canonical(p: NCPoly, r: int) -> tuple[NCPoly, list[CertTerm]]:
    """(q, terms): q the canonical form of p at r = 1 or 2 (every place in ℝʳ resolved, every 1×1 piece
    a trace; r = 0: only the latter), and p − q = Σ terms up to the identity "a 1×1 matrix is its own trace"."""
    cert: list[CertTerm] = []
    out: dict = {}
    terms = _resolve(p, _complete(r), cert, r) if r else \
        [(c, tm, w) for (tm, w), c in p.terms.items()]   # r = 0: only the 1×1 pieces (the last column)
    for c, tm, w in terms:
        c, tm, w = _extract(c, tm, w)
        if c == 0:
            continue
        key = (tm, w)
        out[key] = out[key] + c if key in out else c
    return NCPoly(out, p.row, p.col), cert
