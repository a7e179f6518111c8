"""Tracing: a claim runs on tracers that hold no value, no number system and no backend.

A tracer is a node of the graph being built, with its kind (a matrix, a number,
a scene, or an engine value of unknown kind) and, for a matrix, its shape.  The
scene a claim gets (:class:`TraceScene`) offers the documented API and nothing
else; what it returns are tracers again.  So claim code can branch only on what
every method shares: the sizes (at a fixed size) and the structure of what it
built.  Every refused operation raises :class:`TraceRefused` with a message that
does not depend on the method (no method runs during a trace), and is recorded
in the graph first, so a claim that catches the refusal is still refused.

Functions the claim hands to the engine (a Hamiltonian, a function to
differentiate, an operator's argument) are traced once, as ``fn`` nodes whose
parameters are a scene and further tracers; the engine later calls the
evaluated function, never the claim's code.  Engine helpers that need more
than the scene's API are :func:`primitive`: inside a trace a call to one is a
single node.
"""
from __future__ import annotations

import functools
import inspect
import sys
from fractions import Fraction
import math
from typing import Any, Callable, Iterator

from stiefelsym.ir.seal import refuse_registration
from stiefelsym.latex import one_line
from stiefelsym.ir.families import COMPARISONS, SYMBOLS, SizeFamily
from stiefelsym.ir.graph import _REFS, Graph, Named, Ref, Size, _ref
from stiefelsym.ir.sites import RECORDING, STOP, claim_site
from stiefelsym.ir.statements import DOMAINS, Count, Inverse, Rank, RightInverse


class TraceRefused(TypeError):
    """A claim asked its scene for something the IR does not hold (the same message on every method)."""


#: the traces running (innermost last); engine primitives called while a trace runs are recorded
_ACTIVE: list["Trace"] = []

#: engine functions recorded as single steps, by qualified name
PRIMITIVES: dict[str, Callable] = {}
#: engine steps whose value does not move with the point (their derivative along a flow is 0), by
#: qualified name
CONSTANT_PRIMITIVES: dict[str, Callable] = {}
#: engine steps whose value is zero wherever they are defined (a check of their arguments that raises otherwise): a
#: check made at the point, so their derivative along a flow and their adjoint are 0 only where no argument moves
#: (elsewhere the scene evaluates them, its dual numbers checking both parts: see :mod:`.derivative`)
ZERO_PRIMITIVES: dict[str, Callable] = {}
#: engine constants a claim may hand to a primitive, by identity
_NAMED: dict[int, tuple[str, Any]] = {}


def primitive(f: Callable | None = None, *, returns: Any = None, like: dict[str, str] | None = None,
              constant: bool = False, check: Callable[["Trace", dict], None] | None = None,
              zero: bool = False) -> Any:
    """Mark an engine function as one step of the IR: called while a claim is traced, it becomes a
    ``prim`` node (its function arguments traced once); otherwise it runs as written.

    ``returns``: the structure of its value for claim code (None: an engine value; k: a tuple of
    k values; "scene": a scene; ("like", name): the structure of the value of the function argument
    ``name``, or, when ``name`` is a matrix argument, a matrix of its spaces; ("mat", spaces): a matrix of
    those spaces, such as ("r", "r")).  ``like``: for a function
    argument, the argument whose structure its second parameter has (a point of a phase space of the
    caller's).  ``constant``: its value does not move with the point of the scene it is given (a
    coordinate basis vector): its derivative along every flow is 0 (see :mod:`.derivative`).  ``check``: called
    while tracing with the trace and the step's bound arguments, before the node is made: it refuses
    (``trace.refuse``) arguments the step is not defined for, from the graph alone (the same refusal whatever
    the method)."""
    if f is None:
        return lambda g: primitive(g, returns=returns, like=like, constant=constant, check=check, zero=zero)
    refuse_registration("an engine step (primitive)")
    qual = f"{f.__module__}.{f.__qualname__}"
    PRIMITIVES[qual] = f
    if constant:
        CONSTANT_PRIMITIVES[qual] = f
    if zero:
        ZERO_PRIMITIVES[qual] = f
    sig = inspect.signature(f)

    @functools.wraps(f)
    def wrapper(*args, **kw):
        if _ACTIVE:
            bound = None            # the arguments by name, bound once for the check and the shapes
            shaped = type(returns) is tuple and returns[0] == "like"
            if check is not None or like or shaped:
                try:
                    bound = sig.bind(*args, **kw).arguments
                except TypeError:
                    if like or shaped:
                        raise
                    # no check: the step's own call raises as it does untraced
            if check is not None and bound is not None:
                check(_ACTIVE[-1], bound)
            shapes = {}
            if like or shaped:
                shapes = {bound[name]: bound[other] for name, other in (like or {}).items() if name in bound}
                if shaped and returns[1] in bound:
                    shapes["__returns__"] = bound[returns[1]]
            return _ACTIVE[-1].prim(qual, args, kw, returns, shapes)
        return f(*args, **kw)
    wrapper.__ir_primitive__ = qual          # type: ignore[attr-defined]
    _NAMED[id(wrapper)] = (qual, wrapper)
    return wrapper


#: checks of an engine step's node made from the graph once its functions are traced (qualname -> check(trace,
#: ref)): they refuse (``trace.refuse``) what the step is not defined for, the same refusal whatever the method
STEP_GRAPH_CHECKS: dict[str, Callable[["Trace", Any], None]] = {}


def _not_a_value(tx: type) -> str:
    """The refusal of an object of type ``tx`` as an argument or operand, with a hint for a float and a check."""
    hint = (": write ½ as s.q(1, 2) or Fraction(1, 2), or divide (x / 2)" if tx is float else
            ": a statement is a check of its own, the value of a key of the dict the claim returns "
            "({'dim V': Count(...), 'rank M': Rank(...)})" if tx in (Count, Rank) else "")
    return f"{_article(tx.__name__)} {tx.__name__} is not a value of the IR (exact constants are int and Fraction){hint}"


def _article(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" else "a"


def named(qualname: str, obj: Any) -> Any:
    """Register an engine constant (an operator space, an engine function) a claim may pass on."""
    refuse_registration("an engine constant (named)")
    _NAMED[id(obj)] = (qualname, obj)
    PRIMITIVES.setdefault(qualname, obj)
    return obj


def is_tracer(x: Any) -> bool:
    return isinstance(x, (Tracer, TraceScene))


# ---------------------------------------------------------------------------------------------
# sizes

class Dim:
    """A size ``k·n`` or ``k·r`` as claim code sees it.  It carries no number: it is the expression
    k·d and the trace it belongs to.  Its number is given out by one door, :meth:`_int` (int(n),
    range(n), n == 3, str(n), hash(n) ... all go through it), which asks the trace: at a fixed size
    the trace answers, traced with symbolic sizes the use is refused (and recorded).  So a claim
    that traces with symbolic sizes without a refusal read no size, and its graph at every size is
    the same.  Apart from the door, a size may be multiplied by a positive int and used as a size of the
    scene's blocks; any other attribute is refused."""

    __slots__ = ("_expr", "_owner")

    def __init__(self, size: Size, trace: "Trace") -> None:
        object.__setattr__(self, "_expr", Size(size.k, size.d, None))
        object.__setattr__(self, "_owner", trace)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a size is read-only")

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)      # Python's probes of protocols
        return self._owner.refuse(f"a size has no attribute {name!r} (its number is int(n), at fixed sizes)")

    def __reduce__(self):
        return self._owner.refuse("a size cannot be pickled (its number is int(n), at fixed sizes)")

    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self

    def _int(self, what: str = "as a number") -> int:
        return self._owner.size_number(self._expr, what)

    def _statement_int(self, what: str) -> int:
        return self._int(f"in {what}")

    def __mul__(self, c: Any) -> Any:
        # a size times a positive int is a size (k·d); times 0 or a negative int it is no size of a space,
        # only a number: through the door (a fixed size's number; refused with symbolic sizes)
        if type(c) is int and c > 0:
            s = self._expr
            return Dim(Size(s.k * c, s.d, None), self._owner)
        return self._int("as a number" if type(c) in (int, Dim) else AS_SCALAR) * (c._int() if type(c) is Dim else c)

    __rmul__ = __mul__

    def __repr__(self) -> str:
        return repr(self._int("in text"))

    def __hash__(self) -> int:
        return hash(self._int("as a key"))


#: the use named when a size meets a value of the claim in arithmetic: with symbolic sizes the way to write it
AS_SCALAR = ("in arithmetic with a value of the claim (the size as a scalar of the claim: s.tr(s.Ir) = r, "
             "s.tr(s.In) = n)")
#: the operations of a size that are arithmetic (the others read it as an int, a key, a text, a truth value)
_ARITHMETIC = frozenset({"__add__", "__radd__", "__sub__", "__rsub__", "__truediv__", "__rtruediv__", "__pow__",
                         "__rpow__"})


def _dim_op(name: str):
    def op(self, *args):
        value = bool(args) and not all(type(a) in (int, Dim) for a in args)
        v = self._int(AS_SCALAR if value and name in _ARITHMETIC else "as a number")
        return getattr(v, name)(*[a._int() if type(a) is Dim else a for a in args])
    op.__name__ = name
    return op


def _dim_comparison(name: str):
    """A comparison of a size with a size of the same trace or an int: one question to the trace (see
    :meth:`Trace.size_compare`); with anything else, the numbers of the sizes."""
    def op(self, other):
        if (type(other) is Dim and other._owner is self._owner) or type(other) is int:
            return self._owner.size_compare(self._expr, name, other._expr if type(other) is Dim else other)
        return getattr(self._int(), name)(other._int() if type(other) is Dim else other)
    op.__name__ = name
    return op


for _name in ("__add__", "__radd__", "__sub__", "__rsub__", "__floordiv__", "__rfloordiv__", "__truediv__",
              "__rtruediv__", "__mod__", "__rmod__", "__pow__", "__rpow__", "__neg__", "__pos__", "__abs__",
              "__int__", "__index__", "__float__", "__bool__", "__str__", "__format__", "__divmod__", "__rdivmod__",
              "__round__", "__complex__"):
    setattr(Dim, _name, _dim_op(_name))
for _name in COMPARISONS:
    setattr(Dim, _name, _dim_comparison(_name))


def _val(a: Any, t: "Trace") -> int | None:
    """The value of a size (an int, a :class:`Size` at a fixed size: the trace's number), or None.
    The engine's own checks of shapes (what they refuse is recorded), not a door for claim code."""
    return a if type(a) is int else t._numbers(a) if type(a) is Size else None


def _same_size(a: Any, b: Any, t: "Trace") -> bool | None:
    """Whether two sizes agree (for sizes of the scene: the same multiple of the same space); None
    when it cannot be told."""
    if a is None or b is None:
        return None
    if type(a) is Size and type(b) is Size:
        return (a.k, a.d) == (b.k, b.d)
    va, vb = _val(a, t), _val(b, t)
    if va is None or vb is None:
        return None
    return va == vb


def _add_sizes(t: "Trace", a: Any, b: Any) -> Any:
    if type(a) is Size and type(b) is Size and a.d == b.d:
        return Size(a.k + b.k, a.d, None)
    va, vb = _val(a, t), _val(b, t)
    return None if va is None or vb is None else va + vb


# ---------------------------------------------------------------------------------------------
# tracers

MAT, SCALAR, ANY = "matrix", "number", "value"


