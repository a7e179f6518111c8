"""The dimension-free scene: claims run on letters of a free algebra.

:class:`FreeScene` offers the matrix interface of
:class:`stiefelsym.scene.Scene` (X, P, A, Φ, Ψ, λ, κ, ε, traces, resolvents,
Dirac flows, derivatives along flows) with 1×1 :class:`~stiefelsym.backends.matrix.Mat`
whose entry is a word polynomial (an n×r, r×n, n×n or r×r block), and 2×2
``Mat`` of them for 2r×2r block matrices.  The field :class:`FreeField`
normalizes entries with the standard rewriting system (the constraints
(cond_XP) and the resolvent identities), which is confluent (see the tests),
so a residual is zero for every n, r and every symmetric A iff its normal form
is 0, up to consequences of the constraints that the rules do not generate.
The metric realization (cond_XP2) has its own rules and the multipliers of its
flows (:mod:`.metric`).  Objects that need coordinates raise :class:`NeedsCoordinates`.
"""
from __future__ import annotations

import re
from fractions import Fraction
from typing import Any, Callable, Mapping

import numpy as np
import symengine as se

from stiefelsym.backends.fields import Dual, DualField, Field
from stiefelsym.backends.matrix import CoordinateTracker, Mat, definite
from stiefelsym.ir.trace import TraceRefused
from stiefelsym.scene import (ENGINE_CHECK_DEPTH, FRESH, check_generic_kind, user_name, TANGENT_KEYS, USER_SCALAR, Flow, HermitianComponents, PaperObjects, _fresh_key, _number,
                              engine_check, map_entries)
from stiefelsym.free.algebra import (LEADING, Letter, NCPoly, NeedsCoordinates, OperatorLetter, apply_operator, as_coef, divisor, coef_latex, derivation,
                      letter_pair, mark_moving, record_refusal, refuse, skew_letter, substitute, symmetric_letter, trace)
from stiefelsym.free.mat import FreeBackend, FreeDualBackend, entry_of, one_block
from stiefelsym.free.rewriting import (_NONZERO_NUMBER_TYPES, _SIMPLE, Certificate, Order, Reduction,
                        RewritingError, RewritingSystem, SharedMemos, nonzero_terms, simplify_coef)
from stiefelsym.free.traces import gradient
from stiefelsym.free.columns import COLUMNS, COVECTORS, DN, KW, WK, WKt, SPLIT, SREF, ER, LEAD, LEADt, ERt, canonical, canonical_form, column_hypotheses
from stiefelsym.free.letters import (X, Xt, P, Pt, A, Y, Yt, Q, Qt, AINV, DX, DXt, DY, DYt, DXd, DXdt, DYd, DYdt, DOUBLE, CU, CUt,
                      CV, CVt, CUd, CUdt, CVd, CVdt, COMPLEX, COMPLEX_HYPOTHESES, W0_RE, W0_IM, PI, LAMBDA,
                      FreeSolveError, _i, _w, hypothesis, _by, _holds_letter)

Function = Callable[[Any], Any]


def _generic_tex(name: str) -> str:
    """A generic letter's name in a derivation: a trailing number and what follows an underscore as a subscript
    (W1 as W_1, eta_n as eta_n, W1_b as W_{1,b}), and the elements of an inverse statement (InverseY1,
    InverseX2: the y and x of "op(inv(y)) = y") as y_1, x_2."""
    head, _, rest = name.partition("_")
    m = re.fullmatch(r"(Inverse)?([A-Za-z]+?)(\d*)", head)
    if m is None:
        return name.replace("_", r"\_")
    base = m.group(2).lower() if m.group(1) and len(m.group(2)) == 1 else m.group(2)
    if len(base) > 1:
        base = rf"\mathit{{{base}}}"
    parts = rest.split("_") if "_" in name else []
    if any(not x for x in parts):
        return name.replace("_", r"\_")       # an empty part (x_, a__b): the name as it is written
    sub = ",".join(x for x in (m.group(3), *parts) if x)
    return base + (f"_{{{sub}}}" if sub else "")


def _raw(x: Any) -> Any:
    """What a traced function hands back is the engine's own value."""
    return x

SCALAR_T = "1"
COND_XX = "X^T X = I_r (cond_XP)"
COND_XP = "X^T P + P^T X = 0 (cond_XP)"


#: the letters a flow may move (the points of T*V); A, A^-1 and the resolvents are constants
MOVABLE = ("X", "P", "Y", "Q")


def _vanishes_part(p: Any) -> bool:
    """Whether a part of a dual number is 0 (an exact zero or the zero polynomial)."""
    return p.is_zero_raw() if isinstance(p, NCPoly) else p == 0


def _check_movable(key: Any, tracker: Any) -> None:
    """A key of a tangent vector: one of the letters the algebra moves; the complex point (Zc, Zc_dot),
    which the coordinate scenes move, is left to them (a refusal: undecided); any other key is refused
    as the coordinate scenes refuse it (TraceRefused)."""
    if key in MOVABLE:
        return
    if key in TANGENT_KEYS:
        raise refuse(f"a tangent vector that moves the complex point ({key}): the dimension-free algebra "
                     f"moves {', '.join(MOVABLE)}", tracker)
    record_refusal(f"a tangent vector that moves {key!r}", tracker)
    raise TraceRefused(f"a tangent vector moves {', '.join(MOVABLE)}, not {key!r} "
                       "(A and the resolvents are constant along flows)")


class FreeSize:
    """A size k·n or k·r of the dimension-free scene.

    It sizes identity and zero blocks and nothing else: comparing sizes, using one as a
    number, in arithmetic or as a loop bound needs coordinates (a fixed n, r)."""

    __slots__ = ("kind", "k", "_tracker")

    def __init__(self, kind: str, k: int = 1, tracker: CoordinateTracker | None = None) -> None:
        self.kind, self.k, self._tracker = kind, k, tracker

    def __mul__(self, c: Any) -> "FreeSize":
        if isinstance(c, int) and not isinstance(c, bool) and c >= 1:
            return FreeSize(self.kind, self.k * c, self._tracker)
        return self._arithmetic()

    __rmul__ = __mul__

    def _as_scalar(self) -> str:
        """The way to write the size as a scalar of the claim, which the free algebra holds: a trace."""
        return f"{self.k if self.k > 1 else ''}s.tr(s.I{self.kind})"

    def _arithmetic(self, *args: Any) -> Any:
        raise refuse(f"the size {self} in arithmetic (as a scalar of the claim it is {self._as_scalar()})",
                     self._tracker)

    def _number(self, *args: Any) -> Any:
        raise refuse(f"using the size {self} as a number (as a loop bound or an index it needs fixed sizes; as a "
                     f"scalar of the claim it is {self._as_scalar()})", self._tracker)

    def _refuse(self, *args: Any) -> Any:
        raise refuse(f"using the size {self} as a number", self._tracker)

    __eq__ = __ne__ = __lt__ = __le__ = __gt__ = __ge__ = _refuse
    __add__ = __radd__ = __sub__ = __rsub__ = __truediv__ = __pow__ = _arithmetic
    __int__ = __index__ = __float__ = _number
    __neg__ = _arithmetic
    __floordiv__ = __rfloordiv__ = __mod__ = __bool__ = _refuse
    __hash__ = object.__hash__

    def __repr__(self) -> str:
        return f"{self.k if self.k > 1 else ''}{self.kind}"


def _standard_rules() -> tuple:
    """The rules of (cond_XP), built once: add_rule checks their types, their order and their
    cofactors; the rules are immutable, so every scene's system may share them."""
    global _STANDARD_RULES
    if _STANDARD_RULES is None:
        system = RewritingSystem(Order([X, P, A, Xt, Pt]))
        system.add_rule((Xt, X), _i("r"), COND_XX, name="XtX", cofactors=[_by(hypothesis("XtX"))])
        system.add_rule((Pt, X), -_w(Xt, P), COND_XP, name="PtX", cofactors=[_by(hypothesis("XtP+PtX"))])
        _STANDARD_RULES = tuple(system.rules)
    return _STANDARD_RULES


#: the size of the memo of simplified coefficients up to which nonzero numbers are added to it
_SIMPLE_NUMBERS_MAX = 50_000

_STANDARD_RULES: tuple | None = None
#: the polynomial of each letter (the word of one letter)
_LETTER_POLYS: dict = {}
#: the memos of every standard system (until it gets a rule of its own)
_STANDARD_MEMOS = SharedMemos()


class _LetterBook(dict):
    """A scene's letters by name; each one is admitted to the shared memos of the standard
    systems (see SharedMemos.admit: a name with another meaning than the memos' empties them)."""

    def __setitem__(self, name: str, letter: Letter) -> None:
        _STANDARD_MEMOS.admit(letter)
        super().__setitem__(name, letter)

    def setdefault(self, name: str, letter: Letter) -> Letter:
        if name not in self:
            self[name] = letter
        return self[name]

    def update(self, *args: Any, **kw: Any) -> None:
        for name, letter in dict(*args, **kw).items():
            self[name] = letter


#: the refusal of M.inv() (a linear solve) in the free algebra, with what to write for a proof for all n, r
INVERSE_NEEDS_COORDINATES = ("solving a linear system entrywise (M.inv() of a matrix other than a resolvent: "
                             "write (μI − A)⁻¹ as s.resolvent(μ), and (A² − λ²)⁻¹ as (R(−λ) − R(λ))/(2λ), "
                             "for a proof for every n, r)")


def standard_system() -> RewritingSystem:
    """(cond_XP) as rules: XᵀX → I_r, PᵀX → −XᵀP (order X < P < A < Xᵀ < Pᵀ); a fresh system
    (its own order and record of what it used) on the shared, checked rules, with the memos of
    every standard system until it gets a rule of its own."""
    return RewritingSystem(Order([X, P, A, Xt, Pt]), _standard_rules(), shared=_STANDARD_MEMOS)


def resolvent_letter(mu: Any, k: int = 1) -> Letter:
    """The letter R_mu = (mu I_n - A)^{-1} (symmetric n×n); k > 1 tells apart coefficients that print alike."""
    c = as_coef(mu)
    return symmetric_letter(f"R[{c}]" + (f"#{k}" if k > 1 else ""), "n", rf"(\left({coef_latex(c)}\right) \mathbf{{I}}_n - A)^{{-1}}"
                            if not c.is_Symbol else rf"({coef_latex(c)} \mathbf{{I}}_n - A)^{{-1}}")


def add_resolvent(system: RewritingSystem, mu: Any, resolvents: dict[Letter, Any],
                  ainv: bool = False) -> Letter:
    """Add R = (mu I − A)^{-1} with A R, R A → mu R − I and the resolvent identity with the others."""
    mu = as_coef(mu)
    for S, nu in resolvents.items():   # the same resolvent iff the same coefficient, never by name
        if simplify_coef(nu - mu) == 0:
            return S
    R = resolvent_letter(mu)
    taken = {str(S) for S in resolvents}
    k = 1
    while str(R) in taken:             # another coefficient that prints alike: a fresh letter
        k += 1
        R = resolvent_letter(mu, k)
    if simplify_coef(mu) == 0:
        system.order.add(AINV)         # A^{-1} < R_0, so that R_0 -> -A^{-1} whenever both are present
    system.order.add(R)
    reason = f"A R = R A = mu R - I_n for R = (mu I_n - A)^(-1), mu = {mu} (definition of the resolvent)"
    left, right = hypothesis("res_left", R, mu), hypothesis("res_right", R, mu)
    # A R − (mu R − I) = −[(mu I − A) R − I], and likewise on the right
    system.add_rule((A, R), _w(R) * mu - _i("n"), reason, name=f"A{R}", cofactors=[_by(left, -1)])
    system.add_rule((R, A), _w(R) * mu - _i("n"), reason, name=f"{R}A", cofactors=[_by(right, -1)])
    for S, nu in resolvents.items():
        if simplify_coef(nu - mu) == 0:
            continue
        rhs = (_w(R) - _w(S)) * (se.Integer(1) / divisor(nu - mu))
        why = f"resolvent identity R_mu R_nu = (R_mu - R_nu)/(nu - mu), mu = {mu}, nu = {nu} (mu != nu)"
        s_left, s_right = hypothesis("res_left", S, nu), hypothesis("res_right", S, nu)
        # (nu − mu) R S − R + S = R [(nu I − A) S − I] − [R (mu I − A) − I] S
        system.add_rule((R, S), rhs, why, name=f"{R}{S}",
                        cofactors=[_by(s_left, 1 / (nu - mu), left=(R,)), _by(right, -1 / (nu - mu), right=(S,))])
        # (mu − nu) S R − S + R = S [(mu I − A) R − I] − [S (nu I − A) − I] R
        system.add_rule((S, R), rhs, why, name=f"{S}{R}",
                        cofactors=[_by(left, 1 / (mu - nu), left=(S,)), _by(s_right, -1 / (mu - nu), right=(R,))])
    if ainv:
        _ainv_resolvent_rules(system, R, mu)
    resolvents[R] = mu
    return R


def _ainv_resolvent_rules(system: RewritingSystem, R: Letter, mu: Any) -> None:
    """The rules that relate A^{-1} and R = (mu I − A)^{-1}: R_0 = −A^{-1} at mu = 0, else
    A^{-1} R = R A^{-1} = (R + A^{-1})/mu."""
    left, right = hypothesis("res_left", R, mu), hypothesis("res_right", R, mu)
    if simplify_coef(mu) == 0:
        why = "R_0 = (0 I_n - A)^(-1) = -A^(-1) (the resolvent at 0 is minus the inverse)"
        # R_0 + A^{-1} = −A^{-1} [(0 I − A) R_0 − I] − [A^{-1} A − I] R_0
        cofactors = [_by(left, -1, left=(AINV,)), _by(hypothesis("AinvA"), -1, right=(R,))]
        if system.order.less((AINV,), (R,)):   # always so for add_resolvent's order
            system.add_rule((R,), -_w(AINV), why, name=f"{R}=-Ainv", cofactors=cofactors)
        else:
            system.add_rule((AINV,), -_w(R), why, name=f"Ainv=-{R}", cofactors=cofactors)
        return
    rhs = (_w(R) + _w(AINV)) * (se.Integer(1) / divisor(mu))
    why = f"A^(-1) R_mu = R_mu A^(-1) = (R_mu + A^(-1))/mu, mu = {mu} (mu != 0)"
    # mu A^{-1} R − R − A^{-1} = A^{-1} [(mu I − A) R − I] + [A^{-1} A − I] R
    system.add_rule((AINV, R), rhs, why, name=f"Ainv{R}",
                    cofactors=[_by(left, 1 / mu, left=(AINV,)), _by(hypothesis("AinvA"), 1 / mu, right=(R,))])
    # mu R A^{-1} − R − A^{-1} = [R (mu I − A) − I] A^{-1} + R [A A^{-1} − I]
    system.add_rule((R, AINV), rhs, why, name=f"{R}Ainv",
                    cofactors=[_by(right, 1 / mu, right=(AINV,)), _by(hypothesis("AAinv"), 1 / mu, left=(R,))])


