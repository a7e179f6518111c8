"""Typed words and noncommutative polynomials with involution.

A :class:`Letter` is a matrix symbol with a row and a column index type
(``"n"`` or ``"r"``) and an adjoint partner (the transpose): X ↔ Xᵀ, A* = A,
ξ* = −ξ.  A word is a tuple of letters that compose (the column type of each
letter is the row type of the next).  An :class:`NCPoly` is a linear
combination of terms ``(traces, word)`` with symengine coefficients, all of one
type ``(row, col)``; ``traces`` is a sorted tuple of cyclic words, a product of
traces that multiplies the word (traces are central).  The empty word of type
``(t, t)`` is the identity I_t; polynomials of type ``("1", "1")`` are scalars
(trace forms).  Nothing here knows the constraints: normal forms live in
:mod:`stiefelsym.free.rewriting`.
"""
from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from fractions import Fraction
from typing import Any, Iterable, Iterator, Mapping

import symengine as se

from stiefelsym.backends.fields import Dual
from stiefelsym.backends.matrix import NeedsCoordinates, engine_number_type  # noqa: F401 (one exception for every backend)

# ---------------------------------------------------------------------------
# the one door of refusals: a refusal of the dimension-free scene is recorded in the run's record
# (the scene's tracker) *before* it is raised, so that a claim that catches it and goes on cannot
# turn it into a proof: the free method gives no "proved" when the record holds a refusal.

#: the suffix that marks a refusal in a tracker's record (the rest is what was refused)
REFUSED = " (refused: needs coordinates)"

#: the record of the free run in progress (its scene's tracker): for refusals of objects shared by
#: every run (the dimension symbols n, r) and of the rewriting system, which know no scene
_RUN_RECORD: ContextVar = ContextVar("stiefelsym_free_run_record", default=None)


def record_refusal(what: str, tracker: Any = None) -> None:
    """Record the refusal ``what`` in ``tracker`` (the scene's) and in the record of the run."""
    run = _RUN_RECORD.get()
    for t in (tracker, run if run is not tracker else None):
        if t is None:
            continue
        door = getattr(t, "refuse", None)   # the record's own door for refusals, where it has one
        if door is not None:
            door(what)
        else:
            t.touch(what + REFUSED)


def refuse(what: str, tracker: Any = None) -> NeedsCoordinates:
    """The refusal ``what``, recorded (see :func:`record_refusal`): ``raise refuse(what, tracker)``."""
    record_refusal(what, tracker)
    return NeedsCoordinates(what)


def refusals(tracker: Any) -> list[str]:
    """The refusals in a tracker's record (what was refused)."""
    out = list(getattr(tracker, "refused", ()))
    return out + [u[: -len(REFUSED)] for u in tracker.used if u.endswith(REFUSED) and u[: -len(REFUSED)] not in out]


@contextmanager
def recording(tracker: Any) -> Iterator[None]:
    """Within: the refusals that know no scene go to ``tracker`` (the free method's run)."""
    token = _RUN_RECORD.set(tracker)
    try:
        yield
    finally:
        _RUN_RECORD.reset(token)

#: index type of scalars
SCALAR = "1"


@engine_number_type
class Dimension(se.Dummy):
    """The symbol n or r: usable in formulas (tr I_r = r), not as an integer or in comparisons.

    A dummy symbol: a symbol a claim creates with the same name is a different symbol."""

    def _refuse(self, *args: Any) -> Any:
        raise refuse(f"using the dimension {self} as a number")

    __index__ = __int__ = __float__ = __complex__ = __lt__ = __le__ = __gt__ = __ge__ = _refuse


#: dimension symbols: tr(I_n) = n, tr(I_r) = r
DIMENSIONS = {"n": Dimension("n"), "r": Dimension("r"), SCALAR: se.Integer(1)}
#: the object ℝʳ⁻¹ of the first r − 1 columns of I_r (the columns e_1, ..., e_{n−1} of X ∈ SO(n))
LEADING = "r-1"
DIMENSIONS[LEADING] = DIMENSIONS["r"] - 1

Coef = Any  # a symengine expression


#: the steps d = n − r >= 0 and e = r − 1 >= 0 in which the door for divisors writes a size (n = 1 + e + d,
#: r = 1 + e): plain symbols of reserved names, the same after a round trip through sympy
_STEPS = (se.Symbol("stiefelsym_size_step_d"), se.Symbol("stiefelsym_size_step_e"))


def divisor(k: Coef) -> Coef:
    """k, as a divisor: refused (recorded) when it depends on the sizes n, r and may be 0 at some size: a
    division by n − 4 or by n − r holds for all n, r as a rational function, but is 0/0 at n = 4 or at r = n,
    so no statement for every n, r follows from it.  k is put over one denominator, k = N/D (N, D polynomials),
    and each of N and D must be nonzero at every size n ≥ r ≥ 1 by :func:`_nonzero_at_every_size` (n + r, −2n,
    λ + n, n − r + 1).  (A pole of k at a size is refused as a zero of N is: 1/(n + r) − 1/(2n) =
    (n − r)/(2n(n + r)) is 0 at r = n.)  A k that is identically 0 raises ZeroDivisionError (as at a fixed size:
    1/0 would be nan, a normal form that is never 0)."""
    if se.expand(k) == 0:
        raise ZeroDivisionError("division by an identically zero expression")
    syms = getattr(k, "free_symbols", None)
    n, r = DIMENSIONS["n"], DIMENSIONS["r"]
    if not syms or not any(x in syms for x in (n, r)):
        return k
    import sympy
    d, e = _STEPS
    # the sizes written in the steps before sympy sees them (a dimension symbol does not survive the round trip
    # in every symengine version)
    num, den = sympy.fraction(sympy.cancel(sympy.sympify(k.subs({n: 1 + e + d, r: 1 + e}))))
    if num == 0:
        raise ZeroDivisionError("division by an identically zero expression")
    if not (_nonzero_at_every_size(num) and _nonzero_at_every_size(den)):
        raise refuse(f"a division by {k}, an expression in the sizes that may vanish at some n, r")
    return k


