"""Rewriting systems on typed words: normal forms, critical pairs, completion.

A :class:`Rule` replaces a word (its left-hand side) by a polynomial of the
same type whose words are all smaller in a deg-lex :class:`Order`; the order is
a well-order, so repeated reduction terminates.  Every rule carries the reason
it is valid on T*V (a constraint, a resolvent identity, or the critical pair
it completes).  If every critical pair resolves (:func:`critical_pairs`), the
system is confluent and normal forms are unique (Bergman's diamond lemma): a
residual whose normal form is 0 holds, and one whose normal form is not 0 is
not a consequence of the rules.

Traces are reduced as cyclic words: a rule applies in any rotation, and
tr(w*) = tr(w).  Confluence of that reduction needs, on top of the word
critical pairs, the *cyclic* critical pairs (two left-hand sides that cover a
cyclic word and overlap at both ends), which :func:`critical_pairs` also lists.

Certificates.  A rule may carry its *cofactors*: lhs − rhs written as
Σ c·u·h·v over named :class:`Hypothesis` generators h (XᵀX − I_r, …), checked
when the rule is added.  :meth:`RewritingSystem.certify` traces a reduction
step by step and returns p − nf(p) as Σ c·T·a·h·b (and Σ c·T·tr(a·h·b)·w for
steps inside traces, T a product of traces): when nf(p) = 0 this is a cofactor
representation of p in the two-sided ideal of the hypotheses, which
:mod:`stiefelsym.certificate_check` re-expands without any rewriting.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Sequence

import symengine as se

from stiefelsym.free.algebra import (DIMENSIONS, SCALAR, Coef, Letter, NCPoly, Word, check_word, cprod, csum, cycle_rep,
                      memo_put, merge_traces, min_rotation, operator_letters_in, record_refusal, star_word, trace,
                      word_key, word_latex, word_str)


class RewritingError(ValueError):
    """A rule that does not decrease, is ill-typed, or a reduction that does not terminate."""


#: the class of symengine's zero (a singleton): ``type(c) is ZERO_TYPE`` is the cheap zero test of
#: a coefficient that :func:`simplify_coef` returned
_ZERO = se.Integer(0)
ZERO_TYPE = type(_ZERO)
_NUMBER_TYPES = frozenset(type(x) for x in (se.Integer(0), se.Integer(1), se.Integer(-1), se.Integer(2),
                                             se.Rational(1, 2)))
#: simplify_coef is a pure function of its (hashable, structurally compared) argument
_SIMPLIFIED: dict = {}
_SIMPLIFIED_MAX = 50_000


def simplify_coef(c: Coef) -> Coef:
    """Expanded coefficient; rational coefficients are zero iff their expanded numerator is.

    Zero comes back as symengine's zero (``type(c) is ZERO_TYPE``).  Memoized."""
    if type(c) in _NUMBER_TYPES:
        return c
    try:
        return _SIMPLIFIED[c]
    except KeyError:
        pass
    except TypeError:              # not hashable: no memo
        return _simplify(c)
    e = _simplify(c)
    if len(_SIMPLIFIED) >= _SIMPLIFIED_MAX:
        _SIMPLIFIED.clear()
        _SIMPLE.clear()
    _SIMPLIFIED[c] = e
    if type(e) is not ZERO_TYPE:
        _SIMPLE.add(e)   # simplify_coef is idempotent: e simplifies to itself
    return e


#: nonzero coefficients that simplify_coef returns unchanged (its nonzero values)
_SIMPLE: set = set()
_NONZERO_NUMBER_TYPES = frozenset(_NUMBER_TYPES - {ZERO_TYPE})


def is_simplified(c: Coef) -> bool:
    """Whether simplify_coef(c) is c (a nonzero number, or a nonzero value simplify_coef returned)."""
    if type(c) in _NONZERO_NUMBER_TYPES:
        return True
    try:
        return c in _SIMPLE
    except TypeError:
        return False


def _simplify(c: Coef) -> Coef:
    if getattr(c, "is_Number", False):
        return _ZERO if c == 0 else c
    e = se.expand(c)
    if e == 0:
        return _ZERO
    if e.is_Number:
        return e
    if isinstance(e, se.Add):
        e = se.expand(e)   # symengine may leave a sum of numbers (1 - 1) after one pass
        if e == 0:
            return _ZERO
        if e.is_Number:
            return e
    num, den = e.as_numer_denom()
    if den.is_Number:
        return e
    num = se.expand(num)
    return _ZERO if num == 0 else e


def nonzero_terms(terms: dict) -> dict:
    """The terms with simplified coefficients, zero coefficients dropped (a new dict)."""
    out = {}
    for k, c in terms.items():
        t = type(c)
        if t in _NUMBER_TYPES:
            if t is not ZERO_TYPE:
                out[k] = c
            continue
        c = simplify_coef(c)
        if type(c) is not ZERO_TYPE:
            out[k] = c
    return out


#: entries of a system's memo of polynomials (reduce, certify) before it is emptied: they hold whole
#: polynomials (an eager scene reduces every intermediate one), so few
POLY_MEMO_MAX = 4096
#: the trace factors of a term without traces, as a normal form (read only)
_NO_TRACES = {(): se.Integer(1)}