# ---------------------------------------------------------------------------
class FreeField(Field):
    """Entries are word polynomials; normal form by the scene's rewriting system."""

    name = "free"
    exact = True
    #: entries are blocks for every n, r: no coordinates (no entries, no shapes)
    coordinates = False

    def __init__(self, system: RewritingSystem, lazy: bool = False,
                 tracker: CoordinateTracker | None = None) -> None:
        self.system = system
        #: lazy: keep expressions as built (reduce only when asked), so that a residual can be
        #: shown before its reduction, with the rules that reduce it
        self.lazy = lazy
        #: the record of the scene (refusals of the field are recorded there before they are raised)
        self.tracker = tracker

    def native_backend(self) -> FreeBackend:
        """The whole-matrix backend (:mod:`.mat`): the matrices stay :class:`Mat`."""
        return FreeBackend(self, values=type(self) is FreeField)

    def const(self, q: int | Fraction) -> Any:
        return as_coef(Fraction(q))

    def param(self, name: str, rng=None) -> Any:
        return se.Symbol(name)

    def reciprocal(self, c: Any) -> Any:
        """1/c through the free algebra's door for divisors (:func:`~stiefelsym.free.algebra.divisor`): a number
        of the scene that is identically 0 raises ZeroDivisionError (1/0 would be nan or zoo, a normal form that is
        never 0), one that may be 0 at some size is refused."""
        if isinstance(c, NCPoly):
            return NCPoly.scalar(1) / c
        k = as_coef(c)
        if k is None:           # (a number of a tangent scene: its own division)
            return self.const(1) / c
        return se.Integer(1) / divisor(k)

    def normalize(self, x: Any) -> Any:
        if type(x) is NCPoly:
            if self.lazy:   # collect coefficients only
                numbers, simple = _NONZERO_NUMBER_TYPES, _SIMPLE   # is_simplified, inlined
                try:
                    if simple.issuperset(x.terms.values()):   # every coefficient (one pass in C)
                        return x
                    for c in x.terms.values():
                        if c not in simple:
                            if type(c) not in numbers:
                                return NCPoly._raw(nonzero_terms(x.terms), x.row, x.col)
                            if len(simple) < _SIMPLE_NUMBERS_MAX:
                                simple.add(c)   # a nonzero number: simplify_coef returns it unchanged
                except TypeError:   # an unhashable coefficient: not known to be simplified
                    return NCPoly._raw(nonzero_terms(x.terms), x.row, x.col)
                return x    # polynomials are immutable: nothing to collect, the same one
            return self.system.normal_form(x)
        c = as_coef(x)
        return simplify_coef(c) if c is not None else x

    def is_zero(self, x: Any) -> bool:
        if isinstance(x, NCPoly):
            return self.system.is_zero(x)
        if type(x) is Dual:             # a value of a tangent scene: zero when both parts are
            return self.is_zero(x.a) and self.is_zero(x.b)
        c = as_coef(x)
        if c is None:
            raise TypeError(f"is_zero of a {type(x).__name__} on the free algebra")
        return simplify_coef(c) == 0

    def star(self, x: Any) -> Any:
        return x.star() if isinstance(x, NCPoly) else x

    def entry_trace(self, x: Any) -> Any:
        return trace(x) if isinstance(x, NCPoly) else x

    def describe(self, x: Any) -> str:
        return x.latex() if isinstance(x, NCPoly) else str(x)

    def solve(self, M, B):
        raise refuse(INVERSE_NEEDS_COORDINATES, self.tracker)

    def rank(self, M):
        raise refuse("a rank", self.tracker)


class FreeDualField(DualField):
    """a + bε over the free field, with the involution and the trace."""

    coordinates = False

    def native_backend(self) -> FreeDualBackend:
        return FreeDualBackend(self)

    def star(self, x: Any) -> Any:
        x = self.lift(x)
        return Dual(self.base.star(x.a), self.base.star(x.b))

    def entry_trace(self, x: Any) -> Any:
        x = self.lift(x)
        return Dual(self.base.entry_trace(x.a), self.base.entry_trace(x.b))

    def solve(self, M, B):
        raise refuse(INVERSE_NEEDS_COORDINATES, self.base.tracker)

    def rank(self, M):
        raise refuse("a rank", self.base.tracker)


# ---------------------------------------------------------------------------
#: the momentum maps Φ, Ψ of a lazy free scene: (entry, index spaces), built once (see _constant_object)
_CONSTANT_OBJECTS: dict[str, tuple | None] = {"Phi": None, "Psi": None}


def _component(flow: Any, key: str, poly: NCPoly, tracker: Any) -> NCPoly:
    """The flow's component for the letter ``key`` (the polynomial ``poly``), as a polynomial of its shape
    (0 where the flow has none); a component of another shape is refused and recorded."""
    dot = flow.get(key)
    if dot is None:
        return NCPoly.zero(poly.row, poly.col)
    b = entry_of(dot) if isinstance(dot, Mat) else dot
    if not isinstance(b, NCPoly) or b.shape != poly.shape:
        record_refusal(f"a flow whose {key}-component is not a {poly.row}×{poly.col} block", tracker)
        raise TypeError(f"the flow's {key}-component must be a {poly.row}×{poly.col} polynomial")
    return b