def _nonzero_at_every_size(p: Any) -> bool:
    """Whether the sympy polynomial p, in the steps d, e (n = 1 + e + d, r = 1 + e) and other symbols, is nonzero
    at every size: as a polynomial in its other symbols it has a coefficient, a polynomial in d and e, whose
    coefficients all have one sign and whose constant term is not 0 (so it is at least that constant in size
    wherever d, e ≥ 0: n + r, n − r + 1, 2n − r, n² − nr + r², −2n pass; n − r, r − 1, 2r − n do not).  False also
    where p is no polynomial in them (a size under a root)."""
    import sympy
    d, e = (sympy.Symbol(x.name) for x in _STEPS)
    if not ({d, e} & p.free_symbols):
        return True
    others = sorted(p.free_symbols - {d, e}, key=str)
    try:
        poly = sympy.Poly(p, *others, d, e)
    except sympy.PolynomialError:
        return False
    groups: dict = {}
    for monom, c in poly.terms():
        if not c.is_number:
            return False
        groups.setdefault(monom[:-2], {})[monom[-2:]] = c
    return any(g.get((0, 0), 0) != 0 and (all(c > 0 for c in g.values()) or all(c < 0 for c in g.values()))
               for g in groups.values())


class Letter(str):
    """A matrix letter: name (its identity), index types, adjoint partner and sign, LaTeX."""

    row: str
    col: str
    latex: str
    adjoint: "Letter"
    adjoint_sign: int
    sort_key: tuple

    def __new__(cls, name: str, row: str, col: str, latex: str | None = None) -> "Letter":
        obj = super().__new__(cls, name)
        obj.row, obj.col = row, col
        obj.latex = latex if latex is not None else name
        obj.adjoint, obj.adjoint_sign = obj, 1
        obj.sort_key = (1, name)
        return obj


def letter_pair(name: str, adjoint_name: str, row: str, col: str,
                latex: str | None = None, adjoint_latex: str | None = None) -> tuple[Letter, Letter]:
    """A letter L and its transpose L* (types swapped)."""
    L = Letter(name, row, col, latex)
    Lt = Letter(adjoint_name, col, row, adjoint_latex if adjoint_latex is not None else f"{L.latex}^{{T}}")
    L.adjoint, Lt.adjoint = Lt, L
    Lt.sort_key = (0, adjoint_name)  # representatives of traces start with a transpose: tr(XᵀAX)
    return L, Lt


def symmetric_letter(name: str, t: str, latex: str | None = None) -> Letter:
    """A self-adjoint letter (symmetric t×t matrix)."""
    return Letter(name, t, t, latex)


def skew_letter(name: str, t: str, latex: str | None = None) -> Letter:
    """An anti-self-adjoint letter (skew-symmetric t×t matrix): L* = −L."""
    L = Letter(name, t, t, latex)
    L.adjoint_sign = -1
    return L


Word = tuple  # tuple[Letter, ...]
Traces = tuple  # sorted tuple of cyclic words
Key = tuple  # (Traces, Word)


def check_word(w: Word) -> None:
    """Raise TypeError unless consecutive letters compose."""
    for a, b in zip(w, w[1:]):
        if a.col != b.row:
            raise TypeError(f"ill-typed word {word_str(w)}: {a} is ·×{a.col}, {b} is {b.row}×·")


def star_word(w: Word) -> tuple[int, Word]:
    """w* = sign · (reversed word of adjoint letters)."""
    hit = _memo_get(_STARS, w)
    if hit is not None:
        return hit
    return _memo_put(_STARS, w, _star_word(w))


def _star_word(w: Word) -> tuple[int, Word]:
    sign = 1
    out = []
    for L in reversed(w):
        sign *= L.adjoint_sign
        out.append(L.adjoint)
    return sign, tuple(out)


def word_key(w: Word) -> tuple:
    """A total order on words used for canonical representatives (length, then letters,
    transposed letters first)."""
    return (len(w), tuple(L.sort_key for L in w))


# Memos of functions of a word.  Letters compare by name, so a hit counts only when the stored
# word has the very same letter objects (a letter of another scene with the same name may have
# other types or another adjoint).
_ROTATIONS: dict = {}
_CYCLE_REPS: dict = {}
_STARS: dict = {}
_MEMO_MAX = 50_000


def _memo_get(memo: dict, w: Word) -> Any:
    hit = memo.get(w)
    if hit is not None:
        stored, value = hit
        for a, b in zip(stored, w):
            if a is not b:
                return None
        return value
    return None


def _memo_put(memo: dict, w: Word, value: Any) -> Any:
    if len(memo) >= _MEMO_MAX:
        memo.clear()
    memo[w] = (w, value)
    return value


def min_rotation(c: Word) -> Word:
    """The least rotation of a cyclic word (in the order of :func:`word_key`)."""
    hit = _memo_get(_ROTATIONS, c)
    if hit is not None:
        return hit
    keys = [L.sort_key for L in c]
    first = min(keys)
    starts = [k for k, x in enumerate(keys) if x == first]   # a least rotation starts with the least letter
    best = starts[0] if len(starts) == 1 else min(starts, key=lambda k: keys[k:] + keys[:k])
    return _memo_put(_ROTATIONS, c, c[best:] + c[:best])