class Order:
    """Deg-lex order on words: longer is larger, equal lengths compare letter ranks left to right.

    Letters not listed rank after the listed ones, in the order they are first met."""

    def __init__(self, letters: Iterable[str] = ()) -> None:
        self._rank: dict[str, int] = {}
        for L in letters:
            self.add(L)

    def add(self, letter: str) -> int:
        if letter not in self._rank:
            self._rank[letter] = len(self._rank)
        return self._rank[letter]

    def add_last(self, letter: str) -> int:
        """Rank ``letter`` after every letter listed now or later (a letter that commutes with others
        by rules L·x → x·L, whichever x comes later)."""
        if letter not in self._rank:
            self._rank[letter] = (1 << 30) + len(self._rank)
        return self._rank[letter]

    def key(self, w: Word) -> tuple:
        rank = self._rank
        return (len(w), tuple(rank[L] if L in rank else self.add(L) for L in w))

    def less(self, u: Word, v: Word) -> bool:
        return self.key(u) < self.key(v)

    @property
    def letters(self) -> list[str]:
        return sorted(self._rank, key=self._rank.get)

    def copy(self) -> "Order":
        return Order(self.letters)


@dataclass(frozen=True)
class Hypothesis:
    """A named generator h of the ideal of relations (a polynomial that vanishes on T*V).

    The name is what a certificate records; the independent checker rebuilds
    h from its own table of names, never from this polynomial."""

    name: str
    poly: NCPoly = field(compare=False)

    def __str__(self) -> str:
        return f"{self.name}: {self.poly}"


@dataclass(frozen=True)
class Cofactor:
    """coef · left · h · right (a term of a rule's cofactor expansion)."""

    coef: Coef
    left: Word
    hyp: Hypothesis
    right: Word

    def value(self) -> NCPoly:
        h = self.hyp.poly
        return NCPoly.word(self.left, h.row) * h * NCPoly.word(self.right, h.col) * self.coef


def cofactor_sum(cofactors: Iterable[Cofactor], row: str, col: str) -> NCPoly:
    out = NCPoly.zero(row, col)
    for cf in cofactors:
        out = out + cf.value()
    return out


@dataclass(frozen=True)
class Rule:
    """lhs → rhs, valid because of ``reason``; ``cofactors`` write lhs − rhs through the
    hypotheses (None: not known, and reductions using the rule cannot be certified)."""

    name: str
    lhs: Word
    rhs: NCPoly
    reason: str
    cofactors: tuple | None = field(default=None, compare=False)

    def latex(self) -> str:
        return rf"{word_latex(self.lhs)} \to {self.rhs.latex()}"

    def __str__(self) -> str:
        text = self.__dict__.get("_text")   # (a function of the rule's fields, which are frozen)
        if text is None:
            text = f"{self.name}: {word_str(self.lhs)} -> {self.rhs}   [{self.reason}]"
            object.__setattr__(self, "_text", text)
        return text


@dataclass
class Reduction:
    """A residual, its normal form and the rules used to get there."""

    residual: NCPoly
    normal_form: NCPoly
    rules: list[Rule]

    @property
    def is_zero(self) -> bool:
        return not self.normal_form.terms

    def latex(self) -> str:
        """A short derivation: the residual, the rules applied (with reasons), the normal form
        (memoized: a function of the polynomials' terms and the rules, which the key holds)."""
        try:
            key = (self.residual.row, self.residual.col, tuple(self.residual.terms.items()),
                   tuple(self.normal_form.terms.items()),
                   tuple((r.name, r.lhs, r.reason, tuple(r.rhs.terms.items())) for r in self.rules))
            hit = _REDUCTION_LATEX.get(key)
        except TypeError:   # an unhashable coefficient: no memo
            key = hit = None
        if hit is not None:
            return hit
        text = self._latex()
        if key is not None:
            memo_put(_REDUCTION_LATEX, key, text, 10_000)
        return text

    def _latex(self) -> str:
        lines = [r"\begin{aligned}", "R &= " + _rows(self.residual.latex_terms()) + r" \\"]
        lines.append(rf"\operatorname{{nf}}(R) &= {self.normal_form.latex()}")
        lines.append(r"\end{aligned}")
        body = "\n".join(lines)
        if not self.rules:
            return rf"\[{body}\]" + "\nNo rule was needed."
        items = "\n".join(rf"  \item ${r.latex()}$ ({latex_text(r.reason)})" for r in self.rules)
        return rf"\[{body}\]" + "\nusing\n\\begin{itemize}\n" + items + "\n\\end{itemize}"


_REDUCTION_LATEX: dict = {}

#: characters of LaTeX per row of a long residual in a derivation (a display row of about the page's width)
ROW_CHARS = 160


def _rows(terms: list[str]) -> str:
    """The signed terms of a sum as the rows of an aligned display (each row about ROW_CHARS of LaTeX; the
    report shrinks a display still wider than the page)."""
    rows, row = [], ""
    for t in terms:
        if row and len(row) + len(t) > ROW_CHARS:
            rows.append(row)
            row = t
        else:
            row = f"{row} {t}" if row else t
    rows.append(row)
    return " \\\\\n  &\\quad ".join(rows)