class FreeScene(PaperObjects):
    """T*V_{n,r} for all n, r at once: the scene interface over the free algebra."""

    chart = "free"
    #: (cond_XP), or "metric": (cond_XP2) with A positive definite (see :mod:`.metric`)
    realization = "standard"

    def __init__(self, tracker: CoordinateTracker | None = None, system: RewritingSystem | None = None,
                 realization: str = "standard", lazy: bool = False, columns: int = 0, square: bool = False) -> None:
        if realization not in ("standard", "metric"):
            raise NeedsCoordinates(f"the {realization!r} realization of T*V")
        if realization == "metric" and (columns or square):
            raise NeedsCoordinates("the metric realization of T*V with the columns of R^r or at r = n")
        if realization == "metric" and system is None:
            from stiefelsym.free.metric import metric_system
            system = metric_system()
        if system is None:
            # r = n: the order P < X (for the rule XP^T -> -PX^T); the standard rules decrease in it too
            system = (RewritingSystem(Order([P, X, A, Xt, Pt]), _standard_rules()) if square
                      else standard_system())
        self.system = system
        self._tracker = tracker if tracker is not None else CoordinateTracker()
        self._field: Field = FreeField(self.system, lazy, self._tracker)
        self.options: dict[str, Any] = {}
        self.params: dict[str, Any] = {}
        self._cache: dict[str, Any] = {}
        self._letters: dict[Letter, Mat] = {}
        self._resolvents: dict[Letter, Any] = {}
        #: the spectral parameters that move with the point: (normal form, the symbol standing for it)
        self._moving: list[tuple[NCPoly, Any]] = []
        self._extras: set[str] = set()
        self._named: dict[str, Letter] = _LetterBook()
        #: the multipliers Λ of the metric realization's flows, letters with their Sylvester relations ρ
        self._sylvester: dict = {}
        if realization == "metric":
            self.realization = "metric"
            self._extras |= {"metric", "ainv"}   # A^{-1} and its rules belong to the metric system
        #: r given (1 or 2: the claim is stated at that r only; 0: every r): the columns E_1, ..., E_r
        #: of R^r are letters, and E_1 E_1^T + ... + E_r E_r^T = I_r a hypothesis of normal forms
        if columns not in (0, 1, 2):
            raise ValueError(f"columns: the fixed r, 1 or 2 (0 for every r), not {columns!r}")
        self.columns = columns
        #: r = n is given (T*SO(n) = T*V(n, n)): X X^T = I_n, and P X^T = -X P^T
        self.square = square
        if square:
            self._square_rules()

    field = property(lambda self: self._field, doc="the free algebra (read-only)")
    tracker = property(lambda self: self._tracker, doc="the record of looks at coordinates (read-only)")

    def __getattr__(self, name: str) -> Any:
        """Coordinate-scene API this backend does not offer (jacobian, general_params, ...)."""
        from stiefelsym.scene import Scene

        if not name.startswith("__") and hasattr(Scene, name):
            raise refuse(f"Scene.{name}", self.__dict__.get("_tracker"))
        raise AttributeError(name)

    # -- primitives -----------------------------------------------------------
    def _cached(self, key: str, build: Callable[[], Any]) -> Any:
        hit = self._cache.get(key)
        if hit is None:
            if key in _CONSTANT_OBJECTS and type(self) is FreeScene and self._field.lazy:
                hit = self._cache[key] = self._constant_object(key, build)
            else:
                hit = self._cache[key] = build()
        return hit

    def _constant_object(self, key: str, build: Callable[[], Any]) -> Any:
        """An object of the paper that is one polynomial in the letters X, P (the momentum maps):
        built once by its definition on a lazy scene (lazy scenes keep expressions as built, in
        letters every scene shares, so every one builds the same polynomial), wrapped per scene."""
        hit = _CONSTANT_OBJECTS[key]
        if hit is None:
            value = build()
            if not (isinstance(value, Mat) and value._shape() == (1, 1) and not value._coords
                    and value._field is self._field):
                return value
            hit = _CONSTANT_OBJECTS[key] = (entry_of(value), value.tags)
        return one_block(hit[0], self._field, hit[1], self._tracker)

    def _prim(self, key: str, poly: NCPoly) -> Mat:
        """The 1×1 matrix holding a primitive letter (overridden by the tangent scene)."""
        return one_block(poly, self.field, poly.shape, self.tracker)

    def _letter(self, L: Letter) -> Mat:
        hit = self._letters.get(L)
        if hit is None:
            self._named[str(L)] = L
            poly = _LETTER_POLYS.get(L)
            if poly is None or next(iter(poly.terms))[1][0] is not L:   # letters that print alike differ
                poly = _LETTER_POLYS[L] = _w(L)   # polynomials are immutable: one per letter
            hit = self._letters[L] = self._prim(str(L), poly)
        return hit

    @property
    def n(self) -> "FreeSize":
        """The size n: good for sizing blocks (s.zeros(s.n, s.r), 2 * s.r), nothing else."""
        return FreeSize("n", 1, self._tracker)

    @property
    def r(self) -> "FreeSize":
        """The size r: good for sizing blocks, nothing else."""
        return FreeSize("r", 1, self._tracker)

    @property
    def X(self) -> Mat:
        return self._letter(X)

    @property
    def P(self) -> Mat:
        return self._letter(P)

    @property
    def A(self) -> Mat:
        return self._letter(A)

    def _standard_only(self, what: str) -> None:
        """Refuse (recorded) what the free scene offers for the standard realization (cond_XP) only."""
        if self.realization != "standard":
            raise refuse(f"{what} in the {self.realization} realization of T*V (offered for (cond_XP) only)",
                         self.tracker)

    def _second_point(self) -> None:
        self._standard_only("a second point Y, Q")
        if "second" not in self._extras:
            self._extras.add("second")
            self.system.order.add(Y)
            self.system.order.add(Q)
            self.system.order.add(Yt)
            self.system.order.add(Qt)
            self.system.add_rule((Yt, Y), _i("r"), "Y^T Y = I_r (second point)", name="YtY",
                                 cofactors=[_by(hypothesis("YtY"))])
            self.system.add_rule((Qt, Y), -_w(Yt, Q), "Y^T Q + Q^T Y = 0 (second point)", name="QtY",
                                 cofactors=[_by(hypothesis("YtQ+QtY"))])

    @property
    def Y(self) -> Mat:
        """A second point (Y, Q) of T*V_{n,r} (free letters with its own constraints)."""
        self._second_point()
        return self._letter(Y)

    @property
    def Q(self) -> Mat:
        self._second_point()
        return self._letter(Q)

    def _column_letters(self) -> None:
        if "columns" not in self._extras:
            self._extras.add("columns")
            for L in COLUMNS[:self.columns] + COVECTORS[:self.columns]:
                self.system.order.add(L)
            hyps = column_hypotheses()
            for i, Eit in enumerate(COVECTORS[:self.columns], start=1):
                for j, Ej in enumerate(COLUMNS[:self.columns], start=1):
                    rhs = _i(SCALAR_T) if i == j else NCPoly.zero(SCALAR_T, SCALAR_T)
                    self.system.add_rule((Eit, Ej), rhs, f"E_{i}^T E_{j} = {int(i == j)} (the basis of R^r)",
                                         name=f"E{i}tE{j}", cofactors=[_by(hyps[f"E{i}tE{j}"])])

    def _square_rules(self) -> None:
        """At r = n: XXᵀ → I_n (X is orthogonal) and XPᵀ → −PXᵀ, because
        XPᵀ + PXᵀ = X(XᵀP + PᵀX)Xᵀ − (XXᵀ − I)PXᵀ − XPᵀ(XXᵀ − I) (in the order P < X of the scene at
        r = n: the other direction loops in traces, tr(XᵀPXᵀP) → tr(XᵀXPᵀP) ↺)."""
        h, g = hypothesis("XXt"), hypothesis("XtP+PtX")
        why = "X X^T = I_n: X is square (r = n, where the claim is stated)"
        self.system.add_rule((X, Xt), _i("n"), why, name="XXt", cofactors=[_by(h)])
        self.system.add_rule((X, Pt), -_w(P, Xt), "X P^T = -P X^T: X^T P is skew and X X^T = I_n (r = n)",
                             name="XPt", cofactors=[_by(g, 1, left=(X,), right=(Xt,)), _by(h, -1, right=(P, Xt)),
                                                    _by(h, -1, left=(X, Pt))])
        # XᵀPXᵀ + Pᵀ = (XᵀP + PᵀX)Xᵀ − Pᵀ(XXᵀ − I)
        self.system.add_rule((Xt, P, Xt), -_w(Pt), "X^T P X^T = -P^T X X^T = -P^T (r = n)", name="XtPXt",
                             cofactors=[_by(g, 1, right=(Xt,)), _by(h, -1, left=(Pt,))])
        # the completion of P^T X P^T two ways (Knuth-Bendix: with it the word rules are confluent)
        self.system.add_rule((Pt, P, Xt), _w(Xt, P, Pt), "P^T P X^T = X^T P P^T (r = n; completion of PtX, XPt)",
                             name="PtPXt", cofactors=[_by(g, -1, right=(Pt,)), _by(g, 1, left=(Pt, X), right=(Xt,)),
                                                      _by(h, -1, left=(Pt,), right=(P, Xt)), _by(h, -1, left=(Pt, X, Pt))])

    def last_column(self) -> Mat:
        """E_r, the last column of I_r, as an r×1 letter (E_rᵀE_r = 1): XE_r is the last column of X."""
        if "last" not in self._extras:
            self._extras.add("last")
            self.system.order.add(ER)
            self.system.order.add(ERt)
            self.system.add_rule((ERt, ER), _i(SCALAR_T), "E_r^T E_r = 1 (the last column of I_r)", name="ErtEr",
                                 cofactors=[_by(column_hypotheses()["ErtEr"])])
        self._named.setdefault(str(ER), ER)
        return self._cached("column:last", lambda: self._const_block(_w(ER), ("r", "?")))

    def projector_n(self) -> Mat:
        """D, an orthogonal projector of ℝⁿ, as an n×n symmetric letter with the rule D² → D and nothing else:
        a proof holds for every orthogonal projector of ℝⁿ (every subspace, every rank)."""
        if "projector_n" not in self._extras:
            self._extras.add("projector_n")
            self.system.order.add(DN)
            self.system.add_rule((DN, DN), _w(DN), "D^2 = D (D an orthogonal projector of R^n)", name="DnDn",
                                 cofactors=[_by(hypothesis("DnDn"))])
        self._named.setdefault(str(DN), DN)
        return self._cached("projector_n", lambda: self._const_block(_w(DN), ("n", "n")))

    def _kernel_letters(self) -> None:
        """W (n×r) and K (n×n symmetric) with the rules KW → 0 and WᵀK → 0 and nothing else."""
        if "kernel" not in self._extras:
            self._extras.add("kernel")
            for L in (WK, KW, WKt):
                self.system.order.add(L)
            self.system.add_rule((KW, WK), NCPoly.zero("n", "r"), "K W = 0 (K annihilates W)", name="KwWk",
                                 cofactors=[_by(hypothesis("KwWk"))])
            self.system.add_rule((WKt, KW), NCPoly.zero("r", "n"), "W^T K = 0 (the transpose of K W = 0)",
                                 name="WktKw", cofactors=[_by(hypothesis("WktKw"))])
        for L in (WK, WKt, KW):
            self._named.setdefault(str(L), L)

    def kernel_frame(self) -> Mat:
        """W, a generic constant n×r matrix, as a letter (with Wᵀ) tied to the annihilator K of
        :meth:`kernel_annihilator` by KW = 0 and nothing else."""
        self._kernel_letters()
        return self._cached("kernel:W", lambda: self._const_block(_w(WK), ("n", "r")))

    def kernel_annihilator(self) -> Mat:
        """K, a symmetric n×n letter with KW = 0 (and WᵀK = 0) and nothing else: a proof holds for every
        symmetric K that annihilates W (the projector onto ker Wᵀ and its multiples among them)."""
        self._kernel_letters()
        return self._cached("kernel:K", lambda: self._const_block(_w(KW), ("n", "n")))

    def reflection(self) -> Mat:
        """S, an orthogonal symmetry of ℝⁿ that commutes with A, as an n×n symmetric letter ranked after every
        other letter, with the rules S² → I_n, SA → AS and SR → RS for every resolvent R (from SA = AS and the
        resolvent's definition): a proof holds for every S = Sᵀ with S² = I_n and SA = AS (with A diagonal:
        every reflection S_i of a coordinate hyperplane, and every product of them)."""
        if "reflection" not in self._extras:
            self._extras.add("reflection")
            self.system.order.add_last(SREF)
            self.system.add_rule((SREF, SREF), _i("n"), "S^2 = I_n (S an orthogonal symmetry)", name="SrefSref",
                                 cofactors=[_by(hypothesis("SrefSref"))])
            self.system.add_rule((SREF, A), _w(A, SREF), "S A = A S (S commutes with A)", name="SrefA",
                                 cofactors=[_by(hypothesis("SrefA"))])
            for R in list(self._resolvents):
                self._reflection_resolvent_rule(R)
        self._named.setdefault(str(SREF), SREF)
        return self._cached("reflection", lambda: self._const_block(_w(SREF), ("n", "n")))

    def _reflection_resolvent_rule(self, R: Letter) -> None:
        """S R → R S for R = (μI − A)⁻¹: SR − RS = R(SA − AS)R − [R(μI − A) − I]SR + RS[(μI − A)R − I]."""
        if (SREF, R) in self.system._lhs:
            return
        mu = self._resolvents[R]
        self.system.add_rule((SREF, R), _w(R, SREF), "S R = R S (S commutes with A, so with its resolvents)",
                             name=f"Sref{R}", cofactors=[
                                 _by(hypothesis("SrefA"), 1, left=(R,), right=(R,)),
                                 _by(hypothesis("res_right", R, mu), -1, right=(SREF, R)),
                                 _by(hypothesis("res_left", R, mu), 1, left=(R, SREF))])

    def split_projector(self, i: int) -> Mat:
        """D (i = 0) or C (i = 1), the orthogonal projectors of ℝʳ onto the blocks of a splitting
        ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂}, as r×r symmetric letters with the rules D² → D, C² → C, DC → 0, CD → 0 and
        nothing else (not D + C = I_r): a proof holds for every pair of orthogonal blocks of ℝʳ."""
        if i not in (0, 1):
            raise ValueError(f"a splitting of R^r into two blocks has no block {i + 1}")
        if "split" not in self._extras:
            self._extras.add("split")
            hyps = column_hypotheses()
            for L in SPLIT:
                self.system.order.add(L)
            for L in SPLIT:
                for M in SPLIT:
                    rhs = _w(L) if L == M else NCPoly.zero("r", "r")
                    self.system.add_rule((L, M), rhs, f"{L.latex}{M.latex} = {L.latex if L == M else 0} (the "
                                         "projectors of two orthogonal blocks of R^r)", name=f"{L}{M}",
                                         cofactors=[_by(hyps[f"{L}{M}"])])
        L = SPLIT[i]
        self._named.setdefault(str(L), L)
        return self._cached(f"column:split{i}", lambda: self._const_block(_w(L), ("r", "r")))

    def leading_columns(self) -> Mat:
        """(E_1, ..., E_{r−1}), the first r − 1 columns of I_r, as an r×(r−1) letter E_{<r}, with the last
        column E_r: E_{<r}ᵀE_{<r} = I_{r−1}, E_{<r}ᵀE_r = 0 and E_{<r}E_{<r}ᵀ = I_r − E_rE_rᵀ (for every r)."""
        self.last_column()
        if "leading" not in self._extras:
            self._extras.add("leading")
            self.system.order.add(LEAD)
            self.system.order.add(LEADt)
            hyps = column_hypotheses()
            why = "the columns of I_r: its first r - 1 and its last"
            self.system.add_rule((LEADt, LEAD), _i(LEADING), why, name="EleadtElead",
                                 cofactors=[_by(hyps["EleadtElead"])])
            self.system.add_rule((LEADt, ER), NCPoly.zero(LEADING, SCALAR_T), why, name="EleadtEr",
                                 cofactors=[_by(hyps["EleadtEr"])])
            self.system.add_rule((ERt, LEAD), NCPoly.zero(SCALAR_T, LEADING), why, name="ErtElead",
                                 cofactors=[_by(hyps["ErtElead"])])
            self.system.add_rule((LEAD, LEADt), _i("r") - _w(ER, ERt), why, name="EleadEleadt",
                                 cofactors=[_by(hyps["EleadEleadt+ErErt"])])
        self._named.setdefault(str(LEAD), LEAD)
        return self._cached("column:leading", lambda: self._const_block(_w(LEAD), ("r", "?")))

    def _double(self, key: str) -> Mat:
        """A generic point of the double Neumann system as letters: XᵀY → I_r, YᵀX → I_r, ẊᵀY → −XᵀẎ,
        YᵀẊ → −ẎᵀX (its constraints and their transposes)."""
        if "double" not in self._extras:
            self._extras.add("double")
            for L in (DX, DY, DXd, DYd, DXt, DYdt, DYt, DXdt):   # XᵀẎ < ẊᵀY, ẎᵀX < YᵀẊ
                self.system.order.add(L)
            self.system.add_rule((DXt, DY), _i("r"), "X^T Y = I_r (D0)", name="DXtDY", cofactors=[_by(hypothesis("DXtDY"))])
            self.system.add_rule((DYt, DX), _i("r"), "Y^T X = I_r (D0)", name="DYtDX", cofactors=[_by(hypothesis("DYtDX"))])
            self.system.add_rule((DXdt, DY), -_w(DXt, DYd), "X'^T Y + X^T Y' = 0 (D0, differentiated)", name="DXdtDY",
                                 cofactors=[_by(hypothesis("DXdtDY+DXtDYd"))])
            self.system.add_rule((DYt, DXd), -_w(DYdt, DX), "Y^T X' + Y'^T X = 0 (D0, differentiated)", name="DYtDXd",
                                 cofactors=[_by(hypothesis("DYtDXd+DYdtDX"))])
        L = DOUBLE[key]
        self._named.setdefault(str(L), L)
        return self._cached(f"double:{key}", lambda: self._const_block(_w(L), ("n", "r")))

    @property
    def DX(self) -> Mat:
        return self._double("X")

    @property
    def DY(self) -> Mat:
        return self._double("Y")

    @property
    def DXdot(self) -> Mat:
        return self._double("Xdot")

    @property
    def DYdot(self) -> Mat:
        return self._double("Ydot")

    def _complex(self, L: Letter) -> Mat:
        """A part (U, V, U̇ or V̇) of the generic point of T W(n, r), realified, as an n×r letter, with
        the rules of Z̄ᵀZ = I_r and of its derivative (real and imaginary parts): VᵀV → I_r − UᵀU,
        VᵀU → UᵀV, V̇ᵀV → −U̇ᵀU − UᵀU̇ − VᵀV̇, V̇ᵀU → U̇ᵀV + UᵀV̇ − VᵀU̇.  No left-hand side ends with
        a letter another one starts with, so the rules have no critical pairs: they are confluent, and
        a normal form is 0 iff the polynomial is in the ideal of the constraints."""
        if "complex" not in self._extras:
            self._extras.add("complex")
            for M in (CU, CV, CUd, CVd, CUt, CVt, CUdt, CVdt):   # V̇ᵀ, then Vᵀ are the largest letters
                self.system.order.add(M)
            h = {name: hypothesis(name) for name in COMPLEX_HYPOTHESES}
            self.system.add_rule((CVt, CV), _i("r") - _w(CUt, CU), "U^T U + V^T V = I_r (W0, real part)",
                                 name="VtV", cofactors=[_by(h["UtU+VtV"])])
            self.system.add_rule((CVt, CU), _w(CUt, CV), "U^T V - V^T U = 0 (W0, imaginary part)",
                                 name="VtU", cofactors=[_by(h["UtV-VtU"], -1)])
            self.system.add_rule((CVdt, CV), -_w(CUdt, CU) - _w(CUt, CUd) - _w(CVt, CVd),
                                 "U'^T U + U^T U' + V'^T V + V^T V' = 0 (W0 differentiated, real part)",
                                 name="VdtV", cofactors=[_by(h["UdtU+UtUd+VdtV+VtVd"])])
            self.system.add_rule((CVdt, CU), _w(CUdt, CV) + _w(CUt, CVd) - _w(CVt, CUd),
                                 "U'^T V + U^T V' - V'^T U - V^T U' = 0 (W0 differentiated, imaginary part)",
                                 name="VdtU", cofactors=[_by(h["UdtV+UtVd-VdtU-VtUd"], -1)])
        self._named.setdefault(str(L), L)
        return self._cached(f"complex:{L}", lambda: self._const_block(_w(L), ("n", "r")))

    @property
    def Zc(self) -> Mat:
        """The generic point Z = U + iV of W(n, r), realified: the block matrix [[U, −V], [V, U]] of
        letters (spaces ℝⁿ ⊕ ℝⁿ and ℝʳ ⊕ ℝʳ)."""
        return self._cached("Zc", lambda: self.realify(self._complex(CU), self._complex(CV)))

    @property
    def Zc_dot(self) -> Mat:
        """The generic tangent vector Ż = U̇ + iV̇ at Zc (Z̄ᵀŻ + Ż̄ᵀZ = 0), realified."""
        return self._cached("Zc_dot", lambda: self.realify(self._complex(CUd), self._complex(CVd)))

    def _complex_parts(self, M: Any, what: str) -> tuple[NCPoly, NCPoly]:
        """(Re, Im) of a realified n×r complex matrix given by its blocks [[a, b], [c, d]]: refused unless
        the rules show a = d and b = −c (the matrix is complex-linear)."""
        a = M._view() if isinstance(M, Mat) and M._shape() == (2, 2) else None
        if a is None or not all(isinstance(x, NCPoly) and x.shape == ("n", "r") for x in a.flat):
            raise refuse(f"{what} that is not a realified n×r complex matrix of blocks", self.tracker)
        if not (self.reduce(a[0, 0] - a[1, 1]).is_zero and self.reduce(a[0, 1] + a[1, 0]).is_zero):
            raise refuse(f"{what} whose blocks are not those of a complex matrix [[U, -V], [V, U]]", self.tracker)
        return a[0, 0], a[1, 0]

    def _derivative_at_complex_point(self, F: Callable[[Any, dict], Any], point: Mapping[str, Any],
                                     tangent: Mapping[str, Any]) -> Any:
        """d/dε F(t, z + ε·v) at the generic complex point z = (Z, Ż): the derivation of the value F(z)
        (a polynomial in the letters U, V, U̇, V̇) that sends each letter to its part of v, for a v that
        keeps (W0) and its derivative (checked by the rules: the derivative is then that of F on the
        constraint set)."""
        images: dict[Letter, NCPoly] = {}
        for k, v in tangent.items():
            if k not in COMPLEX:
                raise refuse(f"a tangent vector of the complex point that moves {k!r}", self.tracker)
            images[COMPLEX[k][0]], images[COMPLEX[k][1]] = self._complex_parts(v, "a tangent vector")
        for name in COMPLEX_HYPOTHESES:
            if not self.reduce(derivation(hypothesis(name).poly, images)).is_zero:
                raise refuse("a derivative along a vector that does not keep (W0) and its derivative", self.tracker)
        # F's own variables are fresh letters: a value of this scene F closes over keeps the point's
        # letters and is a constant of F, not moved with the point
        _FRESH[0] += 1
        fresh, own = {}, {}
        for k, parts in COMPLEX.items():
            fresh[k] = []
            for L in parts:
                Fl, _ = letter_pair(f"{L}'{_FRESH[0]}", f"{L.adjoint}'{_FRESH[0]}", L.row, L.col, L.latex,
                                    L.adjoint.latex)
                fresh[k].append(Fl)
                own[Fl] = _w(L)
        moved = {Fl: images[L] for k, parts in COMPLEX.items() for Fl, L in zip(fresh[k], parts) if L in images}
        value = F(self, {k: self.realify(*(self._const_mat(_w(Fl)) for Fl in fresh[k])) if k in fresh else v
                         for k, v in dict(point).items()})

        def derivative(x: Any) -> Any:
            if not isinstance(x, NCPoly):
                return se.Integer(0)
            return self.field.normalize(substitute(derivation(x, moved), own))
        return map_entries(value, derivative, self)

    def _derivative_at_double_point(self, F: Callable[[Any, dict], Any], point: Mapping[str, Any],
                                    tangent: Mapping[str, Any]) -> Any:
        """d/dε F(t, z + ε·v) at the double point z: the derivation of the value F(z) (a polynomial in the
        point's letters) that sends each letter to its component of v, for a v that keeps (D0) and its
        derivative (checked by the rules: the derivative is then that of F on the constraint set)."""
        images = {}
        for k, v in tangent.items():
            e = entry_of(v) if isinstance(v, Mat) and v._shape() == (1, 1) else None
            if k not in DOUBLE or not isinstance(e, NCPoly) or e.shape != ("n", "r"):
                raise refuse("a tangent vector of the double system that is not given by its n×r blocks", self.tracker)
            images[DOUBLE[k]] = e
        for rel in (hypothesis("DXtDY").poly, hypothesis("DXdtDY+DXtDYd").poly):
            if not self.reduce(derivation(rel, images)).is_zero:
                raise refuse("a derivative along a vector that does not keep (D0) and its derivative", self.tracker)
        # F's own variables are fresh letters: a value of this scene F closes over (its DX, DY ...) keeps
        # the point's letters and is a constant of F, not moved with the point
        _FRESH[0] += 1
        fresh, own = {}, {}
        for k, L in DOUBLE.items():
            Fl, Flt = letter_pair(f"{L}'{_FRESH[0]}", f"{L.adjoint}'{_FRESH[0]}", L.row, L.col, L.latex,
                                  L.adjoint.latex)
            fresh[k], own[Fl] = Fl, _w(L)
        moved = {fresh[k]: images[L] for k, L in DOUBLE.items() if L in images}
        value = F(self, {k: self._const_mat(_w(fresh[k])) if k in fresh else v for k, v in dict(point).items()})

        def derivative(x: Any) -> Any:
            if not isinstance(x, NCPoly):
                return se.Integer(0)
            return self.field.normalize(substitute(derivation(x, moved), own))
        return map_entries(value, derivative, self)

    def euler_lagrange_double(self, T: Callable, U: Callable, constraints: Callable, position: Mapping[str, Any],
                              velocity: Mapping[str, Any]) -> tuple[dict[str, Mat], list]:
        """The Euler–Lagrange equations d/dt ∂T/∂q̇ = −∂U/∂q + ∂tr(Mᵀg)/∂q, g = XᵀY − I_r = 0, of a Lagrangian
        T(q̇) − U(q) on pairs (X, Y) of n×r matrices, solved in the free algebra at the generic point of the
        double system (its letters and rules (D0)) and evaluated at the given point by substitution: the
        accelerations from the equations (each c·q̈_k + terms free of q̈), the r×r multiplier M (or Mᵀ)
        from g̈ = 0.  Refused unless the constraints are exactly XᵀY − I_r, T has constant coefficients,
        and the point satisfies (D0) and its derivative."""
        if set(position) != {"X", "Y"} or set(velocity) != {"X", "Y"}:
            raise refuse("Euler-Lagrange equations of variables other than a pair (X, Y)", self.tracker)
        q = {"X": self._double("X"), "Y": self._double("Y")}
        g = constraints(self, q)
        g = g[0] if isinstance(g, (list, tuple)) and len(g) == 1 else g
        D0 = _w(DXt, DY) - _i("r")
        if not isinstance(g, Mat) or not isinstance(entry_of(g), NCPoly) or (entry_of(g) - D0).expand().terms:
            raise refuse("Euler-Lagrange equations with constraints other than X^T Y = I_r", self.tracker)
        images = {}
        for key, L in (("X", DX), ("Y", DY)):
            images[L] = entry_of(position[key]) if isinstance(position[key], Mat) else None
            images[DOUBLE[key + "dot"]] = entry_of(velocity[key]) if isinstance(velocity[key], Mat) else None
        if any(not isinstance(e, NCPoly) or e.shape != ("n", "r") for e in images.values()):
            raise refuse("a point of the double system that is not given by n×r blocks", self.tracker)
        for rel in (D0, hypothesis("DXdtDY+DXtDYd").poly):
            if not self.reduce(substitute(rel, images)).is_zero:
                raise refuse("a point that the rules do not show to satisfy (D0) and its derivative", self.tracker)
        acc = {"X": Letter("ddX", "n", "r"), "Y": Letter("ddY", "n", "r")}
        for L in acc.values():
            L.adjoint = Letter(f"{L}t", "r", "n")
            L.adjoint.adjoint = L
        M = Letter("Mu", "r", "r")
        M.adjoint = Letter("Mut", "r", "r")
        M.adjoint.adjoint = M
        # T and U are evaluated at fresh letters (their own variables): a value of this scene they close
        # over keeps the point's letters and is a constant of theirs
        _FRESH[0] += 1
        fresh = {k: letter_pair(f"{L}'{_FRESH[0]}", f"{L.adjoint}'{_FRESH[0]}", L.row, L.col, L.latex,
                                L.adjoint.latex)[0] for k, L in DOUBLE.items()}
        back = {fresh[k]: _w(L) for k, L in DOUBLE.items()}
        kinetic = self._trace_form(T(self, {k: self._const_mat(_w(fresh[k + "dot"])) for k in ("X", "Y")}))
        _refuse_unless_quadratic(kinetic, [fresh[k + "dot"] for k in ("X", "Y")], self.tracker)
        potential = self._trace_form(U(self, {k: self._const_mat(_w(fresh[k])) for k in ("X", "Y")}))
        force = trace(_w(M.adjoint) * D0)
        equations = []
        for key, L in (("X", DX), ("Y", DY)):
            momentum = gradient(kinetic, fresh[key + "dot"])
            if momentum.letters() & {DX, DY, DXt, DYt, fresh["X"], fresh["Y"], fresh["X"].adjoint,
                                     fresh["Y"].adjoint}:
                raise refuse("a kinetic energy whose coefficients depend on the position", self.tracker)
            # d/dt ∂T/∂q̇ = ∂T/∂q̇ at q̇ ↦ q̈ less its value at q̇ = 0 (constant coefficients, degree <= 2: ∂T/∂q̇ =
            # Kq̇ + b, whose derivative is Kq̈): F's own velocities only
            momentum = (substitute(momentum, {fresh[k + "dot"]: _w(acc[k]) for k in ("X", "Y")})
                        - substitute(momentum, {fresh[k + "dot"]: NCPoly.zero(fresh[k + "dot"].row,
                                                                              fresh[k + "dot"].col) for k in ("X", "Y")}))
            equations.append(substitute(momentum, back) + substitute(gradient(potential, fresh[key]), back)
                             - gradient(force, L))
        nf = self.system.normal_form
        solved = solve_multipliers([nf(e) for e in equations], list(acc.values()), self.system)
        gdot = derivation(D0, {DX: _w(DXd), DY: _w(DYd)})
        gddot = nf(substitute(derivation(gdot, {DX: _w(DXd), DY: _w(DYd), DXd: _w(acc["X"]), DYd: _w(acc["Y"])}),
                              solved))
        for unknown in (M, M.adjoint):
            sol = _isolate(gddot, unknown, [M, M.adjoint])
            if sol is not None:
                mult = {unknown: nf(sol), unknown.adjoint: nf(sol).star()}
                break
        else:
            raise refuse("the multiplier of X^T Y = I_r, not solvable in the free algebra", self.tracker)
        out = {k: self._const_mat(self.field.normalize(substitute(nf(substitute(solved[acc[k]], mult)), images)))
               for k in ("X", "Y")}
        return out, []

    def euler_lagrange_complex(self, T: Callable, U: Callable, constraints: Callable, position: Mapping[str, Any],
                               velocity: Mapping[str, Any]) -> tuple[dict[str, Mat], list]:
        """The Euler–Lagrange equations of a Lagrangian T(Ż) − U(Z) of a realified complex n×r matrix
        Z = U + iV with the holonomic constraints Z̄ᵀZ = I_r, solved in the free algebra at the generic point
        of T W(n, r) (its letters and rules) and evaluated at the given point by substitution.  The
        constraint is a Hermitian r×r matrix: its real part g₁ = UᵀU + VᵀV − I_r (symmetric) and its
        imaginary part g₂ = UᵀV − VᵀU (skew), with a symmetric multiplier Σ and a skew K:
        d/dt ∂T/∂q̇ = −∂U/∂q + ∂tr(Σg₁ + Kg₂)/∂q for q = U, V gives the accelerations (each c·q̈ + terms
        free of q̈), and g̈₁ = 0, g̈₂ = 0 give Σ and K (each c·Σ, c·K + terms free of both).  Refused unless
        the constraints are exactly the Hermitian components of Z̄ᵀZ − I_r, T has constant coefficients, and
        the point satisfies (W0) and its derivative."""
        if set(position) != {"Z"} or set(velocity) != {"Z"}:
            raise refuse("Euler-Lagrange equations of variables other than one complex matrix Z", self.tracker)
        self._complex(CU)
        hyp = {name: hypothesis(name).poly for name in COMPLEX_HYPOTHESES}
        g1, g2 = hyp["UtU+VtV"], hyp["UtV-VtU"]
        # T, U and the constraints are evaluated at fresh letters (their own variables): a value of this
        # scene they close over keeps the point's letters and is a constant of theirs
        _FRESH[0] += 1
        fresh = {L: letter_pair(f"{L}'{_FRESH[0]}", f"{L.adjoint}'{_FRESH[0]}", L.row, L.col, L.latex,
                                L.adjoint.latex)[0] for L in (CU, CV, CUd, CVd)}
        back = {fresh[L]: _w(L) for L in fresh}

        def at(re: Letter, im: Letter) -> Mat:
            return self.realify(self._const_mat(_w(fresh[re])), self._const_mat(_w(fresh[im])))
        g = constraints(self, {"Z": at(CU, CV)})
        g = g[0] if isinstance(g, (list, tuple)) and len(g) == 1 else g
        blocks = g.matrix._view() if isinstance(g, HermitianComponents) and g.matrix._shape() == (2, 2) else None
        own = {L: _w(F) for L, F in fresh.items()}
        want = [[substitute(g1, own), -substitute(g2, own)], [substitute(g2, own), substitute(g1, own)]]
        if blocks is None or any(not isinstance(blocks[i, j], NCPoly) or (blocks[i, j] - want[i][j]).expand().terms
                                 for i in range(2) for j in range(2)):
            raise refuse("Euler-Lagrange equations with constraints other than the Hermitian components of "
                         "conj(Z)^T Z - I_r", self.tracker)
        images = {}
        for where, (real, imag) in ((position["Z"], COMPLEX["Z"]), (velocity["Z"], COMPLEX["Zdot"])):
            images[real], images[imag] = self._complex_parts(where, "a point of W(n, r)")
        for h in hyp.values():
            if not self.reduce(substitute(h, images)).is_zero:
                raise refuse("a point that the rules do not show to satisfy (W0) and its derivative", self.tracker)
        acc = {}
        for L in (CU, CV):
            acc[L] = Letter(f"dd{L}", "n", "r")
            acc[L].adjoint = Letter(f"dd{L}t", "r", "n")
            acc[L].adjoint.adjoint = acc[L]
        kinetic = self._trace_form(T(self, {"Z": at(CUd, CVd)}))
        _refuse_unless_quadratic(kinetic, [fresh[CUd], fresh[CVd]], self.tracker)
        potential = self._trace_form(U(self, {"Z": at(CU, CV)}))
        force = trace(_w(W0_RE) * g1) + trace(_w(W0_IM) * g2)
        positions = {CU, CV, CUt, CVt} | {x for L in (CU, CV) for x in (fresh[L], fresh[L].adjoint)}
        equations = []
        for q, qd in ((CU, CUd), (CV, CVd)):
            momentum = gradient(kinetic, fresh[qd])
            if momentum.letters() & positions:
                raise refuse("a kinetic energy whose coefficients depend on the position", self.tracker)
            # d/dt ∂T/∂q̇ = ∂T/∂q̇ at q̇ ↦ q̈ less its value at q̇ = 0 (constant coefficients, degree <= 2): T's own
            # velocities only
            momentum = (substitute(momentum, {fresh[CUd]: _w(acc[CU]), fresh[CVd]: _w(acc[CV])})
                        - substitute(momentum, {fresh[L]: NCPoly.zero(fresh[L].row, fresh[L].col) for L in (CUd, CVd)}))
            equations.append(substitute(momentum, back) + substitute(gradient(potential, fresh[q]), back)
                             - gradient(force, q))
        nf = self.system.normal_form
        solved = solve_multipliers([nf(e) for e in equations], list(acc.values()), self.system)
        first = {CU: _w(CUd), CV: _w(CVd)}
        second = {**first, CUd: _w(acc[CU]), CVd: _w(acc[CV])}
        mult = {}
        for h, unknown in ((g1, W0_RE), (g2, W0_IM)):
            hddot = nf(substitute(derivation(derivation(h, first), second), solved))
            sol = _isolate(hddot, unknown, [W0_RE, W0_IM])
            if sol is None:
                raise refuse("the multipliers of conj(Z)^T Z = I_r, not solvable in the free algebra", self.tracker)
            mult[unknown] = nf(sol)
        out = [self._const_mat(self.field.normalize(substitute(nf(substitute(solved[acc[L]], mult)), images)))
               for L in (CU, CV)]
        return {"Z": self.realify(*out)}, []

    def _trace_form(self, value: Any) -> NCPoly:
        """A Lagrangian's part (its kinetic or potential energy) as a scalar trace form, or refused."""
        return self._scalar_trace_form(value, "a Lagrangian", entry_of)

    def at_point(self, Xv: Mat, Pv: Mat) -> "FreePointScene":
        """The problem at the point (Xv, Pv) of T*V (n×r blocks of this scene; refused unless they satisfy
        (cond_XP) by the rules): see :class:`FreePointScene`."""
        self._standard_only("a scene at another point")
        xs, ps = (entry_of(M) if isinstance(M, Mat) and M._shape() == (1, 1) else None for M in (Xv, Pv))
        if not isinstance(xs, NCPoly) or not isinstance(ps, NCPoly) or xs.shape != ("n", "r") or ps.shape != ("n", "r"):
            raise refuse("a point of T*V that is not given by two n×r blocks", self.tracker)
        for rel in (xs.star() * xs - _i("r"), xs.star() * ps + ps.star() * xs):
            if not self.reduce(rel).is_zero:
                raise refuse("a point that the rules do not show to lie on T*V", self.tracker)
        return FreePointScene(self, xs, ps)

    def column(self, i: int) -> Mat:
        """E_{i+1} ∈ ℝʳ (0 ≤ i < r) as an r×1 letter, for a claim stated at one r = 1 or 2 only (the scene was
        made with ``columns=r``: E₁E₁ᵀ + … + E_rE_rᵀ = I_r is then a hypothesis of its normal forms)."""
        if not self.columns:
            raise refuse(f"the column e_{i + 1} = X E_{i + 1} (a basis vector of R^r) for every r", self.tracker)
        if not 0 <= i < self.columns:
            raise ValueError(f"E_{i + 1} is not a basis vector of R^{self.columns}")
        self._column_letters()
        L = COLUMNS[i]
        self._named.setdefault(str(L), L)
        return self._cached(f"column:{i}", lambda: self._const_block(_w(L), ("r", "?")))

    @property
    def Ainv(self) -> Mat:
        """A^{-1} (A invertible): A A^{-1} = A^{-1} A = I_n, and its products with resolvents."""
        if "ainv" not in self._extras:
            self._extras.add("ainv")
            self.system.order.add(AINV)
            self.system.add_rule((A, AINV), _i("n"), "A A^(-1) = I_n", name="AAinv",
                                 cofactors=[_by(hypothesis("AAinv"))])
            self.system.add_rule((AINV, A), _i("n"), "A^(-1) A = I_n", name="AinvA",
                                 cofactors=[_by(hypothesis("AinvA"))])
            for R, mu in self._resolvents.items():
                _ainv_resolvent_rules(self.system, R, mu)
        return self._letter(AINV)

    @property
    def a(self) -> Any:
        raise refuse("the eigenvalues a_i of A", self.tracker)

    def sym_operator(self, name: str = "AA") -> Callable[[Mat], Mat]:
        """A generic symmetric operator 𝔸 on so(n) (for ⟨a, b⟩ = −½ tr(ab)), as letters: 𝔸(M) for an
        n×n block M is Σ c·𝔸⟨w⟩ over the words w of M (an r×r block M: the operator of that name on
        so(r), r×r letters; linear in M; 𝔸 acts on the skew part, as
        the coordinate scenes' operator does), each 𝔸⟨w⟩ an opaque skew n×n letter.  Its symmetry
        is a normal form of traces (:func:`~stiefelsym.free.algebra.operator_pair_rep`) and the
        rule of gradients (:func:`~stiefelsym.free.traces.gradient`); along a flow d𝔸(M) = 𝔸(dM)."""
        op = user_name(name, "sym_operator")
        scene = self

        def apply(M: Any) -> Mat:
            if not isinstance(M, Mat) or M._shape() != (1, 1):
                raise refuse(f"the operator {op} on a matrix that is not one n×n or r×r block", scene.tracker)
            if tuple(M.tags) not in (("n", "n"), ("r", "r")):
                raise TypeError(f"the operator {op} acts on so(n) or so(r), not on a {M.tags[0]}×{M.tags[1]} matrix")
            t = M.tags[0]
            x = entry_of(M)
            if isinstance(x, Dual):   # along a flow: d𝔸(M) = 𝔸(dM)
                y: Any = Dual(apply_operator(op, x.a), apply_operator(op, x.b))
            elif isinstance(x, NCPoly):
                y = apply_operator(op, x)
            else:
                raise TypeError(f"the operator {op} acts on so(n), not on a scalar")
            for L in _operator_letters(y):
                scene._named.setdefault(str(L), L)
            f = M._field   # the operator is one for every scene: on a tangent scene, its dual numbers
            return one_block(f.normalize(y), f, (t, t), M.tracker)

        return apply

    def generic(self, name: str, m: str, k: str, kind: str = "general") -> Mat:
        """A generic m×k matrix (m, k in {"n", "r"}): a free letter G with transpose G^T; a symmetric
        (``kind`` "sym") or skew ("skew") one is a letter that is its own transpose, or minus it."""
        if m not in ("n", "r") or k not in ("n", "r"):
            raise ValueError(f"generic({name!r}, {m!r}, {k!r}): the index spaces are 'n' or 'r'")
        user_name(name, "generic")
        suffix = check_generic_kind(m, k, kind)
        # the letter's name holds its spaces and its kind, as the fixed-size scenes' keys do: the matrices of one
        # name on R^n x R^r, R^r x R^n, R^n x R^n, R^r x R^r, and the general, symmetric and skew ones, are all
        # different letters (letters are compared by name); gen:S[nxn]:sym, gen:K[rxr]:skew, gen:G[nxr] with
        # gen:G[nxr]^T (no claim's name spells another: a name is letters, digits and underscores, as on every
        # scene)
        key = f"gen:{name}[{m}x{k}]{suffix}"
        tex = _generic_tex(name)
        if kind != "general":
            make = symmetric_letter if kind == "sym" else skew_letter
            self._named.setdefault(key, make(key, m, tex))
        else:
            G, _ = letter_pair(key, f"{key}^T", m, k, tex, f"{tex}^{{T}}")
            self._named.setdefault(key, G)
        return self._cached(key, lambda: self._prim(key, _w(self._named[key])))

    def _engine_letters(self, tag: str, x: Mat) -> tuple[Mat, Mat]:
        """Two generic elements of the space of x (one block m×k) of the engine's own: free letters no claim can
        name (eng:tag:y, eng:tag:z), at which a step checks a claim's operator (brackets._check_symmetric)."""
        e = entry_of(x) if isinstance(x, Mat) and x._shape() == (1, 1) else None
        while type(e) is Dual:          # on a tangent scene: the letters' type is the value's
            e = e.a
        if not isinstance(e, NCPoly) or e.row not in ("n", "r") or e.col not in ("n", "r"):
            raise refuse(f"{tag}: an operator on a space other than one block of n×n, n×r, r×n or r×r matrices",
                         self.tracker)
        out = []
        depth = ENGINE_CHECK_DEPTH[0]       # a check nested in another's function: letters of its own
        for t in ("y", "z"):
            key = f"eng:{tag}:{t}[{e.row}x{e.col}]" + (f"@{depth}" if depth else "")
            if key not in self._named:
                G, _ = letter_pair(key, f"{key}^T", e.row, e.col, f"{t}_{{{tag}}}", f"{t}_{{{tag}}}^{{T}}")
                self._named[key] = G
            out.append(self._cached(key, lambda key=key: self._prim(key, _w(self._named[key]))))
        return out[0], out[1]

    def fresh(self, *args: Any) -> Mat:
        """fresh(index, m, k): the fresh element number ``index`` of a graph (a claim's ``s.fresh(m, k)``), a free
        letter no claim can name (gen:fresh:i; a claim's generic letters are letters and digits), with its
        transpose; fresh(m, k), engine code called on the scene itself: the next of the scene's own."""
        key = _fresh_key(self, args, ("n", "r"))
        m, k = args[-2:]
        index = key[len(FRESH):key.index("[")]
        name = f"gen:fresh:{index}"
        G, _ = letter_pair(name, f"{name}^T", m, k, f"w_{{{index}}}", f"w_{{{index}}}^{{T}}")
        self._named.setdefault(str(G), G)
        return self._cached(name, lambda: self._prim(str(G), _w(self._named[str(G)])))

    def _skew(self, name: str, t: str, latex: str) -> Mat:
        self._named.setdefault(name, skew_letter(name, t, latex))
        return self._cached(f"skew:{name}", lambda: self._prim(name, _w(self._named[name])))

    @property
    def xi(self) -> Mat:
        """A generic element of so(n) (a skew letter)."""
        return self._skew("xi", "n", r"\xi")

    @property
    def zeta(self) -> Mat:
        return self._skew("zeta", "n", r"\zeta")

    @property
    def eta(self) -> Mat:
        """A generic element of so(r)."""
        return self._skew("eta", "r", r"\eta")

    @property
    def theta(self) -> Mat:
        return self._skew("theta", "r", r"\theta")

    # -- scalars --------------------------------------------------------------
    def _param(self, name: str) -> Any:
        if name not in self.params:
            # the paper's scalars are the symbols lambda, kappa, epsilon; a claim's own scalar is a
            # dummy symbol, never equal to another symbol, whatever its name
            self.params[name] = se.Dummy(name) if name.startswith(USER_SCALAR) else se.Symbol(name)
        return self.params[name]

    def const(self, q: int | Fraction) -> Any:
        return _number(self, as_coef(Fraction(q)))

    def q(self, num: int, den: int = 1) -> Any:
        return _number(self, as_coef(Fraction(num, den)))

    # -- matrices ---------------------------------------------------------------
    def _blocks(self, m: Any, tag: str | None) -> tuple[str, int]:
        """(index type, number of diagonal blocks) for a size given as s.n, s.r, k·s.n, k·s.r or
        by a definite index space ("n", "2r", "r+r")."""
        atoms = definite(tag) if tag is not None else None
        if isinstance(m, FreeSize):
            t, k = m.kind, m.k
        elif atoms and len(set(atoms)) == 1:
            t, k = atoms[0], len(atoms)
        else:
            raise refuse(f"a matrix of size {m!r} (index space {tag!r})", self.tracker)
        if atoms is not None and atoms != (t,) * k:
            raise TypeError(f"the size {k if k > 1 else ''}{t} does not match the index space {tag!r}")
        return t, k

    @staticmethod
    def _tag(t: str, k: int, tag: str | None) -> str:
        return tag or (t if k == 1 else f"{k}{t}")

    def scalar_matrix(self, c: Any, m: Any, tag: str | None = None) -> Mat:
        """c·I_m for m = n, r (or k·n, k·r: a k×k block diagonal)."""
        c = _raw(c)
        t, k = self._blocks(m, tag)
        blocks = [[(_i(t) * c if i == j else NCPoly.zero(t, t)) for j in range(k)] for i in range(k)]
        return Mat._rows(blocks, self.field, (self._tag(t, k, tag),) * 2, self.tracker)

    def identity(self, m: Any, tag: str | None = None) -> Mat:
        return self.scalar_matrix(1, m, tag)

    def zeros(self, m: Any, k: Any, tags=(None, None)) -> Mat:
        t1, k1 = self._blocks(m, tags[0])
        t2, k2 = self._blocks(k, tags[1])
        rows = [[NCPoly.zero(t1, t2) for _ in range(k2)] for _ in range(k1)]
        return Mat._rows(rows, self.field, (self._tag(t1, k1, tags[0]), self._tag(t2, k2, tags[1])), self.tracker)

    def mat(self, rows, tags=("?", "?")) -> Mat:
        """A block matrix from rows of blocks (word polynomials of the scene); its spaces are the
        sums of the blocks' types.  Scalars as entries need coordinates."""
        rows = [list(row) for row in rows]
        if not rows or not rows[0] or any(len(row) != len(rows[0]) for row in rows):
            raise ValueError("a matrix needs a rectangular, non-empty grid of blocks")
        for row in rows:
            for x in row:
                if type(x) is not NCPoly:
                    raise refuse("a matrix built from scalar entries", self.tracker)
        row_types = [row[0].row for row in rows]
        col_types = [x.col for x in rows[0]]
        for row, t in zip(rows, row_types):
            for x, c in zip(row, col_types):
                if (x.row, x.col) != (t, c):
                    raise TypeError(f"a block of type {x.row}x{x.col} where {t}x{c} is needed")
        spaces = ("+".join(row_types), "+".join(col_types))
        for given, built in zip(tags, spaces):
            if given not in ("?", None) and definite(given) != definite(built):
                raise TypeError(f"the blocks span {built}, not {given!r}")
        return Mat._rows(rows, self.field, spaces, self.tracker)

    @property
    def In(self) -> Mat:
        return self._cached("In", lambda: self._const_mat(_i("n")))

    @property
    def Ir(self) -> Mat:
        return self._cached("Ir", lambda: self._const_mat(_i("r")))

    def _const_mat(self, p: NCPoly) -> Mat:
        return one_block(p, self.field, p.shape, self.tracker)

    def _const_block(self, p: NCPoly, tags: tuple) -> Mat:
        """A constant of the scene (constant along every flow) with the given index spaces."""
        x = Dual(p, NCPoly.zero(p.row, p.col)) if isinstance(self.field, DualField) else p
        return one_block(x, self.field, tags, self.tracker)

    def tr(self, M: Any) -> Any:
        if isinstance(M, Mat):
            return _number(self, M._trace())
        M = _raw(M)
        return _number(self, self._field.normalize(self._field.entry_trace(M)))

    def resolvent(self, mu: Any) -> Mat:
        """(mu I_n − A)^{-1} as a letter R_mu with A R = R A = mu R − I."""
        m = self._spectral_parameter(_raw(mu))
        R = add_resolvent(self.system, m, self._resolvents, ainv="ainv" in self._extras)
        if any(m is x for _, x in self._moving):
            mark_moving(R)
        if "reflection" in self._extras:
            self._reflection_resolvent_rule(R)
        return self._letter(R)

    def _spectral_parameter(self, mu: Any) -> Any:
        """The coefficient of R_mu.  A scalar polynomial of the scene with no letter is its number; one that
        moves with the point (a polynomial in traces, μ = tr(PᵀP) + λ) is a fresh symbol m standing for it,
        the same for the same normal form: R_m's rules hold for every value of m, so an identity they give
        holds at m = μ(X, P) (the derivatives of R along flows, −μ'R², are written by the derivative passes
        of the graph, with the letter R of the same μ)."""
        if as_coef(mu) is not None:
            return mu
        if isinstance(mu, Dual):
            raise refuse("a resolvent at a spectral parameter that moves with the point, inside a derivative the "
                         "free scene takes itself (a bracket or a flow of a function that holds it)", self.tracker)
        if not (isinstance(mu, NCPoly) and mu.is_scalar):
            raise refuse("a resolvent at a spectral parameter that is not a scalar polynomial of the scene",
                         self.tracker)
        nf = self.system.normal_form(mu)
        if all(not t and not w for (t, w) in nf.terms):
            return nf.scalar_value()
        moving = self._moving
        for q, m in moving:
            if q == nf:
                return m
        if moving:   # the resolvent identity between the two would divide by m1 − m2, which may vanish on T*V
            raise refuse("resolvents at two spectral parameters that move with the point", self.tracker)
        m = se.Dummy(f"m{len(moving) + 1}")
        moving.append((nf, m))
        return m

    # -- flows ------------------------------------------------------------------
    def _hamiltonian(self, H: Function) -> NCPoly:
        value = _raw(H(self))
        if isinstance(value, Mat):
            if value._shape() != (1, 1):
                raise TypeError("a Hamiltonian must be a scalar")
            value = entry_of(value)
        if not isinstance(value, NCPoly):
            c = as_coef(value)
            if c is None:
                what = f"a Hamiltonian that is not a trace form ({type(value).__name__})"
                record_refusal(what, self.tracker)
                raise TypeError(f"a Hamiltonian must be a trace form, got {type(value).__name__}")
            value = NCPoly.scalar(c)
        if not value.is_scalar:
            record_refusal("a Hamiltonian that is not a scalar trace form", self.tracker)
            raise TypeError("a Hamiltonian must be a scalar trace form")
        return value

    def _as_written(self, what: str) -> None:
        """Ambient quantities (gradients, canonical flows, multipliers, the bracket {,}_0) depend on
        a function off T*V.  A lazy scene keeps every expression as built (no rule is applied while a
        function is evaluated), so a trace form H is the polynomial the claim wrote, defined on all of
        (X, P)-space, and its cyclic derivative is its ambient gradient; an eager scene has reduced H
        modulo the constraints and refuses."""
        if not getattr(self._field, "lazy", False):
            raise refuse(what, self.tracker)

    def gradient(self, H: Function) -> tuple[Mat, Mat]:
        """(∂H/∂X, ∂H/∂P) of the trace form H as written: the cyclic derivative of the polynomial
        the lazy scene built (each gradient then reduced, which changes it only off T*V)."""
        self._as_written("the ambient gradient of H, which depends on H off T*V")
        return self._gradient(H, ambient=True)

    def _gradient(self, H: Function, ambient: bool = False) -> tuple[Mat, Mat]:
        """(∂H/∂X, ∂H/∂P) of the trace form H as the scene's arithmetic built it: on a lazy scene the
        polynomial as written (the ambient gradient), on an eager one H reduced modulo the
        constraints (which changes H only off T*V, so Dirac flows are unaffected, but the
        canonical flow and the multipliers Λ, Π are those of the reduced form).

        H is evaluated on a scene of its own whose X, P are fresh letters (:class:`FunctionScene`):
        a value of this scene that H closes over keeps the letters X, P and is a constant of H.
        ``ambient``: the gradient is used off T*V too (an ambient gradient or flow, not a Dirac flow), so H
        may not hold a flow whose multipliers are solved on T*V (see :class:`FunctionScene`)."""
        def build():
            u = FunctionScene(self, ambient)
            h = u._hamiltonian(H)
            self._cache[f"holds a flow:{id(H)}"] = (H, u.nested_flow)
            return tuple(self._const_mat(self.system.normal_form(u.back(gradient(h, u.own(L))))) for L in (X, P))
        return self._cached_for("grad:ambient" if ambient else "grad", H, build)

    def form_gradient(self, form: Callable[[Any, Mat], Any], index: str) -> Mat:
        """The gradient G, for ⟨a, b⟩ = −½ tr(ab), of an affine form c ↦ form(self, c) on gl(m)
        (m = n or r, ``index``): form(c) − form(0) = ⟨G, c⟩ for every c, with no basis of gl(m).

        The form is evaluated at a fresh m×m letter C (with its transpose Cᵀ, no rule mentions
        them) to a trace form F, and G = −2 (∂F/∂C)ᵀ by cyclic differentiation
        (:func:`~stiefelsym.free.traces.gradient`: dF = tr((∂F/∂C)ᵀ dC) = ⟨−2(∂F/∂C)ᵀ, dC⟩).  A
        gradient that still holds C means the form is not affine in c: refused."""
        if index not in ("n", "r"):
            raise ValueError(f"form_gradient: the index space is 'n' or 'r', not {index!r}")
        global _FORM_LETTERS
        _FORM_LETTERS += 1
        C, _ = letter_pair(f"form:{_FORM_LETTERS}", f"form:{_FORM_LETTERS}^T", index, index, "C", "C^{T}")
        value = self._scalar_trace_form(_raw(form(self, self._prim(str(C), _w(C)))), "a form", entry_of)
        g = gradient(value, C)
        if _holds_letter(g, C):
            raise refuse("the gradient of a form that is not affine in its argument", self.tracker)
        return self._const_mat(self.field.normalize(g.star() * se.Integer(-2)))

    def _scalar_trace_form(self, value: Any, what: str, entry: Callable[[Mat], Any]) -> NCPoly:
        """A form's value at a letter as a scalar trace form (a 1×1 matrix's ``entry``, or a number), or refused: the
        gradient of ``what`` whose value is not a number, or not a trace form."""
        if isinstance(value, Mat):
            if value._shape() != (1, 1):
                raise refuse(f"the gradient of {what} whose value is not a number", self.tracker)
            value = entry(value)
        if not isinstance(value, NCPoly):
            c = as_coef(value)
            if c is None:
                raise refuse(f"the gradient of {what} whose value is not a trace form ({type(value).__name__})",
                             self.tracker)
            value = NCPoly.scalar(c)
        if not value.is_scalar:
            raise refuse(f"the gradient of {what} whose value is not a number", self.tracker)
        return value

    def declared_gradient_holds(self, value: Callable[[Any, Mat], Any], x: Mat, G: Mat) -> bool:
        """Whether ``G`` is the gradient at x, for ⟨a, b⟩ = −½ tr(ab), of y ↦ ``value(self, y)`` (y in x's space: one
        block of n×n, n×r, r×n or r×r matrices): the value's gradient by cyclic differentiation at a letter C of the
        engine's own (:meth:`_engine_letters`), x put in C's place, less G has normal form zero.  On a tangent scene
        (inside a derivative along a flow) both parts are compared: the gradient of the value's tangent part is the
        tangent part of G (d/dt ∇h(t, x) = ∇(dh/dt)(t, x) for a point x that does not move; a moving point needs
        the Hessian, refused).  A value that is not a trace form (it reads entries or blocks) needs coordinates."""
        y, _ = self._engine_letters("gradient", x)
        ex = entry_of(x)
        if type(ex) is Dual:
            if not _vanishes_part(ex.b):
                raise refuse("a declared gradient at a point that moves along the flow (its derivative needs the "
                             "Hessian of the value)", self.tracker)
            ex = ex.a
        if type(ex) is Dual:
            raise refuse("a declared gradient inside nested dual numbers", self.tracker)
        depth = ENGINE_CHECK_DEPTH[0]
        C = self._named[f"eng:gradient:y[{ex.row}x{ex.col}]" + (f"@{depth}" if depth else "")]
        with engine_check():
            v = _raw(value(self, y))
        v = entry_of(v) if isinstance(v, Mat) and v._shape() == (1, 1) else v
        g = entry_of(_raw(G))
        nf = (self.field.base if isinstance(self.field, DualField) else self.field).normalize
        vs, gs = ((v.a, v.b) if type(v) is Dual else (v, None)), ((g.a, g.b) if type(g) is Dual else (g, None))
        for vp, gp in zip(vs, gs):
            if vp is None and gp is None:
                continue
            if type(vp) is Dual or type(gp) is Dual:
                raise refuse("a declared gradient inside nested dual numbers", self.tracker)
            vp = self._scalar_trace_form(se.Integer(0) if vp is None else vp, "a function", entry_of)
            at_x = substitute(nf(gradient(vp, C).star() * se.Integer(-2)), {C: ex})
            target = self._const_mat(NCPoly.zero(ex.row, ex.col) if gp is None else gp)
            if not bool((self._const_mat(nf(at_x)) - target).is_zero()):
                return False
        return True

    def _holds_flow(self, H: Function) -> bool:
        """Whether H, as evaluated for its gradient, solved a flow's multipliers modulo the constraints (which
        changes H off T*V: its Dirac flow stands, its ambient gradient and its multipliers Λ, Π do not)."""
        self._gradient(H)
        hit = self._cache.get(f"holds a flow:{id(H)}")
        return hit is None or hit[0] is not H or hit[1]

    def _dual_field(self) -> "FreeDualField":
        """The dual numbers over this scene's field (one for every tangent scene of this scene)."""
        f = self._cache.get("dual field")
        if f is None:
            f = self._cache["dual field"] = FreeDualField(self._field)
        return f

    def _cached_for(self, key: str, obj: Any, build: Callable[[], Any]) -> Any:
        full = f"{key}:{id(obj)}"
        if full not in self._cache:
            self._cache[full] = (obj, build())
        return self._cache[full][1]

    def canonical_flow(self, H: Function) -> Flow:
        """The Hamiltonian vector field of H as written for the ambient bracket {,}_0:
        Ẋ = ∂H/∂P, Ṗ = −∂H/∂X."""
        self._as_written("the ambient (canonical) flow, which depends on H off T*V")
        HX, HP = self._gradient(H, ambient=True)
        return Flow(HP, -HX)

    def dirac_flow(self, H: Function) -> Flow:
        """(dot_XP): Ẋ = H_P − XΠ, Ṗ = −H_X + XΛ + PΠ with Π, Λ solved in the free algebra."""
        def build():
            flow = self._multiplier_flow(H)
            if getattr(self._field, "lazy", False) and not self._holds_flow(H):
                return flow                     # H as written: Λ, Π are H's own multipliers
            return Flow(flow.Xdot, flow.Pdot)   # the multipliers of the reduced form are not H's
        return self._cached_for("dflow", H, build)

    def multiplier_flow(self, H: Function) -> Flow:
        """(dot_XP) with the Lagrange multipliers Λ, Π of H as written (see :meth:`_as_written`)."""
        self._as_written("the Lagrange multipliers, which depend on H off T*V")
        if self._holds_flow(H):
            raise refuse("the Lagrange multipliers of a Hamiltonian that holds a flow (solved modulo the constraints, "
                         "which changes it off T*V)", self.tracker)
        return self.dirac_flow(H)

    def _multiplier_flow(self, H: Function) -> Flow:
        HX, HP = (entry_of(m) for m in self._gradient(H))
        if self.realization == "metric":
            return self._metric_flow(HX, HP)
        Xd, Pd, Lam, Pi = self._pair_multipliers(HX, HP, X, P)
        return Flow(self._const_mat(Xd), self._const_mat(Pd),
                    multipliers={"Pi": self._const_mat(Pi), "Lambda": self._const_mat(Lam)})

    def _metric_flow(self, HX: NCPoly, HP: NCPoly) -> Flow:
        """The Dirac flow of the gradient (H_X, H_P) on (cond_XP2): Ẋ = H_P − A⁻¹XΠ, Ṗ = −H_X + XΛ + A⁻¹PΠ with
        Π = 0 by the uniqueness of the solution of its Sylvester equation, Λ a letter whose relation ρ joins
        the ideal (see :mod:`.metric`); refused where a multiplier equation is of neither form."""
        from stiefelsym.free.metric import metric_multipliers
        try:
            m = metric_multipliers(self.system, HX, HP, self._sylvester)
        except FreeSolveError as exc:   # a refusal: recorded before it reaches claim code
            record_refusal(f"the Lagrange multipliers of a Hamiltonian on (cond_XP2) ({exc})", self.tracker)
            raise NeedsCoordinates(f"the multipliers of the metric realization: {exc}") from None
        self._sylvester[m.letter] = m
        self._named[str(m.letter)] = m.letter
        return Flow(self._const_mat(m.Xdot), self._const_mat(m.Pdot),
                    multipliers={"Pi": self._const_mat(NCPoly.zero("r", "r")), "Lambda": self._const_mat(_w(m.letter))})

    def _pair_multipliers(self, HX: NCPoly, HP: NCPoly, x_letter: Letter, p_letter: Letter) -> tuple:
        """(dot_XP) for one pair (x, p) of T*V: ẋ = H_p − xΠ, ṗ = −H_x + xΛ + pΠ with the symmetric Π, Λ
        for which the flow keeps xᵀx = I_r and xᵀp + pᵀx = 0, solved in the free algebra.  Returns
        (ẋ, ṗ, Λ, Π), reduced."""
        nf = self.system.normal_form
        x, p = _w(x_letter), _w(p_letter)
        Pi, Lam = _w(PI), _w(LAMBDA)
        Xd = HP - x * Pi
        Pd = -HX + x * Lam + p * Pi
        eq_XX = nf(Xd.star() * x + x.star() * Xd)
        eq_XP = nf(Xd.star() * p + x.star() * Pd + Pd.star() * x + p.star() * Xd)
        try:
            solved = solve_multipliers([eq_XX, eq_XP], [PI, LAMBDA], self.system)
        except FreeSolveError as exc:   # a refusal too: recorded before it reaches claim code
            record_refusal(f"the Lagrange multipliers of a Hamiltonian ({exc})", self.tracker)
            raise
        Xd, Pd = (nf(substitute(v, solved)) for v in (Xd, Pd))
        return Xd, Pd, solved[LAMBDA], solved[PI]

    # -- phase spaces made of the scene's points ---------------------------------------------------
    def _own_point(self, point: Mapping[str, Any], what: str) -> list[str]:
        """The keys of a point that is the scene's own letters (X, P, and Y, Q of the second point):
        anything else (a matrix built from them, another phase space) needs coordinates."""
        keys = list(point)
        if not keys or any(k not in MOVABLE or point[k] is not getattr(self, k) for k in keys):
            raise refuse(f"{what} at a point that is not the scene's own (X, P, Y, Q)", self.tracker)
        return keys

    def derivative_at_own_point(self, F: Callable[[Any, dict], Any], point: Mapping[str, Any],
                                tangent: Mapping[str, Any]) -> Any:
        """d/dε F(t, point + ε·tangent) at ε = 0 for the scene's own point: the derivative of
        t ↦ F(t, {k: t.k}) along the tangent (letters not moved are constant)."""
        if set(point) == set(DOUBLE) and all(point[k] is self._double(k) for k in DOUBLE):
            return self._derivative_at_double_point(F, point, tangent)
        if set(point) == set(COMPLEX) and point["Z"] is self.Zc and point["Zdot"] is self.Zc_dot:
            return self._derivative_at_complex_point(F, point, tangent)
        keys = self._own_point(point, "a derivative")
        # only the point handed to F moves: F's scene is not moved (at fixed sizes its X, P are the scene's,
        # constant along the tangent).  The free derivative below moves every X, P of F's value, so a
        # function that reads its scene's point other than through its argument is refused: its value on a
        # scene of fresh letters, at the point of this scene's own letters, holds a fresh letter
        self._reads_only_its_point(F, keys, "a derivative")
        return self.d(lambda t: F(t, {k: getattr(t, k) for k in keys}), dict(tangent))

    def _reads_only_its_point(self, F: Callable[[Any, dict], Any], keys: list[str], what: str) -> None:
        """Refuse a function F(t, z) of a point of the scene's own letters that reads its scene's point t.X,
        t.P, ... other than through z: at fixed sizes only z moves (or is differentiated), while this scene
        makes t.k and z[k] one letter.  Its value on a scene of fresh letters, at the point of this scene's
        own letters, then holds a fresh letter."""
        u = FunctionScene(self)
        if _fresh_letters_in(_raw(F(u, {k: getattr(self, k) for k in keys})), set(u._fresh.values()), set()):
            raise refuse(f"{what} at the scene's own point of a function that reads its scene's point (X, P, Y, "
                         "Q) other than through its argument", self.tracker)

    def pairs_dirac_flow(self, H: Callable[[Any, dict], Any], point: Mapping[str, Any],
                         pairs: Any) -> dict[str, Mat]:
        """The Dirac flow of H(t, z) on a product of copies of T*V(n, r), one for each (position,
        momentum) pair of the scene's own letters, each with its constraints (cond_XP): the
        constraints of a pair involve only its own letters, so each pair has its own multipliers,
        ẋ = H_p − xΠ, ṗ = −H_x + xΛ + pΠ, solved in the free algebra."""
        self._standard_only("a Dirac flow on pairs of points")
        keys = self._own_point(point, "a Hamiltonian flow")
        pairs = [tuple(pq) for pq in pairs]
        if sorted(k for pq in pairs for k in pq) != sorted(keys) or any(len(pq) != 2 for pq in pairs):
            raise refuse("a Hamiltonian flow whose pairs are not the point's letters", self.tracker)
        letters = {k: self._named[k] for k in keys}
        self._reads_only_its_point(H, keys, "a Hamiltonian flow")
        u = FunctionScene(self)         # H's own letters: fresh (a value of this scene it closes over is a constant)
        h = u._hamiltonian(lambda t: H(t, {k: getattr(t, k) for k in keys}))
        nf = self.system.normal_form
        out: dict[str, Mat] = {}
        for xk, pk in pairs:
            if (xk, pk) not in (("X", "P"), ("Y", "Q")):
                raise refuse(f"a Hamiltonian flow with the pair ({xk}, {pk})", self.tracker)
            HX, HP = (nf(u.back(gradient(h, u.own(letters[k])))) for k in (xk, pk))
            Xd, Pd, _, _ = self._pair_multipliers(HX, HP, letters[xk], letters[pk])
            out[xk], out[pk] = self._const_mat(Xd), self._const_mat(Pd)
        return out

    def tangent(self, flow: Mapping[str, Mat]) -> "FreeTangentScene":
        for key in dict(flow):
            _check_movable(key, self.tracker)
        return FreeTangentScene(self, flow)

    def _gradient_pair(self, HX: Mat, HP: Mat) -> tuple[Mat, Mat]:
        """A gradient (∂H/∂X, ∂H/∂P) of a trace form as written, computed by the graph, handed on as
        :meth:`gradient` hands its own (refused by an eager scene, each gradient reduced; see
        :mod:`stiefelsym.ir.derivative`)."""
        self._as_written("the ambient gradient of H, which depends on H off T*V")
        HX, HP = (L * 0 if G is None else G for G, L in ((HX, self.X), (HP, self.P)))   # None: H does not read it
        return tuple(self._const_mat(self.system.normal_form(entry_of(G))) for G in (HX, HP))

    def _tangent_vector(self, flow: Flow | Mapping[str, Mat], keys: tuple) -> dict[str, Mat]:
        """The components ``keys`` of a flow as the tangent scene reads them (its keys checked as
        :meth:`tangent` checks them, a component's block as the tangent scene checks it when the
        letter is read; 0 where the flow does not move it): what the graph's derivatives along the
        flow read (see :mod:`stiefelsym.ir.derivative`)."""
        tangent = flow.tangent() if isinstance(flow, Flow) else dict(flow)
        for key in tangent:
            _check_movable(key, self.tracker)
        out = {}
        for key in keys:
            poly = entry_of(getattr(self, key))
            out[key] = one_block(_component(tangent, key, poly, self.tracker), self.field, poly.shape, self.tracker)
        return out

    def d(self, F: Function | Any, flow: Flow | Mapping[str, Mat]) -> Any:
        """The derivative of F along a flow (X ↦ Ẋ, P ↦ Ṗ; A, R constant).

        F is a function of the scene (differentiated as written, by dual
        numbers), or a value (Mat, polynomial, list, dict), differentiated by
        the derivation of the free algebra; the latter needs a flow tangent to
        T*V, which is checked (ValueError otherwise)."""
        tangent = flow.tangent() if isinstance(flow, Flow) else dict(flow)
        if callable(F):
            return _map_value(_raw(F(self.tangent(tangent))), self)
        images = self._tangent_images(tangent)
        nf = self.field.normalize   # lazy: the derivative as computed, reduced with the residual
        return map_entries(F, lambda x: nf(derivation(x, images)) if isinstance(x, NCPoly)
                            else se.Integer(0), self)

    def _tangent_images(self, tangent: Mapping[str, Any]) -> dict[Letter, NCPoly]:
        images = {}
        for key, v in tangent.items():
            if key in ("X", "P") and key not in self._named:
                getattr(self, key)          # every scene's letters (named on first use: Φ, Ψ are built once)
            if key not in MOVABLE or key not in self._named:
                record_refusal(f"a flow that moves {key!r}", self.tracker)
                raise KeyError(f"the flow moves {key!r}, which is not a letter of this scene")
            images[self._named[key]] = entry_of(v) if isinstance(v, Mat) else v
        if self.realization == "metric":
            from stiefelsym.free.metric import constraint_polys
            relations = constraint_polys()
        else:
            relations = [(_w(Xt, X), COND_XX), (_w(Xt, P) + _w(Pt, X), COND_XP)]
        if "second" in self._extras:
            relations += [(_w(Yt, Y), "Y^T Y = I_r"), (_w(Yt, Q) + _w(Qt, Y), "Y^T Q + Q^T Y = 0")]
        for rel, why in relations:
            d = derivation(rel, images)   # (along a metric flow: modulo the relation of its multiplier too)
            if not (self.reduce(d).is_zero if self._sylvester else self.system.is_zero(d)):
                record_refusal(f"the derivative of a value along a flow that does not preserve {why}", self.tracker)
                raise ValueError(f"the flow does not preserve {why}: differentiate a function of the "
                                 "scene (d(lambda s: ..., flow)) instead of a value")
        return images

    def canonical_bracket(self, F: Function, G: Function) -> Any:
        """{F, G}_0 = tr(F_Xᵀ G_P) − tr(F_Pᵀ G_X) for F, G as written (see :meth:`_as_written`)."""
        self._as_written("the ambient bracket {F, G}_0, which depends on F, G off T*V")
        FX, FP = self._gradient(F, ambient=True)
        GX, GP = self._gradient(G, ambient=True)
        return self.tr(FX.T @ GP) - self.tr(FP.T @ GX)

    def bracket(self, F: Function, G: Function) -> Any:
        """The Dirac bracket {F, G} = derivative of F along the Dirac flow of G."""
        return self.d(F, self.dirac_flow(G))

    def _graph_flows(self) -> frozenset:
        """What the graph may compute of the flows and brackets here (see :mod:`stiefelsym.ir.derivative`):
        the bracket, as the derivative along the Dirac flow, which the scene solves (and the magnetic
        bracket of :mod:`stiefelsym.twisted`, along the scene's own magnetic flow), and the derivative at its own
        point of :mod:`stiefelsym.systems`, along the tangent vector; a derivative nested in the function of
        another, as nodes over the enclosing function's scene (the scene's dual numbers do not nest: a tangent
        scene's primitives are the letters X, P moved once)."""
        from stiefelsym.ir.derivative import (BRACKET_ALONG_FLOW, NESTED_DERIVATIVES, POINT_DERIVATIVES, SYSTEMS_OWN,
                                              TWISTED_ALONG_FLOW)
        return frozenset({BRACKET_ALONG_FLOW, TWISTED_ALONG_FLOW, SYSTEMS_OWN, POINT_DERIVATIVES, NESTED_DERIVATIVES})

    def _share(self, base: "FreeScene") -> None:
        """What a scene made from ``base`` (its tangent scene, a function's scene) shares with it: the
        parameters, the resolvents, the extra letters, the columns and the square case."""
        self.params = base.params
        self._resolvents = base._resolvents
        self._moving = base._moving
        self._sylvester = base._sylvester
        self.realization = base.realization
        self._extras = base._extras
        self.columns = base.columns
        self.square = base.square

    def reduce(self, x: Any) -> Reduction:
        """Normal form of one entry with the rules used (for reports); with the columns of V(n, 2),
        the canonical form of :mod:`.columns` and the rules in turn until neither changes it."""
        p = x if isinstance(x, NCPoly) else NCPoly.scalar(x)
        if self._sylvester:
            return self._sylvester_reduce(p)
        if "columns" not in self._extras and "last" not in self._extras:
            red = self.system.reduce(p)
            if red.is_zero or not self.columns:
                return red
        if self.columns:
            self._column_letters()   # r is given: what the rules leave, in the basis of R^r
        rules: list = []
        q = p
        for _ in range(self.system.max_depth):
            red = self.system.reduce(canonical_form(q, self.columns))
            rules += [r for r in red.rules if r not in rules]
            if red.normal_form == q:
                return Reduction(p, red.normal_form, rules)
            q = red.normal_form
        raise RewritingError("the canonical form of the columns and the rules do not settle")

    def _sylvester_reduce(self, p: NCPoly, certify: bool = False) -> Any:
        """The rules and the steps ΛM → −MΛ + C of the multipliers of the metric realization in turn until
        neither changes p (see :mod:`.metric`): the Reduction, or with ``certify`` the Certificate."""
        from stiefelsym.free.metric import sylvester_step
        rules: list = []
        terms: list = []
        q = p
        for _ in range(self.system.max_depth):
            if certify:
                step = self.system.certify(q)
                terms += step.terms
                red_nf = step.normal_form
            else:
                red = self.system.reduce(q)
                rules += [r for r in red.rules if r not in rules]
                red_nf = red.normal_form
            nxt, cert, used = sylvester_step(red_nf, self._sylvester)
            terms += cert
            rules += [r for r in used if r not in rules]
            if not cert:
                return Certificate(p, red_nf, terms) if certify else Reduction(p, red_nf, rules)
            q = nxt
        raise RewritingError("the rules and the Sylvester relations of the multipliers do not settle")

    def certify(self, p: NCPoly, normal_form: NCPoly) -> Certificate:
        """p − nf(p) through the hypotheses (see :meth:`RewritingSystem.certify`); with the columns,
        the resolutions of :func:`.columns.canonical` and the rules' steps, in the order of :meth:`reduce`."""
        if self._sylvester:
            cert = self._sylvester_reduce(p, certify=True)
            if cert.normal_form != normal_form:
                raise RewritingError("the certificate's normal form is not the reduction's")
            return cert
        if ("columns" not in self._extras and "last" not in self._extras) or self.system.is_zero(p):
            return self.system.certify(p, normal_form)   # the rules alone (as reduce found, or as they suffice)
        terms: list = []
        q = p
        for _ in range(self.system.max_depth):
            c, cert = canonical(q, self.columns)
            terms += cert
            step = self.system.certify(c)
            terms += step.terms
            if step.normal_form == q:
                q = step.normal_form
                break
            q = step.normal_form
        if q != normal_form:
            raise RewritingError("the certificate's normal form is not the reduction's")
        return Certificate(p, q, terms)