class Tracer:
    """A node of the graph as claim code holds it: a matrix, a number, or an engine value."""

    __slots__ = ("_t", "_r", "_kind", "_shape")
    __array_ufunc__ = None          # numpy hands every operation back to the tracer
    __array_priority__ = 1000

    def __init__(self, t: "Trace", r: Ref, kind: str, shape: tuple = (None, None)) -> None:
        _SET_T(self, t)
        _SET_R(self, r)
        _SET_KIND(self, kind)
        _SET_SHAPE(self, shape)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a traced value is read-only")

    # -- what has no meaning on a graph -----------------------------------------------------
    def _value_read(self, *args: Any) -> Any:
        self._t.refuse(f"the value of a traced {self._kind} was read (claims compute with values; "
                       "they never look at them)")

    def _comparison(self, *args: Any) -> Any:
        self._t.refuse(f"a comparison of a traced {self._kind} (claims compute with values; "
                       "they never look at them)")

    __bool__ = __float__ = __int__ = __index__ = __complex__ = __round__ = _value_read
    __lt__ = __le__ = __gt__ = __ge__ = __eq__ = __ne__ = _comparison
    __hash__ = object.__hash__
    __array__ = _value_read

    def __len__(self) -> int:
        return self._t.refuse(f"the length of a traced {self._kind} is not known")

    def __iter__(self):
        if self._kind == MAT:
            return self._t.refuse("a matrix is not iterable: read entries as M[i, j]")
        return self._t.refuse(f"a traced {self._kind} is not iterable")

    def __repr__(self) -> str:
        # the spaces of a matrix, never a number of a size (a text that differed between a trace at a
        # fixed size and one with symbolic sizes would tell them apart without the door of Dim)
        if self._kind == MAT:
            m, k = (x.text() if type(x) is Size else "?" for x in self._shape)
            return f"<traced {m}x{k} matrix>"
        return f"<traced {self._kind}>"

    __str__ = __repr__

    def __format__(self, spec: str) -> str:
        return repr(self)

    def __reduce__(self):
        return self._t.refuse("a traced value cannot be pickled")

    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self

    # -- shape --------------------------------------------------------------------------------
    @property
    def shape(self) -> tuple:
        if self._kind != MAT or None in self._shape:
            return self._t.refuse(f"the shape of a traced {self._kind} is not known")
        return tuple(Dim(s, self._t) if type(s) is Size else s for s in self._shape)

    @property
    def tags(self) -> tuple:
        """The spaces of a matrix's rows and columns as its sizes give them ('n', 'r', or '?')."""
        if self._kind != MAT:
            return self._t.refuse(f"a traced {self._kind} has no spaces")
        return tuple(x.d if type(x) is Size and x.k == 1 else "?" for x in self._shape)

    def inv(self) -> "Tracer":
        """The inverse of a square matrix."""
        if self._kind == SCALAR or _same_size(*self._shape, self._t) is False:
            return self._t.refuse("the inverse of a matrix that is not square")
        if self._kind == MAT and _val(self._shape[0], self._t) == 0:
            # refused here, whatever the method (a 0 x 0 inverse was the empty matrix to one backend and
            # a singular point to the others)
            return self._t.refuse("the inverse of an empty (0 x 0) matrix")
        return self._t.new("inv", (self._r,), self._kind, self._shape[::-1])

    def trace(self) -> "Tracer":
        """The trace of a square matrix."""
        if self._kind == SCALAR or _same_size(*self._shape, self._t) is False:
            return self._t.refuse("the trace of a matrix that is not square")
        return self._t.new("trace", (self._r,), SCALAR if self._kind == MAT else ANY)

    @property
    def T(self) -> "Tracer":
        if self._kind == SCALAR:
            return self._t.refuse("a number has no transpose")
        return self._t.new("T", (self._r,), self._kind, self._shape[::-1])

    # -- algebra ------------------------------------------------------------------------------
    def _sum(self, o: Any, op: str, swap: bool = False) -> "Tracer":
        t = self._t
        a = t.number_arg(o)
        kind_o = o._kind if isinstance(o, Tracer) else SCALAR
        kinds = {self._kind, kind_o}
        if kinds == {MAT, SCALAR}:
            return t.refuse("a sum of a matrix and a number (write c·I for a multiple of the identity)")
        if self._kind == MAT and kind_o == MAT:
            for x, y in zip(self._shape, o._shape):
                if _same_size(x, y, t) is False:
                    return t.refuse(f"a sum of matrices whose spaces do not match ({self!r}, {o!r})")
        shape = self._shape if self._kind == MAT else o._shape if kind_o == MAT else (None, None)
        if self._kind == MAT and None in shape and kind_o == MAT:
            shape = tuple(x if x is not None else y for x, y in zip(self._shape, o._shape))
        kind = ANY if ANY in kinds else self._kind
        args = (a, self._r) if swap else (self._r, a)
        return t.new(op, args, kind, shape)

    def __add__(self, o): return self._sum(o, "add")
    def __radd__(self, o): return self._sum(o, "add", swap=True)
    def __sub__(self, o): return self._sum(o, "sub")
    def __rsub__(self, o): return self._sum(o, "sub", swap=True)

    def __neg__(self):
        return self._t.new("neg", (self._r,), self._kind, self._shape)

    def __pos__(self):
        return self

    def __matmul__(self, o):
        t = self._t
        if not isinstance(o, Tracer):
            return t.refuse("a matrix product with something that is not a matrix of the scene")
        if SCALAR in (self._kind, o._kind):
            return t.refuse("a matrix product with a number (use *)")
        if _same_size(self._shape[1], o._shape[0], t) is False:
            return t.refuse(f"a product of matrices whose spaces do not match ({self!r} @ {o!r})")
        kind = MAT if self._kind == o._kind == MAT else ANY
        return t.new("matmul", (self._r, o._r), kind, (self._shape[0], o._shape[1]))

    def __rmatmul__(self, o):
        return self._t.refuse("a matrix product with something that is not a matrix of the scene")

    def _times(self, o: Any, swap: bool) -> "Tracer":
        t = self._t
        a = t.number_arg(o)
        kind_o = o._kind if isinstance(o, Tracer) else SCALAR
        if self._kind == MAT and kind_o == MAT:
            return t.refuse("a product of two matrices with * (use @)")
        kind = MAT if MAT in (self._kind, kind_o) else ANY if ANY in (self._kind, kind_o) else SCALAR
        shape = self._shape if self._kind == MAT else o._shape if kind_o == MAT else (None, None)
        return t.new("mul", (a, self._r) if swap else (self._r, a), kind, shape)

    def __mul__(self, o): return self._times(o, False)
    def __rmul__(self, o): return self._times(o, True)

    def __truediv__(self, o):
        t = self._t
        a = t.number_arg(o)
        if isinstance(o, Tracer) and o._kind == MAT:
            return t.refuse("a division by a matrix (use an inverse or a solve)")
        if type(o) in (int, Fraction) and o == 0:
            return t.refuse("a division by the constant 0")
        return t.new("div", (self._r, a), self._kind, self._shape)

    def __rtruediv__(self, o):
        t = self._t
        if self._kind == MAT:
            return t.refuse("a division by a matrix (use an inverse or a solve)")
        return t.new("div", (t.number_arg(o), self._r), self._kind, self._shape)

    def __pow__(self, k):
        t = self._t
        if type(k) is Dim:
            k = k._int("as an exponent")
        if self._kind == MAT:
            return t.refuse("M ** k of a matrix: ** is the power of a number; a matrix power is a product, "
                            "M @ M @ ... (or functools.reduce(operator.matmul, [M] * k))")
        if type(k) is not int:
            return t.refuse(f"a power of a number with an exponent that is not an int ({type(k).__name__}): "
                            "the residuals are rational functions")
        return t.new("pow", (self._r, k), self._kind, self._shape)

    def __abs__(self):
        return self._t.refuse("abs() of a traced value: the residuals are rational functions (for a magnitude, "
                              "use a square, x * x, or tr(M.T @ M) of a matrix)")

    # -- parts ----------------------------------------------------------------------------------
    def __getitem__(self, idx):
        t = self._t
        if self._kind == SCALAR:
            return t.refuse("a number has no entries")
        if type(idx) is str:
            if idx in _FLOW_ITEMS and self._kind == ANY and t.g.ops[self._r.i] == "call" \
                    and t.g.args[self._r.i][1] in _FLOW_CALLS:
                return self.__getattr__(_FLOW_ITEMS[idx])   # flow["X"] is flow.Xdot: the same node
            return t.new("item", (self._r, idx), ANY)
        if self._kind == ANY and type(idx) is int:
            return t.new("item", (self._r, idx), ANY)
        if not isinstance(idx, tuple) or len(idx) != 2:
            return t.refuse("index a matrix with two indices, M[i, j] or M[i0:i1, j0:j1]")
        enc, shape = [], []
        for i, ax in zip(idx, self._shape):
            if type(i) is Dim:
                i = i._int("as an index")
            if type(i) is int:
                length = _val(ax, t)
                if length is not None and not -length <= i < length:
                    # refused here, whatever the method: a backend would raise its own IndexError (or none)
                    return t.refuse(f"entry index {i} out of range for an axis of length {length}")
                enc.append(i)
                shape.append(None)
            elif type(i) is slice:
                parts = []
                for p in (i.start, i.stop, i.step):
                    if type(p) is Dim:
                        p = p._int("as an index")
                    if p is not None and type(p) is not int:
                        return t.refuse("a slice of a matrix has int bounds")
                    parts.append(p)
                if parts[2] == 0:
                    return t.refuse("a slice of a matrix with step 0")
                enc.append(("slice",) + tuple(parts))
                shape.append(len(range(*slice(*parts).indices(_val(ax, t)))) if _val(ax, t) is not None else None)
            else:
                return t.refuse("a matrix index is an int or a slice")
        if all(type(e) is int for e in enc):
            return t.new("entry", (self._r, enc[0], enc[1]), SCALAR if self._kind == MAT else ANY)
        ks = ["slice" if type(e) is tuple else "int" for e in enc]
        shape = [1 if k == "int" else s for k, s in zip(ks, shape)]
        return t.new("entry", (self._r, enc[0], enc[1]), MAT if self._kind == MAT else ANY, tuple(shape))

    # -- engine values of unknown kind (flows, operator spaces, tensors) ------------------------
    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)      # Python's and numpy's probes of protocols
        if name not in VALUE_ATTRS:
            return self._t.refuse(f"a traced {self._kind} has no attribute {name!r}")
        if self._kind != ANY:
            return self._t.refuse(f"a traced {self._kind} has no attribute {name!r}")
        kind, shape = VALUE_ATTRS[name]
        return self._t.new("attr", (self._r, name), kind, self._t.shape_of(shape))

    def __call__(self, *args, **kw):
        if self._kind != ANY:
            return self._t.refuse(f"a traced {self._kind} is not callable")
        return self._t.new("apply", (self._r,) + tuple(self._t.arg(a, functions=True) for a in args)
                           + self._t.kw(kw), ANY)


#: the scene's methods that return a flow on T*V, and the components a claim may read from one by
#: key as from a tangent vector: flow["X"] is flow.Xdot, flow["P"] is flow.Pdot
_FLOW_CALLS = frozenset({"dirac_flow", "multiplier_flow", "canonical_flow"})
_FLOW_ITEMS = {"X": "Xdot", "P": "Pdot"}

#: attributes of engine values a claim may read (flows, functions and tensors of the brackets module):
#: their kind and shape
VALUE_ATTRS: dict[str, tuple[str, tuple | None]] = {
    "Xdot": (MAT, ("n", "r")), "Pdot": (MAT, ("n", "r")), "extra": (ANY, None), "multipliers": (ANY, None),
    "tangent": (ANY, None), "scaled": (ANY, None), "bracket": (ANY, None), "grad": (ANY, None),
    "pullback": (ANY, None), "value": (ANY, None), "gradient": (ANY, None), "sharp": (ANY, None),
    "space": (ANY, None), "project": (ANY, None), "zero": (ANY, None), "basis": (ANY, None), "form": (ANY, None),
}