def latex_text(s: str) -> str:
    """Plain text (a rule's reason) in LaTeX text mode, its ASCII scripts set as scripts (memoized)."""
    hit = _LATEX_TEXT.get(s)
    if hit is None:
        hit = memo_put(_LATEX_TEXT, s, _latex_text(s), 10_000)
    return hit


_LATEX_TEXT: dict = {}


def _latex_text(s: str) -> str:
    # ASCII scripts as scripts (X^T, I_r), everything else escaped (cond_XP stays as it is written)
    from stiefelsym.latex import tex_words
    return tex_words(s)


class SharedMemos:
    """The memos of every rewriting system with one rule set (the standard rules of (cond_XP)):
    normal forms and certificates of words and traces are functions of the rules alone, so the
    scenes of a process share them until one adds a rule.  What a system reports about its own
    reductions (the rules they used, their trace fallbacks) stays its own."""

    LIMIT = 200_000

    def __init__(self) -> None:
        self.word: dict = {}
        self.cycle: dict = {}
        self.trace: dict = {}
        self.cert: tuple[dict, dict, dict] = ({}, {}, {})
        #: normal forms of polynomials, by identity: id -> (polynomial, normal form, rules used), and
        #: certificates of polynomials without traces: ("cert", id) -> (polynomial, terms)
        self.poly: dict = {}
        #: the meaning (index spaces, adjoint) of each letter name the memos may hold
        self.letters: dict[str, tuple] = {}

    def _memos(self) -> tuple[dict, ...]:
        return (self.word, self.cycle, self.trace, self.poly) + self.cert

    def bound(self) -> None:
        """Empty the memos when they outgrow LIMIT entries (between two systems' uses)."""
        if sum(len(m) for m in self._memos()) > self.LIMIT:
            for m in self._memos():
                m.clear()

    def admit(self, letter: Letter) -> None:
        """A scene's letter enters the memos' words.  Words are keyed by their letters' names, so
        a name must keep one meaning while the memos hold it: two claims' s.fresh(...) number i
        (gen:fresh:i) or s.generic("G", ...) of other index spaces are other letters under one
        name, and a normal form memoized for one (its letters, their types) is not the other's.
        A name met with another meaning empties the memos."""
        adj = getattr(letter, "adjoint", letter)
        meaning = (getattr(letter, "row", None), getattr(letter, "col", None),
                   getattr(letter, "adjoint_sign", 1), str(adj), getattr(adj, "row", None), getattr(adj, "col", None))
        known = self.letters.get(str(letter))
        if known == meaning:
            return
        if known is not None:
            for m in self._memos():
                m.clear()
            self.letters.clear()
        self.letters[str(letter)] = meaning