def _refuse_unless_quadratic(kinetic: NCPoly, velocities: list, tracker: Any) -> None:
    """Refuse a kinetic energy of degree above 2 in the velocities, as the fixed sizes refuse it
    (systems.NOT_QUADRATIC): its third difference T(3v) − 3T(2v) + 3T(v) − T(0) is Σ_k (3ᵏ − 3·2ᵏ + 3 − 0ᵏ)T_k
    over T's homogeneous parts T_k in the velocity letters, with coefficient 0 for k <= 2 and positive for
    k >= 3; the letters are free (no rule relates them), so it has no term exactly when every T_k, k >= 3, is 0."""
    def scaled(m: int) -> NCPoly:
        return substitute(kinetic, {L: (_w(L) * m if m else NCPoly.zero(L.row, L.col)) for L in velocities})
    if (scaled(3) - scaled(2) * 3 + scaled(1) * 3 - scaled(0)).expand().terms:
        from stiefelsym.systems import NOT_QUADRATIC
        raise refuse(NOT_QUADRATIC, tracker)


class FreeTangentScene(FreeScene):
    """The free scene with primitives perturbed by ε·flow (entries a + bε)."""

    def __init__(self, base: FreeScene, flow: Mapping[str, Mat]) -> None:
        super().__init__(base.tracker, base.system)
        self.base = base
        self.flow = dict(flow)
        self._field = base._dual_field()
        self._share(base)
        self._named = base._named
        #: the tangent scene of a function's scene (FunctionScene): that scene's own (fresh) letters
        self._fresh = getattr(base, "_fresh", {})

    def _letter(self, L: Letter) -> Mat:
        F = self._fresh.get(L)
        if F is None:
            return super()._letter(L)
        hit = self._letters.get(F)
        if hit is None:
            hit = self._letters[F] = self._prim(str(L), _w(F))    # moved by the flow's component for L
        return hit

    def _prim(self, key: str, poly: NCPoly) -> Mat:
        return one_block(Dual(poly, _component(self.flow, key, poly, self.tracker)), self.field, poly.shape,
                         self.tracker)

    def _const_mat(self, p: NCPoly) -> Mat:
        return one_block(Dual(p, NCPoly.zero(p.row, p.col)), self.field, p.shape, self.tracker)

    def scalar_matrix(self, c: Any, m: Any, tag: str | None = None) -> Mat:
        M = self.base.scalar_matrix(c, m, tag)
        return _lift_mat(M, self.field)

    def zeros(self, m: Any, k: Any, tags=(None, None)) -> Mat:
        return _lift_mat(self.base.zeros(m, k, tags), self.field)

    def dirac_flow(self, H: Function) -> Flow:
        record_refusal("a flow built along a tangent", self.tracker)
        raise TypeError("flows are built on the base scene, not along a tangent")

    def d(self, F: Function | Any, flow: Flow | Mapping[str, Mat]) -> Any:
        """Refused (recorded): a derivative inside a function this scene's dual numbers differentiate.  The
        dual numbers do not nest (a tangent scene's primitives are the letters moved once, a value of it is
        not a polynomial the derivation takes): the graph writes a nested derivative as nodes where the
        functions allow (see :mod:`stiefelsym.ir.derivative`), and what it leaves needs fixed sizes."""
        raise refuse(_NESTED_DUALS, self.tracker)

    def tangent(self, flow: Mapping[str, Mat]) -> "FreeTangentScene":
        """Refused (recorded): a tangent scene of a tangent scene (see :meth:`d`)."""
        raise refuse(_NESTED_DUALS, self.tracker)