# ---------------------------------------------------------------------------------------------
# the scene

#: the scene's matrices: their spaces (rows, columns)
MATRICES = {"X": ("n", "r"), "P": ("n", "r"), "A": ("n", "n"), "Ainv": ("n", "n"), "Phi": ("n", "n"),
            "Psi": ("r", "r"), "In": ("n", "n"), "Ir": ("r", "r"), "xi": ("n", "n"), "zeta": ("n", "n"),
            "eta": ("r", "r"), "theta": ("r", "r"), "Y": ("n", "r"), "Q": ("n", "r"), "Zc": ((2, "n"), (2, "r")),
            "Zc_dot": ((2, "n"), (2, "r")), "DX": ("n", "r"), "DY": ("n", "r"), "DXdot": ("n", "r"),
            "DYdot": ("n", "r")}
NUMBERS = ("lam", "kappa", "eps")
#: the scene's methods, with the kind of what they return
METHODS = frozenset("""tr killing resolvent q const scalar mat zeros identity scalar_matrix generic general_params
    fresh sym_operator conj realify tangent d gradient dirac_flow multiplier_flow canonical_flow bracket
    canonical_bracket jacobian constraint_bracket_matrix""".split())
#: what a claim may ask of its scene (README: "What a scene s offers")
API = frozenset(MATRICES) | frozenset(NUMBERS) | METHODS | {"a", "n", "r", "constraints"}


class TraceConstraints:
    """The scene's realization of T*V: its name and the function of its constraints."""

    __slots__ = ("name", "build")

    def __init__(self, name: str, build: Callable) -> None:
        self.name, self.build = name, build


#: the slots of a tracer, set by the engine only (its __setattr__ refuses)
_SET_T, _SET_R, _SET_KIND, _SET_SHAPE = (Tracer._t.__set__, Tracer._r.__set__,   # type: ignore[attr-defined]
                                         Tracer._kind.__set__, Tracer._shape.__set__)  # type: ignore[attr-defined]


def _tracer(t: "Trace", r: Ref, kind: str, shape: tuple = (None, None)) -> Tracer:
    """Tracer(t, r, kind, shape), made without the call of __init__."""
    x = _NEW(Tracer)
    _SET_T(x, t)
    _SET_R(x, r)
    _SET_KIND(x, kind)
    _SET_SHAPE(x, shape)
    return x


_NEW = object.__new__
_FRAME = sys._getframe


class TraceScene:
    """The scene as claim code sees it while it is traced."""

    __slots__ = ("_t", "_r")

    def __init__(self, t: "Trace", r: Ref) -> None:
        object.__setattr__(self, "_t", t)
        object.__setattr__(self, "_r", r)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a scene is read-only")

    def __repr__(self) -> str:
        return "<a scene>"

    def __reduce__(self):
        return self._t.refuse("a scene cannot be pickled")

    def __getattr__(self, name: str) -> Any:
        t = self._t
        if name.startswith("_"):
            raise AttributeError(name)
        if name not in API:
            return t.refuse(f"a scene has no {name!r}{_did_you_mean(name)} (see docs/guide.md: what a scene s offers)")
        if name in MATRICES:
            return t.new("attr", (self._r, name), MAT, t.shape_of(MATRICES[name]))
        if name in NUMBERS:
            return t.new("attr", (self._r, name), SCALAR)
        if name in ("n", "r"):
            return Dim(t.size(1, name), t)
        if name == "a":
            n = t.size_number(Size(1, "n", None), None)
            if n is None:
                return t.refuse("the eigenvalues a_i of A (they need fixed sizes and coordinates)")
            base = t.g.add("attr", (self._r, "a"))
            return [t.new("item", (base, i), SCALAR) for i in range(n)]
        if name == "constraints":
            name_, build = t.constraints
            return TraceConstraints(name_, build)
        return functools.partial(_SCENE_METHODS[name], self)


#: names a reader may reach for, and the scene's spelling of them
_ALIASES = {"I": "s.In (n×n) or s.Ir (r×r)", "Id": "s.In or s.Ir", "eye": "s.In or s.Ir", "In_": "s.In",
            "lambda_": "s.lam", "lmbda": "s.lam", "mu": "s.scalar('mu')", "nu": "s.scalar('nu')",
            "epsilon": "s.eps", "kap": "s.kappa", "Ai": "s.Ainv", "A_inv": "s.Ainv", "Ainverse": "s.Ainv",
            "trace": "s.tr(M) or M.trace()", "commutator": "comm(a, b) (from stiefelsym import comm)",
            "comm": "comm(a, b) (from stiefelsym import comm)", "block": "block(...) (from stiefelsym import block)",
            "flow": "s.dirac_flow(H)", "hamiltonian_flow": "s.dirac_flow(H)", "dirac_bracket": "s.bracket(F, G)",
            "poisson": "s.bracket(F, G)", "poisson_bracket": "s.bracket(F, G)", "R": "s.resolvent(mu)",
            "Xdot": "s.dirac_flow(H)['X'] (or .Xdot)", "Pdot": "s.dirac_flow(H)['P'] (or .Pdot)"}


def _did_you_mean(name: str) -> str:
    """A hint for a name the scene does not have: the scene's spelling of it, if it is a known alias
    or the same name in another case."""
    if name in _ALIASES:
        return f": write {_ALIASES[name]}"
    same = sorted(x for x in API if x.lower() == name.lower())
    return f": did you mean s.{same[0]}?" if same else ""


def _call(s: TraceScene, name: str, args: tuple, kind: str, shape: tuple = (None, None), kw: tuple = ()) -> Tracer:
    return s._t.new("call", (s._r, name, args, kw), kind, shape)


def _m_tr(s, M):
    t = s._t
    if not isinstance(M, Tracer) or M._kind == SCALAR:
        return t.refuse("tr takes a matrix of the scene")
    if M._kind == MAT and _same_size(*M._shape, s._t) is False:
        return t.refuse(f"the trace (of the matrix itself, or of a power of it for det and elementary) of a matrix "
                        f"whose row and column spaces do not match ({M!r}): tr, det and powers take a map of one "
                        "space to itself, and a matrix from R^r to R^n (X, P) is not one, "
                        "even at r = n; the square matrix of its entries, s.mat([[M[i, j] for j in range(s.r)] for i "
                        "in range(s.n)], ('n', 'n')), is")
    return _call(s, "tr", (M._r,), SCALAR)


def _m_killing(s, a, b):
    t = s._t
    if not (isinstance(a, Tracer) and isinstance(b, Tracer)) or SCALAR in (a._kind, b._kind):
        return t.refuse("killing takes two matrices of the scene")
    return _call(s, "killing", (a._r, b._r), SCALAR)


def _m_resolvent(s, mu):
    t = s._t
    return _call(s, "resolvent", (t.number_arg(mu),), MAT, t.shape_of(("n", "n")))


def _m_q(s, num, den=1):
    t = s._t
    num, den = (x._int("in s.q") if type(x) is Dim else x for x in (num, den))
    for x in (num, den):
        if type(x) is not int:
            return t.refuse("s.q(num, den) takes ints")
    if den == 0:
        return t.refuse("s.q(num, 0): a zero denominator")
    return _call(s, "q", (num, den), SCALAR)


#: the refusal of a Fraction :func:`_reduced` rejects
MALFORMED_FRACTION = ("a Fraction that is not in lowest terms with int parts and a positive denominator (made by "
                      "hand): write Fraction(p, q)")


def _reduced(q: Fraction) -> bool:
    """Whether a Fraction is one Fraction(p, q) makes: int parts, in lowest terms, a positive denominator (one
    made by hand, with other parts, compares and hashes otherwise and changes when the graph is copied)."""
    num, den = getattr(q, "_numerator", None), getattr(q, "_denominator", None)
    return type(num) is int and type(den) is int and den > 0 and math.gcd(num, den) == 1


def _m_const(s, q):
    t = s._t
    if type(q) not in (int, Fraction):
        return t.refuse(f"a constant is an int or a Fraction, not a {type(q).__name__}")
    if type(q) is Fraction and not _reduced(q):
        return t.refuse(MALFORMED_FRACTION)
    return _call(s, "const", (q,), SCALAR)


def _one_name(t: "Trace", name: str, what: str) -> None:
    """A claim's name names one parameter: a second parameter of the same name (a scalar and a matrix, two
    kinds or two shapes of generic matrix) is refused, for the two would print alike in the traced text, the
    report and a witness (they are two parameters to every method: H_sym − H_skew read "0"; the trial of §2
    and §5 of stop 88, I1).  The same parameter asked for again is the same node."""
    had = t._names.setdefault(name, what)
    if had != what:
        t.refuse(f"the name {name!r} already names {had} of this claim; {what} needs a name of its own (two "
                 "parameters of one name would print alike)")


def _m_scalar(s, name):
    t = s._t
    if type(name) is not str:
        return t.refuse("a scalar parameter is named by a string")
    _one_name(t, name, "a scalar parameter")
    return _call(s, "scalar", (name,), SCALAR)


def _tags(t: "Trace", tags: Any, k: int) -> tuple:
    if type(tags) is str:
        tags = (tags,)
    if type(tags) is not tuple or len(tags) != k or any(type(x) is not str for x in tags):
        return t.refuse("the spaces of a matrix are given as strings ('n', 'r', '?')")
    return tags


def _size_arg(t: "Trace", m: Any, what: str) -> Any:
    if type(m) is Dim:
        return m._expr
    if type(m) is int and m >= 0:
        return m
    return t.refuse(f"{what} is a size (an int, or s.n, s.r and their multiples)")


def _m_mat(s, rows, tags=("?", "?")):
    t = s._t
    tags = _tags(t, tags, 2)
    if type(rows) is Tracer and rows._kind == ANY:       # rows an engine function made
        return _call(s, "mat", (rows._r, tags), MAT)
    if type(rows) not in (list, tuple) or any(type(r) not in (list, tuple) for r in rows):
        return t.refuse("s.mat takes a list of rows")
    width = len(rows[0]) if rows else 0
    if any(len(r) != width for r in rows):
        return t.refuse("the rows of a matrix have the same length")
    out = []
    for r in rows:
        cells = []
        for x in r:
            if type(x) is Tracer and x._t is t and x._kind != MAT:
                cells.append(x._r)      # t.number_arg(x) of a number of this trace, in line
                continue
            if isinstance(x, Tracer) and x._kind == MAT:
                return t.refuse("the entries of s.mat are numbers")
            cells.append(t.number_arg(x))
        out.append(t.g.add("list", tuple(cells)))
    shape = tuple(t.size(1, tg) if tg in ("n", "r") and _val(t.size(1, tg), t) == m else m
                  for tg, m in zip(tags, (len(rows), width)))
    return _call(s, "mat", (t.g.add("list", tuple(out)), tags), MAT, shape)


def _m_zeros(s, m, k, tags=("?", "?")):
    t = s._t
    m, k = _size_arg(t, m, "a number of rows"), _size_arg(t, k, "a number of columns")
    return _call(s, "zeros", (m, k, _tags(t, tags, 2)), MAT, (m, k))


def _m_identity(s, m, tag="?"):
    t = s._t
    m = _size_arg(t, m, "the size of an identity")
    return _call(s, "identity", (m, _tags(t, tag, 1)[0]), MAT, (m, m))


def _m_scalar_matrix(s, c, m, tag="?"):
    t = s._t
    m = _size_arg(t, m, "the size of a scalar matrix")
    return _call(s, "scalar_matrix", (t.number_arg(c), m, _tags(t, tag, 1)[0]), MAT, (m, m))


#: the names of the generic elements an Inverse statement is decided on (no claim code may name them)
INVERSE_ELEMENTS = "Inverse"