class RewritingSystem:
    """Rules on typed words with a deg-lex order; memoized normal forms of words and traces."""

    #: a reduction chain longer than this is reported as non-terminating
    max_depth = 500

    def __init__(self, order: Order | None = None, rules: Iterable[Rule] = (),
                 shared: "SharedMemos | None" = None) -> None:
        """``shared``: the memos of every system with exactly these rules (see :class:`SharedMemos`),
        used until a rule is added."""
        self.order = order if order is not None else Order()
        self.rules: list[Rule] = []
        self._lhs: dict[Word, Rule] = {}
        self._lengths: list[int] = []
        #: irreducible cyclic words whose adjoint did not reduce to ± one cyclic word
        self.trace_fallbacks: set[Word] = set()
        self._fallback_events = 0
        for r in rules:
            self._insert(r, clear=False)
        self._clear()
        if shared is not None:
            shared.bound()
            self._word_memo, self._cycle_memo, self._trace_memo = shared.word, shared.cycle, shared.trace
            self._poly_memo = shared.poly
            self._cert_memos = shared.cert
            self._applied = set()

    def _clear(self) -> None:
        self._word_memo: dict[Word, tuple[dict, frozenset]] = {}
        self._cycle_memo: dict[Word, tuple[dict, frozenset]] = {}
        self._trace_memo: dict[Word, tuple[dict, frozenset]] = {}
        self._poly_memo: dict[int, tuple] = {}
        #: certificates of words, cyclic reductions and trace normal forms (see certify)
        self._cert_memos: tuple[dict, dict, dict] = ({}, {}, {})
        #: the rule names this system's reductions used, while its memos are shared (the memos then
        #: hold other systems' reductions too); None: the memos are its own, and say it
        self._applied: set[str] | None = None

    def _track(self, used: Iterable[str]) -> None:
        if self._applied is not None:
            self._applied.update(used)

    def copy(self) -> "RewritingSystem":
        return RewritingSystem(self.order.copy(), self.rules)

    # -- rules ------------------------------------------------------------
    def add_rule(self, lhs: Sequence[Letter], rhs: NCPoly, reason: str, name: str | None = None,
                 cofactors: Iterable[Cofactor] | None = None) -> Rule:
        """Add lhs → rhs after checking types, that every word of rhs is smaller than lhs and
        that the cofactors (if given) sum to lhs − rhs exactly."""
        lhs = tuple(lhs)
        if not lhs:
            raise RewritingError("a rule needs a nonempty left-hand side")
        check_word(lhs)
        if (rhs.row, rhs.col) != (lhs[0].row, lhs[-1].col):
            raise RewritingError(f"rule {word_str(lhs)}: rhs is {rhs.row}×{rhs.col}, "
                                 f"lhs is {lhs[0].row}×{lhs[-1].col}")
        rhs = rhs.expand()
        for (tm, w), _c in rhs.terms.items():
            if tm:
                raise RewritingError(f"rule {word_str(lhs)}: traces are not allowed on the right-hand side")
            if not self.order.less(w, lhs):
                raise RewritingError(f"rule {word_str(lhs)} -> {rhs} does not decrease: "
                                     f"{word_str(w)} is not smaller than {word_str(lhs)}")
        if lhs in self._lhs:
            raise RewritingError(f"a rule for {word_str(lhs)} exists already")
        if cofactors is not None:
            cofactors = tuple(cofactors)
            gap = NCPoly.word(lhs) - rhs - cofactor_sum(cofactors, rhs.row, rhs.col)
            if any(simplify_coef(c) != 0 for c in gap.terms.values()):
                raise RewritingError(f"rule {word_str(lhs)}: the cofactors do not sum to lhs - rhs "
                                     f"(they miss {gap.expand()})")
        rule = Rule(name or word_str(lhs), lhs, rhs, reason, cofactors)
        self._insert(rule)
        return rule

    def _insert(self, rule: Rule, clear: bool = True) -> None:
        self.rules.append(rule)
        self._lhs[rule.lhs] = rule
        if len(rule.lhs) not in self._lengths:
            self._lengths = sorted(self._lengths + [len(rule.lhs)])
        for L in rule.lhs:
            self.order.add(L)
        if clear:
            self._clear()

    def rule(self, name: str) -> Rule:
        for r in self.rules:
            if r.name == name:
                return r
        raise KeyError(name)

    def decreasing(self, rule: Rule) -> bool:
        """Every word of the rule's rhs is smaller than its lhs."""
        return all(self.order.less(w, rule.lhs) for (_, w) in rule.rhs.terms)

    def find(self, w: Word) -> tuple[int, Rule] | None:
        """The leftmost occurrence of a left-hand side in w."""
        lhs = self._lhs
        for i in range(len(w)):
            for L in self._lengths:
                if i + L > len(w):
                    break
                r = lhs.get(w[i:i + L])
                if r is not None:
                    return i, r
        return None

    # -- words --------------------------------------------------------------
    def _word_nf(self, w: Word, depth: int = 0) -> tuple[dict, frozenset]:
        hit = self._word_memo.get(w)
        if hit is not None:
            return hit
        if depth > self.max_depth:
            what = f"reduction of {word_str(w)} does not terminate"
            record_refusal(what)   # a claim that catches it must not go on to a proof
            raise RewritingError(what)
        found = self.find(w)
        if found is None:
            res = ({w: se.Integer(1)}, frozenset())
        else:
            i, rule = found
            out: dict = {}
            used = {rule.name}
            pre, post = w[:i], w[i + len(rule.lhs):]
            for (_, rw), c in rule.rhs.terms.items():
                sub, u = self._word_nf(pre + rw + post, depth + 1)
                used |= u
                for k, v in sub.items():
                    out[k] = out[k] + c * v if k in out else c * v
            res = (nonzero_terms(out),
                   frozenset(used))
        self._word_memo[w] = res
        return res

    # -- traces ---------------------------------------------------------------
    def _cycle_reduce(self, c: Word, depth: int = 0) -> tuple[dict, frozenset]:
        """tr(c) reduced by the rules in every rotation: {least rotation or (): coefficient}."""
        hit = self._cycle_memo.get(c)
        if hit is not None:
            return hit
        if depth > self.max_depth:
            what = f"cyclic reduction of tr({word_str(c)}) does not terminate"
            record_refusal(what)
            raise RewritingError(what)
        res = None
        for k in range(len(c)):
            rot = c[k:] + c[:k]
            found = self.find(rot)
            if found is None:
                continue
            i, rule = found
            out: dict = {}
            used = {rule.name}
            for (_, rw), coef in rule.rhs.terms.items():
                nw = rot[:i] + rw + rot[i + len(rule.lhs):]
                if not nw:
                    key = ()
                    out[key] = out.get(key, 0) + coef * DIMENSIONS[rot[0].row]
                    continue
                sub, u = self._cycle_reduce(min_rotation(nw), depth + 1)
                used |= u
                for kk, v in sub.items():
                    out[kk] = out[kk] + coef * v if kk in out else coef * v
            res = (nonzero_terms(out),
                   frozenset(used))
            break
        if res is None:
            res = ({c: se.Integer(1)}, frozenset())
        self._cycle_memo[c] = res
        return res

    def _trace_nf(self, c: Word) -> tuple[dict, frozenset]:
        """Normal form of tr(c): cyclic reduction, then one representative per pair {c, c*}."""
        c = min_rotation(c)
        hit = self._trace_memo.get(c)
        if hit is not None:
            return hit
        events = self._fallback_events
        red, used = self._cycle_reduce(c)
        out: dict = {}
        for k, v in red.items():
            if k == ():
                out[()] = out.get((), 0) + v
                continue
            rep, s, u = self._adjoint_rep(k)
            used = used | u
            if rep is not None and operator_letters_in(rep):
                # the symmetry of an operator on so(n): a normal form of the pair of its traces (no rule)
                s2, rep = cycle_rep(rep)
                s = s * s2
                if s2 == 0:
                    rep = None
            if rep is not None:
                out[rep] = out[rep] + v * s if rep in out else v * s
        res = (nonzero_terms(out), used)
        if self._applied is None or self._fallback_events == events:
            # a shared memo never holds a trace whose reduction met a fallback: every system that
            # meets it must record it (trace_fallbacks)
            self._trace_memo[c] = res
        return res

    def _adjoint_rep(self, c: Word) -> tuple[Word | None, Coef, frozenset]:
        """For an irreducible cyclic word c: tr(c) = s·tr(rep); rep None means tr(c) = 0."""
        sign, ws = star_word(c)
        d, used = self._cycle_reduce(min_rotation(ws))
        if len(d) == 1:
            (k, v), = d.items()
            v = v * sign
            if k == c:
                if v == 1:
                    return c, se.Integer(1), used
                if v == -1:
                    return None, se.Integer(0), used
            elif k != () and (v == 1 or v == -1):
                return (c, se.Integer(1), used) if word_key(c) < word_key(k) else (k, v, used)
        self.trace_fallbacks.add(c)
        self._fallback_events += 1
        return c, se.Integer(1), used

    def _traces_nf(self, tm: tuple) -> tuple[dict, frozenset]:
        out: dict = {(): se.Integer(1)}
        used: frozenset = frozenset()
        for c in tm:
            red, u = self._trace_nf(c)
            used |= u
            nxt: dict = {}
            for k1, v1 in out.items():
                for k2, v2 in red.items():
                    k = merge_traces(k1, (k2,) if k2 != () else ())
                    nxt[k] = nxt[k] + v1 * v2 if k in nxt else v1 * v2
            out = nxt
        return out, used

    # -- polynomials ------------------------------------------------------------
    def rules_applied(self) -> list[Rule]:
        """Every rule used by some reduction so far (in rule order): the rules a whole
        computation relied on, including the normalizations made while building it."""
        if self._applied is not None:
            names: set[str] = self._applied
        else:
            names = set()
            for memo in (self._word_memo, self._cycle_memo, self._trace_memo):
                for _value, used in memo.values():
                    names |= set(used)
        return [r for r in self.rules if r.name in names]

    def reduce(self, p: NCPoly) -> Reduction:
        """Normal form of p with the rules used (memoized by the polynomial, which is immutable and
        which the memo holds, so that its id is not reused: like the memos of words and traces, a
        function of the rules; a reduction that met a trace fallback is not kept in a shared memo)."""
        hit = self._poly_memo.get(id(p))
        if hit is not None and hit[0] is p:
            self._track(hit[2])
            return Reduction(p, hit[1], [r for r in self.rules if r.name in hit[2]])
        events = self._fallback_events
        out: dict = {}
        used: set[str] = set()
        for (tm, w), c in p.terms.items():
            wn, u = self._word_nf(w)
            used |= u
            if tm:
                tn, u2 = self._traces_nf(tm)
                used |= u2
            else:
                tn = _NO_TRACES
            for w2, c2 in wn.items():
                for t2, c3 in tn.items():
                    k = (t2, w2)
                    v = cprod(cprod(c, c2), c3)   # c·c2·c3, memoized
                    out[k] = csum(out[k], v) if k in out else v
        terms = nonzero_terms(out)
        self._track(used)
        rules = [r for r in self.rules if r.name in used]
        nf = NCPoly(terms, p.row, p.col)
        if self._applied is None or self._fallback_events == events:
            if len(self._poly_memo) >= POLY_MEMO_MAX:
                self._poly_memo.clear()
            self._poly_memo[id(p)] = (p, nf, frozenset(used))
        return Reduction(p, nf, rules)

    def normal_form(self, p: NCPoly) -> NCPoly:
        return self.reduce(p).normal_form

    def is_zero(self, p: NCPoly) -> bool:
        return not self.normal_form(p).terms

    def trace_normal_form(self, w: Sequence[Letter]) -> NCPoly:
        """Normal form of tr(w) as a scalar polynomial."""
        w = tuple(w)
        check_word(w)
        if w[0].row != w[-1].col:
            raise TypeError(f"tr({word_str(w)}) is not defined: the word is not square")
        red, used = self._trace_nf(w)
        self._track(used)
        return NCPoly({((k,) if k != () else (), ()): v for k, v in red.items()}, SCALAR, SCALAR)


    # -- certificates -----------------------------------------------------------
    # Each helper mirrors a normal-form helper above step for step (same rule, same
    # occurrence, same rotation), and returns what that reduction subtracted, as a
    # dict {(pre, rule name, post): coefficient}: w − nf(w) = Σ c·pre·(l − r)·post for
    # words, tr(c) − nf(tr c) = Σ c·tr(pre·(l − r)·post) for traces.
    def _word_cert(self, w: Word) -> dict:
        memo = self._cert_memos[0]
        hit = memo.get(w)
        if hit is not None:
            return hit
        found = self.find(w)
        out: dict = {}
        if found is not None:
            i, rule = found
            pre, post = w[:i], w[i + len(rule.lhs):]
            out[(pre, rule.name, post)] = se.Integer(1)
            for (_, rw), c in rule.rhs.terms.items():
                _add_scaled(out, self._word_cert(pre + rw + post), c)
        memo[w] = out
        return out

    def _cycle_cert(self, c: Word) -> dict:
        memo = self._cert_memos[1]
        hit = memo.get(c)
        if hit is not None:
            return hit
        out: dict = {}
        for k in range(len(c)):
            rot = c[k:] + c[:k]
            found = self.find(rot)
            if found is None:
                continue
            i, rule = found
            pre, post = rot[:i], rot[i + len(rule.lhs):]
            out[(pre, rule.name, post)] = se.Integer(1)
            for (_, rw), coef in rule.rhs.terms.items():
                nw = pre + rw + post
                if nw:
                    _add_scaled(out, self._cycle_cert(min_rotation(nw)), coef)
            break
        memo[c] = out
        return out

    def _adjoint_cert(self, c: Word) -> dict:
        """What :meth:`_adjoint_rep` replaced: tr(c) = sign·tr(c*-word) structurally, and the
        cyclic reduction of c* certifies tr(c) − (its replacement)."""
        sign, ws = star_word(c)
        d, used = self._cycle_reduce(min_rotation(ws))
        self._track(used)
        if len(d) == 1:
            (k, v), = d.items()
            v = v * sign
            scale = None
            if k == c:
                if v == -1:     # tr(c) = −tr(c) + sign·C, so tr(c) = (sign/2)·C
                    scale = se.Integer(sign) / 2
            elif k != () and (v == 1 or v == -1) and not word_key(c) < word_key(k):
                scale = se.Integer(sign)   # tr(c) − v·tr(k) = sign·C
            if scale is not None:
                out: dict = {}
                _add_scaled(out, self._cycle_cert(min_rotation(ws)), scale)
                return out
        return {}

    def _trace_cert(self, c: Word) -> dict:
        c = min_rotation(c)
        memo = self._cert_memos[2]
        hit = memo.get(c)
        if hit is not None:
            return hit
        red, used = self._cycle_reduce(c)
        self._track(used)
        out: dict = {}
        _add_scaled(out, self._cycle_cert(c), se.Integer(1))
        for k, v in red.items():
            if k != ():
                _add_scaled(out, self._adjoint_cert(k), v)
        memo[c] = out
        return out

    def _traces_cert(self, tm: tuple) -> dict:
        """Π tr(c_i) − Π nf(tr c_i) = Σ_i (Π_{j<i} nf(tr c_j)) (tr c_i − nf(tr c_i)) Π_{j>i} tr(c_j):
        {(trace factors, pre, rule name, post): coefficient}."""
        out: dict = {}
        prefix: dict = {(): se.Integer(1)}
        for i, c in enumerate(tm):
            cert = self._trace_cert(c)
            for pk, pv in prefix.items():
                factors = merge_traces(pk, tm[i + 1:])
                for (pre, name, post), cv in cert.items():
                    key = (factors, pre, name, post)
                    out[key] = out[key] + pv * cv if key in out else pv * cv
            red, used = self._trace_nf(c)
            self._track(used)
            nxt: dict = {}
            for k1, v1 in prefix.items():
                for k2, v2 in red.items():
                    k = merge_traces(k1, (k2,) if k2 != () else ())
                    nxt[k] = nxt[k] + v1 * v2 if k in nxt else v1 * v2
            prefix = nxt
        return out

    def certify(self, p: NCPoly, normal_form: NCPoly | None = None) -> "Certificate":
        """p − nf(p) as a combination of hypotheses (every rule used must carry cofactors);
        ``normal_form``: nf(p) when the caller has it (from :meth:`reduce` of this system).

        Raises :class:`CertificateError` if a rule used has no cofactor expansion."""
        # without traces, the terms are a function of p and the rules (the certificates of its words,
        # memoized, record nothing): kept with the normal forms, by the polynomial (see reduce)
        plain = all(not tm for tm, _w in p.terms)
        hit = self._poly_memo.get(("cert", id(p))) if plain else None
        if hit is not None and hit[0] is p:
            return Certificate(p, self.normal_form(p) if normal_form is None else normal_form, list(hit[1]))
        steps: dict = {}   # (in_trace, trace factors, word, pre, rule name, post) -> coefficient
        for (tm, w), c in p.terms.items():
            if tm:
                for (factors, pre, name, post), v in self._traces_cert(tm).items():
                    key = (True, factors, w, pre, name, post)
                    steps[key] = steps[key] + c * v if key in steps else c * v
                tn, used = self._traces_nf(tm)
                self._track(used)
            else:
                tn = _NO_TRACES
            wc = self._word_cert(w)
            if wc:
                for t2, c3 in tn.items():
                    for (pre, name, post), v in wc.items():
                        key = (False, t2, (), pre, name, post)
                        x = cprod(cprod(c, c3), v)   # c·c3·v, memoized
                        steps[key] = csum(steps[key], x) if key in steps else x
        rules = {r.name: r for r in self.rules}
        terms: dict = {}
        hyps: dict = {}
        for (in_trace, factors, w, pre, name, post), v in steps.items():
            rule = rules[name]
            if rule.cofactors is None:
                raise CertificateError(f"rule {name} ({rule.reason}) has no cofactor expansion")
            for cf in rule.cofactors:
                hyps[cf.hyp.name] = cf.hyp
                key = (in_trace, factors, w, pre + cf.left, cf.hyp.name, cf.right + post)
                x = cprod(v, cf.coef)
                terms[key] = csum(terms[key], x) if key in terms else x
        out = []
        for (in_trace, factors, w, left, name, right), v in terms.items():
            v = simplify_coef(v)
            if v != 0:
                out.append(CertTerm(v, left, hyps[name], right, in_trace, factors, w))
        if plain:
            if len(self._poly_memo) >= POLY_MEMO_MAX:
                self._poly_memo.clear()
            self._poly_memo[("cert", id(p))] = (p, tuple(out))
        return Certificate(p, self.normal_form(p) if normal_form is None else normal_form, out)