def cycle_rep(w: Word) -> tuple[int, Word]:
    """Canonical (sign, representative) of tr(w) under rotation and tr(w*) = tr(w), and for a word
    with one letter of a symmetric operator on so(n), under tr(𝔸(u)V) = tr(u𝔸(V)).

    sign 0 means tr(w) = −tr(w), i.e. the trace vanishes."""
    hit = _memo_get(_CYCLE_REPS, w)
    if hit is not None:
        return hit
    pair = operator_pair_rep(w)   # the symmetry of an operator letter (see operator_pair_rep)
    if pair is not None:
        s0, w0 = pair
        if s0 == 0 or not operator_letters_in(w0[1:]):
            return _memo_put(_CYCLE_REPS, w, pair)
        s1, rep = _rotation_rep(w0)   # an operator inside the other argument: by rotation and transposition
        return _memo_put(_CYCLE_REPS, w, (s0 * s1, rep))
    return _memo_put(_CYCLE_REPS, w, _rotation_rep(w))


def _rotation_rep(w: Word) -> tuple[int, Word]:
    c = min_rotation(w)
    s, ws = star_word(w)
    cs = min_rotation(ws)
    if cs == c:
        return (1 if s == 1 else 0), c
    return (1, c) if word_key(c) < word_key(cs) else (s, cs)


def word_str(w: Word) -> str:
    return "*".join(w) if w else "I"


ONE_TYPE = type(se.Integer(1))
ZERO_TYPE = type(se.Integer(0))
#: symengine classes whose instances are never zero (zero is always of ZERO_TYPE)
_NONZERO_TYPES = frozenset(type(x) for x in (se.Integer(1), se.Integer(-1), se.Integer(2), se.Rational(1, 2),
                                              se.Rational(2, 3), se.Symbol("x"), se.Symbol("x") * 2,
                                              se.Symbol("x") + 1, se.Symbol("x") ** 2))


def coef_is_zero(k: Coef) -> bool:
    """k == 0 (structurally, as symengine compares; no expansion), cheaply."""
    t = type(k)
    if t is ZERO_TYPE:
        return True
    if t in _NONZERO_TYPES:
        return False
    return k == 0


def cmul(a: Coef, b: Coef) -> Coef:
    """a·b, without symengine's multiplication when a factor is 1."""
    if type(a) is ONE_TYPE:
        return b
    if type(b) is ONE_TYPE:
        return a
    return cprod(a, b)


# Coefficient arithmetic, memoized: a symengine product, sum or negation costs about 1 µs, a
# lookup a fifth of that, and a claim meets few distinct coefficients (λ, κ, small integers and
# their products) many times.  Symengine expressions are immutable, hashable and compared
# structurally, and these operations are pure functions of them, so the memo returns exactly the
# expression the operation would build.
_CPROD: dict = {}
_CSUM: dict = {}
_CNEG: dict = {}
_COEF_MEMO_MAX = 100_000


def _coef_memo_full() -> None:
    for memo in (_CPROD, _CSUM, _CNEG):
        if len(memo) >= _COEF_MEMO_MAX:
            memo.clear()


def cprod(a: Coef, b: Coef) -> Coef:
    """a·b (memoized)."""
    key = (a, b)
    try:
        return _CPROD[key]
    except KeyError:
        pass
    except TypeError:   # not hashable: no memo
        return a * b
    v = _CPROD[key] = a * b
    if len(_CPROD) >= _COEF_MEMO_MAX:
        _coef_memo_full()
    return v


def csum(a: Coef, b: Coef) -> Coef:
    """a + b (memoized)."""
    key = (a, b)
    try:
        return _CSUM[key]
    except KeyError:
        pass
    except TypeError:
        return a + b
    v = _CSUM[key] = a + b
    if len(_CSUM) >= _COEF_MEMO_MAX:
        _coef_memo_full()
    return v


_CEXPAND: dict = {}


def cexpand(a: Coef) -> Coef:
    """se.expand(a) (memoized: a pure function of the expression)."""
    try:
        return _CEXPAND[a]
    except KeyError:
        pass
    except TypeError:
        return se.expand(a)
    v = _CEXPAND[a] = se.expand(a)
    if len(_CEXPAND) >= _COEF_MEMO_MAX:
        _CEXPAND.clear()
    return v


def cneg(a: Coef) -> Coef:
    """−a (memoized)."""
    try:
        return _CNEG[a]
    except KeyError:
        pass
    except TypeError:
        return -a
    v = _CNEG[a] = -a
    if len(_CNEG) >= _COEF_MEMO_MAX:
        _coef_memo_full()
    return v


def as_coef(c: Any) -> Coef | None:
    """A commuting scalar as a symengine number/expression, or None if c is not one."""
    if isinstance(c, se.Basic):
        return c
    t = type(c)
    if t is int:
        return se.Integer(c)
    if t is bool:
        return None
    if t is Fraction:
        return se.Integer(c.numerator) / se.Integer(c.denominator)
    if isinstance(c, int):
        return se.Integer(c)
    if isinstance(c, Fraction):
        return se.Integer(c.numerator) / se.Integer(c.denominator)
    return None


#: What symengine's conversion sees of a word polynomial or a block matrix of the free scene: a
#: symengine matrix (0×0).  ``c * p`` with a symengine scalar c then returns NotImplemented at
#: once (symengine leaves products with matrices to the other operand) and p's reflected operator
#: computes it; without it symengine tries every SymPy class on p first (milliseconds per product).
#: Only symengine's arithmetic and comparisons read this; a polynomial is never a symengine number.
SYMENGINE_OPAQUE = se.DenseMatrix(0, 0, [])


def _is_matrix(o: Any) -> bool:
    return getattr(o, "__array_priority__", 0) >= 1000


def merge_traces(a: Traces, b: Traces) -> Traces:
    if not a:
        return b
    if not b:
        return a
    return tuple(sorted(a + b, key=word_key))