#: the refusal of a derivative (or tangent scene) inside a function the free scene's dual numbers differentiate
_NESTED_DUALS = ("a derivative along a flow nested in a derivative, in a form the graph does not write as nodes "
                 "(the dimension-free scene's dual numbers do not nest)")


#: the letters of a point of T*V (and of a second point): a function handed to a scene gets fresh ones
_POINT_LETTERS = (X, P, Y, Q)
_FRESH = [0]


class FunctionScene(FreeScene):
    """The scene a function handed to a free scene (a Hamiltonian, a function to differentiate) is
    evaluated on: the same field, rules, parameters and record, but its point is fresh letters X′, P′
    (Y′, Q′), distinct for every such scene.  A value of the enclosing scene the function closes over
    keeps its letters X, P and so stays a constant of the function; :meth:`back` renames the fresh
    letters to the enclosing scene's own once the function's derivatives are taken."""

    def __init__(self, base: FreeScene, ambient: bool = False) -> None:
        super().__init__(base.tracker, base.system)
        #: the function's ambient gradient is taken (here or in an enclosing function): a flow inside it
        #: whose multipliers are solved modulo the constraints would change it off T*V, and is refused
        self.ambient = ambient or getattr(base, "ambient", False)
        #: a flow's multipliers were solved inside the function (or a function inside it)
        self.nested_flow = False
        self._outer = base
        self._field = base._field
        self._share(base)
        _FRESH[0] += 1
        k = _FRESH[0]
        self._fresh: dict[Letter, Letter] = {}
        for L in _POINT_LETTERS:
            F, Ft = letter_pair(f"{L}'{k}", f"{L.adjoint}'{k}", L.row, L.col, L.latex, L.adjoint.latex)
            self._fresh[L], self._fresh[L.adjoint] = F, Ft
        # back to the enclosing scene's own letters (those of an enclosing function scene, when nested)
        outer = getattr(base, "_fresh", {})
        self._back = {self._fresh[L]: _w(outer.get(L, L)) for L in _POINT_LETTERS}

    def _letter(self, L: Letter) -> Mat:
        return super()._letter(self._fresh.get(L, L))

    def own(self, L: Letter) -> Letter:
        """The fresh letter that stands for the enclosing scene's letter L."""
        return self._fresh[L]

    def back(self, p: NCPoly) -> NCPoly:
        """p with the fresh letters renamed to the enclosing scene's X, P (Y, Q)."""
        return substitute(p, self._back)

    def at_point(self, Xv: Mat, Pv: Mat) -> "FreePointScene":
        raise refuse("a scene at another point inside a function handed to the scene", self.tracker)

    # flows inside a function: their multipliers are solved with the rules of the point X, P; the
    # function's point is its fresh letters, so the gradients are renamed to X, P for the solve and the
    # flow renamed back (an isomorphism of the algebra when no value of the base point is among them)
    def to_point(self, *polys: NCPoly) -> list[NCPoly]:
        """The polynomials with this scene's letters renamed to X, P (Y, Q); refused when they hold the base
        point's own letters too (a captured value, which the renaming would take for this scene's)."""
        if _point_letters_in(list(polys), set()):
            raise refuse("a flow inside a function handed to the scene, of a Hamiltonian that closes over a value "
                         "of the scene's point", self.tracker)
        return [substitute(q, {self._fresh[L]: _w(L) for L in _POINT_LETTERS}) for q in polys]

    def from_point(self, *polys: NCPoly) -> list[NCPoly]:
        """The inverse renaming of :meth:`to_point`."""
        return [substitute(q, {L: _w(self._fresh[L]) for L in _POINT_LETTERS}) for q in polys]

    def refuse_ambient_flow(self) -> None:
        """Refused in a function whose ambient gradient is taken; otherwise recorded (see ``nested_flow``)."""
        s: Any = self
        while isinstance(s, FunctionScene):
            s.nested_flow = True
            s = s._outer
        if self.ambient:
            raise refuse("a flow inside a function whose ambient gradient is taken (its multipliers are solved "
                         "modulo the constraints, which changes the function off T*V)", self.tracker)

    def _multiplier_flow(self, H: Function) -> Flow:
        if self.realization == "metric":
            raise refuse("a flow of the metric realization inside a function handed to the scene (its multiplier "
                         "is a letter, constant for the function)", self.tracker)
        self.refuse_ambient_flow()
        HX, HP = self.to_point(*(entry_of(m) for m in self._gradient(H)))
        Xd, Pd, Lam, Pi = self.from_point(*self._pair_multipliers(HX, HP, X, P))
        return Flow(self._const_mat(Xd), self._const_mat(Pd),
                    multipliers={"Pi": self._const_mat(Pi), "Lambda": self._const_mat(Lam)})

    def pairs_dirac_flow(self, H, point, pairs):
        raise refuse("a flow with multipliers inside a function handed to the scene", self.tracker)

    def derivative_at_own_point(self, F, point, tangent):
        raise refuse("a derivative at a point of a phase space inside a function handed to the scene", self.tracker)

    def euler_lagrange_double(self, T, U, constraints, position, velocity):
        raise refuse("Euler-Lagrange equations inside a function handed to the scene", self.tracker)

    def euler_lagrange_complex(self, T, U, constraints, position, velocity):
        raise refuse("Euler-Lagrange equations inside a function handed to the scene", self.tracker)