def _add_scaled(out: dict, add: dict, scale: Coef) -> None:
    for k, v in add.items():
        out[k] = out[k] + scale * v if k in out else scale * v


class CertificateError(RewritingError):
    """A reduction that cannot be certified (a rule without cofactors)."""


@dataclass(frozen=True)
class CertTerm:
    """coef · Π tr(traces) · left·h·right, or (``in_trace``) coef · Π tr(traces) · tr(left·h·right) · word."""

    coef: Coef
    left: Word
    hyp: Hypothesis
    right: Word
    in_trace: bool = False
    traces: tuple = ()
    word: Word = ()

    def value(self, row: str, col: str) -> NCPoly:
        """The term as a polynomial of type (row, col) (traces in canonical form)."""
        h = self.hyp.poly
        inner = NCPoly.word(self.left, h.row) * h * NCPoly.word(self.right, h.col)
        factors = NCPoly.scalar(self.coef)
        for t in self.traces:
            sign, rep = cycle_rep(t)
            factors = factors * NCPoly({((rep,), ()): se.Integer(sign)}, SCALAR, SCALAR)
        if not self.in_trace:
            return factors * inner
        return factors * trace(inner) * NCPoly.word(self.word, row)

    def __str__(self) -> str:
        body = f"{word_str(self.left)}·[{self.hyp.name}]·{word_str(self.right)}"
        if self.in_trace:
            body = f"tr({body})" + (f"·{word_str(self.word)}" if self.word else "")
        factors = "".join(f"tr({word_str(t)})·" for t in self.traces)
        return f"({self.coef})·{factors}{body}"