#: the kinds of a claim's generic matrix, s.generic(name, m, k, kind)
GENERIC_KINDS = ("general", "sym", "skew")


def generic_kind_problem(m: Any, k: Any, kind: Any) -> str | None:
    """Why s.generic(name, m, k, kind) is refused for its kind (None: it is not): the one message of the trace
    and of every scene."""
    if type(kind) is not str or kind not in GENERIC_KINDS or (kind != "general" and m != k):
        return ("s.generic(name, m, k, kind): the kinds are 'general', 'sym' and 'skew', and a 'sym' or 'skew' "
                "matrix is square (m = k)")
    return None


#: the spaces of a claim's generic matrix: ℝⁿ, ℝʳ, and ℝⁿ⁻ʳ (the second block of the chart at X₀ = (E₁ … E_r), an
#: opaque coordinate space: at fixed sizes only)
GENERIC_SPACES = ("n", "r", "n-r")


def _generic_side(t: "Trace", d: str) -> Any:
    """The size of a side of a generic matrix: k·d for ℝⁿ and ℝʳ; for ℝⁿ⁻ʳ the number n − r, through the door of
    sizes (a claim with one needs fixed sizes)."""
    if d != "n-r":
        return t.size(1, d)
    what = "as the size n − r of a generic block (s.generic(name, 'n-r', ...))"
    n, r = t.size_number(t.size(1, "n"), what), t.size_number(t.size(1, "r"), what)
    return None if n is None or r is None else n - r


def _m_generic(s, name, m, k, kind="general"):
    t = s._t
    if not all(type(x) is str for x in (name, m, k)) or not {m, k} <= set(GENERIC_SPACES):
        return t.refuse("s.generic(name, m, k): a name and the spaces 'n', 'r' or 'n-r'")
    problem = generic_kind_problem(m, k, kind)
    if problem:
        return t.refuse(problem)
    if name.startswith(INVERSE_ELEMENTS) and not t._elements:
        return t.refuse(f"the names {INVERSE_ELEMENTS}... are the generic elements of an Inverse statement")
    _one_name(t, name, f"a generic {'' if kind == 'general' else kind + ' '}{m}×{k} matrix")
    # a general matrix keeps the node of three arguments it always had (the same graphs, the same digests)
    return _call(s, "generic", (name, m, k) if kind == "general" else (name, m, k, kind), MAT,
                 (_generic_side(t, m), _generic_side(t, k)))


def _m_fresh(s, m, k):
    """s.fresh(m, k): a generic m×k matrix (m, k in 'n', 'r') of parameters no claim can name, new at every call.
    The engine numbers it (the trace's count of fresh elements, the same in both traces of a claim): the
    graph holds ``call fresh (i, m, k)``, which the API cannot write (a claim gives no number), and no
    two calls give the same element, so an element drawn for a statement about every element (the
    point and covectors of :func:`stiefelsym.brackets.poisson_checks`) cannot be named or kept by the claim."""
    t = s._t
    if not all(type(x) is str for x in (m, k)) or not {m, k} <= {"n", "r"}:
        return t.refuse("s.fresh(m, k): the spaces 'n' or 'r'")
    t._fresh += 1
    return _call(s, "fresh", (t._fresh, m, k), MAT, t.shape_of((m, k)))


def _m_general_params(s, name, m, k, tags):
    t = s._t
    if type(name) is not str:
        return t.refuse("a parameter block is named by a string")
    m, k = _size_arg(t, m, "a number of rows"), _size_arg(t, k, "a number of columns")
    tags = _tags(t, tags, 2)
    _one_name(t, name, f"a block of parameters ({m}×{k}, spaces {tags[0]}, {tags[1]})")
    return _call(s, "general_params", (name, m, k, tags), MAT, (m, k))


def _m_sym_operator(s, name="AA"):
    t = s._t
    if type(name) is not str:
        return t.refuse("an operator is named by a string")
    _one_name(t, name, "an operator")
    return _call(s, "sym_operator", (name,), ANY)


def _m_conj(s, M):
    t = s._t
    if not isinstance(M, Tracer):
        return t.refuse("conj takes a matrix of the scene")
    return _call(s, "conj", (M._r,), M._kind, M._shape)


def _m_realify(s, U, V):
    t = s._t
    if not (isinstance(U, Tracer) and isinstance(V, Tracer)):
        return t.refuse("realify takes two matrices of the scene")
    shape = tuple(_add_sizes(t, x, x) for x in U._shape)
    return _call(s, "realify", (U._r, V._r), U._kind, shape)


def _not_a_gradient(t: "Trace", flow: Any) -> None:
    if type(flow) is Gradient:
        t.refuse('a derivative along a gradient: a gradient is a covector; write the tangent vector as a dict, '
                 '{"X": g["X"], "P": g["P"]}')


def _m_tangent(s, flow):
    t = s._t
    _not_a_gradient(t, flow)
    return TraceScene(t, t.g.add("call", (s._r, "tangent", (t.arg(flow),), ())))


def _m_d(s, F, flow):
    t = s._t
    _not_a_gradient(t, flow)
    f, out = t.function(F, 1)
    node = t.g.add("call", (s._r, "d", (f, t.arg(flow)), ()))
    return t.mirror(out, node)


def _m_gradient(s, H):
    t = s._t
    f, _ = t.function(H, 1)
    node = t.g.add("call", (s._r, "gradient", (f,), ()))
    shape = t.shape_of(("n", "r"))
    return Gradient((t.new("item", (node, 0), MAT, shape), t.new("item", (node, 1), MAT, shape)))


class Gradient(tuple):
    """(dH/dX, dH/dP), the value of ``s.gradient(H)``: a pair (``HX, HP = s.gradient(H)``), also read by the
    names of its components, ``g["X"]`` and ``g["P"]``, as a flow is."""

    __slots__ = ()

    def __getitem__(self, k: Any) -> Any:
        if type(k) is str:
            if k not in ("X", "P"):
                raise TraceRefused(f"a gradient has the components 'X' and 'P' (dH/dX, dH/dP), not {k!r}")
            k = 0 if k == "X" else 1
        return tuple.__getitem__(self, k)

    def _arithmetic(self, *_: Any) -> Any:
        return tuple.__getitem__(self, 0)._t.refuse(
            'arithmetic on a gradient, a pair (dH/dX, dH/dP): write it on its components, 2 * g["X"]')

    __add__ = __radd__ = __mul__ = __rmul__ = _arithmetic


def _flow_method(name: str):
    def method(s, H):
        t = s._t
        f, _ = t.function(H, 1)
        return _call(s, name, (f,), ANY)
    return method


def _m_bracket(s, F, G):
    t = s._t
    f, _ = t.function(F, 1)
    g, _ = t.function(G, 1)
    return _call(s, "bracket", (f, g), SCALAR)


def _m_canonical_bracket(s, F, G):
    t = s._t
    f, _ = t.function(F, 1)
    g, _ = t.function(G, 1)
    return _call(s, "canonical_bracket", (f, g), SCALAR)


def _components(t: "Trace", out: Any, symmetric: bool) -> int:
    """The number of scalar components of a function's value (the rows of its Jacobian)."""
    if isinstance(out, Tracer):
        if out._kind == SCALAR:
            return 1
        m, k = (_val(x, t) for x in out._shape)
        if out._kind != MAT or m is None or k is None:
            return t.refuse("a Jacobian of a function whose value has no known shape")
        if symmetric:
            if m != k:
                return t.refuse("a Jacobian of symmetric components of a non-square matrix")
            return m * (m + 1) // 2
        return m * k
    if type(out) in (list, tuple, Gradient):
        return sum(_components(t, x, symmetric) for x in out)
    return t.refuse("a Jacobian of a function whose value is not a number, a matrix or a list of them")


def _m_jacobian(s, F, symmetric=None):
    t = s._t
    if symmetric is None:
        symmetric = F is t.constraints[1]
    if type(symmetric) is not bool:
        return t.refuse("symmetric is a bool")
    n, r = t.size_number(Size(1, "n", None), None), t.size_number(Size(1, "r", None), None)
    if n is None:
        return t.refuse("a Jacobian in the coordinates of X, P (it needs fixed sizes)")
    f, out = t.function(F, 1)
    rows = _components(t, out, symmetric)
    node = t.g.add("call", (s._r, "jacobian", (f, symmetric), ()))
    return _grid(t, node, rows, 2 * n * r)


def _grid(t: "Trace", node: Ref, rows: int, cols: int) -> list:
    out = []
    g = t.g
    if g.sites is not None:
        for i in range(rows):
            row = g.add("item", (node, i))
            out.append([t.new("item", (row, j), SCALAR) for j in range(cols)])
        return out
    # Trace.new in line (no sites to record): one tracer per entry
    index, ops, args = g.index, g.ops, g.args
    for i in range(rows):
        row = g.add("item", (node, i))
        cells = []
        for j in range(cols):
            a = (row, j)
            k = index.get(("item", a))
            if k is None:
                k = index[("item", a)] = len(ops)
                ops.append("item")
                args.append(a)
            x = _NEW(Tracer)
            _SET_T(x, t)
            _SET_R(x, _REFS[k] if k < len(_REFS) else _ref(k))
            _SET_KIND(x, SCALAR)
            _SET_SHAPE(x, (None, None))
            cells.append(x)
        out.append(cells)
    return out


def _m_constraint_bracket_matrix(s):
    t = s._t
    if t.size_number(Size(1, "n", None), None) is None:
        return t.refuse("the matrix of constraint brackets (it needs fixed sizes)")
    _, out = t.function(t.constraints[1], 1)
    m = _components(t, out, True)
    return _grid(t, t.g.add("call", (s._r, "constraint_bracket_matrix", (), ())), m, m)


_SCENE_METHODS: dict[str, Callable] = {
    "tr": _m_tr, "killing": _m_killing, "resolvent": _m_resolvent, "q": _m_q, "const": _m_const,
    "scalar": _m_scalar, "mat": _m_mat, "zeros": _m_zeros, "identity": _m_identity,
    "scalar_matrix": _m_scalar_matrix, "generic": _m_generic, "fresh": _m_fresh,
    "general_params": _m_general_params,
    "sym_operator": _m_sym_operator, "conj": _m_conj, "realify": _m_realify, "tangent": _m_tangent,
    "d": _m_d, "gradient": _m_gradient, "dirac_flow": _flow_method("dirac_flow"),
    "multiplier_flow": _flow_method("multiplier_flow"), "canonical_flow": _flow_method("canonical_flow"),
    "bracket": _m_bracket, "canonical_bracket": _m_canonical_bracket, "jacobian": _m_jacobian,
    "constraint_bracket_matrix": _m_constraint_bracket_matrix,
}
assert set(_SCENE_METHODS) == METHODS


# ---------------------------------------------------------------------------------------------
# blocks

def block(rows: Any) -> Tracer:
    """A block matrix of traced matrices (its sizes the sums of the blocks' sizes)."""
    t = next((b._t for row in rows for b in row if isinstance(b, Tracer)), None)
    if t is None:               # the engine's own matrices (engine code, tests)
        from stiefelsym.backends.matrix import block as engine_block
        return engine_block(rows)
    rows = [list(row) for row in rows]
    if not rows or not rows[0] or any(len(row) != len(rows[0]) for row in rows):
        return t.refuse("a block matrix needs a rectangular, non-empty grid of blocks")
    if not all(isinstance(b, Tracer) and b._kind != SCALAR for row in rows for b in row):
        return t.refuse("the blocks of a block matrix must be matrices, not numbers: a zero block is "
                        "s.zeros(rows, columns, spaces), e.g. s.zeros(s.r, s.n, (\"r\", \"n\")), and a multiple of "
                        "the identity c * s.Ir or c * s.In")
    heights = []
    for row in rows:
        h = row[0]._shape[0]
        for b in row[1:]:
            if _same_size(h, b._shape[0], t) is False:
                return t.refuse("the blocks of a block row have different heights")
        heights.append(h)
    widths = []
    for j in range(len(rows[0])):
        w = rows[0][j]._shape[1]
        for row in rows[1:]:
            if _same_size(w, row[j]._shape[1], t) is False:
                return t.refuse("the blocks of a block column have different widths")
        widths.append(w)
    add = functools.partial(_add_sizes, t)
    shape = (functools.reduce(add, heights), functools.reduce(add, widths))
    kind = ANY if any(b._kind == ANY for row in rows for b in row) else MAT
    return t.new("block", (len(rows), len(rows[0]), tuple(b._r for row in rows for b in row)), kind, shape)