@engine_number_type
class NCPoly:
    """A linear combination of (traces, word) terms of one type (row, col)."""

    #: _starred: the transpose, once computed (polynomials are immutable; * is an involution)
    __slots__ = ("terms", "row", "col", "_starred")

    def _symengine_(self) -> Any:
        return SYMENGINE_OPAQUE

    def __init__(self, terms: Mapping[Key, Coef], row: str, col: str) -> None:
        self.terms = dict(terms)
        self.row, self.col = row, col

    @classmethod
    def _raw(cls, terms: dict, row: str, col: str) -> "NCPoly":
        """A polynomial owning ``terms`` (a dict built for it: not copied)."""
        p = object.__new__(cls)
        p.terms, p.row, p.col = terms, row, col
        return p

    # -- construction -------------------------------------------------------
    @classmethod
    def zero(cls, row: str, col: str) -> "NCPoly":
        return cls({}, row, col)

    @classmethod
    def identity(cls, t: str) -> "NCPoly":
        """I_t (the empty word of type (t, t)); t = "1" gives the scalar 1."""
        return cls({((), ()): se.Integer(1)}, t, t)

    @classmethod
    def scalar(cls, c: Any) -> "NCPoly":
        k = as_coef(c)
        if k is None:
            raise TypeError(f"not a scalar: {c!r}")
        return cls._raw({((), ()): k} if not coef_is_zero(k) else {}, SCALAR, SCALAR)

    @classmethod
    def word(cls, w: Iterable[Letter], row: str | None = None, coef: Any = 1) -> "NCPoly":
        """The monomial coef·w; ``row`` types the empty word."""
        w = tuple(w)
        check_word(w)
        if w:
            row, col = w[0].row, w[-1].col
        elif row is None:
            raise TypeError("the empty word needs a type")
        else:
            col = row
        k = as_coef(coef)
        return cls._raw({((), w): k} if not coef_is_zero(k) else {}, row, col)

    # -- queries ------------------------------------------------------------
    @property
    def shape(self) -> tuple[str, str]:
        return (self.row, self.col)

    @property
    def is_scalar(self) -> bool:
        return self.row == SCALAR and self.col == SCALAR

    def is_zero_raw(self) -> bool:
        """No terms (after coefficient expansion); no constraints used."""
        return all(se.expand(c) == 0 for c in self.terms.values())

    def letters(self) -> set[Letter]:
        out: set[Letter] = set()
        for tm, w in self.terms:
            out.update(w)
            for c in tm:
                out.update(c)
        return out

    def coefficient(self, w: Word, traces: Traces = ()) -> Coef:
        return self.terms.get((traces, tuple(w)), se.Integer(0))

    def scalar_value(self) -> Coef:
        """The coefficient of a scalar without traces; TypeError if traces remain."""
        if not self.is_scalar or any(tm for tm, _ in self.terms):
            raise TypeError(f"{self} is not a plain scalar")
        return self.terms.get(((), ()), se.Integer(0))

    # -- arithmetic ---------------------------------------------------------
    def _new(self, terms: dict) -> "NCPoly":
        return NCPoly._raw(terms, self.row, self.col)

    def _same_type(self, o: "NCPoly") -> None:
        if self.shape != o.shape:
            raise TypeError(f"cannot add a {self.row}×{self.col} and a {o.row}×{o.col} polynomial")

    def __add__(self, o: Any):
        if type(o) is NCPoly:
            if self.row != o.row or self.col != o.col:
                self._same_type(o)
            if not o.terms:
                return self
            if not self.terms:
                return o
            out = dict(self.terms)
            for k, c in o.terms.items():
                out[k] = csum(out[k], c) if k in out else c
            return NCPoly._raw(out, self.row, self.col)
        if isinstance(o, NCPoly):
            self._same_type(o)
            out = dict(self.terms)
            for k, c in o.terms.items():
                out[k] = out[k] + c if k in out else c
            return self._new(out)
        if isinstance(o, Dual) or _is_matrix(o):
            return NotImplemented
        k = as_coef(o)
        if k is None:
            return NotImplemented
        if coef_is_zero(k):
            return self
        if not self.is_scalar:
            raise TypeError("adding a scalar to a matrix polynomial: write c·I explicitly")
        return self + NCPoly.scalar(k)

    __radd__ = __add__

    def __neg__(self) -> "NCPoly":
        return self._new({k: cneg(c) for k, c in self.terms.items()})

    def __sub__(self, o: Any):
        if type(o) is NCPoly and self.row == o.row and self.col == o.col:
            # self + (−o) in one pass (the same terms and coefficients)
            if not o.terms:
                return self
            out = dict(self.terms)
            for k, c in o.terms.items():
                out[k] = csum(out[k], cneg(c)) if k in out else cneg(c)
            return NCPoly._raw(out, self.row, self.col)
        if isinstance(o, (Dual,)) or _is_matrix(o):
            return NotImplemented
        return self + (-o)

    def __rsub__(self, o: Any):
        return (-self) + o

    def _scale(self, k: Coef) -> "NCPoly":
        if coef_is_zero(k):
            return self._new({})
        if type(k) is ONE_TYPE:
            return self._new(dict(self.terms))
        return self._new({key: cprod(c, k) for key, c in self.terms.items()})

    def __mul__(self, o: Any):
        if isinstance(o, NCPoly):
            return self._mul_poly(o)
        if isinstance(o, se.Basic):   # a coefficient (what as_coef returns for it), first
            return self._scale(o)
        if isinstance(o, Dual):
            return Dual(self * o.a, self * o.b)
        if _is_matrix(o):
            if self.is_scalar:
                return NotImplemented  # the matrix scales its entries
            raise TypeError("a matrix polynomial cannot multiply a block matrix from the left")
        k = as_coef(o)
        if k is None:
            return NotImplemented
        return self._scale(k)

    def __rmul__(self, o: Any):
        if isinstance(o, NCPoly):
            return o._mul_poly(self)
        k = as_coef(o)
        if k is None:
            return NotImplemented
        return self._scale(k)

    def __truediv__(self, o: Any):
        if isinstance(o, NCPoly):
            return self._scale(se.Integer(1) / divisor(o._divisor_value()))
        k = as_coef(o)
        if k is None:
            return NotImplemented
        return self._scale(se.Integer(1) / divisor(k))

    def __rtruediv__(self, o: Any):
        k = as_coef(o)
        if k is None:
            return NotImplemented
        return NCPoly.scalar(k / divisor(self._divisor_value()))

    def _divisor_value(self) -> Coef:
        """This polynomial as a divisor: a plain scalar (a number, a size, λ); a scalar of the scene (a trace, a
        pairing) is refused, in words: the free algebra has no inverse of a trace."""
        if not self.is_scalar or any(tm for tm, _ in self.terms):
            raise refuse("a division by a scalar that is not a number (a trace or a pairing of the scene: the "
                         "free algebra divides by numbers, sizes and λ only)")
        return self.scalar_value()

    def _mul_poly(self, o: "NCPoly") -> "NCPoly":
        if self.row == SCALAR and self.col == SCALAR:
            row, col = o.row, o.col
            if o.row != SCALAR and any(w for (_, w) in self.terms):   # a 1×1 word scales as its trace
                return trace(self)._mul_poly(o)
        elif o.row == SCALAR and o.col == SCALAR:
            row, col = self.row, self.col
            if self.col != SCALAR and any(w for (_, w) in o.terms):
                return self._mul_poly(trace(o))
        elif self.col == o.row:
            row, col = self.row, o.col
        else:
            raise TypeError(f"cannot multiply a {self.row}×{self.col} by a {o.row}×{o.col} polynomial")
        st, ot = self.terms, o.terms
        if len(st) == 1 and len(ot) == 1:   # one term by one term (letters, monomials): no sums
            ((t1, w1), c1), = st.items()
            ((t2, w2), c2), = ot.items()
            c = c2 if type(c1) is ONE_TYPE else (c1 if type(c2) is ONE_TYPE else cprod(c1, c2))
            return NCPoly._raw({(merge_traces(t1, t2) if t1 and t2 else t1 or t2, w1 + w2): c}, row, col)
        out: dict = {}
        one = ONE_TYPE
        for (t1, w1), c1 in self.terms.items():
            one1 = type(c1) is one
            for (t2, w2), c2 in o.terms.items():
                k = (merge_traces(t1, t2) if t1 and t2 else t1 or t2, w1 + w2)
                c = c2 if one1 else (c1 if type(c2) is one else cprod(c1, c2))   # cmul, inlined
                out[k] = csum(out[k], c) if k in out else c
        return NCPoly._raw(out, row, col)

    def star(self) -> "NCPoly":
        """The involution (transpose): reverses words, adjoint letters; traces are fixed."""
        try:
            return self._starred
        except AttributeError:
            pass
        out: dict = {}
        for (tm, w), c in self.terms.items():
            s, ws = star_word(w)
            k = (tm, ws)
            v = c if s == 1 else cneg(c)
            out[k] = csum(out[k], v) if k in out else v
        res = NCPoly._raw(out, self.col, self.row)
        res._starred = self
        self._starred = res
        return res

    def expand(self) -> "NCPoly":
        """Expanded coefficients, zero terms dropped (no constraints used)."""
        out = {}
        for k, c in self.terms.items():
            e = cexpand(c)
            if not coef_is_zero(e):
                out[k] = e
        return self._new(out)

    def __eq__(self, o: object) -> bool:
        """Equality as elements of the free algebra (no constraints used)."""
        if not isinstance(o, NCPoly):
            k = as_coef(o)
            if k is None:
                return NotImplemented
            return self.is_scalar and (self - k).is_zero_raw() or (k == 0 and self.is_zero_raw())
        return self.shape == o.shape and (self - o).is_zero_raw()

    __hash__ = None  # type: ignore[assignment]

    def _refuse(self, *args: Any) -> Any:
        """A block or a trace form is not a number: using one as a number is a refusal (recorded)."""
        raise refuse("using a polynomial of the free algebra (a block or a trace form) as a number")

    __index__ = __int__ = __float__ = __complex__ = __lt__ = __le__ = __gt__ = __ge__ = _refuse

    # -- printing -----------------------------------------------------------
    def _sorted_terms(self):
        return sorted(self.terms.items(), key=lambda kv: (len(kv[0][0]), [word_key(c) for c in kv[0][0]],
                                                         word_key(kv[0][1])))

    def __str__(self) -> str:
        parts = []
        for (tm, w), c in self._sorted_terms():
            factors = [f"tr({word_str(t)})" for t in tm]
            if w or not factors:
                factors.append(word_str(w) if w else (f"I_{self.row}" if self.row != SCALAR else "1"))
            parts.append(f"({c})*" + "*".join(factors))
        return " + ".join(parts) if parts else "0"

    def __repr__(self) -> str:
        return f"NCPoly[{self.row}x{self.col}]({self})"

    def latex(self) -> str:
        """LaTeX with the paper's notation (X^{T}, (\\lambda I_n - A)^{-1}, tr)."""
        return " ".join(self.latex_terms())

    def latex_terms(self) -> list[str]:
        """The terms of :meth:`latex`, each with its sign (the first without a plus), in its order."""
        if not self.terms:
            return ["0"]
        out = []
        for (tm, w), c in self._sorted_terms():
            if _coef_parts(c)[1] == "0":        # a coefficient that expands to 0 (the term is not there)
                continue
            body = " ".join([rf"\operatorname{{tr}}({word_latex(t)})" for t in tm]
                            + ([word_latex(w)] if w else []))
            if not body and self.row != SCALAR:
                body = rf"\mathbf{{I}}_{{{self.row}}}"
            out.append(_signed_term(c, body).strip())
        if not out:
            return ["0"]
        if out[0].startswith("+ "):
            out[0] = out[0][2:]
        return out