@dataclass
class Certificate:
    """p − normal_form = Σ terms: a cofactor representation of p when the normal form is 0."""

    residual: NCPoly
    normal_form: NCPoly
    terms: list[CertTerm]

    @property
    def proves_zero(self) -> bool:
        return not self.normal_form.terms

    def hypotheses(self) -> list[str]:
        return sorted({t.hyp.name for t in self.terms})

    def value(self) -> NCPoly:
        """Σ terms in the free algebra (a self-check; the independent checker does not use it)."""
        out = NCPoly.zero(self.residual.row, self.residual.col)
        for t in self.terms:
            out = out + t.value(self.residual.row, self.residual.col)
        return out


# ---------------------------------------------------------------------------
# critical pairs and completion
@dataclass
class CriticalPair:
    """Two one-step reductions of ``word`` (a cyclic word for kind 'cyclic')."""

    kind: str  # "overlap", "inclusion" or "cyclic"
    a: Rule
    b: Rule
    word: Word
    left: NCPoly
    right: NCPoly
    difference: NCPoly
    #: where b's left-hand side sits in ``word`` (a's sits at 0)
    offset: int = 0

    @property
    def joinable(self) -> bool:
        return not self.difference.terms

    def __str__(self) -> str:
        w = f"tr({word_str(self.word)})" if self.kind == "cyclic" else word_str(self.word)
        state = "resolves" if self.joinable else f"does NOT resolve: {self.difference}"
        return f"{self.kind} of {self.a.name} and {self.b.name} on {w}: {state}"