# ---------------------------------------------------------------------------------------------
# the trace

class Trace:
    """One tracing of one claim at one size (or with symbolic sizes)."""

    def __init__(self, n: int | None, r: int | None, constraints: tuple[str, Callable],
                 family: SizeFamily | None = None) -> None:
        self.g = Graph()
        # the numbers of the sizes live here, in a function of the trace's own: no Size, Dim or
        # tracer claim code reaches carries one, and the graph gets them when it is sealed.  Traced
        # with a family of sizes (symbolic sizes), a size has a number when it has the same one at
        # every size of the family (r at r = 1)
        if family is not None and (n is not None or r is not None):
            raise ValueError("a trace is at a size or with a family of sizes, not both")
        self._family = family
        self._numbers = family.number if family is not None else _size_numbers(n, r)
        self._like: dict = {}
        self.constraints = constraints
        self._functions: dict[int, tuple[Any, Ref, Any, Any]] = {}
        #: id(object) -> (object, node): the graph of the first evaluation of each object whose evaluations
        #: must be one function (see :func:`same_step_function`)
        self._one_function: dict[Any, tuple[Any, Any]] = {}
        #: id(object) -> the calls of each object whose calls, inline or as an engine step's function, must be
        #: one function (see :func:`same_inline_function`, :func:`_same_call`)
        self._calls: dict[int, dict] = {}
        #: id(function) -> (function, body) at its first trace (see :meth:`function`)
        self._first_bodies: dict[int, tuple[Any, Any]] = {}
        self._elements = False     # the generic elements of an Inverse statement are being made
        self._fresh = 0            # the fresh elements made so far (s.fresh)
        self._open = [0]           # the functions being traced (0: the claim), innermost last
        self._parents: dict[int, frozenset] = {}   # per function, those open when it was traced
        #: name -> (what it names, in words) of the claim's named parameters: one name, one parameter
        self._names: dict[str, str] = {}

    # -- nodes ----------------------------------------------------------------------------------
    def new(self, op: str, args: tuple, kind: str, shape: tuple = (None, None)) -> Tracer:
        # Graph.add and _tracer, in line (the tracer's innermost step)
        g = self.g
        key = (op, args)
        i = g.index.get(key)
        if i is None:
            i = g.index[key] = len(g.ops)
            g.ops.append(op)
            g.args.append(args)
            if g.sites is not None:
                g.sites.append(claim_site(_FRAME(1)))
        x = _NEW(Tracer)
        _SET_T(x, self)
        _SET_R(x, _REFS[i] if i < len(_REFS) else _ref(i))
        _SET_KIND(x, kind)
        _SET_SHAPE(x, shape)
        return x

    def refuse(self, what: str) -> Any:
        self.g.refusals.append(what)
        raise TraceRefused(f"refused: {what}")

    def size(self, k: int, d: str) -> Size:
        """The size expression k·d (it carries no number; one object per k·d, a Size is immutable)."""
        if type(k) is int and type(d) is str:
            hit = _SIZE_MEMO.get((k, d))
            if hit is None:
                hit = _SIZE_MEMO[(k, d)] = Size(k, d, None)
            return hit
        return Size(k, d, None)

    def size_number(self, size: Size, what: str | None) -> int | None:
        """The door of a size's number: at a fixed size its int; with symbolic sizes the use ``what``
        is refused (and recorded), or None for the engine's own question (``what`` None)."""
        v = self._numbers(size)
        if v is None and what is not None:
            self.refuse(f"a size ({size.text()}) used {what}: the claim needs fixed sizes")
        return v

    def size_compare(self, a: Size | int, name: str, b: Size | int) -> bool:
        """The door of a comparison of sizes: at a fixed size the comparison of their numbers; traced with a
        family of sizes its truth value when that is the same at every size of the family; otherwise
        refused (and recorded)."""
        va = a if type(a) is int else self._numbers(a)
        vb = b if type(b) is int else self._numbers(b)
        if va is not None and vb is not None:
            return COMPARISONS[name](va, vb)
        if self._family is None:
            return self.size_number(a if va is None else b, "as a number")
        decided = self._family.decide(a, name, b)
        if decided is None:
            text = lambda x: str(x) if type(x) is int else x.text()    # noqa: E731
            return self.refuse(f"a comparison of sizes ({text(a)} {SYMBOLS[name]} {text(b)}) that is not the same "
                               f"at every size of the family {self._family}: the claim needs fixed sizes")
        return decided

    @property
    def symbolic(self) -> bool:
        """Whether the sizes are symbolic (the engine's question: nothing is recorded)."""
        return self._numbers(Size(1, "n", None)) is None

    def shape_of(self, spaces: tuple | None) -> tuple:
        if spaces is None:
            return (None, None)
        return tuple(self.size(1, d) if type(d) is str else self.size(*d) for d in spaces)

    # -- arguments --------------------------------------------------------------------------------
    def arg(self, x: Any, functions: bool = False) -> Any:
        """An argument of an operation as the graph holds it (refused unless it is a traced value, an
        exact constant, a size, a string, a container of these or an engine constant)."""
        tx = type(x)
        if tx is Tracer or tx is TraceScene:
            if x._t is not self:
                return self.refuse("a traced value of another trace")
            return x._r
        if tx is Fraction and not _reduced(x):
            return self.refuse(MALFORMED_FRACTION)
        if tx is int or tx is bool or tx is Fraction or tx is str or x is None:
            return x
        if tx is Dim:
            return x._expr
        if tx is Gradient:
            x, tx = tuple(x), tuple
        if tx is list or tx is tuple:
            return self.g.add("list" if tx is list else "tuple", tuple(self.arg(y, functions) for y in x))
        if tx is dict:
            keys = tuple(x)
            if any(type(k) is not str for k in keys):
                return self.refuse("the keys of a dict handed to the engine are strings")
            return self.g.add("dict", (keys, tuple(self.arg(x[k], functions) for k in keys)))
        if tx is TraceConstraints:
            return self.arg(x.build, True)
        if id(x) in _NAMED and _NAMED[id(x)][1] is x:
            return Named(_NAMED[id(x)][0])
        if functions and callable(x) and not isinstance(x, type):
            return self.function(x, None)[0]
        return self.refuse(_not_a_value(tx))

    def number_arg(self, x: Any) -> Any:
        """An operand of +, −, · or /: a traced value, an int, a Fraction or a size, and nothing else (an
        allow-list; a bool, which Python counts as an int, is no number of a statement: as the constants of a
        Count, the engine's constants are int and Fraction)."""
        tx = type(x)
        if tx is Tracer or tx is int or tx is Fraction or tx is Dim:
            return self.arg(x)
        if tx is bool:
            return self.refuse("a bool is not a number of the IR (exact constants are int and Fraction): write 1 or 0")
        if tx is str or x is None or tx in (list, tuple, dict, Gradient, TraceConstraints, TraceScene) \
                or id(x) in _NAMED:
            # arguments of the engine's functions (a name, a list of rows, a tangent, a scene, an engine constant),
            # never numbers
            return self.refuse(f"{_article(tx.__name__)} {tx.__name__} is not a number of the IR (exact constants are "
                               "int and Fraction)")
        return self.refuse(_not_a_value(tx))

    def kw(self, kw: dict) -> tuple:
        if not kw:
            return ()
        return (self.g.add("kw", tuple((k, self.arg(v, True)) for k, v in sorted(kw.items()))),)

    # -- functions handed to the engine ----------------------------------------------------------
    def function(self, f: Any, arity: int | None) -> tuple[Ref, Any]:
        """Trace a function of a scene (and further arguments) once: its ``fn`` node and its value."""
        if not callable(f) or isinstance(f, (type, Tracer, TraceScene)):
            return self.refuse("a function of the scene is expected")
        hit = self._functions.get(id(f))
        if hit is not None and hit[0] is f and not getattr(self, "_like", None):
            # the same function object again: it must trace to the same body (its closure, defaults or
            # globals may have changed since; then it is another function, and it is refused)
            k, arity, body = self.g.args[hit[1].i]
            scene = TraceScene(self, self.g.add("scene", (k,)))
            like = hit[3]
            if like is not None:
                extra = [self.mirror(like, self.g.add("param", (k, 1, self.arg(like))))]
            else:
                extra = [self.new("param", (k, i), ANY) for i in range(1, arity)]
            self._open.append(k)
            try:
                again = self.structure(self._call_traced(f, scene, extra))
            finally:
                self._open.pop()
            if again != body:
                return self.refuse("a function that traces to another graph when it is used again (its state "
                                   "changed between two uses)")
            return hit[1], hit[2]
        if arity is None:
            try:
                params = [p for p in inspect.signature(f).parameters.values()
                          if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) and p.default is p.empty]
                arity = max(len(params), 1)
            except (TypeError, ValueError):
                arity = 1
        self.g.fns += 1
        k = self.g.fns
        scene = TraceScene(self, self.g.add("scene", (k,)))
        like = getattr(self, "_like", {}).get(f) if arity == 2 else None
        if like is not None:
            extra = [self.mirror(like, self.g.add("param", (k, 1, self.arg(like))))]
        else:
            extra = [self.new("param", (k, i), ANY) for i in range(1, arity)]
        self._parents[k] = frozenset(self._open)
        self._open.append(k)
        try:
            out = self._call_traced(f, scene, extra)
            body = self.structure(out)
        finally:
            self._open.pop()
        ref = self.g.add("fn", (k, arity, body))
        # a function traced afresh at a use (a step that shapes its parameter like its argument traces it at each use)
        # must be the same graph as at its first (up to the numbering of functions and its parameter's shape): a
        # function whose state changed between two steps (a kinetic energy c·T with c flipped between two
        # euler_lagrange calls, its point's keys in another order at the second) would have each step see another
        # function (stop 79's second review, W3b; stop 80's review, W2)
        first = self._first_bodies.setdefault(id(f), (f, body))
        if first[0] is not f:
            self._first_bodies[id(f)] = (f, body)
        elif first[1] is not body and not self._same_body(first[1], body):
            return self.refuse("a function that traces to another graph when it is used again (its state "
                               "changed between two uses)")
        self._functions[id(f)] = (f, ref, out, like)
        return ref, out

    def _call_traced(self, f: Any, scene: "TraceScene", extra: list) -> Any:
        """f(scene, *extra) while f is traced.  An exception raised in it is recorded as a refusal before it goes on
        up: a claim that catches it and goes on would leave a graph with a function begun and never ended."""
        try:
            return f(scene, *extra)
        except BaseException as exc:
            if type(exc) is not TraceRefused or str(exc).removeprefix("refused: ") not in self.g.refusals:
                # (an engine refusal is recorded by refuse; one the function raised itself is recorded here)
                self.g.refusals.append(f"a function handed to the engine raised {type(exc).__name__} while it was "
                                       "traced (a function of the scene must return its value; an exception in it "
                                       "ends the claim, even where the claim catches it)")
            raise

    def _same_body(self, a: Any, b: Any) -> bool:
        """Whether two traced functions' bodies (a node, or a structure of nodes) are the same graph, up to the
        numbering of functions."""
        na: list[int] = []
        nb: list[int] = []

        def skeleton(x: Any, nodes: list[int]) -> Any:
            if type(x) is Ref:
                nodes.append(x.i)
                return "node"
            if type(x) is tuple:
                return tuple(skeleton(y, nodes) for y in x)
            return (type(x).__name__, x)

        return skeleton(a, na) == skeleton(b, nb) and self.same_graph(na, [], nb, [])

    def check_calls(self) -> None:
        """Hold every object the engine calls at several places (:func:`same_inline_function`,
        :func:`same_step_function` with ``inline``, :func:`same_scene_function`) to one function, once the
        claim's calls are all made (its Inverse statements' included): refuse the claim when they are not.

        A reference is a call with the most distinct arguments (at distinct arguments where there is one); every
        call must pass its arguments as the reference's pattern does or merge more of them (Λ(g, g) after
        Λ(a, b), or Λ(g; g, g) after Λ(x; g, g)), and be the reference's function at its own scene and arguments
        (:func:`_holds`: by shape, the reference's arguments merged as the call passes them, or by substitution
        into the reference, which serves where a call's argument is also a node the function computes, such as
        Λ(a·b; a, b) of the Lie–Poisson form, stop 80).

        The calls of an object fall in two kinds: those on the claim's own scene, and those on another scene
        (an engine step's function at its parameters, a derivative's scene, a point's own).  A call on the
        claim's scene cannot tell a value the function keeps from the claim's scene from one it reads from the
        scene it is given, so the claim's scene stands for the other scene when one of two compared calls is on
        it; calls on other scenes are compared as they are, where s.X kept from the claim's scene is a constant
        and t.X is not (stop 79).  So the calls on other scenes have a reference among them as well, and every
        one of them is held to it as it is.  Candidates are tried in turn (the calls at arguments the function
        does not compute first, a few dozen at most), the first that serves is the reference."""
        own = self.g.index.get(("scene", (0,)))
        simple = ("param", "item", "call", "attr", "scene", "fresh", "generic")
        for calls in self._calls.values():
            cs, what = calls["calls"], calls["what"]
            memo: dict[tuple[int, int], bool] = {}

            def holds(r: int, c: int) -> bool:
                key = (r, c)
                if key not in memo:
                    a, b = cs[r], cs[c]
                    memo[key] = (len(a[2]) == len(b[2]) and all(b[2][i] == b[2][a[2][i]] for i in range(len(a[2])))
                                 and _holds(self, a, b, own))
                return memo[key]

            def serves(group: list[int]) -> bool:
                if len(group) < 2:
                    return True
                most = max(len(set(cs[i][2])) for i in group)
                cands = [i for i in group if len(set(cs[i][2])) == most]
                g_ops = self.g.ops
                cands.sort(key=lambda i: not all(x < 0 or g_ops[x] in simple for x in cs[i][1][1:]))
                return any(all(holds(r, c) for c in group) for r in cands[:32])

            everyone = list(range(len(cs)))
            others = [i for i in everyone if not cs[i][3]]
            # (a reference on another scene first: calls on the claim's scene hold to it exactly)
            everyone.sort(key=lambda i: cs[i][3])
            if not (serves(others) and serves(everyone)):
                self.refuse(f"{what} traces to another graph at one of its calls than at its first (a test of "
                            "its arguments, or its state, changed it): a statement about one function")

    def check_parameters(self) -> None:
        """Refuse a graph in which a function's body, or the claim's checks, read a parameter (or the scene)
        of a function that does not enclose it: a value kept from the trace of another function (a Poisson
        tensor that keeps a point it was evaluated at, a list a function appends its argument to), which no
        evaluation binds."""
        g, empty = self.g, frozenset()
        # nodes read only nodes made before them, so none before the first parameter or function scene reads one:
        # the sweep starts there (the ops are searched in C; scene nodes are few, once per attribute and scene)
        ops, args = g.ops, g.args
        start = len(ops)
        if "param" in ops:
            start = ops.index("param")
        at = -1
        while True:
            try:
                at = ops.index("scene", at + 1, start)
            except ValueError:
                break
            if args[at][0] != 0:
                start = at
                break
        if start == len(ops):
            return
        deps: list[frozenset] = [empty] * start
        nested = Graph._nested
        for op, a in zip(ops[start:], args[start:]):
            below = []
            for x in a:         # Graph.refs in line: a node's arguments are mostly refs
                if type(x) is Ref:
                    dx = deps[x[0]]
                    if dx:
                        below.append(dx)
                elif type(x) is tuple:
                    below += [deps[j] for j in nested(x) if deps[j]]
            if op != "scene" and op != "param" and op != "fn" and len(below) <= 1:
                deps.append(below[0] if below else empty)
                continue
            d: set = set().union(*below)
            if op == "param" or (op == "scene" and a[0] != 0):
                d.add(a[0])
            if op == "fn":
                d.discard(a[0])
                if not d <= self._parents.get(a[0], empty):
                    self.refuse("a function's parameter used outside the function (a value kept from the trace "
                                "of another function)")
            deps.append(frozenset(d))
        if g.output is not None and deps[g.output.i]:
            self.refuse("a function's parameter used outside the function (a value kept from the trace of a "
                        "function, in the claim's checks)")

    # -- structured values ------------------------------------------------------------------------
    def statement(self, v: Any, op: str, args: tuple) -> Any:
        """The node of a Rank or Count statement, with the site of the claim expression that made it (kept on
        the statement: :func:`.sites.statement_site`) when the trace records sites."""
        g = self.g
        made = len(g.ops)
        ref = g.add(op, args)
        if g.sites is not None and len(g.ops) > made:
            g.sites[ref.i] = getattr(v, "_site", None)
        return ref

    def structure(self, v: Any) -> Any:
        """A value a claim (or a traced function) returns, as a node."""
        tv = type(v)
        if tv is Rank:
            m = v.matrix
            if not (type(m) is Tracer and m._kind != SCALAR):
                what = ("a list of rows (a Jacobian?): build the matrix with s.mat(rows)" if isinstance(m, list)
                        else "a number" if type(m) is Tracer else type(m).__name__)
                return self.refuse(f"Rank: the matrix must be a matrix of the scene, not {what}")
            k = v.kernel
            if k is None:
                return self.statement(v, "rank", (m._r, v.expected, v.generic, v.meaning))
            if not (type(k) is Tracer and k._kind != SCALAR):
                return self.refuse(f"Rank: the kernel must be a matrix of the scene (its columns the kernel vectors), "
                                   f"not {'a list' if isinstance(k, list) else 'a number' if type(k) is Tracer else type(k).__name__}")
            if v.generic is not True:
                # the statement refuses it when made; one changed after (object.__setattr__) is refused here, as
                # a trace's refusal, not as an exception of the replay that makes the statement again
                return self.refuse("Rank: a kernel certifies a generic rank (generic=True); a rank at every point "
                                   "needs a constant minor or a RightInverse")
            rows, cols = (x.value if type(x) is Size else x for x in (k._shape[0], m._shape[1]))
            if None not in (rows, cols) and rows != cols:
                return self.refuse(f"Rank: the kernel has {rows} rows and the matrix {cols} columns "
                                   f"(the kernel's columns are vectors v with M v = 0)")
            return self.statement(v, "rank", (m._r, v.expected, v.generic, v.meaning, k._r))
        if tv is Count:
            return self.statement(v, "count", (v.value, v.expected, v.meaning))
        if tv is Inverse or tv is RightInverse:
            return self.refuse(f"an {tv.__name__} statement is a check of the claim (a value of the dict it returns)")
        if tv is int or (tv is Fraction and _reduced(v)):
            return self.g.add("const", (v,))
        return self.arg(v)

    def mirror(self, out: Any, node: Ref) -> Any:
        """Tracers for the parts of an engine result shaped like ``out`` (a function's value)."""
        if isinstance(out, Tracer):
            return Tracer(self, node, out._kind, out._shape)
        if type(out) in (list, tuple, Gradient):
            parts = [self.mirror(x, self.g.add("item", (node, i))) for i, x in enumerate(out)]
            return parts if type(out) is list else tuple(parts) if type(out) is tuple else Gradient(parts)
        if type(out) is dict:
            return {k: self.mirror(x, self.g.add("item", (node, k))) for k, x in out.items()}
        return Tracer(self, node, ANY)

    def inverse(self, v: Inverse | RightInverse) -> Ref:
        """The node of an Inverse statement: op and inv applied, in the claim's scene, to generic
        elements y and x of the product of spaces (fresh generic letters G, symmetrized or skewed), and
        the residuals op(inv(y)) − y, inv(op(x)) − x and those that say op(x), inv(y) are in the product.
        For a RightInverse (op from the spaces ``on`` to the spaces ``to``), y is an element of ``to`` and
        x of ``on``, and the residuals are op(inv(y)) − y and those of inv(y) in ``on``, op(x) in ``to``."""
        scene = TraceScene(self, self.g.add("scene", (0,)))
        right = type(v) is RightInverse
        on = v.on
        to = v.to if right else v.on
        name = type(v).__name__

        def elements(letter: str, spaces: tuple) -> tuple:
            self._elements = True
            try:
                out = []
                for i, d in enumerate(spaces):
                    m, k, kind = DOMAINS[d]
                    G = scene.generic(f"{INVERSE_ELEMENTS}{letter}{i + 1}", m, k)
                    out.append(G + G.T if kind == "sym" else G - G.T if kind == "skew" else G)
                return tuple(out)
            finally:
                self._elements = False

        def image(f: Callable, args: tuple, what: str, spaces: tuple) -> tuple:
            out = f(scene, *args)
            out = (out,) if type(out) is Tracer else out
            # a matrix of the scene (or a value an engine step made, typed when it is evaluated)
            if type(out) not in (tuple, list) or len(out) != len(spaces) or any(
                    type(x) is not Tracer or x._kind == SCALAR for x in out):
                return self.refuse(f"{name}: {what} returns one matrix per space of {' × '.join(spaces)}")
            # ... of the space's own shape: a map of the product into itself (xᵀ on R^{n×r} maps it to
            # R^{r×n}, and is its own inverse there), or of ``on`` into ``to`` for a right inverse
            for x, d in zip(out, spaces):
                want = (self.size(1, DOMAINS[d][0]), self.size(1, DOMAINS[d][1]))
                if x._kind == MAT and any(_same_size(a, b, self) is not True for a, b in zip(x._shape, want)):
                    return self.refuse(f"{name}: {what} returns a {x!r} where {d} has {want[0].d}×{want[1].d} "
                                       "matrices (a map of the product into " + ("the product of its spaces to)"
                                                                                 if right else "itself)"))
            return tuple(out)

        def member(x: Tracer, d: str) -> Tracer | None:
            kind = DOMAINS[d][2]
            return x - x.T if kind == "sym" else x + x.T if kind == "skew" else None

        ys = elements("Y", to)
        inv_y = image(v.inv, ys, "inv", on)
        op_inv_y = image(v.op, inv_y, "op", to)
        xs = elements("X", on)
        op_x = image(v.op, xs, "op", to)
        inv_op_x = () if right else image(v.inv, op_x, "inv", on)
        # op and inv see the elements through their arguments only: op(inv(y)) reads y through inv(y),
        # inv(op(x)) reads x through op(x), inv(y) reads no x and op(x) no y (a function that read an
        # element itself would make the identities say nothing: op = const y, inv = const x)
        for out, stop, what in ((inv_y, ys, "inv(y)"), (op_inv_y, inv_y, "op(inv(y))"), (op_x, xs, "op(x)"),
                                (inv_op_x, op_x, "inv(op(x))")):
            if not out:
                continue
            if self._reads_elements(out, stop):
                return self.refuse(f"{name}: {what} reads a generic element of the statement other than "
                                   "through its argument")
            # the identities hold as rational functions, so they prove op invertible only where every
            # divisor is nonzero: a divisor that is not a constant (tr PᵀP, (PᵀP)⁻¹, x⁻¹, a resolvent)
            # may vanish at some point of T*V or some element, and "at every point" would not follow
            why = self._divisor(out, stop)
            if why:
                return self.refuse(f"{name}: {what} divides by {why}, which may vanish at some point of T*V, "
                                   "some element or some A (op(inv(y)) = y" + ("" if right else " and inv(op(x)) = x")
                                   + " would prove op " + ("onto" if right else "invertible")
                                   + " only where it does not): only constant divisors")
        # op (and inv) are one map each: the code called twice must trace to the same graph of its
        # argument both times (an op whose state or whose test of its argument made it the identity on
        # inv(y) and X Xᵀ x on x would have op(inv(y)) = y "prove" a projection onto)
        for first, a1, second, a2, what in ((op_inv_y, inv_y, op_x, xs, "op"), (inv_y, ys, inv_op_x, op_x, "inv")):
            if second and not self._same_map(first, a1, second, a2):
                return self.refuse(f"{name}: {what} traces to another graph on its second argument than on its "
                                   "first (its state, or a test of its argument, changed it between two calls): "
                                   "a statement about one map")
        residuals = [a - b for a, b in zip(op_inv_y, ys)] + [a - b for a, b in zip(inv_op_x, xs)]
        residuals += [m for m in (member(x, d) for x, d in zip(inv_y + op_x, on + to)) if m is not None]
        # the parts as tuples of references (no container node: the statement's node is the first node
        # made after its subgraph, as when a graph is replayed)
        if right:
            parts = tuple(tuple(x._r for x in p) for p in (ys, inv_y, op_inv_y, xs, op_x, residuals))
            return self.g.add("right_inverse", parts + (on, to, v.meaning))
        parts = tuple(tuple(x._r for x in p) for p in (ys, inv_y, op_inv_y, xs, op_x, inv_op_x, residuals))
        return self.g.add("inverse", parts + (on, v.meaning))

    def _same_map(self, outs1: tuple, args1: tuple, outs2: tuple, args2: tuple) -> bool:
        """Whether the nodes ``outs1`` are the same graph of the nodes ``args1`` as ``outs2`` of ``args2``:
        equal after each argument node is replaced by its position (nodes that read no argument are the
        same nodes: the graph shares equal nodes)."""
        if len(outs1) != len(outs2) or len(args1) != len(args2):
            return False
        return self.same_graph([x._r.i for x in outs1], [x._r.i for x in args1],
                               [x._r.i for x in outs2], [x._r.i for x in args2])

    def same_graph(self, outs1: list, args1: list, outs2: list, args2: list) -> bool:
        """Whether the nodes ``outs1`` (indices) are the same graph of the nodes ``args1`` as ``outs2`` of
        ``args2``, the functions the trace numbers (their scenes, parameters and ``fn`` nodes) renamed in
        order of appearance on each side, a parameter's shape-giving argument left out."""
        g = self.g
        ids: dict[tuple, int] = {}          # hash-consed forms, shared by both sides

        def sub(a: Any, below: dict) -> Any:
            if type(a) is Ref:
                return below[a.i]
            if type(a) is tuple:
                return tuple(sub(b, below) for b in a)
            return (type(a).__name__, a) if type(a) in (int, Fraction, str, bool) else a

        def shape(outs: list, args: list) -> tuple:
            # an argument is a node, or a tuple of nodes that stand for the same argument
            memo: dict[int, tuple] = {i: ("arg", k) for k, a in enumerate(args)
                                      for i in (a if type(a) is tuple else (a,))}
            fns: dict[int, int] = {}
            stack = list(outs)
            while stack:                    # post-order, iteratively (graphs are deep)
                i = stack[-1]
                if i in memo:
                    stack.pop()
                    continue
                op, a = g.ops[i], g.args[i]
                # (a parameter's shape-giving argument is left out: not read, its functions not numbered)
                kids = () if op == "param" else g.refs(i)
                todo = [j for j in kids if j not in memo]
                if todo:
                    stack.extend(todo)
                    continue
                stack.pop()
                below = {j: memo[j] for j in kids}
                if op in ("fn", "param") or (op == "scene" and a[0] != 0):
                    # a function traced in the call: numbered by the trace, so by order of appearance here
                    rest = a[1:2] if op == "param" else a[1:]
                    key = (op, ("fn", fns.setdefault(a[0], len(fns))), sub(rest, below))
                    memo[i] = ("form", ids.setdefault(key, len(ids)))
                elif all(v[0] == "node" for v in below.values()):
                    memo[i] = ("node", i)   # reads no argument: the node itself
                else:
                    key = (op, sub(a, below))
                    memo[i] = ("form", ids.setdefault(key, len(ids)))
            return tuple(memo[i] for i in outs)

        return shape(outs1, args1) == shape(outs2, args2)

    def step_function(self, value: Any) -> int | None:
        """The ``fn`` node (index) of the function argument of the engine step that made ``value``."""
        if type(value) is not Tracer or value._t is not self or self.g.ops[value._r.i] != "prim":
            return None
        return next((j for j in self.g.refs(value._r.i) if self.g.ops[j] == "fn"), None)

    def _divisor(self, outs: tuple, args: tuple) -> str:
        """What a node of ``outs`` (down to the nodes ``args``) divides by when it is not a constant: a
        division by a number, a matrix inverse, a negative power, a resolvent or A⁻¹ outside the metric
        realization ("" when there is none)."""
        g = self.g
        for i in self._below(outs, args):
            op, a = g.ops[i], g.args[i]
            if op == "div" and not self._constant(a[1]):
                return "a number that is not a constant"
            if op == "inv" and not self._constant(a[0]):
                return "a matrix that is not constant (an inverse)"
            if op == "pow" and not (type(a[1]) is int and a[1] >= 0) and not self._constant(a[0]):
                return "a number that is not a constant (a negative power)"
            if op == "call" and a[1] == "resolvent":
                return "a resolvent (μI − A)"
            if op == "attr" and a[1] == "Ainv" and self.constraints[0] != "metric":
                # (the metric realization's A is positive definite: there A⁻¹ is a constant of the system)
                return "A⁻¹ (its determinant det A is zero for a singular A)"
            if op == "prim" and type(a[0]) is Named and a[0].qualname in self._SOLVING_STEPS:
                return (f"the determinant of a linear system of the claim's own ({a[0].qualname.rsplit('.', 1)[-1]}: "
                        "its matrix, from the claim's constraints or kinetic form, may be singular)")
        return ""

    def _below(self, outs: tuple, args: tuple) -> Iterator[int]:
        """The nodes of ``outs`` and below them, down to (not including) the nodes ``args``."""
        g, stop = self.g, {a._r.i for a in args}
        seen: set[int] = set()
        stack = [x._r.i for x in outs]
        while stack:
            i = stack.pop()
            if i in seen or i in stop:
                continue
            seen.add(i)
            yield i
            stack.extend(g.refs(i))

    #: the nodes a constant divisor is made of: numbers and their arithmetic (no scene value, no
    #: parameter, no element, no engine step)
    _CONSTANT_OPS = frozenset({"const", "add", "sub", "mul", "div", "neg", "pow", "matmul", "T", "trace", "inv"})
    _CONSTANT_CALLS = frozenset({"q", "const", "identity", "zeros", "scalar_matrix", "tr"})
    #: engine steps that solve a linear system built from the claim's own functions or matrices (the
    #: multipliers of its constraints, the inverse of its kinetic form, the twisted bracket matrix of
    #: its magnetic matrix, the flows at a point it chooses): a division by their determinant
    _SOLVING_STEPS = frozenset({"stiefelsym.systems.hamiltonian_flow", "stiefelsym.systems.euler_lagrange",
                                "stiefelsym.twisted.bracket", "stiefelsym.twisted.flow",
                                "stiefelsym.twisted.multiplier_flow", "stiefelsym.twisted.at_point"})

    def _constant(self, a: Any) -> bool:
        """Whether the argument ``a`` (a literal or a node) is made of constants only."""
        if type(a) is not Ref:
            return type(a) in (int, Fraction, Size) and a != 0
        g, seen, stack = self.g, set(), [a.i]
        while stack:
            i = stack.pop()
            if i in seen:
                continue
            seen.add(i)
            op, args = g.ops[i], g.args[i]
            if op == "call":
                if args[1] not in self._CONSTANT_CALLS:
                    return False
                stack.extend(j for j in g.refs(i) if g.ops[j] != "scene")
                continue
            if op not in self._CONSTANT_OPS:
                return False
            stack.extend(g.refs(i))
        return True

    def _reads_elements(self, outs: tuple, args: tuple) -> bool:
        """Whether a node of ``outs`` reads a generic element of an Inverse statement other than through
        the nodes ``args`` (the function's arguments)."""
        g = self.g
        for i in self._below(outs, args):
            a = g.args[i]
            if (g.ops[i] == "call" and a[1] == "generic" and type(a[2]) is tuple and type(a[2][0]) is str
                    and a[2][0].startswith(INVERSE_ELEMENTS)):
                return True
        return False

    # -- engine primitives --------------------------------------------------------------------------
    def prim(self, qual: str, args: tuple, kw: dict, returns: Any = None, shapes: dict | None = None) -> Any:
        self._like = shapes or {}
        try:
            ref = self.g.add("prim", (Named(qual),) + tuple(self.arg(a, True) for a in args) + self.kw(kw))
        finally:
            self._like = {}
        check = STEP_GRAPH_CHECKS.get(qual)
        if check is not None:
            check(self, ref)
        if returns == "scene":
            return TraceScene(self, ref)
        if type(returns) is tuple and returns[0] == "mat":     # ("mat", spaces): a matrix of those spaces
            return Tracer(self, ref, MAT, self.shape_of(returns[1]))
        if type(returns) is tuple:              # ("like", name): shaped like a function argument's value
            f = (shapes or {}).get("__returns__")
            if type(f) is Tracer and f._kind == MAT:   # ... or like a matrix argument: a matrix of its spaces
                return Tracer(self, ref, MAT, f._shape)
            hit = self._functions.get(id(f)) if f is not None else None
            return self.mirror(hit[2], ref) if hit is not None else Tracer(self, ref, ANY)
        if type(returns) is int:
            return tuple(self.new("item", (ref, i), ANY) for i in range(returns))
        return Tracer(self, ref, ANY)