def word_latex(w: Word) -> str:
    return " ".join(L.latex for L in w)


def coef_latex(c: Coef) -> str:
    import sympy  # local: only printing needs sympy

    return sympy.latex(sympy.sympify(c._sympy_() if hasattr(c, "_sympy_") else c))


#: coefficient -> (sign "- " or "+ ", LaTeX of its magnitude or None when it is 1, whether it is a sum)
_TERM_LATEX: dict = {}
#: symengine's classes of rational numbers
_RATIONAL_TYPES = frozenset(type(x) for x in (se.Integer(0), se.Integer(1), se.Integer(-1), se.Integer(2),
                                               se.Rational(1, 2), se.Rational(2, 3), se.Rational(-1, 2)))


def _coef_parts(c: Coef) -> tuple[str, str | None, bool]:
    try:
        return _TERM_LATEX[c]
    except (KeyError, TypeError):
        pass
    e = se.expand(c)
    if type(e) in _RATIONAL_TYPES:   # a rational number: SymPy's LaTeX, without loading SymPy
        num, den = (int(x) for x in e.as_numer_denom())
        neg = num < 0
        num = abs(num)
        out = ("- " if neg else "+ ", None if num == den == 1 else str(num) if den == 1
               else rf"\frac{{{num}}}{{{den}}}", False)
    else:
        import sympy

        e = sympy.sympify(e._sympy_())
        neg = e.could_extract_minus_sign()
        mag = -e if neg else e
        out = ("- " if neg else "+ ", None if mag == 1 else sympy.latex(mag), isinstance(mag, sympy.Add))
    return memo_put(_TERM_LATEX, c, out, 50_000)