def _mono(w: Word, t: str) -> NCPoly:
    return NCPoly.word(w, t)


def _trace_of(system: RewritingSystem, p: NCPoly) -> NCPoly:
    out = NCPoly.zero(SCALAR, SCALAR)
    for (tm, w), c in p.terms.items():
        if w:
            t = system.trace_normal_form(w)
        else:
            t = NCPoly.scalar(DIMENSIONS[p.row])
        if tm:
            t = t * NCPoly({(tm, ()): se.Integer(1)}, SCALAR, SCALAR)
        out = out + t * c
    return system.normal_form(out)


def critical_pairs(system: RewritingSystem, cyclic: bool = True) -> list[CriticalPair]:
    """All critical pairs (overlaps, inclusions and, if ``cyclic``, cyclic overlaps) and whether each resolves."""
    out: list[CriticalPair] = []
    rules = system.rules
    for a in rules:
        la = a.lhs
        for b in rules:
            lb = b.lhs
            for k in range(1, min(len(la), len(lb))):
                if la[-k:] == lb[:k]:
                    left = a.rhs * _mono(lb[k:], la[-1].col)
                    right = _mono(la[:-k], la[0].row) * b.rhs
                    diff = system.normal_form(left - right)
                    out.append(CriticalPair("overlap", a, b, la + lb[k:], left, right, diff, len(la) - k))
            if a is not b and len(lb) <= len(la):
                for i in range(len(la) - len(lb) + 1):
                    if la[i:i + len(lb)] == lb:
                        left = a.rhs
                        right = _mono(la[:i], la[0].row) * b.rhs * _mono(la[i + len(lb):], lb[-1].col)
                        diff = system.normal_form(left - right)
                        out.append(CriticalPair("inclusion", a, b, la, left, right, diff, i))
            if cyclic:
                out.extend(_cyclic_pairs(system, a, b))
    return out