def same_step_function(value: Any, obj: Any, what: str, parts: Callable[[Any], tuple] | None = None,
                       inline: bool = False) -> None:
    """In a trace: the function of the engine step that made ``value`` (an evaluation of ``obj``, such as a
    Poisson tensor) must be the same graph (up to the trace's numbering of functions) at every evaluation
    of the same object in the claim, as at its first: an object whose state (or a test of its arguments)
    makes it another function at some evaluations is refused.  ``parts(obj)``: (op, objects) when the
    object's function is the step ``op`` of its parts' functions (a sum: ("add", (T1, T2)); a multiple:
    ("mul", (T,))), each part held to its own evaluations elsewhere in the claim.  ``inline``: the object is
    also called inline by engine code (:func:`same_inline_function`) at one argument, the step function's
    second parameter; the step's function is then held to those calls too.  Outside a trace, nothing."""
    if not _ACTIVE:
        return
    t = _ACTIVE[-1]
    k = t.step_function(value)
    hit = t._functions.get(id(obj))
    if k is not None and hit is not None and hit[0] is obj and hit[1].i in t.g.refs(value._r.i):
        k = hit[1].i                    # a step of several functions: the one the object was traced as
    if k is None:
        return
    body = t.g.args[k][2]
    if type(body) is not Ref:
        return
    g, forms = t.g, t._one_function

    def hold(o: Any, node: int) -> None:
        hit = forms.get(id(o))
        if hit is None or hit[0] is not o:
            forms[id(o)] = (o, node)
        elif not t.same_graph([hit[1]], [], [node], []):
            t.refuse(f"{what} traces to another graph at one of its evaluations than at its first (its state, or "
                     "a test of its arguments, changed it): a statement about one function")
        op, sub = parts(o) if parts is not None else ("", ())
        a = g.args[node]
        if sub and g.ops[node] == op and len(a) >= len(sub) and all(type(x) is Ref for x in a[:len(sub)]):
            for x, part in zip(a, sub):
                hold(part, x.i)

    hold(obj, body.i)
    if inline:
        # the step's function, as a graph of its scene and arguments, is the form every inline call of the object
        # in the claim must have (same_inline_function)
        number = g.args[k][0]
        params = _parameters(g, body.i, number)
        _same_call(t, obj, body.i, params, what)