#: fresh letters of the forms differentiated by :meth:`FreeScene.form_gradient` (one per form)
_FORM_LETTERS = 0


def _point_letters_in(v: Any, out: set) -> set:
    """The letters X, P, Y, Q (and transposes) in a value of a free scene, operator arguments included."""
    return _letters_in(v, lambda L: any(L is M or L is M.adjoint for M in _POINT_LETTERS), out)


def _fresh_letters_in(v: Any, fresh: set, out: set) -> set:
    """The letters of ``fresh`` (and their transposes) in a value of a free scene, operator arguments included."""
    return _letters_in(v, fresh.__contains__, out)


def _letters_in(v: Any, wanted: Callable[[Any], bool], out: set) -> set:
    """The letters L with ``wanted(L)`` in a value of a free scene (matrices, dual numbers, flows, lists and
    dicts of them), operator arguments included."""
    if isinstance(v, Mat):
        for x in v._a.flat:
            _letters_in(x, wanted, out)
    elif isinstance(v, Dual):
        _letters_in(v.a, wanted, out)
        _letters_in(v.b, wanted, out)
    elif isinstance(v, NCPoly):
        stack = list(v.letters())
        while stack:
            L = stack.pop()
            if isinstance(L, OperatorLetter):
                stack.extend(L.argument)
            elif wanted(L):
                out.add(L)
    elif isinstance(v, Flow):
        _letters_in(v.Xdot, wanted, out)
        _letters_in(v.Pdot, wanted, out)
    elif isinstance(v, (list, tuple)):
        for x in v:
            _letters_in(x, wanted, out)
    elif isinstance(v, dict):
        for x in v.values():
            _letters_in(x, wanted, out)
    return out