def _cyclic_pairs(system: RewritingSystem, a: Rule, b: Rule) -> list[CriticalPair]:
    """Cyclic words covered by la (at 0) and lb (at j), overlapping at both ends."""
    la, lb = a.lhs, b.lhs
    out = []
    for m in range(max(len(la), len(lb)), len(la) + len(lb)):
        for j in range(1, len(la)):
            if j + len(lb) <= m:
                continue  # lb does not wrap around to la's start
            c: list = list(la) + [None] * (m - len(la))
            ok = True
            for t, L in enumerate(lb):
                pos = (j + t) % m
                if c[pos] is None:
                    c[pos] = L
                elif c[pos] != L:
                    ok = False
                    break
            if not ok or any(x is None for x in c):
                continue
            cw = tuple(c)
            if cw[-1].col != cw[0].row:
                continue
            rot = cw[j:] + cw[:j]
            left = _trace_of(system, a.rhs * _mono(cw[len(la):], la[-1].col))
            right = _trace_of(system, b.rhs * _mono(rot[len(lb):], lb[-1].col))
            out.append(CriticalPair("cyclic", a, b, cw, left, right, system.normal_form(left - right)))
    return out


def _completion_cofactors(system: RewritingSystem, p: CriticalPair, c: Coef) -> list[Cofactor] | None:
    """Cofactors of the rule that completes the word pair p (leading coefficient c).

    With a at 0 and b at ``offset`` in the word, p.left − p.right =
    −(l_a − r_a)·suffix + prefix·(l_b − r_b)·rest; reducing it subtracts a certified
    combination, and the new rule's lhs − rhs is what is left, divided by c."""
    if p.a.cofactors is None or p.b.cofactors is None:
        return None
    w = p.word
    after_a = w[len(p.a.lhs):]
    before_b, after_b = w[:p.offset], w[p.offset + len(p.b.lhs):]
    try:
        cert = system.certify(p.left - p.right)
    except CertificateError:
        return None
    inv = se.Integer(1) / c
    out = [Cofactor(-cf.coef * inv, cf.left, cf.hyp, cf.right + after_a) for cf in p.a.cofactors]
    out += [Cofactor(cf.coef * inv, before_b + cf.left, cf.hyp, cf.right + after_b) for cf in p.b.cofactors]
    out += [Cofactor(-t.coef * inv, t.left, t.hyp, t.right) for t in cert.terms]
    return out


def is_confluent(system: RewritingSystem, cyclic: bool = True) -> bool:
    return all(p.joinable for p in critical_pairs(system, cyclic))


@dataclass
class CompletionResult:
    """The completed system, whether completion finished, and the rules it added."""

    system: RewritingSystem
    finished: bool
    added: list[Rule] = field(default_factory=list)
    rounds: int = 0
    message: str = ""


def complete(system: RewritingSystem, max_rules: int = 50, max_rounds: int = 20) -> CompletionResult:
    """Knuth–Bendix completion on words (bounded); the input system is not modified.

    Unresolved pairs become rules oriented by the order, leading coefficient
    normalized to 1 (only numeric leading coefficients are divided by)."""
    sys2 = system.copy()
    added: list[Rule] = []
    for rnd in range(1, max_rounds + 1):
        pending = [p for p in critical_pairs(sys2, cyclic=False) if not p.joinable]
        if not pending:
            return CompletionResult(sys2, True, added, rnd - 1, "confluent")
        for p in pending:
            d = sys2.normal_form(p.left - p.right)
            if not d.terms:
                continue
            (tm, lead), c = max(d.terms.items(), key=lambda kv: (len(kv[0][0]), sys2.order.key(kv[0][1])))
            if tm:
                return CompletionResult(sys2, False, added, rnd, f"{p}: leading term has traces")
            if not c.is_Number:
                return CompletionResult(sys2, False, added, rnd,
                                        f"{p}: leading coefficient {c} is not a number")
            if not lead:
                return CompletionResult(sys2, False, added, rnd, f"{p}: the identity is a consequence (inconsistent)")
            rest = d - NCPoly({((), lead): c}, d.row, d.col)
            rule = sys2.add_rule(lead, rest * (se.Integer(-1) / c),
                                 f"completion of {p.a.name}, {p.b.name}", name=f"C{len(added) + 1}",
                                 cofactors=_completion_cofactors(sys2, p, c))
            added.append(rule)
            if len(sys2.rules) > max_rules:
                return CompletionResult(sys2, False, added, rnd, f"more than {max_rules} rules")
    return CompletionResult(sys2, False, added, max_rounds, f"not confluent after {max_rounds} rounds")