def _parameters(g: Graph, body: int, number: int) -> list[int]:
    """The nodes of the function ``number``'s scene and second parameter under ``body`` (-1 for one it does not
    read)."""
    found: dict[str, int] = {}
    seen: set[int] = set()
    stack = [body]
    while stack:
        i = stack.pop()
        if i in seen:
            continue
        seen.add(i)
        op, a = g.ops[i], g.args[i]
        if op == "scene" and a[0] == number:
            found["scene"] = i
        elif op == "param" and a[0] == number and a[1] == 1:
            found["param"] = i
        stack.extend(g.refs(i))
    return [found.get("scene", -1), found.get("param", -1)]


def same_inline_function(value: Any, obj: Any, scene: Any, args: tuple, what: str) -> None:
    """In a trace: ``value`` is obj(scene, *args), called by engine code inline (the value ½<x, op(x)> of
    brackets.quadratic, a tensor's Λ(a, b)|_x): every such call of the object, and the function of the engine
    step that checks it where the claim hands it to one (:func:`same_step_function` with ``inline``), must be the
    same graph of its scene and arguments, as at the first; else the step would check another function than
    the one the claim computes with, or two calls would be two functions (an op that is B·u at the claim's own
    point and u elsewhere, or one with state, stop 79).  Outside a trace, nothing."""
    if not _ACTIVE:
        return
    t = _ACTIVE[-1]
    if (type(scene) is not TraceScene or scene._t is not t or (type(value) is Tracer and value._t is not t)
            or not all(type(x) is Tracer and x._t is t for x in args)):
        t.refuse(f"{what}: a value of the claim's scene, at matrices of it, on the scene")
    out = t.arg(value)
    if type(out) not in (Ref, int, Fraction):
        t.refuse(f"{what}: a value of the claim's scene, at matrices of it, on the scene")
    # a constant value (a number the call returned) is compared as a number (no node: the graph is the claim's)
    _same_call(t, obj, out.i if type(out) is Ref else ("number", out), [scene._r.i] + [x._r.i for x in args], what)