def _lift_mat(M: Mat, field: Field) -> Mat:
    a = np.empty(M._shape(), dtype=object)
    for idx, x in np.ndenumerate(M._view()):
        a[idx] = Dual(x, NCPoly.zero(x.row, x.col) if isinstance(x, NCPoly) else se.Integer(0))
    return Mat._wrap(a, field, M.tags, M.tracker)


def _map_value(v: Any, scene: FreeScene) -> Any:
    """The ε-part of a value computed on a tangent scene, normalized."""
    if type(v) is Mat and v._shape() == (1, 1):   # one block (what map_entries makes of it, at once)
        return Mat._wrap_native(_eps_part(entry_of(v), scene), scene.field, v.tags, scene.tracker, v._coords)
    return map_entries(v, lambda x: _eps_part(x, scene), scene)


def _eps_part(x: Any, scene: FreeScene) -> Any:
    if isinstance(x, Dual):
        return scene.field.normalize(x.b)
    if isinstance(x, NCPoly):
        return NCPoly.zero(x.row, x.col)
    return se.Integer(0)


# ---------------------------------------------------------------------------
def solve_multipliers(equations: list[NCPoly], unknowns: list[Letter],
                      system: RewritingSystem) -> dict[Letter, NCPoly]:
    """Solve equations of the form c·U + (terms free of the unknowns) = 0, one unknown at a time.

    Solved unknowns are substituted into the remaining equations; a solution
    must be self-adjoint when the unknown is.  Raises FreeSolveError otherwise."""
    solved: dict[Letter, NCPoly] = {}
    pending = list(equations)
    todo = list(unknowns)
    while todo:
        progress = False
        for k, eq in enumerate(pending):
            eq = system.normal_form(substitute(eq, solved)) if solved else eq
            pending[k] = eq
            for U in todo:
                sol = _isolate(eq, U, todo)
                if sol is None:
                    continue
                sol = system.normal_form(sol)
                if U.adjoint == U and U.adjoint_sign == 1 and not system.is_zero(sol.star() - sol):
                    record_refusal(f"the multiplier {U}, not symmetric")
                    raise FreeSolveError(f"the solution for {U} is not symmetric: {sol}")
                solved[U] = sol
                todo.remove(U)
                pending.pop(k)
                progress = True
                break
            if progress:
                break
        if not progress:
            names = ", ".join(map(str, todo))
            record_refusal(f"the multipliers {names}, not solvable one at a time")
            raise FreeSolveError(f"the multipliers {names} are not of the form c·U + (terms free of U) = 0 "
                                 "after reduction; solve them with a coordinate backend")
    return solved