def memo_put(memo: dict, key: Any, value: Any, limit: int) -> Any:
    """Store value under key in a bounded memo (cleared when it outgrows limit; an unhashable
    key is not stored) and return value."""
    try:
        if len(memo) > limit:
            memo.clear()
        memo[key] = value
    except TypeError:
        pass
    return value


def _signed_term(c: Coef, body: str) -> str:
    sign, text, is_sum = _coef_parts(c)
    if not body:
        if is_sum and sign.startswith("-"):     # − (n r + r), never − n r + r
            return sign + rf"\left({text}\right)"
        return sign + (text if text is not None else "1")
    if text is None:
        return sign + body
    if is_sum:
        text = rf"\left({text}\right)"
    return sign + text + " " + body


# ---------------------------------------------------------------------------
def trace(p: NCPoly) -> NCPoly:
    """tr(p) as a scalar polynomial (canonical cyclic representatives, no constraints)."""
    if p.is_scalar:
        if all(not w for (_, w) in p.terms):
            return p
        return _scalar_words_as_traces(p)   # a 1×1 word (through a column E_i) is its own trace
    if p.row != p.col:
        raise TypeError(f"trace of a non-square {p.row}×{p.col} polynomial")
    out: dict = {}
    for (tm, w), c in p.terms.items():
        if not w:
            k, v = (tm, ()), c * DIMENSIONS[p.row]
        else:
            s, cw = cycle_rep(w)
            if s == 0:
                continue
            k, v = (merge_traces(tm, (cw,)), ()), c * s
        out[k] = out[k] + v if k in out else v
    return NCPoly(out, SCALAR, SCALAR)


def _scalar_words_as_traces(p: NCPoly) -> NCPoly:
    """A 1×1 polynomial with every word (a path from the scalar object to itself) moved into the
    traces: a 1×1 matrix is its own trace."""
    out: dict = {}
    for (tm, w), c in p.terms.items():
        if w:
            s, cw = cycle_rep(w)
            if s == 0:
                continue
            k, v = (merge_traces(tm, (cw,)), ()), c * s
        else:
            k, v = (tm, ()), c
        out[k] = out[k] + v if k in out else v
    return NCPoly(out, SCALAR, SCALAR)


def substitute(p: NCPoly, images: Mapping[Letter, NCPoly]) -> NCPoly:
    """The algebra homomorphism sending letters to polynomials (adjoints follow by *).

    Images must have the letter's type; traces are substituted inside."""
    full: dict[Letter, NCPoly] = {}
    for L, v in images.items():
        if v.shape != (L.row, L.col):
            raise TypeError(f"image of {L} must be {L.row}×{L.col}, got {v.row}×{v.col}")
        full[L] = v
        if L.adjoint not in images:
            full[L.adjoint] = v.star() * L.adjoint_sign if L.adjoint != L else v
    _operator_images(p, full, lambda q: substitute(q, images))
    out = NCPoly.zero(p.row, p.col)
    for (tm, w), c in p.terms.items():
        term = NCPoly({((), w): c}, p.row, p.col)
        if any(L in full for L in w):
            acc = NCPoly.identity(p.row) * c
            for L in w:
                acc = acc * (full[L] if L in full else NCPoly.word((L,)))
            term = acc
        for cyc in tm:
            if any(L in full for L in cyc):
                acc = NCPoly.identity(cyc[0].row)
                for L in cyc:
                    acc = acc * (full[L] if L in full else NCPoly.word((L,)))
                term = term * trace(acc)
            else:
                term = term * NCPoly({((cyc,), ()): se.Integer(1)}, SCALAR, SCALAR)
        out = out + term
    return out