def _same_call(t: "Trace", obj: Any, out: Any, args: list, what: str, key: Any = None) -> None:
    """Record a call of ``obj`` (its value ``out``, a graph of the nodes ``args``: the scene it is called on, then
    its arguments; or ("number", q), a constant it returned), to be held to one function when the claim's trace
    ends (:meth:`Trace.check_calls`, where the rule is).  Calls of an object that is another object by the end
    (an id reused) start afresh."""
    g = t.g
    own = g.index.get(("scene", (0,)))
    # a parameter the step's function does not read is -1: a placeholder of its own, never one of another's
    entries = [x if x >= 0 else -1 - 1000 * k for k, x in enumerate(args)]
    labels = tuple(next(j for j in range(k + 1) if entries[j] == entries[k]) for k in range(len(entries)))
    on_own = own is not None and args[0] == own
    calls = t._calls.setdefault(key if key is not None else id(obj), {"obj": obj, "calls": [], "what": what})
    if calls["obj"] is not obj:
        calls.update(obj=obj, calls=[], what=what)
    calls["calls"].append((out, tuple(entries), labels, on_own))


def _holds(t: "Trace", ref: tuple, c: tuple, own: int | None) -> bool:
    """Whether the call ``c`` is the function of the call ``ref`` (whose arguments are distinct nodes) at ``c``'s
    scene and arguments: the same graph of them (``c``'s arguments merged as it passes them, Λ(g, g)), or the graph
    ``ref``'s value becomes when ``c``'s scene and arguments are put in place of ``ref``'s (:func:`_substituted`)."""
    r_out, r_entries, _r_labels, r_own = ref
    c_out, c_entries, c_labels, c_own = c
    if len(r_entries) != len(c_entries):
        return False
    if type(r_out) is tuple or type(c_out) is tuple:
        return r_out == c_out
    # the claim's scene stands for the other call's scene where exactly one of the two is on it
    r_e = [(x,) for x in r_entries]
    c_e = [(x,) for x in c_entries]
    if r_own and not c_own:
        c_e[0] = c_e[0] + (own,)
    elif c_own and not r_own:
        r_e[0] = r_e[0] + (own,)
    classes = sorted(set(c_labels))
    merged = [tuple(x for k, e in enumerate(r_e) if c_labels[k] == cl for x in e) for cl in classes]
    if t.same_graph([r_out], merged, [c_out], [c_e[cl] for cl in classes]):
        return True
    if r_own and not c_own:
        # ref's nodes of the claim's scene are values it keeps and values it reads alike: no substitution
        return False
    sigma: dict[int, int] = {}
    for x, y in zip(r_entries, c_entries):
        if x < 0:
            continue            # a parameter the reference does not read
        if y < 0:
            y = -1              # one the call does not read: the reference's value must not depend on it
        if sigma.setdefault(x, y) != y:
            return False
    return _substituted(t.g, r_out, sigma) == c_out


def _substituted(g: Graph, out: int, sigma: dict[int, int]) -> int | None:
    """The node the graph of ``out`` becomes when each node ``x`` of ``sigma`` is replaced by ``sigma[x]``, looked
    up among the graph's nodes (hash-consed: a call that computed that graph made that node); None when a node of
    it is not in the graph, or when ``out`` reads a function's parameter, scene or body other than through the
    nodes of ``sigma`` (the value is then no function of the call's scene and arguments alone), or when it reads a
    node that ``sigma`` maps to −1 (an argument the other call does not read)."""
    memo: dict[int, int] = dict(sigma)
    index, ops, args = g.index, g.ops, g.args

    def put(a: Any) -> Any:
        if type(a) is Ref:
            return _ref(memo[a.i])
        if type(a) is tuple:
            return tuple(put(b) for b in a)
        return a

    stack = [out]
    while stack:
        i = stack[-1]
        if i in memo:
            stack.pop()
            continue
        op, a = ops[i], args[i]
        if op in ("param", "fn") or (op == "scene" and a[0] != 0):
            return None
        kids = g.refs(i)
        todo = [j for j in kids if j not in memo]
        if todo:
            stack.extend(todo)
            continue
        stack.pop()
        if any(memo[j] < 0 for j in kids):
            return None
        if all(memo[j] == j for j in kids):
            memo[i] = i
            continue
        j = index.get((op, put(a)))
        if j is None:
            return None
        memo[i] = j
    return memo[out] if memo[out] >= 0 else None


def same_scene_function(f: Any, scene: Any, value: Any, what: str) -> Any:
    """In a trace: the value of the function ``f`` of a scene, called by engine code on several scenes (the
    claim's and those of the functions it differentiates), must be the same graph of its scene at every
    call of the same object, as at its first (a function whose state makes it another at some calls is
    refused); returns ``value``; outside a trace (or for a value that is not traced), nothing is checked."""
    if not _ACTIVE or type(scene) is not TraceScene or type(value) not in (Tracer, int, Fraction):
        return value
    t = _ACTIVE[-1]
    if scene._t is not t or (type(value) is Tracer and value._t is not t):
        return value
    # a number the call returned is a node too (a function that returns 2, then 0, is not one function)
    node = value._r.i if type(value) is Tracer else ("number", value)
    # every call is the same graph of its scene; the claim's own scene stands for another call's scene where
    # one of the two is on it (a value the function keeps from the claim's scene is the same value there), and
    # calls on two other scenes are compared as they are (see _same_call)
    _same_call(t, f, node, [scene._r.i], what.rstrip(), key=("scene function", id(f)))
    return value


#: the size expressions k·d made so far (see Trace.size)
_SIZE_MEMO: dict[tuple[int, str], Size] = {}


def memo_problems() -> list[str]:
    """What is wrong with the memos the tracer reads (each entry a function of its key: the shared references
    and their text in a digest, the size expressions), where claim code that reached them changed them; empty
    when they are as the engine made them."""
    from stiefelsym.ir import graph as _graph
    out = []
    refs, texts = _graph._REFS, _graph._REF_TEXT
    if len(refs) != len(texts) or any(type(x) is not Ref or len(x) != 1 or x[0] != i for i, x in enumerate(refs)):
        out.append("a shared reference Ref(i) is not the i-th")
    elif any(t != f"%{i}" for i, t in enumerate(texts)):
        out.append("a reference's text in a digest is not %i")
    for key, v in list(_SIZE_MEMO.items()):
        if type(v) is not Size or type(key) is not tuple or (v.k, v.d, v.value) != (key[0], key[1], None):
            out.append(f"the size expression of {key!r} is {v!r}")
            break
    return out


def _size_numbers(n: int | None, r: int | None) -> Callable[[Size], int | None]:
    def number(size: Size) -> int | None:
        v = n if size.d == "n" else r
        return None if v is None else size.k * v
    return number


def trace(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable],
          family: SizeFamily | None = None, sites: bool = False) -> Graph:
    """The graph of ``func`` at the size (n, r), or with symbolic sizes (n = r = None), on every size or
    on the sizes of a ``family`` (see :mod:`.families`).  ``sites``: record, per node, the claim
    expression that made it (:mod:`.sites`: metadata, not part of the graph's digest)."""
    t = Trace(n, r, constraints, family)
    if sites:
        t.g.sites = []
        RECORDING[0] += 1
    _ACTIVE.append(t)
    try:
        out = func(TraceScene(t, t.g.add("scene", (0,))))
        if type(out) is not dict or not out:
            got = ("an empty dict" if type(out) is dict else "None" if out is None else
                   "a matrix or number of the trace: put it in a dict, {'name': residual}" if type(out) is Tracer
                   else f"a {type(out).__name__}")
            t.refuse(f"a claim returns a non-empty dict of named checks, {{'name': residual, ...}} (it returned {got})")
        if any(type(k) is not str for k in out):
            t.refuse("check names are strings")
        if not all(one_line(k, 200) for k in out):
            t.refuse("a check name is 1 to 200 characters of one line (it heads a line of the reports)")
        statements = (Inverse, RightInverse)
        t.g.output = t.g.add("dict", (tuple(out), tuple(t.inverse(v) if type(v) in statements else t.structure(v)
                                                        for v in out.values())))
        t.check_calls()           # (the calls an Inverse statement's op makes included)
        t.check_parameters()
    finally:
        _ACTIVE.pop()
        if sites:
            RECORDING[0] -= 1
    g = t.g.sealed()
    g.sizes = None if n is None else (n, r)
    return g


STOP.add(trace.__code__)     # below the trace's entry no claim code runs: a walk for a site ends there