def _isolate(eq: NCPoly, U: Letter, unknowns: list[Letter]) -> NCPoly | None:
    """−rest/c if eq = c·U + rest with c a nonzero scalar and rest free of all unknowns.  A coefficient that
    depends on the sizes (n − r, n − 2r: zero at some sizes, where the equations have no unique solution) is
    refused (:func:`divisor`): a division the certificate would not show, so the proof would claim sizes where it
    divided by 0."""
    c = eq.terms.get(((), (U,)))
    if c is None or simplify_coef(c) == 0:
        return None
    rest = NCPoly({k: v for k, v in eq.terms.items() if k != ((), (U,))}, eq.row, eq.col)
    if rest.letters() & set(unknowns):
        return None
    return rest * (se.Integer(-1) / divisor(c))


def _operator_letters(y: Any) -> list[OperatorLetter]:
    polys = [y.a, y.b] if isinstance(y, Dual) else [y]
    return [L for q in polys for L in q.letters() if isinstance(L, OperatorLetter)]


# ---------------------------------------------------------------------------
class FreePointScene:
    """The free scene's problem at another point (X₁, P₁) of T*V, given by polynomials of the scene.

    Every value is computed at a generic point of a scene of its own (its letters X, P, the same rules,
    parameters and record) and then evaluated at the point by the substitution X ↦ X₁, P ↦ P₁, which
    maps every consequence of (cond_XP) to one, because (X₁, P₁) satisfies (cond_XP) (checked when the
    scene is made).  Flows it hands out are remembered, so that a derivative along one of them is taken
    at the generic point too; anything else given to it in the coordinates of the base scene is refused."""

    def __init__(self, base: FreeScene, Xv: NCPoly, Pv: NCPoly) -> None:
        self.base = base
        self.inner = FreeScene(base.tracker, realization="standard", lazy=getattr(base.field, "lazy", False),
                               columns=base.columns, square=base.square)
        self.inner.params = base.params
        self._images = {X: Xv, P: Pv}
        self._flows: dict[int, tuple[Flow, Flow]] = {}

    def lift(self, v: Any) -> Any:
        """A value of the generic point, evaluated at the point."""
        if isinstance(v, Flow):
            # the multipliers of s.multiplier_flow(H) too: functions of the point, evaluated there as every value
            out = Flow(self.lift(v.Xdot), self.lift(v.Pdot), multipliers=self.lift(dict(v.multipliers)))
            self._flows[id(out)] = (out, v)
            return out
        if isinstance(v, Mat):
            return map_entries(v, lambda x: self._sub(x), self.base)
        if isinstance(v, NCPoly):
            return self._sub(v)
        if isinstance(v, (list, tuple)):
            return type(v)(self.lift(x) for x in v)
        if isinstance(v, dict):
            return {k: self.lift(x) for k, x in v.items()}
        if callable(v):
            return lambda *a, **k: self.lift(v(*[self._lower(x) for x in a], **{n: self._lower(x) for n, x in k.items()}))
        return v

    def _sub(self, x: Any) -> Any:
        if isinstance(x, NCPoly):
            return self.base.field.normalize(substitute(x, self._images))
        if isinstance(x, Dual):
            raise refuse("a value of a tangent scene at another point", self.base.tracker)
        return x

    def _lower(self, v: Any) -> Any:
        """What the generic point's scene takes for an argument: its own flows, functions, scalars."""
        if isinstance(v, Flow):
            hit = self._flows.get(id(v))
            if hit is None or hit[0] is not v:
                raise refuse("a flow at another point that the point's scene did not make", self.base.tracker)
            return hit[1]
        if isinstance(v, (Mat, NCPoly, dict, list, tuple)):
            raise refuse("a value in the base scene's coordinates handed to the scene at another point",
                         self.base.tracker)
        if callable(v) and self._closes_over_the_point(v):
            raise refuse("a function handed to the scene at another point that closes over a value of the "
                         "point X, P (the base scene's or the point's): read with the point's letters, it would be "
                         "substituted as the function's own variable", self.base.tracker)
        return v

    def _closes_over_the_point(self, f: Callable) -> bool:
        """Whether f, evaluated on a scene whose point is fresh letters, returns the letters X, P (Y, Q):
        they can only come from a value it closes over.  The scene at the point computes at the generic
        point X, P and substitutes (X, P) ↦ (X₁, P₁), which would move such a value too."""
        u = FunctionScene(self.inner)
        for args in ((u,), (u, {"X": u.X, "P": u.P})):
            try:
                return bool(_point_letters_in(f(*args), set()))
            except TypeError as exc:
                if "called with" not in str(exc):
                    return True
            except Exception:
                return True     # not evaluable on its own letters: not taken as a function of the point
        return True

    def _tangent_vector(self, flow: Any, keys: tuple) -> dict[str, Mat]:
        """The components ``keys`` of a flow the point's scene made, as its own tangent reads them at the generic
        point, evaluated at the point: what the graph's derivatives along the flow at the point read (see
        :mod:`stiefelsym.ir.derivative`; a flow given in the base scene's coordinates is refused, as
        :meth:`_lower` refuses it)."""
        return self.lift(self.inner._tangent_vector(self._lower(flow), keys))

    #: what does not depend on the point: taken from the base scene (values given in its coordinates)
    POINTLESS = frozenset({"tr", "killing", "q", "const", "zeros", "In", "Ir", "scalar_matrix", "mat", "A", "Ainv",
                           "resolvent", "lam", "eps", "kappa", "scalar", "xi", "zeta", "eta", "theta", "generic", "fresh",
                           "n", "r", "field", "tracker", "column", "last_column", "leading_columns", "Y", "Q"})

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        if name in self.POINTLESS:
            return getattr(self.base, name)
        return self.lift(getattr(self.inner, name))