def evaluate(p: NCPoly, matrices: Mapping[str, Any], scalars: Mapping[Any, Any] | None = None,
             dims: Mapping[str, int] | None = None) -> Any:
    """p at concrete matrices (numpy object arrays of exact numbers, keyed by letter name).

    A letter whose adjoint is given but not itself evaluates to sign·transpose;
    ``scalars`` maps symbols (λ, κ, ...) to numbers; ``dims`` gives n and r
    (inferred from the matrices when possible).  Returns an array, or a number
    for a scalar.  Used to certify that a nonzero normal form is nonzero."""
    import numpy as np  # local: only evaluation needs arrays

    mats = {k: np.asarray(v, dtype=object) for k, v in matrices.items()}
    d = dict(dims or {})
    for L in p.letters() | {x.adjoint for x in p.letters()}:
        if L in mats:
            d.setdefault(L.row, mats[L].shape[0])
            d.setdefault(L.col, mats[L].shape[1])
    d[SCALAR] = 1
    subs = {DIMENSIONS["n"]: d.get("n", 0), DIMENSIONS["r"]: d.get("r", 0)}
    subs.update(scalars or {})
    subs = {k: as_coef(v) for k, v in subs.items()}

    def number(c: Coef) -> Fraction:
        v = se.expand(se.sympify(c).subs(subs))
        if not v.is_Number:
            raise ValueError(f"coefficient {c} has unassigned symbols {v.free_symbols}")
        num, den = v.as_numer_denom()
        return Fraction(int(num), int(den))

    def letter(L: Letter):
        if L in mats:
            return mats[L]
        if L.adjoint in mats:
            return mats[L.adjoint].T * L.adjoint_sign
        raise KeyError(f"no value for the letter {L}")

    def word_value(w: Word, t: str):
        if t == SCALAR:
            return Fraction(1)
        acc = np.identity(d[t], dtype=object) * Fraction(1)
        for L in w:
            acc = acc.dot(letter(L))
        return acc

    total = None
    for (tm, w), c in p.terms.items():
        v = word_value(w, p.row) * number(c)
        for cyc in tm:
            v = v * sum(np.diag(word_value(cyc, cyc[0].row)), Fraction(0))
        total = v if total is None else total + v
    if total is None:
        return Fraction(0) if p.is_scalar else np.zeros((d[p.row], d[p.col]), dtype=object) * Fraction(0)
    return total


#: whether a letter that moves with the point in a way the free scene does not differentiate (a resolvent at
#: a spectral parameter that moves, see FreeScene.resolvent) was ever made: until then no polynomial is searched
_MOVING_LETTERS: list[bool] = [False]


def mark_moving(L: Letter) -> Letter:
    """Mark L as moving with the point by a derivative the free scene's own derivations do not know (they
    refuse a polynomial that holds it; the derivative passes of the graph write its derivative)."""
    L.moving = True             # type: ignore[attr-defined]
    _MOVING_LETTERS[0] = True
    return L


def refuse_moving(p: "NCPoly", what: str, tracker: Any = None) -> None:
    """Refuse (recorded) to differentiate a polynomial that holds a letter marked by :func:`mark_moving`."""
    if not _MOVING_LETTERS[0]:
        return

    def moving(L: Letter) -> bool:
        return getattr(L, "moving", False) or (isinstance(L, OperatorLetter) and any(moving(x) for x in L.argument))
    if any(moving(L) for L in p.letters()):
        raise refuse(f"{what} of a letter that moves with the point (a resolvent at a moving spectral parameter, "
                     "or the multiplier of a flow of the metric realization: its derivative is not the free scene's "
                     "own)", tracker)


def derivation(p: NCPoly, images: Mapping[Letter, NCPoly]) -> NCPoly:
    """The derivation D with D(L) = images[L], D(L*) = images[L]* (with sign), other letters ↦ 0.

    Traces: D tr(c) = tr(D c).  D is well defined on a quotient only if it maps
    the relations into the ideal (for a flow: the flow is tangent to T*V)."""
    refuse_moving(p, "a derivative along a flow")
    full: dict[Letter, NCPoly] = {}
    for L, v in images.items():
        if v.shape != (L.row, L.col):
            raise TypeError(f"the derivative of {L} must be {L.row}×{L.col}, got {v.row}×{v.col}")
        full[L] = v
        if L.adjoint != L and L.adjoint not in images:
            full[L.adjoint] = v.star() * L.adjoint_sign
    # d𝔸⟨u⟩ = 𝔸(du): the operator is linear and constant along flows
    _operator_images(p, full, lambda q: derivation(q, images))

    def word_derivative(w: Word, t: str) -> NCPoly:
        out = NCPoly.zero(t, w[-1].col if w else t)
        for i, L in enumerate(w):
            if L in full:
                left = NCPoly.word(w[:i], t)
                right = NCPoly.word(w[i + 1:], L.col)
                out = out + left * full[L] * right
        return out

    out = NCPoly.zero(p.row, p.col)
    for (tm, w), c in p.terms.items():
        if w:
            out = out + NCPoly({(tm, ()): c}, SCALAR, SCALAR) * word_derivative(w, p.row)
        for i, cyc in enumerate(tm):
            dc = word_derivative(cyc, cyc[0].row)
            if not dc.terms:
                continue
            rest = NCPoly({(tm[:i] + tm[i + 1:], w): c}, p.row, p.col)
            out = out + rest * trace(dc)
    return out


# ---------------------------------------------------------------------------
# a generic symmetric operator on so(n) as typed letters
class OperatorLetter(Letter):
    """𝔸⟨w⟩ = 𝔸(skew w): a generic linear operator 𝔸 on so(n), symmetric for the Killing form,
    applied to the skew part (w − wᵀ)/2 of an n×n word w (or, of an r×r word, the operator of that
    name on so(r): an r×r letter).  An opaque skew n×n letter whose name
    says the operator and its argument, ``AA(X*Pt)``; :func:`apply_operator` makes only canonical
    ones (the argument is the least of w and its transpose word, see :func:`operator_rep`)."""

    operator: str
    argument: Word


def operator_letter(op: str, arg: Word, t: str = "n") -> OperatorLetter:
    """The letter 𝔸⟨arg⟩ of the operator ``op`` (arg an n×n or r×r word, taken as it is; t its type
    when arg is empty).  The operator of a name on so(r) is another operator than the one on so(n):
    its letters are r×r, and the type of the argument tells them apart."""
    arg = tuple(arg)
    key = (op, arg)
    hit = _OPERATOR_LETTERS.get(key)
    if hit is not None and all(a is b for a, b in zip(hit.argument, arg)) and (arg or hit.row == t):
        return hit
    check_word(arg)
    t = arg[0].row if arg else t
    if t not in ("n", "r") or (arg and arg[-1].col != t):
        raise TypeError(f"the operator {op} acts on so(n) or so(r): its argument {word_str(arg)} is not square")
    L = OperatorLetter.__new__(OperatorLetter, f"{op}({word_str(arg)})", t, t,
                               rf"\mathbb{{{op[0]}}}({word_latex(arg) or 'I'})")
    L.adjoint_sign = -1
    L.operator, L.argument = op, arg
    _OPERATOR_LETTERS[key] = L
    return L


_OPERATOR_LETTERS: dict = {}


def operator_rep(w: Word) -> tuple[int, Word]:
    """(s, v) with skew(w) = s·skew(v) and v the least (word_key) of w and its transpose word:
    wᵀ = σ·w* (w* the reversed word of adjoint letters), so skew(w*) = −σ·skew(w); s = 0 when the
    skew part vanishes (w* = w with σ = 1: a symmetric word, such as the identity)."""
    sigma, ws = star_word(w)
    if ws == w and all(a is b for a, b in zip(ws, w)):
        return (0, w) if sigma == 1 else (1, w)
    return (1, w) if word_key(w) <= word_key(ws) else (-sigma, ws)


def is_operator(L: Any) -> bool:
    return isinstance(L, OperatorLetter)


def apply_operator(op: str, p: NCPoly) -> NCPoly:
    """𝔸(p) for an n×n (or r×r: the operator of that name on so(r)) polynomial p: 𝔸(skew p), linear
    in p, one canonical letter per word (traces are scalars and stay factors)."""
    if p.row != p.col or p.row not in ("n", "r"):
        raise TypeError(f"the operator {op} acts on so(n) or so(r), not on a {p.row}×{p.col} polynomial")
    t = p.row
    out: dict = {}
    for (tm, w), c in p.terms.items():
        tm, w, sp = _scalar_pieces(tm, w)
        if sp == 0:
            continue
        s, v = operator_rep(w)
        s *= sp
        if s == 0:
            continue
        k = (tm, (operator_letter(op, v, t),))
        x = c if s == 1 else cneg(c)
        out[k] = csum(out[k], x) if k in out else x
    return NCPoly(nonzero_terms_raw(out), t, t)


def _scalar_pieces(tm: Traces, w: Word) -> tuple[Traces, Word, int]:
    """An argument word that passes through a 1×1 space twice, u·(x)·v with x 1×1, as tr(x)·u·v (a 1×1
    matrix is its own trace, and 𝔸 is linear): (traces, word, sign), sign 0 when a piece vanishes.  So
    the argument of an operator letter never holds a scalar piece (E₂ᵀE₂, E₁ᵀXᵀPE₂...), which the rules,
    acting outside operator letters, would leave as it is."""
    ks = [k for k in range(len(w)) if w[k].row == SCALAR]
    if len(ks) < 2:
        return tm, w, 1
    sign = 1
    for a, b in zip(ks, ks[1:]):
        s, rep = cycle_rep(w[a:b])
        if s == 0:
            return tm, w, 0
        sign *= s
        tm = merge_traces(tm, (rep,))
    return tm, w[:ks[0]] + w[ks[-1]:], sign


def nonzero_terms_raw(terms: dict) -> dict:
    return {k: c for k, c in terms.items() if not coef_is_zero(c)}


def operator_pair_rep(w: Word) -> tuple[int, Word] | None:
    """The symmetry of 𝔸 as a normal form of traces: tr(𝔸⟨u⟩V) = tr(𝔸(skew u) skew V) is symmetric
    in (u, V), so a cyclic word with exactly one operator letter 𝔸⟨u⟩ and no other is represented by
    (s, (𝔸⟨a⟩,) + b) with {a, b} the canonical words of {u, V} (:func:`operator_rep`), a the one
    without operator letters if one has some (u may hold nested ones), else the lesser in word_key
    order; s = 0 when the trace vanishes.  None when w has no operator letter or more than one.
    (When b holds operators, :func:`cycle_rep` takes the rotation representative of the result.)"""
    ops = [k for k, L in enumerate(w) if isinstance(L, OperatorLetter)]
    if len(ops) != 1:
        return None
    j = ops[0]
    L = w[j]
    V = w[j + 1:] + w[:j]
    s1, u = operator_rep(L.argument)
    s2, v = operator_rep(V)
    if s1 == 0 or s2 == 0:
        return 0, w
    a, b = sorted((u, v), key=lambda x: (operator_letters_in(x), word_key(x)))
    return s1 * s2, (operator_letter(L.operator, a, L.row),) + b


def operator_letters_in(w: Word) -> bool:
    return any(isinstance(L, OperatorLetter) for L in w)


def _operator_images(p: NCPoly, full: dict, image: Any) -> None:
    """Add to ``full`` the image of every operator letter of p whose argument meets ``full``:
    𝔸⟨u⟩ ↦ 𝔸(image(u)) (linearity; the operator itself is constant)."""
    def visit(L: Letter) -> bool:
        if L in full:
            return True
        if not isinstance(L, OperatorLetter):
            return False
        moved = False
        for x in L.argument:
            moved = visit(x) or moved
        if moved:
            full[L] = apply_operator(L.operator, image(NCPoly.word(L.argument, L.row)))
        return moved

    for L in p.letters():
        visit(L)
